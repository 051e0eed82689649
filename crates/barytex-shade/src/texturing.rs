//! Textures in the shading (Buss, *3D Computer Graphics*, 2003, ch. V; L. Yan, GAMES101,
//! Lecture 9): a colour texture can **replace** the colour, **modulate** the lit colour afterwards,
//! or be an **input to lighting** (diffuse or specular reflectance, shininess); a normal map or a
//! bump map perturbs the normal before lighting; an environment map adds the mirrored surroundings.
//! [`SurfaceShader`] does all of these per pixel (Phong shading), each optional.

use barytex_raster::{Fragment, Shader};
use barytex_texture::Sampler;
use glam::{Vec2, Vec3, Vec4};

use crate::environment::{Environment, reflection_direction};
use crate::perturb::{HeightField, bump_normal, decode_normal, perturb_normal};
use crate::{ShadeContext, ShadeVertex};

/// What a colour texture does.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum TextureUse {
    /// The texture's colour is the result: no lighting (decals, baked lighting).
    Replace,
    /// The lit colour is multiplied by the texture afterwards (modulation after lighting).
    Modulate,
    /// The texture is `k_d` (and `k_a`): the diffuse shader of L. Yan's GAMES101, Lecture 9,
    /// `kd = texture(uv); kd *= clamp(N·L, 0, 1)`. Highlights stay the light's colour, unlike
    /// [`Modulate`](Self::Modulate). The default.
    #[default]
    Diffuse,
    /// The texture is `k_s` (a specular or gloss map).
    Specular,
    /// The texture's red channel times `max` is the shininess `n`.
    Shininess {
        /// Shininess for a texel of 1.
        max: f32,
    },
}

/// Per-pixel lighting with optional colour texture, normal map, bump map and environment map.
///
/// Varying: world position, normal, uv and tangent; the uv derivatives the samplers need (and
/// the position derivatives bump mapping needs) come from the rasterizer's exact `ddx`/`ddy`.
#[derive(Clone, Copy)]
pub struct SurfaceShader<'a> {
    /// Camera, lights, material (textures override parts of it).
    pub scene: &'a ShadeContext,
    /// A colour texture and its use.
    pub colour: Option<(&'a (dyn Sampler + Sync), TextureUse)>,
    /// A tangent-space normal map (linear RGB).
    pub normal_map: Option<&'a (dyn Sampler + Sync)>,
    /// A height field and its scale (world units per unit of height).
    pub bump: Option<(&'a (dyn HeightField + Sync), f32)>,
    /// An environment map and how much of it the surface mirrors (0 … 1).
    pub environment: Option<(Environment<'a>, f32)>,
}

impl core::fmt::Debug for SurfaceShader<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("SurfaceShader")
            .field("colour", &self.colour.map(|c| c.1))
            .field("normal_map", &self.normal_map.is_some())
            .field("bump", &self.bump.map(|b| b.1))
            .field("environment", &self.environment)
            .finish()
    }
}

impl<'a> SurfaceShader<'a> {
    /// Plain Phong shading of `scene`: add maps with struct update syntax.
    ///
    /// ```
    /// use barytex_raster::{draw, Framebuffer, PipelineState, TargetLimits};
    /// use barytex_shade::{mesh_vertices, Camera, Light, PhongMaterial, ShadeContext, SurfaceShader, TextureUse, ViewVector};
    /// use barytex_texture::procedural::Checkerboard;
    /// use glam::{Vec3, Vec4};
    ///
    /// let scene = ShadeContext {
    ///     camera: Camera::look_at(Vec3::Z * 3.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0).expect("ok"),
    ///     lights: vec![Light::Directional { direction: -Vec3::Z, color: Vec3::ONE }],
    ///     ambient: Vec3::splat(0.1),
    ///     material: PhongMaterial::default(),
    ///     view: ViewVector::Local,
    /// };
    /// let checker = Checkerboard { even: Vec4::ONE, odd: Vec4::new(0.1, 0.1, 0.1, 1.0), checks: 8.0 };
    /// // A checkered sphere: the texture is the diffuse reflectance.
    /// let shader = SurfaceShader { colour: Some((&checker, TextureUse::Diffuse)), ..SurfaceShader::new(&scene) };
    /// let (vertices, indices) = mesh_vertices(&barytex_uv::mesh::sphere(32, 16).expect("valid"));
    /// let mut fb = Framebuffer::new(64, 64, Vec4::ZERO, &TargetLimits::default())?;
    /// let stats = draw(&mut fb, &shader, &PipelineState::default(), &vertices, &indices);
    /// assert!(stats.fragments_shaded > 1000);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    #[must_use]
    pub fn new(scene: &'a ShadeContext) -> Self {
        Self {
            scene,
            colour: None,
            normal_map: None,
            bump: None,
            environment: None,
        }
    }

