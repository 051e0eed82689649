//! Distortion, chart count and time of every method on generated meshes:
//! `cargo run --release -p barytex-unwrap --example unwrap_stats [sphere|torus|cube|all]`.

use std::time::Instant;

use barytex_unwrap::{
    Method, ParamOptions, UnwrapMesh, atlas_stats, parameterize_with_report, shapes,
};

fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "all".into());
    let meshes: Vec<(&str, UnwrapMesh)> = vec![
        ("sphere", shapes::sphere(48, 96)),
        ("torus", shapes::torus(1.0, 0.35, 96, 48)),
        ("cube", shapes::cube(16)),
    ];
    println!(
        "mesh    triangles method     charts splits fallbacks flips angle(mean/max)    area(mean/max)      seconds"
    );
    for (name, mesh) in meshes.iter().filter(|(n, _)| which == "all" || which == *n) {
        for method in [
            Method::Tutte,
            Method::MeanValue,
            Method::Harmonic,
            Method::Lscm,
            Method::LscmArap,
        ] {
            let options = ParamOptions {
                method,
                ..ParamOptions::default()
            };
            let start = Instant::now();
            let p = parameterize_with_report(mesh, &options).expect("unwrapped");
            let seconds = start.elapsed().as_secs_f64();
            // Per-chart figures (charts are not packed, so each keeps its own scale).
            let mut worst = (0.0f64, 0.0f64);
            let (mut angle, mut area, mut w) = (0.0, 0.0, 0.0);
            let mut flips = 0;
            for c in &p.charts {
                let s = atlas_stats(mesh, std::slice::from_ref(c));
                flips += s.flipped;
                angle += s.angle_distortion_mean * s.surface_area;
                area += s.area_distortion_mean * s.surface_area;
                w += s.surface_area;
                worst = (
                    worst.0.max(s.angle_distortion_max),
                    worst.1.max(s.area_distortion_max),
                );
            }
            let fallbacks = p.reports.iter().filter(|r| r.fell_back).count();
            println!(
                "{name:7} {:9} {:10} {:6} {:6} {:9} {flips:5} {:7.4} / {:9.3} {:7.4} / {:9.3} {seconds:8.3}",
                mesh.triangles().len(),
                format!("{method:?}"),
                p.charts.len(),
                p.splits,
                fallbacks,
                angle / w,
                worst.0,
                area / w,
                worst.1,
            );
        }
    }
}
