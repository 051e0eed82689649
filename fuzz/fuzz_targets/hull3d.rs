//! Fuzz target `hull3d`: decodes the input with
//! `barytex_tests::fuzz_inputs::hull3d::hull3d_points` (layout documented there and in
//! `fuzz/regressions/hull3d/README.md`, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_hull3d`: the exact `orient3d` sign and
//! antisymmetry on the first four points, and the 3D hull's validity (plus the brute-force vertex
//! set for up to 12 points). A failure panics with the violated invariant and the input as a Rust
//! block to paste into a regression test.
#![no_main]

use barytex_tests::fuzz_inputs::hull3d::{HULL3D_LEN, check_hull3d, hull3d_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(HULL3D_LEN)];
    if let Err(message) = check_hull3d(bytes) {
        panic!("{message}\ninput:\n{}", hull3d_code(bytes));
    }
});
