//! Fuzz target `textures_3d`: cube maps, 2D arrays, volumes and comparison sampling with arbitrary descriptors and coordinates. Decodes the input with `barytex_tests::fuzz_inputs::textures_3d` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_textures_3d`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::textures_3d::{
    TEXTURES_3D_LEN, check_textures_3d, textures_3d_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(TEXTURES_3D_LEN)];
    if let Err(message) = check_textures_3d(bytes) {
        panic!("{message}\ninput:\n{}", textures_3d_code(bytes));
    }
});
