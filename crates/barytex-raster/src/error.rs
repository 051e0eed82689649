//! The rasterizer's errors and the limits on what a target may allocate.

use core::fmt;

/// Why a target could not be made or a parameter was refused.
///
/// The messages name what was wrong and the sizes involved, never pixel data.
///
/// ```
/// use barytex_raster::{Framebuffer, RasterError, TargetLimits};
/// use glam::Vec4;
///
/// let r = Framebuffer::new(0, 8, Vec4::ZERO, &TargetLimits::default());
/// assert!(matches!(r, Err(RasterError::InvalidParameter { what: "width", .. })));
/// assert_eq!(r.unwrap_err().to_string(), "width: a target needs at least one pixel per side");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum RasterError {
    /// A parameter out of its range: a zero side, an invalid sample pattern, adaptive options
    /// out of range.
    InvalidParameter {
        /// Which parameter (`"width"`, `"height"`, `"sample count"`, `"adaptive options"`).
        what: &'static str,
        /// Why it was refused.
        reason: &'static str,
    },
    /// Larger than the [`TargetLimits`] allow; nothing was allocated.
    TooLarge {
        /// What was too large (`"width"`, `"height"` or `"bytes"`).
        what: &'static str,
        /// The size asked for (for `"bytes"`, saturated at `u64::MAX`).
        requested: u64,
        /// The limit.
        limit: u64,
    },
    /// The allocator could not provide the memory (or the size does not fit the address space).
    OutOfMemory {
        /// Bytes asked for (saturated at `u64::MAX`).
        bytes: u64,
    },
}

impl fmt::Display for RasterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidParameter { what, reason } => write!(f, "{what}: {reason}"),
            Self::TooLarge {
                what,
                requested,
                limit,
            } => write!(f, "target {what} {requested} exceeds the limit {limit}"),
            Self::OutOfMemory { bytes } => write!(f, "could not allocate {bytes} bytes"),
        }
    }
}

impl std::error::Error for RasterError {}

/// What one render target may allocate: its sides, and its bytes (colour and depth of every
/// sample, the buffers padded to whole [`TILE`](crate::TILE)² tiles).
///
/// ```
/// use barytex_raster::{Framebuffer, RasterError, TargetLimits};
/// use glam::Vec4;
///
/// // 64 × 64 pixels (one tile) × 4 samples × 20 bytes.
/// let limits = TargetLimits { max_bytes: 327_680, ..TargetLimits::default() };
/// let pattern = barytex_raster::SamplePattern::Standard { count: 4 };
/// assert!(Framebuffer::multisampled(64, 64, pattern, Vec4::ZERO, &limits).is_ok());
/// // One more column needs a second tile: twice the bytes.
/// let r = Framebuffer::multisampled(65, 64, pattern, Vec4::ZERO, &limits);
/// assert!(matches!(r, Err(RasterError::TooLarge { what: "bytes", requested: 655_360, .. })));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TargetLimits {
    /// Largest width in pixels.
    pub max_width: u32,
    /// Largest height in pixels.
    pub max_height: u32,
    /// Largest allocation for one target in bytes.
    pub max_bytes: u64,
}

impl Default for TargetLimits {
    /// 16 384 pixels a side (the 2D texture size Direct3D 11 requires of every device,
    /// `D3D11_REQ_TEXTURE2D_U_OR_V_DIMENSION`, as barytex-texture's default), 1 GiB a target.
    fn default() -> Self {
        Self {
            max_width: 16_384,
            max_height: 16_384,
            max_bytes: 1 << 30,
        }
    }
}

impl TargetLimits {
    /// No limit but the address space: for trusted sizes.
    pub const UNLIMITED: Self = Self {
        max_width: u32::MAX,
        max_height: u32::MAX,
        max_bytes: u64::MAX,
    };

    /// Checks the sides of a `width × height` target: not zero, within the limits.
    ///
    /// ```
    /// use barytex_raster::{RasterError, TargetLimits};
    ///
    /// let limits = TargetLimits::default();
    /// assert_eq!(limits.check_sides(1920, 1080), Ok(()));
    /// assert!(matches!(limits.check_sides(1920, 0),
    ///     Err(RasterError::InvalidParameter { what: "height", .. })));
    /// assert_eq!(limits.check_sides(20_000, 1),
    ///     Err(RasterError::TooLarge { what: "width", requested: 20_000, limit: 16_384 }));
    /// ```
    ///
    /// # Errors
    /// [`RasterError::InvalidParameter`] for a zero side, [`RasterError::TooLarge`] beyond a
    /// limit.
    pub fn check_sides(&self, width: u32, height: u32) -> Result<(), RasterError> {
        for (what, side, limit) in [
            ("width", width, self.max_width),
            ("height", height, self.max_height),
        ] {
            if side == 0 {
                return Err(RasterError::InvalidParameter {
                    what,
                    reason: "a target needs at least one pixel per side",
                });
            }
            if side > limit {
                return Err(RasterError::TooLarge {
                    what,
                    requested: side.into(),
                    limit: limit.into(),
                });
            }
        }
        Ok(())
    }

