//! Criterion benchmarks of the UV mappings: time per point for `uv` alone, `uv_and_jacobian`
//! (analytic gradients) and a central finite-difference Jacobian built from six more `uv` calls
//! (what a caller without analytic derivatives would do), per mapping.
//!
//! Inputs: `BATCH` seeded regular points per mapping (off axes and poles). Before the groups run,
//! the finite-difference Jacobian's relative error against the analytic one is printed (f32, step
//! 1e-3 of the object's size), so the cost can be read against the accuracy.
//!
//! Run one group with `cargo bench -p barytex-benches --bench uv -- --noplot uv_sphere`.

use std::hint::black_box;
use std::time::Duration;

use barytex_testkit::seeded::XorShift;
use barytex_testkit::uv::{finite_difference_jacobian, surface_points};
use barytex_uv::mappings::{
    BoxMapping, CylinderCaps, Cylindrical, Planar, SphereProjection, Spherical, Torus,
};
use barytex_uv::{PositionMapping, UvJacobian};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;

/// Points per batch; every bench reports time per point.
const BATCH: usize = 1024;
/// Finite-difference step.
const H: f32 = 1e-3;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
}

fn fd_jacobian(m: &dyn PositionMapping, p: Vec3, n: Vec3) -> Option<UvJacobian> {
    finite_difference_jacobian(m, p, n, H)
}

fn points(rng: &mut XorShift, torus: bool) -> Vec<(Vec3, Vec3)> {
    surface_points(rng, BATCH, torus)
}

fn mappings() -> Vec<(&'static str, Box<dyn PositionMapping>)> {
    vec![
        ("planar", Box::new(Planar::xz(2.0).expect("valid"))),
        (
            "box",
            Box::new(BoxMapping::new(Vec3::ZERO, 2.0).expect("valid")),
        ),
        (
            "cylinder",
            Box::new(
                Cylindrical::new(1.0, 2.0)
                    .expect("valid")
                    .with_caps(CylinderCaps::Planar),
            ),
        ),
        (
            "sphere_equirectangular",
            Box::new(Spherical::new(1.0, SphereProjection::Equirectangular).expect("valid")),
        ),
        (
            "sphere_equal_area",
            Box::new(Spherical::new(1.0, SphereProjection::EqualArea).expect("valid")),
        ),
        ("torus", Box::new(Torus::new(2.0, 0.5).expect("valid"))),
    ]
}

fn bench_mappings(c: &mut Criterion) {
    for (name, m) in mappings() {
        let pts = points(&mut XorShift::new(0x0b5e), name == "torus");
        // Accuracy of the finite-difference Jacobian, printed once per mapping.
        let mut worst = 0.0f32;
        for &(p, n) in &pts {
            let (Some(a), Some(f)) = (m.uv_and_jacobian(p, n), fd_jacobian(m.as_ref(), p, n))
            else {
                continue;
            };
            let err = ((a.du - f.du).length_squared() + (a.dv - f.dv).length_squared()).sqrt();
            let norm = (a.du.length_squared() + a.dv.length_squared()).sqrt();
            worst = worst.max(err / norm);
        }
        println!(
            "uv_{name}: finite-difference Jacobian (f32, h = {H}) worst relative error {worst:.2e}"
        );
        let mut group = c.benchmark_group(format!("uv_{name}"));
        group.throughput(Throughput::Elements(BATCH as u64));
        group.bench_function("uv", |bench| {
            bench.iter(|| {
                for &(p, n) in black_box(&pts[..]) {
                    black_box(m.uv(p, n));
                }
            });
        });
        group.bench_function("uv_and_jacobian_analytic", |bench| {
            bench.iter(|| {
                for &(p, n) in black_box(&pts[..]) {
                    black_box(m.uv_and_jacobian(p, n));
                }
            });
        });
        group.bench_function("jacobian_finite_differences", |bench| {
            bench.iter(|| {
                for &(p, n) in black_box(&pts[..]) {
                    black_box(fd_jacobian(m.as_ref(), p, n));
                }
            });
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_mappings
}
criterion_main!(benches);
