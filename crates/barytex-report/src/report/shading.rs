//! The shading family (barytex-shade): shading frequencies on a lit sphere — flat, Gouraud,
//! Phong, Gouraud + Phong with the highlight test, and the fast approximate Phong — against
//! per-pixel Phong shading at 16 samples per pixel; and normal interpolation, lerp +
//! renormalize against SLERP. Time is per frame (lighting preparation included), one thread.

use barytex_interp::{NormalInterpolation, interpolate_normal};
use barytex_raster::{
    Framebuffer, PipelineState, SamplePattern, Shader, TargetLimits, Viewport, draw,
    render_supersampled,
};
use barytex_shade::{
    Camera, ColouredShader, FastPhongShader, GouraudShader, HighlightTest, HybridShader, Light,
    PhongMaterial, PhongShader, ShadeContext, SlerpPhongShader, ViewVector, fast_phong_vertices,
    flat_vertices, hybrid_vertices, mesh_vertices, slerp_vertices,
};
use barytex_testkit::seeded::XorShift;
use barytex_testkit::sphere;
use barytex_uv::TriMesh;
use glam::{Vec2, Vec3, Vec4};

use super::table::per_case_matrix;
use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::{median_frame_seconds, ns_per_call};

/// The sphere scene: a unit sphere seen from z = 3, one white directional light from the upper
/// left front, a reddish plastic with a sharp highlight.
fn scene() -> ShadeContext {
    ShadeContext {
        camera: Camera::look_at(
            Vec3::new(0.0, 0.0, 3.0),
            Vec3::ZERO,
            Vec3::Y,
            45f32.to_radians(),
            1.0,
            0.1,
            10.0,
        )
        .expect("a regular camera"),
        lights: vec![Light::Directional {
            direction: Vec3::new(1.0, -1.0, -1.5),
            color: Vec3::ONE,
        }],
        ambient: Vec3::splat(0.1),
        material: PhongMaterial {
            diffuse: Vec3::new(0.6, 0.4, 0.3),
            ambient: Vec3::new(0.6, 0.4, 0.3),
            specular: Vec3::splat(0.5),
            shininess: 40.0,
            ..PhongMaterial::default()
        },
        view: ViewVector::Local,
    }
}

fn frame<S: Shader>(size: u32, shader: &S, vertices: &[S::Vertex], indices: &[u32]) -> Framebuffer {
    let mut fb = Framebuffer::new(size, size, Vec4::ZERO, &TargetLimits::default()).expect("small");
    draw(
        &mut fb,
        shader,
        &PipelineState::default(),
        vertices,
        indices,
    );
    fb
}

/// Largest-channel errors at the pixels the reference covers fully (the shading, not the
/// silhouette's anti-aliasing, is compared).
fn errors(image: &Framebuffer, reference: &Framebuffer) -> Vec<f64> {
    let mut out = Vec::new();
    for y in 0..image.height() {
        for x in 0..image.width() {
            let (p, r) = (
                image.pixel(x, y).expect("inside"),
                reference.pixel(x, y).expect("inside"),
            );
            if r.w < 0.999 || p.w == 0.0 {
                continue;
            }
            out.push(f64::from((p.truncate() - r.truncate()).abs().max_element()));
        }
    }
    out
}

