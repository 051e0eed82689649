//! Shading, lighting and texturing techniques of the seed lectures, as pure functions and as
//! [`barytex_raster::Shader`]s.
//!
//! | concept | items |
//! |---|---|
//! | lights | [`Light`] (directional, point, spot), [`SpotShape`] (Warn's `(cos α)^p`, glTF cones), [`Attenuation`] (`min(1/(c1 + c2 d + c3 d²), 1)`) |
//! | illumination models | [`lambert`], [`phong_specular`], [`blinn_phong_specular`], [`Material`], [`Lighting`], [`Specular`] |
//! | atmosphere | [`DepthCue`], [`ExponentialFog`] ([`FogDistance`]), [`HeightFog`], [`atmosphere::blend`] |
//!
//! Conventions: linear-light colours; `N` (normal), `L` (towards the light) and `V` (towards the
//! eye) are unit vectors pointing away from the surface; everything in one space of the
//! caller's choice (world space in the shaders). Nothing panics on NaN, infinite or zero-length
//! input: each function documents the value it returns instead, and no term is ever negative.
//!
//! ```
//! use barytex_shade::{Attenuation, Light, Material};
//! use glam::Vec3;
//!
//! let lamp = Light::Point { position: Vec3::new(0.0, 0.0, 2.0), color: Vec3::ONE,
//!     attenuation: Attenuation::NONE };
//! let lit = Material::default().shade(Vec3::ZERO, Vec3::Z, Vec3::Z, &[lamp], Vec3::splat(0.1));
//! // Ambient 0.07, diffuse 0.7, and the full highlight 0.3: the eye sits on the mirror ray.
//! assert!((lit.total() - Vec3::splat(1.07)).length() < 1e-6);
//! ```
#![forbid(unsafe_code)]

pub mod atmosphere;
mod attenuation;
mod light;
mod model;

pub use atmosphere::{DepthCue, ExponentialFog, FogDistance, HeightFog};
pub use attenuation::Attenuation;
pub use light::{Light, LightSample, SpotShape};
pub use model::{Lighting, Material, Specular, blinn_phong_specular, lambert, phong_specular};
