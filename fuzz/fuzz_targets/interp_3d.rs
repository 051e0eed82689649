//! Fuzz target `interp_3d`: `barycentric_3d` and `inverse_bilinear_3d` on arbitrary f32 bits. Decodes the input with `barytex_tests::fuzz_inputs::interp_3d` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_interp_3d`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::interp_3d::{INTERP_3D_LEN, check_interp_3d, interp_3d_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(INTERP_3D_LEN)];
    if let Err(message) = check_interp_3d(bytes) {
        panic!("{message}\ninput:\n{}", interp_3d_code(bytes));
    }
});
