//! The draw call: vertex stage, primitive assembly, clipping, culling, fixed-point setup,
//! binning to tiles, and tiles rasterized and shaded in parallel — bit-identical output for any
//! thread count, because every tile processes its triangles in submission order and owns its
//! pixels.

use barytex_interp::Interpolate;
use barytex_texture::sampler::CompareFunction;
use glam::{UVec2, Vec2, Vec3, Vec4};
use rayon::prelude::*;

use crate::clip::{ClipVertex, clip, inside};
use crate::edge::EdgeSetup;
use crate::shader::PieceContext;
use crate::state::{Blend, CullMode, FrontFace, PipelineState, Viewport};
use crate::target::{Framebuffer, premultiply};
use crate::{Fragment, Shader};

/// Tile side in pixels.
pub const TILE: u32 = 64;

/// What a draw did: every triangle in is accounted for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct DrawStats {
    /// Triangles submitted (index triples).
    pub triangles_in: u64,
    /// Dropped: an index out of range.
    pub dropped_bad_index: u64,
    /// Dropped: a NaN or infinite clip-space coordinate.
    pub dropped_non_finite: u64,
    /// Entirely outside the near/far planes or the guard band after clipping.
    pub clipped_away: u64,
    /// Triangles that crossed a clip plane and were clipped (drawn in pieces).
    pub clipped: u64,
    /// Culled by facing.
    pub culled: u64,
    /// Zero area after snapping to the sub-pixel grid.
    pub degenerate: u64,
    /// Fragments the fragment stage ran for.
    pub fragments_shaded: u64,
    /// Fragments it discarded.
    pub fragments_discarded: u64,
    /// Fragments that failed the depth test.
    pub fragments_depth_failed: u64,
}

impl DrawStats {
    fn add(&mut self, other: &Self) {
        self.fragments_shaded += other.fragments_shaded;
        self.fragments_discarded += other.fragments_discarded;
        self.fragments_depth_failed += other.fragments_depth_failed;
    }
}

/// A tile's rendering: its rectangle, its colour and depth, and its fragment counts.
struct TileResult {
    rect: [i64; 4],
    color: Vec<Vec4>,
    depth: Vec<f32>,
    stats: DrawStats,
}

/// One screen-space piece of an input triangle.
struct Piece<V> {
    edge: EdgeSetup,
    /// Depth at the piece's vertices.
    depth: [f64; 3],
    front: bool,
    context: PieceContext<V>,
}

fn depth_passes(op: CompareFunction, fragment: f32, stored: f32) -> bool {
    match op {
        CompareFunction::Never => false,
        CompareFunction::Less => fragment < stored,
        CompareFunction::Equal => fragment == stored,
        CompareFunction::LessEqual => fragment <= stored,
        CompareFunction::Greater => fragment > stored,
        CompareFunction::NotEqual => fragment != stored,
        CompareFunction::GreaterEqual => fragment >= stored,
        CompareFunction::Always => true,
    }
}

