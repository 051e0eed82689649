//! `barytex report`: the speed-vs-error report of the interpolation methods.
//!
//! Each family module runs every method on the same inputs, measures its error against an
//! exact-rational (or f64 Newton) reference and its time per call, and returns a [`Section`] of
//! [`Table`]s; this module marks the Pareto front and writes the Markdown.

mod barycentric_2d;
mod barycentric_3d;
mod hull;
mod inverse_bilinear;
mod orientation;
mod raster;
mod shading;
mod slerp;
mod table;
mod texture_filters;
mod uv_distortion;
mod uv_mappings;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub(crate) use table::{ErrorStats, Row, Section, Table};

use crate::timing::TimingConfig;

/// What `barytex report` was asked to do.
#[derive(Clone, Debug)]
pub(crate) struct Options {
    /// Directory for `README.md` and `interp.md`.
    pub(crate) out: PathBuf,
    /// Fewer inputs and batches (for tests); the figures are then rough.
    pub(crate) quick: bool,
    /// The command line as run, for the report's header.
    pub(crate) command: String,
}

/// Input-set sizes and timing effort, from `--quick` or not.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Settings {
    /// Random well-shaped inputs per family.
    pub(crate) random: usize,
    /// Side of Kettner's grid (`n × n` points).
    pub(crate) kettner: u32,
    /// Timing effort.
    pub(crate) timing: TimingConfig,
}

impl Settings {
    fn new(quick: bool) -> Self {
        if quick {
            Self {
                random: 256,
                kettner: 32,
                timing: TimingConfig {
                    batches: 3,
                    min_calls: 1024,
                },
            }
        } else {
            Self {
                random: 4096,
                kettner: 256,
                timing: TimingConfig {
                    batches: 21,
                    min_calls: 65_536,
                },
            }
        }
    }
}

/// Run every family and write `README.md` and `interp.md` into `options.out`.
///
/// # Errors
/// When the output directory or a file cannot be written.
pub(crate) fn run(options: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let settings = Settings::new(options.quick);
    type Family = fn(Settings, &mut dyn FnMut(&str)) -> Section;
    let families: [(&str, Family); 8] = [
        ("2D barycentric", barycentric_2d::run),
        ("3D barycentric", barycentric_3d::run),
        ("orientation", orientation::run),
        ("inverse bilinear", inverse_bilinear::run),
        ("SLERP family", slerp::run),
        ("2D convex hull", hull::run),
        ("UV mappings", uv_mappings::run),
        ("UV distortion", uv_distortion::run),
    ];
    let count = families.len();
    let mut sections = Vec::with_capacity(count);
    for (index, (name, family)) in families.into_iter().enumerate() {
        let started = std::time::Instant::now();
        eprintln!("[{}/{count}] {name} …", index + 1);
        let mut progress = |step: &str| eprintln!("[{}/{count}] {name}: {step}", index + 1);
        let mut section = family(settings, &mut progress);
        for table in &mut section.tables {
            table.mark_pareto();
        }
        eprintln!(
            "[{}/{count}] {name}: done in {:.1} s",
            index + 1,
            started.elapsed().as_secs_f64()
        );
        sections.push(section);
    }
    eprintln!("[texture] texture filters …");
    let started = std::time::Instant::now();
    let (mut texture, files) =
        texture_filters::run(settings, &mut |step| eprintln!("[texture] {step}"));
    for table in &mut texture.tables {
        table.mark_pareto();
    }
    eprintln!("[texture] done in {:.1} s", started.elapsed().as_secs_f64());
    eprintln!("[raster] rasterizer families …");
    let started = std::time::Instant::now();
    let mut raster = raster::run(settings, &mut |step| eprintln!("[raster] {step}"));
    for table in &mut raster.tables {
        table.mark_pareto();
    }
    eprintln!("[raster] done in {:.1} s", started.elapsed().as_secs_f64());
    eprintln!("[shading] shading families …");
    let started = std::time::Instant::now();
    let mut shading = shading::run(settings, &mut |step| eprintln!("[shading] {step}"));
    for table in &mut shading.tables {
        table.mark_pareto();
    }
    eprintln!("[shading] done in {:.1} s", started.elapsed().as_secs_f64());
    std::fs::create_dir_all(&options.out)?;
    let interp = render_interp(options, settings, &sections);
    let index = render_index(options, &sections, &[&texture, &raster, &shading]);
    write(&options.out.join("interp.md"), &interp)?;
    write(
        &options.out.join("texture.md"),
        &render_texture(options, &texture),
    )?;
    for (name, bytes) in &files {
        std::fs::write(options.out.join(name), bytes)
            .map_err(|e| format!("cannot write {name}: {e}"))?;
    }
    write(
        &options.out.join("raster.md"),
        &render_page(options, "the rasterizer (`barytex-raster`)", &raster),
    )?;
    write(
        &options.out.join("shading.md"),
        &render_page(options, "shading (`barytex-shade`)", &shading),
    )?;
    write(&options.out.join("README.md"), &index)?;
    eprintln!(
        "wrote {}, {}, {}, {} and {}",
        options.out.join("README.md").display(),
        options.out.join("interp.md").display(),
        options.out.join("texture.md").display(),
        options.out.join("raster.md").display(),
        options.out.join("shading.md").display()
    );
    Ok(())
}

