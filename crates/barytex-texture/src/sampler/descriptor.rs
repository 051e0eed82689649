//! `SamplerDescriptor`: wgpu's sampler descriptor field for field, plus Vulkan's LOD bias, a cubic
//! filter and the choice of anisotropic filter.

/// What happens to texel coordinates outside the texture (wgpu `AddressMode`, Vulkan
/// `VkSamplerAddressMode`). Applied to **integer texel indices**, as the Vulkan spec does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AddressMode {
    /// Clamp to the first/last texel (`CLAMP_TO_EDGE`). The default, as in wgpu.
    #[default]
    ClampToEdge,
    /// Tile (`REPEAT`).
    Repeat,
    /// Tile, flipping every other copy (`MIRRORED_REPEAT`).
    MirrorRepeat,
    /// Texels outside read the border colour (`CLAMP_TO_BORDER`).
    ClampToBorder,
}

/// Filter within one level (wgpu `FilterMode`, plus Vulkan's `VK_FILTER_CUBIC_EXT`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FilterMode {
    /// The texel containing the coordinate.
    #[default]
    Nearest,
    /// Bilinear: the 2×2 texels around the coordinate, weighted by distance.
    Linear,
    /// Bicubic: the 4×4 texels around the coordinate, weighted by a cubic kernel.
    Cubic(CubicKernel),
}

/// Cubic kernels, all members of the Mitchell–Netravali (B, C) family.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CubicKernel {
    /// B = 0, C = 1/2: interpolating, sharp, may overshoot (Vulkan's cubic filter).
    #[default]
    CatmullRom,
    /// B = 1, C = 0: smooth, never overshoots, blurs.
    BSpline,
    /// B = C = 1/3: Mitchell and Netravali's recommended compromise.
    Mitchell,
}

/// Filter between mip levels (wgpu `MipmapFilterMode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MipmapFilterMode {
    /// The nearest level.
    #[default]
    Nearest,
    /// Blend the two nearest levels (trilinear with linear min/mag filters).
    Linear,
}

/// The colour read outside the texture under [`AddressMode::ClampToBorder`] (wgpu
/// `SamplerBorderColor`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BorderColor {
    /// (0, 0, 0, 0).
    #[default]
    TransparentBlack,
    /// (0, 0, 0, 1).
    OpaqueBlack,
    /// (1, 1, 1, 1).
    OpaqueWhite,
    /// Zero in every channel, alpha included (wgpu's `Zero`, for integer formats).
    Zero,
}

/// The depth-comparison function of a comparison sampler (wgpu `CompareFunction`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunction {
    /// Never passes.
    Never,
    /// Passes if the reference is less than the texel.
    Less,
    /// Passes if equal.
    Equal,
    /// Passes if less or equal.
    LessEqual,
    /// Passes if greater.
    Greater,
    /// Passes if not equal.
    NotEqual,
    /// Passes if greater or equal.
    GreaterEqual,
    /// Always passes.
    Always,
}

/// How minification with `anisotropy_clamp > 1` integrates the elliptical footprint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AnisotropicFilter {
    /// GPU-style: trilinear probes spaced along the footprint's major axis, the level chosen from
    /// the minor axis (Vulkan/D3D).
    #[default]
    Probes,
    /// Elliptical weighted average with a Gaussian weight (Heckbert, pbrt-v4), bounded cost.
    Ewa,
}

/// How to filter a texture: wgpu's `SamplerDescriptor` field for field (without the label), plus
/// Vulkan's `mipLodBias`, a cubic filter and the choice of anisotropic filter.
///
/// The default is wgpu's default: clamp to edge, nearest everywhere, LOD clamp [0, 32], no
/// comparison, anisotropy 1 (off), no border colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplerDescriptor {
    /// Address mode along u.
    pub address_mode_u: AddressMode,
    /// Address mode along v.
    pub address_mode_v: AddressMode,
    /// Address mode along w (3D textures).
    pub address_mode_w: AddressMode,
    /// Filter when the texture is magnified (LOD ≤ 0).
    pub mag_filter: FilterMode,
    /// Filter when the texture is minified (LOD > 0).
    pub min_filter: FilterMode,
    /// Filter between mip levels.
    pub mipmap_filter: MipmapFilterMode,
    /// Smallest level of detail used.
    pub lod_min_clamp: f32,
    /// Largest level of detail used.
    pub lod_max_clamp: f32,
    /// Depth comparison (comparison samplers, used by
    /// [`TextureSampler::sample_compare_level`](crate::TextureSampler::sample_compare_level)),
    /// `None` for colour sampling.
    pub compare: Option<CompareFunction>,
    /// Largest anisotropy ratio, 1 to 16; 1 turns anisotropic filtering off.
    pub anisotropy_clamp: u16,
    /// Colour outside the texture under [`AddressMode::ClampToBorder`]; `None` reads as
    /// [`BorderColor::TransparentBlack`].
    pub border_color: Option<BorderColor>,
    /// Added to the computed level of detail before clamping (Vulkan `mipLodBias`).
    pub lod_bias: f32,
    /// The anisotropic filter used when `anisotropy_clamp > 1`.
    pub anisotropic_filter: AnisotropicFilter,
}

impl Default for SamplerDescriptor {
    fn default() -> Self {
        Self {
            address_mode_u: AddressMode::ClampToEdge,
            address_mode_v: AddressMode::ClampToEdge,
            address_mode_w: AddressMode::ClampToEdge,
            mag_filter: FilterMode::Nearest,
            min_filter: FilterMode::Nearest,
            mipmap_filter: MipmapFilterMode::Nearest,
            lod_min_clamp: 0.0,
            lod_max_clamp: 32.0,
            compare: None,
            anisotropy_clamp: 1,
            border_color: None,
            lod_bias: 0.0,
            anisotropic_filter: AnisotropicFilter::Probes,
        }
    }
}

