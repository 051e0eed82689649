//! The byte layouts of the fuzz targets, decoded in one place: the targets in `fuzz/` and the
//! replay of `fuzz/regressions/<target>/` in the normal test suite both call these functions, so
//! a saved crash input means the same geometry to both.
//!
//! Every input is a run of little-endian `u32` words read as f32 bit patterns (NaNs, infinities,
//! subnormals and ±0 all reachable), then a mode byte `m`; missing bytes read as zero, so every
//! byte string is a valid input. `kind = m & 7` picks geometry that random bits almost never hit,
//! `k = (m >> 3) − 16` is an offset in ulps (−16 … 15).
//!
//! A failing input prints as a Rust block ([`orient_barycentric_code`],
//! [`inverse_bilinear_code`]) that a regression test can paste.

pub mod decoder_panics;
pub mod environment;
pub mod gltf_loader;
pub mod hull2d;
pub mod hull3d;
pub mod interp_3d;
pub mod load_path;
pub mod mip_generation;
pub mod png_jpeg_loader;
pub mod polygon;
pub mod raster_soup;
pub mod render_options;
pub mod sampling;
pub mod shade;
pub mod slerp;
pub mod textures_3d;
pub mod unwrap_pack;
pub mod unwrap_param;
pub mod uv_mappings;

use std::fmt::Write as _;

use glam::Vec2;

use barytex_testkit::invariants::{
    check_barycentric_2d, check_inverse_bilinear_2d, check_orient2d,
};
use barytex_testkit::strategies::step_ulps;

/// Bytes the `orient_barycentric` target reads: 8 words (p, a, b, c) and the mode byte.
pub const ORIENT_BARYCENTRIC_LEN: usize = 8 * 4 + 1;

/// Bytes the `inverse_bilinear` target reads: 10 words (p, x, y, z, w) and the mode byte.
pub const INVERSE_BILINEAR_LEN: usize = 10 * 4 + 1;

/// The little-endian `u32` word `w` of `bytes`, missing bytes reading as zero.
#[must_use]
pub fn word(bytes: &[u8], w: usize) -> u32 {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    u32::from_le_bytes(core::array::from_fn(|k| byte(4 * w + k)))
}

/// Point `i` of `bytes`: words `2i` and `2i + 1` as f32 bit patterns.
#[must_use]
pub fn point(bytes: &[u8], i: usize) -> Vec2 {
    Vec2::new(
        f32::from_bits(word(bytes, 2 * i)),
        f32::from_bits(word(bytes, 2 * i + 1)),
    )
}

/// The mode byte at `offset` split into `(kind, k)`.
#[must_use]
pub fn mode(bytes: &[u8], offset: usize) -> (u8, i32) {
    let m = bytes.get(offset).copied().unwrap_or(0);
    (m & 7, i32::from(m >> 3) - 16)
}

/// `orient_barycentric`: `(p, [a, b, c])`. Kinds: 1 `p` on vertex `a` moved `k` ulps in x;
/// 2 `p` at the midpoint of `ab` moved `k` ulps in y; 3 `c` there instead (a sliver); 4 `b` within
/// `k` ulps of `a` (a tiny edge); others raw.
#[must_use]
pub fn orient_barycentric_geometry(bytes: &[u8]) -> (Vec2, [Vec2; 3]) {
    let (mut p, a, mut b, mut c) = (
        point(bytes, 0),
        point(bytes, 1),
        point(bytes, 2),
        point(bytes, 3),
    );
    let (kind, k) = mode(bytes, 32);
    match kind {
        1 => p = Vec2::new(step_ulps(a.x, k), a.y),
        2 => {
            let m = a + (b - a) * 0.5;
            p = Vec2::new(m.x, step_ulps(m.y, k));
        }
        3 => {
            let m = a + (b - a) * 0.5;
            c = Vec2::new(m.x, step_ulps(m.y, k));
        }
        4 => b = Vec2::new(step_ulps(a.x, k), step_ulps(a.y, k)),
        _ => {}
    }
    (p, [a, b, c])
}

/// The `orient_barycentric` invariants: `check_orient2d` on the triangle and on the three
/// sub-triangles `barycentric_2d` classifies with, then `check_barycentric_2d`.
///
/// # Errors
/// The first violated invariant.
pub fn check_orient_barycentric(bytes: &[u8]) -> Result<(), String> {
    let (p, [a, b, c]) = orient_barycentric_geometry(bytes);
    for (q, r, s) in [(a, b, c), (b, c, p), (c, a, p), (a, b, p)] {
        check_orient2d(q, r, s)?;
    }
    check_barycentric_2d(p, [a, b, c])
}

