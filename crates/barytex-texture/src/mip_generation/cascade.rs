//! The box chain of a power-of-two texture as one streaming pass: the base is read once, row by
//! row, and every pair of finished rows of a level is reduced at once into the next level's row,
//! which is encoded into its texture while still in cache.
//!
//! The plane path ([`super::polyphase_box`]) writes each level as a full f32 RGBA plane (16 bytes
//! a texel) and reads it back twice, to encode and to reduce further: for a 4096² base that is
//! about 200 MB of traffic and 64 MB of fresh pages for level 1 alone. Here the only f32 buffers
//! are two rows per level. Every value is computed by the same formulas, in the same order, as
//! the plane path, so the chains are bit-identical (`tests::cascade_equals_the_plane_path`).

use glam::Vec4;

use super::polyphase_box::{axis_taps, weighted_sum};
use crate::mip_chain::level_size;
use crate::texture2d::try_vec_with_capacity;
use crate::{Limits, Texel, Texture2d, TextureError};

/// One level being produced: its size, its encoded texels so far, and the previous row of the
/// pair its next reduction waits for.
struct Level<T> {
    width: u32,
    height: u32,
    texels: Vec<T>,
    pending: Option<Vec<Vec4>>,
}

/// Levels `1..count` of the box chain of a base of power-of-two sides, from its rows converted by
/// `convert` (premultiplied linear light, or the stored values), encoded by `encode`.
pub(super) fn reduce_chain<T: Texel>(
    base: &Texture2d<T>,
    count: usize,
    convert: impl Fn(T) -> Vec4,
    encode: impl Fn(Vec4) -> T,
) -> Result<Vec<Texture2d<T>>, TextureError> {
    let (w, h) = base.size();
    debug_assert!(w.is_power_of_two() && h.is_power_of_two());
    let mut levels = Vec::new();
    for i in 1..count {
        let (lw, lh) = level_size(w, h, i);
        levels.push(Level {
            width: lw,
            height: lh,
            texels: try_vec_with_capacity(lw as usize * lh as usize)?,
            pending: None,
        });
    }
    for y in 0..h {
        let row = base
            .row(y)
            .map(|texels| texels.iter().map(|&t| convert(t)).collect())
            .unwrap_or_default();
        push_row(&mut levels, (w, h), row, &encode);
    }
    levels
        .into_iter()
        .map(|l| {
            Texture2d::from_texels_with_limits(l.width, l.height, l.texels, &Limits::UNLIMITED)
        })
        .collect()
}

/// Hands a finished row of the level above `levels[0]` (of size `source`) down the cascade.
fn push_row<T: Texel>(
    levels: &mut [Level<T>],
    source: (u32, u32),
    row: Vec<Vec4>,
    encode: &impl Fn(Vec4) -> T,
) {
    let Some((level, below)) = levels.split_first_mut() else {
        return;
    };
    let (sw, sh) = source;
    let pair = if sh == 1 {
        // A source one row tall: each row reduces alone (the copy tap).
        (row, None)
    } else if let Some(first) = level.pending.take() {
        (first, Some(row))
    } else {
        level.pending = Some(row);
        return;
    };
    let mut out = Vec::with_capacity(level.width as usize);
    reduce_rows(&pair.0, pair.1.as_deref(), sw, sh, &mut out);
    level.texels.extend(out.iter().map(|&v| encode(v)));
    push_row(below, (level.width, level.height), out, encode);
}

/// One output row from its source rows: `b` is the second row, `None` when the source is one row
/// tall. The arithmetic is [`super::polyphase_box::reduce`]'s, case by case.
fn reduce_rows(a: &[Vec4], b: Option<&[Vec4]>, sw: u32, sh: u32, out: &mut Vec<Vec4>) {
    match b {
        Some(b) if sw.is_multiple_of(2) => {
            // Both sides even: the plane path's two-row fast case.
            out.extend(
                a.chunks_exact(2)
                    .zip(b.chunks_exact(2))
                    .map(|(a, b)| ((a[0] + a[1]) + (b[0] + b[1])) * 0.25),
            );
        }
        _ => {
            // A side of 1: the general taps loop (weights 1 for a side of 1, ½ ½ for an even one).
            let ty = axis_taps(0, sh);
            let rows = [Some(a), b];
            for x in 0..(sw / 2).max(1) {
                let tx = axis_taps(x, sw);
                out.push(weighted_sum(&tx, &ty, |sx, sy| {
                    rows[sy as usize].unwrap_or(a)[sx as usize]
                }));
            }
        }
    }
}
