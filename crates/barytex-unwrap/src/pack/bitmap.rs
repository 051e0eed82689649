//! A bit-packed occupancy bitmap: one bit per texel, each row `⌈width / 64⌉` `u64` words, and
//! per row the span of its set bits, so range queries on empty rows or past a row's ends take
//! no word reads at all.
//!
//! The packer asks one thing of it, over and over: the last set bit in a range of a row
//! ([`Bitmap::last_set_in`]), answered a word at a time with masks and `leading_zeros`.

/// The most bits a bitmap may hold (64 MiB words in all); larger ones are refused, so a huge
/// scale or texture size never allocates without bound.
pub(crate) const MAX_BITS: usize = 1 << 29;

/// A `width × height` grid of bits, all clear at first.
#[derive(Clone, Debug)]
pub(crate) struct Bitmap {
    width: usize,
    height: usize,
    /// Words per row.
    stride: usize,
    words: Vec<u64>,
    /// Per row, the first and last set bit (`first > last` for an empty row).
    spans: Vec<(usize, usize)>,
}

const EMPTY: (usize, usize) = (usize::MAX, 0);

/// The bits `lo..=hi` (both in `0..64`, `lo <= hi`) of a word set.
fn word_mask(lo: usize, hi: usize) -> u64 {
    let upper = if hi == 63 {
        u64::MAX
    } else {
        (1u64 << (hi + 1)) - 1
    };
    upper & !((1u64 << lo) - 1)
}

impl Bitmap {
    /// A clear bitmap, or `None` when it would hold more than [`MAX_BITS`] bits.
    pub(crate) fn new(width: usize, height: usize) -> Option<Self> {
        let stride = width.div_ceil(64);
        let words = stride.checked_mul(height)?;
        if words.checked_mul(64)? > MAX_BITS {
            return None;
        }
        Some(Self {
            width,
            height,
            stride,
            words: vec![0; words],
            spans: vec![EMPTY; height],
        })
    }

    pub(crate) fn width(&self) -> usize {
        self.width
    }

    pub(crate) fn height(&self) -> usize {
        self.height
    }

    /// Sets bits `x0..=x1` of row `y` (clipped to the bitmap; nothing for `x0 > x1`).
    pub(crate) fn set_span(&mut self, y: usize, x0: usize, x1: usize) {
        if y >= self.height || x0 > x1 || x0 >= self.width {
            return;
        }
        let x1 = x1.min(self.width - 1);
        let row = &mut self.words[y * self.stride..(y + 1) * self.stride];
        let (w0, w1) = (x0 / 64, x1 / 64);
        if w0 == w1 {
            row[w0] |= word_mask(x0 % 64, x1 % 64);
        } else {
            row[w0] |= word_mask(x0 % 64, 63);
            row[w0 + 1..w1].fill(u64::MAX);
            row[w1] |= word_mask(0, x1 % 64);
        }
        let span = &mut self.spans[y];
        *span = (span.0.min(x0), span.1.max(x1));
    }

    /// Whether bit `(x, y)` is set (`false` outside).
    #[cfg(test)]
    pub(crate) fn get(&self, x: usize, y: usize) -> bool {
        x < self.width
            && y < self.height
            && self.words[y * self.stride + x / 64] >> (x % 64) & 1 == 1
    }

    /// The first and last set bit of row `y`, or `None` when it is empty.
    pub(crate) fn span(&self, y: usize) -> Option<(usize, usize)> {
        self.spans.get(y).copied().filter(|s| s.0 <= s.1)
    }

    /// The last set bit of row `y` in `x0..=x1`, or `None` when none is (or the row is outside).
    #[inline]
    pub(crate) fn last_set_in(&self, y: usize, x0: usize, x1: usize) -> Option<usize> {
        let (first, last) = self.span(y)?;
        let x1 = x1.min(last);
        if x0 > x1 || x1 < first {
            return None;
        }
        let x0 = x0.max(first);
        let row = &self.words[y * self.stride..(y + 1) * self.stride];
        let (w0, w1) = (x0 / 64, x1 / 64);
        if w0 == w1 {
            let bits = row[w0] & word_mask(x0 % 64, x1 % 64);
            return (bits != 0).then(|| w0 * 64 + 63 - bits.leading_zeros() as usize);
        }
        for w in (w0..=w1).rev() {
            let lo = if w == w0 { x0 % 64 } else { 0 };
            let hi = if w == w1 { x1 % 64 } else { 63 };
            let bits = row[w] & word_mask(lo, hi);
            if bits != 0 {
                return Some(w * 64 + 63 - bits.leading_zeros() as usize);
            }
        }
        None
    }

    /// The maximal runs of set bits of row `y`, left to right, as `(first, last)`.
    pub(crate) fn runs(&self, y: usize, out: &mut Vec<(u32, u32)>) {
        out.clear();
        let Some((first, last)) = self.span(y) else {
            return;
        };
        let row = &self.words[y * self.stride..(y + 1) * self.stride];
        let mut x = first;
        while x <= last {
            // The run starting at x (set), then the next set bit after it.
            let end = self.next(row, x, false).unwrap_or(self.width).min(last + 1);
            out.push((x as u32, (end - 1) as u32));
            match self.next(row, end, true) {
                Some(n) if n <= last => x = n,
                _ => break,
            }
        }
    }

