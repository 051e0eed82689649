//! Fuzz target `slerp`: decodes the input with `barytex_tests::fuzz_inputs::slerp::slerp_geometry`
//! (layout documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_slerp` over the whole SLERP family. A
//! failure panics with the violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::slerp::{SLERP_LEN, check_slerp, slerp_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(SLERP_LEN)];
    if let Err(message) = check_slerp(bytes) {
        panic!("{message}\ninput:\n{}", slerp_code(bytes));
    }
});