/// Draws indexed triangles (`indices` in triples) into `target` and returns what happened.
///
/// Runs on the current rayon thread pool; the output is bit-identical for any number of threads.
/// Nothing panics on bad input: out-of-range indices, non-finite or huge positions, zero-area and
/// fully clipped triangles are dropped and counted in [`DrawStats`].
pub fn draw<S: Shader>(
    target: &mut Framebuffer,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
) -> DrawStats {
    let mut stats = DrawStats::default();
    let shaded: Vec<(Vec4, S::Varying)> = vertices.par_iter().map(|v| shader.vertex(v)).collect();
    let viewport = state
        .viewport
        .unwrap_or_else(|| Viewport::full(target.width(), target.height()));
    let mut pieces: Vec<Piece<S::Varying>> = Vec::new();
    for tri in indices.chunks_exact(3) {
        stats.triangles_in += 1;
        let Some(input) = tri
            .iter()
            .map(|&i| shaded.get(i as usize).copied())
            .collect::<Option<Vec<_>>>()
        else {
            stats.dropped_bad_index += 1;
            continue;
        };
        let positions = [input[0].0, input[1].0, input[2].0];
        let varyings = [input[0].1, input[1].1, input[2].1];
        if positions.iter().any(|p| !p.is_finite()) {
            stats.dropped_non_finite += 1;
            continue;
        }
        let polygon = if inside(&positions) {
            positions
                .iter()
                .zip([Vec3::X, Vec3::Y, Vec3::Z])
                .map(|(&position, bary)| ClipVertex { position, bary })
                .collect()
        } else {
            stats.clipped += 1;
            clip(&positions)
        };
        if polygon.len() < 3 {
            stats.clipped_away += 1;
            continue;
        }
        // Facing from the whole polygon's NDC area (y up): positive is counter-clockwise.
        let ndc: Vec<Vec3> = polygon
            .iter()
            .map(|v| v.position.truncate() / v.position.w)
            .collect();
        let area: f32 = (0..ndc.len())
            .map(|i| {
                let (p, q) = (ndc[i], ndc[(i + 1) % ndc.len()]);
                p.x * q.y - q.x * p.y
            })
            .sum();
        let ccw = area > 0.0;
        let front = match state.front_face {
            FrontFace::Ccw => ccw,
            FrontFace::Cw => !ccw,
        };
        if (state.cull == CullMode::Back && !front) || (state.cull == CullMode::Front && front) {
            stats.culled += 1;
            continue;
        }
        let to_screen = |v: &ClipVertex, n: Vec3| {
            (
                Vec2::new(
                    viewport.x + (n.x + 1.0) * 0.5 * viewport.width,
                    viewport.y + (1.0 - n.y) * 0.5 * viewport.height,
                ),
                f64::from(viewport.min_depth)
                    + f64::from(n.z) * f64::from(viewport.max_depth - viewport.min_depth),
                1.0 / f64::from(v.position.w),
            )
        };
        let mut drawn = false;
        for k in 1..polygon.len() - 1 {
            let ids = [0, k, k + 1];
            let s = ids.map(|i| to_screen(&polygon[i], ndc[i]));
            let Some(edge) = EdgeSetup::new(s.map(|v| v.0)) else {
                continue;
            };
            drawn = true;
            let (g0, g1, g2) = edge.gradients();
            let bary = ids.map(|i| polygon[i].bary);
            pieces.push(Piece {
                edge,
                depth: s.map(|v| v.1),
                front,
                context: PieceContext {
                    varyings,
                    grads: [g0, g1, g2],
                    inv_w: s.map(|v| v.2),
                    bary: (bary != [Vec3::X, Vec3::Y, Vec3::Z]).then_some(bary),
                    interpolation: state.interpolation,
                },
            });
        }
        if !drawn {
            stats.degenerate += 1;
        }
    }
    // The rectangle that may be written: target ∩ viewport ∩ scissor.
    let (w, h) = (i64::from(target.width()), i64::from(target.height()));
    let mut rect = [0, 0, w, h];
    let vp = [
        viewport.x.floor() as i64,
        viewport.y.floor() as i64,
        (viewport.x + viewport.width).ceil() as i64,
        (viewport.y + viewport.height).ceil() as i64,
    ];
    rect = [
        rect[0].max(vp[0]),
        rect[1].max(vp[1]),
        rect[2].min(vp[2]),
        rect[3].min(vp[3]),
    ];
    if let Some(s) = state.scissor {
        rect = [
            rect[0].max(i64::from(s.x0)),
            rect[1].max(i64::from(s.y0)),
            rect[2].min(i64::from(s.x1)),
            rect[3].min(i64::from(s.y1)),
        ];
    }
    if rect[0] >= rect[2] || rect[1] >= rect[3] || pieces.is_empty() {
        return stats;
    }
    // Bin pieces to tiles in submission order.
    let tile = i64::from(TILE);
    let (tiles_x, tiles_y) = ((w + tile - 1) / tile, (h + tile - 1) / tile);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); (tiles_x * tiles_y) as usize];
    for (id, piece) in pieces.iter().enumerate() {
        let b = piece.edge.bbox;
        let (x0, y0) = (b[0].max(rect[0]), b[1].max(rect[1]));
        let (x1, y1) = (b[2].min(rect[2]), b[3].min(rect[3]));
        if x0 >= x1 || y0 >= y1 {
            continue;
        }
        for ty in y0 / tile..=(y1 - 1) / tile {
            for tx in x0 / tile..=(x1 - 1) / tile {
                bins[(ty * tiles_x + tx) as usize].push(id as u32);
            }
        }
    }
    let width = target.width() as usize;
    let color = &target.color;
    let depth = &target.depth;
    let results: Vec<TileResult> = bins
        .par_iter()
        .enumerate()
        .filter(|(_, bin)| !bin.is_empty())
        .map(|(index, bin)| {
            let (tx, ty) = (index as i64 % tiles_x, index as i64 / tiles_x);
            let t = [
                (tx * tile).max(rect[0]),
                (ty * tile).max(rect[1]),
                ((tx + 1) * tile).min(rect[2]),
                ((ty + 1) * tile).min(rect[3]),
            ];
            let tw = (t[2] - t[0]).max(0) as usize;
            let th = (t[3] - t[1]).max(0) as usize;
            let mut local_color = Vec::with_capacity(tw * th);
            let mut local_depth = Vec::with_capacity(tw * th);
            for y in t[1]..t[3] {
                let row = y as usize * width;
                local_color.extend_from_slice(&color[row + t[0] as usize..row + t[2] as usize]);
                local_depth.extend_from_slice(&depth[row + t[0] as usize..row + t[2] as usize]);
            }
            let mut tile_stats = DrawStats::default();
            for &id in bin {
                shade_piece(
                    &pieces[id as usize],
                    shader,
                    state,
                    t,
                    tw,
                    &mut local_color,
                    &mut local_depth,
                    &mut tile_stats,
                );
            }
            TileResult {
                rect: t,
                color: local_color,
                depth: local_depth,
                stats: tile_stats,
            }
        })
        .collect();
    for TileResult {
        rect: t,
        color: local_color,
        depth: local_depth,
        stats: tile_stats,
    } in results
    {
        let tw = (t[2] - t[0]) as usize;
        for (row, y) in (t[1]..t[3]).enumerate() {
            let start = y as usize * width + t[0] as usize;
            target.color[start..start + tw].copy_from_slice(&local_color[row * tw..(row + 1) * tw]);
            target.depth[start..start + tw].copy_from_slice(&local_depth[row * tw..(row + 1) * tw]);
        }
        stats.add(&tile_stats);
    }
    stats
}

