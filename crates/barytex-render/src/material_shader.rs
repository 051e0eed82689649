//! The shader a scene's primitives are drawn with: glTF's base colour (factor × texture ×
//! vertex colour), alpha modes, emission, occlusion, and per-pixel Blinn–Phong under the
//! scene's punctual lights — or glTF's unlit model.

use std::borrow::Cow;

use barytex_gltf::material::AlphaMode;
use barytex_raster::{Fragment, Shader};
use barytex_shade::Light;
use barytex_texture::Sampler as _;
use barytex_uv::{SurfacePoint, UvMapping as _, UvSample};
use glam::{Mat4, Vec2, Vec3, Vec4};

use crate::lights::{light_terms, shininess};
use crate::surface::{Reads, Surface};
use crate::textures::{PreparedTexture, Slot};

/// A primitive's vertex data in world space.
pub(crate) struct WorldPrimitive<'a> {
    pub(crate) positions: Vec<Vec3>,
    pub(crate) normals: Option<Vec<Vec3>>,
    pub(crate) uv0: Option<Cow<'a, [Vec2]>>,
    pub(crate) uv1: Option<Cow<'a, [Vec2]>>,
    pub(crate) colors: Option<Cow<'a, [Vec4]>>,
    /// World-space tangents (bitangent sign in `w`), for normal-mapped materials.
    pub(crate) tangents: Option<Vec<Vec4>>,
    /// Flat shading: the (diffuse, specular) light each vertex carries, evaluated once per
    /// triangle (the vertices are unwelded, three per triangle).
    pub(crate) lighting: Option<Vec<(Vec3, Vec3)>>,
}

/// The material as the shader reads it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShaderMaterial {
    pub(crate) base_color: Vec4,
    pub(crate) base_texture: Option<Slot>,
    pub(crate) emissive: Vec3,
    pub(crate) emissive_texture: Option<Slot>,
    pub(crate) occlusion_texture: Option<Slot>,
    pub(crate) occlusion_strength: f32,
    /// glTF's tangent-space normal map and its `scale` (per-pixel shading only).
    pub(crate) normal_texture: Option<Slot>,
    pub(crate) normal_scale: f32,
    /// glTF's metallic-roughness texture: roughness in G, metallic in B (times the factors).
    pub(crate) metallic_roughness_texture: Option<Slot>,
    pub(crate) metallic: f32,
    pub(crate) roughness: f32,
    pub(crate) alpha_mode: AlphaMode,
    pub(crate) lit: bool,
}

/// Where lighting is evaluated: the shading frequencies of Foley, van Dam, Feiner and Hughes,
/// *Computer Graphics: Principles and Practice*, 2nd ed., §16.2 (constant, Gouraud, Phong).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Frequency {
    /// Once per polygon: the light each (unwelded) vertex carries, evaluated at the
    /// triangle's centroid with its face normal, constant across the triangle.
    Flat,
    /// At the vertices, interpolated (the texture still modulates per pixel).
    Gouraud,
    /// Per pixel with the interpolated, renormalized normal.
    Phong,
}

/// Draws one primitive.
pub(crate) struct MaterialShader<'a> {
    pub(crate) frequency: Frequency,
    /// The scene's equirectangular environment, reflected by smooth lit surfaces.
    pub(crate) environment: Option<&'a PreparedTexture>,
    /// Exponential fog over the final colour, with the camera's forward direction.
    pub(crate) fog: Option<(barytex_shade::ExponentialFog, Vec3)>,
    pub(crate) view_projection: Mat4,
    pub(crate) eye: Vec3,
    pub(crate) primitive: &'a WorldPrimitive<'a>,
    pub(crate) material: ShaderMaterial,
    pub(crate) textures: &'a [PreparedTexture],
    pub(crate) lights: &'a [Light],
    pub(crate) ambient: Vec3,
    /// Interpolate every part of the varying, read or not, and shade every material through
    /// the general path (tests compare it with the default, which interpolates only what
    /// [`reads`](MaterialShader::reads) names and takes the unlit short path).
    pub(crate) interpolate_all: bool,
}

/// The output alpha under glTF's alpha mode (§3.9.4 "Alpha Coverage") for a base colour of
/// alpha `alpha`: 1 when opaque or kept by the mask, the alpha when blended; `None` when the
/// mask discards the fragment.
pub(crate) fn coverage_alpha(mode: AlphaMode, alpha: f32) -> Option<f32> {
    match mode {
        AlphaMode::Opaque => Some(1.0),
        // Discarded below the cutoff only: a NaN alpha is kept (not `alpha >= cutoff`).
        AlphaMode::Mask { cutoff } => {
            if alpha < cutoff {
                None
            } else {
                Some(1.0)
            }
        }
        AlphaMode::Blend => Some(alpha),
    }
}

