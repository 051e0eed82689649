//! glTF's unlit model (`KHR_materials_unlit`: base colour factor × base colour texture × vertex
//! colour, and the alpha mode) without fog, drawn with a varying of its own: the base texture's
//! texture coordinates and the vertex colour: with the clip position, the vertex stage writes
//! 48 bytes a vertex instead of 128 with a [`Surface`].
//!
//! [`MaterialShader`] draws every material with one varying type, [`Surface`], that carries
//! every part a material may read (position, normal, both uv sets, colour, vertex light,
//! tangent) and interpolates only those it does. For an unlit material that is two or six
//! floats of 24, but the vertex stage still writes the whole surface of every vertex and each
//! fragment still tests which parts to interpolate. Here the vertex stage's outputs (memory a
//! draw touches for the first time: a page fault every 4 KiB) are three eighths of the size, and
//! a fragment interpolates its two parts without a test. The values are the same operations on
//! the same inputs as [`MaterialShader`]'s general path, so the image is identical (tested by
//! the renders that interpolate every part through the general path).
//!
//! [`Surface`]: crate::surface::Surface

use barytex_gltf::material::AlphaMode;
use barytex_interp::Interpolate;
use barytex_raster::{Fragment, Shader};
use barytex_uv::UvSample;
use barytex_uv::mappings::TexCoordMapping;
use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};

use crate::material_shader::{MaterialShader, WorldPrimitive, coverage_alpha};
use crate::textures::PreparedTexture;

/// What an unlit fragment reads: the base texture's coordinate set and, when the primitive has
/// vertex colours, the colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct UnlitVarying {
    /// `TEXCOORD_n` of the base colour texture's set (zero without a base texture).
    uv: Vec2,
    /// `COLOR_0`, as an array: a `Vec4` would align the varying to 16 bytes (32 in all).
    color: [f32; 4],
    /// Whether `color` is interpolated: without vertex colours it stays white, exactly (the
    /// weights of three white vertices need not sum to exactly 1 in `f32`).
    colored: bool,
}

impl Interpolate for UnlitVarying {
    #[inline]
    fn scale(self, w: f32) -> Self {
        Self {
            uv: self.uv.scale(w),
            color: self.colour_or_white(|c| c.scale(w)),
            colored: self.colored,
        }
    }

    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            uv: self.uv.add(o.uv),
            color: self.colour_or_white(|c| c.add(Vec4::from_array(o.color))),
            colored: self.colored,
        }
    }

    #[inline]
    fn lerp(self, o: Self, t: f32) -> Self {
        Self {
            uv: self.uv.lerp(o.uv, t),
            color: self.colour_or_white(|c| Interpolate::lerp(c, Vec4::from_array(o.color), t)),
            colored: self.colored,
        }
    }

    #[inline(always)]
    fn combine3(v: [Self; 3], w: [f32; 3]) -> Self {
        let colour = |i: usize| Vec4::from_array(v[i].color);
        Self {
            uv: Vec2::combine3([v[0].uv, v[1].uv, v[2].uv], w),
            color: v[0].colour_or_white(|_| Vec4::combine3([colour(0), colour(1), colour(2)], w)),
            colored: v[0].colored,
        }
    }
}

impl UnlitVarying {
    /// `f` of the colour when it is interpolated, else white.
    #[inline(always)]
    fn colour_or_white(&self, f: impl FnOnce(Vec4) -> Vec4) -> [f32; 4] {
        if self.colored {
            f(Vec4::from_array(self.color)).to_array()
        } else {
            [1.0; 4]
        }
    }
}

/// Draws one primitive of an unlit material without fog (see the module's documentation).
pub(crate) struct UnlitShader<'a> {
    view_projection: Mat4,
    primitive: &'a WorldPrimitive<'a>,
    base_color: Vec4,
    alpha_mode: AlphaMode,
    /// The base colour texture and its mapping, when the material has one on set 0 or 1 (a
    /// primitive has no other sets: the general path's mapping finds nothing there).
    base: Option<(&'a PreparedTexture, TexCoordMapping)>,
    /// Whether that mapping's transform is the identity (no `KHR_texture_transform`, the common
    /// case): [`map`](Self::map) then replaces the three matrix products by what they come to,
    /// each component plus `+0` (see there).
    identity: bool,
}

