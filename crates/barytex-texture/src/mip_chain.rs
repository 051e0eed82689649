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
#[must_use]
pub fn level_size(width: u32, height: u32, level: usize) -> (u32, u32) {
    let shift = u32::try_from(level).unwrap_or(u32::MAX).min(31);
    ((width >> shift).max(1), (height >> shift).max(1))
}

impl<T: Texel> MipChain<T> {
    /// A chain of the base level alone (magnification-only textures need no more).
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
    #[must_use]
    #[inline]
    pub fn levels(&self) -> &[Texture2d<T>] {
        &self.levels
    }

    /// Level `i`, or `None` past the last.
    #[must_use]
    #[inline]
    pub fn level(&self, i: usize) -> Option<&Texture2d<T>> {
        self.levels.get(i)
    }

    /// The base level.
    #[must_use]
    #[inline]
    pub fn base(&self) -> &Texture2d<T> {
        // Constructors guarantee at least one level.
        &self.levels[0]
    }

    /// The number of levels (≥ 1).
    #[must_use]
    #[inline]
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Always false: a chain has at least its base. (For clippy's `len_without_is_empty`.)
    #[must_use]
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// Whether the chain goes down to 1×1.
    #[must_use]
    pub fn is_complete(&self) -> bool {
        let (w, h) = self.base().size();
        self.levels.len() == full_length(w, h)
    }

    /// The levels, giving up the chain.
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
