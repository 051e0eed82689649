//! The file-access policy: relative URIs stay inside the model's folder (after percent-decoding,
//! `..` and symbolic links), only regular files are read and never beyond the limits, and error
//! messages never print values read from a file.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use barytex_gltf::{
    LoadOptions, ResolveError, Scene, SceneError, UriResolver, load_path, load_slice,
    load_slice_with_base, load_with_resolver,
};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

/// Floats whose decimal forms are easy to spot in a message (1234.5, 42.25, 7.125, …).
const SECRET: [f32; 9] = [
    1234.5, 42.25, 7.125, 9876.5, 31.75, 2.0625, 555.5, 66.25, 8.875,
];

/// The texts of [`SECRET`]'s values as `{}` prints them.
fn secret_texts() -> Vec<String> {
    SECRET.iter().map(|v| format!("{v}")).collect()
}

fn secret_bytes() -> Vec<u8> {
    SECRET.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// A fresh folder `<tmp>/barytex-access-<pid>-<name>` with `model/` (the glTF's folder) and
/// `outside/secret.bin` (36 bytes of [`SECRET`]) beside it.
fn sandbox(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("barytex-access-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("model")).unwrap();
    std::fs::create_dir_all(dir.join("outside")).unwrap();
    std::fs::write(dir.join("outside/secret.bin"), secret_bytes()).unwrap();
    dir
}

/// A triangle whose POSITION accessor reads buffer 0 (`uri`, 36 bytes) with `min`/`max` that
/// match [`SECRET`]: if the buffer is read, the load succeeds.
fn positions_from(uri: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":36,"uri":"{uri}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
                      "min":[555.5,31.75,2.0625],"max":[9876.5,66.25,8.875]}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    )
}

/// The same triangle with `min`/`max` all zero: a min/max mismatch on every element.
fn mismatched_positions_from(uri: &str) -> String {
    positions_from(uri)
        .replace("[555.5,31.75,2.0625]", "[0,0,0]")
        .replace("[9876.5,66.25,8.875]", "[0,0,0]")
}

/// Writes `json` as `model/scene.gltf` and loads it.
fn load_model(dir: &Path, json: &str, options: &LoadOptions) -> Result<Scene, SceneError> {
    let path = dir.join("model/scene.gltf");
    std::fs::write(&path, json).unwrap();
    load_path(&path, options)
}

/// Asserts the error names `pointer` and prints none of [`SECRET`]'s values.
#[track_caller]
fn assert_refused_quietly(r: &Result<Scene, SceneError>, pointer: &str) {
    let e = r
        .as_ref()
        .err()
        .unwrap_or_else(|| panic!("{pointer}: loaded"));
    assert_eq!(e.pointer(), Some(pointer), "{e}");
    if pointer.ends_with("/uri") {
        assert!(matches!(e, SceneError::Denied { .. }), "{e:?}");
    }
    let text = e.to_string();
    for secret in secret_texts() {
        assert!(!text.contains(&secret), "{text} prints {secret}");
    }
}

/// Runs `f` on a thread; panics if it has not returned after 20 s (a hang, not an answer).
fn within<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(Duration::from_secs(20))
        .unwrap_or_else(|_| panic!("{what}: still loading after 20 s"))
}

