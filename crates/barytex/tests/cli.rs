//! End-to-end tests of the `barytex` command: the demo scene, `render`, `examples` and
//! `uv-layout`.
#![allow(clippy::unwrap_used)]

mod common;

use common::{barytex, gltf_fixture, temp_dir};
use std::process::Command;

#[test]
fn examples_prints_the_worked_examples() {
    let output = barytex().arg("examples").output().unwrap();
    assert!(output.status.success(), "exit status {:?}", output.status);
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.contains("Examples 7 and 9"), "{stdout}");
    // Example 9's point (1, 0) (Buss 2003, Exercise IV.5) with its exact weights
    // (5/7, −1/7, 3/7), and its location.
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
    // Schaefer's scanline triangle A = (0, 0), B = (1, 5), C = (4, 2): the covered integer
    // points row by row, each with its exact weights (α, β, γ) of A, B, C.
    assert!(stdout.contains("Schaefer"), "{stdout}");
    for (point, weights) in [
        ("(1, 1)", "(2/3, 1/9, 2/9)"),
        ("(1, 2)", "(1/2, 1/3, 1/6)"),
        ("(2, 2)", "(1/3, 2/9, 4/9)"),
        ("(3, 2)", "(1/6, 1/9, 13/18)"),
        ("(1, 3)", "(1/3, 5/9, 1/9)"),
        ("(2, 3)", "(1/6, 4/9, 7/18)"),
        ("(1, 4)", "(1/6, 7/9, 1/18)"),
    ] {
        assert!(
            stdout
                .lines()
                .any(|l| l.trim_start().starts_with(point) && l.contains(weights)),
            "no {point} {weights} row in:\n{stdout}"
        );
    }
    for span in [
        "y = 1: x = 1",
        "y = 2: x = 1 to 3",
        "y = 3: x = 1 to 2",
        "y = 4: x = 1",
    ] {
        assert!(stdout.contains(span), "no span `{span}` in:\n{stdout}");
    }
    assert!(!stdout.contains("does not exist yet"), "{stdout}");
    assert!(stdout.contains("Kettner"), "{stdout}");
    assert!(
        stdout.contains("cargo run --release -p barytex-report"),
        "{stdout}"
    );
}

