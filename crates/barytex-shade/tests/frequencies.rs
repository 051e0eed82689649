//! Flat, Gouraud, Phong and Gouraud + Phong (H-test) on a sphere at 128², against per-pixel
//! lighting with the sphere's exact normals.

mod common;

use barytex_raster::Framebuffer;
use barytex_shade::{
    ColouredShader, GouraudShader, HighlightTest, HybridShader, NormalWeighting, PhongShader,
    flat_vertices, hybrid_vertices, mesh_vertices, vertex_normals,
};
use barytex_shade::{PhongMaterial, ShadeContext};
use common::{SIZE, error, render, scene};
use glam::Vec3;

/// The exact unit sphere, ray traced through the pixel centres and lit with its exact point and
/// normal.
fn traced_sphere(scene: &ShadeContext) -> Framebuffer {
    let inverse = scene.camera.view_projection().inverse();
    let mut pixels = Vec::new();
    for y in 0..SIZE {
        for x in 0..SIZE {
            let ndc_x = (x as f32 + 0.5) / SIZE as f32 * 2.0 - 1.0;
            let ndc_y = 1.0 - (y as f32 + 0.5) / SIZE as f32 * 2.0;
            let far = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 1.0));
            let eye = scene.camera.eye;
            let d = (far - eye).normalize();
            // |eye + t d|² = 1.
            let b = eye.dot(d);
            let c = eye.length_squared() - 1.0;
            let disc = b * b - c;
            if disc < 0.0 {
                continue;
            }
            let t = -b - disc.sqrt();
            let p = eye + d * t;
            pixels.push((x, y, scene.light(p, p.normalize()).total().extend(1.0)));
        }
    }
    common::from_pixels(SIZE, &pixels)
}

#[test]
fn error_ordering_flat_gouraud_hybrid_phong() {
    let scene = scene();
    let mesh = barytex_uv::mesh::sphere(24, 12).expect("valid");
    let (vertices, indices) = mesh_vertices(&mesh);
    let reference = traced_sphere(&scene);
    let (fv, fi) = flat_vertices(&mesh, &scene);
    let flat = render(&ColouredShader { scene: &scene }, &fv, &fi);
    let gouraud = render(&GouraudShader { scene: &scene }, &vertices, &indices);
    let phong = render(&PhongShader::new(&scene), &vertices, &indices);
    let (hv, hi, stats) = hybrid_vertices(&mesh, &scene, &HighlightTest::default());
    let hybrid = render(&HybridShader { scene: &scene }, &hv, &hi);

    let e_flat = error(&flat, &reference);
    let e_gouraud = error(&gouraud, &reference);
    let e_phong = error(&phong, &reference);
    let e_hybrid = error(&hybrid, &reference);
    let hybrid_vs_phong = error(&hybrid, &phong);
    println!(
        "mean/max error vs exact normals: flat {e_flat:?}, gouraud {e_gouraud:?}, hybrid \
         {e_hybrid:?}, phong {e_phong:?}; hybrid vs phong {hybrid_vs_phong:?}; {stats:?}"
    );
    assert!(e_flat.2 > 8000, "the sphere covers the image centre");
    assert!(e_flat.0 > e_gouraud.0);
    assert!(e_gouraud.0 > e_hybrid.0);
    assert!(e_hybrid.0 >= e_phong.0);
    assert!(e_flat.1 > e_gouraud.1 && e_gouraud.1 > e_phong.1);
    // The hybrid matches Phong within a small error while running Phong on a minority of
    // triangles: the highlight is where the error was. What is left is Gouraud's diffuse error
    // (the H-test only looks for highlights) and sub-threshold specular.
    let matte = ShadeContext {
        material: PhongMaterial {
            specular: Vec3::ZERO,
            ..scene.material
        },
        ..scene.clone()
    };
    let diffuse_only = error(
        &render(&GouraudShader { scene: &matte }, &vertices, &indices),
        &render(&PhongShader::new(&matte), &vertices, &indices),
    );
    let test = HighlightTest::default();
    assert!(
        hybrid_vs_phong.1 <= diffuse_only.1 + 2.0 * f64::from(test.threshold) + 1e-6,
        "{hybrid_vs_phong:?} {diffuse_only:?}"
    );
    assert!(hybrid_vs_phong.0 < e_gouraud.0 / 2.0);
    assert!(stats.phong * 3 < stats.triangles, "{stats:?}");
    assert!(stats.phong > 0);
}

