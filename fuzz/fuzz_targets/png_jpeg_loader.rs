//! Fuzz target `png_jpeg_loader`: arbitrary bytes as a PNG or JPEG file, decoded under small limits. Decodes the input with `barytex_tests::fuzz_inputs::png_jpeg_loader` (layout
//! and invariants documented there, shared with the regression replay in
//! `tests/tests/fuzz_regressions.rs`) and asserts `check_png_jpeg_loader`. A failure panics with the
//! violated invariant and the input as a Rust block.
#![no_main]

use barytex_tests::fuzz_inputs::png_jpeg_loader::{
    PNG_JPEG_LEN, check_png_jpeg_loader, png_jpeg_loader_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    barytex_tests::fuzz_inputs::decoder_panics::let_dependency_panics_unwind();
    let bytes = &data[..data.len().min(PNG_JPEG_LEN)];
    if let Err(message) = check_png_jpeg_loader(bytes) {
        panic!("{message}\ninput:\n{}", png_jpeg_loader_code(bytes));
    }
});
