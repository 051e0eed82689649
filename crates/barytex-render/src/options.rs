//! What a render is asked to do: size, camera, shading, texture filter, anti-aliasing.

use barytex_gltf::{SamplerParams, TextureRole, TextureRoles};
use barytex_texture::sampler::{
    AnisotropicFilter, FilterMode, MipmapFilterMode, SamplerDescriptor,
};
use glam::Vec4;

/// Which camera to look through.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CameraChoice {
    /// The first camera the scene places (depth-first, in its node order), or the automatic
    /// camera when it places none.
    #[default]
    First,
    /// The automatic camera (see [`auto_camera`](crate::auto_camera)), even when the
    /// scene has cameras.
    Auto,
    /// The document's camera `n` (glTF `cameras[n]`), placed by the first node of the scene
    /// that instantiates it (see [`scene_camera`](crate::scene_camera)); an error when the
    /// document has no camera `n` or the scene places it nowhere.
    Index(usize),
}

/// How surfaces are lit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shading {
    /// glTF's unlit model for every material: base colour factor × base colour texture ×
    /// vertex colour. Comparable with any renderer, no lighting differences.
    Unlit,
    /// Lighting once per polygon's plane: the face normal at every pixel (facets visible).
    Flat,
    /// Lighting at the vertices, interpolated across the triangle (the texture still
    /// modulates per pixel); highlights inside a triangle are lost.
    Gouraud,
    /// Per-pixel Blinn–Phong with the scene's punctual lights (a headlight when it has none)
    /// and the interpolated, renormalized normal. Materials marked `KHR_materials_unlit` stay
    /// unlit under every lit mode.
    #[default]
    Phong,
    /// Gouraud, except on triangles where the five-stage highlight test (H-test,
    /// `barytex_shade::HighlightTest`, whose crate documentation cites its source) finds a visible
    /// specular highlight: those get Phong.
    Hybrid,
}

impl Shading {
    /// The textures this shading samples: the base colour only when unlit; no normal maps
    /// under flat and Gouraud shading (they show only per pixel); every texture otherwise.
    /// A loader given these ([`barytex_gltf::LoadOptions::image_roles`]) decodes nothing else.
    ///
    /// ```
    /// use barytex_gltf::TextureRole;
    /// use barytex_render::Shading;
    ///
    /// assert!(!Shading::Unlit.texture_roles().contains(TextureRole::Emissive));
    /// assert!(!Shading::Gouraud.texture_roles().contains(TextureRole::Normal));
    /// assert!(Shading::Phong.texture_roles().contains(TextureRole::Normal));
    /// ```
    #[must_use]
    pub fn texture_roles(self) -> TextureRoles {
        let lit = TextureRoles::NONE
            .with(TextureRole::BaseColor)
            .with(TextureRole::Emissive)
            .with(TextureRole::MetallicRoughness)
            .with(TextureRole::Occlusion);
        match self {
            Self::Unlit => TextureRoles::NONE.with(TextureRole::BaseColor),
            Self::Flat | Self::Gouraud => lit,
            Self::Phong | Self::Hybrid => lit.with(TextureRole::Normal),
        }
    }
}

/// The texture filter, overriding the files' samplers (their wrap modes stay).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Filter {
    /// What each glTF sampler asks for (mipmaps when its minification filter uses them).
    #[default]
    FromFile,
    /// Nearest texel, no mipmaps.
    Nearest,
    /// Bilinear, no mipmaps.
    Bilinear,
    /// Bilinear within and linear between mip levels.
    Trilinear,
    /// Anisotropic probes over trilinear, up to `n` (1–16) probes.
    Anisotropic(u16),
    /// Elliptical weighted average.
    Ewa,
}

/// What a [`Filter`] makes of one texture's glTF sampler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResolvedFilter {
    /// The descriptor to sample with (the file's wrap modes; filters as the [`Filter`] says).
    pub descriptor: SamplerDescriptor,
    /// Whether the filter reads mip levels: a chain is then built where the texture is
    /// minified on screen (without one, level 0 is sampled alone).
    pub mipmapped: bool,
}

