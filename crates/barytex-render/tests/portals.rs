//! Portals and mirrors, against renders that place the seen geometry by hand:
//!
//! - a mirror facing a textured, one-sided quad shows its reflection bit for bit as the quad
//!   reflected by hand (a mirroring instance) with no mirror, under every anti-aliasing mode
//!   and the mip-reading filters;
//! - a portal between two rooms shows, inside its screen rectangle, bit for bit what the
//!   equivalent camera sees of the second room (the rectangle as the scissor), and the first
//!   room outside it; a tint lays its colour over that view;
//! - an octree (barytex-shade's) in the second room, through the portal, likewise;
//! - two facing mirrors recurse exactly as deep as `portal_depth` allows;
//! - portals the camera cannot see change no bit; renders are the same for 1 and 3 threads;
//! - degenerate portals (collinear, zero area, NaN, infinite, behind the camera, edge-on) never
//!   panic and are counted.

use std::sync::Arc;

use barytex_gltf::camera::{DocumentCamera, Projection, SceneCamera};
use barytex_gltf::material::{Material, TextureRef};
use barytex_gltf::mesh::{Mesh, Primitive};
use barytex_gltf::scene::{MeshInstance, Scene, SceneImage, Texture};
use barytex_gltf::{Portal, SamplerParams, Topology};
use barytex_render::{AntiAliasing, Filter, RenderOptions, Rendered, Shading, render};
use barytex_shade::Octree;
use barytex_texture::load::AnyTexture2d;
use barytex_texture::{Srgba8, Texture2d};
use barytex_uv::mappings::TexCoordMapping;
use glam::{Mat4, UVec3, Vec2, Vec3, Vec4};

const ANTI_ALIASING: [AntiAliasing; 7] = [
    AntiAliasing::None,
    AntiAliasing::Msaa(4),
    AntiAliasing::Msaa(8),
    AntiAliasing::Supersample(3),
    AntiAliasing::Jitter(2),
    AntiAliasing::Supersample(6),
    AntiAliasing::Adaptive(8),
];

/// Quads `[corners]` (counter-clockwise seen from the front) in one primitive, with uvs over
/// each quad and one colour per quad.
fn quads(quads: &[([Vec3; 4], Vec4)], material: usize) -> Primitive {
    let mut p = Primitive {
        positions: Vec::new(),
        normals: None,
        tangents: None,
        tex_coords0: Some(Vec::new()),
        tex_coords1: None,
        colors0: Some(Vec::new()),
        triangles: Vec::new(),
        indices: Vec::new(),
        material: Some(material),
        topology: Topology::Triangles,
    };
    for (corners, colour) in quads {
        let base = p.positions.len() as u32;
        p.positions.extend(corners);
        if let Some(uv) = p.tex_coords0.as_mut() {
            uv.extend([Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y]);
        }
        if let Some(c) = p.colors0.as_mut() {
            c.extend([*colour; 4]);
        }
        p.triangles
            .extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
    }
    p
}

fn instance(node: usize, primitive: Primitive, world: Mat4) -> MeshInstance {
    MeshInstance {
        node,
        node_name: None,
        world,
        flips_winding: world.determinant() < 0.0,
        mesh: Arc::new(Mesh {
            index: node,
            name: None,
            primitives: vec![primitive],
        }),
    }
}

/// A scene of `instances` seen by a 45° camera placed by `camera_world`; material 0 is
/// textured with a 16² checker of coloured squares, material 1 is plain white (vertex colours).
fn scene(instances: Vec<MeshInstance>, camera_world: Mat4, portals: Vec<Portal>) -> Scene {
    let checker = Texture2d::from_fn(16, 16, |x, y| {
        let odd = (x / 4 + y / 4) % 2 == 1;
        Srgba8(if odd {
            [230, (x * 15) as u8, 40, 255]
        } else {
            [20, 60, (y * 15) as u8, 255]
        })
    })
    .expect("small");
    let projection = Projection::Perspective {
        yfov: 45_f32.to_radians(),
        aspect_ratio: None,
        znear: 0.1,
        zfar: Some(200.0),
    };
    Scene {
        instances,
        cameras: vec![SceneCamera {
            node: 99,
            camera: 0,
            name: None,
            projection,
            world: camera_world,
        }],
        document_cameras: vec![DocumentCamera {
            name: None,
            projection,
        }],
        materials: vec![
            Material {
                base_color_texture: Some(TextureRef {
                    texture: 0,
                    image: Some(0),
                    sampler: SamplerParams::default(),
                    mapping: TexCoordMapping::new(0),
                }),
                ..Material::default()
            },
            Material::default(),
        ],
        textures: vec![Texture {
            image: Some(0),
            sampler: SamplerParams::default(),
        }],
        images: vec![SceneImage {
            name: None,
            srgb: Some(Arc::new(AnyTexture2d::Srgba8(checker))),
            linear: None,
        }],
        portals,
        ..Scene::default()
    }
}

