//! The draw call: vertex stage, primitive assembly, clipping, culling, fixed-point setup,
//! binning to tiles, and tiles rasterized and shaded in parallel — bit-identical output for any
//! thread count, because every tile processes its triangles in submission order and owns its
//! pixels.

use glam::Vec4;
use rayon::prelude::*;

use crate::Shader;
use crate::format::ColorFormat;
use crate::pieces::{Pieces, assemble_parallel};
use crate::state::{PipelineState, Viewport};
use crate::target::{Framebuffer, TILE};
use crate::tile::{TileTarget, shade_piece};

/// What a draw did: every triangle in is accounted for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct DrawStats {
    /// Triangles submitted (index triples).
    pub triangles_in: u64,
    /// Points submitted ([`draw_points`](crate::draw_points)).
    pub points_in: u64,
    /// Line segments submitted ([`draw_lines`](crate::draw_lines); a strip or loop counted
    /// segment by segment).
    pub lines_in: u64,
    /// Dropped: an index out of range.
    pub dropped_bad_index: u64,
    /// Dropped: a NaN or infinite clip-space coordinate.
    pub dropped_non_finite: u64,
    /// Entirely outside the near/far planes or the guard band after clipping (a point: outside
    /// the view volume).
    pub clipped_away: u64,
    /// Triangles that crossed a clip plane and were clipped (drawn in pieces).
    pub clipped: u64,
    /// Culled by facing (triangles only: points and lines face the viewer).
    pub culled: u64,
    /// Zero area (a triangle) or zero length (a line segment) after snapping to the sub-pixel
    /// grid, or a point beyond [`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub degenerate: u64,
    /// Fragments the fragment stage ran for.
    pub fragments_shaded: u64,
    /// Fragments it discarded.
    pub fragments_discarded: u64,
    /// Fragments that failed the depth test.
    pub fragments_depth_failed: u64,
}

/// Field by field: the statistics of several draws (or of a draw's tiles) summed.
impl core::ops::AddAssign<&DrawStats> for DrawStats {
    fn add_assign(&mut self, other: &Self) {
        self.triangles_in += other.triangles_in;
        self.points_in += other.points_in;
        self.lines_in += other.lines_in;
        self.dropped_bad_index += other.dropped_bad_index;
        self.dropped_non_finite += other.dropped_non_finite;
        self.clipped_away += other.clipped_away;
        self.clipped += other.clipped;
        self.culled += other.culled;
        self.degenerate += other.degenerate;
        self.fragments_shaded += other.fragments_shaded;
        self.fragments_discarded += other.fragments_discarded;
        self.fragments_depth_failed += other.fragments_depth_failed;
    }
}

/// The rectangle `[x0, y0, x1, y1)` that a draw may write: target ∩ viewport ∩ scissor.
pub(crate) fn writable_rect<C: ColorFormat>(
    target: &Framebuffer<C>,
    state: &PipelineState,
    viewport: Viewport,
) -> [i64; 4] {
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
    rect
}

/// How many pieces ahead a tile's loop asks for a piece's setup: each piece is a cache miss
/// otherwise (the pieces are visited in tile order, not in the order they were built).
const PREFETCH_AHEAD: usize = 4;

/// `target.clear(color)` then [`draw`], bit for bit, in one pass over the target's memory:
/// each tile is cleared by the job that draws it, just before, so that its lines are still in
/// the cache when its triangles are drawn (the clear of a tiled GPU or of Mesa's llvmpipe, a
/// render pass's "load op clear" in Vulkan and WebGPU). The mask is kept (as by
/// [`Framebuffer::clear`]: every sample is cleared, masked or not).
///
/// ```
/// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw,
///     draw_cleared};
/// use glam::{Vec3, Vec4};
///
/// struct White;
/// impl Shader for White {
///     type Vertex = Vec3;
///     type Varying = f32;
///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), 0.0) }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(Vec4::ONE) }
/// }
/// let tri = [Vec3::new(-1.0, -1.0, 0.5), Vec3::new(1.0, -1.0, 0.5), Vec3::new(-1.0, 1.0, 0.5)];
/// let (limits, state) = (TargetLimits::default(), PipelineState::default());
/// let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
/// let mut a = Framebuffer::new(70, 70, Vec4::ONE, &limits)?;
/// a.clear(red);
/// let stats_a = draw(&mut a, &White, &state, &tri, &[0, 1, 2]);
/// let mut b = Framebuffer::new(70, 70, Vec4::ONE, &limits)?;
/// let stats_b = draw_cleared(&mut b, red, &White, &state, &tri, &[0, 1, 2]);
/// assert_eq!(stats_a, stats_b);
/// assert_eq!(b.pixel(69, 0), Some(red)); // cleared, not drawn
/// assert_eq!(b.pixel(0, 69), Some(Vec4::ONE)); // drawn
/// assert!((0..70).all(|y| (0..70).all(|x| a.pixel(x, y) == b.pixel(x, y))));
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
pub fn draw_cleared<S: Shader, C: ColorFormat>(
    target: &mut Framebuffer<C>,
    color: Vec4,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
) -> DrawStats {
    draw_tiles(target, Some(color), shader, state, vertices, indices)
}

