//! The renderer on the sample models and the demo scene: every model renders; known answers of
//! the test models (UnlitTest's colours, TextureSettingsTest's absent red); the automatic camera
//! as documented; determinism; the demo against its committed golden image.

mod common;

use std::collections::HashMap;
use std::path::PathBuf;

use barytex_gltf::{LoadOptions, Scene, load_path};
use barytex_raster::RasterError;
use barytex_render::{
    AntiAliasing, CameraChoice, Filter, RenderError, RenderOptions, Shading, auto_camera, render,
    scene_bounds,
};
use glam::Vec3;

fn load(relative: &str) -> Option<Scene> {
    let path = common::fixtures()?.join("gltf").join(relative);
    Some(load_path(&path, &LoadOptions::default()).unwrap_or_else(|e| panic!("{relative}: {e}")))
}

fn srgb(options: &RenderOptions, scene: &Scene) -> Vec<[u8; 4]> {
    let out = render(scene, options).expect("renders");
    out.image
        .to_srgba8()
        .expect("small")
        .texels()
        .iter()
        .map(|t| t.0)
        .collect()
}

fn small(width: u32, height: u32) -> RenderOptions {
    RenderOptions {
        width,
        height,
        ..RenderOptions::default()
    }
}

#[test]
fn every_sample_model_renders() {
    let models = common::sample_models();
    for path in &models {
        let scene = load_path(path, &LoadOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for shading in [Shading::Phong, Shading::Unlit] {
            let options = RenderOptions {
                shading,
                ..small(96, 72)
            };
            let out =
                render(&scene, &options).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let d = out.stats.draw;
            // A flat model in the xz plane is edge-on to the automatic camera (it looks down
            // −Z): all its triangles are degenerate on screen, which is right.
            let edge_on = d.degenerate == d.triangles_in;
            assert!(
                d.fragments_shaded > 0 || edge_on,
                "{}: nothing drawn ({:?})",
                path.display(),
                out.stats
            );
            if edge_on {
                println!("note: {} is edge-on to its camera", path.display());
            }
        }
    }
    println!("{} sample files rendered", models.len());
}

/// The sRGB encoding of a linear value, in f64, correctly rounded to 8 bits (independent of the
/// library's tables).
fn encode(linear: f64) -> u8 {
    let s = if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round().clamp(0.0, 255.0) as u8
}

/// UnlitTest: the two objects show one flat colour each wherever they are seen, with lighting
/// on (the materials are unlit) or off. The README calls them #FF7F00 and #007FFF; the file's
/// factor 0.217637640824031 encodes to 128.47 by the sRGB formula (127.5 by a 2.2 gamma), so the
/// exact answer is #FF8000 / #0080FF — one step from the README's, and asserted exactly.
#[test]
fn unlit_test_shows_its_two_exact_colours() {
    let Some(scene) = load("UnlitTest/glTF-Binary/UnlitTest.glb") else {
        return;
    };
    for shading in [Shading::Phong, Shading::Unlit] {
        let options = RenderOptions {
            shading,
            ..small(160, 120)
        };
        let pixels = srgb(&options, &scene);
        // The objects are centred: the top-left pixel is background.
        let background = pixels[0];
        let mut counts: HashMap<[u8; 4], usize> = HashMap::new();
        for p in pixels {
            if p != background {
                *counts.entry(p).or_default() += 1;
            }
        }
        let mut common: Vec<_> = counts.into_iter().collect();
        common.sort_by_key(|&(_, n)| std::cmp::Reverse(n));
        let top: Vec<[u8; 4]> = common.iter().take(2).map(|&(c, _)| c).collect();
        let g = encode(0.217_637_640_824_031);
        assert_eq!(g, 128);
        assert!(
            top.contains(&[255, g, 0, 255]) && top.contains(&[0, g, 255, 255]),
            "{shading:?}: {:?}",
            &common[..common.len().min(4)]
        );
        // Everything else is an edge pixel blending with the background (none without AA).
        let others: usize = common.iter().skip(2).map(|&(_, n)| n).sum();
        assert_eq!(
            others,
            0,
            "{shading:?}: {:?}",
            &common[..common.len().min(6)]
        );
    }
}

/// TextureSettingsTest: wrap modes and double-sidedness right means green checkmarks only — no
/// red "X" anywhere.
#[test]
fn texture_settings_test_shows_no_red() {
    let Some(scene) = load("TextureSettingsTest/glTF-Binary/TextureSettingsTest.glb") else {
        return;
    };
    for filter in [Filter::FromFile, Filter::Nearest, Filter::Trilinear] {
        let options = RenderOptions {
            shading: Shading::Unlit,
            filter,
            ..small(400, 400)
        };
        let pixels = srgb(&options, &scene);
        let red = pixels
            .iter()
            .filter(|p| p[0] > 150 && p[1] < 100 && p[2] < 100)
            .count();
        let green = pixels
            .iter()
            .filter(|p| p[1] > 150 && p[0] < 100 && p[2] < 100)
            .count();
        assert_eq!(red, 0, "{filter:?}: {red} red pixels");
        assert!(green > 1000, "{filter:?}: only {green} green pixels");
    }
}

/// The automatic camera: looking down −Z at the bounding box's centre, from the distance where
/// the bounding sphere just fits — every point of the sphere projects inside the image, and the
/// sphere touches its shorter side.
#[test]
fn the_automatic_camera_frames_the_bounding_sphere() {
    let Some(scene) = load("Box/glTF-Binary/Box.glb") else {
        return;
    };
    for aspect in [0.5_f32, 1.0, 16.0 / 9.0] {
        let camera = auto_camera(&scene, aspect).expect("a box");
        let (lo, hi) = scene_bounds(&scene).expect("a box");
        let centre = (lo + hi) * 0.5;
        let radius = (hi - lo).length() * 0.5;
        assert!((camera.eye.truncate() - centre.truncate()).length() < 1e-5);
        let clip = camera.projection * camera.view;
        let mut reach = 0.0_f32;
        for i in 0..2000 {
            let (a, b) = (i as f32 * 2.399_963, (i as f32 / 1000.0) - 1.0);
            let r = (1.0 - b * b).sqrt();
            let p = centre + Vec3::new(r * a.cos(), r * a.sin(), b) * radius;
            let c = clip * p.extend(1.0);
            let ndc = c.truncate() / c.w;
            assert!(c.w > 0.0 && ndc.x.abs() <= 1.0 + 1e-3 && ndc.y.abs() <= 1.0 + 1e-3);
            assert!((0.0..=1.0).contains(&ndc.z), "{ndc}");
            reach = reach.max(if aspect >= 1.0 {
                ndc.y.abs()
            } else {
                ndc.x.abs()
            });
        }
        assert!(
            reach > 0.98,
            "the sphere should touch the image's short side: {reach}"
        );
    }
}

/// glTF 2.0 §3.7.2 modes 0–3: MeshPrimitiveModes' top row (POINTS at y = 3) and middle row
/// (LINES, LINE_LOOP, LINE_STRIP at x = −2, 0, 2, y = 0) are drawn unlit in the default
/// material's white, and the automatic camera frames them too.
#[test]
fn points_and_lines_are_drawn_and_framed() {
    let Some(scene) = load("MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf") else {
        return;
    };
    // Seven vertices within x ∈ [−0.866, 0.866], y ∈ [−1, 1], placed at y = 3, 0 and −3 with
    // the outer columns at x = ±2: the points row reaches y = 4, the triangles' row y = −4.
    let (lo, hi) = scene_bounds(&scene).expect("geometry");
    assert!(
        (lo - Vec3::new(-2.866, -4.0, 0.0)).abs().max_element() < 1e-5,
        "{lo}"
    );
    assert!(
        (hi - Vec3::new(2.866, 4.0, 0.0)).abs().max_element() < 1e-5,
        "{hi}"
    );
    let options = small(96, 96);
    let out = render(&scene, &options).expect("renders");
    // 7 points; 6 + 7 (the loop closed) + 6 segments.
    assert_eq!((out.stats.draw.points_in, out.stats.draw.lines_in), (7, 19));
    assert_eq!(out.stats.triangles, 16);
    let pixels = srgb(&options, &scene);
    let background = at(&pixels, 96, 0, 0);
    let drawn = |x: std::ops::Range<u32>, y: std::ops::Range<u32>| {
        y.flat_map(|y| x.clone().map(move |x| (x, y)))
            .filter(|&(x, y)| at(&pixels, 96, x, y) != background)
            .inspect(|&(x, y)| assert_eq!(at(&pixels, 96, x, y), [255; 4], "({x}, {y})"))
            .count()
    };
    // The bounding sphere (radius √(2.866² + 4²) ≈ 4.92) spans the 96 pixels: about 9.75
    // pixels per unit around the centre (48, 48). The points row, y ∈ [2, 4], is pixel rows
    // 9–29: one pixel per point, none shared.
    assert_eq!(drawn(0..96, 0..33), 7);
    // The lines row, y ∈ [−1, 1], is rows 38–58; each of its three meshes drew.
    for columns in [0..35, 35..61, 61..96] {
        let n = drawn(columns.clone(), 34..62);
        assert!(n > 10, "columns {columns:?}: {n} pixels");
    }
}

#[test]
fn bad_options_are_errors() {
    let Some(scene) = load("Box/glTF-Binary/Box.glb") else {
        return;
    };
    assert!(matches!(
        render(&scene, &small(0, 10)),
        Err(RenderError::InvalidOption(_))
    ));
    assert_eq!(
        render(
            &scene,
            &RenderOptions {
                camera: CameraChoice::Index(3),
                ..small(8, 8)
            }
        )
        .err(),
        Some(RenderError::NoSuchCamera { index: 3, count: 0 })
    );
    assert!(render(&Scene::default(), &small(8, 8)).is_err());
    assert!(matches!(
        render(
            &scene,
            &RenderOptions {
                anti_aliasing: AntiAliasing::Msaa(3),
                ..small(8, 8)
            }
        ),
        Err(RenderError::Raster(RasterError::InvalidParameter {
            what: "sample count",
            ..
        }))
    ));
}

use barytex_render::demo::demo_options;

#[test]
fn the_demo_is_the_same_for_any_thread_count() {
    let scene = barytex_render::demo::demo_scene();
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool")
            .install(|| srgb(&demo_options(160, 90), &scene))
    };
    assert_eq!(run(1), run(3));
}

