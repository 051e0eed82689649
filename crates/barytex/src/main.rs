//! The `barytex` command.
//!
//! - `barytex` (what `cargo run --release` runs): renders the built-in demo scene to
//!   `barytex-demo.png` and prints where it went and how long each stage took (`barytex demo`
//!   takes the render options, and `--mirror` for the demo with a standing mirror).
//! - `barytex render FILE [--scene N] [--camera N|auto] [--size WxH] [--shading unlit|phong]
//!   [--filter …] [--aa …] [--background COLOUR] [--threads N] [-o OUT.png] [--print-camera]
//!   [--stats] [--frames N] [--portal-depth N] [--allow-dir DIR]…`: a glTF/GLB (its URIs read only files under its folder and
//!   each DIR). `--camera N` is the document's `cameras[N]`; `--list-cameras` lists them and
//!   where the scene places them, and renders nothing.
//! - `barytex examples`: the worked examples of Buss, *3D Computer Graphics* (2003), ch. IV,
//!   and Schaefer's scanline triangle, checked against exact arithmetic.
//! - `barytex uv-layout FILE [--scene N] [--size N] [-o DIR] [--allow-dir DIR]…`: the uv layout
//!   of every textured primitive over its texture (default folder `<file stem>-uv-layout`).
//! - `barytex uv-layout --mesh sphere|equal-area-sphere|torus|cylinder|cube|plane [--size N]
//!   [-o FILE.png]`: a parametric mesh's uv layout (default `<mesh>.png` in the current folder).
//! - `barytex unwrap FILE [-o OUT.gltf] [--uv-set N] [--size N] [--padding N] [--method …]
//!   [--stats] [--layout FILE.png] [--allow-dir DIR]…`: new texture coordinates for every mesh
//!   of the scene (charts packed into the unit square, checked exactly for flips and overlaps),
//!   written as `TEXCOORD_N` of a new .gltf and .bin with a picture of the layout
//!   (`--mesh torus|sphere|…` unwraps a built-in mesh; `--dump-mesh`/`--compare-uvs` measure a
//!   peer's uvs the same way, see docs/UNWRAP.md).
//!
//! The speed-vs-error report (`docs/report/`) is the workspace tool `barytex-report`
//! (`cargo run --release -p barytex-report`), not a subcommand: it measures against test
//! references and peer crates the command does not carry. `barytex report` says so.

mod exact;
mod examples;
mod progress;
mod render_cmd;
mod unwrap_cmd;
mod uv_layout;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

/// barytex: interpolation math and texturing, exact where a sign decides topology.
///
/// Without a subcommand, renders the built-in demo scene to barytex-demo.png.
#[derive(Debug, Parser)]
#[command(name = "barytex", version, about, long_about = None)]
struct Cli {
    /// What to do; the demo scene when absent.
    #[command(subcommand)]
    command: Option<Command>,
}

