//! Reading the files a glTF refers to: confined to the model's folder (and the roots the caller
//! allows), regular files only, never more than the limit. [`UriResolver`] lets an embedder
//! serve relative URIs itself instead.
//!
//! A relative URI (RFC 3986 §4.2, percent-decoded per §2.1) is untrusted: after decoding,
//! `%2e%2e/` is `../`, and `..` climbs out of any folder. The default resolver therefore
//! normalizes the path lexically and refuses it, without touching the file system, when it
//! leaves every allowed root; it then canonicalizes the path (following symbolic links) and
//! refuses it again when the real file lies outside. A path that leaves the roots is refused the
//! same way whether or not a file exists there, so a document cannot probe for files.

use std::fmt;
use std::fs::File;
use std::io::Read as _;
use std::path::{Component, Path, PathBuf};

use crate::SceneError;

/// Serves the files that a document's relative URIs name (buffers and images), for
/// [`load_with_resolver`](crate::load_with_resolver): an embedder that keeps assets in an
/// archive, a database or an object store answers here, and decides what a document may reach.
///
/// `uri_path` is the URI's path, percent-decoded and without query or fragment (for
/// `textures/Wood%20Floor.png?v=2` it is `textures/Wood Floor.png`); it comes from the untrusted
/// document and may contain `..`, absolute paths or any Unicode. `data:` URIs and bufferViews
/// never reach the resolver, and neither do absolute URLs (`http:`, `file:`), which are never
/// fetched.
///
/// ```
/// use barytex_gltf::{LoadOptions, ResolveError, UriResolver, load_with_resolver};
///
/// /// Serves one buffer from memory and refuses every other name.
/// struct OneBuffer(Vec<u8>);
///
/// impl UriResolver for OneBuffer {
///     fn read(&self, uri_path: &str, max_bytes: u64) -> Result<Vec<u8>, ResolveError> {
///         match uri_path {
///             "triangle.bin" if self.0.len() as u64 <= max_bytes => Ok(self.0.clone()),
///             "triangle.bin" => Err(ResolveError::TooLarge(self.0.len() as u64)),
///             _ => Err(ResolveError::Denied),
///         }
///     }
/// }
///
/// let positions: Vec<u8> = [0.0_f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
///     .iter()
///     .flat_map(|v| v.to_le_bytes())
///     .collect();
/// let gltf = r#"{
///   "asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri": "triangle.bin"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}],
///   "scenes": [{"nodes": [0]}]
/// }"#;
/// let resolver = OneBuffer(positions);
/// let scene = load_with_resolver(gltf.as_bytes(), &resolver, &LoadOptions::default())?;
/// assert_eq!(scene.triangle_count(), 1);
///
/// // Any other file is refused, and the error names the URI's JSON pointer.
/// let other = gltf.replace("triangle.bin", "../secret.bin");
/// let refused = load_with_resolver(other.as_bytes(), &resolver, &LoadOptions::default());
/// assert_eq!(refused.unwrap_err().pointer(), Some("/buffers/0/uri"));
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
pub trait UriResolver {
    /// The bytes of the file `uri_path` names, at most `max_bytes` of them (the loader refuses
    /// a longer answer anyway).
    ///
    /// # Errors
    /// [`ResolveError::Denied`] for a name the document may not reach, or a reason it cannot be
    /// read.
    fn read(&self, uri_path: &str, max_bytes: u64) -> Result<Vec<u8>, ResolveError>;

    /// The size in bytes of the file `uri_path` names, for a buffer that no bufferView uses
    /// (checked to exist and to hold its `byteLength`, not loaded). The default reads it
    /// through [`read`](Self::read) with the same `max_bytes`.
    ///
    /// # Errors
    /// As [`read`](Self::read).
    fn size(&self, uri_path: &str, max_bytes: u64) -> Result<u64, ResolveError> {
        self.read(uri_path, max_bytes).map(|b| b.len() as u64)
    }
}

/// Why a [`UriResolver`] did not serve a file.
#[derive(Debug)]
#[non_exhaustive]
pub enum ResolveError {
    /// The document may not reach this file (it leaves the allowed folders, or the resolver
    /// serves no such name). Reported the same way whether or not the file exists.
    Denied,
    /// The file is not a regular file (a folder, a device, a FIFO, a socket).
    NotRegularFile,
    /// The file holds more than `max_bytes` (the size found, or `max_bytes + 1` when reading
    /// stopped there).
    TooLarge(u64),
    /// The file could not be read.
    Io(std::io::Error),
}

