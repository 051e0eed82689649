//! Tutte's theorem, checked exactly: uniform and mean-value embeddings of random disk meshes
//! onto a circle have every triangle positively oriented (`robust::orient2d > 0`).

mod common;

use barytex_unwrap::{BoundaryShape, Weights, embed_disk, is_positively_oriented};
use common::{delaunay_lifted, disk_points, height, perturbed_grid};
use glam::DVec2;
use proptest::prelude::*;

fn assert_bijective(
    positions: &[glam::DVec3],
    triangles: &[[u32; 3]],
    weights: Weights,
) -> Result<(), TestCaseError> {
    let e = embed_disk(positions, triangles, weights, BoundaryShape::Circle)
        .map_err(|err| TestCaseError::fail(format!("{err}")))?;
    prop_assert!(e.solve.converged, "{weights:?}: {:?}", e.solve);
    for t in triangles {
        let uv: [DVec2; 3] = t.map(|v| e.uvs[v as usize]);
        prop_assert!(
            is_positively_oriented(uv),
            "{weights:?}: triangle {t:?} at {uv:?}"
        );
    }
    prop_assert_eq!(e.flips, 0);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn tutte_and_mean_value_on_random_delaunay_disks(points in disk_points(), h in height()) {
        if let Some((p, t)) = delaunay_lifted(&points, &h) {
            assert_bijective(&p, &t, Weights::Uniform)?;
            assert_bijective(&p, &t, Weights::MeanValue)?;
        }
    }

    #[test]
    fn tutte_and_mean_value_on_perturbed_lifted_grids(
        n in 1u32..24,
        m in 1u32..24,
        jitter in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 1..64),
        h in height(),
    ) {
        let (p, t) = perturbed_grid(n, m, &jitter, &h);
        assert_bijective(&p, &t, Weights::Uniform)?;
        assert_bijective(&p, &t, Weights::MeanValue)?;
    }
}

#[test]
fn boundary_lies_on_the_circle_by_arc_length() {
    let g = barytex_unwrap::shapes::grid(4, 4, |_, _| 0.0);
    let e = embed_disk(
        g.positions(),
        g.triangles(),
        Weights::Uniform,
        BoundaryShape::Circle,
    )
    .expect("a disk");
    // Perimeter 4: the circle's radius is 4 / 2π.
    let r = 4.0 / core::f64::consts::TAU;
    for (v, p) in g.positions().iter().enumerate() {
        let on_boundary = p.x == 0.0 || p.x == 1.0 || p.y == 0.0 || p.y == 1.0;
        if on_boundary {
            assert!((e.uvs[v].length() - r).abs() < 1e-12, "{v}: {}", e.uvs[v]);
        } else {
            assert!(e.uvs[v].length() < r);
        }
    }
}

#[test]
fn square_boundary_counts_triangles_with_three_vertices_on_one_side() {
    // A regular 16-gon triangulated as a fan from vertex 0: vertices 0, 1, 2 land on the
    // square's first side, so triangle [0, 1, 2] is degenerate there (Floater 2003's condition
    // fails); on the circle nothing is.
    let n = 16u32;
    let p: Vec<glam::DVec3> = (0..n)
        .map(|k| {
            let a = core::f64::consts::TAU * f64::from(k) / f64::from(n);
            glam::DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    let t: Vec<[u32; 3]> = (1..n - 1).map(|k| [0, k, k + 1]).collect();
    let square = embed_disk(&p, &t, Weights::Uniform, BoundaryShape::Square).expect("a disk");
    let circle = embed_disk(&p, &t, Weights::Uniform, BoundaryShape::Circle).expect("a disk");
    assert_eq!(circle.flips, 0);
    assert!(!is_positively_oriented(
        t[0].map(|v| square.uvs[v as usize])
    ));
    assert!(square.flips > 0);
}

#[test]
fn harmonic_weights_can_flip_and_the_flips_are_counted() {
    // A fan whose centre sits near one boundary edge of a long thin polygon, lifted: angles
    // opposite some edges exceed π/2 on both sides, making weights negative.
    let n = 24;
    let mut p = vec![glam::DVec3::new(0.0, -0.95, 0.0)];
    for k in 0..n {
        let a = core::f64::consts::TAU * f64::from(k) / f64::from(n);
        p.push(glam::DVec3::new(3.0 * a.cos(), a.sin(), 0.0));
    }
    let t: Vec<[u32; 3]> = (0..n).map(|k| [0, 1 + k, 1 + (k + 1) % n]).collect();
    let h = embed_disk(&p, &t, Weights::Cotangent, BoundaryShape::Circle).expect("a disk");
    let m = embed_disk(&p, &t, Weights::MeanValue, BoundaryShape::Circle).expect("a disk");
    assert_eq!(m.flips, 0);
    // Whatever the harmonic map does, its count is the exact count.
    let exact = t
        .iter()
        .filter(|t| !is_positively_oriented(t.map(|v| h.uvs[v as usize])))
        .count();
    assert_eq!(h.flips, exact);
}

#[test]
fn not_a_disk_is_an_error() {
    let s = barytex_unwrap::shapes::sphere(4, 6);
    let e = embed_disk(
        s.positions(),
        s.triangles(),
        Weights::Uniform,
        BoundaryShape::Circle,
    );
    assert!(
        matches!(
            e,
            Err(barytex_unwrap::UnwrapError::NotADisk {
                boundary_loops: 0,
                ..
            })
        ),
        "{e:?}"
    );
}
