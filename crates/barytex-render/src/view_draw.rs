//! One view of the scene drawn into a target: the opaque and masked items, then every portal
//! the view sees (its visible samples masked, the view through it drawn into a second target
//! and copied back through the mask, recursively up to the depth limit, then its tinted
//! surface), then the blended items back to front. Without portals this is the item loop alone.

use barytex_raster::{
    Blend, CullMode, DepthCompare, DrawStats, Framebuffer, FrontFace, PipelineState, RasterError,
    Shader, TargetLimits, Viewport, draw, draw_lines, draw_points, mask_samples,
};
use glam::{Vec2, Vec3};

use crate::RenderOptions;
use crate::material_shader::{Frequency, MaterialShader};
use crate::portals::{PortalSurface, View};
use crate::prepare::{ItemKind, Prepared};
use crate::raster_only::RasterOnly;
use crate::unlit_shader::UnlitShader;

/// The most views drawn through portals in one pass over the scene; beyond it a portal shows
/// the background, as at the depth limit (each portal a view sees can open another view, so
/// the count can grow as the number of portals to the power of the depth).
pub const MAX_PORTAL_VIEWS_PER_PASS: u64 = 256;

/// What the portals of a render did, summed over its passes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct PortalViews {
    /// Views drawn through a portal.
    pub(crate) drawn: u64,
    /// Portals seen at the depth limit (or past the per-pass view budget, or whose oblique
    /// frustum degenerates): their region shows the background.
    pub(crate) closed: u64,
    /// What the portals drew: the views through them and their surfaces.
    pub(crate) draw: DrawStats,
    /// Views drawn in the current pass (against [`MAX_PORTAL_VIEWS_PER_PASS`]).
    in_pass: u64,
}

impl PortalViews {
    /// Starts counting a new pass against the per-pass budget.
    pub(crate) fn new_pass(&mut self) {
        self.in_pass = 0;
    }
}

/// Draws one item's primitives of `kind` with `shader`, or with a constant fragment stage when
/// `raster_only`.
fn draw_item<S: Shader<Vertex = u32>>(
    fb: &mut Framebuffer,
    shader: &S,
    state: &PipelineState,
    kind: ItemKind,
    raster_only: bool,
    vertices: &[u32],
    indices: &[u32],
) -> DrawStats {
    let (v, raster) = (vertices, &RasterOnly(shader));
    match (kind, raster_only) {
        (ItemKind::Triangles, true) => draw(fb, raster, state, v, indices),
        (ItemKind::Triangles, false) => draw(fb, shader, state, v, indices),
        (ItemKind::Points, true) => draw_points(fb, raster, state, v, indices),
        (ItemKind::Points, false) => draw_points(fb, shader, state, v, indices),
        (ItemKind::Lines(t), true) => draw_lines(fb, raster, state, v, indices, t),
        (ItemKind::Lines(t), false) => draw_lines(fb, shader, state, v, indices, t),
    }
}

/// Everything a view's draws share.
pub(crate) struct SceneDraw<'a> {
    pub(crate) prepared: &'a Prepared<'a>,
    pub(crate) options: &'a RenderOptions,
    pub(crate) frequency: Frequency,
    pub(crate) sample_shading: bool,
    pub(crate) interpolate_all: bool,
}

