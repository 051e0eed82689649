//! Replays every saved fuzz input of `fuzz/regressions/<target>/` through the same invariant
//! checks as the fuzz target, so a crash found once stays fixed without needing `cargo fuzz`.
//!
//! The byte layouts live in `barytex_tests::fuzz_inputs`, which both the fuzz targets and this
//! test call, so a saved input decodes to the same geometry in both (the `layout_*` tests below
//! pin the decoding of hand-written inputs).
//!
//! Every file of the directory except `README.md` is an input. A missing or empty directory fails
//! the test, so a renamed target or a lost seed is noticed.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use barytex_tests::fuzz_inputs::hull2d::{check_hull2d, hull2d_points};
use barytex_tests::fuzz_inputs::hull3d::{check_hull3d, hull3d_points};
use barytex_tests::fuzz_inputs::polygon::{check_polygon, polygon_geometry};
use barytex_tests::fuzz_inputs::{
    check_inverse_bilinear, check_orient_barycentric, inverse_bilinear_geometry,
    orient_barycentric_geometry,
};
use glam::{Vec2, Vec3};

fn regressions_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz/regressions")
        .join(target)
}

/// Runs `check` on every input file of the target's directory; fails listing every violation.
fn replay(target: &str, check: fn(&[u8]) -> Result<(), String>) {
    let dir = regressions_dir(target);
    let entries =
        std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()));
    let mut files: Vec<PathBuf> = entries
        .map(|entry| entry.expect("directory entry").path())
        .filter(|path| path.is_file() && path.file_name().is_some_and(|n| n != "README.md"))
        .collect();
    files.sort();
    assert!(
        !files.is_empty(),
        "no fuzz inputs in {}: every target keeps at least one seed",
        dir.display()
    );
    let mut failures = String::new();
    for file in &files {
        let bytes = std::fs::read(file).expect("readable input");
        if let Err(message) = check(&bytes) {
            let name = file.file_name().unwrap_or_default().to_string_lossy();
            let _ = writeln!(failures, "fuzz/regressions/{target}/{name}: {message}");
        }
    }
    assert!(
        failures.is_empty(),
        "{target}: invariants violated by saved inputs (of {} replayed):\n{failures}",
        files.len()
    );
    println!("{target}: {} inputs replayed", files.len());
}

#[test]
fn environment_regressions() {
    replay(
        "environment",
        barytex_tests::fuzz_inputs::environment::check_environment,
    );
}

#[test]
fn gltf_loader_regressions() {
    replay(
        "gltf_loader",
        barytex_tests::fuzz_inputs::gltf_loader::check_gltf_loader,
    );
}

#[test]
fn raster_soup_regressions() {
    replay(
        "raster_soup",
        barytex_tests::fuzz_inputs::raster_soup::check_raster_soup,
    );
}

#[test]
fn sampling_regressions() {
    replay(
        "sampling",
        barytex_tests::fuzz_inputs::sampling::check_sampling,
    );
}

#[test]
fn mip_generation_regressions() {
    replay(
        "mip_generation",
        barytex_tests::fuzz_inputs::mip_generation::check_mip_generation,
    );
}

#[test]
fn slerp_regressions() {
    replay("slerp", barytex_tests::fuzz_inputs::slerp::check_slerp);
}

#[test]
fn uv_mappings_regressions() {
    replay(
        "uv_mappings",
        barytex_tests::fuzz_inputs::uv_mappings::check_uv_mappings,
    );
}

#[test]
fn png_jpeg_loader_regressions() {
    replay(
        "png_jpeg_loader",
        barytex_tests::fuzz_inputs::png_jpeg_loader::check_png_jpeg_loader,
    );
}

#[test]
fn render_options_regressions() {
    replay(
        "render_options",
        barytex_tests::fuzz_inputs::render_options::check_render_options,
    );
}

#[test]
fn textures_3d_regressions() {
    replay(
        "textures_3d",
        barytex_tests::fuzz_inputs::textures_3d::check_textures_3d,
    );
}

#[test]
fn interp_3d_regressions() {
    replay(
        "interp_3d",
        barytex_tests::fuzz_inputs::interp_3d::check_interp_3d,
    );
}

#[test]
fn shade_regressions() {
    replay("shade", barytex_tests::fuzz_inputs::shade::check_shade);
}

#[test]
fn load_path_regressions() {
    replay(
        "load_path",
        barytex_tests::fuzz_inputs::load_path::check_load_path,
    );
}

#[test]
fn unwrap_pack_regressions() {
    replay(
        "unwrap_pack",
        barytex_tests::fuzz_inputs::unwrap_pack::check_unwrap_pack,
    );
}