impl Filter {
    /// The descriptor and mip use of a texture whose glTF sampler is `file`, under this filter.
    ///
    /// ```
    /// use barytex_gltf::{MinFilter, SamplerParams};
    /// use barytex_render::Filter;
    ///
    /// let no_mips = SamplerParams { min_filter: MinFilter::Linear, ..SamplerParams::default() };
    /// assert!(!Filter::FromFile.resolve(&no_mips).mipmapped);
    /// assert!(Filter::Trilinear.resolve(&no_mips).mipmapped);
    /// assert_eq!(Filter::Anisotropic(8).resolve(&no_mips).descriptor.anisotropy_clamp, 8);
    /// ```
    #[must_use]
    pub fn resolve(self, file: &SamplerParams) -> ResolvedFilter {
        let mut d = file.to_descriptor();
        let mut mipmapped = file.uses_mipmaps();
        let mut set =
            |d: &mut SamplerDescriptor, filter: FilterMode, mip: Option<MipmapFilterMode>| {
                d.mag_filter = filter;
                d.min_filter = filter;
                mipmapped = mip.is_some();
                match mip {
                    Some(m) => {
                        d.mipmap_filter = m;
                        d.lod_max_clamp = 32.0;
                    }
                    None => {
                        d.mipmap_filter = MipmapFilterMode::Nearest;
                        d.lod_max_clamp = SamplerParams::NO_MIPMAPS_MAX_LOD;
                    }
                }
            };
        match self {
            Self::FromFile => {}
            Self::Nearest => set(&mut d, FilterMode::Nearest, None),
            Self::Bilinear => set(&mut d, FilterMode::Linear, None),
            Self::Trilinear => set(&mut d, FilterMode::Linear, Some(MipmapFilterMode::Linear)),
            Self::Anisotropic(n) => {
                set(&mut d, FilterMode::Linear, Some(MipmapFilterMode::Linear));
                d.anisotropy_clamp = n.clamp(1, 16);
                d.anisotropic_filter = AnisotropicFilter::Probes;
            }
            Self::Ewa => {
                set(&mut d, FilterMode::Linear, Some(MipmapFilterMode::Linear));
                d.anisotropy_clamp = 16;
                d.anisotropic_filter = AnisotropicFilter::Ewa;
            }
        }
        ResolvedFilter {
            descriptor: d,
            mipmapped,
        }
    }
}

/// Anti-aliasing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AntiAliasing {
    /// One sample per pixel, at its centre.
    #[default]
    None,
    /// Supersampling on a regular `n × n` grid, shading every sample.
    Supersample(u32),
    /// Supersampling with `n × n` stratified positions jittered per pixel.
    Jitter(u32),
    /// MSAA with the standard positions for `n` samples (1, 2, 4, 8 or 16): coverage per
    /// sample, shading per pixel.
    Msaa(u32),
    /// Adaptive supersampling up to `n` samples per pixel.
    Adaptive(u32),
}

/// Everything a render needs besides the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Which camera.
    pub camera: CameraChoice,
    /// Lighting model.
    pub shading: Shading,
    /// Texture filter.
    pub filter: Filter,
    /// Anti-aliasing.
    pub anti_aliasing: AntiAliasing,
    /// Background colour (linear, straight alpha).
    pub background: Vec4,
    /// Exponential fog (Euclidean distance from the eye) over lit and unlit surfaces; `None`:
    /// clear air.
    pub fog: Option<barytex_shade::ExponentialFog>,
    /// Also time every pass again with a constant fragment shader into a scratch copy of the
    /// target, to split the draw time into rasterization and shading
    /// ([`RenderStats::raster_seconds`](super::RenderStats::raster_seconds)). Costs about one
    /// more draw; the image is unchanged.
    pub measure_stages: bool,
    /// How many portals deep a view may look (the scene's
    /// [`Portal`](barytex_gltf::Portal)s: a view through a mirror that sees another mirror is
    /// 2 deep); a portal seen at this depth shows the background under its tint. 0 draws every
    /// portal closed.
    pub portal_depth: u32,
}

impl Default for RenderOptions {
    /// 800 × 600, the first camera, Blinn–Phong, the files' filters, no anti-aliasing, a
    /// mid-grey background, no fog, portals 4 deep.
    fn default() -> Self {
        Self {
            width: 800,
            height: 600,
            camera: CameraChoice::First,
            shading: Shading::Phong,
            filter: Filter::FromFile,
            anti_aliasing: AntiAliasing::None,
            background: Vec4::new(0.18, 0.18, 0.2, 1.0),
            fog: None,
            measure_stages: false,
            portal_depth: 4,
        }
    }
}
