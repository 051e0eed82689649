//! Views through portals and mirrors: the camera moved by a portal's transform, with an oblique
//! near plane at the portal's plane, and the checks that decide which portals a view sees.
//!
//! Seen through a portal with transform `M`, a world point `q` appears at `M·q`: the view
//! through it is the scene drawn with the view matrix `V·M` (Luebke and Georges, "Portals and
//! Mirrors: Simple, Fast Evaluation of Potentially Visible Sets", I3D 1995). What lies between
//! the eye and the portal's plane in that view must not show, so the projection's near plane is
//! moved onto the portal's plane (E. Lengyel, "Oblique View Frustum Depth Projection and
//! Clipping", *Journal of Game Development* 1(2), 2005): the rasterizer's homogeneous clipping
//! against `z ≥ 0` then cuts exactly there. A mirror's `M` has a negative determinant, which
//! turns every triangle's winding on screen: the view swaps its front-face rule.

use barytex_gltf::Portal;
use barytex_raster::{Fragment, Shader};
use glam::{Mat4, Vec3, Vec4};

use crate::RenderCamera;

/// A portal ready to draw: its polygon as a triangle fan, its plane, its transform.
#[derive(Clone, Debug)]
pub(crate) struct PreparedPortal {
    pub(crate) polygon: Vec<Vec3>,
    /// Index triples of the fan from vertex 0 (the polygon is convex).
    pub(crate) fan: Vec<u32>,
    /// `(n, d)`: `n·p + d > 0` in front.
    pub(crate) plane: Vec4,
    pub(crate) transform: Mat4,
    pub(crate) tint: Vec4,
    /// The polygon's largest bounding-box side (for tolerances).
    pub(crate) extent: f32,
}

/// The portals that pass [`Portal::check`], and how many did not (they are not drawn).
pub(crate) fn prepare_portals(portals: &[Portal]) -> (Vec<PreparedPortal>, usize) {
    let mut out = Vec::new();
    for portal in portals {
        let Ok(plane) = portal.check() else { continue };
        let n = portal.polygon.len() as u32;
        let (lo, hi) = portal.polygon.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), &v| (lo.min(v), hi.max(v)),
        );
        out.push(PreparedPortal {
            polygon: portal.polygon.clone(),
            fan: (1..n.saturating_sub(1))
                .flat_map(|k| [0, k, k + 1])
                .collect(),
            plane,
            transform: portal.transform,
            tint: portal.tint,
            extent: (hi - lo).max_element(),
        });
    }
    let skipped = portals.len() - out.len();
    (out, skipped)
}

/// One view of the scene: the camera's, or one through a chain of portals.
#[derive(Clone, Copy, Debug)]
pub(crate) struct View {
    /// World → view.
    pub(crate) view: Mat4,
    pub(crate) view_projection: Mat4,
    /// The eye in world space (where the scene is seen from, through the portals).
    pub(crate) eye: Vec3,
    pub(crate) forward: Vec3,
    /// Whether the portals' transforms mirror (an odd number of reflections).
    pub(crate) flips: bool,
    /// In a view through a portal, the world plane beyond which the view starts (`near·p > 0`
    /// is drawn): the portal's plane as the transform sees it.
    pub(crate) near: Option<Vec4>,
    /// Portals passed through to get here.
    pub(crate) level: u32,
}

impl View {
    /// The camera's own view.
    pub(crate) fn camera(camera: &RenderCamera) -> Self {
        Self {
            view: camera.view,
            view_projection: camera.projection * camera.view,
            eye: camera.eye,
            forward: camera.forward(),
            flips: false,
            near: None,
            level: 0,
        }
    }

    /// Whether `portal` can show anything in this view: the eye strictly in front of it, and
    /// (through a portal) some of it beyond this view's near plane — the portal this view came
    /// through, and a target portal's way back, lie on it and are left out.
    pub(crate) fn sees(&self, portal: &PreparedPortal) -> bool {
        let in_front = portal.plane.dot(self.eye.extend(1.0)) > 0.0;
        let beyond = self.near.is_none_or(|near| {
            let scale = near.truncate().length();
            let tolerance = 1e-4 * portal.extent * scale;
            portal
                .polygon
                .iter()
                .any(|p| near.dot(p.extend(1.0)) > tolerance)
        });
        in_front && beyond
    }

    /// The view through `portal`, with `projection` (the camera's) made oblique at the portal's
    /// plane; `None` where that projection degenerates (the eye on the plane, a far plane the
    /// portal's plane does not cut in front of the eye, non-finite matrices).
    pub(crate) fn through(&self, portal: &PreparedPortal, projection: Mat4) -> Option<Self> {
        let view = self.view * portal.transform;
        // The portal plane in this view's eye space, visible side positive: what shows through
        // the portal lies behind it (n·p + d < 0) as seen from here.
        let plane = -(self.view.inverse().transpose() * portal.plane);
        let projection = oblique(projection, plane)?;
        let to_world = view.inverse();
        let out = Self {
            view,
            view_projection: projection * view,
            eye: to_world.transform_point3(Vec3::ZERO),
            forward: to_world.transform_vector3(Vec3::NEG_Z).normalize_or_zero(),
            flips: self.flips != (portal.transform.determinant() < 0.0),
            // p appears at M·p, which must lie behind the portal: −(n·M·p + d) > 0.
            near: Some(-(portal.transform.transpose() * portal.plane)),
            level: self.level + 1,
        };
        (out.view_projection.is_finite() && out.eye.is_finite()).then_some(out)
    }
}

