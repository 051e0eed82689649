//! Criterion benchmarks of a bilinear remap: a 2048² RGBA8 image through a smooth warp to a 2048²
//! output, single-threaded — the peer to beat is OpenCV's `remap` INTER_LINEAR (≈ 3.6 ns per output
//! pixel on this kind of machine when the project set its speed targets; `tools/opencv_remap.py`
//! measures it on the same warp beside this bench). In the same run:
//!
//! - barytex `remap_bilinear_rgba8` (exact texel addressing, f32 weights, one rounding);
//! - barytex `TextureSampler::sample_level` with a bilinear descriptor (the general path:
//!   premultiplied filtering, every address mode), then encoded to RGBA8;
//! - image `imageops::sample_bilinear` (the peer in Rust).
//!
//! Before the groups run, each method's max error against an exact f64 bilinear is printed in
//! 8-bit steps. Run with `cargo bench -p barytex-benches --bench remap`.

use std::hint::black_box;
use std::time::Duration;

use barytex_texture::remap::remap_bilinear_rgba8;
use barytex_texture::{Rgba8, Sampler, SamplerDescriptor, Texel, Texture2d, TextureSampler};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec2;

const SIDE: u32 = 2048;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

fn source() -> Texture2d<Rgba8> {
    Texture2d::from_fn(SIDE, SIDE, |x, y| {
        Rgba8([
            (x * 255 / SIDE) as u8,
            (y * 255 / SIDE) as u8,
            ((x ^ y) & 0xff) as u8,
            255,
        ])
    })
    .expect("2048²")
}

/// The smooth warp of `tools/opencv_remap.py`: pixel centres displaced by up to 20 pixels
/// sinusoidally, in texture coordinates.
fn warp() -> Vec<Vec2> {
    let n = SIDE as f32;
    let mut coords = Vec::with_capacity((SIDE * SIDE) as usize);
    for y in 0..SIDE {
        for x in 0..SIDE {
            let (xf, yf) = (x as f32, y as f32);
            let dx = 20.0 * (core::f32::consts::TAU * 3.0 * yf / n).sin();
            let dy = 20.0 * (core::f32::consts::TAU * 2.0 * xf / n).cos();
            coords.push(Vec2::new((xf + 0.5 + dx) / n, (yf + 0.5 + dy) / n));
        }
    }
    coords
}

fn exact(src: &Texture2d<Rgba8>, uv: Vec2) -> [f64; 4] {
    let n = i64::from(SIDE);
    let x = f64::from(uv.x) * f64::from(SIDE) - 0.5;
    let y = f64::from(uv.y) * f64::from(SIDE) - 0.5;
    let (fx, fy) = (x - x.floor(), y - y.floor());
    let (x0, y0) = (x.floor() as i64, y.floor() as i64);
    let at = |i: i64, j: i64| {
        let (i, j) = (i.clamp(0, n - 1) as u32, j.clamp(0, n - 1) as u32);
        src.texel(i, j).expect("clamped").0.map(f64::from)
    };
    let (a, b, c, d) = (
        at(x0, y0),
        at(x0 + 1, y0),
        at(x0, y0 + 1),
        at(x0 + 1, y0 + 1),
    );
    core::array::from_fn(|k| {
        (a[k] * (1.0 - fx) + b[k] * fx) * (1.0 - fy) + (c[k] * (1.0 - fx) + d[k] * fx) * fy
    })
}

fn max_error(src: &Texture2d<Rgba8>, coords: &[Vec2], out: &[[u8; 4]]) -> f64 {
    coords
        .iter()
        .zip(out)
        .step_by(7)
        .map(|(uv, o)| {
            let want = exact(src, *uv);
            (0..4)
                .map(|k| (f64::from(o[k]) - want[k]).abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

fn barytex_fast(src: &Texture2d<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    remap_bilinear_rgba8(src, coords, out).expect("same length");
}

fn barytex_sampler(sampler: &TextureSampler<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    for (uv, o) in coords.iter().zip(out.iter_mut()) {
        *o = Rgba8::from_linear(sampler.sample_level(*uv, 0.0));
    }
}

fn image_peer(img: &image::RgbaImage, coords: &[Vec2], out: &mut [Rgba8]) {
    for (uv, o) in coords.iter().zip(out.iter_mut()) {
        *o = Rgba8(
            image::imageops::sample_bilinear(img, uv.x.clamp(0.0, 1.0), uv.y.clamp(0.0, 1.0))
                .map_or([0; 4], |p| p.0),
        );
    }
}

fn bench(c: &mut Criterion) {
    let src = source();
    let coords = warp();
    let sampler = TextureSampler::single_level(src.clone(), SamplerDescriptor::bilinear());
    let img =
        image::RgbaImage::from_raw(SIDE, SIDE, src.texels().iter().flat_map(|t| t.0).collect())
            .expect("2048²");
    let mut out = vec![Rgba8::default(); coords.len()];
    let mut errors = Vec::new();
    for (name, run) in [
        (
            "barytex remap_bilinear_rgba8",
            &(|o: &mut [Rgba8]| barytex_fast(&src, &coords, o)) as &dyn Fn(&mut [Rgba8]),
        ),
        ("barytex TextureSampler", &|o: &mut [Rgba8]| {
            barytex_sampler(&sampler, &coords, o)
        }),
        ("image sample_bilinear", &|o: &mut [Rgba8]| {
            image_peer(&img, &coords, o)
        }),
    ] {
        run(&mut out);
        let bytes: Vec<[u8; 4]> = out.iter().map(|t| t.0).collect();
        errors.push(format!("{name} {:.3}", max_error(&src, &coords, &bytes)));
    }
    println!(
        "max error vs exact f64 bilinear, 8-bit steps: {}",
        errors.join(", ")
    );
    let mut group = c.benchmark_group("remap_2048_rgba8_bilinear");
    group.throughput(Throughput::Elements(coords.len() as u64));
    group.bench_function("barytex_remap_bilinear_rgba8", |b| {
        b.iter(|| barytex_fast(&src, black_box(&coords), &mut out));
    });
    group.bench_function("barytex_texture_sampler", |b| {
        b.iter(|| barytex_sampler(&sampler, black_box(&coords), &mut out));
    });
    group.bench_function("image_sample_bilinear", |b| {
        b.iter(|| image_peer(&img, black_box(&coords), &mut out));
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
