//! Metallic-roughness materials (glTF 2.0 §3.9) with `KHR_materials_unlit` and
//! `KHR_texture_transform`. Texture references keep the texture index, the UV set and the UV
//! transform as one [`TexCoordMapping`] (a 3×3 matrix), so a renderer applies
//! `uv' = (M · (u, v, 1)).xy` through barytex-uv's mapping seam and nothing else.

use barytex_uv::mappings::TexCoordMapping;
use glam::{Vec2, Vec3, Vec4};

use crate::SceneError;
use crate::json::{Obj, as_obj};
use crate::sampler::SamplerParams;

/// How alpha is interpreted (`alphaMode`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum AlphaMode {
    /// Alpha ignored, fully opaque (the default).
    #[default]
    Opaque,
    /// Alpha compared against `cutoff`: below is transparent, at or above opaque.
    Mask {
        /// `alphaCutoff`, default 0.5.
        cutoff: f32,
    },
    /// Alpha-blended.
    Blend,
}

/// A material's reference to a texture (`textureInfo`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextureRef {
    /// Index into the document's `textures`.
    pub texture: usize,
    /// Index into the document's `images` (the texture's `source`); `None` when the texture
    /// has no core source (only an extension's, e.g. `EXT_texture_webp`).
    pub image: Option<usize>,
    /// The texture's sampler (defaults when it has none).
    pub sampler: SamplerParams,
    /// How the texture is mapped: which `TEXCOORD_n` set to read (after any
    /// `KHR_texture_transform` override) through the `KHR_texture_transform` matrix (identity
    /// when absent) — a [`UvMapping`](barytex_uv::UvMapping) a renderer evaluates per pixel.
    pub mapping: TexCoordMapping,
}

/// The part a texture plays in a metallic-roughness material (glTF 2.0 §3.9.2–§3.9.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TextureRole {
    /// `pbrMetallicRoughness.baseColorTexture` (sRGB).
    BaseColor,
    /// `emissiveTexture` (sRGB).
    Emissive,
    /// `pbrMetallicRoughness.metallicRoughnessTexture` (linear).
    MetallicRoughness,
    /// `normalTexture` (linear).
    Normal,
    /// `occlusionTexture` (linear).
    Occlusion,
}

impl TextureRole {
    /// Every role.
    pub const ALL: [Self; 5] = [
        Self::BaseColor,
        Self::Emissive,
        Self::MetallicRoughness,
        Self::Normal,
        Self::Occlusion,
    ];
}

/// A set of [`TextureRole`]s: which textures a loader decodes
/// ([`LoadOptions::image_roles`](crate::LoadOptions::image_roles)).
///
/// ```
/// use barytex_gltf::{TextureRole, TextureRoles};
///
/// let unlit = TextureRoles::NONE.with(TextureRole::BaseColor);
/// assert!(unlit.contains(TextureRole::BaseColor));
/// assert!(!unlit.contains(TextureRole::Normal));
/// assert!(TextureRoles::ALL.contains(TextureRole::Normal));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TextureRoles(u8);

impl TextureRoles {
    /// No texture.
    pub const NONE: Self = Self(0);
    /// Every texture.
    pub const ALL: Self = Self(0b1_1111);

    const fn bit(role: TextureRole) -> u8 {
        1 << (role as u8)
    }

    /// This set with `role` added.
    #[must_use]
    pub const fn with(self, role: TextureRole) -> Self {
        Self(self.0 | Self::bit(role))
    }

    /// Whether `role` is in the set.
    #[must_use]
    pub const fn contains(self, role: TextureRole) -> bool {
        self.0 & Self::bit(role) != 0
    }
}

impl Default for TextureRoles {
    /// Every texture.
    fn default() -> Self {
        Self::ALL
    }
}

