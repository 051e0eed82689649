//! A tiny seeded pseudo-random generator, so the report's inputs are the same on every run.

use glam::{Vec2, Vec3};

/// Marsaglia's xorshift64.
pub(crate) struct XorShift(u64);

impl XorShift {
    /// A generator from a seed (0 is replaced by 1: xorshift has no zero state).
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed.max(1))
    }

    /// The next 64 random bits.
    pub(crate) fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// Uniform in `[lo, hi)` from 24 random bits.
    pub(crate) fn f32_in(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u64() >> 40) as f32 / (1u32 << 24) as f32;
        lo + (hi - lo) * unit
    }

    /// Uniform integer in `lo..=hi`.
    pub(crate) fn i32_in(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1) as u64;
        (i64::from(lo) + (self.next_u64() % span) as i64) as i32
    }

    /// A point uniform in `[lo, hi)²`.
    pub(crate) fn vec2_in(&mut self, lo: f32, hi: f32) -> Vec2 {
        Vec2::new(self.f32_in(lo, hi), self.f32_in(lo, hi))
    }

    /// A point uniform in `[lo, hi)³`.
    pub(crate) fn vec3_in(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(
            self.f32_in(lo, hi),
            self.f32_in(lo, hi),
            self.f32_in(lo, hi),
        )
    }
}

/// `x` moved by `k` steps of f32 spacing (toward +∞ for positive `k`).
pub(crate) fn step_ulps(x: f32, k: i32) -> f32 {
    let mut y = x;
    for _ in 0..k.unsigned_abs() {
        y = if k > 0 { y.next_up() } else { y.next_down() };
    }
    y
}
