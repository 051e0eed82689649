//! Buffers: where their bytes come from (the GLB BIN chunk, a `data:` URI or a file next to the
//! glTF), with the declared `byteLength` checked against limits before reading and against the
//! data actually found after.

use crate::access::{self, UriResolver};
use crate::json::Obj;
use crate::uri::{self, Uri};
use crate::{SceneError, SceneLimits};

/// A buffer as declared.
#[derive(Clone, Debug)]
pub(crate) struct BufferDef {
    pub(crate) ptr: String,
    pub(crate) byte_length: u64,
    /// `None`: the GLB BIN chunk (buffer 0 of a GLB) or a placeholder without data.
    pub(crate) uri: Option<Uri>,
}

impl BufferDef {
    pub(crate) fn parse(obj: Obj<'_>, limits: &SceneLimits) -> Result<Self, SceneError> {
        let byte_length = obj.req_u64("byteLength")?;
        if byte_length == 0 {
            return Err(obj.error("byteLength", "byteLength must be ≥ 1"));
        }
        if byte_length > limits.max_buffer_bytes {
            return Err(SceneError::TooLarge {
                pointer: obj.at("byteLength"),
                what: "buffer bytes",
                requested: byte_length,
                limit: limits.max_buffer_bytes,
            });
        }
        let uri = match obj.opt_str("uri")? {
            None => None,
            Some(s) => {
                let parsed = uri::parse(s, limits.max_buffer_bytes)
                    .map_err(|reason| obj.error("uri", reason))?;
                if let Uri::Data { media_type, .. } = &parsed
                    && media_type != "application/octet-stream"
                    && media_type != "application/gltf-buffer"
                {
                    return Err(obj.error(
                            "uri",
                            format!("buffer data URI media type {media_type:?} is not application/octet-stream or application/gltf-buffer"),
                        ));
                }
                Some(parsed)
            }
        };
        Ok(Self {
            ptr: obj.ptr.to_owned(),
            byte_length,
            uri,
        })
    }
}

/// Where a document came from, for resolving its buffers and images.
#[derive(Clone, Copy)]
pub(crate) struct Source<'a> {
    /// What serves relative URIs (the model's folder, or the embedder's resolver); `None` for
    /// in-memory input.
    pub(crate) files: Option<&'a dyn UriResolver>,
    /// The GLB BIN chunk, when the input was a GLB with one.
    pub(crate) bin: Option<&'a [u8]>,
    /// Whether the input was a GLB.
    pub(crate) is_glb: bool,
}

/// Loads the data of every buffer that a bufferView uses (`used`); unused buffers are only
/// checked (their file must exist and be long enough), never read.
pub(crate) fn load_all(
    defs: &[BufferDef],
    used: &[bool],
    source: Source<'_>,
    limits: &SceneLimits,
    warnings: &mut Vec<String>,
) -> Result<Vec<Option<Vec<u8>>>, SceneError> {
    let total: u64 = defs
        .iter()
        .map(|d| d.byte_length)
        .fold(0, u64::saturating_add);
    if total > limits.max_total_buffer_bytes {
        return Err(SceneError::TooLarge {
            pointer: "/buffers".to_owned(),
            what: "total buffer bytes",
            requested: total,
            limit: limits.max_total_buffer_bytes,
        });
    }
    let mut out = Vec::with_capacity(defs.len());
    for (i, def) in defs.iter().enumerate() {
        let is_used = used.get(i).copied().unwrap_or(false);
        out.push(load_one(i, def, is_used, source, limits, warnings)?);
    }
    Ok(out)
}

fn load_one(
    index: usize,
    def: &BufferDef,
    used: bool,
    source: Source<'_>,
    limits: &SceneLimits,
    warnings: &mut Vec<String>,
) -> Result<Option<Vec<u8>>, SceneError> {
    let uri_ptr = format!("{}/uri", def.ptr);
    let data: Vec<u8> = match &def.uri {
        None if source.is_glb && index == 0 => {
            let bin = source.bin.ok_or_else(|| {
                SceneError::invalid(&def.ptr, "buffer 0 has no uri but the GLB has no BIN chunk")
            })?;
            let declared = usize::try_from(def.byte_length).unwrap_or(usize::MAX);
            if bin.len() < declared {
                return Err(SceneError::invalid(
                    &def.ptr,
                    format!(
                        "BIN chunk holds {} bytes, byteLength declares {}",
                        bin.len(),
                        def.byte_length
                    ),
                ));
            }
            if bin.len() - declared > 3 {
                warnings.push(format!(
                    "{}: the BIN chunk has {} bytes beyond byteLength",
                    def.ptr,
                    bin.len() - declared
                ));
            }
            bin.get(..declared).unwrap_or_default().to_vec()
        }
        None => {
            if used {
                warnings.push(format!("{}: buffer without uri has no data", def.ptr));
            }
            return Ok(None);
        }
        Some(Uri::Data { bytes, .. }) => bytes.clone(),
        Some(Uri::NonRelative(u)) => {
            if used {
                return Err(SceneError::invalid(
                    uri_ptr,
                    format!("non-relative URI {u:?}: only data URIs and relative files are loaded"),
                ));
            }
            warnings.push(format!(
                "{uri_ptr}: unused buffer with non-relative URI {u:?} not fetched"
            ));
            return Ok(None);
        }
        Some(Uri::Relative(rel)) => {
            let Some(files) = source.files else {
                return Err(SceneError::invalid(
                    uri_ptr,
                    format!(
                        "external file {rel:?} cannot be resolved for in-memory input (no base folder)"
                    ),
                ));
            };
            if !used {
                let len = access::size(
                    files,
                    &uri_ptr,
                    rel,
                    "buffer file bytes",
                    limits.max_buffer_bytes,
                )?;
                if len < def.byte_length {
                    return Err(SceneError::invalid(
                        &def.ptr,
                        format!(
                            "file holds {len} bytes, byteLength declares {}",
                            def.byte_length
                        ),
                    ));
                }
                return Ok(None);
            }
            access::fetch(
                files,
                &uri_ptr,
                rel,
                "buffer file bytes",
                limits.max_buffer_bytes,
            )?
        }
    };
    let declared = usize::try_from(def.byte_length).unwrap_or(usize::MAX);
    if data.len() < declared {
        return Err(SceneError::invalid(
            &def.ptr,
            format!(
                "data holds {} bytes, byteLength declares {}",
                data.len(),
                def.byte_length
            ),
        ));
    }
    if data.len() > declared {
        warnings.push(format!(
            "{}: data holds {} bytes, more than byteLength {}",
            def.ptr,
            data.len(),
            def.byte_length
        ));
    }
    let mut data = data;
    data.truncate(declared);
    Ok(Some(data))
}
