//! `barytex render FILE` and the default demo: load (or build) a scene, render it, write a PNG,
//! and say where it went and how long each stage took.

use crate::progress::Progress;
use std::path::{Path, PathBuf};
use std::time::Instant;

use barytex_gltf::{LoadOptions, Projection, Scene, load_path};
use barytex_render::{
    AntiAliasing, CameraChoice, Filter, PreparedScene, RenderOptions, RenderStats, Rendered,
    Shading,
};
use glam::{Vec3, Vec4};

/// What to render and how.
#[derive(Clone, Debug)]
pub(crate) struct Options {
    /// The glTF/GLB file; `None` renders the built-in demo scene.
    pub(crate) file: Option<PathBuf>,
    /// The demo scene with its standing mirror (`barytex demo --mirror`).
    pub(crate) demo_mirror: bool,
    /// Which of the file's scenes.
    pub(crate) scene: Option<usize>,
    /// Folders besides the file's own that its URIs may read (`--allow-dir`).
    pub(crate) allowed_roots: Vec<PathBuf>,
    /// The render settings.
    pub(crate) render: RenderOptions,
    /// Worker threads (`None`: all cores).
    pub(crate) threads: Option<usize>,
    /// Where the PNG goes.
    pub(crate) out: PathBuf,
    /// Print the camera's matrices.
    pub(crate) print_camera: bool,
    /// List the cameras instead of rendering.
    pub(crate) list_cameras: bool,
    /// Print the render statistics.
    pub(crate) stats: bool,
    /// Draws of the prepared scene (`--frames`, at least 1).
    pub(crate) frames: u32,
}

/// `WxH`, e.g. `1024x768`.
pub(crate) fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| format!("size `{text}`: expected WIDTHxHEIGHT, e.g. 800x600"))?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|&v| (1..=16_384).contains(&v))
            .ok_or_else(|| format!("size `{text}`: each side must be 1 to 16384"))
    };
    Ok((side(w)?, side(h)?))
}

/// The most worker threads `--threads` accepts: far more than any machine has cores, far
/// fewer than the thousands at which spawning fails ("Resource temporarily unavailable").
pub(crate) const MAX_THREADS: usize = 1024;

/// `0` (all cores) to [`MAX_THREADS`].
pub(crate) fn parse_threads(text: &str) -> Result<usize, String> {
    let too_many = || format!("threads `{text}`: at most {MAX_THREADS} (0: all cores)");
    let n: u128 = text.trim().parse().map_err(|_| {
        format!("threads `{text}`: expected a number of threads, 0 to {MAX_THREADS}")
    })?;
    usize::try_from(n)
        .ok()
        .filter(|&n| n <= MAX_THREADS)
        .ok_or_else(too_many)
}

/// The most frames `--frames` accepts.
pub(crate) const MAX_FRAMES: u32 = 1000;

/// `1` to [`MAX_FRAMES`].
pub(crate) fn parse_frames(text: &str) -> Result<u32, String> {
    text.trim()
        .parse::<u32>()
        .ok()
        .filter(|n| (1..=MAX_FRAMES).contains(n))
        .ok_or_else(|| format!("frames `{text}`: expected a whole number from 1 to {MAX_FRAMES}"))
}

/// `frames: …`, the draws of a prepared scene drawn `draws.len()` times (seconds each, in
/// order): the first, and the median, minimum and maximum of the rest (warm frames), in
/// milliseconds.
fn frames_line(draws: &[f64]) -> String {
    let ms = |seconds: f64| format!("{:.2} ms", seconds * 1e3);
    let Some((first, warm)) = draws.split_first() else {
        return "frames: none".to_owned();
    };
    if warm.is_empty() {
        return format!("frames: 1, draw {}", ms(*first));
    }
    let mut sorted = warm.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    let median = if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    };
    format!(
        "frames: {}, draw (raster + shade) of the first {}; of the {n} after it median {}, \
         min {}, max {}",
        draws.len(),
        ms(*first),
        ms(median),
        ms(sorted[0]),
        ms(sorted[n - 1])
    )
}

/// `auto` or a camera index.
pub(crate) fn parse_camera(text: &str) -> Result<CameraChoice, String> {
    if text == "auto" {
        return Ok(CameraChoice::Auto);
    }
    text.parse()
        .map(CameraChoice::Index)
        .map_err(|_| format!("camera `{text}`: expected `auto` or a camera index"))
}

