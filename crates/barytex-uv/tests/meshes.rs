//! Parametric meshes: valid attributes, outward counter-clockwise winding, duplicated seams (no
//! triangle spans more than half the texture), closed surfaces watertight after welding equal
//! positions, tangents along `∂p/∂u` with glTF handedness, and refusal of zero or huge
//! resolutions before allocating.

use std::collections::HashMap;

use barytex_uv::UvError;
use barytex_uv::mesh::{self, MAX_VERTICES, MeshDefect, SphereUv, TriMesh};
use glam::{Vec2, Vec3};
use proptest::prelude::*;

/// Every generator at a resolution, with whether its surface is closed.
fn all_meshes(a: u32, b: u32) -> Vec<(String, TriMesh, bool)> {
    let build = |name: &str, mesh: Result<TriMesh, UvError>, closed: bool| {
        (
            format!("{name}({a}, {b})"),
            mesh.expect("a valid resolution"),
            closed,
        )
    };
    vec![
        build("plane", mesh::plane(a, b), false),
        build("cube", mesh::cube(a), true),
        build("cylinder", mesh::cylinder(a.max(3), b, false), false),
        build("capped cylinder", mesh::cylinder(a.max(6), b, true), true),
        build("sphere", mesh::sphere(a.max(3), b.max(2)), true),
        build(
            "equal-area sphere",
            mesh::sphere_with(a.max(3), b.max(2), SphereUv::EqualArea),
            true,
        ),
        build("torus", mesh::torus(a.max(3), b.max(3), 1.0, 0.4), true),
    ]
}

fn corners<T: Copy>(values: &[T], triangle: [u32; 3]) -> [T; 3] {
    triangle.map(|i| values[i as usize])
}

/// `∂p/∂u` and `∂p/∂v` of the triangle's affine uv → position map.
fn triangle_derivatives(p: [Vec3; 3], uv: [Vec2; 3]) -> Option<(Vec3, Vec3)> {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let (d1, d2) = (uv[1] - uv[0], uv[2] - uv[0]);
    let det = d1.x * d2.y - d2.x * d1.y;
    if det.abs() < 1e-12 {
        return None;
    }
    Some(((e1 * d2.y - e2 * d1.y) / det, (e2 * d1.x - e1 * d2.x) / det))
}

/// Positions as exact bit patterns (generators make shared positions bit-identical).
fn key(p: Vec3) -> [u32; 3] {
    (p + Vec3::ZERO).to_array().map(f32::to_bits)
}

#[test]
fn every_mesh_validates() {
    for (a, b) in [(1, 1), (3, 2), (4, 3), (17, 9), (64, 32)] {
        for (name, mesh, _) in all_meshes(a, b) {
            assert_eq!(mesh.validate(), Ok(()), "{name}");
            assert!(!mesh.indices.is_empty(), "{name}");
        }
    }
}

#[test]
fn winding_is_counter_clockwise_outward() {
    for (a, b) in [(1, 1), (3, 2), (16, 8), (33, 17)] {
        for (name, mesh, _) in all_meshes(a, b) {
            for &triangle in &mesh.indices {
                let p = corners(&mesh.positions, triangle);
                let face = (p[1] - p[0]).cross(p[2] - p[0]);
                assert!(face.length() > 0.0, "{name}: degenerate {triangle:?}");
                for n in corners(&mesh.normals, triangle) {
                    assert!(face.dot(n) > 0.0, "{name}: {triangle:?} faces inward");
                }
            }
        }
    }
}

#[test]
fn no_triangle_spans_half_the_texture() {
    // From 6 segments on (a cap's fan triangle spans the chord sin(π/segments) of its disc of
    // radius 1/2, which is > 1/2 below 6).
    for (a, b) in [(2, 2), (6, 2), (8, 4), (31, 15)] {
        for (name, mesh, _) in all_meshes(a, b) {
            for &triangle in &mesh.indices {
                let uv = corners(&mesh.uvs, triangle);
                for (i, j) in [(0, 1), (1, 2), (2, 0)] {
                    let d = (uv[i] - uv[j]).abs();
                    assert!(d.x <= 0.5 && d.y <= 0.5, "{name}: {triangle:?} spans {d}");
                }
                for c in uv {
                    assert!(
                        c.cmpge(Vec2::ZERO).all() && c.cmple(Vec2::ONE).all(),
                        "{name}"
                    );
                }
            }
        }
    }
}

