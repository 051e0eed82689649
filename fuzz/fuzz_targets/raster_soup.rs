//! Fuzz target `raster_soup`: arbitrary triangle soups (and watertight fans) through the whole
//! draw call of barytex-raster, and the same vertices as points and as lines. Decodes the input with
//! `barytex_tests::fuzz_inputs::raster_soup` (layout documented there, shared with the
//! regression replay in `tests/tests/fuzz_regressions.rs`) and asserts `check_raster_soup`: no
//! panic, no write outside the target or scissor, every triangle, point and line accounted for,
//! fans covered at most once per pixel.
#![no_main]

use barytex_tests::fuzz_inputs::raster_soup::{
    RASTER_SOUP_LEN, check_raster_soup, raster_soup_code,
};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = &data[..data.len().min(RASTER_SOUP_LEN)];
    if let Err(message) = check_raster_soup(bytes) {
        panic!("{message}\ninput:\n{}", raster_soup_code(bytes));
    }
});
