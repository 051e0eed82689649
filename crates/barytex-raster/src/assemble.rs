//! Primitive assembly: index triples to screen-space pieces — clipping, facing and culling,
//! the viewport transform and fixed-point setup. Every triangle that is not drawn is counted.

use glam::{DVec2, Vec2, Vec3, Vec4};

use crate::clip::{ClipVertex, MAX_CLIPPED, clip, inside};
use crate::draw::DrawStats;
use crate::edge::EdgeSetup;
use crate::shader::PieceContext;
use crate::state::{CullMode, FrontFace, Interpolation, PipelineState, Viewport};

/// One screen-space piece of an input triangle (a clipped triangle is a fan of pieces).
///
/// The input triangle's varyings are not copied into the piece: it names the vertex stage's
/// outputs by index, and [`context`](Self::context) gathers them where a tile draws the piece.
/// Three copied varyings were half of a piece's bytes, and the pieces of a draw are memory it
/// touches for the first time (a page fault every 4 KiB: on Suzanne at 1024², 3 936 triangles,
/// assembly's faults took about as long as its arithmetic).
pub(crate) struct Piece {
    pub(crate) edge: EdgeSetup,
    /// Depth at the piece's vertices.
    pub(crate) depth: [f64; 3],
    pub(crate) front: bool,
    /// The input triangle's vertices: indices into the vertex stage's outputs, in range (checked
    /// by [`assemble`]).
    vertices: [u32; 3],
    /// Screen gradients of the piece's barycentrics.
    grads: [DVec2; 3],
    /// 1/w at the piece's vertices.
    inv_w: [f64; 3],
    /// The piece's vertices as barycentrics of the input triangle (`None`: the identity).
    bary: Option<[Vec3; 3]>,
    interpolation: Interpolation,
}

impl Piece {
    /// The piece of the screen triangle `s` (each vertex's position, depth and `1/w`, from
    /// [`to_screen`]) with its setup `edge`, of the input triangle `vertices`; `bary` is its
    /// vertices' weights over the input triangle's, `None` for the input triangle itself.
    #[inline(always)]
    fn new(
        edge: EdgeSetup,
        s: [(Vec2, f64, f64); 3],
        front: bool,
        vertices: [u32; 3],
        bary: Option<[Vec3; 3]>,
        state: &PipelineState,
    ) -> Self {
        let (g0, g1, g2) = edge.gradients();
        Piece {
            edge,
            depth: [s[0].1, s[1].1, s[2].1],
            front,
            vertices,
            grads: [g0, g1, g2],
            inv_w: [s[0].2, s[1].2, s[2].2],
            bary,
            interpolation: state.interpolation,
        }
    }

    /// What the fragments of the piece need from it, with its input triangle's varyings from
    /// `shaded`, the vertex stage's outputs the piece was assembled from.
    #[inline(always)]
    pub(crate) fn context<V: Copy>(&self, shaded: &[(Vec4, V)]) -> PieceContext<V> {
        PieceContext {
            varyings: self.vertices.map(|i| shaded[i as usize].1),
            grads: self.grads,
            inv_w: self.inv_w,
            bary: self.bary,
            interpolation: self.interpolation,
        }
    }

    /// Asks the cache for the piece's lines: its setup, depths, vertex indices (read by
    /// [`prefetch_varyings`](Self::prefetch_varyings)) and what [`context`](Self::context)
    /// copies. Each field not asked for was a miss per piece and tile on small triangles.
    #[inline(always)]
    pub(crate) fn prefetch(&self) {
        #[cfg(target_arch = "x86_64")]
        {
            self.edge.prefetch();
            safe_arch::prefetch_t0(&self.depth);
            safe_arch::prefetch_t0(&self.vertices);
            safe_arch::prefetch_t0(&self.grads);
            safe_arch::prefetch_t0(&self.inv_w);
            safe_arch::prefetch_t0(&self.bary);
        }
    }