fn options(anti_aliasing: AntiAliasing) -> RenderOptions {
    RenderOptions {
        width: 80,
        height: 60,
        shading: Shading::Unlit,
        filter: Filter::Bilinear,
        anti_aliasing,
        ..RenderOptions::default()
    }
}

/// Every bit of the resolved linear colour, pixel by pixel.
fn bits(out: &Rendered) -> Vec<[u32; 4]> {
    let rows = out.image.to_linear_rgba().expect("small");
    rows.iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect()
}

/// The camera-to-world matrix of a camera at `eye` looking at `target`, +y up.
fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    let forward = (target - eye).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    Mat4::from_cols(
        right.extend(0.0),
        up.extend(0.0),
        (-forward).extend(0.0),
        eye.extend(1.0),
    )
}

/// The textured quad at z = 2, x ∈ [−3, −1], facing −z (away from the camera, towards the
/// mirror): one-sided, so the camera itself sees nothing of it.
fn textured_quad() -> Primitive {
    let corners = [
        Vec3::new(-3.0, -1.0, 2.0),
        Vec3::new(-3.0, 1.0, 2.0),
        Vec3::new(-1.0, 1.0, 2.0),
        Vec3::new(-1.0, -1.0, 2.0),
    ];
    quads(&[(corners, Vec4::ONE)], 0)
}

#[test]
fn a_mirror_shows_the_reflection_placed_by_hand() {
    let camera = look_at(Vec3::new(2.5, 0.3, 6.0), Vec3::new(-0.5, 0.0, 0.0));
    let glass = vec![
        Vec3::new(-4.0, -3.0, 0.0),
        Vec3::new(4.0, -3.0, 0.0),
        Vec3::new(4.0, 3.0, 0.0),
        Vec3::new(-4.0, 3.0, 0.0),
    ];
    let mirror = Portal::mirror(glass).expect("a rectangle");
    assert_eq!(
        mirror.transform,
        Mat4::from_scale(Vec3::new(1.0, 1.0, -1.0))
    );
    // Behind the glass, a green card the mirror hides from the camera: the view through the
    // mirror must not show it (reflected, it would float in front of the glass), which only
    // the oblique near plane at the glass prevents.
    let card = quads(
        &[(
            [
                Vec3::new(-1.0, -1.0, -0.5),
                Vec3::new(1.0, -1.0, -0.5),
                Vec3::new(1.0, 1.0, -0.5),
                Vec3::new(-1.0, 1.0, -0.5),
            ],
            rgb(0.0, 1.0, 0.0),
        )],
        1,
    );
    let mut with_mirror = scene(
        vec![
            instance(0, textured_quad(), Mat4::IDENTITY),
            instance(2, card, Mat4::IDENTITY),
        ],
        camera,
        vec![mirror],
    );
    with_mirror.materials[1].double_sided = true;
    // By hand: the quad again under the reflection z → −z (a mirroring instance, so its
    // winding turns as the mirror's does), and no mirror.
    let by_hand = scene(
        vec![
            instance(0, textured_quad(), Mat4::IDENTITY),
            instance(
                1,
                textured_quad(),
                Mat4::from_scale(Vec3::new(1.0, 1.0, -1.0)),
            ),
        ],
        camera,
        Vec::new(),
    );
    // Every anti-aliasing mode with bilinear filtering; the mip-reading filters (their level of
    // detail from the exact derivatives) under MSAA and jitter.
    let mip_filters = [Filter::Trilinear, Filter::Anisotropic(8), Filter::Ewa];
    let cases = ANTI_ALIASING
        .map(|aa| (aa, Filter::Bilinear))
        .into_iter()
        .chain(
            mip_filters
                .into_iter()
                .flat_map(|f| [(AntiAliasing::Msaa(4), f), (AntiAliasing::Jitter(2), f)]),
        );
    for (aa, filter) in cases {
        let options = RenderOptions {
            filter,
            ..options(aa)
        };
        let mirrored = render(&with_mirror, &options).expect("renders");
        let expected = render(&by_hand, &options).expect("renders");
        let (a, b) = (bits(&mirrored), bits(&expected));
        let background = options.background.to_array().map(f32::to_bits);
        let textured = b.iter().filter(|p| **p != background).count();
        assert!(
            textured > 150,
            "{aa:?}: the reflection covers {textured} pixels"
        );
        let differ = a.iter().zip(&b).filter(|(x, y)| x != y).count();
        assert_eq!(differ, 0, "{aa:?}: {differ} pixels differ");
        assert!(mirrored.stats.portal_views >= 1, "{aa:?}");
        // The camera sees the quad's back only: culled, in both scenes.
        assert!(expected.stats.draw.culled > 0);
    }
}

