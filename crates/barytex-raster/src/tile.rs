//! One tile's work: the covered pixels (or samples) of a piece, the depth test, the fragment
//! stage and blending, into the tile's own slice of the target.

use barytex_interp::Interpolate;
use glam::{UVec2, Vec4};

use crate::assemble::Piece;
use crate::draw::DrawStats;
use crate::format::ColorFormat;
use crate::paired::shade_centres_paired;
use crate::run_depth::for_each_run_pixel;
use crate::samples::SamplePattern;
use crate::shader::PieceContext;
use crate::state::{Blend, DepthCompare, Interpolation, PipelineState};
use crate::target::{TILE, premultiply};
use crate::{Fragment, Shader};

/// The pixels of a tile (its buffers' length at one sample per pixel).
pub(crate) const TILE_PIXELS: usize = (TILE * TILE) as usize;

/// A tile's slice of the target and what it needs to address it.
pub(crate) struct TileTarget<'a, C: ColorFormat> {
    /// `[x0, y0, x1, y1)`: the tile's pixels that may be written.
    pub(crate) rect: [i64; 4],
    /// The tile's top-left pixel.
    pub(crate) origin: (i64, i64),
    pub(crate) color: &'a mut [C::Sample],
    pub(crate) depth: &'a mut [f32],
    /// One flag per pixel (tile-local), `None`: every pixel.
    pub(crate) mask: Option<&'a [bool]>,
    pub(crate) pattern: SamplePattern,
    pub(crate) samples: u32,
}

impl<C: ColorFormat> TileTarget<'_, C> {
    #[inline]
    fn local(&self, x: i64, y: i64) -> usize {
        ((y - self.origin.1) * i64::from(TILE) + (x - self.origin.0)) as usize
    }

    /// Reads one depth and one colour sample per cache line of the tile's pixels in `extent`
    /// (the union of the boxes of the pieces to draw there), in address order, before the
    /// pieces are drawn.
    ///
    /// The pieces read the depth at scattered pixels, each read a dependency of its pixel's
    /// depth test, and write the colour there; with small triangles the lines came one miss at
    /// a time, from beyond the L2 cache (a clear has just written the whole target). Read in
    /// order, independently of each other, they stream in together (the hardware prefetcher
    /// follows), and the pieces then find them in the cache: on 10k random 20-pixel triangles
    /// at 1024², a fifth off the draw. (Software prefetches of the same lines, all at once or
    /// a few pieces ahead, gained nothing there.)
    #[inline]
    pub(crate) fn touch(&self, extent: [i64; 4]) {
        const LINE: usize = 64;
        let x0 = extent[0].max(self.rect[0]);
        let y0 = extent[1].max(self.rect[1]);
        let x1 = extent[2].min(self.rect[2]);
        let y1 = extent[3].min(self.rect[3]);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let samples = self.samples as usize;
        let per_line = (LINE / core::mem::size_of::<C::Sample>()).max(1);
        let mut bits = 0_u32;
        for y in y0..y1 {
            let (first, end) = (
                self.local(x0, y) * samples,
                (self.local(x1 - 1, y) + 1) * samples,
            );
            // Every line once (the last sample too: a row need not start on a line).
            let mut i = first;
            while i < end {
                bits |= self.depth[i].to_bits();
                i += LINE / 4;
            }
            bits |= self.depth[end - 1].to_bits();
            let mut i = first;
            while i < end {
                core::hint::black_box(self.color[i]);
                i += per_line;
            }
            core::hint::black_box(self.color[end - 1]);
        }
        core::hint::black_box(bits);
    }
}

#[inline]
pub(crate) fn blend(state: &PipelineState, src: Vec4, dst: Vec4) -> Vec4 {
    match state.blend {
        Blend::Replace => src,
        Blend::Over => src + dst * (1.0 - src.w),
    }
}

/// [`blend`] of the premultiplied `src` over a stored sample, stored back in format `C`.
#[inline]
fn blend_stored<C: ColorFormat>(state: &PipelineState, src: Vec4, dst: C::Sample) -> C::Sample {
    C::store_premultiplied(blend(state, src, C::load(dst)))
}

/// The perspective-correct weights at the two ends of the current span, for affine spans.
struct SpanCache {
    row: i64,
    start: i64,
    /// The span's ends, clamped to the row's covered pixels.
    range: (i64, i64),
    ends: [[f64; 3]; 2],
}