/// The frequencies table on one sphere tessellation.
fn frequencies_table(mesh: &TriMesh, label: &str, size: u32, runs: usize) -> (Table, String) {
    let scene = scene();
    let (vertices, indices) = mesh_vertices(mesh);
    let (scene_ref, vertices_ref, indices_ref) = (&scene, &vertices, &indices);
    let reference = render_supersampled(
        size,
        size,
        Vec4::ZERO,
        SamplePattern::Regular { n: 4 },
        &TargetLimits::default(),
        move |fb: &mut Framebuffer, shift: Vec2| {
            let state = PipelineState {
                viewport: Some(Viewport {
                    x: shift.x,
                    y: shift.y,
                    ..Viewport::full(size, size)
                }),
                ..PipelineState::default()
            };
            draw(
                fb,
                &PhongShader::new(scene_ref),
                &state,
                vertices_ref,
                indices_ref,
            );
        },
    )
    .expect("small");
    let test = HighlightTest::default();
    let mut phong_triangles = (0, 0, 0);
    type Method<'a> = (&'a str, bool, Box<dyn FnMut() -> Framebuffer + Send + 'a>);
    let mut methods: Vec<Method<'_>> = vec![
        (
            "flat (one lighting per triangle, at its centroid)",
            false,
            Box::new(|| {
                let (v, i) = flat_vertices(mesh, &scene);
                frame(size, &ColouredShader { scene: &scene }, &v, &i)
            }),
        ),
        (
            "Gouraud (lighting per vertex)",
            false,
            Box::new(|| frame(size, &GouraudShader { scene: &scene }, &vertices, &indices)),
        ),
        (
            "Phong (lighting per pixel, 1 sample)",
            true,
            Box::new(|| frame(size, &PhongShader::new(&scene), &vertices, &indices)),
        ),
        (
            "Phong with SLERP-interpolated normals",
            false,
            Box::new(|| {
                let (v, i, normals) = slerp_vertices(mesh);
                let shader = SlerpPhongShader {
                    scene: &scene,
                    normals: &normals,
                };
                frame(size, &shader, &v, &i)
            }),
        ),
        (
            "Gouraud + Phong where the H-test sees a highlight",
            false,
            Box::new(|| {
                let (v, i, stats) = hybrid_vertices(mesh, &scene, &test);
                phong_triangles = (stats.phong, stats.triangles, stats.back_facing);
                frame(size, &HybridShader { scene: &scene }, &v, &i)
            }),
        ),
        (
            "fast approximate Phong (quadratic, 6 lightings per triangle)",
            false,
            Box::new(|| {
                let (v, i, nodes) = fast_phong_vertices(mesh, &scene);
                let shader = FastPhongShader {
                    scene: &scene,
                    nodes: &nodes,
                };
                frame(size, &shader, &v, &i)
            }),
        ),
    ];
    let mut rows = Vec::new();
    let mut pixels = 0;
    for (name, is_default, render) in &mut methods {
        let (seconds, image) = median_frame_seconds(runs, render);
        let e = errors(&image, &reference);
        pixels = e.len();
        rows.push(Row {
            method: (*name).to_owned(),
            is_default: *is_default,
            ns: seconds * 1e9,
            abs: ErrorStats::of(e),
            ..Row::default()
        });
    }
    drop(methods);
    let table = Table {
        title: format!("shading frequencies on a {label} sphere"),
        description: format!(
            "A {size}² view of the unit {label} UV sphere ({} triangles) lit by one white \
             directional light (Phong lobe, n = 40, k_s = 0.5). The error is the largest \
             channel's |pixel − reference| (linear light, 0…1) at the pixels the reference \
             covers fully; the reference is per-pixel Phong shading at 4×4 = 16 regular samples \
             per pixel (accumulated passes), so Phong's own error is its missing anti-aliasing. \
             **Time is ns per frame** (preparing per-triangle lighting included), median of \
             {runs} frames, one thread.",
            mesh.indices.len()
        ),
        inputs: pixels,
        rows,
        time_unit: "frame".to_owned(),
        error_label: "max |pixel − reference| (linear light)".to_owned(),
        ..Table::default()
    };
    let note = format!(
        "H-test on the {label} sphere: {} of {} triangles ({:.1} %) took the Phong path; {} \
         back-facing triangles were not tested.",
        phong_triangles.0,
        phong_triangles.1,
        100.0 * phong_triangles.0 as f64 / phong_triangles.1.max(1) as f64,
        phong_triangles.2
    );
    (table, note)
}

/// Angle (radians) between `r` and the f64 SLERP of `(a, b, t)`.
fn slerp_error(a: Vec3, b: Vec3, t: f32, r: Vec3) -> f64 {
    let f = |v: Vec3| vec![f64::from(v.x), f64::from(v.y), f64::from(v.z)];
    let reference = sphere::slerp(&f(a), &f(b), f64::from(t), &[1.0, 0.0, 0.0])
        .unwrap_or_else(|| vec![0.0, 0.0, 0.0]);
    sphere::errors(&f(r), &reference).0
}

