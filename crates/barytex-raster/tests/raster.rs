//! The rasterizer: watertightness and the top-left rule, perspective-correct varyings and their
//! derivatives, near-plane clipping, robustness, determinism across thread counts.

mod common;

use std::sync::atomic::Ordering;

use barytex_raster::TargetLimits;
use barytex_raster::{
    CullMode, DrawStats, Fragment, Framebuffer, Interpolation, PipelineState, Shader, draw,
};
use common::{Counter, no_depth};
use glam::{Mat4, Vec2, Vec3, Vec4};
use proptest::prelude::*;

/// Screen position (pixels, y down) of a `w × h` target → clip space with w = 1.
fn clip_of(p: Vec2, w: u32, h: u32) -> Vec4 {
    Vec4::new(
        p.x / w as f32 * 2.0 - 1.0,
        1.0 - p.y / h as f32 * 2.0,
        0.5,
        1.0,
    )
}

/// [`common::jittered_grid`] in clip space.
fn jittered_grid(n: u32, w: u32, h: u32, seed: u64) -> (Vec<Vec4>, Vec<u32>) {
    let (screen, indices) = common::jittered_grid(n, w, h, seed);
    (screen.iter().map(|&p| clip_of(p, w, h)).collect(), indices)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Watertight: a jittered mesh covering the whole target shades every pixel exactly once —
    /// no gaps and no double coverage along shared edges, whatever the jitter.
    #[test]
    fn meshes_are_watertight(n in 2_u32..24, seed in any::<u64>(), w in 8_u32..80, h in 8_u32..80) {
        let (vertices, indices) = jittered_grid(n, w, h, seed);
        let counter = Counter::new(w, h);
        let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
        let stats = draw(&mut fb, &counter, &no_depth(), &vertices, &indices);
        for (i, c) in counter.counts.iter().enumerate() {
            prop_assert_eq!(c.load(Ordering::Relaxed), 1, "pixel {} covered wrongly", i);
        }
        prop_assert_eq!(stats.fragments_shaded, u64::from(w * h));
    }

    /// Totality: any bit patterns as clip coordinates and any indices — no panic, every triangle
    /// accounted for, nothing written outside the target (the counter would panic on an index).
    #[test]
    fn total_on_hostile_geometry(bits in prop::collection::vec(any::<[u32; 4]>(), 3..12),
                                 indices in prop::collection::vec(0_u32..14, 0..30)) {
        let vertices: Vec<Vec4> = bits
            .iter()
            .map(|b| Vec4::from_array(b.map(f32::from_bits)))
            .collect();
        let counter = Counter::new(16, 16);
        let mut fb = Framebuffer::new(16, 16, Vec4::ZERO, &TargetLimits::default()).expect("small");
        let stats = draw(&mut fb, &counter, &no_depth(), &vertices, &indices);
        let accounted = stats.dropped_bad_index + stats.dropped_non_finite + stats.clipped_away
            + stats.culled + stats.degenerate;
        prop_assert!(accounted <= stats.triangles_in);
        prop_assert_eq!(stats.triangles_in, (indices.len() / 3) as u64);
    }
}

/// The top-left rule on pixel centres exactly on edges: an axis-aligned rectangle from x = 0.5
/// to 2.5 and y = 0.5 to 2.5 covers the centres on its left and top edges (column 0, row 0) but
/// not those on its right and bottom edges (column 2, row 2).
#[test]
fn top_left_rule_on_pixel_centres() {
    let (w, h) = (4, 4);
    let corners = [
        Vec2::new(0.5, 0.5),
        Vec2::new(2.5, 0.5),
        Vec2::new(2.5, 2.5),
        Vec2::new(0.5, 2.5),
    ];
    let vertices: Vec<Vec4> = corners.iter().map(|&p| clip_of(p, w, h)).collect();
    let counter = Counter::new(w, h);
    let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
    draw(
        &mut fb,
        &counter,
        &no_depth(),
        &vertices,
        &[0, 1, 2, 0, 2, 3],
    );
    let covered: Vec<u32> = counter
        .counts
        .iter()
        .map(|c| c.load(Ordering::Relaxed))
        .collect();
    #[rustfmt::skip]
    let want = [
        1, 1, 0, 0,
        1, 1, 0, 0,
        0, 0, 0, 0,
        0, 0, 0, 0,
    ];
    assert_eq!(covered, want);
}

