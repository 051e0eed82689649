//! The textures a render samples: each (image, colour space, sampler) the scene's materials use,
//! with a mip chain only when the filter uses mipmaps and the texture is actually minified
//! somewhere on screen.

use std::collections::HashMap;
use std::sync::Arc;

use barytex_gltf::SamplerParams;
use barytex_gltf::material::TextureRef;
use barytex_gltf::scene::Scene;
use barytex_texture::load::{AnyTexture2d, ColorSpace};
use barytex_texture::{
    MipChain, MipOptions, Sampler as _, SamplerDescriptor, Texel, Texture2d, TextureError,
    TextureSampler,
};
use barytex_uv::mappings::TexCoordMapping;
use glam::{Vec2, Vec4};

use crate::{Filter, ResolvedFilter};

/// A decoded texture with its filter, whatever its texel format.
#[derive(Clone, Debug)]
pub(crate) enum PreparedTexture {
    Srgba8(TextureSampler<barytex_texture::Srgba8>),
    Rgba8(TextureSampler<barytex_texture::Rgba8>),
    R8(TextureSampler<barytex_texture::R8>),
    Rgba16f(TextureSampler<barytex_texture::Rgba16f>),
    Rgba32f(TextureSampler<barytex_texture::Rgba32f>),
}

impl PreparedTexture {
    /// Linear straight-alpha colour over the pixel footprint.
    #[inline]
    pub(crate) fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
        match self {
            Self::Srgba8(s) => s.sample(uv, ddx, ddy),
            Self::Rgba8(s) => s.sample(uv, ddx, ddy),
            Self::R8(s) => s.sample(uv, ddx, ddy),
            Self::Rgba16f(s) => s.sample(uv, ddx, ddy),
            Self::Rgba32f(s) => s.sample(uv, ddx, ddy),
        }
    }

    /// [`sample`](Self::sample) through `mapped` with an 8-bit sRGB texture's lookup inlined
    /// into the caller (the base colour's format in nearly every file; the unlit fragment
    /// loop's one lookup); other formats through the call.
    #[inline(always)]
    pub(crate) fn sample_base(&self, mapped: &barytex_uv::UvSample) -> Vec4 {
        match self {
            Self::Srgba8(s) => s.sample(mapped.uv, mapped.duvdx, mapped.duvdy),
            other => other.sample(mapped.uv, mapped.duvdx, mapped.duvdy),
        }
    }

    /// [`sample_base`](Self::sample_base) at two points, the lookups interleaved for the sRGB
    /// format ([`TextureSampler::sample_pair`](barytex_texture::TextureSampler::sample_pair));
    /// the same values.
    #[inline(always)]
    pub(crate) fn sample_base_pair(
        &self,
        a: &barytex_uv::UvSample,
        b: &barytex_uv::UvSample,
    ) -> [Vec4; 2] {
        match self {
            Self::Srgba8(s) => s.sample_pair([a.uv, a.duvdx, a.duvdy], [b.uv, b.duvdx, b.duvdy]),
            other => [other.sample_base(a), other.sample_base(b)],
        }
    }
}

impl barytex_texture::Sampler for PreparedTexture {
    fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
        Self::sample(self, uv, ddx, ddy)
    }

    fn sample_level(&self, uv: Vec2, lod: f32) -> Vec4 {
        match self {
            Self::Srgba8(s) => s.sample_level(uv, lod),
            Self::Rgba8(s) => s.sample_level(uv, lod),
            Self::R8(s) => s.sample_level(uv, lod),
            Self::Rgba16f(s) => s.sample_level(uv, lod),
            Self::Rgba32f(s) => s.sample_level(uv, lod),
        }
    }
}