/// A material, with the specification's defaults filled in.
///
/// ```
/// use barytex_gltf::{AlphaMode, LoadOptions, load_slice};
/// use glam::Vec4;
///
/// let gltf = br#"{"asset": {"version": "2.0"}, "materials": [
///   {"name": "leaf", "alphaMode": "MASK", "doubleSided": true,
///    "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.6, 0.1, 1], "metallicFactor": 0}}]}"#;
/// let scene = load_slice(gltf, &LoadOptions::default())?;
/// let leaf = scene.material(Some(0));
/// assert_eq!(leaf.alpha_mode, AlphaMode::Mask { cutoff: 0.5 }); // the default cutoff
/// assert_eq!(leaf.base_color_factor, Vec4::new(0.2, 0.6, 0.1, 1.0));
/// assert_eq!((leaf.metallic_factor, leaf.roughness_factor), (0.0, 1.0));
/// assert!(leaf.double_sided && !leaf.unlit);
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// The material's name, if any.
    pub name: Option<String>,
    /// Linear base colour and alpha (default white, opaque).
    pub base_color_factor: Vec4,
    /// Base colour texture (sRGB).
    pub base_color_texture: Option<TextureRef>,
    /// Metalness (default 1).
    pub metallic_factor: f32,
    /// Roughness (default 1).
    pub roughness_factor: f32,
    /// Metallic (B) / roughness (G) texture (linear).
    pub metallic_roughness_texture: Option<TextureRef>,
    /// Tangent-space normal map (linear).
    pub normal_texture: Option<TextureRef>,
    /// Scale of the normal map's X and Y (default 1).
    pub normal_scale: f32,
    /// Ambient occlusion (R channel, linear).
    pub occlusion_texture: Option<TextureRef>,
    /// How much occlusion applies (default 1).
    pub occlusion_strength: f32,
    /// Emitted linear colour (default black).
    pub emissive_factor: Vec3,
    /// Emissive texture (sRGB).
    pub emissive_texture: Option<TextureRef>,
    /// Alpha interpretation.
    pub alpha_mode: AlphaMode,
    /// Whether back faces are rendered (and lit with a flipped normal).
    pub double_sided: bool,
    /// `KHR_materials_unlit`: shade with the base colour only.
    pub unlit: bool,
}

impl Default for Material {
    /// The default material glTF prescribes for primitives without one.
    fn default() -> Self {
        Self {
            name: None,
            base_color_factor: Vec4::ONE,
            base_color_texture: None,
            metallic_factor: 1.0,
            roughness_factor: 1.0,
            metallic_roughness_texture: None,
            normal_texture: None,
            normal_scale: 1.0,
            occlusion_texture: None,
            occlusion_strength: 1.0,
            emissive_factor: Vec3::ZERO,
            emissive_texture: None,
            alpha_mode: AlphaMode::Opaque,
            double_sided: false,
            unlit: false,
        }
    }
}

impl Material {
    /// Every texture reference with the colour space its image must be decoded in.
    ///
    /// ```
    /// use barytex_gltf::{Material, SamplerParams, TextureRef};
    /// use barytex_texture::load::ColorSpace;
    /// use barytex_uv::mappings::TexCoordMapping;
    ///
    /// let colour = TextureRef {
    ///     texture: 0,
    ///     image: Some(0),
    ///     sampler: SamplerParams::default(),
    ///     mapping: TexCoordMapping::new(0),
    /// };
    /// let normal = TextureRef { texture: 1, image: Some(1), ..colour };
    /// let m = Material { base_color_texture: Some(colour), normal_texture: Some(normal), ..Material::default() };
    /// // Colour is decoded as sRGB, a normal map as linear data.
    /// assert_eq!(m.texture_refs(), [(colour, ColorSpace::Srgb), (normal, ColorSpace::Linear)]);
    /// assert!(Material::default().texture_refs().is_empty());
    /// ```
    #[must_use]
    pub fn texture_refs(&self) -> Vec<(TextureRef, barytex_texture::load::ColorSpace)> {
        self.texture_roles()
            .into_iter()
            .map(|(_, t, cs)| (t, cs))
            .collect()
    }

    /// The texture references with the role each plays and the colour space it is decoded in,
    /// in [`texture_refs`](Self::texture_refs)' order.
    ///
    /// ```
    /// use barytex_gltf::{Material, TextureRole};
    ///
    /// assert!(Material::default().texture_roles().is_empty());
    /// assert_eq!(TextureRole::ALL.len(), 5);
    /// ```
    #[must_use]
    pub fn texture_roles(
        &self,
    ) -> Vec<(TextureRole, TextureRef, barytex_texture::load::ColorSpace)> {
        use barytex_texture::load::ColorSpace::{Linear, Srgb};
        [
            (TextureRole::BaseColor, self.base_color_texture, Srgb),
            (TextureRole::Emissive, self.emissive_texture, Srgb),
            (
                TextureRole::MetallicRoughness,
                self.metallic_roughness_texture,
                Linear,
            ),
            (TextureRole::Normal, self.normal_texture, Linear),
            (TextureRole::Occlusion, self.occlusion_texture, Linear),
        ]
        .into_iter()
        .filter_map(|(role, t, cs)| t.map(|t| (role, t, cs)))
        .collect()
    }