    /// The first bit at or after `x` in `row` that is `set` (or clear), or `None`.
    fn next(&self, row: &[u64], x: usize, set: bool) -> Option<usize> {
        if x >= self.width {
            return None;
        }
        let mut w = x / 64;
        let mut bits = if set { row[w] } else { !row[w] } & !((1u64 << (x % 64)) - 1);
        loop {
            if bits != 0 {
                let found = w * 64 + bits.trailing_zeros() as usize;
                return (found < self.width).then_some(found);
            }
            w += 1;
            if w >= self.stride {
                return None;
            }
            bits = if set { row[w] } else { !row[w] };
        }
    }

    /// This bitmap grown by `r` bits on every side and dilated by a `(2r + 1)²` square (the
    /// Chebyshev ball of radius `r`): a bit of the result is set when a set bit of `self` is at
    /// most `r` rows and `r` columns away. `None` when the result would be too large.
    pub(crate) fn dilated(&self, r: usize) -> Option<Self> {
        let width = self.width.checked_add(2 * r)?;
        let height = self.height.checked_add(2 * r)?;
        // Rows dilated sideways first (each run a..=b, moved right by r, becomes a..=b + 2r),
        // then each output row is the OR of the 2r + 1 sideways rows at or below it.
        let mut wide = Self::new(width, self.height)?;
        let mut runs = Vec::new();
        for y in 0..self.height {
            self.runs(y, &mut runs);
            for &(a, b) in &runs {
                wide.set_span(y, a as usize, b as usize + 2 * r);
            }
        }
        let mut out = Self::new(width, height)?;
        let stride = out.stride;
        for y in 0..height {
            let from = y.saturating_sub(2 * r);
            let to = y.min(self.height - 1);
            if from > to {
                continue;
            }
            let row = &mut out.words[y * stride..(y + 1) * stride];
            let mut span = EMPTY;
            for source in from..=to {
                if let Some((first, last)) = wide.span(source) {
                    let (w0, w1) = (first / 64, last / 64);
                    let words = &wide.words[source * stride..(source + 1) * stride];
                    for (o, &i) in row[w0..=w1].iter_mut().zip(&words[w0..=w1]) {
                        *o |= i;
                    }
                    span = (span.0.min(first), span.1.max(last));
                }
            }
            out.spans[y] = span;
        }
        Some(out)
    }

    /// This bitmap turned by half a turn: bit `(x, y)` goes to `(width − 1 − x, height − 1 − y)`.
    pub(crate) fn half_turned(&self) -> Self {
        let mut out = Self {
            width: self.width,
            height: self.height,
            stride: self.stride,
            words: vec![0; self.words.len()],
            spans: vec![EMPTY; self.height],
        };
        let mut runs = Vec::new();
        for y in 0..self.height {
            self.runs(y, &mut runs);
            for &(a, b) in &runs {
                let (a, b) = (a as usize, b as usize);
                out.set_span(self.height - 1 - y, self.width - 1 - b, self.width - 1 - a);
            }
        }
        out
    }

    /// Sets every set bit of `other` at offset `(x, y)` here (bits falling outside are dropped).
    pub(crate) fn blit(&mut self, other: &Bitmap, x: usize, y: usize) {
        let mut runs = Vec::new();
        for r in 0..other.height {
            other.runs(r, &mut runs);
            for &(a, b) in &runs {
                self.set_span(y + r, x + a as usize, x + b as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_runs_and_queries_agree_with_single_bits() {
        let mut b = Bitmap::new(200, 3).expect("small");
        b.set_span(1, 3, 70);
        b.set_span(1, 100, 100);
        b.set_span(1, 128, 199);
        for x in 0..200 {
            assert_eq!(b.get(x, 1), (3..=70).contains(&x) || x == 100 || x >= 128);
        }
        let mut runs = Vec::new();
        b.runs(1, &mut runs);
        assert_eq!(runs, vec![(3, 70), (100, 100), (128, 199)]);
        b.runs(0, &mut runs);
        assert!(runs.is_empty());
        assert_eq!(b.last_set_in(1, 0, 99), Some(70));
        assert_eq!(b.last_set_in(1, 71, 99), None);
        assert_eq!(b.last_set_in(1, 71, 127), Some(100));
        assert_eq!(b.last_set_in(1, 0, 1000), Some(199));
        assert_eq!(b.last_set_in(0, 0, 199), None);
        assert_eq!(b.last_set_in(7, 0, 199), None);
        assert_eq!(b.span(1), Some((3, 199)));
    }

    #[test]
    fn dilation_is_the_chebyshev_ball() {
        let mut b = Bitmap::new(70, 5).expect("small");
        b.set_span(2, 66, 66);
        b.set_span(0, 0, 0);
        let d = b.dilated(2).expect("small");
        assert_eq!((d.width(), d.height()), (74, 9));
        for y in 0..9usize {
            for x in 0..74usize {
                let near =
                    |cx: usize, cy: usize| x.abs_diff(cx + 2) <= 2 && y.abs_diff(cy + 2) <= 2;
                assert_eq!(d.get(x, y), near(66, 2) || near(0, 0), "({x}, {y})");
            }
        }
    }

    #[test]
    fn a_half_turn_moves_every_bit() {
        let mut b = Bitmap::new(130, 4).expect("small");
        b.set_span(0, 0, 2);
        b.set_span(3, 60, 129);
        b.set_span(1, 64, 64);
        let t = b.half_turned();
        for y in 0..4 {
            for x in 0..130 {
                assert_eq!(t.get(x, y), b.get(129 - x, 3 - y), "({x}, {y})");
            }
        }
    }

    #[test]
    fn huge_bitmaps_are_refused() {
        assert!(Bitmap::new(1 << 20, 1 << 20).is_none());
        assert!(Bitmap::new(usize::MAX, 2).is_none());
    }
}
