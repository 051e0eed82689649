//! How to pack: the texture size, the padding between charts, whether charts may turn.

use super::PackError;

/// The largest texture side [`PackOptions::size`] accepts (texels).
pub const MAX_ATLAS_SIZE: u32 = 1 << 15;

/// How charts are packed into the unit square.
///
/// ```
/// use barytex_unwrap::pack::PackOptions;
///
/// let lightmap = PackOptions { size: 512, padding: 2, ..PackOptions::default() };
/// assert!(lightmap.validate().is_ok());
/// assert!(PackOptions { size: 4, padding: 2, ..PackOptions::default() }.validate().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PackOptions {
    /// The texture's side in texels (the unit square is `size × size` texels), 1 to
    /// [`MAX_ATLAS_SIZE`].
    pub size: u32,
    /// The gap in texels between any two charts and between a chart and the border; at most a
    /// quarter of `size`.
    pub padding: u32,
    /// Turn each chart to its minimum-area bounding box, and let the packer turn it by 90°
    /// more; without it charts keep the orientation they came with.
    pub rotate: bool,
}

impl Default for PackOptions {
    /// 1024 texels, 4 texels of padding (enough for bilinear filtering and a few mip levels),
    /// rotations on.
    fn default() -> Self {
        Self {
            size: 1024,
            padding: 4,
            rotate: true,
        }
    }
}

impl PackOptions {
    /// Checks the ranges documented on the fields.
    ///
    /// # Errors
    /// [`PackError::Options`] naming the field out of range.
    pub fn validate(&self) -> Result<(), PackError> {
        if self.size == 0 || self.size > MAX_ATLAS_SIZE {
            return Err(PackError::Options("size must be 1 to 32768 texels"));
        }
        if u64::from(self.padding) * 4 > u64::from(self.size) {
            return Err(PackError::Options(
                "padding must be at most a quarter of the size",
            ));
        }
        Ok(())
    }
}
