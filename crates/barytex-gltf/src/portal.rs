//! Portals and mirrors: a planar convex polygon with a transform, through which a renderer draws
//! the scene as the transform places it — another part of the scene (a portal), or the scene
//! reflected about the polygon's plane (a mirror). The potentially visible set through a portal
//! is what its polygon lets through (D. Luebke, C. Georges, "Portals and Mirrors: Simple, Fast
//! Evaluation of Potentially Visible Sets", *Proc. 1995 Symposium on Interactive 3D Graphics*).
//!
//! glTF has no portals: a node declares one in its `extras` (the convention in
//! [`Portal`]'s documentation, also in `docs/PORTALS.md`).

use std::fmt;

use glam::{Mat4, Vec3, Vec4};

/// The most vertices a portal polygon may have (a loader refuses more before reading them).
pub const MAX_PORTAL_VERTICES: usize = 64;

/// A portal: a convex polygon in world space through which the scene appears transformed.
///
/// - `polygon`: the vertices, in order, counter-clockwise seen from the **front** (the side the
///   right-hand normal points to; the side a viewer must be on to see through it);
/// - `transform`: where the scene seen through the portal appears — a world point `q` is seen
///   at `transform · q` (for a mirror, the reflection about the polygon's plane, [`reflection`];
///   for a door into another room, the map from that room's doorway onto this one's);
/// - `tint`: a colour laid over the view through the portal (linear light, straight alpha:
///   alpha 0 leaves the view as it is, alpha 1 hides it).
///
/// # glTF: the `barytex_portal` extras convention
///
/// A node carries a portal in `extras.barytex_portal`, an object with
///
/// - `polygon` (required): 3 to [`MAX_PORTAL_VERTICES`] points `[x, y, z]` in the node's local
///   space, counter-clockwise seen from the front (under a mirroring world matrix the order is
///   reversed, so the front stays the side the local order names, as glTF does for triangles);
/// - exactly one of `mirror: true` (a mirror in the polygon's world-space plane) or
///   `target: n` (node `n`'s surroundings appear at this node: a point at local coordinates `p`
///   of node `n` is seen at local coordinates `p` of this node; `transform` is this node's world
///   matrix times the inverse of node `n`'s);
/// - `tint` (optional): `[r, g, b, a]`, each in `[0, 1]`; default `[0, 0, 0, 0]`.
///
/// The world-space polygon must pass [`Portal::check`]. For example, a 2 × 2 mirror facing +z:
///
/// ```
/// use barytex_gltf::{LoadOptions, load_slice};
/// use glam::Vec3;
///
/// let gltf = br#"{"asset": {"version": "2.0"},
///   "nodes": [{"name": "mirror", "translation": [0, 1, 0], "extras": {"barytex_portal": {
///     "polygon": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], "mirror": true,
///     "tint": [0.9, 0.95, 1.0, 0.1]}}}],
///   "scenes": [{"nodes": [0]}]}"#;
/// let scene = load_slice(gltf, &LoadOptions::default())?;
/// let mirror = &scene.portals[0];
/// assert_eq!(mirror.polygon[2], Vec3::new(1.0, 2.0, 0.0));
/// assert_eq!(mirror.name.as_deref(), Some("mirror"));
/// // It reflects through z = 0: a point in front appears as far behind.
/// assert_eq!(mirror.transform.transform_point3(Vec3::new(0.5, 1.0, 2.0)), Vec3::new(0.5, 1.0, -2.0));
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Portal {
    /// The node that declares it (`None`: built in code).
    pub node: Option<usize>,
    /// The node's name, if any.
    pub name: Option<String>,
    /// World-space vertices, counter-clockwise seen from the front.
    pub polygon: Vec<Vec3>,
    /// World → world: a point `q` is seen through the portal at `transform · q`.
    pub transform: Mat4,
    /// Laid over the view through the portal (linear, straight alpha).
    pub tint: Vec4,
}

