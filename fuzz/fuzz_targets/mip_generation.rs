//! Fuzz target `mip_generation`: mip-chain generation for arbitrary sizes (≤ 16×16), filters, colour spaces, alpha-coverage references and level counts. Decodes the input with
//! `barytex_tests::fuzz_inputs::mip_generation` (layout documented there, shared with the regression replay
//! in `tests/tests/fuzz_regressions.rs`) and asserts `check_mip_generation`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::mip_generation::{
    MIP_LEN, check_mip_generation, mip_generation_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(MIP_LEN)];
    if let Err(message) = check_mip_generation(bytes) {
        panic!("{message}\ninput:\n{}", mip_generation_code(bytes));
    }
});