/// An equirectangular environment ready to sample: a linear-light mip chain, trilinear with
/// 8 anisotropic probes, repeating around (u) and clamped at the poles (v).
pub(crate) fn environment(image: &AnyTexture2d) -> Result<Option<PreparedTexture>, TextureError> {
    use barytex_texture::sampler::{AddressMode, FilterMode, MipmapFilterMode};
    let descriptor = SamplerDescriptor {
        address_mode_u: AddressMode::Repeat,
        address_mode_v: AddressMode::ClampToEdge,
        mag_filter: FilterMode::Linear,
        min_filter: FilterMode::Linear,
        mipmap_filter: MipmapFilterMode::Linear,
        anisotropy_clamp: 8,
        ..SamplerDescriptor::default()
    };
    Ok(Some(match image {
        AnyTexture2d::Srgba8(t) => PreparedTexture::Srgba8(prepare(t, descriptor, true)?),
        AnyTexture2d::Rgba8(t) => PreparedTexture::Rgba8(prepare(t, descriptor, true)?),
        AnyTexture2d::R8(t) => PreparedTexture::R8(prepare(t, descriptor, true)?),
        AnyTexture2d::Rgba16f(t) => PreparedTexture::Rgba16f(prepare(t, descriptor, true)?),
        AnyTexture2d::Rgba32f(t) => PreparedTexture::Rgba32f(prepare(t, descriptor, true)?),
        _ => return Ok(None),
    }))
}

fn prepare<T: Texel>(
    texture: &Texture2d<T>,
    descriptor: SamplerDescriptor,
    mipmapped: bool,
) -> Result<TextureSampler<T>, TextureError> {
    prepare_owned(texture.clone(), descriptor, mipmapped)
}

fn prepare_owned<T: Texel>(
    texture: Texture2d<T>,
    descriptor: SamplerDescriptor,
    mipmapped: bool,
) -> Result<TextureSampler<T>, TextureError> {
    Ok(if mipmapped {
        TextureSampler::new(
            MipChain::generate(texture, &MipOptions::default())?,
            descriptor,
        )
    } else {
        TextureSampler::single_level(texture, descriptor)
    })
}

/// How a texture's alpha is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum AlphaUse {
    /// Alpha is coverage: filtering blends premultiplied colour (the base colour of MASK and
    /// BLEND materials).
    Coverage,
    /// Alpha is ignored: every texel counts as opaque, so its colour is filtered as stored
    /// whatever its alpha — glTF's OPAQUE base colour (§3.9.4 "Alpha Coverage"), and every
    /// texture whose alpha the material never reads (emissive, occlusion, metallic-roughness,
    /// normal), as a GPU filters them.
    Ignored,
}

/// `texture` for `alpha`: itself, or (when alpha is ignored and some texel is not opaque) a
/// copy whose every texel has alpha one, its colour as stored.
fn prepared_for<T: Texel>(
    texture: &Texture2d<T>,
    alpha: AlphaUse,
    descriptor: SamplerDescriptor,
    mipmapped: bool,
) -> Result<TextureSampler<T>, TextureError> {
    let opaque = |t: &T| t.to_linear().w == 1.0;
    if alpha == AlphaUse::Coverage || texture.texels().iter().all(opaque) {
        return prepare(texture, descriptor, mipmapped);
    }
    let mut copy = texture.clone();
    for t in copy.texels_mut() {
        let c = t.to_linear();
        if c.w != 1.0 {
            *t = T::from_linear(c.truncate().extend(1.0));
        }
    }
    prepare_owned(copy, descriptor, mipmapped)
}

/// A material's texture slot ready to sample: the texture and its uv mapping.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slot {
    /// Index into [`Textures::list`].
    pub(crate) texture: usize,
    /// Which `TEXCOORD_n`, through `KHR_texture_transform`.
    pub(crate) mapping: TexCoordMapping,
}

/// The prepared textures and what preparing them did.
#[derive(Debug, Default)]
pub(crate) struct Textures {
    pub(crate) list: Vec<PreparedTexture>,
    /// (image, sRGB?, the glTF sampler, how alpha is read) → index into `list`; the render's [`Filter`] is the
    /// same for every texture, so the glTF sampler decides the descriptor.
    index: HashMap<(usize, bool, SamplerParams, AlphaUse), usize>,
    /// The textures [`Textures::slot`] asked for, prepared together by [`Textures::prepare_all`]
    /// (in `list`'s order).
    pending: Vec<Pending>,
    /// Mip chains built.
    pub(crate) mip_chains: usize,
    /// Textures whose filter uses mipmaps but that are never minified: no chain built.
    pub(crate) mips_skipped: usize,
    /// Seconds preparing the textures (copies and mip chains, in parallel), wall time.
    pub(crate) mip_seconds: f64,
}

/// A texture to prepare: the decoded image and how it will be sampled.
#[derive(Debug)]
struct Pending {
    decoded: Arc<AnyTexture2d>,
    alpha: AlphaUse,
    descriptor: SamplerDescriptor,
    mipmapped: bool,
}

