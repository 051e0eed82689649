//! Cross-crate integration tests of barytex live in `tests/`. This library holds the fuzz
//! targets' input decoders ([`fuzz_inputs`]), shared by the cargo-fuzz targets in `fuzz/` and the
//! regression replay in `tests/fuzz_regressions.rs`: they span every crate (up to the glTF
//! loader), so they live here rather than in barytex-testkit, whose users then build only the
//! crates they test. It also compiles the README's example as a doc test, so the front page
//! cannot drift from the API.
#![doc = include_str!("../../README.md")]

pub mod fuzz_inputs;
