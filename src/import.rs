//! Scenes from what modelling tools and file formats export: a vertex array with an index
//! buffer (glTF, OBJ after triangulation, most engines' meshes), or any iterator of triangles;
//! triangles converted from one scalar to another; and (with `alloc`) shared vertices and
//! indices welded from a triangle soup.

use crate::{Error, Input, Scalar, Scene, Triangle, Vec3};
#[cfg(feature = "alloc")]
use alloc::vec::Vec;

impl<S: Scalar, const N: usize> Scene<S, N> {
    /// A scene of one-sided triangles from `vertices` and an index buffer, three indices per
    /// triangle (counter-clockwise seen from the front), e.g. `&[u16]` or `&[u32]` as glTF
    /// stores them.
    ///
    /// Errors: [`Error::IndexCount`] for a buffer whose length is not a multiple of three,
    /// [`Error::VertexIndex`] naming the triangle and the index beyond `vertices` or negative
    /// (checked before anything is pushed), and those of [`push`](Self::push), naming the
    /// triangle.
    ///
    /// ```
    /// use ballcast::{Error, Scene, Vec3};
    /// let v = Vec3::new;
    /// let quad = [v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)];
    /// let scene: Scene<f32, 8> = Scene::from_indexed(&quad, &[0u16, 1, 2, 0, 2, 3])?;
    /// assert_eq!(scene.len(), 2);
    /// let bad = Scene::<f32, 8>::from_indexed(&quad, &[0u32, 1, 2, 0, 2, 4]).unwrap_err();
    /// assert_eq!(bad, Error::VertexIndex { triangle: 1, index: 4, vertices: 4 });
    /// assert_eq!(bad.to_string(), "triangle 1: vertex index 4 is beyond the 4 vertices");
    /// let negative = Scene::<f32, 8>::from_indexed(&quad, &[0i32, -1, 2]).unwrap_err();
    /// assert_eq!(negative.to_string(), "triangle 0: vertex index -1 is negative");
    /// # Ok::<(), Error>(())
    /// ```
    pub fn from_indexed<I: Copy + TryInto<i128>>(
        vertices: &[Vec3<S>],
        indices: &[I],
    ) -> Result<Self, Error> {
        let mut scene = Self::new();
        scene.extend_indexed(vertices, indices)?;
        Ok(scene)
    }

    /// [`from_indexed`](Self::from_indexed) into this scene: triangle indices in errors are
    /// those the triangles would have had in the scene. On an error from a push, the triangles
    /// before it stay in the scene ([`clear`](Self::clear) it to start again).
    pub fn extend_indexed<I: Copy + TryInto<i128>>(
        &mut self,
        vertices: &[Vec3<S>],
        indices: &[I],
    ) -> Result<(), Error> {
        if !indices.len().is_multiple_of(3) {
            return Err(Error::IndexCount { len: indices.len() });
        }
        let first = self.len();
        let corner = |k: usize| {
            // Every primitive integer converts to `i128` exactly (`u128` beyond it saturates).
            let index: i128 = indices[k].try_into().unwrap_or(i128::MAX);
            let found = usize::try_from(index).ok().and_then(|i| vertices.get(i));
            found.copied().ok_or(Error::VertexIndex {
                triangle: first + k / 3,
                index,
                vertices: vertices.len(),
            })
        };
        for k in 0..indices.len() {
            corner(k)?;
        }
        for k in (0..indices.len()).step_by(3) {
            let t = Triangle::new(corner(k)?, corner(k + 1)?, corner(k + 2)?);
            self.push(t)?;
        }
        Ok(())
    }

    /// Pushes every triangle of `triangles` (one-sided), stopping at the first error, which
    /// names the triangle; those before it stay in the scene.
    pub fn try_extend<T: IntoIterator<Item = Triangle<S>>>(
        &mut self,
        triangles: T,
    ) -> Result<(), Error> {
        triangles
            .into_iter()
            .try_for_each(|t| self.push(t).map(|_| ()))
    }
}

/// Collecting triangles into a scene pushes each (one-sided), and fails as
/// [`Scene::push`] does:
///
/// ```
/// use ballcast::{Error, Scene, Triangle, Vec3};
/// let v = Vec3::new;
/// let tiles = (0..4).map(|i| {
///     let x = i as f64;
///     Triangle::new(v(x, 0.0, 0.0), v(x, 0.0, 1.0), v(x + 1.0, 0.0, 0.0))
/// });
/// let scene: Scene<f64, 4> = tiles.clone().collect::<Result<_, _>>()?;
/// assert_eq!(scene.len(), 4);
/// let full: Result<Scene<f64, 3>, _> = tiles.collect();
/// assert_eq!(full.unwrap_err(), Error::Full { capacity: 3 });
/// # Ok::<(), Error>(())
/// ```
impl<S: Scalar, const N: usize> FromIterator<Triangle<S>> for Result<Scene<S, N>, Error> {
    fn from_iter<T: IntoIterator<Item = Triangle<S>>>(triangles: T) -> Self {
        let mut scene = Scene::new();
        scene.try_extend(triangles)?;
        Ok(scene)
    }
}

