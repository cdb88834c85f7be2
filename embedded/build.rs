//! Puts memory.x where the linker (cortex-m-rt's link.x) finds it, and bakes the firmware's
//! levels into `OUT_DIR` with the bake `cargo run --example bake` uses (`ballcast-level`):
//! `ramp.rs` (`examples/data/ramp.obj`, 96 triangles) and `arena.rs` (`arena.obj`, 2 168),
//! both I16F16 meshes in flash; and the compact forms of `forms` (`src/forms.rs`): `compact.rs`
//! (the arena as a `CompactMesh`) and `terrain.rs` (a 64 × 64 `Heightfield`). A bad level fails
//! the build with the loader's message.
use ballcast::bvh::{LeafSize, nodes_for};
use ballcast::{CompactMesh, Degenerates, Heightfield, HeightfieldShape, Mesh, Node, Vec3};
use fixed::types::I16F16;
use std::fmt::Write as _;
use std::{env, fs, path::PathBuf};

#[path = "src/forms.rs"]
mod forms;

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    for name in ["ramp", "arena"] {
        let path = format!("../examples/data/{name}.obj");
        println!("cargo:rerun-if-changed={path}");
        let baked = ballcast_level::load(&path).and_then(|l| ballcast_level::bake::<I16F16>(&l));
        match baked {
            Ok(b) => fs::write(out.join(format!("{name}.rs")), b.source).unwrap(),
            Err(e) => panic!("{e}"),
        }
    }
    println!("cargo:rerun-if-changed=src/forms.rs");
    fs::write(out.join("compact.rs"), compact()).unwrap();
    fs::write(out.join("terrain.rs"), terrain()).unwrap();
}

/// `items` as a Rust array literal, one per line.
fn list(items: impl Iterator<Item = String>) -> String {
    items.fold(String::from("[\n"), |s, i| s + "    " + &i + ",\n") + "]"
}

/// A vertex as the `v` of the generated code.
fn vertex(p: Vec3<I16F16>) -> String {
    format!("v({}, {}, {})", p.x.to_bits(), p.y.to_bits(), p.z.to_bits())
}

/// The arena as a compact mesh (u16 indices) in flash.
fn compact() -> String {
    let level = ballcast_level::load("../examples/data/arena.obj").unwrap();
    let tris = ballcast_level::triangles::<I16F16>(&level).unwrap();
    let n = tris.len();
    let (mut nodes, mut prepared) = (vec![Node::default(); nodes_for(n)], vec![Mesh::filler(); n]);
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    // Leaves of four: the smallest tree, which the compact mesh borrows.
    let (mesh, _) = Mesh::build(
        &tris,
        Degenerates::Skip.with_leaf_size(LeafSize::Four),
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )
    .unwrap();
    let (vertices, indices) = forms::indexed(&tris);
    let k = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; k], vec![0u16; k], vec![0u8; k]);
    let c = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let (nodes, grid, vertices, triangles, order, bytes, class) = c.parts();
    let mut s = String::from(
        "use ballcast::fixed::types::I16F16;\nuse ballcast::{CompactMesh, Grid, Node, Vec3};\n\n",
    );
    s += "const fn v(x: i32, y: i32, z: i32) -> Vec3<I16F16> {\n    Vec3::new(I16F16::from_bits(x), I16F16::from_bits(y), I16F16::from_bits(z))\n}\n\n";
    let _ = writeln!(
        s,
        "pub static NODES: [Node; {}] = {};",
        nodes.len(),
        list(nodes.iter().map(|n| format!("{n:?}")))
    );
    let _ = writeln!(
        s,
        "pub static VERTICES: [Vec3<I16F16>; {}] = {};",
        vertices.len(),
        list(vertices.iter().map(|&p| vertex(p)))
    );
    let _ = writeln!(
        s,
        "pub static TRIANGLES: [[u16; 3]; {}] = {};",
        triangles.len(),
        list(triangles.iter().map(|t| format!("{t:?}")))
    );
    let _ = writeln!(s, "pub static ORDER: [u16; {}] = {order:?};", order.len());
    let _ = writeln!(s, "pub static BYTES: [u8; {}] = {bytes:?};", bytes.len());
    let _ = writeln!(
        s,
        "pub static MESH: CompactMesh<'static, I16F16, u16> =\n    CompactMesh::from_parts(&NODES, {grid:?}, &VERTICES, &TRIANGLES, &ORDER, &BYTES, {class});"
    );
    s
}

/// The 64 × 64 terrain as a heightfield in flash.
fn terrain() -> String {
    let heights = forms::heights();
    let mut cells = vec![0u8; (forms::CELLS * forms::CELLS) as usize];
    let (spacing, unit) = (
        I16F16::from_bits(forms::SPACING_BITS),
        I16F16::from_bits(forms::UNIT_BITS),
    );
    let n = forms::CELLS;
    let f = Heightfield::build(
        HeightfieldShape {
            origin: Vec3::ZERO,
            spacing,
            unit,
            columns: n,
            rows: n,
        },
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let mut s = String::from(
        "use ballcast::fixed::types::I16F16;\nuse ballcast::{Heightfield, HeightfieldShape, Vec3};\n\n",
    );
    let _ = writeln!(
        s,
        "pub static HEIGHTS: [i16; {}] = {heights:?};",
        heights.len()
    );
    let _ = writeln!(
        s,
        "pub static CELLS: [u8; {}] = {:?};",
        f.cells().len(),
        f.cells()
    );
    let _ = writeln!(
        s,
        "pub static FIELD: Heightfield<'static, I16F16> = Heightfield::from_parts(HeightfieldShape {{ origin: Vec3::new(I16F16::ZERO, I16F16::ZERO, I16F16::ZERO), spacing: I16F16::from_bits({}), unit: I16F16::from_bits({}), columns: {n}, rows: {n} }}, &HEIGHTS, &CELLS, {:?}, {});",
        forms::SPACING_BITS,
        forms::UNIT_BITS,
        f.bounds(),
        f.class()
    );
    s
}
