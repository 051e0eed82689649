//! The named hard cases of this crate, in one place: run by the tests, the fuzz regressions and
//! the speed-vs-error report (`barytex-report`).
//!
//! Each case is plain data; the tests compute the exact answer from it with rational arithmetic,
//! so a case never carries a hard-coded expected float.
//!
//! ```
//! use barytex_interp::hard_cases::{kettner_grid, triangles_2d};
//! use barytex_interp::{locate_2d, orient2d, Orientation};
//!
//! // Where a case pins the location down by construction, the exact predicates agree.
//! for case in triangles_2d() {
//!     if let Some(expected) = case.expected {
//!         assert_eq!(locate_2d(case.point, case.triangle), Ok(expected), "{}", case.name);
//!     }
//! }
//! // Kettner's grid straddles the line y = x: the diagonal is collinear, the rest is not.
//! for (p, a, b) in kettner_grid(8) {
//!     let collinear = orient2d(p, a, b)? == Orientation::Collinear;
//!     assert_eq!(collinear, p.x == p.y);
//! }
//! # Ok::<(), barytex_interp::InterpError>(())
//! ```

use glam::{Vec2, Vec3};

use crate::Location;

mod hulls;
mod hulls_3d;
mod polygons;
mod rotations;

pub use hulls::{HullCase2d, hull_circle_2d, hulls_2d};
pub use hulls_3d::*;
pub use polygons::*;
pub use rotations::{QuatPairCase, VectorPairCase, quaternion_pairs, vector_pairs};

/// Kettner et al.'s grid ("Classroom examples of robustness problems in geometric
/// computations"): the points `(0.5 + i·ulp, 0.5 + j·ulp)` for `i, j` in `0..n`, tested against
/// the line through `(12, 12)` and `(24, 24)`. Naive f32 orientation gets thousands of these
/// signs wrong; an exact predicate none.
///
/// Yields `(p, a, b)` with `a = (12, 12)` and `b = (24, 24)`; `n` is clamped to 65 536.
pub fn kettner_grid(n: u32) -> impl Iterator<Item = (Vec2, Vec2, Vec2)> {
    let n = n.min(1 << 16);
    let a = Vec2::new(12.0, 12.0);
    let b = Vec2::new(24.0, 24.0);
    let base = 0.5f32.to_bits();
    (0..n).flat_map(move |i| {
        (0..n).map(move |j| {
            let p = Vec2::new(f32::from_bits(base + i), f32::from_bits(base + j));
            (p, a, b)
        })
    })
}

/// A named 2D triangle and query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleCase {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter (aspect, offset, scale, …), 0 when it has none.
    pub parameter: f32,
    /// `[a, b, c]`.
    pub triangle: [Vec2; 3],
    /// The query point.
    pub point: Vec2,
    /// The location when the case pins it down by construction.
    pub expected: Option<Location>,
}

/// A named 3D triangle and query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle3Case {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter, 0 when it has none.
    pub parameter: f32,
    /// `[a, b, c]`.
    pub triangle: [Vec3; 3],
    /// The query point (in the plane up to rounding).
    pub point: Vec3,
}

/// A named quad and the `(α, β)` to map forward and invert.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadCase {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter, 0 when it has none.
    pub parameter: f32,
    /// `[x, y, z, w]` as in [`bilinear`](crate::bilinear).
    pub quad: [Vec2; 4],
    /// The preimage to round-trip.
    pub alpha_beta: Vec2,
}

const ASPECTS: [f32; 5] = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7];
const OFFSETS: [f32; 4] = [1e4, 1e5, 1e6, 1e7];
const TINY: [f32; 3] = [1e-10, 1e-20, 1e-30];

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A quad from its corners' f32 bit patterns (the cases found by search, exactly).
fn bits_quad(corners: [[u32; 2]; 4]) -> [Vec2; 4] {
    corners.map(|c| Vec2::from_array(c.map(f32::from_bits)))
}