/// An sRGB colour, `#rrggbb`, `#rrggbbaa` or `r,g,b[,a]` (each 0 to 255; alpha 255 when
/// absent), as the renderer takes it: linear light (IEC 61966-2-1's transfer function) and
/// straight alpha.
pub(crate) fn parse_background(text: &str) -> Result<Vec4, String> {
    let bytes: Option<Vec<u8>> = match text.trim().strip_prefix('#') {
        Some(hex)
            if (hex.len() == 6 || hex.len() == 8) && hex.bytes().all(|b| b.is_ascii_hexdigit()) =>
        {
            (0..hex.len())
                .step_by(2)
                .map(|i| u8::from_str_radix(&hex[i..i + 2], 16).ok())
                .collect()
        }
        Some(_) => None,
        None => text
            .split(',')
            .map(|part| {
                let part = part.trim();
                let digits = !part.is_empty() && part.bytes().all(|b| b.is_ascii_digit());
                part.parse::<u8>().ok().filter(|_| digits)
            })
            .collect(),
    };
    match bytes.as_deref() {
        Some(&[r, g, b]) => Ok((r, g, b, 255)),
        Some(&[r, g, b, a]) => Ok((r, g, b, a)),
        _ => Err(format!(
            "background `{}`: expected #rrggbb, #rrggbbaa or r,g,b[,a] with each 0 to 255",
            text.escape_debug()
        )),
    }
    .map(|(r, g, b, a)| {
        use barytex_texture::srgb::decode;
        Vec4::new(decode(r), decode(g), decode(b), f32::from(a) / 255.0)
    })
}

fn number_after(
    text: &str,
    prefix: &str,
    range: std::ops::RangeInclusive<u32>,
) -> Result<u32, String> {
    text.strip_prefix(prefix)
        .and_then(|n| n.parse::<u32>().ok())
        .filter(|n| range.contains(n))
        .ok_or_else(|| {
            format!(
                "`{text}`: expected {prefix}N with N from {} to {}",
                range.start(),
                range.end()
            )
        })
}

/// `file|nearest|bilinear|trilinear|aniso:N|ewa`.
pub(crate) fn parse_filter(text: &str) -> Result<Filter, String> {
    Ok(match text {
        "file" => Filter::FromFile,
        "nearest" => Filter::Nearest,
        "bilinear" => Filter::Bilinear,
        "trilinear" => Filter::Trilinear,
        "ewa" => Filter::Ewa,
        _ if text.starts_with("aniso:") => {
            Filter::Anisotropic(number_after(text, "aniso:", 1..=16)? as u16)
        }
        _ => {
            return Err(format!(
                "filter `{text}`: expected file, nearest, bilinear, trilinear, aniso:N or ewa"
            ));
        }
    })
}

/// `none|ssaa:N|jitter:N|msaa:N|adaptive:N`.
pub(crate) fn parse_aa(text: &str) -> Result<AntiAliasing, String> {
    Ok(match text {
        "none" => AntiAliasing::None,
        _ if text.starts_with("ssaa:") => {
            AntiAliasing::Supersample(number_after(text, "ssaa:", 1..=16)?)
        }
        _ if text.starts_with("jitter:") => {
            AntiAliasing::Jitter(number_after(text, "jitter:", 1..=16)?)
        }
        _ if text.starts_with("msaa:") => {
            let n = number_after(text, "msaa:", 1..=16)?;
            if !matches!(n, 1 | 2 | 4 | 8 | 16) {
                return Err(format!("`{text}`: MSAA takes 1, 2, 4, 8 or 16 samples"));
            }
            AntiAliasing::Msaa(n)
        }
        _ if text.starts_with("adaptive:") => {
            AntiAliasing::Adaptive(number_after(text, "adaptive:", 4..=256)?)
        }
        _ => {
            return Err(format!(
                "anti-aliasing `{text}`: expected none, ssaa:N (N×N), jitter:N (N×N), msaa:N or \
                 adaptive:N (up to N samples)"
            ));
        }
    })
}

