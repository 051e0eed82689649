//! Byte layout and checks of the `unwrap_pack` fuzz target: random and degenerate meshes
//! (duplicate vertices, zero-area triangles, repeated indices, non-manifold edges, every scale
//! from subnormal to huge) through `barytex_unwrap::unwrap`, which must never panic and must
//! return an atlas that passes the exact checks (no flip, no overlap, every uv in the square,
//! every triangle in exactly one chart), or a packing error.
//!
//! - byte 0: `m`; `m % 3` picks [`ChartMethod::Parameterize`] (default options),
//!   [`ChartMethod::PerTriangle`] or [`ChartMethod::TrianglePairs`]; bit 7 turns rotations off.
//! - byte 1: `s`; the atlas side is `16 · (1 + (s & 63))` texels, the padding `s >> 6` texels.
//! - byte 2: `e`; coordinates are scaled by `2^(8·(e & 31) − 128)` (subnormal to `2¹²⁰`).
//! - bytes 3 … 98: [`UNWRAP_PACK_VERTICES`] vertices, three `i8` coordinates each (a small
//!   integer grid: duplicates and collinear triples are common).
//! - the rest: triangles, three bytes each, indices modulo the vertex count (only complete
//!   triples, at most [`UNWRAP_PACK_MAX_TRIANGLES`]).

use barytex_unwrap::pack::{PackError, PackOptions};
use barytex_unwrap::{ChartMethod, UnwrapError, UnwrapMesh, UnwrapOptions, check_atlas, unwrap};
use glam::DVec3;

/// Vertices an input holds.
pub const UNWRAP_PACK_VERTICES: usize = 32;

/// The most triangles an input holds.
pub const UNWRAP_PACK_MAX_TRIANGLES: usize = 64;

/// Bytes the `unwrap_pack` target reads at most.
pub const UNWRAP_PACK_LEN: usize = 3 + 3 * UNWRAP_PACK_VERTICES + 3 * UNWRAP_PACK_MAX_TRIANGLES;

/// The input's mesh and options.
#[must_use]
pub fn unwrap_pack_input(bytes: &[u8]) -> (Vec<DVec3>, Vec<[u32; 3]>, UnwrapOptions) {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let (m, s, e) = (byte(0), byte(1), byte(2));
    let scale = 2f64.powi(8 * i32::from(e & 31) - 128);
    let positions: Vec<DVec3> = (0..UNWRAP_PACK_VERTICES)
        .map(|v| {
            let c = |k: usize| f64::from(byte(3 + 3 * v + k) as i8) * scale;
            DVec3::new(c(0), c(1), c(2))
        })
        .collect();
    let tail = bytes.get(3 + 3 * UNWRAP_PACK_VERTICES..).unwrap_or(&[]);
    let n = UNWRAP_PACK_VERTICES as u32;
    let triangles: Vec<[u32; 3]> = tail
        .chunks_exact(3)
        .take(UNWRAP_PACK_MAX_TRIANGLES)
        .map(|t| {
            [
                u32::from(t[0]) % n,
                u32::from(t[1]) % n,
                u32::from(t[2]) % n,
            ]
        })
        .collect();
    let charts = [
        ChartMethod::Parameterize,
        ChartMethod::PerTriangle,
        ChartMethod::TrianglePairs,
    ][usize::from(m % 3)];
    let options = UnwrapOptions {
        charts,
        pack: PackOptions {
            size: 16 * (1 + u32::from(s & 63)),
            padding: u32::from(s >> 6),
            rotate: m & 0x80 == 0,
        },
        ..UnwrapOptions::default()
    };
    (positions, triangles, options)
}

/// Unwraps the input and checks the atlas (see the module docs).
///
/// # Errors
/// The violated invariant.
pub fn check_unwrap_pack(bytes: &[u8]) -> Result<(), String> {
    let (positions, triangles, options) = unwrap_pack_input(bytes);
    let count = triangles.len();
    let mesh = UnwrapMesh::new(positions, triangles).map_err(|e| format!("mesh refused: {e}"))?;
    let atlas = match unwrap(&mesh, &options) {
        Ok(atlas) => atlas,
        Err(UnwrapError::Pack(PackError::TooManyCharts { .. })) => return Ok(()),
        Err(e) => return Err(format!("unwrap failed: {e}")),
    };
    if !atlas.check.is_valid() {
        return Err(format!(
            "the atlas fails the exact checks: {:?}",
            atlas.check
        ));
    }
    if check_atlas(&atlas.charts) != atlas.check {
        return Err("check_atlas disagrees with the pipeline's check".to_owned());
    }
    let mut seen = vec![0u32; count];
    for chart in &atlas.charts {
        for &f in &chart.faces {
            *seen
                .get_mut(f as usize)
                .ok_or_else(|| format!("chart face {f} out of range"))? += 1;
        }
    }
    if let Some(f) = seen.iter().position(|&k| k != 1) {
        return Err(format!("triangle {f} is in {} charts", seen[f]));
    }
    let eff = atlas.pack.efficiency;
    if !(0.0..=1.0).contains(&eff) {
        return Err(format!("packing efficiency {eff} outside [0, 1]"));
    }
    Ok(())
}
