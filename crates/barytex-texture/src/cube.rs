//! Cube-map textures sampled by direction, with **seamless** filtering: a bilinear tap that falls
//! off a face reads the adjacent face's texel, and a tap off a corner the average of the three
//! texels that meet there (what GPUs do in seamless mode), so there is no seam at the edges.
//!
//! Faces and their `(s, t)` follow the Vulkan table, taken from barytex-uv's
//! [`cube_face_uv`](barytex_uv::environment::cube_face_uv) and
//! [`cube_direction`](barytex_uv::environment::cube_direction).

use barytex_uv::environment::{CubeFace, cube_direction, cube_face_uv, cube_face_uv_and_jacobian};
use glam::{Vec2, Vec3, Vec4};

use crate::addressing::{linear_taps, nearest_index};
use crate::sampler::texel_fetch::{premultiply, unpremultiply};
use crate::sampler::{FilterMode, MipmapFilterMode, SamplerDescriptor};
use crate::{MipChain, Texel, Texture2d, TextureError};

/// Six square faces in Vulkan layer order (+X, −X, +Y, −Y, +Z, −Z), each with its mip chain,
/// and the filters to sample them with (address modes do not apply: a cube has no edge).
///
/// # Documented values for bad input
/// A zero or non-finite direction gives transparent black; non-finite derivatives select the
/// most blurred level the clamps allow. The descriptor's LOD clamps, bias and anisotropy are
/// sanitised as [`TextureSampler::new`](crate::TextureSampler::new) does (a NaN `lod_min_clamp`
/// is 0, a NaN `lod_max_clamp` 32, a non-finite bias 0).
#[derive(Clone, Debug)]
pub struct CubeTexture<T> {
    faces: [MipChain<T>; 6],
    descriptor: SamplerDescriptor,
}

