//! Shared inputs and references for barytex-uv's benchmarks and report: seeded surface points
//! and the central finite-difference Jacobian a caller without analytic derivatives would take.

use glam::{Vec2, Vec3};

use barytex_uv::{PositionMapping, UvJacobian};

use crate::seeded::XorShift;

/// Central differences of `m.uv` with step `h` (six evaluations), each wrapped across the
/// u/v seam by removing whole turns; `None` where any evaluation is.
#[must_use]
pub fn finite_difference_jacobian(
    m: &dyn PositionMapping,
    p: Vec3,
    n: Vec3,
    h: f32,
) -> Option<UvJacobian> {
    let uv = m.uv(p, n)?;
    let mut grads = [Vec3::ZERO; 2];
    for (i, e) in [Vec3::X, Vec3::Y, Vec3::Z].into_iter().enumerate() {
        let mut d = m.uv(p + h * e, n)? - m.uv(p - h * e, n)?;
        d -= d.round();
        let g: Vec2 = d / (2.0 * h);
        grads[0][i] = g.x;
        grads[1][i] = g.y;
    }
    Some(UvJacobian {
        uv,
        du: grads[0],
        dv: grads[1],
    })
}

/// `n` seeded `(position, normal)` pairs: on the unit sphere between ±1.3 rad latitude (off the
/// poles), or with `torus` on the torus R = 2, r = ½ about the y axis.
#[must_use]
pub fn surface_points(rng: &mut XorShift, n: usize, torus: bool) -> Vec<(Vec3, Vec3)> {
    (0..n)
        .map(|_| {
            let (st, ct) = rng.f32_in(0.0, std::f32::consts::TAU).sin_cos();
            if torus {
                let (sp, cp) = rng.f32_in(0.0, std::f32::consts::TAU).sin_cos();
                let ring = 2.0 + 0.5 * cp;
                (
                    Vec3::new(ring * st, 0.5 * sp, ring * ct),
                    Vec3::new(cp * st, sp, cp * ct),
                )
            } else {
                let lat = rng.f32_in(-1.3, 1.3);
                let n = Vec3::new(lat.cos() * st, lat.sin(), lat.cos() * ct);
                (n, n)
            }
        })
        .collect()
}
