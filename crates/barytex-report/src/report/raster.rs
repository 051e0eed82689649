//! The rasterizer families: perspective interpolation (affine, affine spans, exact) on a ground
//! plane receding to the horizon, against the exact ray–plane texture coordinate; and
//! anti-aliasing (none, MSAA, supersampling regular / per-pixel jittered / accumulated,
//! adaptive) on a Siemens star, against a 256-sample reference. Time is per frame, one thread.

use barytex_raster::{
    AdaptiveOptions, CullMode, Fragment, Framebuffer, Interpolation, PipelineState, SamplePattern,
    Shader, TargetLimits, Viewport, draw, render_adaptive, render_supersampled,
};
use glam::{DVec3, Mat4, Vec2, Vec3, Vec4};

use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::median_frame_seconds;

/// Texels per unit of uv in the perspective family (a 256² texture).
const TEXELS: f64 = 256.0;

/// World-space vertices with uv, drawn as the uv itself (so the image is the interpolation).
struct UvShader {
    mvp: Mat4,
}

impl Shader for UvShader {
    type Vertex = (Vec3, Vec2);
    type Varying = Vec2;
    fn vertex(&self, &(p, uv): &(Vec3, Vec2)) -> (Vec4, Vec2) {
        (self.mvp * p.extend(1.0), uv)
    }
    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        Some(Vec4::new(f.varying.x, f.varying.y, 0.0, 1.0))
    }
}

/// The perspective family: the slanted plane x + y = −1.2 from the origin looking down −z (60°
/// vertical field of view), parametrised by `s` across and `z` along the view, uv = (s/4 + ½,
/// z/4). Depth varies along rows and columns (on a level floor each row has one depth, and
/// affine spans would be exact).
fn perspective_table(settings: Settings, runs: usize) -> Table {
    let quick = settings.random < 1024;
    let (w, h) = if quick { (128_u32, 96_u32) } else { (512, 384) };
    let fov = 60_f32.to_radians();
    let aspect = w as f32 / h as f32;
    let shader = UvShader {
        mvp: barytex_shade::camera::perspective(fov, aspect, 0.1, 400.0),
    };
    let (s_max, z_near, z_far) = (200.0_f32, -0.5_f32, -100.0_f32);
    let r = std::f32::consts::FRAC_1_SQRT_2;
    let on_plane = |s: f32, z: f32| {
        (
            Vec3::new(-0.6 + s * r, -0.6 - s * r, z),
            Vec2::new(s / 4.0 + 0.5, z / 4.0),
        )
    };
    let vertices = vec![
        on_plane(-s_max, z_near),
        on_plane(s_max, z_near),
        on_plane(s_max, z_far),
        on_plane(-s_max, z_far),
    ];
    let indices = [0, 1, 2, 0, 2, 3];
    // The exact uv at each pixel centre, where the ray meets the quad.
    let tan = f64::from(fov / 2.0).tan();
    let exact = |x: u32, y: u32| -> Option<(f64, f64)> {
        let ndc_x = (f64::from(x) + 0.5) / f64::from(w) * 2.0 - 1.0;
        let ndc_y = 1.0 - (f64::from(y) + 0.5) / f64::from(h) * 2.0;
        let d = DVec3::new(ndc_x * f64::from(aspect) * tan, ndc_y * tan, -1.0);
        if d.x + d.y >= 0.0 {
            return None;
        }
        let p = d * (-1.2 / (d.x + d.y));
        let s = (p.x - p.y) * std::f64::consts::FRAC_1_SQRT_2;
        (s.abs() < f64::from(s_max) && p.z < f64::from(z_near) && p.z > f64::from(z_far))
            .then(|| (s / 4.0 + 0.5, p.z / 4.0))
    };
    let methods = [
        ("perspective-correct", Interpolation::Perspective),
        (
            "affine spans of 8 px",
            Interpolation::AffineSpans { span: 8 },
        ),
        (
            "affine spans of 16 px",
            Interpolation::AffineSpans { span: 16 },
        ),
        (
            "affine spans of 32 px",
            Interpolation::AffineSpans { span: 32 },
        ),
        ("affine (wrong foreshortening)", Interpolation::Affine),
    ];
    let mut rows = Vec::new();
    let mut pixels = 0;
    for (name, interpolation) in methods {
        let state = PipelineState {
            cull: CullMode::None,
            depth_compare: None,
            depth_write: false,
            interpolation,
            ..PipelineState::default()
        };
        let (seconds, fb) = median_frame_seconds(runs, || {
            let mut fb =
                Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
            draw(&mut fb, &shader, &state, &vertices, &indices);
            fb
        });
        let mut errors = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let (Some((u, v)), Some(c)) = (exact(x, y), fb.pixel(x, y)) else {
                    continue;
                };
                if c.w == 0.0 {
                    continue;
                }
                let d = (f64::from(c.x) - u).hypot(f64::from(c.y) - v) * TEXELS;
                errors.push(d);
            }
        }
        pixels = errors.len();
        rows.push(Row {
            method: name.to_owned(),
            is_default: interpolation == Interpolation::Perspective,
            ns: seconds * 1e9 / f64::from(w * h),
            abs: ErrorStats::of(errors),
            ..Row::default()
        });
    }
    Table {
        title: "perspective interpolation on a receding slanted plane".to_owned(),
        description: format!(
            "A {w}×{h} view of the slanted plane x + y = −1.2 from the origin (60° vertical field \
             of view; depth varies along rows, so spans are not trivially exact), uv = (s/4 + ½, \
             z/4) with s across the plane, z ∈ [−100, −0.5], on a 256² texture: the error is \
             |Δuv| in **texels** against the exact ray–plane intersection at each covered pixel \
             centre (f64); time is ns per **pixel of the frame** (the fragment stage only \
             outputs the uv, so interpolation dominates), median of {runs} frames, one thread."
        ),
        inputs: pixels,
        rows,
        time_unit: "pixel".to_owned(),
        error_label: "max |Δuv| (texels)".to_owned(),
        ..Table::default()
    }
}

