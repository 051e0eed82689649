//! A whole atlas end to end: a torus (closed, genus 1, so it must be cut) unwrapped with the
//! default method (segmentation, LSCM, ARAP), packed into a 512-texel square with 2 texels of
//! padding, checked exactly, and written as a Wavefront OBJ with its texture coordinates (`vt`),
//! which any modeller opens.
//!
//! Run with `cargo run --release -p barytex-unwrap --example atlas_obj -- [OUT.obj]` (default
//! `barytex-atlas.obj` in the temporary folder).

use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;

use barytex_unwrap::pack::PackOptions;
use barytex_unwrap::{UnwrapOptions, shapes, unwrap};

fn main() -> Result<(), Box<dyn Error>> {
    let out = std::env::args_os().nth(1).map_or_else(
        || std::env::temp_dir().join("barytex-atlas.obj"),
        PathBuf::from,
    );
    let mesh = shapes::torus(1.0, 0.35, 48, 24);
    let options = UnwrapOptions {
        pack: PackOptions {
            size: 512,
            padding: 2,
            rotate: true,
        },
        ..UnwrapOptions::default()
    };
    let atlas = unwrap(&mesh, &options)?;
    println!(
        "{} triangles -> {} charts, packing efficiency {:.1}% at {:.1} texels per unit; \
         {} flipped, {} overlapping pairs, {} uvs outside the square",
        mesh.triangles().len(),
        atlas.charts.len(),
        100.0 * atlas.pack.efficiency,
        atlas.pack.texels_per_unit,
        atlas.check.flipped.len(),
        atlas.check.overlaps.between_charts.len() + atlas.check.overlaps.within_charts.len(),
        atlas.check.outside
    );
    if !atlas.check.is_valid() {
        return Err("the exact checks failed".into());
    }
    // OBJ: every mesh position once, every chart vertex's uv once, faces as v/vt pairs
    // (1-based), counter-clockwise in uv as on the surface.
    let mut obj = String::from("# barytex-unwrap atlas_obj example\n");
    for p in mesh.positions() {
        let _ = writeln!(obj, "v {} {} {}", p.x, p.y, p.z);
    }
    let mut base = 1;
    for chart in &atlas.charts {
        for uv in &chart.uvs {
            let _ = writeln!(obj, "vt {} {}", uv.x, uv.y);
        }
        for t in &chart.triangles {
            let corner = |k: usize| {
                let local = t[k] as usize;
                format!("{}/{}", chart.vertices[local] + 1, base + local)
            };
            let _ = writeln!(obj, "f {} {} {}", corner(0), corner(1), corner(2));
        }
        base += chart.uvs.len();
    }
    std::fs::write(&out, obj)?;
    println!("wrote {}", out.display());
    Ok(())
}
