//! Extension objects anywhere in the document: each must be a JSON object, declared in
//! `extensionsUsed`, and — for the Khronos extensions whose placement is specified — attached to
//! the kind of object the extension extends (a `KHR_materials_*` object on a node is a broken
//! file, not a feature).

use serde_json::Value;

use crate::SceneError;
use crate::json::child;

/// The kind of glTF object a JSON pointer designates, as far as extension placement cares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Root,
    Node,
    Material,
    Texture,
    TextureInfo,
    Primitive,
    ChannelTarget,
    Buffer,
    BufferView,
    Other,
}

fn classify(tokens: &[&str]) -> Kind {
    match tokens {
        [] => Kind::Root,
        ["nodes", _] => Kind::Node,
        ["materials", _] => Kind::Material,
        ["textures", _] => Kind::Texture,
        ["buffers", _] => Kind::Buffer,
        ["bufferViews", _] => Kind::BufferView,
        ["meshes", _, "primitives", _] => Kind::Primitive,
        ["animations", _, "channels", _, "target"] => Kind::ChannelTarget,
        ["materials", .., last] if last.ends_with("Texture") => Kind::TextureInfo,
        _ => Kind::Other,
    }
}

/// Where an extension's objects may appear; `None` for extensions this table does not know.
fn placement(name: &str) -> Option<&'static [Kind]> {
    Some(match name {
        "KHR_lights_punctual" => &[Kind::Root, Kind::Node],
        "KHR_materials_variants" => &[Kind::Root, Kind::Primitive],
        n if n.starts_with("KHR_materials_") => &[Kind::Material],
        "KHR_texture_transform" => &[Kind::TextureInfo],
        "EXT_texture_webp" | "KHR_texture_basisu" | "EXT_texture_avif" => &[Kind::Texture],
        "KHR_node_visibility" | "EXT_mesh_gpu_instancing" => &[Kind::Node],
        "KHR_animation_pointer" => &[Kind::ChannelTarget],
        "KHR_draco_mesh_compression" => &[Kind::Primitive],
        "EXT_meshopt_compression" => &[Kind::Buffer, Kind::BufferView],
        "KHR_mesh_quantization" => &[],
        _ => return None,
    })
}

/// Checks every `extensions` object in the tree.
pub(crate) fn check(root: &Value, used: &[String]) -> Result<(), SceneError> {
    let mut tokens = Vec::new();
    walk(root, "", &mut tokens, used)
}

fn walk<'a>(
    value: &'a Value,
    ptr: &str,
    tokens: &mut Vec<&'a str>,
    used: &[String],
) -> Result<(), SceneError> {
    if tokens.len() > 128 {
        return Err(SceneError::invalid(ptr, "JSON nested too deeply"));
    }
    match value {
        Value::Object(map) => {
            for (key, item) in map {
                let item_ptr = child(ptr, key);
                match key.as_str() {
                    "extras" => {}
                    "extensions" => {
                        let Value::Object(exts) = item else {
                            return Err(SceneError::invalid(
                                item_ptr,
                                "'extensions' must be an object",
                            ));
                        };
                        let kind = classify(tokens);
                        for (name, ext) in exts {
                            let ext_ptr = child(&item_ptr, name);
                            if !ext.is_object() {
                                return Err(SceneError::invalid(
                                    ext_ptr,
                                    "an extension must be a JSON object",
                                ));
                            }
                            if !used.iter().any(|u| u == name) {
                                return Err(SceneError::invalid(
                                    ext_ptr,
                                    format!("{name} is not declared in extensionsUsed"),
                                ));
                            }
                            if placement(name).is_some_and(|kinds| !kinds.contains(&kind)) {
                                return Err(SceneError::invalid(
                                    ext_ptr,
                                    format!("{name} does not extend this kind of object"),
                                ));
                            }
                            tokens.push("extensions");
                            tokens.push(name);
                            walk(ext, &ext_ptr, tokens, used)?;
                            tokens.pop();
                            tokens.pop();
                        }
                    }
                    _ => {
                        tokens.push(key);
                        walk(item, &item_ptr, tokens, used)?;
                        tokens.pop();
                    }
                }
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                // Array positions only matter as "some index": a fixed token keeps the borrow simple.
                tokens.push("#");
                walk(item, &child(ptr, &i.to_string()), tokens, used)?;
                tokens.pop();
            }
        }
        _ => {}
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placement_by_pointer() {
        assert_eq!(
            classify(&["materials", "#", "pbrMetallicRoughness", "baseColorTexture"]),
            Kind::TextureInfo
        );
        assert_eq!(
            classify(&["meshes", "#", "primitives", "#"]),
            Kind::Primitive
        );
        assert_eq!(classify(&[]), Kind::Root);
        assert_eq!(classify(&["nodes", "#"]), Kind::Node);
    }
}