#[test]
fn closed_surfaces_are_watertight_after_welding() {
    for (a, b) in [(1, 1), (3, 2), (5, 3), (16, 8), (40, 21)] {
        for (name, mesh, closed) in all_meshes(a, b) {
            let mut welded = HashMap::new();
            let ids: Vec<usize> = mesh
                .positions
                .iter()
                .map(|&p| {
                    let next = welded.len();
                    *welded.entry(key(p)).or_insert(next)
                })
                .collect();
            let mut edges: HashMap<(usize, usize), (u32, u32)> = HashMap::new();
            for &[a, b, c] in &mesh.indices {
                for (from, to) in [(a, b), (b, c), (c, a)] {
                    let (from, to) = (ids[from as usize], ids[to as usize]);
                    // Counted per direction: a closed, consistently wound surface uses each
                    // undirected edge once in each direction.
                    let entry = edges.entry((from.min(to), from.max(to))).or_default();
                    if from < to {
                        entry.0 += 1;
                    } else {
                        entry.1 += 1;
                    }
                }
            }
            let open = edges.values().filter(|&&uses| uses != (1, 1)).count();
            if closed {
                assert_eq!(
                    open, 0,
                    "{name}: {open} edges not shared by exactly 2 triangles"
                );
            } else {
                assert!(open > 0, "{name} should have a boundary");
                assert!(
                    edges.values().all(|&(x, y)| x <= 1 && y <= 1),
                    "{name}: an edge used twice in the same direction"
                );
            }
        }
    }
}

/// The largest angle between a vertex tangent and its triangle's `∂p/∂u`, for the resolutions
/// tested, is below this multiple of the grid's angular step `max(2π/a, π/b)` (measured: 0.500,
/// at the sphere's poles, where the pole vertex sits half a column from the rim's corners).
const TANGENT_ANGLE_PER_STEP: f32 = 0.51;

#[test]
fn tangents_follow_du_with_gltf_handedness() {
    for (a, b) in [(8, 4), (16, 8), (48, 24), (96, 64)] {
        let step = (std::f32::consts::TAU / a as f32).max(std::f32::consts::PI / b as f32);
        let mut worst = 0.0_f32;
        for (name, mesh, _) in all_meshes(a, b) {
            for &triangle in &mesh.indices {
                let (dpdu, dpdv) = triangle_derivatives(
                    corners(&mesh.positions, triangle),
                    corners(&mesh.uvs, triangle),
                )
                .expect("non-degenerate uv triangle");
                for i in triangle {
                    let (n, t) = (mesh.normals[i as usize], mesh.tangents[i as usize]);
                    let angle = t.truncate().angle_between(dpdu);
                    worst = worst.max(angle / step);
                    assert!(
                        angle <= TANGENT_ANGLE_PER_STEP * step,
                        "{name}: vertex {i} tangent {t} vs ∂p/∂u {dpdu}: {angle} rad"
                    );
                    // Every generated mapping is unmirrored.
                    assert_eq!(t.w, 1.0, "{name}: vertex {i}");
                    // glTF: the bitangent w·(n × t) points up the image (decreasing v).
                    assert!(
                        t.w * n.cross(t.truncate()).dot(dpdv) < 0.0,
                        "{name}: vertex {i}"
                    );
                }
            }
        }
        println!("{a}×{b}: worst tangent angle {worst:.3} grid steps");
    }
}

#[test]
fn seams_are_duplicated_columns() {
    let sphere = mesh::sphere(12, 6).expect("valid");
    let seam: Vec<_> = (0..sphere.positions.len())
        .filter(|&i| sphere.uvs[i].x == 0.0 && sphere.positions[i].y.abs() < 1.0)
        .collect();
    assert_eq!(seam.len(), 5);
    for i in seam {
        let twins: Vec<_> = (0..sphere.positions.len())
            .filter(|&j| key(sphere.positions[j]) == key(sphere.positions[i]))
            .collect();
        assert_eq!(twins.len(), 2, "vertex {i}");
        assert!(twins.iter().any(|&j| sphere.uvs[j].x == 1.0));
    }
}

