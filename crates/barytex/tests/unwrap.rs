//! End-to-end tests of `barytex unwrap`: a fixture unwrapped, re-loaded with barytex-gltf, its
//! new uv set checked exactly (no overlap, no flip, inside the square), every old attribute
//! carried to the split vertices, and the result rendered; a GLB; errors without panics.
#![allow(clippy::unwrap_used)]

mod common;

use std::collections::HashSet;
use std::path::Path;

use barytex_gltf::{LoadOptions, Primitive, load_path};
use barytex_unwrap::overlap::{find_overlaps, orient};
use common::{barytex, gltf_fixture, temp_dir};
use glam::DVec2;

fn only_primitive(path: &Path) -> Primitive {
    let scene = load_path(path, &LoadOptions::default()).unwrap();
    assert_eq!(scene.instances.len(), 1);
    scene.instances[0].mesh.primitives[0].clone()
}

fn bits<const N: usize>(v: [f32; N]) -> [u32; N] {
    v.map(f32::to_bits)
}

/// Unwraps `model` into `dir/out.gltf` and checks the result against the input.
fn unwrap_and_check(model: &Path, dir: &Path, extra: &[&str]) {
    let out = dir.join("out.gltf");
    let stats = dir.join("stats.json");
    let output = barytex()
        .args([
            "unwrap",
            model.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .args(["--size", "512", "--padding", "2", "--stats", "--stats-json"])
        .arg(&stats)
        .args(extra)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(stdout.contains("flips 0"), "{stdout}");
    assert!(dir.join("out-uv-layout.png").exists());
    let before = only_primitive(model);
    let after = only_primitive(&out);
    // The new set is TEXCOORD_1 (the model has TEXCOORD_0), one uv per new vertex.
    assert!(before.tex_coords0.is_some());
    let uvs = after.tex_coords1.as_ref().expect("TEXCOORD_1 written");
    assert_eq!(uvs.len(), after.positions.len());
    assert_eq!(after.triangles.len(), before.triangles.len());
    // Every new vertex is an old one: position, normal, tangent and old uv together.
    let key = |p: &Primitive, i: usize| {
        (
            bits(p.positions[i].to_array()),
            p.normals.as_ref().map(|n| bits(n[i].to_array())),
            p.tangents.as_ref().map(|n| bits(n[i].to_array())),
            p.tex_coords0.as_ref().map(|n| bits(n[i].to_array())),
        )
    };
    let old: HashSet<_> = (0..before.positions.len())
        .map(|i| key(&before, i))
        .collect();
    assert!((0..after.positions.len()).all(|i| old.contains(&key(&after, i))));
    // The same triangles (as position triples, in any order).
    let corners = |p: &Primitive| {
        let mut t: Vec<_> = p
            .triangles
            .iter()
            .map(|t| t.map(|i| bits(p.positions[i as usize].to_array())))
            .collect();
        t.sort_unstable();
        t
    };
    assert_eq!(corners(&before), corners(&after));
    // Exactly: no two triangles of the new layout overlap, none is degenerate or turned the
    // other way (glTF's v runs down, so the layout's counter-clockwise triangles read clockwise
    // here), every uv is in the unit square.
    let uv: Vec<DVec2> = uvs.iter().map(|p| p.as_dvec2()).collect();
    assert!(
        uv.iter()
            .all(|p| p.cmpge(DVec2::ZERO).all() && p.cmple(DVec2::ONE).all())
    );
    let each: Vec<u32> = (0..after.triangles.len() as u32).collect();
    let overlaps = find_overlaps(&uv, &after.triangles, &each);
    assert!(overlaps.is_clean(), "{overlaps:?}");
    if extra.is_empty() {
        // Pairs: the two triangles of a chart share an edge, so their boxes meet and are tested.
        assert!(overlaps.pairs_tested > 0);
    }
    for t in &after.triangles {
        let [a, b, c] = t.map(|i| uv[i as usize]);
        assert!(orient(a, b, c) < 0.0);
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(json["exact_flips"], 0);
    assert_eq!(json["exact_overlaps"], 0);
    assert!(json["meshes"][0]["efficiency"].as_f64().unwrap() > 0.2);
    // The renderer takes the result as it is (its own folder only).
    let png = dir.join("render.png");
    let render = barytex()
        .args(["render", out.to_str().unwrap(), "--size", "64x48", "-o"])
        .arg(&png)
        .output()
        .unwrap();
    assert!(
        render.status.success(),
        "{}",
        String::from_utf8_lossy(&render.stderr)
    );
    assert!(png.exists());
}

#[test]
fn suzanne_unwraps_into_a_valid_second_uv_set_and_renders() {
    let Some(model) = gltf_fixture("Suzanne/glTF/Suzanne.gltf") else {
        return;
    };
    let dir = temp_dir("unwrap-suzanne");
    unwrap_and_check(&model, &dir, &[]);
    // The textures and the old buffer were copied beside the output.
    assert!(dir.join("Suzanne_BaseColor.png").exists() && dir.join("Suzanne.bin").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn avocado_unwraps_per_triangle() {
    let Some(model) = gltf_fixture("Avocado/glTF/Avocado.gltf") else {
        return;
    };
    let dir = temp_dir("unwrap-avocado");
    unwrap_and_check(&model, &dir, &["--method", "per-triangle"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_glb_is_written_when_asked_for_from_gltf_and_from_glb() {
    let dir = temp_dir("unwrap-to-glb");
    std::fs::create_dir_all(&dir).unwrap();
    for (fixture, uv_set) in [
        ("Suzanne/glTF/Suzanne.gltf", 1),
        ("Box/glTF-Binary/Box.glb", 0),
    ] {
        let Some(model) = gltf_fixture(fixture) else {
            continue;
        };
        let out = dir.join(format!("out-{uv_set}.glb"));
        let output = barytex()
            .args(["unwrap", model.to_str().unwrap(), "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{fixture}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        // One file holds the JSON and every new array: no .bin beside it.
        assert!(!dir.join(format!("out-{uv_set}-uv.bin")).exists());
        let bytes = std::fs::read(&out).unwrap();
        assert_eq!(&bytes[..4], b"glTF");
        assert_eq!(
            u32::from_le_bytes(bytes[8..12].try_into().unwrap()) as usize,
            bytes.len()
        );
        let before = only_primitive(&model);
        let after = only_primitive(&out);
        let uvs = if uv_set == 1 {
            after.tex_coords1.as_ref()
        } else {
            after.tex_coords0.as_ref()
        };
        assert_eq!(uvs.unwrap().len(), after.positions.len(), "{fixture}");
        assert_eq!(after.triangles.len(), before.triangles.len(), "{fixture}");
        if uv_set == 1 {
            // The old uvs of a .gltf input still load, bit for bit (their buffer moved to 1).
            let old = |p: &Primitive| p.tex_coords0.clone().unwrap();
            assert_eq!(old(&before).len(), before.positions.len());
            assert!(old(&after).iter().all(|uv| old(&before).contains(uv)));
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_glb_unwraps_with_its_binary_chunk_written_out() {
    let Some(model) = gltf_fixture("Box/glTF-Binary/Box.glb") else {
        return;
    };
    let dir = temp_dir("unwrap-glb");
    let out = dir.join("box.gltf");
    let output = barytex()
        .args([
            "unwrap",
            model.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let before = only_primitive(&model);
    let after = only_primitive(&out);
    // Box has no uvs: the new set is TEXCOORD_0.
    assert!(before.tex_coords0.is_none());
    assert_eq!(
        after.tex_coords0.as_ref().unwrap().len(),
        after.positions.len()
    );
    assert_eq!(after.triangles.len(), before.triangles.len());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_unwrap_input_is_an_error_not_a_panic() {
    let dir = temp_dir("unwrap-errors");
    std::fs::create_dir_all(&dir).unwrap();
    let missing = dir.join("missing.gltf");
    let mut cases: Vec<(Vec<String>, &str)> = vec![
        (
            vec!["unwrap".into(), missing.display().to_string()],
            "missing.gltf",
        ),
        (
            vec![
                "unwrap".into(),
                "--mesh".into(),
                "torus".into(),
                "--size".into(),
                "0".into(),
            ],
            "size",
        ),
        (
            vec![
                "unwrap".into(),
                "--mesh".into(),
                "torus".into(),
                "--size".into(),
                "16".into(),
                "--padding".into(),
                "4".into(),
                "--method".into(),
                "per-triangle".into(),
            ],
            "do not fit",
        ),
        (
            ["unwrap", "--mesh", "torus", "--cone", "0"]
                .map(String::from)
                .to_vec(),
            "--cone <DEGREES>",
        ),
        (
            ["unwrap", "--mesh", "torus", "--cone", "NaN"]
                .map(String::from)
                .to_vec(),
            "above 0 and at most 180",
        ),
        (
            ["unwrap", "--mesh", "torus", "--max-angle-distortion", "0.5"]
                .map(String::from)
                .to_vec(),
            "--max-angle-distortion <RATIO>",
        ),
    ];
    if let Some(model) = gltf_fixture("Suzanne/glTF/Suzanne.gltf") {
        let m = model.display().to_string();
        let o = dir.join("o.obj").display().to_string();
        cases.push((
            vec!["unwrap".into(), m.clone(), "-o".into(), o],
            "writes .gltf",
        ));
        let o = dir.join("o.gltf").display().to_string();
        cases.push((
            vec![
                "unwrap".into(),
                m,
                "-o".into(),
                o,
                "--uv-set".into(),
                "3".into(),
            ],
            "without gaps",
        ));
    }
    for (args, expected) in cases {
        let output = barytex().current_dir(&dir).args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "{args:?} succeeded");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_built_in_mesh_unwraps_and_draws_its_layout() {
    let dir = temp_dir("unwrap-torus");
    std::fs::create_dir_all(&dir).unwrap();
    let layout = dir.join("torus.png");
    let output = barytex()
        .args(["unwrap", "--mesh", "torus", "--stats", "--layout"])
        .arg(&layout)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    assert!(
        stdout.contains("flips 0") && stdout.contains("0 overlapping pairs"),
        "{stdout}"
    );
    assert!(layout.exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// The number after `charts ` in `--stats` output.
fn chart_count(stdout: &str) -> usize {
    let rest = &stdout[stdout.find("  charts ").unwrap() + 9..];
    rest[..rest.find(',').unwrap()].parse().unwrap()
}

#[test]
fn a_smaller_cone_gives_more_flatter_charts() {
    let dir = temp_dir("unwrap-cone");
    std::fs::create_dir_all(&dir).unwrap();
    let layout = dir.join("sphere.png");
    let run = |cone: &str| {
        let output = barytex()
            .args(["unwrap", "--mesh", "sphere", "--stats", "--cone", cone])
            .arg("--layout")
            .arg(&layout)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
        assert!(output.status.success(), "{stdout}");
        assert!(stdout.contains("flips 0"), "{stdout}");
        chart_count(&stdout)
    };
    let (narrow, wide) = (run("30"), run("85"));
    assert!(narrow > wide, "{narrow} charts at 30°, {wide} at 85°");
    std::fs::remove_dir_all(&dir).ok();
}
