//! What the rasterizer benchmarks share: a mesh already in clip space, a nearest-texel texture,
//! and the same shading written once for barytex's pipeline and once for euc's.

#![allow(dead_code)] // Each benchmark uses its part.

use barytex_raster::{
    ColorFormat, CullMode, Fragment, Framebuffer, PipelineState, SamplePattern, Shader,
    TargetLimits, draw, draw_cleared,
};
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use euc::{Pipeline, Target};
use glam::{Vec2, Vec3, Vec4};

/// Clip positions (z in [0, w]), uvs and normals per vertex; triangles as index triples.
pub(crate) struct ClipMesh {
    pub(crate) clip: Vec<Vec4>,
    pub(crate) uv: Vec<Vec2>,
    pub(crate) normal: Vec<Vec3>,
    pub(crate) indices: Vec<u32>,
}

/// Packed `0xAARRGGBB` texels, row-major from the top-left, looked up nearest with repeat (done
/// by hand on both sides, as euc's own example does, so the rasterizers are compared, not the
/// samplers).
pub(crate) struct NearestTexture {
    pub(crate) width: usize,
    pub(crate) height: usize,
    pub(crate) texels: Vec<u32>,
}

impl NearestTexture {
    /// A two-colour checker of `cell`-texel squares.
    pub(crate) fn checker(side: usize, cell: usize) -> Self {
        Self {
            width: side,
            height: side,
            texels: (0..side * side)
                .map(|i| {
                    let (x, y) = (i % side, i / side);
                    if (x / cell + y / cell).is_multiple_of(2) {
                        0xFFE0_E0E0
                    } else {
                        0xFF20_4080
                    }
                })
                .collect(),
        }
    }

    pub(crate) fn texel(&self, uv: Vec2) -> u32 {
        let wrap = |t: f32, n: usize| ((t - t.floor()) * n as f32) as usize % n.max(1);
        self.texels[wrap(uv.y, self.height) * self.width + wrap(uv.x, self.width)]
    }
}

pub(crate) fn unpack(c: u32) -> Vec4 {
    Vec4::new(
        ((c >> 16) & 0xff) as f32 / 255.0,
        ((c >> 8) & 0xff) as f32 / 255.0,
        (c & 0xff) as f32 / 255.0,
        1.0,
    )
}

/// barytex's side: positions already in clip space.
struct BarytexShader<'a> {
    mesh: &'a ClipMesh,
    texture: &'a NearestTexture,
    light: Vec3,
    lit: bool,
}

impl Shader for BarytexShader<'_> {
    type Vertex = u32;
    type Varying = (Vec2, Vec3);
    fn vertex(&self, &i: &u32) -> (Vec4, (Vec2, Vec3)) {
        let i = i as usize;
        (self.mesh.clip[i], (self.mesh.uv[i], self.mesh.normal[i]))
    }
    fn fragment(&self, f: &Fragment<'_, (Vec2, Vec3)>) -> Option<Vec4> {
        let c = unpack(self.texture.texel(f.varying.0));
        Some(if self.lit {
            let lambert = f.varying.1.normalize_or_zero().dot(self.light).max(0.0);
            (c.truncate() * (0.15 + lambert)).extend(1.0)
        } else {
            c
        })
    }
}

/// euc's side: the same data, the same shading, packed ARGB output.
struct EucPipeline<'a> {
    mesh: &'a ClipMesh,
    texture: &'a NearestTexture,
    light: Vec3,
    lit: bool,
}

impl Pipeline for EucPipeline<'_> {
    type Vertex = u32;
    type VsOut = (vek::Vec2<f32>, vek::Vec3<f32>);
    type Pixel = u32;
    fn vert(&self, &i: &u32) -> ([f32; 4], Self::VsOut) {
        let i = i as usize;
        let (uv, n) = (self.mesh.uv[i], self.mesh.normal[i]);
        (
            self.mesh.clip[i].to_array(),
            (vek::Vec2::new(uv.x, uv.y), vek::Vec3::new(n.x, n.y, n.z)),
        )
    }
    fn frag(&self, (uv, n): &Self::VsOut) -> u32 {
        let c = self.texture.texel(Vec2::new(uv.x, uv.y));
        if self.lit {
            let n = Vec3::new(n.x, n.y, n.z).normalize_or_zero();
            let k = 0.15 + n.dot(self.light).max(0.0);
            let s = |v: u32| ((v & 0xff) as f32 * k).min(255.0) as u32;
            0xFF00_0000 | s(c >> 16) << 16 | s(c >> 8) << 8 | s(c)
        } else {
            c
        }
    }
}

fn light() -> Vec3 {
    Vec3::new(0.3, 0.8, 0.5).normalize()
}

/// Draws `mesh` into a new `size²` barytex target, depth-tested, no culling.
pub(crate) fn render_barytex(
    mesh: &ClipMesh,
    texture: &NearestTexture,
    lit: bool,
    size: u32,
) -> Framebuffer {
    let mut fb = Framebuffer::new(size, size, Vec4::ZERO, &TargetLimits::default()).expect("size²");
    let shader = BarytexShader {
        mesh,
        texture,
        light: light(),
        lit,
    };
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    let vertices: Vec<u32> = (0..mesh.clip.len() as u32).collect();
    draw(&mut fb, &shader, &state, &vertices, &mesh.indices);
    fb
}