/// Sanity: the same document loads when the buffer is inside the folder.
#[test]
fn a_buffer_inside_the_folder_loads() {
    let dir = sandbox("inside");
    std::fs::write(dir.join("model/data.bin"), secret_bytes()).unwrap();
    let r = load_model(&dir, &positions_from("data.bin"), &LoadOptions::default());
    assert!(r.is_ok(), "{r:?}");
    // `..` that stays inside the folder is fine.
    std::fs::create_dir_all(dir.join("model/sub")).unwrap();
    let r = load_model(
        &dir,
        &positions_from("sub/../data.bin"),
        &LoadOptions::default(),
    );
    assert!(r.is_ok(), "{r:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `..`, percent-encoded dots and slashes, and absolute paths cannot leave the model's folder.
#[test]
fn uris_leaving_the_folder_are_refused() {
    let dir = sandbox("traversal");
    std::fs::create_dir_all(dir.join("model/sub")).unwrap();
    let absolute = dir.join("outside/secret.bin").display().to_string();
    for uri in [
        "../outside/secret.bin",
        "%2e%2e/outside/secret.bin",
        "%2E%2E%2Foutside%2Fsecret.bin",
        "..%2foutside%2fsecret.bin",
        "sub/../../outside/secret.bin",
        "./sub/%2e%2e/%2e%2e/outside/secret.bin",
        absolute.as_str(),
    ] {
        let r = load_model(&dir, &positions_from(uri), &LoadOptions::default());
        assert_refused_quietly(&r, "/buffers/0/uri");
        // Also when a mismatch would have printed the values.
        let r = load_model(
            &dir,
            &mismatched_positions_from(uri),
            &LoadOptions::default(),
        );
        assert_refused_quietly(&r, "/buffers/0/uri");
    }
    // Images too.
    let r = load_slice_with_base(
        textured("../outside/secret.bin").as_bytes(),
        &dir.join("model"),
        &LoadOptions::default(),
    );
    assert!(
        r.as_ref()
            .err()
            .and_then(SceneError::pointer)
            .is_some_and(|p| p == "/images/0/uri"),
        "{r:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A triangle whose material samples an image at `uri` (positions are zeros).
fn textured(uri: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "images":[{{"uri":"{uri}"}}],
            "textures":[{{"source":0}}],
            "materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}],
            "accessors":[{{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}},
                         {{"componentType":5126,"count":3,"type":"VEC2"}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"material":0}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    )
}

/// An unused buffer outside the folder: refused the same way whether the file exists or not,
/// so a document cannot probe for files or their sizes.
#[test]
fn unused_buffers_outside_the_folder_reveal_nothing() {
    let dir = sandbox("unused");
    let unused = |uri: &str| {
        format!(
            r#"{{"asset":{{"version":"2.0"}},"buffers":[{{"byteLength":1000,"uri":"{uri}"}}]}}"#
        )
    };
    let present = load_model(
        &dir,
        &unused("../outside/secret.bin"),
        &LoadOptions::default(),
    );
    let absent = load_model(
        &dir,
        &unused("../outside/absent.bin"),
        &LoadOptions::default(),
    );
    assert_refused_quietly(&present, "/buffers/0/uri");
    assert_refused_quietly(&absent, "/buffers/0/uri");
    let present = present.err().unwrap().to_string();
    let absent = absent.err().unwrap().to_string();
    assert_eq!(present.replace("secret", "absent"), absent);
    assert!(!present.contains("36"), "{present} reveals the size");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Symbolic links inside the folder that lead out of it (to a file, or a folder) are refused;
/// one that stays inside is followed.
#[cfg(unix)]
#[test]
fn symlinks_leaving_the_folder_are_refused() {
    use std::os::unix::fs::symlink;
    let dir = sandbox("symlink");
    symlink(dir.join("outside/secret.bin"), dir.join("model/link.bin")).unwrap();
    symlink(dir.join("outside"), dir.join("model/linked")).unwrap();
    symlink("/nonexistent-barytex/x.bin", dir.join("model/dangling.bin")).unwrap();
    for uri in ["link.bin", "linked/secret.bin", "dangling.bin"] {
        let r = load_model(&dir, &positions_from(uri), &LoadOptions::default());
        assert_refused_quietly(&r, "/buffers/0/uri");
        let r = load_model(
            &dir,
            &mismatched_positions_from(uri),
            &LoadOptions::default(),
        );
        assert_refused_quietly(&r, "/buffers/0/uri");
    }
    std::fs::write(dir.join("model/real.bin"), secret_bytes()).unwrap();
    symlink(dir.join("model/real.bin"), dir.join("model/inside.bin")).unwrap();
    let r = load_model(&dir, &positions_from("inside.bin"), &LoadOptions::default());
    assert!(r.is_ok(), "{r:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A min/max mismatch, an out-of-range index and a bad sparse index are reported by element
/// and component index, never by the value read from the buffer.
#[test]
fn errors_never_print_values_read_from_buffers() {
    let dir = sandbox("values");
    std::fs::write(dir.join("model/data.bin"), secret_bytes()).unwrap();
    let r = load_model(
        &dir,
        &mismatched_positions_from("data.bin"),
        &LoadOptions::default(),
    );
    assert_refused_quietly(&r, "/accessors/0");
    let text = r.err().unwrap().to_string();
    assert!(text.contains("element 0 component 0"), "{text}");

    // Indices 0, 1 and 4242 (u16) over three vertices; 1234 as a sparse index.
    let mut bytes = Vec::new();
    for v in [0.0_f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    for i in [0_u16, 1, 4242, 1234] {
        bytes.extend_from_slice(&i.to_le_bytes());
    }
    std::fs::write(dir.join("model/mesh.bin"), &bytes).unwrap();
    let indexed = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":44,"uri":"mesh.bin"}],
        "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                     {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#;
    let r = load_model(&dir, indexed, &LoadOptions::default());
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("index 2"), "{text}");
    assert!(
        !text.contains("4242"),
        "{text} prints a value read from the buffer"
    );

    let sparse = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":44,"uri":"mesh.bin"}],
        "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":42,"byteLength":2},
                       {"buffer":0,"byteLength":12}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0],
                      "sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},
                                "values":{"bufferView":2}}}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#;
    let r = load_model(&dir, sparse, &LoadOptions::default());
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("sparse index 0"), "{text}");
    assert!(
        !text.contains("1234"),
        "{text} prints a value read from the buffer"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `/dev/zero` (size 0 by its metadata, endless when read) as the model: refused at once.
#[cfg(unix)]
#[test]
fn a_device_as_the_model_is_refused() {
    let r = within("/dev/zero", || {
        load_path("/dev/zero", &LoadOptions::default()).map(|_| ())
    });
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("not a regular file"), "{text}");
}

/// A FIFO in the model's folder, as a buffer, as an image and as the model: refused, not a hang.
#[cfg(unix)]
#[test]
fn a_fifo_in_the_folder_is_refused() {
    let dir = sandbox("fifo");
    let made = std::process::Command::new("mkfifo")
        .arg(dir.join("model/pipe.bin"))
        .status();
    if !made.is_ok_and(|s| s.success()) {
        println!("note: mkfifo unavailable, test skipped");
        return;
    }
    let model = dir.join("model");
    let gltf = positions_from("pipe.bin");
    let r = within("buffer", move || {
        load_slice_with_base(gltf.as_bytes(), &model, &LoadOptions::default()).map(|_| ())
    });
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("not a regular file"), "{text}");
    // Unused, it is still checked (and still not opened for reading).
    let model = dir.join("model");
    let unused = r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"pipe.bin"}]}"#;
    let r = within("unused buffer", move || {
        load_slice_with_base(unused.as_bytes(), &model, &LoadOptions::default()).map(|_| ())
    });
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("not a regular file"), "{text}");
    let model = dir.join("model");
    let r = within("image", move || {
        load_slice_with_base(
            textured("pipe.bin").as_bytes(),
            &model,
            &LoadOptions::default(),
        )
        .map(|_| ())
    });
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("not a regular file"), "{text}");
    let pipe = dir.join("model/pipe.bin");
    let r = within("model", move || {
        load_path(&pipe, &LoadOptions::default()).map(|_| ())
    });
    let text = r.err().map(|e| e.to_string()).unwrap_or_default();
    assert!(text.contains("not a regular file"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// In-memory input has no folder: every relative URI is refused, as before.
#[test]
fn in_memory_input_resolves_no_files() {
    let r = load_slice(
        positions_from("data.bin").as_bytes(),
        &LoadOptions::default(),
    );
    assert!(
        r.as_ref()
            .err()
            .and_then(SceneError::pointer)
            .is_some_and(|p| p == "/buffers/0/uri"),
        "{r:?}"
    );
}

/// `/dev/zero` through a URI: outside the folder it is refused as such; with `/dev` allowed it
/// is refused as not a regular file (its metadata says 0 bytes; reading it never ends).
#[cfg(target_os = "linux")]
#[test]
fn a_device_through_a_uri_is_refused() {
    let dir = sandbox("device-uri");
    // One `..` per folder below the root (`/` itself is not a normal component).
    let depth = dir.join("model").components().count() - 1;
    let uri = format!("{}dev/zero", "../".repeat(depth));
    let r = load_model(&dir, &positions_from(&uri), &LoadOptions::default());
    assert_refused_quietly(&r, "/buffers/0/uri");
    let gltf = positions_from(&uri);
    let model = dir.join("model");
    let r = within("/dev/zero allowed", move || {
        let options = LoadOptions {
            allowed_roots: vec![PathBuf::from("/dev")],
            ..LoadOptions::default()
        };
        load_slice_with_base(gltf.as_bytes(), &model, &options).map(|_| ())
    });
    let e = r.err().unwrap();
    assert!(matches!(&e, SceneError::Denied { pointer, .. } if pointer == "/buffers/0/uri"));
    assert!(e.to_string().contains("not a regular file"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `LoadOptions::allowed_roots` opens a sibling folder, and nothing beyond it.
#[test]
fn an_allowed_root_opens_a_sibling_folder() {
    let dir = sandbox("allowed");
    std::fs::create_dir_all(dir.join("elsewhere")).unwrap();
    std::fs::write(dir.join("elsewhere/other.bin"), secret_bytes()).unwrap();
    let allowed = LoadOptions {
        allowed_roots: vec![dir.join("outside")],
        ..LoadOptions::default()
    };
    let r = load_model(&dir, &positions_from("../outside/secret.bin"), &allowed);
    assert!(r.is_ok(), "{r:?}");
    // Through percent-encoding too: the same path after decoding.
    let r = load_model(&dir, &positions_from("%2e%2e/outside/secret.bin"), &allowed);
    assert!(r.is_ok(), "{r:?}");
    // Another sibling stays closed.
    let r = load_model(&dir, &positions_from("../elsewhere/other.bin"), &allowed);
    assert_refused_quietly(&r, "/buffers/0/uri");
    // A root that does not exist allows nothing (and is not an error by itself).
    let missing = LoadOptions {
        allowed_roots: vec![dir.join("no-such-folder")],
        ..LoadOptions::default()
    };
    let r = load_model(&dir, &positions_from("../outside/secret.bin"), &missing);
    assert_refused_quietly(&r, "/buffers/0/uri");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Serves `data.bin` from memory, counts the names it was asked for, refuses the rest.
struct Memory {
    bytes: Vec<u8>,
    asked: std::sync::Mutex<Vec<String>>,
}

impl UriResolver for Memory {
    fn read(&self, uri_path: &str, _max_bytes: u64) -> Result<Vec<u8>, ResolveError> {
        self.asked.lock().unwrap().push(uri_path.to_owned());
        if uri_path == "dir/data file.bin" {
            Ok(self.bytes.clone())
        } else {
            Err(ResolveError::Denied)
        }
    }
}

/// The resolver hook serves a buffer by its decoded path; its refusals are `Denied`; an answer
/// over the limit is refused even if the resolver ignored `max_bytes`.
#[test]
fn a_resolver_serves_uris() {
    let memory = Memory {
        bytes: secret_bytes(),
        asked: std::sync::Mutex::new(Vec::new()),
    };
    let r = load_with_resolver(
        positions_from("dir/data%20file.bin?v=2").as_bytes(),
        &memory,
        &LoadOptions::default(),
    );
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(*memory.asked.lock().unwrap(), ["dir/data file.bin"]);
    let r = load_with_resolver(
        positions_from("../etc/passwd").as_bytes(),
        &memory,
        &LoadOptions::default(),
    );
    assert_refused_quietly(&r, "/buffers/0/uri");
    // An unused buffer asks through `size`, whose default reads.
    let unused =
        r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":100,"uri":"dir/data%20file.bin"}]}"#;
    let r = load_with_resolver(unused.as_bytes(), &memory, &LoadOptions::default());
    assert_eq!(
        r.err()
            .and_then(|e| e.pointer().map(str::to_owned))
            .as_deref(),
        Some("/buffers/0")
    );
    let mut small = LoadOptions::default();
    small.limits.max_buffer_bytes = 36;
    small.limits.max_image_file_bytes = 8;
    let r = load_with_resolver(textured("dir/data%20file.bin").as_bytes(), &memory, &small);
    assert!(
        matches!(&r, Err(SceneError::TooLarge { pointer, requested: 36, limit: 8, .. })
            if pointer == "/images/0/uri"),
        "{r:?}"
    );
}
