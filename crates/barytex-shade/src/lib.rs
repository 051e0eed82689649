//! Shading, lighting and texturing techniques of the classic local illumination and shading
//! literature (see [References](#references)), as pure functions and as
//! [`barytex_raster::Shader`]s.
//!
//! | concept | items |
//! |---|---|
//! | lights | [`Light`] (directional, point, spot), [`SpotShape`] (Warn's `(cos α)^p`, glTF cones), [`Attenuation`] (`min(1/(c1 + c2 d + c3 d²), 1)`, or glTF's range-windowed `1/d²`) |
//! | illumination models | [`lambert`], [`phong_specular`], [`blinn_phong_specular`], [`normalized_blinn_phong_specular`], [`PhongMaterial`], [`Lighting`], [`Specular`] |
//! | camera and scene | [`Camera`] ([`camera::look_at`], [`camera::perspective`]), [`ShadeContext`], [`ViewVector`], [`ShadeVertex`], [`mesh_vertices`] |
//! | normals | [`face_normal`], [`vertex_normals`] ([`NormalWeighting`]: uniform, area, angle) |
//! | shading frequencies | flat ([`flat_vertices`] + [`ColouredShader`]), [`GouraudShader`], [`PhongShader`] (or [`SlerpPhongShader`]), Gouraud + Phong with the H-test ([`HighlightTest`], [`hybrid_vertices`], [`HybridShader`]), the exact-normal [`ReferenceShader`] |
//! | speed-ups | [`ViewVector::Constant`], [`PhongShader`] without renormalization, [`precomputed_vertex_colours`], fast approximate Phong ([`fast_phong_vertices`], [`FastPhongShader`], [`quadratic_interpolate`]) |
//! | texturing | [`SurfaceShader`] with [`TextureUse`] (replace, modulate, diffuse/specular/shininess input) |
//! | normal perturbation | [`decode_normal`], [`perturb_normal`] (normal maps), [`generate_tangents`] (MikkTSpace), [`bump_normal`] and [`HeightField`] (bump maps) |
//! | environment maps | [`Environment`] (cube, sphere map, equirect), [`DirectionSampler`], [`reflection_direction`] |
//! | displacement mapping | [`displace`] ([`Seams`]: weld copies across uv seams, or not) |
//! | octree rendering | [`Octree`], [`child_order`], [`render_back_to_front`] (no depth test), [`render_front_to_back`] with a [`CoverageQuadtree`], [`render_depth_tested`] |
//! | atmosphere | [`DepthCue`], [`ExponentialFog`] ([`FogDistance`]), [`HeightFog`], [`atmosphere::blend`] |
//!
//! Conventions: linear-light colours; `N` (normal), `L` (towards the light) and `V` (towards the
//! eye) are unit vectors pointing away from the surface; everything in one space of the
//! caller's choice (world space in the shaders). Nothing panics on NaN, infinite or zero-length
//! input: each function documents the value it returns instead, and no term is ever negative.
//!
//! # References
//! - J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, *Computer Graphics: Principles and
//!   Practice*, 2nd ed., Addison-Wesley, 1990, ch. 16 "Illumination and Shading": §16.1, the
//!   illumination models (emission `I = k_i`, ambient `I = I_a k_a`, Lambert's `I = I_p k_d
//!   (N·L)`, the attenuation `f_att = min(1/(c1 + c2 d + c3 d²), 1)`, depth cueing
//!   `I' = s0 I + (1 − s0) I_dc`, Phong's `I = I_p W(θ) (cos α)^n`, Warn's spotlight); §16.2,
//!   flat, Gouraud and Phong shading and the problems of interpolated shading.
//! - *Octreen piirtäminen. Huomioita portaalitekniikasta. Octree edestä taakse. Valaistus ja
//!   sävytys*, Finnish computer graphics lecture notes, pp. 272–295: octree drawing back to front
//!   and front to back, exponential and height-dependent fog, combined Gouraud and Phong shading
//!   with the five-stage highlight test (H-test), and the shading speed-ups.
//! - H. Gouraud, "Continuous shading of curved surfaces", *IEEE Transactions on Computers*
//!   C-20(6), 1971.
//! - B. T. Phong, "Illumination for computer generated pictures", *Communications of the ACM*
//!   18(6), 1975.
//! - J. F. Blinn, "Models of light reflection for computer synthesized pictures", *SIGGRAPH '77*
//!   (the half vector); "Simulation of wrinkled surfaces", *SIGGRAPH '78* (bump mapping).
//! - D. R. Warn, "Lighting controls for synthetic images", *SIGGRAPH '83*.
//! - G. Bishop, D. M. Weimer, "Fast Phong shading", *SIGGRAPH '86*.
//! - R. L. Cook, "Shade trees", *SIGGRAPH '84* (displacement mapping).
//! - J. F. Blinn, M. E. Newell, "Texture and reflection in computer generated images",
//!   *Communications of the ACM* 19(10), 1976; N. Greene, "Environment mapping and other
//!   applications of world projections", *IEEE Computer Graphics and Applications* 6(11), 1986.
//! - S. R. Buss, *3D Computer Graphics: A Mathematical Introduction with OpenGL*, Cambridge
//!   University Press, 2003, ch. V: the uses of a texture (replace the colour, modulate it after
//!   lighting, or feed the lighting), bump mapping (Figure V.8: needs Phong shading, not
//!   Gouraud), environment mapping.
//! - S. Schaefer, *Shading/Texturing*, lecture slides, Texas A&M University: the vertex normal
//!   `N_V = ΣN_k / |ΣN_k|`, renormalized normal interpolation, the reflected ray
//!   `r = 2(n·v)n − v` into a cube map whose faces are infinitely far, normal maps storing XYZ
//!   as RGB, displacement mapping and the cracks at chart seams.
//! - L. Yan, *GAMES101: Introduction to Modern Computer Graphics*, Lecture 9 "Shading 3 (Texture
//!   Mapping cont.)", 2020: the diffuse texture shader
//!   `kd = texture(uv); kd *= clamp(dot(−lightDir, n), 0, 1)`.
//! - L. J. Doctor, J. G. Torborg, "Display techniques for octree-encoded objects", *IEEE Computer
//!   Graphics and Applications* 1(3), 1981 (back-to-front octree traversal).
//!
//! ```
//! use barytex_shade::{Attenuation, Light, PhongMaterial};
//! use glam::Vec3;
//!
//! let lamp = Light::Point { position: Vec3::new(0.0, 0.0, 2.0), color: Vec3::ONE,
//!     attenuation: Attenuation::NONE };
//! let lit = PhongMaterial::default().shade(Vec3::ZERO, Vec3::Z, Vec3::Z, &[lamp], Vec3::splat(0.1));
//! // Ambient 0.07, diffuse 0.7, and the full highlight 0.3: the eye sits on the mirror ray.
//! assert!((lit.total() - Vec3::splat(1.07)).length() < 1e-6);
//! ```
#![forbid(unsafe_code)]

