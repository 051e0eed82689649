//! Fuzz target `uv_mappings`: decodes the input with
//! `barytex_tests::fuzz_inputs::uv_mappings::uv_mappings_input` (layout documented there,
//! shared with the regression replay in `tests/tests/fuzz_regressions.rs`) and asserts
//! `check_uv_mappings`: every mapping buildable from the input is total (no NaN inside `Some`,
//! `None` for non-finite input, periodic coordinates in range, `map` is the chain rule), and
//! seam repair keeps its invariants. A failure panics with the violated invariant and the input.
#![no_main]

use barytex_tests::fuzz_inputs::uv_mappings::{
    UV_MAPPINGS_LEN, check_uv_mappings, uv_mappings_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(UV_MAPPINGS_LEN)];
    if let Err(message) = check_uv_mappings(bytes) {
        panic!("{message}\ninput:\n{}", uv_mappings_code(bytes));
    }
});