    /// Reads `/materials/i`; `textures` maps a texture index to its image and sampler.
    pub(crate) fn parse(
        obj: Obj<'_>,
        textures: &[(Option<usize>, SamplerParams)],
        warnings: &mut Vec<String>,
    ) -> Result<Self, SceneError> {
        let mut m = Self {
            name: obj.opt_str("name")?.map(str::to_owned),
            ..Self::default()
        };
        if let Some(pbr) = obj.opt_obj("pbrMetallicRoughness")? {
            let ptr = obj.at("pbrMetallicRoughness");
            let pbr = as_obj(pbr, &ptr)?;
            if let Some(f) = pbr.opt_f32s::<4>("baseColorFactor")? {
                if f.iter().any(|c| !(0.0..=1.0).contains(c)) {
                    return Err(pbr.error("baseColorFactor", "components must be in [0, 1]"));
                }
                m.base_color_factor = Vec4::from(f);
            }
            m.metallic_factor = unit(pbr, "metallicFactor", 1.0)?;
            m.roughness_factor = unit(pbr, "roughnessFactor", 1.0)?;
            m.base_color_texture = texture_ref(pbr, "baseColorTexture", textures)?;
            m.metallic_roughness_texture = texture_ref(pbr, "metallicRoughnessTexture", textures)?;
        }
        if let Some(f) = obj.opt_f32s::<3>("emissiveFactor")? {
            if f.iter().any(|c| !(0.0..=1.0).contains(c)) {
                return Err(obj.error("emissiveFactor", "components must be in [0, 1]"));
            }
            m.emissive_factor = Vec3::from(f);
        }
        m.emissive_texture = texture_ref(obj, "emissiveTexture", textures)?;
        m.normal_texture = texture_ref(obj, "normalTexture", textures)?;
        if let Some(n) = obj.opt_obj("normalTexture")? {
            let ptr = obj.at("normalTexture");
            m.normal_scale = as_obj(n, &ptr)?.opt_f32("scale")?.unwrap_or(1.0);
        }
        m.occlusion_texture = texture_ref(obj, "occlusionTexture", textures)?;
        if let Some(o) = obj.opt_obj("occlusionTexture")? {
            let ptr = obj.at("occlusionTexture");
            m.occlusion_strength = unit(as_obj(o, &ptr)?, "strength", 1.0)?;
        }
        let cutoff = obj.opt_f32("alphaCutoff")?;
        if cutoff.is_some_and(|c| c < 0.0) {
            return Err(obj.error("alphaCutoff", "alphaCutoff must be ≥ 0"));
        }
        m.alpha_mode = match obj.opt_str("alphaMode")? {
            None | Some("OPAQUE") => AlphaMode::Opaque,
            Some("MASK") => AlphaMode::Mask {
                cutoff: cutoff.unwrap_or(0.5),
            },
            Some("BLEND") => AlphaMode::Blend,
            Some(other) => {
                warnings.push(format!(
                    "{}: unknown alphaMode {other:?}, treated as OPAQUE",
                    obj.at("alphaMode")
                ));
                AlphaMode::Opaque
            }
        };
        m.double_sided = obj.opt_bool("doubleSided")?.unwrap_or(false);
        m.unlit = obj.extension("KHR_materials_unlit")?.is_some();
        check_pbr_extension_ranges(obj)?;
        Ok(m)
    }
}

/// How a numeric property of a PBR extension is bounded.
#[derive(Clone, Copy)]
enum Range {
    Unit,
    NonNegative,
    Positive,
    /// `KHR_materials_ior`: 0 or at least 1.
    Ior,
}

