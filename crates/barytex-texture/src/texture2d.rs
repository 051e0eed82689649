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
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d, TextureError};
    ///
    /// let t = Texture2d::new(3, 2, R8(7))?;
    /// assert_eq!(t.size(), (3, 2));
    /// assert!(t.texels().iter().all(|&texel| texel == R8(7)));
    /// // A zero side is refused rather than giving an empty texture.
    /// assert_eq!(Texture2d::new(0, 2, R8(7)), Err(TextureError::Empty { width: 0, height: 2 }));
    /// # Ok::<(), TextureError>(())
    /// ```
    pub fn new(width: u32, height: u32, fill: T) -> Result<Self, TextureError> {
        Self::new_with_limits(width, height, fill, &Limits::default())
    }

    /// A texture filled with one texel, under the caller's limits.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    ///
    /// ```
    /// use barytex_texture::{Limits, Rgba32f, Texture2d, TextureError};
    ///
    /// // 64×64 RGBA32F texels are 64 KiB: over a 16 KiB budget, refused before allocating.
    /// let limits = Limits { max_bytes: 16 * 1024, ..Limits::default() };
    /// let err = Texture2d::new_with_limits(64, 64, Rgba32f::default(), &limits).unwrap_err();
    /// assert!(matches!(err, TextureError::TooLarge { what: "bytes", requested: 65_536, .. }));
    /// assert!(Texture2d::new_with_limits(32, 32, Rgba32f::default(), &limits).is_ok());
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// // Texel (x, y) holds 10·y + x: rows run top to bottom.
    /// let t = Texture2d::from_fn(3, 2, |x, y| R8((10 * y + x) as u8))?;
    /// assert_eq!(t.texel(2, 1), Some(R8(12)));
    /// assert_eq!(t.texels()[3], R8(10));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{Limits, R8, Texture2d, TextureError};
    ///
    /// let limits = Limits { max_width: 4, ..Limits::default() };
    /// let mut calls = 0;
    /// let err = Texture2d::from_fn_with_limits(5, 1, &limits, |_, _| {
    ///     calls += 1;
    ///     R8(0)
    /// });
    /// assert!(matches!(err, Err(TextureError::TooLarge { what: "width", requested: 5, limit: 4 })));
    /// assert_eq!(calls, 0); // refused before any texel was made
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d, TextureError};
    ///
    /// let t = Texture2d::from_texels(2, 2, vec![R8(1), R8(2), R8(3), R8(4)])?;
    /// assert_eq!(t.texel(0, 1), Some(R8(3)));
    /// // Three texels cannot fill 2×2.
    /// assert_eq!(
    ///     Texture2d::from_texels(2, 2, vec![R8(0); 3]),
    ///     Err(TextureError::DataLength { expected: 4, actual: 3 })
    /// );
    /// # Ok::<(), TextureError>(())
    /// ```
    pub fn from_texels(width: u32, height: u32, texels: Vec<T>) -> Result<Self, TextureError> {
        Self::from_texels_with_limits(width, height, texels, &Limits::default())
    }

    /// [`from_texels`](Self::from_texels) under the caller's limits.
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a length that is not `width × height`.
    ///
    /// ```
    /// use barytex_texture::{Limits, R8, Texture2d, TextureError};
    ///
    /// let limits = Limits { max_height: 1, ..Limits::default() };
    /// assert!(Texture2d::from_texels_with_limits(4, 1, vec![R8(0); 4], &limits).is_ok());
    /// assert!(matches!(
    ///     Texture2d::from_texels_with_limits(2, 2, vec![R8(0); 4], &limits),
    ///     Err(TextureError::TooLarge { what: "height", .. })
    /// ));
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let t = Texture2d::new(5, 3, R8(0))?;
    /// assert_eq!((t.width(), t.height()), (5, 3));
    /// assert_eq!(t.size(), (t.width(), t.height()));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels (≥ 1).
    ///
    /// ```
    /// # use barytex_texture::{R8, Texture2d};
    /// assert_eq!(Texture2d::new(1, 9, R8(0))?.height(), 9);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// `(width, height)`.
    ///
    /// ```
    /// # use barytex_texture::{R8, Texture2d};
    /// assert_eq!(Texture2d::new(4, 2, R8(0))?.size(), (4, 2));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// All texels, row-major.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let t = Texture2d::from_fn(2, 2, |x, y| R8((2 * y + x) as u8))?;
    /// assert_eq!(t.texels(), &[R8(0), R8(1), R8(2), R8(3)]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn texels(&self) -> &[T] {
        &self.texels
    }

    /// All texels, row-major, mutable.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let mut t = Texture2d::new(2, 2, R8(0))?;
    /// t.texels_mut()[3] = R8(9); // index 3 is (1, 1) in row-major order
    /// assert_eq!(t.texel(1, 1), Some(R8(9)));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn texels_mut(&mut self) -> &mut [T] {
        &mut self.texels
    }

    /// The texels, giving up the texture.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let t = Texture2d::from_texels(3, 1, vec![R8(1), R8(2), R8(3)])?;
    /// assert_eq!(t.into_texels(), vec![R8(1), R8(2), R8(3)]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn into_texels(self) -> Vec<T> {
        self.texels
    }

    /// Row `y` (top = 0); `None` past the last row.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let t = Texture2d::from_fn(3, 2, |x, y| R8((10 * y + x) as u8))?;
    /// assert_eq!(t.row(1), Some(&[R8(10), R8(11), R8(12)][..]));
    /// assert_eq!(t.row(2), None);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn row(&self, y: u32) -> Option<&[T]> {
        let w = self.width as usize;
        let start = (y as usize).checked_mul(w)?;
        self.texels.get(start..start + w)
    }

    /// Texel (x, y); `None` outside.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let t = Texture2d::from_fn(3, 2, |x, y| R8((10 * y + x) as u8))?;
    /// assert_eq!(t.texel(2, 1), Some(R8(12)));
    /// assert_eq!(t.texel(3, 0), None); // no wrapping or clamping here
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn texel(&self, x: u32, y: u32) -> Option<T> {
        (x < self.width && y < self.height)
            .then(|| self.texels[y as usize * self.width as usize + x as usize])
    }

    /// Texel (x, y), mutable; `None` outside.
    ///
    /// ```
    /// use barytex_texture::{R8, Texture2d};
    ///
    /// let mut t = Texture2d::new(2, 2, R8(0))?;
    /// if let Some(texel) = t.texel_mut(0, 1) {
    ///     *texel = R8(5);
    /// }
    /// assert_eq!(t.texels(), &[R8(0), R8(0), R8(5), R8(0)]);
    /// assert!(t.texel_mut(2, 0).is_none());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{Srgba8, Texture2d};
    ///
    /// // sRGB byte 188 decodes to about 0.5 linear light; alpha stays linear.
    /// let t = Texture2d::new(1, 1, Srgba8([188, 0, 255, 128]))?;
    /// let c = t.linear(0, 0).unwrap();
    /// assert!((c.x - 0.5).abs() < 0.003);
    /// assert_eq!((c.y, c.z), (0.0, 1.0));
    /// assert_eq!(c.w, 128.0 / 255.0);
    /// assert_eq!(t.linear(1, 0), None);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn linear(&self, x: u32, y: u32) -> Option<Vec4> {
        self.texel(x, y).map(Texel::to_linear)
    }

    /// The same texture converted texel by texel to another format (through linear light).
    ///
    /// # Errors
    /// A failed allocation.
    ///
    /// ```
    /// use barytex_texture::{Rgba8, Srgba8, Texture2d};
    ///
    /// // Linear 50 % grey (byte 128) is sRGB byte 188.
    /// let linear = Texture2d::new(2, 1, Rgba8([128, 128, 128, 255]))?;
    /// let srgb: Texture2d<Srgba8> = linear.convert()?;
    /// assert_eq!(srgb.texel(1, 0), Some(Srgba8([188, 188, 188, 255])));
    /// // And back: the round trip returns the same bytes.
    /// assert_eq!(srgb.convert::<Rgba8>()?, linear);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
    ///
    /// ```
    /// use barytex_texture::{Rgba32f, Srgba8, Texture2d};
    ///
    /// let t = Texture2d::new(1, 1, Srgba8([255, 0, 0, 255]))?;
    /// assert_eq!(t.to_linear()?.texel(0, 0), Some(Rgba32f([1.0, 0.0, 0.0, 1.0])));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
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
