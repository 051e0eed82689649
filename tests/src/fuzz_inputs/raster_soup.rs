//! Byte layout and checks of the `raster_soup` fuzz target: a soup of up to 8 triangles with
//! arbitrary clip-space coordinates drawn into a 16×16 target with an arbitrary scissor, culling,
//! depth test and interpolation mode.
//!
//! Layout: byte 0 state (bits 0–1 cull: none, back, front; bit 2 clockwise front; bit 3 depth
//! test; bit 4 affine; bit 5 blend over; bit 6 scissor), bytes 1–4 scissor x0, y0, x1, y1 (mod 17),
//! byte 5 mode: bits 0–2 kind 1 = the words are pixel positions on the 1/256 grid (a watertight
//! fan around the target's centre is drawn instead of the soup); bits 3–5 samples (1 sample, MSAA
//! standard 4, MSAA standard 16, 3×3 per-pixel jitter shaded per sample, 2×2 regular shaded per
//! sample, 4 standard with affine spans of 8); bits 6–7 the line topology of the second draw
//! (list, strip, loop, list); then 4 words (x, y, z, w as f32 bit patterns) per vertex, 3
//! vertices per triangle.
//!
//! Every input is drawn three times into fresh targets with the same state: as triangles, then
//! its vertices as points, then as lines of the topology above.

use std::fmt::Write as _;
use std::sync::atomic::{AtomicU32, Ordering};

use barytex_raster::{
    Blend, CullMode, DepthCompare, DrawStats, Fragment, Framebuffer, FrontFace, Interpolation,
    LineTopology, PipelineState, SamplePattern, Scissor, Shader, TargetLimits, draw, draw_lines,
    draw_points,
};
use glam::{Vec2, Vec4};

use super::word;

/// Side of the target.
pub const SIDE: u32 = 16;
/// Bytes the target reads: 6 header bytes and 8 triangles of 3 vertices of 4 words.
pub const RASTER_SOUP_LEN: usize = 6 + 8 * 3 * 16;

struct Recorder {
    /// Fragments whose pixel is outside the target.
    outside: AtomicU32,
    /// Fragments per pixel.
    counts: Vec<AtomicU32>,
    /// Coverage per pixel and sample (32 slots per pixel).
    samples: Vec<AtomicU32>,
}

impl Shader for Recorder {
    type Vertex = Vec4;
    type Varying = Vec2;
    fn vertex(&self, v: &Vec4) -> (Vec4, Vec2) {
        (*v, Vec2::new(v.x, v.y))
    }
    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        if f.pixel.x >= SIDE || f.pixel.y >= SIDE {
            self.outside.fetch_add(1, Ordering::Relaxed);
            return None;
        }
        let i = (f.pixel.y * SIDE + f.pixel.x) as usize;
        self.counts[i].fetch_add(1, Ordering::Relaxed);
        for k in 0..32 {
            if f.coverage & (1 << k) != 0 {
                self.samples[i * 32 + k].fetch_add(1, Ordering::Relaxed);
            }
        }
        let (dx, dy) = (f.ddx(), f.ddy());
        Some(Vec4::new(f.varying.x, dx.x, dy.y, 1.0))
    }
}

