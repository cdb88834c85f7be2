//! The heightfield bake: a terrain as a [`Heightfield`] in flash (two bytes a grid vertex and one
//! a cell, about 1.5 bytes a triangle), from a grey heightmap image or from heights of the
//! caller's own.
//!
//! A heightmap is a PNG image ([`png`]) of grey pixels, 8 or 16 bits a sample, one pixel a grid
//! vertex: pixel `(x, y)` (column `x` from the left, row `y` from the top) is vertex `(x, y)` of
//! the grid, at `origin + (x spacing, height × sample / full, y spacing)`, so the image's top
//! row is the terrain's edge of least z and a white pixel lies `height` above a black one, as
//! terrain editors export them. A fully transparent pixel (alpha zero) cuts a hole: every cell
//! it is a corner of is left out.

use super::source::{self, point};
use super::{Baked, Emit, Form, Stats};
use super::{LevelError, Problem, Reason};
use ballcast::heightfield::{HOLE, MAX_TRIANGLES};
use ballcast::{Heightfield, HeightfieldShape, Scalar, Vec3};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// A heightmap image loaded as a heightfield's heights.
#[derive(Clone, Debug, PartialEq)]
pub struct Heightmap {
    /// The file it came from.
    pub path: PathBuf,
    /// Cells along x: the image's width less one.
    pub columns: u32,
    /// Cells along z: the image's height less one.
    pub rows: u32,
    /// One sample a pixel, row by row from the top: black 0, white 65 535 (an 8-bit sample
    /// `k` widened to `k × 257`).
    pub samples: Vec<u16>,
    /// One per cell, row by row: whether it is a hole (a corner's pixel fully transparent).
    pub holes: Vec<bool>,
}

/// Where a heightmap lies in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// The grid's corner of least x and z (the image's top left pixel), at a black pixel's
    /// height.
    pub origin: [f64; 3],
    /// The cells' side.
    pub spacing: f64,
    /// How far above a black pixel a white one lies.
    pub height: f64,
}

/// The most pixels a heightmap may have: 4096 × 4096. A larger terrain's baked source would
/// run to hundreds of megabytes; refusing it before decoding also keeps a small file that
/// declares a huge image from taking the memory it asks for.
pub const MAX_PIXELS: u64 = 1 << 24;

/// Loads a grey PNG heightmap (1, 2, 4, 8 or 16 bits a sample, widened to 16; colour images
/// whose pixels are all grey are taken too, palettes expanded; a fully transparent pixel's
/// colour does not matter).
///
/// Errors: [`Problem::Io`], [`Problem::Malformed`] (not a PNG, or a broken one),
/// [`Problem::TooLarge`] beyond [`MAX_PIXELS`], [`Problem::Colour`] naming the first coloured
/// pixel, [`Problem::Heightfield`] for an image narrower or lower than two pixels.
pub fn load_heightmap(path: impl AsRef<Path>) -> Result<Heightmap, LevelError> {
    let path = path.as_ref();
    let fail = |p| LevelError::new(path, p);
    let file = std::fs::File::open(path).map_err(|e| fail(Problem::Io(e)))?;
    // Room for MAX_PIXELS of 16-bit colour and alpha.
    let limits = png::Limits { bytes: 1 << 27 };
    let mut decoder = png::Decoder::new_with_limits(std::io::BufReader::new(file), limits);
    decoder.set_transformations(png::Transformations::EXPAND);
    let malformed = |e: png::DecodingError| fail(Problem::Malformed(e.to_string()));
    let mut reader = decoder.read_info().map_err(malformed)?;
    let (width, height) = (reader.info().width, reader.info().height);
    let pixels = u64::from(width) * u64::from(height);
    if pixels > MAX_PIXELS {
        return Err(fail(Problem::TooLarge { width, height }));
    }
    if width < 2 || height < 2 {
        let (columns, rows) = (width.saturating_sub(1), height.saturating_sub(1));
        return Err(fail(Problem::Heightfield(
            ballcast::HeightfieldError::Empty { columns, rows },
        )));
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| fail(Problem::TooLarge { width, height }))?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf).map_err(malformed)?;
    let channels = info.color_type.samples();
    let wide = info.bit_depth == png::BitDepth::Sixteen;
    let sample = |k: usize| -> u16 {
        if wide {
            u16::from_be_bytes([buf[2 * k], buf[2 * k + 1]])
        } else {
            u16::from(buf[k]) * 257
        }
    };
    let alpha = matches!(
        info.color_type,
        png::ColorType::GrayscaleAlpha | png::ColorType::Rgba
    );
    let colours = if channels >= 3 { 3 } else { 1 };
    let pixels = pixels as usize;
    let mut samples = Vec::with_capacity(pixels);
    let mut clear = Vec::with_capacity(pixels);
    for p in 0..pixels {
        let first = p * channels;
        let grey = sample(first);
        let hole = alpha && sample(first + channels - 1) == 0;
        if !hole && (1..colours).any(|c| sample(first + c) != grey) {
            let (x, y) = ((p % width as usize) as u32, (p / width as usize) as u32);
            return Err(fail(Problem::Colour { x, y }));
        }
        samples.push(grey);
        clear.push(hole);
    }
    let (columns, rows) = (width - 1, height - 1);
    let w = width as usize;
    let holes = (0..rows as usize)
        .flat_map(|k| (0..columns as usize).map(move |i| (i, k)))
        .map(|(i, k)| [(i, k), (i + 1, k), (i, k + 1), (i + 1, k + 1)])
        .map(|corners| corners.iter().any(|&(i, k)| clear[k * w + i]))
        .collect();
    Ok(Heightmap {
        path: path.to_path_buf(),
        columns,
        rows,
        samples,
        holes,
    })
}

