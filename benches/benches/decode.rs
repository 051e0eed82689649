//! Criterion benchmark of texture loading: a 2048² RGB PNG (the layout of most glTF colour
//! textures) decoded into 4-byte RGBA texels, beside the `image` crate giving the same texels
//! (`load_from_memory` + `into_rgba8`, the usual way to get RGBA8 from it), in the same run.
//! Both read the same encoded bytes from memory; the outputs are checked equal before timing.
//!
//! Run with `cargo bench -p barytex-benches --bench decode`.

use std::hint::black_box;
use std::time::Duration;

use barytex_texture::Limits;
use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_memory};
use criterion::{Criterion, criterion_group, criterion_main};
use image::{DynamicImage, ImageFormat, RgbImage};

const SIDE: u32 = 2048;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

/// A deterministic RGB texture that compresses like a photographed one: smooth gradients with
/// a little noise in the low bits (so PNG's filters and deflate both have work).
fn encoded_png() -> Vec<u8> {
    let mut state = 0x1234_5678_u32;
    let image = RgbImage::from_fn(SIDE, SIDE, |x, y| {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        let n = (state >> 28) as u8;
        image::Rgb([
            ((x * 255 / SIDE) as u8).wrapping_add(n),
            ((y * 255 / SIDE) as u8).wrapping_add(n >> 1),
            (((x + y) * 127 / SIDE) as u8).wrapping_add(n >> 2),
        ])
    });
    let mut bytes = std::io::Cursor::new(Vec::new());
    DynamicImage::ImageRgb8(image)
        .write_to(&mut bytes, ImageFormat::Png)
        .expect("encodes");
    bytes.into_inner()
}

fn barytex_rgba(bytes: &[u8]) -> AnyTexture2d {
    load_from_memory(bytes, ColorSpace::Srgb, &Limits::default()).expect("decodes")
}

fn image_rgba(bytes: &[u8]) -> image::RgbaImage {
    image::load_from_memory(bytes)
        .expect("decodes")
        .into_rgba8()
}

fn bench(c: &mut Criterion) {
    let bytes = encoded_png();
    let AnyTexture2d::Srgba8(ours) = barytex_rgba(&bytes) else {
        panic!("an RGB PNG loads as Srgba8");
    };
    let ours: Vec<u8> = ours.texels().iter().flat_map(|t| t.0).collect();
    assert_eq!(ours, image_rgba(&bytes).into_raw(), "the same texels");
    println!(
        "decode: {SIDE}² RGB PNG, {:.1} MB encoded",
        bytes.len() as f64 / 1e6
    );
    let mut group = c.benchmark_group("decode_png_rgb_2048");
    group.bench_function("barytex_load_from_memory", |b| {
        b.iter(|| black_box(barytex_rgba(black_box(&bytes))));
    });
    group.bench_function("image_load_into_rgba8", |b| {
        b.iter(|| black_box(image_rgba(black_box(&bytes))));
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