#[test]
fn unwrap_param_regressions() {
    use barytex_tests::fuzz_inputs::unwrap_param::{UNWRAP_TRIANGLES_AT, unwrap_param_input};
    replay(
        "unwrap_param",
        barytex_tests::fuzz_inputs::unwrap_param::check_unwrap_param,
    );
    // Layout: kind 1 (integer grid) reads coordinates modulo 4; extra triangles index modulo
    // the vertex count.
    let mut bytes = vec![1u8, 3, 3, 1];
    for c in [5u32, 6, 7, 0, 1, 2, 4, 4, 4] {
        bytes.extend(c.to_le_bytes());
    }
    bytes.resize(UNWRAP_TRIANGLES_AT, 0);
    bytes.extend([0, 4, 2]);
    let (p, t, o) = unwrap_param_input(&bytes);
    assert_eq!(
        p,
        vec![
            glam::DVec3::new(1.0, 2.0, 3.0),
            glam::DVec3::new(0.0, 1.0, 2.0),
            glam::DVec3::ZERO
        ]
    );
    assert_eq!(t, vec![[0, 1, 2]]);
    assert_eq!(o.method, barytex_unwrap::Method::Tutte);
}

/// `fuzz/max_len` gives every target in `fuzz/fuzz_targets/` the input size its decoder reads
/// (`.ci/run` passes it to libFuzzer as `-max_len`).
#[test]
fn max_len_table_matches_the_decoders() {
    use barytex_tests::fuzz_inputs as f;
    let decoders: &[(&str, usize)] = &[
        ("orient_barycentric", f::ORIENT_BARYCENTRIC_LEN),
        ("inverse_bilinear", f::INVERSE_BILINEAR_LEN),
        ("slerp", f::slerp::SLERP_LEN),
        ("polygon", f::polygon::POLYGON_LEN),
        ("hull2d", f::hull2d::HULL2D_LEN),
        ("hull3d", f::hull3d::HULL3D_LEN),
        ("uv_mappings", f::uv_mappings::UV_MAPPINGS_LEN),
        ("environment", f::environment::ENVIRONMENT_LEN),
        ("sampling", f::sampling::SAMPLING_LEN),
        ("mip_generation", f::mip_generation::MIP_LEN),
        ("raster_soup", f::raster_soup::RASTER_SOUP_LEN),
        ("gltf_loader", f::gltf_loader::GLTF_LEN),
        ("png_jpeg_loader", f::png_jpeg_loader::PNG_JPEG_LEN),
        ("render_options", f::render_options::RENDER_OPTIONS_LEN),
        ("textures_3d", f::textures_3d::TEXTURES_3D_LEN),
        ("interp_3d", f::interp_3d::INTERP_3D_LEN),
        ("shade", f::shade::SHADE_LEN),
        ("load_path", f::load_path::LOAD_PATH_LEN),
        ("unwrap_pack", f::unwrap_pack::UNWRAP_PACK_LEN),
        ("unwrap_param", f::unwrap_param::UNWRAP_PARAM_LEN),
    ];
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz");
    let table = std::fs::read_to_string(fuzz.join("max_len")).expect("fuzz/max_len");
    let table: Vec<(String, usize)> = table
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let mut it = l.split_whitespace();
            let name = it.next().expect("a target").to_owned();
            let len = it.next().and_then(|n| n.parse().ok());
            (
                name,
                len.unwrap_or_else(|| panic!("fuzz/max_len: no length in {l:?}")),
            )
        })
        .collect();
    let mut targets: Vec<String> = std::fs::read_dir(fuzz.join("fuzz_targets"))
        .expect("fuzz/fuzz_targets")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .map(|p| {
            p.file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    targets.sort();
    let mut listed: Vec<String> = table.iter().map(|(t, _)| t.clone()).collect();
    listed.sort();
    assert_eq!(
        listed, targets,
        "fuzz/max_len must list every fuzz target once"
    );
    for (target, len) in &table {
        let want = decoders
            .iter()
            .find(|(t, _)| t == target)
            .unwrap_or_else(|| panic!("{target}: add its decoder's length to this test"))
            .1;
        assert_eq!(*len, want, "fuzz/max_len: {target}");
    }
}

/// The generated glTF seeds reach deep: they load under the fuzz limits with their embedded
/// image, lights, cameras and both primitives (indexed, and non-indexed with a sparse accessor).
#[test]
fn gltf_seeds_load_with_everything() {
    use barytex_gltf::{LoadOptions, load_slice};
    use barytex_tests::fuzz_inputs::gltf_loader::fuzz_limits;
    for name in ["seed-textured-lights.glb", "seed-textured-lights.gltf"] {
        let bytes = std::fs::read(regressions_dir("gltf_loader").join(name)).expect("a seed");
        let options = LoadOptions {
            limits: fuzz_limits(),
            ..LoadOptions::default()
        };
        let scene = load_slice(&bytes, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(scene.lights.len(), 3, "{name}");
        assert_eq!(scene.cameras.len(), 2, "{name}");
        assert_eq!(scene.stats.images_decoded, 1, "{name}");
        assert_eq!(scene.stats.primitives_loaded, 3, "{name}");
        assert!(scene.warnings.is_empty(), "{name}: {:?}", scene.warnings);
    }
    // The render_options scene loads too (it panics otherwise).
    let scene = barytex_tests::fuzz_inputs::render_options::render_options_scene();
    assert_eq!((scene.lights.len(), scene.cameras.len()), (3, 1));
    assert_eq!(scene.stats.images_decoded, 1);
}

#[test]
fn orient_barycentric_regressions() {
    replay("orient_barycentric", check_orient_barycentric);
}

#[test]
fn inverse_bilinear_regressions() {
    replay("inverse_bilinear", check_inverse_bilinear);
}

fn le_words(words: &[u32], mode: Option<u8>) -> Vec<u8> {
    let mut bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    bytes.extend(mode);
    bytes
}

#[test]
fn layout_orient_barycentric() {
    let bits = |x: f32| x.to_bits();
    let words = [1.0, 0.0, 0.0, 0.0, 2.0, 3.0, 3.0, 1.0].map(bits);
    let (p, tri) = orient_barycentric_geometry(&le_words(&words, None));
    assert_eq!(p, Vec2::new(1.0, 0.0));
    assert_eq!(tri, [Vec2::ZERO, Vec2::new(2.0, 3.0), Vec2::new(3.0, 1.0)]);
    // Short input: missing bytes read as zero.
    assert_eq!(
        orient_barycentric_geometry(&[]),
        (Vec2::ZERO, [Vec2::ZERO; 3])
    );
    // Mode 3 with k = +1: c is the midpoint of ab, one ulp up in y.
    let (_, [_, _, c]) = orient_barycentric_geometry(&le_words(&words, Some((17 << 3) | 3)));
    assert_eq!(c, Vec2::new(1.0, 1.5f32.next_up()));
}

#[test]
fn layout_inverse_bilinear() {
    let bits = |x: f32| x.to_bits();
    let words = [0.5, 0.25, 0.0, 0.0, 4.0, 0.0, 5.0, 3.0, 0.0, 2.0].map(bits);
    let quad = [
        Vec2::ZERO,
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(0.0, 2.0),
    ];
    assert_eq!(
        inverse_bilinear_geometry(&le_words(&words, None)),
        (Vec2::new(0.5, 0.25), quad)
    );
    // Mode 1 with k = −1: p is corner x, one ulp down in x.
    let (p, _) = inverse_bilinear_geometry(&le_words(&words, Some((15 << 3) | 1)));
    assert_eq!(p, Vec2::new(-f32::from_bits(1), 0.0));
}

#[test]
fn polygon_regressions() {
    replay("polygon", check_polygon);
    // Layout: p, then `c % 9` vertices, mode byte 72, count byte 73.
    let bits = |x: f32| x.to_bits();
    let words = [0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0].map(bits);
    let mut bytes = le_words(&words, None);
    bytes.resize(73, 0);
    bytes.push(3);
    let (p, polygon) = polygon_geometry(&bytes);
    assert_eq!(p, Vec2::splat(0.5));
    assert_eq!(polygon, [Vec2::ZERO, Vec2::X, Vec2::ONE]);
}

#[test]
fn hull2d_regressions() {
    replay("hull2d", check_hull2d);
    // Layout: grid kind (1) at e = 16 (scale 1) reads byte pairs as integer points.
    assert_eq!(
        hull2d_points(&[(16 << 3) | 1, 3, 0xfe]),
        vec![Vec2::new(3.0, -2.0)]
    );
}

#[test]
fn hull3d_regressions() {
    replay("hull3d", check_hull3d);
    // Layout: mode byte, then whole 12-byte points (a partial point is ignored).
    let mut bytes = vec![0u8];
    for x in [1.0f32, 2.0, 3.0, 4.0] {
        bytes.extend(x.to_bits().to_le_bytes());
    }
    assert_eq!(hull3d_points(&bytes), vec![Vec3::new(1.0, 2.0, 3.0)]);
    // Kind 6 with k = -1: the last point of the line is one ulp down in y.
    let line = hull3d_points(&[(15 << 3) | 6, 33, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    assert_eq!(line, vec![Vec3::new(1.0, 2.0f32.next_down(), 3.0)]);
}
