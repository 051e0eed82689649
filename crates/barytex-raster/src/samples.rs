//! Where the samples of a pixel lie: regular grids, stratified jitter, and the GPUs' standard
//! multisample positions. Positions are snapped to the 1/256-pixel grid of the fixed-point edge
//! functions, so coverage at a sample is decided exactly, with the same top-left rule as at
//! pixel centres.

use glam::Vec2;

use crate::edge::SUBPIXEL_BITS;
use crate::error::RasterError;

/// The most samples a pixel of a multisampled target may have (coverage is a 32-bit mask).
pub const MAX_SAMPLES: u32 = 32;

/// The largest grid side of [`SamplePattern::offsets`] (and so of
/// [`render_supersampled`](crate::render_supersampled)): 64 × 64 = 4096 passes.
pub const MAX_GRID: u32 = 64;

const ONE: i64 = 1 << SUBPIXEL_BITS;

/// Where the samples of a pixel lie.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplePattern {
    /// The centres of an `n × n` grid of sub-pixel cells (`n = 1`: the pixel centre).
    Regular {
        /// Cells per side.
        n: u32,
    },
    /// One random position in each cell of an `n × n` grid (stratified jitter); `seed` makes it
    /// repeatable. In a multisampled [`Framebuffer`](crate::Framebuffer) the positions differ
    /// from pixel to pixel (aliasing turns into noise); in
    /// [`render_supersampled`](crate::render_supersampled) they differ from pass to pass.
    Jittered {
        /// Cells per side.
        n: u32,
        /// Selects the positions.
        seed: u64,
    },
    /// The standard sample positions of Vulkan and Direct3D for 1, 2, 4, 8 or 16 samples (what
    /// a GPU's MSAA uses; rotated grids that resolve near-horizontal and near-vertical edges
    /// with as many levels as samples).
    Standard {
        /// 1, 2, 4, 8 or 16.
        count: u32,
    },
}

/// Vulkan's standard sample locations, in 1/16 pixel from the pixel's top-left corner.
const STANDARD_1: [(u8, u8); 1] = [(8, 8)];
const STANDARD_2: [(u8, u8); 2] = [(12, 12), (4, 4)];
const STANDARD_4: [(u8, u8); 4] = [(6, 2), (14, 6), (2, 10), (10, 14)];
const STANDARD_8: [(u8, u8); 8] = [
    (9, 5),
    (7, 11),
    (13, 9),
    (5, 3),
    (3, 13),
    (1, 7),
    (11, 15),
    (15, 1),
];
const STANDARD_16: [(u8, u8); 16] = [
    (9, 9),
    (7, 5),
    (5, 10),
    (12, 7),
    (3, 6),
    (10, 13),
    (13, 11),
    (11, 3),
    (6, 14),
    (8, 1),
    (4, 2),
    (2, 12),
    (0, 8),
    (15, 4),
    (14, 15),
    (1, 0),
];

impl SamplePattern {
    /// One sample at the pixel centre: no anti-aliasing.
    pub const CENTRE: Self = Self::Regular { n: 1 };

    /// Samples per pixel (saturating: a pattern beyond `u32::MAX` samples reports `u32::MAX`).
    ///
    /// ```
    /// use barytex_raster::SamplePattern;
    ///
    /// assert_eq!(SamplePattern::CENTRE.count(), 1);
    /// assert_eq!(SamplePattern::Regular { n: 3 }.count(), 9);
    /// assert_eq!(SamplePattern::Standard { count: 16 }.count(), 16);
    /// assert_eq!(SamplePattern::Regular { n: u32::MAX }.count(), u32::MAX);
    /// ```
    #[must_use]
    pub fn count(self) -> u32 {
        match self {
            Self::Regular { n } | Self::Jittered { n, .. } => n.max(1).saturating_mul(n.max(1)),
            Self::Standard { count } => count,
        }
    }

    /// Checks the pattern: at most [`MAX_SAMPLES`] samples, a standard count of 1, 2, 4, 8 or 16.
    ///
    /// ```
    /// use barytex_raster::{RasterError, SamplePattern};
    ///
    /// assert_eq!(SamplePattern::Standard { count: 8 }.validate(), Ok(()));
    /// assert_eq!(SamplePattern::Jittered { n: 5, seed: 1 }.validate(), Ok(()));
    /// // 6 × 6 = 36 samples do not fit a 32-bit coverage mask.
    /// assert!(matches!(
    ///     SamplePattern::Regular { n: 6 }.validate(),
    ///     Err(RasterError::InvalidParameter { what: "sample count", .. })
    /// ));
    /// assert!(SamplePattern::Standard { count: 3 }.validate().is_err());
    /// ```
    ///
    /// # Errors
    /// [`RasterError::InvalidParameter`] naming what is wrong.
    pub fn validate(self) -> Result<(), RasterError> {
        match self {
            Self::Standard { count } if !matches!(count, 1 | 2 | 4 | 8 | 16) => {
                Err(RasterError::InvalidParameter {
                    what: "sample count",
                    reason: "standard patterns have 1, 2, 4, 8 or 16 samples",
                })
            }
            Self::Regular { n } | Self::Jittered { n, .. } if n > 5 => {
                Err(RasterError::InvalidParameter {
                    what: "sample count",
                    reason: "at most 5 × 5 samples per pixel (a 32-bit coverage mask)",
                })
            }
            _ => Ok(()),
        }
    }

