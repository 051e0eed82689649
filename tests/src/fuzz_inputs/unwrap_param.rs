//! Byte layout and checks of the `unwrap_param` fuzz target (mesh parameterization).
//!
//! Layout: byte 0 the geometry kind (`& 7`); byte 1 the options (`% 5` the method — LscmArap,
//! Lscm, MeanValue, Tutte, Harmonic; bit 3 welding off; bit 4 non-manifold rejected; bit 5 the
//! square boundary); byte 2 the vertex count (`% 33`); byte 3 the extra triangle count (`% 65`);
//! then [`UNWRAP_MAX_POINTS`] points of three little-endian `u32` words from offset 4, and from
//! offset [`UNWRAP_TRIANGLES_AT`] [`UNWRAP_MAX_TRIANGLES`] triangles of three index bytes (taken
//! modulo the vertex count). Missing bytes read as zero, so every byte string is an input.
//!
//! Kinds: 0 raw f32 bits (NaN and infinities reach `UnwrapMesh::new`, which must refuse them);
//! 1 a 4³ integer grid (many equal, collinear and coplanar points: duplicates, zero areas);
//! 2 integers below 2²⁴ times `2^(6k)` with `k` from point 0's first word (1e-30 … 1e30);
//! 3 a lifted `g × g` grid (`g` from the vertex count) with heights from the words;
//! 4 a sphere, 5 a torus, 6 a subdivided cube, sizes from the vertex count; 7 the unit-circle
//! points `(cos, sin, word-height)`. Kinds 3–6 use the generated mesh's own vertices and
//! triangles; the extra triangles (non-manifold edges, repeated indices, flipped duplicates) are
//! appended to every kind.

use std::fmt::Write as _;

use barytex_unwrap::{
    BoundaryShape, Method, NonManifold, ParamOptions, UnwrapError, UnwrapMesh, flipped_triangles,
    parameterize_with_report, shapes,
};
use glam::DVec3;

use super::word;

/// Points read.
pub const UNWRAP_MAX_POINTS: usize = 32;

/// Extra triangles read.
pub const UNWRAP_MAX_TRIANGLES: usize = 64;

/// Offset of the triangle bytes.
pub const UNWRAP_TRIANGLES_AT: usize = 4 + 12 * UNWRAP_MAX_POINTS;

/// Bytes the `unwrap_param` target reads.
pub const UNWRAP_PARAM_LEN: usize = UNWRAP_TRIANGLES_AT + 3 * UNWRAP_MAX_TRIANGLES;

/// The decoded input: positions, triangles and options.
#[must_use]
pub fn unwrap_param_input(bytes: &[u8]) -> (Vec<DVec3>, Vec<[u32; 3]>, ParamOptions) {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let kind = byte(0) & 7;
    let flags = byte(1);
    let method = [
        Method::LscmArap,
        Method::Lscm,
        Method::MeanValue,
        Method::Tutte,
        Method::Harmonic,
    ][usize::from(flags % 5)];
    let options = ParamOptions {
        method,
        weld: flags & 8 == 0,
        non_manifold: if flags & 16 == 0 {
            NonManifold::Cut
        } else {
            NonManifold::Reject
        },
        boundary: if flags & 32 == 0 {
            BoundaryShape::Circle
        } else {
            BoundaryShape::Square
        },
        max_iterations: 5,
        ..ParamOptions::default()
    };
    let nv = usize::from(byte(2)) % (UNWRAP_MAX_POINTS + 1);
    let body = bytes.get(4..).unwrap_or(&[]);
    let w = |i: usize, c: usize| word(body, 3 * i + c);
    let unit = |x: u32| f64::from(x as i32) / 2_147_483_648.0;
    let size = (nv as u32).max(1);
    let (mut positions, mut triangles): (Vec<DVec3>, Vec<[u32; 3]>) = match kind {
        3 => {
            let g = size.min(6);
            let m = shapes::grid(g, g, |_, _| 0.0);
            let p = m
                .positions()
                .iter()
                .enumerate()
                .map(|(i, p)| p.with_z(unit(w(i % UNWRAP_MAX_POINTS, 0))))
                .collect();
            (p, m.triangles().to_vec())
        }
        4..=6 => {
            let m = match kind {
                4 => shapes::sphere(2 + size % 6, 3 + size % 8),
                5 => shapes::torus(
                    1.0,
                    0.25 + 0.5 * unit(w(0, 0)).abs(),
                    3 + size % 8,
                    3 + size % 6,
                ),
                _ => shapes::cube(1 + size % 3),
            };
            (m.positions().to_vec(), m.triangles().to_vec())
        }
        _ => {
            let p = (0..nv)
                .map(|i| {
                    let c = |j: usize| w(i, j);
                    match kind {
                        1 => DVec3::new(
                            f64::from(c(0) % 4),
                            f64::from(c(1) % 4),
                            f64::from(c(2) % 4),
                        ),
                        2 => {
                            let k = (w(0, 0) % 32) as i32 - 16;
                            let f = |x: u32| f64::from((x as i32) >> 8) * 2f64.powi(6 * k);
                            DVec3::new(f(c(0)), f(c(1)), f(c(2)))
                        }
                        7 => {
                            let a = core::f64::consts::TAU * i as f64 / nv as f64;
                            DVec3::new(a.cos(), a.sin(), unit(c(0)))
                        }
                        _ => DVec3::new(
                            f64::from(f32::from_bits(c(0))),
                            f64::from(f32::from_bits(c(1))),
                            f64::from(f32::from_bits(c(2))),
                        ),
                    }
                })
                .collect();
            (p, Vec::new())
        }
    };
    if positions.is_empty() {
        positions.push(DVec3::ZERO);
    }
    let n = positions.len();
    let extra = usize::from(byte(3)) % (UNWRAP_MAX_TRIANGLES + 1);
    for t in 0..extra {
        let at = UNWRAP_TRIANGLES_AT + 3 * t;
        triangles.push(core::array::from_fn(|k| {
            (usize::from(byte(at + k)) % n) as u32
        }));
    }
    (positions, triangles, options)
}

