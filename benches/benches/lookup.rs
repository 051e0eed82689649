//! Criterion benchmarks of single texture lookups through `TextureSampler`, each beside a
//! **same-result minimal kernel**: a hand-written function, kept here, that computes the same
//! value for this one configuration (RGBA8 sRGB, repeat addressing, a power-of-two texture) with
//! nothing general about it — no descriptor, no address-mode dispatch, no level math where there is
//! one level. The kernels are the bar the sampler's general path has to meet (issue 19).
//!
//! The workload is a coherent scan: 256 × 256 lookups stepping across a 512² texture the way a
//! rasterizer's pixels do, with constant derivatives:
//! - `nearest` and `bilinear`: one level, the footprint a little below one texel (magnification);
//! - `trilinear`: the full linear-light mip chain, a footprint of 1.6 texels (λ ≈ 0.68, levels 0
//!   and 1 blended).
//!
//! - `trilinear_varying`: the same scan with derivatives that grow down the screen (×1 to ×1.5,
//!   as under perspective; λ ≈ 0.68 … 1.26): the level of detail changes from lookup to lookup,
//!   as in a rasterizer, and about half of the lookups blend levels 1 and 2.
//!
//! Before the groups run, the largest difference between each kernel and the sampler over the
//! scan is printed and must be within 2⁻²² (1 ulp at 0.5, relative to the [0, 1] range): both
//! compute the same formulas; the kernel's level of detail is computed in f32 rather than f64.
//! The two trilinear groups also time `sample_pair` over the same scan, two lookups at a time
//! and interleaved (the renderer's unlit fragment loop), checked first to give `sample`'s
//! results bit for bit.
//! Run with `cargo bench -p barytex-benches --bench lookup`.

use std::hint::black_box;
use std::time::Duration;

use barytex_texture::{
    MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texture2d, TextureSampler, srgb,
};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{Vec2, Vec4};

const SIDE: u32 = 512;
const SCAN: u32 = 256;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

/// A 512² sRGB texture with varied colours and alpha (so premultiplying matters).
fn texture() -> Texture2d<Srgba8> {
    Texture2d::from_fn(SIDE, SIDE, |x, y| {
        let h = x.wrapping_mul(2_654_435_761) ^ y.wrapping_mul(40_503);
        Srgba8([
            (x * 255 / SIDE) as u8,
            (h >> 8) as u8,
            ((x ^ y) & 0xff) as u8,
            128 + ((h >> 16) & 0x7f) as u8,
        ])
    })
    .expect("512²")
}

/// The scan: uv per lookup and the constant derivatives, `texels` texels per step.
fn scan(texels: f32) -> (Vec<Vec2>, Vec2, Vec2) {
    let step = texels / SIDE as f32;
    // A slight rotation so rows do not stay on one texel row.
    let (s, c) = 0.1_f32.sin_cos();
    let ddx = Vec2::new(c, s) * step;
    let ddy = Vec2::new(-s, c) * step;
    let origin = Vec2::new(0.123, 0.456);
    let uv = (0..SCAN * SCAN)
        .map(|i| {
            let (x, y) = ((i % SCAN) as f32, (i / SCAN) as f32);
            origin + ddx * x + ddy * y
        })
        .collect();
    (uv, ddx, ddy)
}

/// Straight → premultiplied, decoding an sRGB texel (the sampler's per-tap work).
#[inline]
fn tap(texels: &[Srgba8], side: u32, x: i64, y: i64) -> Vec4 {
    let mask = i64::from(side) - 1;
    let t = texels[((y & mask) * i64::from(side) + (x & mask)) as usize].0;
    let table = srgb::decode_table();
    let a = f32::from(t[3]) / 255.0;
    Vec4::new(
        table[usize::from(t[0])] * a,
        table[usize::from(t[1])] * a,
        table[usize::from(t[2])] * a,
        a,
    )
}

#[inline]
fn unpremultiply(c: Vec4) -> Vec4 {
    if c.w > 0.0 {
        (c.truncate() / c.w).extend(c.w)
    } else {
        Vec4::ZERO
    }
}