/// A box `[lo, hi]` of walls facing inwards, one colour per wall (unlit vertex colours).
fn room(lo: Vec3, hi: Vec3, colours: [Vec4; 6]) -> Primitive {
    let c =
        |x: usize, y: usize, z: usize| Vec3::new([lo.x, hi.x][x], [lo.y, hi.y][y], [lo.z, hi.z][z]);
    quads(
        &[
            ([c(0, 0, 0), c(0, 1, 0), c(0, 1, 1), c(0, 0, 1)], colours[0]), // x = lo, facing +x
            ([c(1, 0, 0), c(1, 0, 1), c(1, 1, 1), c(1, 1, 0)], colours[1]), // x = hi, facing −x
            ([c(0, 0, 0), c(0, 0, 1), c(1, 0, 1), c(1, 0, 0)], colours[2]), // floor, facing +y
            ([c(0, 1, 0), c(1, 1, 0), c(1, 1, 1), c(0, 1, 1)], colours[3]), // ceiling, facing −y
            ([c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0)], colours[4]), // back, facing +z
            ([c(0, 0, 1), c(0, 1, 1), c(1, 1, 1), c(1, 0, 1)], colours[5]), // front, facing −z
        ],
        1,
    )
}

fn rgb(r: f32, g: f32, b: f32) -> Vec4 {
    Vec4::new(r, g, b, 1.0)
}

/// Room A around the camera (at (0, 0, 4), looking down −z), room B 100 units along x; the
/// portal on A's back wall shows B: B's doorway node is at (100, 0, 0), A's portal node at
/// (0, 0, −4), so `transform` moves B by (−100, 0, −4).
fn two_rooms(extra: Vec<MeshInstance>, tint: Vec4) -> (Scene, Mat4) {
    let room_a = room(
        Vec3::new(-6.0, -4.0, -4.5),
        Vec3::new(6.0, 4.0, 6.0),
        [
            rgb(0.8, 0.2, 0.2),
            rgb(0.2, 0.8, 0.2),
            rgb(0.5, 0.5, 0.5),
            rgb(0.9, 0.9, 0.6),
            rgb(0.3, 0.3, 0.9),
            rgb(0.1, 0.1, 0.1),
        ],
    );
    let room_b = room(
        Vec3::new(95.0, -5.0, -10.0),
        Vec3::new(105.0, 5.0, 0.0),
        [
            rgb(0.9, 0.5, 0.1),
            rgb(0.1, 0.6, 0.9),
            rgb(0.4, 0.25, 0.1),
            rgb(0.95, 0.95, 0.95),
            rgb(0.6, 0.1, 0.6),
            rgb(1.0, 1.0, 0.0),
        ],
    );
    let transform = Mat4::from_translation(Vec3::new(0.0, 0.0, -4.0))
        * Mat4::from_translation(Vec3::new(100.0, 0.0, 0.0)).inverse();
    let door = vec![
        Vec3::new(-2.0, -2.0, -4.0),
        Vec3::new(2.0, -2.0, -4.0),
        Vec3::new(2.0, 2.0, -4.0),
        Vec3::new(-2.0, 2.0, -4.0),
    ];
    let portal = Portal::new(door, transform).with_tint(tint);
    let mut instances = vec![
        instance(0, room_a, Mat4::IDENTITY),
        instance(1, room_b, Mat4::IDENTITY),
    ];
    instances.extend(extra);
    let camera = Mat4::from_translation(Vec3::new(0.0, 0.0, 4.0));
    (scene(instances, camera, vec![portal]), transform)
}

