//! What the command's end-to-end tests share: the binary, scratch folders and the glTF sample
//! models.
#![allow(dead_code)] // Each test file uses its part.

use std::path::PathBuf;
use std::process::Command;

/// The `barytex` binary under test.
pub(crate) fn barytex() -> Command {
    Command::new(env!("CARGO_BIN_EXE_barytex"))
}

/// A fresh directory under the system's temporary directory, unique to this process and name.
pub(crate) fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("barytex-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// A glTF sample model under the shared fixtures (`barytex_testkit::fixtures_dir`); `None`, with
/// a note, when it is absent.
pub(crate) fn gltf_fixture(relative: &str) -> Option<PathBuf> {
    let path = barytex_testkit::fixtures_dir()
        .map(|dir| dir.join("gltf").join(relative))
        .filter(|path| path.exists());
    if path.is_none() {
        println!("note: fixture gltf/{relative} absent, test skipped");
    }
    path
}