#[test]
fn h_test_has_no_false_negatives_on_the_sphere() {
    // Every triangle with a visible specular anywhere (dense sampling) passes the test.
    let scene = scene();
    let mesh = barytex_uv::mesh::sphere(24, 12).expect("valid");
    let test = HighlightTest::default();
    let mut missed = 0;
    for tri in &mesh.indices {
        let p = tri.map(|i| mesh.positions[i as usize]);
        let n = tri.map(|i| mesh.normals[i as usize]);
        let mut peak = 0.0f32;
        let k = 24;
        for i in 0..=k {
            for j in 0..=k - i {
                let (a, b) = (i as f32 / k as f32, j as f32 / k as f32);
                let c = 1.0 - a - b;
                let q = p[0] * a + p[1] * b + p[2] * c;
                let m = (n[0] * a + n[1] * b + n[2] * c).normalize_or_zero();
                peak = peak.max(scene.light(q, m).specular.max_element());
            }
        }
        if peak >= 2.0 * test.threshold && !test.run(&scene, p, n).has_highlight() {
            missed += 1;
        }
    }
    assert_eq!(missed, 0);
}

#[test]
fn vertex_normal_weightings_agree_on_a_sphere() {
    let mesh = barytex_uv::mesh::sphere(24, 12).expect("valid");
    // The generated mesh duplicates its seam column and its pole vertices (one per column), so a
    // seam or pole vertex sees only the triangles on one side and its averaged normal leans by
    // about half a column (7.6–7.9° measured). Weld coincident vertices first: then every
    // vertex, seams and poles included, has its full ring of triangles.
    let key = |p: Vec3| (p * 1e5).round().to_array().map(|c| c as i64);
    let mut first = std::collections::HashMap::new();
    let welded_index: Vec<u32> = (0..mesh.positions.len())
        .map(|i| *first.entry(key(mesh.positions[i])).or_insert(i as u32))
        .collect();
    let indices: Vec<[u32; 3]> = mesh
        .indices
        .iter()
        .map(|t| t.map(|i| welded_index[i as usize]))
        .collect();
    assert!(
        first.len() < mesh.positions.len(),
        "the seams were welded: {} of {} vertices",
        first.len(),
        mesh.positions.len()
    );
    // The exact normal of the unit sphere at p is p. With the 15° facets of a 24 × 12 sphere the
    // averaged normal is within a few degrees of it at every vertex; the worst cases are next to
    // the poles, where the triangles above and below a vertex differ most. Measured worst: 1.61°
    // uniform, 2.63° area-weighted, 0.60° angle-weighted; the bounds leave about 15–65 %
    // headroom (the mesh is fixed, so only the weighting code can move these) and lie far below
    // the 7.6–7.9° of the unwelded mesh.
    for (weighting, bound_degrees) in [
        (NormalWeighting::Uniform, 2.0f32),
        (NormalWeighting::Area, 3.0),
        (NormalWeighting::Angle, 1.0),
    ] {
        let normals = vertex_normals(&mesh.positions, &indices, weighting);
        let worst = welded_index
            .iter()
            .map(|&i| {
                let i = i as usize;
                mesh.positions[i].angle_between(normals[i])
            })
            .fold(0.0f32, f32::max);
        assert!(
            worst.to_degrees() < bound_degrees,
            "{weighting:?}: {}° off the exact normal",
            worst.to_degrees()
        );
    }
}

#[test]
fn angle_weighting_ignores_how_a_face_is_split() {
    // A vertex at the corner of a cube: one face split into 3 triangles around it, the other two
    // faces whole. The angle-weighted normal is the diagonal; the uniform one leans.
    let p = vec![
        Vec3::ZERO,
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::new(1.0, 1.0, 0.0) * 0.5,
        Vec3::new(1.0, 0.0, 0.0) * 0.5 + Vec3::Y * 0.25,
    ];
    // z = 0 face (normal −z) split in three around vertex 0; x = 0 face and y = 0 face whole.
    let tris = vec![[0, 5, 1], [0, 4, 5], [0, 2, 4], [0, 3, 2], [0, 1, 3]];
    let angle = vertex_normals(&p, &tris, NormalWeighting::Angle)[0];
    let uniform = vertex_normals(&p, &tris, NormalWeighting::Uniform)[0];
    let diagonal = -Vec3::ONE.normalize();
    assert!(angle.angle_between(diagonal) < 1e-5, "{angle}");
    assert!(uniform.angle_between(diagonal) > 0.2, "{uniform}");
}