impl<T: Texel> CubeTexture<T> {
    /// A cube from six face chains.
    ///
    /// # Errors
    /// [`TextureError::InvalidParameter`] when a face is not square or the faces differ in size or
    /// chain length.
    ///
    /// ```
    /// use barytex_texture::{CubeTexture, MipChain, R8, SamplerDescriptor, Texture2d};
    /// use glam::Vec3;
    ///
    /// // Face k (+X, −X, +Y, −Y, +Z, −Z) is a 2×2 face filled with 40·k.
    /// let face = |k: u8| Texture2d::new(2, 2, R8(40 * k)).map(MipChain::single);
    /// let faces = [face(0)?, face(1)?, face(2)?, face(3)?, face(4)?, face(5)?];
    /// let cube = CubeTexture::new(faces, SamplerDescriptor::bilinear())?;
    /// assert_eq!(cube.faces()[5].base().texel(0, 0), Some(R8(200)));
    /// // A non-square face is refused.
    /// let wide = || Texture2d::new(2, 1, R8(0)).map(MipChain::single);
    /// let bad = [wide()?, wide()?, wide()?, wide()?, wide()?, wide()?];
    /// assert!(CubeTexture::new(bad, SamplerDescriptor::bilinear()).is_err());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    pub fn new(
        faces: [MipChain<T>; 6],
        descriptor: SamplerDescriptor,
    ) -> Result<Self, TextureError> {
        let (w, h) = faces[0].base().size();
        let levels = faces[0].len();
        if w != h {
            return Err(TextureError::InvalidParameter {
                what: "faces",
                reason: "cube faces must be square",
            });
        }
        if faces
            .iter()
            .any(|f| f.base().size() != (w, h) || f.len() != levels)
        {
            return Err(TextureError::InvalidParameter {
                what: "faces",
                reason: "cube faces must have equal sizes and chain lengths",
            });
        }
        // The LOD clamps and bias as `TextureSampler` sanitises them: a NaN `lod_min_clamp` made
        // `clamp_lod` panic (`f32::clamp` with a NaN bound).
        Ok(Self {
            faces,
            descriptor: descriptor.sanitized(),
        })
    }

    /// The face chains.
    ///
    /// ```
    /// use barytex_texture::{CubeTexture, MipChain, R8, SamplerDescriptor, Texture2d};
    /// use glam::Vec3;
    ///
    /// // Face k (+X, −X, +Y, −Y, +Z, −Z) is a 2×2 face filled with 40·k.
    /// let face = |k: u8| Texture2d::new(2, 2, R8(40 * k)).map(MipChain::single);
    /// let faces = [face(0)?, face(1)?, face(2)?, face(3)?, face(4)?, face(5)?];
    /// let cube = CubeTexture::new(faces, SamplerDescriptor::bilinear())?;
    /// let sizes: Vec<_> = cube.faces().iter().map(|f| f.base().size()).collect();
    /// assert_eq!(sizes, [(2, 2); 6]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn faces(&self) -> &[MipChain<T>; 6] {
        &self.faces
    }

    /// The colour seen along `dir` at an explicit level of detail.
    ///
    /// ```
    /// use barytex_texture::{CubeTexture, MipChain, R8, SamplerDescriptor, Texture2d};
    /// use glam::Vec3;
    ///
    /// // Face k (+X, −X, +Y, −Y, +Z, −Z) is a 2×2 face filled with 40·k.
    /// let face = |k: u8| Texture2d::new(2, 2, R8(40 * k)).map(MipChain::single);
    /// let faces = [face(0)?, face(1)?, face(2)?, face(3)?, face(4)?, face(5)?];
    /// let cube = CubeTexture::new(faces, SamplerDescriptor::bilinear())?;
    /// // The direction picks the face by its largest component; the length does not matter.
    /// assert_eq!(cube.sample_level(Vec3::new(0.0, 0.0, -3.0), 0.0).x, R8(200).0 as f32 / 255.0);
    /// assert_eq!(cube.sample_level(Vec3::new(0.1, 1.0, 0.2), 0.0).x, R8(80).0 as f32 / 255.0);
    /// // The edge between +X and +Z blends the two faces equally, with no seam.
    /// let edge = cube.sample_level(Vec3::new(1.0, 0.0, 1.0), 0.0).x;
    /// assert!((edge - 80.0 / 255.0).abs() < 1e-6);
    /// assert_eq!(cube.sample_level(Vec3::ZERO, 0.0), glam::Vec4::ZERO);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn sample_level(&self, dir: Vec3, lod: f32) -> Vec4 {
        let Some((face, uv)) = cube_face_uv(dir) else {
            return Vec4::ZERO;
        };
        unpremultiply(self.filter(face, uv, self.clamp_lod(lod)))
    }

    /// The colour seen along `dir`, filtered over the footprint given by the direction's screen
    /// derivatives `ddx`, `ddy` (projected onto the face through the face map's Jacobian).
    ///
    /// ```
    /// use barytex_texture::{CubeTexture, MipChain, R8, SamplerDescriptor, Texture2d};
    /// use glam::Vec3;
    ///
    /// // Face k (+X, −X, +Y, −Y, +Z, −Z) is a 2×2 face filled with 40·k.
    /// let face = |k: u8| Texture2d::new(2, 2, R8(40 * k)).map(MipChain::single);
    /// let faces = [face(0)?, face(1)?, face(2)?, face(3)?, face(4)?, face(5)?];
    /// let cube = CubeTexture::new(faces, SamplerDescriptor::bilinear())?;
    /// let c = cube.sample(Vec3::X, Vec3::ZERO, Vec3::ZERO);
    /// assert_eq!(c, cube.sample_level(Vec3::X, 0.0));
    /// assert_eq!(c.x, 0.0);
    /// assert_eq!(cube.sample(Vec3::NAN, Vec3::ZERO, Vec3::ZERO), glam::Vec4::ZERO);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn sample(&self, dir: Vec3, ddx: Vec3, ddy: Vec3) -> Vec4 {
        let Some((face, j)) = cube_face_uv_and_jacobian(dir) else {
            return Vec4::ZERO;
        };
        let duv = |d: Vec3| Vec2::new(j.du.dot(d), j.dv.dot(d));
        let size = self.faces[0].base().size();
        let lod = crate::sampler::lod::lod(duv(ddx), duv(ddy), size);
        unpremultiply(self.filter(face, j.uv, self.clamp_lod(lod)))
    }

    fn clamp_lod(&self, lod: f32) -> f32 {
        let d = &self.descriptor;
        let biased = lod + d.lod_bias;
        let (lo, hi) = (d.lod_min_clamp, d.lod_max_clamp.max(d.lod_min_clamp));
        if biased.is_nan() {
            hi
        } else {
            biased.clamp(lo, hi)
        }
    }

    fn filter(&self, face: CubeFace, uv: Vec2, lod: f32) -> Vec4 {
        let d = &self.descriptor;
        if lod <= 0.0 {
            return self.filter_level(0, face, uv, d.mag_filter);
        }
        let last = self.faces[0].len() - 1;
        let level = |x: f32| {
            if x >= last as f32 {
                last
            } else {
                x.max(0.0) as usize
            }
        };
        match d.mipmap_filter {
            MipmapFilterMode::Nearest => {
                self.filter_level(level((lod + 0.5).ceil() - 1.0), face, uv, d.min_filter)
            }
            MipmapFilterMode::Linear => {
                let floor = lod.floor();
                let (lo, hi) = (level(floor), level(floor + 1.0));
                let a = self.filter_level(lo, face, uv, d.min_filter);
                if lo == hi {
                    return a;
                }
                let b = self.filter_level(hi, face, uv, d.min_filter);
                a + (b - a) * (lod - floor)
            }
        }
    }

    fn level(&self, face: CubeFace, level: usize) -> &Texture2d<T> {
        &self.faces[face.layer() as usize].levels()[level]
    }

    /// Premultiplied texel `(i, j)` of `face` at `level`, following the cube across edges.
    fn texel(&self, level: usize, face: CubeFace, i: i64, j: i64) -> Vec4 {
        let n = i64::from(self.level(face, level).width());
        let inside = |k: i64| (0..n).contains(&k);
        match (inside(i), inside(j)) {
            (true, true) => self.fetch(level, face, i, j),
            (false, false) => {
                // Off a corner: the three texels meeting there.
                let (ci, cj) = (i.clamp(0, n - 1), j.clamp(0, n - 1));
                (self.fetch(level, face, ci, cj)
                    + self.across_edge(level, face, ci, j)
                    + self.across_edge(level, face, i, cj))
                    / 3.0
            }
            _ => self.across_edge(level, face, i, j),
        }
    }

    /// The texel of the adjacent face that the centre of off-face texel `(i, j)` projects onto.
    fn across_edge(&self, level: usize, face: CubeFace, i: i64, j: i64) -> Vec4 {
        let n = self.level(face, level).width();
        let nf = n as f32;
        let centre = Vec2::new((i as f32 + 0.5) / nf, (j as f32 + 0.5) / nf);
        match cube_direction(face, centre).and_then(cube_face_uv) {
            Some((other, uv)) => {
                let x = nearest_index(uv.x, n).clamp(0, i64::from(n) - 1);
                let y = nearest_index(uv.y, n).clamp(0, i64::from(n) - 1);
                self.fetch(level, other, x, y)
            }
            None => Vec4::ZERO,
        }
    }

    fn fetch(&self, level: usize, face: CubeFace, i: i64, j: i64) -> Vec4 {
        let t = self.level(face, level);
        let (x, y) = (u32::try_from(i).unwrap_or(0), u32::try_from(j).unwrap_or(0));
        t.texel(x, y)
            .map_or(Vec4::ZERO, |texel| premultiply(texel.to_linear()))
    }

    fn filter_level(&self, level: usize, face: CubeFace, uv: Vec2, filter: FilterMode) -> Vec4 {
        let n = self.level(face, level).width();
        match filter {
            FilterMode::Nearest => {
                let clamp = |k: i64| k.clamp(0, i64::from(n) - 1);
                self.fetch(
                    level,
                    face,
                    clamp(nearest_index(uv.x, n)),
                    clamp(nearest_index(uv.y, n)),
                )
            }
            // Cubic filtering of cube maps is not offered; it reads as bilinear.
            FilterMode::Linear | FilterMode::Cubic(_) => {
                let (tx, ty) = (linear_taps(uv.x, n), linear_taps(uv.y, n));
                let (x0, y0) = (tx.i0, ty.i0);
                let c00 = self.texel(level, face, x0, y0);
                let c10 = self.texel(level, face, x0 + 1, y0);
                let c01 = self.texel(level, face, x0, y0 + 1);
                let c11 = self.texel(level, face, x0 + 1, y0 + 1);
                let top = c00 + (c10 - c00) * tx.frac;
                let bottom = c01 + (c11 - c01) * tx.frac;
                top + (bottom - top) * ty.frac
            }
        }
    }
}
