//! The barycentrics and depth of the pixels of a covered run, two pixels per step where the
//! arithmetic allows it, bit for bit what the per-pixel evaluation gives.
//!
//! Per pixel the weights are `λⱼ = Eⱼ · (1 / area2)` (`Eⱼ` the edge value at the centre, an
//! integer) and the depth `z = f32(λ₀·d₀ + λ₁·d₁ + λ₂·d₂)`, summed left to right in f64. The
//! two-pixel path computes the same IEEE operations on both lanes of an SSE2 register: every
//! product and sum is rounded as the scalar one is, so the results are identical (no fused
//! multiply-add, no reassociation). It steps the edge values in f64 rather than i64: on a
//! covered centre `0 ≤ Eⱼ ≤ area2`, so when `area2 < 2⁵³` every value met along a run, and
//! each step `a·256` (below 2⁴⁰), is an integer that f64 holds exactly, and so are their sums.
//! Larger triangles take the scalar path on i64 values.

/// Below this, edge values of covered centres (`0 ≤ E ≤ area2`) are exact in f64.
#[cfg(target_arch = "x86_64")]
const EXACT_F64: i64 = 1 << 53;

/// Calls `pixel(k, λ, z)` for the pixels `k = 0..len` of a run whose edge values at the first
/// centre are `e` and change by `step` per pixel, with the weights `λ` (input order) and the
/// depth `z` of each: `λⱼ = eⱼ · inv_area`, `z = f32(Σ λⱼ·depthⱼ)`.
#[inline(always)]
pub(crate) fn for_each_run_pixel(
    e: [i64; 3],
    step: [i64; 3],
    area2: i64,
    inv_area: f64,
    depth: [f64; 3],
    len: usize,
    mut pixel: impl FnMut(usize, [f64; 3], f32),
) {
    #[cfg(target_arch = "x86_64")]
    if area2 < EXACT_F64 {
        pairs(e, step, inv_area, depth, len, pixel);
        return;
    }
    let _ = area2;
    let mut e = e;
    for k in 0..len {
        let lambda = e.map(|v| v as f64 * inv_area);
        pixel(k, lambda, depth_of(lambda, depth));
        for i in 0..3 {
            e[i] += step[i];
        }
    }
}

/// `f32(λ₀·d₀ + λ₁·d₁ + λ₂·d₂)`, summed left to right.
#[inline(always)]
pub(crate) fn depth_of(lambda: [f64; 3], depth: [f64; 3]) -> f32 {
    (lambda[0] * depth[0] + lambda[1] * depth[1] + lambda[2] * depth[2]) as f32
}

/// Two pixels per step in the lanes of SSE2 registers (lane 0 pixel `k`, lane 1 pixel `k + 1`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn pairs(
    e: [i64; 3],
    step: [i64; 3],
    inv_area: f64,
    depth: [f64; 3],
    len: usize,
    mut pixel: impl FnMut(usize, [f64; 3], f32),
) {
    use safe_arch::{add_m128d, m128d, set_splat_m128d};
    // Exact: |e| < 2⁵³ on covered centres, |step| < 2⁴⁰.
    let ef = e.map(|v| v as f64);
    let sf = step.map(|s| s as f64);
    let mut values: [m128d; 3] =
        core::array::from_fn(|i| m128d::from_array([ef[i], ef[i] + sf[i]]));
    let two_steps = sf.map(|s| set_splat_m128d(2.0 * s));
    let inv = set_splat_m128d(inv_area);
    let d = depth.map(set_splat_m128d);
    let mut k = 0;
    while k < len {
        let [(l0, z0), (l1, z1)] = lambda_depth_pair(values, inv, d);
        pixel(k, l0, z0);
        if k + 1 < len {
            pixel(k + 1, l1, z1);
        }
        for i in 0..3 {
            values[i] = add_m128d(values[i], two_steps[i]);
        }
        k += 2;
    }
}

/// The weights `λ = e · inv_area` and depths `z = f32(Σ λⱼ·dⱼ)` (summed left to right) of the
/// two pixels whose edge values `e` are the lanes of `e` (`inv_area` and the depths `d` in both
/// lanes): each lane's operations are those of [`depth_of`], rounded as they are.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) fn lambda_depth_pair(
    e: [safe_arch::m128d; 3],
    inv_area: safe_arch::m128d,
    d: [safe_arch::m128d; 3],
) -> [([f64; 3], f32); 2] {
    use safe_arch::{add_m128d, convert_to_m128_from_m128d, m128d, mul_m128d};
    let l = e.map(|v| mul_m128d(v, inv_area));
    let z = add_m128d(
        add_m128d(mul_m128d(l[0], d[0]), mul_m128d(l[1], d[1])),
        mul_m128d(l[2], d[2]),
    );
    let z = convert_to_m128_from_m128d(z).to_array();
    let l = l.map(m128d::to_array);
    [
        ([l[0][0], l[1][0], l[2][0]], z[0]),
        ([l[0][1], l[1][1], l[2][1]], z[1]),
    ]
}