    /// Sample `k` of pixel `(x, y)` in 1/256 pixel from the pixel's top-left corner, each
    /// coordinate in `[0, 256)`.
    #[must_use]
    pub(crate) fn fixed_offset(self, x: i64, y: i64, k: u32) -> (i64, i64) {
        match self {
            Self::Regular { n } => {
                let n = i64::from(n.max(1));
                let (i, j) = (i64::from(k) % n, i64::from(k) / n);
                // The cell centre (2i + 1)/(2n), rounded to the grid.
                (
                    ((2 * i + 1) * ONE + n) / (2 * n),
                    ((2 * j + 1) * ONE + n) / (2 * n),
                )
            }
            Self::Jittered { n, seed } => {
                let n = i64::from(n.max(1));
                let (i, j) = (i64::from(k) % n, i64::from(k) / n);
                let key = hash(seed, (x as u64) ^ ((y as u64) << 32), u64::from(k));
                let cell = |c: i64, r: u64| (c * ONE + (r % 65_536) as i64 * ONE / 65_536) / n;
                (cell(i, key), cell(j, key >> 16))
            }
            Self::Standard { count } => {
                let table: &[(u8, u8)] = match count {
                    2 => &STANDARD_2,
                    4 => &STANDARD_4,
                    8 => &STANDARD_8,
                    16 => &STANDARD_16,
                    _ => &STANDARD_1,
                };
                let (sx, sy) = table[k as usize % table.len()];
                (i64::from(sx) * 16, i64::from(sy) * 16)
            }
        }
    }

    /// Sample `k` of pixel `(x, y)` as an offset in pixels from the pixel's top-left corner,
    /// exactly where a multisampled [`Framebuffer`](crate::Framebuffer) tests coverage (on the
    /// 1/256-pixel grid).
    ///
    /// ```
    /// use barytex_raster::SamplePattern;
    /// use glam::Vec2;
    ///
    /// // Vulkan's 4× positions, in sixteenths of a pixel: (6, 2), (14, 6), (2, 10), (10, 14).
    /// let p = SamplePattern::Standard { count: 4 };
    /// assert_eq!(p.sample_offset(0, 0, 1), Vec2::new(14.0, 6.0) / 16.0);
    /// assert_eq!(p.sample_offset(9, 4, 1), p.sample_offset(0, 0, 1)); // the same in every pixel
    /// // Jitter differs from pixel to pixel but stays in its cell of the 2 × 2 grid.
    /// let j = SamplePattern::Jittered { n: 2, seed: 5 };
    /// let o = j.sample_offset(3, 7, 3);
    /// assert!(o.x >= 0.5 && o.x < 1.0 && o.y >= 0.5 && o.y < 1.0);
    /// ```
    #[must_use]
    pub fn sample_offset(self, x: u32, y: u32, k: u32) -> Vec2 {
        let (ox, oy) = self.fixed_offset(i64::from(x), i64::from(y), k);
        Vec2::new(ox as f32, oy as f32) / ONE as f32
    }

    /// Whether every pixel has the same positions.
    pub(crate) fn is_uniform(self) -> bool {
        !matches!(self, Self::Jittered { n, .. } if n > 1)
    }