/// `projection` (clip z in `[0, w]`) with its near plane replaced by `plane` (eye space,
/// visible where `plane·v > 0`, the eye strictly on the other side): Lengyel's oblique frustum, adapted to a `[0, 1]` depth range.
/// The third row becomes `a·plane`, so clip `z = 0` exactly on the plane; `a` puts the far
/// plane through the corner `Q` of the original frustum's far face on the plane's visible side
/// (`Q = P⁻¹·(sgn c′ₓ, sgn c′ᵧ, 1, 1)` for the plane `c′` in clip space), which keeps as much
/// of the original far plane as any oblique far plane can. `None` for a degenerate result.
pub(crate) fn oblique(projection: Mat4, plane: Vec4) -> Option<Mat4> {
    // The eye (the origin) must be strictly on the hidden side.
    if plane.w.is_nan() || plane.w >= 0.0 {
        return None;
    }
    let inverse = projection.inverse();
    let clip_plane = inverse.transpose() * plane;
    let corner = inverse * Vec4::new(clip_plane.x.signum(), clip_plane.y.signum(), 1.0, 1.0);
    let w_row = projection.row(3);
    let along = plane.dot(corner);
    let a = w_row.dot(corner) / along;
    if !(a.is_finite() && a > 0.0 && along != 0.0) {
        return None;
    }
    let z = plane * a;
    let mut out = projection;
    out.x_axis.z = z.x;
    out.y_axis.z = z.y;
    out.z_axis.z = z.z;
    out.w_axis.z = z.w;
    out.is_finite().then_some(out)
}

/// A portal's surface: world positions, one colour.
pub(crate) struct PortalSurface {
    pub(crate) view_projection: Mat4,
    pub(crate) color: Vec4,
}

impl Shader for PortalSurface {
    type Vertex = Vec3;
    type Varying = f32;

    fn vertex(&self, p: &Vec3) -> (Vec4, f32) {
        (self.view_projection * p.extend(1.0), 0.0)
    }

    fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(self.color)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera_projection() -> Mat4 {
        // glTF's perspective (OpenGL z) followed by z′ = (z + w)/2, as the renderer uses.
        let gl = barytex_gltf::Projection::Perspective {
            yfov: 0.8,
            aspect_ratio: None,
            znear: 0.1,
            zfar: Some(100.0),
        }
        .matrix(1.5);
        let to_unit = Mat4::from_cols(
            Vec4::X,
            Vec4::Y,
            Vec4::new(0.0, 0.0, 0.5, 0.0),
            Vec4::new(0.0, 0.0, 0.5, 1.0),
        );
        to_unit * gl
    }

    /// The oblique near plane is the given plane: clip z is 0 on it and positive beyond; x, y
    /// and w are the original projection's; depth still grows along every ray.
    #[test]
    fn oblique_projections_clip_at_the_plane() {
        let p = camera_projection();
        // A plane slanted across the view 3 to 5 units ahead, visible side away from the eye.
        let n = Vec3::new(0.3, -0.2, -1.0).normalize();
        let plane = n.extend(-4.0);
        let o = oblique(p, plane).expect("regular");
        for (x, y) in [(0.0, 0.0), (1.0, 0.5), (-1.5, -0.8)] {
            // The point of the plane on the ray through (x, y, −1).
            let dir = Vec3::new(x, y, -1.0);
            let t = 4.0 / n.dot(dir);
            let on = (dir * t).extend(1.0);
            let clip = o * on;
            assert!(clip.z.abs() < 1e-5 * clip.w, "{clip}");
            let original = p * on;
            assert_eq!(
                (clip.x, clip.y, clip.w),
                (original.x, original.y, original.w)
            );
            let mut last = 0.0;
            for k in 1..20 {
                let q = o * (dir * t * (1.0 + k as f32 * 0.2)).extend(1.0);
                let depth = q.z / q.w;
                assert!(
                    depth > last,
                    "depth grows beyond the plane: {depth} after {last}"
                );
                last = depth;
            }
            assert!(
                last <= 1.0,
                "the original frustum's near part stays inside: {last}"
            );
        }
        // The eye on the plane, or behind the plane's visible side: no oblique frustum.
        assert_eq!(oblique(p, Vec4::new(0.0, 0.0, -1.0, 0.0)), None);
        assert_eq!(oblique(p, Vec4::NAN), None);
    }
}
