//! Fuzz target `sampling`: an arbitrary sampler descriptor, RGBA8 texture (≤ 8×8) and mip chain, and arbitrary uv, derivatives and LOD. Decodes the input with
//! `barytex_tests::fuzz_inputs::sampling` (layout documented there, shared with the regression replay
//! in `tests/tests/fuzz_regressions.rs`) and asserts `check_sampling`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::sampling::{SAMPLING_LEN, check_sampling, sampling_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(SAMPLING_LEN)];
    if let Err(message) = check_sampling(bytes) {
        panic!("{message}\ninput:\n{}", sampling_code(bytes));
    }
});
