//! Fuzz target `environment`: decodes the input with
//! `barytex_tests::fuzz_inputs::environment::environment_geometry` (layout documented there,
//! shared with the regression replay in `tests/tests/fuzz_regressions.rs`) and asserts
//! `check_environment` over the environment maps of `barytex-uv`: totality on any direction and
//! texture coordinate, face selection, round trips within the stated bounds. A failure panics
//! with the violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::environment::{
    ENVIRONMENT_LEN, check_environment, environment_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(ENVIRONMENT_LEN)];
    if let Err(message) = check_environment(bytes) {
        panic!("{message}\ninput:\n{}", environment_code(bytes));
    }
});