pub mod atmosphere;
mod attenuation;
pub mod camera;
mod context;
mod displacement;
mod environment;
mod frequency;
mod highlight;
mod light;
mod model;
mod normals;
mod octree;
mod perturb;
mod speedups;
mod texturing;

pub use atmosphere::{DepthCue, ExponentialFog, FogDistance, HeightFog};
pub use attenuation::Attenuation;
pub use camera::Camera;
pub use context::{ShadeContext, ShadeVertex, ViewVector, mesh_vertices};
pub use displacement::{Seams, displace};
pub use environment::{DirectionSampler, Environment, reflection_direction};
pub use frequency::{
    ColouredShader, ColouredVertex, GouraudShader, PhongShader, ReferenceShader, SlerpPhongShader,
    SlerpVertex, flat_vertices, slerp_triangle_normal, slerp_vertices,
};
pub use highlight::{
    HighlightTest, HighlightVerdict, HybridShader, HybridStats, HybridVertex, hybrid_vertices,
};
pub use light::{Light, LightSample, SpotShape};
pub use model::{
    Lighting, PhongMaterial, Specular, blinn_phong_specular, lambert,
    normalized_blinn_phong_specular, phong_specular,
};
pub use normals::{NormalWeighting, face_normal, vertex_normals};
pub use octree::{
    CoverageQuadtree, FrontToBackStats, Octree, Voxel, child_order, render_back_to_front,
    render_depth_tested, render_front_to_back,
};
pub use perturb::{HeightField, bump_normal, decode_normal, generate_tangents, perturb_normal};
pub use speedups::{
    FastPhongNodes, FastPhongShader, FastPhongVertex, fast_phong_vertices,
    precomputed_vertex_colours, quadratic_interpolate,
};
pub use texturing::{SurfaceShader, SurfaceVarying, TextureUse};

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
