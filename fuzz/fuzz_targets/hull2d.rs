//! Fuzz target `hull2d`: decodes the input with `barytex_tests::fuzz_inputs::hull2d::hull2d_points`
//! (layout documented there, shared with the regression replay in `tests/tests/fuzz_regressions.rs`)
//! and asserts `barytex_tests::fuzz_inputs::hull2d::check_hull2d`: both collinear policies give
//! an exactly valid hull (or the typed error for non-finite points), consistent with each other
//! and, for small inputs, equal to the brute-force rational hull. A failure panics with the
//! violated invariant and the input as a Rust block to paste into a regression test.
#![no_main]

use barytex_tests::fuzz_inputs::hull2d::{HULL2D_LEN, check_hull2d, hull2d_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(HULL2D_LEN)];
    if let Err(message) = check_hull2d(bytes) {
        panic!("{message}\ninput:\n{}", hull2d_code(bytes));
    }
});