/// Why a [`Portal`] cannot be drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PortalError {
    /// Fewer than 3 vertices.
    TooFewVertices,
    /// More than [`MAX_PORTAL_VERTICES`].
    TooManyVertices,
    /// A NaN or infinite vertex, transform entry or tint channel.
    NonFinite,
    /// The polygon has (numerically) no area: coincident or collinear vertices.
    ZeroArea,
    /// A vertex lies off the polygon's plane by more than 10⁻⁴ of the polygon's extent.
    NotPlanar,
    /// The polygon turns both ways (or its vertices are not in order around it).
    NotConvex,
    /// The transform has no inverse (a zero scale, a projection onto a plane).
    SingularTransform,
}

impl fmt::Display for PortalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::TooFewVertices => "a portal polygon needs at least 3 vertices",
            Self::TooManyVertices => "a portal polygon has at most 64 vertices",
            Self::NonFinite => "a portal's vertices, transform and tint must be finite",
            Self::ZeroArea => "the portal polygon has no area",
            Self::NotPlanar => "the portal polygon is not planar",
            Self::NotConvex => "the portal polygon is not convex",
            Self::SingularTransform => "the portal transform has no inverse",
        })
    }
}

impl std::error::Error for PortalError {}

/// The reflection about the plane `n·p + d = 0` (`plane = (n, d)`, `n` a unit vector): the
/// Householder matrix `I − 2nnᵀ` with the translation `−2dn`. Its determinant is −1 (it turns
/// counter-clockwise into clockwise), and it is its own inverse.
///
/// ```
/// use barytex_gltf::portal::reflection;
/// use glam::{Vec3, Vec4};
///
/// let m = reflection(Vec4::new(0.0, 1.0, 0.0, -2.0)); // the plane y = 2
/// assert_eq!(m.transform_point3(Vec3::new(1.0, 5.0, 3.0)), Vec3::new(1.0, -1.0, 3.0));
/// assert_eq!(m * m, glam::Mat4::IDENTITY);
/// assert_eq!(m.determinant(), -1.0);
/// ```
#[must_use]
pub fn reflection(plane: Vec4) -> Mat4 {
    let n = plane.truncate();
    let d = plane.w;
    Mat4::from_cols(
        (Vec3::X - 2.0 * n.x * n).extend(0.0),
        (Vec3::Y - 2.0 * n.y * n).extend(0.0),
        (Vec3::Z - 2.0 * n.z * n).extend(0.0),
        (-2.0 * d * n).extend(1.0),
    )
}

impl Portal {
    /// A clear portal through `polygon` showing the scene moved by `transform`.
    #[must_use]
    pub fn new(polygon: Vec<Vec3>, transform: Mat4) -> Self {
        Self {
            node: None,
            name: None,
            polygon,
            transform,
            tint: Vec4::ZERO,
        }
    }

    /// A clear mirror: the portal whose transform is the [`reflection`] about the polygon's
    /// [`plane`](Self::plane).
    ///
    /// ```
    /// use barytex_gltf::portal::{Portal, PortalError};
    /// use glam::Vec3;
    ///
    /// let square = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    /// let mirror = Portal::mirror(square)?;
    /// assert_eq!(mirror.transform.transform_point3(Vec3::new(0.5, 0.5, 3.0)), Vec3::new(0.5, 0.5, -3.0));
    /// let collinear = vec![Vec3::ZERO, Vec3::X, Vec3::new(2.0, 0.0, 0.0)];
    /// assert_eq!(Portal::mirror(collinear), Err(PortalError::ZeroArea));
    /// # Ok::<(), PortalError>(())
    /// ```
    ///
    /// # Errors
    /// As [`check`](Self::check), for the polygon.
    pub fn mirror(polygon: Vec<Vec3>) -> Result<Self, PortalError> {
        let mut portal = Self::new(polygon, Mat4::IDENTITY);
        let plane = portal.check()?;
        portal.transform = reflection(plane);
        Ok(portal)
    }

    /// This portal with `tint` laid over its view.
    #[must_use]
    pub fn with_tint(self, tint: Vec4) -> Self {
        Self { tint, ..self }
    }

