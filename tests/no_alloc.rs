//! Construction and queries allocate nothing: a counting global allocator sees zero allocations
//! while triangles are standardized and sweeps tested, in every scalar.

mod common;

use ballcast::{Scalar, StandardTriangle, Sweep, Triangle};
use common::v;
use fixed::types::{I16F16, I32F32};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Builds, standardizes and queries; returns the hit count so nothing is optimised away.
fn work<S: Scalar>() -> usize {
    let mut hits = 0;
    for i in 0..64 {
        let k = i as f64 / 8.0;
        let t = Triangle::new(v::<S>([0.0, 0.0, 0.0]), v([k, 0.5, 4.0]), v([4.0, -0.5, k]));
        let Ok(st) = StandardTriangle::new(&t) else {
            continue;
        };
        let s = Sweep::new(v([1.0, 5.0, 1.0]), v([1.5, -3.0, 1.0 + k]), S::ONE).unwrap();
        hits += st.face_collision(&s).is_some() as usize;
        hits += st.to_standard(v([k, k, k])).is_ok() as usize;
        let _ = Sweep::new(v([f64::NAN; 3]), v([0.0; 3]), S::ONE);
    }
    hits
}

// One test function: the counter is global, and tests in one binary run on parallel threads.
#[test]
fn standardize_and_query_allocate_nothing_in_any_scalar() {
    for (name, run) in [
        ("f32", work::<f32> as fn() -> usize),
        ("f64", work::<f64>),
        ("I32F32", work::<I32F32>),
        ("I16F16", work::<I16F16>),
    ] {
        let before = ALLOCATIONS.load(Ordering::SeqCst);
        let hits = run();
        let after = ALLOCATIONS.load(Ordering::SeqCst);
        assert!(hits > 0, "{name}: the workload must exercise hits");
        assert_eq!(after - before, 0, "{name} allocated");
    }
    // The counter itself works: a Vec allocates.
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let v = std::hint::black_box(vec![1u8; 16]);
    assert!(ALLOCATIONS.load(Ordering::SeqCst) > before && v.len() == 16);
}