/// `unlit|flat|gouraud|phong|hybrid`.
pub(crate) fn parse_shading(text: &str) -> Result<Shading, String> {
    match text {
        "unlit" => Ok(Shading::Unlit),
        "flat" => Ok(Shading::Flat),
        "gouraud" => Ok(Shading::Gouraud),
        "phong" => Ok(Shading::Phong),
        "hybrid" => Ok(Shading::Hybrid),
        _ => Err(format!(
            "shading `{text}`: expected unlit, flat, gouraud, phong or hybrid"
        )),
    }
}

/// The deepest portal nesting `--portal-depth` accepts: each level can multiply the views.
pub(crate) const MAX_PORTAL_DEPTH: u32 = 16;

/// A portal depth from 0 to [`MAX_PORTAL_DEPTH`].
pub(crate) fn parse_portal_depth(text: &str) -> Result<u32, String> {
    text.parse::<u32>()
        .ok()
        .filter(|&d| d <= MAX_PORTAL_DEPTH)
        .ok_or_else(|| {
            format!("portal depth `{text}`: expected a whole number from 0 to {MAX_PORTAL_DEPTH}")
        })
}

/// A fog density ≥ 0 per unit of distance.
pub(crate) fn parse_fog(text: &str) -> Result<f32, String> {
    text.parse::<f32>()
        .ok()
        .filter(|d| d.is_finite() && *d >= 0.0)
        .ok_or_else(|| format!("fog `{text}`: expected a density ≥ 0 (per unit of distance)"))
}

/// Loads the file (its images decoded on `threads` threads) or builds the demo.
fn load(options: &Options, threads: usize) -> Result<(Scene, f64), String> {
    let started = Instant::now();
    let scene = match &options.file {
        None if options.demo_mirror => barytex_render::demo::demo_scene_with_mirror(),
        None => barytex_render::demo::demo_scene(),
        Some(path) => load_path(
            path,
            &LoadOptions {
                scene: options.scene,
                allowed_roots: options.allowed_roots.clone(),
                // Decode (and require) only the textures this shading reads.
                image_roles: options.render.shading.texture_roles(),
                decode_threads: threads,
                ..LoadOptions::default()
            },
        )
        .map_err(|e| format!("{}: {e}", path.display()))?,
    };
    Ok((scene, started.elapsed().as_secs_f64()))
}

fn print_stats(rendered: &Rendered, scene: &Scene, portal_depth: u32) {
    let s = &rendered.stats;
    let d = &s.draw;
    println!(
        "scene: {} instances, {} triangles per pass, {} primitives; loader: {} images decoded, \
         {} skipped (unused), {} point and line primitives",
        scene.instances.len(),
        s.triangles,
        s.primitives,
        scene.stats.images_decoded,
        scene.stats.images_skipped,
        scene.stats.primitives_points_lines
    );
    println!(
        "textures: {} prepared, {} mip chains built, {} not built (never minified); tangents \
         generated for {} normal-mapped primitives",
        s.textures, s.mip_chains, s.mips_skipped, s.tangents_generated
    );
    println!(
        "varyings: {} floats interpolated per fragment over the draws, {} skipped (never read by \
         their material)",
        s.varyings_interpolated, s.varyings_skipped
    );
    println!(
        "draw: {} passes, {:.2} samples/pixel, {} fragments shaded, {} discarded, {} failed depth; \
         triangles culled {}, clipped {}, clipped away {}, degenerate {}, non-finite {}",
        s.passes,
        s.samples_per_pixel,
        d.fragments_shaded,
        d.fragments_discarded,
        d.fragments_depth_failed,
        d.culled,
        d.clipped,
        d.clipped_away,
        d.degenerate,
        d.dropped_non_finite
    );
    if s.hybrid_phong_triangles + s.hybrid_gouraud_triangles > 0 {
        println!(
            "hybrid shading: the highlight test sent {} triangles to Phong, {} to Gouraud",
            s.hybrid_phong_triangles, s.hybrid_gouraud_triangles
        );
    }
    if !scene.portals.is_empty() {
        println!(
            "portals: {} in the scene, {} not drawable (degenerate); {} views drawn through them, \
             {} seen closed (at --portal-depth {}); {} fragments shaded through them",
            scene.portals.len(),
            s.portals_skipped,
            s.portal_views,
            s.portals_closed,
            portal_depth,
            s.portal_draw.fragments_shaded
        );
    }
    if let Some(a) = &s.adaptive {
        println!(
            "adaptive: {} samples in {} passes; pixels at the maximum: {}",
            a.samples,
            a.passes,
            a.histogram.last().copied().unwrap_or(0)
        );
    }
    for w in &scene.warnings {
        println!("warning: {w}");
    }
}