fn render_texture(options: &Options, section: &Section) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Speed vs error: texture filtering (`barytex-texture`)\n"
    );
    let _ = writeln!(
        out,
        "Generated by `{}`{}. Every number below was measured by that run.\n",
        options.command,
        if options.quick {
            " (**quick mode: small images, rough timings**)"
        } else {
            ""
        }
    );
    let _ = writeln!(out, "- Machine: {}.", machine_info());
    let _ = writeln!(
        out,
        "- **Pareto** marks the filters that no other filter of the same table beats in both \
         time per lookup and max error. Only ratios within one run are meaningful.\n"
    );
    section.render(&mut out);
    out
}

fn render_page(options: &Options, title: &str, section: &Section) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# Speed vs error: {title}\n");
    let _ = writeln!(
        out,
        "Generated by `{}`{}. Every number below was measured by that run.\n",
        options.command,
        if options.quick {
            " (**quick mode: small images, rough timings**)"
        } else {
            ""
        }
    );
    let _ = writeln!(out, "- Machine: {}.", machine_info());
    let _ = writeln!(
        out,
        "- The `ns/call` column is ns per pixel of the frame unless a table says otherwise. \
         **Pareto** marks the methods that \
         no other method of the same table beats in both time and max error. Only ratios within \
         one run are meaningful.\n"
    );
    section.render(&mut out);
    out
}

fn write(path: &Path, text: &str) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()).into())
}

/// A description of the machine the figures were taken on.
pub(crate) fn machine_info() -> String {
    let threads = std::thread::available_parallelism().map_or(0, std::num::NonZero::get);
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned());
    let mut features = Vec::new();
    if cfg!(target_feature = "fma") {
        features.push("fma");
    }
    if cfg!(target_feature = "avx2") {
        features.push("avx2");
    }
    let features = if features.is_empty() {
        "none beyond the target's baseline (no `fma`: `f32::mul_add` is a library call)".to_owned()
    } else {
        features.join(", ")
    };
    format!(
        "{cpu}; {threads} hardware threads (`available_parallelism`); {} {}; \
         compiled-in target features: {features}; {} build",
        std::env::consts::OS,
        std::env::consts::ARCH,
        if cfg!(debug_assertions) {
            "debug"
        } else {
            "release"
        },
    )
}

fn render_interp(options: &Options, settings: Settings, sections: &[Section]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Speed vs error: interpolation math (`barytex-interp`)\n"
    );
    let _ = writeln!(
        out,
        "Generated by `{}`{}. Every number below was measured by that run.\n",
        options.command,
        if options.quick {
            " (**quick mode: few inputs, rough timings**)"
        } else {
            ""
        }
    );
    let _ = writeln!(out, "- Machine: {}.", machine_info());
    let _ = writeln!(
        out,
        "- Times are the **median** ns per call over {} timed batches of at least {} calls \
         (one untimed warm-up batch), inputs read through `black_box` and results passed to \
         `black_box`, one thread. Machines like this one are noisy and shared: **only ratios \
         within one run are meaningful**.",
        settings.timing.batches, settings.timing.min_calls
    );
    if !cfg!(target_feature = "fma") {
        let _ = writeln!(
            out,
            "- This build has no `fma` target feature, so `f32::mul_add` in the \
             difference-of-products (`dop`) methods compiles to a call to the C library's `fmaf`, \
             which dominates their time. To time them with the FMA instruction, build with \
             `RUSTFLAGS=\"-C target-cpu=native\"` on an FMA machine (not done in this run)."
        );
    }
    let _ = writeln!(
        out,
        "- Inputs come from a seeded xorshift generator, so every run measures the same inputs; \
         every method of a table runs on exactly the same inputs."
    );
    let _ = writeln!(
        out,
        "- Errors are against exact rational arithmetic (`barytex_testkit::exact`; the exact value \
         is rounded to f64 before subtracting, a relative 2⁻⁵³ that is far below every f32 error \
         shown) or, for inverse bilinear, against Newton's method in f64 \
         (`barytex_testkit::reference::inverse_bilinear_newton`). A NaN or infinite result \
         counts as an infinite error."
    );
    let _ = writeln!(
        out,
        "- **Pareto** marks the methods that no other method of the same table beats in both \
         time and the table's error measure (max abs error, or wrong signs for orientation).\n"
    );
    for section in sections {
        section.render(&mut out);
    }
    out
}

fn render_index(options: &Options, sections: &[Section], pages: &[&Section]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# barytex reports\n");
    let _ = writeln!(
        out,
        "Generated by `{}` (run `cargo run --release -- report` at the repository root to \
         regenerate; `--quick` for a fast, rough run). Only ratios within one run are \
         meaningful.\n",
        options.command
    );
    let _ = writeln!(out, "| report | contents |");
    let _ = writeln!(out, "|---|---|");
    let families: Vec<&str> = sections.iter().map(|s| s.heading.as_str()).collect();
    let _ = writeln!(
        out,
        "| [interp.md](interp.md) | speed vs error of the interpolation math: {} |",
        families.join(", ")
    );
    let _ = writeln!(
        out,
        "| [texture.md](texture.md) | speed vs error of the texture filters on the standard \
         scenes, with a picture strip |"
    );
    let _ = writeln!(
        out,
        "| [raster.md](raster.md) | speed vs error of the rasterizer's options: perspective \
         interpolation (affine, spans, exact) and anti-aliasing (MSAA, supersampling, adaptive) |"
    );
    let _ = writeln!(
        out,
        "| [shading.md](shading.md) | speed vs error of the shading frequencies (flat, Gouraud, \
         Phong, the H-test hybrid, fast Phong) and of normal interpolation |\n"
    );
    let _ = writeln!(out, "## Headlines (this run)\n");
    for section in sections.iter().chain(pages.iter().copied()) {
        for line in section.headlines() {
            let _ = writeln!(out, "- {line}");
        }
    }
    out
}
