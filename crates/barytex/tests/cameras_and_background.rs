//! `--camera N` is the document's camera `N` (glTF 2.0 §3.10.2: `cameras[N]`, placed by the first
//! node of the scene that instantiates it), `--list-cameras` lists the document's cameras and
//! where the scene places them, and `--background` sets the clear colour, alpha included.
#![allow(clippy::unwrap_used)]

mod common;

use common::{barytex, gltf_fixture, temp_dir};
use std::path::{Path, PathBuf};

/// The triangle (0, 0, 0), (1, 0, 0), (0, 1, 0) as an embedded buffer.
const TRIANGLE_BUFFER: &str = r#""buffers": [{"byteLength": 36, "uri":
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]"#;

/// A triangle and three cameras whose scene order differs from their document order: node 1
/// places camera 1 first; camera 0 is placed by node 3 (under node 2, which moves it by z + 1)
/// and again later by node 4; camera 2 is placed by no node of the scene.
fn three_cameras_gltf(dir: &Path) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let path = dir.join("cameras.gltf");
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, {TRIANGLE_BUFFER},
  "cameras": [
    {{"name": "near", "type": "perspective", "perspective": {{"yfov": 0.8, "znear": 0.1}}}},
    {{"name": "far", "type": "orthographic",
      "orthographic": {{"xmag": 2, "ymag": 2, "znear": 0.1, "zfar": 20}}}},
    {{"name": "unused", "type": "perspective",
      "perspective": {{"yfov": 0.5, "znear": 0.1, "zfar": 50, "aspectRatio": 1.5}}}}],
  "nodes": [
    {{"mesh": 0}},
    {{"camera": 1, "translation": [0.25, 0.25, 8]}},
    {{"children": [3], "translation": [0, 0, 1]}},
    {{"camera": 0, "translation": [0.25, 0.25, 2]}},
    {{"camera": 0, "translation": [9, 9, 9]}}],
  "scenes": [{{"nodes": [0, 1, 2, 4]}}]}}"#
    );
    std::fs::write(&path, json).unwrap();
    path
}

/// Runs `barytex` and returns (exit code, stdout, stderr).
fn run(args: &[&std::ffi::OsStr]) -> (Option<i32>, String, String) {
    let output = barytex().args(args).output().unwrap();
    (
        output.status.code(),
        String::from_utf8(output.stdout).unwrap(),
        String::from_utf8(output.stderr).unwrap(),
    )
}

/// The one stderr line of a refused command (exit status 1, `barytex: …`, no panic).
#[track_caller]
fn refused_line(args: &[&std::ffi::OsStr]) -> String {
    let (code, _, stderr) = run(args);
    assert_eq!(code, Some(1), "{args:?}: {stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{args:?}: one line expected: {stderr}");
    assert!(lines[0].starts_with("barytex: "), "{stderr}");
    lines[0].to_owned()
}

/// The eye position `--print-camera` reports, as printed.
fn eye(stdout: &str) -> &str {
    let at = stdout
        .find("eye at ")
        .unwrap_or_else(|| panic!("no eye in {stdout}"));
    let rest = &stdout[at + "eye at ".len()..];
    &rest[..=rest.find(')').unwrap()]
}