/// The progress callback sees every pass, numbered from 1, against the planned count:
/// exactly `n²` for accumulated supersampling, at most the maximum for adaptive sampling, one
/// for MSAA.
#[test]
fn progress_counts_every_pass() {
    use barytex_render::{planned_passes, render_with_progress};
    let scene = barytex_render::demo::demo_scene();
    for anti_aliasing in [
        AntiAliasing::Supersample(6),
        AntiAliasing::Adaptive(8),
        AntiAliasing::Msaa(4),
    ] {
        let options = RenderOptions {
            anti_aliasing,
            ..demo_options(32, 18)
        };
        let mut seen = Vec::new();
        let out = render_with_progress(&scene, &options, &mut |done, planned| {
            seen.push((done, planned));
        })
        .expect("renders");
        let planned = planned_passes(anti_aliasing);
        assert_eq!(seen.len() as u32, out.stats.passes, "{anti_aliasing:?}");
        assert!(
            seen.iter()
                .enumerate()
                .all(|(i, &(done, p))| done == i as u32 + 1 && p == planned && done <= planned),
            "{anti_aliasing:?}: {seen:?}"
        );
        if let AntiAliasing::Supersample(n) = anti_aliasing {
            assert_eq!(out.stats.passes, n * n);
        }
    }
}

