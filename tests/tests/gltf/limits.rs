//! Each `SceneLimits` field refused on its own, with `SceneError::TooLarge` naming the limit
//! (checked before anything that size is allocated), plus `SceneError::Io` for missing files
//! and `SceneError::UnsupportedExtension`. Every document is built here, so nothing depends on
//! the shared fixtures.

mod common;

use barytex_gltf::{
    LoadOptions, SceneError, SceneLimits, load_path, load_slice, load_slice_with_base,
};
use barytex_texture::load::encode_png;
use barytex_texture::{Rgba8, Texture2d};

use common::{assert_too_large, temp_dir, with_limits};

/// One triangle (three zero positions, no bufferView) placed by `nodes` nodes, all roots.
fn triangle_instanced(nodes: usize) -> String {
    let node_list = vec![r#"{"mesh":0}"#; nodes].join(",");
    let roots: Vec<String> = (0..nodes).map(|i| i.to_string()).collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "accessors":[{{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "nodes":[{node_list}],"scenes":[{{"nodes":[{}]}}]}}"#,
        roots.join(",")
    )
}

#[test]
fn max_file_bytes_is_checked_before_parsing() {
    let gltf = triangle_instanced(1);
    let len = gltf.len() as u64;
    let limits = SceneLimits {
        max_file_bytes: len - 1,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "file bytes", "", len, len - 1);
    // Not even parsed: garbage of the same length gets the same answer, not a JSON error.
    let garbage = vec![b'{'; gltf.len()];
    let r = load_slice(&garbage, &with_limits(limits));
    assert_too_large(&r, "file bytes", "", len, len - 1);
    // `load_path` checks the file's size from its metadata, before reading it.
    let dir = temp_dir("file-bytes");
    let path = dir.join("scene.gltf");
    std::fs::write(&path, &gltf).expect("write");
    let r = load_path(&path, &with_limits(limits));
    assert_too_large(&r, "file bytes", "", len, len - 1);
    // At the limit it loads.
    let at = SceneLimits {
        max_file_bytes: len,
        ..SceneLimits::default()
    };
    let r = load_path(&path, &with_limits(at));
    assert!(matches!(&r, Ok(s) if s.triangle_count() == 1), "{r:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn max_total_buffer_bytes_sums_every_buffer() {
    // Three 600-byte buffers (declared only: never read), each under the per-buffer limit.
    let gltf = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":600},{"byteLength":600},{"byteLength":600}]}"#;
    let limits = SceneLimits {
        max_buffer_bytes: 1000,
        max_total_buffer_bytes: 1500,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "total buffer bytes", "/buffers", 1800, 1500);
    // Byte lengths near u64::MAX saturate instead of wrapping below the limit.
    let huge = format!(
        r#"{{"asset":{{"version":"2.0"}},"buffers":[{{"byteLength":{m}}},{{"byteLength":{m}}}]}}"#,
        m = u64::MAX / 2 + 1
    );
    let limits = SceneLimits {
        max_buffer_bytes: u64::MAX,
        max_total_buffer_bytes: u64::MAX - 1,
        ..SceneLimits::default()
    };
    let r = load_slice(huge.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "total buffer bytes", "/buffers", u64::MAX, u64::MAX - 1);
    // Under the default limits the three small buffers load.
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(r.is_ok(), "{r:?}");
}

/// A 2×2 PNG.
fn tiny_png() -> Vec<u8> {
    let texture = Texture2d::from_fn(2, 2, |x, y| {
        Rgba8([(x * 255) as u8, (y * 255) as u8, 0, 255])
    })
    .expect("2×2");
    encode_png(&texture).expect("encode")
}

#[test]
fn max_image_file_bytes_refuses_external_and_data_uri_images() {
    let png = tiny_png();
    let len = png.len() as u64;
    let dir = temp_dir("image-bytes");
    std::fs::write(dir.join("tex.png"), &png).expect("write");
    let gltf = common::textured_triangle("tex.png");
    let small = SceneLimits {
        max_image_file_bytes: len - 1,
        ..SceneLimits::default()
    };
    // External file: its size (from the metadata) against the limit, before reading.
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &with_limits(small));
    assert_too_large(&r, "image file bytes", "/images/0/uri", len, len - 1);
    // Also when images are not decoded: the bytes are checked either way.
    let no_decode = LoadOptions {
        decode_images: false,
        ..with_limits(small)
    };
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &no_decode);
    assert_too_large(&r, "image file bytes", "/images/0/uri", len, len - 1);
    // At the limit it loads and decodes.
    let at = SceneLimits {
        max_image_file_bytes: len,
        ..SceneLimits::default()
    };
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &with_limits(at));
    assert!(r.is_ok(), "{r:?}");

    // A data URI is bounded by the same limit before its base64 is decoded; it is refused as
    // an invalid `uri` whose reason names the limit.
    use base64::Engine as _;
    let data = format!(
        "data:image/png;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(vec![0u8; 3000])
    );
    let gltf = common::textured_triangle(&data);
    let limits = SceneLimits {
        max_image_file_bytes: 1000,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert!(
        matches!(&r, Err(SceneError::Invalid { pointer, reason })
            if pointer == "/images/0/uri" && reason.contains("exceeds the limit 1000")),
        "{r:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn max_nodes_counts_the_node_array() {
    let gltf = triangle_instanced(5);
    let limits = SceneLimits {
        max_nodes: 4,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "nodes", "/nodes", 5, 4);
    // Nodes that no scene uses count too (the whole array is parsed).
    let unused = r#"{"asset":{"version":"2.0"},"nodes":[{},{},{},{},{}]}"#;
    let r = load_slice(unused.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "nodes", "/nodes", 5, 4);
    let at = SceneLimits {
        max_nodes: 5,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(at));
    assert!(matches!(&r, Ok(s) if s.triangle_count() == 5), "{r:?}");
}

#[test]
fn max_instances_counts_node_mesh_pairs() {
    let gltf = triangle_instanced(5);
    let limits = SceneLimits {
        max_instances: 4,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    // The fifth placement (node 4) is the one refused.
    assert_too_large(&r, "mesh instances", "/nodes/4", 5, 4);
    // Nodes without a mesh are not instances.
    let mixed = r#"{"asset":{"version":"2.0"},
        "accessors":[{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0},{},{},{},{"mesh":0},{},{"mesh":0}],
        "scenes":[{"nodes":[0,1,2,3,4,5,6]}]}"#;
    let r = load_slice(mixed.as_bytes(), &with_limits(limits));
    assert!(matches!(&r, Ok(s) if s.triangle_count() == 3), "{r:?}");
}

#[test]
fn max_unbacked_accessor_elements_bounds_accessors_without_a_buffer_view() {
    // 3000 zeros cost no bytes in the file; the limit of 2999 refuses them before allocating.
    let gltf = r#"{"asset":{"version":"2.0"},
        "accessors":[{"componentType":5126,"count":3000,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#;
    let limits = SceneLimits {
        max_unbacked_accessor_elements: 2999,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(
        &r,
        "elements in an accessor without bufferView",
        "/accessors/0/count",
        3000,
        2999,
    );
    // The general element limit is checked first and named separately.
    let both = SceneLimits {
        max_accessor_elements: 100,
        max_unbacked_accessor_elements: 10,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(both));
    assert_too_large(&r, "accessor elements", "/accessors/0/count", 3000, 100);
    // An accessor backed by a bufferView is not bound by the unbacked limit: 4 elements of
    // VEC3 f32 from a 48-byte buffer load under an unbacked limit of 1.
    let backed = format!(
        r#"{{"asset":{{"version":"2.0"}},
            "buffers":[{{"byteLength":48,"uri":"data:application/octet-stream;base64,{}"}}],
            "bufferViews":[{{"buffer":0,"byteLength":48}}],
            "accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"mode":4}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#,
        {
            use base64::Engine as _;
            base64::engine::general_purpose::STANDARD.encode([0u8; 48])
        }
    );
    let tight = SceneLimits {
        max_unbacked_accessor_elements: 1,
        ..SceneLimits::default()
    };
    let r = load_slice(backed.as_bytes(), &with_limits(tight));
    assert!(r.is_ok(), "{r:?}");
}

#[test]
fn missing_files_are_io_errors_naming_the_path() {
    let dir = temp_dir("io");
    // The glTF itself.
    let missing = dir.join("no-such-scene.gltf");
    let r = load_path(&missing, &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Io { path, source })
            if path.contains("no-such-scene.gltf") && source.kind() == std::io::ErrorKind::NotFound),
        "{r:?}"
    );
    // An external buffer that a bufferView uses.
    let gltf = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":36,"uri":"missing.bin"}],
        "bufferViews":[{"buffer":0,"byteLength":36}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#;
    let path = dir.join("buffer.gltf");
    std::fs::write(&path, gltf).expect("write");
    let r = load_path(&path, &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Io { path, .. }) if path.contains("missing.bin")),
        "{r:?}"
    );
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("missing.bin"), "{text}");
    // An external buffer nothing uses is still checked for existence.
    let unused = r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"unused.bin"}]}"#;
    let r = load_slice_with_base(unused.as_bytes(), &dir, &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Io { path, .. }) if path.contains("unused.bin")),
        "{r:?}"
    );
    // An external image.
    let gltf = common::textured_triangle("missing.png");
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Io { path, .. }) if path.contains("missing.png")),
        "{r:?}"
    );
    // In-memory input without a base folder cannot resolve relative files: `Invalid`, not `Io`.
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Invalid { pointer, .. }) if pointer == "/images/0/uri"),
        "{r:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn unknown_required_extensions_are_unsupported() {
    let gltf = r#"{"asset":{"version":"2.0"},
        "extensionsUsed":["EXT_no_such_thing"],
        "extensionsRequired":["EXT_no_such_thing"]}"#;
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::UnsupportedExtension(name)) if name == "EXT_no_such_thing"),
        "{r:?}"
    );
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("EXT_no_such_thing"), "{text}");
    // Merely used (not required), an unknown extension is ignored.
    let used_only = r#"{"asset":{"version":"2.0"},"extensionsUsed":["EXT_no_such_thing"]}"#;
    let r = load_slice(used_only.as_bytes(), &LoadOptions::default());
    assert!(r.is_ok(), "{r:?}");
    // Required but not listed as used: an invalid document, naming the entry.
    let not_used = r#"{"asset":{"version":"2.0"},"extensionsRequired":["EXT_no_such_thing"]}"#;
    let r = load_slice(not_used.as_bytes(), &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Invalid { pointer, .. }) if pointer == "/extensionsRequired/0"),
        "{r:?}"
    );
}
