//! Which instruction-set build of the fragment loop a draw runs.
//!
//! The loop that shades a piece's pixels in pairs (shaders with [`Shader::PAIRS`]) is compiled
//! twice for the common state (replace blending, depth written, no mask; the other states have
//! the baseline build only, which keeps compile time down): for the x86-64 baseline (SSE2) and
//! for AVX2 + FMA (x86-64-v3, whose three-operand VEX forms, `roundss` and the like need fewer
//! instructions), chosen per piece at run time
//! through `pulp`'s `V3` token (the workspace forbids `unsafe`, which calling a
//! `#[target_feature]` function directly needs). Rust never contracts `a * b + c` into a fused
//! multiply-add on its own, so both builds compute the same IEEE operations in the same order:
//! the same image, bit for bit (tested with the AVX2 build allowed and forbidden). Unlit
//! Avocado at 1024², one thread: 20.0–20.5 → 18.7 ms a draw, 226 → 188 M instructions.
//!
//! [`Shader::PAIRS`]: crate::Shader::PAIRS

use core::sync::atomic::{AtomicBool, Ordering};

/// Whether draws may run the AVX2 build (when the processor has it).
static AVX2_ALLOWED: AtomicBool = AtomicBool::new(true);

/// Allows (the default) or forbids the AVX2 + FMA build of the paired fragment loop, for every
/// draw of the process from the next piece on. Forbidding it changes speed only, never an
/// image: for comparing the builds, or for timing the baseline on a machine that has AVX2.
///
/// ```
/// barytex_raster::allow_avx2(false);
/// assert!(!barytex_raster::avx2_in_use());
/// barytex_raster::allow_avx2(true);
/// ```
pub fn allow_avx2(allowed: bool) {
    AVX2_ALLOWED.store(allowed, Ordering::Relaxed);
}

/// Whether draws run the AVX2 + FMA build: allowed ([`allow_avx2`]) and the processor has
/// AVX2, FMA and the rest of x86-64-v3 (always `false` on other architectures).
#[must_use]
pub fn avx2_in_use() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        v3().is_some()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The token that runs code compiled for x86-64-v3, when allowed and available (the
/// processor's features are detected once, then cached by `pulp`).
#[cfg(target_arch = "x86_64")]
#[inline]
pub(crate) fn v3() -> Option<pulp::x86::V3> {
    if AVX2_ALLOWED.load(Ordering::Relaxed) {
        pulp::x86::V3::try_new()
    } else {
        None
    }
}
