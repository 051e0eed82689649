//! The two chunks of a GLB container (glTF 2.0 §4.4 "Binary glTF Layout"): the JSON and the
//! optional binary buffer, every length checked against the data.

/// `(json, bin)` of a GLB, or why not.
pub(crate) fn split(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), String> {
    let word = |at: usize| -> Option<u32> {
        Some(u32::from_le_bytes(bytes.get(at..at + 4)?.try_into().ok()?))
    };
    if bytes.get(0..4) != Some(b"glTF") || word(4) != Some(2) {
        return Err("not a version 2 GLB".to_owned());
    }
    let total = (word(8).ok_or("truncated GLB header")? as usize).min(bytes.len());
    let mut at = 12;
    let mut chunks: Vec<(u32, &[u8])> = Vec::new();
    while at + 8 <= total && chunks.len() < 2 {
        let (Some(length), Some(kind)) = (word(at), word(at + 4)) else {
            break;
        };
        let start = at + 8;
        let end = start
            .checked_add(length as usize)
            .filter(|&e| e <= total)
            .ok_or("a GLB chunk runs past the end of the file")?;
        chunks.push((kind, &bytes[start..end]));
        at = end;
    }
    match chunks.as_slice() {
        [(0x4E4F_534A, json)] => Ok((json, None)),
        [(0x4E4F_534A, json), (0x004E_4942, bin)] => Ok((json, Some(bin))),
        [(0x4E4F_534A, json), _] => Ok((json, None)),
        _ => Err("the GLB's first chunk is not JSON".to_owned()),
    }
}
