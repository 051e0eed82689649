//! The shading speed-ups of the Finnish lecture notes *Valaistus ja sävytys* (p. 292), each with
//! its error measured against exact Phong shading on the test sphere (128², one directional light).

mod common;

use barytex_shade::{
    ColouredShader, FastPhongShader, GouraudShader, PhongShader, ViewVector, fast_phong_vertices,
    mesh_vertices, precomputed_vertex_colours, quadratic_interpolate,
};
use common::{error, render, scene};
use glam::Vec3;

fn sphere() -> barytex_uv::TriMesh {
    barytex_uv::mesh::sphere(24, 12).expect("valid")
}

#[test]
fn constant_view_vector_error() {
    let scene = scene();
    let mesh = sphere();
    let (v, i) = mesh_vertices(&mesh);
    let exact = render(&PhongShader::new(&scene), &v, &i);
    let mut fast = scene.clone();
    // The lecture notes' constant V = [0, 0, 1]: here the camera looks down −z, so V = +z.
    fast.view = ViewVector::Constant(Vec3::Z);
    let approx = render(&PhongShader::new(&fast), &v, &i);
    let e = error(&approx, &exact);
    println!("constant view vector: mean {:.4}, max {:.4}", e.0, e.1);
    // The highlight moves: a visible error, bounded by the specular reflectance.
    assert!(e.1 > 0.02 && e.1 <= 0.5 + 1e-6, "{e:?}");
    // Diffuse-only materials do not care.
    let mut matte = scene.clone();
    matte.material.specular = Vec3::ZERO;
    let mut matte_fast = matte.clone();
    matte_fast.view = ViewVector::Constant(Vec3::Z);
    let e = error(
        &render(&PhongShader::new(&matte_fast), &v, &i),
        &render(&PhongShader::new(&matte), &v, &i),
    );
    assert_eq!(e.1, 0.0);
}

#[test]
fn skipping_per_pixel_renormalization_error() {
    let scene = scene();
    let (v, i) = mesh_vertices(&sphere());
    let exact = render(&PhongShader::new(&scene), &v, &i);
    let lazy = render(
        &PhongShader {
            scene: &scene,
            renormalize: false,
        },
        &v,
        &i,
    );
    let e = error(&lazy, &exact);
    println!("unrenormalized normals: mean {:.4}, max {:.4}", e.0, e.1);
    // Lerped unit normals 15° apart are at most cos 7.5° = 0.991 long: a small darkening of the
    // diffuse term, and a highlight whose R = 2(N·L)N − L is no longer unit either.
    assert!(e.1 > 1e-3 && e.1 < 0.5, "{e:?}");
}

#[test]
fn precomputed_vertex_colours_are_exact_while_static() {
    let scene = scene();
    let mesh = sphere();
    let (v, i) = mesh_vertices(&mesh);
    let (cv, ci) = precomputed_vertex_colours(&mesh, &scene);
    let gouraud = render(&GouraudShader { scene: &scene }, &v, &i);
    let baked = render(&ColouredShader { scene: &scene }, &cv, &ci);
    assert_eq!(error(&baked, &gouraud).1, 0.0);
    // The eye moves a little (the light stays): the diffuse part stays right, the baked
    // highlight is stale.
    let mut moved = scene.clone();
    moved.camera = barytex_shade::Camera::look_at(
        Vec3::new(0.4, 0.2, 3.0),
        Vec3::ZERO,
        Vec3::Y,
        45f32.to_radians(),
        1.0,
        0.1,
        10.0,
    )
    .expect("regular");
    let fresh = render(&GouraudShader { scene: &moved }, &v, &i);
    let stale = render(&ColouredShader { scene: &moved }, &cv, &ci);
    let e = error(&stale, &fresh);
    println!(
        "stale precomputed colours after an eye move: mean {:.4}, max {:.4}",
        e.0, e.1
    );
    assert!(e.1 > 0.01, "{e:?}");
}

#[test]
fn fast_phong_error() {
    let scene = scene();
    let mesh = sphere();
    let (v, i) = mesh_vertices(&mesh);
    let exact = render(&PhongShader::new(&scene), &v, &i);
    let (fv, fi, nodes) = fast_phong_vertices(&mesh, &scene);
    let fast = render(
        &FastPhongShader {
            scene: &scene,
            nodes: &nodes,
        },
        &fv,
        &fi,
    );
    let gouraud = render(&GouraudShader { scene: &scene }, &v, &i);
    let e = error(&fast, &exact);
    let g = error(&gouraud, &exact);
    println!(
        "fast Phong vs Phong: mean {:.5}, max {:.4}; Gouraud vs Phong: mean {:.5}, max {:.4}",
        e.0, e.1, g.0, g.1
    );
    assert!(e.1 < 0.03, "{e:?}");
    assert!(e.0 < g.0 / 10.0 && e.1 < g.1 / 5.0, "{e:?} {g:?}");
}

#[test]
fn quadratic_interpolation_is_exact_for_quadratics() {
    // f(b) = b1² + 3 b0 b2 − b2 at the six nodes.
    let f = |b: Vec3| Vec3::splat(b.y * b.y + 3.0 * b.x * b.z - b.z);
    let nodes = [
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::new(0.5, 0.5, 0.0),
        Vec3::new(0.0, 0.5, 0.5),
        Vec3::new(0.5, 0.0, 0.5),
    ];
    let colours = nodes.map(f);
    for b in [
        Vec3::new(0.2, 0.3, 0.5),
        Vec3::new(0.6, 0.1, 0.3),
        Vec3::splat(1.0 / 3.0),
    ] {
        assert!(
            (quadratic_interpolate(&colours, b) - f(b))
                .abs()
                .max_element()
                < 1e-6
        );
    }
}