/// `measure_stages` times a second, constant-shader draw of every pass into a scratch copy: the
/// image and the counts are those of the plain render, and only the measured render reports a
/// rasterization time. Adaptive supersampling is included: its passes depend on the image, so a
/// copy that leaked into the target would change them.
#[test]
fn measuring_the_stages_changes_nothing_but_the_timings() {
    let scene = barytex_render::demo::demo_scene();
    for anti_aliasing in [AntiAliasing::Msaa(4), AntiAliasing::Adaptive(8)] {
        let plain = RenderOptions {
            anti_aliasing,
            ..demo_options(96, 54)
        };
        let measured = RenderOptions {
            measure_stages: true,
            ..plain
        };
        let (a, b) = (
            render(&scene, &plain).expect("renders"),
            render(&scene, &measured).expect("renders"),
        );
        assert_eq!(a.stats.raster_seconds, None);
        let raster = b.stats.raster_seconds.expect("measured");
        assert!(raster > 0.0 && raster.is_finite(), "{raster}");
        assert_eq!(a.stats.draw, b.stats.draw, "{anti_aliasing:?}");
        assert_eq!(a.stats.passes, b.stats.passes, "{anti_aliasing:?}");
        assert_eq!(
            a.image.to_srgba8().expect("small").texels(),
            b.image.to_srgba8().expect("small").texels(),
            "{anti_aliasing:?}"
        );
    }
}

