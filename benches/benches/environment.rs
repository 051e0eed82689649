//! Criterion benchmarks of the environment maps of `barytex-uv`: forward (direction → uv), the
//! forward map with its analytic Jacobian, and the inverse (uv → direction), per direction.
//!
//! Inputs: `BATCH` seeded directions uniform in the cube `[−1, 1]³` (not normalized: the maps
//! normalize or are scale-invariant) and the uvs they map to. Time per call.
//!
//! Run one group with `cargo bench -p barytex-benches --bench environment -- --noplot forward`.

use std::hint::black_box;
use std::time::Duration;

use barytex_testkit::seeded::XorShift;
use barytex_uv::environment::{
    EnvironmentMap, cube_direction, cube_face_uv, equirect_direction, octahedral_decode,
    reflect_normalized, sphere_map_direction,
};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;

/// Inputs per batch; every bench reports time per element of the batch.
const BATCH: usize = 1024;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
}

fn directions() -> Vec<Vec3> {
    let mut rng = XorShift::new(0x0e_0e);
    (0..BATCH)
        .map(|_| {
            loop {
                let d = rng.vec3_in(-1.0, 1.0);
                if d.length() > 1e-2 {
                    break d;
                }
            }
        })
        .collect()
}

fn bench_forward(c: &mut Criterion) {
    let dirs = directions();
    let mut group = c.benchmark_group("environment_forward");
    group.throughput(Throughput::Elements(BATCH as u64));
    for map in EnvironmentMap::ALL {
        group.bench_function(map.name(), |bench| {
            bench.iter(|| {
                for &d in black_box(&dirs[..]) {
                    black_box(map.uv(d));
                }
            });
        });
        group.bench_function(format!("{}_with_jacobian", map.name()), |bench| {
            bench.iter(|| {
                for &d in black_box(&dirs[..]) {
                    black_box(map.uv_and_direction_jacobian(d));
                }
            });
        });
    }
    group.bench_function("reflect_normalized", |bench| {
        bench.iter(|| {
            for w in black_box(&dirs[..]).windows(2) {
                black_box(reflect_normalized(w[0], w[1]));
            }
        });
    });
    group.finish();
}

fn bench_inverse(c: &mut Criterion) {
    let dirs = directions();
    let cube: Vec<_> = dirs.iter().filter_map(|&d| cube_face_uv(d)).collect();
    let uvs = |map: EnvironmentMap| -> Vec<_> { dirs.iter().filter_map(|&d| map.uv(d)).collect() };
    let (equirect, sphere, octahedral) = (
        uvs(EnvironmentMap::Equirect),
        uvs(EnvironmentMap::SphereMap),
        uvs(EnvironmentMap::Octahedral),
    );
    let mut group = c.benchmark_group("environment_inverse");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("cube", |bench| {
        bench.iter(|| {
            for &(face, st) in black_box(&cube[..]) {
                black_box(cube_direction(face, st));
            }
        });
    });
    group.bench_function("equirect", |bench| {
        bench.iter(|| {
            for &uv in black_box(&equirect[..]) {
                black_box(equirect_direction(uv));
            }
        });
    });
    group.bench_function("sphere-map", |bench| {
        bench.iter(|| {
            for &uv in black_box(&sphere[..]) {
                black_box(sphere_map_direction(uv));
            }
        });
    });
    group.bench_function("octahedral", |bench| {
        bench.iter(|| {
            for &uv in black_box(&octahedral[..]) {
                black_box(octahedral_decode(uv));
            }
        });
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_forward, bench_inverse
}
criterion_main!(benches);
