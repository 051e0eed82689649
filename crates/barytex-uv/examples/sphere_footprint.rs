//! A uv mapping with derivatives, as a renderer uses it: ray-trace a unit sphere, take each
//! pixel's surface point with its screen-space derivatives (the neighbouring pixels' rays hit the
//! tangent plane, as in pbrt), map it with the equirectangular sphere mapping, and print which mip
//! level a 1024×512 texture would be sampled at (`log₂` of the footprint in texels).
//!
//! Run with `cargo run -p barytex-uv --example sphere_footprint`. The `barytex-texture` crate's
//! `sphere_sampler` example feeds the same samples to a texture sampler.

use barytex_uv::mappings::{SphereProjection, Spherical};
use barytex_uv::{SurfacePoint, UvMapping};
use glam::{Vec2, Vec3};

const WIDTH: u32 = 48;
const HEIGHT: u32 = 24;
const TEXTURE: Vec2 = Vec2::new(1024.0, 512.0);
const EYE: Vec3 = Vec3::new(0.0, 0.0, 3.0);

/// The view ray through pixel `(x, y)` (centre at `+ 0.5`), a pinhole looking down −z with a
/// vertical field of view of about 45°; character cells are twice as tall as wide.
fn ray(x: f32, y: f32) -> Vec3 {
    let f = HEIGHT as f32 / (2.0 * 0.414);
    Vec3::new(
        (x - WIDTH as f32 / 2.0) / (2.0 * f),
        -(y - HEIGHT as f32 / 2.0) / f,
        -1.0,
    )
    .normalize()
}

/// Where the ray from the eye along `d` first meets the unit sphere.
fn hit_sphere(d: Vec3) -> Option<Vec3> {
    let b = EYE.dot(d);
    let disc = b * b - (EYE.length_squared() - 1.0);
    (disc >= 0.0).then(|| EYE + d * (-b - disc.sqrt()))
}

/// Where the ray along `d` meets the plane through `p` with normal `n`.
fn hit_plane(d: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    EYE + d * (n.dot(p - EYE) / n.dot(d))
}

/// The surface point seen through pixel `(x, y)`, with `∂p/∂x` and `∂p/∂y`.
fn surface_point(x: f32, y: f32) -> Option<SurfacePoint> {
    let p = hit_sphere(ray(x, y))?;
    let n = p.normalize();
    let dpdx = hit_plane(ray(x + 1.0, y), p, n) - p;
    let dpdy = hit_plane(ray(x, y + 1.0), p, n) - p;
    Some(SurfacePoint::with_derivatives(p, n, dpdx, dpdy))
}

fn main() {
    let mapping =
        Spherical::new(1.0, SphereProjection::Equirectangular).expect("radius 1 is valid");
    println!(
        "mip level of a {TEXTURE} texture over a ray-traced sphere ('.' = background, '+' = above 9):"
    );
    let mut levels = Vec::new();
    for y in 0..HEIGHT {
        let mut row = String::new();
        for x in 0..WIDTH {
            let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
            let Some(sample) = surface_point(px, py).and_then(|point| mapping.map(&point)) else {
                row.push('.');
                continue;
            };
            // The footprint in texels: the longer of the two pixel steps, as GPUs pick a level.
            let footprint = (sample.duvdx * TEXTURE)
                .length()
                .max((sample.duvdy * TEXTURE).length());
            let level = footprint.max(1.0).log2();
            levels.push(level);
            row.push(if level > 9.5 {
                '+'
            } else {
                char::from(b'0' + level.round() as u8)
            });
        }
        println!("{row}");
    }
    let (min, max) = levels
        .iter()
        .fold((f32::MAX, f32::MIN), |(lo, hi), &l| (lo.min(l), hi.max(l)));
    println!("levels from {min:.2} (facing the eye) to {max:.2} (grazing, near the silhouette)");

    // The derivatives are what finite differences of uv between neighbouring pixels give.
    let (x, y) = (30.5, 9.5);
    let point = surface_point(x, y).expect("on the sphere");
    let sample = mapping.map(&point).expect("off the pole axis");
    let right = mapping
        .map(&surface_point(x + 1.0, y).expect("on the sphere"))
        .expect("mapped");
    println!(
        "at pixel ({x}, {y}): uv {:.4}, du/dx {:.5}, next pixel's uv minus this one {:.5}",
        sample.uv,
        sample.duvdx,
        right.uv - sample.uv
    );
}