/// The demo against `tests/golden/demo-320x180.png`: at most 2 sRGB steps apart anywhere and 0.05
/// on average (the same build gives identical bytes; the slack is for other libm versions).
/// `BARYTEX_BLESS=1` rewrites the golden image.
#[test]
fn the_demo_matches_its_golden_image() {
    let golden = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/golden/demo-320x180.png");
    let scene = barytex_render::demo::demo_scene();
    let image = render(&scene, &demo_options(320, 180))
        .expect("renders")
        .image
        .to_srgba8()
        .expect("small");
    if std::env::var_os("BARYTEX_BLESS").is_some() {
        barytex_texture::load::save_png(&image, &golden).expect("writes the golden image");
        return;
    }
    let bytes = std::fs::read(&golden).expect("golden image present (BARYTEX_BLESS=1 writes it)");
    let expected = barytex_texture::load::load_from_memory(
        &bytes,
        barytex_texture::load::ColorSpace::Srgb,
        &barytex_texture::Limits::default(),
    )
    .expect("decodes");
    let barytex_texture::load::AnyTexture2d::Srgba8(expected) = expected else {
        panic!("the golden image is 8-bit RGBA");
    };
    assert_eq!(expected.size(), image.size());
    let (mut max, mut sum) = (0_u8, 0_u64);
    for (a, b) in image.texels().iter().zip(expected.texels()) {
        for k in 0..4 {
            let d = a.0[k].abs_diff(b.0[k]);
            max = max.max(d);
            sum += u64::from(d);
        }
    }
    let mean = sum as f64 / (image.texels().len() * 4) as f64;
    assert!(max <= 2 && mean <= 0.05, "max {max}, mean {mean}");
}

/// Pixel (x, y) of an sRGB render `width` wide.
fn at(pixels: &[[u8; 4]], width: u32, x: u32, y: u32) -> [u8; 4] {
    pixels[(y * width + x) as usize]
}

fn close(a: [u8; 4], b: [u8; 4], steps: u8) -> bool {
    a.iter().zip(&b).all(|(p, q)| p.abs_diff(*q) <= steps)
}

/// TextureTransformTest's rotation quad (bottom left): the arrow must end at the green marker,
/// not at the red one, which the model places where a rotation in the wrong direction points.
#[test]
fn texture_transform_test_rotates_toward_the_green_marker() {
    let Some(scene) = load("TextureTransformTest/glTF/TextureTransformTest.gltf") else {
        return;
    };
    let (w, h) = (600_u32, 400_u32);
    let options = RenderOptions {
        shading: Shading::Unlit,
        ..small(w, h)
    };
    let pixels = srgb(&options, &scene);
    // The bottom-left quad and its markers: the left 42 % of the image, its lower half.
    let region = |x: u32, y: u32| x < w * 42 / 100 && y >= h / 2;
    let (mut green, mut red, mut black) = (Vec::new(), Vec::new(), Vec::new());
    for y in 0..h {
        for x in 0..w {
            let [r, g, b, _] = at(&pixels, w, x, y);
            let p = glam::Vec2::new(x as f32, y as f32);
            if !region(x, y) {
                continue;
            }
            if g > 150 && r < 80 && b < 80 {
                green.push(p);
            } else if r > 150 && g < 60 && b < 60 {
                red.push(p);
            } else if r < 40 && g < 40 && b < 40 {
                black.push(p);
            }
        }
    }
    assert!(!green.is_empty() && !red.is_empty() && !black.is_empty());
    let centroid = |ps: &[glam::Vec2]| ps.iter().sum::<glam::Vec2>() / ps.len() as f32;
    let nearest = |c: glam::Vec2| {
        black
            .iter()
            .map(|p| p.distance(c))
            .fold(f32::INFINITY, f32::min)
    };
    let (to_green, to_red) = (nearest(centroid(&green)), nearest(centroid(&red)));
    assert!(
        to_red > 3.0 * to_green,
        "arrow to green marker {to_green} px, to red {to_red} px"
    );
}

