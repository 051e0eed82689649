//! End-to-end tests of the `barytex` command: the demo and `report --quick`.
#![allow(clippy::unwrap_used)]

use std::path::PathBuf;
use std::process::Command;

fn barytex() -> Command {
    Command::new(env!("CARGO_BIN_EXE_barytex"))
}

/// A fresh directory under the system's temporary directory, unique to this process and name.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("barytex-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn demo_prints_the_seed_examples() {
    let output = barytex().output().unwrap();
    assert!(output.status.success(), "exit status {:?}", output.status);
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.contains("Examples 7 and 9"), "{stdout}");
    // Example 9's point (1, 0) with the seed's exact weights (5/7, −1/7, 3/7), and its location.
    let row = stdout
        .lines()
        .find(|l| l.trim_start().starts_with("(1, 0)") && l.contains("(5/7, -1/7, 3/7)"))
        .unwrap_or_else(|| panic!("no Example 9 row in:\n{stdout}"));
    assert!(row.contains("Outside"), "{row}");
    assert!(
        stdout.contains("(3/2, 3/2)") && stdout.contains("(5/14, 3/7, 3/14)"),
        "{stdout}"
    );
    assert!(stdout.contains("Example 10"), "{stdout}");
    assert!(stdout.contains("Kettner"), "{stdout}");
    assert!(stdout.contains("barytex report"), "{stdout}");
}

#[test]
fn quick_report_writes_every_family() {
    let dir = temp_dir("report");
    let output = barytex()
        .args(["report", "--quick", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        output.status.success(),
        "exit status {:?}\n{stderr}",
        output.status
    );
    let index = std::fs::read_to_string(dir.join("README.md")).unwrap();
    let interp = std::fs::read_to_string(dir.join("interp.md")).unwrap();
    assert!(index.contains("interp.md"), "{index}");
    for heading in [
        "## 2D barycentric",
        "## 3D barycentric",
        "## Orientation",
        "## Inverse bilinear",
        "## SLERP family",
        "## 2D convex hull",
        "## UV mappings",
        "## UV distortion",
    ] {
        assert!(interp.contains(heading), "missing {heading:?}");
    }
    let texture = std::fs::read_to_string(dir.join("texture.md")).unwrap();
    assert!(index.contains("texture.md"), "{index}");
    for heading in [
        "## Texture filters",
        "### checkerboard plane at a grazing angle",
        "### fine text",
        "### rotated stripes",
        "texture-filters-grazing.png",
    ] {
        assert!(texture.contains(heading), "missing {heading:?}");
    }
    let strip = std::fs::read(dir.join("texture-filters-grazing.png")).unwrap();
    assert!(strip.starts_with(b"\x89PNG"), "not a PNG");
    // One progress line per family on stderr.
    for family in [
        "2D barycentric",
        "3D barycentric",
        "orientation",
        "inverse bilinear",
    ] {
        assert!(
            stderr.contains(family),
            "no progress for {family}:\n{stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn uv_layout_writes_a_png_of_the_requested_size() {
    let dir = temp_dir("uv-layout");
    let out = dir.join("torus.png");
    let output = barytex()
        .args(["uv-layout", "--mesh", "torus", "--size", "96", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.status.success(), "exit status {:?}", output.status);
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("wrote") && stdout.contains("torus.png"),
        "{stdout}"
    );
    assert!(stdout.contains("distortion"), "{stdout}");
    let png = std::fs::read(&out).unwrap();
    // The PNG signature, then IHDR's width and height (big-endian).
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |at: usize| u32::from_be_bytes(png[at..at + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (96, 96));
    // A zero size is refused with a message, not a panic.
    let refused = barytex()
        .args(["uv-layout", "--mesh", "cube", "--size", "0", "--out"])
        .arg(dir.join("never.png"))
        .output()
        .unwrap();
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("out of range"));
    let _ = std::fs::remove_dir_all(&dir);
}