impl Heightmap {
    /// The grid in `S`: its shape and its heights. The height step is the scalar's nearest
    /// value to `height / 65 535`; in fixed point, where that one lies below it (white would
    /// not fit in 16 bits of steps), the next one up, and one step of the scalar where it
    /// rounds to zero. A sample `k` lies `k × height / 65 535` above black, rounded to the
    /// nearest step: within half a height step (plus the rounding of the origin's height to
    /// the scalar).
    ///
    /// Errors: [`Problem::Placement`] naming the value as given: a height or spacing that is
    /// not positive and finite, or an origin coordinate that is not finite; a spacing or (in
    /// floating point) a height step that rounds to zero in the scalar; a corner of the grid,
    /// black's or white's height beyond the scalar's range.
    #[allow(clippy::type_complexity)]
    pub fn grid<S: Scalar + Emit>(
        &self,
        placement: &Placement,
    ) -> Result<(HeightfieldShape<S>, Vec<i16>), LevelError> {
        let Placement {
            origin: [x, y, z],
            spacing,
            height,
        } = *placement;
        let fail = |what, value, reason| {
            let problem = Problem::Placement {
                what,
                value,
                scalar: S::NAME,
                reason,
            };
            Err(LevelError::new(&self.path, problem))
        };
        for (what, value) in [("height", height), ("spacing", spacing)] {
            if !(value > 0.0 && value.is_finite()) {
                return fail(what, value, Reason::NotPositive);
            }
        }
        for value in [x, y, z] {
            if !value.is_finite() {
                return fail("origin", value, Reason::NotFinite);
            }
        }
        let limit = S::LIMIT.to_f64();
        let far = |o: f64, n: u32| o.abs().max((o + f64::from(n) * spacing).abs());
        let corners = [(x, self.columns), (z, self.rows)];
        if let Some(value) = corners
            .map(|(o, n)| far(o, n))
            .into_iter()
            .find(|&v| v > limit)
        {
            return fail("grid's far corner", value, Reason::Beyond { limit });
        }
        if let Some(value) = [y, y + height].into_iter().find(|v| v.abs() > limit) {
            return fail("terrain's height", value, Reason::Beyond { limit });
        }
        if S::from_f64(spacing) == S::ZERO {
            return fail("spacing", spacing, Reason::Zero);
        }
        let step = height / 65535.0;
        let ratio = |unit: S| step / unit.to_f64();
        let mut unit = S::from_f64(step);
        let fixed = !S::PRECISION.relative;
        if fixed && (unit == S::ZERO || (65535.0 * ratio(unit)).round() > 65535.0) {
            // Within range (`height` is), so one step more is too.
            unit = unit + S::EPSILON;
        }
        if unit == S::ZERO {
            return fail("height step", step, Reason::Zero);
        }
        let r = ratio(unit);
        // White's height in steps, and the offset that centres the range on zero.
        let top = (65535.0 * r).round();
        let half = ((top + 1.0) / 2.0).floor();
        let heights = self
            .samples
            .iter()
            .map(|&k| ((f64::from(k) * r).round() - half) as i16)
            .collect();
        let shape = HeightfieldShape {
            origin: Vec3::new(x, y + half * unit.to_f64(), z).map(S::from_f64),
            spacing: S::from_f64(spacing),
            unit,
            columns: self.columns,
            rows: self.rows,
        };
        Ok((shape, heights))
    }