/// Rasterizes and shades one piece into the tile.
pub(crate) fn shade_piece<S: Shader, C: ColorFormat>(
    piece: &Piece,
    shaded: &[(Vec4, S::Varying)],
    shader: &S,
    state: &PipelineState,
    tile: &mut TileTarget<'_, C>,
    stats: &mut DrawStats,
) {
    let context = &piece.context(shaded);
    if tile.samples == 1 {
        shade_single(piece, context, shader, state, tile, stats);
    } else {
        shade_multi(piece, context, shader, state, tile, stats);
    }
}

/// One sample per pixel, at its centre.
fn shade_single<S: Shader, C: ColorFormat>(
    piece: &Piece,
    context: &PieceContext<S::Varying>,
    shader: &S,
    state: &PipelineState,
    tile: &mut TileTarget<'_, C>,
    stats: &mut DrawStats,
) {
    if let Interpolation::AffineSpans { span } = state.interpolation {
        shade_spans(
            piece,
            context,
            shader,
            state,
            tile,
            stats,
            i64::from(span.clamp(2, 256)),
        );
        return;
    }
    // The depth test, the depth write, the mask and the blend resolved once per piece, not
    // per pixel: the common cases get their own loop (the comparison a single instruction,
    // the blend and the depth write a store, no mask to read).
    let write = state.depth_write;
    let keep_depth = move |z: f32, stored: f32| if write { z } else { stored };
    match (
        state.depth_compare,
        state.blend,
        tile.mask.is_none() && write,
    ) {
        (Some(DepthCompare::Less), Blend::Replace, true) => {
            let (test, store) = (|z, s| z < s, |z, _| z);
            shade_centres::<S, C, false, false>(piece, context, shader, tile, stats, test, store);
        }
        (Some(DepthCompare::LessEqual), Blend::Replace, true) => {
            let (test, store) = (|z, s| z <= s, |z, _| z);
            shade_centres::<S, C, false, false>(piece, context, shader, tile, stats, test, store);
        }
        (Some(DepthCompare::Less), Blend::Over, _) => {
            let test = |z, s| z < s;
            shade_centres::<S, C, true, true>(
                piece, context, shader, tile, stats, test, keep_depth,
            );
        }
        (op, Blend::Replace, _) => {
            let test = |z, s| op.is_none_or(|op: DepthCompare| op.passes(z, s));
            shade_centres::<S, C, false, true>(
                piece, context, shader, tile, stats, test, keep_depth,
            );
        }
        (op, Blend::Over, _) => {
            let test = |z, s| op.is_none_or(|op: DepthCompare| op.passes(z, s));
            shade_centres::<S, C, true, true>(
                piece, context, shader, tile, stats, test, keep_depth,
            );
        }
    }
}

