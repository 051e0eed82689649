//! Relative URIs of a model written to another folder (RFC 3986 §4.2 relative references,
//! percent-encoded per §2.1): a file the output's folder can reach downwards is named relative
//! to it; any other is copied beside the output (keeping its path below the model's folder),
//! so that the output loads under the loader's default confinement (its own folder only). A
//! file is copied only from the model's folder or a folder `--allow-dir` names.

use std::path::{Component, Path, PathBuf};

use percent_encoding::{AsciiSet, NON_ALPHANUMERIC, percent_decode_str, utf8_percent_encode};

/// What a path segment may keep unencoded: RFC 3986's unreserved characters.
const SEGMENT: &AsciiSet = &NON_ALPHANUMERIC
    .remove(b'-')
    .remove(b'.')
    .remove(b'_')
    .remove(b'~');

/// `path` with `.` and `..` folded away lexically (a `..` above the start is kept).
fn normalize(path: &Path) -> PathBuf {
    let mut out: Vec<Component<'_>> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => match out.last() {
                Some(Component::Normal(_)) => {
                    out.pop();
                }
                _ => out.push(c),
            },
            _ => out.push(c),
        }
    }
    out.iter().collect()
}

/// `target` relative to the folder `from` (both absolute and normalized).
fn relative(from: &Path, target: &Path) -> PathBuf {
    let a: Vec<Component<'_>> = from.components().collect();
    let b: Vec<Component<'_>> = target.components().collect();
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut out = PathBuf::new();
    for _ in common..a.len() {
        out.push("..");
    }
    for c in &b[common..] {
        out.push(c);
    }
    out
}

/// A path as a relative URI reference: its segments percent-encoded, joined by `/`.
pub(crate) fn encode(path: &Path) -> String {
    path.components()
        .map(|c| match c {
            Component::ParentDir => "..".to_owned(),
            other => utf8_percent_encode(&other.as_os_str().to_string_lossy(), SEGMENT).to_string(),
        })
        .collect::<Vec<_>>()
        .join("/")
}

/// Where a referenced file goes: its new URI, and the copy to make (from, to), if any.
#[derive(Debug, PartialEq)]
pub(crate) struct Placed {
    pub(crate) uri: String,
    pub(crate) copy: Option<(PathBuf, PathBuf)>,
}

/// Places the file `uri` of a model in `model_dir` for a model in `out_dir` (both absolute and
/// canonical): `Ok(None)` for a URI that is not a relative file reference (`data:`, a scheme,
/// an absolute path), which stays as it is.
///
/// # Errors
/// A file to copy that is not under `model_dir` or one of `roots` after resolving links, or that
/// cannot be resolved.
pub(crate) fn place(
    uri: &str,
    model_dir: &Path,
    out_dir: &Path,
    roots: &[PathBuf],
) -> Result<Option<Placed>, String> {
    let Some(rebased) = rebase(uri, model_dir, out_dir) else {
        return Ok(None);
    };
    if !rebased.starts_with("../") && rebased != ".." {
        return Ok(Some(Placed {
            uri: rebased,
            copy: None,
        }));
    }
    let path = uri.split(['?', '#']).next().unwrap_or(uri);
    let decoded = percent_decode_str(path)
        .decode_utf8()
        .map_err(|_| "a URI that is not UTF-8 once decoded".to_owned())?;
    let target = normalize(&model_dir.join(decoded.as_ref()));
    let mut below = relative(model_dir, &target);
    if below.components().next() == Some(Component::ParentDir) {
        below = PathBuf::from(target.file_name().ok_or("a URI naming a folder")?);
    }
    let real = std::fs::canonicalize(&target)
        .map_err(|e| format!("a referenced file ({}): {e}", below.display()))?;
    let inside = std::iter::once(model_dir)
        .chain(roots.iter().map(PathBuf::as_path))
        .any(|root| std::fs::canonicalize(root).is_ok_and(|r| real.starts_with(r)));
    if !inside {
        return Err(format!(
            "a referenced file ({}) is outside the model's folder and the --allow-dir folders",
            below.display()
        ));
    }
    Ok(Some(Placed {
        uri: encode(&below),
        copy: Some((real, out_dir.join(&below))),
    }))
}

/// The URI `uri` of a model in `model_dir` rewritten for a model in `out_dir` (both absolute):
/// `None` for a URI that is not a relative file reference (`data:`, a scheme, an absolute
/// path), which stays as it is.
pub(crate) fn rebase(uri: &str, model_dir: &Path, out_dir: &Path) -> Option<String> {
    let has_scheme = uri
        .split_once(':')
        .is_some_and(|(s, _)| !s.is_empty() && !s.contains('/'));
    if has_scheme || uri.starts_with('/') || uri.starts_with('#') || uri.is_empty() {
        return None;
    }
    let path = uri.split(['?', '#']).next().unwrap_or(uri);
    let decoded = percent_decode_str(path).decode_utf8().ok()?;
    let target = normalize(&model_dir.join(decoded.as_ref()));
    Some(encode(&relative(&normalize(out_dir), &target)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rebases_into_a_sibling_folder() {
        let got = rebase("tex/a%20b.png", Path::new("/m/model"), Path::new("/m/out"));
        assert_eq!(got.as_deref(), Some("../model/tex/a%20b.png"));
        assert_eq!(
            rebase("x.bin", Path::new("/m"), Path::new("/m")).as_deref(),
            Some("x.bin")
        );
        assert_eq!(rebase("data:,abc", Path::new("/m"), Path::new("/n")), None);
        assert_eq!(
            rebase("Unicode❤.png", Path::new("/m"), Path::new("/m")).as_deref(),
            Some("Unicode%E2%9D%A4.png")
        );
    }
}