#[test]
fn averaged_normals_can_all_be_parallel() {
    // Foley et al., *Computer Graphics: Principles and Practice* (2nd ed., 1990), §16.2, on
    // unrepresentative vertex normals: a corrugated strip whose face normals alternate ±30° about
    // +y gives every vertex the normal +y, so Gouraud shades the whole strip one colour.
    let mut p = Vec::new();
    for i in 0..7 {
        let y = if i % 2 == 0 { 0.0 } else { 0.577 };
        p.push(Vec3::new(i as f32, y, 0.0));
        p.push(Vec3::new(i as f32, y, -1.0));
    }
    let mut tris = Vec::new();
    for i in 0..6u32 {
        let (a, b, c, d) = (2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3);
        tris.push([a, c, b]);
        tris.push([b, c, d]);
    }
    // Angle weighting: each vertex sees as much of the face on its left as on its right.
    let n = vertex_normals(&p, &tris, NormalWeighting::Angle);
    for (k, normal) in n.iter().enumerate().take(12).skip(2) {
        assert!(normal.angle_between(Vec3::Y) < 1e-5, "{k}: {normal}");
    }
}

#[test]
fn slerp_phong_is_close_to_phong() {
    let scene = scene();
    let mesh = barytex_uv::mesh::sphere(24, 12).expect("valid");
    let (vertices, indices) = mesh_vertices(&mesh);
    let reference = traced_sphere(&scene);
    let phong = render(&PhongShader::new(&scene), &vertices, &indices);
    let (sv, si, normals) = barytex_shade::slerp_vertices(&mesh);
    let slerped = render(
        &barytex_shade::SlerpPhongShader {
            scene: &scene,
            normals: &normals,
        },
        &sv,
        &si,
    );
    let gouraud = render(&GouraudShader { scene: &scene }, &vertices, &indices);
    let (e_phong, e_slerp, e_gouraud) = (
        error(&phong, &reference),
        error(&slerped, &reference),
        error(&gouraud, &reference),
    );
    let between = error(&slerped, &phong);
    println!("vs traced sphere: phong {e_phong:?}, slerp {e_slerp:?}; slerp vs phong {between:?}");
    assert!(e_slerp.0 < e_gouraud.0 / 2.0);
    assert!(e_slerp.0 < 2.0 * e_phong.0);
    assert!(between.1 < 0.01, "{between:?}");
}

#[test]
fn slerp_triangle_normal_corners_and_edges() {
    let n = [Vec3::X, Vec3::Y, Vec3::Z];
    assert_eq!(barytex_shade::slerp_triangle_normal(n, Vec3::X), Vec3::X);
    assert!((barytex_shade::slerp_triangle_normal(n, Vec3::Y) - Vec3::Y).length() < 1e-6);
    assert!((barytex_shade::slerp_triangle_normal(n, Vec3::Z) - Vec3::Z).length() < 1e-6);
    // A quarter of the way along edge 01: 22.5° from X (lerp + renormalize gives 18.4°).
    let q = barytex_shade::slerp_triangle_normal(n, Vec3::new(0.75, 0.25, 0.0));
    assert!((q.angle_between(Vec3::X).to_degrees() - 22.5).abs() < 1e-4);
    let c = barytex_shade::slerp_triangle_normal(n, Vec3::splat(1.0 / 3.0));
    assert!((c.length() - 1.0).abs() < 1e-6);
    assert_eq!(
        barytex_shade::slerp_triangle_normal([Vec3::ZERO; 3], Vec3::X),
        Vec3::ZERO
    );
}

/// The Finnish lecture notes *Valaistus ja sävytys*, p. 291 (orientation dependence; Foley et al.
/// 1990, §16.2): "the result depends on the polygon's orientation if the polygons are not
/// triangles" — a quad split along one diagonal or the other interpolates different colours.
#[test]
fn quads_shade_differently_when_split_along_the_other_diagonal() {
    use barytex_shade::{ColouredVertex, ShadeContext};
    let scene: ShadeContext = scene();
    let quad = [
        Vec3::new(-0.8, -0.8, 0.0),
        Vec3::new(0.8, -0.8, 0.0),
        Vec3::new(0.8, 0.8, 0.0),
        Vec3::new(-0.8, 0.8, 0.0),
    ];
    let colours = [Vec3::ONE, Vec3::ZERO, Vec3::ONE, Vec3::ZERO];
    let vertices: Vec<ColouredVertex> = quad
        .iter()
        .zip(colours)
        .map(|(&position, colour)| ColouredVertex { position, colour })
        .collect();
    let shader = ColouredShader { scene: &scene };
    let a = render(&shader, &vertices, &[0, 1, 2, 0, 2, 3]);
    let b = render(&shader, &vertices, &[0, 1, 3, 1, 2, 3]);
    let centre = |fb: &barytex_raster::Framebuffer| fb.pixel(64, 64).expect("in").x;
    // Along diagonal 0–2 both ends are white; along 1–3 both are black.
    assert!(centre(&a) > 0.9, "{}", centre(&a));
    assert!(centre(&b) < 0.1, "{}", centre(&b));
}