/// The pixels (x, y) of an 80 × 60 image whose centre is inside the portal's screen rectangle
/// by more than a pixel (`Some(true)`), outside by more than a pixel (`Some(false)`), or near
/// its edge (`None`).
fn inside_door(scene: &Scene, options: &RenderOptions, x: u32, y: u32) -> Option<bool> {
    let camera = barytex_render::choose_camera(scene, options).expect("a camera");
    let corner = |p: Vec3| {
        let c = camera.projection * camera.view * p.extend(1.0);
        Vec2::new(
            (c.x / c.w + 1.0) * 0.5 * options.width as f32,
            (1.0 - c.y / c.w) * 0.5 * options.height as f32,
        )
    };
    let (lo, hi) = (
        corner(Vec3::new(-2.0, 2.0, -4.0)),
        corner(Vec3::new(2.0, -2.0, -4.0)),
    );
    let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
    let inside = p.cmpgt(lo + 1.0).all() && p.cmplt(hi - 1.0).all();
    let outside = p.cmplt(lo - 1.0).any() || p.cmpgt(hi + 1.0).any();
    if inside {
        Some(true)
    } else if outside {
        Some(false)
    } else {
        None
    }
}

/// Compares the render through the portal with the equivalent camera's (inside the door) and
/// with the scene without the portal (outside it); returns the pixels compared inside.
fn check_through_door(with_portal: &Scene, transform: Mat4, aa: AntiAliasing) -> usize {
    let options = options(aa);
    let through = render(with_portal, &options).expect("renders");
    // The equivalent camera: the camera moved by the portal's inverse transform.
    let mut direct = with_portal.clone();
    direct.portals.clear();
    let plain = render(&direct, &options).expect("renders");
    direct.cameras[0].world = transform.inverse() * direct.cameras[0].world;
    let equivalent = render(&direct, &options).expect("renders");
    let (a, b, c) = (bits(&through), bits(&equivalent), bits(&plain));
    let mut compared = 0;
    for y in 0..options.height {
        for x in 0..options.width {
            let i = (y * options.width + x) as usize;
            match inside_door(with_portal, &options, x, y) {
                Some(true) => {
                    assert_eq!(a[i], b[i], "{aa:?}: ({x}, {y}) through the door");
                    compared += 1;
                }
                Some(false) => assert_eq!(a[i], c[i], "{aa:?}: ({x}, {y}) beside the door"),
                None => {}
            }
        }
    }
    assert_eq!(
        through.stats.portal_views,
        u64::from(through.stats.passes),
        "{aa:?}"
    );
    compared
}

#[test]
fn a_portal_shows_the_other_room_as_the_equivalent_camera_does() {
    let (with_portal, transform) = two_rooms(Vec::new(), Vec4::ZERO);
    for aa in [
        AntiAliasing::None,
        AntiAliasing::Msaa(4),
        AntiAliasing::Jitter(2),
    ] {
        let compared = check_through_door(&with_portal, transform, aa);
        // The door is 4 units wide at distance 8 under a 45° field of view: 36 × 36 pixels.
        assert!(compared > 1000, "{aa:?}: {compared}");
    }
}

#[test]
fn a_tint_is_laid_over_the_view() {
    let tint = Vec4::new(0.0, 0.2, 1.0, 0.25);
    let (clear, _) = two_rooms(Vec::new(), Vec4::ZERO);
    let (tinted, _) = two_rooms(Vec::new(), tint);
    let options = options(AntiAliasing::None);
    let a = render(&clear, &options).expect("renders").image;
    let b = render(&tinted, &options).expect("renders").image;
    let (mut inside, mut outside) = (0, 0);
    for y in 0..options.height {
        for x in 0..options.width {
            let (p, q) = (a.pixel(x, y).expect("in"), b.pixel(x, y).expect("in"));
            match inside_door(&clear, &options, x, y) {
                Some(true) => {
                    let over = tint.truncate() * tint.w + p.truncate() * (1.0 - tint.w);
                    assert!(
                        (q.truncate() - over).abs().max_element() < 1e-6,
                        "({x}, {y})"
                    );
                    inside += 1;
                }
                Some(false) => {
                    assert_eq!(p, q);
                    outside += 1;
                }
                None => {}
            }
        }
    }
    assert!(inside > 1000 && outside > 2500, "{inside} {outside}");
}

