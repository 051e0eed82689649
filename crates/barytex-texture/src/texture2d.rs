//! `Texture2d`: a width × height grid of texels of one format, rows top to bottom.

use glam::Vec4;

use crate::{Limits, Rgba32f, Texel, TextureError};

/// A 2D grid of texels, row-major, texel (0, 0) at the top-left.
///
/// Every constructor checks [`Limits`] and allocates fallibly, so untrusted sizes give an error,
/// never an abort. Sides are at least 1.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture2d<T> {
    width: u32,
    height: u32,
    texels: Vec<T>,
}

/// Allocates `count` texels without aborting on failure.
pub(crate) fn try_vec_with_capacity<T>(count: usize) -> Result<Vec<T>, TextureError> {
    let mut texels = Vec::new();
    texels
        .try_reserve_exact(count)
        .map_err(|_| TextureError::OutOfMemory {
            bytes: (count as u64).saturating_mul(core::mem::size_of::<T>() as u64),
        })?;
    Ok(texels)
}

impl<T: Texel> Texture2d<T> {
    /// A texture filled with one texel, under the default [`Limits`].
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn new(width: u32, height: u32, fill: T) -> Result<Self, TextureError> {
        Self::new_with_limits(width, height, fill, &Limits::default())
    }

    /// A texture filled with one texel, under the caller's limits.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn new_with_limits(
        width: u32,
        height: u32,
        fill: T,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        Self::from_fn_with_limits(width, height, limits, |_, _| fill)
    }

    /// A texture whose texel (x, y) is `f(x, y)`, under the default [`Limits`]; `f` runs row by
    /// row.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn from_fn(
        width: u32,
        height: u32,
        f: impl FnMut(u32, u32) -> T,
    ) -> Result<Self, TextureError> {
        Self::from_fn_with_limits(width, height, &Limits::default(), f)
    }

    /// [`from_fn`](Self::from_fn) under the caller's limits.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn from_fn_with_limits(
        width: u32,
        height: u32,
        limits: &Limits,
        mut f: impl FnMut(u32, u32) -> T,
    ) -> Result<Self, TextureError> {
        limits.check(width, height, T::FORMAT.bytes_per_texel())?;
        let count = texel_count(width, height);
        let mut texels = try_vec_with_capacity(count)?;
        for y in 0..height {
            for x in 0..width {
                texels.push(f(x, y));
            }
        }
        Ok(Self {
            width,
            height,
            texels,
        })
    }

    /// Wraps texels already in memory (row-major, `width × height` of them) under the default
    /// [`Limits`].
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a length that is not `width × height`.
    pub fn from_texels(width: u32, height: u32, texels: Vec<T>) -> Result<Self, TextureError> {
        Self::from_texels_with_limits(width, height, texels, &Limits::default())
    }

    /// [`from_texels`](Self::from_texels) under the caller's limits.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a length that is not `width × height`.
    pub fn from_texels_with_limits(
        width: u32,
        height: u32,
        texels: Vec<T>,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        limits.check(width, height, T::FORMAT.bytes_per_texel())?;
        let expected = u64::from(width) * u64::from(height);
        if texels.len() as u64 != expected {
            return Err(TextureError::DataLength {
                expected,
                actual: texels.len() as u64,
            });
        }
        Ok(Self {
            width,
            height,
            texels,
        })
    }

    /// Width in texels (≥ 1).
    #[must_use]
    #[inline]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels (≥ 1).
    #[must_use]
    #[inline]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// `(width, height)`.
    #[must_use]
    #[inline]
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// All texels, row-major.
    #[must_use]
    #[inline]
    pub fn texels(&self) -> &[T] {
        &self.texels
    }

    /// All texels, row-major, mutable.
    #[must_use]
    #[inline]
    pub fn texels_mut(&mut self) -> &mut [T] {
        &mut self.texels
    }

    /// The texels, giving up the texture.
    #[must_use]
    pub fn into_texels(self) -> Vec<T> {
        self.texels
    }

    /// Row `y` (top = 0); `None` past the last row.
    #[must_use]
    #[inline]
    pub fn row(&self, y: u32) -> Option<&[T]> {
        let w = self.width as usize;
        let start = (y as usize).checked_mul(w)?;
        self.texels.get(start..start + w)
    }

    /// Texel (x, y); `None` outside.
    #[must_use]
    #[inline]
    pub fn texel(&self, x: u32, y: u32) -> Option<T> {
        (x < self.width && y < self.height)
            .then(|| self.texels[y as usize * self.width as usize + x as usize])
    }

    /// Texel (x, y), mutable; `None` outside.
    #[must_use]
    #[inline]
    pub fn texel_mut(&mut self, x: u32, y: u32) -> Option<&mut T> {
        if x < self.width && y < self.height {
            let w = self.width as usize;
            self.texels.get_mut(y as usize * w + x as usize)
        } else {
            None
        }
    }

    /// Texel (x, y) as linear-light RGBA with straight alpha; `None` outside.
    #[must_use]
    #[inline]
    pub fn linear(&self, x: u32, y: u32) -> Option<Vec4> {
        self.texel(x, y).map(Texel::to_linear)
    }

    /// The same texture converted texel by texel to another format (through linear light).
    ///
    /// # Errors
    /// A failed allocation.
    pub fn convert<U: Texel>(&self) -> Result<Texture2d<U>, TextureError> {
        let mut texels = try_vec_with_capacity(self.texels.len())?;
        texels.extend(self.texels.iter().map(|t| U::from_linear(t.to_linear())));
        Ok(Texture2d {
            width: self.width,
            height: self.height,
            texels,
        })
    }

    /// The texture as linear-light f32 RGBA.
    ///
    /// # Errors
    /// A failed allocation.
    pub fn to_linear(&self) -> Result<Texture2d<Rgba32f>, TextureError> {
        self.convert()
    }
}

fn texel_count(width: u32, height: u32) -> usize {
    // Limits::check has proven width·height·bytes fits usize.
    width as usize * height as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{R8, Srgba8};

    #[test]
    fn from_fn_is_row_major_from_the_top_left() {
        let t = Texture2d::from_fn(3, 2, |x, y| R8((10 * y + x) as u8)).expect("small");
        assert_eq!(t.texels(), &[R8(0), R8(1), R8(2), R8(10), R8(11), R8(12)]);
        assert_eq!(t.texel(2, 1), Some(R8(12)));
        assert_eq!(t.texel(3, 0), None);
        assert_eq!(t.row(1), Some(&[R8(10), R8(11), R8(12)][..]));
        assert_eq!(t.row(2), None);
    }

    #[test]
    fn limits_refuse_before_allocating() {
        let limits = Limits {
            max_width: 100_000,
            max_height: 100_000,
            max_bytes: 1 << 20,
        };
        let err = Texture2d::new_with_limits(100_000, 100_000, Srgba8::default(), &limits);
        assert!(matches!(
            err,
            Err(TextureError::TooLarge { what: "bytes", .. })
        ));
        assert!(matches!(
            Texture2d::new(0, 5, R8(0)),
            Err(TextureError::Empty { .. })
        ));
        assert!(matches!(
            Texture2d::new(20_000, 1, R8(0)),
            Err(TextureError::TooLarge { what: "width", .. })
        ));
    }

    #[test]
    fn from_texels_checks_the_length() {
        assert!(matches!(
            Texture2d::from_texels(2, 2, vec![R8(0); 3]),
            Err(TextureError::DataLength {
                expected: 4,
                actual: 3
            })
        ));
    }
}
