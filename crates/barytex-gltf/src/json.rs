//! Typed, pointer-tracking reads from the glTF JSON tree.
//!
//! The loader reads `serde_json` values (re-exported as `serde_json::Value`) field by field rather
//! than deserialising `gltf::json::Root`: that type refuses valid files (a scene without `nodes`,
//! an integer written as `1.0`) and its validation indexes arrays unchecked. Reading by hand
//! also lets every error carry the JSON pointer of the field at fault.

use serde_json::Value;

use crate::SceneError;

/// A JSON object (a `Value` known to be `Value::Object`) with the pointer that reaches it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Obj<'a> {
    value: &'a Value,
    pub(crate) ptr: &'a str,
}

/// Appends a reference token to a JSON pointer (escaping `~` and `/` per RFC 6901).
pub(crate) fn child(ptr: &str, token: &str) -> String {
    let escaped = token.replace('~', "~0").replace('/', "~1");
    format!("{ptr}/{escaped}")
}

fn type_error(ptr: String, expected: &str, got: &Value) -> SceneError {
    let kind = match got {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    };
    SceneError::invalid(ptr, format!("expected {expected}, found {kind}"))
}

/// Reads a JSON number as a non-negative integer; `1.0` counts (the validator accepts it).
pub(crate) fn as_u64(value: &Value, ptr: &str) -> Result<u64, SceneError> {
    if let Some(n) = value.as_u64() {
        return Ok(n);
    }
    if let Some(f) = value.as_f64() {
        if f.fract() == 0.0 && (0.0..9.0e15).contains(&f) {
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            return Ok(f as u64);
        }
        return Err(SceneError::invalid(
            ptr,
            format!("expected a non-negative integer, found {f}"),
        ));
    }
    Err(type_error(ptr.to_owned(), "a non-negative integer", value))
}

/// Reads a JSON number as a finite f32.
pub(crate) fn as_f32(value: &Value, ptr: &str) -> Result<f32, SceneError> {
    let f = value
        .as_f64()
        .ok_or_else(|| type_error(ptr.to_owned(), "a number", value))?;
    #[allow(clippy::cast_possible_truncation)]
    let g = f as f32;
    if !g.is_finite() {
        return Err(SceneError::invalid(
            ptr,
            format!("{f} is not a finite single-precision number"),
        ));
    }
    Ok(g)
}

/// Reads an object.
pub(crate) fn as_obj<'a>(value: &'a Value, ptr: &'a str) -> Result<Obj<'a>, SceneError> {
    match value {
        Value::Object(_) => Ok(Obj { value, ptr }),
        other => Err(type_error(ptr.to_owned(), "an object", other)),
    }
}

impl<'a> Obj<'a> {
    /// The pointer to one of this object's fields.
    pub(crate) fn at(&self, key: &str) -> String {
        child(self.ptr, key)
    }

    /// The object itself.
    pub(crate) fn value(&self) -> &'a Value {
        self.value
    }

    /// The raw value of a field.
    pub(crate) fn get(&self, key: &str) -> Option<&'a Value> {
        self.value.get(key)
    }

    /// An error about a field of this object.
    pub(crate) fn error(&self, key: &str, reason: impl Into<String>) -> SceneError {
        SceneError::invalid(self.at(key), reason)
    }

    fn missing(&self, key: &str) -> SceneError {
        SceneError::invalid(self.ptr, format!("required property '{key}' is missing"))
    }

    /// An optional non-negative integer.
    pub(crate) fn opt_u64(&self, key: &str) -> Result<Option<u64>, SceneError> {
        self.get(key).map(|v| as_u64(v, &self.at(key))).transpose()
    }

    /// A required non-negative integer.
    pub(crate) fn req_u64(&self, key: &str) -> Result<u64, SceneError> {
        self.opt_u64(key)?.ok_or_else(|| self.missing(key))
    }

    /// An optional index into an array of `len` objects.
    pub(crate) fn opt_index(
        &self,
        key: &str,
        len: usize,
        what: &str,
    ) -> Result<Option<usize>, SceneError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let ptr = self.at(key);
        check_index(as_u64(v, &ptr)?, len, what, &ptr).map(Some)
    }

    /// A required index into an array of `len` objects.
    pub(crate) fn req_index(&self, key: &str, len: usize, what: &str) -> Result<usize, SceneError> {
        self.opt_index(key, len, what)?
            .ok_or_else(|| self.missing(key))
    }

    /// An optional finite number.
    pub(crate) fn opt_f32(&self, key: &str) -> Result<Option<f32>, SceneError> {
        self.get(key).map(|v| as_f32(v, &self.at(key))).transpose()
    }

    /// A required finite number.
    pub(crate) fn req_f32(&self, key: &str) -> Result<f32, SceneError> {
        self.opt_f32(key)?.ok_or_else(|| self.missing(key))
    }

    /// An optional array of exactly `N` finite numbers.
    pub(crate) fn opt_f32s<const N: usize>(
        &self,
        key: &str,
    ) -> Result<Option<[f32; N]>, SceneError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let ptr = self.at(key);
        let arr = v
            .as_array()
            .ok_or_else(|| type_error(ptr.clone(), "an array", v))?;
        if arr.len() != N {
            return Err(SceneError::invalid(
                ptr,
                format!("expected {N} numbers, found {}", arr.len()),
            ));
        }
        let mut out = [0.0; N];
        for (i, (slot, item)) in out.iter_mut().zip(arr).enumerate() {
            *slot = as_f32(item, &child(&ptr, &i.to_string()))?;
        }
        Ok(Some(out))
    }

    /// An optional string.
    pub(crate) fn opt_str(&self, key: &str) -> Result<Option<&'a str>, SceneError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::String(s)) => Ok(Some(s)),
            Some(other) => Err(type_error(self.at(key), "a string", other)),
        }
    }

    /// A required string.
    pub(crate) fn req_str(&self, key: &str) -> Result<&'a str, SceneError> {
        self.opt_str(key)?.ok_or_else(|| self.missing(key))
    }

    /// An optional boolean.
    pub(crate) fn opt_bool(&self, key: &str) -> Result<Option<bool>, SceneError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Bool(b)) => Ok(Some(*b)),
            Some(other) => Err(type_error(self.at(key), "a boolean", other)),
        }
    }

    /// An optional object (returned with its pointer, which the caller keeps alive).
    pub(crate) fn opt_obj(&self, key: &str) -> Result<Option<&'a Value>, SceneError> {
        match self.get(key) {
            None => Ok(None),
            Some(v @ Value::Object(_)) => Ok(Some(v)),
            Some(other) => Err(type_error(self.at(key), "an object", other)),
        }
    }

    /// An optional array.
    pub(crate) fn opt_array(&self, key: &str) -> Result<Option<&'a [Value]>, SceneError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Array(a)) => Ok(Some(a)),
            Some(other) => Err(type_error(self.at(key), "an array", other)),
        }
    }

    /// An optional array of indices into an array of `len` objects.
    pub(crate) fn opt_indices(
        &self,
        key: &str,
        len: usize,
        what: &str,
    ) -> Result<Option<Vec<usize>>, SceneError> {
        let Some(arr) = self.opt_array(key)? else {
            return Ok(None);
        };
        let ptr = self.at(key);
        let mut out = Vec::with_capacity(arr.len());
        for (i, v) in arr.iter().enumerate() {
            let p = child(&ptr, &i.to_string());
            out.push(check_index(as_u64(v, &p)?, len, what, &p)?);
        }
        Ok(Some(out))
    }

    /// The object of a named extension, if present.
    pub(crate) fn extension(&self, name: &str) -> Result<Option<&'a Value>, SceneError> {
        let Some(ext) = self.opt_obj("extensions")? else {
            return Ok(None);
        };
        match ext.get(name) {
            None => Ok(None),
            Some(v @ Value::Object(_)) => Ok(Some(v)),
            Some(other) => Err(type_error(
                child(&self.at("extensions"), name),
                "an object",
                other,
            )),
        }
    }
}

