//! Images: declared sources checked for every image (one of `uri`/`bufferView`, MIME type,
//! the file's magic bytes and chunk structure), pixels decoded only for images a material of the
//! chosen scene samples, with the texture limits checked against the header before decoding.

use std::borrow::Cow;

use barytex_texture::load::{AnyTexture2d, ColorSpace};

use crate::access;
use crate::accessor::{Reader, ViewDef};
use crate::buffer::Source;
use crate::json::Obj;
use crate::uri::{self, Uri};
use crate::{SceneError, SceneLimits};

/// Where an image's bytes are.
#[derive(Clone, Debug)]
pub(crate) enum ImageSource {
    Uri(Uri),
    View(usize),
}

/// An image as declared.
#[derive(Clone, Debug)]
pub(crate) struct ImageDef {
    pub(crate) ptr: String,
    pub(crate) name: Option<String>,
    pub(crate) source: ImageSource,
    /// Declared MIME type (`mimeType`, or a data URI's media type).
    pub(crate) mime: Option<String>,
}

fn mime_allowed(mime: &str, webp: bool) -> bool {
    matches!(mime, "image/png" | "image/jpeg") || (webp && mime == "image/webp")
}

impl ImageDef {
    pub(crate) fn parse(
        obj: Obj<'_>,
        views: &[ViewDef],
        webp: bool,
        limits: &SceneLimits,
    ) -> Result<Self, SceneError> {
        let uri_str = obj.opt_str("uri")?;
        let view = obj.opt_index("bufferView", views.len(), "bufferView")?;
        let mut mime = obj.opt_str("mimeType")?.map(str::to_owned);
        if let Some(m) = &mime
            && !mime_allowed(m, webp)
        {
            return Err(obj.error("mimeType", format!("unsupported image MIME type {m:?}")));
        }
        let source = match (uri_str, view) {
            (Some(_), Some(_)) | (None, None) => {
                return Err(SceneError::invalid(
                    obj.ptr,
                    "exactly one of 'uri' and 'bufferView' must be defined",
                ));
            }
            (Some(u), None) => {
                let parsed = uri::parse(u, limits.max_image_file_bytes)
                    .map_err(|reason| obj.error("uri", reason))?;
                if let Uri::Data { media_type, .. } = &parsed {
                    if !mime_allowed(media_type, webp) {
                        return Err(obj.error(
                            "uri",
                            format!("image data URI media type {media_type:?} is not image/png or image/jpeg"),
                        ));
                    }
                    if let Some(m) = &mime
                        && m != media_type
                    {
                        return Err(obj.error(
                            "mimeType",
                            "mimeType differs from the data URI's media type",
                        ));
                    }
                    mime = Some(media_type.clone());
                }
                ImageSource::Uri(parsed)
            }
            (None, Some(v)) => {
                if mime.is_none() {
                    return Err(
                        obj.error("bufferView", "an image in a bufferView requires 'mimeType'")
                    );
                }
                if views.get(v).is_some_and(|v| v.stride.is_some()) {
                    return Err(obj.error(
                        "bufferView",
                        "an image's bufferView must not define byteStride",
                    ));
                }
                ImageSource::View(v)
            }
        };
        Ok(Self {
            ptr: obj.ptr.to_owned(),
            name: obj.opt_str("name")?.map(str::to_owned),
            source,
            mime,
        })
    }

    /// The encoded bytes. `Ok(None)` for a non-relative URI (never fetched).
    pub(crate) fn bytes<'r>(
        &self,
        reader: &'r Reader<'_>,
        source: Source<'_>,
        limits: &SceneLimits,
    ) -> Result<Option<Cow<'r, [u8]>>, SceneError> {
        let uri_ptr = format!("{}/uri", self.ptr);
        match &self.source {
            ImageSource::View(v) => Ok(Some(Cow::Borrowed(reader.view_bytes(*v, &self.ptr)?))),
            ImageSource::Uri(Uri::Data { bytes, .. }) => Ok(Some(Cow::Owned(bytes.clone()))),
            ImageSource::Uri(Uri::NonRelative(_)) => Ok(None),
            ImageSource::Uri(Uri::Relative(rel)) => {
                let files = source.files.ok_or_else(|| {
                    SceneError::invalid(
                        &uri_ptr,
                        format!("external image {rel:?} cannot be resolved for in-memory input"),
                    )
                })?;
                let bytes = access::fetch(
                    files,
                    &uri_ptr,
                    rel,
                    "image file bytes",
                    limits.max_image_file_bytes,
                )?;
                Ok(Some(Cow::Owned(bytes)))
            }
        }
    }

    /// Checks the encoded bytes: recognised format matching the declared MIME type, and a
    /// complete chunk/segment structure. Returns a warning for an unrecognised format (an error
    /// only if the image is decoded).
    pub(crate) fn check_bytes(&self, bytes: &[u8]) -> Result<Option<String>, SceneError> {
        let sniffed = sniff(bytes).map_err(|reason| SceneError::Image {
            pointer: self.ptr.clone(),
            reason,
        })?;
        match (sniffed, &self.mime) {
            (Some(found), Some(declared)) if found != declared => Err(SceneError::invalid(
                &self.ptr,
                format!("declared {declared} but the data is {found}"),
            )),
            (None, _) => Ok(Some(format!("{}: image format not recognised", self.ptr))),
            _ => Ok(None),
        }
    }

    /// Decodes the image in `color_space`, refusing it before decoding when the header exceeds
    /// `limits.image`.
    pub(crate) fn decode(
        &self,
        bytes: &[u8],
        color_space: ColorSpace,
        limits: &SceneLimits,
    ) -> Result<AnyTexture2d, SceneError> {
        if sniff(bytes).ok().flatten() == Some("image/webp") {
            return Err(SceneError::Image {
                pointer: self.ptr.clone(),
                reason: "WebP images are not supported".to_owned(),
            });
        }
        barytex_texture::load::load_from_memory(bytes, color_space, &limits.image).map_err(|e| {
            SceneError::Image {
                pointer: self.ptr.clone(),
                reason: e.to_string(),
            }
        })
    }
}

