//! Byte layout and checks of the `hull3d` fuzz target (3D convex hull and `orient3d`).
//!
//! Byte 0 is the mode byte `m` (`kind = m & 7`, `k = (m >> 3) − 16`), then every 12 bytes are one
//! point: three little-endian `u32` words read as f32 bits (only whole points count, at most
//! [`HULL3D_MAX_POINTS`]). Kinds map the raw words onto geometry random bits almost never hit.

use std::fmt::Write as _;

use glam::Vec3;

use super::word;
use barytex_testkit::invariants_3d::{check_convex_hull_3d, check_orient3d};
use barytex_testkit::strategies::step_ulps;

/// The most points the `hull3d` target reads (validation is `O(n · F)`).
pub const HULL3D_MAX_POINTS: usize = 32;

/// Bytes the `hull3d` target reads: the mode byte and [`HULL3D_MAX_POINTS`] points.
pub const HULL3D_LEN: usize = 1 + 12 * HULL3D_MAX_POINTS;

/// The `hull3d` points. Kinds: 0 raw bits; 1 a 4³ integer grid (coordinate = word mod 4: many
/// coplanar, collinear and equal points); 2 a last-ulp cloud (coordinate = a base, from point 0's
/// first word, plus word mod 4 ulps); 3 integers below 2²⁴ times `2^(6k)` (scales 2⁻⁹⁶ … 2⁹⁰, so
/// 1e-30 and 1e30); 4 the exact plane `z = x + y` over an 8² grid with the last point `k` ulps
/// off in z; 5 directions normalized onto the unit sphere; 6 the line `t·(1, 2, 3)` with the last
/// point `k` ulps off in y; 7 a tilted plane `a + u(b − a) + v(c − a)` rounded to f32 (a nearly
/// coplanar slab), `a, b, c` and `u, v` in `[-1, 1]` from the words.
#[must_use]
pub fn hull3d_points(bytes: &[u8]) -> Vec<Vec3> {
    let n = (bytes.len().saturating_sub(1) / 12).min(HULL3D_MAX_POINTS);
    let body = bytes.get(1..).unwrap_or(&[]);
    let (kind, k) = super::mode(bytes, 0);
    let w = |i: usize, c: usize| word(body, 3 * i + c);
    let unit = |x: u32| (x as i32) as f32 / 2_147_483_648.0;
    let mut points: Vec<Vec3> = (0..n)
        .map(|i| {
            let c = |j: usize| w(i, j);
            match kind {
                1 => Vec3::new((c(0) % 4) as f32, (c(1) % 4) as f32, (c(2) % 4) as f32),
                2 => {
                    let base = (w(0, 0) & 0x7f7f_ffff).min(0x7f7f_fff0);
                    let f = |x: u32| f32::from_bits(base + x % 4);
                    Vec3::new(f(c(0)), f(c(1)), f(c(2)))
                }
                3 => {
                    let scale = 2f32.powi(6 * k);
                    let f = |x: u32| ((x as i32) >> 8) as f32 * scale;
                    Vec3::new(f(c(0)), f(c(1)), f(c(2)))
                }
                4 => {
                    let (x, y) = ((c(0) % 8) as f32, (c(1) % 8) as f32);
                    Vec3::new(x, y, x + y)
                }
                5 => {
                    let p = Vec3::new(unit(c(0)), unit(c(1)), unit(c(2))).as_dvec3();
                    let len = p.length();
                    if len > 0.0 {
                        (p / len).as_vec3()
                    } else {
                        Vec3::X
                    }
                }
                6 => Vec3::new(1.0, 2.0, 3.0) * ((c(0) % 64) as f32 - 32.0),
                7 => {
                    let corner = |j: usize| Vec3::new(unit(w(j, 0)), unit(w(j, 1)), unit(w(j, 2)));
                    let (a, b, cc) = (corner(0), corner(1), corner(2));
                    a + (b - a) * unit(c(0)) + (cc - a) * unit(c(1))
                }
                _ => Vec3::new(
                    f32::from_bits(c(0)),
                    f32::from_bits(c(1)),
                    f32::from_bits(c(2)),
                ),
            }
        })
        .collect();
    if let Some(last) = points.last_mut() {
        match kind {
            4 => last.z = step_ulps(last.z, k),
            6 => last.y = step_ulps(last.y, k),
            _ => {}
        }
    }
    points
}

/// The `hull3d` invariants: `check_convex_hull_3d` on the points and `check_orient3d` on the first
/// four (when there are four).
///
/// # Errors
/// The first violated invariant.
pub fn check_hull3d(bytes: &[u8]) -> Result<(), String> {
    let points = hull3d_points(bytes);
    if let [a, b, c, d, ..] = points[..] {
        check_orient3d(a, b, c, d)?;
    }
    check_convex_hull_3d(&points)
}

/// The `hull3d` input as a Rust block that re-runs its checks.
#[must_use]
pub fn hull3d_code(bytes: &[u8]) -> String {
    let points = hull3d_points(bytes);
    let mut out = String::from("{\n    let points = [\n");
    for p in &points {
        let _ = writeln!(
            out,
            "        Vec3::new(f32::from_bits({:#010x}), f32::from_bits({:#010x}), f32::from_bits({:#010x})), // {p:?}",
            p.x.to_bits(),
            p.y.to_bits(),
            p.z.to_bits(),
        );
    }
    out.push_str("    ];\n");
    if points.len() >= 4 {
        out.push_str("    check_orient3d(points[0], points[1], points[2], points[3]).unwrap();\n");
    }
    out.push_str("    check_convex_hull_3d(&points).unwrap();\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_decode_and_print() {
        let mut bytes = vec![1u8]; // kind 1: grid
        for x in [0u32, 1, 2, 3, 5, 6, 7, 9, 10, 11, 13, 14] {
            bytes.extend(x.to_le_bytes());
        }
        let points = hull3d_points(&bytes);
        assert_eq!(points.len(), 4);
        assert_eq!(points[1], Vec3::new(3.0, 1.0, 2.0));
        assert!(check_hull3d(&bytes).is_ok());
        let code = hull3d_code(&bytes);
        assert!(code.contains("check_convex_hull_3d(&points).unwrap();"));
        assert!(code.contains("Vec3::new(f32::from_bits(0x40400000), f32::from_bits(0x3f800000), f32::from_bits(0x40000000)), // Vec3(3.0, 1.0, 2.0)"));
        assert!(hull3d_points(&[]).is_empty());
        assert!(check_hull3d(&[7]).is_ok());
    }
}
