//! Test support shared by barytex's property tests, fuzz targets, benchmarks and report: it
//! depends only on barytex-interp, -uv and -texture, so a crate's tests build no more than those.
//!
//! - [`strategies`]: proptest strategies for floats (bounded and raw bit patterns), triangles and
//!   quads (well-shaped and near-degenerate), and near-equal perturbations.
//! - [`exact`]: exact-rational reference implementations (every finite float is a rational).
//! - [`reference`](mod@reference): f64 reference implementations where exact ones are impractical.
//! - [`invariants`]: checks that return `Err(description)` instead of panicking, so property
//!   tests and fuzz targets assert exactly the same things; [`invariants_3d`] does the same for
//!   `orient3d` and the 3D convex hull.
//! - [`sphere`]: f64 references for the SLERP family (slices, any dimension).
//! - [`polygon_invariants`]: exact Wachspress references and the generalized-barycentric
//!   invariant check shared by the polygon property tests and the `polygon` fuzz target.
//! - [`seeded`]: a seeded generator and input shapes shared by the benchmarks and the report.
//! - [`uv`](mod@uv): seeded surface points and the finite-difference Jacobian for barytex-uv's
//!   benchmarks and report.
//! - [`sampling_invariants`]: dEQP-style allowed-result boxes for texture lookups.
//! - [`ulp`]: distances in units in the last place.
//! - [`components`]: flatten any interpolable value into `f64` components for comparisons.
#![forbid(unsafe_code)]

pub mod components;
pub mod exact;
pub mod invariants;
pub mod invariants_3d;
pub mod polygon_invariants;
pub mod precise;
pub mod reference;
pub mod sampling_invariants;
pub mod seeded;
pub mod sphere;
pub mod strategies;
pub mod ulp;
pub mod uv;

/// Where the test fixtures live (the Khronos glTF 2.0 sample models and the glTF-Validator test
/// assets, kept outside the repository): `$BARYTEX_FIXTURES`, else `../shared/fixtures` relative
/// to the workspace root. `None` when absent, after printing a note (the tests then skip).
#[must_use]
pub fn fixtures_dir() -> Option<std::path::PathBuf> {
    let dir = std::env::var_os("BARYTEX_FIXTURES")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| {
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/fixtures")
        });
    if !dir.is_dir() {
        println!(
            "note: fixtures folder {} absent, test skipped",
            dir.display()
        );
        return None;
    }
    Some(dir)
}

/// Every `.gltf`/`.glb` of the glTF sample models under [`fixtures_dir`]
/// (`<fixtures>/gltf/<model>/glTF*/`), sorted; empty when the fixtures are absent.
#[must_use]
pub fn sample_models() -> Vec<std::path::PathBuf> {
    let Some(root) = fixtures_dir() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let Ok(models) = std::fs::read_dir(root.join("gltf")) else {
        return out;
    };
    for model in models.flatten() {
        let Ok(variants) = std::fs::read_dir(model.path()) else {
            continue;
        };
        for variant in variants.flatten() {
            if !variant.file_name().to_string_lossy().starts_with("glTF") {
                continue;
            }
            let Ok(files) = std::fs::read_dir(variant.path()) else {
                continue;
            };
            for f in files.flatten() {
                let p = f.path();
                if p.extension().is_some_and(|e| e == "gltf" || e == "glb") {
                    out.push(p);
                }
            }
        }
    }
    out.sort();
    out
}

/// A PNG whose header claims `width × height` 8-bit RGBA and whose only image data is `idat`
/// (hand-made chunks with correct CRCs): its size can be read from the header, but decoding it
/// fails unless `idat` really holds the pixels. For tests of limits checked before decoding.
#[must_use]
pub fn png_with_header(width: u32, height: u32, idat: &[u8]) -> Vec<u8> {
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        let len = u32::try_from(data.len()).expect("a test chunk fits in u32");
        png.extend_from_slice(&len.to_be_bytes());
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        png.extend_from_slice(&body);
        png.extend_from_slice(&crc32(&body).to_be_bytes());
    };
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&width.to_be_bytes());
    ihdr.extend_from_slice(&height.to_be_bytes());
    ihdr.extend_from_slice(&[8, 6, 0, 0, 0]); // 8-bit RGBA, deflate, no filter, no interlace
    chunk(b"IHDR", &ihdr);
    chunk(b"IDAT", idat);
    chunk(b"IEND", &[]);
    png
}

/// CRC-32 (ISO 3309 / IEEE, as PNG chunks use it).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFF_u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}