/// `⌊x⌋` by truncation (no library call on targets without SSE4.1); exact for |x| < 2⁶³, which
/// the scan's coordinates are.
#[inline]
fn floor(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t > x { t - 1.0 } else { t }
}

#[inline]
fn nearest_kernel(level: &Texture2d<Srgba8>, uv: Vec2) -> Vec4 {
    let n = f64::from(level.size().0);
    let x = floor(f64::from(uv.x) * n) as i64;
    let y = floor(f64::from(uv.y) * n) as i64;
    unpremultiply(tap(level.texels(), level.size().0, x, y))
}

#[inline]
fn bilinear_premultiplied(level: &Texture2d<Srgba8>, uv: Vec2) -> Vec4 {
    let side = level.size().0;
    let n = f64::from(side);
    let (x, y) = (f64::from(uv.x) * n - 0.5, f64::from(uv.y) * n - 0.5);
    let (fx, fy) = (floor(x), floor(y));
    let (ax, ay) = ((x - fx) as f32, (y - fy) as f32);
    let (x0, y0) = (fx as i64, fy as i64);
    let texels = level.texels();
    let c00 = tap(texels, side, x0, y0);
    let c10 = tap(texels, side, x0 + 1, y0);
    let c01 = tap(texels, side, x0, y0 + 1);
    let c11 = tap(texels, side, x0 + 1, y0 + 1);
    let top = c00 + (c10 - c00) * ax;
    let bottom = c01 + (c11 - c01) * ax;
    top + (bottom - top) * ay
}

#[inline]
fn bilinear_kernel(level: &Texture2d<Srgba8>, uv: Vec2) -> Vec4 {
    unpremultiply(bilinear_premultiplied(level, uv))
}

#[inline]
fn trilinear_kernel(chain: &MipChain<Srgba8>, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
    let n = SIDE as f32;
    let rho2 = (ddx * n).length_squared().max((ddy * n).length_squared());
    let lod = 0.5 * rho2.log2();
    if lod <= 0.0 {
        return bilinear_kernel(chain.base(), uv);
    }
    let floor = lod.floor();
    let lo = floor as usize;
    let a = bilinear_premultiplied(&chain.levels()[lo], uv);
    let b = bilinear_premultiplied(&chain.levels()[lo + 1], uv);
    unpremultiply(a + (b - a) * (lod - floor))
}

/// `scan(texels)` with the derivatives of row `y` scaled by `1 + y / (2·SCAN)`.
fn varying_scan(texels: f32) -> Vec<(Vec2, Vec2, Vec2)> {
    let (uv, ddx, ddy) = scan(texels);
    uv.into_iter()
        .enumerate()
        .map(|(i, uv)| {
            let s = 1.0 + (i as u32 / SCAN) as f32 / (2 * SCAN) as f32;
            (uv, ddx * s, ddy * s)
        })
        .collect()
}

fn max_difference(a: &[Vec4], b: &[Vec4]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(a, b)| (*a - *b).abs().max_element())
        .fold(0.0, f32::max)
}