/// How to render (shared by `render` and `demo`).
#[derive(Debug, Args)]
struct RenderArgs {
    /// Image size, WIDTHxHEIGHT.
    #[arg(long, default_value = "960x540", value_parser = render_cmd::parse_size)]
    size: (u32, u32),
    /// `auto` (the documented automatic camera) or N, the file's camera N (glTF `cameras[N]`,
    /// where the first node of the scene that uses it places it; --list-cameras lists them);
    /// default: the first camera the scene places, else auto.
    #[arg(long, value_parser = render_cmd::parse_camera)]
    camera: Option<barytex_render::CameraChoice>,
    /// Print the file's cameras (index, name, projection, which node of the scene places each
    /// and where) and exit without rendering.
    #[arg(long)]
    list_cameras: bool,
    /// The colour where nothing is drawn, sRGB: `#rrggbb`, `#rrggbbaa` or `r,g,b[,a]` with
    /// each 0 to 255; alpha below 255 is kept in the PNG (`#00000000`: transparent, so alpha
    /// is the coverage). Fog fades to it. Default: `#76767c`, opaque.
    #[arg(long, value_name = "COLOUR", allow_hyphen_values = true)]
    background: Option<String>,
    /// unlit (glTF's unlit model: base colour × texture × vertex colour), flat, gouraud,
    /// phong, or hybrid (Gouraud, and Phong on triangles the highlight test picks).
    #[arg(long, default_value = "phong", value_parser = render_cmd::parse_shading)]
    shading: barytex_render::Shading,
    /// Exponential fog density per unit of distance, in the background colour.
    #[arg(long, value_parser = render_cmd::parse_fog)]
    fog: Option<f32>,
    /// file (the glTF samplers), nearest, bilinear, trilinear, aniso:N or ewa.
    #[arg(long, value_parser = render_cmd::parse_filter)]
    filter: Option<barytex_render::Filter>,
    /// none, ssaa:N (N×N grid), jitter:N (N×N, per pixel), msaa:N (1, 2, 4, 8, 16) or
    /// adaptive:N (up to N samples where needed).
    #[arg(long, value_parser = render_cmd::parse_aa)]
    aa: Option<barytex_render::AntiAliasing>,
    /// How many portals or mirrors deep a view may look (glTF nodes with
    /// `extras.barytex_portal`, see docs/PORTALS.md), 0 to 16; 0 draws them closed.
    #[arg(long, default_value_t = barytex_render::RenderOptions::default().portal_depth,
          value_parser = render_cmd::parse_portal_depth)]
    portal_depth: u32,
    /// Worker threads, at most 1024 (absent or 0: all cores); the image is the same for any
    /// count.
    #[arg(long, value_parser = render_cmd::parse_threads)]
    threads: Option<usize>,
    /// Print the view and projection matrices.
    #[arg(long)]
    print_camera: bool,
    /// Print what the loader and renderer did (textures, mips, fragments, skipped objects), and
    /// time rasterization apart from shading (one more draw with a constant shader).
    #[arg(long)]
    stats: bool,
    /// Draw the prepared scene this many times (1 to 1000) and print the draw's median, minimum
    /// and maximum: the first frame in a process touches fresh memory, later ones are warm, as
    /// an application drawing frame after frame sees them. The PNG is the last frame's.
    #[arg(long, default_value_t = 1, value_parser = render_cmd::parse_frames)]
    frames: u32,
}

/// Options of `barytex render`.
#[derive(Debug, Args)]
struct RenderFileArgs {
    /// The glTF (.gltf) or GLB (.glb) file.
    file: PathBuf,
    /// Which of the file's scenes (default: its `scene`, else the first).
    #[arg(long)]
    scene: Option<usize>,
    /// The PNG to write.
    #[arg(short, long, default_value = "barytex-render.png")]
    out: PathBuf,
    /// A folder besides the model's own that its relative URIs may read (repeatable); by
    /// default a model reads only files under its own folder.
    #[arg(long = "allow-dir", value_name = "DIR")]
    allow_dir: Vec<PathBuf>,
    #[command(flatten)]
    render: RenderArgs,
}

/// Options of `barytex demo`.
#[derive(Debug, Args)]
struct DemoArgs {
    /// The PNG to write.
    #[arg(short, long, default_value = "barytex-demo.png")]
    out: PathBuf,
    /// Stand a framed mirror behind the objects (a portal drawn through an oblique near plane;
    /// see docs/PORTALS.md).
    #[arg(long)]
    mirror: bool,
    #[command(flatten)]
    render: RenderArgs,
}

impl RenderArgs {
    /// The demo's defaults, as `barytex_render::demo::demo_options` sets them (anisotropic
    /// filtering, 4× MSAA, fog).
    fn demo_defaults() -> Self {
        let demo = barytex_render::demo::demo_options(960, 540);
        Self {
            size: (demo.width, demo.height),
            camera: None,
            list_cameras: false,
            background: None,
            shading: demo.shading,
            filter: Some(demo.filter),
            aa: Some(demo.anti_aliasing),
            fog: demo.fog.map(|f| f.density),
            threads: None,
            print_camera: false,
            stats: false,
            frames: 1,
            portal_depth: demo.portal_depth,
        }
    }

