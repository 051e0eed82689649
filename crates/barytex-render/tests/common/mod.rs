//! Shared helpers for the renderer's integration tests: the sample fixtures.
#![allow(dead_code, unreachable_pub, unused_imports)]

use std::path::PathBuf;

/// The shared fixtures folder ([`barytex_testkit::fixtures_dir`]: `$BARYTEX_FIXTURES` or
/// `../shared/fixtures`); `None`, with a printed note, when it is absent.
#[must_use]
pub fn fixtures() -> Option<PathBuf> {
    let dir = barytex_testkit::fixtures_dir();
    if dir.is_none() {
        println!("note: fixtures folder absent, test skipped");
    }
    dir
}

pub use barytex_testkit::sample_models;
