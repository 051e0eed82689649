//! Cube maps: seamless across every edge and corner, constants, mip selection, bad input.

use barytex_texture::{
    CubeTexture, MipChain, MipOptions, Rgba32f, SamplerDescriptor, Texture2d, TextureError,
};
use glam::{Vec3, Vec4};

fn face(n: u32, seed: u32) -> Texture2d<Rgba32f> {
    Texture2d::from_fn(n, n, |x, y| {
        let h = (x.wrapping_mul(73_856_093)
            ^ y.wrapping_mul(19_349_663)
            ^ seed.wrapping_mul(83_492_791))
            % 1000;
        let v = h as f32 / 999.0;
        Rgba32f([v, 1.0 - v, 0.5 * v, 1.0])
    })
    .expect("small")
}

fn cube(n: u32, descriptor: SamplerDescriptor) -> CubeTexture<Rgba32f> {
    let faces = core::array::from_fn(|i| {
        MipChain::generate(face(n, i as u32), &MipOptions::default()).expect("chain")
    });
    CubeTexture::new(faces, descriptor).expect("valid cube")
}

/// Points on every edge (midpoints and quarter points) and every corner of the cube.
fn seam_points() -> Vec<Vec3> {
    let mut points = Vec::new();
    for a in [-1.0_f32, 1.0] {
        for b in [-1.0_f32, 1.0] {
            for t in [-0.5_f32, 0.0, 0.37] {
                points.push(Vec3::new(a, b, t));
                points.push(Vec3::new(a, t, b));
                points.push(Vec3::new(t, a, b));
            }
            for c in [-1.0_f32, 1.0] {
                points.push(Vec3::new(a, b, c));
            }
        }
    }
    points
}

/// Approaching an edge or corner from any side gives the same colour: the difference between
/// directions 1e-4 apart across the seam is what 1e-4 of bilinear slope allows — and far below
/// the jumps of a per-face clamp-to-edge lookup (which fails this test by 0.29 at an edge).
#[test]
fn seamless_across_every_edge_and_corner() {
    let n = 8;
    let cube = cube(n, SamplerDescriptor::bilinear());
    let offsets = [
        Vec3::X,
        Vec3::NEG_X,
        Vec3::Y,
        Vec3::NEG_Y,
        Vec3::Z,
        Vec3::NEG_Z,
    ];
    for p in seam_points() {
        let centre = cube.sample_level(p, 0.0);
        for o in offsets {
            let nearby = cube.sample_level(p + o * 1e-4, 0.0);
            // Slope ≤ (max texel difference 1) per texel = n/2 per unit on the face plane.
            let bound = 1e-4 * n as f32 + 1e-5;
            assert!(
                (nearby - centre).abs().max_element() <= bound,
                "{p:?} + {o:?}: {nearby:?} vs {centre:?}"
            );
        }
    }
}

#[test]
fn constant_cube_is_constant_everywhere() {
    let value = Rgba32f([0.25, 0.5, 0.75, 1.0]);
    let faces = core::array::from_fn(|_| {
        MipChain::generate(
            Texture2d::new(4, 4, value).expect("4²"),
            &MipOptions::default(),
        )
        .expect("chain")
    });
    let cube = CubeTexture::new(faces, SamplerDescriptor::trilinear()).expect("valid");
    for p in seam_points() {
        for lod in [0.0, 0.5, 1.5, 9.0] {
            let c = cube.sample_level(p, lod);
            assert!(
                (c - Vec4::from_array(value.0)).abs().max_element() < 1e-6,
                "{p:?} {lod}: {c:?}"
            );
        }
    }
}

#[test]
fn derivatives_pick_coarser_levels_for_larger_footprints() {
    let cube = cube(16, SamplerDescriptor::trilinear());
    let dir = Vec3::new(0.3, 0.2, 1.0);
    // One texel of a 16² face spans 2/16 of the face plane at z = 1.
    let fine = cube.sample(dir, Vec3::X * 0.125, Vec3::Y * 0.125);
    let coarse = cube.sample(dir, Vec3::X * 2.0, Vec3::Y * 2.0);
    assert_eq!(fine, cube.sample_level(dir, 0.0));
    assert_eq!(coarse, cube.sample_level(dir, 4.0));
}

#[test]
fn bad_input_has_documented_values() {
    let cube = cube(4, SamplerDescriptor::trilinear());
    assert_eq!(cube.sample_level(Vec3::ZERO, 0.0), Vec4::ZERO);
    assert_eq!(cube.sample_level(Vec3::NAN, 0.0), Vec4::ZERO);
    assert_eq!(cube.sample(Vec3::INFINITY, Vec3::X, Vec3::Y), Vec4::ZERO);
    let last = cube.sample_level(Vec3::Z, 99.0);
    assert_eq!(cube.sample(Vec3::Z, Vec3::NAN, Vec3::Y), last);
    let faces = core::array::from_fn(|i| {
        let side = if i == 3 { 8 } else { 4 };
        MipChain::single(Texture2d::new(side, side, Rgba32f::default()).expect("small"))
    });
    assert!(matches!(
        CubeTexture::new(faces, SamplerDescriptor::default()),
        Err(TextureError::InvalidParameter { .. })
    ));
}
