//! Environment maps behind the [`UvMapping`](crate::UvMapping) seam: the direction is the
//! surface normal, the view vector reflected about it (the Jacobian chained through the
//! reflection), or a direction given per pixel.

use glam::{Vec2, Vec3};

use super::reflect::{reflect, unit};
use super::{
    cube_face_uv_and_jacobian, equirect_uv_and_jacobian, octahedral_uv_and_jacobian,
    sphere_map_uv_and_jacobian,
};
use crate::{PositionMapping, UvJacobian};

/// Which parameterization of the sphere of directions a texture stores.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EnvironmentMap {
    /// A cube map; `uv` is the face-local `(s, t)` of [`cube_face_uv`](super::cube_face_uv) (the
    /// face is not part of the result: use `cube_face_uv` for it).
    Cube,
    /// [`equirect_uv`](super::equirect_uv).
    Equirect,
    /// [`sphere_map_uv`](super::sphere_map_uv).
    SphereMap,
    /// [`octahedral_encode`](super::octahedral_encode).
    Octahedral,
}

impl EnvironmentMap {
    /// All four maps.
    pub const ALL: [Self; 4] = [
        Self::Cube,
        Self::Equirect,
        Self::SphereMap,
        Self::Octahedral,
    ];

    /// A short lowercase name (`"cube"`, `"equirect"`, `"sphere-map"`, `"octahedral"`).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Cube => "cube",
            Self::Equirect => "equirect",
            Self::SphereMap => "sphere-map",
            Self::Octahedral => "octahedral",
        }
    }

    /// The coordinate of the direction `dir` (any finite nonzero length) and its gradients with
    /// respect to `dir` (in the [`UvJacobian`] fields `du`, `dv`). `None` where the map is
    /// undefined or its gradient infinite (see each map's `*_uv_and_jacobian`).
    ///
    /// # Accuracy
    /// That of the map's `*_uv_and_jacobian` function.
    ///
    /// ```
    /// use barytex_uv::environment::EnvironmentMap;
    /// use glam::{Vec2, Vec3};
    ///
    /// let j = EnvironmentMap::Cube.uv_and_direction_jacobian(Vec3::Z).expect("nonzero");
    /// assert_eq!(j.uv, Vec2::splat(0.5));
    /// ```
    #[must_use]
    pub fn uv_and_direction_jacobian(self, dir: Vec3) -> Option<UvJacobian> {
        match self {
            Self::Cube => cube_face_uv_and_jacobian(dir).map(|(_, j)| j),
            Self::Equirect => equirect_uv_and_jacobian(dir),
            Self::SphereMap => sphere_map_uv_and_jacobian(dir),
            Self::Octahedral => octahedral_uv_and_jacobian(dir),
        }
    }

    /// The coordinate of `dir` alone, or `None` where the map is undefined.
    ///
    /// ```
    /// use barytex_uv::environment::EnvironmentMap;
    /// use glam::{Vec2, Vec3};
    ///
    /// assert_eq!(EnvironmentMap::Equirect.uv(Vec3::NEG_Z), Some(Vec2::splat(0.5)));
    /// ```
    #[must_use]
    pub fn uv(self, dir: Vec3) -> Option<Vec2> {
        match self {
            Self::Cube => super::cube_face_uv(dir).map(|(_, st)| st),
            Self::Equirect => super::equirect_uv(dir),
            Self::SphereMap => super::sphere_map_uv(dir),
            Self::Octahedral => super::octahedral_encode(dir),
        }
    }
}

/// What direction an [`EnvironmentMapping`] looks up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lookup {
    /// The surface normal itself (irradiance maps, debugging). The coordinate does not depend on
    /// the position, so the Jacobian with respect to the position is zero.
    Normal,
    /// The view vector reflected about the normal: `r = reflect(n, normalize(eye − p))`
    /// ([`reflect`](super::reflect)), a mirror. `eye` is in the same space as the position.
    Reflect {
        /// The eye position.
        eye: Vec3,
    },
    /// The point's position is itself the direction (any finite nonzero length), and its
    /// screen derivatives are the direction's: a direction computed per pixel (a reflection
    /// that follows a curved mirror's interpolated normal, a sky dome) looks the map up with
    /// the footprint it sweeps. The normal is not read.
    Direction,
}

/// An environment map as a [`UvMapping`](crate::UvMapping) (through [`PositionMapping`]): the coordinate of the direction chosen by `lookup`
/// in `map`, with its gradients with respect to the position, the normal held fixed.
///
/// For [`Lookup::Reflect`], with `v = (e − p)/L`, `L = |e − p|`, `P = I − vvᵀ` and
/// `M = 2nnᵀ − I`: `∂r/∂p = −M·P/L`, so `∇ₚu = −P·(M·∇ᵣu)/L` (both factors symmetric).
///
/// `None` when the normal is zero or not finite, the position is at the eye, or the map is
/// undefined at the direction (see [`EnvironmentMap::uv_and_direction_jacobian`]).
///
/// # Accuracy
/// The gradients match central differences of `uv` in f64 within `1e-3` relative
/// (`environment.rs::mapping_jacobian_matches_finite_differences`).
///
/// ```
/// use barytex_uv::environment::{EnvironmentMap, EnvironmentMapping, Lookup};
/// use barytex_uv::{PositionMapping, SurfacePoint, UvMapping};
/// use glam::{Vec2, Vec3};
///
/// // A mirror floor seen at 45° from +z reflects the sky 45° above the horizon towards −z.
/// let eye = Vec3::new(0.0, 5.0, 5.0);
/// let mirror = EnvironmentMapping { map: EnvironmentMap::Equirect, lookup: Lookup::Reflect { eye } };
/// let uv = mirror.uv(Vec3::ZERO, Vec3::Y).expect("defined");
/// assert!((uv - Vec2::new(0.5, 0.25)).length() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnvironmentMapping {
    /// The parameterization of the texture.
    pub map: EnvironmentMap,
    /// The direction looked up.
    pub lookup: Lookup,
}

impl PositionMapping for EnvironmentMapping {
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        match self.lookup {
            Lookup::Direction => self.map.uv_and_direction_jacobian(position),
            Lookup::Normal => {
                let n = unit(normal)?;
                let j = self.map.uv_and_direction_jacobian(n)?;
                Some(UvJacobian {
                    uv: j.uv,
                    du: Vec3::ZERO,
                    dv: Vec3::ZERO,
                })
            }
            Lookup::Reflect { eye } => {
                let n = unit(normal)?;
                let to_eye = eye - position;
                let v = unit(to_eye)?;
                let len = to_eye.length();
                let r = reflect(n, v);
                let j = self.map.uv_and_direction_jacobian(r)?;
                let chain = |g: Vec3| {
                    let w = 2.0 * n.dot(g) * n - g;
                    -(w - v.dot(w) * v) / len
                };
                let out = UvJacobian {
                    uv: j.uv,
                    du: chain(j.du),
                    dv: chain(j.dv),
                };
                (out.du.is_finite() && out.dv.is_finite()).then_some(out)
            }
        }
    }
}