/// A textured plane in perspective: uv from the shader, compared with the exact uv of the
/// ray through each pixel centre (f64 ray–plane intersection), and its derivatives compared
/// with exact differences of that mapping.
struct PlaneUv {
    view_projection: Mat4,
}

impl Shader for PlaneUv {
    type Vertex = (Vec3, Vec2);
    type Varying = Vec2;
    fn vertex(&self, v: &(Vec3, Vec2)) -> (Vec4, Vec2) {
        (self.view_projection * v.0.extend(1.0), v.1)
    }
    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        Some(Vec4::new(f.varying.x, f.varying.y, f.ddx().x, f.ddy().y))
    }
}

/// Perspective with depth in [0, 1] and y up in clip space, looking down −z: glam's right-handed
/// DirectX-convention `perspective`.
fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    glam::camera::rh::proj::directx::perspective(fov_y, aspect, near, far)
}

fn ground_plane() -> (Vec<(Vec3, Vec2)>, Vec<u32>) {
    // The plane y = −1, x ∈ [−4, 4], z ∈ [−20, −1]; uv = ((x + 4)/8, (z + 20)/19).
    let corners = [(-4.0, -20.0), (4.0, -20.0), (4.0, -1.0), (-4.0, -1.0)];
    let vertices = corners
        .iter()
        .map(|&(x, z)| {
            (
                Vec3::new(x, -1.0, z),
                Vec2::new((x + 4.0) / 8.0, (z + 20.0) / 19.0),
            )
        })
        .collect();
    (vertices, vec![0, 2, 1, 0, 3, 2])
}

/// The exact uv at pixel centre (x, y) of a `w × h` image (f64 ray–plane intersection).
fn exact_uv(x: f64, y: f64, w: f64, h: f64, fov_y: f64) -> Option<(f64, f64)> {
    let t = (fov_y / 2.0).tan();
    let dx = (x / w * 2.0 - 1.0) * t * (w / h);
    let dy = (1.0 - y / h * 2.0) * t;
    // Ray (dx, dy, −1)·s meets y = −1 at s = −1/dy.
    if dy >= 0.0 {
        return None;
    }
    let s = -1.0 / dy;
    let (px, pz) = (dx * s, -s);
    ((-4.0..=4.0).contains(&px) && (-20.0..=-1.0).contains(&pz))
        .then(|| ((px + 4.0) / 8.0, (pz + 20.0) / 19.0))
}