/// Lerp + renormalize against SLERP on unit normal pairs at the angles meshes have.
fn normals_table(settings: Settings) -> Table {
    let mut rng = XorShift::new(0x5ade);
    let angles = [5.0f32, 15.0, 45.0, 90.0];
    let per_angle = (settings.random / angles.len()).max(16);
    let mut inputs = Vec::new();
    for &degrees in &angles {
        for _ in 0..per_angle {
            let a = loop {
                if let Some(v) = rng.vec3_in(-1.0, 1.0).try_normalize() {
                    break v;
                }
            };
            let axis = loop {
                if let Some(v) = a.cross(rng.vec3_in(-1.0, 1.0)).try_normalize() {
                    break v;
                }
            };
            let b = glam::Quat::from_axis_angle(axis, degrees.to_radians()) * a;
            inputs.push((a, b.normalize(), rng.f32_in(0.0, 1.0), degrees));
        }
    }
    let methods = [
        (
            "interpolate_normal(…, NormalInterpolation::Renormalize)",
            NormalInterpolation::Renormalize,
        ),
        (
            "interpolate_normal(…, NormalInterpolation::Slerp)",
            NormalInterpolation::Slerp,
        ),
    ];
    let mut rows = Vec::new();
    let mut matrix = vec![Vec::new(); angles.len()];
    for (name, method) in methods {
        let data: Vec<(Vec3, Vec3, f32)> = inputs.iter().map(|&(a, b, t, _)| (a, b, t)).collect();
        let ns = ns_per_call(&data, settings.timing, |(a, b, t)| {
            interpolate_normal(a, b, t, method)
        });
        let e: Vec<f64> = inputs
            .iter()
            .map(|&(a, b, t, _)| slerp_error(a, b, t, interpolate_normal(a, b, t, method)))
            .collect();
        for (k, &degrees) in angles.iter().enumerate() {
            let worst = inputs
                .iter()
                .zip(&e)
                .filter(|((_, _, _, d), _)| *d == degrees)
                .map(|(_, &x)| x)
                .fold(0.0f64, f64::max);
            matrix[k].push(format!("{:.1e} rad", worst));
        }
        rows.push(Row {
            method: name.to_owned(),
            is_default: method == NormalInterpolation::Renormalize,
            ns,
            abs: ErrorStats::of(e),
            ..Row::default()
        });
    }
    let cases: Vec<String> = angles
        .iter()
        .map(|d| format!("normals {d}° apart"))
        .collect();
    let names: Vec<String> = ["lerp + renormalize", "SLERP"]
        .iter()
        .map(|s| (*s).to_owned())
        .collect();
    Table {
        title: "normal interpolation: lerp + renormalize vs SLERP".to_owned(),
        description: format!(
            "{per_angle} random pairs of unit normals at each of {} apart, at a uniform random \
             fraction t: the error is the angle (radians) to the evenly spaced normal (an f64 \
             SLERP). Lerp + renormalize stays on the arc but runs unevenly along it; on a sphere \
             mesh it is nevertheless the exact normal of the surface point nearest the chord, \
             so which one is \"right\" depends on what the vertices sample.",
            angles
                .iter()
                .map(|d| format!("{d}°"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        inputs: inputs.len(),
        rows,
        extra: vec![per_case_matrix(
            "Max error per angle:",
            &cases,
            &names,
            &matrix,
        )],
        error_label: "max angle error (rad)".to_owned(),
        ..Table::default()
    }
}

/// The shading tables.
pub(crate) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let quick = settings.random < 1024;
    let (size, runs) = if quick { (96, 2) } else { (256, 7) };
    let mut tables = Vec::new();
    let mut notes = Vec::new();
    for (segments, rings) in [(16_u32, 8_u32), (48, 24)] {
        progress(&format!("shading frequencies, {segments}×{rings} sphere"));
        let mesh = barytex_uv::mesh::sphere(segments, rings).expect("a valid sphere");
        let (table, note) = frequencies_table(&mesh, &format!("{segments}×{rings}"), size, runs);
        tables.push(table);
        notes.push(note);
    }
    progress("normal interpolation");
    tables.push(normals_table(settings));
    Section {
        heading: "Shading".to_owned(),
        intro: "barytex-shade's shading frequencies and normal interpolation, each against a \
                supersampled or f64 reference."
            .to_owned(),
        tables,
        notes,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quick_run_orders_the_frequencies() {
        let section = run(Settings::new(true), &mut |_| {});
        assert_eq!(section.tables.len(), 3);
        for table in &section.tables[..2] {
            let max = |k: usize| table.rows[k].abs.expect("measured").max;
            let median = |k: usize| table.rows[k].abs.expect("measured").median;
            // flat > Gouraud > hybrid ≥ Phong by median error; the hybrid fixes Gouraud's
            // worst pixels (the highlight) and never beats Phong.
            assert!(median(0) > median(1), "{table:?}");
            assert!(median(1) > median(4) && median(4) >= median(2), "{table:?}");
            assert!(max(1) > max(4) && max(4) >= max(2), "{table:?}");
        }
    }
}
