//! Interpolation math for texturing and rasterization, exact where a sign decides topology.
//!
//! `barytex-interp` is the bottom crate of barytex: it depends only on [`glam`], works without `std`, and every approximate function states an
//! `# Accuracy` bound that a test enforces (see `docs/ACCURACY.md` in the repository).
//!
//! | concept | items |
//! |---|---|
//! | weighted sums of any attribute | [`Interpolate`], [`interpolate3`] |
//! | linear interpolation | [`lerp`], [`lerp_f64`], [`inverse_lerp`], [`segment_parameter_2d`], [`segment_parameter_3d`] |
//! | checked weights | [`AffineCombination`], [`ConvexCombination`] |
//! | exact orientation | [`orient2d`], [`Orientation`] |
//! | exact 3D orientation | [`orient3d`] |
//! | barycentric coordinates | [`barycentric_2d`] → [`Barycentric2d`], [`locate_2d`] → [`Location`], [`barycentric_3d`] → [`Barycentric3d`], [`methods`] |
//! | convex polygons (generalized barycentric) | [`wachspress_weights`], [`mean_value_weights`], [`GeneralizedBarycentric`], [`interpolate_polygon`], [`PolygonLocation`], [`PolygonError`] |
//! | quads and cubes | [`bilinear`], [`inverse_bilinear_2d`], [`inverse_bilinear_3d`], [`trilinear`] |
//! | projective space | [`Homogeneous3`], [`perspective_correct_weights`], [`perspective_interpolate`] |
//! | spherical interpolation | [`slerp`] and [`try_slerp`] for every [`Slerp`] type (glam's `Vec2`, `Vec3`, `Vec3A`, `Vec4`, `Quat` and their `D` twins), [`slerp_along`] with [`QuatPath`], the fast [`nlerp_quat`], [`nlerp_corrected_quat`] with [`NlerpCorrection`], [`slerp_eberly_quat`] behind [`QuatInterpolation`], normals by [`interpolate_normal`] |
//! | 2D convex hull (exact) | [`convex_hull_2d`], [`ConvexHull2d`], [`CollinearPoints`], [`HullShape2d`], [`HullError2d`], [`HullDefect2d`] |
//! | 3D convex hull | [`convex_hull_3d`], [`ConvexHull3d`], [`HullError3d`], [`HullDefect3d`] |
//!
//! # Conventions
//!
//! - **Numbers.** f32 on the data path, f64 or exact arithmetic inside predicates and solvers;
//!   orientation signs are those of the determinant `(b − a) × (c − a)` in a y-up frame.
//! - **Results are structs or enums, not bare tuples or arrays**, named after their function:
//!   [`barycentric_2d`] → [`Barycentric2d`], [`barycentric_3d`] → [`Barycentric3d`],
//!   [`inverse_bilinear_2d`] → [`InverseBilinear`], [`convex_hull_2d`] → [`ConvexHull2d`].
//! - **One generic function per operation, not one per glam type**: [`slerp`] works on every
//!   [`Slerp`] type; an option is an enum ([`QuatPath`], [`NlerpCorrection`],
//!   [`NormalInterpolation`]), never a `bool`.
//! - **Errors.** Nothing panics on NaN, infinite, huge or degenerate input. What happens instead
//!   depends on the kind of function, one rule per kind:
//!   - *Predicates, locators, solvers and constructors* ([`orient2d`], [`orient3d`],
//!     [`locate_2d`], [`barycentric_2d`], [`barycentric_3d`], [`inverse_lerp`],
//!     [`segment_parameter_2d`], [`inverse_bilinear_2d`], [`perspective_correct_weights`],
//!     [`AffineCombination::new`], …) return `Result<_, InterpError>`; the variant says which
//!     input was bad and why. A concept with failure modes of its own has its own error enum in
//!     the same role: [`HullError2d`], [`HullError3d`], [`PolygonError`].
//!   - *Interpolators* ([`lerp`], [`bilinear`], [`trilinear`], [`slerp`], [`nlerp_quat`],
//!     [`interpolate_normal`], …) are total: bad input gives the value their docs state (the
//!     zero vector for the SLERP family, IEEE propagation of NaN for [`lerp`]). Where a caller
//!     needs to tell bad input apart, a `try_` twin ([`try_slerp`], [`try_slerp_along`]) returns
//!     `Result<_, InterpError>`, an error for exactly the inputs the total form maps to its
//!     fallback.
//!   - `Option` is only for a query whose empty answer is a legitimate outcome, not a rejected
//!     input: [`InverseBilinear::inside`] (no preimage in the unit square),
//!     [`Homogeneous3::to_point`] (a point at infinity), [`Interpolate::combine`] (nothing to
//!     combine).
//!
//! # References
//!
//! Short citations in the item docs refer to:
//!
//! - **Buss 2003**: S. R. Buss, *3D Computer Graphics: A Mathematical Introduction with OpenGL*,
//!   Cambridge University Press, 2003; chapter IV, "Averaging and Interpolation" (linear,
//!   barycentric, bilinear and trilinear interpolation and their inverses, convex sets,
//!   homogeneous coordinates, hyperbolic interpolation, spherical linear interpolation).
//! - **Denisjuk**: A. Denisjuk, *Interpolacja i teksturowanie* (Interpolation and texturing),
//!   course text, University of Warmia and Mazury in Olsztyn, which follows Buss ch. IV–V with
//!   numbered definitions, theorems and worked examples ("Denisjuk, Example 7").
//! - **Shoemake 1985**: K. Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985.
//! - **Phong 1975**: B. T. Phong, "Illumination for computer generated pictures", CACM 18(6), 1975.
//! - **Heckbert and Moreton 1991**: P. S. Heckbert and H. P. Moreton, "Interpolation for polygon
//!   texture mapping and shading", in *State of the Art in Computer Graphics: Visualization and
//!   Modeling*, Springer, 1991.
//! - **Schaefer's shading lecture**: S. Schaefer, "Shading/Texturing", lecture slides, Texas A&M
//!   University.
//!
//! ```
//! use barytex_interp::{barycentric_2d, Location};
//! use glam::Vec2;
//!
//! let tri = [Vec2::new(0.0, 0.0), Vec2::new(2.0, 3.0), Vec2::new(3.0, 1.0)];
//! let b = barycentric_2d(Vec2::new(2.0, 3.0), tri)?;
//! assert_eq!(b.weights, [0.0, 1.0, 0.0]);
//! assert_eq!(b.location, Location::OnVertex(1));
//! # Ok::<(), barytex_interp::InterpError>(())
//! ```
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("barytex-interp needs the `std` feature or, on no_std targets, the `libm` feature");

