//! Fuzz target `shade`: Phong shading with arbitrary lights, attenuations, spot shapes and lobes. Decodes the input with `barytex_tests::fuzz_inputs::shade` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_shade`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::shade::{SHADE_LEN, check_shade, shade_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(SHADE_LEN)];
    if let Err(message) = check_shade(bytes) {
        panic!("{message}\ninput:\n{}", shade_code(bytes));
    }
});
