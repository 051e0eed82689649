//! Hostile input: random byte flips of valid files never panic, and size claims are refused
//! before anything of that size is allocated.

mod common;

use barytex_gltf::{LoadOptions, SceneError, SceneLimits, load_slice, load_slice_with_base};
use base64::Engine as _;
use proptest::prelude::*;

/// Files that are self-contained (GLB, embedded glTF) and small enough to mutate many times.
fn seeds() -> Vec<(std::path::PathBuf, Vec<u8>)> {
    common::sample_models()
        .into_iter()
        .filter(|p| {
            let s = p.to_string_lossy();
            s.contains("glTF-Binary") || s.contains("glTF-Embedded")
        })
        .filter_map(|p| {
            let bytes = std::fs::read(&p).ok()?;
            (bytes.len() < 400_000).then_some((p, bytes))
        })
        .collect()
}

/// A small deterministic generator (xorshift64*), so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % n.max(1) as u64).unwrap_or(0)
    }
}

fn assert_no_panic(result: &Result<barytex_gltf::Scene, SceneError>, what: &str) {
    if let Err(SceneError::Internal(msg)) = result {
        panic!("{what}: the loader panicked: {msg}");
    }
}

#[test]
fn byte_flips_never_panic() {
    let seeds = seeds();
    let options = LoadOptions::default();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut ok, mut refused) = (0usize, 0usize);
    for (path, bytes) in &seeds {
        let base = path.parent().unwrap_or(path);
        for round in 0..400 {
            let mut m = bytes.clone();
            let flips = 1 + rng.below(8);
            for _ in 0..flips {
                let i = rng.below(m.len());
                match rng.below(4) {
                    0 => m[i] ^= 1 << rng.below(8),
                    1 => m[i] = rng.below(256) as u8,
                    // Digits and structural characters matter most in the JSON.
                    2 => m[i] = b"0123456789-.eE,:[]{}\"9"[rng.below(22)],
                    _ => {
                        let cut = rng.below(m.len());
                        m.truncate(cut.max(1));
                        break;
                    }
                }
            }
            let r = load_slice_with_base(&m, base, &options);
            assert_no_panic(&r, &format!("{} round {round}", path.display()));
            if r.is_ok() { ok += 1 } else { refused += 1 }
        }
    }
    println!(
        "{} seeds, {ok} mutants loaded, {refused} refused, none panicked",
        seeds.len()
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, failure_persistence: None, .. ProptestConfig::default() })]

    /// Arbitrary bytes, raw or behind a GLB header, never panic.
    #[test]
    fn arbitrary_bytes_never_panic(body in proptest::collection::vec(any::<u8>(), 0..512), glb in any::<bool>()) {
        let mut bytes = Vec::new();
        if glb {
            bytes.extend_from_slice(b"glTF");
            bytes.extend_from_slice(&2u32.to_le_bytes());
            bytes.extend_from_slice(&(u32::try_from(body.len() + 12).unwrap_or(0)).to_le_bytes());
        }
        bytes.extend_from_slice(&body);
        let r = load_slice(&bytes, &LoadOptions::default());
        prop_assert!(!matches!(r, Err(SceneError::Internal(_))));
    }
}

