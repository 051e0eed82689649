//! Byte layout and checks of the `polygon` fuzz target.
//!
//! | bytes  | meaning                                                                   |
//! |--------|---------------------------------------------------------------------------|
//! | 0..8   | `p`: two little-endian `u32` f32 bit patterns                             |
//! | 8..72  | up to 8 vertices, two words each                                          |
//! | 72     | mode byte `m`: `kind = m & 7`, `k = (m >> 3) − 16` ulps                   |
//! | 73     | vertex count `c % 9` (0 … 8: fewer than 3 is a valid, rejected input)     |
//!
//! Random bits almost never make a convex polygon, so kinds 1–5 build one on an ellipse
//! ([`polygon_on_ellipse`]): centre = raw vertex 0, radii = `|raw vertex 1|`, the angle gap
//! after vertex `i` is `1 + (top byte of vertex i's x word)`, start angle from `p.y`'s bits.
//! Kinds: 0, 6, 7 raw; 1 ellipse, `p` raw; 2 ellipse, `p` = vertex 0 moved `k` ulps in x;
//! 3 ellipse, `p` = midpoint of edge 0 moved `k` ulps in y; 4 ellipse, `p` a convex combination
//! with weights from the bytes of `p`'s words; 5 ellipse with vertex 1 replaced by the midpoint
//! of vertices 0 and 2 moved `k` ulps in x (nearly collinear consecutive vertices), `p` as in 4.

use std::fmt::Write as _;

use glam::Vec2;

use super::{code, mode, point, word};
use barytex_testkit::polygon_invariants::{check_polygon_all, polygon_on_ellipse};
use barytex_testkit::strategies::step_ulps;

/// Bytes the `polygon` target reads.
pub const POLYGON_LEN: usize = 74;

/// Decodes `(p, polygon)`.
#[must_use]
pub fn polygon_geometry(bytes: &[u8]) -> (Vec2, Vec<Vec2>) {
    let n = usize::from(bytes.get(73).copied().unwrap_or(0)) % 9;
    let raw: Vec<Vec2> = (0..n).map(|i| point(bytes, i + 1)).collect();
    let mut p = point(bytes, 0);
    let (kind, k) = mode(bytes, 72);
    if !(1..=5).contains(&kind) || n < 3 {
        return (p, raw);
    }
    let gaps: Vec<f64> = (0..n)
        .map(|i| 1.0 + f64::from(word(bytes, 2 * (i + 1)) >> 24))
        .collect();
    let start = f64::from(word(bytes, 1) >> 8) * (core::f64::consts::TAU / 16_777_216.0);
    let mut polygon = polygon_on_ellipse(raw[0], raw[1].abs(), start, &gaps);
    let convex_point = |polygon: &[Vec2]| {
        let bytes_of_p = [word(bytes, 0).to_le_bytes(), word(bytes, 1).to_le_bytes()].concat();
        let w: Vec<f64> = (0..polygon.len())
            .map(|i| 1.0 + f64::from(bytes_of_p[i % 8]))
            .collect();
        let total: f64 = w.iter().sum();
        let q = polygon
            .iter()
            .zip(&w)
            .fold(glam::DVec2::ZERO, |acc, (v, wi)| {
                acc + v.as_dvec2() * (wi / total)
            });
        q.as_vec2()
    };
    match kind {
        1 => {}
        2 => p = Vec2::new(step_ulps(polygon[0].x, k), polygon[0].y),
        3 => {
            let m = polygon[0] + (polygon[1] - polygon[0]) * 0.5;
            p = Vec2::new(m.x, step_ulps(m.y, k));
        }
        4 => p = convex_point(&polygon),
        _ => {
            let m = polygon[0] + (polygon[2] - polygon[0]) * 0.5;
            polygon[1] = Vec2::new(step_ulps(m.x, k), m.y);
            p = convex_point(&polygon);
        }
    }
    (p, polygon)
}

/// The `polygon` invariants: [`check_polygon_all`] (both methods, every documented property,
/// bit-identical rotation invariance).
///
/// # Errors
/// The first violated invariant.
pub fn check_polygon(bytes: &[u8]) -> Result<(), String> {
    let (p, polygon) = polygon_geometry(bytes);
    check_polygon_all(p, &polygon)
}

/// The `polygon` input as a Rust block that re-runs its check.
#[must_use]
pub fn polygon_code(bytes: &[u8]) -> String {
    let (p, polygon) = polygon_geometry(bytes);
    let mut out = format!("{{\n    let p = {}\n    let polygon = [\n", code(p, ';'));
    for v in polygon {
        let _ = writeln!(out, "        {}", code(v, ','));
    }
    out.push_str("    ];\n    check_polygon_all(p, &polygon).unwrap();\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_decodes_and_prints() {
        let mut bytes: Vec<u8> = [0.5f32, 0.5, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0]
            .iter()
            .flat_map(|x| x.to_bits().to_le_bytes())
            .collect();
        bytes.resize(POLYGON_LEN, 0);
        bytes[73] = 4;
        let (p, polygon) = polygon_geometry(&bytes);
        assert_eq!(p, Vec2::splat(0.5));
        assert_eq!(polygon, [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y]);
        assert_eq!(check_polygon(&bytes), Ok(()));
        assert!(polygon_code(&bytes).contains("check_polygon_all(p, &polygon).unwrap();"));
        // Kind 4: a convex polygon on an ellipse and a point inside it.
        bytes[72] = (16 << 3) | 4;
        bytes[16..24].copy_from_slice(&[0, 0, 128, 63, 0, 0, 0, 64]); // radii (1, 2)
        let (_, ellipse) = polygon_geometry(&bytes);
        assert_eq!(ellipse.len(), 4);
        assert_eq!(check_polygon(&bytes), Ok(()));
    }
}
