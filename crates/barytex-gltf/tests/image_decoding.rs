//! Images decode in parallel, with the result of decoding them one after another: the same
//! textures for any number of threads, each source decoded once, and the error of the first
//! image (in document order) that fails, whether it fails while decoding or before.

use barytex_gltf::{LoadOptions, Scene, SceneError, SceneLimits, load_path};
use barytex_texture::load::{AnyTexture2d, save_png};
use barytex_texture::{Srgba8, Texture2d};

/// A PNG of `w × h` texels of one colour.
fn write_png(dir: &std::path::Path, name: &str, w: u32, h: u32, rgb: [u8; 3]) {
    let texels = vec![Srgba8([rgb[0], rgb[1], rgb[2], 255]); (w * h) as usize];
    let image = Texture2d::from_texels(w, h, texels).expect("small");
    save_png(&image, dir.join(name)).expect("writes");
}

/// CRC-32 (ISO 3309, as PNG chunks use), bit by bit.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0_u32;
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

/// A PNG whose chunks are well formed (lengths, CRCs, a 2 × 2 RGB header) but whose pixel data
/// is not zlib: it passes every check before decoding and fails the decode.
fn write_undecodable_png(dir: &std::path::Path, name: &str) {
    let chunk = |kind: &[u8], data: &[u8]| {
        let mut c = (data.len() as u32).to_be_bytes().to_vec();
        let body = [kind, data].concat();
        c.extend_from_slice(&body);
        c.extend_from_slice(&crc32(&body).to_be_bytes());
        c
    };
    let mut header = Vec::new();
    header.extend_from_slice(&2_u32.to_be_bytes());
    header.extend_from_slice(&2_u32.to_be_bytes());
    header.extend_from_slice(&[8, 2, 0, 0, 0]);
    let png = [
        b"\x89PNG\r\n\x1a\n".to_vec(),
        chunk(b"IHDR", &header),
        chunk(b"IDAT", b"this is not a zlib stream at all"),
        chunk(b"IEND", b""),
    ]
    .concat();
    std::fs::write(dir.join(name), png).expect("writes");
}

/// A glTF whose one mesh has a primitive per image URI, each with a material whose base colour
/// texture is that image; loaded with `limits`, images decoded on `threads` threads.
fn load(
    dir: &std::path::Path,
    uris: &[&str],
    limits: SceneLimits,
    threads: usize,
) -> Result<Scene, SceneError> {
    let list = |f: &dyn Fn(usize) -> String| (0..uris.len()).map(f).collect::<Vec<_>>().join(",");
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},
        "images":[{}],
        "textures":[{}],
        "materials":[{}],
        "accessors":[{{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}},
                     {{"componentType":5126,"count":3,"type":"VEC2"}}],
        "meshes":[{{"primitives":[{}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#,
        list(&|i| format!(r#"{{"uri":"{}"}}"#, uris[i])),
        list(&|i| format!(r#"{{"source":{i}}}"#)),
        list(&|i| format!(r#"{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":{i}}}}}}}"#)),
        list(&|i| format!(r#"{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"material":{i}}}"#)),
    );
    std::fs::write(dir.join("scene.gltf"), gltf).expect("writes");
    load_path(
        dir.join("scene.gltf"),
        &LoadOptions {
            limits,
            decode_threads: threads,
            ..LoadOptions::default()
        },
    )
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("barytex-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    dir
}

/// Width, height and first texel of each image's sRGB texture.
fn summary(scene: &Scene) -> Vec<Option<(u32, u32, [u8; 4])>> {
    scene
        .images
        .iter()
        .map(|image| match image.srgb.as_deref() {
            Some(AnyTexture2d::Srgba8(t)) => Some((t.size().0, t.size().1, t.texels()[0].0)),
            Some(_) => panic!("an 8-bit PNG decodes to Srgba8"),
            None => None,
        })
        .collect()
}

#[test]
fn any_thread_count_gives_the_same_textures_and_each_source_decodes_once() {
    let dir = temp_dir("parallel-decode");
    let colours: Vec<[u8; 3]> = (0..7_u8).map(|i| [i * 30, 255 - i * 30, i]).collect();
    for (i, &c) in colours.iter().enumerate() {
        write_png(&dir, &format!("{i}.png"), 3 + i as u32, 5 + 2 * i as u32, c);
    }
    // Image 7 names image 2's file again: one source, one decode, one shared texture.
    let uris = [
        "0.png", "1.png", "2.png", "3.png", "4.png", "5.png", "6.png", "2.png",
    ];
    let scenes: Vec<Scene> = [1, 2, 3, 0]
        .map(|threads| load(&dir, &uris, SceneLimits::default(), threads).expect("loads"))
        .into();
    let _ = std::fs::remove_dir_all(&dir);
    let expected: Vec<_> = uris
        .iter()
        .map(|uri| {
            let i: usize = uri[..1].parse().expect("a digit");
            let c = colours[i];
            Some((3 + i as u32, 5 + 2 * i as u32, [c[0], c[1], c[2], 255]))
        })
        .collect();
    for scene in &scenes {
        assert_eq!(summary(scene), expected);
        assert_eq!(scene.stats.images_decoded, 7);
        let (a, b) = (&scene.images[2].srgb, &scene.images[7].srgb);
        assert!(std::sync::Arc::ptr_eq(
            a.as_ref().expect("decoded"),
            b.as_ref().expect("decoded")
        ));
    }
}

#[test]
fn an_earlier_image_that_fails_to_decode_wins_over_a_later_one_over_budget() {
    let dir = temp_dir("decode-error-order");
    write_png(&dir, "small.png", 2, 2, [1, 2, 3]);
    write_undecodable_png(&dir, "broken.png");
    write_png(&dir, "big.png", 64, 64, [4, 5, 6]);
    // 2·2 + 2·2 texels of 4 bytes fit; the 64 × 64 image does not.
    let limits = SceneLimits {
        max_total_image_bytes: 1024,
        ..SceneLimits::default()
    };
    let first_broken = load(&dir, &["small.png", "broken.png", "big.png"], limits, 3);
    let first_big = load(&dir, &["small.png", "big.png", "broken.png"], limits, 3);
    let fine = load(&dir, &["small.png", "small.png"], limits, 3);
    let _ = std::fs::remove_dir_all(&dir);
    match first_broken.expect_err("image 1 fails") {
        SceneError::Image { pointer, .. } => assert_eq!(pointer, "/images/1"),
        other => panic!("expected image 1's decoding error, got {other}"),
    }
    match first_big.expect_err("image 1 is over budget") {
        SceneError::TooLarge { pointer, .. } => assert_eq!(pointer, "/images/1"),
        other => panic!("expected image 1 over budget, got {other}"),
    }
    assert_eq!(fine.expect("within budget").stats.images_decoded, 1);
}