/// `stages: …`, the time of each stage in milliseconds. `target` is the render target's
/// creation (allocation and first clear); rasterization and shading are told apart only when
/// the render measured them (`--stats`).
fn stage_line(load: f64, decode: f64, s: &RenderStats, save: f64) -> String {
    let ms = |seconds: f64| format!("{:.1} ms", seconds * 1e3);
    let draw = match s.raster_seconds {
        Some(raster) => format!(
            "raster {}, shade {}",
            ms(raster),
            ms((s.draw_seconds - raster).max(0.0))
        ),
        None => format!("raster + shade {}", ms(s.draw_seconds)),
    };
    format!(
        "stages: load {}, decode {}, prepare {}, mips {}, target {}, {draw}, encode + write {}",
        ms(load - decode),
        ms(decode),
        ms(s.prepare_seconds - s.mip_seconds),
        ms(s.mip_seconds),
        ms(s.target_seconds),
        ms(save)
    )
}

/// What is rendered, for messages: the file, or the demo scene.
fn what(options: &Options) -> String {
    options.file.as_ref().map_or_else(
        || {
            if options.demo_mirror {
                "the built-in demo scene with a mirror".to_owned()
            } else {
                "the built-in demo scene".to_owned()
            }
        },
        |p| p.display().to_string(),
    )
}

/// `(x, y, z)` with Rust's shortest round-trip formatting.
fn point(p: Vec3) -> String {
    format!("({}, {}, {})", p.x, p.y, p.z)
}

/// A projection's parameters as glTF names them (glTF 2.0 §5.12–5.14).
fn describe_projection(projection: &Projection) -> String {
    match *projection {
        Projection::Perspective {
            yfov,
            aspect_ratio,
            znear,
            zfar,
        } => format!(
            "perspective, yfov {yfov} rad, aspect ratio {}, znear {znear}, zfar {}",
            aspect_ratio.map_or_else(|| "of the image".to_owned(), |a| a.to_string()),
            zfar.map_or_else(|| "infinite".to_owned(), |f| f.to_string())
        ),
        Projection::Orthographic {
            xmag,
            ymag,
            znear,
            zfar,
        } => format!("orthographic, xmag {xmag}, ymag {ymag}, znear {znear}, zfar {zfar}"),
    }
}

/// `--list-cameras`: a heading, then one line per camera of the document (glTF `cameras[i]`,
/// what `--camera i` picks): its name, projection, and the node of the scene that places it
/// (the first in depth-first scene order; later ones are listed after "also by"), with the eye
/// there; then the camera a render without `--camera` uses.
fn list_cameras(what: &str, scene: &Scene) -> String {
    use std::fmt::Write;
    let scene_name = scene.scene_index.map_or_else(
        || "the scene (every root node)".to_owned(),
        |i| format!("scene {i}"),
    );
    let count = scene.document_cameras.len();
    let mut text = format!(
        "{what}: {count} camera{} in the document; where {scene_name} places them:\n",
        if count == 1 { "" } else { "s" }
    );
    for (index, camera) in scene.document_cameras.iter().enumerate() {
        let name = camera
            .name
            .as_ref()
            .map_or_else(|| "(unnamed)".to_owned(), |n| format!("{n:?}"));
        let _ = write!(
            text,
            "camera {index} {name}: {}; ",
            describe_projection(&camera.projection)
        );
        let mut placements = scene.cameras.iter().filter(|c| c.camera == index);
        match placements.next() {
            Some(first) => {
                let _ = write!(
                    text,
                    "placed by node {}, eye at {}",
                    first.node,
                    point(first.world.transform_point3(Vec3::ZERO))
                );
                let others: Vec<String> = placements.map(|c| c.node.to_string()).collect();
                if !others.is_empty() {
                    let _ = write!(text, "; also by node {}", others.join(", "));
                }
            }
            None => {
                let _ = write!(text, "not placed by {scene_name}");
            }
        }
        text.push('\n');
    }
    match scene.cameras.first() {
        Some(first) => {
            let _ = writeln!(
                text,
                "default: camera {} (the first the scene places; --camera auto for the \
                 automatic camera)",
                first.camera
            );
        }
        None => text.push_str("default: the automatic camera (the scene places no camera)\n"),
    }
    text
}

