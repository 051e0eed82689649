//! f64 reference implementations, and ports of peers' algorithms measured beside ours.

use glam::{DVec2, Vec2};

/// The bilinear map in f64.
#[must_use]
pub fn bilinear_f64([x, y, z, w]: [DVec2; 4], ab: DVec2) -> DVec2 {
    let (a, b) = (ab.x, ab.y);
    x * ((1.0 - a) * (1.0 - b)) + y * (a * (1.0 - b)) + z * (a * b) + w * ((1.0 - a) * b)
}

/// Newton's method on the bilinear map in f64, from `start`: the reference preimage of `p`.
///
/// Converges quadratically from a start near the answer; `None` when the Jacobian is singular
/// or it does not converge in 50 steps.
#[must_use]
pub fn inverse_bilinear_newton(p: DVec2, quad: [DVec2; 4], start: DVec2) -> Option<DVec2> {
    let [x, y, z, w] = quad;
    let mut ab = start;
    for _ in 0..50 {
        let r = bilinear_f64(quad, ab) - p;
        let d_alpha = (y - x) * (1.0 - ab.y) + (z - w) * ab.y;
        let d_beta = (w - x) * (1.0 - ab.x) + (z - y) * ab.x;
        let det = d_alpha.perp_dot(d_beta);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // Solve [d_alpha d_beta] · step = r by Cramer's rule (2×2).
        let step = DVec2::new(r.perp_dot(d_beta) / det, d_alpha.perp_dot(r) / det);
        ab -= step;
        if step.abs().max_element() <= 1e-17 * ab.abs().max_element().max(1.0) {
            return Some(ab);
        }
    }
    // Not converged to a step of 1e-17: accept only a tiny residual, relative to the quad.
    let size = quad
        .iter()
        .map(|c| (*c - quad[0]).length())
        .fold(0.0, f64::max);
    ((bilinear_f64(quad, ab) - p).length() <= 1e-14 * size).then_some(ab)
}

/// A port of the widely copied inverse-bilinear routine of Quilez, which pbrt-v4's
/// `InvertBilinear` follows: f32 throughout, and an absolute `|k2| < 1e-3` threshold that
/// switches to the linear (parallelogram) branch. Measured beside ours to show what the
/// threshold costs on small quads.
#[must_use]
pub fn quilez_inverse_bilinear_f32(p: Vec2, [a, b, c, d]: [Vec2; 4]) -> Vec2 {
    let e = b - a;
    let f = d - a;
    let g = a - b + c - d;
    let h = p - a;
    let k2 = g.perp_dot(f);
    let k1 = e.perp_dot(f) + h.perp_dot(g);
    let k0 = h.perp_dot(e);
    if k2.abs() < 1e-3 {
        let v = -k0 / k1;
        return Vec2::new((h.x * k1 + f.x * k0) / (e.x * k1 - g.x * k0), v);
    }
    let disc = k1 * k1 - 4.0 * k0 * k2;
    if disc < 0.0 {
        return Vec2::splat(-1.0);
    }
    let s = disc.sqrt();
    let ik2 = 0.5 / k2;
    let mut v = (-k1 - s) * ik2;
    let mut u = (h.x - f.x * v) / (e.x + g.x * v);
    if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
        v = (-k1 + s) * ik2;
        u = (h.x - f.x * v) / (e.x + g.x * v);
    }
    Vec2::new(u, v)
}
