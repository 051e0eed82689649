//! The passes over a prepared scene: one material shader per item and shading frequency, drawn
//! in order into the target the anti-aliasing mode asks for (one multisampled target, or
//! accumulated or adaptive supersampling over several passes).

use std::time::Instant;

use barytex_raster::{
    AdaptiveOptions, AdaptiveStats, DrawStats, Framebuffer, RasterError, SamplePattern,
    TargetLimits, render_adaptive, render_supersampled,
};
use glam::{Vec2, Vec3};

use crate::material_shader::{Frequency, MaterialShader};
use crate::portals::View;
use crate::prepare::Prepared;
use crate::surface::Reads;
use crate::view_draw::{PortalViews, SceneDraw};
use crate::{AntiAliasing, RenderError, RenderOptions, Shading, planned_passes};

/// Which parts of the varying the material shaders interpolate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Varyings {
    /// Only what each material reads (the renderer's behaviour).
    Read,
    /// Every part (tests check that skipping the unread parts changes no pixel).
    #[cfg_attr(not(test), allow(dead_code))]
    All,
}

/// What the passes produced.
pub(crate) struct Drawn {
    pub(crate) image: Framebuffer,
    pub(crate) draw: DrawStats,
    pub(crate) passes: u32,
    pub(crate) samples_per_pixel: f64,
    pub(crate) adaptive: Option<AdaptiveStats>,
    /// Varying floats interpolated per fragment, and those skipped, summed over the draws.
    pub(crate) varyings: (usize, usize),
    pub(crate) draw_seconds: f64,
    pub(crate) target_seconds: f64,
    pub(crate) raster_seconds: Option<f64>,
    /// What the portals did.
    pub(crate) portal_views: PortalViews,
}

/// The shading frequency of the items' main index lists.
fn frequency(shading: Shading) -> Frequency {
    match shading {
        Shading::Flat => Frequency::Flat,
        Shading::Gouraud | Shading::Hybrid => Frequency::Gouraud,
        Shading::Unlit | Shading::Phong => Frequency::Phong,
    }
}

