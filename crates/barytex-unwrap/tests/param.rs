//! The pipeline: every chart a disk with zero flips, every triangle in exactly one chart, on
//! closed and high-genus meshes and on degenerate input.

mod common;

use barytex_unwrap::{
    Chart, HalfEdgeMesh, Method, NonManifold, ParamOptions, UnwrapError, UnwrapMesh, chart_stats,
    flipped_triangles, parameterize, parameterize_with_report, shapes,
};
use glam::DVec3;
use proptest::prelude::*;

/// The chart's vertices merged where position and uv are bit-equal (undoing the split by
/// original vertex), then its disk check: one component, one boundary loop, χ = 1.
fn is_disk(mesh: &UnwrapMesh, chart: &Chart) -> Result<(), UnwrapError> {
    let mut key_of = std::collections::HashMap::new();
    let merged: Vec<u32> = chart
        .vertices
        .iter()
        .zip(&chart.uvs)
        .map(|(&v, uv)| {
            let p = mesh.positions()[v as usize];
            let key = (
                p.to_array().map(f64::to_bits),
                uv.to_array().map(f64::to_bits),
            );
            let next = key_of.len() as u32;
            *key_of.entry(key).or_insert(next)
        })
        .collect();
    let tris: Vec<[u32; 3]> = chart
        .triangles
        .iter()
        .map(|t| t.map(|v| merged[v as usize]))
        .collect();
    HalfEdgeMesh::from_triangles(key_of.len() as u32, &tris)?
        .check_disk()
        .map(|_| ())
}

/// Every triangle once, zero flips, every non-degenerate chart a disk, chart triangles matching
/// the mesh's (same vertices, same corner order).
fn check_atlas(mesh: &UnwrapMesh, charts: &[Chart]) {
    let mut seen = vec![0u32; mesh.triangles().len()];
    for (c, chart) in charts.iter().enumerate() {
        assert_eq!(flipped_triangles(chart), 0, "chart {c}");
        assert_eq!(chart.vertices.len(), chart.uvs.len());
        for (j, &f) in chart.faces.iter().enumerate() {
            seen[f as usize] += 1;
            let mapped = chart.triangles[j].map(|v| chart.vertices[v as usize]);
            assert_eq!(
                mapped,
                mesh.triangles()[f as usize],
                "chart {c} triangle {j}"
            );
        }
        if chart.faces.len() > 1 {
            is_disk(mesh, chart).unwrap_or_else(|e| panic!("chart {c}: {e}"));
        }
    }
    assert!(
        seen.iter().all(|&s| s == 1),
        "every triangle in exactly one chart"
    );
}