    /// The sample offsets of pixel (0, 0) from its top-left corner, each in `[0, 1)²` (for a
    /// jittered pattern, the positions one pass of
    /// [`render_supersampled`](crate::render_supersampled) uses for every pixel). Grids are
    /// limited to [`MAX_GRID`] × [`MAX_GRID`]: a larger `n` gives that many. A `Standard` count
    /// other than 1, 2, 4, 8 or 16 (which [`validate`](Self::validate) refuses) gives the one
    /// centre sample, as [`sample_offset`](Self::sample_offset) places it (it used to give
    /// `count` copies of the centre: 4 G of them for `u32::MAX`).
    ///
    /// ```
    /// use barytex_raster::SamplePattern;
    /// use glam::Vec2;
    ///
    /// assert_eq!(SamplePattern::CENTRE.offsets(), vec![Vec2::splat(0.5)]);
    /// assert_eq!(
    ///     SamplePattern::Regular { n: 2 }.offsets(),
    ///     vec![Vec2::new(0.25, 0.25), Vec2::new(0.75, 0.25), Vec2::new(0.25, 0.75), Vec2::new(0.75, 0.75)]
    /// );
    /// assert_eq!(SamplePattern::Jittered { n: 100, seed: 0 }.offsets().len(), 64 * 64);
    /// ```
    #[must_use]
    pub fn offsets(self) -> Vec<Vec2> {
        let this = match self {
            Self::Regular { n } => Self::Regular { n: n.min(MAX_GRID) },
            Self::Jittered { n, seed } => Self::Jittered {
                n: n.min(MAX_GRID),
                seed,
            },
            Self::Standard { count } if !matches!(count, 1 | 2 | 4 | 8 | 16) => {
                Self::Standard { count: 1 }
            }
            standard => standard,
        };
        match this {
            Self::Jittered { n, seed } => {
                // Per-pass jitter keeps the unquantized positions.
                let n = n.max(1);
                let cell = 1.0 / n as f32;
                (0..n * n)
                    .map(|k| {
                        let (i, j) = (k % n, k / n);
                        let u = hash01(seed, u64::from(k), 0);
                        let v = hash01(seed, u64::from(k), 1);
                        Vec2::new((i as f32 + u) * cell, (j as f32 + v) * cell)
                    })
                    .collect()
            }
            _ => (0..this.count())
                .map(|k| {
                    let (x, y) = this.fixed_offset(0, 0, k);
                    Vec2::new(x as f32, y as f32) / ONE as f32
                })
                .collect(),
        }
    }
}

/// SplitMix64 of a seed, an index and a stream.
fn hash(seed: u64, index: u64, stream: u64) -> u64 {
    let mut z = seed
        .wrapping_add(index.wrapping_mul(0x9E37_79B9_7F4A_7C15))
        .wrapping_add(stream.wrapping_mul(0xD1B5_4A32_D192_ED03));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A uniform value in [0, 1) from a seed, an index and a stream.
pub(crate) fn hash01(seed: u64, index: u64, stream: u64) -> f32 {
    (hash(seed, index, stream) >> 40) as f32 / (1u64 << 24) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_stay_inside_the_pixel_and_in_their_cells() {
        for pattern in [
            SamplePattern::Regular { n: 3 },
            SamplePattern::Jittered { n: 4, seed: 7 },
            SamplePattern::Standard { count: 16 },
        ] {
            for (x, y) in [(0, 0), (5, 9), (-3, 1000)] {
                for k in 0..pattern.count() {
                    let (ox, oy) = pattern.fixed_offset(x, y, k);
                    assert!(
                        (0..ONE).contains(&ox) && (0..ONE).contains(&oy),
                        "{pattern:?}"
                    );
                    if let SamplePattern::Jittered { n, .. } = pattern {
                        let (i, j) = (i64::from(k % n), i64::from(k / n));
                        let cell = ONE / i64::from(n);
                        assert_eq!((ox / cell, oy / cell), (i, j));
                    }
                }
            }
        }
    }

    #[test]
    fn huge_grids_are_capped_not_overflowed() {
        assert_eq!(
            SamplePattern::Jittered { n: 70_000, seed: 1 }.count(),
            u32::MAX
        );
        let offsets = SamplePattern::Jittered { n: 70_000, seed: 1 }.offsets();
        assert_eq!(offsets.len(), (MAX_GRID * MAX_GRID) as usize);
        assert_eq!(
            SamplePattern::Regular { n: u32::MAX }.offsets().len(),
            (MAX_GRID * MAX_GRID) as usize
        );
        assert!(SamplePattern::Regular { n: 6 }.validate().is_err());
        assert!(SamplePattern::Standard { count: 3 }.validate().is_err());
        assert!(SamplePattern::Standard { count: 16 }.validate().is_ok());
    }

    #[test]
    fn standard_patterns_have_distinct_rows_and_columns() {
        // What makes them good on near-axis edges: n samples give n coverage levels.
        for count in [2, 4, 8, 16] {
            let p = SamplePattern::Standard { count };
            let mut xs: Vec<i64> = (0..count).map(|k| p.fixed_offset(0, 0, k).0).collect();
            let mut ys: Vec<i64> = (0..count).map(|k| p.fixed_offset(0, 0, k).1).collect();
            xs.sort_unstable();
            ys.sort_unstable();
            xs.dedup();
            ys.dedup();
            assert_eq!((xs.len(), ys.len()), (count as usize, count as usize));
        }
    }
}