    /// The shading normal at one pixel: the interpolated normal renormalized, then bumped and
    /// normal-mapped.
    fn normal(&self, f: &Fragment<'_, SurfaceVarying>, duv: Option<(Vec2, Vec2)>) -> Vec3 {
        let (p, n, uv, t) = f.varying;
        let _ = p;
        let mut n = n.normalize_or_zero();
        if let (Some((height, scale)), Some((du_dx, du_dy))) = (self.bump, duv) {
            let (dx, dy) = f.derivatives();
            // Central differences of the height over the pixel's footprint in uv.
            let h = |q: Vec2| height.height(q) * scale;
            let dhdx = h(uv + du_dx * 0.5) - h(uv - du_dx * 0.5);
            let dhdy = h(uv + du_dy * 0.5) - h(uv - du_dy * 0.5);
            n = bump_normal(n, dx.0, dy.0, dhdx, dhdy);
        }
        if let (Some(map), Some((du_dx, du_dy))) = (self.normal_map, duv) {
            let m = decode_normal(map.sample(uv, du_dx, du_dy).truncate());
            n = perturb_normal(n, t, m);
        }
        n
    }
}

/// Position, normal, uv, tangent.
pub type SurfaceVarying = (Vec3, Vec3, Vec2, Vec4);

impl Shader for SurfaceShader<'_> {
    type Vertex = ShadeVertex;
    type Varying = SurfaceVarying;
    fn vertex(&self, v: &ShadeVertex) -> (Vec4, SurfaceVarying) {
        (
            self.scene.clip(v.position),
            (v.position, v.normal, v.uv, v.tangent),
        )
    }

    fn fragment(&self, f: &Fragment<'_, SurfaceVarying>) -> Option<Vec4> {
        let needs_duv = self.colour.is_some() || self.normal_map.is_some() || self.bump.is_some();
        let duv = needs_duv.then(|| {
            let (dx, dy) = f.derivatives();
            (dx.2, dy.2)
        });
        let (p, _, uv, _) = f.varying;
        let n = self.normal(f, duv);
        let (du_dx, du_dy) = duv.unwrap_or_default();
        let texel = self.colour.map(|(s, u)| (s.sample(uv, du_dx, du_dy), u));
        let mut material = self.scene.material;
        match texel {
            Some((c, TextureUse::Replace)) => return Some(c),
            Some((c, TextureUse::Diffuse)) => {
                material.diffuse = c.truncate();
                material.ambient = c.truncate();
            }
            Some((c, TextureUse::Specular)) => material.specular = c.truncate(),
            Some((c, TextureUse::Shininess { max })) => material.shininess = c.x * max,
            Some((_, TextureUse::Modulate)) | None => {}
        }
        let mut colour = self.scene.light_with(&material, p, n).total();
        if let Some((c, TextureUse::Modulate)) = texel {
            colour *= c.truncate();
        }
        if let Some((env, k)) = self.environment {
            let eye = self.scene.camera.eye;
            let r = reflection_direction(p, n, eye);
            // The reflected ray's change per pixel, from the varying's derivatives.
            let (dx, dy) = f.derivatives();
            let rx = reflection_direction(p + dx.0, (n + dx.1).normalize_or_zero(), eye) - r;
            let ry = reflection_direction(p + dy.0, (n + dy.1).normalize_or_zero(), eye) - r;
            let e = env.sample(r, rx, ry).truncate();
            let k = k.clamp(0.0, 1.0);
            colour = colour * (1.0 - k) + e * k;
        }
        Some(colour.extend(1.0))
    }
}