impl SceneDraw<'_> {
    /// The pipeline state of a draw in `view`, with the viewport moved by `shift`.
    fn state(&self, view: &View, shift: Vec2, flips_winding: bool) -> PipelineState {
        let (width, height) = (self.options.width, self.options.height);
        PipelineState {
            // A mirrored view turns every triangle's winding on screen.
            front_face: if flips_winding != view.flips {
                FrontFace::Cw
            } else {
                FrontFace::Ccw
            },
            viewport: Some(Viewport {
                x: shift.x,
                y: shift.y,
                ..Viewport::full(width, height)
            }),
            sample_shading: self.sample_shading,
            ..PipelineState::default()
        }
    }

    /// Draws the items `order` (indices into the prepared items) as `view` sees them, with a
    /// constant fragment stage when `raster_only`.
    fn draw_items(
        &self,
        fb: &mut Framebuffer,
        shift: Vec2,
        raster_only: bool,
        view: &View,
        order: &[usize],
    ) -> DrawStats {
        let prepared = self.prepared;
        let items = &prepared.items;
        let mut stats = DrawStats::default();
        for &i in order {
            let item = &items[i];
            let passes: [(Frequency, &[u32]); 2] = [
                (self.frequency, &item.indices),
                (Frequency::Phong, &item.phong_indices),
            ];
            for (frequency, indices) in passes {
                if indices.is_empty() {
                    continue;
                }
                let shader = MaterialShader {
                    frequency,
                    environment: prepared.environment.as_ref(),
                    fog: self.options.fog.map(|f| (f, view.forward)),
                    view_projection: view.view_projection,
                    eye: view.eye,
                    primitive: &item.primitive,
                    material: item.material,
                    textures: &prepared.textures.list,
                    lights: &prepared.lights,
                    ambient: Vec3::splat(0.03),
                    interpolate_all: self.interpolate_all,
                };
                let state = PipelineState {
                    cull: if item.double_sided {
                        CullMode::None
                    } else {
                        CullMode::Back
                    },
                    blend: if item.blended {
                        Blend::Over
                    } else {
                        Blend::Replace
                    },
                    depth_write: !item.blended,
                    ..self.state(view, shift, item.flips_winding)
                };
                let v = &item.vertices;
                let s = match UnlitShader::of(&shader) {
                    Some(unlit) => {
                        draw_item(fb, &unlit, &state, item.kind, raster_only, v, indices)
                    }
                    None => draw_item(fb, &shader, &state, item.kind, raster_only, v, indices),
                };
                stats += &s;
            }
        }
        stats
    }

    /// Draws the scene as `view` sees it into `fb` (viewport moved by `shift`), portals and all;
    /// returns what the scene's own items drew in this view (what the portals drew goes to
    /// `portal_views`).
    ///
    /// # Errors
    /// A target or mask for a portal's view that cannot be allocated.
    pub(crate) fn draw_view(
        &self,
        fb: &mut Framebuffer,
        shift: Vec2,
        raster_only: bool,
        view: &View,
        portal_views: &mut PortalViews,
    ) -> Result<DrawStats, RasterError> {
        let prepared = self.prepared;
        let order = &prepared.order;
        if prepared.portals.is_empty() {
            return Ok(self.draw_items(fb, shift, raster_only, view, order));
        }
        let opaque = order
            .iter()
            .take_while(|&&i| !prepared.items[i].blended)
            .count();
        let mut stats = self.draw_items(fb, shift, raster_only, view, &order[..opaque]);
        for portal in &prepared.portals {
            if !view.sees(portal) {
                continue;
            }
            let surface = |color| PortalSurface {
                view_projection: view.view_projection,
                color,
            };
            // The portal's samples that are visible in this view: one-sided, depth-tested
            // against what is drawn, not written.
            let state = PipelineState {
                depth_compare: Some(DepthCompare::Less),
                depth_write: false,
                ..self.state(view, shift, false)
            };
            let clip: Vec<_> = portal
                .polygon
                .iter()
                .map(|p| view.view_projection * p.extend(1.0))
                .collect();
            let (mask, _) = mask_samples(fb, &state, &clip, &portal.fan)?;
            if mask.is_empty() {
                continue;
            }
            let inner_view = (view.level < self.options.portal_depth
                && portal_views.in_pass < MAX_PORTAL_VIEWS_PER_PASS)
                .then(|| view.through(portal, prepared.camera.projection))
                .flatten();
            match inner_view {
                Some(inner_view) => {
                    portal_views.drawn += 1;
                    portal_views.in_pass += 1;
                    let mut inner = Framebuffer::multisampled(
                        fb.width(),
                        fb.height(),
                        fb.pattern(),
                        self.options.background,
                        &TargetLimits::default(),
                    )?;
                    // Only the pixels the mask touches are rasterized and shaded.
                    inner.set_mask(Some(&|x, y| mask.pixel(x, y) != 0))?;
                    let seen =
                        self.draw_view(&mut inner, shift, raster_only, &inner_view, portal_views)?;
                    portal_views.draw += &seen;
                    fb.copy_samples(&inner, &mask)?;
                }
                None => {
                    // Closed: the background, on exactly the masked samples.
                    portal_views.closed += 1;
                    let background = surface(self.options.background);
                    let s = draw(fb, &background, &state, &portal.polygon, &portal.fan);
                    portal_views.draw += &s;
                }
            }
            // The surface: the tint over the view, and the portal's depth, so that what is
            // drawn later (other portals, blended items) is hidden behind it.
            let over = PipelineState {
                blend: Blend::Over,
                depth_write: true,
                ..state
            };
            portal_views.draw += &draw(
                fb,
                &surface(portal.tint),
                &over,
                &portal.polygon,
                &portal.fan,
            );
        }
        stats += &self.draw_items(fb, shift, raster_only, view, &order[opaque..]);
        Ok(stats)
    }
}