/// Rasterizes and shades one piece inside tile rectangle `t` (local buffers `tw` wide).
#[allow(clippy::too_many_arguments)]
fn shade_piece<S: Shader>(
    piece: &Piece<S::Varying>,
    shader: &S,
    state: &PipelineState,
    t: [i64; 4],
    tw: usize,
    color: &mut [Vec4],
    depth: &mut [f32],
    stats: &mut DrawStats,
) {
    let context = &piece.context;
    piece.edge.for_each_covered(t, |x, y, lambda| {
        let index = (y - t[1]) as usize * tw + (x - t[0]) as usize;
        let z = (0..3).map(|i| lambda[i] * piece.depth[i]).sum::<f64>() as f32;
        if let Some(op) = state.depth_compare
            && !depth_passes(op, z, depth[index])
        {
            stats.fragments_depth_failed += 1;
            return;
        }
        let weights = context.input_weights(context.weights(lambda));
        let fragment = Fragment {
            varying: S::Varying::combine3(context.varyings, weights),
            depth: z,
            pixel: UVec2::new(x as u32, y as u32),
            front_facing: piece.front,
            lambda,
            piece: context,
        };
        stats.fragments_shaded += 1;
        let Some(c) = shader.fragment(&fragment) else {
            stats.fragments_discarded += 1;
            return;
        };
        let src = premultiply(c);
        color[index] = match state.blend {
            Blend::Replace => src,
            Blend::Over => src + color[index] * (1.0 - src.w),
        };
        if state.depth_write {
            depth[index] = z;
        }
    });
}