    /// Bakes the heightmap placed by `placement` as [`bake_heightfield`] does.
    ///
    /// Errors: those of [`grid`](Self::grid) and [`bake_heightfield`].
    pub fn bake<S: Scalar + Emit>(&self, placement: &Placement) -> Result<Baked, LevelError> {
        let columns = self.columns as usize;
        let hole = |i: u32, k: u32| self.holes[k as usize * columns + i as usize];
        let (shape, heights) = self.grid::<S>(placement)?;
        bake_heightfield(&self.path, shape, &heights, hole)
    }
}

/// Bakes the heightfield [`Heightfield::build`] makes of `shape`, `heights` and `hole` into
/// source defining `HEIGHTS`, `CELLS` and `HEIGHTFIELD: Heightfield<'static, S>`; `path` names
/// where the heights came from in the source's header. Check the statics in a test against
/// the run-time build (`Heightfield` compares as `==`).
///
/// Errors: [`Problem::Heightfield`] when the build refuses (the grid beyond the scalar's range,
/// a height step that rounds to zero in it, sizes that do not match, a degenerate cell).
pub fn bake_heightfield<S: Scalar + Emit>(
    path: &Path,
    shape: HeightfieldShape<S>,
    heights: &[i16],
    hole: impl Fn(u32, u32) -> bool,
) -> Result<Baked, LevelError> {
    // None for a grid too large, which the build refuses before it needs the bytes.
    let cells = (shape.columns as usize).saturating_mul(shape.rows as usize);
    let mut bytes = vec![0u8; if cells <= MAX_TRIANGLES / 2 { cells } else { 0 }];
    let field = Heightfield::build(shape, heights, hole, &mut bytes)
        .map_err(|e| LevelError::new(path, Problem::Heightfield(e)))?;
    let cells = field.cells();
    let holes = cells.iter().filter(|&&b| b & HOLE != 0).count();
    let [lo, hi] = field.bounds();
    let far = [0, shape.columns].map(|i| {
        [0, shape.rows].map(|k| {
            [lo, hi].map(|h| {
                let corner = Vec3::new(
                    shape.origin.x + S::from_f64(f64::from(i)).mul(shape.spacing),
                    shape.origin.y + S::from_f64(f64::from(h)).mul(shape.unit),
                    shape.origin.z + S::from_f64(f64::from(k)).mul(shape.spacing),
                );
                corner.abs().max_element().to_f64()
            })
        })
    });
    let stats = Stats {
        scalar: S::NAME,
        form: Form::Heightfield {
            columns: shape.columns,
            rows: shape.rows,
            holes,
        },
        triangles: field.len(),
        skipped: Vec::new(),
        skipped_origins: Vec::new(),
        two_sided: 0,
        bytes: size_of_val(field.heights()) + size_of_val(cells),
        extent: far
            .iter()
            .flatten()
            .flatten()
            .fold(0.0, |m: f64, &c| m.max(c)),
    };
    let s = S::NAME;
    let items = "Heightfield, HeightfieldShape, Vec3";
    let mut o = source::header::<S>(path, &stats, items, false);
    let doc = "The heights, row by row (x fastest), in steps of the shape's unit.";
    let width = shape.columns as usize + 1;
    source::array(
        &mut o,
        doc,
        "HEIGHTS",
        "i16",
        field.heights(),
        width.min(16),
    );
    let doc = "The cells' bytes, row by row: active edges and holes.";
    source::array(&mut o, doc, "CELLS", "u8", cells, 16);
    let _ = writeln!(
        o,
        "/// The heightfield, in flash.\npub static HEIGHTFIELD: Heightfield<'static, {s}> = Heightfield::from_parts(\n    \
         HeightfieldShape {{ origin: v({}), spacing: s({}), unit: s({}), columns: {}, rows: {} }},\n    \
         &HEIGHTS,\n    &CELLS,\n    {:?},\n    {},\n);",
        point(shape.origin),
        shape.spacing.bits(),
        shape.unit.bits(),
        shape.columns,
        shape.rows,
        field.bounds(),
        field.class()
    );
    Ok(Baked { source: o, stats })
}
