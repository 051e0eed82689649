//! The varying a scene shader interpolates: world position, normal, both texture coordinate
//! sets, the vertex colour, Gouraud's vertex light and the tangent — each only when the
//! material reads it ([`Reads`]).

use barytex_interp::Interpolate;
use glam::{Vec2, Vec3, Vec4};

/// Which parts of a [`Surface`] a material reads. The rasterizer interpolates the whole varying;
/// `Surface`'s [`Interpolate`] skips the parts not read (they keep their
/// [`Surface::default`] value, and the vertex colour is white), so a textured unlit material
/// interpolates 2 floats of the 24, not all of them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Reads(u8);

impl Reads {
    pub(crate) const POSITION: Self = Self(1);
    pub(crate) const NORMAL: Self = Self(1 << 1);
    pub(crate) const UV0: Self = Self(1 << 2);
    pub(crate) const UV1: Self = Self(1 << 3);
    pub(crate) const COLOR: Self = Self(1 << 4);
    /// Gouraud's (and flat shading's) vertex light: `diffuse` and `specular`.
    pub(crate) const LIGHT: Self = Self(1 << 5);
    pub(crate) const TANGENT: Self = Self(1 << 6);
    /// Every part (tests compare a render that interpolates everything).
    pub(crate) const ALL: Self = Self(0x7f);
    /// Every part, with its name and its size in floats, in [`Surface`]'s order.
    pub(crate) const PARTS: [(Self, &'static str, usize); 7] = [
        (Self::POSITION, "position", 3),
        (Self::NORMAL, "normal", 3),
        (Self::UV0, "uv0", 2),
        (Self::UV1, "uv1", 2),
        (Self::COLOR, "colour", 4),
        (Self::LIGHT, "vertex light", 6),
        (Self::TANGENT, "tangent", 4),
    ];

    #[must_use]
    pub(crate) const fn contains(self, part: Self) -> bool {
        self.0 & part.0 == part.0
    }

    /// `self` with `part` added when `condition` holds.
    #[must_use]
    pub(crate) const fn with_if(self, part: Self, condition: bool) -> Self {
        if condition {
            Self(self.0 | part.0)
        } else {
            self
        }
    }
}

/// What the fragment stage of a scene material reads, interpolated over the triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Surface {
    pub(crate) position: Vec3,
    pub(crate) normal: Vec3,
    pub(crate) uv0: Vec2,
    pub(crate) uv1: Vec2,
    pub(crate) color: Vec4,
    /// Gouraud shading's per-vertex diffuse and specular light (zero otherwise).
    pub(crate) diffuse: Vec3,
    pub(crate) specular: Vec3,
    /// World-space tangent with the bitangent sign in `w` (normal-mapped materials only).
    pub(crate) tangent: Vec4,
    /// The parts above that are interpolated (the same at every vertex of a draw).
    pub(crate) reads: Reads,
}

/// `read()` when `reads` contains `part`, else `unread`.
#[inline]
fn part<T>(reads: Reads, part: Reads, unread: T, read: impl FnOnce() -> T) -> T {
    if reads.contains(part) { read() } else { unread }
}

/// Builds a [`Surface`] with reads `$r`, each part from `$f` applied to the part's field
/// name (skipped parts get their unread value).
macro_rules! surface_from_parts {
    ($r:expr, |$field:ident| $e:expr) => {{
        let r = $r;
        Surface {
            position: part(r, Reads::POSITION, Vec3::ZERO, || {
                let $field = |s: &Surface| s.position;
                $e
            }),
            normal: part(r, Reads::NORMAL, Vec3::ZERO, || {
                let $field = |s: &Surface| s.normal;
                $e
            }),
            uv0: part(r, Reads::UV0, Vec2::ZERO, || {
                let $field = |s: &Surface| s.uv0;
                $e
            }),
            uv1: part(r, Reads::UV1, Vec2::ZERO, || {
                let $field = |s: &Surface| s.uv1;
                $e
            }),
            color: part(r, Reads::COLOR, Vec4::ONE, || {
                let $field = |s: &Surface| s.color;
                $e
            }),
            diffuse: part(r, Reads::LIGHT, Vec3::ZERO, || {
                let $field = |s: &Surface| s.diffuse;
                $e
            }),
            specular: part(r, Reads::LIGHT, Vec3::ZERO, || {
                let $field = |s: &Surface| s.specular;
                $e
            }),
            tangent: part(r, Reads::TANGENT, Vec4::ZERO, || {
                let $field = |s: &Surface| s.tangent;
                $e
            }),
            reads: r,
        }
    }};
}

impl Interpolate for Surface {
    #[inline]
    fn scale(self, w: f32) -> Self {
        surface_from_parts!(self.reads, |f| Interpolate::scale(f(&self), w))
    }

    #[inline]
    fn add(self, o: Self) -> Self {
        surface_from_parts!(self.reads, |f| Interpolate::add(f(&self), f(&o)))
    }

    #[inline]
    fn lerp(self, o: Self, t: f32) -> Self {
        surface_from_parts!(self.reads, |f| Interpolate::lerp(f(&self), f(&o), t))
    }

    // Always inlined: called out of line, the three 100-byte surfaces are copied into the
    // call (a `memcpy` as costly as the interpolation itself), three times per fragment.
    #[inline(always)]
    fn combine3(v: [Self; 3], w: [f32; 3]) -> Self {
        surface_from_parts!(v[0].reads, |f| Interpolate::combine3(
            [f(&v[0]), f(&v[1]), f(&v[2])],
            w
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn surface(k: f32, reads: Reads) -> Surface {
        Surface {
            position: Vec3::splat(k),
            normal: Vec3::splat(k + 1.0),
            uv0: Vec2::splat(k + 2.0),
            uv1: Vec2::splat(k + 3.0),
            color: Vec4::splat(k + 4.0),
            diffuse: Vec3::splat(k + 5.0),
            specular: Vec3::splat(k + 6.0),
            tangent: Vec4::splat(k + 7.0),
            reads,
        }
    }

    #[test]
    fn read_parts_interpolate_exactly_and_unread_parts_keep_their_defaults() {
        let w = [0.2, 0.3, 0.5];
        let all = Surface::combine3([1.0, 2.0, 3.0].map(|k| surface(k, Reads::ALL)), w);
        for (part, name, _) in Reads::PARTS {
            let some = Surface::combine3([1.0, 2.0, 3.0].map(|k| surface(k, part)), w);
            let unread = Surface {
                reads: part,
                color: Vec4::ONE,
                ..Surface::default()
            };
            let expected = match name {
                "position" => Surface {
                    position: all.position,
                    ..unread
                },
                "normal" => Surface {
                    normal: all.normal,
                    ..unread
                },
                "uv0" => Surface {
                    uv0: all.uv0,
                    ..unread
                },
                "uv1" => Surface {
                    uv1: all.uv1,
                    ..unread
                },
                "colour" => Surface {
                    color: all.color,
                    ..unread
                },
                "vertex light" => Surface {
                    diffuse: all.diffuse,
                    specular: all.specular,
                    ..unread
                },
                _ => Surface {
                    tangent: all.tangent,
                    ..unread
                },
            };
            assert_eq!(some, expected, "{name}");
            // Clipping's lerp skips the same parts.
            let a = surface(1.0, part);
            let lerped = Interpolate::lerp(a, surface(3.0, part), 0.25);
            assert_eq!(lerped.reads, part, "{name}");
            assert_eq!(lerped.color == Vec4::ONE, name != "colour", "{name}");
        }
    }
}
