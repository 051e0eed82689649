//! Environment mapping: the reflection vector and the four usual parameterizations of the sphere
//! of directions, each forward (direction → texture coordinate, with gradients) and inverse.
//!
//! | map | forward | inverse | singular / seam |
//! |---|---|---|---|
//! | reflection | [`reflect`], [`reflect_normalized`] | — | — |
//! | cube (Vulkan/wgpu faces) | [`cube_face_uv`], [`cube_face_uv_and_jacobian`] | [`cube_direction`] | face edges |
//! | equirectangular | [`equirect_uv`], [`equirect_uv_and_jacobian`] | [`equirect_direction`] | `u` seam at `+z`, poles `±y` |
//! | OpenGL sphere map | [`sphere_map_uv`], [`sphere_map_uv_and_jacobian`] | [`sphere_map_direction`] | `(0, 0, −1)` (the rim) |
//! | octahedral (Cigolle et al. 2014) | [`octahedral_encode`], [`octahedral_uv_and_jacobian`] | [`octahedral_decode`] | folds (lower half) |
//! | as a [`UvMapping`](crate::UvMapping) | [`EnvironmentMapping`] ([`EnvironmentMap`], [`Lookup`]) | — | — |
//!
//! Conventions: directions are in a right-handed, y-up space and need not be unit length (the
//! maps are scale-invariant; zero, NaN and infinite directions give `None`). Every texture
//! coordinate is in `[0, 1]²` with `(0, 0)` the image's top-left corner and `v` growing
//! downwards (glTF, Vulkan); each function documents its axes. The sphere map and the octahedral
//! map keep the coordinates of their defining formulas (OpenGL's `(s, t)`, the paper's `uv`)
//! so that existing textures read correctly.
//!
//! ```
//! use barytex_uv::environment::{cube_direction, cube_face_uv, reflect};
//! use glam::Vec3;
//!
//! // The view vector points from the surface to the eye.
//! let r = reflect(Vec3::Y, Vec3::new(0.0, 1.0, 1.0).normalize());
//! let (face, st) = cube_face_uv(r).expect("nonzero");
//! let back = cube_direction(face, st).expect("finite");
//! assert!(back.angle_between(r) < 1e-6);
//! ```

mod cube;
mod equirect;
mod mapping;
mod octahedral;
mod reflect;
mod sphere_map;

pub use cube::{
    CUBE_ROUND_TRIP_BOUND, CubeFace, cube_direction, cube_face_uv, cube_face_uv_and_jacobian,
};
pub use equirect::{
    EQUIRECT_ROUND_TRIP_BOUND, equirect_direction, equirect_uv, equirect_uv_and_jacobian,
};
pub use mapping::{EnvironmentMap, EnvironmentMapping, Lookup};
pub use octahedral::{
    OCTAHEDRAL_ROUND_TRIP_BOUND, octahedral_decode, octahedral_encode, octahedral_uv_and_jacobian,
};
pub use reflect::{reflect, reflect_normalized};
pub use sphere_map::{
    SPHERE_MAP_ROUND_TRIP_BOUND, sphere_map_direction, sphere_map_uv, sphere_map_uv_and_jacobian,
};