#[test]
fn closed_meshes_become_disks_without_flips() {
    for (name, mesh) in [
        ("sphere", shapes::sphere(16, 32)),
        ("torus", shapes::torus(1.0, 0.3, 32, 16)),
        ("cube", shapes::cube(4)),
    ] {
        for method in [
            Method::LscmArap,
            Method::Lscm,
            Method::MeanValue,
            Method::Tutte,
            Method::Harmonic,
        ] {
            let options = ParamOptions {
                method,
                ..ParamOptions::default()
            };
            let p = parameterize_with_report(&mesh, &options).expect("unwrapped");
            check_atlas(&mesh, &p.charts);
            assert!(p.charts.len() >= 2, "{name}: a closed surface needs a cut");
            // Surface units: every chart's uv area is its surface area.
            for c in &p.charts {
                let s = chart_stats(&mesh, c);
                let rel = (s.uv_area / s.surface_area - 1.0).abs();
                assert!(
                    rel < 1e-9,
                    "{name} {method:?}: uv area {} vs {}",
                    s.uv_area,
                    s.surface_area
                );
            }
            if matches!(method, Method::Lscm | Method::LscmArap) {
                for c in &p.charts {
                    let s = chart_stats(&mesh, c);
                    if c.faces.len() >= 8 {
                        assert!(
                            s.angle_distortion_mean <= options.max_angle_distortion,
                            "{name} {method:?}: {s:?}"
                        );
                        assert!(
                            s.area_distortion_mean <= options.max_area_distortion,
                            "{name} {method:?}: {s:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_cube_splits_along_its_creases() {
    let mesh = shapes::cube(3);
    let charts = parameterize(&mesh, &ParamOptions::default()).expect("unwrapped");
    assert_eq!(charts.len(), 6);
    for c in &charts {
        let s = chart_stats(&mesh, c);
        assert!(
            s.angle_distortion_max < 1.0 + 1e-9 && s.area_distortion_max < 1.0 + 1e-9,
            "{s:?}"
        );
    }
}

#[test]
fn seams_given_by_the_caller_are_cut() {
    // A flat grid is one chart; a seam across its middle row splits it.
    let g = shapes::grid(4, 4, |_, _| 0.0);
    assert_eq!(
        parameterize(&g, &ParamOptions::default())
            .expect("ok")
            .len(),
        1
    );
    let seams: Vec<[u32; 2]> = (0..4).map(|i| [10 + i, 10 + i + 1]).collect();
    let options = ParamOptions {
        seams,
        ..ParamOptions::default()
    };
    let charts = parameterize(&g, &options).expect("ok");
    assert_eq!(charts.len(), 2);
    check_atlas(&g, &charts);
}

#[test]
fn degenerate_triangles_get_charts_of_their_own() {
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::Y,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::ONE,
    ];
    // A good triangle, a repeated index, a zero-area (collinear) one, an all-equal one.
    let t = vec![[0, 1, 2], [0, 0, 1], [0, 1, 3], [4, 4, 4]];
    let mesh = UnwrapMesh::new(p, t).expect("valid");
    let p = parameterize_with_report(&mesh, &ParamOptions::default()).expect("ok");
    check_atlas(&mesh, &p.charts);
    assert_eq!(p.reports.iter().filter(|r| r.degenerate).count(), 3);
}

#[test]
fn duplicate_vertices_weld_or_stay_apart() {
    // Two triangles of a square with their own copies of the diagonal's vertices.
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::ONE.with_z(0.0),
        DVec3::ZERO,
        DVec3::ONE.with_z(0.0),
        DVec3::Y,
    ];
    let mesh = UnwrapMesh::new(p, vec![[0, 1, 2], [3, 4, 5]]).expect("valid");
    let welded = parameterize(&mesh, &ParamOptions::default()).expect("ok");
    assert_eq!(welded.len(), 1);
    // The chart keeps the original vertex indices (4 + the 2 duplicates = 6 chart vertices).
    assert_eq!(welded[0].vertices.len(), 6);
    check_atlas(&mesh, &welded);
    let apart = parameterize(
        &mesh,
        &ParamOptions {
            weld: false,
            ..ParamOptions::default()
        },
    )
    .expect("ok");
    assert_eq!(apart.len(), 2);
    check_atlas(&mesh, &apart);
}

#[test]
fn non_manifold_edges_are_cut_or_rejected() {
    // Three triangles on the edge (0, 1), and a bowtie at vertex 0.
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::Y,
        DVec3::new(0.5, -1.0, 0.0),
        DVec3::new(0.5, 0.0, 1.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(-1.0, -1.0, 0.0),
    ];
    let t = vec![[0, 1, 2], [1, 0, 3], [1, 0, 4], [0, 5, 6]];
    let mesh = UnwrapMesh::new(p, t).expect("valid");
    let p = parameterize_with_report(&mesh, &ParamOptions::default()).expect("cut");
    check_atlas(&mesh, &p.charts);
    assert!(p.non_manifold_half_edges >= 3);
    let strict = ParamOptions {
        non_manifold: NonManifold::Reject,
        ..ParamOptions::default()
    };
    let e = parameterize(&mesh, &strict);
    assert!(
        matches!(
            e,
            Err(UnwrapError::NonManifoldEdge { a: 1, b: 0 }
                | UnwrapError::NonManifoldEdge { a: 0, b: 1 })
        ),
        "{e:?}"
    );
}

#[test]
fn options_out_of_range_are_errors() {
    let g = shapes::grid(2, 2, |_, _| 0.0);
    for options in [
        ParamOptions {
            cone_degrees: f64::NAN,
            ..ParamOptions::default()
        },
        ParamOptions {
            cone_degrees: 0.0,
            ..ParamOptions::default()
        },
        ParamOptions {
            max_angle_distortion: 0.5,
            ..ParamOptions::default()
        },
        ParamOptions {
            max_area_distortion: f64::NAN,
            ..ParamOptions::default()
        },
        ParamOptions {
            seams: vec![[0, 99]],
            ..ParamOptions::default()
        },
    ] {
        assert!(parameterize(&g, &options).is_err(), "{options:?}");
    }
}

#[test]
fn huge_and_tiny_coordinates_unwrap() {
    for scale in [1e-300, 1e-150, 1e150, 1e300] {
        let s = shapes::sphere(6, 8);
        let p: Vec<DVec3> = s.positions().iter().map(|&p| p * scale).collect();
        let mesh = UnwrapMesh::new(p, s.triangles().to_vec()).expect("finite");
        let charts = parameterize(&mesh, &ParamOptions::default()).expect("ok");
        check_atlas(&mesh, &charts);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random triangle soups over few vertices (repeated indices, duplicates, non-manifold edges
    /// and vertices, zero areas): never a panic, never a flip, every triangle once.
    #[test]
    fn random_soups_never_flip(
        points in prop::collection::vec(prop::array::uniform3(-4i8..4), 3..24),
        tris in prop::collection::vec(prop::array::uniform3(0u32..24), 1..64),
        method in prop::sample::select(vec![Method::LscmArap, Method::Lscm, Method::MeanValue, Method::Tutte, Method::Harmonic]),
    ) {
        let n = points.len() as u32;
        let p: Vec<DVec3> = points.iter().map(|q| DVec3::new(q[0].into(), q[1].into(), q[2].into())).collect();
        let t: Vec<[u32; 3]> = tris.iter().map(|t| t.map(|v| v % n)).collect();
        let mesh = UnwrapMesh::new(p, t).expect("valid");
        let charts = parameterize(&mesh, &ParamOptions { method, ..ParamOptions::default() }).expect("cut mode never fails");
        check_atlas(&mesh, &charts);
    }
}
