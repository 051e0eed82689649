//! Cross-crate integration tests of barytex live in `tests/`; this library only compiles the
//! README's example as a doc test, so the front page cannot drift from the API.
#![doc = include_str!("../../README.md")]