/// White triangles given in pixels of a `size` target.
struct White {
    size: Vec2,
}

impl Shader for White {
    type Vertex = Vec2;
    type Varying = f32;
    fn vertex(&self, p: &Vec2) -> (Vec4, f32) {
        (
            Vec4::new(
                p.x / self.size.x * 2.0 - 1.0,
                1.0 - p.y / self.size.y * 2.0,
                0.5,
                1.0,
            ),
            0.0,
        )
    }
    fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(Vec4::ONE)
    }
}

/// A Siemens star: `spokes` white wedges around the image centre, reaching past the corners.
fn siemens_star(w: u32, h: u32, spokes: u32) -> (Vec<Vec2>, Vec<u32>) {
    let centre = Vec2::new(w as f32, h as f32) * 0.5 + Vec2::new(0.37, 0.21);
    let radius = (w.max(h) as f32) * 1.5;
    let mut vertices = Vec::new();
    for k in 0..spokes {
        let a0 = (2 * k) as f32 * std::f32::consts::PI / spokes as f32 + 0.1;
        let a1 = a0 + std::f32::consts::PI / spokes as f32;
        vertices.push(centre);
        vertices.push(centre + Vec2::new(a0.cos(), a0.sin()) * radius);
        vertices.push(centre + Vec2::new(a1.cos(), a1.sin()) * radius);
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices)
}

