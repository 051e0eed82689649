//! Fuzz target `orient_barycentric`: decodes the input with
//! `barytex_tests::fuzz_inputs::orient_barycentric_geometry` (layout documented there, shared with the
//! regression replay in `tests/tests/fuzz_regressions.rs`) and asserts
//! `barytex_tests::fuzz_inputs::check_orient_barycentric`. A failure panics with the violated invariant and
//! the input as a Rust block to paste into a regression test.
#![no_main]

use barytex_tests::fuzz_inputs::{
    ORIENT_BARYCENTRIC_LEN, check_orient_barycentric, orient_barycentric_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(ORIENT_BARYCENTRIC_LEN)];
    if let Err(message) = check_orient_barycentric(bytes) {
        panic!("{message}\ninput:\n{}", orient_barycentric_code(bytes));
    }
});
