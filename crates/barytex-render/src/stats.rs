//! What a render did and how long each stage took.

use barytex_raster::{AdaptiveStats, DrawStats};

use crate::passes::Drawn;
use crate::prepare::{ItemKind, Prepared};

/// What a render did and how long each stage took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RenderStats {
    /// Primitives drawn (opaque and masked first, then blended back to front).
    pub primitives: usize,
    /// Triangles submitted per pass (point and line primitives are counted in `draw`'s
    /// `points_in` and `lines_in`).
    pub triangles: usize,
    /// Fragment and triangle counts of the scene's items as the camera sees them, summed over
    /// passes (what portals draw is in [`portal_draw`](Self::portal_draw)).
    pub draw: DrawStats,
    /// Passes over the scene (more than one for accumulated and adaptive supersampling).
    pub passes: u32,
    /// Mean samples per pixel.
    pub samples_per_pixel: f64,
    /// The adaptive sampler's statistics, when it ran.
    pub adaptive: Option<AdaptiveStats>,
    /// Textures prepared (image × colour space × filter).
    pub textures: usize,
    /// Mip chains built.
    pub mip_chains: usize,
    /// Textures whose filter uses mipmaps but which are never minified (no chain built).
    pub mips_skipped: usize,
    /// Primitives whose tangents were generated (MikkTSpace) for a normal map.
    pub tangents_generated: usize,
    /// Hybrid shading: triangles the highlight test sent to Phong shading, and the rest
    /// (Gouraud).
    pub hybrid_phong_triangles: usize,
    /// Hybrid shading: triangles shaded Gouraud.
    pub hybrid_gouraud_triangles: usize,
    /// Varying floats interpolated per fragment, summed over the draws (a primitive split by
    /// hybrid shading counts twice): only what each material reads at its shading frequency.
    pub varyings_interpolated: usize,
    /// Varying floats not interpolated because the material never reads them, summed likewise
    /// (the full varying is 24 floats: position, normal, two uv sets, colour, Gouraud's vertex
    /// light, tangent).
    pub varyings_skipped: usize,
    /// Seconds preparing geometry, textures and mip chains.
    pub prepare_seconds: f64,
    /// Of `prepare_seconds`, those preparing the textures (copies and mip chains, several
    /// textures in parallel): wall time.
    pub mip_seconds: f64,
    /// Seconds rasterizing and shading (the two are interleaved per pixel), without creating
    /// the target ([`target_seconds`](Self::target_seconds)).
    pub draw_seconds: f64,
    /// Seconds creating the render target of a single-pass anti-aliasing mode (none, MSAA,
    /// supersampling up to 5 × 5): its allocation and the clear that first touches every page
    /// (20 bytes per sample). Accumulated and adaptive supersampling create their targets
    /// inside the draw, which counts them.
    pub target_seconds: f64,
    /// With [`RenderOptions::measure_stages`](crate::RenderOptions::measure_stages): seconds the
    /// same passes took with a fragment shader that returns a constant (vertex stage, clipping,
    /// coverage, depth test, interpolation of the varyings, writes). `draw_seconds` minus this is
    /// the shading's cost.
    /// Alpha-masked fragments are not discarded in that pass, so it may do slightly more work.
    pub raster_seconds: Option<f64>,
    /// Views drawn through portals and mirrors, summed over passes.
    pub portal_views: u64,
    /// Fragment and triangle counts of what the portals drew — the scene in the views through
    /// them, and their surfaces — summed over passes.
    pub portal_draw: DrawStats,
    /// Portals seen but drawn closed (the background under the tint), summed over passes: at
    /// the [`portal_depth`](crate::RenderOptions::portal_depth) limit, past the
    /// [`MAX_PORTAL_VIEWS_PER_PASS`](crate::MAX_PORTAL_VIEWS_PER_PASS) budget, or seen so
    /// nearly edge-on that no oblique frustum exists.
    pub portals_closed: u64,
    /// The scene's portals that are not drawn because they fail
    /// [`Portal::check`](barytex_gltf::Portal::check) (degenerate, non-planar, non-convex,
    /// non-finite, singular).
    pub portals_skipped: usize,
}

impl RenderStats {
    /// The statistics of a render that prepared `prepared` and drew `drawn`.
    pub(crate) fn of(prepared: &Prepared<'_>, drawn: &Drawn) -> Self {
        let items = &prepared.items;
        Self {
            primitives: items.len(),
            triangles: items
                .iter()
                .filter(|i| i.kind == ItemKind::Triangles)
                .map(|i| (i.indices.len() + i.phong_indices.len()) / 3)
                .sum(),
            draw: drawn.draw,
            passes: drawn.passes,
            samples_per_pixel: drawn.samples_per_pixel,
            adaptive: drawn.adaptive.clone(),
            textures: prepared.textures.list.len(),
            mip_chains: prepared.textures.mip_chains,
            mips_skipped: prepared.textures.mips_skipped,
            tangents_generated: prepared.tangents_generated,
            hybrid_phong_triangles: prepared.hybrid_phong_triangles,
            hybrid_gouraud_triangles: prepared.hybrid_gouraud_triangles,
            varyings_interpolated: drawn.varyings.0,
            varyings_skipped: drawn.varyings.1,
            prepare_seconds: prepared.seconds,
            mip_seconds: prepared.textures.mip_seconds,
            draw_seconds: drawn.draw_seconds,
            target_seconds: drawn.target_seconds,
            raster_seconds: drawn.raster_seconds,
            portal_views: drawn.portal_views.drawn,
            portal_draw: drawn.portal_views.draw,
            portals_closed: drawn.portal_views.closed,
            portals_skipped: prepared.portals_skipped,
        }
    }
}
