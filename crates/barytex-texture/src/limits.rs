//! Size limits for untrusted input, checked before anything is allocated (image-rs's `Limits`).

use crate::TextureError;

/// The largest texture this crate will allocate. Loaders and constructors check these **before**
/// allocating, so an image that claims to be 100000×100000 is refused, not attempted.
///
/// The defaults allow any texture a GPU allows (16384² RGBA32F is 4 GiB, so the byte limit of
/// 1 GiB is what usually decides).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest width in texels.
    pub max_width: u32,
    /// Largest height in texels (or depth, layers).
    pub max_height: u32,
    /// Largest allocation for one texture (a mip chain counts all its levels) in bytes.
    pub max_bytes: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_width: 16_384,
            max_height: 16_384,
            max_bytes: 1 << 30,
        }
    }
}

impl Limits {
    /// No limit but the address space: for trusted, generated input.
    pub const UNLIMITED: Self = Self {
        max_width: u32::MAX,
        max_height: u32::MAX,
        max_bytes: u64::MAX,
    };

    /// Checks a `width × height` texture of `bytes_per_texel`-byte texels; returns its size in bytes.
    ///
    /// # Errors
    /// [`TextureError::Empty`] for a zero side, [`TextureError::TooLarge`] beyond a limit.
    ///
    /// ```
    /// use barytex_texture::{Limits, TextureError};
    ///
    /// let limits = Limits::default();
    /// // 256×128 texels of 4 bytes.
    /// assert_eq!(limits.check(256, 128, 4), Ok(131_072));
    /// assert_eq!(limits.check(0, 1, 4), Err(TextureError::Empty { width: 0, height: 1 }));
    /// assert!(matches!(
    ///     limits.check(100_000, 1, 4),
    ///     Err(TextureError::TooLarge { what: "width", requested: 100_000, limit: 16_384 })
    /// ));
    /// // A byte budget decides for large texels: 1024² RGBA32F is 16 MiB.
    /// let small = Limits { max_bytes: 1 << 20, ..Limits::default() };
    /// assert!(matches!(small.check(1024, 1024, 16), Err(TextureError::TooLarge { what: "bytes", .. })));
    /// assert_eq!(Limits::UNLIMITED.check(1024, 1024, 16), Ok(16 << 20));
    /// // No limit but the arithmetic: a size past u64 is refused, not saturated.
    /// assert!(matches!(
    ///     Limits::UNLIMITED.check(u32::MAX, u32::MAX, 16),
    ///     Err(TextureError::TooLarge { what: "bytes", requested: u64::MAX, .. })
    /// ));
    /// ```
    pub fn check(
        &self,
        width: u32,
        height: u32,
        bytes_per_texel: usize,
    ) -> Result<u64, TextureError> {
        if width == 0 || height == 0 {
            return Err(TextureError::Empty { width, height });
        }
        if width > self.max_width {
            return Err(TextureError::TooLarge {
                what: "width",
                requested: width.into(),
                limit: self.max_width.into(),
            });
        }
        if height > self.max_height {
            return Err(TextureError::TooLarge {
                what: "height",
                requested: height.into(),
                limit: self.max_height.into(),
            });
        }
        // u32 × u32 fits u64, but not times a texel's bytes for the largest sides (under
        // `UNLIMITED`). An overflow is refused as "more than u64::MAX bytes", never saturated:
        // a saturated product equal to an `u64::MAX` limit would pass.
        let bytes = u64::from(width)
            .checked_mul(u64::from(height))
            .and_then(|texels| texels.checked_mul(bytes_per_texel as u64));
        let Some(bytes) = bytes else {
            return Err(TextureError::TooLarge {
                what: "bytes",
                requested: u64::MAX,
                limit: self.max_bytes,
            });
        };
        if bytes > self.max_bytes || usize::try_from(bytes).is_err() {
            return Err(TextureError::TooLarge {
                what: "bytes",
                requested: bytes,
                limit: self.max_bytes,
            });
        }
        Ok(bytes)
    }
}
