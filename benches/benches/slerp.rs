//! Criterion benchmarks of the SLERP family with glam and nalgebra side by side.
//!
//! Inputs: `BATCH` seeded unit-quaternion pairs with 4D angles spread over `[0, π/2]` (the short
//! path's range) and unit-vector pairs with angles over `[0, π]`, each with its own `t`
//! (`barytex_testkit::sphere`, the same shapes the report and the tests use). Time per call.
//!
//! Run one group with `cargo bench -p barytex-benches --bench slerp -- --noplot quat_slerp`.

use std::hint::black_box;
use std::time::Duration;

use barytex_interp::{
    NlerpCorrection, NormalInterpolation, QuatInterpolation, interpolate_normal,
    nlerp_corrected_quats, nlerp_quats, slerp,
};
use barytex_testkit::seeded::XorShift;
use barytex_testkit::sphere;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{Quat, Vec3};
use nalgebra::{Quaternion, Unit, UnitQuaternion, Vector3};

/// Inputs per batch; every bench reports time per element of the batch.
const BATCH: usize = 1024;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
}

fn to_nalgebra(q: Quat) -> UnitQuaternion<f32> {
    UnitQuaternion::new_unchecked(Quaternion::new(q.w, q.x, q.y, q.z))
}

fn bench_quat_slerp(c: &mut Criterion) {
    let mut rng = XorShift::new(0x5e1e);
    let pairs = sphere::quat_pairs(&mut rng, BATCH, std::f32::consts::FRAC_PI_2);
    let nalgebra_pairs: Vec<_> = pairs
        .iter()
        .map(|&(a, b, t)| (to_nalgebra(a), to_nalgebra(b), t))
        .collect();
    let mut group = c.benchmark_group("quat_slerp");
    group.throughput(Throughput::Elements(BATCH as u64));
    for method in QuatInterpolation::ALL {
        group.bench_function(format!("barytex_{}", method.name()), |bench| {
            bench.iter(|| {
                for &(a, b, t) in black_box(&pairs[..]) {
                    black_box(method.interpolate(a, b, t));
                }
            });
        });
    }
    // The slice functions, on the same pairs split into three slices (setup, untimed), writing
    // into a preallocated output like the loops above write into black_box.
    let (slice_a, slice_b, slice_t): (Vec<Quat>, Vec<Quat>, Vec<f32>) =
        pairs.iter().map(|&(a, b, t)| (a, b, t)).collect();
    let mut slice_out = vec![Quat::IDENTITY; BATCH];
    group.bench_function("barytex_nlerp_slices", |bench| {
        bench.iter(|| {
            nlerp_quats(
                black_box(&slice_a),
                black_box(&slice_b),
                black_box(&slice_t),
                &mut slice_out,
            )
            .expect("same lengths");
            black_box(&slice_out);
        });
    });
    group.bench_function("barytex_nlerp-corrected_slices", |bench| {
        bench.iter(|| {
            nlerp_corrected_quats(
                black_box(&slice_a),
                black_box(&slice_b),
                black_box(&slice_t),
                NlerpCorrection::Precise,
                &mut slice_out,
            )
            .expect("same lengths");
            black_box(&slice_out);
        });
    });
    group.bench_function("barytex_slerp_direct_call", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(slerp(a, b, t));
            }
        });
    });
    group.bench_function("glam_Quat_slerp", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(a.slerp(b, t));
            }
        });
    });
    group.bench_function("glam_Quat_lerp_nlerp", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(a.lerp(b, t));
            }
        });
    });
    group.bench_function("nalgebra_UnitQuaternion_try_slerp", |bench| {
        bench.iter(|| {
            for (a, b, t) in black_box(&nalgebra_pairs[..]) {
                black_box(a.try_slerp(b, *t, 1e-7));
            }
        });
    });
    group.bench_function("nalgebra_UnitQuaternion_nlerp", |bench| {
        bench.iter(|| {
            for (a, b, t) in black_box(&nalgebra_pairs[..]) {
                black_box(a.nlerp(b, *t));
            }
        });
    });
    group.finish();
}

fn bench_vec3_slerp(c: &mut Criterion) {
    let mut rng = XorShift::new(0x7ec3);
    let pairs = sphere::vec3_pairs(&mut rng, BATCH, std::f32::consts::PI);
    let nalgebra_pairs: Vec<_> = pairs
        .iter()
        .map(|&(a, b, t)| {
            (
                Unit::new_unchecked(Vector3::new(a.x, a.y, a.z)),
                Unit::new_unchecked(Vector3::new(b.x, b.y, b.z)),
                t,
            )
        })
        .collect();
    let mut group = c.benchmark_group("vec3_slerp");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("barytex_slerp", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(slerp(a, b, t));
            }
        });
    });
    group.bench_function("barytex_interpolate_normal_renormalize", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(interpolate_normal(
                    a,
                    b,
                    t,
                    NormalInterpolation::Renormalize,
                ));
            }
        });
    });
    group.bench_function("glam_Vec3_slerp", |bench| {
        bench.iter(|| {
            for &(a, b, t) in black_box(&pairs[..]) {
                black_box(Vec3::slerp(a, b, t));
            }
        });
    });
    group.bench_function("nalgebra_Unit_Vector3_try_slerp", |bench| {
        bench.iter(|| {
            for (a, b, t) in black_box(&nalgebra_pairs[..]) {
                black_box(a.try_slerp(b, *t, 1e-7));
            }
        });
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_quat_slerp, bench_vec3_slerp
}
criterion_main!(benches);