#[test]
fn zero_and_tiny_resolutions_are_refused() {
    assert!(matches!(mesh::plane(0, 3), Err(UvError::OutOfRange { .. })));
    assert!(matches!(mesh::plane(3, 0), Err(UvError::OutOfRange { .. })));
    assert!(matches!(mesh::cube(0), Err(UvError::OutOfRange { .. })));
    assert!(matches!(
        mesh::cylinder(2, 1, true),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        mesh::cylinder(3, 0, true),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        mesh::sphere(2, 8),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        mesh::sphere(8, 1),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        mesh::torus(8, 2, 1.0, 0.5),
        Err(UvError::OutOfRange { .. })
    ));
}

#[test]
fn bad_torus_radii_are_refused() {
    for (major, minor) in [(1.0, 0.0), (1.0, -0.5), (0.5, 0.5), (0.5, 1.0)] {
        assert!(matches!(
            mesh::torus(8, 8, major, minor),
            Err(UvError::OutOfRange { .. })
        ));
    }
    for (major, minor) in [(f32::NAN, 0.5), (1.0, f32::INFINITY), (f32::INFINITY, 0.5)] {
        assert!(matches!(
            mesh::torus(8, 8, major, minor),
            Err(UvError::NonFinite { .. })
        ));
    }
}

#[test]
fn huge_resolutions_are_refused_before_allocating() {
    let too_large = |r: Result<TriMesh, UvError>| matches!(r, Err(UvError::TooLarge { limit, .. }) if limit == MAX_VERTICES);
    assert!(too_large(mesh::plane(u32::MAX, u32::MAX)));
    assert!(too_large(mesh::plane(1 << 12, 1 << 12)));
    assert!(too_large(mesh::cube(u32::MAX)));
    assert!(too_large(mesh::cube(1000)));
    assert!(too_large(mesh::cylinder(u32::MAX, 1, true)));
    assert!(too_large(mesh::sphere(u32::MAX, u32::MAX)));
    assert!(too_large(mesh::torus(1 << 16, 1 << 16, 2.0, 1.0)));
    // Exactly at the limit is built: (2047 + 1)(2047 + 1) = 2^22.
    assert_eq!(
        mesh::plane(2047, 2047)
            .expect("at the limit")
            .positions
            .len() as u64,
        MAX_VERTICES
    );
}

#[test]
fn validate_reports_each_defect() {
    let good = mesh::sphere(6, 3).expect("valid");
    let mut m = good.clone();
    m.uvs.pop();
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::LengthMismatch { what: "uvs", .. })
    ));
    let mut m = good.clone();
    m.positions[2].x = f32::NAN;
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::NonFinite {
            vertex: 2,
            what: "position"
        })
    ));
    let mut m = good.clone();
    m.normals[1] *= 2.0;
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::NotUnit {
            vertex: 1,
            what: "normal"
        })
    ));
    let mut m = good.clone();
    m.tangents[3].w = 0.5;
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::NotUnit {
            vertex: 3,
            what: "handedness"
        })
    ));
    let mut m = good.clone();
    m.tangents[4] = m.normals[4].extend(1.0);
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::TangentNotOrthogonal { vertex: 4 })
    ));
    let mut m = good;
    m.indices[0][1] = u32::MAX;
    assert!(matches!(
        m.validate(),
        Err(MeshDefect::IndexOutOfRange {
            triangle: 0,
            index: u32::MAX
        })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any resolution within a small range builds a valid mesh of the predicted size.
    #[test]
    fn any_small_resolution_builds(a in 3_u32..40, b in 3_u32..40, radius in 0.01_f32..0.99) {
        let torus = mesh::torus(a, b, 1.0, radius).expect("valid");
        prop_assert_eq!(torus.validate(), Ok(()));
        prop_assert_eq!(torus.positions.len() as u32, (a + 1) * (b + 1));
        prop_assert_eq!(torus.indices.len() as u32, 2 * a * b);
        let sphere = mesh::sphere(a, b).expect("valid");
        prop_assert_eq!(sphere.validate(), Ok(()));
        prop_assert_eq!(sphere.indices.len() as u32, 2 * a * (b - 1));
        let cylinder = mesh::cylinder(a, b, true).expect("valid");
        prop_assert_eq!(cylinder.validate(), Ok(()));
        prop_assert_eq!(cylinder.indices.len() as u32, 2 * a * b + 2 * a);
    }
}