fn bench(c: &mut Criterion) {
    let base = texture();
    let chain = MipChain::generate(base.clone(), &MipOptions::default()).expect("chain");
    let repeat = barytex_texture::sampler::AddressMode::Repeat;
    let nearest = TextureSampler::single_level(
        base.clone(),
        SamplerDescriptor::default().with_address_mode(repeat),
    );
    let bilinear = TextureSampler::single_level(
        base.clone(),
        SamplerDescriptor::bilinear().with_address_mode(repeat),
    );
    let trilinear = TextureSampler::new(
        chain.clone(),
        SamplerDescriptor::trilinear().with_address_mode(repeat),
    );
    let (mag_uv, mag_dx, mag_dy) = scan(0.9);
    let (min_uv, min_dx, min_dy) = scan(1.6);
    compare(
        c,
        "nearest",
        &mag_uv,
        |uv| nearest.sample(uv, mag_dx, mag_dy),
        |uv| nearest_kernel(&base, uv),
        None,
    );
    compare(
        c,
        "bilinear",
        &mag_uv,
        |uv| bilinear.sample(uv, mag_dx, mag_dy),
        |uv| bilinear_kernel(&base, uv),
        None,
    );
    let constant: Vec<[Vec2; 3]> = min_uv.iter().map(|&uv| [uv, min_dx, min_dy]).collect();
    compare(
        c,
        "trilinear",
        &min_uv,
        |uv| trilinear.sample(uv, min_dx, min_dy),
        |uv| trilinear_kernel(&chain, uv, min_dx, min_dy),
        Some((&trilinear, &constant)),
    );
    let varying = varying_scan(1.6);
    let lookups: Vec<[Vec2; 3]> = varying.iter().map(|&(uv, x, y)| [uv, x, y]).collect();
    compare(
        c,
        "trilinear_varying",
        &varying,
        |(uv, ddx, ddy)| trilinear.sample(uv, ddx, ddy),
        |(uv, ddx, ddy)| trilinear_kernel(&chain, uv, ddx, ddy),
        Some((&trilinear, &lookups)),
    );
}

/// The scan's lookups through `sample_pair`, two at a time.
fn fill_pairs(out: &mut [Vec4], lookups: &[[Vec2; 3]], sampler: &TextureSampler<Srgba8>) {
    for (o, l) in out.chunks_exact_mut(2).zip(lookups.chunks_exact(2)) {
        let [a, b] = sampler.sample_pair(l[0], l[1]);
        o[0] = a;
        o[1] = b;
    }
}

#[inline]
fn fill<P: Copy>(out: &mut [Vec4], uvs: &[P], lookup: impl Fn(P) -> Vec4) {
    for (o, uv) in out.iter_mut().zip(uvs) {
        *o = lookup(*uv);
    }
}

/// Checks that the kernel gives the sampler's results, then times both in one group. A lookup's
/// input `P` is its coordinate, or its coordinate and derivatives. With `many` (the sampler and
/// the same lookups as `[uv, ddx, ddy]`), the group also times `sample_pair` over the scan two
/// at a time, after checking that it gives `sample`'s results bit for bit.
fn compare<P: Copy>(
    c: &mut Criterion,
    name: &str,
    uvs: &[P],
    sampler: impl Fn(P) -> Vec4,
    kernel: impl Fn(P) -> Vec4,
    many: Option<(&TextureSampler<Srgba8>, &[[Vec2; 3]])>,
) {
    let mut out = vec![Vec4::ZERO; uvs.len()];
    let mut reference = out.clone();
    fill(&mut out, uvs, &sampler);
    fill(&mut reference, uvs, &kernel);
    let d = max_difference(&out, &reference);
    assert!(d <= 2f32.powi(-22), "{name}: kernel differs by {d:e}");
    println!("{name}: max |sampler − minimal kernel| over the scan {d:.2e}");
    if let Some((s, lookups)) = many {
        let mut other = vec![Vec4::ZERO; uvs.len()];
        fill_pairs(&mut other, lookups, s);
        let bits = |c: &Vec4| c.to_array().map(f32::to_bits);
        assert!(
            other.iter().zip(&out).all(|(a, b)| bits(a) == bits(b)),
            "{name}: sample_pair differs from sample"
        );
    }

    let mut group = c.benchmark_group(format!("lookup_srgba8_repeat_{name}"));
    group.throughput(Throughput::Elements(uvs.len() as u64));
    group.bench_function("barytex_texture_sampler", |b| {
        b.iter(|| fill(&mut out, black_box(uvs), &sampler));
    });
    group.bench_function("minimal_kernel", |b| {
        b.iter(|| fill(&mut out, black_box(uvs), &kernel));
    });
    if let Some((s, lookups)) = many {
        group.bench_function("barytex_sample_pair", |b| {
            b.iter(|| fill_pairs(&mut out, black_box(lookups), s));
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
