//! The texture-filter family: every filter of barytex-texture on the standard scenes (a
//! checkerboard plane at a grazing angle, fine text, rotated stripes), time per sample against
//! the error from a supersampled reference, and a picture strip of the grazing plane.
//!
//! The reference integrates the texture's own bilinear reconstruction over each pixel's
//! footprint parallelogram with 32 × 32 (quick: 8 × 8) stratified jittered samples
//! (`barytex_texture::reference::SupersampledReference`): it is what a perfect filter of this
//! texture would return, so the error isolates the filter.

use std::hint::black_box;
use std::time::Instant;

use barytex_texture::reference::{PixelFilter, SupersampledReference};
use barytex_texture::sampler::{AnisotropicFilter, CubicKernel, FilterMode, MipmapFilterMode};
use barytex_texture::{
    MipChain, MipColorSpace, MipOptions, Rgba8, Sampler, SamplerDescriptor, Srgba8, Texel,
    Texture2d, TextureSampler, load::encode_png, sampler::AddressMode,
};
use glam::{DVec2, Vec2, Vec4};

use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::median;

/// One pixel's lookup: texture coordinate and screen derivatives.
#[derive(Clone, Copy, Debug)]
struct Lookup {
    uv: Vec2,
    ddx: Vec2,
    ddy: Vec2,
}

/// A test scene: an image of `width × height` lookups into a texture.
struct Scene {
    name: &'static str,
    description: &'static str,
    texture: Texture2d<Srgba8>,
    width: u32,
    height: u32,
    lookups: Vec<Lookup>,
}

/// Lookups of a mapping from pixel centres to uv, with derivatives as differences of the exact
/// (f64) mapping one pixel right and down.
fn lookups(width: u32, height: u32, map: impl Fn(DVec2) -> DVec2) -> Vec<Lookup> {
    let mut out = Vec::with_capacity((width * height) as usize);
    for y in 0..height {
        for x in 0..width {
            let p = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let uv = map(p);
            out.push(Lookup {
                uv: uv.as_vec2(),
                ddx: (map(p + DVec2::X) - uv).as_vec2(),
                ddy: (map(p + DVec2::Y) - uv).as_vec2(),
            });
        }
    }
    out
}

fn checker_texture(side: u32, square: u32) -> Texture2d<Srgba8> {
    Texture2d::from_fn(side, side, |x, y| {
        if (x / square + y / square).is_multiple_of(2) {
            Srgba8([235, 235, 235, 255])
        } else {
            Srgba8([20, 20, 20, 255])
        }
    })
    .expect("small")
}

/// "Fine text": rows of glyph-like bars one or two texels thick, dark on light.
fn text_texture(side: u32) -> Texture2d<Srgba8> {
    Texture2d::from_fn(side, side, |x, y| {
        let (cx, cy) = (x % 8, y % 12);
        let glyph = (x / 8).wrapping_mul(2_654_435_761) ^ (y / 12).wrapping_mul(40_503);
        let ink = cy < 9
            && cx < 6
            && ((cx == 0 && glyph & 1 != 0)
                || (cx == 5 && glyph & 2 != 0)
                || (cy == 0 && glyph & 4 != 0)
                || (cy == 4 && glyph & 8 != 0)
                || (cy == 8 && glyph & 16 != 0)
                || (cx == 2 && glyph & 32 != 0));
        if ink {
            Srgba8([10, 10, 30, 255])
        } else {
            Srgba8([245, 240, 225, 255])
        }
    })
    .expect("small")
}