impl MaterialShader<'_> {
    /// The parts of the varying [`fragment`](Shader::fragment) reads for this material,
    /// primitive and shading frequency; only those are interpolated.
    pub(crate) fn reads(&self) -> Reads {
        if self.interpolate_all {
            return Reads::ALL;
        }
        let m = &self.material;
        let p = self.primitive;
        let has_normals = p.normals.is_some();
        let per_vertex_light = m.lit
            && match self.frequency {
                Frequency::Gouraud => has_normals,
                Frequency::Flat => p.lighting.is_some(),
                Frequency::Phong => false,
            };
        let per_pixel_normal = m.lit
            && has_normals
            && (self.frequency == Frequency::Phong || self.environment.is_some());
        let normal_mapped = m.lit
            && has_normals
            && self.frequency == Frequency::Phong
            && m.normal_texture.is_some()
            && p.tangents.is_some();
        let slots = [
            m.base_texture,
            m.emissive_texture,
            m.occlusion_texture,
            m.metallic_roughness_texture,
            m.normal_texture,
        ];
        let uses_set = |set: u32| slots.iter().flatten().any(|s| s.mapping.set == set);
        Reads::default()
            .with_if(Reads::POSITION, m.lit || self.fog.is_some())
            .with_if(Reads::NORMAL, per_pixel_normal)
            .with_if(Reads::UV0, uses_set(0))
            .with_if(Reads::UV1, uses_set(1))
            .with_if(Reads::COLOR, p.colors.is_some())
            .with_if(Reads::LIGHT, per_vertex_light)
            .with_if(Reads::TANGENT, normal_mapped)
    }

    /// Whether [`UnlitShader`](crate::unlit_shader::UnlitShader) draws what this shader
    /// would: an unlit material without fog, with only the parts it reads interpolated (tests
    /// interpolate everything to compare the two paths).
    pub(crate) fn takes_unlit_path(&self) -> bool {
        !self.material.lit && self.fog.is_none() && !self.interpolate_all
    }

    fn light_terms(&self, n: Vec3, view: Vec3, position: Vec3, shininess: f32) -> (Vec3, Vec3) {
        light_terms(self.lights, n, view, position, shininess)
    }

    fn fogged(&self, colour: Vec3, position: Vec3) -> Vec3 {
        match self.fog {
            Some((fog, forward)) => fog.apply(colour, self.eye, forward, position),
            None => colour,
        }
    }
}

impl MaterialShader<'_> {
    /// The pixel as the uv mappings see it: both vertex texture coordinate sets with their
    /// screen derivatives.
    fn surface_point(s: &Surface, ddx: &Surface, ddy: &Surface) -> SurfacePoint {
        let set = |uv: Vec2, dx: Vec2, dy: Vec2| UvSample {
            uv,
            duvdx: dx,
            duvdy: dy,
        };
        SurfacePoint::with_derivatives(s.position, s.normal, ddx.position, ddy.position)
            .with_tex_coords([set(s.uv0, ddx.uv0, ddy.uv0), set(s.uv1, ddx.uv1, ddy.uv1)])
    }

    /// The slot's texture through its uv mapping (the vertex set and `KHR_texture_transform`);
    /// `None` when the material has no such texture or the mapping is undefined at the pixel.
    fn sample(&self, slot: Option<Slot>, point: &SurfacePoint) -> Option<Vec4> {
        let slot = slot?;
        let texture = self.textures.get(slot.texture)?;
        Some(texture.sample_uv(&slot.mapping.map(point)?))
    }
}

impl Shader for MaterialShader<'_> {
    type Vertex = u32;
    type Varying = Surface;

    fn vertex(&self, &i: &u32) -> (Vec4, Surface) {
        let i = i as usize;
        let p = self.primitive;
        let position = p.positions.get(i).copied().unwrap_or(Vec3::NAN);
        let surface = Surface {
            position,
            normal: p
                .normals
                .as_ref()
                .and_then(|n| n.get(i))
                .copied()
                .unwrap_or_default(),
            uv0: p
                .uv0
                .as_ref()
                .and_then(|n| n.get(i))
                .copied()
                .unwrap_or_default(),
            uv1: p
                .uv1
                .as_ref()
                .and_then(|n| n.get(i))
                .copied()
                .unwrap_or_default(),
            color: p
                .colors
                .as_ref()
                .and_then(|n| n.get(i))
                .copied()
                .unwrap_or(Vec4::ONE),
            tangent: p
                .tangents
                .as_ref()
                .and_then(|t| t.get(i))
                .copied()
                .unwrap_or_default(),
            reads: self.reads(),
            ..Surface::default()
        };
        let mut surface = surface;
        if let Some(&(d, sp)) = p.lighting.as_ref().and_then(|l| l.get(i)) {
            (surface.diffuse, surface.specular) = (d, sp);
        } else if self.frequency == Frequency::Gouraud && self.material.lit && p.normals.is_some() {
            let n = surface.normal.normalize_or_zero();
            let view = (self.eye - position).normalize_or_zero();
            // Facing the eye, as the per-pixel path flips it for double-sided back faces.
            let n = if n.dot(view) < 0.0 { -n } else { n };
            let shininess = shininess(self.material.roughness);
            (surface.diffuse, surface.specular) = self.light_terms(n, view, position, shininess);
        }
        (self.view_projection * position.extend(1.0), surface)
    }

    /// Every material through one call (the unlit short path is [`UnlitShader`]'s, a shader
    /// of its own: the pixel loop inlines that one).
    ///
    /// [`UnlitShader`]: crate::unlit_shader::UnlitShader
    #[inline(always)]
    fn fragment(&self, f: &Fragment<'_, Surface>) -> Option<Vec4> {
        self.general(f)
    }
}

