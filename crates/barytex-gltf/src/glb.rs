//! The GLB container, parsed by hand with every length checked: the `gltf` crate's own GLB
//! reader trusts the header (and panics on a zero-length file), so untrusted bytes never reach it.
//!
//! Layout (glTF 2.0 §4.4): a 12-byte header `magic "glTF", version 2, total length`, then chunks
//! `length, type, data[length]`, each length a multiple of 4. The first chunk is JSON, the second
//! (optional) is the one BIN chunk; chunks of unknown type are skipped.

use crate::SceneError;

/// `"glTF"` read as a little-endian u32.
const MAGIC: u32 = 0x4654_6C67;
/// `"JSON"` chunk type.
const CHUNK_JSON: u32 = 0x4E4F_534A;
/// `"BIN\0"` chunk type.
const CHUNK_BIN: u32 = 0x004E_4942;
const HEADER_LEN: usize = 12;
const CHUNK_HEADER_LEN: usize = 8;

/// A validated GLB: the JSON chunk and the BIN chunk, borrowed from the file.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Glb<'a> {
    /// The JSON chunk's bytes (may end in space padding, which JSON ignores).
    pub(crate) json: &'a [u8],
    /// The BIN chunk's bytes, when present.
    pub(crate) bin: Option<&'a [u8]>,
    /// Bytes after the declared total length (ignored, reported as a warning).
    pub(crate) trailing_bytes: usize,
}

/// Whether `bytes` start with the GLB magic.
pub(crate) fn is_glb(bytes: &[u8]) -> bool {
    bytes.get(..4) == Some(b"glTF".as_slice())
}

fn read_u32(bytes: &[u8], at: usize) -> Option<u32> {
    let b = bytes.get(at..at.checked_add(4)?)?;
    Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
}

fn err(msg: impl Into<String>) -> SceneError {
    SceneError::Glb(msg.into())
}

/// Parses and validates a GLB container.
pub(crate) fn parse(bytes: &[u8]) -> Result<Glb<'_>, SceneError> {
    if bytes.len() < HEADER_LEN {
        return Err(err(format!(
            "unexpected end of header: {} bytes, a GLB header has 12",
            bytes.len()
        )));
    }
    let magic = read_u32(bytes, 0).ok_or_else(|| err("unexpected end of header"))?;
    if magic != MAGIC {
        return Err(err(format!(
            "invalid magic 0x{magic:08x}, expected \"glTF\""
        )));
    }
    let version = read_u32(bytes, 4).ok_or_else(|| err("unexpected end of header"))?;
    if version != 2 {
        return Err(err(format!(
            "unsupported GLB version {version}, expected 2"
        )));
    }
    let length = read_u32(bytes, 8).ok_or_else(|| err("unexpected end of header"))?;
    let length = usize::try_from(length).map_err(|_| err("total length does not fit memory"))?;
    if length < HEADER_LEN + CHUNK_HEADER_LEN {
        return Err(err(format!(
            "total length {length} is too small for a header and a JSON chunk"
        )));
    }
    if length > bytes.len() {
        return Err(err(format!(
            "total length {length} exceeds the {} bytes present",
            bytes.len()
        )));
    }
    if length % 4 != 0 {
        return Err(err(format!("total length {length} is not a multiple of 4")));
    }
    let data = bytes
        .get(..length)
        .ok_or_else(|| err("total length mismatch"))?;
    let mut at = HEADER_LEN;
    let mut json: Option<&[u8]> = None;
    let mut bin: Option<&[u8]> = None;
    let mut index = 0usize;
    while at < data.len() {
        if data.len() - at < CHUNK_HEADER_LEN {
            return Err(err(format!("unexpected end of chunk header at byte {at}")));
        }
        let chunk_len = read_u32(data, at).ok_or_else(|| err("unexpected end of chunk header"))?;
        let chunk_type =
            read_u32(data, at + 4).ok_or_else(|| err("unexpected end of chunk header"))?;
        let chunk_len =
            usize::try_from(chunk_len).map_err(|_| err("chunk length does not fit memory"))?;
        if chunk_len % 4 != 0 {
            return Err(err(format!(
                "chunk {index} length {chunk_len} is not a multiple of 4"
            )));
        }
        let start = at + CHUNK_HEADER_LEN;
        let end = start
            .checked_add(chunk_len)
            .filter(|&end| end <= data.len())
            .ok_or_else(|| {
                err(format!(
                    "chunk {index} ({chunk_len} bytes at byte {start}) runs past the total length {length}"
                ))
            })?;
        let chunk = data
            .get(start..end)
            .ok_or_else(|| err("chunk out of range"))?;
        match (index, chunk_type) {
            (0, CHUNK_JSON) => {
                if chunk.is_empty() {
                    return Err(err("the JSON chunk is empty"));
                }
                json = Some(chunk);
            }
            (0, other) => {
                return Err(err(format!(
                    "the first chunk has type 0x{other:08x}, expected JSON"
                )));
            }
            (_, CHUNK_JSON) => return Err(err(format!("chunk {index}: a second JSON chunk"))),
            (1, CHUNK_BIN) => bin = Some(chunk),
            (_, CHUNK_BIN) => {
                return Err(err(format!(
                    "chunk {index}: a BIN chunk must be the second chunk and appear once"
                )));
            }
            // Unknown chunk types are skipped (glTF 2.0 §4.4.3.1).
            _ => {}
        }
        at = end;
        index += 1;
    }
    let json = json.ok_or_else(|| err("no JSON chunk"))?;
    Ok(Glb {
        json,
        bin,
        trailing_bytes: bytes.len() - length,
    })
}

