//! The scene's images, decoded where a used material reads them: planned in document order
//! (bytes read and checked, each image's header checked against the limits and the total
//! budget), then decoded on up to [`LoadOptions::decode_threads`] threads, one image at a time
//! per thread (the calling thread among them).
//!
//! The result is what decoding them one after another gives, error included: when planning
//! stops at an error, the images planned before it are still decoded, and the first of them
//! that fails (in document order) is the error returned, as it would have been reached first.

use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use barytex_texture::load::ColorSpace;

use crate::accessor::Reader;
use crate::buffer::Source;
use crate::image::{ImageDef, ImageSource};
use crate::scene::{SceneImage, SceneStats};
use crate::uri::Uri;
use crate::{LoadOptions, SceneError};

/// Which images to decode: `(image, sRGB?)` pairs a material reads in a role the caller wants,
/// and the images sampled only in other roles (an error there is only a warning).
pub(crate) struct WantedImages {
    pub(crate) wanted: BTreeSet<(usize, bool)>,
    pub(crate) unread: BTreeSet<usize>,
}

/// The decoded images (one entry per image of the document) and the seconds spent checking
/// headers and decoding (not reading files).
pub(crate) struct DecodedImages {
    pub(crate) images: Vec<SceneImage>,
    pub(crate) seconds: f64,
}

/// Where an image's encoded bytes come from, to decode each source once.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum ImageKey<'a> {
    View(usize),
    Data(&'a [u8]),
    /// A relative URI (its text: two spellings of one file are two sources) or an unfetched
    /// absolute one.
    Uri(&'a str),
}

fn image_key(def: &ImageDef) -> ImageKey<'_> {
    match &def.source {
        ImageSource::View(v) => ImageKey::View(*v),
        ImageSource::Uri(Uri::Data { bytes, .. }) => ImageKey::Data(bytes),
        ImageSource::Uri(Uri::Relative(u) | Uri::NonRelative(u)) => ImageKey::Uri(u),
    }
}

/// One decode: image `image`'s bytes (`sources[source]`) in `space`.
struct Job {
    image: usize,
    source: usize,
    space: ColorSpace,
}

/// An image's slots before decoding: the jobs that will fill them.
#[derive(Default)]
struct PlannedSlots {
    srgb: Option<usize>,
    linear: Option<usize>,
}

