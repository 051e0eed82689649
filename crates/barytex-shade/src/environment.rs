//! Environment mapping (Blinn and Newell 1976; Greene 1986; Buss, *3D Computer Graphics*, 2003,
//! §V.3; S. Schaefer's *Shading/Texturing* slides): the reflected ray `r = 2(n·v)n − v` looks up a
//! cube map (faces assumed infinitely far), an OpenGL sphere map or an equirectangular panorama.

use barytex_texture::{CubeTexture, Sampler, Texel};
use barytex_uv::environment::{EnvironmentMap, EnvironmentMapping, Lookup};
use barytex_uv::{SurfacePoint, UvMapping};
use glam::{Vec3, Vec4};

/// Anything that returns a colour for a direction and its screen derivatives (a cube map).
pub trait DirectionSampler {
    /// The colour seen along `dir`, filtered over the footprint `ddx`, `ddy`.
    fn sample_direction(&self, dir: Vec3, ddx: Vec3, ddy: Vec3) -> Vec4;
}

impl<T: Texel> DirectionSampler for CubeTexture<T> {
    fn sample_direction(&self, dir: Vec3, ddx: Vec3, ddy: Vec3) -> Vec4 {
        self.sample(dir, ddx, ddy)
    }
}

/// Where the environment is stored.
#[derive(Clone, Copy)]
pub enum Environment<'a> {
    /// A cube map ([`barytex_texture::CubeTexture`]).
    Cube(&'a (dyn DirectionSampler + Sync)),
    /// An OpenGL sphere map (the image of a mirror ball seen from `+z`).
    SphereMap(&'a (dyn Sampler + Sync)),
    /// An equirectangular (latitude–longitude) panorama.
    Equirect(&'a (dyn Sampler + Sync)),
}

impl core::fmt::Debug for Environment<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::Cube(_) => "Environment::Cube",
            Self::SphereMap(_) => "Environment::SphereMap",
            Self::Equirect(_) => "Environment::Equirect",
        })
    }
}

impl Environment<'_> {
    /// The colour seen along `dir` with the direction's screen derivatives `ddx`, `ddy`
    /// (projected through the map's Jacobian to pick a mip level).
    ///
    /// # Special values
    /// A zero or non-finite direction, a sphere map's singular direction `−z`, or a non-finite
    /// footprint gives transparent black.
    #[must_use]
    pub fn sample(&self, dir: Vec3, ddx: Vec3, ddy: Vec3) -> Vec4 {
        // The direction is the looked-up "position" and its derivatives the footprint: the
        // map's UvMapping does the chain rule, the sampler picks the level.
        let through = |map: EnvironmentMap, s: &dyn Sampler| {
            let mapping = EnvironmentMapping {
                map,
                lookup: Lookup::Direction,
            };
            let point = SurfacePoint::with_derivatives(dir, Vec3::ZERO, ddx, ddy);
            mapping
                .map(&point)
                .map_or(Vec4::ZERO, |mapped| s.sample_uv(&mapped))
        };
        match *self {
            Self::Cube(c) => c.sample_direction(dir, ddx, ddy),
            Self::SphereMap(s) => through(EnvironmentMap::SphereMap, s),
            Self::Equirect(s) => through(EnvironmentMap::Equirect, s),
        }
    }
}

/// The mirror direction at `p` with unit normal `n` seen from `eye`: `r = 2(n·v)n − v` with
/// `v = (eye − p)/|eye − p|`; zero when `p` is at the eye or anything is not finite.
///
/// ```
/// use barytex_shade::reflection_direction;
/// use glam::Vec3;
/// // Looking straight down at a floor: the ray goes straight up.
/// assert_eq!(reflection_direction(Vec3::ZERO, Vec3::Y, Vec3::Y * 3.0), Vec3::Y);
/// ```
#[must_use]
#[inline]
pub fn reflection_direction(p: Vec3, n: Vec3, eye: Vec3) -> Vec3 {
    let v = (eye - p).normalize_or_zero();
    let r = barytex_uv::environment::reflect(n, v);
    if r.is_finite() { r } else { Vec3::ZERO }
}