    /// The polygon's plane `(n, d)`: `n` the unit normal towards the front (Newell's normal,
    /// F. Tampieri, "Newell's Method for Computing the Plane Equation of a Polygon", *Graphics
    /// Gems III*, 1992), `d = −n·c` for the vertices' centroid `c`; `None` for fewer than 3
    /// vertices, a non-finite vertex or no area. Not a full [`check`](Self::check).
    ///
    /// ```
    /// use barytex_gltf::portal::Portal;
    /// use glam::{Mat4, Vec3, Vec4};
    ///
    /// // Counter-clockwise seen from +z, at z = 2.
    /// let p = Portal::new(vec![Vec3::new(0.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 2.0), Vec3::new(0.0, 1.0, 2.0)], Mat4::IDENTITY);
    /// assert_eq!(p.plane(), Some(Vec4::new(0.0, 0.0, 1.0, -2.0)));
    /// assert_eq!(Portal::new(vec![Vec3::NAN; 3], Mat4::IDENTITY).plane(), None);
    /// ```
    #[must_use]
    pub fn plane(&self) -> Option<Vec4> {
        let p = &self.polygon;
        if p.len() < 3 || p.iter().any(|v| !v.is_finite()) {
            return None;
        }
        // Newell's sums over the polygon moved to its centroid and scaled to unit extent, so
        // that neither its position nor its size under- or overflows them.
        let centre = p.iter().copied().sum::<Vec3>() / p.len() as f32;
        let scale = 1.0 / self.extent();
        if !(centre.is_finite() && scale.is_finite() && scale > 0.0) {
            return None;
        }
        let mut normal = Vec3::ZERO;
        for (i, &a) in p.iter().enumerate() {
            let (a, b) = (
                (a - centre) * scale,
                (p[(i + 1) % p.len()] - centre) * scale,
            );
            normal += Vec3::new(
                (a.y - b.y) * (a.z + b.z),
                (a.z - b.z) * (a.x + b.x),
                (a.x - b.x) * (a.y + b.y),
            );
        }
        // Twice the area of the unit-extent polygon (NaN fails too).
        if normal.length().is_nan() || normal.length() <= 1e-6 {
            return None;
        }
        let n = normal.normalize();
        n.is_finite().then(|| n.extend(-n.dot(centre)))
    }