    /// Asks the cache for the input triangle's varyings in `shaded`, which
    /// [`context`](Self::context) gathers: the pieces of a tile name vertices all over the
    /// vertex stage's outputs, and each gather waited on a miss.
    #[inline(always)]
    pub(crate) fn prefetch_varyings<V>(&self, shaded: &[(Vec4, V)]) {
        #[cfg(target_arch = "x86_64")]
        for i in self.vertices {
            if let Some(vertex) = shaded.get(i as usize) {
                safe_arch::prefetch_t0(&vertex.1);
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = shaded;
    }
}

/// The pieces of the triangles `indices` over the vertex-stage outputs `shaded`, in submission
/// order; what was dropped goes into `stats`.
pub(crate) fn assemble<V: Copy>(
    shaded: &[(Vec4, V)],
    indices: &[u32],
    state: &PipelineState,
    viewport: Viewport,
    stats: &mut DrawStats,
) -> Vec<Piece> {
    let mut pieces = Vec::with_capacity(indices.len() / 3);
    for tri in indices.chunks_exact(3) {
        stats.triangles_in += 1;
        let fetch = |i: u32| shaded.get(i as usize).copied();
        let (Some(v0), Some(v1), Some(v2)) = (fetch(tri[0]), fetch(tri[1]), fetch(tri[2])) else {
            stats.dropped_bad_index += 1;
            continue;
        };
        let positions = [v0.0, v1.0, v2.0];
        let vertices = [tri[0], tri[1], tri[2]];
        if positions.iter().any(|p| !p.is_finite()) {
            stats.dropped_non_finite += 1;
            continue;
        }
        // Most triangles need no clipping: their own path, without the clipper's buffers.
        if inside(&positions) {
            whole_triangle(&positions, vertices, state, viewport, stats, &mut pieces);
            continue;
        }
        stats.clipped += 1;
        let mut clipped_polygon = [ClipVertex::default(); MAX_CLIPPED];
        let len = clip(&positions, &mut clipped_polygon);
        let polygon = &clipped_polygon[..len];
        if len < 3 {
            stats.clipped_away += 1;
            continue;
        }
        // Facing from the whole polygon's NDC area (y up): positive is counter-clockwise.
        let mut ndc = [Vec3::ZERO; MAX_CLIPPED];
        for (n, v) in ndc.iter_mut().zip(polygon) {
            *n = v.position.truncate() / v.position.w;
        }
        let ndc = &ndc[..len];
        // The cross products summed in polygon order (`(i + 1) % len` without a division).
        let area: f32 = (0..len)
            .map(|i| {
                let (p, q) = (ndc[i], ndc[if i + 1 == len { 0 } else { i + 1 }]);
                p.x * q.y - q.x * p.y
            })
            .sum();
        let Some(front) = facing(state, area) else {
            stats.culled += 1;
            continue;
        };
        let to_screen = |v: &ClipVertex, n: Vec3| to_screen(viewport, v.position.w, n);
        let mut drawn = false;
        for k in 1..len - 1 {
            let s = [
                to_screen(&polygon[0], ndc[0]),
                to_screen(&polygon[k], ndc[k]),
                to_screen(&polygon[k + 1], ndc[k + 1]),
            ];
            let Some(edge) = EdgeSetup::new([s[0].0, s[1].0, s[2].0]) else {
                continue;
            };
            drawn = true;
            let bary = [polygon[0].bary, polygon[k].bary, polygon[k + 1].bary];
            let bary = (bary != [Vec3::X, Vec3::Y, Vec3::Z]).then_some(bary);
            pieces.push(Piece::new(edge, s, front, vertices, bary, state));
        }
        if !drawn {
            stats.degenerate += 1;
        }
    }
    pieces
}

/// The screen position, depth and `1/w` of a vertex at NDC `n` with clip-space `w`.
#[inline(always)]
fn to_screen(viewport: Viewport, w: f32, n: Vec3) -> (Vec2, f64, f64) {
    (
        Vec2::new(
            viewport.x + (n.x + 1.0) * 0.5 * viewport.width,
            viewport.y + (1.0 - n.y) * 0.5 * viewport.height,
        ),
        f64::from(viewport.min_depth)
            + f64::from(n.z) * f64::from(viewport.max_depth - viewport.min_depth),
        1.0 / f64::from(w),
    )
}

/// [`assemble`]'s work for a triangle inside every clip plane: the same operations as for a
/// clipped polygon of three vertices (facing, culling, viewport, setup), without the polygon's
/// buffers, its barycentric frame (the identity) or the fan loop: most triangles take this
/// path, and copying them through the clipper's arrays was a good part of assembly.
#[inline(always)]
fn whole_triangle(
    positions: &[Vec4; 3],
    vertices: [u32; 3],
    state: &PipelineState,
    viewport: Viewport,
    stats: &mut DrawStats,
    pieces: &mut Vec<Piece>,
) {
    // `xyz / w` lane by lane: each lane's division is the IEEE one of the scalar path.
    let ndc = positions.map(|p| (p / Vec4::splat(p.w)).truncate());
    // The cross products summed in polygon order, as for a clipped polygon.
    let cross = |p: Vec3, q: Vec3| p.x * q.y - q.x * p.y;
    let area: f32 = [
        cross(ndc[0], ndc[1]),
        cross(ndc[1], ndc[2]),
        cross(ndc[2], ndc[0]),
    ]
    .into_iter()
    .sum();
    let Some(front) = facing(state, area) else {
        stats.culled += 1;
        return;
    };
    let s: [(Vec2, f64, f64); 3] =
        core::array::from_fn(|i| to_screen(viewport, positions[i].w, ndc[i]));
    let Some(edge) = EdgeSetup::new([s[0].0, s[1].0, s[2].0]) else {
        stats.degenerate += 1;
        return;
    };
    pieces.push(Piece::new(edge, s, front, vertices, None, state));
}

/// Whether a polygon whose NDC area (y up, summed in polygon order) is `area` faces the front,
/// or `None` when `state` culls it.
#[inline(always)]
fn facing(state: &PipelineState, area: f32) -> Option<bool> {
    // Positive is counter-clockwise.
    let ccw = area > 0.0;
    let front = match state.front_face {
        FrontFace::Ccw => ccw,
        FrontFace::Cw => !ccw,
    };
    let culled =
        (state.cull == CullMode::Back && !front) || (state.cull == CullMode::Front && front);
    (!culled).then_some(front)
}
