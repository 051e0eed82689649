//! The atlas half: exact overlap test against brute force, packing invariants, the whole
//! pipeline on generated meshes (flat, closed, with degenerate triangles).

use barytex_unwrap::overlap::{find_overlaps, triangles_overlap};
use barytex_unwrap::pack::{PackError, PackOptions, pack};
use barytex_unwrap::{Chart, ChartMethod, UnwrapMesh, UnwrapOptions, check_atlas, unwrap};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

/// A torus of `n × m` quads, each split in two.
fn torus(n: u32, m: u32) -> UnwrapMesh {
    let mut p = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (u, v) = (
                std::f64::consts::TAU * f64::from(i) / f64::from(n),
                std::f64::consts::TAU * f64::from(j) / f64::from(m),
            );
            let r = 1.0 + 0.4 * v.cos();
            p.push(DVec3::new(r * u.cos(), r * u.sin(), 0.4 * v.sin()));
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    UnwrapMesh::new(p, t).expect("valid torus")
}

#[test]
fn every_method_gives_a_valid_atlas_on_a_torus() {
    let mesh = torus(24, 12);
    for method in [
        ChartMethod::Parameterize,
        ChartMethod::PerTriangle,
        ChartMethod::TrianglePairs,
    ] {
        let options = UnwrapOptions {
            charts: method,
            pack: PackOptions {
                size: 512,
                padding: 2,
                rotate: true,
            },
            ..UnwrapOptions::default()
        };
        let atlas = unwrap(&mesh, &options).expect("unwraps");
        assert!(atlas.check.is_valid(), "{method:?}: {:?}", atlas.check);
        let faces: usize = atlas.charts.iter().map(|c| c.faces.len()).sum();
        assert_eq!(faces, mesh.triangles().len());
        assert!(atlas.pack.efficiency > 0.2, "{method:?}: {:?}", atlas.pack);
        assert!(atlas.pack.efficiency <= 1.0);
        // Packing is a similarity per chart with one scale for all: a flat chart's triangles
        // keep their surface areas times the density squared; a parameterized chart's total uv
        // area is its surface area (parameterize's scaling), times the same.
        let scale = atlas.pack.texels_per_unit / 512.0;
        for chart in &atlas.charts {
            let (mut sum3, mut sum2) = (0.0, 0.0);
            for (j, t) in chart.triangles.iter().enumerate() {
                let f = mesh.triangles()[chart.faces[j] as usize];
                let q = f.map(|i| mesh.positions()[i as usize]);
                let area3 = (q[1] - q[0]).cross(q[2] - q[0]).length() / 2.0;
                let u = t.map(|i| chart.uvs[i as usize]);
                let area2 = (u[1] - u[0]).perp_dot(u[2] - u[0]) / 2.0;
                let expected = area3 * scale * scale;
                if method != ChartMethod::Parameterize {
                    assert!((area2 - expected).abs() < 1e-5 * expected + 1e-12);
                }
                sum3 += expected;
                sum2 += area2;
            }
            assert!(
                (sum2 - sum3).abs() < 1e-4 * sum3,
                "{method:?}: {sum2} vs {sum3}"
            );
        }
    }
}

#[test]
fn pairs_halve_the_charts_of_a_quad_mesh() {
    let mesh = torus(16, 8);
    let options = UnwrapOptions {
        charts: ChartMethod::TrianglePairs,
        ..UnwrapOptions::default()
    };
    let pairs = unwrap(&mesh, &options).expect("unwraps");
    assert_eq!(pairs.charts.len(), mesh.triangles().len() / 2);
}

