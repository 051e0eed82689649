//! A mesh's own texture coordinates: one vertex uv set, interpolated by the rasterizer, through
//! an affine transform — glTF's `TEXCOORD_n` with `KHR_texture_transform`.

use glam::{Mat3, Vec2, Vec3};

use crate::{SurfacePoint, UvMapping, UvSample};

/// Reads the vertex texture coordinate set `set` of a [`SurfacePoint`] and transforms it, with
/// its screen derivatives, by the affine `transform`: `uv′ = (M · (u, v, 1)).xy` and
/// `∂uv′/∂x = (M · (∂u/∂x, ∂v/∂x, 0)).xy` (the translation drops out of derivatives).
///
/// `None` for a set the point does not carry (`set > 1`) or a non-finite result.
///
/// ```
/// use barytex_uv::mappings::TexCoordMapping;
/// use barytex_uv::{SurfacePoint, UvMapping, UvSample};
/// use glam::{Vec2, Vec3};
///
/// // uv scaled by 2 in u: the coordinate and its derivatives double along u.
/// let mapping = TexCoordMapping::khr_texture_transform(0, Vec2::ZERO, 0.0, Vec2::new(2.0, 1.0));
/// let vertex = UvSample { uv: Vec2::new(0.25, 0.5), duvdx: Vec2::new(0.01, 0.0), duvdy: Vec2::new(0.0, 0.01) };
/// let point = SurfacePoint::at(Vec3::ZERO, Vec3::Z).with_tex_coords([vertex, UvSample::default()]);
/// let s = mapping.map(&point).expect("finite");
/// assert_eq!(s.uv, Vec2::new(0.5, 0.5));
/// assert_eq!(s.duvdx, Vec2::new(0.02, 0.0));
/// assert_eq!(s.duvdy, Vec2::new(0.0, 0.01));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexCoordMapping {
    /// Which vertex texture coordinate set to read (`TEXCOORD_set`).
    pub set: u32,
    /// The affine transform of the texture coordinate (bottom row `0 0 1`).
    pub transform: Mat3,
}

impl Default for TexCoordMapping {
    /// Set 0, untransformed.
    fn default() -> Self {
        Self::new(0)
    }
}

impl TexCoordMapping {
    /// The set `set`, untransformed.
    #[must_use]
    pub const fn new(set: u32) -> Self {
        Self {
            set,
            transform: Mat3::IDENTITY,
        }
    }

    /// The set `set` through glTF's `KHR_texture_transform` (offset, rotation in radians,
    /// scale): `M = translation · rotation · scale`, with `u′ = cos·u + sin·v`,
    /// `v′ = −sin·u + cos·v` for the rotation.
    ///
    /// That is the direction the extension's prose and example fix: its example (offset
    /// `[0, 1]`, rotation π/2, scale ½) must land on the image's lower-left quadrant, and the
    /// sample model TextureTransformTest shows a red marker when the rotation turns the other
    /// way. The GLSL snippet in the extension's README, read as column-major, turns the other
    /// way (a slip in that snippet; three.js, Babylon.js and the sample viewer agree with the
    /// example).
    ///
    /// ```
    /// use barytex_uv::mappings::TexCoordMapping;
    /// use glam::{Vec2, Vec3};
    ///
    /// // The extension's example: the lower-left quadrant, rotated.
    /// let m = TexCoordMapping::khr_texture_transform(
    ///     0, Vec2::new(0.0, 1.0), std::f32::consts::FRAC_PI_2, Vec2::splat(0.5)).transform;
    /// let corner = |u: f32, v: f32| (m * Vec3::new(u, v, 1.0)).truncate();
    /// assert!(corner(1.0, 0.0).distance(Vec2::new(0.0, 0.5)) < 1e-6);
    /// assert!(corner(1.0, 1.0).distance(Vec2::new(0.5, 0.5)) < 1e-6);
    /// ```
    #[must_use]
    pub fn khr_texture_transform(set: u32, offset: Vec2, rotation: f32, scale: Vec2) -> Self {
        let (s, c) = rotation.sin_cos();
        let translation = Mat3::from_cols(Vec3::X, Vec3::Y, Vec3::new(offset.x, offset.y, 1.0));
        let rotation = Mat3::from_cols(Vec3::new(c, -s, 0.0), Vec3::new(s, c, 0.0), Vec3::Z);
        let scale = Mat3::from_diagonal(Vec3::new(scale.x, scale.y, 1.0));
        Self {
            set,
            transform: translation * rotation * scale,
        }
    }