    fn options(
        self,
        file: Option<PathBuf>,
        scene: Option<usize>,
        allowed_roots: Vec<PathBuf>,
        out: PathBuf,
    ) -> Result<render_cmd::Options, String> {
        let background = match &self.background {
            Some(text) => render_cmd::parse_background(text)?,
            None => barytex_render::RenderOptions::default().background,
        };
        Ok(render_cmd::Options {
            demo_mirror: false,
            file,
            scene,
            allowed_roots,
            render: barytex_render::RenderOptions {
                width: self.size.0,
                height: self.size.1,
                camera: self.camera.unwrap_or_default(),
                shading: self.shading,
                filter: self.filter.unwrap_or_default(),
                anti_aliasing: self.aa.unwrap_or_default(),
                fog: self
                    .fog
                    .filter(|&d| d > 0.0)
                    .map(|density| barytex_shade::ExponentialFog {
                        density,
                        colour: background.truncate(),
                        distance: barytex_shade::FogDistance::Euclidean,
                    }),
                background,
                measure_stages: false,
                portal_depth: self.portal_depth,
            },
            threads: self.threads,
            out,
            print_camera: self.print_camera,
            list_cameras: self.list_cameras,
            stats: self.stats,
            frames: self.frames,
        })
    }
}

/// The subcommands.
#[derive(Debug, Subcommand)]
enum Command {
    /// Render the built-in demo scene (what `barytex` without arguments does).
    Demo(DemoArgs),
    /// Render a glTF 2.0 or GLB file to a PNG.
    Render(RenderFileArgs),
    /// Print the worked examples of Buss, 3D Computer Graphics (2003), ch. IV, and Schaefer's
    /// scanline triangle, checked against exact arithmetic.
    Examples,
    /// Moved to the workspace tool `barytex-report`; says how to run it.
    #[command(hide = true, disable_help_flag = true)]
    Report {
        /// What was typed after `report`, passed on in the message.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Draw uv layouts (wireframe, seams in red): a glTF file's textured primitives over their
    /// textures, or a parametric mesh's over a checker.
    UvLayout(UvLayoutArgs),
    /// New texture coordinates for a glTF model: charts packed into the unit square with a
    /// padding, checked exactly (no flip, no overlap), written as a new uv set with a picture of
    /// the layout.
    Unwrap(UnwrapArgs),
}

/// Options of `barytex unwrap` (a glTF file or `--mesh`, not both).
#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("source").required(true).args(["file", "mesh"])))]
struct UnwrapArgs {
    /// A glTF (.gltf) or GLB (.glb) file: every mesh of its scene is unwrapped.
    file: Option<PathBuf>,
    /// A built-in mesh instead of a file (no model is written; its own uvs are ignored).
    #[arg(long, value_enum)]
    mesh: Option<uv_layout::MeshKind>,
    /// Which of the file's scenes (default: its `scene`, else the first).
    #[arg(long, requires = "file")]
    scene: Option<usize>,
    /// A folder besides the model's own that its relative URIs may read (repeatable).
    #[arg(long = "allow-dir", value_name = "DIR", requires = "file")]
    allow_dir: Vec<PathBuf>,
    /// The .gltf to write (with a .bin of the same stem beside it) or the .glb (one file);
    /// default `<file stem>-unwrapped.gltf`.
    #[arg(short, long, requires = "file")]
    out: Option<PathBuf>,
    /// The uv set N to write, TEXCOORD_N (replaced if present); default 1 when every primitive
    /// has TEXCOORD_0 (kept for its textures), else 0.
    #[arg(long)]
    uv_set: Option<u32>,
    /// Texture side in texels (1 to 32768).
    #[arg(long, default_value_t = 1024)]
    size: u32,
    /// Texels between charts and to the border (at most a quarter of the size).
    #[arg(long, default_value_t = 4)]
    padding: u32,
    /// How charts are made.
    #[arg(long, value_enum, default_value = "lscm-arap")]
    method: unwrap_cmd::MethodArg,
    /// Keep charts as they are instead of turning them to their minimum-area boxes.
    #[arg(long)]
    no_rotate: bool,
    /// Segmentation cone in degrees (0 to 180]: a chart's normals stay this close to its mean
    /// normal; smaller gives more, flatter charts (default: the library's).
    #[arg(long, value_name = "DEGREES", value_parser = unwrap_cmd::parse_cone)]
    cone: Option<f64>,
    /// Split a chart whose mean angle distortion σ1/σ2 exceeds this (at least 1; default: the
    /// library's). Free-boundary methods only.
    #[arg(long, value_name = "RATIO", value_parser = unwrap_cmd::parse_ratio)]
    max_angle_distortion: Option<f64>,
    /// Split a chart whose mean area distortion exceeds this (at least 1; default: the
    /// library's). Free-boundary methods only.
    #[arg(long, value_name = "RATIO", value_parser = unwrap_cmd::parse_ratio)]
    max_area_distortion: Option<f64>,
    /// ARAP iterations at most, for lscm-arap (default: the library's).
    #[arg(long, value_name = "N")]
    arap_iterations: Option<u32>,
    /// The layout picture (default `<out stem>-uv-layout.png`; meshes after the first add
    /// `-mesh<N>`).
    #[arg(long, value_name = "FILE")]
    layout: Option<PathBuf>,
    /// Print charts, flips, overlaps, packing efficiency, distortion and time per stage.
    #[arg(long)]
    stats: bool,
    /// Write the figures as JSON to FILE.
    #[arg(long, value_name = "FILE")]
    stats_json: Option<PathBuf>,
    /// Write the welded mesh that is unwrapped (positions, triangles) as JSON to FILE, for a
    /// peer to unwrap (tools/xatlas_unwrap.py); one-mesh models only.
    #[arg(long, value_name = "FILE")]
    dump_mesh: Option<PathBuf>,
    /// Measure a peer's uvs of that mesh (JSON: vertex_of, uvs, indices) the same way as
    /// ours; one-mesh models only.
    #[arg(long, value_name = "FILE")]
    compare_uvs: Option<PathBuf>,
}

/// Options of `barytex uv-layout` (a glTF file or `--mesh`, not both).
#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("source").required(true).args(["file", "mesh"])))]
struct UvLayoutArgs {
    /// A glTF (.gltf) or GLB (.glb) file: one picture per textured primitive, over the texture
    /// its material samples (the base colour texture, else its first), in that texture's uv set
    /// and transform.
    file: Option<PathBuf>,
    /// Which of the file's scenes (default: its `scene`, else the first).
    #[arg(long, requires = "file")]
    scene: Option<usize>,
    /// A folder besides the model's own that its relative URIs may read (repeatable); by
    /// default a model reads only files under its own folder.
    #[arg(long = "allow-dir", value_name = "DIR", requires = "file")]
    allow_dir: Vec<PathBuf>,
    /// A built-in parametric mesh instead of a file.
    #[arg(long, value_enum)]
    mesh: Option<uv_layout::MeshKind>,
    /// Picture side in pixels (1 to 8192).
    #[arg(long, default_value_t = 512)]
    size: u32,
    /// With `--mesh`, the PNG to write (default `<mesh>.png` in the current folder); with a
    /// file, the folder for its pictures (default `<file stem>-uv-layout`).
    #[arg(short, long)]
    out: Option<PathBuf>,
}

/// What `barytex report ARGS…` says: the report is the workspace tool `barytex-report` now,
/// with the same options.
fn report_moved(args: &[String]) -> String {
    let passed = if args.is_empty() {
        String::new()
    } else {
        format!(" -- {}", args.join(" "))
    };
    format!(
        "the speed-vs-error report is the workspace tool barytex-report now; from the \
         repository root run `cargo run --release -p barytex-report{passed}`"
    )
}

/// Makes `barytex … | head` end quietly: `println!` panics when the reader has gone, and that
/// panic's message and backtrace are noise, not a bug. Every other panic reports as usual.
fn quiet_on_closed_stdout() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or_default();
        if message.starts_with("failed printing to stdout") && message.contains("Broken pipe") {
            // What a shell reports for a process ended by SIGPIPE.
            std::process::exit(141);
        }
        default(info);
    }));
}