#[test]
fn hostile_meshes_never_panic() {
    let scene = scene();
    let mut mesh = barytex_uv::mesh::sphere(8, 4).expect("valid");
    mesh.positions[3] = Vec3::NAN;
    mesh.normals[4] = Vec3::ZERO;
    mesh.normals[5] = Vec3::splat(f32::INFINITY);
    mesh.indices.push([0, 1, 9999]);
    mesh.indices.push([0, 0, 0]);
    let (v, i) = mesh_vertices(&mesh);
    let _ = render(&GouraudShader { scene: &scene }, &v, &i);
    let _ = render(&PhongShader::new(&scene), &v, &i);
    let (fv, fi) = flat_vertices(&mesh, &scene);
    let _ = render(&ColouredShader { scene: &scene }, &fv, &fi);
    let (hv, hi, _) = hybrid_vertices(&mesh, &scene, &HighlightTest::default());
    let _ = render(&HybridShader { scene: &scene }, &hv, &hi);
    let (sv, si, n) = barytex_shade::slerp_vertices(&mesh);
    let _ = render(
        &barytex_shade::SlerpPhongShader {
            scene: &scene,
            normals: &n,
        },
        &sv,
        &si,
    );
    let (qv, qi, nodes) = barytex_shade::fast_phong_vertices(&mesh, &scene);
    let _ = render(
        &barytex_shade::FastPhongShader {
            scene: &scene,
            nodes: &nodes,
        },
        &qv,
        &qi,
    );
    assert!(
        barytex_shade::Camera::look_at(Vec3::ZERO, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 1.0)
            .is_none()
    );
    assert!(
        barytex_shade::Camera::look_at(Vec3::ZERO, Vec3::Y, Vec3::Y, 1.0, 1.0, 0.1, 1.0).is_none()
    );
}

#[test]
fn h_test_stages() {
    use barytex_shade::{Camera, HighlightVerdict, Light, ShadeContext, Specular, ViewVector};
    let scene = ShadeContext {
        camera: Camera::look_at(Vec3::Z * 5.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0)
            .expect("regular"),
        lights: vec![Light::Directional {
            direction: -Vec3::Z,
            color: Vec3::ONE,
        }],
        ambient: Vec3::ZERO,
        material: PhongMaterial {
            shininess: 400.0,
            ..PhongMaterial::default()
        },
        view: ViewVector::Constant(Vec3::Z),
    };
    // A distant eye and light (constant V = L = +z): the mirror peak is where the normal is +z.
    let test = HighlightTest::default();
    let p = [
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ];
    // A vertex normal facing the eye and the light: stage 2.
    let facing = [Vec3::Z, Vec3::X, Vec3::Y];
    assert_eq!(test.run(&scene, p, facing), HighlightVerdict::Vertex(0));
    // Normals tilted ±30° about y on edge 01: the peak is at the edge's midpoint (stage 3).
    let tilt = |a: f32| Vec3::new(a.sin(), 0.0, a.cos());
    let edge = [tilt(0.5), tilt(-0.5), Vec3::new(0.0, 0.8, 0.6)];
    assert_eq!(test.run(&scene, p, edge), HighlightVerdict::Edge(0));
    // All normals turned away from the mirror direction: stage 5.
    let away = [
        Vec3::X,
        Vec3::new(0.9, 0.1, 0.1).normalize(),
        Vec3::new(0.9, -0.1, 0.2).normalize(),
    ];
    assert_eq!(test.run(&scene, p, away), HighlightVerdict::None);
    // A matte material: stage 1.
    let matte = ShadeContext {
        material: PhongMaterial {
            lobe: Specular::None,
            ..scene.material
        },
        ..scene.clone()
    };
    assert_eq!(test.run(&matte, p, facing), HighlightVerdict::NoSpecular);
}

/// The Finnish lecture notes *Valaistus ja sävytys*, p. 291 (polygonal silhouettes; Foley et al.
/// 1990, §16.2): "interpolated shading does nothing for the polygonal silhouette" — Gouraud and
/// Phong cover exactly the same pixels, and both miss pixels the true sphere covers.
#[test]
fn silhouettes_stay_polygonal() {
    let scene = scene();
    let mesh = barytex_uv::mesh::sphere(12, 6).expect("valid");
    let (v, i) = mesh_vertices(&mesh);
    let covered = |fb: &barytex_raster::Framebuffer| {
        (0..SIZE * SIZE)
            .filter(|k| fb.pixel(k % SIZE, k / SIZE).expect("in").w > 0.0)
            .count()
    };
    let gouraud = covered(&render(&GouraudShader { scene: &scene }, &v, &i));
    let phong = covered(&render(&PhongShader::new(&scene), &v, &i));
    let exact = covered(&traced_sphere(&scene));
    assert_eq!(gouraud, phong);
    assert!(exact > phong + 100, "{exact} {phong}");
}