#[test]
fn perspective_correct_varyings_and_derivatives_are_exact() {
    let (w, h) = (96_u32, 64_u32);
    let fov = 60_f32.to_radians();
    let shader = PlaneUv {
        view_projection: perspective(fov, w as f32 / h as f32, 0.1, 100.0),
    };
    let (vertices, indices) = ground_plane();
    let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    let stats = draw(&mut fb, &shader, &state, &vertices, &indices);
    assert!(stats.fragments_shaded > 1000, "{stats:?}");
    let (mut checked, mut worst_uv, mut worst_d) = (0, 0.0_f64, 0.0_f64);
    for y in 0..h {
        for x in 0..w {
            let (cx, cy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            // Only pixels whose centre and neighbours are inside the plane.
            let (Some(uv), Some(right), Some(down)) = (
                exact_uv(cx, cy, f64::from(w), f64::from(h), f64::from(fov)),
                exact_uv(cx + 1e-3, cy, f64::from(w), f64::from(h), f64::from(fov)),
                exact_uv(cx, cy + 1e-3, f64::from(w), f64::from(h), f64::from(fov)),
            ) else {
                continue;
            };
            let Some(c) = fb.pixel(x, y) else { continue };
            if c.w == 0.0 {
                continue;
            }
            checked += 1;
            let du_dx = (right.0 - uv.0) / 1e-3;
            let dv_dy = (down.1 - uv.1) / 1e-3;
            let (du_dy, dv_dx) = ((down.0 - uv.0) / 1e-3, (right.1 - uv.1) / 1e-3);
            // Vertices snap to 1/256 pixel, which moves the image of the plane by up to that:
            // the uv error is bounded by the uv gradient times 1/256 pixel (plus f32 rounding).
            let bound_u = (du_dx.abs() + du_dy.abs()) / 256.0 + 1e-5;
            let bound_v = (dv_dx.abs() + dv_dy.abs()) / 256.0 + 1e-5;
            worst_uv = worst_uv
                .max((f64::from(c.x) - uv.0).abs() / bound_u)
                .max((f64::from(c.y) - uv.1).abs() / bound_v);
            worst_d = worst_d
                .max((f64::from(c.z) - du_dx).abs() / du_dx.abs().max(1e-6))
                .max((f64::from(c.w) - dv_dy).abs() / dv_dy.abs().max(1e-6));
        }
    }
    assert!(checked > 1000, "{checked} pixels checked");
    assert!(worst_uv <= 1.0, "worst uv error / bound {worst_uv}");
    assert!(worst_d < 2e-2, "worst relative derivative error {worst_d}");
}

/// GPU-style quad differences are close to the analytic derivative but less accurate against the
/// exact one (they measure it half a pixel away).
struct QuadVsAnalytic {
    view_projection: Mat4,
}

impl Shader for QuadVsAnalytic {
    type Vertex = (Vec3, Vec2);
    type Varying = Vec2;
    fn vertex(&self, v: &(Vec3, Vec2)) -> (Vec4, Vec2) {
        (self.view_projection * v.0.extend(1.0), v.1)
    }
    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        Some(Vec4::new(f.ddy().y, f.ddy_quad().y, 0.0, 1.0))
    }
}

