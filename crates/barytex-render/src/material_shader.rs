//! The shader a scene's primitives are drawn with: glTF's base colour (factor × texture ×
//! vertex colour), alpha modes, emission, occlusion, and per-pixel Blinn–Phong under the
//! scene's punctual lights — or glTF's unlit model.

use std::borrow::Cow;

use barytex_raster::{Fragment, Shader};
use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};

use crate::surface::{Reads, Surface};
use crate::textures::{PreparedTexture, Slot};
use barytex_gltf::light::LightKind;
use barytex_gltf::material::AlphaMode;

/// A light in world space, ready to evaluate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WorldLight {
    pub(crate) kind: LightKind,
    /// Colour × intensity.
    pub(crate) radiance: Vec3,
    pub(crate) position: Vec3,
    /// Where the light points (unit).
    pub(crate) direction: Vec3,
    pub(crate) range: Option<f32>,
}

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

/// Where lighting is evaluated (seed 001/004's shading frequencies).
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
    pub(crate) lights: &'a [WorldLight],
    pub(crate) ambient: Vec3,
}

/// glTF's recommended range falloff for punctual lights, times the inverse square law.
fn distance_attenuation(distance: f32, range: Option<f32>) -> f32 {
    let d2 = (distance * distance).max(1e-8);
    let window = range.map_or(1.0, |r| {
        let x = distance / r;
        (1.0 - x * x * x * x).clamp(0.0, 1.0)
    });
    window / d2
}

/// KHR_lights_punctual's smooth spot cone.
fn cone_attenuation(cos_angle: f32, inner: f32, outer: f32) -> f32 {
    let (cos_outer, cos_inner) = (outer.cos(), inner.cos());
    let scale = 1.0 / (cos_inner - cos_outer).max(1e-3);
    let t = ((cos_angle - cos_outer) * scale).clamp(0.0, 1.0);
    t * t
}

impl MaterialShader<'_> {
    /// The parts of the varying [`fragment`](Shader::fragment) reads for this material,
    /// primitive and shading frequency; only those are interpolated.
    pub(crate) fn reads(&self) -> Reads {
        #[cfg(test)]
        if crate::surface::INTERPOLATE_ALL.load(std::sync::atomic::Ordering::Relaxed) {
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
        let uses_set = |set: u32| {
            slots
                .iter()
                .flatten()
                .any(|s| (s.tex_coord == 1) == (set == 1))
        };
        Reads::default()
            .with_if(Reads::POSITION, m.lit || self.fog.is_some())
            .with_if(Reads::NORMAL, per_pixel_normal)
            .with_if(Reads::UV0, uses_set(0))
            .with_if(Reads::UV1, uses_set(1))
            .with_if(Reads::COLOR, p.colors.is_some())
            .with_if(Reads::LIGHT, per_vertex_light)
            .with_if(Reads::TANGENT, normal_mapped)
    }

    fn light_terms(&self, n: Vec3, view: Vec3, position: Vec3, shininess: f32) -> (Vec3, Vec3) {
        light_terms(self.lights, n, view, position, shininess)
    }

    /// Blinn–Phong exponent from glTF's roughness.
    fn shininess(roughness: f32) -> f32 {
        shininess(roughness)
    }

    fn fogged(&self, colour: Vec3, position: Vec3) -> Vec3 {
        match self.fog {
            Some((fog, forward)) => fog.apply(colour, self.eye, forward, position),
            None => colour,
        }
    }
}