/// The covered pixel centres of a piece: the tile's mask (if `MASKED`), depth test
/// `passes(fragment, stored)`, the fragment stage, replace (`OVER` false) or "over" blending,
/// and `store(fragment, stored)` into the depth buffer. Perspective-correct or affine weights;
/// the results are those of [`blend`] and [`DepthCompare::passes`] pixel by pixel.
#[inline]
fn shade_centres<S: Shader, C: ColorFormat, const OVER: bool, const MASKED: bool>(
    piece: &Piece,
    context: &PieceContext<S::Varying>,
    shader: &S,
    tile: &mut TileTarget<'_, C>,
    stats: &mut DrawStats,
    passes: impl Fn(f32, f32) -> bool,
    store: impl Fn(f32, f32) -> f32,
) {
    if S::PAIRS
        && let Ok(color) = <&mut [C::Sample; TILE_PIXELS]>::try_from(&mut *tile.color)
        && let Ok(depth) = <&mut [f32; TILE_PIXELS]>::try_from(&mut *tile.depth)
    {
        let target = (tile.rect, tile.origin, tile.mask);
        // One call, spelled once, for both builds below (a closure in a `let` cannot carry
        // `#[inline(always)]` on stable Rust, and the AVX2 build needs it inlined).
        macro_rules! paired {
            () => {
                shade_centres_paired::<S, C, OVER, MASKED>(
                    piece,
                    context,
                    shader,
                    target,
                    (color, depth),
                    stats,
                    passes,
                    store,
                )
            };
        }
        // The AVX2 + FMA build where allowed and present (`cpu_features`): everything the
        // loop calls is inlined into it, so compiled for those features; the same results.
        // Only for the common state (replace, depth written, no mask): each build of the loop
        // is compile time, for every shader and format (CI took 48 min with all four).
        #[cfg(target_arch = "x86_64")]
        if !OVER
            && !MASKED
            && let Some(simd) = crate::cpu_features::v3()
        {
            return simd.vectorize(
                #[inline(always)]
                || paired!(),
            );
        }
        return paired!();
    }
    let depths = piece.depth;
    let inv_area = piece.edge.inv_area();
    let (ox, oy) = tile.origin;
    let mask = tile.mask.filter(|_| MASKED);
    let front_facing = piece.front;
    let color = &mut *tile.color;
    let depth = &mut *tile.depth;
    // Fragments shaded = pixels visited − masked − failed (one counter per pixel less).
    let (mut visited, mut skipped, mut discarded, mut failed) = (0_u64, 0_u64, 0_u64, 0_u64);
    // A covered centre not masked out, at pixel `(x, y)` with weights `λ` and depth `z`.
    let mut pixel =
        |color: &mut C::Sample, stored: &mut f32, xy, lambda, z| match shade_pixel::<S, C, OVER>(
            shader,
            context,
            front_facing,
            (color, stored),
            xy,
            (lambda, z),
            (&passes, &store),
        ) {
            Outcome::Failed => failed += 1,
            Outcome::Discarded => discarded += 1,
            Outcome::Written => {}
        };
    #[cfg(target_arch = "x86_64")]
    if let Some(small) = piece.edge.small_box(tile.rect)
        && let Ok(color) = <&mut [C::Sample; TILE_PIXELS]>::try_from(&mut *color)
        && let Ok(depth) = <&mut [f32; TILE_PIXELS]>::try_from(&mut *depth)
    {
        // A narrow box: its covered centres from bit masks, without the spans' setup and loops.
        // The tile's buffers as arrays and the index reduced modulo their length (a no-op for
        // a pixel of the tile): no bounds checks in the pixel loop (four per pair of pixels,
        // an eighth of its instructions).
        small.for_each_covered(
            inv_area,
            depths,
            #[inline(always)]
            |x, y, lambda, z| {
                let index = ((y - oy) * i64::from(TILE) + (x - ox)) as usize % TILE_PIXELS;
                visited += 1;
                if MASKED && mask.is_some_and(|keep| !keep[index]) {
                    skipped += 1;
                    return;
                }
                pixel(&mut color[index], &mut depth[index], (x, y), lambda, z);
            },
        );
        stats.fragments_shaded += visited - skipped - failed;
        stats.fragments_discarded += discarded;
        stats.fragments_depth_failed += failed;
        return;
    }
    let step = piece.edge.x_step();
    let area2 = piece.edge.area2();
    piece
        .edge
        .for_each_covered_span(tile.rect, |y, (xs, xe), e| {
            // The span's slices of the tile's rows.
            let start = ((y - oy) * i64::from(TILE) + (xs - ox)) as usize;
            let len = (xe - xs) as usize;
            let keep = mask.map(|m| &m[start..start + len]);
            let color = &mut color[start..start + len];
            let depth = &mut depth[start..start + len];
            visited += len as u64;
            // Edge j is opposite input vertex j: its value is that vertex's weight.
            for_each_run_pixel(e, step, area2, inv_area, depths, len, |k, lambda, z| {
                if MASKED && keep.is_some_and(|keep| !keep[k]) {
                    skipped += 1;
                    return;
                }
                pixel(&mut color[k], &mut depth[k], (xs + k as i64, y), lambda, z);
            });
        });
    stats.fragments_shaded += visited - skipped - failed;
    stats.fragments_discarded += discarded;
    stats.fragments_depth_failed += failed;
}

/// What became of a covered centre in [`shade_pixel`].
enum Outcome {
    Failed,
    Discarded,
    Written,
}

/// A covered centre not masked out, at pixel `(x, y)` with weights `λ` and depth `z`: the depth
/// test `passes(z, stored)`, the fragment stage, replace (`OVER` false) or "over" blending into
/// `color`, and `store(z, stored)` into `stored`.
#[inline(always)]
fn shade_pixel<S: Shader, C: ColorFormat, const OVER: bool>(
    shader: &S,
    context: &PieceContext<S::Varying>,
    front_facing: bool,
    (color, stored): (&mut C::Sample, &mut f32),
    (x, y): (i64, i64),
    (lambda, z): ([f64; 3], f32),
    (passes, store): (&impl Fn(f32, f32) -> bool, &impl Fn(f32, f32) -> f32),
) -> Outcome {
    if !passes(z, *stored) {
        return Outcome::Failed;
    }
    let weights = context.weights(lambda);
    let fragment = Fragment {
        varying: S::Varying::combine3(context.varyings, context.input_weights(weights)),
        depth: z,
        pixel: UVec2::new(x as u32, y as u32),
        front_facing,
        coverage: 1,
        lambda,
        piece: context,
    };
    let Some(c) = shader.fragment(&fragment) else {
        return Outcome::Discarded;
    };
    *color = if OVER {
        let src = premultiply(c);
        C::store_premultiplied(src + C::load(*color) * (1.0 - src.w))
    } else {
        C::store(c)
    };
    *stored = store(z, *stored);
    Outcome::Written
}

