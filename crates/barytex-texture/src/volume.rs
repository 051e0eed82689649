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
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, Texture2dArray};
    /// use glam::Vec2;
    ///
    /// // Three 2×2 layers holding 0, 100 and 200.
    /// let layer = |v: u8| Texture2d::new(2, 2, R8(v)).map(MipChain::single);
    /// let array = Texture2dArray::new(vec![layer(0)?, layer(100)?, layer(200)?], SamplerDescriptor::bilinear())?;
    /// assert_eq!(array.layer_count(), 3);
    /// // Layers of different sizes are refused, and so is an empty array.
    /// let odd = Texture2d::new(4, 4, R8(0)).map(MipChain::single)?;
    /// assert!(Texture2dArray::new(vec![layer(0)?, odd], SamplerDescriptor::default()).is_err());
    /// assert!(Texture2dArray::<R8>::new(Vec::new(), SamplerDescriptor::default()).is_err());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, Texture2dArray};
    /// use glam::Vec2;
    ///
    /// // Three 2×2 layers holding 0, 100 and 200.
    /// let layer = |v: u8| Texture2d::new(2, 2, R8(v)).map(MipChain::single);
    /// let array = Texture2dArray::new(vec![layer(0)?, layer(100)?, layer(200)?], SamplerDescriptor::bilinear())?;
    /// assert_eq!(array.layer_count(), 3);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn layer_count(&self) -> usize {
        self.layers.len()
    }

    /// The layer a layer coordinate selects.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, Texture2dArray};
    /// use glam::Vec2;
    ///
    /// // Three 2×2 layers holding 0, 100 and 200.
    /// let layer = |v: u8| Texture2d::new(2, 2, R8(v)).map(MipChain::single);
    /// let array = Texture2dArray::new(vec![layer(0)?, layer(100)?, layer(200)?], SamplerDescriptor::bilinear())?;
    /// // Round to nearest even, then clamp (Vulkan).
    /// assert_eq!(array.layer_index(0.5), 0);
    /// assert_eq!(array.layer_index(1.5), 2);
    /// assert_eq!(array.layer_index(1.4), 1);
    /// assert_eq!(array.layer_index(7.0), 2);
    /// assert_eq!(array.layer_index(-3.0), 0);
    /// assert_eq!(array.layer_index(f32::NAN), 0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, Texture2dArray};
    /// use glam::Vec2;
    ///
    /// // Three 2×2 layers holding 0, 100 and 200.
    /// let layer = |v: u8| Texture2d::new(2, 2, R8(v)).map(MipChain::single);
    /// let array = Texture2dArray::new(vec![layer(0)?, layer(100)?, layer(200)?], SamplerDescriptor::bilinear())?;
    /// let c = array.sample(Vec2::splat(0.5), 1.2, Vec2::ZERO, Vec2::ZERO);
    /// assert_eq!(c.x, 100.0 / 255.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn sample(&self, uv: Vec2, layer: f32, ddx: Vec2, ddy: Vec2) -> Vec4 {
        self.layers[self.layer_index(layer)].sample(uv, ddx, ddy)
    }

    /// `Sampler::sample_level` on the selected layer.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, Texture2dArray};
    /// use glam::Vec2;
    ///
    /// // Three 2×2 layers holding 0, 100 and 200.
    /// let layer = |v: u8| Texture2d::new(2, 2, R8(v)).map(MipChain::single);
    /// let array = Texture2dArray::new(vec![layer(0)?, layer(100)?, layer(200)?], SamplerDescriptor::bilinear())?;
    /// assert_eq!(array.sample_level(Vec2::splat(0.5), 2.0, 0.0).x, 200.0 / 255.0);
    /// // Layers are never blended: 0.5 rounds to layer 0.
    /// assert_eq!(array.sample_level(Vec2::splat(0.5), 0.5, 0.0).x, 0.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{Limits, R32f, Texture3d, TextureError};
    ///
    /// let volume = Texture3d::from_fn([4, 3, 2], &Limits::default(), |x, y, z| R32f((x + 10 * y + 100 * z) as f32))?;
    /// assert_eq!(volume.size(), [4, 3, 2]);
    /// assert_eq!(volume.texel(3, 2, 1), Some(R32f(123.0)));
    /// // The depth counts against max_height.
    /// let flat = Limits { max_height: 2, ..Limits::default() };
    /// assert!(matches!(
    ///     Texture3d::from_fn([2, 2, 3], &flat, |_, _, _| R32f(0.0)),
    ///     Err(TextureError::TooLarge { what: "height", .. })
    /// ));
    /// # Ok::<(), TextureError>(())
    /// ```
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
    ///
    /// ```
    /// # use barytex_texture::{Limits, R8, Texture3d};
    /// let volume = Texture3d::from_fn([5, 1, 7], &Limits::default(), |_, _, _| R8(0))?;
    /// assert_eq!(volume.size(), [5, 1, 7]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn size(&self) -> [u32; 3] {
        self.size
    }

    /// Texel (x, y, z); `None` outside.
    ///
    /// ```
    /// use barytex_texture::{Limits, R8, Texture3d};
    ///
    /// let volume = Texture3d::from_fn([2, 2, 2], &Limits::default(), |x, y, z| R8((x + 2 * y + 4 * z) as u8))?;
    /// assert_eq!(volume.texel(1, 0, 1), Some(R8(5)));
    /// assert_eq!(volume.texel(0, 0, 2), None);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    /// blend is seven lerps `a + (b − a)·t`, exact at texel centres and on constants. On
    /// trilinear functions at dyadic points it is within `8·ε·max|texel|` of the function, and
    /// exact when every blend step is: texels that are multiples of `2^e` with
    /// `max|texel| ≤ 2^(23 + e − p − q − r)` (the difference `b − a` of opposite-sign texels may
    /// double it) at points whose three weights are multiples of `2^−p`, `2^−q`, `2^−r` (the
    /// condition of `barytex_interp::trilinear`, whose proof applies step by step). Not exact
    /// beyond it: one bit less of headroom than the lerp form. Tests
    /// `tests/volume.rs::{trilinear_reproduces_trilinear_functions,
    /// trilinear_is_exact_under_the_dyadic_condition}`.
    ///
    /// ```
    /// use barytex_texture::{Limits, R32f, SamplerDescriptor, Texture3d};
    /// use glam::Vec3;
    ///
    /// let volume = Texture3d::from_fn([2, 2, 2], &Limits::default(), |x, y, z| R32f((x + 2 * y + 4 * z) as f32))?;
    /// // Trilinear at the centre: the mean of the eight texels, (0 + … + 7)/8.
    /// assert_eq!(volume.sample(Vec3::splat(0.5), &SamplerDescriptor::bilinear()).x, 3.5);
    /// // Nearest: the texel containing the point, here (1, 0, 1).
    /// assert_eq!(volume.sample(Vec3::new(0.75, 0.25, 0.75), &SamplerDescriptor::default()).x, 5.0);
    /// assert_eq!(volume.sample(Vec3::NAN, &SamplerDescriptor::default()), glam::Vec4::ZERO);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
