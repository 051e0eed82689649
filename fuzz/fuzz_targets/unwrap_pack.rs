//! Fuzz target `unwrap_pack`: decodes the input with
//! `barytex_tests::fuzz_inputs::unwrap_pack::unwrap_pack_input` (layout documented there, shared
//! with the regression replay in `tests/tests/fuzz_regressions.rs`) into a random or degenerate
//! mesh and unwrap options, and asserts `check_unwrap_pack`: `barytex_unwrap::unwrap` never
//! panics, and its atlas passes the exact checks (no flip, no overlap, inside the square, every
//! triangle in one chart) or the charts do not fit.
#![no_main]

use barytex_tests::fuzz_inputs::unwrap_pack::{UNWRAP_PACK_LEN, check_unwrap_pack};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(UNWRAP_PACK_LEN)];
    if let Err(message) = check_unwrap_pack(bytes) {
        panic!("{message}\ninput bytes: {bytes:?}");
    }
});
