//! The `UvMapping` seam: a surface point (and optionally its screen-space derivatives) → texture
//! coordinates and their derivatives.

use glam::{Vec2, Vec3};

/// A point on a surface as a mapping sees it: object-space position and unit normal, the
/// screen-space derivatives of the position (`∂p/∂x`, `∂p/∂y` per pixel; zero when unknown), and
/// the interpolated vertex texture coordinates with their screen derivatives (what
/// [`TexCoordMapping`](crate::mappings::TexCoordMapping) reads; zero when the mesh has none).
///
/// This is pbrt-v4's `TextureEvalContext` (Pharr, Jakob, Humphreys, *Physically Based
/// Rendering*, 4th ed., §10.3): everything a mapping may read, computed once per pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfacePoint {
    /// Object-space position.
    pub position: Vec3,
    /// Unit surface normal (used by box/triplanar mappings and environment maps).
    pub normal: Vec3,
    /// `∂position/∂x` per pixel.
    pub dpdx: Vec3,
    /// `∂position/∂y` per pixel.
    pub dpdy: Vec3,
    /// The vertex texture coordinate sets (glTF's `TEXCOORD_0`, `TEXCOORD_1`) interpolated at
    /// the point, with their screen derivatives.
    pub tex_coords: [UvSample; 2],
}

impl SurfacePoint {
    /// A point without screen-space derivatives or vertex texture coordinates.
    #[must_use]
    pub const fn at(position: Vec3, normal: Vec3) -> Self {
        Self::with_derivatives(position, normal, Vec3::ZERO, Vec3::ZERO)
    }

    /// A point with screen-space derivatives, without vertex texture coordinates.
    #[must_use]
    pub const fn with_derivatives(position: Vec3, normal: Vec3, dpdx: Vec3, dpdy: Vec3) -> Self {
        const NONE: UvSample = UvSample {
            uv: Vec2::ZERO,
            duvdx: Vec2::ZERO,
            duvdy: Vec2::ZERO,
        };
        Self {
            position,
            normal,
            dpdx,
            dpdy,
            tex_coords: [NONE; 2],
        }
    }

    /// The same point with interpolated vertex texture coordinates (sets 0 and 1).
    #[must_use]
    pub const fn with_tex_coords(mut self, tex_coords: [UvSample; 2]) -> Self {
        self.tex_coords = tex_coords;
        self
    }
}

/// Texture coordinates and their gradients with respect to the position (the mapping's
/// Jacobian): `u` changes by `du·δp` and `v` by `dv·δp` for a small displacement `δp`, the normal
/// held fixed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UvJacobian {
    /// The texture coordinate.
    pub uv: Vec2,
    /// `∇u` with respect to the position.
    pub du: Vec3,
    /// `∇v` with respect to the position.
    pub dv: Vec3,
}

impl UvJacobian {
    /// The chain rule, once: the texture coordinate with its screen derivatives for a position
    /// that moves by `dpdx` and `dpdy` per pixel (`∂u/∂x = ∇u·∂p/∂x`, and likewise). `None` when
    /// a derivative is not finite.
    ///
    /// ```
    /// use barytex_uv::UvJacobian;
    /// use glam::{Vec2, Vec3};
    ///
    /// let j = UvJacobian { uv: Vec2::new(0.5, 0.25), du: Vec3::X / 2.0, dv: Vec3::Z / 2.0 };
    /// let s = j.chain(Vec3::X * 0.1, Vec3::Z * 0.1).expect("finite");
    /// assert_eq!((s.duvdx, s.duvdy), (Vec2::new(0.05, 0.0), Vec2::new(0.0, 0.05)));
    /// ```
    #[must_use]
    #[inline]
    pub fn chain(self, dpdx: Vec3, dpdy: Vec3) -> Option<UvSample> {
        let sample = UvSample {
            uv: self.uv,
            duvdx: Vec2::new(self.du.dot(dpdx), self.dv.dot(dpdx)),
            duvdy: Vec2::new(self.du.dot(dpdy), self.dv.dot(dpdy)),
        };
        (sample.duvdx.is_finite() && sample.duvdy.is_finite()).then_some(sample)
    }
}

/// Texture coordinates with their screen-space derivatives, what a sampler needs to pick a level.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UvSample {
    /// The texture coordinate.
    pub uv: Vec2,
    /// `∂uv/∂x` per pixel.
    pub duvdx: Vec2,
    /// `∂uv/∂y` per pixel.
    pub duvdy: Vec2,
}

/// The seam between surfaces and samplers: a surface point → texture coordinates with their
/// screen derivatives, what a [`Sampler`](https://docs.rs/barytex-texture) needs to pick a level
/// (pbrt-v4's `TextureMapping2D`, Pharr, Jakob, Humphreys, *Physically Based Rendering*, 4th
/// ed., §10.2).
///
/// Two kinds implement it: [`PositionMapping`]s compute uv from the position (planar, box,
/// cylindrical, spherical, torus, environment maps) and get `map` from their Jacobian by the
/// chain rule; [`TexCoordMapping`](crate::mappings::TexCoordMapping) reads a mesh's vertex uv
/// set and applies an affine transform (glTF's `KHR_texture_transform`).
///
/// # Laws (checked for every mapping by the crate's tests)
/// - Total: NaN or infinite input, and points where the mapping is singular (a pole, an axis),
///   give `None`; never a panic, never a NaN inside `Some`.
pub trait UvMapping {
    /// Texture coordinates and their screen-space derivatives at `point`, or `None` where the
    /// mapping is undefined.
    fn map(&self, point: &SurfacePoint) -> Option<UvSample>;
}

/// A mapping computed from the position (and normal) alone, with its Jacobian.
///
/// Implementors provide [`uv_and_jacobian`](Self::uv_and_jacobian); the blanket [`UvMapping`]
/// implementation applies the Jacobian to the point's screen-space derivatives
/// ([`UvJacobian::chain`], computed once per point as pbrt does) and [`uv`](Self::uv) drops the
/// derivatives.
///
/// # Laws (checked for every mapping by the crate's tests)
/// - Total: NaN or infinite input, and points where the mapping is singular (a pole, an axis),
///   give `None`; never a panic, never a NaN inside `Some`.
/// - The Jacobian matches central finite differences of `uv` away from seams and poles.
/// - `map(p).duvdx == (du·dpdx, dv·dpdx)` and likewise for y.
pub trait PositionMapping {
    /// The texture coordinate at `position` (with unit `normal`) and its gradients, or `None`
    /// where the mapping is undefined.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian>;

    /// The texture coordinate alone.
    fn uv(&self, position: Vec3, normal: Vec3) -> Option<Vec2> {
        self.uv_and_jacobian(position, normal).map(|j| j.uv)
    }
}

impl<T: PositionMapping + ?Sized> UvMapping for T {
    #[inline]
    fn map(&self, point: &SurfacePoint) -> Option<UvSample> {
        self.uv_and_jacobian(point.position, point.normal)?
            .chain(point.dpdx, point.dpdy)
    }
}