impl SamplerDescriptor {
    /// The descriptor as the samplers use it: a NaN `lod_min_clamp` becomes 0, a NaN
    /// `lod_max_clamp` 32, `lod_max_clamp` is raised to `lod_min_clamp`, a non-finite `lod_bias`
    /// becomes 0, and `anisotropy_clamp` is clamped to 1…16 ([`TextureSampler::new`] and
    /// [`CubeTexture::new`](crate::CubeTexture::new) apply it).
    ///
    /// [`TextureSampler::new`]: crate::TextureSampler::new
    pub(crate) fn sanitized(self) -> Self {
        let mut d = self;
        if d.lod_min_clamp.is_nan() {
            d.lod_min_clamp = 0.0;
        }
        if d.lod_max_clamp.is_nan() {
            d.lod_max_clamp = 32.0;
        }
        d.lod_max_clamp = d.lod_max_clamp.max(d.lod_min_clamp);
        if !d.lod_bias.is_finite() {
            d.lod_bias = 0.0;
        }
        d.anisotropy_clamp = d.anisotropy_clamp.clamp(1, 16);
        d
    }

    /// Bilinear within a level, nearest level: wgpu's common "linear" sampler without mip blending.
    ///
    /// ```
    /// use barytex_texture::{R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// // Two texels, 0 and 1: halfway between their centres reads 0.5.
    /// let texture = Texture2d::from_texels(2, 1, vec![R32f(0.0), R32f(1.0)])?;
    /// let linear = TextureSampler::single_level(texture.clone(), SamplerDescriptor::bilinear());
    /// assert_eq!(linear.sample_level(Vec2::new(0.5, 0.5), 0.0).x, 0.5);
    /// // The default sampler is nearest: the same point lies in texel 1.
    /// let nearest = TextureSampler::single_level(texture, SamplerDescriptor::default());
    /// assert_eq!(nearest.sample_level(Vec2::new(0.5, 0.5), 0.0).x, 1.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn bilinear() -> Self {
        Self {
            mag_filter: FilterMode::Linear,
            min_filter: FilterMode::Linear,
            ..Self::default()
        }
    }

    /// Trilinear: bilinear within levels, linear between them.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// // Level 0 is [0, 1], level 1 their mean 0.5; at texel 0's centre and LOD ½:
    /// let base = Texture2d::from_texels(2, 1, vec![R32f(0.0), R32f(1.0)])?;
    /// let chain = MipChain::generate(base, &MipOptions::default())?;
    /// let uv = Vec2::new(0.25, 0.5);
    /// // trilinear blends the two levels halfway,
    /// let tri = TextureSampler::new(chain.clone(), SamplerDescriptor::trilinear());
    /// assert_eq!(tri.sample_level(uv, 0.5).x, 0.25);
    /// // bilinear picks the nearest level (Vulkan: ⌈λ + ½⌉ − 1 = 0).
    /// let bi = TextureSampler::new(chain, SamplerDescriptor::bilinear());
    /// assert_eq!(bi.sample_level(uv, 0.5).x, 0.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn trilinear() -> Self {
        Self {
            mipmap_filter: MipmapFilterMode::Linear,
            ..Self::bilinear()
        }
    }

    /// Trilinear with GPU-style anisotropic probes, ratio clamped to `max_anisotropy` (1–16).
    ///
    /// ```
    /// use barytex_texture::SamplerDescriptor;
    /// use barytex_texture::sampler::MipmapFilterMode;
    ///
    /// let d = SamplerDescriptor::anisotropic(8);
    /// assert_eq!(d.anisotropy_clamp, 8);
    /// assert_eq!(d.mipmap_filter, MipmapFilterMode::Linear);
    /// // The ratio is clamped to 1..=16.
    /// assert_eq!(SamplerDescriptor::anisotropic(64).anisotropy_clamp, 16);
    /// assert_eq!(SamplerDescriptor::anisotropic(0).anisotropy_clamp, 1);
    /// ```
    #[must_use]
    pub fn anisotropic(max_anisotropy: u16) -> Self {
        Self {
            anisotropy_clamp: max_anisotropy.clamp(1, 16),
            ..Self::trilinear()
        }
    }

    /// The same address mode on every axis.
    ///
    /// ```
    /// use barytex_texture::sampler::AddressMode;
    /// use barytex_texture::{R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// let texture = Texture2d::from_texels(2, 1, vec![R32f(0.0), R32f(1.0)])?;
    /// let at = |mode| {
    ///     let d = SamplerDescriptor::default().with_address_mode(mode);
    ///     TextureSampler::single_level(texture.clone(), d).sample_level(Vec2::new(1.25, 0.5), 0.0).x
    /// };
    /// // u = 1.25 is texel index 2: repeat reads texel 0, clamp the last texel, mirror texel 1.
    /// assert_eq!(at(AddressMode::Repeat), 0.0);
    /// assert_eq!(at(AddressMode::ClampToEdge), 1.0);
    /// assert_eq!(at(AddressMode::MirrorRepeat), 1.0);
    /// // The border is transparent black by default.
    /// let border = SamplerDescriptor::default().with_address_mode(AddressMode::ClampToBorder);
    /// assert_eq!(border.address_mode_v, AddressMode::ClampToBorder);
    /// assert_eq!(at(AddressMode::ClampToBorder), 0.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn with_address_mode(self, mode: AddressMode) -> Self {
        Self {
            address_mode_u: mode,
            address_mode_v: mode,
            address_mode_w: mode,
            ..self
        }
    }
}