/// The integer cell of a voxel's corner.
fn cell_of(min: Vec3, size: f32) -> [i32; 3] {
    let q = (min / size).round();
    [q.x as i32, q.y as i32, q.z as i32]
}

/// One cube per filled cell of `tree`, its faces towards empty cells only, coloured per cell.
fn octree_mesh(tree: &Octree, eye: Vec3) -> Primitive {
    let voxels = tree.back_to_front(eye);
    let size = voxels.first().map_or(1.0, |v| v.size);
    let filled: std::collections::BTreeSet<[i32; 3]> =
        voxels.iter().map(|v| cell_of(v.min, size)).collect();
    let mut faces = Vec::new();
    for v in &voxels {
        let cell = cell_of(v.min, size);
        let c = |x: f32, y: f32, z: f32| v.min + Vec3::new(x, y, z) * size;
        let colour = v.colour.extend(1.0);
        let sides: [([i32; 3], [Vec3; 4]); 6] = [
            (
                [-1, 0, 0],
                [c(0., 0., 0.), c(0., 0., 1.), c(0., 1., 1.), c(0., 1., 0.)],
            ),
            (
                [1, 0, 0],
                [c(1., 0., 0.), c(1., 1., 0.), c(1., 1., 1.), c(1., 0., 1.)],
            ),
            (
                [0, -1, 0],
                [c(0., 0., 0.), c(1., 0., 0.), c(1., 0., 1.), c(0., 0., 1.)],
            ),
            (
                [0, 1, 0],
                [c(0., 1., 0.), c(0., 1., 1.), c(1., 1., 1.), c(1., 1., 0.)],
            ),
            (
                [0, 0, -1],
                [c(0., 0., 0.), c(0., 1., 0.), c(1., 1., 0.), c(1., 0., 0.)],
            ),
            (
                [0, 0, 1],
                [c(0., 0., 1.), c(1., 0., 1.), c(1., 1., 1.), c(0., 1., 1.)],
            ),
        ];
        for (step, corners) in sides {
            let n = [cell[0] + step[0], cell[1] + step[1], cell[2] + step[2]];
            if !filled.contains(&n) {
                faces.push((corners, colour));
            }
        }
    }
    quads(&faces, 1)
}

#[test]
fn an_octree_seen_through_a_portal() {
    // A ball of 8³ cells in room B, coloured by height.
    let (origin, size) = (Vec3::new(98.0, -3.0, -8.0), 4.0);
    let tree = Octree::from_cells(3, origin, size, |c: UVec3| {
        let p = c.as_vec3() + 0.5 - 4.0;
        (p.length() < 3.6).then(|| Vec3::new(0.2 + c.y as f32 * 0.1, 0.9 - c.x as f32 * 0.1, 0.3))
    });
    let virtual_eye = Vec3::new(100.0, 0.0, 4.0);
    let ball = octree_mesh(&tree, virtual_eye);
    assert!(ball.triangles.len() > 200);
    let (with_portal, transform) = two_rooms(vec![instance(2, ball, Mat4::IDENTITY)], Vec4::ZERO);
    for aa in [AntiAliasing::None, AntiAliasing::Msaa(4)] {
        let compared = check_through_door(&with_portal, transform, aa);
        assert!(compared > 1000, "{aa:?}: {compared}");
    }
}

/// Two mirrors facing each other across a coloured quad, the camera between them looking at
/// one: every level of recursion sees the other mirror once.
fn facing_mirrors() -> Scene {
    let square = |z: f32, facing: f32| {
        let mut p = vec![
            Vec3::new(-3.0, -3.0, z),
            Vec3::new(3.0, -3.0, z),
            Vec3::new(3.0, 3.0, z),
            Vec3::new(-3.0, 3.0, z),
        ];
        if facing < 0.0 {
            p.reverse();
        }
        p
    };
    let tint = Vec4::new(0.2, 0.4, 0.9, 0.2);
    let back = Portal::mirror(square(-4.0, 1.0))
        .expect("square")
        .with_tint(tint);
    let front = Portal::mirror(square(4.0, -1.0))
        .expect("square")
        .with_tint(tint);
    let marker = quads(
        &[(
            [
                Vec3::new(0.5, -1.0, 0.0),
                Vec3::new(1.5, -1.0, 0.0),
                Vec3::new(1.5, 0.0, 0.0),
                Vec3::new(0.5, 0.0, 0.0),
            ],
            rgb(1.0, 0.5, 0.0),
        )],
        1,
    );
    let mut double_sided = scene(
        vec![instance(0, marker, Mat4::IDENTITY)],
        look_at(Vec3::new(0.3, 0.4, 2.0), Vec3::new(0.0, 0.0, -4.0)),
        vec![back, front],
    );
    double_sided.materials[1].double_sided = true;
    double_sided
}

