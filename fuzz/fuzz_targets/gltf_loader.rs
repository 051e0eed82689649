//! Fuzz target `gltf_loader`: arbitrary bytes as a glTF or GLB file. Asserts
//! `barytex_tests::fuzz_inputs::gltf_loader::check_gltf_loader` (no panic, no caught panic,
//! accepted scenes render), shared with the regression replay in `tests/tests/fuzz_regressions.rs`.
#![no_main]

use barytex_tests::fuzz_inputs::gltf_loader::{GLTF_LEN, check_gltf_loader, gltf_loader_code};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    barytex_tests::fuzz_inputs::decoder_panics::let_dependency_panics_unwind();
    let bytes = &data[..data.len().min(GLTF_LEN)];
    if let Err(message) = check_gltf_loader(bytes) {
        panic!("{message}\ninput:\n{}", gltf_loader_code(bytes));
    }
});
