//! Fuzz target `inverse_bilinear`: decodes the input with
//! `barytex_tests::fuzz_inputs::inverse_bilinear_geometry` (layout documented there, shared with the
//! regression replay in `tests/tests/fuzz_regressions.rs`) and asserts
//! `barytex_tests::fuzz_inputs::check_inverse_bilinear`. A failure panics with the violated invariant and
//! the input as a Rust block to paste into a regression test.
#![no_main]

use barytex_tests::fuzz_inputs::{
    INVERSE_BILINEAR_LEN, check_inverse_bilinear, inverse_bilinear_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(INVERSE_BILINEAR_LEN)];
    if let Err(message) = check_inverse_bilinear(bytes) {
        panic!("{message}\ninput:\n{}", inverse_bilinear_code(bytes));
    }
});
