//! Layered and volume textures: [`Texture2dArray`] (layers of equal size, a layer picked per
//! lookup) and [`Texture3d`] (a w × h × d grid of texels, trilinear interpolation of volumes).

use glam::{Vec3, Vec4};

use crate::addressing::{linear_taps, nearest_index, wrap};
use crate::sampler::texel_fetch::{border_value, premultiply, unpremultiply};
use crate::sampler::{FilterMode, Sampler, SamplerDescriptor};
use crate::texture2d::try_vec_with_capacity;
use crate::{Limits, MipChain, Texel, TextureError, TextureSampler};
use glam::Vec2;

/// A 2D array texture: layers of equal size, each with its mip chain, sampled with one
/// descriptor. The layer coordinate is rounded to nearest even and clamped to the layers, as
/// Vulkan specifies (`l = clamp(RNE(a), 0, layers − 1)`); a NaN layer reads layer 0.
#[derive(Clone, Debug)]
pub struct Texture2dArray<T> {
    layers: Vec<TextureSampler<T>>,
}

impl<T: Texel> Texture2dArray<T> {
    /// An array from layer chains of equal base size and length.
    ///
    /// # Errors
    /// [`TextureError::InvalidParameter`] for no layers or layers of different sizes.
    pub fn new(
        layers: Vec<MipChain<T>>,
        descriptor: SamplerDescriptor,
    ) -> Result<Self, TextureError> {
        let Some(first) = layers.first() else {
            return Err(TextureError::InvalidParameter {
                what: "layers",
                reason: "an array texture needs at least one layer",
            });
        };
        let (size, len) = (first.base().size(), first.len());
        if layers
            .iter()
            .any(|l| l.base().size() != size || l.len() != len)
        {
            return Err(TextureError::InvalidParameter {
                what: "layers",
                reason: "layers must have equal sizes and chain lengths",
            });
        }
        Ok(Self {
            layers: layers
                .into_iter()
                .map(|chain| TextureSampler::new(chain, descriptor))
                .collect(),
        })
    }

    /// The number of layers.
    #[must_use]
    pub fn layer_count(&self) -> usize {
        self.layers.len()
    }

    /// The layer a layer coordinate selects.
    #[must_use]
    pub fn layer_index(&self, layer: f32) -> usize {
        let last = self.layers.len() - 1;
        let rounded = layer.round_ties_even();
        if rounded.is_nan() || rounded <= 0.0 {
            0
        } else if rounded >= last as f32 {
            last
        } else {
            rounded as usize
        }
    }

    /// `Sampler::sample` on the selected layer.
    #[must_use]
    pub fn sample(&self, uv: Vec2, layer: f32, ddx: Vec2, ddy: Vec2) -> Vec4 {
        self.layers[self.layer_index(layer)].sample(uv, ddx, ddy)
    }

    /// `Sampler::sample_level` on the selected layer.
    #[must_use]
    pub fn sample_level(&self, uv: Vec2, layer: f32, lod: f32) -> Vec4 {
        self.layers[self.layer_index(layer)].sample_level(uv, lod)
    }
}

/// A volume of `width × height × depth` texels, slice-major (slice `z`, then rows, then
/// columns), texel (0, 0, 0) at the top-left of the first slice.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture3d<T> {
    size: [u32; 3],
    texels: Vec<T>,
}

impl<T: Texel> Texture3d<T> {
    /// A volume whose texel (x, y, z) is `f(x, y, z)`, under `limits` (the depth is checked
    /// against `max_height`, the bytes against `max_bytes`).
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn from_fn(
        size: [u32; 3],
        limits: &Limits,
        mut f: impl FnMut(u32, u32, u32) -> T,
    ) -> Result<Self, TextureError> {
        let [w, h, d] = size;
        let slice = limits.check(w, h, T::FORMAT.bytes_per_texel())?;
        limits.check(w, d, 1)?;
        let bytes = slice.saturating_mul(u64::from(d));
        if bytes > limits.max_bytes || usize::try_from(bytes).is_err() {
            return Err(TextureError::TooLarge {
                what: "bytes",
                requested: bytes,
                limit: limits.max_bytes,
            });
        }
        let mut texels = try_vec_with_capacity(w as usize * h as usize * d as usize)?;
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    texels.push(f(x, y, z));
                }
            }
        }
        Ok(Self { size, texels })
    }

    /// `[width, height, depth]`.
    #[must_use]
    pub fn size(&self) -> [u32; 3] {
        self.size
    }

    /// Texel (x, y, z); `None` outside.
    #[must_use]
    pub fn texel(&self, x: u32, y: u32, z: u32) -> Option<T> {
        let [w, h, d] = self.size;
        (x < w && y < h && z < d)
            .then(|| self.texels[(z as usize * h as usize + y as usize) * w as usize + x as usize])
    }

    /// The filtered colour at `uvw` (each in [0, 1] across the volume), with the descriptor's
    /// address modes per axis and its `mag_filter` (nearest, or trilinear for `Linear`/`Cubic`);
    /// a non-finite coordinate gives transparent black.
    ///
    /// # Accuracy
    /// Trilinear weights are the exact-coordinate weights rounded once to f32 (as in 2D); the
    /// blend is seven lerps `a + (b − a)·t`, exact at texel centres and on constants, and exact
    /// on trilinear functions at dyadic points (`tests/volume.rs`).
    #[must_use]
    pub fn sample(&self, uvw: Vec3, descriptor: &SamplerDescriptor) -> Vec4 {
        if !uvw.is_finite() {
            return Vec4::ZERO;
        }
        let [w, h, d] = self.size;
        let modes = [
            descriptor.address_mode_u,
            descriptor.address_mode_v,
            descriptor.address_mode_w,
        ];
        let border = border_value(descriptor.border_color.unwrap_or_default());
        let fetch = |x: i64, y: i64, z: i64| match (
            wrap(x, w, modes[0]),
            wrap(y, h, modes[1]),
            wrap(z, d, modes[2]),
        ) {
            (Some(x), Some(y), Some(z)) => self
                .texel(x, y, z)
                .map_or(border, |t| premultiply(t.to_linear())),
            _ => border,
        };
        let value = match descriptor.mag_filter {
            FilterMode::Nearest => fetch(
                nearest_index(uvw.x, w),
                nearest_index(uvw.y, h),
                nearest_index(uvw.z, d),
            ),
            FilterMode::Linear | FilterMode::Cubic(_) => {
                let (tx, ty, tz) = (
                    linear_taps(uvw.x, w),
                    linear_taps(uvw.y, h),
                    linear_taps(uvw.z, d),
                );
                let (x0, y0, z0) = (tx.i0, ty.i0, tz.i0);
                let (x1, y1, z1) = (
                    x0.saturating_add(1),
                    y0.saturating_add(1),
                    z0.saturating_add(1),
                );
                let lerp = |a: Vec4, b: Vec4, t: f32| a + (b - a) * t;
                let plane = |z: i64| {
                    let top = lerp(fetch(x0, y0, z), fetch(x1, y0, z), tx.frac);
                    let bottom = lerp(fetch(x0, y1, z), fetch(x1, y1, z), tx.frac);
                    lerp(top, bottom, ty.frac)
                };
                lerp(plane(z0), plane(z1), tz.frac)
            }
        };
        unpremultiply(value)
    }
}
