//! LSCM reproduces planar meshes up to a similarity; ARAP never adds a flip.

mod common;

use barytex_unwrap::{
    BoundaryShape, Weights, arap_refine, embed_disk, is_positively_oriented, lscm,
};
use common::{Height, delaunay_lifted, disk_points, height, perturbed_grid};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

/// The documented `# Accuracy` of `lscm` on a planar mesh: distance to the best similarity,
/// relative to the chart's diameter.
const LSCM_PLANAR_BOUND: f64 = 1e-8;

fn cmul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

fn conj(a: DVec2) -> DVec2 {
    DVec2::new(a.x, -a.y)
}

/// The largest distance from `w` to the least-squares similarity image `α z + β` of `z`,
/// divided by the diameter of `z` (bounding-box diagonal).
fn similarity_error(z: &[DVec2], w: &[DVec2]) -> f64 {
    let n = z.len() as f64;
    let zm = z.iter().sum::<DVec2>() / n;
    let wm = w.iter().sum::<DVec2>() / n;
    let mut num = DVec2::ZERO;
    let mut den = 0.0;
    for (a, b) in z.iter().zip(w) {
        num += cmul(conj(*a - zm), *b - wm);
        den += (*a - zm).length_squared();
    }
    let alpha = num / den;
    let (lo, hi) = z
        .iter()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(l, h), p| {
            (l.min(*p), h.max(*p))
        });
    let diameter = (hi - lo).length() * alpha.length();
    z.iter()
        .zip(w)
        .map(|(a, b)| (cmul(alpha, *a - zm) + wm - *b).length())
        .fold(0.0, f64::max)
        / diameter
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// A planar mesh, placed in a random plane in space: LSCM's output is a similarity image.
    #[test]
    fn lscm_reproduces_a_planar_mesh(
        points in common::disk_points(),
        axis in (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64),
        angle in 0.0..6.3f64,
        offset in (-100.0..100.0f64, -100.0..100.0f64, -100.0..100.0f64),
    ) {
        let flat = Height { waves: [(0.0, 0.0, 0.0, 0.0); 3] };
        let Some((p, t)) = delaunay_lifted(&points, &flat) else { return Ok(()) };
        let axis = DVec3::new(axis.0, axis.1, axis.2).try_normalize().unwrap_or(DVec3::Z);
        let rotation = glam::DQuat::from_axis_angle(axis, angle);
        let offset = DVec3::new(offset.0, offset.1, offset.2);
        let placed: Vec<DVec3> = p.iter().map(|&q| rotation * q + offset).collect();
        let e = lscm(&placed, &t).map_err(|err| TestCaseError::fail(format!("{err}")))?;
        prop_assert_eq!(e.flips, 0);
        let z: Vec<DVec2> = p.iter().map(|q| q.truncate()).collect();
        let err = similarity_error(&z, &e.uvs);
        prop_assert!(err <= LSCM_PLANAR_BOUND, "error {err:e}, solve {:?}", e.solve);
    }

    /// From a flip-free start, ARAP stays flip-free and lowers its energy; from a start with
    /// flips (a mean-value embedding with its interior scrambled), it never adds one.
    #[test]
    fn arap_never_increases_flips(
        points in disk_points(),
        h in height(),
        scramble in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 1..32),
        amount in 0.0..0.5f64,
    ) {
        let Some((p, t)) = delaunay_lifted(&points, &h) else { return Ok(()) };
        let mut uvs = lscm(&p, &t).map_err(|err| TestCaseError::fail(format!("{err}")))?.uvs;
        let start_flips = count(&uvs, &t);
        let r = arap_refine(&p, &t, &mut uvs, 10).map_err(|err| TestCaseError::fail(format!("{err}")))?;
        prop_assert!(r.flips_after <= r.flips_before.max(start_flips));
        prop_assert_eq!(r.flips_after, count(&uvs, &t));
        prop_assert!(r.energy_after <= r.energy_before);

        let e = embed_disk(&p, &t, Weights::MeanValue, BoundaryShape::Circle)
            .map_err(|err| TestCaseError::fail(format!("{err}")))?;
        let mut uvs = e.uvs;
        let radius = uvs.iter().map(|u| u.length()).fold(0.0, f64::max);
        for (k, u) in uvs.iter_mut().enumerate() {
            if u.length() < 0.999 * radius {
                let (dx, dy) = scramble[k % scramble.len()];
                *u += amount * radius * DVec2::new(dx, dy);
            }
        }
        let before = count(&uvs, &t);
        let r = arap_refine(&p, &t, &mut uvs, 10).map_err(|err| TestCaseError::fail(format!("{err}")))?;
        prop_assert!(r.flips_after <= before, "{} > {before}", r.flips_after);
        prop_assert_eq!(r.flips_after, count(&uvs, &t));
    }
}

fn count(uvs: &[DVec2], t: &[[u32; 3]]) -> usize {
    t.iter()
        .filter(|t| !is_positively_oriented(t.map(|v| uvs[v as usize])))
        .count()
}

#[test]
fn arap_recovers_the_isometry_of_a_developable_strip() {
    // A cylinder patch is developable: ARAP should reach near-zero energy.
    let (p, t) = perturbed_grid(
        20,
        4,
        &[(0.0, 0.0)],
        &Height {
            waves: [(0.0, 0.0, 0.0, 0.0); 3],
        },
    );
    let bent: Vec<DVec3> = p
        .iter()
        .map(|q| DVec3::new(q.x.sin(), q.y, q.x.cos()))
        .collect();
    // Start far from the isometry: the strip's boundary on a circle.
    let mut uvs = embed_disk(&bent, &t, Weights::MeanValue, BoundaryShape::Circle)
        .expect("a disk")
        .uvs;
    let r = arap_refine(&bent, &t, &mut uvs, 200).expect("fits");
    assert_eq!(r.flips_after, 0);
    assert!(r.energy_after < 1e-2 * r.energy_before, "{r:?}");
    // Every edge keeps its length within 2%.
    for tri in &t {
        for k in 0..3 {
            let (i, j) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
            let (l3, l2) = ((bent[i] - bent[j]).length(), (uvs[i] - uvs[j]).length());
            assert!(
                (l2 / l3 - 1.0).abs() < 0.02,
                "edge {i}-{j}: {l3} -> {l2}, {r:?}"
            );
        }
    }
}