/// Draws `mesh` into a new `size²` euc target, depth-tested, no culling.
pub(crate) fn render_euc(
    mesh: &ClipMesh,
    texture: &NearestTexture,
    lit: bool,
    size: u32,
) -> Buffer2d<u32> {
    let mut color = Buffer2d::new([size as usize, size as usize], 0_u32);
    let mut depth = Buffer2d::new([size as usize, size as usize], 1.0_f32);
    let pipeline = EucPipeline {
        mesh,
        texture,
        light: light(),
        lit,
    };
    pipeline.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
        &mesh.indices,
        &mut color,
        Some(&mut depth),
    );
    color
}

/// The constant colour of the rasterization-only comparison.
pub(crate) const FLAT: [f32; 4] = [0.8, 0.5, 0.2, 1.0];

/// [`FLAT`] as euc's 4-byte pixel: the same bytes barytex's `Rgba8Unorm` stores (`[r, g, b, a]`
/// in memory, little-endian), rounded to nearest as it rounds.
pub(crate) fn flat_u32() -> u32 {
    u32::from_le_bytes(FLAT.map(|v| (v * 255.0 + 0.5) as u8))
}

/// barytex's side of the rasterization-only comparison: one interpolated float (unused), a
/// constant colour.
struct ConstantShader<'a> {
    mesh: &'a ClipMesh,
}

impl Shader for ConstantShader<'_> {
    type Vertex = u32;
    type Varying = f32;
    fn vertex(&self, &i: &u32) -> (Vec4, f32) {
        (self.mesh.clip[i as usize], 0.0)
    }
    fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(Vec4::from_array(FLAT))
    }
}

/// euc's side: the same vertices, one interpolated float, the same constant colour as the
/// pixel type `P` (four f32, or the 4 bytes of [`flat_u32`]).
struct ConstantPipeline<'a, P> {
    mesh: &'a ClipMesh,
    pixel: P,
}

impl<P: Clone> Pipeline for ConstantPipeline<'_, P> {
    type Vertex = u32;
    type VsOut = f32;
    type Pixel = P;
    fn vert(&self, &i: &u32) -> ([f32; 4], f32) {
        (self.mesh.clip[i as usize].to_array(), 0.0)
    }
    fn frag(&self, _: &f32) -> P {
        self.pixel.clone()
    }
}

/// A barytex target for the rasterization-only comparison (allocated once, outside the timed
/// loop: [`raster_only_barytex`] clears it).
pub(crate) fn barytex_target<C: ColorFormat>(size: u32) -> Framebuffer<C> {
    Framebuffer::<C>::with_format(
        size,
        size,
        SamplePattern::CENTRE,
        Vec4::ZERO,
        &TargetLimits::default(),
    )
    .expect("size²")
}

/// Rasterization alone on barytex: clears `fb` (colour and depth), then draws `mesh` with a
/// constant shader, depth-tested, no culling.
pub(crate) fn raster_only_barytex<C: ColorFormat>(
    mesh: &ClipMesh,
    vertices: &[u32],
    fb: &mut Framebuffer<C>,
) {
    fb.clear(Vec4::ZERO);
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    draw(
        fb,
        &ConstantShader { mesh },
        &state,
        vertices,
        &mesh.indices,
    );
}

/// [`raster_only_barytex`] with the clear done by the draw, tile by tile
/// ([`draw_cleared`]): the same pixels, depths and statistics.
pub(crate) fn raster_only_barytex_draw_cleared<C: ColorFormat>(
    mesh: &ClipMesh,
    vertices: &[u32],
    fb: &mut Framebuffer<C>,
) {
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    draw_cleared(
        fb,
        Vec4::ZERO,
        &ConstantShader { mesh },
        &state,
        vertices,
        &mesh.indices,
    );
}

/// An euc colour target and depth buffer (allocated once, outside the timed loop:
/// [`raster_only_euc`] clears them).
pub(crate) fn euc_targets<P: Clone>(size: u32, zero: P) -> (Buffer2d<P>, Buffer2d<f32>) {
    (
        Buffer2d::new([size as usize, size as usize], zero),
        Buffer2d::new([size as usize, size as usize], 1.0_f32),
    )
}

/// Rasterization alone on euc: clears the targets, then draws the same as
/// [`raster_only_barytex`], writing `pixel`.
pub(crate) fn raster_only_euc<P: Clone>(
    mesh: &ClipMesh,
    pixel: P,
    zero: P,
    (color, depth): &mut (Buffer2d<P>, Buffer2d<f32>),
) {
    color.clear(zero);
    depth.clear(1.0);
    ConstantPipeline { mesh, pixel }
        .draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
            &mesh.indices,
            color,
            Some(depth),
        );
}

/// 10 000 random triangles about 20 pixels across on a `size²` target, at random depths in
/// [0, 1] (the raster benchmarks' `random_10k`).
pub(crate) fn random_scene(size: u32) -> ClipMesh {
    let mut state = 0x2545_F491_4F6C_DD1D_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut scene = ClipMesh {
        clip: Vec::new(),
        uv: Vec::new(),
        normal: Vec::new(),
        indices: Vec::new(),
    };
    let px = 2.0 / size as f32;
    for _ in 0..10_000 {
        let centre = Vec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0);
        let z = next();
        for _ in 0..3 {
            let offset = Vec2::new(next() - 0.5, next() - 0.5) * 20.0 * px;
            let p = centre + offset;
            scene.indices.push(scene.clip.len() as u32);
            scene.clip.push(Vec4::new(p.x, p.y, z, 1.0));
            scene.uv.push(Vec2::new(next(), next()));
            scene.normal.push(Vec3::Z);
        }
    }
    scene
}