/// Loads or builds the scene, renders it, writes the PNG.
pub(crate) fn run(options: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.threads.unwrap_or(0))
        .build()?;
    if options.list_cameras {
        let (scene, _) = load(options, pool.current_num_threads())?;
        print!("{}", list_cameras(&what(options), &scene));
        return Ok(());
    }
    let progress = Progress::start();
    progress.stage("loading");
    // Loaded, and the camera checked, before the render is announced: a missing or invalid file
    // or a camera the scene lacks is one error line. Images decode on as many threads as the
    // render runs on.
    let (scene, load_seconds) = load(options, pool.current_num_threads())?;
    barytex_render::choose_camera(&scene, &options.render)?;
    progress.suspend(|| {
        println!(
            "rendering {} at {}×{} on {} thread(s)",
            what(options),
            options.render.width,
            options.render.height,
            pool.current_num_threads()
        );
    });
    progress.stage("rendering");
    let render_options = RenderOptions {
        measure_stages: options.stats,
        ..options.render
    };
    let (rendered, draws) = pool.install(|| {
        let prepared = PreparedScene::new(&scene, &render_options)?;
        let frames = options.frames.max(1);
        // One progress bar over every frame's passes.
        let draw = |frame: u32| {
            prepared.render_with_progress(&mut |done, planned| {
                progress.passes(frame * planned + done, frames * planned);
            })
        };
        let mut rendered = draw(0)?;
        let mut draws = vec![rendered.stats.draw_seconds];
        for frame in 1..frames {
            rendered = draw(frame)?;
            draws.push(rendered.stats.draw_seconds);
        }
        Ok::<_, barytex_render::RenderError>((rendered, draws))
    })?;
    progress.stage("writing");
    let started = Instant::now();
    // Encoded on the same pool as the render (rows in parallel).
    let image = pool.install(|| rendered.image.to_srgba8())?;
    save(&image, &options.out)?;
    let save_seconds = started.elapsed().as_secs_f64();
    progress.finish();
    if options.print_camera {
        println!("{}", rendered.camera.describe());
    }
    println!(
        "{}",
        stage_line(
            load_seconds,
            scene.decode_seconds,
            &rendered.stats,
            save_seconds
        )
    );
    if options.frames > 1 {
        println!("{}", frames_line(&draws));
    }
    if options.stats {
        print_stats(&rendered, &scene, options.render.portal_depth);
    }
    let shown = std::fs::canonicalize(&options.out).unwrap_or_else(|_| options.out.clone());
    println!("wrote {}", shown.display());
    Ok(())
}