/// The decoded input: state, sample pattern, vertices, indices, whether it is the watertight
/// fan.
#[must_use]
pub fn raster_soup_input(
    bytes: &[u8],
) -> (PipelineState, SamplePattern, Vec<Vec4>, Vec<u32>, bool) {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let s = byte(0);
    let mut state = PipelineState {
        cull: [
            CullMode::None,
            CullMode::Back,
            CullMode::Front,
            CullMode::None,
        ][usize::from(s & 3)],
        front_face: if s & 4 != 0 {
            FrontFace::Cw
        } else {
            FrontFace::Ccw
        },
        depth_compare: (s & 8 != 0).then_some(DepthCompare::LessEqual),
        interpolation: if s & 16 != 0 {
            Interpolation::Affine
        } else {
            Interpolation::Perspective
        },
        blend: if s & 32 != 0 {
            Blend::Over
        } else {
            Blend::Replace
        },
        ..PipelineState::default()
    };
    if s & 64 != 0 {
        let c = |i| u32::from(byte(i) % 17);
        state.scissor = Some(Scissor {
            x0: c(1),
            y0: c(2),
            x1: c(3),
            y1: c(4),
        });
    }
    let (pattern, sample_shading) = match (byte(5) >> 3) & 7 {
        1 => (SamplePattern::Standard { count: 4 }, false),
        2 => (SamplePattern::Standard { count: 16 }, false),
        3 => (SamplePattern::Jittered { n: 3, seed: 9 }, true),
        4 => (SamplePattern::Regular { n: 2 }, true),
        5 => {
            if state.interpolation == Interpolation::Perspective {
                state.interpolation = Interpolation::AffineSpans { span: 8 };
            }
            (SamplePattern::Standard { count: 4 }, false)
        }
        _ => (SamplePattern::CENTRE, false),
    };
    state.sample_shading = sample_shading;
    let fan = byte(5) & 7 == 1;
    let count = bytes.len().saturating_sub(6) / 16;
    let words = |v: usize| -> [u32; 4] {
        core::array::from_fn(|k| word(&bytes[6.min(bytes.len())..], 4 * v + k))
    };
    if fan {
        // Rim points from the words (clamped to ±64 pixels on the 1/256 grid) around the centre:
        // consecutive rim points sorted by angle make non-overlapping triangles.
        let centre = Vec2::splat(SIDE as f32 / 2.0);
        let mut rim: Vec<Vec2> = (0..count.clamp(3, 24))
            .map(|v| {
                let w = words(v);
                let f = |x: u32| ((x % 32_768) as f32 / 256.0) - 64.0;
                centre + Vec2::new(f(w[0]), f(w[1]))
            })
            .filter(|p| *p != centre)
            .collect();
        rim.sort_by(|a, b| {
            let (da, db) = (*a - centre, *b - centre);
            da.y.atan2(da.x).total_cmp(&db.y.atan2(db.x))
        });
        rim.dedup_by(|a, b| {
            let (da, db) = (*a - centre, *b - centre);
            da.y.atan2(da.x) == db.y.atan2(db.x)
        });
        let to_clip = |p: Vec2| {
            Vec4::new(
                p.x / SIDE as f32 * 2.0 - 1.0,
                1.0 - p.y / SIDE as f32 * 2.0,
                0.5,
                1.0,
            )
        };
        let mut vertices = vec![to_clip(centre)];
        vertices.extend(rim.iter().map(|&p| to_clip(p)));
        let n = rim.len();
        // Only wedges turning counter-clockwise by less than π: a wedge across a gap of π or
        // more would cover the short way round, over its neighbours.
        let indices = (0..n)
            .filter(|&i| {
                let (a, b) = (rim[i] - centre, rim[(i + 1) % n] - centre);
                a.perp_dot(b) > 0.0
            })
            .flat_map(|i| [0, 1 + i as u32, 1 + ((i + 1) % n) as u32])
            .collect();
        state.cull = CullMode::None;
        state.depth_compare = None;
        return (state, pattern, vertices, indices, true);
    }
    let vertices: Vec<Vec4> = (0..count.min(24))
        .map(|v| Vec4::from_array(words(v).map(f32::from_bits)))
        .collect();
    let indices = (0..vertices.len() as u32).collect();
    (state, pattern, vertices, indices, false)
}

/// The line topology of the second draw (byte 5, bits 6–7).
fn line_topology(bytes: &[u8]) -> LineTopology {
    match bytes.get(5).copied().unwrap_or(0) >> 6 {
        1 => LineTopology::Strip,
        2 => LineTopology::Loop,
        _ => LineTopology::List,
    }
}

