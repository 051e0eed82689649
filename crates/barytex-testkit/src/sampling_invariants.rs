//! dEQP-style verification of texture lookups: instead of one expected value, the **set** of
//! values a conforming sampler may return when coordinates, weights and the level of detail are
//! perturbed within the Vulkan minimum precisions (8 sub-texel bits, 8 weight bits, 8 LOD
//! fraction bits), as a per-channel box. A result outside the box is wrong.
//!
//! The verifier re-implements Vulkan's addressing and filtering from the specification, in f64,
//! independently of barytex-texture's code. It covers nearest and linear filters within a level,
//! nearest and linear mip selection, and every address mode; textures are assumed opaque (alpha 1),
//! so premultiplication does not enter.

use barytex_texture::sampler::{
    AddressMode, BorderColor, FilterMode, MipmapFilterMode, SamplerDescriptor,
};
use barytex_texture::{MipChain, Texel, Texture2d};
use glam::{DVec4, Vec2, Vec4};

/// Sub-texel coordinate precision in texels (2⁻⁸).
pub const COORDINATE_PRECISION: f64 = 1.0 / 256.0;
/// Filter-weight precision (2⁻⁸).
pub const WEIGHT_PRECISION: f64 = 1.0 / 256.0;
/// Level-of-detail precision (2⁻⁸).
pub const LOD_PRECISION: f64 = 1.0 / 256.0;

/// A per-channel interval of allowed results.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValueBox {
    /// Lower bounds.
    pub lo: DVec4,
    /// Upper bounds.
    pub hi: DVec4,
}

impl ValueBox {
    const EMPTY: Self = Self {
        lo: DVec4::splat(f64::INFINITY),
        hi: DVec4::splat(f64::NEG_INFINITY),
    };

    fn include(&mut self, v: DVec4) {
        self.lo = self.lo.min(v);
        self.hi = self.hi.max(v);
    }