    /// The largest side of the polygon's bounding box (0 when empty).
    fn extent(&self) -> f32 {
        let (lo, hi) = self.polygon.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), &v| (lo.min(v), hi.max(v)),
        );
        (hi - lo).max_element().max(0.0)
    }

    /// Checks that the portal can be drawn and returns its [`plane`](Self::plane): 3 to
    /// [`MAX_PORTAL_VERTICES`] finite vertices with area, on one plane (within 10⁻⁴ of the
    /// polygon's extent), turning one way (convex, within the same tolerance); a finite,
    /// invertible transform; a finite tint.
    ///
    /// ```
    /// use barytex_gltf::portal::{Portal, PortalError};
    /// use glam::{Mat4, Vec3};
    ///
    /// let square = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    /// assert!(Portal::new(square.clone(), Mat4::IDENTITY).check().is_ok());
    /// let dented = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0)]
    ///     .map(|(x, y)| Vec3::new(x, y, 0.0)).to_vec();
    /// assert_eq!(Portal::new(dented, Mat4::IDENTITY).check(), Err(PortalError::NotConvex));
    /// let bent = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.5), Vec3::Y];
    /// assert_eq!(Portal::new(bent, Mat4::IDENTITY).check(), Err(PortalError::NotPlanar));
    /// let flat = Mat4::from_scale(Vec3::new(1.0, 1.0, 0.0));
    /// assert_eq!(Portal::new(square, flat).check(), Err(PortalError::SingularTransform));
    /// ```
    ///
    /// # Errors
    /// The first [`PortalError`] that applies, in the order of the list above.
    pub fn check(&self) -> Result<Vec4, PortalError> {
        let p = &self.polygon;
        if p.len() < 3 {
            return Err(PortalError::TooFewVertices);
        }
        if p.len() > MAX_PORTAL_VERTICES {
            return Err(PortalError::TooManyVertices);
        }
        if p.iter().any(|v| !v.is_finite()) || !self.transform.is_finite() || !self.tint.is_finite()
        {
            return Err(PortalError::NonFinite);
        }
        let plane = self.plane().ok_or(PortalError::ZeroArea)?;
        let n = plane.truncate();
        let extent = self.extent();
        let tolerance = 1e-4 * extent;
        if p.iter().any(|v| (n.dot(*v) + plane.w).abs() > tolerance) {
            return Err(PortalError::NotPlanar);
        }
        // Convex: every corner turns towards the normal, and the turns add up to one loop
        // (a star polygon turns one way too, but around more than once).
        let mut turning = 0.0_f32;
        for i in 0..p.len() {
            let (a, b, c) = (p[i], p[(i + 1) % p.len()], p[(i + 2) % p.len()]);
            let (u, v) = (b - a, c - b);
            let turn = u.cross(v).dot(n);
            if turn < -tolerance * extent {
                return Err(PortalError::NotConvex);
            }
            if u.length_squared() > 0.0 && v.length_squared() > 0.0 {
                turning += u.angle_between(v);
            }
        }
        if turning > 2.0 * core::f32::consts::PI + 1e-3 {
            return Err(PortalError::NotConvex);
        }
        let det = self.transform.determinant();
        let regular = det.abs() >= f32::MIN_POSITIVE && det.is_finite();
        if !regular || !self.transform.inverse().is_finite() {
            return Err(PortalError::SingularTransform);
        }
        Ok(plane)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degenerate_polygons_are_errors_not_panics() {
        let id = Mat4::IDENTITY;
        let check = |p: Vec<Vec3>| Portal::new(p, id).check();
        assert_eq!(check(vec![]), Err(PortalError::TooFewVertices));
        assert_eq!(check(vec![Vec3::ZERO; 2]), Err(PortalError::TooFewVertices));
        assert_eq!(
            check(vec![Vec3::ZERO; 65]),
            Err(PortalError::TooManyVertices)
        );
        assert_eq!(check(vec![Vec3::ONE; 4]), Err(PortalError::ZeroArea));
        let collinear = vec![Vec3::ZERO, Vec3::ONE, Vec3::splat(2.0), Vec3::splat(3.0)];
        assert_eq!(check(collinear), Err(PortalError::ZeroArea));
        let nan = vec![Vec3::ZERO, Vec3::X, Vec3::new(f32::NAN, 1.0, 0.0)];
        assert_eq!(check(nan), Err(PortalError::NonFinite));
        let huge = vec![
            Vec3::ZERO,
            Vec3::splat(f32::MAX),
            Vec3::new(-f32::MAX, f32::MAX, 0.0),
        ];
        assert!(check(huge).is_err());
        let tiny = [Vec3::ZERO, Vec3::X, Vec3::Y].map(|v| v * 1e-30).to_vec();
        assert!(check(tiny).is_ok(), "scale does not matter");
        // A pentagram: every corner turns the same way, twice around.
        let star: Vec<Vec3> = (0..5)
            .map(|k| {
                let a = (k * 2) as f32 * core::f32::consts::TAU / 5.0;
                Vec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        assert_eq!(check(star), Err(PortalError::NotConvex));
        let tinted = Portal::new(vec![Vec3::ZERO, Vec3::X, Vec3::Y], id).with_tint(Vec4::NAN);
        assert_eq!(tinted.check(), Err(PortalError::NonFinite));
    }

    #[test]
    fn mirrors_reflect_about_their_plane_and_flip_winding() {
        let tri = vec![
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        ];
        let m = Portal::mirror(tri.clone()).expect("a triangle");
        for v in &tri {
            assert!((m.transform.transform_point3(*v) - *v).length() < 1e-6);
        }
        // (1, 1, 1) is 2/√3 in front of the plane x + y + z = 1: its image is (−⅓, −⅓, −⅓).
        let image = m.transform.transform_point3(Vec3::ONE);
        assert!((image - Vec3::splat(-1.0 / 3.0)).length() < 1e-6, "{image}");
        assert!(m.transform.determinant() < 0.0);
        assert!((m.transform * m.transform).abs_diff_eq(Mat4::IDENTITY, 1e-6));
        assert!(PortalError::NotConvex.to_string().contains("convex"));
    }
}