/// The 2D triangle table: slivers of aspect 1e-3 … 1e-7, offsets 1e4 … 1e7, tiny scales down to
/// 1e-30, subnormal coordinates, huge coordinates, points exactly on edges and vertices, and
/// points one ulp off an edge.
pub fn triangles_2d() -> impl Iterator<Item = TriangleCase> {
    let slivers = ASPECTS.into_iter().map(|k| TriangleCase {
        name: "sliver",
        parameter: k,
        triangle: [v(0.0, 0.0), v(1.0, 0.0), v(0.5, k)],
        point: v(0.3, 0.4 * k),
        expected: None,
    });
    let offsets = OFFSETS.into_iter().map(|o| TriangleCase {
        name: "offset",
        parameter: o,
        triangle: [v(o, o), v(o + 1000.0, o), v(o, o + 1000.0)],
        point: v(o + 250.0, o + 300.0),
        expected: Some(Location::Inside),
    });
    let tiny = TINY.into_iter().map(|s| TriangleCase {
        name: "tiny scale",
        parameter: s,
        triangle: [v(0.0, 0.0), v(3.0 * s, s), v(s, 3.0 * s)],
        point: v(1.5 * s, 1.25 * s),
        expected: Some(Location::Inside),
    });
    let fixed = [
        TriangleCase {
            name: "subnormal",
            parameter: 1e-40,
            triangle: [v(0.0, 0.0), v(1e-40, 0.0), v(0.0, 1e-40)],
            point: v(2e-41, 3e-41),
            expected: Some(Location::Inside),
        },
        TriangleCase {
            name: "huge",
            parameter: 1e38,
            triangle: [v(-3e38, -3e38), v(3e38, -3e38), v(0.0, 3e38)],
            point: v(1e37, 1e37),
            expected: Some(Location::Inside),
        },
        TriangleCase {
            name: "on edge midpoint",
            parameter: 0.0,
            triangle: [v(0.0, 0.0), v(3.0, 1.0), v(1.0, 3.0)],
            point: v(2.0, 2.0),
            expected: Some(Location::OnEdge(0)),
        },
        TriangleCase {
            name: "on edge, inexact parameter",
            parameter: 0.0,
            triangle: [v(0.1, 0.1), v(0.7, 0.1), v(0.3, 0.9)],
            point: v(0.3, 0.1),
            expected: Some(Location::OnEdge(2)),
        },
        TriangleCase {
            name: "on vertex",
            parameter: 0.0,
            triangle: [v(0.1, 0.2), v(0.7, 0.1), v(0.3, 0.9)],
            point: v(0.7, 0.1),
            expected: Some(Location::OnVertex(1)),
        },
        TriangleCase {
            name: "one ulp outside an edge",
            parameter: 0.0,
            triangle: [v(0.5, 0.5), v(12.0, 12.0), v(0.0, 24.0)],
            point: v(f32::from_bits(0.5f32.to_bits() + 1), 0.5),
            expected: Some(Location::Outside),
        },
        TriangleCase {
            name: "one ulp inside an edge",
            parameter: 0.0,
            triangle: [v(0.5, 0.5), v(12.0, 12.0), v(0.0, 24.0)],
            point: v(6.0, f32::from_bits(6.0f32.to_bits() + 1)),
            expected: Some(Location::Inside),
        },
        TriangleCase {
            name: "clockwise",
            parameter: 0.0,
            triangle: [v(0.0, 0.0), v(0.0, 1.0), v(1.0, 0.0)],
            point: v(0.25, 0.25),
            expected: Some(Location::Inside),
        },
        TriangleCase {
            name: "Denisjuk example 9, outside",
            parameter: 0.0,
            triangle: [v(0.0, 0.0), v(2.0, 3.0), v(3.0, 1.0)],
            point: v(1.0, 0.0),
            expected: Some(Location::Outside),
        },
    ];
    slivers.chain(offsets).chain(tiny).chain(fixed)
}

/// The 3D triangle table: tilted slivers of aspect 1e-3 … 1e-7, offsets 1e4 … 1e7, and points
/// 1e3, 1e8 and 1e13 triangle sizes away from a small triangle.
pub fn triangles_3d() -> impl Iterator<Item = Triangle3Case> {
    let slivers = ASPECTS.into_iter().map(|k| {
        let a = Vec3::new(0.0, 0.0, 0.0);
        let b = Vec3::new(1.0, 1.0, 1.0);
        let c = Vec3::new(0.5 + k, 0.5 - k, 0.5);
        Triangle3Case {
            name: "tilted sliver",
            parameter: k,
            triangle: [a, b, c],
            point: a * 0.3 + b * 0.3 + c * 0.4,
        }
    });
    let offsets = OFFSETS.into_iter().map(|o| {
        let base = Vec3::splat(o);
        Triangle3Case {
            name: "offset",
            parameter: o,
            triangle: [
                base,
                base + Vec3::new(1000.0, 0.0, 500.0),
                base + Vec3::new(0.0, 1000.0, 250.0),
            ],
            point: base + Vec3::new(250.0, 500.0, 250.0),
        }
    });
    // A point far from a small triangle (off its plane and off its span), where the weights'
    // old form ((b − p) × (c − p))·n rounded away (fuzz `interp_3d` found distance 1e13 at size
    // 1e-17); parameter: the distance over the triangle's size.
    let far = [1e3f32, 1e8, 1e13].into_iter().map(|d| {
        let size = 1e-3;
        let a = Vec3::new(0.1, -0.2, 0.05);
        Triangle3Case {
            name: "far point",
            parameter: d,
            triangle: [
                a,
                a + Vec3::new(size, 0.0, 0.0),
                a + Vec3::new(0.0, size, 0.0),
            ],
            point: a + Vec3::new(0.3, 0.6, 0.7) * (size * d),
        }
    });
    slivers.chain(offsets).chain(far)
}

