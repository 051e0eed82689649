//! Cube maps in the Vulkan/wgpu convention: face selection by the major axis and per-face
//! `(s, t)` from the table of the Vulkan specification ("Cube Map Face Selection").

use glam::{Vec2, Vec3};

use super::reflect::unit;
use crate::UvJacobian;

/// A face of a cube map, numbered as the array layers of a Vulkan/wgpu cube texture
/// (`+X, −X, +Y, −Y, +Z, −Z` = layers 0…5; the same order as OpenGL's
/// `GL_TEXTURE_CUBE_MAP_POSITIVE_X + i` and Direct3D's `D3D11_TEXTURECUBE_FACE_*`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CubeFace {
    /// Layer 0, major axis `+x`.
    PositiveX = 0,
    /// Layer 1, major axis `−x`.
    NegativeX = 1,
    /// Layer 2, major axis `+y`.
    PositiveY = 2,
    /// Layer 3, major axis `−y`.
    NegativeY = 3,
    /// Layer 4, major axis `+z`.
    PositiveZ = 4,
    /// Layer 5, major axis `−z`.
    NegativeZ = 5,
}

impl CubeFace {
    /// The six faces in layer order.
    pub const ALL: [Self; 6] = [
        Self::PositiveX,
        Self::NegativeX,
        Self::PositiveY,
        Self::NegativeY,
        Self::PositiveZ,
        Self::NegativeZ,
    ];

    /// The array layer of this face (0…5).
    #[must_use]
    pub const fn layer(self) -> u32 {
        self as u32
    }

    /// The face stored in array `layer`, or `None` for a layer above 5.
    #[must_use]
    pub const fn from_layer(layer: u32) -> Option<Self> {
        match layer {
            0 => Some(Self::PositiveX),
            1 => Some(Self::NegativeX),
            2 => Some(Self::PositiveY),
            3 => Some(Self::NegativeY),
            4 => Some(Self::PositiveZ),
            5 => Some(Self::NegativeZ),
            _ => None,
        }
    }

    /// The face's frame `[a, b, c]` from the Vulkan table: `sc = a·d`, `tc = b·d`, `|ma| = c·d`
    /// for a direction `d` on this face, so `c` is the outward face normal, `a` the direction of
    /// increasing `s` (u, to the right) and `b` of increasing `t` (v, down the image).
    ///
    /// | face | `sc` | `tc` | `ma` |
    /// |---|---|---|---|
    /// | `+X` | `−rz` | `−ry` | `rx` |
    /// | `−X` | `+rz` | `−ry` | `rx` |
    /// | `+Y` | `+rx` | `+rz` | `ry` |
    /// | `−Y` | `+rx` | `−rz` | `ry` |
    /// | `+Z` | `+rx` | `−ry` | `rz` |
    /// | `−Z` | `−rx` | `−ry` | `rz` |
    ///
    /// ```
    /// use barytex_uv::environment::CubeFace;
    /// use glam::Vec3;
    ///
    /// assert_eq!(CubeFace::PositiveX.frame(), [Vec3::NEG_Z, Vec3::NEG_Y, Vec3::X]);
    /// ```
    #[must_use]
    pub const fn frame(self) -> [Vec3; 3] {
        match self {
            Self::PositiveX => [Vec3::NEG_Z, Vec3::NEG_Y, Vec3::X],
            Self::NegativeX => [Vec3::Z, Vec3::NEG_Y, Vec3::NEG_X],
            Self::PositiveY => [Vec3::X, Vec3::Z, Vec3::Y],
            Self::NegativeY => [Vec3::X, Vec3::NEG_Z, Vec3::NEG_Y],
            Self::PositiveZ => [Vec3::X, Vec3::NEG_Y, Vec3::Z],
            Self::NegativeZ => [Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z],
        }
    }

    /// The face whose major axis `dir` points along, or `None` for a zero or non-finite `dir`.
    ///
    /// The major axis is the component of largest magnitude. Ties are broken as the Vulkan
    /// specification recommends ("`rz` wins over `ry` and `rx`, and `ry` wins over `rx`"): on an
    /// edge or corner shared by faces the face of the later axis (`z`, then `y`) is chosen. The
    /// sign of the winning component picks `+` or `−` (a `−0.0` component can only win when all
    /// three are zero, which gives `None`).
    ///
    /// ```
    /// use barytex_uv::environment::CubeFace;
    /// use glam::Vec3;
    ///
    /// assert_eq!(CubeFace::of(Vec3::new(0.2, -3.0, 1.0)), Some(CubeFace::NegativeY));
    /// // |x| = |y| = |z|: z wins.
    /// assert_eq!(CubeFace::of(Vec3::new(1.0, 1.0, -1.0)), Some(CubeFace::NegativeZ));
    /// // |x| = |y| > |z|: y wins.
    /// assert_eq!(CubeFace::of(Vec3::new(1.0, 1.0, 0.0)), Some(CubeFace::PositiveY));
    /// assert_eq!(CubeFace::of(Vec3::ZERO), None);
    /// ```
    #[must_use]
    pub fn of(dir: Vec3) -> Option<Self> {
        if !dir.is_finite() {
            return None;
        }
        let a = dir.abs();
        let face = if a.z >= a.x && a.z >= a.y {
            if dir.z > 0.0 {
                Self::PositiveZ
            } else {
                Self::NegativeZ
            }
        } else if a.y >= a.x {
            if dir.y > 0.0 {
                Self::PositiveY
            } else {
                Self::NegativeY
            }
        } else if dir.x > 0.0 {
            Self::PositiveX
        } else {
            Self::NegativeX
        };
        (a.max_element() > 0.0).then_some(face)
    }
}

