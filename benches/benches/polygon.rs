//! Generalized barycentric coordinates over convex polygons (Wachspress 1975; Floater, "Mean value
//! coordinates", 2003), against the triangle-fan split they replace (whose result depends on the
//! split: Foley et al., *Computer Graphics: Principles and Practice*, 2nd ed., 1990, §16.2), in
//! one criterion run.
//!
//! For a quad, a pentagon and a 16-gon (seeded, perturbed regular polygons, each with a point
//! strictly inside from random convex weights), every method writes one weight per vertex:
//! - `wachspress`, `mean_value`: `barytex_interp::{wachspress_weights, mean_value_weights}`;
//! - `fan_barycentric_2d`: split into the fan from vertex 0, find the triangle holding the
//!   point with `barytex_interp::barycentric_2d` (exact classification) and scatter its three
//!   weights (the usual renderer approach, whose answer depends on the split);
//! - `fan_barycentric_2d_f64`: the same with `barytex_interp::methods::barycentric_2d_f64`
//!   (plain f64, no classification), the point taken by the first triangle whose weights are
//!   all ≥ 0.
//!
//! Times are per point (`Throughput::Elements(batch size)`). Run with
//! `cargo bench -p barytex-benches --bench polygon`.

use std::hint::black_box;
use std::time::Duration;

use barytex_interp::methods::barycentric_2d_f64;
use barytex_interp::{barycentric_2d, mean_value_weights, wachspress_weights};
use barytex_testkit::polygon_invariants::polygon_on_ellipse;
use barytex_testkit::seeded::XorShift;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec2;

/// Points per batch; every bench reports time per point.
const BATCH: usize = 512;

/// `BATCH` convex `n`-gons on perturbed unit circles (angle gaps 0.6 … 1.4 of the mean), each
/// with a point inside from random positive weights.
fn polygons(rng: &mut XorShift, n: usize) -> Vec<(Vec2, Vec<Vec2>)> {
    (0..BATCH)
        .map(|_| {
            let gaps: Vec<f64> = (0..n).map(|_| f64::from(rng.f32_in(0.6, 1.4))).collect();
            let start = f64::from(rng.f32_in(0.0, core::f32::consts::TAU));
            let centre = rng.vec2_in(-10.0, 10.0);
            let radii = Vec2::new(rng.f32_in(0.5, 2.0), rng.f32_in(0.5, 2.0));
            let poly = polygon_on_ellipse(centre, radii, start, &gaps);
            let w: Vec<f32> = (0..n).map(|_| rng.f32_in(0.05, 1.0)).collect();
            let total: f32 = w.iter().sum();
            let p = poly
                .iter()
                .zip(&w)
                .fold(Vec2::ZERO, |acc, (v, wi)| acc + *v * (wi / total));
            (p, poly)
        })
        .collect()
}

/// Fan split with exact `barycentric_2d`: the first fan triangle that holds `p` (closed).
fn fan_exact(p: Vec2, poly: &[Vec2], weights: &mut [f32]) {
    weights.fill(0.0);
    for i in 1..poly.len() - 1 {
        if let Ok(b) = barycentric_2d(p, [poly[0], poly[i], poly[i + 1]])
            && b.location.is_inside_closed()
        {
            weights[0] = b.weights[0];
            weights[i] = b.weights[1];
            weights[i + 1] = b.weights[2];
            return;
        }
    }
}

/// Fan split with plain f64 barycentric weights.
fn fan_f64(p: Vec2, poly: &[Vec2], weights: &mut [f32]) {
    weights.fill(0.0);
    for i in 1..poly.len() - 1 {
        let w = barycentric_2d_f64(p, [poly[0], poly[i], poly[i + 1]]);
        if w.iter().all(|&x| x >= 0.0) {
            weights[0] = w[0];
            weights[i] = w[1];
            weights[i + 1] = w[2];
            return;
        }
    }
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
}

fn bench_polygons(c: &mut Criterion) {
    let mut rng = XorShift::new(0x9017);
    for (label, n) in [("quad", 4), ("pentagon", 5), ("16-gon", 16)] {
        let inputs = polygons(&mut rng, n);
        let mut weights = vec![0.0f32; n];
        let mut group = c.benchmark_group(format!("polygon_{label}"));
        group.throughput(Throughput::Elements(BATCH as u64));
        group.bench_function("wachspress", |b| {
            b.iter(|| {
                for (p, poly) in black_box(&inputs[..]) {
                    let r = wachspress_weights(*p, poly, &mut weights);
                    black_box((black_box(r).is_ok(), &weights));
                }
            });
        });
        group.bench_function("mean_value", |b| {
            b.iter(|| {
                for (p, poly) in black_box(&inputs[..]) {
                    let r = mean_value_weights(*p, poly, &mut weights);
                    black_box((black_box(r).is_ok(), &weights));
                }
            });
        });
        group.bench_function("fan_barycentric_2d", |b| {
            b.iter(|| {
                for (p, poly) in black_box(&inputs[..]) {
                    fan_exact(*p, poly, &mut weights);
                    black_box(&weights);
                }
            });
        });
        group.bench_function("fan_barycentric_2d_f64", |b| {
            b.iter(|| {
                for (p, poly) in black_box(&inputs[..]) {
                    fan_f64(*p, poly, &mut weights);
                    black_box(&weights);
                }
            });
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_polygons
}
criterion_main!(benches);