/// The invariants: no panic; no fragment outside the target or the scissor; every triangle,
/// point and line accounted for in the statistics; a fan of non-overlapping triangles covers
/// each sample at most once (watertight, no double coverage).
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_raster_soup(bytes: &[u8]) -> Result<(), String> {
    let (state, pattern, vertices, indices, fan) = raster_soup_input(bytes);
    let stats = |recorder: &Recorder,
                 what: &str,
                 draw_into: &dyn Fn(&mut Framebuffer, &Recorder) -> DrawStats| {
        let mut fb =
            Framebuffer::multisampled(SIDE, SIDE, pattern, Vec4::ZERO, &TargetLimits::default())
                .map_err(|e| e.to_string())?;
        let stats = draw_into(&mut fb, recorder);
        check_recorded(recorder, &state, pattern, fan && what == "triangles")
            .map_err(|e| format!("{what}: {e}"))?;
        Ok::<DrawStats, String>(stats)
    };
    let triangles = stats(&Recorder::new(), "triangles", &|fb, r| {
        draw(fb, r, &state, &vertices, &indices)
    })?;
    if triangles.triangles_in != (indices.len() / 3) as u64 {
        return Err(format!("{triangles:?} for {} indices", indices.len()));
    }
    let points = stats(&Recorder::new(), "points", &|fb, r| {
        draw_points(fb, r, &state, &vertices, &indices)
    })?;
    if points.points_in != indices.len() as u64 {
        return Err(format!("{points:?} for {} points", indices.len()));
    }
    let topology = line_topology(bytes);
    let lines = stats(&Recorder::new(), "lines", &|fb, r| {
        draw_lines(fb, r, &state, &vertices, &indices, topology)
    })?;
    let segments = topology.segments(&indices).len();
    if lines.lines_in != segments as u64 {
        return Err(format!("{lines:?} for {segments} {topology:?} segments"));
    }
    Ok(())
}

impl Recorder {
    fn new() -> Self {
        Self {
            outside: AtomicU32::new(0),
            counts: (0..SIDE * SIDE).map(|_| AtomicU32::new(0)).collect(),
            samples: (0..SIDE * SIDE * 32).map(|_| AtomicU32::new(0)).collect(),
        }
    }
}

/// What one draw recorded: nothing outside the target or the scissor, and (for a watertight
/// fan) no sample covered twice.
fn check_recorded(
    recorder: &Recorder,
    state: &PipelineState,
    pattern: SamplePattern,
    fan: bool,
) -> Result<(), String> {
    let outside = recorder.outside.load(Ordering::Relaxed);
    if outside > 0 {
        return Err(format!(
            "{outside} fragments outside the {SIDE}×{SIDE} target"
        ));
    }
    for (i, c) in recorder.counts.iter().enumerate() {
        let c = c.load(Ordering::Relaxed);
        let (x, y) = (i as u32 % SIDE, i as u32 / SIDE);
        if let Some(s) = state.scissor
            && c > 0
            && !(x >= s.x0 && x < s.x1 && y >= s.y0 && y < s.y1)
        {
            return Err(format!(
                "pixel ({x}, {y}) written outside the scissor {s:?}"
            ));
        }
        for k in 0..32 {
            let n = recorder.samples[i * 32 + k].load(Ordering::Relaxed);
            if fan && n > 1 {
                return Err(format!(
                    "sample {k} of pixel ({x}, {y}) covered {n} times by a fan ({pattern:?})"
                ));
            }
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn raster_soup_code(bytes: &[u8]) -> String {
    let (state, pattern, vertices, indices, fan) = raster_soup_input(bytes);
    let mut out = String::from("{\n");
    let topology = line_topology(bytes);
    let _ = writeln!(
        out,
        "    // {state:?}, {pattern:?}, fan = {fan}, lines {topology:?}"
    );
    let _ = writeln!(out, "    // vertices {vertices:?}, indices {indices:?}");
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_raster_soup(bytes), Ok(()));\n}");
    out
}
