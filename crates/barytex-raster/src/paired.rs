//! A piece's covered pixel centres shaded two at a time, for shaders that interleave two
//! fragments ([`Shader::PAIRS`]): each centre that passes the depth test waits for the next
//! one, and the two go to [`Shader::fragment_pair`] together; a piece's odd last one goes to
//! [`Shader::fragment`] alone.
//!
//! The results are those of the one-at-a-time loop in `tile.rs`: the two centres of a pair are
//! different pixels of one piece, so neither's depth test reads what the other writes, and
//! each is written (colour, then depth) exactly as there.
//!
//! On x86-64 the loop also runs as an AVX2 + FMA build (`cpu_features`): every closure below
//! is `#[inline(always)]`, since one left out of line is compiled for the baseline alone (the
//! span closure's was: the whole pixel loop stayed SSE2).

use barytex_interp::Interpolate;
use glam::{UVec2, Vec4};

use crate::assemble::Piece;
use crate::draw::DrawStats;
use crate::format::ColorFormat;
use crate::run_depth::for_each_run_pixel;
use crate::shader::PieceContext;
use crate::target::{TILE, premultiply};
use crate::tile::TILE_PIXELS;
use crate::{Fragment, Shader};

/// A covered centre that passed the depth test.
#[derive(Clone, Copy)]
struct Passed {
    /// Its index in the tile's buffers.
    index: usize,
    pixel: UVec2,
    lambda: [f64; 3],
    z: f32,
}

/// The state of one piece's pairing over one tile.
struct Pairs<'a, S: Shader, C: ColorFormat, P, St, const OVER: bool> {
    shader: &'a S,
    context: &'a PieceContext<S::Varying>,
    front_facing: bool,
    color: &'a mut [C::Sample; TILE_PIXELS],
    depth: &'a mut [f32; TILE_PIXELS],
    passes: P,
    store: St,
    /// The tile's mask (`MASKED` draws only).
    mask: Option<&'a [bool]>,
    waiting: Option<Passed>,
    visited: u64,
    skipped: u64,
    failed: u64,
    discarded: u64,
}

impl<S, C, P, St, const OVER: bool> Pairs<'_, S, C, P, St, OVER>
where
    S: Shader,
    C: ColorFormat,
    P: Fn(f32, f32) -> bool,
    St: Fn(f32, f32) -> f32,
{
    /// A covered centre at tile index `index`, pixel `(x, y)`, weights `λ` and depth `z`.
    #[inline(always)]
    fn centre(&mut self, index: usize, xy: (i64, i64), lambda: [f64; 3], z: f32) {
        self.visited += 1;
        if self.mask.is_some_and(|keep| !keep[index]) {
            self.skipped += 1;
            return;
        }
        self.visit(index, xy, lambda, z);
    }

    /// [`centre`](Self::centre) past the mask.
    #[inline(always)]
    fn visit(&mut self, index: usize, (x, y): (i64, i64), lambda: [f64; 3], z: f32) {
        // A no-op for a pixel of the tile: no bounds checks below.
        let index = index % TILE_PIXELS;
        if !(self.passes)(z, self.depth[index]) {
            self.failed += 1;
            return;
        }
        let now = Passed {
            index,
            pixel: UVec2::new(x as u32, y as u32),
            lambda,
            z,
        };
        let Some(first) = self.waiting.take() else {
            self.waiting = Some(now);
            return;
        };
        let (a, b) = (self.fragment(&first), self.fragment(&now));
        let [ca, cb] = self.shader.fragment_pair(&a, &b);
        self.write(&first, ca);
        self.write(&now, cb);
    }

    /// The waiting centre, alone.
    #[inline(always)]
    fn flush(&mut self) {
        if let Some(last) = self.waiting.take() {
            let c = self.shader.fragment(&self.fragment(&last));
            self.write(&last, c);
        }
    }

    /// What the fragment stage sees at a centre (as `tile::shade_pixel` builds it).
    #[inline(always)]
    fn fragment(&self, p: &Passed) -> Fragment<'_, S::Varying> {
        let context = self.context;
        let weights = context.weights(p.lambda);
        Fragment {
            varying: S::Varying::combine3(context.varyings, context.input_weights(weights)),
            depth: p.z,
            pixel: p.pixel,
            front_facing: self.front_facing,
            coverage: 1,
            lambda: p.lambda,
            piece: context,
        }
    }

    /// Replace (`OVER` false) or "over" blending of the fragment stage's colour `c` into the
    /// centre's sample and its depth stored, as `tile::shade_pixel` writes them.
    #[inline(always)]
    fn write(&mut self, p: &Passed, c: Option<Vec4>) {
        let Some(c) = c else {
            self.discarded += 1;
            return;
        };
        let color = &mut self.color[p.index];
        *color = if OVER {
            let src = premultiply(c);
            C::store_premultiplied(src + C::load(*color) * (1.0 - src.w))
        } else {
            C::store(c)
        };
        let stored = &mut self.depth[p.index];
        *stored = (self.store)(p.z, *stored);
    }
}

/// `tile::shade_centres` with the centres shaded in pairs, into the tile's buffers as arrays:
/// the mask (if `MASKED`), the depth test `passes(fragment, stored)`, the fragment stage,
/// replace or "over" blending, `store(fragment, stored)`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn shade_centres_paired<S, C, const OVER: bool, const MASKED: bool>(
    piece: &Piece,
    context: &PieceContext<S::Varying>,
    shader: &S,
    (rect, (ox, oy), mask): ([i64; 4], (i64, i64), Option<&[bool]>),
    (color, depth): (&mut [C::Sample; TILE_PIXELS], &mut [f32; TILE_PIXELS]),
    stats: &mut DrawStats,
    passes: impl Fn(f32, f32) -> bool,
    store: impl Fn(f32, f32) -> f32,
) where
    S: Shader,
    C: ColorFormat,
{
    let depths = piece.depth;
    let inv_area = piece.edge.inv_area();
    let mut pairs = Pairs::<S, C, _, _, OVER> {
        shader,
        context,
        front_facing: piece.front,
        color,
        depth,
        passes,
        store,
        mask: mask.filter(|_| MASKED),
        waiting: None,
        visited: 0,
        skipped: 0,
        failed: 0,
        discarded: 0,
    };
    let index = |x: i64, y: i64| ((y - oy) * i64::from(TILE) + (x - ox)) as usize;
    let narrow = 'narrow: {
        #[cfg(target_arch = "x86_64")]
        if let Some(small) = piece.edge.small_box(rect) {
            // A narrow box: its covered centres from bit masks.
            small.for_each_covered(
                inv_area,
                depths,
                #[inline(always)]
                |x, y, lambda, z| pairs.centre(index(x, y), (x, y), lambda, z),
            );
            break 'narrow true;
        }
        false
    };
    if !narrow {
        let (step, area2) = (piece.edge.x_step(), piece.edge.area2());
        piece.edge.for_each_covered_span(
            rect,
            #[inline(always)]
            |y, (xs, xe), e| {
                let (start, len) = (index(xs, y), (xe - xs) as usize);
                // Edge j is opposite input vertex j: its value is that vertex's weight.
                for_each_run_pixel(
                    e,
                    step,
                    area2,
                    inv_area,
                    depths,
                    len,
                    #[inline(always)]
                    |k, lambda, z| pairs.centre(start + k, (xs + k as i64, y), lambda, z),
                );
            },
        );
    }
    pairs.flush();
    stats.fragments_shaded += pairs.visited - pairs.skipped - pairs.failed;
    stats.fragments_discarded += pairs.discarded;
    stats.fragments_depth_failed += pairs.failed;
}
