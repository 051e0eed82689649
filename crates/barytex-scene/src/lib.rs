//! glTF 2.0 and GLB scenes: a validating loader that never panics, flattened for rendering.
#![forbid(unsafe_code)]