    /// `sample` (a vertex set's interpolated coordinate and derivatives) through the
    /// transform; `None` when the result is not finite.
    #[must_use]
    #[inline]
    pub fn transform_sample(&self, sample: &UvSample) -> Option<UvSample> {
        let t = self.transform;
        let out = UvSample {
            uv: (t * sample.uv.extend(1.0)).truncate(),
            duvdx: (t * sample.duvdx.extend(0.0)).truncate(),
            duvdy: (t * sample.duvdy.extend(0.0)).truncate(),
        };
        (out.uv.is_finite() && out.duvdx.is_finite() && out.duvdy.is_finite()).then_some(out)
    }
}

impl UvMapping for TexCoordMapping {
    #[inline]
    fn map(&self, point: &SurfacePoint) -> Option<UvSample> {
        let sample = point.tex_coords.get(usize::try_from(self.set).ok()?)?;
        self.transform_sample(sample)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(uv: Vec2) -> SurfacePoint {
        let set = UvSample {
            uv,
            duvdx: Vec2::new(1.0 / 64.0, 0.0),
            duvdy: Vec2::new(0.0, 1.0 / 64.0),
        };
        SurfacePoint::at(Vec3::ZERO, Vec3::Z).with_tex_coords([set, UvSample::default()])
    }

    #[test]
    fn identity_passes_the_vertex_set_through() {
        let p = point(Vec2::new(0.3, 0.7));
        assert_eq!(TexCoordMapping::new(0).map(&p), Some(p.tex_coords[0]));
        assert_eq!(TexCoordMapping::new(1).map(&p), Some(p.tex_coords[1]));
    }

    #[test]
    fn missing_sets_and_non_finite_results_are_none() {
        let p = point(Vec2::new(0.3, 0.7));
        assert_eq!(TexCoordMapping::new(2).map(&p), None);
        assert_eq!(TexCoordMapping::new(u32::MAX).map(&p), None);
        assert_eq!(TexCoordMapping::new(0).map(&point(Vec2::NAN)), None);
        let huge =
            TexCoordMapping::khr_texture_transform(0, Vec2::ZERO, 0.0, Vec2::splat(f32::MAX));
        assert_eq!(huge.map(&point(Vec2::splat(4.0))), None);
        let nan = TexCoordMapping::khr_texture_transform(0, Vec2::ZERO, f32::NAN, Vec2::ONE);
        assert_eq!(nan.map(&point(Vec2::splat(0.5))), None);
    }

    #[test]
    fn rotation_turns_derivatives_and_offset_leaves_them() {
        let quarter = TexCoordMapping::khr_texture_transform(
            0,
            Vec2::new(5.0, -3.0),
            std::f32::consts::FRAC_PI_2,
            Vec2::ONE,
        );
        let s = quarter.map(&point(Vec2::ZERO)).expect("finite");
        assert_eq!(s.uv, Vec2::new(5.0, -3.0));
        // u′ = cos·u + sin·v, v′ = −sin·u + cos·v: ∂u/∂x = 1/64 becomes ∂v′/∂x = −1/64.
        assert!((s.duvdx - Vec2::new(0.0, -1.0 / 64.0)).length() < 1e-9);
        assert!((s.duvdy - Vec2::new(1.0 / 64.0, 0.0)).length() < 1e-9);
    }

    /// `KHR_texture_transform`'s offset, scale and rotation direction, and the extension's own
    /// example (the unit square onto the lower-left quadrant).
    #[test]
    fn texture_transform_follows_the_extension() {
        let m = TexCoordMapping::khr_texture_transform(
            0,
            Vec2::new(0.5, 0.25),
            0.0,
            Vec2::new(2.0, 3.0),
        );
        let uv = m.transform * Vec3::new(1.0, 1.0, 1.0);
        assert!((uv.x - 2.5).abs() < 1e-6 && (uv.y - 3.25).abs() < 1e-6);
        let r = TexCoordMapping::khr_texture_transform(
            0,
            Vec2::ZERO,
            std::f32::consts::FRAC_PI_2,
            Vec2::ONE,
        );
        let uv = r.transform * Vec3::new(1.0, 0.0, 1.0);
        assert!(uv.x.abs() < 1e-6 && (uv.y + 1.0).abs() < 1e-6);
        let example = TexCoordMapping::khr_texture_transform(
            0,
            Vec2::new(0.0, 1.0),
            std::f32::consts::FRAC_PI_2,
            Vec2::splat(0.5),
        );
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (0.5, 0.5)] {
            let t = example.transform * Vec3::new(u, v, 1.0);
            assert!(
                (-1e-6..=0.5 + 1e-6).contains(&t.x) && (0.5 - 1e-6..=1.0 + 1e-6).contains(&t.y),
                "({u}, {v}) → {t}"
            );
        }
    }
}
