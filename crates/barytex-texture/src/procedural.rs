//! Procedural textures: computed on the fly from the coordinate (Peachey 1985, Perlin 1985),
//! implementing the same [`Sampler`](crate::Sampler) as image textures so filters can be compared
//! on them — and one, [`BoxFilteredCheckerboard`], filtered analytically: exact ground truth.

mod checkerboard;
mod noise;
mod stripes;

pub use checkerboard::{BoxFilteredCheckerboard, Checkerboard};
pub use noise::ValueNoise;
pub use stripes::Stripes;
