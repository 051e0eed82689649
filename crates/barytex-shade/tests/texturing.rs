//! Texture uses, normal maps, bump maps, MikkTSpace tangents and environment maps.

mod common;

use barytex_shade::{
    Camera, Environment, PhongShader, SurfaceShader, TextureUse, bump_normal, generate_tangents,
    mesh_vertices, perturb_normal,
};
use barytex_texture::{
    CubeTexture, MipChain, Rgba32f, Sampler, SamplerDescriptor, Texel, Texture2d,
};
use common::{SIZE, error, render, scene};
use glam::{Vec2, Vec3, Vec4};

/// A texture that is one colour everywhere.
struct Constant(Vec4);

impl Sampler for Constant {
    fn sample(&self, _: Vec2, _: Vec2, _: Vec2) -> Vec4 {
        self.0
    }
    fn sample_level(&self, _: Vec2, _: f32) -> Vec4 {
        self.0
    }
}

fn sphere() -> (Vec<barytex_shade::ShadeVertex>, Vec<u32>) {
    mesh_vertices(&barytex_uv::mesh::sphere(24, 12).expect("valid"))
}

#[test]
fn surface_shader_without_maps_is_phong() {
    let scene = scene();
    let (v, i) = sphere();
    let a = render(&SurfaceShader::new(&scene), &v, &i);
    let b = render(&PhongShader::new(&scene), &v, &i);
    assert_eq!(error(&a, &b).1, 0.0);
}

#[test]
fn texture_uses() {
    let scene = scene();
    let (v, i) = sphere();
    let tex = Constant(Vec4::new(0.2, 0.5, 0.8, 1.0));
    let with = |u| {
        render(
            &SurfaceShader {
                colour: Some((&tex, u)),
                ..SurfaceShader::new(&scene)
            },
            &v,
            &i,
        )
    };
    // Replace: the texture, unlit, everywhere the sphere covers.
    let replaced = with(TextureUse::Replace);
    assert_eq!(replaced.pixel(64, 64), Some(tex.0));
    // Modulate: the lit colour times the texture.
    let plain = render(&PhongShader::new(&scene), &v, &i);
    let modulated = with(TextureUse::Modulate);
    for (x, y) in [(64, 64), (50, 40), (80, 90)] {
        let expect = plain.pixel(x, y).expect("in").truncate() * tex.0.truncate();
        let got = modulated.pixel(x, y).expect("in").truncate();
        assert!((expect - got).abs().max_element() < 1e-6);
    }
    // Diffuse input equals a material whose k_d = k_a = texture.
    let mut textured = scene.clone();
    textured.material.diffuse = tex.0.truncate();
    textured.material.ambient = tex.0.truncate();
    let expect = render(&PhongShader::new(&textured), &v, &i);
    assert!(error(&with(TextureUse::Diffuse), &expect).1 < 1e-6);
    // Specular input: k_s from the texture; highlights take its colour.
    textured = scene.clone();
    textured.material.specular = tex.0.truncate();
    let expect = render(&PhongShader::new(&textured), &v, &i);
    assert!(error(&with(TextureUse::Specular), &expect).1 < 1e-6);
    // Shininess from the red channel.
    textured = scene.clone();
    textured.material.shininess = 0.2 * 100.0;
    let expect = render(&PhongShader::new(&textured), &v, &i);
    assert!(error(&with(TextureUse::Shininess { max: 100.0 }), &expect).1 < 1e-5);
}

#[test]
fn flat_normal_map_equals_no_map() {
    let scene = scene();
    let mesh = barytex_uv::mesh::sphere(24, 12).expect("valid");
    let (v, i) = mesh_vertices(&mesh);
    let flat = Constant(Vec4::new(0.5, 0.5, 1.0, 1.0));
    let mapped = render(
        &SurfaceShader {
            normal_map: Some(&flat),
            ..SurfaceShader::new(&scene)
        },
        &v,
        &i,
    );
    let plain = render(&PhongShader::new(&scene), &v, &i);
    assert!(error(&mapped, &plain).1 < 1e-5);
    // A tilted map changes the image.
    let tilted = Constant(Vec4::new(0.8, 0.5, 0.9, 1.0));
    let mapped = render(
        &SurfaceShader {
            normal_map: Some(&tilted),
            ..SurfaceShader::new(&scene)
        },
        &v,
        &i,
    );
    assert!(error(&mapped, &plain).0 > 0.01);
}

