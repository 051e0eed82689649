//! Criterion benchmarks of the exact 3D orientation and the 3D convex hull.
//!
//! `orient3d`: barytex's filtered exact predicate against the `robust` crate's (Shewchuk's
//! adaptive `orient3d`, whose sign is the opposite of ours) and a naive, unfiltered f64
//! determinant, on random points and on near-coplanar ones (parallelograms of 24-bit integer
//! corners, exactly coplanar or one unit off, where the filter fails and the exact stage runs).
//! `convex_hull_3d`: 1e5 points uniform in a ball and on a sphere (every point a corner).
//!
//! Run with `cargo bench -p barytex-benches --bench hull3d`.

use std::hint::black_box;
use std::time::Duration;

use barytex_interp::methods::orient3d_naive_f64;
use barytex_interp::{convex_hull_3d, orient3d};
use barytex_testkit::seeded::XorShift;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;

/// Inputs per orientation batch; the bench reports time per call.
const BATCH: usize = 1024;

/// Points per hull.
const HULL_POINTS: usize = 100_000;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

type Quad = [Vec3; 4];

fn random_quads(rng: &mut XorShift) -> Vec<Quad> {
    (0..BATCH)
        .map(|_| [0; 4].map(|_| rng.vec3_in(-100.0, 100.0)))
        .collect()
}

/// `d = a + b − c` on 24-bit integer corners (exactly coplanar), half of them with `d` one unit
/// off in one coordinate, scaled by a power of two.
fn near_coplanar_quads(rng: &mut XorShift) -> Vec<Quad> {
    let half = 1 << 22;
    (0..BATCH)
        .map(|i| {
            let mut corner = || {
                Vec3::new(
                    rng.i32_in(-half, half) as f32,
                    rng.i32_in(-half, half) as f32,
                    rng.i32_in(-half, half) as f32,
                )
            };
            let (a, b, c) = (corner(), corner(), corner());
            let mut d = a + b - c;
            if i % 2 == 1 {
                d[i % 3] += 1.0;
            }
            [a, b, c, d].map(|p| p * 2f32.powi(-20))
        })
        .collect()
}

fn robust_orient3d([a, b, c, d]: Quad) -> f64 {
    let coord = |v: Vec3| robust::Coord3D {
        x: v.x,
        y: v.y,
        z: v.z,
    };
    robust::orient3d(coord(a), coord(b), coord(c), coord(d))
}

fn bench_orient3d(c: &mut Criterion) {
    let mut rng = XorShift::new(0x3d0);
    let sets = [
        ("random", random_quads(&mut rng)),
        ("near_coplanar", near_coplanar_quads(&mut rng)),
    ];
    // The peers must agree with us on these inputs (robust is exact too, with the other sign).
    for (_, quads) in &sets {
        for &[a, b, p, q] in quads {
            let ours = orient3d(a, b, p, q).map_or(0, |o| o.sign());
            let theirs = -robust_orient3d([a, b, p, q]).signum() as i8;
            let theirs = if robust_orient3d([a, b, p, q]) == 0.0 {
                0
            } else {
                theirs
            };
            assert_eq!(ours, theirs, "{a:?} {b:?} {p:?} {q:?}");
        }
    }
    let mut group = c.benchmark_group("orient3d");
    group.throughput(Throughput::Elements(BATCH as u64));
    for (set, quads) in &sets {
        group.bench_function(format!("barytex_orient3d/{set}"), |b| {
            b.iter(|| {
                for &[p, q, r, s] in quads {
                    let _ = black_box(orient3d(p, q, r, s));
                }
            });
        });
        group.bench_function(format!("robust_orient3d/{set}"), |b| {
            b.iter(|| {
                for &quad in quads {
                    black_box(robust_orient3d(quad));
                }
            });
        });
        group.bench_function(format!("naive_f64/{set}"), |b| {
            b.iter(|| {
                for &[p, q, r, s] in quads {
                    black_box(orient3d_naive_f64(p, q, r, s));
                }
            });
        });
    }
    group.finish();
}

fn ball(rng: &mut XorShift, n: usize, surface: bool) -> Vec<Vec3> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let p = rng.vec3_in(-1.0, 1.0);
        let len = p.length();
        if len <= 1.0 && len > 1e-3 {
            out.push(if surface { p / len } else { p });
        }
    }
    out
}

fn bench_hull3d(c: &mut Criterion) {
    let mut rng = XorShift::new(0x4b11);
    let sets = [
        ("ball_1e5", ball(&mut rng, HULL_POINTS, false)),
        ("sphere_1e5", ball(&mut rng, HULL_POINTS, true)),
    ];
    let mut group = c.benchmark_group("convex_hull_3d");
    group.sample_size(10);
    for (set, points) in &sets {
        let corners = convex_hull_3d(points).map_or(0, |h| h.vertices().len());
        println!(
            "convex_hull_3d/{set}: {corners} corners of {}",
            points.len()
        );
        group.bench_function(format!("barytex_convex_hull_3d/{set}"), |b| {
            b.iter(|| black_box(convex_hull_3d(black_box(points))));
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_orient3d, bench_hull3d
}
criterion_main!(benches);