fn main() -> ExitCode {
    quiet_on_closed_stdout();
    let cli = Cli::parse();
    let result = match cli.command {
        None => RenderArgs::demo_defaults()
            .options(None, None, Vec::new(), PathBuf::from("barytex-demo.png"))
            .map_err(Into::into)
            .and_then(|options| render_cmd::run(&options)),
        Some(Command::Demo(args)) => {
            let defaults = RenderArgs::demo_defaults();
            let render = RenderArgs {
                filter: args.render.filter.or(defaults.filter),
                aa: args.render.aa.or(defaults.aa),
                fog: args.render.fog.or(defaults.fog),
                ..args.render
            };
            render
                .options(None, None, Vec::new(), args.out)
                .map(|options| render_cmd::Options {
                    demo_mirror: args.mirror,
                    ..options
                })
                .map_err(Into::into)
                .and_then(|options| render_cmd::run(&options))
        }
        Some(Command::Render(args)) => args
            .render
            .options(Some(args.file), args.scene, args.allow_dir, args.out)
            .map_err(Into::into)
            .and_then(|options| render_cmd::run(&options)),
        Some(Command::Examples) => examples::run(),
        Some(Command::Report { args }) => Err(report_moved(&args).into()),
        Some(Command::Unwrap(args)) => {
            let source = match (args.file, args.mesh) {
                (Some(path), None) => Ok(unwrap_cmd::Source::File {
                    path,
                    scene: args.scene,
                    allowed_roots: args.allow_dir,
                }),
                (None, Some(kind)) => Ok(unwrap_cmd::Source::Mesh(kind)),
                _ => Err("unwrap takes a FILE or --mesh, not both".into()),
            };
            source.and_then(|source| {
                unwrap_cmd::run(&unwrap_cmd::Options {
                    source,
                    out: args.out,
                    uv_set: args.uv_set,
                    method: args.method,
                    param: {
                        let d = barytex_unwrap::ParamOptions::default();
                        barytex_unwrap::ParamOptions {
                            cone_degrees: args.cone.unwrap_or(d.cone_degrees),
                            max_angle_distortion: args
                                .max_angle_distortion
                                .unwrap_or(d.max_angle_distortion),
                            max_area_distortion: args
                                .max_area_distortion
                                .unwrap_or(d.max_area_distortion),
                            max_iterations: args.arap_iterations.unwrap_or(d.max_iterations),
                            ..d
                        }
                    },
                    pack: barytex_unwrap::pack::PackOptions {
                        size: args.size,
                        padding: args.padding,
                        rotate: !args.no_rotate,
                    },
                    layout: args.layout,
                    stats: args.stats,
                    stats_json: args.stats_json,
                    dump_mesh: args.dump_mesh,
                    compare_uvs: args.compare_uvs,
                })
            })
        }
        Some(Command::UvLayout(args)) => {
            // clap's `source` group already requires exactly one of the two.
            let source = match (args.file, args.mesh) {
                (Some(path), None) => Ok(uv_layout::Source::File {
                    path,
                    scene: args.scene,
                    allowed_roots: args.allow_dir,
                }),
                (None, Some(kind)) => Ok(uv_layout::Source::Mesh(kind)),
                _ => Err("uv-layout takes a FILE or --mesh, not both".into()),
            };
            source.and_then(|source| {
                uv_layout::run(&uv_layout::Options {
                    source,
                    size: args.size,
                    out: args.out,
                })
            })
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("barytex: {error}");
            ExitCode::FAILURE
        }
    }
}
