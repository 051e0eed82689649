//! Budgets over the whole flattened scene, not one object at a time: instanced triangles and
//! vertices (a mesh times the nodes placing it), light instances, and the decoded bytes of all
//! images together. Each is refused with `SceneError::TooLarge` naming the object that crossed
//! it, before the work or the allocation it would cost. Every document is built here.

mod common;

use std::sync::Arc;

use barytex_gltf::{LoadOptions, SceneError, SceneLimits, load_slice, load_slice_with_base};
use barytex_texture::load::encode_png;
use barytex_texture::{Rgba8, Texture2d};

use common::{assert_too_large, temp_dir, with_limits};

/// A mesh of `triangles` non-indexed triangles (zero positions, no bufferView) placed by
/// `nodes` root nodes.
fn mesh_instanced(triangles: u64, nodes: usize) -> String {
    let node_list = vec![r#"{"mesh":0}"#; nodes].join(",");
    let roots: Vec<String> = (0..nodes).map(|i| i.to_string()).collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "accessors":[{{"componentType":5126,"count":{},"type":"VEC3","min":[0,0,0],"max":[0,0,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "nodes":[{node_list}],"scenes":[{{"nodes":[{}]}}]}}"#,
        3 * triangles,
        roots.join(",")
    )
}

#[test]
fn max_instanced_triangles_counts_every_placement() {
    // 10 triangles placed 5 times: 50 instanced, 10 decoded (under `max_triangles`).
    let gltf = mesh_instanced(10, 5);
    let limits = SceneLimits {
        max_instanced_triangles: 49,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    // The fifth placement (node 4) is the one that crosses the limit.
    assert_too_large(&r, "instanced triangles", "/nodes/4", 50, 49);
    let at = SceneLimits {
        max_instanced_triangles: 50,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(at));
    assert!(
        matches!(&r, Ok(s) if s.stats.instanced_triangles == 50 && s.stats.triangles == 10),
        "{r:?}"
    );
}

#[test]
fn instancing_a_big_mesh_is_refused_under_the_default_limits() {
    // 10⁵ placements of a 10⁴-triangle mesh (zeros: no bytes in the file) claim 10⁹ triangles
    // from ~2 MB of JSON. Each is within `max_triangles` and `max_instances`; their product
    // is refused at the node crossing 50 M, before any mesh is decoded or copied.
    let gltf = mesh_instanced(10_000, 100_000);
    assert!(gltf.len() < 2 << 20, "{}", gltf.len());
    let started = std::time::Instant::now();
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert_too_large(
        &r,
        "instanced triangles",
        "/nodes/5000",
        50_010_000,
        50_000_000,
    );
    assert!(started.elapsed().as_secs() < 10, "{:?}", started.elapsed());
}

#[test]
fn max_instanced_vertices_counts_every_placement() {
    // 10 non-indexed triangles are 30 vertices; 5 placements are 150.
    let gltf = mesh_instanced(10, 5);
    let limits = SceneLimits {
        max_instanced_vertices: 149,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "instanced vertices", "/nodes/4", 150, 149);
    let at = SceneLimits {
        max_instanced_vertices: 150,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(at));
    assert!(r.is_ok(), "{r:?}");
    // Vertices count even where few triangles use them: one indexed triangle over 40 vertices
    // (an index buffer of three zeros), placed 4 times, is 160 instanced vertices.
    let indexed = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":4,"uri":"data:application/octet-stream;base64,AAAAAA=="}],
        "bufferViews":[{"buffer":0,"byteLength":4,"target":34963}],
        "accessors":[{"componentType":5126,"count":40,"type":"VEC3","min":[0,0,0],"max":[0,0,0]},
                     {"bufferView":0,"componentType":5121,"count":3,"type":"SCALAR"}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
        "nodes":[{"mesh":0},{"mesh":0},{"mesh":0},{"mesh":0}],
        "scenes":[{"nodes":[0,1,2,3]}]}"#;
    let r = load_slice(indexed.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "instanced vertices", "/nodes/3", 160, 149);
}

/// One point light placed by `nodes` root nodes.
fn light_instanced(nodes: usize) -> String {
    let node_list = vec![r#"{"extensions":{"KHR_lights_punctual":{"light":0}}}"#; nodes].join(",");
    let roots: Vec<String> = (0..nodes).map(|i| i.to_string()).collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},"extensionsUsed":["KHR_lights_punctual"],
            "extensions":{{"KHR_lights_punctual":{{"lights":[{{"type":"point"}}]}}}},
            "nodes":[{node_list}],"scenes":[{{"nodes":[{}]}}]}}"#,
        roots.join(",")
    )
}

#[test]
fn max_lights_counts_placed_lights() {
    let gltf = light_instanced(5);
    let limits = SceneLimits {
        max_lights: 4,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(limits));
    assert_too_large(&r, "lights", "/nodes/4", 5, 4);
    let at = SceneLimits {
        max_lights: 5,
        ..SceneLimits::default()
    };
    let r = load_slice(gltf.as_bytes(), &with_limits(at));
    assert!(matches!(&r, Ok(s) if s.lights.len() == 5), "{r:?}");
    // One light placed by 10⁴ nodes is refused under the default limit (1024), instead of
    // costing 10⁴ lights at every shaded sample.
    let big = light_instanced(10_000);
    let r = load_slice(big.as_bytes(), &LoadOptions::default());
    assert_too_large(&r, "lights", "/nodes/1024", 1025, 1024);
}

