//! `barytex uv-layout`: draws uv layouts (wireframe, seams in red) to PNGs: a parametric mesh's
//! over a checker (`--mesh`), or every textured primitive of a glTF scene over its texture
//! (`FILE`, in [`scene`]).

pub(crate) mod scene;

use std::path::PathBuf;

use barytex_uv::UvError;
use barytex_uv::distortion::MeshDistortion;
use barytex_uv::layout::{LayoutOptions, draw_uv_layout, write_png};
use barytex_uv::mesh::{self, TriMesh};
use clap::ValueEnum;

/// The meshes `uv-layout` can draw, at the resolutions of the pictures in `docs/uv-layout`.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub(crate) enum MeshKind {
    /// `sphere(32, 16)`, equirectangular.
    Sphere,
    /// `sphere_with(32, 16, EqualArea)`.
    EqualAreaSphere,
    /// `torus(32, 16, 1.0, 0.4)`.
    Torus,
    /// `torus(256, 128, 1.0, 0.4)`: 65 536 triangles, for timing large meshes.
    DenseTorus,
    /// `cylinder(24, 4, caps)`.
    Cylinder,
    /// `cube(4)`, the 3 × 2 atlas.
    Cube,
    /// `plane(8, 8)`.
    Plane,
}

impl MeshKind {
    pub(crate) fn build(self) -> Result<TriMesh, UvError> {
        match self {
            Self::Sphere => mesh::sphere(32, 16),
            Self::EqualAreaSphere => mesh::sphere_with(32, 16, mesh::SphereUv::EqualArea),
            Self::Torus => mesh::torus(32, 16, 1.0, 0.4),
            Self::DenseTorus => mesh::torus(256, 128, 1.0, 0.4),
            Self::Cylinder => mesh::cylinder(24, 4, true),
            Self::Cube => mesh::cube(4),
            Self::Plane => mesh::plane(8, 8),
        }
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            Self::Sphere => "sphere",
            Self::EqualAreaSphere => "equal-area-sphere",
            Self::Torus => "torus",
            Self::DenseTorus => "dense-torus",
            Self::Cylinder => "cylinder",
            Self::Cube => "cube",
            Self::Plane => "plane",
        }
    }
}

/// What `uv-layout` was asked for.
pub(crate) struct Options {
    /// A glTF/GLB file, or a parametric mesh.
    pub(crate) source: Source,
    /// Picture side in pixels.
    pub(crate) size: u32,
    /// The PNG (`--mesh`) or the folder (`FILE`) to write.
    pub(crate) out: Option<PathBuf>,
}

/// Where the meshes come from.
pub(crate) enum Source {
    /// One of the parametric meshes.
    Mesh(MeshKind),
    /// The textured primitives of a glTF file's scene.
    File {
        /// The `.gltf` or `.glb`.
        path: PathBuf,
        /// Which of its scenes.
        scene: Option<usize>,
        /// Folders besides the file's own that its URIs may read (`--allow-dir`).
        allowed_roots: Vec<PathBuf>,
    },
}

/// Draws the pictures and writes them, printing where.
pub(crate) fn run(options: &Options) -> Result<(), Box<dyn std::error::Error>> {
    match &options.source {
        Source::Mesh(kind) => run_mesh(*kind, options.size, options.out.clone()),
        Source::File {
            path,
            scene,
            allowed_roots,
        } => scene::run_file(
            path,
            *scene,
            allowed_roots,
            options.size,
            options.out.clone(),
        ),
    }
}

/// Draws a parametric mesh and writes it (default `<mesh>.png` in the current folder, as
/// `render` writes `barytex-render.png` there).
fn run_mesh(
    kind: MeshKind,
    size: u32,
    out: Option<PathBuf>,
) -> Result<(), Box<dyn std::error::Error>> {
    let mesh = kind.build()?;
    let picture = draw_uv_layout(&mesh, size, &LayoutOptions::default())?;
    let out = out.unwrap_or_else(|| PathBuf::from(format!("{}.png", kind.name())));
    if let Some(parent) = out.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    write_png(&picture, &out)?;
    println!(
        "wrote {} ({}×{}, {} triangles)",
        out.display(),
        size,
        size,
        mesh.indices.len()
    );
    if let Some(d) = MeshDistortion::of(&mesh) {
        println!(
            "distortion (area-weighted mean / max): area {:.4} / {:.2}, angle {:.3} / {:.2}",
            d.area_mean, d.area_max, d.angle_mean, d.angle_max
        );
    }
    Ok(())
}