#[test]
fn camera_n_is_the_documents_camera_n() {
    let dir = temp_dir("camera-index");
    let gltf = three_cameras_gltf(&dir);
    let out = dir.join("out.png");
    let os = std::ffi::OsStr::new;
    let render = |camera: &str| {
        let mut args = vec![
            os("render"),
            gltf.as_os_str(),
            os("--size"),
            os("16x12"),
            os("--print-camera"),
            os("-o"),
            out.as_os_str(),
        ];
        if !camera.is_empty() {
            args.extend([os("--camera"), os(camera)]);
        }
        run(&args)
    };
    // Camera 0 is where its first node in scene order (node 3) puts it, not node 4.
    let (code, stdout, stderr) = render("0");
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("glTF camera 0,"), "{stdout}");
    assert_eq!(eye(&stdout), "(0.25, 0.25, 3)", "{stdout}");
    let (code, stdout, stderr) = render("1");
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("glTF camera 1,"), "{stdout}");
    assert_eq!(eye(&stdout), "(0.25, 0.25, 8)", "{stdout}");
    // Without --camera: the first camera the scene places (node 1's, camera 1).
    let (code, stdout, stderr) = render("");
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("glTF camera 1,"), "{stdout}");

    // A camera the scene never places, and one the document does not have: one line each,
    // naming it, and no "rendering …" announced for nothing.
    let line = refused_line(&[
        os("render"),
        gltf.as_os_str(),
        os("--camera"),
        os("2"),
        os("-o"),
        out.as_os_str(),
    ]);
    assert!(
        line.contains("camera 2") && line.contains("\"unused\"") && line.contains("not placed"),
        "{line}"
    );
    let line = refused_line(&[
        os("render"),
        gltf.as_os_str(),
        os("--camera"),
        os("3"),
        os("-o"),
        out.as_os_str(),
    ]);
    assert!(
        line.contains("camera 3") && line.contains("3 cameras"),
        "{line}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn list_cameras_names_every_document_camera_and_renders_nothing() {
    let dir = temp_dir("list-cameras");
    let gltf = three_cameras_gltf(&dir);
    let out = dir.join("never.png");
    let os = std::ffi::OsStr::new;
    let (code, stdout, stderr) = run(&[
        os("render"),
        gltf.as_os_str(),
        os("--list-cameras"),
        os("-o"),
        out.as_os_str(),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!out.exists(), "--list-cameras rendered");
    assert!(!stdout.contains("rendering"), "{stdout}");
    let line = |n: usize| {
        stdout
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("camera {n} ")))
            .unwrap_or_else(|| panic!("no camera {n} in:\n{stdout}"))
    };
    let near = line(0);
    assert!(
        near.contains("\"near\"")
            && near.contains("perspective")
            && near.contains("node 3")
            && near.contains("(0.25, 0.25, 3)")
            && near.contains("node 4"),
        "{near}"
    );
    let far = line(1);
    assert!(
        far.contains("\"far\"")
            && far.contains("orthographic")
            && far.contains("node 1")
            && far.contains("(0.25, 0.25, 8)"),
        "{far}"
    );
    let unused = line(2);
    assert!(
        unused.contains("\"unused\"")
            && unused.contains("perspective")
            && unused.contains("not placed"),
        "{unused}"
    );
    assert!(
        stdout.contains("default: camera 1"),
        "the default camera is named: {stdout}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn list_cameras_on_the_cameras_sample_and_the_demo() {
    if let Some(model) = gltf_fixture("Cameras/glTF/Cameras.gltf") {
        let (code, stdout, stderr) = run(&[
            std::ffi::OsStr::new("render"),
            model.as_os_str(),
            std::ffi::OsStr::new("--list-cameras"),
        ]);
        assert_eq!(code, Some(0), "{stderr}");
        let cameras: Vec<&str> = stdout
            .lines()
            .filter(|l| l.trim_start().starts_with("camera "))
            .collect();
        assert_eq!(cameras.len(), 2, "{stdout}");
        assert!(
            cameras[0].contains("perspective") && cameras[0].contains("node 1"),
            "{stdout}"
        );
        assert!(
            cameras[1].contains("orthographic") && cameras[1].contains("node 2"),
            "{stdout}"
        );
    }
    let (code, stdout, stderr) = run(&[
        std::ffi::OsStr::new("demo"),
        std::ffi::OsStr::new("--list-cameras"),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stdout.contains("camera 0 \"demo\"") && stdout.contains("perspective"),
        "{stdout}"
    );
}

fn rgba_image(path: &Path) -> barytex_texture::Texture2d<barytex_texture::Srgba8> {
    use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_path};
    match load_from_path(path, ColorSpace::Srgb, &barytex_texture::Limits::default()).unwrap() {
        AnyTexture2d::Srgba8(t) => t,
        other => panic!("unexpected format {:?}", other.size()),
    }
}

#[test]
fn a_transparent_background_leaves_coverage_in_alpha() {
    let dir = temp_dir("background");
    std::fs::create_dir_all(&dir).unwrap();
    let gltf = dir.join("triangle.gltf");
    std::fs::write(
        &gltf,
        format!(
            r#"{{"asset": {{"version": "2.0"}}, {TRIANGLE_BUFFER},
              "nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}]}}"#
        ),
    )
    .unwrap();
    let os = std::ffi::OsStr::new;
    for (background, corner) in [
        ("#00000000", [0, 0, 0, 0]),
        ("0,0,0,0", [0, 0, 0, 0]),
        ("#ff8000", [255, 128, 0, 255]),
        ("10, 20, 30, 128", [10, 20, 30, 128]),
    ] {
        let out = dir.join("out.png");
        let (code, _, stderr) = run(&[
            os("render"),
            gltf.as_os_str(),
            os("--size"),
            os("32x32"),
            os("--shading"),
            os("unlit"),
            os("--background"),
            os(background),
            os("-o"),
            out.as_os_str(),
        ]);
        assert_eq!(code, Some(0), "{background}: {stderr}");
        let image = rgba_image(&out);
        let at = |x, y| -> [u8; 4] { image.texel(x, y).unwrap().into() };
        // Nothing is drawn in the corners; the automatic camera centres the triangle, whose
        // centroid is inside it: drawn, opaque (the default material, white).
        for (x, y) in [(0, 0), (31, 0), (31, 31)] {
            assert_eq!(at(x, y), corner, "{background} at ({x}, {y})");
        }
        assert_eq!(
            at(13, 18),
            [255, 255, 255, 255],
            "{background} on the model"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_backgrounds_are_refused_with_one_line() {
    let os = std::ffi::OsStr::new;
    for bad in [
        "#12345",
        "#1234567",
        "#gg0000",
        "123456",
        "256,0,0",
        "1,2",
        "1,2,3,4,5",
        "-1,0,0",
        "1.5,0,0",
        "red",
        "",
        "#",
    ] {
        for command in ["render", "demo"] {
            let mut args = vec![os(command)];
            if command == "render" {
                args.push(os("never-read.gltf"));
            }
            args.extend([os("--background"), os(bad), os("-o"), os("never.png")]);
            let line = refused_line(&args);
            assert!(line.contains("background"), "{bad}: {line}");
            assert!(!Path::new("never.png").exists());
        }
    }
}

/// The default background is documented in `--help` as the sRGB colour the PNG shows.
#[test]
fn the_default_background_is_in_the_help() {
    let default = barytex_render::RenderOptions::default().background;
    let byte = |v: f32| barytex_texture::srgb::encode(v);
    let hex = format!(
        "#{:02x}{:02x}{:02x}",
        byte(default.x),
        byte(default.y),
        byte(default.z)
    );
    for command in ["render", "demo"] {
        let (code, stdout, _) = run(&[std::ffi::OsStr::new(command), "--help".as_ref()]);
        assert_eq!(code, Some(0));
        assert!(
            stdout.contains("--background") && stdout.contains(&hex),
            "{command} --help names {hex}: {stdout}"
        );
    }
}