// The hulls return their vertex lists in a `Vec`: the crate needs an allocator, not `std`.
extern crate alloc;

#[cfg(feature = "std")]
extern crate std;

mod barycentric2d;
mod barycentric3d;
mod bilinear;
mod combination;
mod determinant;
mod error;
pub mod hard_cases;
mod homogeneous;
mod hull2d;
mod hull3d;
mod interpolate;
mod inverse_bilinear;
mod lerp;
mod math;
mod orient;
mod orient3d;
mod perspective;
mod polygon;
mod slerp;
mod trilinear;

pub use barycentric2d::{Barycentric2d, Location, barycentric_2d, locate_2d};
pub use barycentric3d::{Barycentric3d, barycentric_3d};
pub use bilinear::bilinear;
pub use combination::{AffineCombination, ConvexCombination};
pub use error::InterpError;
pub use homogeneous::Homogeneous3;
pub use hull2d::{
    CollinearPoints, ConvexHull2d, HullDefect2d, HullError2d, HullShape2d, convex_hull_2d,
};
pub use hull3d::{ConvexHull3d, HullDefect3d, HullError3d, convex_hull_3d};
pub use interpolate::{Interpolate, interpolate3};
pub use inverse_bilinear::{InverseBilinear, inverse_bilinear_2d, inverse_bilinear_3d};
pub use lerp::{inverse_lerp, lerp, lerp_f64, segment_parameter_2d, segment_parameter_3d};
pub use orient::{Orientation, orient2d};
pub use orient3d::orient3d;
pub use perspective::{perspective_correct_weights, perspective_interpolate};
pub use polygon::{
    GeneralizedBarycentric, PolygonError, PolygonLocation, interpolate_polygon, mean_value_weights,
    wachspress_weights,
};
pub use slerp::*;
pub use trilinear::trilinear;

/// The alternative methods that trade accuracy for speed, kept public so the speed-vs-error report
/// and the benchmarks can measure them against the defaults on the same inputs.
///
/// Use the crate-level functions unless you have measured that one of these is good enough.
///
/// ```
/// use barytex_interp::methods::{
///     barycentric_2d_f64, barycentric_3d_cramer_f32, orient2d_naive_f32, PrecomputedTriangle3,
/// };
/// use barytex_interp::{barycentric_2d, barycentric_3d, hard_cases::kettner_grid, orient2d};
/// use glam::{Vec2, Vec3};
///
/// // Naive f32 orientation gets some of Kettner's near-collinear signs wrong.
/// let wrong = kettner_grid(64)
///     .filter(|&(p, a, b)| Ok(orient2d_naive_f32(p, a, b)) != orient2d(p, a, b))
///     .count();
/// assert!(wrong > 0);
/// // On a well-shaped triangle the alternatives agree with the defaults.
/// let tri = [Vec2::ZERO, Vec2::new(3.0, 0.0), Vec2::new(0.0, 3.0)];
/// assert_eq!(barycentric_2d_f64(Vec2::ONE, tri), barycentric_2d(Vec2::ONE, tri)?.weights);
/// let tri3 = [Vec3::ZERO, Vec3::new(3.0, 0.0, 0.0), Vec3::new(0.0, 3.0, 0.0)];
/// let want = barycentric_3d(Vec3::ONE, tri3)?.weights;
/// let pre = PrecomputedTriangle3::new(tri3)?;
/// for got in [pre.weights(Vec3::ONE), barycentric_3d_cramer_f32(Vec3::ONE, tri3)] {
///     assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-6));
/// }
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
pub mod methods {
    pub use crate::barycentric2d::methods::{
        barycentric_2d_dop_f32, barycentric_2d_f64, barycentric_2d_naive_f32,
    };
    pub use crate::barycentric3d::methods::{
        PrecomputedTriangle3, barycentric_3d_cramer_f32, barycentric_3d_cross_f32,
    };
    pub use crate::orient::methods::{orient2d_dop_f32, orient2d_naive_f32};
    pub use crate::orient3d::methods::orient3d_naive_f64;
}

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