impl MaterialShader<'_> {
    /// [`fragment`](Shader::fragment) for every material and shading frequency.
    #[inline(never)]
    fn general(&self, f: &Fragment<'_, Surface>) -> Option<Vec4> {
        let s = f.varying;
        let m = &self.material;
        let needs_derivatives = m.base_texture.is_some()
            || m.emissive_texture.is_some()
            || m.occlusion_texture.is_some()
            || m.metallic_roughness_texture.is_some()
            || m.normal_texture.is_some()
            || self.environment.is_some()
            || (m.lit && (self.primitive.normals.is_none() || self.frequency == Frequency::Flat));
        let (ddx, ddy) = if needs_derivatives {
            f.derivatives()
        } else {
            (Surface::default(), Surface::default())
        };
        let point = Self::surface_point(&s, &ddx, &ddy);
        let mut base = m.base_color * s.color;
        if let Some(t) = self.sample(m.base_texture, &point) {
            base *= t;
        }
        let alpha = coverage_alpha(m.alpha_mode, base.w)?;
        if !m.lit {
            return Some(self.fogged(base.truncate(), s.position).extend(alpha));
        }
        let view = (self.eye - s.position).normalize_or_zero();
        let (mut metallic, mut roughness) = (m.metallic, m.roughness);
        if let Some(t) = self.sample(m.metallic_roughness_texture, &point) {
            roughness *= t.y;
            metallic *= t.z;
        }
        let albedo = base.truncate() * (1.0 - metallic);
        let specular_color = Vec3::splat(0.04).lerp(base.truncate(), metallic);
        let has_normals = self.primitive.normals.is_some();
        let per_vertex = match self.frequency {
            Frequency::Gouraud => has_normals,
            Frequency::Flat => self.primitive.lighting.is_some(),
            Frequency::Phong => false,
        };
        let (diffuse, specular) = if per_vertex {
            (s.diffuse, s.specular)
        } else {
            // The interpolated normal, or the face normal from the position's derivatives.
            let mut n = if has_normals && self.frequency == Frequency::Phong {
                s.normal.normalize_or_zero()
            } else {
                ddx.position.cross(ddy.position).normalize_or_zero()
            };
            if n.dot(view) < 0.0
                && (!f.front_facing || !has_normals || self.frequency == Frequency::Flat)
            {
                n = -n;
            }
            // Normal mapping: per pixel only (Gouraud and flat shading never see it).
            if self.frequency == Frequency::Phong
                && has_normals
                && s.tangent.truncate().length_squared() > 0.0
                && let Some(t) = self.sample(m.normal_texture, &point)
            {
                let mut tangent_space = barytex_shade::decode_normal(t.truncate());
                tangent_space.x *= m.normal_scale;
                tangent_space.y *= m.normal_scale;
                let tangent = s
                    .tangent
                    .truncate()
                    .normalize_or_zero()
                    .extend(s.tangent.w.signum());
                n = barytex_shade::perturb_normal(n, tangent, tangent_space);
            }
            self.light_terms(n, view, s.position, shininess(roughness))
        };
        let mut color = albedo * diffuse + specular_color * specular;
        // Environment mapping (Blinn and Newell, "Texture and reflection in computer generated
        // images", CACM 19(10), 1976): the reflected ray looks the panorama up, weighted by
        // smoothness; its screen derivatives come from the position's and normal's, so the
        // filter sees the footprint (a curved mirror minifies the panorama strongly).
        if let Some(env) = self.environment {
            let smooth = (1.0 - roughness) * (1.0 - roughness);
            let n = if has_normals {
                s.normal.normalize_or_zero()
            } else {
                ddx.position.cross(ddy.position).normalize_or_zero()
            };
            let reflect = |p: Vec3, n: Vec3| barytex_shade::reflection_direction(p, n, self.eye);
            let r = reflect(s.position, n);
            if smooth > 0.0 && r != Vec3::ZERO {
                let dx = reflect(
                    s.position + ddx.position,
                    (s.normal + ddx.normal).normalize_or_zero(),
                ) - r;
                let dy = reflect(
                    s.position + ddy.position,
                    (s.normal + ddy.normal).normalize_or_zero(),
                ) - r;
                let sky = barytex_shade::Environment::Equirect(env).sample(r, dx, dy);
                color += specular_color * sky.truncate() * smooth;
            }
        }
        let mut ambient = self.ambient * base.truncate();
        if let Some(o) = self.sample(m.occlusion_texture, &point) {
            ambient *= 1.0 + m.occlusion_strength * (o.x - 1.0);
        }
        let mut emissive = m.emissive;
        if let Some(e) = self.sample(m.emissive_texture, &point) {
            emissive *= e.truncate();
        }
        Some(
            self.fogged(color + ambient + emissive, s.position)
                .extend(alpha),
        )
    }
}
