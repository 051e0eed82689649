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

/// Harmonic weights turn negative on obtuse pairs; on strongly jittered grids lifted onto steep
/// height fields some embeddings flip. Mean value never does on the same meshes, and the
/// reported count is the exact one.
#[test]
fn harmonic_weights_can_flip_and_the_flips_are_counted() {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut harmonic_flips = 0;
    for _ in 0..60 {
        let jitter: Vec<(f64, f64)> = (0..64).map(|_| (1.6 * next(), 1.6 * next())).collect();
        let h = common::Height {
            waves: [(next(), 9.0 * next(), 9.0 * next(), 3.0 * next()); 3],
        };
        let (p, t) = perturbed_grid(8, 8, &jitter, &h);
        let harmonic =
            embed_disk(&p, &t, Weights::Cotangent, BoundaryShape::Circle).expect("a disk");
        let mean = embed_disk(&p, &t, Weights::MeanValue, BoundaryShape::Circle).expect("a disk");
        assert_eq!(mean.flips, 0);
        let exact = t
            .iter()
            .filter(|t| !is_positively_oriented(t.map(|v| harmonic.uvs[v as usize])))
            .count();
        assert_eq!(harmonic.flips, exact);
        harmonic_flips += exact;
    }
    println!("harmonic flips over 60 meshes: {harmonic_flips}");
    assert!(harmonic_flips > 0, "the negative-weight caveat is real");
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
