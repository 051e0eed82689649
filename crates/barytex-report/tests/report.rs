//! End-to-end tests of `barytex-report --quick`: every family's section and page is written,
//! every speed-vs-error chart is written, linked from its page and well-formed enough to be an
//! SVG, and the progress bar stays off a stderr that is not a terminal.
#![allow(clippy::unwrap_used)]

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The `barytex-report` binary under test.
fn barytex_report() -> Command {
    Command::new(env!("CARGO_BIN_EXE_barytex-report"))
}

/// A fresh directory under the system's temporary directory, unique to this process and name.
fn temp_dir(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("barytex-report-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The targets of the Markdown image links `![…](target)` of `page`.
fn image_links(page: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = page;
    while let Some(at) = rest.find("![") {
        rest = &rest[at + 2..];
        let Some(close) = rest.find("](") else { break };
        let after = &rest[close + 2..];
        let Some(end) = after.find(')') else { break };
        out.push(after[..end].to_owned());
        rest = &after[end..];
    }
    out
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn quick_report_writes_every_family() {
    let dir = temp_dir("report");
    let output = barytex_report()
        .args(["--quick", "--out"])
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
    // Observations are sentences computed from the figures, one per scene and comparison; the
    // picture strip is not one of them.
    let observations = texture
        .split("Observations (computed from the figures above):")
        .nth(1)
        .expect("texture.md has observations");
    let notes: Vec<&str> = observations
        .lines()
        .take_while(|l| l.is_empty() || l.starts_with("- "))
        .filter(|l| l.starts_with("- "))
        .collect();
    assert_eq!(notes.len(), 6, "{notes:?}");
    assert!(
        notes
            .iter()
            .all(|n| n.contains("trilinear") && !n.contains("![")),
        "{notes:?}"
    );
    let raster = std::fs::read_to_string(dir.join("raster.md")).unwrap();
    assert!(index.contains("raster.md"), "{index}");
    for heading in [
        "## Rasterizer",
        "### perspective interpolation",
        "affine spans of 16 px",
        "### anti-aliasing on a Siemens star",
        "MSAA 4",
        "adaptive",
    ] {
        assert!(raster.contains(heading), "missing {heading:?}");
    }
    let shading = std::fs::read_to_string(dir.join("shading.md")).unwrap();
    assert!(index.contains("shading.md"), "{index}");
    for heading in ["Gouraud", "H-test", "fast approximate Phong", "SLERP"] {
        assert!(shading.contains(heading), "missing {heading:?}");
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
fn quick_report_writes_and_links_the_charts() {
    let dir = temp_dir("charts");
    let output = barytex_report()
        .args(["--quick", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        output.status.success(),
        "exit status {:?}\n{stderr}",
        output.status
    );

    // stderr is a pipe here: the bar is hidden (no escape sequences, no carriage returns), and
    // each family still logs plain lines, numbered over all eleven families.
    assert!(!stderr.contains('\u{1b}'), "terminal escapes:\n{stderr}");
    assert!(!stderr.contains('\r'), "carriage returns:\n{stderr}");
    for line in [
        "[1/11] 2D barycentric …",
        "[8/11] UV distortion: done in",
        "[9/11] texture filters …",
        "[10/11] rasterizer: done in",
        "[11/11] shading: done in",
        "speed-vs-error charts",
    ] {
        assert!(stderr.contains(line), "no {line:?} in:\n{stderr}");
    }

    // Every page links its charts (one per table with an error measure), each file exists.
    let mut linked = BTreeSet::new();
    for (page, prefix, at_least) in [
        ("interp.md", "interp-", 20),
        ("texture.md", "texture-", 3),
        ("raster.md", "raster-", 2),
        ("shading.md", "shading-", 3),
    ] {
        let text = read(&dir, page);
        let charts: Vec<String> = image_links(&text)
            .into_iter()
            .filter(|l| l.ends_with(".svg"))
            .collect();
        assert!(
            charts.len() >= at_least,
            "{page} links {} charts: {charts:?}",
            charts.len()
        );
        for chart in charts {
            assert!(chart.starts_with(prefix), "{page} links {chart}");
            let svg = read(&dir, &chart);
            assert!(
                svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""),
                "{chart}"
            );
            assert!(svg.trim_end().ends_with("</svg>"), "{chart}");
            assert!(svg.contains("class=\"point"), "{chart} has no points");
            assert!(
                svg.contains("(ns)</text>"),
                "{chart} has no time axis label"
            );
            assert!(!svg.contains("NaN\""), "{chart} has a NaN coordinate");
            assert!(linked.insert(chart.clone()), "{chart} linked twice");
        }
    }
    // No chart is written without a link.
    let written: BTreeSet<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".svg"))
        .collect();
    assert_eq!(written, linked);

    // Spot checks: the 2D barycentric chart; orientation's zero wrong signs in the "exact" band;
    // the hull's peers as squares; the shading chart's time per frame.
    let bary = read(&dir, "interp-2d-barycentric-random-well-shaped.svg");
    assert!(bary.contains(">2D barycentric: random well-shaped</text>"));
    assert!(bary.contains(">time per call (ns)</text>"));
    assert!(bary.contains(">max abs error of the weights</text>"));
    assert!(bary.contains("barycentric_2d (default)"));
    let orient = read(&dir, "interp-orientation-random.svg");
    assert!(orient.contains(">0 (exact)</text>"), "{orient}");
    assert!(orient.contains(">wrong signs (count)</text>"));
    let hull = read(&dir, "interp-2d-convex-hull-circle.svg");
    assert!(hull.contains("class=\"point peer\""));
    assert!(hull.contains(">time per input point (ns)</text>"));
    let shading = read(&dir, "shading-shading-frequencies-on-a-16-8-sphere.svg");
    assert!(shading.contains(">time per frame (ns)</text>"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--help` names every page the report writes.
#[test]
fn help_lists_every_page() {
    let output = barytex_report().arg("--help").output().unwrap();
    assert!(output.status.success());
    let help = String::from_utf8_lossy(&output.stdout);
    for page in [
        "README.md",
        "interp.md",
        "texture.md",
        "raster.md",
        "shading.md",
        "texture-filters-grazing.png",
        "SVG",
    ] {
        assert!(help.contains(page), "{page} missing from:\n{help}");
    }
}