    fn union(self, other: Self) -> Self {
        Self {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// Whether `v` lies in the box widened by `slack` (absolute, per channel).
    #[must_use]
    pub fn contains(&self, v: Vec4, slack: f64) -> bool {
        let v = v.as_dvec4();
        (0..4).all(|i| v[i] >= self.lo[i] - slack && v[i] <= self.hi[i] + slack)
    }
}

fn wrap(i: i64, size: u32, mode: AddressMode) -> Option<u32> {
    let n = i64::from(size);
    let j = match mode {
        AddressMode::ClampToEdge => i.max(0).min(n - 1),
        AddressMode::Repeat => ((i % n) + n) % n,
        AddressMode::MirrorRepeat => {
            // Reflect about −½ and n − ½ (Vulkan's mirror with period 2n).
            let p = ((i % (2 * n)) + 2 * n) % (2 * n);
            if p < n { p } else { 2 * n - 1 - p }
        }
        AddressMode::ClampToBorder => {
            if i < 0 || i >= n {
                return None;
            }
            i
        }
    };
    u32::try_from(j).ok()
}

fn border(desc: &SamplerDescriptor) -> DVec4 {
    match desc.border_color.unwrap_or(BorderColor::TransparentBlack) {
        BorderColor::TransparentBlack | BorderColor::Zero => DVec4::ZERO,
        BorderColor::OpaqueBlack => DVec4::new(0.0, 0.0, 0.0, 1.0),
        BorderColor::OpaqueWhite => DVec4::ONE,
    }
}

fn texel<T: Texel>(level: &Texture2d<T>, x: i64, y: i64, desc: &SamplerDescriptor) -> DVec4 {
    let (w, h) = level.size();
    match (
        wrap(x, w, desc.address_mode_u),
        wrap(y, h, desc.address_mode_v),
    ) {
        (Some(x), Some(y)) => level
            .linear(x, y)
            .map_or(DVec4::ZERO, |c: Vec4| c.as_dvec4()),
        _ => border(desc),
    }
}

/// The allowed box for one level and one in-level filter.
fn level_box<T: Texel>(
    level: &Texture2d<T>,
    uv: Vec2,
    filter: FilterMode,
    desc: &SamplerDescriptor,
) -> ValueBox {
    let (w, h) = level.size();
    let (x, y) = (
        f64::from(uv.x) * f64::from(w),
        f64::from(uv.y) * f64::from(h),
    );
    let d = COORDINATE_PRECISION;
    let mut out = ValueBox::EMPTY;
    match filter {
        FilterMode::Nearest => {
            for i in candidates(x - d, x + d) {
                for j in candidates(y - d, y + d) {
                    out.include(texel(level, i, j, desc));
                }
            }
        }
        FilterMode::Linear | FilterMode::Cubic(_) => {
            let (x, y) = (x - 0.5, y - 0.5);
            for i in candidates(x - d, x + d) {
                for j in candidates(y - d, y + d) {
                    let c00 = texel(level, i, j, desc);
                    let c10 = texel(level, i + 1, j, desc);
                    let c01 = texel(level, i, j + 1, desc);
                    let c11 = texel(level, i + 1, j + 1, desc);
                    let (a0, a1) = weight_range(x - i as f64, d);
                    let (b0, b1) = weight_range(y - j as f64, d);
                    // A bilinear function's extremes over a rectangle are at its corners.
                    for a in [a0, a1] {
                        for b in [b0, b1] {
                            let top = c00 * (1.0 - a) + c10 * a;
                            let bottom = c01 * (1.0 - a) + c11 * a;
                            out.include(top * (1.0 - b) + bottom * b);
                        }
                    }
                }
            }
        }
    }
    out
}

/// Integer cells that `[lo, hi]` touches.
fn candidates(lo: f64, hi: f64) -> impl Iterator<Item = i64> {
    (lo.floor() as i64)..=(hi.floor() as i64)
}

/// The weight interval of the upper tap for a fractional position `f` (which may lie slightly
/// outside [0, 1) for a neighbouring candidate cell), widened by the precisions.
fn weight_range(f: f64, coordinate: f64) -> (f64, f64) {
    let lo = (f - coordinate - WEIGHT_PRECISION).clamp(0.0, 1.0);
    let hi = (f + coordinate + WEIGHT_PRECISION).clamp(0.0, 1.0);
    (lo, hi)
}

/// The allowed result box of `sample_level(uv, lod)` on `chain` with `desc` (anisotropy off),
/// `lod` already biased and clamped.
#[must_use]
pub fn allowed_sample_level<T: Texel>(
    chain: &MipChain<T>,
    desc: &SamplerDescriptor,
    uv: Vec2,
    lod: f32,
) -> ValueBox {
    let lod = f64::from(lod);
    let (lo, hi) = (lod - LOD_PRECISION, lod + LOD_PRECISION);
    let last = chain.len() - 1;
    let mut out = ValueBox::EMPTY;
    if lo <= 0.0 {
        out = out.union(level_box(chain.base(), uv, desc.mag_filter, desc));
    }
    if hi > 0.0 {
        let lo = lo.max(0.0);
        match desc.mipmap_filter {
            MipmapFilterMode::Nearest => {
                let first = ((lo + 0.5).ceil() - 1.0).max(0.0) as usize;
                let end = ((hi + 0.5).ceil() - 1.0).max(0.0) as usize;
                for level in first.min(last)..=end.min(last) {
                    out = out.union(level_box(&chain.levels()[level], uv, desc.min_filter, desc));
                }
            }
            MipmapFilterMode::Linear => {
                // Levels at or beyond the last one all read the last (and the saturating cast
                // keeps a huge LOD from overflowing `base + 1`).
                let first = (lo.floor() as usize).min(last);
                let end = (hi.floor() as usize).min(last);
                for base in first..=end {
                    let (l0, l1) = (base, (base + 1).min(last));
                    let b0 = level_box(&chain.levels()[l0], uv, desc.min_filter, desc);
                    let b1 = level_box(&chain.levels()[l1], uv, desc.min_filter, desc);
                    let (t0, t1) = weight_range(lod.clamp(lo, hi) - base as f64, LOD_PRECISION);
                    for t in [t0, t1] {
                        out.include(b0.lo * (1.0 - t) + b1.lo * t);
                        out.include(b0.hi * (1.0 - t) + b1.hi * t);
                    }
                }
            }
        }
    }
    out
}

/// Checks a `sample_level` result against [`allowed_sample_level`], with `slack` for the
/// implementation's f32 rounding (a few ulp of the largest texel value).
///
/// # Errors
/// A description naming the lookup when the result is outside the allowed box.
pub fn check_sample_level<T: Texel>(
    chain: &MipChain<T>,
    desc: &SamplerDescriptor,
    uv: Vec2,
    lod: f32,
    result: Vec4,
    slack: f64,
) -> Result<(), String> {
    let allowed = allowed_sample_level(chain, desc, uv, lod);
    if allowed.contains(result, slack) {
        Ok(())
    } else {
        Err(format!(
            "sample_level(uv = {uv:?}, lod = {lod}) = {result:?} outside the allowed box \
             {:?} … {:?} ({desc:?})",
            allowed.lo, allowed.hi
        ))
    }
}