/// A tile with work: its index and its slices of the colour and depth buffers.
type TileJob<'a, C> = (usize, (&'a mut [<C as ColorFormat>::Sample], &'a mut [f32]));

/// Draws indexed triangles (`indices` in triples) into `target` and returns what happened.
///
/// The target may store its colour in any [`ColorFormat`] (the float default, or 4 bytes per
/// sample with [`Rgba8Unorm`](crate::Rgba8Unorm)); coverage, depth and the fragments shaded do
/// not depend on it.
///
/// Runs on the current rayon thread pool; the output is bit-identical for any number of threads.
/// Nothing panics on bad input: out-of-range indices, non-finite or huge positions, zero-area and
/// fully clipped triangles are dropped and counted in [`DrawStats`]. Memory: besides the shaded
/// vertices and the triangles' clipped pieces (both proportional to the input), the tiles'
/// lists of pieces are held to 64 MiB; a scene whose lists would be longer (many triangles
/// each over many tiles) is drawn in batches of consecutive triangles, with the same result.
///
/// ```
/// use barytex_raster::{DepthCompare, DrawStats, Fragment, Framebuffer, PipelineState, Shader,
///     TargetLimits, draw};
/// use glam::{Vec3, Vec4};
///
/// /// Clip-space positions, one colour per draw.
/// struct Solid(Vec4);
/// impl Shader for Solid {
///     type Vertex = Vec3;
///     type Varying = f32;
///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), 0.0) }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(self.0) }
/// }
/// let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
/// let blue = Vec4::new(0.0, 0.0, 1.0, 1.0);
/// // The lower-left half of the screen at depth 0.5 and a full-screen triangle behind it.
/// let near = [Vec3::new(-1.0, -1.0, 0.5), Vec3::new(1.0, -1.0, 0.5), Vec3::new(-1.0, 1.0, 0.5)];
/// let far = [Vec3::new(-1.0, -1.0, 0.9), Vec3::new(3.0, -1.0, 0.9), Vec3::new(-1.0, 3.0, 0.9)];
/// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
/// let state = PipelineState { depth_compare: Some(DepthCompare::Less), ..PipelineState::default() };
/// let mut stats = draw(&mut fb, &Solid(red), &state, &near, &[0, 1, 2]);
/// // Index 7 does not exist: that triangle is dropped and counted, not a panic.
/// stats += &draw(&mut fb, &Solid(blue), &state, &far, &[0, 1, 2, 0, 1, 7]);
/// assert_eq!(fb.pixel(0, 7), Some(red)); // bottom-left: the near triangle wins the depth test
/// assert_eq!(fb.depth(0, 7), Some(0.5));
/// assert_eq!(fb.pixel(7, 0), Some(blue)); // top-right: only the far one
/// assert_eq!(stats.triangles_in, 3);
/// assert_eq!(stats.dropped_bad_index, 1);
/// // The near triangle covers the 28 pixels with x < y (the centres on the diagonal lie on its
/// // right edge, which the top-left rule leaves out); there the far one fails the depth test.
/// assert_eq!(stats.fragments_depth_failed, 28);
/// assert_eq!(stats.fragments_shaded, 28 + (64 - 28));
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
pub fn draw<S: Shader, C: ColorFormat>(
    target: &mut Framebuffer<C>,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
) -> DrawStats {
    draw_tiles(target, None, shader, state, vertices, indices)
}

/// The most bin entries (a piece's index in one tile's list, 4 bytes) a draw holds at once:
/// 64 MiB. Bins hold pieces × tiles entries, a product no input size bounds (a million
/// full-screen triangles on a 4096² target would need 16 GiB), so a draw whose bins would grow
/// past this is drawn in batches of consecutive pieces, each batch's tiles before the next's:
/// every tile still draws its pieces in submission order, so the output does not change.
const MAX_BIN_ENTRIES: usize = 1 << 24;