fn scenes(quick: bool) -> Vec<Scene> {
    let (w, h) = if quick { (96, 64) } else { (192, 128) };
    let (wf, hf) = (f64::from(w), f64::from(h));
    // Ground plane y = −1 seen from the origin looking down −z, vertical field of view 60°,
    // horizon at 1/8 of the height: every pixel below it hits the plane.
    let grazing = move |p: DVec2| {
        let focal = hf / 2.0 / (30.0_f64).to_radians().tan();
        let horizon = hf / 8.0;
        let dx = (p.x - wf / 2.0) / focal;
        let dy = (p.y - horizon) / focal;
        let t = 1.0 / dy; // ray (dx, −dy, −1) meets y = −1 at t = 1/dy
        DVec2::new(dx * t / 4.0 + 0.5, -t / 4.0)
    };
    let angle = 30.0_f64.to_radians();
    let rotated = move |p: DVec2| {
        let (s, c) = angle.sin_cos();
        DVec2::new(c * p.x - s * p.y, s * p.x + c * p.y) * (2.7 / 256.0)
    };
    let text = move |p: DVec2| p * (2.3 / 256.0);
    vec![
        Scene {
            name: "checkerboard plane at a grazing angle",
            description: "256² checker (8-texel squares, repeat) on a ground plane from 1/8 of \
                          the image height down: minification from 1× to far beyond 16×, \
                          strongly anisotropic",
            texture: checker_texture(256, 8),
            width: w,
            height: h,
            lookups: lookups(w, h, grazing),
        },
        Scene {
            name: "fine text",
            description: "256² page of one- and two-texel glyph strokes, minified 2.3× \
                          isotropically",
            texture: text_texture(256),
            width: w,
            height: h,
            lookups: lookups(w, h, text),
        },
        Scene {
            name: "rotated stripes",
            description: "256² checker of 2-texel squares (stripes in both directions) rotated \
                          30°, minified 2.7×",
            texture: checker_texture(256, 2),
            width: w,
            height: h,
            lookups: lookups(w, h, rotated),
        },
    ]
}

/// The filters compared, default first.
fn filters() -> Vec<(&'static str, bool, SamplerDescriptor)> {
    let base = SamplerDescriptor::default().with_address_mode(AddressMode::Repeat);
    let bilinear = SamplerDescriptor {
        mag_filter: FilterMode::Linear,
        min_filter: FilterMode::Linear,
        ..base
    };
    let trilinear = SamplerDescriptor {
        mipmap_filter: MipmapFilterMode::Linear,
        ..bilinear
    };
    let aniso = |n: u16| SamplerDescriptor {
        anisotropy_clamp: n,
        ..trilinear
    };
    vec![
        ("trilinear", true, trilinear),
        (
            "nearest, no mips",
            false,
            SamplerDescriptor {
                lod_max_clamp: 0.0,
                ..base
            },
        ),
        (
            "bilinear, no mips",
            false,
            SamplerDescriptor {
                lod_max_clamp: 0.0,
                ..bilinear
            },
        ),
        ("nearest-mip (nearest texel)", false, base),
        ("bilinear, nearest mip", false, bilinear),
        (
            "bicubic Catmull-Rom, trilinear",
            false,
            SamplerDescriptor {
                mag_filter: FilterMode::Cubic(CubicKernel::CatmullRom),
                min_filter: FilterMode::Cubic(CubicKernel::CatmullRom),
                ..trilinear
            },
        ),
        ("anisotropic ×2", false, aniso(2)),
        ("anisotropic ×4", false, aniso(4)),
        ("anisotropic ×8", false, aniso(8)),
        ("anisotropic ×16", false, aniso(16)),
        (
            "EWA (≤ 16:1)",
            false,
            SamplerDescriptor {
                anisotropic_filter: AnisotropicFilter::Ewa,
                ..aniso(16)
            },
        ),
    ]
}

/// Per-pixel errors (max over RGB, linear light) and the PSNR of an image against the reference.
fn errors(image: &[Vec4], reference: &[Vec4]) -> (Vec<f64>, f64) {
    let errs: Vec<f64> = image
        .iter()
        .zip(reference)
        .map(|(a, b)| f64::from((*a - *b).truncate().abs().max_element()))
        .collect();
    let mse = image
        .iter()
        .zip(reference)
        .map(|(a, b)| f64::from((*a - *b).truncate().length_squared()) / 3.0)
        .sum::<f64>()
        / image.len() as f64;
    (errs, 10.0 * (1.0 / mse).log10())
}

