//! What the unit tests share besides their random stream: one test per scalar for each
//! property, instantiated by [`per_scalar`].

/// One test module per property, with a test per scalar: `per_scalar!(a, b)` runs
/// `a::<f32>()`, `a::<f64>()`, `a::<I16F16>()` and `a::<I32F32>()` as `a::f32` and so on (the
/// integration tests' `tests/meshes` has the same for theirs).
macro_rules! per_scalar {
    ($($test:ident),* $(,)?) => {$(
        mod $test {
            #[test]
            fn f32() {
                super::$test::<f32>()
            }
            #[test]
            fn f64() {
                super::$test::<f64>()
            }
            #[test]
            fn i16f16() {
                super::$test::<fixed::types::I16F16>()
            }
            #[test]
            fn i32f32() {
                super::$test::<fixed::types::I32F32>()
            }
        }
    )*};
}
pub(crate) use per_scalar;
