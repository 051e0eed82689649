//! The scene's lights as barytex-shade lights, and the one reflectance model every shading
//! mode evaluates with them: the normalized Blinn–Phong of [`barytex_shade::Specular`] with a
//! Lambertian `1/π` diffuse term. Flat, Gouraud, Phong and the hybrid's highlight test all call
//! barytex-shade; nothing here re-implements a light.

use std::f32::consts::{FRAC_1_PI, PI};

use barytex_gltf::light::{LightKind, SceneLight};
use barytex_shade::{
    Attenuation, Camera, Light, PhongMaterial, ShadeContext, Specular, SpotShape, ViewVector,
};
use glam::Vec3;

use crate::framing::RenderCamera;

/// A `KHR_lights_punctual` light placed in the world, as barytex-shade evaluates it: colour ×
/// intensity, glTF's range-windowed inverse-square falloff, the smooth spot cone.
#[must_use]
pub(crate) fn shade_light(light: &SceneLight) -> Light {
    let color = light.light.color * light.light.intensity;
    let attenuation = Attenuation::Punctual {
        range: light.light.range,
    };
    match light.light.kind {
        LightKind::Directional => Light::Directional {
            direction: light.direction,
            color,
        },
        LightKind::Point => Light::Point {
            position: light.position,
            color,
            attenuation,
        },
        LightKind::Spot {
            inner_cone_angle,
            outer_cone_angle,
        } => Light::Spot {
            position: light.position,
            direction: light.direction,
            color,
            attenuation,
            shape: SpotShape::Cone {
                inner: inner_cone_angle,
                outer: outer_cone_angle,
            },
        },
    }
}

/// The scene's lights in world space; a headlight (a directional light of irradiance π along
/// the view direction) when it has none.
#[must_use]
pub(crate) fn world_lights(lights: &[SceneLight], camera: &RenderCamera) -> Vec<Light> {
    let mut out: Vec<Light> = lights.iter().map(shade_light).collect();
    if out.is_empty() {
        out.push(Light::Directional {
            direction: camera.forward(),
            color: Vec3::splat(PI),
        });
    }
    out
}

/// Blinn–Phong exponent from glTF's roughness (α = roughness², n = 2/α² − 2).
#[must_use]
pub(crate) fn shininess(roughness: f32) -> f32 {
    let alpha_r = (roughness * roughness).clamp(0.02, 1.0);
    (2.0 / (alpha_r * alpha_r) - 2.0).max(1.0)
}

/// The reflectance the renderer lights glTF materials with, before their colours: diffuse
/// `1/π` (Lambert) and the normalized Blinn–Phong lobe of exponent `shininess`.
#[must_use]
fn brdf(shininess: f32) -> PhongMaterial {
    PhongMaterial {
        emission: Vec3::ZERO,
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(FRAC_1_PI),
        specular: Vec3::ONE,
        shininess,
        lobe: Specular::NormalizedBlinnPhong,
    }
}

/// The lights' diffuse and specular light at `position` with unit normal `n`, seen along the
/// unit `view`, before the material's albedo and specular colour multiply them.
#[must_use]
pub(crate) fn light_terms(
    lights: &[Light],
    n: Vec3,
    view: Vec3,
    position: Vec3,
    shininess: f32,
) -> (Vec3, Vec3) {
    let lit = brdf(shininess).shade(position, n, view, lights, Vec3::ZERO);
    (lit.diffuse, lit.specular)
}

/// The highlight test's view of one material: the same lights and the same lobe the shader
/// evaluates, weighted by the material's specular colour `f0`.
#[must_use]
pub(crate) fn highlight_context(
    camera: &RenderCamera,
    lights: &[Light],
    f0: Vec3,
    roughness: f32,
) -> ShadeContext {
    ShadeContext {
        camera: Camera {
            eye: camera.eye,
            view: camera.view,
            projection: camera.projection,
        },
        lights: lights.to_vec(),
        ambient: Vec3::ZERO,
        material: PhongMaterial {
            diffuse: Vec3::ZERO,
            specular: f0,
            ..brdf(shininess(roughness))
        },
        view: ViewVector::Local,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use barytex_gltf::light::PunctualLight;

    fn scene_light(kind: LightKind, range: Option<f32>) -> SceneLight {
        SceneLight {
            node: 0,
            light_index: 0,
            light: PunctualLight {
                name: None,
                kind,
                color: Vec3::new(1.0, 0.5, 0.25),
                intensity: 4.0,
                range,
            },
            world: glam::Mat4::IDENTITY,
            position: Vec3::new(0.0, 2.0, 0.0),
            direction: Vec3::NEG_Y,
        }
    }

    /// glTF's falloff and cone reach the shaders through barytex-shade: intensity 4 at distance
    /// 2 is 1 (inverse square), the range window cuts it off, the cone narrows it.
    #[test]
    fn punctual_lights_fall_off_as_gltf_specifies() {
        let point = shade_light(&scene_light(LightKind::Point, None));
        let s = point.sample(Vec3::ZERO).expect("regular");
        assert_eq!(s.intensity, Vec3::new(1.0, 0.5, 0.25));
        let ranged = shade_light(&scene_light(LightKind::Point, Some(2.0)));
        assert_eq!(
            ranged.sample(Vec3::ZERO).expect("regular").intensity,
            Vec3::ZERO
        );
        let cone = LightKind::Spot {
            inner_cone_angle: 0.1,
            outer_cone_angle: 0.2,
        };
        let spot = shade_light(&scene_light(cone, None));
        assert_eq!(
            spot.sample(Vec3::ZERO).expect("on axis").intensity,
            s.intensity
        );
        // 0.3 rad off the axis: outside the outer cone.
        let off = Vec3::new(2.0 * 0.3_f32.tan(), 0.0, 0.0);
        assert_eq!(spot.sample(off).expect("regular").intensity, Vec3::ZERO);
    }

    /// The diffuse term of a light straight above is E/π; the specular term at the mirror
    /// direction is the normalized lobe's peak (n + 8)/(8π) times E.
    #[test]
    fn light_terms_are_lambert_and_the_normalized_lobe() {
        let sun = [Light::Directional {
            direction: Vec3::NEG_Y,
            color: Vec3::splat(2.0),
        }];
        let (d, s) = light_terms(&sun, Vec3::Y, Vec3::Y, Vec3::ZERO, 16.0);
        assert!((d - Vec3::splat(2.0 / PI)).abs().max_element() < 1e-6);
        assert!(
            (s - Vec3::splat(2.0 * 24.0 / (8.0 * PI)))
                .abs()
                .max_element()
                < 1e-5
        );
    }
}