    /// Checks an allocation of `bytes` (`None`: the product overflowed `u64`) against
    /// [`max_bytes`](Self::max_bytes) and the address space; returns it as a `usize`.
    ///
    /// ```
    /// use barytex_raster::{RasterError, TargetLimits};
    ///
    /// let limits = TargetLimits { max_bytes: 1 << 20, ..TargetLimits::default() };
    /// assert_eq!(limits.check_bytes(Some(1 << 20)), Ok(1 << 20));
    /// assert!(matches!(limits.check_bytes(Some((1 << 20) + 1)),
    ///     Err(RasterError::TooLarge { what: "bytes", .. })));
    /// // A product that overflowed: over any finite limit.
    /// let bytes = u64::MAX.checked_mul(20);
    /// assert!(matches!(limits.check_bytes(bytes), Err(RasterError::TooLarge { .. })));
    /// ```
    ///
    /// # Errors
    /// [`RasterError::TooLarge`] beyond the limit (an overflowed product counts as `u64::MAX`
    /// bytes), [`RasterError::OutOfMemory`] beyond the address space.
    pub fn check_bytes(&self, bytes: Option<u64>) -> Result<usize, RasterError> {
        let requested = bytes.unwrap_or(u64::MAX);
        if requested > self.max_bytes {
            return Err(RasterError::TooLarge {
                what: "bytes",
                requested,
                limit: self.max_bytes,
            });
        }
        bytes
            .and_then(|b| usize::try_from(b).ok())
            .ok_or(RasterError::OutOfMemory { bytes: requested })
    }
}

/// `n` copies of `value` in a vector allocated fallibly: an error, not an abort, when the
/// allocator refuses (or `n` elements overflow the address space).
pub(crate) fn try_filled<T: Clone>(n: usize, value: T) -> Result<Vec<T>, RasterError> {
    let bytes = n.checked_mul(size_of::<T>());
    let mut v = Vec::new();
    match bytes {
        Some(_) if v.try_reserve_exact(n).is_ok() => {
            v.resize(n, value);
            Ok(v)
        }
        _ => Err(RasterError::OutOfMemory {
            bytes: bytes.map_or(u64::MAX, |b| u64::try_from(b).unwrap_or(u64::MAX)),
        }),
    }
}

/// [`try_filled`], the copies written in parallel on the current rayon pool (a target's
/// first write touches every page of it: tens of megabytes for a 1024² frame).
pub(crate) fn try_filled_parallel<T: Clone + Send + Sync>(
    n: usize,
    value: T,
) -> Result<Vec<T>, RasterError> {
    use rayon::prelude::*;
    let bytes = n.checked_mul(size_of::<T>());
    let mut v = Vec::new();
    match bytes {
        Some(_) if v.try_reserve_exact(n).is_ok() => {
            // One thread fills faster alone (a plain memory fill, no job splitting).
            if rayon::current_num_threads() > 1 {
                v.par_extend(rayon::iter::repeat_n(value, n));
            } else {
                v.resize(n, value);
            }
            Ok(v)
        }
        _ => Err(RasterError::OutOfMemory {
            bytes: bytes.map_or(u64::MAX, |b| u64::try_from(b).unwrap_or(u64::MAX)),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sides_are_checked_width_first_and_zero_before_size() {
        let l = TargetLimits::default();
        assert_eq!(l.check_sides(1, 1), Ok(()));
        assert_eq!(l.check_sides(16_384, 16_384), Ok(()));
        assert!(matches!(
            l.check_sides(0, 0),
            Err(RasterError::InvalidParameter { what: "width", .. })
        ));
        assert!(matches!(
            l.check_sides(5, 0),
            Err(RasterError::InvalidParameter { what: "height", .. })
        ));
        assert_eq!(
            l.check_sides(16_385, 0),
            Err(RasterError::TooLarge {
                what: "width",
                requested: 16_385,
                limit: 16_384
            })
        );
        assert_eq!(
            TargetLimits::UNLIMITED.check_sides(u32::MAX, u32::MAX),
            Ok(())
        );
    }

    #[test]
    fn bytes_are_checked_against_the_limit_and_overflow() {
        let l = TargetLimits {
            max_bytes: 100,
            ..TargetLimits::default()
        };
        assert_eq!(l.check_bytes(Some(100)), Ok(100));
        assert_eq!(
            l.check_bytes(Some(101)),
            Err(RasterError::TooLarge {
                what: "bytes",
                requested: 101,
                limit: 100
            })
        );
        // An overflowing product: over any finite limit, beyond the address space otherwise.
        assert_eq!(
            l.check_bytes(None),
            Err(RasterError::TooLarge {
                what: "bytes",
                requested: u64::MAX,
                limit: 100
            })
        );
        assert_eq!(
            TargetLimits::UNLIMITED.check_bytes(None),
            Err(RasterError::OutOfMemory { bytes: u64::MAX })
        );
    }

    #[test]
    fn failed_allocations_are_errors() {
        assert_eq!(
            try_filled(usize::MAX, 0_u32),
            Err(RasterError::OutOfMemory { bytes: u64::MAX })
        );
        // isize::MAX / 2 bytes: a size the allocator is asked for and refuses.
        assert!(matches!(
            try_filled(usize::MAX / 4, 0_u8),
            Err(RasterError::OutOfMemory { .. })
        ));
        assert_eq!(try_filled(3, 7_u8), Ok(vec![7, 7, 7]));
    }

    #[test]
    fn messages_name_the_parameter_and_sizes() {
        let e = RasterError::TooLarge {
            what: "bytes",
            requested: 2,
            limit: 1,
        };
        assert_eq!(e.to_string(), "target bytes 2 exceeds the limit 1");
        assert_eq!(
            RasterError::OutOfMemory { bytes: 9 }.to_string(),
            "could not allocate 9 bytes"
        );
    }
}