/// [`draw`], and with `clear` the clear of every tile: that colour and depth 1 written by each
/// tile's job before it draws (every tile has a job then), or by [`Framebuffer::clear`] when the
/// draw has nothing to draw.
fn draw_tiles<S: Shader, C: ColorFormat>(
    target: &mut Framebuffer<C>,
    clear: Option<Vec4>,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
) -> DrawStats {
    draw_batched(
        target,
        clear,
        shader,
        state,
        (vertices, indices),
        MAX_BIN_ENTRIES,
    )
}

/// [`draw_tiles`] with bins of at most `max_entries` entries (or one piece's tiles, when that is
/// more) at a time.
fn draw_batched<S: Shader, C: ColorFormat>(
    target: &mut Framebuffer<C>,
    clear: Option<Vec4>,
    shader: &S,
    state: &PipelineState,
    (vertices, indices): (&[S::Vertex], &[u32]),
    max_entries: usize,
) -> DrawStats {
    let mut stats = DrawStats::default();
    let shaded: Vec<(Vec4, S::Varying)> = vertices.par_iter().map(|v| shader.vertex(v)).collect();
    let viewport = state
        .viewport
        .unwrap_or_else(|| Viewport::full(target.width(), target.height()));
    let pieces = assemble_parallel(&shaded, indices, state, viewport, &mut stats);
    let rect = writable_rect(target, state, viewport);
    if rect[0] >= rect[2] || rect[1] >= rect[3] || pieces.len() == 0 {
        if let Some(color) = clear {
            target.clear(color);
        }
        return stats;
    }
    let mut bins = Bins::new(target, rect);
    let mut clear = clear.map(C::store);
    let mut next = 0;
    while next < pieces.len() {
        next = bins.fill(&pieces, next, max_entries);
        debug_assert!(bins.entries <= max_entries.max(bins.pieces.len()));
        stats += &draw_bins(target, clear, shader, state, (&shaded, &pieces), &bins);
        // Later batches draw over the first one's clear.
        clear = None;
        bins.empty();
    }
    stats
}

/// The union of no boxes: any box's union with it is that box.
const NO_EXTENT: [i64; 4] = [i64::MAX, i64::MAX, i64::MIN, i64::MIN];

/// Each tile's pieces, in submission order, and the union of their boxes.
struct Bins {
    /// The pixels a draw may write, `[x0, y0, x1, y1)`.
    rect: [i64; 4],
    tiles_x: i64,
    /// Per tile, its pieces' indices.
    pieces: Vec<Vec<u32>>,
    /// Per tile, the union of its pieces' boxes (clipped to the tile when used).
    extents: Vec<[i64; 4]>,
    /// Entries in `pieces`.
    entries: usize,
}

impl Bins {
    fn new<C: ColorFormat>(target: &Framebuffer<C>, rect: [i64; 4]) -> Self {
        let tile = i64::from(TILE);
        let tiles_x = i64::from(target.tiles_x());
        let tiles_y = (i64::from(target.height()) + tile - 1) / tile;
        let count = (tiles_x * tiles_y) as usize;
        Self {
            rect,
            tiles_x,
            pieces: vec![Vec::new(); count],
            extents: vec![NO_EXTENT; count],
            entries: 0,
        }
    }

    /// Bins the pieces from position `first` (in submission order) on, in order, until the next
    /// piece would take the entries past `max_entries` (the first always goes in: one piece's
    /// entries are at most the tile count); returns the position of the first piece not binned.
    fn fill(&mut self, pieces: &Pieces, first: usize, max_entries: usize) -> usize {
        let tile = i64::from(TILE);
        let rect = self.rect;
        for (ordinal, (id, piece)) in pieces.iter().enumerate().skip(first) {
            let b = piece.edge.bbox;
            let (x0, y0) = (b[0].max(rect[0]), b[1].max(rect[1]));
            let (x1, y1) = (b[2].min(rect[2]), b[3].min(rect[3]));
            if x0 >= x1 || y0 >= y1 {
                continue;
            }
            // Unsigned (the box is inside the target, so not negative): a shift.
            let tile_of = |v: i64| (v as u64 / tile as u64) as i64;
            let (tx0, ty0, tx1, ty1) = (tile_of(x0), tile_of(y0), tile_of(x1 - 1), tile_of(y1 - 1));
            let entries = ((tx1 - tx0 + 1) * (ty1 - ty0 + 1)) as usize;
            if self.entries > 0 && self.entries + entries > max_entries {
                return ordinal;
            }
            self.entries += entries;
            for ty in ty0..=ty1 {
                for tx in tx0..=tx1 {
                    let index = (ty * self.tiles_x + tx) as usize;
                    self.pieces[index].push(id);
                    let e = &mut self.extents[index];
                    *e = [e[0].min(x0), e[1].min(y0), e[2].max(x1), e[3].max(y1)];
                }
            }
        }
        pieces.len()
    }