impl Pending {
    fn prepare(&self) -> Result<PreparedTexture, TextureError> {
        let (alpha, descriptor, mipmapped) = (self.alpha, self.descriptor, self.mipmapped);
        Ok(match self.decoded.as_ref() {
            AnyTexture2d::Srgba8(t) => {
                PreparedTexture::Srgba8(prepared_for(t, alpha, descriptor, mipmapped)?)
            }
            AnyTexture2d::Rgba8(t) => {
                PreparedTexture::Rgba8(prepared_for(t, alpha, descriptor, mipmapped)?)
            }
            AnyTexture2d::R8(t) => {
                PreparedTexture::R8(prepared_for(t, alpha, descriptor, mipmapped)?)
            }
            AnyTexture2d::Rgba16f(t) => {
                PreparedTexture::Rgba16f(prepared_for(t, alpha, descriptor, mipmapped)?)
            }
            AnyTexture2d::Rgba32f(t) => {
                PreparedTexture::Rgba32f(prepared_for(t, alpha, descriptor, mipmapped)?)
            }
            // `slot` queues only the formats above.
            _ => {
                return Err(TextureError::InvalidParameter {
                    what: "texture format",
                    reason: "not one the renderer samples",
                });
            }
        })
    }
}

/// The largest texels-per-pixel ratio (square root of the area ratio) of any on-screen triangle
/// that samples texture slot `r`, for an image of the given size.
pub(crate) type MinificationProbe<'a> = &'a dyn Fn(&TextureRef, (u32, u32)) -> f32;

impl Textures {
    /// The slot for `r` decoded as `space`, preparing its texture on first use; `None` when the
    /// scene has no decoded image for it.
    pub(crate) fn slot(
        &mut self,
        scene: &Scene,
        r: &TextureRef,
        space: ColorSpace,
        alpha: AlphaUse,
        filter: Filter,
        minification: MinificationProbe<'_>,
    ) -> Result<Option<Slot>, TextureError> {
        let Some(image) = r.image.and_then(|i| scene.images.get(i)) else {
            return Ok(None);
        };
        let srgb = space == ColorSpace::Srgb;
        let Some(decoded) = (if srgb { &image.srgb } else { &image.linear }) else {
            return Ok(None);
        };
        let key = (r.image.unwrap_or(usize::MAX), srgb, r.sampler, alpha);
        let texture = if let Some(&i) = self.index.get(&key) {
            i
        } else {
            let size = match decoded.as_ref() {
                AnyTexture2d::Srgba8(t) => t.size(),
                AnyTexture2d::Rgba8(t) => t.size(),
                AnyTexture2d::R8(t) => t.size(),
                AnyTexture2d::Rgba16f(t) => t.size(),
                AnyTexture2d::Rgba32f(t) => t.size(),
                // A format this renderer does not know: drawn untextured.
                _ => return Ok(None),
            };
            let ResolvedFilter {
                descriptor,
                mipmapped: wants_mips,
            } = filter.resolve(&r.sampler);
            let mipmapped = wants_mips && minification(r, size) > 1.0;
            if mipmapped {
                self.mip_chains += 1;
            } else if wants_mips {
                self.mips_skipped += 1;
            }
            self.pending.push(Pending {
                decoded: Arc::clone(decoded),
                alpha,
                descriptor,
                mipmapped,
            });
            self.index.insert(key, self.pending.len() - 1);
            self.pending.len() - 1
        };
        Ok(Some(Slot {
            texture,
            mapping: r.mapping,
        }))
    }

    /// Prepares every texture the slots asked for (copies, mip chains), in parallel on the
    /// current rayon pool: the chains of a material's textures are independent, and each is
    /// one sequential pass. `list[i]` is the texture of slot index `i` whatever the thread count.
    pub(crate) fn prepare_all(&mut self) -> Result<(), TextureError> {
        use rayon::prelude::*;
        let started = std::time::Instant::now();
        let prepared: Vec<PreparedTexture> = self
            .pending
            .par_iter()
            .map(Pending::prepare)
            .collect::<Result<_, _>>()?;
        self.list.extend(prepared);
        self.pending.clear();
        self.mip_seconds += started.elapsed().as_secs_f64();
        Ok(())
    }
}
