//! Seeded, reproducible inputs for the benchmarks and the speed-vs-error report: the same
//! generator and the same shapes in both, so a bench and a report row measure the same kind of
//! input. (Property tests use [`strategies`](crate::strategies) instead, which shrink.)

use glam::{Vec2, Vec3};

use crate::strategies::{is_strictly_convex_ccw, shape_quality};

/// Marsaglia's xorshift64: tiny, fast, and the same sequence on every machine.
#[derive(Clone, Debug)]
pub struct XorShift(u64);

impl XorShift {
    /// A generator from a seed (0 is replaced by 1: xorshift has no zero state).
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed.max(1))
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// Uniform in `[lo, hi)` from 24 random bits.
    pub fn f32_in(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u64() >> 40) as f32 / (1u32 << 24) as f32;
        lo + (hi - lo) * unit
    }

    /// Uniform integer in `lo..=hi`.
    pub fn i32_in(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1) as u64;
        (i64::from(lo) + (self.next_u64() % span) as i64) as i32
    }

    /// A point uniform in `[lo, hi)²`.
    pub fn vec2_in(&mut self, lo: f32, hi: f32) -> Vec2 {
        Vec2::new(self.f32_in(lo, hi), self.f32_in(lo, hi))
    }

    /// A point uniform in `[lo, hi)³`.
    pub fn vec3_in(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(
            self.f32_in(lo, hi),
            self.f32_in(lo, hi),
            self.f32_in(lo, hi),
        )
    }
}

/// `n` well-shaped triangles in `[-100, 100]²` (shape quality ≥ 0.05, either orientation), each
/// with a point of affine weights in about `[-0.25, 1.25]` (some inside, some outside).
pub fn triangles_2d(rng: &mut XorShift, n: usize) -> Vec<(Vec2, [Vec2; 3])> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let tri = [
            rng.vec2_in(-100.0, 100.0),
            rng.vec2_in(-100.0, 100.0),
            rng.vec2_in(-100.0, 100.0),
        ];
        if shape_quality(tri) < 0.05 {
            continue;
        }
        let (u, v) = (rng.f32_in(-0.25, 1.25), rng.f32_in(-0.25, 1.25));
        out.push((tri[0] * (1.0 - u - v) + tri[1] * u + tri[2] * v, tri));
    }
    out
}

/// `n` well-shaped triangles in `[-100, 100]³`, each with a point of its plane (up to rounding).
pub fn triangles_3d(rng: &mut XorShift, n: usize) -> Vec<(Vec3, [Vec3; 3])> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let tri = [
            rng.vec3_in(-100.0, 100.0),
            rng.vec3_in(-100.0, 100.0),
            rng.vec3_in(-100.0, 100.0),
        ];
        let [a, b, c] = tri.map(|v| v.as_dvec3());
        let longest = (b - a)
            .length_squared()
            .max((c - b).length_squared())
            .max((a - c).length_squared());
        if (b - a).cross(c - a).length() < 0.05 * longest {
            continue;
        }
        let (u, v) = (rng.f32_in(-0.25, 1.25), rng.f32_in(-0.25, 1.25));
        out.push((tri[0] * (1.0 - u - v) + tri[1] * u + tri[2] * v, tri));
    }
    out
}

/// A strictly convex, counter-clockwise quad with one corner per quarter of a perturbed unit
/// circle.
pub fn convex_quad(rng: &mut XorShift) -> [Vec2; 4] {
    loop {
        let start = rng.f32_in(0.0, core::f32::consts::TAU);
        let mut quad = [Vec2::ZERO; 4];
        for (i, corner) in quad.iter_mut().enumerate() {
            let angle = start + i as f32 * core::f32::consts::FRAC_PI_2 + rng.f32_in(-0.4, 0.4);
            *corner = Vec2::new(angle.cos(), angle.sin()) * rng.f32_in(0.7, 1.3);
        }
        if is_strictly_convex_ccw(quad) {
            return quad;
        }
    }
}

/// `n` points uniform in `[-1, 1)²` (the hull benchmarks' and report's "uniform square").
pub fn points_in_square(rng: &mut XorShift, n: usize) -> Vec<Vec2> {
    (0..n).map(|_| rng.vec2_in(-1.0, 1.0)).collect()
}

/// `n` points on the unit circle in scrambled order
/// ([`barytex_interp::hard_cases::hull_circle_2d`]): every point is near the hull, so nothing
/// can be filtered away.
#[must_use]
pub fn points_on_circle(n: usize) -> Vec<Vec2> {
    barytex_interp::hard_cases::hull_circle_2d(n)
}
