//! The evidence behind the sparse solver: time, iterations and residuals of every linear solve
//! on a ~50k-triangle disk (a 160 × 160 grid lifted onto a height field):
//! `cargo run --release -p barytex-unwrap --example solver_evidence`.
//!
//! Besides the solvers' own (recursive) residuals it measures the equations directly: for the
//! uniform weights, how far each interior vertex is from the mean of its neighbours; for LSCM,
//! the similarity error on the flat grid.

use std::time::Instant;

use barytex_unwrap::{BoundaryShape, Weights, arap_refine, embed_disk, lscm, shapes};
use glam::DVec2;

fn main() {
    let n = 160;
    let lifted = shapes::grid(n, n, |x, y| 0.3 * (5.0 * x).sin() * (4.0 * y).cos());
    let (p, t) = (lifted.positions(), lifted.triangles());
    println!("{} vertices, {} triangles", p.len(), t.len());
    println!("solve                      seconds  solver    iterations  relative residual  flips");
    for (name, w) in [
        ("Tutte", Weights::Uniform),
        ("mean value", Weights::MeanValue),
        ("harmonic", Weights::Cotangent),
    ] {
        let start = Instant::now();
        let e = embed_disk(p, t, w, BoundaryShape::Circle).expect("a disk");
        let s = start.elapsed().as_secs_f64();
        println!(
            "{name:26} {s:7.3}  {:8}  {:10}  {:17.3e}  {}",
            if e.solve.direct { "Cholesky" } else { "Krylov" },
            e.solve.iterations,
            e.solve.relative_residual,
            e.flips
        );
        if w == Weights::Uniform {
            // Independent check of the equations: u_i = mean of the neighbours.
            let mut nbrs = vec![Vec::new(); p.len()];
            for tri in t {
                for k in 0..3 {
                    nbrs[tri[k] as usize].push(tri[(k + 1) % 3]);
                    nbrs[tri[(k + 1) % 3] as usize].push(tri[k]);
                }
            }
            let radius = e.uvs.iter().map(|u| u.length()).fold(0.0, f64::max);
            let mut worst = 0.0f64;
            for (v, list) in nbrs.iter_mut().enumerate() {
                list.sort_unstable();
                list.dedup();
                let interior = {
                    let q = p[v];
                    q.x > 0.0 && q.x < 1.0 && q.y > 0.0 && q.y < 1.0
                };
                if interior {
                    let mean =
                        list.iter().map(|&j| e.uvs[j as usize]).sum::<DVec2>() / list.len() as f64;
                    worst = worst.max((e.uvs[v] - mean).length() / radius);
                }
            }
            println!("  max |u_i - mean(neighbours)| / radius = {worst:.3e}");
        }
    }
    for (name, mesh) in [
        ("LSCM lifted", &lifted),
        ("LSCM flat", &shapes::grid(n, n, |_, _| 0.0)),
    ] {
        let start = Instant::now();
        let e = lscm(mesh.positions(), mesh.triangles()).expect("a disk");
        let s = start.elapsed().as_secs_f64();
        println!(
            "{name:26} {s:7.3}  {:8}  {:10}  {:17.3e}  {}",
            if e.solve.direct { "Cholesky" } else { "Krylov" },
            e.solve.iterations,
            e.solve.relative_residual,
            e.flips
        );
    }
    let mut uvs = lscm(p, t).expect("a disk").uvs;
    let start = Instant::now();
    let r = arap_refine(p, t, &mut uvs, 10).expect("fits");
    println!(
        "ARAP, 10 iterations        {:7.3}  accepted {}, energy {:.4e} -> {:.4e}, flips {} -> {}",
        start.elapsed().as_secs_f64(),
        r.iterations,
        r.energy_before,
        r.energy_after,
        r.flips_before,
        r.flips_after
    );
}