/// One sample per pixel with affine spans ([`Interpolation::AffineSpans`]).
fn shade_spans<S: Shader, C: ColorFormat>(
    piece: &Piece,
    context: &PieceContext<S::Varying>,
    shader: &S,
    state: &PipelineState,
    tile: &mut TileTarget<'_, C>,
    stats: &mut DrawStats,
    span: i64,
) {
    let mut cache = SpanCache {
        row: i64::MIN,
        start: 0,
        range: (0, 0),
        ends: [[0.0; 3]; 2],
    };
    let rect = tile.rect;
    piece.edge.for_each_covered(rect, |x, y, lambda| {
        let index = tile.local(x, y);
        if let Some(mask) = tile.mask
            && !mask[index]
        {
            return;
        }
        let z = (0..3).map(|i| lambda[i] * piece.depth[i]).sum::<f64>() as f32;
        if let Some(op) = state.depth_compare
            && !op.passes(z, tile.depth[index])
        {
            stats.fragments_depth_failed += 1;
            return;
        }
        let weights = span_weights(context, &mut cache, span, x, y, lambda);
        let fragment = Fragment {
            varying: S::Varying::combine3(context.varyings, context.input_weights(weights)),
            depth: z,
            pixel: UVec2::new(x as u32, y as u32),
            front_facing: piece.front,
            coverage: 1,
            lambda,
            piece: context,
        };
        stats.fragments_shaded += 1;
        let Some(c) = shader.fragment(&fragment) else {
            stats.fragments_discarded += 1;
            return;
        };
        tile.color[index] = blend_stored::<C>(state, premultiply(c), tile.color[index]);
        if state.depth_write {
            tile.depth[index] = z;
        }
    });
}

/// Affine spans: exact weights at the span's ends (cached along the row), linear in between.
///
/// The ends are clamped to the row's covered pixels: beyond the triangle the perspective
/// weights are extrapolated, and near the plane's horizon (1/w → 0) they blow up.
fn span_weights<V: Copy>(
    context: &crate::shader::PieceContext<V>,
    cache: &mut SpanCache,
    span: i64,
    x: i64,
    y: i64,
    lambda: [f64; 3],
) -> [f64; 3] {
    let start = x.div_euclid(span) * span;
    if cache.row != y || cache.start != start {
        // The row's covered pixel range from here: λᵢ + gᵢ·(x′ − x) ≥ 0 for every i.
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for (l, g) in lambda.iter().zip(context.grads.map(|g| g.x)) {
            if g > 0.0 {
                lo = lo.max(-l / g);
            } else if g < 0.0 {
                hi = hi.min(-l / g);
            }
        }
        // Pixel offsets from x, rounded inwards (x itself is covered: lo ≤ 0 ≤ hi).
        let first = (x + lo.max(-1e9).ceil() as i64).clamp(start, x);
        let last = (x + hi.min(1e9).floor() as i64).clamp(x, start + span);
        let at = |px: i64| -> [f64; 3] {
            let l: [f64; 3] =
                core::array::from_fn(|i| lambda[i] + context.grads[i].x * (px - x) as f64);
            context.weights(l)
        };
        *cache = SpanCache {
            row: y,
            start,
            range: (first, last),
            ends: [at(first), at(last)],
        };
    }
    let (first, last) = cache.range;
    if last <= first {
        return context.weights(lambda);
    }
    let t = (x - first) as f64 / (last - first) as f64;
    let [a, b] = cache.ends;
    core::array::from_fn(|i| a[i] + (b[i] - a[i]) * t)
}