#[test]
fn padding_holds_in_texels() {
    let mesh = torus(12, 6);
    let size = 256;
    let padding = 3;
    let options = UnwrapOptions {
        charts: ChartMethod::PerTriangle,
        pack: PackOptions {
            size,
            padding,
            rotate: true,
        },
        ..UnwrapOptions::default()
    };
    let atlas = unwrap(&mesh, &options).expect("unwraps");
    let texel = 1.0 / f64::from(size);
    let boxes: Vec<(DVec2, DVec2)> = atlas
        .charts
        .iter()
        .map(|c| {
            c.uvs.iter().fold(
                (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
                |(lo, hi), &p| (lo.min(p), hi.max(p)),
            )
        })
        .collect();
    let gap = f64::from(padding) * texel;
    for (lo, hi) in &boxes {
        assert!(lo.cmpge(DVec2::splat(gap)).all() && hi.cmple(DVec2::splat(1.0 - gap)).all());
    }
    // Any two triangles of different charts are at least `padding` texels apart (their boxes
    // need not be: outline and raster packers nest charts into each other's corners).
    let triangles: Vec<Vec<[DVec2; 3]>> = atlas
        .charts
        .iter()
        .map(|c| {
            c.triangles
                .iter()
                .map(|t| t.map(|i| c.uvs[i as usize]))
                .collect()
        })
        .collect();
    for i in 0..triangles.len() {
        for j in i + 1..triangles.len() {
            for s in &triangles[i] {
                for t in &triangles[j] {
                    let d = triangle_distance(s, t);
                    assert!(d >= gap, "charts {i} and {j}: {} texels apart", d / texel);
                }
            }
        }
    }
}

/// The distance between two triangles that do not overlap: the least distance between their
/// edges (0 when edges cross).
fn triangle_distance(s: &[DVec2; 3], t: &[DVec2; 3]) -> f64 {
    assert!(!barytex_unwrap::overlap::triangles_overlap(*s, *t));
    let point = |p: DVec2, a: DVec2, b: DVec2| {
        let l = (b - a).length_squared();
        let u = if l > 0.0 {
            ((p - a).dot(b - a) / l).clamp(0.0, 1.0)
        } else {
            0.0
        };
        p.distance(a + (b - a) * u)
    };
    let side = |a: DVec2, b: DVec2, p: DVec2| barytex_unwrap::overlap::orient(a, b, p).signum();
    let mut closest = f64::INFINITY;
    for k in 0..3 {
        let (a, b) = (s[k], s[(k + 1) % 3]);
        for l in 0..3 {
            let (c, d) = (t[l], t[(l + 1) % 3]);
            if side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0 {
                return 0.0;
            }
            closest = closest
                .min(point(a, c, d))
                .min(point(b, c, d))
                .min(point(c, a, b))
                .min(point(d, a, b));
        }
    }
    closest
}

#[test]
fn too_many_charts_is_an_error() {
    let mesh = torus(40, 20);
    let options = UnwrapOptions {
        charts: ChartMethod::PerTriangle,
        pack: PackOptions {
            size: 64,
            padding: 4,
            rotate: true,
        },
        ..UnwrapOptions::default()
    };
    assert!(matches!(
        unwrap(&mesh, &options),
        Err(barytex_unwrap::UnwrapError::Pack(
            PackError::TooManyCharts { .. }
        ))
    ));
}

#[test]
fn bad_options_and_non_finite_uvs_are_errors() {
    let mut charts = vec![Chart {
        faces: vec![0],
        vertices: vec![0, 1, 2],
        triangles: vec![[0, 1, 2]],
        uvs: vec![DVec2::ZERO, DVec2::X, DVec2::new(f64::NAN, 1.0)],
    }];
    assert!(matches!(
        pack(&mut charts, &PackOptions::default()),
        Err(PackError::NonFinite { chart: 0 })
    ));
    for bad in [
        PackOptions {
            size: 0,
            ..PackOptions::default()
        },
        PackOptions {
            size: 1 << 16,
            ..PackOptions::default()
        },
        PackOptions {
            size: 16,
            padding: 5,
            rotate: false,
        },
    ] {
        assert!(matches!(
            pack(&mut charts, &bad),
            Err(PackError::Options(_))
        ));
    }
}

#[test]
fn degenerate_triangles_get_positive_charts() {
    // A zero-area triangle, a repeated index, a sliver and a normal triangle.
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(0.5, 1e-12, 0.0),
        DVec3::Y,
    ];
    let t = vec![[0, 1, 2], [0, 0, 1], [0, 1, 3], [0, 1, 4]];
    let mesh = UnwrapMesh::new(p, t).expect("valid");
    for method in [
        ChartMethod::Parameterize,
        ChartMethod::PerTriangle,
        ChartMethod::TrianglePairs,
    ] {
        let options = UnwrapOptions {
            charts: method,
            ..UnwrapOptions::default()
        };
        let atlas = unwrap(&mesh, &options).expect("unwraps");
        assert!(atlas.check.is_valid(), "{method:?}: {:?}", atlas.check);
    }
}

