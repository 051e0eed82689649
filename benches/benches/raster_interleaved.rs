//! The raster-only random-triangle bench of `raster.rs` timed in turn instead of in criterion's
//! blocks: barytex's clear then draw, barytex's `draw_cleared`, and euc's clear then draw, one
//! draw each per round, then the minimum and the median of each over the rounds and the ratios.
//!
//! On a shared 2-core machine criterion's estimates for one function move by ±15 % between
//! runs (other work comes and goes during its seconds of samples); rounds that interleave the
//! three sides see the same machine, and the minimum is the least disturbed draw of each. Each
//! side's first draw after the others' runs with a cold cache (the three targets are 8 MB
//! each), so the medians are slower than criterion's; the minimums are the figure to compare.
//!
//! Run with `cargo bench -p barytex-benches --bench raster_interleaved` (`ROUNDS=N` sets the
//! number of rounds, 80 by default).

mod common;

use std::time::Instant;

use barytex_raster::Rgba8Unorm;
use common::{
    barytex_target, euc_targets, flat_u32, random_scene, raster_only_barytex,
    raster_only_barytex_draw_cleared, raster_only_euc,
};

const SIZE: u32 = 1024;

fn main() {
    let scene = random_scene(SIZE);
    let vertices: Vec<u32> = (0..scene.clip.len() as u32).collect();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let mut fb = barytex_target::<Rgba8Unorm>(SIZE);
    let mut euc = euc_targets(SIZE, 0_u32);
    let rounds = std::env::var("ROUNDS")
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or(80);
    let mut seconds = [const { Vec::new() }; 3];
    for _ in 0..rounds {
        let start = Instant::now();
        one.install(|| raster_only_barytex(&scene, &vertices, &mut fb));
        seconds[0].push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        one.install(|| raster_only_barytex_draw_cleared(&scene, &vertices, &mut fb));
        seconds[1].push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        raster_only_euc(&scene, flat_u32(), 0, &mut euc);
        seconds[2].push(start.elapsed().as_secs_f64());
    }
    for times in &mut seconds {
        times.sort_by(f64::total_cmp);
    }
    let [ours, cleared, theirs] = &seconds;
    for (what, at) in [("minimum", 0), ("median", rounds / 2)] {
        let (a, b, e) = (ours[at], cleared[at], theirs[at]);
        println!(
            "raster_only_1024_random_10k, {rounds} rounds, {what}: barytex clear + draw {:.3} ms, \
             draw_cleared {:.3} ms, euc {:.3} ms; euc ÷ barytex {:.2} (clear + draw), {:.2} \
             (draw_cleared)",
            a * 1e3,
            b * 1e3,
            e * 1e3,
            e / a,
            e / b
        );
    }
}