/// `inverse_bilinear`: `(p, [x, y, z, w])`. Kinds: 1 `p` on corner `x` moved `k` ulps in x;
/// 2 `p` at the midpoint of edge `xy` moved `k` ulps in y; 3 `z` completing a parallelogram,
/// moved `k` ulps in x; 4 `p` on the surface at `(α, β)` from the top 24 bits of words 0 and 1,
/// moved `k` ulps in x; others raw.
#[must_use]
pub fn inverse_bilinear_geometry(bytes: &[u8]) -> (Vec2, [Vec2; 4]) {
    let mut p = point(bytes, 0);
    let mut quad = [
        point(bytes, 1),
        point(bytes, 2),
        point(bytes, 3),
        point(bytes, 4),
    ];
    let [x, y, _, w] = quad;
    let (kind, k) = mode(bytes, 40);
    match kind {
        1 => p = Vec2::new(step_ulps(x.x, k), x.y),
        2 => {
            let m = x + (y - x) * 0.5;
            p = Vec2::new(m.x, step_ulps(m.y, k));
        }
        3 => {
            let z = y + w - x;
            quad[2] = Vec2::new(step_ulps(z.x, k), z.y);
        }
        4 => {
            let unit = |bits: u32| (bits >> 8) as f32 * (1.0 / 16_777_216.0);
            let q = barytex_interp::bilinear(quad, unit(word(bytes, 0)), unit(word(bytes, 1)));
            p = Vec2::new(step_ulps(q.x, k), q.y);
        }
        _ => {}
    }
    (p, quad)
}

/// The `inverse_bilinear` invariant: `check_inverse_bilinear_2d`.
///
/// # Errors
/// The violated invariant.
pub fn check_inverse_bilinear(bytes: &[u8]) -> Result<(), String> {
    let (p, quad) = inverse_bilinear_geometry(bytes);
    check_inverse_bilinear_2d(p, quad)
}

/// `Vec2::new(f32::from_bits(0x…), f32::from_bits(0x…))` followed by `term` (`;` or `,`) and
/// the values as a comment.
fn code(v: Vec2, term: char) -> String {
    format!(
        "Vec2::new(f32::from_bits({:#010x}), f32::from_bits({:#010x})){term} // ({:?}, {:?})",
        v.x.to_bits(),
        v.y.to_bits(),
        v.x,
        v.y
    )
}

/// The `orient_barycentric` input as a Rust block that re-runs its checks.
#[must_use]
pub fn orient_barycentric_code(bytes: &[u8]) -> String {
    let (p, [a, b, c]) = orient_barycentric_geometry(bytes);
    let mut out = String::from("{\n");
    for (name, v) in [("p", p), ("a", a), ("b", b), ("c", c)] {
        let _ = writeln!(out, "    let {name} = {}", code(v, ';'));
    }
    out.push_str("    for (q, r, s) in [(a, b, c), (b, c, p), (c, a, p), (a, b, p)] {\n");
    out.push_str("        check_orient2d(q, r, s).unwrap();\n    }\n");
    out.push_str("    check_barycentric_2d(p, [a, b, c]).unwrap();\n}");
    out
}

/// The `inverse_bilinear` input as a Rust block that re-runs its check.
#[must_use]
pub fn inverse_bilinear_code(bytes: &[u8]) -> String {
    let (p, quad) = inverse_bilinear_geometry(bytes);
    let mut out = format!("{{\n    let p = {}\n    let quad = [\n", code(p, ';'));
    for c in quad {
        let _ = writeln!(out, "        {}", code(c, ','));
    }
    out.push_str("    ];\n    check_inverse_bilinear_2d(p, quad).unwrap();\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_print_as_rust_code() {
        let bytes: Vec<u8> = [1.0f32, 2.0, 0.0, 0.0, 4.0, 0.0, 0.0, 4.0]
            .iter()
            .flat_map(|x| x.to_bits().to_le_bytes())
            .collect();
        let code = orient_barycentric_code(&bytes);
        assert!(code.contains(
            "let p = Vec2::new(f32::from_bits(0x3f800000), f32::from_bits(0x40000000)); // (1.0, 2.0)"
        ));
        assert!(code.contains("check_barycentric_2d(p, [a, b, c]).unwrap();"));
        assert!(check_orient_barycentric(&bytes).is_ok());
        let code = inverse_bilinear_code(&[]);
        assert!(code.contains("check_inverse_bilinear_2d(p, quad).unwrap();"));
    }
}