/// The `unwrap_param` invariants: `UnwrapMesh::new` refuses exactly the non-finite inputs;
/// `parameterize_with_report` succeeds (under `NonManifold::Reject` it may refuse a
/// non-manifold mesh, with that error); every triangle is in exactly one chart, with its own
/// vertices in order; every uv is finite; no chart has a flipped triangle (exact `orient2d`).
///
/// # Errors
/// The first violated invariant.
pub fn check_unwrap_param(bytes: &[u8]) -> Result<(), String> {
    let (positions, triangles, options) = unwrap_param_input(bytes);
    let finite = positions.iter().all(|p| p.is_finite());
    let mesh = match UnwrapMesh::new(positions, triangles) {
        Ok(mesh) if finite => mesh,
        Ok(_) => return Err("UnwrapMesh::new accepted a non-finite position".into()),
        Err(UnwrapError::NonFinite { .. }) if !finite => return Ok(()),
        Err(e) => return Err(format!("UnwrapMesh::new refused a valid mesh: {e}")),
    };
    let p = match parameterize_with_report(&mesh, &options) {
        Ok(p) => p,
        Err(UnwrapError::NonManifoldEdge { .. } | UnwrapError::NonManifoldVertex { .. })
            if options.non_manifold == NonManifold::Reject =>
        {
            return Ok(());
        }
        Err(e) => return Err(format!("parameterize failed: {e}")),
    };
    let mut seen = vec![0u32; mesh.triangles().len()];
    for (c, chart) in p.charts.iter().enumerate() {
        if chart.faces.len() != chart.triangles.len() || chart.vertices.len() != chart.uvs.len() {
            return Err(format!("chart {c}: inconsistent lengths"));
        }
        if let Some(uv) = chart.uvs.iter().find(|uv| !uv.is_finite()) {
            return Err(format!("chart {c}: non-finite uv {uv}"));
        }
        let flips = flipped_triangles(chart);
        if flips != 0 {
            return Err(format!("chart {c}: {flips} flipped triangles"));
        }
        for (j, &f) in chart.faces.iter().enumerate() {
            let Some(slot) = seen.get_mut(f as usize) else {
                return Err(format!("chart {c}: face {f} out of range"));
            };
            *slot += 1;
            let mapped = chart.triangles[j].map(|v| chart.vertices.get(v as usize).copied());
            if mapped != mesh.triangles()[f as usize].map(Some) {
                return Err(format!("chart {c}: triangle {j} does not match face {f}"));
            }
        }
    }
    if let Some(f) = seen.iter().position(|&s| s != 1) {
        return Err(format!("face {f} is in {} charts", seen[f]));
    }
    Ok(())
}

/// The decoded input as Rust code that rebuilds the mesh and options.
#[must_use]
pub fn unwrap_param_code(bytes: &[u8]) -> String {
    let (positions, triangles, options) = unwrap_param_input(bytes);
    let mut out = String::from("let positions = vec![\n");
    for p in &positions {
        let _ = writeln!(
            out,
            "    DVec3::new(f64::from_bits({:#x}), f64::from_bits({:#x}), f64::from_bits({:#x})), // {p}",
            p.x.to_bits(),
            p.y.to_bits(),
            p.z.to_bits()
        );
    }
    let _ = writeln!(
        out,
        "];\nlet triangles = vec!{triangles:?};\nlet options = {options:?};"
    );
    out
}