#[test]
fn recursion_stops_at_the_depth_limit() {
    let scene = facing_mirrors();
    let mut last: Option<Vec<[u32; 4]>> = None;
    for depth in 0..6 {
        let options = RenderOptions {
            portal_depth: depth,
            ..options(AntiAliasing::None)
        };
        let out = render(&scene, &options).expect("renders");
        assert_eq!(out.stats.portal_views, u64::from(depth), "depth {depth}");
        assert_eq!(out.stats.portals_closed, 1, "depth {depth}");
        let image = bits(&out);
        if let Some(previous) = &last {
            // One more level shows more: the innermost opening is no longer closed.
            assert_ne!(previous, &image, "depth {depth}");
        }
        last = Some(image);
    }
    // At depth 0 the mirror is closed: the background under its tint.
    let options = RenderOptions {
        portal_depth: 0,
        ..options(AntiAliasing::None)
    };
    let closed = render(&scene, &options).expect("renders").image;
    let tint = Vec4::new(0.2, 0.4, 0.9, 0.2);
    let expected = tint.truncate() * tint.w + options.background.truncate() * (1.0 - tint.w);
    let centre = closed.pixel(40, 30).expect("in");
    assert!(
        (centre.truncate() - expected).abs().max_element() < 1e-6,
        "{centre}"
    );
}

#[test]
fn portals_render_the_same_on_any_thread_count() {
    let scene = facing_mirrors();
    for aa in [AntiAliasing::Msaa(4), AntiAliasing::Adaptive(8)] {
        let options = options(aa);
        let run = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("pool")
                .install(|| bits(&render(&scene, &options).expect("renders")))
        };
        assert!(run(1) == run(3), "{aa:?}");
    }
}

#[test]
fn portals_out_of_sight_change_no_bit() {
    let camera = look_at(Vec3::new(2.5, 0.3, 6.0), Vec3::new(-0.5, 0.0, 0.0));
    let plain = scene(
        vec![instance(0, textured_quad(), Mat4::IDENTITY)],
        camera,
        Vec::new(),
    );
    // Behind the camera, and facing away from it.
    let behind = Portal::mirror(vec![
        Vec3::new(-1.0, -1.0, 9.0),
        Vec3::new(-1.0, 1.0, 9.0),
        Vec3::new(1.0, 1.0, 9.0),
        Vec3::new(1.0, -1.0, 9.0),
    ])
    .expect("square");
    let away = Portal::mirror(vec![
        Vec3::new(-1.0, -1.0, -3.0),
        Vec3::new(-1.0, 1.0, -3.0),
        Vec3::new(1.0, 1.0, -3.0),
        Vec3::new(1.0, -1.0, -3.0),
    ])
    .expect("square");
    let mut with = plain.clone();
    with.portals = vec![behind, away];
    for aa in [AntiAliasing::None, AntiAliasing::Msaa(4)] {
        let a = render(&plain, &options(aa)).expect("renders");
        let b = render(&with, &options(aa)).expect("renders");
        assert!(bits(&a) == bits(&b), "{aa:?}");
        assert_eq!((b.stats.portal_views, b.stats.portals_closed), (0, 0));
    }
}

/// A tiny deterministic generator (SplitMix64), for the sweep below.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn coordinate(&mut self) -> f32 {
        const SPECIAL: [f32; 8] = [
            f32::NAN,
            f32::INFINITY,
            -f32::INFINITY,
            0.0,
            1e30,
            -1e30,
            1e-30,
            6.0,
        ];
        let r = self.next();
        if r.is_multiple_of(5) {
            SPECIAL[(r >> 8) as usize % SPECIAL.len()]
        } else {
            ((r >> 11) as f64 / (1u64 << 53) as f64 * 16.0 - 8.0) as f32
        }
    }
}

