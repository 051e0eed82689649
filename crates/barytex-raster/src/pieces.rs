//! A draw's pieces in submission order, as parallel primitive assembly made them: one list per
//! chunk of triangles, named by a `u32` that packs the chunk and the place in it.

use glam::Vec4;
use rayon::prelude::*;

use crate::assemble::{Piece, assemble};
use crate::draw::DrawStats;
use crate::state::{PipelineState, Viewport};

/// Triangles per parallel job of primitive assembly: enough that a job outweighs its
/// scheduling, few enough that two threads share a mesh of a few thousand triangles.
const ASSEMBLY_CHUNK: usize = 512;

/// Bits of a piece's name that number it within its chunk: a chunk of [`ASSEMBLY_CHUNK`]
/// triangles has at most 7 pieces each (a triangle clipped to a polygon of
/// [`MAX_CLIPPED`](crate::clip::MAX_CLIPPED) vertices), 3 584 < 2¹².
const IN_CHUNK_BITS: u32 = 12;
const _: () = assert!(ASSEMBLY_CHUNK * (crate::clip::MAX_CLIPPED - 2) < 1 << IN_CHUNK_BITS);

/// The pieces of a draw, chunk by chunk.
///
/// Not concatenated into one list: on two threads that copy (into memory touched for the first
/// time, a page fault every 4 KiB) ran on one thread after the parallel assembly and took about
/// as long as it (Suzanne at 1024², 2 916 pieces).
pub(crate) struct Pieces {
    chunks: Vec<Vec<Piece>>,
    /// A piece's name is `chunk << shift | index` (one chunk: `shift` 32, the name is the index).
    shift: u32,
    len: usize,
}

impl Pieces {
    /// The piece named `id` (a name from [`iter`](Self::iter)).
    #[inline(always)]
    pub(crate) fn get(&self, id: u32) -> &Piece {
        let id = u64::from(id);
        let chunk = (id >> self.shift) as usize;
        let index = (id & ((1_u64 << self.shift) - 1)) as usize;
        &self.chunks[chunk][index]
    }

    /// Every piece with its name, in submission order (the names increase).
    pub(crate) fn iter(&self) -> impl Iterator<Item = (u32, &Piece)> {
        let shift = self.shift;
        self.chunks.iter().enumerate().flat_map(move |(c, chunk)| {
            chunk
                .iter()
                .enumerate()
                .map(move |(k, piece)| (((c as u64) << shift | k as u64) as u32, piece))
        })
    }

    /// How many pieces there are.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The pieces of one list (named by their index: at most `u32::MAX` of them are drawn, as
    /// the bins hold `u32` names).
    fn single(pieces: Vec<Piece>) -> Self {
        Self {
            len: pieces.len(),
            chunks: vec![pieces],
            shift: 32,
        }
    }
}

/// [`assemble`] over chunks of triangles in parallel, the pieces kept in submission order (so
/// the result, and everything drawn from it, does not depend on the thread count).
pub(crate) fn assemble_parallel<V: Copy + Send + Sync>(
    shaded: &[(Vec4, V)],
    indices: &[u32],
    state: &PipelineState,
    viewport: Viewport,
    stats: &mut DrawStats,
) -> Pieces {
    let chunk_count = indices.len().div_ceil(3 * ASSEMBLY_CHUNK);
    // One thread: one list (no chunks to make); the pieces are the same either way. So many
    // chunks that their names would not fit in 32 bits (2²⁹ triangles): one list too.
    if chunk_count <= 1
        || rayon::current_num_threads() == 1
        || chunk_count > 1 << (32 - IN_CHUNK_BITS)
    {
        return Pieces::single(assemble(shaded, indices, state, viewport, stats));
    }
    let chunks: Vec<(Vec<Piece>, DrawStats)> = indices
        .par_chunks(3 * ASSEMBLY_CHUNK)
        .map(|chunk| {
            let mut chunk_stats = DrawStats::default();
            let pieces = assemble(shaded, chunk, state, viewport, &mut chunk_stats);
            (pieces, chunk_stats)
        })
        .collect();
    let mut pieces = Pieces {
        chunks: Vec::with_capacity(chunks.len()),
        shift: IN_CHUNK_BITS,
        len: 0,
    };
    for (chunk, chunk_stats) in chunks {
        pieces.len += chunk.len();
        pieces.chunks.push(chunk);
        *stats += &chunk_stats;
    }
    pieces
}
