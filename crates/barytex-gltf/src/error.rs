//! The crate's error type: every refusal names the offending object by JSON pointer, so a user
//! (or a test) can tell *which* part of an untrusted file was wrong, not just that it was.

use core::fmt;

/// Why a glTF/GLB file was refused.
#[derive(Debug)]
#[non_exhaustive]
pub enum SceneError {
    /// A file could not be read (the glTF itself, an external buffer or an image).
    Io {
        /// The path that failed: the glTF's path as given, or a URI's decoded path.
        path: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// A URI names a file this load may not read: one outside the model's folder and the
    /// allowed roots ([`LoadOptions::allowed_roots`](crate::LoadOptions::allowed_roots)), one a
    /// [`UriResolver`](crate::UriResolver) refused, or one that is not a regular file.
    Denied {
        /// JSON pointer to the URI, e.g. `/buffers/0/uri`.
        pointer: String,
        /// The URI's decoded path and why it was refused.
        reason: String,
    },
    /// The JSON could not be parsed, or did not have the glTF schema's shape.
    Json(String),
    /// The GLB container is malformed (header, chunk lengths, alignment, chunk order).
    Glb(String),
    /// A glTF object breaks a rule of the specification.
    Invalid {
        /// JSON pointer to the object, e.g. `/accessors/3`.
        pointer: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Something exceeds a [`SceneLimits`](crate::SceneLimits) value; nothing that size was
    /// allocated.
    TooLarge {
        /// JSON pointer to the object that asked for it (empty for the file itself).
        pointer: String,
        /// Which limit (`"file bytes"`, `"accessor elements"`, …).
        what: &'static str,
        /// The size asked for.
        requested: u64,
        /// The limit.
        limit: u64,
    },
    /// The file needs an extension this loader does not implement (`extensionsRequired`).
    UnsupportedExtension(String),
    /// The loader panicked (caught by its last line of defence): a bug in this crate or a
    /// dependency, reported instead of unwinding into the caller.
    Internal(String),
    /// An image could not be decoded or was refused by the texture limits.
    Image {
        /// JSON pointer to the image, e.g. `/images/0`.
        pointer: String,
        /// The decoder's or the limit's message.
        reason: String,
    },
}

impl SceneError {
    /// Shorthand for [`SceneError::Invalid`].
    pub(crate) fn invalid(pointer: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::Invalid {
            pointer: pointer.into(),
            reason: reason.into(),
        }
    }

    /// The JSON pointer of the object at fault, when the error names one.
    ///
    /// ```
    /// use barytex_gltf::{LoadOptions, SceneError, load_slice};
    ///
    /// // The node refers to mesh 3, which does not exist.
    /// let bad = br#"{"asset": {"version": "2.0"}, "nodes": [{"mesh": 3}]}"#;
    /// let err = load_slice(bad, &LoadOptions::default()).unwrap_err();
    /// assert!(matches!(err, SceneError::Invalid { .. }));
    /// assert_eq!(err.pointer(), Some("/nodes/0/mesh"));
    /// // A malformed container names no object.
    /// let glb = b"glTF\x02\x00\x00\x00\x0c\x00\x00\x00";
    /// assert_eq!(load_slice(glb, &LoadOptions::default()).unwrap_err().pointer(), None);
    /// ```
    #[must_use]
    pub fn pointer(&self) -> Option<&str> {
        match self {
            Self::Invalid { pointer, .. }
            | Self::TooLarge { pointer, .. }
            | Self::Denied { pointer, .. }
            | Self::Image { pointer, .. } => Some(pointer),
            _ => None,
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Io { path, source } => write!(f, "cannot read {path}: {source}"),
            Self::Denied { pointer, reason } => write!(f, "{pointer}: {reason}"),
            Self::Json(msg) => write!(f, "invalid glTF JSON: {msg}"),
            Self::Glb(msg) => write!(f, "invalid GLB container: {msg}"),
            Self::Invalid { pointer, reason } => write!(f, "{pointer}: {reason}"),
            Self::TooLarge {
                pointer,
                what,
                requested,
                limit,
            } => write!(f, "{pointer}: {what} {requested} exceeds the limit {limit}"),
            Self::UnsupportedExtension(name) => {
                write!(f, "required extension {name} is not supported")
            }
            Self::Image { pointer, reason } => write!(f, "{pointer}: image: {reason}"),
            Self::Internal(msg) => write!(f, "internal error (a bug): {msg}"),
        }
    }
}

impl std::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}