impl fmt::Display for ResolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Denied => f.write_str("outside the folders this load may read"),
            Self::NotRegularFile => f.write_str("not a regular file"),
            Self::TooLarge(n) => write!(f, "{n} bytes is too large"),
            Self::Io(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ResolveError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Io(e) => Some(e),
            _ => None,
        }
    }
}

/// The default resolver: files under `base` (the model's folder) or one of `extra` roots.
pub(crate) struct FolderResolver<'a> {
    pub(crate) base: &'a Path,
    pub(crate) extra: &'a [PathBuf],
}

impl FolderResolver<'_> {
    /// The canonical path of `uri_path`'s file, refused when it leaves every root.
    fn locate(&self, uri_path: &str) -> Result<PathBuf, ResolveError> {
        let relative = Path::new(uri_path);
        if uri_path.starts_with(['/', '\\'])
            || relative.is_absolute()
            || relative.has_root()
            || uri_path.contains('\0')
        {
            return Err(ResolveError::Denied);
        }
        // `Path::parent` of a bare file name is the empty path: the current folder.
        let base = if self.base.as_os_str().is_empty() {
            Path::new(".")
        } else {
            self.base
        };
        let base = base.canonicalize().map_err(ResolveError::Io)?;
        // Roots that do not exist allow nothing.
        let mut roots = vec![base.clone()];
        roots.extend(self.extra.iter().filter_map(|r| r.canonicalize().ok()));
        let inside = |p: &Path| roots.iter().any(|r| p.starts_with(r));
        // Lexically first: a path that leaves every root is refused without asking the file
        // system whether anything is there.
        let lexical = normalize(&base.join(relative)).ok_or(ResolveError::Denied)?;
        if !inside(&lexical) {
            return Err(ResolveError::Denied);
        }
        match lexical.canonicalize() {
            Ok(real) if inside(&real) => Ok(real),
            Ok(_) => Err(ResolveError::Denied),
            // A symbolic link on the way that resolves nowhere is refused like one that leads
            // out: otherwise whether its target exists would show.
            Err(_) if has_symlink(&lexical, &roots) => Err(ResolveError::Denied),
            Err(e) => Err(ResolveError::Io(e)),
        }
    }
}

impl UriResolver for FolderResolver<'_> {
    fn read(&self, uri_path: &str, max_bytes: u64) -> Result<Vec<u8>, ResolveError> {
        read_regular_file(&self.locate(uri_path)?, max_bytes)
    }

    fn size(&self, uri_path: &str, _max_bytes: u64) -> Result<u64, ResolveError> {
        let path = self.locate(uri_path)?;
        let meta = std::fs::metadata(&path).map_err(ResolveError::Io)?;
        if !meta.is_file() {
            return Err(ResolveError::NotRegularFile);
        }
        Ok(meta.len())
    }
}

/// `path` (absolute) with `.` and `..` resolved lexically; `None` if `..` climbs above the root.
fn normalize(path: &Path) -> Option<PathBuf> {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::Prefix(_) | Component::RootDir | Component::Normal(_) => out.push(c),
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    return None;
                }
            }
        }
    }
    Some(out)
}

/// Whether some existing prefix of `path` below one of `roots` is a symbolic link.
fn has_symlink(path: &Path, roots: &[PathBuf]) -> bool {
    path.ancestors()
        .take_while(|p| !roots.iter().any(|r| r == p))
        .any(|p| {
            p.symlink_metadata()
                .is_ok_and(|m| m.file_type().is_symlink())
        })
}

/// Reads `path` if it is a regular file of at most `max_bytes`.
///
/// The type is checked before opening (opening a FIFO for reading blocks until a writer comes)
/// and again on the opened handle (the name may have been replaced in between). On Unix the
/// open itself does not wait either: it asks for `O_NONBLOCK`, so a name swapped for a FIFO
/// after the first check opens at once and the second check refuses it (for a regular file the
/// flag changes nothing). The size from the metadata is not trusted either (a device reports
/// 0): the read stops after `max_bytes + 1`.
///
/// What the loader reads every file with; public so that a tool reading the same untrusted
/// folder (a model rewritten beside its files) reads it the same way.
///
/// # Errors
/// [`ResolveError::NotRegularFile`] for a folder, device, FIFO or socket,
/// [`ResolveError::TooLarge`] beyond `max_bytes`, [`ResolveError::Io`] when it cannot be read.
///
/// ```
/// use barytex_gltf::{ResolveError, read_regular_file};
///
/// let dir = std::env::temp_dir();
/// let path = dir.join(format!("barytex-read-doc-{}.bin", std::process::id()));
/// std::fs::write(&path, [1u8, 2, 3])?;
/// assert_eq!(read_regular_file(&path, 3)?, [1, 2, 3]);
/// assert!(matches!(read_regular_file(&path, 2), Err(ResolveError::TooLarge(3))));
/// assert!(matches!(read_regular_file(&dir, 3), Err(ResolveError::NotRegularFile)));
/// std::fs::remove_file(&path)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_regular_file(path: &Path, max_bytes: u64) -> Result<Vec<u8>, ResolveError> {
    let meta = std::fs::metadata(path).map_err(ResolveError::Io)?;
    if !meta.is_file() {
        return Err(ResolveError::NotRegularFile);
    }
    if meta.len() > max_bytes {
        return Err(ResolveError::TooLarge(meta.len()));
    }
    let file = open_without_waiting(path).map_err(ResolveError::Io)?;
    let meta = file.metadata().map_err(ResolveError::Io)?;
    if !meta.is_file() {
        return Err(ResolveError::NotRegularFile);
    }
    if meta.len() > max_bytes {
        return Err(ResolveError::TooLarge(meta.len()));
    }
    let capacity = usize::try_from(meta.len()).unwrap_or(0);
    let mut bytes = Vec::with_capacity(capacity);
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(ResolveError::Io)?;
    if bytes.len() as u64 > max_bytes {
        return Err(ResolveError::TooLarge(bytes.len() as u64));
    }
    Ok(bytes)
}

