//! Fuzz target `load_path`: a model on disk with fuzzed buffer and image URIs, next to decoys outside its folder. Decodes the input with `barytex_tests::fuzz_inputs::load_path` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_load_path`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::load_path::{LOAD_PATH_LEN, check_load_path, load_path_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    barytex_tests::fuzz_inputs::decoder_panics::let_dependency_panics_unwind();
    let bytes = &data[..data.len().min(LOAD_PATH_LEN)];
    if let Err(message) = check_load_path(bytes) {
        panic!("{message}\ninput:\n{}", load_path_code(bytes));
    }
});
