//! Primitive assembly: index triples to screen-space pieces — clipping, facing and culling,
//! the viewport transform and fixed-point setup. Every triangle that is not drawn is counted.

use glam::{Vec2, Vec3, Vec4};

use crate::clip::{ClipVertex, MAX_CLIPPED, clip, inside};
use crate::draw::DrawStats;
use crate::edge::EdgeSetup;
use crate::shader::PieceContext;
use crate::state::{CullMode, FrontFace, PipelineState, Viewport};

/// One screen-space piece of an input triangle (a clipped triangle is a fan of pieces).
pub(crate) struct Piece<V> {
    pub(crate) edge: EdgeSetup,
    /// Depth at the piece's vertices.
    pub(crate) depth: [f64; 3],
    pub(crate) front: bool,
    pub(crate) context: PieceContext<V>,
}

/// The pieces of the triangles `indices` over the vertex-stage outputs `shaded`, in submission
/// order; what was dropped goes into `stats`.
pub(crate) fn assemble<V: Copy>(
    shaded: &[(Vec4, V)],
    indices: &[u32],
    state: &PipelineState,
    viewport: Viewport,
    stats: &mut DrawStats,
) -> Vec<Piece<V>> {
    let mut pieces = Vec::with_capacity(indices.len() / 3);
    for tri in indices.chunks_exact(3) {
        stats.triangles_in += 1;
        let fetch = |i: u32| shaded.get(i as usize).copied();
        let (Some(v0), Some(v1), Some(v2)) = (fetch(tri[0]), fetch(tri[1]), fetch(tri[2])) else {
            stats.dropped_bad_index += 1;
            continue;
        };
        let positions = [v0.0, v1.0, v2.0];
        let varyings = [v0.1, v1.1, v2.1];
        if positions.iter().any(|p| !p.is_finite()) {
            stats.dropped_non_finite += 1;
            continue;
        }
        let mut polygon = [ClipVertex::default(); MAX_CLIPPED];
        let len = if inside(&positions) {
            for (slot, (&position, bary)) in
                polygon
                    .iter_mut()
                    .zip(positions.iter().zip([Vec3::X, Vec3::Y, Vec3::Z]))
            {
                *slot = ClipVertex { position, bary };
            }
            3
        } else {
            stats.clipped += 1;
            clip(&positions, &mut polygon)
        };
        if len < 3 {
            stats.clipped_away += 1;
            continue;
        }
        let polygon = &polygon[..len];
        // Facing from the whole polygon's NDC area (y up): positive is counter-clockwise.
        let mut ndc = [Vec3::ZERO; MAX_CLIPPED];
        for (n, v) in ndc.iter_mut().zip(polygon) {
            *n = v.position.truncate() / v.position.w;
        }
        let ndc = &ndc[..len];
        let area: f32 = (0..len)
            .map(|i| {
                let (p, q) = (ndc[i], ndc[(i + 1) % len]);
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
        for k in 1..len - 1 {
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
    pieces
}
