//! Hard cases for the 2D and 3D convex hulls.

use alloc::vec::Vec;

use glam::{DVec2, Vec2};

use super::kettner_grid;

/// A named 2D point set whose exact hull is hard to get right.
#[derive(Clone, Debug, PartialEq)]
pub struct HullCase2d {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter (size, scale, …), 0 when it has none.
    pub parameter: f32,
    /// The input points.
    pub points: Vec<Vec2>,
    /// The number of strict corners when the construction pins it down (grids, equal points).
    pub corners: Option<usize>,
}

/// `n` points on the circle of radius 1 about the origin, at angles `2π·k/n` rounded to f32, in a
/// scrambled order (point `i` has `k = i·s mod n` for a stride `s` coprime to `n`), so sorting
/// algorithms get no head start.
///
/// Rounding to f32 moves each point by up to half an ulp (3e-8) off the circle, while neighbours
/// at `n = 10⁶` bulge only 5e-12 beyond their chord: the exact hull keeps a fraction of the
/// points, and which ones only exact orientation decides.
#[must_use]
pub fn hull_circle_2d(n: usize) -> Vec<Vec2> {
    let stride = coprime_stride(n);
    (0..n)
        .map(|i| {
            let k = (i as u128 * stride as u128 % n as u128) as f64;
            let angle = core::f64::consts::TAU * k / n as f64;
            DVec2::from_angle(angle).as_vec2()
        })
        .collect()
}

/// A stride near `0.618·n` that is coprime to `n` (1 for `n ≤ 2`).
fn coprime_stride(n: usize) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut s = (n as f64 * 0.618) as usize | 1;
    while n > 2 && gcd(s, n) != 1 {
        s += 2;
    }
    s.max(1)
}

/// The `k × k` integer grid `(i, j)` scaled by `scale` (every boundary row is a collinear run).
fn grid(k: i32, scale: f32) -> Vec<Vec2> {
    (0..k)
        .flat_map(|i| (0..k).map(move |j| Vec2::new(i as f32, j as f32) * scale))
        .collect()
}

/// The 2D hull table: a circle (4096 points; [`hull_circle_2d`] makes 10⁶), square and diamond
/// grids with long collinear runs (also at subnormal scale), equal points and signed zeros,
/// 3000 exactly collinear points, Kettner's last-ulp grid beside its line, points of a segment
/// rounded to f32 (each within an ulp of the line), and the circle and a cloud near 1e30, 1e38,
/// 1e-30, plus magnitudes 1e-30 and 1e30 mixed.
#[must_use]
pub fn hulls_2d() -> Vec<HullCase2d> {
    let case = |name, parameter, points, corners| HullCase2d {
        name,
        parameter,
        points,
        corners,
    };
    let diamond: Vec<Vec2> = (-32i32..=32)
        .flat_map(|i| {
            let r = 32 - i.abs();
            (-r..=r).map(move |j| Vec2::new(i as f32, j as f32))
        })
        .collect();
    let collinear: Vec<Vec2> = (0..3000)
        .map(|i| {
            let t = (i * 1777 % 3000) as f32;
            Vec2::new(t - 1500.0, 2.0 * t + 1.0)
        })
        .collect();
    let kettner: Vec<Vec2> = kettner_grid(8)
        .map(|(p, _, _)| p)
        .chain([Vec2::new(12.0, 12.0), Vec2::new(24.0, 24.0)])
        .collect();
    let (a, b) = (Vec2::new(0.1, 0.3), Vec2::new(0.7, 1.9));
    let rounded_segment: Vec<Vec2> = (0..=1000)
        .map(|i| a + (b - a) * (i as f32 / 1000.0))
        .collect();
    let circle = hull_circle_2d(256);
    let huge_cloud: Vec<Vec2> = (0..500)
        .map(|i| {
            let u = ((i * 7919) % 1000) as f32 / 1000.0 - 0.5;
            let v = ((i * 104_729) % 997) as f32 / 997.0 - 0.5;
            Vec2::new(u, v) * 3.0e38 * 2.0
        })
        .collect();
    let mut mixed = grid(8, 1e-30);
    mixed.extend([
        Vec2::new(1e30, 0.0),
        Vec2::new(0.0, 1e30),
        Vec2::new(5e29, 5e29),
        Vec2::new(-1e-30, 1e30),
    ]);
    Vec::from([
        case("circle", 4096.0, hull_circle_2d(4096), None),
        case("square grid", 64.0, grid(64, 1.0), Some(4)),
        case("diamond grid", 32.0, diamond, Some(4)),
        case("subnormal grid", 1e-44, grid(8, f32::from_bits(1)), Some(4)),
        case(
            "all equal",
            0.0,
            Vec::from([Vec2::new(0.3, -0.7); 1000]),
            Some(1),
        ),
        case(
            "signed zeros",
            0.0,
            Vec::from([
                Vec2::new(0.0, -0.0),
                Vec2::new(-0.0, 0.0),
                Vec2::ZERO,
                Vec2::new(-0.0, -0.0),
            ]),
            Some(1),
        ),
        case("3000 collinear", 3000.0, collinear, Some(2)),
        case("Kettner last-ulp grid", 8.0, kettner, None),
        case("segment rounded to f32", 1000.0, rounded_segment, None),
        case(
            "circle near 1e30",
            1e30,
            circle.iter().map(|&p| p * 1e30).collect(),
            None,
        ),
        case("cloud near 1e38", 3e38, huge_cloud, None),
        case(
            "circle near 1e-30",
            1e-30,
            circle.iter().map(|&p| p * 1e-30).collect(),
            None,
        ),
        case("mixed 1e-30 and 1e30", 1e30, mixed, None),
    ])
}