/// All pairs, tested one by one.
fn brute_force(uvs: &[DVec2], tris: &[[u32; 3]]) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for i in 0..tris.len() {
        for j in i + 1..tris.len() {
            let a = tris[i].map(|k| uvs[k as usize]);
            let b = tris[j].map(|k| uvs[k as usize]);
            if triangles_overlap(a, b) {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

fn point() -> impl Strategy<Value = DVec2> {
    // Small integer grids make touching, shared and collinear corners common.
    (0..12i32, 0..12i32).prop_map(|(x, y)| DVec2::new(f64::from(x) / 4.0, f64::from(y) / 4.0))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn the_grid_finds_what_brute_force_finds(
        uvs in proptest::collection::vec(point(), 3..40),
        raw in proptest::collection::vec((0u32..1000, 0u32..1000, 0u32..1000), 1..30),
        charts in 1u32..4,
    ) {
        let n = uvs.len() as u32;
        let tris: Vec<[u32; 3]> = raw.iter().map(|&(a, b, c)| [a % n, b % n, c % n]).collect();
        let chart_of: Vec<u32> = (0..tris.len() as u32).map(|k| k % charts).collect();
        let report = find_overlaps(&uvs, &tris, &chart_of);
        let mut found: Vec<(u32, u32)> =
            report.between_charts.iter().chain(&report.within_charts).copied().collect();
        found.sort_unstable();
        prop_assert_eq!(found, brute_force(&uvs, &tris));
        for &(i, j) in &report.within_charts {
            prop_assert_eq!(chart_of[i as usize], chart_of[j as usize]);
        }
    }

    #[test]
    fn overlap_is_symmetric_and_order_free(
        a in proptest::array::uniform3(point()),
        b in proptest::array::uniform3(point()),
    ) {
        let o = triangles_overlap(a, b);
        prop_assert_eq!(o, triangles_overlap(b, a));
        prop_assert_eq!(o, triangles_overlap([a[0], a[2], a[1]], [b[1], b[2], b[0]]));
        // A non-degenerate triangle overlaps itself; far apart, nothing overlaps.
        let area = (a[1] - a[0]).perp_dot(a[2] - a[0]);
        prop_assert_eq!(triangles_overlap(a, a), area != 0.0);
        prop_assert!(!triangles_overlap(a, b.map(|p| p + DVec2::new(10.0, 0.0))));
    }

    #[test]
    fn random_soups_unwrap_validly_or_say_why(
        pts in proptest::collection::vec((-4i32..4, -4i32..4, -4i32..4), 3..20),
        raw in proptest::collection::vec((0u32..100, 0u32..100, 0u32..100), 1..40),
        method in 0u8..3,
        size in 16u32..600,
        padding in 0u32..4,
    ) {
        let p: Vec<DVec3> = pts.iter().map(|&(x, y, z)| DVec3::new(x.into(), y.into(), z.into())).collect();
        let n = p.len() as u32;
        let t: Vec<[u32; 3]> = raw.iter().map(|&(a, b, c)| [a % n, b % n, c % n]).collect();
        let mesh = UnwrapMesh::new(p, t).expect("indices in range");
        let charts = [ChartMethod::Parameterize, ChartMethod::PerTriangle, ChartMethod::TrianglePairs][usize::from(method)];
        let options = UnwrapOptions {
            charts,
            pack: PackOptions { size, padding, rotate: true },
            ..UnwrapOptions::default()
        };
        match unwrap(&mesh, &options) {
            Ok(atlas) => {
                prop_assert!(atlas.check.is_valid(), "{:?}", atlas.check);
                prop_assert_eq!(check_atlas(&atlas.charts), atlas.check);
            }
            Err(e) => prop_assert!(matches!(e, barytex_unwrap::UnwrapError::Pack(_)), "{e}"),
        }
    }
}

#[cfg(feature = "parallel")]
#[test]
fn charts_do_not_depend_on_the_number_of_threads() {
    let mesh = torus(32, 16);
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool")
            .install(|| {
                barytex_unwrap::parameterize(&mesh, &barytex_unwrap::ParamOptions::default())
            })
            .expect("unwrapped")
    };
    let one = run(1);
    assert!(one.len() > 1, "a torus needs seams");
    assert_eq!(one, run(3));
}
