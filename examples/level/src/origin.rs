//! Where each triangle of a level came from in its file, so that a message naming triangle
//! 14203 also names what a level designer can find in the modelling tool: an OBJ face's line
//! (and which triangle of its polygon), a glTF node, mesh, primitive and triangle.
//!
//! Kept compact beside the triangles ([`Origins`]: a few `u32` a triangle, names stored once
//! per `o`/`g` line or glTF node) and spelled out on demand ([`Origin`]).

use std::fmt;

/// Where one triangle of a level came from in its file.
#[non_exhaustive]
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// A face (`f`) of a Wavefront OBJ file.
    Obj {
        /// The face's line, counting from 1.
        line: usize,
        /// For a face of four or more corners, split into triangles: which of them this one
        /// is and how many there are, counting from 1. `None` for a face that is a triangle.
        split: Option<(usize, usize)>,
        /// The name on the last `o` line before the face, if any.
        object: Option<String>,
        /// The name on the last `g` line before the face, if any.
        group: Option<String>,
    },
    /// A triangle of a glTF primitive; indices count from 0, as glTF's own do.
    Gltf {
        /// The node's index.
        node: usize,
        /// The node's name, if it has one.
        node_name: Option<String>,
        /// The mesh's index.
        mesh: usize,
        /// The mesh's name, if it has one.
        mesh_name: Option<String>,
        /// The primitive's index in its mesh.
        primitive: usize,
        /// The triangle's index in its primitive (in a strip or fan, its place along it).
        triangle: usize,
    },
}

/// Writes `what` and, where there is one, its name quoted (escaped: a name with a line break
/// cannot break a message or the baked file's comment).
fn named(f: &mut fmt::Formatter<'_>, what: &str, name: &Option<String>) -> fmt::Result {
    match name {
        Some(name) => write!(f, "{what} {name:?}"),
        None => f.write_str(what),
    }
}

/// `line 12, triangle 2 of 3 in its polygon, object "Room", group "floor"`, or `node 3
/// "Floor", mesh 2 "Tiles", primitive 0's triangle 17`.
impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Obj {
                line,
                split,
                object,
                group,
            } => {
                write!(f, "line {line}")?;
                if let Some((k, n)) = split {
                    write!(f, ", triangle {k} of {n} in its polygon")?;
                }
                if object.is_some() {
                    f.write_str(", ")?;
                    named(f, "object", object)?;
                }
                if group.is_some() {
                    f.write_str(", ")?;
                    named(f, "group", group)?;
                }
                Ok(())
            }
            Self::Gltf {
                node,
                node_name,
                mesh,
                mesh_name,
                primitive,
                triangle,
            } => {
                named(f, &format!("node {node}"), node_name)?;
                named(f, &format!(", mesh {mesh}"), mesh_name)?;
                write!(f, ", primitive {primitive}'s triangle {triangle}")
            }
        }
    }
}

/// One triangle's origin as stored: indices, names by their number in [`Origins`]' list
/// (0 for none, `k` for the `k`-th).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Record {
    Obj {
        line: u32,
        /// 0 for a face that is a triangle, else which triangle (from 1) of `pieces`.
        piece: u32,
        pieces: u32,
        object: u32,
        group: u32,
    },
    Gltf {
        node: u32,
        node_name: u32,
        mesh: u32,
        mesh_name: u32,
        primitive: u32,
        triangle: u32,
    },
}

/// Where every triangle of a level came from, one compact record a triangle in the level's
/// order; read through [`Level::origin`](crate::Level::origin). `Origins::default()` knows
/// none.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Origins {
    records: Vec<Record>,
    names: Vec<String>,
}

impl Origins {
    /// How many triangles it has a record for.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// Whether it has none.
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// Where triangle `index` came from, if it has a record.
    pub fn get(&self, index: usize) -> Option<Origin> {
        let name = |k: u32| match k {
            0 => None,
            k => self.names.get(k as usize - 1).cloned(),
        };
        Some(match *self.records.get(index)? {
            Record::Obj {
                line,
                piece,
                pieces,
                object,
                group,
            } => Origin::Obj {
                line: line as usize,
                split: (piece > 0).then_some((piece as usize, pieces as usize)),
                object: name(object),
                group: name(group),
            },
            Record::Gltf {
                node,
                node_name,
                mesh,
                mesh_name,
                primitive,
                triangle,
            } => Origin::Gltf {
                node: node as usize,
                node_name: name(node_name),
                mesh: mesh as usize,
                mesh_name: name(mesh_name),
                primitive: primitive as usize,
                triangle: triangle as usize,
            },
        })
    }

    /// Stores `name` (none where empty) and gives the number a record refers to it by.
    pub(crate) fn name(&mut self, name: Option<&str>) -> u32 {
        match name.filter(|n| !n.is_empty()) {
            None => 0,
            Some(n) => {
                self.names.push(n.to_string());
                u32::try_from(self.names.len()).unwrap_or(0)
            }
        }
    }

    /// Records an OBJ face's triangle: `piece` of `pieces` (from 1) where the face was split.
    pub(crate) fn push_obj(
        &mut self,
        line: usize,
        (piece, pieces): (usize, usize),
        names: [u32; 2],
    ) {
        let piece = if pieces > 1 { piece } else { 0 };
        let [object, group] = names;
        if let (Ok(line), Ok(piece), Ok(pieces)) = (small(line), small(piece), small(pieces)) {
            self.records.push(Record::Obj {
                line,
                piece,
                pieces,
                object,
                group,
            });
        }
    }

    /// Records a glTF primitive's triangle; `node` and `mesh` are (index, name number).
    pub(crate) fn push_gltf(
        &mut self,
        (node, node_name): (usize, u32),
        (mesh, mesh_name): (usize, u32),
        primitive: usize,
        triangle: usize,
    ) {
        let all = (small(node), small(mesh), small(primitive), small(triangle));
        if let (Ok(node), Ok(mesh), Ok(primitive), Ok(triangle)) = all {
            self.records.push(Record::Gltf {
                node,
                node_name,
                mesh,
                mesh_name,
                primitive,
                triangle,
            });
        }
    }
}

/// `n` as a record holds it. Where a count lies beyond `u32` (a file of billions of lines),
/// the triangle gets no record: the records fall out of step with the triangles, and the
/// level then names no triangle's place rather than wrong ones.
fn small(n: usize) -> Result<u32, std::num::TryFromIntError> {
    u32::try_from(n)
}
