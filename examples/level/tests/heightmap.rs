//! Heightmap images as heightfields: how pixels become heights and holes, and every bad image
//! refused with the file and the problem named.

use ballcast::HeightfieldError;
use ballcast::fixed::types::I16F16;
use ballcast_level::{LevelError, Placement, Problem, Reason, load_heightmap};
use std::path::{Path, PathBuf};

/// A file in the temporary directory, removed when dropped.
struct Temp(PathBuf);

impl Temp {
    fn new(name: &str) -> Self {
        Temp(std::env::temp_dir().join(format!("ballcast-level-{}-{name}", std::process::id())))
    }
}

impl AsRef<Path> for Temp {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Writes a PNG of `width` × `height` pixels of `samples` (big-endian for 16 bits) into the
/// temporary directory.
fn png(
    name: &str,
    (width, height): (u32, u32),
    color: png::ColorType,
    depth: png::BitDepth,
    samples: &[u8],
) -> Temp {
    let path = Temp::new(name);
    let file = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
    let mut e = png::Encoder::new(file, width, height);
    e.set_color(color);
    e.set_depth(depth);
    e.write_header().unwrap().write_image_data(samples).unwrap();
    path
}

fn problem<T>(r: Result<T, LevelError>) -> Problem {
    match r {
        Ok(_) => panic!("accepted"),
        Err(e) => e.problem,
    }
}

const GREY: png::ColorType = png::ColorType::Grayscale;
const EIGHT: png::BitDepth = png::BitDepth::Eight;

#[test]
fn an_8_bit_map_reads_as_the_16_bit_one_times_257() {
    let eight = [0u8, 1, 127, 128, 254, 255];
    let sixteen: Vec<u8> = eight
        .iter()
        .flat_map(|&k| (u16::from(k) * 257).to_be_bytes())
        .collect();
    let a = png("a8.png", (3, 2), GREY, EIGHT, &eight);
    let b = png("a16.png", (3, 2), GREY, png::BitDepth::Sixteen, &sixteen);
    let (a, b) = (load_heightmap(a).unwrap(), load_heightmap(b).unwrap());
    assert_eq!((a.columns, a.rows), (2, 1));
    assert_eq!(a.samples, b.samples);
    assert_eq!(
        (a.samples[0], a.samples[2], a.samples[5]),
        (0, 127 * 257, 65535)
    );
    assert_eq!(a.holes, [false, false]);
}

#[test]
fn black_lies_at_the_origin_and_white_the_height_above() {
    let map = load_heightmap(png("bw.png", (2, 2), GREY, EIGHT, &[0, 255, 255, 0])).unwrap();
    let placement = Placement {
        origin: [1.0, -2.0, 3.0],
        spacing: 0.5,
        height: 6.0,
    };
    let mut cells = [0u8; 1];
    let (shape, heights) = map.grid::<f64>(&placement).unwrap();
    let field = ballcast::Heightfield::build(shape, &heights, |_, _| false, &mut cells).unwrap();
    let (black, white) = (field.vertex(0, 0).unwrap(), field.vertex(1, 0).unwrap());
    assert!((black.y + 2.0).abs() < 1e-12 && (white.y - 4.0).abs() < 1e-12);
    assert_eq!((black.x, black.z, white.x), (1.0, 3.0, 1.5));
    assert_eq!(field.vertex(0, 1).unwrap().z, 3.5);
}

/// A fully transparent pixel cuts every cell it is a corner of: four round an inner pixel, two
/// along an edge, one at a corner; a half transparent one cuts nothing.
#[test]
fn transparent_pixels_cut_the_cells_around_them() {
    let (w, h) = (5u32, 4u32);
    let mut samples = vec![[100u8, 255]; (w * h) as usize];
    let clear = |x: u32, y: u32| (y * w + x) as usize;
    samples[clear(2, 1)][1] = 0; // inner: cells (1, 0), (2, 0), (1, 1), (2, 1)
    samples[clear(0, 3)][1] = 0; // corner: cell (0, 2)
    samples[clear(4, 2)][1] = 0; // edge: cells (3, 1), (3, 2)
    samples[clear(0, 0)][1] = 128; // half transparent: no hole
    let flat: Vec<u8> = samples.concat();
    let path = png(
        "holes.png",
        (w, h),
        png::ColorType::GrayscaleAlpha,
        EIGHT,
        &flat,
    );
    let map = load_heightmap(path).unwrap();
    let holes: Vec<(u32, u32)> = (0..map.holes.len() as u32)
        .filter(|&c| map.holes[c as usize])
        .map(|c| (c % 4, c / 4))
        .collect();
    assert_eq!(
        holes,
        [(1, 0), (2, 0), (1, 1), (2, 1), (3, 1), (0, 2), (3, 2)]
    );
}

#[test]
fn a_grey_colour_image_is_taken_a_coloured_one_refused_at_its_pixel() {
    let mut rgb: Vec<u8> = [10u8, 20, 30, 40, 50, 60]
        .iter()
        .flat_map(|&k| [k; 3])
        .collect();
    let grey = png("rgb.png", (3, 2), png::ColorType::Rgb, EIGHT, &rgb);
    let plain = png("grey.png", (3, 2), GREY, EIGHT, &[10, 20, 30, 40, 50, 60]);
    assert_eq!(
        load_heightmap(grey).unwrap().samples,
        load_heightmap(plain).unwrap().samples
    );
    rgb[3 * 5 + 1] = 51; // pixel (2, 1): green off by one
    let coloured = png("red.png", (3, 2), png::ColorType::Rgb, EIGHT, &rgb);
    let e = load_heightmap(&coloured).unwrap_err();
    assert!(matches!(e.problem, Problem::Colour { x: 2, y: 1 }), "{e}");
    assert!(
        e.to_string().starts_with(&coloured.0.display().to_string()),
        "{e}"
    );
    // A fully transparent pixel is a hole: its colour does not matter.
    let rgba: Vec<u8> = [10u8, 20, 30, 40]
        .iter()
        .flat_map(|&k| [k, k, k, 255])
        .collect();
    let mut rgba = rgba;
    rgba[4..8].copy_from_slice(&[200, 0, 0, 0]);
    let clear = png("clear.png", (2, 2), png::ColorType::Rgba, EIGHT, &rgba);
    assert_eq!(load_heightmap(clear).unwrap().holes, [true]);
}

#[test]
fn broken_and_missing_files_are_errors_not_panics() {
    let garbage = Temp::new("x.png");
    std::fs::write(&garbage, b"not a png at all").unwrap();
    assert!(matches!(
        problem(load_heightmap(&garbage)),
        Problem::Malformed(_)
    ));
    // A real image cut short in its data.
    let whole = std::fs::read(png("cut.png", (40, 40), GREY, EIGHT, &[7; 1600])).unwrap();
    std::fs::write(&garbage, &whole[..whole.len() - 30]).unwrap();
    assert!(matches!(
        problem(load_heightmap(&garbage)),
        Problem::Malformed(_)
    ));
    assert!(matches!(
        problem(load_heightmap(garbage.0.with_extension("none.png"))),
        Problem::Io(_)
    ));
}

#[test]
fn a_single_row_or_column_is_refused() {
    for size in [(3, 1), (1, 3)] {
        let path = png("line.png", size, GREY, EIGHT, &[1, 2, 3]);
        let p = problem(load_heightmap(path));
        assert!(
            matches!(p, Problem::Heightfield(HeightfieldError::Empty { .. })),
            "{p:?}"
        );
    }
}

/// Heights below I16F16's resolution: a terrain of 0.25, 0.5 or 4.0001 is as tall as asked
/// (to half a step of the scalar), its step one or more of I16F16's, its grey levels rounded to it.
#[test]
fn a_short_heightmap_in_i16f16_is_as_tall_as_asked() {
    let path = png("ramp.png", (3, 2), GREY, EIGHT, &[0, 128, 255, 255, 64, 0]);
    let map = load_heightmap(path).unwrap();
    let lsb = I16F16::DELTA.to_num::<f64>();
    for height in [0.25, 0.5, 4.0001] {
        let placement = Placement {
            origin: [0.0; 3],
            spacing: 1.0,
            height,
        };
        let (shape, heights) = map.grid::<I16F16>(&placement).unwrap();
        let mut cells = [0u8; 2];
        let build = ballcast::Heightfield::build(shape, &heights, |_, _| false, &mut cells);
        let field = build.unwrap();
        let step = shape.unit.to_num::<f64>();
        for (k, &sample) in map.samples.iter().enumerate() {
            let (i, row) = (k as u32 % 3, k as u32 / 3);
            let y = field.vertex(i, row).unwrap().y.to_num::<f64>();
            let asked = f64::from(sample) / 65535.0 * height;
            assert!(
                (y - asked).abs() <= step / 2.0 + lsb,
                "{height} {k}: {y} {asked}"
            );
        }
    }
}

/// In `f32` every height is the image's to a few parts in 10^7 of the terrain's height: the
/// step is `H / 65 535` to `f32`'s precision and each sample a whole number of steps.
#[test]
fn an_f32_heightmap_keeps_every_grey_level() {
    let samples: Vec<u8> = (0..=255).collect();
    let map = load_heightmap(png("levels.png", (16, 16), GREY, EIGHT, &samples)).unwrap();
    let placement = Placement {
        origin: [0.0, -3.0, 0.0],
        spacing: 1.0,
        height: 4.0,
    };
    let (shape, heights) = map.grid::<f32>(&placement).unwrap();
    let mut cells = [0u8; 225];
    let field = ballcast::Heightfield::build(shape, &heights, |_, _| false, &mut cells).unwrap();
    for (k, &sample) in map.samples.iter().enumerate() {
        let y = field.vertex(k as u32 % 16, k as u32 / 16).unwrap().y;
        let asked = -3.0 + f64::from(sample) / 65535.0 * 4.0;
        assert!((f64::from(y) - asked).abs() < 1.2e-6, "{k}: {y} {asked}");
    }
}

/// A placement the scalar cannot hold, each error naming the value as given: a height that is
/// not positive and finite, a spacing that rounds to zero, cells of 300 over 32 cells (past
/// I16F16's range), a white 2.2e9 high (a debug build's overflow, once), an origin that is
/// not finite.
#[test]
fn a_placement_the_scalar_cannot_hold_is_refused() {
    let map = load_heightmap(format!("{}/../data/hills.png", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let flat = Placement {
        origin: [0.0; 3],
        spacing: 1.0,
        height: 4.0,
    };
    let refused = |p: Placement| match problem(map.bake::<I16F16>(&p)) {
        Problem::Placement {
            what,
            value,
            reason,
            ..
        } => (what, value, reason),
        other => panic!("{other:?}"),
    };
    for height in [0.0, -1.0, f64::INFINITY] {
        let p = Placement { height, ..flat };
        assert_eq!(refused(p), ("height", height, Reason::NotPositive));
    }
    let limit = Reason::Beyond { limit: 4096.0 };
    let tall = Placement {
        height: 2.2e9,
        ..flat
    };
    assert_eq!(refused(tall), ("terrain's height", 2.2e9, limit));
    let fine = Placement {
        spacing: 1e-9,
        ..flat
    };
    assert_eq!(refused(fine), ("spacing", 1e-9, Reason::Zero));
    let wide = Placement {
        spacing: 300.0,
        ..flat
    };
    assert_eq!(refused(wide), ("grid's far corner", 9600.0, limit));
    let lost = Placement {
        origin: [0.0, f64::NAN, 0.0],
        ..flat
    };
    assert!(matches!(refused(lost), ("origin", _, Reason::NotFinite)));
}

/// An image that declares more than `MAX_PIXELS` is refused from its header, before any of it
/// is decoded or allocated (here a header alone declaring 30 000 × 30 000).
#[test]
fn a_huge_image_is_refused_from_its_header() {
    let path = Temp::new("huge.png");
    let file = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
    let mut e = png::Encoder::new(file, 30_000, 30_000);
    e.set_color(GREY);
    e.set_depth(EIGHT);
    let mut w = e.write_header().unwrap();
    // The start of a data chunk, which the decoder reads up to before it reports the header.
    w.write_chunk(png::chunk::IDAT, &[0x78, 0x9c]).unwrap();
    drop(w);
    let p = problem(load_heightmap(&path));
    assert!(
        matches!(
            p,
            Problem::TooLarge {
                width: 30_000,
                height: 30_000
            }
        ),
        "{p:?}"
    );
}
