//! Placing a boundary loop on a convex curve by arc length.

use glam::{DVec2, DVec3};

/// The convex curve a fixed-boundary embedding maps the boundary onto.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BoundaryShape {
    /// A circle whose circumference is the boundary's length. Strictly convex: three boundary
    /// vertices are never collinear, so Tutte's theorem applies with no extra condition.
    #[default]
    Circle,
    /// A square whose perimeter is the boundary's length. Only convex: a triangle with all three
    /// vertices on one side is degenerate (counted as flipped), as Floater (2003, "One-to-one
    /// piecewise linear mappings over triangulations", *Math. Comp.* 72) explains.
    Square,
}

/// Share of the parameter spacing given to the vertex count rather than arc length: it keeps
/// consecutive boundary vertices apart even when an edge has zero length.
const UNIFORM_SHARE: f64 = 0.05;

/// The positions of the loop's vertices on `shape`, counter-clockwise, spaced by 3-D arc length
/// (with [`UNIFORM_SHARE`] of uniform spacing), the curve's length equal to the loop's.
pub(crate) fn place_boundary(
    positions: &[DVec3],
    boundary: &[u32],
    shape: BoundaryShape,
) -> Vec<DVec2> {
    let n = boundary.len();
    let mut cumulative = Vec::with_capacity(n);
    let mut total = 0.0;
    for k in 0..n {
        cumulative.push(total);
        let a = positions[boundary[k] as usize];
        let b = positions[boundary[(k + 1) % n] as usize];
        total += (b - a).length();
    }
    let share = if total > 0.0 && total.is_finite() {
        UNIFORM_SHARE
    } else {
        1.0
    };
    let scale = if total > 0.0 && total.is_finite() {
        total
    } else {
        n as f64
    };
    cumulative
        .iter()
        .enumerate()
        .map(|(k, &s)| {
            let by_length = if share < 1.0 { s / total } else { 0.0 };
            let t = (1.0 - share) * by_length + share * (k as f64 / n as f64);
            match shape {
                BoundaryShape::Circle => {
                    let r = scale / core::f64::consts::TAU;
                    let (sin, cos) = (core::f64::consts::TAU * t).sin_cos();
                    DVec2::new(r * cos, r * sin)
                }
                BoundaryShape::Square => {
                    let side = scale / 4.0;
                    let s = 4.0 * t;
                    let (edge, f) = (s.floor().min(3.0), s - s.floor().min(3.0));
                    let h = 0.5 * side;
                    match edge as u8 {
                        0 => DVec2::new(-h + f * side, -h),
                        1 => DVec2::new(h, -h + f * side),
                        2 => DVec2::new(h - f * side, h),
                        _ => DVec2::new(-h, h - f * side),
                    }
                }
            }
        })
        .collect()
}