#[test]
fn handedness_flips_the_bitangent() {
    let n = Vec3::Z;
    let m = Vec3::new(0.0, 0.6, 0.8);
    let right = perturb_normal(n, Vec4::new(1.0, 0.0, 0.0, 1.0), m);
    let left = perturb_normal(n, Vec4::new(1.0, 0.0, 0.0, -1.0), m);
    assert!((right - Vec3::new(0.0, 0.6, 0.8)).length() < 1e-6);
    assert!((left - Vec3::new(0.0, -0.6, 0.8)).length() < 1e-6);
    // Degenerate tangents leave the normal alone.
    assert_eq!(perturb_normal(n, Vec4::ZERO, m), n);
    assert_eq!(perturb_normal(n, Vec4::new(0.0, 0.0, 1.0, 1.0), m), n);
    assert_eq!(
        perturb_normal(n, Vec4::new(1.0, 0.0, 0.0, 1.0), Vec3::NAN),
        n
    );
}

#[test]
#[allow(clippy::needless_range_loop)]
fn mikktspace_agrees_with_the_analytic_tangents() {
    let mesh = barytex_uv::mesh::sphere(32, 16).expect("valid");
    let generated = generate_tangents(&mesh).expect("regular");
    let (mut checked, mut sum, mut worst) = (0, 0.0f32, 0.0f32);
    for k in 0..mesh.positions.len() {
        // Skip the poles, where every column's tangent differs.
        if mesh.positions[k].y.abs() > 0.95 {
            continue;
        }
        let (a, b) = (generated[k], mesh.tangents[k]);
        assert_eq!(a.w, b.w, "vertex {k}");
        // MikkTSpace averages the faces' tangents: a few degrees off the analytic ∂p/∂u on a
        // 32 × 16 sphere near the poles, much less at the equator.
        let angle = a.truncate().angle_between(b.truncate());
        assert!(angle < 0.15, "vertex {k}: {a} {b}");
        worst = worst.max(angle);
        sum += angle;
        checked += 1;
    }
    assert!(checked > 400);
    let mean = sum / checked as f32;
    println!("MikkTSpace vs analytic tangents: mean {mean} rad, worst {worst} rad");
    assert!(mean <= 0.03, "mean {mean} worst {worst}");
    let mut broken = mesh.clone();
    broken.indices.push([0, 1, 99_999]);
    assert!(generate_tangents(&broken).is_none());
}

#[test]
fn bump_on_a_plane_is_exact() {
    for (hx, hy, s) in [
        (0.3f32, -0.2f32, 0.01f32),
        (2.0, 0.5, 0.1),
        (-1.0, 1.0, 1e-3),
    ] {
        // Pixel steps s along x and y on the plane z = 0; the height's change per pixel.
        let n = bump_normal(Vec3::Z, Vec3::X * s, Vec3::Y * s, hx * s, hy * s);
        let exact = Vec3::new(-hx, -hy, 1.0).normalize();
        assert!((n - exact).length() < 4e-7, "{n} {exact}");
    }
    assert_eq!(bump_normal(Vec3::Z, Vec3::ZERO, Vec3::Y, 1.0, 1.0), Vec3::Z);
    assert_eq!(
        bump_normal(Vec3::Z, Vec3::X, Vec3::Y, f32::NAN, 1.0),
        Vec3::Z
    );
}