/// Opens `path` for reading without waiting for a FIFO's writer (Unix: `O_NONBLOCK`).
fn open_without_waiting(path: &Path) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt as _;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// Reads the file `uri_path` through `files` for the object at `uri_ptr`: at most `limit`
/// bytes, refused with a [`SceneError`] naming that pointer and never the file's contents.
pub(crate) fn fetch(
    files: &dyn UriResolver,
    uri_ptr: &str,
    uri_path: &str,
    what: &'static str,
    limit: u64,
) -> Result<Vec<u8>, SceneError> {
    let bytes = files
        .read(uri_path, limit)
        .map_err(|e| scene_error(e, uri_ptr, uri_path, what, limit))?;
    if bytes.len() as u64 > limit {
        return Err(scene_error(
            ResolveError::TooLarge(bytes.len() as u64),
            uri_ptr,
            uri_path,
            what,
            limit,
        ));
    }
    Ok(bytes)
}

/// The size of the file `uri_path` (see [`UriResolver::size`]), refused as in [`fetch`].
pub(crate) fn size(
    files: &dyn UriResolver,
    uri_ptr: &str,
    uri_path: &str,
    what: &'static str,
    limit: u64,
) -> Result<u64, SceneError> {
    files
        .size(uri_path, limit)
        .map_err(|e| scene_error(e, uri_ptr, uri_path, what, limit))
}

fn scene_error(
    e: ResolveError,
    uri_ptr: &str,
    uri_path: &str,
    what: &'static str,
    limit: u64,
) -> SceneError {
    match e {
        ResolveError::Denied | ResolveError::NotRegularFile => SceneError::Denied {
            pointer: uri_ptr.to_owned(),
            reason: format!("{uri_path:?}: {e}"),
        },
        ResolveError::TooLarge(requested) => SceneError::TooLarge {
            pointer: uri_ptr.to_owned(),
            what,
            requested,
            limit,
        },
        ResolveError::Io(source) => SceneError::Io {
            path: uri_path.to_owned(),
            source,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize_resolves_dots_and_refuses_climbing_above_the_root() {
        assert_eq!(
            normalize(Path::new("/a/b/../c/./d")),
            Some(PathBuf::from("/a/c/d"))
        );
        assert_eq!(normalize(Path::new("/a/../..")), None);
        assert_eq!(normalize(Path::new("/a/..")), Some(PathBuf::from("/")));
    }

    /// The race the second type check closes: a name that is a FIFO by the time it is opened.
    /// The open must return at once (no writer ever comes) and the handle's type check refuse
    /// it. Skipped, with a note, where `mkfifo` cannot make one.
    #[cfg(unix)]
    #[test]
    fn a_fifo_opens_without_waiting_and_is_refused() {
        let dir = std::env::temp_dir().join(format!("barytex-fifo-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temporary folder");
        let fifo = dir.join("image.png");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|status| status.success()) {
            println!("note: mkfifo unavailable, FIFO test skipped");
            let _ = std::fs::remove_dir_all(&dir);
            return;
        }
        let (sender, receiver) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let opened =
                open_without_waiting(&path).map(|file| file.metadata().map(|m| m.is_file()));
            let _ = sender.send(opened.map(|is_file| is_file.ok()).ok());
        });
        let opened = receiver.recv_timeout(std::time::Duration::from_secs(10));
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(
            opened.expect("the open returned without a writer"),
            Some(Some(false)),
            "opened, and the handle is not a regular file"
        );
    }
}
