//! URIs inside a glTF: `data:` URIs (base64 payload, media type checked) and relative file
//! references (percent-decoded; `access` decides which files they may reach). Absolute URLs are
//! refused: a loader of untrusted files must not fetch from the network.

use base64::Engine as _;

/// What a `uri` property refers to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Uri {
    /// An embedded `data:` URI, decoded.
    Data {
        /// The declared media type (`application/octet-stream`, `image/png`, …), may be empty.
        media_type: String,
        /// The decoded payload.
        bytes: Vec<u8>,
    },
    /// A file relative to the glTF, percent-decoded (may contain any Unicode).
    Relative(String),
    /// An absolute URL (`http://…`, `file:…`): never fetched.
    NonRelative(String),
}

/// Parses a `uri` property. `max_bytes` bounds the decoded size of a data URI, checked before
/// decoding (base64 decodes to at most 3/4 of its length).
pub(crate) fn parse(uri: &str, max_bytes: u64) -> Result<Uri, String> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let (header, payload) = rest
            .split_once(',')
            .ok_or_else(|| "a data URI without ',' separating header and data".to_owned())?;
        let mut parts = header.split(';');
        let media_type = parts.next().unwrap_or_default().to_owned();
        let mut base64 = false;
        for param in parts {
            if param == "base64" {
                base64 = true;
            } else if !param.contains('=') {
                return Err(format!("malformed data URI parameter {param:?}"));
            }
        }
        if !base64 {
            // RFC 2397: without ";base64" the payload is percent-encoded octets.
            if payload.len() as u64 > max_bytes {
                return Err(format!(
                    "data URI of {} bytes exceeds the limit {max_bytes}",
                    payload.len()
                ));
            }
            let bytes: Vec<u8> = percent_encoding::percent_decode_str(payload).collect();
            return Ok(Uri::Data { media_type, bytes });
        }
        let claimed = (payload.len() as u64 / 4).saturating_mul(3);
        if claimed > max_bytes {
            return Err(format!(
                "data URI of about {claimed} bytes exceeds the limit {max_bytes}"
            ));
        }
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(payload)
            .map_err(|e| format!("invalid base64 in data URI: {e}"))?;
        return Ok(Uri::Data { media_type, bytes });
    }
    if uri.is_empty() {
        return Err("empty URI".to_owned());
    }
    // RFC 3986 scheme: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":" before any '/', '?', '#'.
    if let Some(colon) = uri.find(':') {
        let before = uri.get(..colon).unwrap_or_default();
        if !before.contains(['/', '?', '#']) {
            let valid_scheme = before
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic())
                && before
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'));
            if !valid_scheme {
                return Err(format!("invalid URI {uri:?}: malformed scheme"));
            }
            return Ok(Uri::NonRelative(uri.to_owned()));
        }
    }
    let path = uri.split(['?', '#']).next().unwrap_or_default();
    let decoded = percent_encoding::percent_decode_str(path)
        .decode_utf8()
        .map_err(|e| format!("invalid percent-encoding in URI {uri:?}: {e}"))?;
    if decoded.is_empty() {
        return Err(format!("URI {uri:?} names no file"));
    }
    Ok(Uri::Relative(decoded.into_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_uris() {
        assert_eq!(
            parse("data:application/octet-stream;base64,AAEC", 100),
            Ok(Uri::Data {
                media_type: "application/octet-stream".into(),
                bytes: vec![0, 1, 2]
            })
        );
        assert!(parse("data:application/octet-stream;;base64,AA==", 100).is_err());
        assert_eq!(
            parse("data:application/gltf-buffer,0%01", 100),
            Ok(Uri::Data {
                media_type: "application/gltf-buffer".into(),
                bytes: vec![b'0', 1]
            })
        );
        assert!(parse("data:image/png;base64,`", 100).is_err());
        assert!(parse("data:application/octet-stream;base64,AAECAAEC", 3).is_err());
    }

    #[test]
    fn relative_and_absolute() {
        assert_eq!(
            parse("Unicode%E2%9D%A4.bin", 0),
            Ok(Uri::Relative("Unicode❤.bin".into()))
        );
        assert_eq!(
            parse("Box%20With%20Spaces.bin", 0),
            Ok(Uri::Relative("Box With Spaces.bin".into()))
        );
        assert!(matches!(
            parse("http://x/y.bin", 0),
            Ok(Uri::NonRelative(_))
        ));
        assert!(parse(":", 0).is_err());
        assert!(parse("", 0).is_err());
    }
}
