//! UV parameterization for texturing: every mapping returns texture coordinates **together with
//! their derivatives**, so a sampler can pick a mip level (pbrt's chain: surface point → mapping
//! → sampler).
//!
//! | concept | items |
//! |---|---|
//! | the seam | [`UvMapping`], [`PositionMapping`], [`SurfacePoint`], [`UvJacobian`], [`UvSample`] |
//! | mesh texture coordinates | [`TexCoordMapping`](mappings::TexCoordMapping) (a vertex uv set with glTF's `KHR_texture_transform`) |
//! | object-space mappings | [`mappings`]: [`Planar`](mappings::Planar), [`BoxMapping`](mappings::BoxMapping), [`Cylindrical`](mappings::Cylindrical), [`Spherical`](mappings::Spherical), [`Torus`](mappings::Torus) |
//! | seam repair | [`seam::repair_seam`], [`seam::repair_sphere_triangle`] |
//! | environment maps | [`environment`] |
//! | parametric meshes | [`mesh`]: [`TriMesh`], [`mesh::plane`], [`mesh::cube`], [`mesh::cylinder`], [`mesh::sphere`], [`mesh::torus`] |
//! | distortion | [`distortion`]: [`MeshDistortion`], [`TriangleDistortion`], [`distortion::singular_values`] |
//! | uv-layout pictures (feature `layout`) | `layout::draw_uv_layout`, `layout::uv_edges` |
//!
//! Conventions: uv (0, 0) is the top-left of the image (glTF), `u` to the right, `v` down;
//! angles in radians; right-handed, y-up object space. Nothing panics on NaN, infinite or
//! degenerate input: mappings return `None`, constructors a [`UvError`].
//!
//! # References
//! - S. R. Buss, *3D Computer Graphics: A Mathematical Introduction with OpenGL*, Cambridge
//!   University Press, 2003, ch. V "Texture Mapping": the cylinder, the sphere's two projections
//!   (eqs. (V.2) and (V.3), Figure V.5) and the torus (Figure V.6); the seam of Figure V.4;
//!   sphere and box environment maps (Figures V.10, V.11).
//! - J. F. Blinn, M. E. Newell, "Texture and reflection in computer generated images",
//!   *Communications of the ACM* 19(10), 1976 (environment mapping by the reflected ray).
//! - N. Greene, "Environment mapping and other applications of world projections", *IEEE
//!   Computer Graphics and Applications* 6(11), 1986 (cube maps).
//! - Z. H. Cigolle et al., "A survey of efficient representations for independent unit
//!   vectors", *Journal of Computer Graphics Techniques* 3(2), 2014 (octahedral maps).
//!
//! ```
//! use barytex_uv::{PositionMapping, SurfacePoint, UvJacobian, UvMapping};
//! use glam::{Vec2, Vec3};
//!
//! /// The xz plane, one texture repeat per 2 units.
//! struct Floor;
//!
//! impl PositionMapping for Floor {
//!     fn uv_and_jacobian(&self, p: Vec3, _normal: Vec3) -> Option<UvJacobian> {
//!         p.is_finite().then(|| UvJacobian {
//!             uv: Vec2::new(p.x, p.z) / 2.0,
//!             du: Vec3::X / 2.0,
//!             dv: Vec3::Z / 2.0,
//!         })
//!     }
//! }
//!
//! // A pixel step of 0.1 along x moves u by 0.05.
//! let point = SurfacePoint::with_derivatives(Vec3::new(1.0, 0.0, 0.5), Vec3::Y, Vec3::X * 0.1, Vec3::Z * 0.1);
//! let sample = Floor.map(&point).expect("finite");
//! assert_eq!(sample.uv, Vec2::new(0.5, 0.25));
//! assert_eq!(sample.duvdx, Vec2::new(0.05, 0.0));
//! ```
#![forbid(unsafe_code)]

pub mod distortion;
pub mod environment;
mod error;
#[cfg(feature = "layout")]
pub mod layout;
mod mapping;
pub mod mappings;
pub mod mesh;
pub mod seam;

pub use distortion::{MeshDistortion, TriangleDistortion};
pub use error::UvError;
pub use mapping::{PositionMapping, SurfacePoint, UvJacobian, UvMapping, UvSample};
pub use mesh::{MeshDefect, TriMesh};

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