/// The JSON chunk and the BIN chunk (when present) of a GLB file, validated as the loader
/// validates them (glTF 2.0 §4.4: header, chunk lengths and order, every length checked against
/// the data; unknown chunk types skipped).
///
/// # Errors
/// [`SceneError::Glb`] naming what is wrong with the container.
///
/// ```
/// use barytex_gltf::glb_chunks;
///
/// let mut glb = b"glTF".to_vec();
/// glb.extend(2u32.to_le_bytes());
/// glb.extend(24u32.to_le_bytes()); // header 12 + chunk header 8 + 4 bytes of JSON
/// glb.extend(4u32.to_le_bytes());
/// glb.extend(b"JSON");
/// glb.extend(b"{}  ");
/// assert_eq!(glb_chunks(&glb)?, (b"{}  ".as_slice(), None));
/// assert!(glb_chunks(b"glTF").is_err());
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
pub fn glb_chunks(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), SceneError> {
    let glb = parse(bytes)?;
    Ok((glb.json, glb.bin))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn glb(chunks: &[(u32, &[u8])]) -> Vec<u8> {
        let mut body = Vec::new();
        for (ty, data) in chunks {
            body.extend_from_slice(&u32::try_from(data.len()).unwrap_or(0).to_le_bytes());
            body.extend_from_slice(&ty.to_le_bytes());
            body.extend_from_slice(data);
        }
        let mut out = Vec::new();
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&u32::try_from(body.len() + 12).unwrap_or(0).to_le_bytes());
        out.extend_from_slice(&body);
        out
    }

    #[test]
    fn accepts_json_and_bin() {
        let bytes = glb(&[(CHUNK_JSON, b"{}  "), (CHUNK_BIN, &[1, 2, 3, 4])]);
        let parsed = parse(&bytes);
        assert!(matches!(
            parsed,
            Ok(Glb {
                bin: Some([1, 2, 3, 4]),
                ..
            })
        ));
    }

    #[test]
    fn refuses_malformed_containers() {
        assert!(parse(&[]).is_err());
        assert!(parse(b"glTF").is_err());
        assert!(parse(&glb(&[(CHUNK_BIN, &[0; 4])])).is_err());
        assert!(parse(&glb(&[(CHUNK_JSON, b"{}  "), (CHUNK_JSON, b"{}  ")])).is_err());
        assert!(parse(&glb(&[(CHUNK_JSON, b"{} "), (CHUNK_BIN, &[0; 4])])).is_err());
        let mut bad_len = glb(&[(CHUNK_JSON, b"{}  ")]);
        bad_len[8] = 200;
        assert!(parse(&bad_len).is_err());
    }
}