/// Reads, checks and decodes the images of `defs` that `wanted` names (see the module docs);
/// warnings and counts go to `warnings` and `stats`.
///
/// # Errors
/// The first error in document order: an image's bytes that cannot be read or do not match
/// their declared type (when the image is needed), a header over the limits or over the total
/// budget, or an image that fails to decode.
pub(crate) fn decode_images<'r>(
    defs: &[ImageDef],
    reader: &'r Reader<'_>,
    source: Source<'_>,
    options: &LoadOptions,
    wanted: &WantedImages,
    warnings: &mut Vec<String>,
    stats: &mut SceneStats,
) -> Result<DecodedImages, SceneError> {
    let limits = &options.limits;
    let mut seconds = 0.0;
    let mut sources: Vec<Cow<'r, [u8]>> = Vec::new();
    let mut jobs: Vec<Job> = Vec::new();
    let mut planned: Vec<PlannedSlots> = Vec::with_capacity(defs.len());
    // Decodes by (source, sRGB?): entries sharing a source share its texture, and only
    // distinct decodes count against `max_total_image_bytes`.
    let mut by_key: BTreeMap<(ImageKey<'_>, bool), usize> = BTreeMap::new();
    let mut image_bytes = 0u64;
    let mut stop = None;
    for (i, def) in defs.iter().enumerate() {
        planned.push(PlannedSlots::default());
        let wants_srgb = wanted.wanted.contains(&(i, true));
        let wants_linear = wanted.wanted.contains(&(i, false));
        let checked = def.bytes(reader, source, limits).and_then(|bytes| {
            match &bytes {
                Some(b) => def.check_bytes(b),
                None => Ok(None),
            }
            .map(|warning| (bytes, warning))
        });
        let bytes = match checked {
            Ok((bytes, warning)) => {
                warnings.extend(warning);
                bytes
            }
            // Sampled only in roles the caller does not read: not needed. (An image no
            // material samples stays required, as the glTF-Validator requires it.)
            Err(e) if !(wants_srgb || wants_linear) && wanted.unread.contains(&i) => {
                warnings.push(format!(
                    "{}: image not usable, and not needed: {e}",
                    def.ptr
                ));
                stats.images_skipped += 1;
                continue;
            }
            Err(e) => {
                stop = Some(e);
                break;
            }
        };
        let Some(bytes) = bytes else {
            warnings.push(format!("{}: non-relative image URI not fetched", def.ptr));
            stats.images_skipped += 1;
            continue;
        };
        if !(wants_srgb || wants_linear) || !options.decode_images {
            stats.images_skipped += 1;
        }
        if !options.decode_images {
            continue;
        }
        sources.push(bytes);
        let at = sources.len() - 1;
        for (wants, space) in [
            (wants_srgb, ColorSpace::Srgb),
            (wants_linear, ColorSpace::Linear),
        ] {
            if !wants {
                continue;
            }
            let key = (image_key(def), space == ColorSpace::Srgb);
            let job = match by_key.get(&key) {
                Some(&job) => job,
                None => {
                    let checking = Instant::now();
                    let checked = check_budget(def, &sources[at], space, options, &mut image_bytes);
                    seconds += checking.elapsed().as_secs_f64();
                    if let Err(e) = checked {
                        stop = Some(e);
                        break;
                    }
                    jobs.push(Job {
                        image: i,
                        source: at,
                        space,
                    });
                    by_key.insert(key, jobs.len() - 1);
                    jobs.len() - 1
                }
            };
            let slots = &mut planned[i];
            match space {
                ColorSpace::Srgb => slots.srgb = Some(job),
                ColorSpace::Linear => slots.linear = Some(job),
            }
        }
        if stop.is_some() {
            break;
        }
    }
    // Every planned decode runs, so that an earlier image's decoding error wins over a later
    // image's planning error, as one after another.
    let decoding = Instant::now();
    let decoded = run_jobs(&jobs, options.decode_threads, |job| {
        defs[job.image].decode(&sources[job.source], job.space, limits)
    });
    seconds += decoding.elapsed().as_secs_f64();
    let mut textures = Vec::with_capacity(decoded.len());
    for result in decoded {
        textures.push(Arc::new(result?));
    }
    if let Some(e) = stop {
        return Err(e);
    }
    stats.images_decoded += textures.len();
    let images = defs
        .iter()
        .zip(planned)
        .map(|(def, slots)| SceneImage {
            name: def.name.clone(),
            srgb: slots.srgb.map(|j| Arc::clone(&textures[j])),
            linear: slots.linear.map(|j| Arc::clone(&textures[j])),
        })
        .collect();
    Ok(DecodedImages { images, seconds })
}

/// `decode(job)` for every job, results in job order, on up to `threads` threads (0: as many
/// as the machine has): the calling thread and scoped helpers take the next job until none is
/// left. A helper the system cannot start leaves its share to the others.
fn run_jobs<T: Send>(jobs: &[Job], threads: usize, decode: impl Fn(&Job) -> T + Sync) -> Vec<T> {
    let threads = match threads {
        0 => std::thread::available_parallelism().map_or(1, usize::from),
        n => n,
    }
    .min(jobs.len());
    if threads <= 1 {
        return jobs.iter().map(decode).collect();
    }
    let next = AtomicUsize::new(0);
    // Takes jobs until none is left: (index, result) pairs.
    let work = || {
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(job) = jobs.get(i) else {
                return done;
            };
            done.push((i, decode(job)));
        }
    };
    let mut results = std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads)
            .filter_map(|_| std::thread::Builder::new().spawn_scoped(scope, work).ok())
            .collect();
        let mut results = work();
        for helper in helpers {
            // A decoder that panics is a bug: the panic goes on in the caller.
            results.extend(
                helper
                    .join()
                    .unwrap_or_else(|p| std::panic::resume_unwind(p)),
            );
        }
        results
    });
    results.sort_unstable_by_key(|&(i, _)| i);
    results.into_iter().map(|(_, result)| result).collect()
}

/// Checks an image's header, before anything is decoded: its own limits (as `decode` checks
/// them), then the total budget, which it adds its decoded size to.
fn check_budget(
    def: &ImageDef,
    bytes: &[u8],
    space: ColorSpace,
    options: &LoadOptions,
    image_bytes: &mut u64,
) -> Result<(), SceneError> {
    let limits = &options.limits;
    let image_error = |e: barytex_texture::TextureError| SceneError::Image {
        pointer: def.ptr.clone(),
        reason: e.to_string(),
    };
    let (width, height, need) =
        barytex_texture::load::decoded_size(bytes, space).map_err(image_error)?;
    limits.image.check(width, height, 16).map_err(image_error)?;
    *image_bytes = image_bytes.saturating_add(need);
    if *image_bytes > limits.max_total_image_bytes {
        return Err(SceneError::TooLarge {
            pointer: def.ptr.clone(),
            what: "total decoded image bytes",
            requested: *image_bytes,
            limit: limits.max_total_image_bytes,
        });
    }
    Ok(())
}