#[test]
fn flat_height_field_gives_the_unperturbed_normal() {
    let scene = scene();
    let (v, i) = sphere();
    let constant = |_: Vec2| 0.25f32;
    let bumped = render(
        &SurfaceShader {
            bump: Some((&constant, 0.1)),
            ..SurfaceShader::new(&scene)
        },
        &v,
        &i,
    );
    let plain = render(&PhongShader::new(&scene), &v, &i);
    assert!(error(&bumped, &plain).1 < 1e-5);
    let ripples = |uv: Vec2| (uv.x * 80.0).sin() * 0.5;
    let bumped = render(
        &SurfaceShader {
            bump: Some((&ripples, 0.02)),
            ..SurfaceShader::new(&scene)
        },
        &v,
        &i,
    );
    assert!(error(&bumped, &plain).0 > 0.01);
}

fn face_colours() -> [Vec4; 6] {
    [
        Vec4::new(1.0, 0.0, 0.0, 1.0), // +X
        Vec4::new(0.0, 1.0, 1.0, 1.0), // −X
        Vec4::new(0.0, 1.0, 0.0, 1.0), // +Y
        Vec4::new(1.0, 0.0, 1.0, 1.0), // −Y
        Vec4::new(0.0, 0.0, 1.0, 1.0), // +Z
        Vec4::new(1.0, 1.0, 0.0, 1.0), // −Z
    ]
}

fn cube() -> CubeTexture<Rgba32f> {
    let faces = face_colours().map(|c| {
        MipChain::single(Texture2d::from_fn(8, 8, |_, _| Rgba32f::from_linear(c)).expect("small"))
    });
    CubeTexture::new(faces, SamplerDescriptor::bilinear()).expect("square faces")
}

/// A mirror floor seen from straight above reflects the sky (+Y face); seen from +z at 30°
/// above the floor, the mirrored ray rises at 30° towards −z and meets the −Z face.
#[test]
fn mirror_plane_reflects_the_expected_cube_face() {
    let cube = cube();
    let plane = barytex_uv::mesh::plane(4, 4).expect("valid");
    let (v, i) = mesh_vertices(&plane);
    let mut scene = scene();
    scene.lights.clear();
    scene.camera = Camera::look_at(
        Vec3::new(0.0, 3.0, 0.0),
        Vec3::ZERO,
        -Vec3::Z,
        0.5,
        1.0,
        0.1,
        10.0,
    )
    .expect("regular");
    let shader = SurfaceShader {
        environment: Some((Environment::Cube(&cube), 1.0)),
        ..SurfaceShader::new(&scene)
    };
    let fb = render(&shader, &v, &i);
    let centre = fb.pixel(SIZE / 2, SIZE / 2).expect("in");
    assert!(
        (centre - face_colours()[2]).abs().max_element() < 1e-5,
        "{centre}"
    );
    scene.camera = Camera::look_at(
        Vec3::new(0.0, 1.0, 3.0f32.sqrt()),
        Vec3::ZERO,
        Vec3::Y,
        0.3,
        1.0,
        0.1,
        10.0,
    )
    .expect("regular");
    let shader = SurfaceShader {
        environment: Some((Environment::Cube(&cube), 1.0)),
        ..SurfaceShader::new(&scene)
    };
    let fb = render(&shader, &v, &i);
    let centre = fb.pixel(SIZE / 2, SIZE / 2).expect("in");
    assert!(
        (centre - face_colours()[5]).abs().max_element() < 1e-5,
        "{centre}"
    );
}

#[test]
fn sphere_and_equirect_maps_are_sampled_along_the_reflection() {
    let sky = Constant(Vec4::new(0.3, 0.6, 0.9, 1.0));
    for env in [Environment::SphereMap(&sky), Environment::Equirect(&sky)] {
        let c = env.sample(Vec3::new(0.2, 0.9, 0.1), Vec3::ZERO, Vec3::ZERO);
        assert_eq!(c, sky.0);
        assert_eq!(env.sample(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO), Vec4::ZERO);
        assert_eq!(env.sample(Vec3::NAN, Vec3::ZERO, Vec3::ZERO), Vec4::ZERO);
    }
    let cube = cube();
    let env = Environment::Cube(&cube);
    for (k, dir) in [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z]
        .into_iter()
        .enumerate()
    {
        assert!(
            (env.sample(dir, Vec3::ZERO, Vec3::ZERO) - face_colours()[k])
                .abs()
                .max_element()
                < 1e-6
        );
    }
}
