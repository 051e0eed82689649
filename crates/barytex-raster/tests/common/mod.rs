//! What several rasterizer test files share: a pipeline without depth or culling, a jittered
//! mesh that covers a target with no gaps and no overlaps, and a shader that counts the
//! fragments of each pixel.

#![allow(dead_code)] // Each test file uses its part.

use std::sync::atomic::{AtomicU32, Ordering};

use barytex_raster::{CullMode, Fragment, PipelineState, Shader};
use glam::{Vec2, Vec4};

/// Positions already in clip space; counts how often each pixel is shaded.
pub(crate) struct Counter {
    pub(crate) width: u32,
    pub(crate) counts: Vec<AtomicU32>,
}

impl Counter {
    pub(crate) fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            counts: (0..width * height).map(|_| AtomicU32::new(0)).collect(),
        }
    }
}

impl Shader for Counter {
    type Vertex = Vec4;
    type Varying = f32;
    fn vertex(&self, v: &Vec4) -> (Vec4, f32) {
        (*v, 0.0)
    }
    fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
        self.counts[(f.pixel.y * self.width + f.pixel.x) as usize].fetch_add(1, Ordering::Relaxed);
        Some(Vec4::ONE)
    }
}

/// No culling, no depth test, no depth writes.
pub(crate) fn no_depth() -> PipelineState {
    PipelineState {
        cull: CullMode::None,
        depth_compare: None,
        depth_write: false,
        ..PipelineState::default()
    }
}

/// A jittered grid of `n × n` cells spanning a `w × h` target and 4 pixels beyond each side
/// (screen pixels, y down), two triangles per cell. The border vertices stay on the grid and the
/// inner ones move by at most ±0.2 of a cell, which keeps every quad convex, so no triangle folds
/// over another: the mesh covers every point of the target exactly once.
pub(crate) fn jittered_grid(n: u32, w: u32, h: u32, seed: u64) -> (Vec<Vec2>, Vec<u32>) {
    let mut state = seed | 1;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32 - 0.5
    };
    let mut vertices = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let border = i == 0 || j == 0 || i == n || j == n;
            let jitter = if border {
                Vec2::ZERO
            } else {
                Vec2::new(next(), next()) * 0.4
            };
            vertices.push(
                (Vec2::new(i as f32, j as f32) + jitter) / n as f32
                    * Vec2::new(w as f32 + 8.0, h as f32 + 8.0)
                    - Vec2::splat(4.0),
            );
        }
    }
    let mut indices = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let v = |a: u32, b: u32| b * (n + 1) + a;
            indices.extend([v(i, j), v(i + 1, j), v(i + 1, j + 1)]);
            indices.extend([v(i, j), v(i + 1, j + 1), v(i, j + 1)]);
        }
    }
    (vertices, indices)
}
