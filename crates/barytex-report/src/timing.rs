//! Wall-clock time per call: the median over batches, each batch timed with [`Instant`].

use std::hint::black_box;
use std::time::Instant;

/// How much to time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TimingConfig {
    /// Timed batches; the median of their per-call times is reported.
    pub(crate) batches: usize,
    /// Calls per batch at least: small input sets are repeated until a batch has this many.
    pub(crate) min_calls: usize,
}

/// Median nanoseconds per call of `f` over `inputs`.
///
/// One untimed warm-up batch, then `config.batches` timed ones; every call's input comes from a
/// [`black_box`]ed slice and every result goes through [`black_box`], so nothing is hoisted or
/// folded away. `NaN` for an empty input set.
pub(crate) fn ns_per_call<T: Copy, R>(
    inputs: &[T],
    config: TimingConfig,
    mut f: impl FnMut(T) -> R,
) -> f64 {
    if inputs.is_empty() {
        return f64::NAN;
    }
    let repeats = config.min_calls.div_ceil(inputs.len()).max(1);
    let calls = (repeats * inputs.len()) as f64;
    let mut samples = Vec::with_capacity(config.batches);
    for batch in 0..=config.batches {
        let start = Instant::now();
        for _ in 0..repeats {
            for &x in black_box(inputs) {
                black_box(f(x));
            }
        }
        let elapsed = start.elapsed();
        if batch > 0 {
            samples.push(elapsed.as_secs_f64() * 1e9 / calls);
        }
    }
    median(&mut samples)
}

/// The median of `values` (mean of the middle two for an even count); NaN sorts last, `NaN` for
/// an empty slice.
pub(crate) fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let mid = values.len() / 2;
    if values.len() % 2 == 1 {
        values[mid]
    } else {
        0.5 * (values[mid - 1] + values[mid])
    }
}

/// Runs `render` `runs` times (at least once) in a one-thread rayon pool, so frame times do not
/// depend on the machine's core count; returns the median seconds and the last result.
pub(crate) fn median_frame_seconds<T: Send>(
    runs: usize,
    mut render: impl FnMut() -> T + Send,
) -> (f64, T) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let out = pool.install(&mut render);
        times.push(start.elapsed().as_secs_f64());
        last = Some(out);
    }
    (median(&mut times), last.expect("at least one run"))
}