/// TextureLinearInterpolationTest: the emissive factor 0.5 and the texture interpolated halfway
/// between black and white (in linear light, after sRGB decoding) give the same green, 188.
#[test]
fn texture_linear_interpolation_test_spheres_match() {
    let Some(scene) =
        load("TextureLinearInterpolationTest/glTF-Binary/TextureLinearInterpolationTest.glb")
    else {
        return;
    };
    let pixels = srgb(&small(400, 300), &scene);
    let mut sides = [(0_u64, 0_u64); 2];
    for (i, p) in pixels.iter().enumerate() {
        if p[1] > 100 && p[0] < 60 && p[2] < 60 {
            let side = usize::from((i % 400) >= 200);
            sides[side].0 += u64::from(p[1]);
            sides[side].1 += 1;
        }
    }
    let mean = sides.map(|(sum, n)| sum as f64 / n.max(1) as f64);
    assert!(sides.iter().all(|&(_, n)| n > 1000), "{sides:?}");
    assert!((mean[0] - mean[1]).abs() < 1.0, "{mean:?}");
    assert!((mean[0] - 188.0).abs() < 2.0, "{mean:?}");
}

/// TextureCoordinateTest: uv (0, 0) is the image's top-left: the yellow "Top Left" square is in
/// the top-left quadrant, the green "Bottom Right" one in the bottom-right.
#[test]
fn texture_coordinate_test_has_the_origin_at_the_top_left() {
    let Some(scene) = load("TextureCoordinateTest/glTF-Binary/TextureCoordinateTest.glb") else {
        return;
    };
    let (w, h) = (400, 300);
    let pixels = srgb(
        &RenderOptions {
            shading: Shading::Unlit,
            ..small(w, h)
        },
        &scene,
    );
    let count = |x0: u32, y0: u32, f: &dyn Fn([u8; 4]) -> bool| {
        (y0..y0 + h / 2)
            .flat_map(|y| (x0..x0 + w / 2).map(move |x| (x, y)))
            .filter(|&(x, y)| f(at(&pixels, w, x, y)))
            .count()
    };
    let yellow = |p: [u8; 4]| p[0] > 200 && p[1] > 200 && p[2] < 80;
    let green = |p: [u8; 4]| p[1] > 200 && p[0] < 80 && p[2] < 80;
    assert!(count(0, 0, &yellow) > 2000 && count(w / 2, h / 2, &yellow) == 0);
    assert!(count(w / 2, h / 2, &green) > 2000 && count(0, 0, &green) == 0);
}

/// VertexColorTest: vertex colours multiply the base colour, so no cyan, magenta or yellow "X"
/// shows through the red, green and blue checkmarks.
#[test]
fn vertex_color_test_shows_no_crosses() {
    let Some(scene) = load("VertexColorTest/glTF-Binary/VertexColorTest.glb") else {
        return;
    };
    let pixels = srgb(
        &RenderOptions {
            shading: Shading::Unlit,
            ..small(400, 300)
        },
        &scene,
    );
    let count = |f: &dyn Fn(&[u8; 4]) -> bool| pixels.iter().filter(|p| f(p)).count();
    let cyan = count(&|p| p[0] < 80 && p[1] > 150 && p[2] > 150);
    let magenta = count(&|p| p[0] > 150 && p[1] < 80 && p[2] > 150);
    let yellow = count(&|p| p[0] > 150 && p[1] > 150 && p[2] < 80);
    assert_eq!((cyan, magenta, yellow), (0, 0, 0));
    let red = count(&|p| p[0] > 200 && p[1] < 60 && p[2] < 60);
    let green = count(&|p| p[1] > 200 && p[0] < 60 && p[2] < 60);
    assert!(red > 200 && green > 200, "{red} {green}");
}