/// Identifies PNG, JPEG and WebP data and checks its container structure without decoding.
fn sniff(b: &[u8]) -> Result<Option<&'static str>, String> {
    const PNG: &[u8] = b"\x89PNG\r\n\x1a\n";
    if b.starts_with(PNG) {
        check_png(b)?;
        return Ok(Some("image/png"));
    }
    if b.starts_with(&[0xFF, 0xD8, 0xFF]) {
        check_jpeg(b)?;
        return Ok(Some("image/jpeg"));
    }
    if b.len() >= 12 && b.get(..4) == Some(b"RIFF") && b.get(8..12) == Some(b"WEBP") {
        return Ok(Some("image/webp"));
    }
    Ok(None)
}

fn be32(b: &[u8], at: usize) -> Option<u32> {
    let s = b.get(at..at.checked_add(4)?)?;
    Some(u32::from_be_bytes([s[0], s[1], s[2], s[3]]))
}

/// Walks PNG chunks (length, type, data, CRC) up to `IEND`.
fn check_png(b: &[u8]) -> Result<(), String> {
    let mut at = 8usize;
    let mut first = true;
    loop {
        let len = be32(b, at).ok_or("unexpected end of PNG stream")?;
        let ty = b
            .get(at + 4..at + 8)
            .ok_or("unexpected end of PNG stream")?;
        if first && ty != b"IHDR" {
            return Err("PNG does not start with IHDR".to_owned());
        }
        first = false;
        let next = usize::try_from(len)
            .ok()
            .and_then(|l| at.checked_add(12)?.checked_add(l))
            .ok_or("PNG chunk length overflows")?;
        if next > b.len() {
            return Err("unexpected end of PNG stream".to_owned());
        }
        if ty == b"IEND" {
            return Ok(());
        }
        at = next;
    }
}

/// Walks JPEG marker segments up to the start of scan (or the end of image).
fn check_jpeg(b: &[u8]) -> Result<(), String> {
    let mut at = 2usize;
    loop {
        // Markers may be preceded by any number of 0xFF fill bytes.
        let mut marker_at = at;
        if b.get(marker_at) != Some(&0xFF) {
            return Err("invalid JPEG marker".to_owned());
        }
        while b.get(marker_at) == Some(&0xFF) {
            marker_at += 1;
        }
        let marker = *b.get(marker_at).ok_or("unexpected end of JPEG stream")?;
        at = marker_at + 1;
        match marker {
            0xD9 => return Ok(()),
            0x01 | 0xD0..=0xD7 => continue,
            _ => {}
        }
        let hi = *b.get(at).ok_or("unexpected end of JPEG stream")?;
        let lo = *b.get(at + 1).ok_or("unexpected end of JPEG stream")?;
        let len = usize::from(u16::from_be_bytes([hi, lo]));
        if len < 2 {
            return Err("invalid JPEG marker segment length".to_owned());
        }
        let end = at + len;
        if end > b.len() {
            return Err("unexpected end of JPEG stream".to_owned());
        }
        if marker == 0xDA {
            // Entropy-coded data follows the scan header; the decoder checks the rest.
            return Ok(());
        }
        at = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_structure() {
        let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
        png.extend_from_slice(&13u32.to_be_bytes());
        png.extend_from_slice(b"IHDR");
        png.extend_from_slice(&[0; 13 + 4]);
        assert!(sniff(&png).is_err());
        png.extend_from_slice(&0u32.to_be_bytes());
        png.extend_from_slice(b"IEND");
        png.extend_from_slice(&[0; 4]);
        assert_eq!(sniff(&png), Ok(Some("image/png")));
    }

    #[test]
    fn jpeg_structure() {
        assert!(sniff(&[0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x01]).is_err());
        assert!(sniff(&[0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10]).is_err());
        assert_eq!(sniff(&[0xFF, 0xD8, 0xFF, 0xD9]), Ok(Some("image/jpeg")));
    }
}