/// The quad table: Denisjuk's Example 10 quad, an exact parallelogram (A = 0, where thresholded
/// solvers switch branches), a near-parallelogram, a trapezoid, a sliver, corners of mixed
/// magnitude (1e-30 beside 1), tiny scales down to 1e-30, subnormal size, two exact edge points
/// next to a double root (a corner of a κ ≈ 9.1e3 quad, the midpoint of a 2-ulp edge of a
/// κ ≈ 2.2e7 quad) and offsets 1e4 … 1e7.
pub fn quads() -> impl Iterator<Item = QuadCase> {
    let example = [v(0.0, 0.0), v(4.0, 0.0), v(5.0, 3.0), v(0.0, 2.0)];
    let fixed = [
        QuadCase {
            name: "Denisjuk example 10",
            parameter: 0.0,
            quad: example,
            alpha_beta: v(2.0 / 3.0, 1.0 / 3.0),
        },
        QuadCase {
            name: "parallelogram",
            parameter: 0.0,
            quad: [v(0.0, 0.0), v(2.0, 0.5), v(2.5, 1.5), v(0.5, 1.0)],
            alpha_beta: v(0.3, 0.7),
        },
        QuadCase {
            name: "near-parallelogram",
            parameter: 1e-6,
            quad: [v(0.0, 0.0), v(1.0, 0.0), v(1.0 + 1e-6, 1.0), v(0.0, 1.0)],
            alpha_beta: v(0.6, 0.2),
        },
        QuadCase {
            name: "trapezoid",
            parameter: 0.0,
            quad: [v(0.0, 0.0), v(4.0, 0.0), v(3.0, 1.0), v(1.0, 1.0)],
            alpha_beta: v(0.9, 0.95),
        },
        QuadCase {
            name: "sliver",
            parameter: 1e-3,
            quad: [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1e-3), v(0.0, 2e-3)],
            alpha_beta: v(0.25, 0.5),
        },
        QuadCase {
            name: "mixed magnitudes",
            parameter: 1e-30,
            quad: [v(1e-30, 1e-30), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)],
            alpha_beta: v(0.3, 0.6),
        },
        QuadCase {
            name: "subnormal size",
            parameter: 1e-40,
            quad: [v(0.0, 0.0), v(4e-40, 0.0), v(5e-40, 3e-40), v(0.0, 2e-40)],
            alpha_beta: v(0.5, 0.25),
        },
        // Two exact edge points next to a double root of the quadratic in α, found by a
        // brute-force search over edge points (2026-12-03): the roots there are off by more
        // than a solver's fixed slack, and a solver that trusts them answers "outside".
        // The parameter is the quad's condition number κ.
        QuadCase {
            name: "double root at corner w",
            parameter: 9.1e3,
            quad: bits_quad([
                [880_192_450, 3_039_685_282],
                [1_075_184_065, 1_055_254_038],
                [1_065_994_831, 1_073_845_848],
                [1_065_992_186, 1_073_845_740],
            ]),
            alpha_beta: v(0.0, 1.0),
        },
        QuadCase {
            name: "midpoint of a 2-ulp edge",
            parameter: 2.2e7,
            quad: bits_quad([
                [3_200_739_966, 1_071_093_962],
                [1_114_242_872, 1_057_199_641],
                [1_105_605_703, 1_116_904_374],
                [1_105_605_701, 1_116_904_374],
            ]),
            alpha_beta: v(0.5, 1.0),
        },
    ];
    let tiny = TINY.into_iter().map(move |s| QuadCase {
        name: "tiny scale",
        parameter: s,
        quad: example.map(|c| c * s),
        alpha_beta: v(0.5, 0.25),
    });
    let offsets = OFFSETS.into_iter().map(move |o| QuadCase {
        name: "offset",
        parameter: o,
        quad: example.map(|c| c * 256.0 + Vec2::splat(o)),
        alpha_beta: v(0.5, 0.25),
    });
    fixed.into_iter().chain(tiny).chain(offsets)
}

/// Inputs with NaN or infinite coordinates: every public function must answer them with an
/// error, `None` or its documented value, never a panic.
pub const NON_FINITE: [f32; 4] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -f32::NAN];
