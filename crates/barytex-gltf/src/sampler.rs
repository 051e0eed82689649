//! glTF samplers as small enums of their own (the glTF numbers are GL enums), with the spec's
//! defaults and a conversion to `barytex_texture`'s [`SamplerDescriptor`].

use barytex_texture::SamplerDescriptor;
use barytex_texture::sampler::{AddressMode, FilterMode, MipmapFilterMode};

use crate::SceneError;
use crate::json::Obj;

/// Magnification filter (`magFilter`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MagFilter {
    /// `NEAREST` (9728).
    Nearest,
    /// `LINEAR` (9729), the default when absent.
    #[default]
    Linear,
}

/// Minification filter (`minFilter`), including the mipmap modes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MinFilter {
    /// `NEAREST` (9728): no mipmaps.
    Nearest,
    /// `LINEAR` (9729): no mipmaps.
    Linear,
    /// `NEAREST_MIPMAP_NEAREST` (9984).
    NearestMipmapNearest,
    /// `LINEAR_MIPMAP_NEAREST` (9985).
    LinearMipmapNearest,
    /// `NEAREST_MIPMAP_LINEAR` (9986).
    NearestMipmapLinear,
    /// `LINEAR_MIPMAP_LINEAR` (9987), the default when absent (trilinear).
    #[default]
    LinearMipmapLinear,
}

/// Wrap mode along one axis (`wrapS`, `wrapT`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    /// `REPEAT` (10497), the default.
    #[default]
    Repeat,
    /// `CLAMP_TO_EDGE` (33071).
    ClampToEdge,
    /// `MIRRORED_REPEAT` (33648).
    MirroredRepeat,
}

/// A glTF sampler; [`SamplerParams::default`] is what a texture without a sampler uses (repeat,
/// linear magnification, trilinear minification).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SamplerParams {
    /// Magnification filter.
    pub mag_filter: MagFilter,
    /// Minification filter.
    pub min_filter: MinFilter,
    /// Wrap along u (`wrapS`).
    pub wrap_s: Wrap,
    /// Wrap along v (`wrapT`).
    pub wrap_t: Wrap,
}

fn address(wrap: Wrap) -> AddressMode {
    match wrap {
        Wrap::Repeat => AddressMode::Repeat,
        Wrap::ClampToEdge => AddressMode::ClampToEdge,
        Wrap::MirroredRepeat => AddressMode::MirrorRepeat,
    }
}

impl SamplerParams {
    /// Whether the minification filter reads mip levels (`*_MIPMAP_*`).
    ///
    /// ```
    /// use barytex_gltf::{MinFilter, SamplerParams};
    ///
    /// assert!(SamplerParams::default().uses_mipmaps());
    /// let linear = SamplerParams { min_filter: MinFilter::Linear, ..SamplerParams::default() };
    /// assert!(!linear.uses_mipmaps());
    /// ```
    #[must_use]
    pub const fn uses_mipmaps(&self) -> bool {
        !matches!(self.min_filter, MinFilter::Nearest | MinFilter::Linear)
    }

    /// The LOD clamp that emulates a minification filter without mipmaps (`NEAREST`, `LINEAR`):
    /// the Vulkan specification's recipe (§16.5 "Texel Filtering", the note on emulating OpenGL's
    /// non-mipmapped minification: `maxLod = 0.25` with `mipmapMode = NEAREST`). A minified
    /// lookup's λ is then 0.25 — positive, so the minification filter applies (OpenGL 4.6 §8.14)
    /// — and the nearest mip of 0.25 is level 0; a magnified one keeps λ ≤ 0 and the
    /// magnification filter. A clamp of 0 would make every lookup magnified.
    pub const NO_MIPMAPS_MAX_LOD: f32 = 0.25;