/// TextureEncodingTest: in each row (base colour, emissive, metallic-roughness) the four spheres
/// — factors, a 1×1 texture, the same with a gamma chunk, the same with an ICC profile — look the
/// same: textures decoded in the right colour space, metadata ignored.
#[test]
fn texture_encoding_test_columns_match() {
    let Some(scene) = load("TextureEncodingTest/glTF/TextureEncodingTest.gltf") else {
        return;
    };
    let (w, h) = (400, 300);
    let pixels = srgb(&small(w, h), &scene);
    // Sphere centres in the automatic camera's 400 × 300 view.
    let columns = [162, 203, 245, 288];
    for (row, y) in [
        ("base colour", 122),
        ("emissive", 163),
        ("metallic-roughness", 206),
    ] {
        let first = at(&pixels, w, columns[0], y);
        assert!(first != pixels[0], "{row}: no sphere at the expected place");
        for &x in &columns[1..] {
            let p = at(&pixels, w, x, y);
            assert!(
                close(first, p, 3),
                "{row}: column at x = {x}: {p:?} vs {first:?}"
            );
        }
    }
}

/// Mean |a − b| over all channels of two sRGB images.
fn mean_difference(a: &[[u8; 4]], b: &[[u8; 4]]) -> f64 {
    let sum: u64 = a
        .iter()
        .zip(b)
        .flat_map(|(p, q)| p.iter().zip(q).map(|(x, y)| u64::from(x.abs_diff(*y))))
        .sum();
    sum as f64 / (a.len() * 4) as f64
}

/// The shading frequencies on the demo: against per-pixel Phong, flat is further than Gouraud,
/// and the hybrid (Phong only where the H-test finds a highlight) is closer than Gouraud while
/// shading only a minority of triangles with Phong.
#[test]
fn shading_frequencies_order_by_error_on_the_demo() {
    let scene = barytex_render::demo::demo_scene();
    let shade = |shading: Shading| {
        let options = RenderOptions {
            shading,
            ..small(320, 180)
        };
        let out = render(&scene, &options).expect("renders");
        let pixels: Vec<[u8; 4]> = out
            .image
            .to_srgba8()
            .expect("small")
            .texels()
            .iter()
            .map(|t| t.0)
            .collect();
        (pixels, out.stats)
    };
    let (phong, _) = shade(Shading::Phong);
    let (flat, _) = shade(Shading::Flat);
    let (gouraud, _) = shade(Shading::Gouraud);
    let (hybrid, stats) = shade(Shading::Hybrid);
    let (e_flat, e_gouraud, e_hybrid) = (
        mean_difference(&flat, &phong),
        mean_difference(&gouraud, &phong),
        mean_difference(&hybrid, &phong),
    );
    println!(
        "mean |Δ| against Phong (sRGB steps): flat {e_flat:.3}, Gouraud {e_gouraud:.3}, hybrid \
         {e_hybrid:.3}; hybrid Phong triangles {} of {}",
        stats.hybrid_phong_triangles,
        stats.hybrid_phong_triangles + stats.hybrid_gouraud_triangles
    );
    assert!(
        e_flat > e_gouraud && e_gouraud > e_hybrid,
        "{e_flat} {e_gouraud} {e_hybrid}"
    );
    assert!(stats.hybrid_phong_triangles > 0);
    assert!(stats.hybrid_phong_triangles * 4 < stats.hybrid_gouraud_triangles);
}

