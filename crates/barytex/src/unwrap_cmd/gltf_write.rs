//! Writes the unwrapped model: the input's JSON with each unwrapped primitive rewritten (new
//! vertex arrays, since a vertex on a seam is split into one per chart, every attribute gathered
//! through the new-vertex → old-vertex map, plus the new uv set), the new arrays in one `.bin`
//! next to the output, and every relative URI (buffers, images) rebased to the output's folder.
//!
//! Everything else of the document stays as it was (materials, textures, samplers, nodes,
//! cameras, animations, extensions): the original accessors and buffers are kept, so whatever
//! else points at them still finds them. A GLB's binary chunk is written out as the start of the
//! new `<stem>-uv.bin` (its buffer 0), since a `.gltf` cannot embed it.
//!
//! An output named `.glb` is one GLB file instead (glTF 2.0 §4.4, "Binary glTF Layout"): the new
//! arrays go into its binary chunk, which is buffer 0 — after the input GLB's own binary chunk,
//! or, for a `.gltf` input, as a new buffer 0 with every buffer view's index moved up by one.
//! Images and other buffers the model references by URI stay separate files.

use std::path::{Path, PathBuf};

use barytex_gltf::Primitive;
use glam::Vec2;
use serde_json::{Map, Value, json};

use super::uri;

/// The attributes a rewritten primitive can carry over (those barytex-gltf decodes).
pub(crate) const CARRIED: [&str; 6] = [
    "POSITION",
    "NORMAL",
    "TANGENT",
    "TEXCOORD_0",
    "TEXCOORD_1",
    "COLOR_0",
];

/// One primitive's new arrays.
pub(crate) struct NewPrimitive<'a> {
    /// Index into the document's `meshes`.
    pub(crate) mesh: usize,
    /// Index into that mesh's `primitives`.
    pub(crate) primitive: usize,
    /// The decoded primitive (its attributes are gathered).
    pub(crate) source: &'a Primitive,
    /// The old vertex of each new vertex.
    pub(crate) vertex_of: Vec<u32>,
    /// The new uv of each new vertex (glTF's convention: `v` down).
    pub(crate) uvs: Vec<Vec2>,
    /// Triangles over the new vertices.
    pub(crate) triangles: Vec<[u32; 3]>,
}

/// The new binary data and the views and accessors into it.
struct Builder {
    bin: Vec<u8>,
    buffer: usize,
    views: Vec<Value>,
    accessors: Vec<Value>,
    first_view: usize,
    first_accessor: usize,
}

impl Builder {
    fn align(&mut self) {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
    }

    /// Appends f32 elements of `n` components; returns the accessor's index.
    fn floats<const N: usize>(&mut self, data: &[[f32; N]], kind: &str, bounds: bool) -> usize {
        self.align();
        let offset = self.bin.len();
        for e in data {
            for c in e {
                self.bin.extend_from_slice(&c.to_le_bytes());
            }
        }
        self.views.push(json!({
            "buffer": self.buffer, "byteOffset": offset,
            "byteLength": self.bin.len() - offset, "target": 34962
        }));
        let mut accessor = json!({
            "bufferView": self.first_view + self.views.len() - 1,
            "componentType": 5126, "count": data.len(), "type": kind
        });
        if bounds && !data.is_empty() {
            let mut lo = [f32::INFINITY; N];
            let mut hi = [f32::NEG_INFINITY; N];
            for e in data {
                for k in 0..N {
                    lo[k] = lo[k].min(e[k]);
                    hi[k] = hi[k].max(e[k]);
                }
            }
            accessor["min"] = json!(lo.to_vec());
            accessor["max"] = json!(hi.to_vec());
        }
        self.accessors.push(accessor);
        self.first_accessor + self.accessors.len() - 1
    }

    /// Appends u32 triangle indices; returns the accessor's index.
    fn indices(&mut self, triangles: &[[u32; 3]]) -> usize {
        self.align();
        let offset = self.bin.len();
        for i in triangles.iter().flatten() {
            self.bin.extend_from_slice(&i.to_le_bytes());
        }
        self.views.push(json!({
            "buffer": self.buffer, "byteOffset": offset,
            "byteLength": self.bin.len() - offset, "target": 34963
        }));
        self.accessors.push(json!({
            "bufferView": self.first_view + self.views.len() - 1,
            "componentType": 5125, "count": 3 * triangles.len(), "type": "SCALAR"
        }));
        self.first_accessor + self.accessors.len() - 1
    }
}