/// The report is the workspace tool `barytex-report` now: `barytex report …` fails with one line
/// saying how to run it, passing on what was typed, and stays out of the help.
#[test]
fn report_says_where_it_moved() {
    let output = barytex()
        .args(["report", "--quick", "--out", "somewhere"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert!(output.stdout.is_empty());
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(
        stderr.trim_end(),
        "barytex: the speed-vs-error report is the workspace tool barytex-report now; from the \
         repository root run `cargo run --release -p barytex-report -- --quick --out somewhere`"
    );
    let bare = barytex().arg("report").output().unwrap();
    assert!(
        String::from_utf8_lossy(&bare.stderr)
            .contains("run `cargo run --release -p barytex-report`"),
        "{bare:?}"
    );
    let help = barytex().arg("--help").output().unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    assert!(
        help.contains("uv-layout") && !help.contains("report"),
        "{help}"
    );
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

/// `uv-layout --mesh X` without `-o` writes `X.png` into the current folder, as `render` writes
/// `barytex-render.png` there, and creates no folder.
#[test]
fn uv_layout_mesh_writes_into_the_current_folder() {
    let dir = temp_dir("uv-layout-cwd");
    std::fs::create_dir_all(&dir).unwrap();
    let output = barytex()
        .current_dir(&dir)
        .args(["uv-layout", "--mesh", "plane", "--size", "16"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert!(dir.join("plane.png").is_file(), "{output:?}");
    let entries: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(entries, ["plane.png"], "nothing else is created");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `barytex` with no arguments renders the demo scene into the current directory and says where
/// the image went and how long each stage took.
#[test]
fn no_arguments_render_the_demo_scene() {
    let dir = temp_dir("demo");
    std::fs::create_dir_all(&dir).unwrap();
    let output = barytex().current_dir(&dir).output().unwrap();
    assert!(output.status.success(), "exit status {:?}", output.status);
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.contains("stages: load"), "{stdout}");
    let png = dir.join("barytex-demo.png");
    assert!(
        stdout.contains("wrote ") && stdout.contains("barytex-demo.png"),
        "{stdout}"
    );
    let bytes = std::fs::read(&png).expect("the demo image");
    let image = barytex_texture::load::load_from_memory(
        &bytes,
        barytex_texture::load::ColorSpace::Srgb,
        &barytex_texture::Limits::default(),
    )
    .expect("a PNG");
    let barytex_texture::load::AnyTexture2d::Srgba8(image) = image else {
        panic!("an 8-bit RGBA PNG");
    };
    assert_eq!(image.size(), (960, 540));
}

/// `barytex render` on a sample model with every option spelled out; bad options are clear
/// errors with a failing exit status, not panics.
#[test]
fn render_writes_the_file_and_rejects_bad_options() {
    let Some(model) = gltf_fixture("BoxVertexColors/glTF-Binary/BoxVertexColors.glb") else {
        return;
    };
    let dir = temp_dir("render");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("box.png");
    let output = barytex()
        .arg("render")
        .arg(&model)
        .args([
            "--size",
            "64x48",
            "--camera",
            "auto",
            "--shading",
            "unlit",
            "--filter",
            "aniso:4",
            "--aa",
            "msaa:4",
            "--threads",
            "2",
            "--print-camera",
            "--stats",
            "-o",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("automatic camera") && stdout.contains("projection"),
        "{stdout}"
    );
    assert!(stdout.contains("fragments shaded"), "{stdout}");
    assert!(out.is_file());
    for bad in [
        ["--size", "0x10"],
        ["--aa", "msaa:3"],
        ["--filter", "fancy"],
        ["--camera", "7"],
    ] {
        let output = barytex()
            .arg("render")
            .arg(&model)
            .args(bad)
            .arg("-o")
            .arg(dir.join("bad.png"))
            .output()
            .unwrap();
        assert!(!output.status.success(), "{bad:?} should fail");
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(!stderr.contains("panicked"), "{bad:?}: {stderr}");
        assert!(!stderr.is_empty(), "{bad:?}: no message");
    }
}

/// glTFs that claim a 12 GB buffer, a billion-element accessor over a 12-byte buffer, or a
/// billion-element accessor with no buffer at all (zeros) are refused with an error naming the
/// object, before anything that size is allocated: the command runs under a 1 GiB
/// address-space limit (`ulimit -v`), which allocating any of the claims would blow.
#[test]
fn huge_claims_are_refused_under_a_memory_limit() {
    let dir = temp_dir("huge");
    std::fs::create_dir_all(&dir).unwrap();
    let tail = r#""meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
    let accessor = r#""componentType": 5126, "count": 1000000000, "type": "VEC3",
            "min": [0, 0, 0], "max": [1, 1, 1]"#;
    let files = [
        (
            "buffer",
            format!(
                r#"{{"asset": {{"version": "2.0"}},
                "buffers": [{{"byteLength": 12000000000}}],
                "bufferViews": [{{"buffer": 0, "byteLength": 12000000000}}],
                "accessors": [{{"bufferView": 0, {accessor}}}], {tail}"#
            ),
            "/buffers/0",
        ),
        (
            "accessor",
            format!(
                r#"{{"asset": {{"version": "2.0"}},
                "buffers": [{{"byteLength": 12, "uri":
                    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}}],
                "bufferViews": [{{"buffer": 0, "byteLength": 12}}],
                "accessors": [{{"bufferView": 0, {accessor}}}], {tail}"#
            ),
            "/accessors/0",
        ),
        (
            "zeros",
            format!(r#"{{"asset": {{"version": "2.0"}}, "accessors": [{{{accessor}}}], {tail}"#),
            "/accessors/0",
        ),
    ];
    for (name, json, pointer) in files {
        let gltf = dir.join(format!("{name}.gltf"));
        std::fs::write(&gltf, json).unwrap();
        let script = format!(
            "ulimit -v 1048576 && exec '{}' render '{}' --size 16x16 -o '{}'",
            env!("CARGO_BIN_EXE_barytex"),
            gltf.display(),
            dir.join("out.png").display()
        );
        let output = Command::new("bash").args(["-c", &script]).output().unwrap();
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(!output.status.success(), "{name}");
        assert!(
            !stderr.contains("panicked") && !stderr.contains("memory allocation"),
            "{name}: {stderr}"
        );
        assert!(
            stderr.contains(pointer),
            "{name}: the error names {pointer}: {stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// One lit triangle in the z = 0 plane (positions in an embedded buffer), as glTF JSON.
fn triangle_gltf() -> String {
    let mut bytes = Vec::new();
    for v in [0.0_f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    // Base64 by hand (no dependency): 36 bytes, a multiple of 3, so no padding.
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let data: String = bytes
        .chunks(3)
        .flat_map(|c| {
            let n = u32::from(c[0]) << 16 | u32::from(c[1]) << 8 | u32::from(c[2]);
            [18, 12, 6, 0].map(|s| ALPHABET[(n >> s & 63) as usize] as char)
        })
        .collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{data}"}}],
            "bufferViews":[{{"buffer":0,"byteLength":36}}],
            "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    )
}

/// Runs `barytex` with `args`; asserts it fails with exactly one line on stderr, `barytex: …`
/// containing `expect`, and no panic. Returns that line.
#[track_caller]
fn refused(args: &[&std::ffi::OsStr], expect: &str) -> String {
    let output = barytex().args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(!output.status.success(), "{args:?} should fail: {output:?}");
    assert_eq!(output.status.code(), Some(1), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{args:?}: one line expected: {stderr}");
    assert!(
        lines[0].starts_with("barytex: ") && lines[0].contains(expect),
        "{args:?}: expected `barytex: …{expect}…`, got {stderr}"
    );
    lines[0].to_owned()
}

/// `--threads 0` means all cores (rayon's default), not an error and not a panic.
#[test]
fn render_threads_zero_means_all_cores() {
    let dir = temp_dir("threads-zero");
    std::fs::create_dir_all(&dir).unwrap();
    let gltf = dir.join("triangle.gltf");
    std::fs::write(&gltf, triangle_gltf()).unwrap();
    let out = dir.join("out.png");
    let output = barytex()
        .arg("render")
        .arg(&gltf)
        .args(["--size", "32x24", "--threads", "0", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{output:?}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let stdout = String::from_utf8(output.stdout).unwrap();
    let threads: usize = stdout
        .split(" on ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no thread count in {stdout}"));
    assert!(threads >= 1, "{stdout}");
    assert!(out.is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A missing file, a file that is not glTF, a scene index out of range and an output that
/// cannot be written: each a one-line `barytex: …` error, exit status 1, no panic.
#[test]
fn render_refuses_bad_files_scenes_and_outputs() {
    let dir = temp_dir("render-bad");
    std::fs::create_dir_all(&dir).unwrap();
    let gltf = dir.join("triangle.gltf");
    std::fs::write(&gltf, triangle_gltf()).unwrap();
    let out = dir.join("out.png");
    let os = |s: &'static str| std::ffi::OsStr::new(s);
    let size = [os("--size"), os("16x12")];

    let missing = dir.join("no-such-file.gltf");
    let line = refused(
        &[
            os("render"),
            missing.as_os_str(),
            size[0],
            size[1],
            os("-o"),
            out.as_os_str(),
        ],
        "no-such-file.gltf",
    );
    assert!(line.contains("cannot read"), "{line}");
    // The input is checked before the render is announced.
    let output = barytex()
        .arg("render")
        .arg(&missing)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.stdout.is_empty(), "{output:?}");

    let text = dir.join("notes.gltf");
    std::fs::write(&text, "these are not the droids you are looking for\n").unwrap();
    refused(
        &[
            os("render"),
            text.as_os_str(),
            size[0],
            size[1],
            os("-o"),
            out.as_os_str(),
        ],
        "JSON",
    );
    let binary = dir.join("noise.glb");
    std::fs::write(&binary, [0x7f_u8, b'E', b'L', b'F', 2, 1, 1, 0, 0, 0, 0, 0]).unwrap();
    refused(
        &[
            os("render"),
            binary.as_os_str(),
            size[0],
            size[1],
            os("-o"),
            out.as_os_str(),
        ],
        "",
    );

    refused(
        &[
            os("render"),
            gltf.as_os_str(),
            os("--scene"),
            os("5"),
            size[0],
            size[1],
            os("-o"),
            out.as_os_str(),
        ],
        "scene",
    );

    // The output's folder is a regular file: it cannot be created.
    let blocker = dir.join("blocker");
    std::fs::write(&blocker, "a file, not a folder").unwrap();
    let under_file = blocker.join("out.png");
    refused(
        &[
            os("render"),
            gltf.as_os_str(),
            size[0],
            size[1],
            os("-o"),
            under_file.as_os_str(),
        ],
        "cannot create",
    );
    // The output is a folder.
    refused(
        &[
            os("render"),
            gltf.as_os_str(),
            size[0],
            size[1],
            os("-o"),
            dir.as_os_str(),
        ],
        "cannot write",
    );
    // A missing folder is created, not refused.
    let nested = dir.join("new/deeper/out.png");
    let output = barytex()
        .arg("render")
        .arg(&gltf)
        .args(["--size", "16x12", "-o"])
        .arg(&nested)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert!(nested.is_file());
    // The good file with a good output renders (so the refusals above are about what they change).
    let output = barytex()
        .arg("render")
        .arg(&gltf)
        .args(["--size", "16x12", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `uv-layout --size` above 8192 is refused before anything that size is allocated.
#[test]
fn uv_layout_refuses_sizes_above_8192() {
    let dir = temp_dir("uv-layout-huge");
    let out = dir.join("never.png");
    let os = std::ffi::OsStr::new;
    let line = refused(
        &[
            os("uv-layout"),
            os("--mesh"),
            os("sphere"),
            os("--size"),
            os("9000"),
            os("--out"),
            out.as_os_str(),
        ],
        "8192",
    );
    assert!(line.contains("9000"), "{line}");
    assert!(!out.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A triangle in `DIR/model/triangle.gltf` whose positions are in `DIR/shared/triangle.bin`,
/// outside the model's folder: `render` and `uv-layout` refuse the buffer, naming its URI,
/// unless `--allow-dir DIR/shared` opens that folder.
#[test]
fn allow_dir_opens_a_folder_beside_the_model() {
    let dir = temp_dir("allow-dir");
    std::fs::create_dir_all(dir.join("model")).unwrap();
    std::fs::create_dir_all(dir.join("shared")).unwrap();
    let positions: Vec<u8> = [0.0_f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    std::fs::write(dir.join("shared/triangle.bin"), positions).unwrap();
    let gltf = dir.join("model/triangle.gltf");
    std::fs::write(
        &gltf,
        r#"{"asset":{"version":"2.0"},
            "buffers":[{"byteLength":36,"uri":"../shared/triangle.bin"}],
            "bufferViews":[{"buffer":0,"byteLength":36}],
            "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
            "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
            "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#,
    )
    .unwrap();
    let out = dir.join("out.png");
    let shared = dir.join("shared");
    let os = std::ffi::OsStr::new;
    let render = [
        os("render"),
        gltf.as_os_str(),
        os("--size"),
        os("16x12"),
        os("-o"),
        out.as_os_str(),
    ];
    let line = refused(&render, "/buffers/0/uri");
    assert!(line.contains("outside"), "{line}");
    let output = barytex()
        .args(render)
        .args([os("--allow-dir"), shared.as_os_str()])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(out.is_file());

    let layout = [os("uv-layout"), gltf.as_os_str(), os("-o"), dir.as_os_str()];
    refused(&layout, "/buffers/0/uri");
    // Loaded with the folder allowed: the triangle has no uvs, which is the next complaint.
    let with = [layout.as_slice(), &[os("--allow-dir"), shared.as_os_str()]].concat();
    refused(&with, "texture coordinates");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `barytex render /dev/zero` (0 bytes by its metadata, endless when read) is refused at once as
/// not a regular file, under a 1 GiB address-space limit that reading it would blow.
#[cfg(target_os = "linux")]
#[test]
fn render_refuses_a_device() {
    let script = format!(
        "ulimit -v 1048576 && exec timeout 60 '{}' render /dev/zero --size 16x16 -o /dev/null",
        env!("CARGO_BIN_EXE_barytex"),
    );
    let output = Command::new("bash").args(["-c", &script]).output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("not a regular file"), "{stderr}");
}

/// `--threads` above 1024 is refused while parsing, before a thread is spawned: thousands of
/// threads only fail slowly ("Resource temporarily unavailable") and never help.
#[test]
fn render_refuses_more_than_1024_threads() {
    let dir = temp_dir("threads-max");
    std::fs::create_dir_all(&dir).unwrap();
    let gltf = dir.join("triangle.gltf");
    std::fs::write(&gltf, triangle_gltf()).unwrap();
    let out = dir.join("out.png");
    for threads in ["1025", "100000", "18446744073709551615"] {
        let started = std::time::Instant::now();
        let output = barytex()
            .arg("render")
            .arg(&gltf)
            .args(["--size", "8x6", "--threads", threads, "-o"])
            .arg(&out)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "--threads {threads}: {output:?}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(
            stderr.contains(threads) && stderr.contains("1024"),
            "the message should name the value and the maximum: {stderr}"
        );
        assert!(!out.exists(), "--threads {threads} wrote an image");
        assert!(started.elapsed().as_secs() < 10, "{:?}", started.elapsed());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--shading unlit` reads base colours only: a normal map whose file is missing does not refuse
/// the model (it did, before the loader was told which textures the shading reads), while
/// `--shading phong`, which samples it, still does.
#[test]
fn unlit_renders_need_no_normal_map() {
    let dir = temp_dir("unlit-roles");
    std::fs::create_dir_all(&dir).unwrap();
    let positions: Vec<u8> = [0.0_f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    std::fs::write(dir.join("tri.bin"), positions).unwrap();
    let gltf = dir.join("tri.gltf");
    std::fs::write(
        &gltf,
        r#"{"asset":{"version":"2.0"},
            "buffers":[{"byteLength":36,"uri":"tri.bin"}],
            "bufferViews":[{"buffer":0,"byteLength":36}],
            "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                         {"componentType":5126,"count":3,"type":"VEC2"},
                         {"componentType":5126,"count":3,"type":"VEC3"},
                         {"componentType":5126,"count":3,"type":"VEC4"}],
            "images":[{"uri":"missing-normals.png"}],
            "textures":[{"source":0}],
            "materials":[{"normalTexture":{"index":0}}],
            "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1,"NORMAL":2,"TANGENT":3},"material":0}]}],
            "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#,
    )
    .unwrap();
    let out = dir.join("out.png");
    let run = |shading: &str| {
        barytex()
            .arg("render")
            .arg(&gltf)
            .args(["--size", "8x6", "--shading", shading, "-o"])
            .arg(&out)
            .output()
            .unwrap()
    };
    let unlit = run("unlit");
    assert!(
        unlit.status.success(),
        "{}",
        String::from_utf8_lossy(&unlit.stderr)
    );
    let phong = run("phong");
    assert!(!phong.status.success());
    assert!(String::from_utf8_lossy(&phong.stderr).contains("missing-normals.png"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `demo --mirror` draws the view through its mirror (and says so under `--stats`); at
/// `--portal-depth 0` the mirror is closed; a depth beyond 16 is refused before rendering.
#[test]
fn demo_mirror_and_portal_depth() {
    let dir = temp_dir("demo-mirror");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("mirror.png");
    let run = |depth: &str| {
        barytex()
            .args([
                "demo",
                "--mirror",
                "--stats",
                "--size",
                "64x36",
                "--portal-depth",
                depth,
                "-o",
            ])
            .arg(&out)
            .output()
            .unwrap()
    };
    let output = run("4");
    assert!(output.status.success(), "{output:?}");
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("built-in demo scene with a mirror")
            && stdout
                .contains("portals: 1 in the scene, 0 not drawable (degenerate); 1 views drawn"),
        "{stdout}"
    );
    let closed = String::from_utf8(run("0").stdout).unwrap();
    assert!(
        closed.contains("0 views drawn through them, 1 seen closed (at --portal-depth 0)"),
        "{closed}"
    );
    let _ = std::fs::remove_file(&out);
    let output = run("17");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success(), "{output:?}");
    assert!(
        stderr.contains("from 0 to 16") && !stderr.contains("panicked"),
        "{stderr}"
    );
    assert!(!out.exists(), "--portal-depth 17 wrote an image");
    let _ = std::fs::remove_dir_all(&dir);
}
