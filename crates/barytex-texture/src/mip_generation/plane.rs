//! `Plane`: a working buffer of f32 RGBA values between reductions.

use glam::Vec4;

use crate::TextureError;
use crate::texture2d::try_vec_with_capacity;

/// A `width × height` grid of f32 RGBA values (premultiplied linear, or stored values on the
/// naive path), row-major.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Plane {
    /// Width.
    pub(crate) width: u32,
    /// Height.
    pub(crate) height: u32,
    /// Row-major values.
    pub(crate) values: Vec<Vec4>,
}

impl Plane {
    /// An empty plane with room for `width × height` values.
    pub(crate) fn with_capacity(width: u32, height: u32) -> Result<Self, TextureError> {
        Ok(Self {
            width,
            height,
            values: try_vec_with_capacity(width as usize * height as usize)?,
        })
    }
}

impl super::Source for Plane {
    #[inline]
    fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    #[inline]
    fn get(&self, x: u32, y: u32) -> Vec4 {
        self.values[y as usize * self.width as usize + x as usize]
    }

    fn row<'a>(&'a self, y: u32, _buffer: &'a mut Vec<Vec4>) -> &'a [Vec4] {
        let w = self.width as usize;
        let start = y as usize * w;
        self.values.get(start..start + w).unwrap_or(&[])
    }
}
