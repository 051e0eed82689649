//! Per-triangle geometry shared by the embeddings, LSCM, ARAP and the distortion measures.

use glam::{DVec2, DVec3};

/// A triangle whose doubled area is below this fraction of its longest edge squared is treated
/// as degenerate (zero area): its angles and cotangents are not meaningful in floating point.
/// `2A / ℓ² = 1e-12` is a needle whose smallest angle is about 1e-12 radians.
pub(crate) const DEGENERATE_RATIO: f64 = 1e-12;

/// Whether the triangle `p` has (numerically) zero area, or a non-finite area.
pub(crate) fn is_degenerate(p: [DVec3; 3]) -> bool {
    let e = [p[1] - p[0], p[2] - p[1], p[0] - p[2]];
    let longest = e.iter().map(|e| e.length_squared()).fold(0.0, f64::max);
    let doubled_area = e[0].cross(-e[2]).length();
    !(doubled_area.is_finite() && longest.is_finite() && doubled_area > DEGENERATE_RATIO * longest)
}

/// The triangle laid flat in its own plane, orientation kept: `q0 = 0`, `q1` on the +x axis,
/// `q2` above it (y > 0 for a non-degenerate triangle).
pub(crate) fn flatten(p: [DVec3; 3]) -> [DVec2; 3] {
    let e1 = p[1] - p[0];
    let e2 = p[2] - p[0];
    let len = e1.length();
    let x = if len > 0.0 { e1 / len } else { DVec3::X };
    let n = e1.cross(e2);
    let y = n.cross(x).normalize_or_zero();
    [
        DVec2::ZERO,
        DVec2::new(len, 0.0),
        DVec2::new(e2.dot(x), e2.dot(y)),
    ]
}

/// Doubled signed area of a 2-D triangle (floating point, for measures, never for signs).
pub(crate) fn doubled_area_2d(q: [DVec2; 3]) -> f64 {
    (q[1] - q[0]).perp_dot(q[2] - q[0])
}

/// The Jacobian of the affine map taking the flat triangle `q` to the uv triangle `u`, as
/// columns `(∂uv/∂x, ∂uv/∂y)`; `None` for a degenerate `q`.
pub(crate) fn jacobian(q: [DVec2; 3], u: [DVec2; 3]) -> Option<glam::DMat2> {
    let x = glam::DMat2::from_cols(q[1] - q[0], q[2] - q[0]);
    let det = x.determinant();
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let uvm = glam::DMat2::from_cols(u[1] - u[0], u[2] - u[0]);
    Some(uvm * x.inverse())
}

/// The singular values `(σ1, σ2)`, `σ1 ≥ σ2 ≥ 0`, of a 2×2 matrix, and the sign of its
/// determinant, in closed form (Blinn, "Consider the lowly 2×2 matrix", *IEEE CG&A* 1996).
pub(crate) fn singular_values(j: glam::DMat2) -> (f64, f64) {
    let (a, c) = (j.x_axis.x, j.x_axis.y);
    let (b, d) = (j.y_axis.x, j.y_axis.y);
    let e = 0.5 * (a + d);
    let f = 0.5 * (a - d);
    let g = 0.5 * (c + b);
    let h = 0.5 * (c - b);
    let q = e.hypot(h);
    let r = f.hypot(g);
    (q + r, (q - r).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flatten_keeps_lengths_and_orientation() {
        let p = [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(2.0, 2.0, 4.0),
            DVec3::new(1.0, 5.0, 3.0),
        ];
        let q = flatten(p);
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let d3 = (p[i] - p[j]).length();
            let d2 = (q[i] - q[j]).length();
            assert!((d3 - d2).abs() <= 1e-14 * d3, "{d3} {d2}");
        }
        assert!(q[2].y > 0.0);
        assert!(!is_degenerate(p));
        assert!(is_degenerate([p[0], p[1], p[0] + 2.0 * (p[1] - p[0])]));
    }

    #[test]
    fn singular_values_of_a_scaled_rotation() {
        let j =
            glam::DMat2::from_angle(0.7) * glam::DMat2::from_diagonal(glam::DVec2::new(3.0, 0.5));
        let (s1, s2) = singular_values(j);
        assert!(
            (s1 - 3.0).abs() < 1e-14 && (s2 - 0.5).abs() < 1e-14,
            "{s1} {s2}"
        );
    }
}
