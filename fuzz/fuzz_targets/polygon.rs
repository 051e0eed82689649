//! Fuzz target `polygon`: decodes the input with
//! `barytex_tests::fuzz_inputs::polygon::polygon_geometry` (layout documented there, shared
//! with the regression replay in `tests/tests/fuzz_regressions.rs`) and asserts
//! `barytex_tests::fuzz_inputs::polygon::check_polygon` (Wachspress and mean value: every
//! documented property, bit-identical rotation invariance). A failure panics with the violated
//! invariant and the input as a Rust block to paste into a regression test.
#![no_main]

use barytex_tests::fuzz_inputs::polygon::{POLYGON_LEN, check_polygon, polygon_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(POLYGON_LEN)];
    if let Err(message) = check_polygon(bytes) {
        panic!("{message}\ninput:\n{}", polygon_code(bytes));
    }
});
