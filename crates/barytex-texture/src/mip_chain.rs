//! `MipChain`: a texture and its successively halved levels, down to 1×1.

use crate::{Texel, Texture2d, TextureError};

/// Level 0 (the base) and its reductions: level `i + 1` is `max(1, ⌊w/2⌋) × max(1, ⌊h/2⌋)` of
/// level `i`. A chain may stop early (a "partial" chain); [`full_length`] gives the length of a
/// complete one.
#[derive(Clone, Debug, PartialEq)]
pub struct MipChain<T> {
    levels: Vec<Texture2d<T>>,
}

/// The number of levels of a complete chain for a `width × height` base:
/// `⌊log₂ max(width, height)⌋ + 1` (0 for an empty size).
///
/// ```
/// use barytex_texture::mip_chain::full_length;
///
/// assert_eq!(full_length(256, 256), 9); // 256, 128, …, 1
/// assert_eq!(full_length(5, 3), 3); // 5×3, 2×1, 1×1
/// assert_eq!(full_length(1, 1), 1);
/// assert_eq!(full_length(0, 0), 0);
/// ```
#[must_use]
pub fn full_length(width: u32, height: u32) -> usize {
    let side = width.max(height);
    if side == 0 {
        0
    } else {
        (u32::BITS - side.leading_zeros()) as usize
    }
}

/// The size of level `level` of a chain whose base is `width × height`.
///
/// ```
/// use barytex_texture::mip_chain::level_size;
///
/// assert_eq!(level_size(5, 3, 0), (5, 3));
/// assert_eq!(level_size(5, 3, 1), (2, 1)); // rounded down
/// assert_eq!(level_size(5, 3, 2), (1, 1)); // never below 1
/// assert_eq!(level_size(5, 3, 99), (1, 1));
/// ```
#[must_use]
pub fn level_size(width: u32, height: u32, level: usize) -> (u32, u32) {
    let shift = u32::try_from(level).unwrap_or(u32::MAX).min(31);
    ((width >> shift).max(1), (height >> shift).max(1))
}