    /// The equivalent `barytex_texture` sampler. Minification without mipmaps
    /// (`NEAREST`/`LINEAR`) samples only level 0, expressed as a LOD clamp of 0.
    ///
    /// ```
    /// use barytex_gltf::{MinFilter, SamplerParams, Wrap};
    /// use barytex_texture::sampler::{AddressMode, FilterMode, MipmapFilterMode};
    ///
    /// // The glTF default (repeat, trilinear) is barytex's trilinear sampler with repeat.
    /// let d = SamplerParams::default().to_descriptor();
    /// assert_eq!(d.address_mode_u, AddressMode::Repeat);
    /// assert_eq!((d.min_filter, d.mipmap_filter), (FilterMode::Linear, MipmapFilterMode::Linear));
    /// // LINEAR minification without mipmaps: Vulkan's recipe, a LOD clamp of 0.25 with the
    /// // nearest mip, so minified lookups take the min filter on level 0.
    /// let flat = SamplerParams { min_filter: MinFilter::Linear, wrap_t: Wrap::MirroredRepeat, ..SamplerParams::default() };
    /// let d = flat.to_descriptor();
    /// assert_eq!((d.lod_min_clamp, d.lod_max_clamp), (0.0, SamplerParams::NO_MIPMAPS_MAX_LOD));
    /// assert_eq!(d.mipmap_filter, MipmapFilterMode::Nearest);
    /// assert_eq!(d.address_mode_v, AddressMode::MirrorRepeat);
    /// ```
    #[must_use]
    pub fn to_descriptor(&self) -> SamplerDescriptor {
        let mag_filter = match self.mag_filter {
            MagFilter::Nearest => FilterMode::Nearest,
            MagFilter::Linear => FilterMode::Linear,
        };
        let (min_filter, mipmap_filter, mipmapped) = match self.min_filter {
            MinFilter::Nearest => (FilterMode::Nearest, MipmapFilterMode::Nearest, false),
            MinFilter::Linear => (FilterMode::Linear, MipmapFilterMode::Nearest, false),
            MinFilter::NearestMipmapNearest => {
                (FilterMode::Nearest, MipmapFilterMode::Nearest, true)
            }
            MinFilter::LinearMipmapNearest => (FilterMode::Linear, MipmapFilterMode::Nearest, true),
            MinFilter::NearestMipmapLinear => (FilterMode::Nearest, MipmapFilterMode::Linear, true),
            MinFilter::LinearMipmapLinear => (FilterMode::Linear, MipmapFilterMode::Linear, true),
        };
        SamplerDescriptor {
            address_mode_u: address(self.wrap_s),
            address_mode_v: address(self.wrap_t),
            mag_filter,
            min_filter,
            mipmap_filter,
            lod_max_clamp: if mipmapped {
                32.0
            } else {
                Self::NO_MIPMAPS_MAX_LOD
            },
            ..SamplerDescriptor::default()
        }
    }

    /// Reads `/samplers/i`. Unknown enum values fall back to the default with a warning (the
    /// validator treats them as warnings too, for forward compatibility).
    pub(crate) fn parse(obj: Obj<'_>, warnings: &mut Vec<String>) -> Result<Self, SceneError> {
        let mut sampler = Self::default();
        if let Some(v) = obj.opt_u64("magFilter")? {
            sampler.mag_filter = match v {
                9728 => MagFilter::Nearest,
                9729 => MagFilter::Linear,
                other => {
                    warnings.push(format!(
                        "{}: unknown magFilter {other}",
                        obj.at("magFilter")
                    ));
                    MagFilter::Linear
                }
            };
        }
        if let Some(v) = obj.opt_u64("minFilter")? {
            sampler.min_filter = match v {
                9728 => MinFilter::Nearest,
                9729 => MinFilter::Linear,
                9984 => MinFilter::NearestMipmapNearest,
                9985 => MinFilter::LinearMipmapNearest,
                9986 => MinFilter::NearestMipmapLinear,
                9987 => MinFilter::LinearMipmapLinear,
                other => {
                    warnings.push(format!(
                        "{}: unknown minFilter {other}",
                        obj.at("minFilter")
                    ));
                    MinFilter::LinearMipmapLinear
                }
            };
        }
        let wrap = |key: &str, warnings: &mut Vec<String>| -> Result<Wrap, SceneError> {
            Ok(match obj.opt_u64(key)? {
                None | Some(10497) => Wrap::Repeat,
                Some(33071) => Wrap::ClampToEdge,
                Some(33648) => Wrap::MirroredRepeat,
                Some(other) => {
                    warnings.push(format!("{}: unknown wrap mode {other}", obj.at(key)));
                    Wrap::Repeat
                }
            })
        };
        sampler.wrap_s = wrap("wrapS", warnings)?;
        sampler.wrap_t = wrap("wrapT", warnings)?;
        Ok(sampler)
    }
}
