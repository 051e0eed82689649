//! Octree rendering: the back-to-front child order (Doctor and Torborg 1981; the Finnish lecture
//! notes *Octreen piirtäminen*, p. 273) needs no depth test; front to back with a coverage quadtree
//! skips hidden subtrees; both match a depth-tested rendering.

use barytex_raster::Framebuffer;
use barytex_raster::TargetLimits;
use barytex_shade::{
    Camera, CoverageQuadtree, Octree, child_order, render_back_to_front, render_depth_tested,
    render_front_to_back,
};
use glam::{UVec3, Vec3, Vec4};

const SIZE: u32 = 128;

fn target() -> Framebuffer {
    Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &TargetLimits::default()).expect("small")
}

fn camera(eye: Vec3) -> Camera {
    Camera::look_at(eye, Vec3::splat(0.5), Vec3::Y, 0.9, 1.0, 0.05, 20.0)
        .or_else(|| Camera::look_at(eye, Vec3::splat(0.5), Vec3::Z, 0.9, 1.0, 0.05, 20.0))
        .expect("regular")
}

/// A sparse pseudo-random 8³ voxel set in the unit cube.
fn sparse() -> Octree {
    Octree::from_cells(3, Vec3::ZERO, 1.0, |c: UVec3| {
        let h = (c.x * 73 + c.y * 151 + c.z * 283 + c.x * c.y * 7) % 5;
        (h < 2).then(|| Vec3::new(c.x as f32 / 7.0, c.y as f32 / 7.0, c.z as f32 / 7.0) * 0.8 + 0.2)
    })
}

/// Pixels whose colours differ by more than 1e-6 and pixels covered in `a`.
fn differing(a: &Framebuffer, b: &Framebuffer) -> (usize, usize) {
    let (mut diff, mut covered) = (0, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let (p, q) = (a.pixel(x, y).expect("in"), b.pixel(x, y).expect("in"));
            if p.w > 0.0 {
                covered += 1;
            }
            if (p - q).abs().max_element() > 1e-6 {
                diff += 1;
            }
        }
    }
    (diff, covered)
}

#[test]
fn child_order_is_a_painters_order() {
    // Child i may occlude child j only if i is on the eye's side of every plane separating them;
    // then i must come after j.
    for near in 0..8 {
        let order = child_order(near);
        let mut seen = [false; 8];
        for &c in &order {
            seen[c] = true;
        }
        assert!(seen.iter().all(|&s| s));
        for (a, &i) in order.iter().enumerate() {
            for &j in &order[a + 1..] {
                let differ = i ^ j;
                // i is on the eye side of every separating plane: i's bits equal near's there.
                let i_nearer_everywhere = (i ^ near) & differ == 0;
                assert!(!i_nearer_everywhere, "near {near}: {i} before {j}");
            }
        }
    }
}

#[test]
fn back_to_front_without_depth_test_matches_the_depth_buffer() {
    let tree = sparse();
    for eye in [
        Vec3::new(2.5, 1.8, 2.2),
        Vec3::new(-1.5, 0.7, 2.0),
        Vec3::new(0.3, -2.0, -1.7),
        Vec3::new(2.2, 2.4, -1.9),
    ] {
        let cam = camera(eye);
        let (mut painter, mut reference, mut front) = (target(), target(), target());
        let n = render_back_to_front(&tree, &cam, &mut painter);
        render_depth_tested(&tree, &cam, &mut reference);
        let stats = render_front_to_back(&tree, &cam, &mut front);
        let (diff, covered) = differing(&painter, &reference);
        let (diff_front, _) = differing(&front, &reference);
        println!(
            "eye {eye}: {n} voxels, {covered} px, back-to-front differs at {diff}, front-to-back at {diff_front}, {stats:?}"
        );
        assert!(covered > 2000);
        // Bit-identical: the painter's order and the coverage mask resolve every pixel as the
        // depth buffer does.
        assert_eq!(diff, 0);
        assert_eq!(diff_front, 0);
        assert!(stats.drawn <= n);
    }
}

#[test]
fn the_wrong_order_is_visibly_wrong() {
    let tree = sparse();
    let cam = camera(Vec3::new(2.5, 1.8, 2.2));
    let mut reference = target();
    render_depth_tested(&tree, &cam, &mut reference);
    // Painting front to back without a depth test: far voxels overwrite near ones.
    let flipped = sparse();
    let mut wrong = target();
    // The back-to-front order for the opposite eye is front to back for this one.
    let opposite = Camera {
        eye: Vec3::ONE - cam.eye,
        ..cam
    };
    render_back_to_front(&flipped, &opposite, &mut wrong);
    let (diff, covered) = differing(&wrong, &reference);
    assert!(diff * 10 > covered, "{diff} of {covered}");
}

#[test]
fn front_to_back_culls_hidden_subtrees() {
    let solid = Octree::from_cells(3, Vec3::ZERO, 1.0, |_| Some(Vec3::new(0.8, 0.6, 0.3)));
    let cam = camera(Vec3::new(2.5, 1.8, 2.2));
    let (mut front, mut reference) = (target(), target());
    let stats = render_front_to_back(&solid, &cam, &mut front);
    render_depth_tested(&solid, &cam, &mut reference);
    let (diff, covered) = differing(&front, &reference);
    println!("solid 8³: {stats:?}, {diff} of {covered} px differ");
    // 512 voxels; only the three visible faces' voxels (≤ 3·64) are needed.
    assert!(stats.drawn < 200, "{stats:?}");
    assert!(stats.culled > 0);
    assert_eq!(diff, 0);
}

#[test]
fn coverage_quadtree() {
    let mut q = CoverageQuadtree::new(10, 6);
    assert!(!q.covered(0, 0, 10, 6));
    assert!(q.covered(3, 3, 3, 5)); // empty
    for y in 2..4 {
        for x in 4..8 {
            q.mark(x, y);
        }
    }
    assert!(q.covered(4, 2, 8, 4));
    assert!(q.covered(5, 2, 7, 3));
    assert!(!q.covered(3, 2, 8, 4));
    // Outside the image counts as covered.
    assert!(q.covered(10, 0, 16, 16));
    for y in 0..6 {
        for x in 0..10 {
            q.mark(x, y);
        }
    }
    assert!(q.covered(0, 0, 100, 100));
}
