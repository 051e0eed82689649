//! Criterion benchmarks of the 2D convex hull with its Rust peers side by side, on two standard
//! inputs: 10⁶ points uniform in a square and 10⁶ points on a circle.
//!
//! Peers get the same points converted exactly to f64: geo 0.33's `ConvexHull` trait on a
//! `MultiPoint` (its default, QuickHull, collecting the coordinates first), geo's `quick_hull` and
//! `graham_hull` called directly on a coordinate buffer (a fresh copy per call, not timed), and
//! spade's convex hull, which needs a Delaunay triangulation first (bulk-loaded; at 10⁵ points, as
//! it is an order of magnitude slower).
//!
//! Run with `cargo bench -p barytex-benches --bench hull` (one group:
//! `cargo bench -p barytex-benches --bench hull -- circle`).

use std::hint::black_box;
use std::time::Duration;

use barytex_interp::{CollinearPoints, convex_hull_2d};
use barytex_testkit::seeded::{XorShift, points_in_square, points_on_circle};
use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use geo::algorithm::convex_hull::{graham_hull, quick_hull};
use geo::{ConvexHull, Coord, MultiPoint, Point};
use glam::Vec2;
use spade::{DelaunayTriangulation, Point2, Triangulation};

const N: usize = 1_000_000;
const N_SPADE: usize = 100_000;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

fn coords(points: &[Vec2]) -> Vec<Coord<f64>> {
    points
        .iter()
        .map(|p| Coord {
            x: f64::from(p.x),
            y: f64::from(p.y),
        })
        .collect()
}

fn spade_hull_len(points: &[Point2<f64>]) -> usize {
    let t: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::bulk_load(points.to_vec()).expect("spade accepts the inputs");
    t.convex_hull().count()
}

/// One group: ours (both policies) and geo's three entry points on `points`, then spade on the
/// first `N_SPADE` of them.
fn bench_input(c: &mut Criterion, name: &str, points: &[Vec2]) {
    let coords = coords(points);
    let multi: MultiPoint<f64> = coords.iter().map(|&c| Point::from(c)).collect();
    // Vertex counts, once, so a run shows what each method returned.
    let ours = convex_hull_2d(points, CollinearPoints::Drop).expect("finite");
    let geo_len = multi.convex_hull().exterior().0.len() - 1;
    eprintln!(
        "{name}: {} points; barytex Drop {} vertices, Keep {}; geo ConvexHull {geo_len}",
        points.len(),
        ours.len(),
        convex_hull_2d(points, CollinearPoints::Keep)
            .expect("finite")
            .len()
    );

    let mut group = c.benchmark_group(format!("hull_{name}_1e6"));
    group.bench_function("barytex_convex_hull_2d_drop", |b| {
        b.iter(|| convex_hull_2d(black_box(points), CollinearPoints::Drop));
    });
    group.bench_function("barytex_convex_hull_2d_keep", |b| {
        b.iter(|| convex_hull_2d(black_box(points), CollinearPoints::Keep));
    });
    group.bench_function("geo_ConvexHull_MultiPoint", |b| {
        b.iter(|| black_box(&multi).convex_hull());
    });
    group.bench_function("geo_quick_hull", |b| {
        b.iter_batched_ref(
            || coords.clone(),
            |c| quick_hull(black_box(c)),
            BatchSize::LargeInput,
        );
    });
    group.bench_function("geo_graham_hull", |b| {
        b.iter_batched_ref(
            || coords.clone(),
            |c| graham_hull(black_box(c), false),
            BatchSize::LargeInput,
        );
    });
    group.finish();

    let small = &points[..N_SPADE.min(points.len())];
    let spade_points: Vec<Point2<f64>> = small
        .iter()
        .map(|p| Point2::new(f64::from(p.x), f64::from(p.y)))
        .collect();
    let mut group = c.benchmark_group(format!("hull_{name}_1e5"));
    group.bench_function("barytex_convex_hull_2d_drop", |b| {
        b.iter(|| convex_hull_2d(black_box(small), CollinearPoints::Drop));
    });
    group.bench_function("spade_DelaunayTriangulation_bulk_load_convex_hull", |b| {
        b.iter(|| spade_hull_len(black_box(&spade_points)));
    });
    group.finish();
}

fn bench_uniform_square(c: &mut Criterion) {
    let points = points_in_square(&mut XorShift::new(0x5a_2024), N);
    bench_input(c, "uniform_square", &points);
}

fn bench_circle(c: &mut Criterion) {
    bench_input(c, "circle", &points_on_circle(N));
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_uniform_square, bench_circle
}
criterion_main!(benches);