/// Checks an index against the length of the array it points into.
pub(crate) fn check_index(
    index: u64,
    len: usize,
    what: &str,
    ptr: &str,
) -> Result<usize, SceneError> {
    usize::try_from(index)
        .ok()
        .filter(|&i| i < len)
        .ok_or_else(|| {
            SceneError::invalid(
                ptr,
                format!("unresolved reference: {what} {index} does not exist ({len} defined)"),
            )
        })
}

/// Array-valued properties of the glTF schema (and of the extensions this crate reads), all of
/// which require at least one item. Unknown (custom) properties are not judged.
const NON_EMPTY_ARRAYS: [&str; 27] = [
    "accessors",
    "animations",
    "buffers",
    "bufferViews",
    "cameras",
    "images",
    "materials",
    "meshes",
    "nodes",
    "samplers",
    "scenes",
    "skins",
    "textures",
    "extensionsUsed",
    "extensionsRequired",
    "children",
    "primitives",
    "targets",
    "weights",
    "joints",
    "channels",
    "min",
    "max",
    "lights",
    "variants",
    "mappings",
    "matrix",
];

/// Walks the tree refusing empty arrays where the glTF schema forbids them (`minItems: 1`),
/// except inside `extras` and inside extensions this crate does not read.
pub(crate) fn check_no_empty_arrays(
    value: &Value,
    ptr: &str,
    depth: usize,
) -> Result<(), SceneError> {
    const KNOWN_EXTENSIONS: [&str; 4] = [
        "KHR_lights_punctual",
        "KHR_texture_transform",
        "KHR_materials_unlit",
        "KHR_materials_variants",
    ];
    if depth > 128 {
        return Err(SceneError::invalid(ptr, "JSON nested too deeply"));
    }
    match value {
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                check_no_empty_arrays(item, &child(ptr, &i.to_string()), depth + 1)?;
            }
        }
        Value::Object(map) => {
            for (key, item) in map {
                match key.as_str() {
                    "extras" => {}
                    "extensions" => {
                        if let Value::Object(exts) = item {
                            let ext_ptr = child(ptr, key);
                            for (name, ext) in exts {
                                if KNOWN_EXTENSIONS.contains(&name.as_str()) {
                                    check_no_empty_arrays(ext, &child(&ext_ptr, name), depth + 1)?;
                                }
                            }
                        }
                    }
                    _ => {
                        let item_ptr = child(ptr, key);
                        if item.as_array().is_some_and(Vec::is_empty)
                            && NON_EMPTY_ARRAYS.contains(&key.as_str())
                        {
                            return Err(SceneError::invalid(
                                item_ptr,
                                "an empty array (this property needs at least one item)",
                            ));
                        }
                        check_no_empty_arrays(item, &item_ptr, depth + 1)?;
                    }
                }
            }
        }
        _ => {}
    }
    Ok(())
}
