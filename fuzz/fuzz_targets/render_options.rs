//! Fuzz target `render_options`: a fixed small scene rendered with arbitrary render options. Decodes the input with `barytex_tests::fuzz_inputs::render_options` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_render_options`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::render_options::{
    RENDER_OPTIONS_LEN, check_render_options, render_options_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    barytex_tests::fuzz_inputs::decoder_panics::let_dependency_panics_unwind();
    let bytes = &data[..data.len().min(RENDER_OPTIONS_LEN)];
    if let Err(message) = check_render_options(bytes) {
        panic!("{message}\ninput:\n{}", render_options_code(bytes));
    }
});