/// A triangle mesh whose accessor claims `count` elements (no bufferView: zeros).
fn claimed_accessor(count: u64) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "accessors":[{{"componentType":5126,"count":{count},"type":"VEC3","min":[0,0,0],"max":[0,0,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    )
}

#[test]
fn billion_element_accessor_is_refused_before_allocating() {
    let r = load_slice(
        claimed_accessor(1_000_000_000).as_bytes(),
        &LoadOptions::default(),
    );
    assert!(
        matches!(&r, Err(SceneError::TooLarge { what: "accessor elements", pointer, .. }) if pointer == "/accessors/0/count"),
        "{r:?}"
    );
    // Under the element limit but over the triangle limit: refused from the declared counts.
    let options = LoadOptions {
        limits: SceneLimits {
            max_triangles: 1000,
            ..SceneLimits::default()
        },
        ..LoadOptions::default()
    };
    let r = load_slice(claimed_accessor(30_000).as_bytes(), &options);
    assert!(
        matches!(
            r,
            Err(SceneError::TooLarge {
                what: "triangles",
                ..
            })
        ),
        "{r:?}"
    );
    // A small one loads (zeros, one degenerate triangle).
    let r = load_slice(claimed_accessor(3).as_bytes(), &LoadOptions::default());
    assert!(matches!(r, Ok(ref s) if s.triangle_count() == 1), "{r:?}");
}

#[test]
fn huge_buffer_claim_is_refused() {
    let gltf = r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":1000000000000}]}"#;
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(
            r,
            Err(SceneError::TooLarge {
                what: "buffer bytes",
                ..
            })
        ),
        "{r:?}"
    );
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
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

fn png_chunk(out: &mut Vec<u8>, ty: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&u32::try_from(data.len()).unwrap_or(0).to_be_bytes());
    let mut body = ty.to_vec();
    body.extend_from_slice(data);
    out.extend_from_slice(&body);
    out.extend_from_slice(&crc32(&body).to_be_bytes());
}

#[test]
fn gigantic_png_is_refused_before_decoding() {
    // A PNG header claiming 100000 × 100000 RGBA8 (40 GB decoded), with a token IDAT.
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&100_000u32.to_be_bytes());
    ihdr.extend_from_slice(&100_000u32.to_be_bytes());
    ihdr.extend_from_slice(&[8, 6, 0, 0, 0]);
    png_chunk(&mut png, b"IHDR", &ihdr);
    png_chunk(
        &mut png,
        b"IDAT",
        &[0x78, 0x9C, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01],
    );
    png_chunk(&mut png, b"IEND", &[]);
    let image = base64::engine::general_purpose::STANDARD.encode(&png);
    let gltf = common::textured_triangle(&format!("data:image/png;base64,{image}"));
    let start = std::time::Instant::now();
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Image { pointer, reason }) if pointer == "/images/0" && reason.contains("exceeds")),
        "{r:?}"
    );
    assert!(start.elapsed().as_secs() < 5, "refusal should be immediate");
    // The same file without decoding images loads (the header is well-formed).
    let r = load_slice(
        gltf.as_bytes(),
        &LoadOptions {
            decode_images: false,
            ..LoadOptions::default()
        },
    );
    assert!(r.is_ok(), "{r:?}");
}

#[test]
fn deep_hierarchies_and_cycles_are_refused() {
    let chain: Vec<String> = (0..100)
        .map(|i| {
            if i < 99 {
                format!(r#"{{"children":[{}]}}"#, i + 1)
            } else {
                "{}".to_owned()
            }
        })
        .collect();
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},"nodes":[{}],"scenes":[{{"nodes":[0]}}]}}"#,
        chain.join(",")
    );
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(
            r,
            Err(SceneError::TooLarge {
                what: "node depth",
                ..
            })
        ),
        "{r:?}"
    );
    let cycle = r#"{"asset":{"version":"2.0"},"nodes":[{"children":[1]},{"children":[0]}]}"#;
    let r = load_slice(cycle.as_bytes(), &LoadOptions::default());
    assert!(matches!(r, Err(SceneError::Invalid { .. })), "{r:?}");
    let two_parents =
        r#"{"asset":{"version":"2.0"},"nodes":[{"children":[2]},{"children":[2]},{}]}"#;
    let r = load_slice(two_parents.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Invalid { pointer, .. }) if pointer == "/nodes/1/children/0"),
        "{r:?}"
    );
}

#[test]
fn errors_name_the_object() {
    let gltf = r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":4}],
        "bufferViews":[{"buffer":0,"byteLength":4}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":2,"type":"VEC3"}]}"#;
    let err = load_slice(gltf.as_bytes(), &LoadOptions::default()).err();
    let text = err.as_ref().map(ToString::to_string).unwrap_or_default();
    assert!(text.starts_with("/accessors/0"), "{text}");
}
