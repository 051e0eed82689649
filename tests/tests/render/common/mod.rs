//! Shared helpers for the renderer's integration tests: the sample fixtures.
#![allow(dead_code, unreachable_pub, unused_imports)]

/// The shared fixtures folder (`$BARYTEX_FIXTURES` or `../shared/fixtures`), and the sample
/// models in it; `None` / empty, with a printed note, when absent.
pub use barytex_testkit::{fixtures_dir as fixtures, sample_models};