/// The numeric bounds of the Khronos PBR extensions. They are not rendered by this crate, but
/// out-of-range values mark a broken file (the validator's VALUE_NOT_IN_RANGE).
const PBR_EXTENSION_RANGES: &[(&str, &str, Range)] = &[
    (
        "KHR_materials_anisotropy",
        "anisotropyStrength",
        Range::Unit,
    ),
    ("KHR_materials_clearcoat", "clearcoatFactor", Range::Unit),
    (
        "KHR_materials_clearcoat",
        "clearcoatRoughnessFactor",
        Range::Unit,
    ),
    ("KHR_materials_dispersion", "dispersion", Range::NonNegative),
    (
        "KHR_materials_emissive_strength",
        "emissiveStrength",
        Range::NonNegative,
    ),
    ("KHR_materials_ior", "ior", Range::Ior),
    (
        "KHR_materials_iridescence",
        "iridescenceFactor",
        Range::Unit,
    ),
    ("KHR_materials_sheen", "sheenRoughnessFactor", Range::Unit),
    ("KHR_materials_sheen", "sheenColorFactor", Range::Unit),
    ("KHR_materials_specular", "specularFactor", Range::Unit),
    (
        "KHR_materials_specular",
        "specularColorFactor",
        Range::NonNegative,
    ),
    (
        "KHR_materials_transmission",
        "transmissionFactor",
        Range::Unit,
    ),
    (
        "KHR_materials_volume",
        "thicknessFactor",
        Range::NonNegative,
    ),
    (
        "KHR_materials_volume",
        "attenuationDistance",
        Range::Positive,
    ),
    ("KHR_materials_volume", "attenuationColor", Range::Unit),
];

fn check_pbr_extension_ranges(obj: Obj<'_>) -> Result<(), SceneError> {
    for &(ext, key, range) in PBR_EXTENSION_RANGES {
        let Some(e) = obj.extension(ext)? else {
            continue;
        };
        let ptr = crate::json::child(&obj.at("extensions"), ext);
        let e = as_obj(e, &ptr)?;
        let values: Vec<f32> = match e.get(key) {
            None => continue,
            Some(serde_json::Value::Array(items)) => items
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    crate::json::as_f32(v, &crate::json::child(&e.at(key), &i.to_string()))
                })
                .collect::<Result<_, _>>()?,
            Some(v) => vec![crate::json::as_f32(v, &e.at(key))?],
        };
        for v in values {
            let ok = match range {
                Range::Unit => (0.0..=1.0).contains(&v),
                Range::NonNegative => v >= 0.0,
                Range::Positive => v > 0.0,
                Range::Ior => v == 0.0 || v >= 1.0,
            };
            if !ok {
                return Err(e.error(key, format!("{v} is out of range")));
            }
        }
    }
    Ok(())
}

/// A factor in [0, 1] with a default.
fn unit(obj: Obj<'_>, key: &str, default: f32) -> Result<f32, SceneError> {
    let v = obj.opt_f32(key)?.unwrap_or(default);
    if !(0.0..=1.0).contains(&v) {
        return Err(obj.error(key, format!("{v} outside [0, 1]")));
    }
    Ok(v)
}

/// Reads a `textureInfo` (with its `KHR_texture_transform`).
fn texture_ref(
    parent: Obj<'_>,
    key: &str,
    textures: &[(Option<usize>, SamplerParams)],
) -> Result<Option<TextureRef>, SceneError> {
    let Some(info) = parent.opt_obj(key)? else {
        return Ok(None);
    };
    let ptr = parent.at(key);
    let info = as_obj(info, &ptr)?;
    let texture = info.req_index("index", textures.len(), "texture")?;
    let (image, sampler) = textures
        .get(texture)
        .copied()
        .ok_or_else(|| info.error("index", "unresolved texture"))?;
    let mut tex_coord = u32::try_from(info.opt_u64("texCoord")?.unwrap_or(0))
        .map_err(|_| info.error("texCoord", "texCoord out of range"))?;
    let mut transform = None;
    if let Some(tt) = info.extension("KHR_texture_transform")? {
        let tptr = crate::json::child(&info.at("extensions"), "KHR_texture_transform");
        let tt = as_obj(tt, &tptr)?;
        let offset = tt.opt_f32s::<2>("offset")?.map_or(Vec2::ZERO, Vec2::from);
        let rotation = tt.opt_f32("rotation")?.unwrap_or(0.0);
        let scale = tt.opt_f32s::<2>("scale")?.map_or(Vec2::ONE, Vec2::from);
        transform = Some((offset, rotation, scale));
        if let Some(tc) = tt.opt_u64("texCoord")? {
            tex_coord =
                u32::try_from(tc).map_err(|_| tt.error("texCoord", "texCoord out of range"))?;
        }
    }
    let mapping = match transform {
        Some((offset, rotation, scale)) => {
            TexCoordMapping::khr_texture_transform(tex_coord, offset, rotation, scale)
        }
        None => TexCoordMapping::new(tex_coord),
    };
    Ok(Some(TextureRef {
        texture,
        image,
        sampler,
        mapping,
    }))
}