#[test]
fn degenerate_portals_never_panic() {
    let camera = look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO);
    let base = scene(
        vec![instance(0, textured_quad(), Mat4::IDENTITY)],
        camera,
        Vec::new(),
    );
    let p = Vec3::new;
    let mut portals = vec![
        // Collinear, coincident, too few, NaN, infinite.
        Portal::new(
            vec![p(0.0, 0.0, 0.0), p(1.0, 1.0, 0.0), p(2.0, 2.0, 0.0)],
            Mat4::IDENTITY,
        ),
        Portal::new(vec![p(1.0, 1.0, 1.0); 4], Mat4::IDENTITY),
        Portal::new(vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)], Mat4::IDENTITY),
        Portal::new(
            vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(f32::NAN, 1.0, 0.0)],
            Mat4::IDENTITY,
        ),
        Portal::new(
            vec![
                p(0.0, 0.0, 0.0),
                p(f32::INFINITY, 0.0, 0.0),
                p(0.0, 1.0, 0.0),
            ],
            Mat4::IDENTITY,
        ),
        // Drawable polygons with a NaN or singular transform.
        Portal::new(
            vec![p(-1.0, -1.0, 0.0), p(1.0, -1.0, 0.0), p(0.0, 1.0, 0.0)],
            Mat4::NAN,
        ),
        Portal::new(
            vec![p(-1.0, -1.0, 0.0), p(1.0, -1.0, 0.0), p(0.0, 1.0, 0.0)],
            Mat4::ZERO,
        ),
        // A transform whose inverse overflows single precision.
        Portal::new(
            vec![p(-1.0, -1.0, -1.0), p(1.0, -1.0, -1.0), p(0.0, 1.0, -1.0)],
            Mat4::from_scale(Vec3::splat(1e30)),
        ),
    ];
    let skipped = portals.len();
    portals.extend([
        // Behind the camera; through the eye (edge-on); crossing the near plane; huge; tiny;
        // a huge scale.
        Portal::mirror(vec![
            p(-1.0, -1.0, 8.0),
            p(1.0, -1.0, 8.0),
            p(0.0, 1.0, 8.0),
        ])
        .expect("ok"),
        Portal::mirror(vec![p(0.0, -1.0, 0.0), p(0.0, -1.0, 9.0), p(0.0, 1.0, 5.0)]).expect("ok"),
        Portal::mirror(vec![
            p(-1.0, -1.0, 3.0),
            p(1.0, -1.0, 7.0),
            p(0.0, 1.0, 5.0),
        ])
        .expect("ok"),
        Portal::mirror(vec![
            p(-1e30, -1e30, -1.0),
            p(1e30, -1e30, -1.0),
            p(0.0, 1e30, -1.0),
        ])
        .expect("ok"),
        Portal::mirror(vec![
            p(0.0, 0.0, 0.0),
            p(1e-30, 0.0, 0.0),
            p(0.0, 1e-30, 0.0),
        ])
        .expect("ok"),
        Portal::new(
            vec![p(-1.0, -1.0, -1.0), p(1.0, -1.0, -1.0), p(0.0, 1.0, -1.0)],
            Mat4::from_scale(Vec3::splat(1e12)),
        ),
    ]);
    let mut with = base.clone();
    with.portals = portals;
    for aa in ANTI_ALIASING {
        let out = render(&with, &options(aa)).expect("renders");
        assert_eq!(out.stats.portals_skipped, skipped, "{aa:?}");
    }
    // Random polygons of 0 to 6 vertices with NaN, infinite, huge and tiny coordinates, and
    // random transforms: every render succeeds.
    let mut mix = Mix(23);
    for round in 0..120 {
        let count = (mix.next() % 7) as usize;
        let polygon = (0..count)
            .map(|_| Vec3::new(mix.coordinate(), mix.coordinate(), mix.coordinate() * 0.1))
            .collect::<Vec<_>>();
        let transform = match mix.next() % 3 {
            0 => Mat4::from_cols_array(&core::array::from_fn(|_| mix.coordinate())),
            _ => Mat4::from_translation(Vec3::new(mix.coordinate(), 0.0, mix.coordinate())),
        };
        let mut with = base.clone();
        with.portals = vec![Portal::new(polygon.clone(), transform)];
        if let Ok(mirror) = Portal::mirror(polygon) {
            with.portals.push(mirror);
        }
        let aa = ANTI_ALIASING[round % ANTI_ALIASING.len()];
        let options = RenderOptions {
            width: 24,
            height: 16,
            ..options(aa)
        };
        render(&with, &options).expect("renders");
    }
}