    /// Empties every bin, keeping its memory for the next batch.
    fn empty(&mut self) {
        for bin in &mut self.pieces {
            bin.clear();
        }
        self.extents.fill(NO_EXTENT);
        self.entries = 0;
    }
}

/// The tiles' jobs for the pieces in `bins` (every tile when clearing, else those with work).
fn draw_bins<S: Shader, C: ColorFormat>(
    target: &mut Framebuffer<C>,
    clear: Option<C::Sample>,
    shader: &S,
    state: &PipelineState,
    (shaded, pieces): (&[(Vec4, S::Varying)], &Pieces),
    bins: &Bins,
) -> DrawStats {
    let mut stats = DrawStats::default();
    let (rect, tiles_x) = (bins.rect, bins.tiles_x);
    let tile = i64::from(TILE);
    let pattern = target.pattern();
    let samples = target.samples();
    let tile_pixels = (TILE * TILE) as usize;
    let tile_samples = tile_pixels * samples as usize;
    let mask = target.mask.as_deref();
    // Each tile owns a contiguous slice of the tile-major buffers: no copies, no locks. Only
    // the tiles with work become jobs, one tile each: rayon's adaptive splitting over all the
    // target's tiles handed out runs of tiles, and where an object covers part of the image
    // one thread got most of the work (Suzanne at 1024², 2 threads: 74 % against 26 %).
    let jobs: Vec<TileJob<'_, C>> = target
        .color
        .chunks_mut(tile_samples)
        .zip(target.depth.chunks_mut(tile_samples))
        .enumerate()
        .filter(|(index, _)| clear.is_some() || !bins.pieces[*index].is_empty())
        .collect();
    let job = |(index, (color, depth)): TileJob<'_, C>| {
        let (tx, ty) = (index as i64 % tiles_x, index as i64 / tiles_x);
        let mut tile_target = TileTarget::<C> {
            rect: [
                (tx * tile).max(rect[0]),
                (ty * tile).max(rect[1]),
                ((tx + 1) * tile).min(rect[2]),
                ((ty + 1) * tile).min(rect[3]),
            ],
            origin: (tx * tile, ty * tile),
            color,
            depth,
            mask: mask.map(|m| &m[index * tile_pixels..(index + 1) * tile_pixels]),
            pattern,
            samples,
        };
        let mut stats = DrawStats::default();
        // A clear here, just before the tile is drawn, leaves its lines in the cache for it
        // (and needs no `touch`): one pass over the target's memory instead of two.
        if let Some(color) = clear {
            tile_target.color.fill(color);
            tile_target.depth.fill(1.0);
        }
        if tile_target.mask.is_some_and(|m| !m.contains(&true)) {
            return stats;
        }
        let bin = &bins.pieces[index];
        if clear.is_none() {
            tile_target.touch(bins.extents[index]);
        }
        for (k, &id) in bin.iter().enumerate() {
            if let Some(&ahead) = bin.get(k + PREFETCH_AHEAD) {
                pieces.get(ahead).prefetch();
            }
            // Half as far ahead, the varyings of a piece whose indices that asked for.
            if let Some(&ahead) = bin.get(k + PREFETCH_AHEAD / 2) {
                pieces.get(ahead).prefetch_varyings(shaded);
            }
            shade_piece(
                pieces.get(id),
                shaded,
                shader,
                state,
                &mut tile_target,
                &mut stats,
            );
        }
        stats
    };
    // One thread: a plain loop. Rayon's split of 256 one-tile jobs into joins costs ~4 % of a
    // raster-only draw of small triangles there, and buys nothing.
    if rayon::current_num_threads() == 1 {
        for tile in jobs {
            stats += &job(tile);
        }
        return stats;
    }
    let tile_stats: Vec<DrawStats> = jobs.into_par_iter().with_max_len(1).map(job).collect();
    for t in &tile_stats {
        stats += t;
    }
    stats
}

#[cfg(test)]
mod tests;