/// `values` gathered through `vertex_of`, or an error naming what was missing.
fn gather<T: Copy>(values: &[T], vertex_of: &[u32], what: &str) -> Result<Vec<T>, String> {
    vertex_of
        .iter()
        .map(|&v| values.get(v as usize).copied())
        .collect::<Option<Vec<T>>>()
        .ok_or_else(|| format!("{what}: a vertex index out of range"))
}

fn array_len(doc: &Value, key: &str) -> usize {
    doc.get(key).and_then(Value::as_array).map_or(0, Vec::len)
}

fn push_all(doc: &mut Map<String, Value>, key: &str, items: Vec<Value>) {
    let entry = doc
        .entry(key.to_owned())
        .or_insert_with(|| Value::Array(Vec::new()));
    if let Value::Array(list) = entry {
        list.extend(items);
    }
}

/// Rebases the relative `uri` of every element of `doc[key]`, collecting the copies to make.
fn rebase_uris(
    doc: &mut Value,
    key: &str,
    dirs: (&Path, &Path, &[PathBuf]),
    copies: &mut Vec<(PathBuf, PathBuf)>,
) -> Result<(), String> {
    let (model_dir, out_dir, roots) = dirs;
    if let Some(list) = doc.get_mut(key).and_then(Value::as_array_mut) {
        for (i, item) in list.iter_mut().enumerate() {
            let Some(old) = item.get("uri").and_then(Value::as_str) else {
                continue;
            };
            let placed = uri::place(old, model_dir, out_dir, roots)
                .map_err(|e| format!("/{key}/{i}/uri: {e}"))?;
            if let Some(placed) = placed {
                item["uri"] = Value::String(placed.uri);
                copies.extend(placed.copy);
            }
        }
    }
    Ok(())
}

