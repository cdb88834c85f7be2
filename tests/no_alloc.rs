//! Construction and queries allocate nothing: a counting global allocator sees zero allocations
//! while triangles are standardized and sweeps tested, in every scalar.

mod common;

use ballcast::{Scalar, StandardTriangle, Sweep, Triangle};
use common::v;
use fixed::types::{I16F16, I32F32};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

// Per thread: the test harness's own threads allocate while a test runs (more so on a loaded
// machine), and those allocations are not the library's. A `const` thread-local needs no
// allocation of its own, so the allocator can use it.
thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

/// Allocations made so far on this thread.
fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
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

#[test]
fn standardize_and_query_allocate_nothing_in_any_scalar() {
    for (name, run) in [
        ("f32", work::<f32> as fn() -> usize),
        ("f64", work::<f64>),
        ("I32F32", work::<I32F32>),
        ("I16F16", work::<I16F16>),
    ] {
        let before = allocations();
        let hits = run();
        let after = allocations();
        assert!(hits > 0, "{name}: the workload must exercise hits");
        assert_eq!(after - before, 0, "{name} allocated");
    }
    // The counter itself works: a Vec allocates.
    let before = allocations();
    let v = std::hint::black_box(vec![1u8; 16]);
    assert!(allocations() > before && v.len() == 16);
}