fn render(sampler: &TextureSampler<Srgba8>, lookups: &[Lookup]) -> Vec<Vec4> {
    lookups
        .iter()
        .map(|l| sampler.sample(l.uv, l.ddx, l.ddy))
        .collect()
}

/// Median ns per sample over `batches` renders of the whole image.
fn time_per_sample(sampler: &TextureSampler<Srgba8>, lookups: &[Lookup], batches: usize) -> f64 {
    let mut samples = Vec::with_capacity(batches);
    for batch in 0..=batches {
        let start = Instant::now();
        for l in black_box(lookups) {
            black_box(sampler.sample(l.uv, l.ddx, l.ddy));
        }
        if batch > 0 {
            samples.push(start.elapsed().as_secs_f64() * 1e9 / lookups.len() as f64);
        }
    }
    median(&mut samples)
}

/// The strip picture: the reference, then each filter, side by side (sRGB PNG).
fn strip(width: u32, height: u32, images: &[Vec<Vec4>]) -> Option<Vec<u8>> {
    let gap = 4;
    let total = images.len() as u32 * (width + gap) - gap;
    let picture = Texture2d::from_fn(total, height, |x, y| {
        let (i, xi) = ((x / (width + gap)) as usize, x % (width + gap));
        if xi >= width {
            return Rgba8([255, 255, 255, 255]);
        }
        let c = images[i][(y * width + xi) as usize];
        Rgba8(Srgba8::from_linear(c).0)
    })
    .ok()?;
    encode_png(&picture).ok()
}

/// What a scene's figures say, computed from its rows: the filter with the lowest median error
/// and how it compares with trilinear (time and error), and what the sRGB-naive chain costs in
/// error.
fn observations(scene: &str, rows: &[Row]) -> Vec<String> {
    let median = |r: &Row| r.abs.as_ref().map_or(f64::INFINITY, |e| e.median);
    let find = |name: &str| rows.iter().find(|r| r.method == name);
    let mut out = Vec::new();
    let Some(best) = rows
        .iter()
        .filter(|r| median(r).is_finite())
        .min_by(|a, b| median(a).total_cmp(&median(b)))
    else {
        return out;
    };
    if let Some(trilinear) = find("trilinear") {
        // The first row with the lowest median is trilinear itself when nothing beats it
        // (the other filters tie or do worse): say so rather than "1.0× below trilinear's".
        out.push(if median(best) < median(trilinear) {
            format!(
                "{scene}: the lowest median error is {} ({:.1e}), {:.1}× below trilinear's \
                 ({:.1e}), at {:.1}× its time per lookup.",
                best.method,
                median(best),
                median(trilinear) / median(best),
                median(trilinear),
                best.ns / trilinear.ns
            )
        } else {
            format!(
                "{scene}: no filter has a lower median error than trilinear ({:.1e}).",
                median(trilinear)
            )
        });
        if let Some(naive) = find("trilinear, sRGB-naive mip chain") {
            out.push(format!(
                "{scene}: averaging the mip levels as stored sRGB bytes raises trilinear's median \
                 error {:.1}× ({:.1e} → {:.1e}).",
                median(naive) / median(trilinear),
                median(trilinear),
                median(naive)
            ));
        }
    }
    out
}