impl<'a> UnlitShader<'a> {
    /// The unlit shader that draws what `shader` would, when `shader` takes its unlit path
    /// (an unlit material, no fog, parts interpolated as read); `None` otherwise.
    pub(crate) fn of(shader: &MaterialShader<'a>) -> Option<Self> {
        if !shader.takes_unlit_path() {
            return None;
        }
        let m = &shader.material;
        let base = m.base_texture.and_then(|slot| {
            let texture = shader.textures.get(slot.texture)?;
            (slot.mapping.set <= 1).then_some((texture, slot.mapping))
        });
        Some(Self {
            view_projection: shader.view_projection,
            primitive: shader.primitive,
            base_color: m.base_color,
            alpha_mode: m.alpha_mode,
            identity: base.is_some_and(|(_, mapping)| mapping.transform == Mat3::IDENTITY),
            base,
        })
    }
}

impl Shader for UnlitShader<'_> {
    type Vertex = u32;
    type Varying = UnlitVarying;

    fn vertex(&self, &i: &u32) -> (Vec4, UnlitVarying) {
        let i = i as usize;
        let p = self.primitive;
        let position = p.positions.get(i).copied().unwrap_or(Vec3::NAN);
        let set = match self.base {
            Some((_, mapping)) if mapping.set == 1 => &p.uv1,
            Some(_) => &p.uv0,
            None => &None,
        };
        let varying = UnlitVarying {
            uv: set
                .as_ref()
                .and_then(|uv| uv.get(i))
                .copied()
                .unwrap_or_default(),
            color: p
                .colors
                .as_ref()
                .and_then(|c| c.get(i))
                .copied()
                .unwrap_or(Vec4::ONE)
                .to_array(),
            colored: p.colors.is_some(),
        };
        (self.view_projection * position.extend(1.0), varying)
    }

    #[inline(always)]
    fn fragment(&self, f: &Fragment<'_, UnlitVarying>) -> Option<Vec4> {
        // No closure borrows the fragment: one that did stayed out of line in the paired
        // loop's fallback, and the fragments had to live in memory (10 stores a fragment).
        let texel = match self.base {
            Some((texture, mapping)) => self
                .map(mapping, uv_sample(f))
                .map(|mapped| texture.sample_base(&mapped)),
            None => None,
        };
        self.finish(f, texel)
    }

    /// Two fragments with their texture lookups interleaved
    /// ([`PreparedTexture::sample_base_pair`]): the lookup is most of an unlit fragment's
    /// time, one long dependency chain. Unlit Avocado at 1024², one thread: the draw's median
    /// 33.3 → 29.4 ms (14 rounds against the unpaired shader, 2026-12-03); Suzanne, whose
    /// lookups are shorter, 20.2 → 20.1 ms.
    const PAIRS: bool = true;

    #[inline(always)]
    fn fragment_pair(
        &self,
        a: &Fragment<'_, UnlitVarying>,
        b: &Fragment<'_, UnlitVarying>,
    ) -> [Option<Vec4>; 2] {
        let Some((texture, mapping)) = self.base else {
            return [self.finish(a, None), self.finish(b, None)];
        };
        let (Some(ma), Some(mb)) = (
            self.map(mapping, uv_sample(a)),
            self.map(mapping, uv_sample(b)),
        ) else {
            return [self.fragment(a), self.fragment(b)];
        };
        let [ta, tb] = texture.sample_base_pair(&ma, &mb);
        [self.finish(a, Some(ta)), self.finish(b, Some(tb))]
    }
}

impl UnlitShader<'_> {
    /// `mapping.transform_sample(&sample)`, bit for bit: `None` where it is not finite.
    ///
    /// With an identity transform each component of the product is `(1·a + 0·b) + 0·c`, which
    /// is `a + 0` exactly: `0·b` and `0·c` are zeros (or NaN, when `b` or `c` is not finite,
    /// and then so is the result), adding a zero leaves `a` as it is except that `−0` becomes
    /// `+0`, and `a + 0` does the same. Two additions instead of three multiplications and two
    /// additions per component (tested against the product on signed zeros and non-finite
    /// values).
    #[inline(always)]
    fn map(&self, mapping: TexCoordMapping, sample: UvSample) -> Option<UvSample> {
        if self.identity {
            identity_transform_sample(sample)
        } else {
            mapping.transform_sample(&sample)
        }
    }

    /// The fragment's colour from its base texture's texel (`None`: no texture, or a mapping
    /// undefined at the pixel): base colour factor × vertex colour × texel, and the alpha mode.
    #[inline(always)]
    fn finish(&self, f: &Fragment<'_, UnlitVarying>, texel: Option<Vec4>) -> Option<Vec4> {
        let mut base = self.base_color * Vec4::from_array(f.varying.color);
        if let Some(texel) = texel {
            base *= texel;
        }
        let alpha = coverage_alpha(self.alpha_mode, base.w)?;
        Some(base.truncate().extend(alpha))
    }
}

