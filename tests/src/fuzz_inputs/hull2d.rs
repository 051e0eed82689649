//! Byte layout and checks of the `hull2d` fuzz target.
//!
//! Byte 0 is the mode byte `m`: `kind = m & 7`, `e = m >> 3` (0 … 31). The rest is decoded by
//! kind into at most [`HULL2D_MAX_POINTS`] points:
//!
//! - 1 (grid): byte pairs `(i8, i8)` are integer points times `2^(8e − 128)` (from subnormal
//!   `2⁻¹²⁸` to `2¹²⁰`): duplicates and long collinear runs at every scale.
//! - 2 (ulp cluster): a base point from the first 8 bytes (two f32 bit patterns), then byte pairs
//!   `(i8, i8)`, each shifted right by 4, step the base by −8 … 7 ulps per coordinate.
//! - 3 (rounded segment): endpoints `a`, `b` from the first 16 bytes, then each byte `t` gives
//!   `a + (b − a)·(t / 255)` in f32 (each within rounding of the line).
//! - 4 (exact line plus apex): `d`, `o` and `apex` as `(i8, i8)` from the first 6 bytes, then each
//!   byte `t` (as i8) gives `(o + t·d)·2^(8e − 128)`; the apex is the last point.
//! - 0, 5–7 (raw): 8-byte groups are points as two f32 bit patterns (NaN, infinities,
//!   subnormals and ±0 all reachable).

use std::fmt::Write as _;

use glam::Vec2;

use super::point;
use barytex_testkit::invariants::check_convex_hull_2d;
use barytex_testkit::strategies::step_ulps;

/// The most points an input decodes to (the invariant compares up to
/// [`HULL_2D_BRUTE_FORCE_MAX`](barytex_testkit::invariants::HULL_2D_BRUTE_FORCE_MAX) of them with the
/// brute-force hull).
pub const HULL2D_MAX_POINTS: usize = 48;

/// Bytes the `hull2d` target reads at most.
pub const HULL2D_LEN: usize = 1 + 8 * HULL2D_MAX_POINTS;

/// `2^(8e − 128)` for `e` in 0 … 31, exact in f32 (subnormal at the bottom).
fn scale(e: u8) -> f32 {
    2f64.powi(8 * i32::from(e) - 128) as f32
}

/// The `hull2d` input's points (see the module docs for the layout).
#[must_use]
pub fn hull2d_points(bytes: &[u8]) -> Vec<Vec2> {
    let m = bytes.first().copied().unwrap_or(0);
    let (kind, e) = (m & 7, m >> 3);
    let body = bytes.get(1..).unwrap_or(&[]);
    let pairs = |from: usize| {
        body.get(from..)
            .unwrap_or(&[])
            .chunks_exact(2)
            .map(|c| (c[0] as i8, c[1] as i8))
    };
    let mut points: Vec<Vec2> = match kind {
        1 => pairs(0)
            .map(|(x, y)| Vec2::new(f32::from(x), f32::from(y)) * scale(e))
            .collect(),
        2 => {
            let base = point(body, 0);
            pairs(8)
                .map(|(x, y)| {
                    Vec2::new(
                        step_ulps(base.x, i32::from(x >> 4)),
                        step_ulps(base.y, i32::from(y >> 4)),
                    )
                })
                .collect()
        }
        3 => {
            let (a, b) = (point(body, 0), point(body, 1));
            body.get(16..)
                .unwrap_or(&[])
                .iter()
                .map(|&t| a + (b - a) * (f32::from(t) / 255.0))
                .collect()
        }
        4 => {
            let byte = |i: usize| f32::from(body.get(i).copied().unwrap_or(0) as i8);
            let (d, o, apex) = (
                Vec2::new(byte(0), byte(1)),
                Vec2::new(byte(2), byte(3)),
                Vec2::new(byte(4), byte(5)),
            );
            body.get(6..)
                .unwrap_or(&[])
                .iter()
                .map(|&t| (o + d * f32::from(t as i8)) * scale(e))
                .chain(std::iter::once(apex * scale(e)))
                .collect()
        }
        _ => (0..body.len() / 8).map(|i| point(body, i)).collect(),
    };
    points.truncate(HULL2D_MAX_POINTS);
    points
}

/// The `hull2d` invariant: [`check_convex_hull_2d`] on the decoded points.
///
/// # Errors
/// The violated invariant.
pub fn check_hull2d(bytes: &[u8]) -> Result<(), String> {
    check_convex_hull_2d(&hull2d_points(bytes))
}

/// The `hull2d` input as a Rust block that re-runs its check.
#[must_use]
pub fn hull2d_code(bytes: &[u8]) -> String {
    let mut out = String::from("{\n    let points = [\n");
    for p in hull2d_points(bytes) {
        let _ = writeln!(
            out,
            "        Vec2::new(f32::from_bits({:#010x}), f32::from_bits({:#010x})), // ({:?}, {:?})",
            p.x.to_bits(),
            p.y.to_bits(),
            p.x,
            p.y
        );
    }
    out.push_str("    ];\n    check_convex_hull_2d(&points).unwrap();\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_decode_and_print() {
        // Grid kind at e = 16: scale 1.
        let grid = [(16 << 3) | 1, 1, 2, 0xff, 0];
        assert_eq!(
            hull2d_points(&grid),
            vec![Vec2::new(1.0, 2.0), Vec2::new(-1.0, 0.0)]
        );
        assert!(check_hull2d(&grid).is_ok());
        let code = hull2d_code(&grid);
        assert!(code.contains(
            "Vec2::new(f32::from_bits(0x3f800000), f32::from_bits(0x40000000)), // (1.0, 2.0)"
        ));
        assert!(code.contains("check_convex_hull_2d(&points).unwrap();"));
        // Exact line plus apex at scale 1: d = (1, 1), o = (0, 0), apex = (0, 5), t = 0, 1, 2.
        let line = [(16 << 3) | 4, 1, 1, 0, 0, 0, 5, 0, 1, 2];
        assert_eq!(hull2d_points(&line).len(), 4);
        assert!(check_hull2d(&line).is_ok());
        assert!(hull2d_points(&[]).is_empty());
    }
}