/// Runs the family; also returns the picture strip `(file name, PNG bytes)` of the grazing plane.
pub(crate) fn run(
    settings: Settings,
    progress: &mut dyn FnMut(&str),
) -> (Section, Vec<(String, Vec<u8>)>) {
    let quick = settings.random < 1024;
    let n = if quick { 8 } else { 32 };
    let batches = if quick { 3 } else { 9 };
    let mut tables = Vec::new();
    let mut files = Vec::new();
    let mut notes = Vec::new();
    for (scene_index, scene) in scenes(quick).into_iter().enumerate() {
        progress(scene.name);
        let chain =
            MipChain::generate(scene.texture.clone(), &MipOptions::default()).expect("256² chain");
        let continuous = TextureSampler::single_level(
            scene.texture.clone(),
            SamplerDescriptor::bilinear().with_address_mode(AddressMode::Repeat),
        );
        let reference =
            SupersampledReference::new(|uv| continuous.sample_level(uv, 0.0), n, PixelFilter::Box)
                .expect("n ≤ 32");
        let truth: Vec<Vec4> = scene
            .lookups
            .iter()
            .map(|l| reference.sample(l.uv, l.ddx, l.ddy))
            .collect();
        let mut rows = Vec::new();
        let mut images = vec![truth.clone()];
        let mut psnrs = Vec::new();
        for (name, is_default, descriptor) in filters() {
            let sampler = TextureSampler::new(chain.clone(), descriptor);
            let image = render(&sampler, &scene.lookups);
            let (errs, psnr) = errors(&image, &truth);
            psnrs.push(format!("{name} {psnr:.1} dB"));
            rows.push(Row {
                method: name.to_owned(),
                is_default,
                ns: time_per_sample(&sampler, &scene.lookups, batches),
                abs: ErrorStats::of(errs),
                ..Row::default()
            });
            images.push(image);
        }
        // The same trilinear filter over an sRGB-naive chain (levels averaged as stored bytes):
        // the colour-space error the linear-light chain avoids.
        let naive_chain = MipChain::generate(
            scene.texture.clone(),
            &MipOptions {
                color_space: MipColorSpace::SrgbNaive,
                ..MipOptions::default()
            },
        )
        .expect("256² chain");
        let trilinear = filters()[0].2;
        let naive = TextureSampler::new(naive_chain, trilinear);
        let (errs, psnr) = errors(&render(&naive, &scene.lookups), &truth);
        psnrs.push(format!("trilinear over an sRGB-naive chain {psnr:.1} dB"));
        rows.push(Row {
            method: "trilinear, sRGB-naive mip chain".to_owned(),
            is_default: false,
            ns: time_per_sample(&naive, &scene.lookups, batches),
            abs: ErrorStats::of(errs),
            ..Row::default()
        });
        notes.extend(observations(scene.name, &rows));
        let mut extra = Vec::new();
        if scene_index == 0
            && let Some(png) = strip(scene.width, scene.height, &images)
        {
            files.push(("texture-filters-grazing.png".to_owned(), png));
            extra.push(format!(
                "![filters on the grazing plane](texture-filters-grazing.png)\n\n\
                 Picture strip of the grazing plane ({}×{} each), left to right: the \
                 {n}×{n}-sample reference, then {}.",
                scene.width,
                scene.height,
                filters()
                    .iter()
                    .map(|(name, _, _)| *name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
        tables.push(Table {
            title: scene.name.to_owned(),
            description: format!(
                "{}; {}×{} pixels, error = max over RGB of |filter − reference| in linear light \
                 per pixel. PSNR: {}.",
                scene.description,
                scene.width,
                scene.height,
                psnrs.join(", ")
            ),
            inputs: scene.lookups.len(),
            rows,
            time_unit: "lookup".to_owned(),
            error_label: "max |filter − reference| (linear light)".to_owned(),
            extra,
            ..Table::default()
        });
    }
    let section = Section {
        heading: "Texture filters".to_owned(),
        intro: format!(
            "Every filter of `barytex_texture::TextureSampler` on the same lookups (uv and exact \
             screen derivatives per pixel), RGBA8 sRGB textures with linear-light box mip chains. \
             The reference integrates the texture's bilinear reconstruction over each pixel's \
             footprint parallelogram with {n}×{n} stratified jittered samples. Time is the median \
             ns per lookup over {batches} renders of the whole image."
        ),
        tables,
        notes,
    };
    (section, files)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grazing scene's derivatives are what the f64 mapping gives, so LOD rises towards the
    /// horizon.
    #[test]
    fn grazing_scene_minifies_towards_the_horizon() {
        let scene = &scenes(true)[0];
        let near = scene.lookups[(scene.height as usize - 1) * scene.width as usize];
        let far = scene.lookups[(scene.height as usize / 8 + 1) * scene.width as usize];
        let size = |l: Lookup| l.ddx.length().max(l.ddy.length());
        assert!(size(far) > 10.0 * size(near), "{far:?} vs {near:?}");
    }
}
