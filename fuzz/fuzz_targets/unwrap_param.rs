//! Fuzz target `unwrap_param`: decodes the input with
//! `barytex_tests::fuzz_inputs::unwrap_param::unwrap_param_input` (layout documented there and in
//! `fuzz/regressions/unwrap_param/README.md`, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) — random and degenerate meshes (NaN, duplicate vertices,
//! zero-area and repeated-index triangles, non-manifold edges and vertices, huge and tiny
//! scales, closed surfaces) — and asserts `check_unwrap_param`: `parameterize` never panics,
//! every triangle is in exactly one chart, and no chart has a flipped triangle (exact
//! `orient2d`). A failure panics with the violated invariant and the mesh as Rust code.
#![no_main]

use barytex_tests::fuzz_inputs::unwrap_param::{
    UNWRAP_PARAM_LEN, check_unwrap_param, unwrap_param_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(UNWRAP_PARAM_LEN)];
    if let Err(message) = check_unwrap_param(bytes) {
        panic!("{message}\ninput:\n{}", unwrap_param_code(bytes));
    }
});
