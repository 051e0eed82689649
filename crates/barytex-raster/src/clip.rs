//! Homogeneous clipping (Sutherland–Hodgman in clip space, before the divide): against the near
//! plane `z = 0`, the far plane `z = w`, and a guard band `|x|, |y| ≤ G·w` that keeps the
//! fixed-point edge functions in range. Vertices carry their barycentric coordinates with
//! respect to the original triangle, so varyings are interpolated once, exactly, afterwards.

use glam::{Vec3, Vec4};

/// The guard band in NDC units: `|x|, |y| ≤ 64·w` after clipping (screen coordinates within
/// 32 viewports of the target).
pub(crate) const GUARD: f32 = 64.0;

/// A clipped vertex: clip position and barycentrics over the input triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ClipVertex {
    pub(crate) position: Vec4,
    pub(crate) bary: Vec3,
}

/// Signed distances to the planes (inside ≥ 0).
fn planes(p: Vec4) -> [f32; 6] {
    [
        p.z,               // near: z ≥ 0
        p.w - p.z,         // far: z ≤ w
        GUARD * p.w - p.x, // x ≤ G·w
        GUARD * p.w + p.x, // x ≥ −G·w
        GUARD * p.w - p.y,
        GUARD * p.w + p.y,
    ]
}

/// Whether the triangle needs no clipping.
pub(crate) fn inside(tri: &[Vec4; 3]) -> bool {
    tri.iter()
        .all(|&p| planes(p).iter().all(|&d| d >= 0.0) && p.w > 0.0)
}

/// Clips the triangle to the planes; the result is a convex polygon (possibly empty) in the
/// triangle's winding. `w > 0` holds for every output vertex (it follows from `z ≥ 0`,
/// `z ≤ w` together; a vertex with `w = 0` is on both, so it is kept only if `z = w = 0`,
/// which the caller drops as degenerate).
pub(crate) fn clip(tri: &[Vec4; 3]) -> Vec<ClipVertex> {
    let mut poly: Vec<ClipVertex> = tri
        .iter()
        .zip([Vec3::X, Vec3::Y, Vec3::Z])
        .map(|(&position, bary)| ClipVertex { position, bary })
        .collect();
    for plane in 0..6 {
        if poly.is_empty() {
            break;
        }
        let mut out = Vec::with_capacity(poly.len() + 1);
        for i in 0..poly.len() {
            let a = poly[i];
            let b = poly[(i + 1) % poly.len()];
            let (da, db) = (planes(a.position)[plane], planes(b.position)[plane]);
            if da >= 0.0 {
                out.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                out.push(ClipVertex {
                    position: a.position + (b.position - a.position) * t,
                    bary: a.bary + (b.bary - a.bary) * t,
                });
            }
        }
        poly = out;
    }
    poly
}
