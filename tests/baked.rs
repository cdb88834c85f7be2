//! The firmware example's flash scene (`embedded/src/baked.rs`, made by `cargo run --example
//! bake`) is exactly what the library prepares from its source (`embedded/src/ramp.rs`): every
//! baked triangle verifies bit for bit, with the active edges a `Scene` computes.

use ballcast::{Scene, Triangle, Vec3};
use fixed::types::I16F16;

#[path = "../embedded/src/baked.rs"]
mod baked;
#[path = "../embedded/src/ramp.rs"]
mod ramp;

#[test]
fn baked_scene_matches_its_source() {
    let mut scene: Scene<I16F16, { ramp::TRIANGLES }> = Scene::new();
    let sources = ramp::triangles().map(|t| {
        let v = t.map(|p| Vec3::new(p[0], p[1], p[2]).map(I16F16::from_num));
        Triangle::new(v[0], v[1], v[2])
    });
    for t in sources {
        scene.push(t).unwrap();
    }
    assert_eq!(baked::SCENE.len(), sources.len());
    for (i, (baked, source)) in baked::SCENE.iter().zip(&sources).enumerate() {
        assert_eq!(baked.to_parts().verify(source), Ok(()), "triangle {i}");
        assert_eq!(
            Some(baked),
            scene.triangle(i),
            "triangle {i}: features differ"
        );
    }
}