/// Several samples per pixel: coverage and depth per sample; shading per pixel (MSAA) or per
/// sample.
fn shade_multi<S: Shader, C: ColorFormat>(
    piece: &Piece,
    context: &PieceContext<S::Varying>,
    shader: &S,
    state: &PipelineState,
    tile: &mut TileTarget<'_, C>,
    stats: &mut DrawStats,
) {
    const ONE: i64 = 1 << crate::edge::SUBPIXEL_BITS;
    let edge = &piece.edge;
    let samples = tile.samples;
    let pattern = tile.pattern;
    // Edge offsets of each sample from the pixel corner, when every pixel shares them (on the
    // stack: a list on the heap was an allocation per piece and tile).
    let uniform = pattern.is_uniform();
    let mut shared = [[0_i64; 3]; crate::samples::MAX_SAMPLES as usize];
    if uniform {
        for (k, d) in (0..samples).zip(&mut shared) {
            let (ox, oy) = pattern.fixed_offset(0, 0, k);
            *d = edge.offset(ox, oy);
        }
    }
    let centre = edge.offset(ONE / 2, ONE / 2);
    let rect = tile.rect;
    let mut sample_e = [[0_i64; 3]; crate::samples::MAX_SAMPLES as usize];
    edge.for_each_block_pixel(rect, (0, ONE - 1), (0, 0), |x, y, e, all| {
        let mut covered = 0_u32;
        for k in 0..samples {
            let d = if uniform {
                shared[k as usize]
            } else {
                let (ox, oy) = pattern.fixed_offset(x, y, k);
                edge.offset(ox, oy)
            };
            let s: [i64; 3] = core::array::from_fn(|i| e[i] + d[i]);
            sample_e[k as usize] = s;
            if all || edge.covers(s) {
                covered |= 1 << k;
            }
        }
        if covered == 0 {
            return;
        }
        let pixel = tile.local(x, y);
        if let Some(mask) = tile.mask
            && !mask[pixel]
        {
            return;
        }
        let base = pixel * samples as usize;
        // Depth per covered sample.
        let mut passed = 0_u32;
        let mut depths = [0_f32; crate::samples::MAX_SAMPLES as usize];
        for k in 0..samples {
            if covered & (1 << k) == 0 {
                continue;
            }
            let lambda = edge.lambda(sample_e[k as usize]);
            let z = (0..3).map(|i| lambda[i] * piece.depth[i]).sum::<f64>() as f32;
            depths[k as usize] = z;
            let stored = tile.depth[base + k as usize];
            if state.depth_compare.is_none_or(|op| op.passes(z, stored)) {
                passed |= 1 << k;
            }
        }
        if passed == 0 {
            stats.fragments_depth_failed += 1;
            return;
        }
        let mut shade = |lambda: [f64; 3], coverage: u32, depth: f32| {
            let weights = context.weights(lambda);
            let fragment = Fragment {
                varying: S::Varying::combine3(context.varyings, context.input_weights(weights)),
                depth,
                pixel: UVec2::new(x as u32, y as u32),
                front_facing: piece.front,
                coverage,
                lambda,
                piece: context,
            };
            stats.fragments_shaded += 1;
            let c = shader.fragment(&fragment);
            if c.is_none() {
                stats.fragments_discarded += 1;
            }
            c.map(premultiply)
        };
        if state.sample_shading {
            for k in 0..samples {
                if passed & (1 << k) == 0 {
                    continue;
                }
                let lambda = edge.lambda(sample_e[k as usize]);
                let Some(src) = shade(lambda, 1 << k, depths[k as usize]) else {
                    continue;
                };
                let i = base + k as usize;
                tile.color[i] = blend_stored::<C>(state, src, tile.color[i]);
                if state.depth_write {
                    tile.depth[i] = depths[k as usize];
                }
            }
        } else {
            // Shade at the centre when it is covered, else at the first covered sample (as a
            // GPU's centroid interpolation does: never outside the triangle).
            let at_centre: [i64; 3] = core::array::from_fn(|i| e[i] + centre[i]);
            let (lambda, depth) = if edge.covers(at_centre) {
                let l = edge.lambda(at_centre);
                (l, (0..3).map(|i| l[i] * piece.depth[i]).sum::<f64>() as f32)
            } else {
                let k = covered.trailing_zeros() as usize;
                (edge.lambda(sample_e[k]), depths[k])
            };
            let Some(src) = shade(lambda, covered, depth) else {
                return;
            };
            for k in 0..samples {
                if passed & (1 << k) == 0 {
                    continue;
                }
                let i = base + k as usize;
                tile.color[i] = blend_stored::<C>(state, src, tile.color[i]);
                if state.depth_write {
                    tile.depth[i] = depths[k as usize];
                }
            }
        }
    });
}