fn save(
    image: &barytex_texture::Texture2d<barytex_texture::Srgba8>,
    out: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    barytex_texture::load::save_png(image, out)
        .map_err(|e| format!("cannot write {}: {e}", out.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_parse_from_one_to_the_maximum() {
        assert_eq!(parse_frames("1"), Ok(1));
        assert_eq!(parse_frames(" 1000 "), Ok(MAX_FRAMES));
        for bad in ["0", "1001", "-1", "two", "", "4294967296"] {
            let error = parse_frames(bad).expect_err(bad);
            assert!(error.contains("from 1 to 1000"), "{error}");
        }
    }

    #[test]
    fn the_frames_line_sets_the_first_frame_apart() {
        assert_eq!(frames_line(&[0.004]), "frames: 1, draw 4.00 ms");
        let line = frames_line(&[0.009, 0.003, 0.001, 0.002, 0.005]);
        assert_eq!(
            line,
            "frames: 5, draw (raster + shade) of the first 9.00 ms; of the 4 after it median \
             2.50 ms, min 1.00 ms, max 5.00 ms"
        );
        assert!(frames_line(&[0.01, 0.002, 0.003, 0.001]).contains("median 2.00 ms"));
    }

    #[test]
    fn portal_depths_parse_up_to_the_maximum() {
        assert_eq!(parse_portal_depth("0"), Ok(0));
        assert_eq!(parse_portal_depth("16"), Ok(16));
        for bad in ["17", "-1", "two", "", "4294967296"] {
            let error = parse_portal_depth(bad).expect_err(bad);
            assert!(error.contains("from 0 to 16"), "{error}");
        }
    }

    #[test]
    fn threads_parse_up_to_the_maximum() {
        assert_eq!(parse_threads("0"), Ok(0));
        assert_eq!(parse_threads("7"), Ok(7));
        assert_eq!(parse_threads("1024"), Ok(MAX_THREADS));
        for bad in ["1025", "2000", "18446744073709551616", "-1", "x", ""] {
            assert!(parse_threads(bad).is_err(), "{bad:?}");
        }
        let message = parse_threads("2000").err().unwrap_or_default();
        assert!(
            message.contains("2000") && message.contains("1024"),
            "{message}"
        );
    }

    #[test]
    fn sizes_parse_and_refuse() {
        assert_eq!(parse_size("800x600"), Ok((800, 600)));
        assert_eq!(parse_size("64×48"), Ok((64, 48)));
        for bad in ["0x10", "10x0", "16385x2", "800", "axb", "", "-1x5"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn cameras_filters_shadings_and_fog_parse_and_refuse() {
        assert_eq!(parse_camera("auto"), Ok(CameraChoice::Auto));
        assert_eq!(parse_camera("2"), Ok(CameraChoice::Index(2)));
        assert!(parse_camera("-1").is_err() && parse_camera("first").is_err());
        assert_eq!(parse_filter("aniso:16"), Ok(Filter::Anisotropic(16)));
        assert_eq!(parse_filter("ewa"), Ok(Filter::Ewa));
        for bad in ["aniso:0", "aniso:17", "aniso:", "cubic"] {
            assert!(parse_filter(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_shading("hybrid"), Ok(Shading::Hybrid));
        assert!(parse_shading("pbr").is_err());
        assert_eq!(parse_fog("0.04"), Ok(0.04));
        for bad in ["-1", "nan", "inf", "thick"] {
            assert!(parse_fog(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn backgrounds_parse_and_refuse() {
        use barytex_texture::srgb::decode;
        let grey = Vec4::new(decode(0x76), decode(0x76), decode(0x7c), 1.0);
        assert_eq!(parse_background("#76767c"), Ok(grey));
        assert_eq!(parse_background("#76767CFF"), Ok(grey));
        assert_eq!(parse_background("118, 118,124"), Ok(grey));
        assert_eq!(parse_background("#00000000"), Ok(Vec4::ZERO));
        assert_eq!(parse_background("0,0,0,0"), Ok(Vec4::ZERO));
        assert_eq!(
            parse_background("255,0,0,51"),
            Ok(Vec4::new(1.0, 0.0, 0.0, 0.2))
        );
        for bad in [
            "#12345",
            "#1234567",
            "#gg0000",
            "#+1+2+3",
            "123456",
            "256,0,0",
            "+1,0,0",
            "1,2",
            "1,2,3,4,5",
            "-1,0,0",
            "1.5,0,0",
            "1,,2",
            "red",
            "",
            "#",
            "#ééé",
        ] {
            let Err(error) = parse_background(bad) else {
                panic!("{bad} was accepted");
            };
            assert!(error.starts_with("background `"), "{bad}: {error}");
            assert_eq!(error.lines().count(), 1, "{bad}: {error}");
        }
    }

    #[test]
    fn anti_aliasing_parses_and_refuses() {
        assert_eq!(parse_aa("none"), Ok(AntiAliasing::None));
        assert_eq!(parse_aa("msaa:8"), Ok(AntiAliasing::Msaa(8)));
        assert_eq!(parse_aa("ssaa:4"), Ok(AntiAliasing::Supersample(4)));
        assert_eq!(parse_aa("jitter:3"), Ok(AntiAliasing::Jitter(3)));
        assert_eq!(parse_aa("adaptive:40"), Ok(AntiAliasing::Adaptive(40)));
        for bad in [
            "msaa:3",
            "msaa:32",
            "ssaa:0",
            "ssaa:17",
            "adaptive:2",
            "adaptive:999",
            "fxaa",
        ] {
            assert!(parse_aa(bad).is_err(), "{bad}");
        }
    }
}