/// Fog pulls the far floor towards the background colour, more than the near floor.
#[test]
fn fog_fades_the_distance_into_the_background() {
    let scene = barytex_render::demo::demo_scene();
    let fogged_options = demo_options(320, 180);
    let clear_options = RenderOptions {
        fog: None,
        ..fogged_options
    };
    let (clear, fogged) = (srgb(&clear_options, &scene), srgb(&fogged_options, &scene));
    let background = clear[0];
    let row_distance = |pixels: &[[u8; 4]], y: u32| {
        (0..320)
            .map(|x| {
                let p = at(pixels, 320, x, y);
                p.iter()
                    .zip(&background)
                    .map(|(a, b)| f64::from(a.abs_diff(*b)))
                    .sum::<f64>()
            })
            .sum::<f64>()
            / 320.0
    };
    // How much of each row's contrast against the background survives the fog: less far away
    // (just below the horizon) than near (the bottom of the image).
    let kept = |y: u32| row_distance(&fogged, y) / row_distance(&clear, y);
    let (far, near) = (kept(60), kept(175));
    println!("contrast kept: far {far:.3}, near {near:.3}");
    assert!(far < 0.7 && far < near - 0.08, "far {far}, near {near}");
    assert!(near < 1.0, "fog everywhere in front of the eye: {near}");
}

/// Normal mapping: the demo torus's bump texture changes its shading; a flat normal map
/// ((0.5, 0.5, 1) everywhere) leaves it within one sRGB step of no map at all; and Gouraud
/// shading ignores normal maps (they need per-pixel normals).
#[test]
fn normal_maps_perturb_only_per_pixel_shading() {
    use std::sync::Arc;
    let bumpy = barytex_render::demo::demo_scene();
    let mut plain = bumpy.clone();
    plain.materials[3].normal_texture = None;
    let mut flat_map = bumpy.clone();
    // Exactly (0.5, 0.5, 1): 8-bit 128 would decode to a tilt of 1/255.
    let flat = barytex_texture::Texture2d::from_fn(4, 4, |_, _| {
        barytex_texture::Rgba32f([0.5, 0.5, 1.0, 1.0])
    })
    .expect("small");
    flat_map.images[4].linear = Some(Arc::new(barytex_texture::load::AnyTexture2d::Rgba32f(flat)));
    let options = small(320, 180);
    let (b, p, f) = (
        srgb(&options, &bumpy),
        srgb(&options, &plain),
        srgb(&options, &flat_map),
    );
    assert!(mean_difference(&b, &p) > 0.5, "{}", mean_difference(&b, &p));
    let worst = f
        .iter()
        .zip(&p)
        .flat_map(|(x, y)| x.iter().zip(y).map(|(a, b)| a.abs_diff(*b)))
        .max()
        .unwrap_or(0);
    assert!(worst <= 1, "a flat normal map changed a pixel by {worst}");
    let gouraud = RenderOptions {
        shading: Shading::Gouraud,
        ..options
    };
    assert_eq!(srgb(&gouraud, &bumpy), srgb(&gouraud, &plain));
}

/// Environment mapping: the demo's mirror sphere reflects the sky panorama — without it the
/// sphere (metallic, no diffuse) is nearly black; with it, its upper half shows the blue sky.
#[test]
fn the_mirror_sphere_reflects_the_environment() {
    let scene = barytex_render::demo::demo_scene();
    let mut bare = scene.clone();
    bare.environment = None;
    let options = small(320, 180);
    let (with, without) = (srgb(&options, &scene), srgb(&options, &bare));
    // The mirror sphere's upper half in the 320 × 180 view (centre near (125, 119)).
    let region: Vec<(u32, u32)> = (100..150)
        .flat_map(|x| (102..115).map(move |y| (x, y)))
        .filter(|&(x, y)| (x as f32 - 125.0).hypot(y as f32 - 119.0) < 14.0)
        .collect();
    assert!(region.len() > 100);
    let mean = |pixels: &[[u8; 4]], k: usize| {
        region
            .iter()
            .map(|&(x, y)| f64::from(at(pixels, 320, x, y)[k]))
            .sum::<f64>()
            / region.len() as f64
    };
    println!(
        "mirror top: with sky rgb ({:.0}, {:.0}, {:.0}), without ({:.0}, {:.0}, {:.0})",
        mean(&with, 0),
        mean(&with, 1),
        mean(&with, 2),
        mean(&without, 0),
        mean(&without, 1),
        mean(&without, 2)
    );
    assert!(
        mean(&with, 2) > mean(&with, 0) + 30.0,
        "bluish sky reflected"
    );
    assert!(mean(&with, 2) > mean(&without, 2) + 60.0);
}
