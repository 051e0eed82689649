//! `barytex uv-layout FILE`: one picture per textured primitive, drawn over its texture.
#![allow(clippy::unwrap_used)]

mod common;

use common::{barytex, gltf_fixture, temp_dir};
use std::path::{Path, PathBuf};

fn rgba_at(path: &Path, x: u32, y: u32) -> [u8; 4] {
    use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_path};
    let picture = load_from_path(path, ColorSpace::Srgb, &barytex_texture::Limits::default());
    match picture.unwrap() {
        AnyTexture2d::Srgba8(t) => t.texel(x, y).unwrap().into(),
        other => panic!("unexpected format {:?}", other.size()),
    }
}

#[test]
fn a_gltf_file_gets_one_picture_per_textured_primitive_over_its_texture() {
    let Some(file) = gltf_fixture("Avocado/glTF/Avocado.gltf") else {
        return;
    };
    let dir = temp_dir("avocado");
    let output = barytex()
        .arg("uv-layout")
        .arg(&file)
        .args(["--size", "256", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let pictures: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(pictures.len(), 1, "{pictures:?}");
    assert!(stdout.contains("682 triangles"), "{stdout}");
    assert!(stdout.contains("uv range"), "{stdout}");
    // The avocado's base colour texture fills its corners (dark green), not the checker's grey.
    let corner = rgba_at(&pictures[0], 10, 244).map(i32::from);
    assert!(
        corner[1] > corner[0] + 20 && corner[1] > corner[2] + 20,
        "corner {corner:?} is not the texture's green"
    );
    // The white margin stays white.
    assert_eq!(rgba_at(&pictures[0], 0, 0), [255, 255, 255, 255]);
}

#[test]
fn texture_transforms_move_the_layout() {
    let Some(file) = gltf_fixture("TextureTransformTest/glTF/TextureTransformTest.gltf") else {
        return;
    };
    let dir = temp_dir("transform");
    let output = barytex()
        .arg("uv-layout")
        .arg(&file)
        .args(["--size", "64", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    // "Offset U" shifts the quad's uvs by 0.5 in u: its layout is the unit square's right half.
    let offset_u = stdout
        .lines()
        .skip_while(|l| !l.contains("Offset_U-"))
        .nth(1)
        .unwrap_or_default();
    assert!(
        offset_u.contains("[0.500, 1.000] × [0.000, 0.500]"),
        "{stdout}"
    );
}

#[test]
fn bad_uv_layout_input_is_an_error_not_a_panic() {
    let dir = temp_dir("bad");
    std::fs::create_dir_all(&dir).unwrap();
    let not_gltf = dir.join("not.gltf");
    std::fs::write(&not_gltf, b"{ this is not json").unwrap();
    // A regular file where an output folder should be.
    let blocker = dir.join("blocker");
    std::fs::write(&blocker, b"").unwrap();
    let under_blocker = blocker.join("out");
    let cases: Vec<Vec<std::ffi::OsString>> = vec![
        vec!["uv-layout".into()],
        vec!["uv-layout".into(), "--mesh".into(), "teapot".into()],
        vec![
            "uv-layout".into(),
            "--mesh".into(),
            "plane".into(),
            "-o".into(),
            under_blocker.join("plane.png").into(),
        ],
        vec!["uv-layout".into(), dir.join("missing.gltf").into()],
        vec!["uv-layout".into(), not_gltf.clone().into()],
        vec![
            "uv-layout".into(),
            not_gltf.into(),
            "--mesh".into(),
            "sphere".into(),
        ],
    ];
    for args in cases {
        let output = barytex().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "{args:?} succeeded");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(!stderr.trim().is_empty(), "{args:?}: no message");
    }
    if let Some(file) = gltf_fixture("Avocado/glTF/Avocado.gltf") {
        let output = barytex()
            .arg("uv-layout")
            .arg(file)
            .arg("-o")
            .arg(&under_blocker)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            !output.status.success() && !stderr.contains("panicked"),
            "{stderr}"
        );
        assert!(
            stderr.contains("blocker"),
            "the message names the folder: {stderr}"
        );
    }
}

#[test]
fn a_closed_stdout_ends_quietly() {
    // `barytex … | head`: the reader has gone before the first line is printed. Commands that
    // print with `println!` end as if by SIGPIPE; those that write through `io::Write` report
    // the error in one line. Neither panics.
    let dir = temp_dir("pipe");
    let out = dir.join("plane.png");
    for (args, code) in [
        (vec!["examples"], 1),
        (
            vec![
                "uv-layout",
                "--mesh",
                "plane",
                "--size",
                "16",
                "-o",
                out.to_str().unwrap(),
            ],
            141,
        ),
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let output = barytex().args(&args).stdout(writer).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert_eq!(output.status.code(), Some(code), "{args:?}: {stderr}");
    }
}
