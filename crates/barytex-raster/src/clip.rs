//! Homogeneous clipping (Sutherland–Hodgman in clip space, before the divide): against the near
//! plane `z = 0`, the far plane `z = w`, and a guard band `|x|, |y| ≤ G·w` that keeps the
//! fixed-point edge functions in range. Vertices carry their barycentric coordinates with
//! respect to the original triangle, so varyings are interpolated once, exactly, afterwards.

use glam::{Vec3, Vec4};

/// The guard band in NDC units: `|x|, |y| ≤ 64·w` after clipping (screen coordinates within
/// 32 viewports of the target).
pub(crate) const GUARD: f32 = 64.0;

/// A clipped vertex: clip position and barycentrics over the input triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ClipVertex {
    pub(crate) position: Vec4,
    pub(crate) bary: Vec3,
}

/// Signed distances to the planes (inside ≥ 0).
pub(crate) fn planes(p: Vec4) -> [f32; 6] {
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
///
/// Always inlined: called, it read the positions back from the caller's stack (4.6 % of a
/// raster-only draw of small triangles).
#[inline(always)]
pub(crate) fn inside(tri: &[Vec4; 3]) -> bool {
    // Without short-circuits: the 21 comparisons are cheaper than as many branches.
    let mut all = true;
    for &p in tri {
        for d in planes(p) {
            all &= d >= 0.0;
        }
        all &= p.w > 0.0;
    }
    all
}

/// The most vertices a clipped triangle can have: each of the six planes adds at most one.
pub(crate) const MAX_CLIPPED: usize = 9;

/// Clips the triangle to the planes into `out` and returns the vertex count; the result is a
/// convex polygon (possibly empty) in the triangle's winding. `w > 0` holds for every output
/// vertex (it follows from `z ≥ 0`, `z ≤ w` together; a vertex with `w = 0` is on both, so it
/// is kept only if `z = w = 0`, which the caller drops as degenerate). No allocation: this runs
/// once per triangle that crosses a plane.
pub(crate) fn clip(tri: &[Vec4; 3], out: &mut [ClipVertex; MAX_CLIPPED]) -> usize {
    let mut poly = [ClipVertex::default(); MAX_CLIPPED];
    for (slot, (&position, bary)) in
        poly.iter_mut()
            .zip(tri.iter().zip([Vec3::X, Vec3::Y, Vec3::Z]))
    {
        *slot = ClipVertex { position, bary };
    }
    let mut len = 3;
    for plane in 0..6 {
        if len == 0 {
            break;
        }
        let mut n = 0;
        for i in 0..len {
            let a = poly[i];
            let b = poly[(i + 1) % len];
            let (da, db) = (planes(a.position)[plane], planes(b.position)[plane]);
            if da >= 0.0 && n < MAX_CLIPPED {
                out[n] = a;
                n += 1;
            }
            if (da >= 0.0) != (db >= 0.0) && n < MAX_CLIPPED {
                let t = da / (da - db);
                out[n] = ClipVertex {
                    position: a.position + (b.position - a.position) * t,
                    bary: a.bary + (b.bary - a.bary) * t,
                };
                n += 1;
            }
        }
        poly = *out;
        len = n;
    }
    *out = poly;
    len
}