/// The anti-aliasing family on a Siemens star.
#[allow(clippy::too_many_lines)]
fn anti_aliasing_table(settings: Settings, runs: usize) -> (Table, String) {
    let quick = settings.random < 1024;
    let (w, h) = if quick { (96_u32, 64_u32) } else { (256, 192) };
    let (vertices, indices) = siemens_star(w, h, 24);
    let shader = White {
        size: Vec2::new(w as f32, h as f32),
    };
    let black = Vec4::new(0.0, 0.0, 0.0, 1.0);
    let limits = TargetLimits::default();
    let state = PipelineState {
        cull: CullMode::None,
        depth_compare: None,
        depth_write: false,
        ..PipelineState::default()
    };
    let (shader, vertices, indices, limits) = (&shader, &vertices, &indices, &limits);
    let pass = move |fb: &mut Framebuffer, shift: Vec2| {
        let state = PipelineState {
            viewport: Some(Viewport {
                x: shift.x,
                y: shift.y,
                ..Viewport::full(w, h)
            }),
            ..state
        };
        draw(fb, shader, &state, vertices, indices);
    };
    let n_ref = if quick { 8 } else { 16 };
    let reference = render_supersampled(
        w,
        h,
        black,
        SamplePattern::Regular { n: n_ref },
        limits,
        pass,
    )
    .expect("small");
    let multisampled = |pattern: SamplePattern, sample_shading: bool| {
        let state = PipelineState {
            sample_shading,
            ..state
        };
        move || {
            let mut fb = Framebuffer::multisampled(w, h, pattern, black, limits).expect("small");
            draw(&mut fb, shader, &state, vertices, indices);
            (fb, f64::from(pattern.count()))
        }
    };
    type Method<'a> = (&'a str, Box<dyn FnMut() -> (Framebuffer, f64) + Send + 'a>);
    let mut methods: Vec<Method<'_>> = vec![
        (
            "1 sample (no anti-aliasing)",
            Box::new(multisampled(SamplePattern::CENTRE, false)),
        ),
        (
            "MSAA 4, standard positions",
            Box::new(multisampled(SamplePattern::Standard { count: 4 }, false)),
        ),
        (
            "MSAA 8, standard positions",
            Box::new(multisampled(SamplePattern::Standard { count: 8 }, false)),
        ),
        (
            "MSAA 16, standard positions",
            Box::new(multisampled(SamplePattern::Standard { count: 16 }, false)),
        ),
        (
            "supersampling 4×4 regular, shading per sample",
            Box::new(multisampled(SamplePattern::Regular { n: 4 }, true)),
        ),
        (
            "supersampling 4×4 jittered per pixel, shading per sample",
            Box::new(multisampled(
                SamplePattern::Jittered { n: 4, seed: 1 },
                true,
            )),
        ),
        (
            "supersampling 4×4 regular by 16 accumulated passes",
            Box::new(|| {
                let fb =
                    render_supersampled(w, h, black, SamplePattern::Regular { n: 4 }, limits, pass)
                        .expect("small");
                (fb, 16.0)
            }),
        ),
        (
            "adaptive, 4 to 40 samples",
            Box::new(|| {
                let (fb, stats) =
                    render_adaptive(w, h, black, &AdaptiveOptions::default(), limits, pass)
                        .expect("small");
                (fb, stats.mean_samples())
            }),
        ),
    ];
    let mut rows = Vec::new();
    let mut notes = Vec::new();
    let mut edge_pixels = 0;
    for (name, render) in &mut methods {
        let (seconds, (fb, samples)) = median_frame_seconds(runs, render);
        let mut errors = Vec::new();
        let mut squared = 0.0;
        for y in 0..h {
            for x in 0..w {
                let r = f64::from(reference.pixel(x, y).expect("inside").x);
                let g = f64::from(fb.pixel(x, y).expect("inside").x);
                squared += (g - r) * (g - r);
                if r > 1e-3 && r < 1.0 - 1e-3 {
                    errors.push((g - r).abs());
                }
            }
        }
        edge_pixels = errors.len();
        let psnr = 10.0 * (f64::from(w * h) / squared.max(1e-30)).log10();
        notes.push(format!(
            "{name}: {samples:.2} samples per pixel, PSNR {psnr:.1} dB"
        ));
        rows.push(Row {
            method: format!("{name} ({samples:.1} spp)"),
            is_default: name.starts_with("1 sample"),
            ns: seconds * 1e9 / f64::from(w * h),
            abs: ErrorStats::of(errors),
            ..Row::default()
        });
    }
    let table = Table {
        title: "anti-aliasing on a Siemens star".to_owned(),
        description: format!(
            "A {w}×{h} Siemens star of 24 white wedges on black (edges at every angle, frequencies \
             rising to the centre), resolved in linear light; the error is |pixel − reference| \
             over the {edge_pixels} pixels the reference shows partly covered, against \
             {n_ref}×{n_ref} = {} regular samples per pixel by accumulation. `spp` is samples per \
             pixel (adaptive: the mean it took). Time is ns per pixel of the frame, median of \
             {runs} frames, one thread. MSAA shades once per pixel, so it anti-aliases edges \
             only; the supersampling rows shade every sample.",
            n_ref * n_ref
        ),
        inputs: edge_pixels,
        rows,
        time_unit: "pixel".to_owned(),
        error_label: "max |pixel − reference| (linear light)".to_owned(),
        ..Table::default()
    };
    (
        table,
        format!("Anti-aliasing, whole image: {}.", notes.join("; ")),
    )
}

/// Both raster tables.
pub(crate) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let runs = if settings.random < 1024 { 2 } else { 7 };
    progress("perspective interpolation");
    let perspective = perspective_table(settings, runs);
    progress("anti-aliasing");
    let (aa, note) = anti_aliasing_table(settings, runs);
    Section {
        heading: "Rasterizer".to_owned(),
        intro: "barytex-raster's speed-vs-error options, each on one scene, against an exact or \
                heavily supersampled reference."
            .to_owned(),
        tables: vec![perspective, aa],
        notes: vec![note],
    }
}
