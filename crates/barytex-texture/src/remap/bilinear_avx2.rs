//! The bilinear remap of RGBA8 in AVX2, selected at run time (through `pulp`, whose `V3` token
//! proves the CPU has AVX2 and FMA and runs an operation compiled for them; the workspace forbids
//! `unsafe`, and calling a `#[target_feature]` function directly needs it). Bit-identical to the
//! scalar reference and to the SSE2 kernel: the same numbers from the same operations in the
//! same order.
//!
//! The output is walked in blocks of `BLOCK` pixels, each in two passes (the structure of
//! OpenCV's remap, which converts a block of the map before it blends it):
//! - `address`: every pixel's two row offsets (`y₀·w + x₀`, `y₁·w + x₀`) and its f32 weights
//!   `[fx, fy]`, vectorized, into a small array;
//! - `blend`: the loads at those offsets and the blend, four pixels a step.
//!
//! Separated, the texel loads of the second pass no longer wait behind the conversions and
//! clamps of their own pixel, and the offsets come from memory as plain 32-bit integers (no
//! lane extraction, no 64-bit index arithmetic, one bounds check per row pair).

mod address;
mod address32;
mod blend;

use glam::Vec2;
use pulp::x86::V3;

use address::Addressing;

use crate::{Rgba8, Texture2d};

/// The pixels of one block. 64: the two blocks' arrays (2 KiB) stay in L1 beside the texels,
/// the fix-up test for non-finite coordinates is rare, and the prefetch distance (one block)
/// covers the memory latency; blocks of 32 and 128 pixels measured 1–4 % slower.
const BLOCK: usize = 64;

/// The first pass's results for one block.
struct Block {
    /// Per pixel, its left texel's index in its top row and in its bottom row.
    offsets: [u32; 2 * BLOCK],
    /// Per pixel, `[fx, fy]`.
    weights: [f32; 2 * BLOCK],
}

/// Whether the kernel handles `source`: two texels per row (the 8-byte row read), every offset
/// below `2³¹` (the f64 → i32 conversion), sides below `2²⁴` (`u·w` exact in f64 with room).
pub(super) fn applies(source: &Texture2d<Rgba8>) -> bool {
    let (w, h) = source.size();
    (2..(1 << 24)).contains(&w) && h < (1 << 24) && u64::from(w) * u64::from(h) <= 1 << 31
}

/// The AVX2 + FMA token when this CPU has them (detected once, then cached by `pulp`).
pub(super) fn token() -> Option<V3> {
    V3::try_new()
}

/// Remaps `coords` into `out` (same length, checked by the caller); `applies(source)` holds.
pub(super) fn remap(simd: V3, source: &Texture2d<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    let (w, h) = source.size();
    let blend = blend::Blend::new(simd, source.texels());
    if w.is_power_of_two() && h.is_power_of_two() {
        let address = address32::Address32::new(simd, w, h);
        simd.vectorize(Run {
            address,
            blend,
            coords,
            out,
        });
    } else {
        let address = address::Address64::new(simd, w, h);
        simd.vectorize(Run {
            address,
            blend,
            coords,
            out,
        });
    }
}

/// The remap as `vectorize`'s operation: a struct rather than a closure, because `call` must be
/// `#[inline(always)]` for the whole loop to be compiled inside `vectorize`'s AVX2 function (a
/// closure this large is not inlined there, and its intrinsics become calls).
struct Run<'a, 'b, A> {
    address: A,
    blend: blend::Blend<'a>,
    coords: &'b [Vec2],
    out: &'b mut [Rgba8],
}

impl<A: Addressing> pulp::NullaryFnOnce for Run<'_, '_, A> {
    type Output = ();

    #[inline(always)]
    fn call(self) {
        run(&self.address, &self.blend, self.coords, self.out);
    }
}

/// The blocks of `coords` into `out`, the addressing of each block one block ahead of its blend
/// so that the blend can prefetch the texels of the pixels `BLOCK` on at their exact offsets.
/// (Every function called inside `vectorize` is `#[inline(always)]`: one left out is compiled
/// without AVX2, and its intrinsics become calls.)
#[inline(always)]
fn run(address: &impl Addressing, blend: &blend::Blend<'_>, coords: &[Vec2], out: &mut [Rgba8]) {
    // The last, partial block's coordinates padded with (0, 0): finite, their pixels dropped.
    let full = coords.len() / BLOCK * BLOCK;
    let mut padded = [Vec2::ZERO; BLOCK];
    padded[..coords.len() - full].copy_from_slice(&coords[full..]);
    let mut blocks = coords[..full]
        .chunks_exact(BLOCK)
        .chain((full < coords.len()).then_some(&padded[..]));
    let Some(mut this_coords) = blocks.next() else {
        return;
    };
    let (mut first, mut second) = (Block::new(), Block::new());
    // Swapped as references after each block: swapping the arrays would copy 2 KiB a block.
    let (mut this, mut next) = (&mut first, &mut second);
    let mut this_finite = address::address_block(address, this_coords, this);
    for out in out.chunks_mut(BLOCK) {
        let next_coords = blocks.next();
        let mut next_finite = true;
        if let Some(c) = next_coords {
            next_finite = address::address_block(address, c, next);
        }
        // The last block prefetches itself again (a hint: no effect on any result).
        let ahead = if next_coords.is_some() {
            &*next
        } else {
            &*this
        };
        if out.len() == BLOCK {
            blend.block(this, ahead, out);
        } else {
            let mut pixels = [Rgba8::default(); BLOCK];
            blend.block(this, ahead, &mut pixels);
            out.copy_from_slice(&pixels[..out.len()]);
        }
        if !this_finite {
            for (c, o) in this_coords.iter().zip(out) {
                if !c.is_finite() {
                    *o = Rgba8([0; 4]);
                }
            }
        }
        core::mem::swap(&mut this, &mut next);
        if let Some(c) = next_coords {
            this_coords = c;
        }
        this_finite = next_finite;
    }
}

impl Block {
    fn new() -> Self {
        Self {
            offsets: [0; 2 * BLOCK],
            weights: [0.0; 2 * BLOCK],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::remap::test_inputs::{coords, texture};

    #[test]
    fn avx2_kernel_matches_the_scalar_path_bit_for_bit() {
        let Some(simd) = token() else {
            eprintln!("skipped: this CPU has no AVX2/FMA");
            return;
        };
        // Powers of two on both sides take the f32 addressing, the others the f64 one.
        for (w, h) in [
            (2, 1),
            (2, 2),
            (3, 5),
            (7, 3),
            (64, 64),
            (16, 256),
            (1024, 2),
            (100, 37),
            (64, 37),
            (1, 9),
        ] {
            let src = texture(w, h, u64::from(w * 131 + h));
            let mut c = coords(w, h, u64::from(w + 7 * h));
            if w % 2 == 1 {
                c.pop(); // an odd count: the last pixel takes the one-pixel path
            }
            let mut fast = vec![Rgba8::default(); c.len()];
            let mut reference = fast.clone();
            super::super::remap_scalar(&src, &c, &mut reference);
            if applies(&src) {
                remap(simd, &src, &c, &mut fast);
                for (k, (f, r)) in fast.iter().zip(&reference).enumerate() {
                    assert_eq!(f, r, "{w}×{h} at {:?}", c[k]);
                }
            } else {
                assert_eq!(w, 1, "only a one-texel-wide source takes the scalar path");
            }
        }
    }
}
