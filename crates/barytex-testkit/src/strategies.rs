//! proptest strategies for the inputs that break numerical code.

use glam::{Vec2, Vec3};
use proptest::prelude::*;

/// Finite f32 uniformly in `[lo, hi]`.
pub fn bounded_f32(lo: f32, hi: f32) -> impl Strategy<Value = f32> + Clone {
    lo..=hi
}

/// Any f32 bit pattern: NaNs, infinities, subnormals, ±0 and everything else, uniformly by bits.
pub fn bits_f32() -> impl Strategy<Value = f32> + Clone {
    any::<u32>().prop_map(f32::from_bits)
}

/// Any *finite* f32, chosen by bit pattern (so tiny, subnormal and huge magnitudes are as likely
/// as ordinary ones).
pub fn finite_bits_f32() -> impl Strategy<Value = f32> + Clone {
    bits_f32().prop_filter("finite", |x| x.is_finite())
}

/// A `Vec2` with both components in `[lo, hi]`.
pub fn vec2_in(lo: f32, hi: f32) -> impl Strategy<Value = Vec2> + Clone {
    (lo..=hi, lo..=hi).prop_map(|(x, y)| Vec2::new(x, y))
}

/// A `Vec3` with all components in `[lo, hi]`.
pub fn vec3_in(lo: f32, hi: f32) -> impl Strategy<Value = Vec3> + Clone {
    (lo..=hi, lo..=hi, lo..=hi).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A `Vec2` from arbitrary bit patterns (NaN and infinities included).
pub fn vec2_bits() -> impl Strategy<Value = Vec2> + Clone {
    (bits_f32(), bits_f32()).prop_map(|(x, y)| Vec2::new(x, y))
}

/// `x` moved by `k` ulps (`k` may be negative); stays finite for finite `x` away from the
/// extremes.
#[must_use]
pub fn step_ulps(x: f32, k: i32) -> f32 {
    let mut y = x;
    for _ in 0..k.unsigned_abs() {
        y = if k > 0 { y.next_up() } else { y.next_down() };
    }
    y
}

/// `x` and a value within `max_ulps` ulps of it: near-equal perturbations.
pub fn near_equal_f32(max_ulps: i32) -> impl Strategy<Value = (f32, f32)> + Clone {
    (-1.0e3f32..1.0e3, -max_ulps..=max_ulps).prop_map(|(x, k)| (x, step_ulps(x, k)))
}

/// Twice the signed area over the longest edge squared: 0 for slivers, ~0.87 for equilateral.
#[must_use]
pub fn shape_quality(tri: [Vec2; 3]) -> f64 {
    let [a, b, c] = tri.map(|v| v.as_dvec2());
    let area2 = (b - a).perp_dot(c - a).abs();
    let longest = (b - a)
        .length_squared()
        .max((c - b).length_squared())
        .max((a - c).length_squared());
    if longest == 0.0 { 0.0 } else { area2 / longest }
}

/// A well-shaped triangle in `[-100, 100]²` (quality ≥ 0.05), either orientation.
pub fn triangle_2d() -> impl Strategy<Value = [Vec2; 3]> + Clone {
    [
        vec2_in(-100.0, 100.0),
        vec2_in(-100.0, 100.0),
        vec2_in(-100.0, 100.0),
    ]
    .prop_filter("well shaped", |t| shape_quality(*t) >= 0.05)
}

/// A triangle at a given scale and offset: `triangle_2d() · scale + offset`.
pub fn scaled_triangle_2d(scale: f32, offset: f32) -> impl Strategy<Value = [Vec2; 3]> + Clone {
    triangle_2d().prop_map(move |t| t.map(|v| v * (scale / 100.0) + Vec2::splat(offset)))
}

/// A near-degenerate triangle: `c` is a point of segment `ab` moved by a few ulps, so the exact
/// orientation is often zero and otherwise tiny.
pub fn near_degenerate_triangle_2d() -> impl Strategy<Value = [Vec2; 3]> + Clone {
    (
        vec2_in(-100.0, 100.0),
        vec2_in(-100.0, 100.0),
        0.0f32..=1.0,
        -3i32..=3,
        -3i32..=3,
    )
        .prop_map(|(a, b, t, kx, ky)| {
            let c = a + (b - a) * t;
            [a, b, Vec2::new(step_ulps(c.x, kx), step_ulps(c.y, ky))]
        })
}

/// A strictly convex, counter-clockwise quad `[x, y, z, w]` with corners on a perturbed ellipse
/// at angles at least 0.35 rad apart, in `[-10, 10]²`.
pub fn convex_quad() -> impl Strategy<Value = [Vec2; 4]> + Clone {
    (
        [0.35f32..1.2, 0.35f32..1.2, 0.35f32..1.2, 0.35f32..1.2],
        0.0f32..6.3,
        [0.7f32..1.3, 0.7f32..1.3, 0.7f32..1.3, 0.7f32..1.3],
        0.3f32..3.0,
        0.3f32..3.0,
        vec2_in(-5.0, 5.0),
    )
        .prop_filter_map(
            "angles span less than 2π",
            |(gaps, start, radii, sx, sy, c)| {
                let total: f32 = gaps[..3].iter().sum();
                if total + 0.35 >= core::f32::consts::TAU {
                    return None;
                }
                let mut angle = start;
                let mut quad = [Vec2::ZERO; 4];
                for i in 0..4 {
                    let r = radii[i];
                    quad[i] = c + Vec2::new(sx * r * angle.cos(), sy * r * angle.sin());
                    angle += gaps[i];
                }
                is_strictly_convex_ccw(quad).then_some(quad)
            },
        )
}

/// Whether the quad turns left at every corner, exactly (f64 cross products of f32 inputs are
/// exact enough for the margins these strategies produce, and the check is only a filter).
#[must_use]
pub fn is_strictly_convex_ccw(q: [Vec2; 4]) -> bool {
    (0..4).all(|i| {
        let a = q[i].as_dvec2();
        let b = q[(i + 1) % 4].as_dvec2();
        let c = q[(i + 2) % 4].as_dvec2();
        (b - a).perp_dot(c - b) > 0.0
    })
}

/// A parallelogram, or one corner moved by a few ulps from it: the case where thresholded
/// solvers switch branches.
pub fn near_parallelogram_quad() -> impl Strategy<Value = [Vec2; 4]> + Clone {
    (
        vec2_in(-10.0, 10.0),
        vec2_in(0.5, 5.0),
        vec2_in(-2.0, 2.0),
        -4i32..=4,
    )
        .prop_filter_map("convex", |(x, e, f, k)| {
            let f = Vec2::new(f.x, f.y.abs() + 0.5);
            let y = x + e;
            let w = x + f;
            let z = x + e + f;
            let quad = [x, y, Vec2::new(step_ulps(z.x, k), z.y), w];
            is_strictly_convex_ccw(quad).then_some(quad)
        })
}

/// Four non-coplanar points in `[-10, 10]³`: the case of Corollary 12 of A. Denisjuk's lecture
/// *Interpolacja i teksturowanie* (after Buss, *3D Computer Graphics*, 2003, Theorem IV.6):
/// bilinear interpolation of non-coplanar corners is one-to-one.
pub fn non_planar_quad_3d() -> impl Strategy<Value = [Vec3; 4]> + Clone {
    [
        vec3_in(-10.0, 10.0),
        vec3_in(-10.0, 10.0),
        vec3_in(-10.0, 10.0),
        vec3_in(-10.0, 10.0),
    ]
    .prop_filter("clearly non-planar", |q| {
        let [x, y, z, w] = q.map(|v| v.as_dvec3());
        let volume = (y - x).cross(z - x).dot(w - x).abs();
        let scale = (y - x).length().max((z - x).length()).max((w - x).length());
        volume > 0.05 * scale * scale * scale
    })
}

/// Affine weights: three finite values that sum to 1 exactly in f64 for the first two and close
/// to it for all three, in `[-3, 3]`.
pub fn affine_weights3() -> impl Strategy<Value = [f32; 3]> + Clone {
    (-3.0f32..3.0, -3.0f32..3.0).prop_map(|(a, b)| [a, b, 1.0 - a - b])
}

/// Convex weights: three non-negative values that sum to 1 (up to one rounding).
pub fn convex_weights3() -> impl Strategy<Value = [f32; 3]> + Clone {
    (0.0f32..1.0, 0.0f32..1.0).prop_map(|(a, b)| {
        let (a, b) = if a + b > 1.0 {
            (1.0 - a, 1.0 - b)
        } else {
            (a, b)
        };
        [a, b, (1.0 - a - b).max(0.0)]
    })
}
