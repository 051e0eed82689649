//! Displacement mapping: exact shared edges, seams, silhouettes.

mod common;

use std::collections::HashSet;

use barytex_shade::{ReferenceShader, Seams, displace, mesh_vertices};
use common::{render, scene};
use glam::{Vec2, Vec3};

fn distinct_positions(mesh: &barytex_uv::TriMesh) -> usize {
    mesh.positions
        .iter()
        .map(|p| (*p + Vec3::ZERO).to_array().map(f32::to_bits))
        .collect::<HashSet<_>>()
        .len()
}

#[test]
fn zero_height_keeps_the_surface_and_shares_edge_points_exactly() {
    let plane = barytex_uv::mesh::plane(2, 2).expect("valid");
    let flat = displace(&plane, &|_: Vec2| 0.0, 1.0, 1, Seams::Ignore);
    assert_eq!(flat.positions.len(), 3 * plane.indices.len());
    assert!(flat.positions.iter().all(|p| p.y == 0.0));
    // Level 3 on a 2 × 2 grid: the refined grid has 7 × 7 points; every point on a shared edge
    // has the same bits in both triangles.
    let fine = displace(&plane, &|_: Vec2| 0.0, 1.0, 3, Seams::Ignore);
    assert_eq!(fine.indices.len(), 9 * plane.indices.len());
    assert_eq!(distinct_positions(&fine), 49);
    assert!(fine.normals.iter().all(|n| (*n - Vec3::Y).length() < 1e-6));
}

/// Pairs of seam copies (u = 0 and u = 1 at the same v) and their largest gap.
fn seam_gap(mesh: &barytex_uv::TriMesh) -> (usize, f32) {
    let mut pairs = 0;
    let mut gap = 0.0f32;
    for (i, a) in mesh.uvs.iter().enumerate() {
        if a.x != 0.0 {
            continue;
        }
        for (j, b) in mesh.uvs.iter().enumerate() {
            if b.x == 1.0 && b.y == a.y {
                pairs += 1;
                gap = gap.max(mesh.positions[i].distance(mesh.positions[j]));
            }
        }
    }
    (pairs, gap)
}

#[test]
fn welding_closes_the_seam_crack() {
    let sphere = barytex_uv::mesh::sphere(16, 8).expect("valid");
    // A height that is not periodic in u: 0 on one side of the seam, 0.2 on the other.
    let ramp = |uv: Vec2| uv.x;
    let naive = displace(&sphere, &ramp, 0.2, 2, Seams::Ignore);
    let welded = displace(&sphere, &ramp, 0.2, 2, Seams::Weld);
    let (pairs, crack) = seam_gap(&naive);
    assert!(pairs > 10);
    assert!(crack > 0.05, "{crack}");
    let (_, closed) = seam_gap(&welded);
    assert_eq!(closed, 0.0);
    // Welded copies share one normal too.
    assert!(welded.validate().is_ok(), "{:?}", welded.validate());
}

#[test]
fn displacement_changes_the_silhouette() {
    let scene = scene();
    let sphere = barytex_uv::mesh::sphere(24, 12).expect("valid");
    let bumpy = displace(
        &sphere,
        &|uv: Vec2| (uv.x * 48.0).sin().max(0.0),
        0.15,
        4,
        Seams::Weld,
    );
    let coverage = |mesh: &barytex_uv::TriMesh| {
        let (v, i) = mesh_vertices(mesh);
        let fb = render(
            &ReferenceShader {
                scene: &scene,
                normal: |p: Vec3| p.normalize_or_zero(),
            },
            &v,
            &i,
        );
        (0..common::SIZE * common::SIZE)
            .filter(|k| fb.pixel(k % common::SIZE, k / common::SIZE).expect("in").w > 0.0)
            .count()
    };
    let (before, after) = (coverage(&sphere), coverage(&bumpy));
    assert!(after > before + 200, "{before} {after}");
}

#[test]
fn bad_input_never_panics() {
    let mut sphere = barytex_uv::mesh::sphere(6, 3).expect("valid");
    sphere.indices.push([0, 1, 10_000]);
    sphere.normals.truncate(3);
    let out = displace(&sphere, &|_: Vec2| f32::NAN, 1.0, 0, Seams::Weld);
    assert!(out.positions.iter().all(|p| p.is_finite()));
    let out = displace(&sphere, &|_: Vec2| 1.0, f32::INFINITY, 200, Seams::Ignore);
    assert!(out.positions.iter().all(|p| p.is_finite()));
}