impl<S: Scalar> Triangle<S> {
    /// The same triangle in another scalar, each coordinate rounded to nearest, refusing a
    /// coordinate that `T` cannot hold within its safe range rather than saturating it.
    ///
    /// Errors: [`Error::NaN`]; [`Error::OutOfRange`] with the coordinate's value and `T`'s
    /// range. Either names the vertex ([`Input::Vertex`]); for one triangle of many,
    /// [`Error::at`] adds its index (`t.try_cast().map_err(|e| e.at(i))`), as a mesh's build
    /// names the triangles it refuses.
    ///
    /// ```
    /// use ballcast::{Error, Input, Triangle, Vec3};
    /// use fixed::types::I16F16;
    /// let v = Vec3::new;
    /// let t = Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 1.5), v(1.0, 0.0, 0.0));
    /// assert_eq!(t.try_cast::<I16F16>()?.v1.z, I16F16::from_num(1.5));
    /// let far = Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 1e6), v(1.0, 0.0, 0.0));
    /// let err = far.try_cast::<I16F16>().map_err(|e| e.at(7)).unwrap_err();
    /// assert!(matches!(err, Error::OutOfRange { input: Input::Vertex(1), value: 1e6, .. }));
    /// assert_eq!(
    ///     err.to_string(),
    ///     "triangle 7: a coordinate of v1 is 1000000, outside the accepted range [-4096, 4096]"
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn try_cast<T: Scalar>(&self) -> Result<Triangle<T>, Error> {
        let cast = |k: u8, p: Vec3<S>| p.try_cast::<T>().map_err(|e| e.of(Input::Vertex(k)));
        Ok(Triangle::new(
            cast(0, self.v0)?,
            cast(1, self.v1)?,
            cast(2, self.v2)?,
        ))
    }
}

/// What [`weld`] makes: the shared vertices, and three indices into them per triangle.
#[cfg(feature = "alloc")]
pub type Welded<S> = (Vec<Vec3<S>>, Vec<[u32; 3]>);

/// Shared vertices and index triples from a triangle soup (what most loaders give; what
/// [`CompactMesh::compact`](crate::CompactMesh::compact) takes): corners equal bit for bit
/// become one vertex, numbered in order of first appearance, and each triangle keeps its
/// corners' order, so the triangles rebuilt from the two are the input's, bit for bit. A
/// corner at `-0.0` stays apart from one at `0.0`: a triangle prepared from one can answer
/// with zeros of the other sign than one prepared from the other (the mesh's adjacency counts
/// them as one point all the same). `O(N log N)`: the corners sorted by value. Needs the
/// `alloc` feature.
///
/// Errors: [`Error::NaN`] naming the first triangle with a NaN coordinate (equal to nothing, it
/// could not be welded, nor prepared); [`Error::Full`] beyond `u32::MAX / 3` triangles (the
/// indices are `u32`).
///
/// ```
/// use ballcast::{Vec3, Triangle, import::weld};
/// let v = Vec3::new;
/// let quad = [
///     Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0)),
///     Triangle::new(v(0.0, 0.0, 0.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)),
/// ];
/// let (vertices, indices) = weld(&quad)?;
/// assert_eq!(vertices.len(), 4);
/// assert_eq!(indices, [[0, 1, 2], [0, 2, 3]]);
/// # Ok::<(), ballcast::Error>(())
/// ```
#[cfg(feature = "alloc")]
pub fn weld<S: Scalar>(triangles: &[Triangle<S>]) -> Result<Welded<S>, Error> {
    use core::cmp::Ordering;
    const MAX: usize = u32::MAX as usize / 3;
    if triangles.len() > MAX {
        return Err(Error::Full { capacity: MAX });
    }
    let corners: Vec<Vec3<S>> = triangles.iter().flat_map(Triangle::vertices).collect();
    let unordered = |c: &S| c.partial_cmp(c).is_none();
    if let Some(k) = corners
        .iter()
        .position(|p| p.to_array().iter().any(unordered))
    {
        return Err(Error::NaN {
            input: crate::Input::Vertex((k % 3) as u8),
            triangle: Some(k / 3),
        });
    }
    // Without NaN the order by value (x, then y, then z), then by the signs of zeros, then by
    // position, is total, and corners equal bit for bit form runs that begin with their first
    // appearance.
    let signs = |k: usize| corners[k].to_array().map(|c| c.to_f64().is_sign_negative());
    let by_value = |a: &usize, b: &usize| {
        let (p, q) = (corners[*a].to_array(), corners[*b].to_array());
        let mut axes = p.iter().zip(&q).map(|(x, y)| x.partial_cmp(y));
        let first = axes.find(|o| *o != Some(Ordering::Equal)).flatten();
        let value = first.unwrap_or(Ordering::Equal);
        value.then(signs(*a).cmp(&signs(*b))).then(a.cmp(b))
    };
    let mut sorted: Vec<usize> = (0..corners.len()).collect();
    sorted.sort_unstable_by(by_value);
    // Each corner's first corner equal bit for bit.
    let same = |a: usize, b: usize| corners[a] == corners[b] && signs(a) == signs(b);
    let mut first: Vec<usize> = (0..corners.len()).collect();
    for run in sorted.chunk_by(|&a, &b| same(a, b)) {
        for &k in run {
            first[k] = run[0];
        }
    }
    let (mut vertices, mut number) = (Vec::new(), Vec::with_capacity(corners.len()));
    for (k, &f) in first.iter().enumerate() {
        let n = if f == k {
            vertices.push(corners[k]);
            vertices.len() - 1
        } else {
            number[f]
        };
        number.push(n);
    }
    let indices = number
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]].map(|n| n as u32))
        .collect();
    Ok((vertices, indices))
}