#[test]
fn quad_derivatives_are_close_but_less_exact_than_analytic() {
    let (w, h) = (96_u32, 64_u32);
    let fov = 60_f32.to_radians();
    let shader = QuadVsAnalytic {
        view_projection: perspective(fov, w as f32 / h as f32, 0.1, 100.0),
    };
    let (vertices, indices) = ground_plane();
    let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    draw(&mut fb, &shader, &state, &vertices, &indices);
    let (mut analytic_err, mut quad_err, mut n) = (0.0_f64, 0.0_f64, 0);
    for y in 0..h {
        for x in 0..w {
            let (cx, cy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let (Some(uv), Some(down), Some(c)) = (
                exact_uv(cx, cy, f64::from(w), f64::from(h), f64::from(fov)),
                exact_uv(cx, cy + 1e-3, f64::from(w), f64::from(h), f64::from(fov)),
                fb.pixel(x, y),
            ) else {
                continue;
            };
            if c.w == 0.0 || c.x == 0.0 {
                continue;
            }
            let exact = (down.1 - uv.1) / 1e-3;
            analytic_err += (f64::from(c.x) - exact).abs() / exact.abs();
            quad_err += (f64::from(c.y) - exact).abs() / exact.abs();
            n += 1;
        }
    }
    assert!(n > 1000, "{n}");
    let (analytic_err, quad_err) = (analytic_err / f64::from(n), quad_err / f64::from(n));
    println!(
        "mean relative error of ∂v/∂y over {n} pixels: analytic {analytic_err:.2e}, quad {quad_err:.2e}"
    );
    assert!(quad_err < 0.2, "quad differences far off: {quad_err}");
    assert!(
        analytic_err < quad_err / 4.0,
        "analytic {analytic_err} vs quad {quad_err}"
    );
    // An absolute bound too: relative to the quad error alone (6.9e-2 measured), a 100× worse
    // analytic derivative would still pass. The analytic mean is measured at 1.46e-4, which
    // includes the f32 rounding of the output and the error of the reference itself (a forward
    // difference of the exact uv with a 1e-3 pixel step); 1e-3 leaves about 7× headroom and
    // still fails a 10× regression.
    assert!(
        analytic_err < 1e-3,
        "analytic derivative regressed: mean relative error {analytic_err}"
    );
}

/// Affine interpolation shows the wrong foreshortening of Buss, *3D Computer Graphics* (2003),
/// Figure V.2: on the same plane its uv error is orders of magnitude larger.
#[test]
fn affine_interpolation_is_visibly_wrong_under_perspective() {
    let (w, h) = (96_u32, 64_u32);
    let fov = 60_f32.to_radians();
    let shader = PlaneUv {
        view_projection: perspective(fov, w as f32 / h as f32, 0.1, 100.0),
    };
    let (vertices, indices) = ground_plane();
    let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let state = PipelineState {
        cull: CullMode::None,
        interpolation: Interpolation::Affine,
        ..PipelineState::default()
    };
    draw(&mut fb, &shader, &state, &vertices, &indices);
    let mut worst: f64 = 0.0;
    for y in 0..h {
        for x in 0..w {
            let (cx, cy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            if let (Some(uv), Some(c)) = (
                exact_uv(cx, cy, f64::from(w), f64::from(h), f64::from(fov)),
                fb.pixel(x, y),
            ) && (c.w != 0.0 || c.x != 0.0)
            {
                worst = worst.max((f64::from(c.y) - uv.1).abs());
            }
        }
    }
    assert!(worst > 0.05, "affine error {worst}");
}

/// A triangle crossing the near plane is clipped, not dropped: its visible part is drawn.
#[test]
fn near_plane_crossing_triangles_are_clipped_not_dropped() {
    let (w, h) = (32_u32, 32_u32);
    // One vertex behind the camera (z < 0 and w < 0 in clip space): dividing by its w would
    // flip it; clipped at z = 0 the visible part is the quad with NDC corners (±0.5, −0.5),
    // (±0.75, 0.25).
    let vertices = vec![
        Vec4::new(-0.5, -0.5, 0.5, 1.0),
        Vec4::new(0.5, -0.5, 0.5, 1.0),
        Vec4::new(0.0, 2.0, -1.5, -1.0),
    ];
    let counter = Counter::new(w, h);
    let mut fb = Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let stats = draw(&mut fb, &counter, &no_depth(), &vertices, &[0, 1, 2]);
    assert_eq!(stats.clipped, 1, "{stats:?}");
    assert!(stats.fragments_shaded > 20, "{stats:?}");
    assert!(
        counter
            .counts
            .iter()
            .all(|c| c.load(Ordering::Relaxed) <= 1)
    );
}

#[test]
fn bad_geometry_is_dropped_and_counted() {
    let vertices = vec![
        Vec4::new(0.0, 0.0, 0.5, 1.0),
        Vec4::new(1.0, 0.0, 0.5, 1.0),
        Vec4::new(0.0, 1.0, 0.5, 1.0),
        Vec4::new(f32::NAN, 0.0, 0.5, 1.0),
        Vec4::new(1e30, 1e30, 0.5, 1.0),
        Vec4::new(0.5, 0.5, 0.5, 1.0),
    ];
    let counter = Counter::new(8, 8);
    let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let indices = [0, 1, 3, 0, 1, 99, 0, 0, 0, 0, 1, 4, 0, 1, 2];
    let stats = draw(&mut fb, &counter, &no_depth(), &vertices, &indices);
    assert_eq!(stats.triangles_in, 5);
    assert_eq!(stats.dropped_non_finite, 1);
    assert_eq!(stats.dropped_bad_index, 1);
    assert_eq!(stats.degenerate, 1);
    assert!(stats.fragments_shaded > 0);
    assert_eq!(
        DrawStats::default().triangles_in,
        0,
        "default stats are zero"
    );
}

/// The same scene rendered with 1, 2 and 7 threads gives identical colours, bit for bit.
#[test]
fn output_is_bit_identical_for_any_thread_count() {
    let (w, h) = (200_u32, 150_u32);
    let fov = 60_f32.to_radians();
    let shader = PlaneUv {
        view_projection: perspective(fov, w as f32 / h as f32, 0.1, 100.0),
    };
    let (mut vertices, mut indices) = ground_plane();
    // Overlapping translucent-looking geometry: a second plane crossing the first.
    let base = vertices.len() as u32;
    for &(p, uv) in &ground_plane().0 {
        vertices.push((Vec3::new(p.x * 0.5, p.y + 0.3, p.z), uv));
    }
    indices.extend([base, base + 2, base + 1, base, base + 3, base + 2]);
    let render = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| {
            let mut fb =
                Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
            let state = PipelineState {
                cull: CullMode::None,
                ..PipelineState::default()
            };
            draw(&mut fb, &shader, &state, &vertices, &indices);
            fb.to_linear_rgba()
                .expect("resolve")
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect::<Vec<u32>>()
        })
    };
    let one = render(1);
    assert_eq!(one, render(2));
    assert_eq!(one, render(7));
}

