//! Skyline bottom-left rectangle packing (Jylänki, "A thousand ways to pack the bin — a
//! practical approach to two-dimensional rectangle bin packing", 2010, §4 "The Skyline
//! algorithms", SKYLINE-BL).
//!
//! The packed area's upper outline is kept as a list of horizontal segments; each rectangle goes
//! where its top edge is lowest (ties: leftmost), resting on the highest segment under it. The
//! list never holds more segments than the bin is wide in integer units, so placing `n`
//! rectangles costs at most `O(n · width)`.

/// A skyline over a `width × height` bin in integer units.
#[derive(Clone, Debug)]
pub(crate) struct Skyline {
    width: u32,
    height: u32,
    /// Segments `(x, y, length)` left to right, covering `[0, width)` exactly.
    segments: Vec<(u32, u32, u32)>,
}

/// Where a rectangle went.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Spot {
    /// Bottom-left corner.
    pub(crate) x: u32,
    /// Bottom-left corner.
    pub(crate) y: u32,
    /// Whether the rectangle was turned by 90° (its width and height swapped).
    pub(crate) turned: bool,
}

impl Skyline {
    /// An empty bin (both sides at least 1).
    pub(crate) fn new(width: u32, height: u32) -> Self {
        Self {
            width: width.max(1),
            height: height.max(1),
            segments: vec![(0, 0, width.max(1))],
        }
    }

    /// The lowest `y` a `w`-wide rectangle can rest at with its left edge on segment `i`, or
    /// `None` past the right edge.
    fn rest(&self, i: usize, w: u32) -> Option<u32> {
        let x = self.segments[i].0;
        if u64::from(x) + u64::from(w) > u64::from(self.width) {
            return None;
        }
        let end = x + w;
        let mut y = 0;
        for &(sx, sy, _) in &self.segments[i..] {
            if sx >= end {
                break;
            }
            y = y.max(sy);
        }
        Some(y)
    }

    /// The best spot for a `w × h` rectangle (also turned when `turn` allows): the lowest top
    /// edge, then the leftmost; `None` when it fits nowhere.
    fn find(&self, w: u32, h: u32, turn: bool) -> Option<(usize, Spot, u32, u32)> {
        let mut best: Option<(u64, u32, usize, Spot, u32, u32)> = None;
        let options: &[(u32, u32, bool)] = if turn && w != h {
            &[(w, h, false), (h, w, true)]
        } else {
            &[(w, h, false)]
        };
        for &(rw, rh, turned) in options {
            for i in 0..self.segments.len() {
                let Some(y) = self.rest(i, rw) else {
                    break;
                };
                let top = u64::from(y) + u64::from(rh);
                if top > u64::from(self.height) {
                    continue;
                }
                let x = self.segments[i].0;
                if best.is_none_or(|b| (top, x) < (b.0, b.1)) {
                    best = Some((top, x, i, Spot { x, y, turned }, rw, rh));
                }
            }
        }
        best.map(|(_, _, i, spot, rw, rh)| (i, spot, rw, rh))
    }

    /// Places a `w × h` rectangle (turned by 90° if that sits lower and `turn` allows), or
    /// returns `None` when it fits nowhere (the skyline is then unchanged).
    pub(crate) fn insert(&mut self, w: u32, h: u32, turn: bool) -> Option<Spot> {
        let (i, spot, rw, _) = self.find(w, h, turn)?;
        let rh = if spot.turned { w } else { h };
        let top = spot.y + rh;
        let end = spot.x + rw;
        // Replace the segments under [x, end) by one at `top`; keep the uncovered tail of the
        // last one.
        let mut j = i;
        while j < self.segments.len() && self.segments[j].0 < end {
            j += 1;
        }
        let last = self.segments[j - 1];
        let tail = last.0 + last.2;
        let mut replacement = vec![(spot.x, top, rw)];
        if tail > end {
            replacement.push((end, last.1, tail - end));
        }
        self.segments.splice(i..j, replacement);
        // Merge neighbours of equal height.
        let mut merged: Vec<(u32, u32, u32)> = Vec::with_capacity(self.segments.len());
        for &s in &self.segments {
            match merged.last_mut() {
                Some(m) if m.1 == s.1 => m.2 += s.2,
                _ => merged.push(s),
            }
        }
        self.segments = merged;
        Some(spot)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_a_bin_exactly_with_equal_squares() {
        let mut sky = Skyline::new(8, 8);
        let mut spots: Vec<Spot> = (0..16)
            .map(|_| sky.insert(2, 2, false).expect("fits"))
            .collect();
        assert!(sky.insert(1, 1, true).is_none());
        spots.sort_by_key(|s| (s.y, s.x));
        for (k, s) in spots.iter().enumerate() {
            assert_eq!((s.x, s.y), (2 * (k as u32 % 4), 2 * (k as u32 / 4)));
        }
    }

    #[test]
    fn turns_a_rectangle_that_only_fits_turned() {
        let mut sky = Skyline::new(3, 10);
        assert!(sky.insert(5, 2, false).is_none());
        let spot = sky.insert(5, 2, true).expect("fits turned");
        assert!(spot.turned);
    }
}
