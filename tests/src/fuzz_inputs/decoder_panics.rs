//! Letting the image decoders' panics reach the loader's guard under libFuzzer.
//!
//! libFuzzer's panic hook (libfuzzer-sys) aborts on every panic, before any `catch_unwind` can
//! see it. The texture loader runs third-party decoders under a guard that turns their panics
//! into [`TextureError::Decode`](barytex_texture::TextureError::Decode) (zune-jpeg's inverse
//! DCTs and upsampler panic on some corrupt files: zune-image issue #361), so under the fuzzer
//! such a panic would be reported although the loader handles it. [`let_dependency_panics_unwind`]
//! makes the targets that decode images let a panic raised inside a crates.io dependency unwind
//! to that guard; a panic nothing catches still aborts at libFuzzer's top level (its own
//! `catch_unwind` around each input), and a panic anywhere else aborts at once, as before.

use std::sync::Once;
use std::sync::atomic::{AtomicBool, Ordering};

/// Whether a panic at `file` was raised inside a crates.io dependency (a path under Cargo's
/// registry sources), not in this workspace or the standard library.
#[must_use]
pub fn raised_in_dependency(file: &str) -> bool {
    file.replace('\\', "/").contains("/registry/src/")
}

/// Installs, once, a panic hook in front of libFuzzer's: a panic raised inside a crates.io
/// dependency unwinds (the first one is printed as a note: a fuzzer that found such an input
/// hits it thousands of times); every other one goes to the previous hook (libFuzzer's, which
/// prints it and aborts). Call it first in a target that decodes images.
pub fn let_dependency_panics_unwind() {
    static INSTALL: Once = Once::new();
    static NOTED: AtomicBool = AtomicBool::new(false);
    INSTALL.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| match info.location() {
            Some(at) if raised_in_dependency(at.file()) => {
                if !NOTED.swap(true, Ordering::Relaxed) {
                    eprintln!(
                        "note: a dependency panicked at {at}; unwinding to the caller's guard \
                         (further ones not shown)"
                    );
                }
            }
            _ => previous(info),
        }));
    });
}

#[cfg(test)]
mod tests {
    use super::raised_in_dependency;

    #[test]
    fn dependency_paths_are_told_from_the_workspace_and_std() {
        assert!(raised_in_dependency(
            "/root/.cargo/registry/src/index.crates.io-1949cf8c6b5b557f/zune-jpeg-0.5.15/src/idct/avx2.rs"
        ));
        assert!(raised_in_dependency(
            r"C:\Users\ci\.cargo\registry\src\index.crates.io-x\zune-jpeg-0.5.15\src\idct\avx2.rs"
        ));
        assert!(!raised_in_dependency("crates/barytex-texture/src/load.rs"));
        assert!(!raised_in_dependency(
            "/work/main/crates/barytex-texture/src/load.rs"
        ));
        assert!(!raised_in_dependency(
            "/rustc/59807616e1fa2540724bfbac14d7976d7e4a3860/library/core/src/option.rs"
        ));
    }
}
