//! A check of a PNG's palette chunk before the file reaches the `png` decoder.
//!
//! PNG requires the PLTE chunk to hold 1 to 256 three-byte entries (PNG, 3rd edition, §11.2.3
//! "PLTE Palette": "a chunk length not divisible by 3 is an error"). The `png` crate (0.18.1)
//! panics on such a chunk in its palette expansion instead of refusing the file (found by the
//! `png_jpeg_loader` fuzz target), so the loader refuses it first.

use crate::TextureError;

/// The PNG signature.
const SIGNATURE: [u8; 8] = [137, 80, 78, 71, 13, 10, 26, 10];

/// `Err` when `bytes` is a PNG whose PLTE chunk (before the first IDAT) is not 3 to 768 bytes
/// in whole entries; `Ok` otherwise, including for anything that is not a PNG (the decoder
/// judges the rest). Reads chunk headers only: at most one step per chunk, each at least 12
/// bytes, so the walk is bounded by the file's length.
pub(crate) fn check_palette(bytes: &[u8]) -> Result<(), TextureError> {
    if bytes.get(..8) != Some(SIGNATURE.as_slice()) {
        return Ok(());
    }
    let mut at = 8usize;
    while let Some(header) = bytes.get(at..at + 8) {
        let length = u32::from_be_bytes([header[0], header[1], header[2], header[3]]);
        match &header[4..8] {
            b"PLTE" if length == 0 || length % 3 != 0 || length > 768 => {
                return Err(TextureError::Decode(format!(
                    "PNG palette (PLTE) of {length} bytes: it must hold 1 to 256 three-byte entries"
                )));
            }
            b"IDAT" | b"IEND" => return Ok(()),
            _ => {}
        }
        // Chunk header, data, CRC; a length past the end ends the walk (the decoder reports it).
        at = match (length as usize).checked_add(at + 12) {
            Some(next) => next,
            None => return Ok(()),
        };
    }
    Ok(())
}