/// The face and its `(s, t)` texture coordinate for the direction `dir` (any finite nonzero
/// length): `s = ½(sc/|ma| + 1)`, `t = ½(tc/|ma| + 1)` with `sc`, `tc`, `ma` from the Vulkan
/// table ([`CubeFace::frame`]); `(s, t) = (0, 0)` is the top-left texel corner of the layer, as
/// in Vulkan, wgpu and glTF. `None` for a zero or non-finite `dir`. Ties between axes as in
/// [`CubeFace::of`].
///
/// Both coordinates lie in `[0, 1]` exactly (`|sc| ≤ |ma|`, and division is correctly rounded).
///
/// # Accuracy
/// `(s, t)` within 2 ulps of 1 (an absolute `2.4e-7`) of the exact value for the f32 input;
/// [`cube_direction`] of the result is within [`CUBE_ROUND_TRIP_BOUND`] radians of `dir`
/// (`environment.rs::cube_round_trips`).
///
/// ```
/// use barytex_uv::environment::{CubeFace, cube_face_uv};
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(cube_face_uv(Vec3::X), Some((CubeFace::PositiveX, Vec2::splat(0.5))));
/// // On +Z, +x is to the right and +y up (t = 0 at the top).
/// assert_eq!(cube_face_uv(Vec3::new(1.0, 1.0, 2.0)), Some((CubeFace::PositiveZ, Vec2::new(0.75, 0.25))));
/// assert_eq!(cube_face_uv(Vec3::NAN), None);
/// ```
#[must_use]
pub fn cube_face_uv(dir: Vec3) -> Option<(CubeFace, Vec2)> {
    let face = CubeFace::of(dir)?;
    let [a, b, c] = face.frame();
    let ma = c.dot(dir);
    let st = 0.5 * (Vec2::new(a.dot(dir), b.dot(dir)) / ma + 1.0);
    Some((face, st))
}

/// The unit direction through `uv` on `face`, the inverse of [`cube_face_uv`]:
/// `normalize(c + (2s − 1)a + (2t − 1)b)` with the face's [`frame`](CubeFace::frame).
///
/// `uv` outside `[0, 1]²` continues the face's plane (the direction then belongs to another
/// face). `None` when `uv` is not finite or so large that the direction overflows.
///
/// # Accuracy
/// Within [`CUBE_ROUND_TRIP_BOUND`] radians of the exact direction; `cube_face_uv` of the result
/// gives back `face` and `uv` within `4e-7` for `uv` in `[0, 1]²` away from the face edges
/// (`environment.rs::cube_uv_round_trips`).
///
/// ```
/// use barytex_uv::environment::{CubeFace, cube_direction};
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(cube_direction(CubeFace::NegativeY, Vec2::splat(0.5)), Some(Vec3::NEG_Y));
/// ```
#[must_use]
pub fn cube_direction(face: CubeFace, uv: Vec2) -> Option<Vec3> {
    if !uv.is_finite() {
        return None;
    }
    let [a, b, c] = face.frame();
    let p = 2.0 * uv - 1.0;
    unit(c + p.x * a + p.y * b)
}

/// Angle (radians) within which `cube_direction(cube_face_uv(d))` returns a unit direction `d`
/// (`environment.rs::cube_round_trips`).
pub const CUBE_ROUND_TRIP_BOUND: f32 = 6.0e-7;

/// [`cube_face_uv`] with the gradients of `s` and `t` with respect to the direction (the face
/// held fixed): `∇s = ½(a − (sc/|ma|)c)/|ma|`, likewise `∇t` with `b`. Both gradients are
/// orthogonal to `dir` (the map ignores length). `None` as for `cube_face_uv`, or when the
/// gradients overflow (`|dir|` below about `1e-38`).
///
/// # Accuracy
/// Relative to the largest gradient entry, within `1e-6` of the exact gradient
/// (`environment.rs::cube_jacobian_matches_finite_differences` checks it against central
/// differences in f64).
///
/// ```
/// use barytex_uv::environment::cube_face_uv_and_jacobian;
/// use glam::{Vec2, Vec3};
///
/// let (_, j) = cube_face_uv_and_jacobian(Vec3::Z).expect("nonzero");
/// assert_eq!(j.uv, Vec2::splat(0.5));
/// assert_eq!((j.du, j.dv), (Vec3::X * 0.5, Vec3::NEG_Y * 0.5));
/// ```
#[must_use]
pub fn cube_face_uv_and_jacobian(dir: Vec3) -> Option<(CubeFace, UvJacobian)> {
    let face = CubeFace::of(dir)?;
    let [a, b, c] = face.frame();
    // Scaled so that |ma| = 1: the gradients of a degree-0 function scale as 1/|dir|.
    let scale = c.dot(dir);
    let (sc, tc) = (a.dot(dir) / scale, b.dot(dir) / scale);
    let j = UvJacobian {
        uv: 0.5 * Vec2::new(sc + 1.0, tc + 1.0),
        du: 0.5 * (a - sc * c) / scale,
        dv: 0.5 * (b - tc * c) / scale,
    };
    (j.du.is_finite() && j.dv.is_finite()).then_some((face, j))
}