impl<T: Texel> MipChain<T> {
    /// A chain of the base level alone (magnification-only textures need no more).
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, Texture2d};
    ///
    /// let chain = MipChain::single(Texture2d::new(4, 4, R8(1))?);
    /// assert_eq!(chain.len(), 1);
    /// assert!(!chain.is_complete()); // a 4×4 base has a 3-level chain
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn single(base: Texture2d<T>) -> Self {
        Self { levels: vec![base] }
    }

    /// A chain from levels built elsewhere; checks that each level has the size the halving rule
    /// gives.
    ///
    /// # Errors
    /// [`TextureError::InvalidParameter`] for no levels, a wrong level size, or more levels than a
    /// complete chain has.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, Texture2d, TextureError};
    ///
    /// let level = |w, h| Texture2d::new(w, h, R8(0));
    /// let chain = MipChain::from_levels(vec![level(4, 2)?, level(2, 1)?, level(1, 1)?])?;
    /// assert!(chain.is_complete());
    /// // 4×2 halves to 2×1, not 2×2.
    /// assert!(matches!(
    ///     MipChain::from_levels(vec![level(4, 2)?, level(2, 2)?]),
    ///     Err(TextureError::InvalidParameter { what: "levels", .. })
    /// ));
    /// assert!(MipChain::<R8>::from_levels(Vec::new()).is_err());
    /// # Ok::<(), TextureError>(())
    /// ```
    pub fn from_levels(levels: Vec<Texture2d<T>>) -> Result<Self, TextureError> {
        let Some(base) = levels.first() else {
            return Err(TextureError::InvalidParameter {
                what: "levels",
                reason: "a mip chain needs at least the base level",
            });
        };
        let (w, h) = base.size();
        if levels.len() > full_length(w, h) {
            return Err(TextureError::InvalidParameter {
                what: "levels",
                reason: "more levels than a complete chain has",
            });
        }
        for (i, level) in levels.iter().enumerate() {
            if level.size() != level_size(w, h, i) {
                return Err(TextureError::InvalidParameter {
                    what: "levels",
                    reason: "a level is not half the size of the one before (rounded down, at least 1)",
                });
            }
        }
        Ok(Self { levels })
    }

    /// All levels, base first (never empty).
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let chain = MipChain::generate(Texture2d::new(8, 2, R8(3))?, &MipOptions::default())?;
    /// let sizes: Vec<_> = chain.levels().iter().map(|l| l.size()).collect();
    /// assert_eq!(sizes, [(8, 2), (4, 1), (2, 1), (1, 1)]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn levels(&self) -> &[Texture2d<T>] {
        &self.levels
    }

    /// Level `i`, or `None` past the last.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let chain = MipChain::generate(Texture2d::new(2, 2, R8(3))?, &MipOptions::default())?;
    /// assert_eq!(chain.level(1).map(|l| l.texels().to_vec()), Some(vec![R8(3)]));
    /// assert!(chain.level(2).is_none());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn level(&self, i: usize) -> Option<&Texture2d<T>> {
        self.levels.get(i)
    }

    /// The base level.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let base = Texture2d::from_fn(2, 2, |x, _| R8(x as u8))?;
    /// let chain = MipChain::generate(base.clone(), &MipOptions::default())?;
    /// assert_eq!(chain.base(), &base);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn base(&self) -> &Texture2d<T> {
        // Constructors guarantee at least one level.
        &self.levels[0]
    }

    /// The number of levels (≥ 1).
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let options = MipOptions { max_levels: Some(2), ..MipOptions::default() };
    /// let chain = MipChain::generate(Texture2d::new(16, 16, R8(0))?, &options)?;
    /// assert_eq!(chain.len(), 2);
    /// assert!(!chain.is_empty());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Always false: a chain has at least its base. (For clippy's `len_without_is_empty`.)
    ///
    /// ```
    /// # use barytex_texture::{MipChain, R8, Texture2d};
    /// assert!(!MipChain::single(Texture2d::new(1, 1, R8(0))?).is_empty());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// Whether the chain goes down to 1×1.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let base = Texture2d::new(4, 4, R8(0))?;
    /// assert!(MipChain::generate(base.clone(), &MipOptions::default())?.is_complete());
    /// let partial = MipOptions { max_levels: Some(2), ..MipOptions::default() };
    /// assert!(!MipChain::generate(base, &partial)?.is_complete());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn is_complete(&self) -> bool {
        let (w, h) = self.base().size();
        self.levels.len() == full_length(w, h)
    }

    /// The levels, giving up the chain.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, Texture2d};
    ///
    /// let chain = MipChain::generate(Texture2d::new(2, 1, R8(9))?, &MipOptions::default())?;
    /// let levels = chain.into_levels();
    /// assert_eq!(levels.len(), 2);
    /// assert_eq!(levels[1].texels(), &[R8(9)]);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn into_levels(self) -> Vec<Texture2d<T>> {
        self.levels
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::R8;

    #[test]
    fn full_length_is_floor_log2_plus_one() {
        assert_eq!(full_length(1, 1), 1);
        assert_eq!(full_length(2, 1), 2);
        assert_eq!(full_length(3, 1), 2);
        assert_eq!(full_length(1, 4096), 13);
        assert_eq!(full_length(4095, 7), 12);
        assert_eq!(full_length(0, 0), 0);
        assert_eq!(level_size(5, 3, 1), (2, 1));
        assert_eq!(level_size(5, 3, 2), (1, 1));
        assert_eq!(level_size(5, 3, 99), (1, 1));
    }

    #[test]
    fn from_levels_checks_sizes() {
        let t = |w, h| Texture2d::new(w, h, R8(0)).expect("small");
        assert!(
            MipChain::from_levels(vec![t(5, 3), t(2, 1), t(1, 1)]).is_ok_and(|c| c.is_complete())
        );
        assert!(MipChain::from_levels(vec![t(5, 3), t(3, 2)]).is_err());
        assert!(MipChain::from_levels(vec![t(1, 1), t(1, 1)]).is_err());
        assert!(MipChain::<R8>::from_levels(vec![]).is_err());
        assert!(!MipChain::single(t(4, 4)).is_complete());
    }
}