/// Clip-space positions with a colour each: the colour is the varying, interpolated.
struct Coloured;

impl Shader for Coloured {
    type Vertex = (Vec4, Vec4);
    type Varying = Vec4;
    fn vertex(&self, v: &(Vec4, Vec4)) -> (Vec4, Vec4) {
        *v
    }
    fn fragment(&self, f: &Fragment<'_, Vec4>) -> Option<Vec4> {
        // The derivatives read the piece's varyings too.
        let (dx, dy) = f.derivatives();
        Some(f.varying + (dx - dy) * 0.25)
    }
}

/// Enough triangles that parallel assembly works in several chunks (512 triangles each), some
/// of them clipped into several pieces, some culled, some with an index out of range: 1, 2 and
/// 3 threads give the same image bit for bit and the same statistics.
#[test]
fn chunked_assembly_is_bit_identical_for_any_thread_count() {
    let (w, h) = (160_u32, 120_u32);
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 40) as f32 / (1 << 24) as f32
    };
    // w from −0.2 to 1.8: some vertices behind the eye, so their triangles are clipped.
    let vertices: Vec<(Vec4, Vec4)> = (0..4000)
        .map(|_| {
            let clip = Vec4::new(
                next() * 3.0 - 1.5,
                next() * 3.0 - 1.5,
                next(),
                next() * 2.0 - 0.2,
            );
            (clip, Vec4::new(next(), next(), next(), 1.0))
        })
        .collect();
    let mut indices: Vec<u32> = (0..3 * 2100)
        .map(|_| (next() * 4000.0) as u32 % 4000)
        .collect();
    indices[3 * 1000 + 1] = 4000; // out of range, in the second chunk
    let render = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| {
            let mut fb =
                Framebuffer::new(w, h, Vec4::ZERO, &TargetLimits::default()).expect("small");
            let state = PipelineState {
                cull: CullMode::Back,
                ..PipelineState::default()
            };
            let stats = draw(&mut fb, &Coloured, &state, &vertices, &indices);
            let bits = fb
                .to_linear_rgba()
                .expect("resolve")
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect::<Vec<u32>>();
            (bits, stats)
        })
    };
    let one = render(1);
    assert!(one.1.clipped > 0 && one.1.culled > 0 && one.1.dropped_bad_index == 1);
    assert!(one.1.fragments_shaded > 0);
    assert_eq!(one, render(2));
    assert_eq!(one, render(3));
}
