//! `barytex demo|render` prints the time of every stage; `--stats` splits rasterization from
//! shading.
#![allow(clippy::unwrap_used)]

mod common;

use common::{barytex, temp_dir};

fn stages_line(extra: &[&str]) -> String {
    let dir = temp_dir("stages");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("demo.png");
    let output = barytex()
        .args(["demo", "--size", "64x36", "-o"])
        .arg(&out)
        .args(extra)
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(output.status.success(), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
    stdout
        .lines()
        .find(|l| l.starts_with("stages: "))
        .unwrap_or_else(|| panic!("no stages line in:\n{stdout}"))
        .to_owned()
}

/// The milliseconds after `name ` in the stages line.
fn milliseconds(line: &str, name: &str) -> f64 {
    let rest = line
        .split(", ")
        .find_map(|part| part.trim_start_matches("stages: ").strip_prefix(name))
        .unwrap_or_else(|| panic!("no `{name}` in {line}"));
    rest.trim().trim_end_matches(" ms").parse().unwrap()
}

#[test]
fn every_stage_is_timed() {
    let plain = stages_line(&[]);
    for stage in [
        "load ",
        "decode ",
        "prepare ",
        "mips ",
        "target ",
        "raster + shade ",
        "encode + write ",
    ] {
        assert!(milliseconds(&plain, stage) >= 0.0, "{plain}");
    }
    let split = stages_line(&["--stats"]);
    let (raster, shade) = (
        milliseconds(&split, "raster "),
        milliseconds(&split, "shade "),
    );
    assert!(raster > 0.0 && shade >= 0.0, "{split}");
}

#[test]
fn frames_draws_the_prepared_scene_again_and_again() {
    let dir = temp_dir("frames");
    std::fs::create_dir_all(&dir).unwrap();
    let run = |frames: &str, name: &str| {
        let out = dir.join(name);
        let output = barytex()
            .args(["demo", "--size", "48x27", "--frames", frames, "-o"])
            .arg(&out)
            .output()
            .unwrap();
        let stdout = String::from_utf8(output.stdout).unwrap();
        let stderr = String::from_utf8(output.stderr).unwrap();
        (output.status.success(), stdout, stderr, out)
    };
    let (ok, once, _, single) = run("1", "one.png");
    assert!(ok, "{once}");
    assert!(!once.contains("frames:"), "{once}");
    let (ok, stdout, _, last) = run("4", "four.png");
    assert!(ok, "{stdout}");
    let line = stdout
        .lines()
        .find(|l| l.starts_with("frames: 4, draw"))
        .unwrap_or_else(|| panic!("no frames line in:\n{stdout}"));
    assert!(line.contains("of the 3 after it median"), "{line}");
    // The last of four draws is the image of a single one.
    assert_eq!(
        std::fs::read(&single).unwrap(),
        std::fs::read(&last).unwrap()
    );
    for bad in ["0", "1001", "x"] {
        let (ok, _, stderr, _) = run(bad, "bad.png");
        assert!(!ok && stderr.contains("from 1 to 1000"), "{bad}: {stderr}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
