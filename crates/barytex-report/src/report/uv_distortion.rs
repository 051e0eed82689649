//! The UV distortion family: per surface and uv mapping (the parametric meshes' own mappings),
//! the area-weighted mean and the maximum of the angle and area distortion, and what measuring
//! costs.

use std::fmt::Write as _;
use std::time::Instant;

use barytex_uv::UvError;
use barytex_uv::distortion::MeshDistortion;
use barytex_uv::mesh::{self, SphereUv, TriMesh};

use super::{Section, Settings};

/// The surfaces and mappings measured, at `a × b` (a around, b along).
fn surfaces(a: u32, b: u32) -> Vec<(&'static str, Result<TriMesh, UvError>)> {
    vec![
        ("plane, planar", mesh::plane(a, a)),
        ("cube, 3 × 2 atlas", mesh::cube(b)),
        (
            "cylinder (open), s = θ/2π, t linear in y",
            mesh::cylinder(a, b, false),
        ),
        ("cylinder with planar caps", mesh::cylinder(a, b, true)),
        (
            "sphere, equirectangular (t = φ/180° + 1/2)",
            mesh::sphere_with(a, b, SphereUv::Equirectangular),
        ),
        (
            "sphere, equal-area (t = sin φ/2 + 1/2)",
            mesh::sphere_with(a, b, SphereUv::EqualArea),
        ),
        (
            "torus R = 1, r = 0.4, s = θ/2π, t = φ/2π",
            mesh::torus(a, b, 1.0, 0.4),
        ),
    ]
}

/// Measures every surface and writes the table into the section's intro.
pub(crate) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let (a, b) = if settings.random < 1024 {
        (64, 32)
    } else {
        (256, 128)
    };
    let mut intro = format!(
        "Distortion of each parametric mesh's uv mapping (`barytex_uv::distortion`), at {a} × {b} \
         (segments × rings): per triangle the singular values σ1 ≥ σ2 of the surface → uv \
         Jacobian; angle distortion σ1/σ2, area distortion max(ρ, 1/ρ) with ρ the triangle's \
         area ratio over the mesh's mean; means are area-weighted; 1 is undistorted. The \
         figures include the flat triangles' discretization (≈ 1.6/rings of excess area \
         distortion on the sphere).\n\n\
         | surface, mapping | triangles | area mean | area max | angle mean | angle max | µs to measure |\n\
         |---|---|---|---|---|---|---|\n"
    );
    let mut notes = Vec::new();
    let mut spheres = Vec::new();
    for (name, built) in surfaces(a, b) {
        progress(name);
        let row = built.ok().and_then(|mesh| {
            let started = Instant::now();
            let measured = MeshDistortion::of(&mesh)?;
            Some((measured, started.elapsed().as_secs_f64() * 1e6))
        });
        match row {
            Some((d, micros)) => {
                let _ = writeln!(
                    intro,
                    "| {name} | {} | {:.4} | {:.2} | {:.3} | {:.2} | {micros:.0} |",
                    d.triangles, d.area_mean, d.area_max, d.angle_mean, d.angle_max
                );
                if name.starts_with("sphere") {
                    spheres.push(d);
                }
            }
            None => {
                let _ = writeln!(intro, "| {name} | — | — | — | — | — | — |");
            }
        }
    }
    if let [equirectangular, equal_area] = spheres.as_slice() {
        notes.push(format!(
            "The equirectangular sphere has {:.1}× the excess area distortion (area mean − 1) of \
             the equal-area one ({:.4} vs {:.4}; its closed form is 1.5166, the equal-area \
             mapping's 1), but the equal-area one pays in angle distortion ({:.2} vs {:.2} mean).",
            equirectangular.area_excess_ratio(equal_area),
            equirectangular.area_mean,
            equal_area.area_mean,
            equal_area.angle_mean,
            equirectangular.angle_mean,
        ));
    }
    Section {
        heading: "UV distortion".to_owned(),
        intro,
        tables: Vec::new(),
        notes,
    }
}