/// A `side`² RGBA PNG (decoded: 4 bytes a texel, sRGB or linear).
fn png(side: u32) -> Vec<u8> {
    let t =
        Texture2d::from_fn(side, side, |x, y| Rgba8([x as u8, y as u8, 0, 255])).expect("texture");
    encode_png(&t).expect("encode")
}

/// A triangle whose materials sample images at `uris` (one material and texture per image,
/// each used by its own primitive); `linear_too` also samples image 0 as metallic-roughness
/// (linear, a second decode of the same image).
fn textured(uris: &[&str], linear_too: bool) -> String {
    let images: Vec<String> = uris.iter().map(|u| format!(r#"{{"uri":"{u}"}}"#)).collect();
    let textures: Vec<String> = (0..uris.len())
        .map(|i| format!(r#"{{"source":{i}}}"#))
        .collect();
    let materials: Vec<String> = (0..uris.len())
        .map(|i| {
            let mr = if linear_too && i == 0 {
                r#","metallicRoughnessTexture":{"index":0}"#
            } else {
                ""
            };
            format!(r#"{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":{i}}}{mr}}}}}"#)
        })
        .collect();
    let primitives: Vec<String> = (0..uris.len())
        .map(|i| format!(r#"{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"material":{i}}}"#))
        .collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "images":[{}],"textures":[{}],"materials":[{}],
            "accessors":[{{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}},
                         {{"componentType":5126,"count":3,"type":"VEC2"}}],
            "meshes":[{{"primitives":[{}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#,
        images.join(","),
        textures.join(","),
        materials.join(","),
        primitives.join(",")
    )
}

#[test]
fn max_total_image_bytes_counts_each_distinct_source_once() {
    let dir = temp_dir("total-image-bytes");
    std::fs::write(dir.join("a.png"), png(64)).expect("write");
    std::fs::write(dir.join("b.png"), png(64)).expect("write");
    // Three image entries, two of them the same file: two decodes of 64² × 4 B = 16 384 B.
    let gltf = textured(&["a.png", "a.png", "b.png"], false);
    let at = SceneLimits {
        max_total_image_bytes: 32_768,
        ..SceneLimits::default()
    };
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &with_limits(at));
    let scene = r.unwrap_or_else(|e| panic!("{e}"));
    let srgb = |i: usize| scene.images[i].srgb.clone().expect("decoded");
    // The two entries for one file share one decoded texture.
    assert!(Arc::ptr_eq(&srgb(0), &srgb(1)));
    assert!(!Arc::ptr_eq(&srgb(0), &srgb(2)));
    // One byte less: the third entry (a new source) is refused.
    let under = SceneLimits {
        max_total_image_bytes: 32_767,
        ..SceneLimits::default()
    };
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &with_limits(under));
    assert_too_large(&r, "total decoded image bytes", "/images/2", 32_768, 32_767);
    // The same image decoded both as sRGB and as linear data is two textures: both count.
    let both = textured(&["a.png"], true);
    let r = load_slice_with_base(both.as_bytes(), &dir, &with_limits(at));
    assert!(
        matches!(&r, Ok(s) if s.images[0].srgb.is_some() && s.images[0].linear.is_some()),
        "{r:?}"
    );
    let r = load_slice_with_base(both.as_bytes(), &dir, &with_limits(under));
    assert_too_large(&r, "total decoded image bytes", "/images/0", 32_768, 32_767);
    // Eight entries for one image are one decode under a budget for one.
    let eight = textured(&["a.png"; 8], false);
    let one = SceneLimits {
        max_total_image_bytes: 16_384,
        ..SceneLimits::default()
    };
    let r = load_slice_with_base(eight.as_bytes(), &dir, &with_limits(one));
    assert!(matches!(&r, Ok(s) if s.stats.images_decoded == 1), "{r:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A PNG whose header claims `width × height` RGBA8 but whose data is only a zlib header:
/// decoding it fails, but its size can be read.
fn png_header_only(width: u32, height: u32) -> Vec<u8> {
    barytex_testkit::png_with_header(width, height, &[0x78, 0x9C])
}

#[test]
fn the_image_budget_is_checked_from_headers_before_decoding() {
    let dir = temp_dir("image-headers");
    std::fs::write(dir.join("small.png"), png(8)).expect("write");
    // 4000² RGBA8 is 64 MB decoded: within the per-image limit (1 GiB), over a 32 MiB budget.
    std::fs::write(dir.join("big.png"), png_header_only(4000, 4000)).expect("write");
    let gltf = textured(&["small.png", "big.png"], false);
    let limits = SceneLimits {
        max_total_image_bytes: 32 << 20,
        ..SceneLimits::default()
    };
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &with_limits(limits));
    // Refused from its header: decoding would have failed (there are no pixels).
    assert_too_large(
        &r,
        "total decoded image bytes",
        "/images/1",
        256 + 64_000_000,
        32 << 20,
    );
    // Under the default budget (2 GiB) it is decoded, and fails as the corrupt file it is.
    let r = load_slice_with_base(gltf.as_bytes(), &dir, &LoadOptions::default());
    assert!(
        matches!(&r, Err(SceneError::Image { pointer, .. }) if pointer == "/images/1"),
        "{r:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