/// The lights' diffuse (already divided by π) and specular (normalized Blinn–Phong lobe)
/// contributions at `position` with unit normal `n`, before the material's colours.
pub(crate) fn light_terms(
    lights: &[WorldLight],
    n: Vec3,
    view: Vec3,
    position: Vec3,
    shininess: f32,
) -> (Vec3, Vec3) {
    {
        let (mut diffuse, mut specular) = (Vec3::ZERO, Vec3::ZERO);
        for light in lights {
            let (l, attenuation) = match light.kind {
                LightKind::Directional => (-light.direction, 1.0),
                LightKind::Point | LightKind::Spot { .. } => {
                    let to_light = light.position - position;
                    let d = to_light.length();
                    let l = to_light / d.max(1e-12);
                    let mut a = distance_attenuation(d, light.range);
                    if let LightKind::Spot {
                        inner_cone_angle,
                        outer_cone_angle,
                    } = light.kind
                    {
                        a *= cone_attenuation(
                            light.direction.dot(-l),
                            inner_cone_angle,
                            outer_cone_angle,
                        );
                    }
                    (l, a)
                }
            };
            let n_dot_l = n.dot(l);
            if n_dot_l <= 0.0 || attenuation <= 0.0 {
                continue;
            }
            let irradiance = light.radiance * (n_dot_l * attenuation);
            let h = (l + view).normalize_or_zero();
            let lobe = (shininess + 8.0) / (8.0 * std::f32::consts::PI)
                * n.dot(h).max(0.0).powf(shininess);
            diffuse += irradiance / std::f32::consts::PI;
            specular += irradiance * lobe;
        }
        (diffuse, specular)
    }
}

/// Blinn–Phong exponent from glTF's roughness (α = roughness², n = 2/α² − 2).
pub(crate) fn shininess(roughness: f32) -> f32 {
    let alpha_r = (roughness * roughness).clamp(0.02, 1.0);
    (2.0 / (alpha_r * alpha_r) - 2.0).max(1.0)
}

impl MaterialShader<'_> {
    fn sample(
        &self,
        slot: Option<Slot>,
        s: &Surface,
        ddx: &Surface,
        ddy: &Surface,
    ) -> Option<Vec4> {
        let slot = slot?;
        let texture = self.textures.get(slot.texture)?;
        let (uv, dx, dy) = if slot.tex_coord == 1 {
            (s.uv1, ddx.uv1, ddy.uv1)
        } else {
            (s.uv0, ddx.uv0, ddy.uv0)
        };
        let t: Mat3 = slot.transform;
        let uv = (t * uv.extend(1.0)).truncate();
        let (dx, dy) = (
            (t * dx.extend(0.0)).truncate(),
            (t * dy.extend(0.0)).truncate(),
        );
        Some(texture.sample(uv, dx, dy))
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
            let shininess = Self::shininess(self.material.roughness);
            (surface.diffuse, surface.specular) = self.light_terms(n, view, position, shininess);
        }
        (self.view_projection * position.extend(1.0), surface)
    }

    fn fragment(&self, f: &Fragment<'_, Surface>) -> Option<Vec4> {
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
            (f.ddx(), f.ddy())
        } else {
            (Surface::default(), Surface::default())
        };
        let mut base = m.base_color * s.color;
        if let Some(t) = self.sample(m.base_texture, &s, &ddx, &ddy) {
            base *= t;
        }
        let alpha = match m.alpha_mode {
            AlphaMode::Opaque => 1.0,
            AlphaMode::Mask { cutoff } => {
                if base.w < cutoff {
                    return None;
                }
                1.0
            }
            AlphaMode::Blend => base.w,
        };
        if !m.lit {
            return Some(self.fogged(base.truncate(), s.position).extend(alpha));
        }
        let view = (self.eye - s.position).normalize_or_zero();
        let (mut metallic, mut roughness) = (m.metallic, m.roughness);
        if let Some(t) = self.sample(m.metallic_roughness_texture, &s, &ddx, &ddy) {
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
                && let Some(t) = self.sample(m.normal_texture, &s, &ddx, &ddy)
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
            self.light_terms(n, view, s.position, Self::shininess(roughness))
        };
        let mut color = albedo * diffuse + specular_color * specular;
        // Environment mapping (seed 000): the reflected ray looks the panorama up, weighted by
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
        if let Some(o) = self.sample(m.occlusion_texture, &s, &ddx, &ddy) {
            ambient *= 1.0 + m.occlusion_strength * (o.x - 1.0);
        }
        let mut emissive = m.emissive;
        if let Some(e) = self.sample(m.emissive_texture, &s, &ddx, &ddy) {
            emissive *= e.truncate();
        }
        Some(
            self.fogged(color + ambient + emissive, s.position)
                .extend(alpha),
        )
    }
}
