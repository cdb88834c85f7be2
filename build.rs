//! Sets `ballcast_no_long_mul` on cores without a 32 × 32 → 64-bit multiply (Armv6-M such as the
//! Cortex-M0/M0+, and Armv8-M Baseline such as the Cortex-M23). There `I16F16` forms its exact
//! double-width products from four 32-bit multiplies instead of calling `__aeabi_lmul`; the
//! products are the same integers either way, so results are bit-identical on every target.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(ballcast_no_long_mul)");
    println!("cargo::rerun-if-env-changed=TARGET");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("thumbv8m.base") {
        println!("cargo::rustc-cfg=ballcast_no_long_mul");
    }
}
