//! Elliptically weighted averaging (Heckbert 1989; pbrt-v4 `MIPMap::EWA`): every texel inside the
//! ellipse spanned by the footprint's axes, weighted by a Gaussian of its elliptical distance.

use glam::{DVec4, Vec2, Vec4};

use crate::sampler::texel_fetch::{Addressing, fetch};
use crate::{Texel, Texture2d};

/// The Gaussian falloff `α`: `w(r²) = e^(−α r²) − e^(−α)`, zero on the ellipse's boundary.
const ALPHA: f32 = 2.0;

/// The most texels one level's EWA may visit (its bounding box): 256², far above what a clamped
/// footprint needs (about 70² at anisotropy 16) and small enough to bound a lookup's cost.
pub(crate) const MAX_TEXELS: i64 = 1 << 16;

/// The filter ellipse: two axes in uv units and the level of detail its minor axis selects.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ellipse {
    pub(crate) axis0: Vec2,
    pub(crate) axis1: Vec2,
    pub(crate) lod: f32,
}

/// The EWA-filtered premultiplied colour of `level` at `uv`; `None` when the ellipse's bounding
/// box holds more than [`MAX_TEXELS`] texels (a level too fine for the footprint).
///
/// The ellipse is scaled to the level's texels and widened by one texel in each direction (pbrt's
/// `+1`), so it always covers at least the bilinear neighbourhood; the caller clamps the
/// eccentricity, which bounds the texels visited.
pub(crate) fn filter<T: Texel>(
    level: &Texture2d<T>,
    uv: Vec2,
    ellipse: &Ellipse,
    addressing: &Addressing,
) -> Option<Vec4> {
    let (w, h) = level.size();
    let size = Vec2::new(w as f32, h as f32);
    // Texel space with texel centres at integers.
    let st = uv * size - Vec2::splat(0.5);
    let d0 = ellipse.axis0 * size;
    let d1 = ellipse.axis1 * size;
    let mut a = d0.y * d0.y + d1.y * d1.y + 1.0;
    let mut b = -2.0 * (d0.x * d0.y + d1.x * d1.y);
    let mut c = d0.x * d0.x + d1.x * d1.x + 1.0;
    let inv_f = 1.0 / (a * c - b * b * 0.25);
    a *= inv_f;
    b *= inv_f;
    c *= inv_f;
    let det = -b * b + 4.0 * a * c;
    let inv_det = 1.0 / det;
    let u_half = 2.0 * inv_det * (det * c).sqrt();
    let v_half = 2.0 * inv_det * (det * a).sqrt();
    if !(u_half.is_finite() && v_half.is_finite() && st.is_finite()) {
        return None;
    }
    let (s0, s1) = ((st.x - u_half).ceil(), (st.x + u_half).floor());
    let (t0, t1) = ((st.y - v_half).ceil(), (st.y + v_half).floor());
    let edge = (-ALPHA).exp();
    // Thousands of terms may be summed: accumulate in f64 so the normalised result keeps f32
    // accuracy (an f32 sum drifted 20 ε on a constant texture; found by the `sampling` fuzz target).
    let mut sum = DVec4::ZERO;
    let mut weight_sum = 0.0_f64;
    let (s0, s1, t0, t1) = (s0 as i64, s1 as i64, t0 as i64, t1 as i64);
    // Either range may be empty (a needle ellipse between texel centres); an empty column range
    // must not leave the row loop running over a huge row range (found by the `sampling` fuzz
    // target: 12 s for one lookup), so bound the rows and columns separately too.
    let columns = s1.saturating_sub(s0).saturating_add(1).max(0);
    let rows = t1.saturating_sub(t0).saturating_add(1).max(0);
    if columns > MAX_TEXELS || rows > MAX_TEXELS || columns.saturating_mul(rows) > MAX_TEXELS {
        return None;
    }
    for t in t0..=t1 {
        let tt = t as f32 - st.y;
        for s in s0..=s1 {
            let ss = s as f32 - st.x;
            let r2 = a * ss * ss + b * ss * tt + c * tt * tt;
            if r2 < 1.0 {
                // The form is positive definite, so `r2 ≥ 0`; rounding can make it negative
                // where `ss` and `tt` are huge (coordinates beyond i64 texel indices, whose
                // terms nearly cancel), and a weight of `e^(−α·r2)` then overflows to +∞ and
                // the average to NaN, i.e. transparent black (found by the `sampling` fuzz
                // target: uv ≈ 1.7e22 under clamp-to-edge). Clamped, the weight stays in
                // `[0, 1 − e^(−α)]`.
                let r2 = r2.max(0.0);
                let weight = f64::from((-ALPHA * r2).exp() - edge);
                sum += fetch(level, s, t, addressing).as_dvec4() * weight;
                weight_sum += weight;
            }
        }
    }
    Some(if weight_sum > 0.0 {
        (sum / weight_sum).as_vec4()
    } else {
        fetch(level, st.x.round() as i64, st.y.round() as i64, addressing)
    })
}