/// `transform_sample` through the identity transform, as [`UnlitShader::map`] computes it.
#[inline(always)]
fn identity_transform_sample(sample: UvSample) -> Option<UvSample> {
    let out = UvSample {
        uv: sample.uv + Vec2::ZERO,
        duvdx: sample.duvdx + Vec2::ZERO,
        duvdy: sample.duvdy + Vec2::ZERO,
    };
    (out.uv.is_finite() && out.duvdx.is_finite() && out.duvdy.is_finite()).then_some(out)
}

/// The base texture's coordinates at a fragment, with their screen derivatives.
#[inline(always)]
fn uv_sample(f: &Fragment<'_, UnlitVarying>) -> UvSample {
    let (duvdx, duvdy) = f.derivatives_of(|v: &UnlitVarying| v.uv);
    UvSample {
        uv: f.varying.uv,
        duvdx,
        duvdy,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn varying(k: f32, colored: bool) -> UnlitVarying {
        UnlitVarying {
            uv: Vec2::new(k, k + 0.5),
            color: if colored {
                [k, k + 1.0, k + 2.0, k + 3.0]
            } else {
                [1.0; 4]
            },
            colored,
        }
    }

    #[test]
    fn vertex_outputs_are_three_eighths_of_a_surfaces() {
        let (unlit, surface) = (
            size_of::<(Vec4, UnlitVarying)>(),
            size_of::<(Vec4, crate::surface::Surface)>(),
        );
        eprintln!("vertex stage output: {unlit} bytes, with a Surface {surface}");
        assert!(8 * unlit <= 3 * surface, "{unlit} against {surface}");
    }

    #[test]
    fn colours_interpolate_as_vec4_and_white_stays_exactly_white() {
        // Weights whose f32 sum is not 1: three white vertices would not give white.
        let w = [0.45_f32, 0.35, 0.2];
        assert_ne!(w[0] + w[1] + w[2], 1.0);
        let plain = UnlitVarying::combine3([1.0, 2.0, 3.0].map(|k| varying(k, false)), w);
        assert_eq!(plain.color, [1.0; 4]);
        let vs = [1.0, 2.0, 3.0].map(|k| varying(k, true));
        let coloured = UnlitVarying::combine3(vs, w);
        let as_vec4 = Vec4::combine3(vs.map(|v| Vec4::from_array(v.color)), w);
        assert_eq!(coloured.color, as_vec4.to_array());
        assert_eq!(coloured.uv, Vec2::combine3(vs.map(|v| v.uv), w));
        // Clipping's lerp too.
        let lerped = Interpolate::lerp(vs[0], vs[1], 0.25);
        let expected = Interpolate::lerp(
            Vec4::from_array(vs[0].color),
            Vec4::from_array(vs[1].color),
            0.25,
        );
        assert_eq!(lerped.color, expected.to_array());
        assert_eq!(Interpolate::lerp(plain, plain, 0.3).color, [1.0; 4]);
    }

    #[test]
    fn the_identity_shortcut_is_the_transform_bit_for_bit() {
        let values = [
            0.0,
            -0.0,
            0.25,
            -0.75,
            1e-30,
            -1e-45,
            -3.5,
            3e38,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let mapping = TexCoordMapping::new(1);
        assert_eq!(mapping.transform, Mat3::IDENTITY);
        let bits = |s: Option<UvSample>| {
            s.map(|s| [s.uv, s.duvdx, s.duvdy].map(|v| v.to_array().map(f32::to_bits)))
        };
        let n = values.len();
        let mut some = 0;
        for i in 0..n * n * n {
            let pick = |k: usize| values[(i / n.pow(k as u32 % 3) + k) % n];
            let sample = UvSample {
                uv: Vec2::new(pick(0), pick(1)),
                duvdx: Vec2::new(pick(2), pick(3)),
                duvdy: Vec2::new(pick(4), pick(5)),
            };
            let expected = mapping.transform_sample(&sample);
            some += usize::from(expected.is_some());
            assert_eq!(
                bits(identity_transform_sample(sample)),
                bits(expected),
                "{sample:?}"
            );
        }
        assert!(some > 0, "some samples must be finite");
    }
}
