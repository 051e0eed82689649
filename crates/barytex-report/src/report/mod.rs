//! The speed-vs-error report of the interpolation methods, the texture filters, the rasterizer
//! and the shading.
//!
//! Each family module runs every method on the same inputs, measures its error against an
//! exact-rational (or f64 Newton) reference and its time per call, and returns a [`Section`] of
//! [`Table`]s; this module marks the Pareto front and writes the Markdown, with a speed-vs-error
//! chart (SVG, [`chart`]) under every table that has an error measure. While the families run, a
//! progress bar on stderr shows which one is being measured (only when stderr is a terminal;
//! otherwise plain progress lines, as logs want).

mod barycentric_2d;
mod barycentric_3d;
mod chart;
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

use indicatif::{ProgressBar, ProgressStyle};

pub(crate) use table::{ErrorStats, Row, Section, Table};

use crate::timing::TimingConfig;

/// What `barytex-report` was asked to do.
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

/// Progress over the families: an indicatif bar on stderr when stderr is a terminal, else (tests,
/// CI logs, redirects) one plain line per step, as before the bar existed.
struct Progress {
    bar: ProgressBar,
    count: usize,
}

impl Progress {
    fn new(count: usize) -> Self {
        // `ProgressBar::new` draws on stderr and is hidden when stderr is not a terminal.
        let bar = ProgressBar::new(count as u64);
        if let Ok(style) = ProgressStyle::with_template(
            "{elapsed_precise} [{bar:30.cyan/blue}] {pos}/{len} {wide_msg}",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        if !bar.is_hidden() {
            bar.enable_steady_tick(std::time::Duration::from_millis(250));
        }
        Self { bar, count }
    }

    /// A line for the log: above the bar when it is drawn, else plain on stderr.
    fn line(&self, text: &str) {
        if self.bar.is_hidden() {
            eprintln!("{text}");
        } else {
            self.bar.println(text);
        }
    }

    /// Family `index` (from 0) starts.
    fn start(&self, index: usize, name: &str) {
        if self.bar.is_hidden() {
            eprintln!("[{}/{}] {name} …", index + 1, self.count);
        } else {
            self.bar.set_message(name.to_owned());
        }
    }

    /// A step within family `index`.
    fn step(&self, index: usize, name: &str, step: &str) {
        if self.bar.is_hidden() {
            eprintln!("[{}/{}] {name}: {step}", index + 1, self.count);
        } else {
            self.bar.set_message(format!("{name}: {step}"));
        }
    }

    /// Family `index` is done after `seconds`.
    fn done(&self, index: usize, name: &str, seconds: f64) {
        self.line(&format!(
            "[{}/{}] {name}: done in {seconds:.1} s",
            index + 1,
            self.count
        ));
        self.bar.inc(1);
    }

    /// Runs family `index` with its progress lines.
    fn measure<T>(
        &self,
        index: usize,
        name: &str,
        family: impl FnOnce(&mut dyn FnMut(&str)) -> T,
    ) -> T {
        let started = std::time::Instant::now();
        self.start(index, name);
        let result = family(&mut |step: &str| self.step(index, name, step));
        self.done(index, name, started.elapsed().as_secs_f64());
        result
    }

    fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// Run every family and write `README.md`, the pages and their charts into `options.out`.
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
    let progress = Progress::new(families.len() + 3);
    let mut sections = Vec::with_capacity(families.len());
    for (index, (name, family)) in families.into_iter().enumerate() {
        sections.push(progress.measure(index, name, |step| family(settings, step)));
    }
    let (mut texture, files) = progress.measure(sections.len(), "texture filters", |step| {
        texture_filters::run(settings, step)
    });
    let mut raster = progress.measure(sections.len() + 1, "rasterizer", |step| {
        raster::run(settings, step)
    });
    let mut shading = progress.measure(sections.len() + 2, "shading", |step| {
        shading::run(settings, step)
    });
    progress.finish();
    for section in sections
        .iter_mut()
        .chain([&mut texture, &mut raster, &mut shading])
    {
        for table in &mut section.tables {
            table.mark_pareto();
        }
    }

    let mut charts = Vec::new();
    for section in &mut sections {
        let prefix = format!("interp-{}", slug(&section.heading));
        charts.extend(attach_charts(&prefix, section));
    }
    charts.extend(attach_charts("texture", &mut texture));
    charts.extend(attach_charts("raster", &mut raster));
    charts.extend(attach_charts("shading", &mut shading));

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
    for (name, svg) in &charts {
        write(&options.out.join(name), svg)?;
    }
    write(&options.out.join("README.md"), &index)?;
    eprintln!(
        "wrote {}, {}, {}, {} and {}",
        options.out.join("README.md").display(),
        options.out.join("interp.md").display(),
        options.out.join("texture.md").display(),
        options.out.join("raster.md").display(),
        options.out.join("shading.md").display()
    );
    eprintln!(
        "wrote {} speed-vs-error charts ({}/*.svg)",
        charts.len(),
        options.out.display()
    );
    Ok(())
}

/// Builds the chart of every table of `section` that has one, names its file
/// `{prefix}-{table}.svg` and records the name in the table (so that the page links it).
/// Returns `(file name, SVG)` pairs.
fn attach_charts(prefix: &str, section: &mut Section) -> Vec<(String, String)> {
    let mut charts: Vec<(String, String)> = Vec::new();
    for table in &mut section.tables {
        let Some(chart) = table.scatter_chart(&section.heading) else {
            continue;
        };
        let stem = format!("{prefix}-{}", slug(&table.title));
        let mut name = format!("{stem}.svg");
        let mut n = 2;
        while charts.iter().any(|(taken, _)| *taken == name) {
            name = format!("{stem}-{n}.svg");
            n += 1;
        }
        table.chart = Some(name.clone());
        charts.push((name, chart.to_svg()));
    }
    charts
}

/// Lower-case ASCII letters and digits, runs of anything else as one `-`.
fn slug(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.is_empty() && !out.ends_with('-') {
            out.push('-');
        }
    }
    out.trim_end_matches('-').to_owned()
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
        "Generated by `{}` (run `cargo run --release -p barytex-report` at the repository root \
         to regenerate; `-- --quick` for a fast, rough run). Only ratios within one run are \
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
         Phong, the H-test hybrid, fast Phong) and of normal interpolation |"
    );
    let _ = writeln!(
        out,
        "| [unwrap.md](unwrap.md) | uv unwrapping beside xatlas: charts, flips, overlaps, packing \
         efficiency, distortion and time per method on Suzanne, Avocado, a torus and a sphere, \
         with a distortion-vs-time chart; generated by `tools/xatlas_unwrap.py` (Python: xatlas \
         is a Python package), not by this tool |"
    );
    let _ = writeln!(
        out,
        "| [peers.md](peers.md) | the hot paths beside peers and same-result kernels in \
         criterion runs (lookups, mips, remap, SLERP, the rasterizer beside euc, the unlit frame \
         beside llvmpipe, the demo frame); run by hand from `benches/` and `tools/`, every speed \
         bar at once by `python3 tools/speed_bars.py`, not by this tool |\n"
    );
    let _ = writeln!(
        out,
        "Under every table with an error measure, a chart (`*.svg` next to the pages) plots each \
         method's time against its error, both on log scales; zero errors sit in a band marked \
         \"0 (exact)\", infinite or NaN ones in a band marked \"∞ / NaN\".\n"
    );
    let _ = writeln!(out, "## Headlines (this run)\n");
    for section in sections.iter().chain(pages.iter().copied()) {
        for line in section.headlines() {
            let _ = writeln!(out, "- {line}");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(method: &str, ns: f64, abs_max: f64) -> Row {
        Row {
            method: method.to_owned(),
            ns,
            abs: Some(ErrorStats {
                max: abs_max,
                median: abs_max,
            }),
            ..Row::default()
        }
    }

    #[test]
    fn slugs_are_lower_case_ascii_words() {
        assert_eq!(slug("2D barycentric"), "2d-barycentric");
        assert_eq!(
            slug("shading frequencies on a 16×8 sphere"),
            "shading-frequencies-on-a-16-8-sphere"
        );
        assert_eq!(slug("Planar::xz: Jacobian"), "planar-xz-jacobian");
        assert_eq!(slug("  (peer) "), "peer");
    }

    #[test]
    fn charts_are_attached_and_linked_from_the_tables() {
        let mut section = Section {
            heading: "2D barycentric".to_owned(),
            tables: vec![
                Table {
                    title: "random [well] shaped".to_owned(),
                    rows: vec![
                        row("naive", 4.5, 1.3e-6),
                        Row {
                            is_default: true,
                            ..row("barycentric_2d", 20.0, 6e-8)
                        },
                        row("robust::orient2d (peer, f32 → f64)", 3.0, 0.0),
                    ],
                    ..Table::default()
                },
                // One row: no chart.
                Table {
                    title: "single".to_owned(),
                    rows: vec![row("naive", 4.5, 1.3e-6)],
                    ..Table::default()
                },
                // Same slug as the first: a distinct file.
                Table {
                    title: "random well shaped".to_owned(),
                    rows: vec![row("a", 1.0, 1.0), row("b", 2.0, 0.5)],
                    ..Table::default()
                },
            ],
            ..Section::default()
        };
        for table in &mut section.tables {
            table.mark_pareto();
        }
        let charts = attach_charts("interp-2d-barycentric", &mut section);
        let names: Vec<&str> = charts.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "interp-2d-barycentric-random-well-shaped.svg",
                "interp-2d-barycentric-random-well-shaped-2.svg"
            ]
        );
        assert_eq!(section.tables[1].chart, None);
        let svg = &charts[0].1;
        assert!(svg.contains("barycentric_2d (default)"));
        assert!(svg.contains("class=\"point peer\""));
        assert!(svg.contains(">0 (exact)</text>"));
        let mut page = String::new();
        section.render(&mut page);
        assert!(
            page.contains(
                "![Speed vs error, random well shaped: one point per method, time and error on \
                 log scales](interp-2d-barycentric-random-well-shaped.svg)"
            ),
            "{page}"
        );
        assert!(page.contains("(interp-2d-barycentric-random-well-shaped-2.svg)"));
        // The link comes after the table and before the next table's heading.
        let link = page.find("](interp-2d-barycentric-random-well-shaped.svg)");
        let last_row = page.find("| robust::orient2d");
        let next = page.find("### single");
        assert!(last_row < link && link < next, "{page}");
    }
}
