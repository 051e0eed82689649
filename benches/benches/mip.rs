//! Criterion benchmarks of mip-chain generation on a 4096² RGBA8 sRGB image, single-threaded,
//! peers in the same run:
//!
//! - barytex, linear light (decode sRGB, premultiply, box, un-premultiply, correctly rounded
//!   encode) — the correct chain;
//! - barytex, sRGB-naive (box on the stored bytes, straight alpha);
//! - fast_image_resize, `ResizeAlg::Convolution(FilterType::Box)` level by level (premultiplies
//!   alpha, filters the sRGB bytes: not linear light);
//! - image, `imageops::resize` with `FilterType::Triangle` level by level.
//!
//! Every side reads the 64 MB base in place: barytex's chain takes ownership of a base cloned
//! outside the timed region (`iter_batched`), the peers borrow the bytes.
//!
//! Before the groups run, each chain's level-1 error against an f64 linear-light box reference
//! is printed (max over channels, in 8-bit steps), so time can be read against accuracy.
//!
//! Run with `cargo bench -p barytex-benches --bench mip`.

use std::hint::black_box;
use std::time::Duration;

use barytex_texture::{MipChain, MipColorSpace, MipOptions, Srgba8, Texture2d, srgb};
use criterion::{Criterion, criterion_group, criterion_main};
use fast_image_resize::images::{Image, ImageRef};
use fast_image_resize::{FilterType, PixelType, ResizeAlg, ResizeOptions, Resizer};

const SIDE: u32 = 4096;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

/// A deterministic test image: smooth gradients, a fine checker and a soft alpha ramp.
fn image_bytes() -> Vec<u8> {
    let mut bytes = Vec::with_capacity((SIDE * SIDE * 4) as usize);
    for y in 0..SIDE {
        for x in 0..SIDE {
            let checker = if (x / 3 + y / 5) % 2 == 0 { 60 } else { 0 };
            bytes.extend_from_slice(&[
                ((x * 255 / SIDE) as u8).saturating_add(checker),
                (y * 255 / SIDE) as u8,
                ((x ^ y) & 0xff) as u8,
                (255 - (x + y) * 128 / SIDE) as u8,
            ]);
        }
    }
    bytes
}

fn texture(bytes: &[u8]) -> Texture2d<Srgba8> {
    let texels = bytes
        .chunks_exact(4)
        .map(|c| Srgba8([c[0], c[1], c[2], c[3]]))
        .collect();
    Texture2d::from_texels(SIDE, SIDE, texels).expect("4096²")
}

fn barytex_chain(base: Texture2d<Srgba8>, color_space: MipColorSpace) -> MipChain<Srgba8> {
    MipChain::generate(
        base,
        &MipOptions {
            color_space,
            ..MipOptions::default()
        },
    )
    .expect("chain")
}

/// fast_image_resize's box chain: each level resized from the previous one, the base read in
/// place (no copy of the 64 MB source inside the timed loop). The result holds levels 1.. (the
/// base is the caller's, as barytex's chain holds the base it was given).
fn fir_chain(bytes: &[u8]) -> Vec<Image<'static>> {
    let mut resizer = Resizer::new();
    let options = ResizeOptions::new().resize_alg(ResizeAlg::Convolution(FilterType::Box));
    let base = ImageRef::new(SIDE, SIDE, bytes, PixelType::U8x4).expect("base");
    let mut side = SIDE / 2;
    let mut first = Image::new(side, side, PixelType::U8x4);
    resizer.resize(&base, &mut first, &options).expect("resize");
    let mut levels = vec![first];
    while side > 1 {
        side /= 2;
        let mut next = Image::new(side, side, PixelType::U8x4);
        let previous = levels.last().expect("at least level 1");
        resizer
            .resize(previous, &mut next, &options)
            .expect("resize");
        levels.push(next);
    }
    levels
}

/// image's Triangle chain, the base read in place; levels 1.. as for fir.
fn image_chain(bytes: &[u8]) -> Vec<image::RgbaImage> {
    let base =
        image::ImageBuffer::<image::Rgba<u8>, &[u8]>::from_raw(SIDE, SIDE, bytes).expect("base");
    let mut side = SIDE / 2;
    let first = image::imageops::resize(&base, side, side, image::imageops::FilterType::Triangle);
    let mut levels = vec![first];
    while side > 1 {
        side /= 2;
        let previous = levels.last().expect("at least level 1");
        let next =
            image::imageops::resize(previous, side, side, image::imageops::FilterType::Triangle);
        levels.push(next);
    }
    levels
}

/// Level-1 error of an RGBA8 result against the f64 linear-light premultiplied box reference,
/// in 8-bit steps of the encoded value (max over texels and channels).
fn level1_error(bytes: &[u8], level1: &[u8]) -> f64 {
    let half = (SIDE / 2) as usize;
    let side = SIDE as usize;
    let mut worst: f64 = 0.0;
    for y in 0..half {
        for x in 0..half {
            let mut sum = [0.0_f64; 4];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let i = ((2 * y + dy) * side + 2 * x + dx) * 4;
                let a = f64::from(bytes[i + 3]) / 255.0;
                for c in 0..3 {
                    sum[c] += f64::from(srgb::decode(bytes[i + c])) * a;
                }
                sum[3] += a;
            }
            let alpha = sum[3] / 4.0;
            let j = (y * half + x) * 4;
            for c in 0..3 {
                if alpha > 0.0 {
                    let linear = sum[c] / 4.0 / alpha;
                    let want = f64::from(srgb::from_linear(linear as f32)) * 255.0;
                    worst = worst.max((f64::from(level1[j + c]) - want).abs());
                }
            }
            worst = worst.max((f64::from(level1[j + 3]) - alpha * 255.0).abs());
        }
    }
    worst
}

fn bench(c: &mut Criterion) {
    let bytes = image_bytes();
    let base = texture(&bytes);
    let flat = |chain: &MipChain<Srgba8>| -> Vec<u8> {
        chain.levels()[1]
            .texels()
            .iter()
            .flat_map(|t| t.0)
            .collect()
    };
    println!(
        "level-1 max error vs f64 linear-light box, in 8-bit steps: barytex linear {:.2}, \
         barytex sRGB-naive {:.2}, fast_image_resize Box {:.2}, image Triangle {:.2}",
        level1_error(
            &bytes,
            &flat(&barytex_chain(base.clone(), MipColorSpace::LinearLight))
        ),
        level1_error(
            &bytes,
            &flat(&barytex_chain(base.clone(), MipColorSpace::SrgbNaive))
        ),
        level1_error(&bytes, fir_chain(&bytes)[0].buffer()),
        level1_error(&bytes, image_chain(&bytes)[0].as_raw()),
    );
    let mut group = c.benchmark_group("mip_chain_4096_rgba8");
    group.bench_function("barytex_linear_light", |b| {
        b.iter_batched(
            || base.clone(),
            |t| black_box(barytex_chain(t, MipColorSpace::LinearLight)),
            criterion::BatchSize::LargeInput,
        );
    });
    group.bench_function("barytex_srgb_naive", |b| {
        b.iter_batched(
            || base.clone(),
            |t| black_box(barytex_chain(t, MipColorSpace::SrgbNaive)),
            criterion::BatchSize::LargeInput,
        );
    });
    group.bench_function("fast_image_resize_box", |b| {
        b.iter(|| black_box(fir_chain(&bytes)));
    });
    group.bench_function("image_triangle", |b| {
        b.iter(|| black_box(image_chain(&bytes)));
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