/// Draws `prepared` as `options` ask, calling `on_pass(done, planned)` after each pass.
///
/// # Errors
/// An invalid sample count, or a target that cannot be allocated.
#[allow(clippy::too_many_lines)] // One dispatch over the anti-aliasing modes.
pub(crate) fn draw_passes(
    prepared: &Prepared<'_>,
    options: &RenderOptions,
    varyings: Varyings,
    on_pass: &mut dyn FnMut(u32, u32),
) -> Result<Drawn, RenderError> {
    let (width, height) = (options.width, options.height);
    let camera = &prepared.camera;
    let view_projection = camera.projection * camera.view;
    let forward = camera.forward();
    let items = &prepared.items;
    let sample_shading = matches!(
        options.anti_aliasing,
        AntiAliasing::Supersample(_) | AntiAliasing::Jitter(_)
    );
    let frequency = frequency(options.shading);
    let shader_for = |i: usize, frequency| MaterialShader {
        frequency,
        environment: prepared.environment.as_ref(),
        fog: options.fog.map(|f| (f, forward)),
        view_projection,
        eye: camera.eye,
        primitive: &items[i].primitive,
        material: items[i].material,
        textures: &prepared.textures.list,
        lights: &prepared.lights,
        ambient: Vec3::splat(0.03),
        interpolate_all: varyings == Varyings::All,
    };
    // The varying floats each draw interpolates, and those it skips (never read).
    let (mut varyings_interpolated, mut varyings_skipped) = (0, 0);
    for (i, item) in items.iter().enumerate() {
        for (frequency, indices) in [
            (frequency, &item.indices),
            (Frequency::Phong, &item.phong_indices),
        ] {
            if !indices.is_empty() {
                let reads = shader_for(i, frequency).reads();
                for (part, _, floats) in Reads::PARTS {
                    if reads.contains(part) {
                        varyings_interpolated += floats;
                    } else {
                        varyings_skipped += floats;
                    }
                }
            }
        }
    }
    let scene = SceneDraw {
        prepared,
        options,
        frequency,
        sample_shading,
        interpolate_all: varyings == Varyings::All,
    };
    let camera_view = View::camera(camera);
    // Errors inside a pass (a target for a portal's view that cannot be allocated) are kept
    // for after the passes, which run inside the raster crate's callbacks.
    let mut pass_error: Option<RasterError> = None;
    let mut portal_views = PortalViews::default();
    let mut total = DrawStats::default();
    let mut passes = 0_u32;
    // Seconds of the constant-shader passes, and of those passes with their copies (taken out
    // of the draw time).
    let (mut raster_seconds, mut measuring_seconds) = (0.0, 0.0);
    let mut draw_scene = |fb: &mut Framebuffer, shift: Vec2| {
        passes += 1;
        portal_views.new_pass();
        if options.measure_stages {
            // The same pass from the same state (depth, mask), into a copy that is dropped.
            let copying = Instant::now();
            let mut scratch = fb.clone();
            let started = Instant::now();
            let mut ignored = PortalViews::default();
            if let Err(e) = scene.draw_view(&mut scratch, shift, true, &camera_view, &mut ignored) {
                pass_error.get_or_insert(e);
            }
            raster_seconds += started.elapsed().as_secs_f64();
            measuring_seconds += copying.elapsed().as_secs_f64();
        }
        match scene.draw_view(fb, shift, false, &camera_view, &mut portal_views) {
            Ok(stats) => total += &stats,
            Err(e) => {
                pass_error.get_or_insert(e);
            }
        }
        on_pass(passes, planned_passes(options.anti_aliasing));
    };
    let limits = TargetLimits::default();
    let background = options.background;
    let drawing = Instant::now();
    // Seconds creating the one target of the single-pass modes (allocation and the clear that
    // first touches every page), told apart from the draw: a renderer drawing frame after
    // frame clears one target instead.
    let target_seconds = core::cell::Cell::new(0.0);
    let multisampled = |pattern: SamplePattern,
                        draw_scene: &mut dyn FnMut(&mut Framebuffer, Vec2)| {
        let creating = Instant::now();
        let mut fb = Framebuffer::multisampled(width, height, pattern, background, &limits)?;
        target_seconds.set(target_seconds.get() + creating.elapsed().as_secs_f64());
        draw_scene(&mut fb, Vec2::ZERO);
        Ok::<_, RasterError>((fb, f64::from(pattern.count())))
    };
    let mut adaptive = None;
    let (image, samples_per_pixel) = match options.anti_aliasing {
        AntiAliasing::None => multisampled(SamplePattern::CENTRE, &mut draw_scene)?,
        AntiAliasing::Msaa(n) => {
            multisampled(SamplePattern::Standard { count: n }, &mut draw_scene)?
        }
        AntiAliasing::Supersample(n) | AntiAliasing::Jitter(n) if n == 0 || n > 16 => {
            return Err(RenderError::InvalidOption(format!(
                "{n}×{n} samples per pixel (n from 1 to 16)"
            )));
        }
        AntiAliasing::Supersample(n) if n <= 5 => {
            multisampled(SamplePattern::Regular { n }, &mut draw_scene)?
        }
        AntiAliasing::Jitter(n) if n <= 5 => {
            multisampled(SamplePattern::Jittered { n, seed: 1 }, &mut draw_scene)?
        }
        AntiAliasing::Supersample(n) => (
            render_supersampled(
                width,
                height,
                background,
                SamplePattern::Regular { n },
                &limits,
                &mut draw_scene,
            )?,
            f64::from(n * n),
        ),
        AntiAliasing::Jitter(n) => (
            render_supersampled(
                width,
                height,
                background,
                SamplePattern::Jittered { n, seed: 1 },
                &limits,
                &mut draw_scene,
            )?,
            f64::from(n * n),
        ),
        AntiAliasing::Adaptive(max) => {
            let adaptive_options = AdaptiveOptions {
                max_samples: max.max(4),
                ..AdaptiveOptions::default()
            };
            let (fb, stats) = render_adaptive(
                width,
                height,
                background,
                &adaptive_options,
                &limits,
                &mut draw_scene,
            )?;
            let spp = stats.mean_samples();
            adaptive = Some(stats);
            (fb, spp)
        }
    };
    let target_seconds = target_seconds.get();
    let draw_seconds = drawing.elapsed().as_secs_f64() - measuring_seconds - target_seconds;
    if let Some(e) = pass_error {
        return Err(e.into());
    }
    Ok(Drawn {
        portal_views,
        image,
        draw: total,
        passes,
        samples_per_pixel,
        adaptive,
        varyings: (varyings_interpolated, varyings_skipped),
        draw_seconds,
        target_seconds,
        raster_seconds: options.measure_stages.then_some(raster_seconds),
    })
}