/// Writes `out` (a `.gltf` and its `.bin`, or one `.glb`), and copies the files it references
/// that its folder cannot reach (see [`uri::place`]); returns the path of the file holding the
/// new arrays (the `.bin`, or the `.glb` itself) and the copies. `model_dir` and
/// the output's folder must be absolute and canonical; `roots` are the `--allow-dir` folders.
pub(crate) fn write(
    mut doc: Value,
    glb_bin: Option<&[u8]>,
    model_dir: &Path,
    roots: &[PathBuf],
    out: &Path,
    uv_set: u32,
    primitives: &[NewPrimitive<'_>],
) -> Result<(PathBuf, Vec<PathBuf>), String> {
    if !doc.is_object() {
        return Err("the glTF JSON is not an object".to_owned());
    }
    let out_dir = out.parent().unwrap_or_else(|| Path::new("."));
    let glb_out = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    let mut copies = Vec::new();
    for key in ["buffers", "images"] {
        rebase_uris(&mut doc, key, (model_dir, out_dir, roots), &mut copies)?;
    }
    let stem = out
        .file_stem()
        .map_or_else(|| "unwrapped".into(), |s| s.to_string_lossy().into_owned());
    let bin_name = format!("{stem}-uv.bin");
    let bin_path = out_dir.join(&bin_name);
    let bin_uri = uri::encode(Path::new(&bin_name));
    let clash = doc
        .get("buffers")
        .and_then(Value::as_array)
        .is_some_and(|b| {
            b.iter()
                .any(|b| b.get("uri").and_then(Value::as_str) == Some(&bin_uri))
        });
    if clash && !glb_out {
        return Err(format!(
            "{}: the model already uses a buffer of that name; choose another -o",
            bin_path.display()
        ));
    }
    // A GLB's binary chunk is buffer 0 (glTF 2.0 §4.4.3.3): it starts the new .bin, which
    // becomes that buffer's file; otherwise the new .bin is a new buffer.
    let glb_buffer = glb_bin.is_some()
        && doc
            .get("buffers")
            .and_then(|b| b.get(0))
            .is_some_and(|b| b.get("uri").is_none());
    let mut builder = Builder {
        bin: match (glb_buffer, glb_bin) {
            (true, Some(bin)) => {
                let declared = doc["buffers"][0]["byteLength"].as_u64().unwrap_or(0);
                let keep = usize::try_from(declared)
                    .unwrap_or(usize::MAX)
                    .min(bin.len());
                bin[..keep].to_vec()
            }
            _ => Vec::new(),
        },
        // A new buffer goes last in a .gltf, first in a .glb (moved there below).
        buffer: if glb_buffer || glb_out {
            0
        } else {
            array_len(&doc, "buffers")
        },
        views: Vec::new(),
        accessors: Vec::new(),
        first_view: array_len(&doc, "bufferViews"),
        first_accessor: array_len(&doc, "accessors"),
    };
    let uv_name = format!("TEXCOORD_{uv_set}");
    let mut rewritten: Vec<(usize, usize, Value, usize)> = Vec::new();
    for p in primitives {
        let s = p.source;
        let json_primitive = &doc["meshes"][p.mesh]["primitives"][p.primitive];
        let mut attributes = Map::new();
        let names: Vec<String> = json_primitive
            .get("attributes")
            .and_then(Value::as_object)
            .map(|a| a.keys().cloned().collect())
            .unwrap_or_default();
        let at = format!("/meshes/{}/primitives/{}", p.mesh, p.primitive);
        for name in names.into_iter().filter(|n| *n != uv_name) {
            let index = match name.as_str() {
                "POSITION" => {
                    let v = gather(&s.positions, &p.vertex_of, &at)?;
                    Some(builder.floats(&to_arrays(&v, |x| x.to_array()), "VEC3", true))
                }
                "NORMAL" => s
                    .normals
                    .as_ref()
                    .map(|n| gather(n, &p.vertex_of, &at))
                    .transpose()?
                    .map(|v| builder.floats(&to_arrays(&v, |x| x.to_array()), "VEC3", false)),
                "TANGENT" => s
                    .tangents
                    .as_ref()
                    .map(|n| gather(n, &p.vertex_of, &at))
                    .transpose()?
                    .map(|v| builder.floats(&to_arrays(&v, |x| x.to_array()), "VEC4", false)),
                "TEXCOORD_0" | "TEXCOORD_1" => {
                    let source = if name == "TEXCOORD_0" {
                        &s.tex_coords0
                    } else {
                        &s.tex_coords1
                    };
                    source
                        .as_ref()
                        .map(|n| gather(n, &p.vertex_of, &at))
                        .transpose()?
                        .map(|v| builder.floats(&to_arrays(&v, |x| x.to_array()), "VEC2", false))
                }
                "COLOR_0" => s
                    .colors0
                    .as_ref()
                    .map(|n| gather(n, &p.vertex_of, &at))
                    .transpose()?
                    .map(|v| builder.floats(&to_arrays(&v, |x| x.to_array()), "VEC4", false)),
                other => {
                    return Err(format!(
                        "{at}: attribute {other} cannot be carried over yet (unwrap rewrites \
                         {}); nothing was written",
                        CARRIED.join(", ")
                    ));
                }
            };
            if let Some(index) = index {
                attributes.insert(name, json!(index));
            }
        }
        let uvs = builder.floats(&to_arrays(&p.uvs, |x| x.to_array()), "VEC2", false);
        attributes.insert(uv_name.clone(), json!(uvs));
        let indices = builder.indices(&p.triangles);
        rewritten.push((p.mesh, p.primitive, Value::Object(attributes), indices));
    }
    for (mesh, primitive, attributes, indices) in rewritten {
        let target = &mut doc["meshes"][mesh]["primitives"][primitive];
        if let Some(object) = target.as_object_mut() {
            object.insert("attributes".to_owned(), attributes);
            object.insert("indices".to_owned(), json!(indices));
            // Triangle lists (strips and fans were unrolled into triangles).
            object.remove("mode");
        }
    }
    builder.align();
    let Builder {
        bin,
        views,
        accessors,
        first_view,
        ..
    } = builder;
    let byte_length = bin.len();
    let root = doc
        .as_object_mut()
        .ok_or("the glTF JSON is not an object")?;
    push_all(root, "bufferViews", views);
    push_all(root, "accessors", accessors);
    if glb_out {
        if glb_buffer {
            root["buffers"][0]["byteLength"] = json!(byte_length);
        } else {
            // The new buffer becomes buffer 0, the binary chunk: every older view moves up.
            let old_views = root
                .get_mut("bufferViews")
                .and_then(Value::as_array_mut)
                .map_or(&mut [][..], |v| &mut v[..first_view]);
            for view in old_views {
                if let Some(b) = view.get("buffer").and_then(Value::as_u64) {
                    view["buffer"] = json!(b + 1);
                }
            }
            let buffers = root
                .entry("buffers")
                .or_insert_with(|| Value::Array(Vec::new()));
            if let Some(list) = buffers.as_array_mut() {
                list.insert(0, json!({ "byteLength": byte_length }));
            }
        }
    } else if glb_buffer {
        root["buffers"][0]["uri"] = json!(bin_uri);
        root["buffers"][0]["byteLength"] = json!(byte_length);
    } else {
        push_all(
            root,
            "buffers",
            vec![json!({"uri": bin_uri, "byteLength": byte_length})],
        );
    }
    let (text, bin_path) = if glb_out {
        let json = serde_json::to_vec(&doc).map_err(|e| format!("JSON: {e}"))?;
        (glb(&json, &bin)?, out.to_path_buf())
    } else {
        let text = serde_json::to_vec_pretty(&doc).map_err(|e| format!("JSON: {e}"))?;
        std::fs::write(&bin_path, &bin).map_err(|e| format!("{}: {e}", bin_path.display()))?;
        (text, bin_path)
    };
    let mut copied = Vec::new();
    for (from, to) in copies {
        if std::fs::canonicalize(&to).is_ok_and(|t| t == from) {
            continue;
        }
        let bytes = read_copy_source(&from, max_copy_bytes())?;
        if let Some(parent) = to.parent() {
            std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
        }
        std::fs::write(&to, bytes).map_err(|e| format!("{}: {e}", to.display()))?;
        copied.push(to);
    }
    std::fs::write(out, text).map_err(|e| format!("{}: {e}", out.display()))?;
    Ok((bin_path, copied))
}

/// A GLB file (glTF 2.0 §4.4): the 12-byte header, the JSON chunk padded with spaces and the
/// binary chunk padded with zeros, each to a multiple of 4 bytes.
fn glb(json: &[u8], bin: &[u8]) -> Result<Vec<u8>, String> {
    let padded = |n: usize| n.next_multiple_of(4);
    let total = 12 + 8 + padded(json.len()) + 8 + padded(bin.len());
    let too_big = || format!("the GLB would be {total} bytes, over the format's 4 GiB");
    let length = |n: usize| u32::try_from(n).map_err(|_| too_big());
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&length(total)?.to_le_bytes());
    out.extend_from_slice(&length(padded(json.len()))?.to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(json);
    out.resize(out.len() + padded(json.len()) - json.len(), b' ');
    out.extend_from_slice(&length(padded(bin.len()))?.to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(bin);
    out.resize(total, 0);
    Ok(out)
}

/// The largest file copied beside the output: what the loader accepts for one buffer or image.
fn max_copy_bytes() -> u64 {
    let limits = barytex_gltf::SceneLimits::default();
    limits.max_buffer_bytes.max(limits.max_image_file_bytes)
}

/// The bytes of a referenced file to copy, read as the loader reads its files
/// ([`barytex_gltf::read_regular_file`]): only a regular file within `max_bytes`. The loader
/// never reads a URI that no texture uses, so without this a FIFO there (whose open waits for a
/// writer forever) or a device would reach the copy unchecked.
fn read_copy_source(from: &Path, max_bytes: u64) -> Result<Vec<u8>, String> {
    let name = from.file_name().unwrap_or_default().to_string_lossy();
    barytex_gltf::read_regular_file(from, max_bytes).map_err(|e| match e {
        barytex_gltf::ResolveError::TooLarge(size) => {
            format!("{name}: {size} bytes, more than the {max_bytes} a referenced file may have")
        }
        barytex_gltf::ResolveError::NotRegularFile => {
            format!("{name}: not a regular file, not copied")
        }
        other => format!("{name}: {other}"),
    })
}

fn to_arrays<T, const N: usize>(values: &[T], f: impl Fn(&T) -> [f32; N]) -> Vec<[f32; N]> {
    values.iter().map(f).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_within_the_limit_are_copied() {
        let dir = std::env::temp_dir().join(format!("barytex-copy-source-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temporary folder");
        let file = dir.join("a.png");
        std::fs::write(&file, [0u8; 10]).expect("writable");
        assert_eq!(read_copy_source(&file, 10), Ok(vec![0u8; 10]));
        assert!(read_copy_source(&file, 9).is_err_and(|e| e.contains("more than")));
        assert!(read_copy_source(&dir, 10).is_err_and(|e| e.contains("not a regular file")));
        #[cfg(unix)]
        {
            let fifo = dir.join("fifo.png");
            let made = std::process::Command::new("mkfifo").arg(&fifo).status();
            if made.is_ok_and(|status| status.success()) {
                assert!(read_copy_source(&fifo, 10).is_err_and(|e| e.contains("not a regular")));
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
