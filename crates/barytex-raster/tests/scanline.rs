//! The scanline backend: the worked example of S. Schaefer's *Shading/Texturing* lecture slides
//! (Texas A&M University) reproduced with exact rationals, and the same coverage as the
//! edge-function backend on random fixed-point triangles.

mod common;

use std::ops::{Add, Div, Mul, Sub};
use std::sync::atomic::Ordering;

use barytex_raster::TargetLimits;
use barytex_raster::scanline::{SampleRule, Scalar, ScanVertex, scanline_fill};
use barytex_raster::{CullMode, Framebuffer, PipelineState, draw};
use common::Counter;
use glam::Vec4;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use proptest::prelude::*;

/// Exact rationals for the generic fill.
#[derive(Clone, Debug, PartialEq, PartialOrd)]
struct Q(BigRational);

impl Add for Q {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Q(self.0 + o.0)
    }
}
impl Sub for Q {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Q(self.0 - o.0)
    }
}
impl Mul for Q {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Q(self.0 * o.0)
    }
}
impl Div for Q {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        Q(self.0 / o.0)
    }
}
impl Scalar for Q {
    fn from_i64(i: i64) -> Self {
        Q(BigRational::from_integer(BigInt::from(i)))
    }
    fn half() -> Self {
        Q(BigRational::new(BigInt::one(), BigInt::from(2)))
    }
    fn ceil_i64(&self) -> Option<i64> {
        self.0.ceil().to_integer().to_i64()
    }
}

fn q(n: i64, d: i64) -> Q {
    Q(BigRational::new(BigInt::from(n), BigInt::from(d)))
}

/// Schaefer's worked example: triangle A = (0,0), B = (1,5), C = (4,2), F = barycentric weights;
/// the rows and values of the slides, exactly.
#[test]
fn schaefer_worked_example_is_reproduced_exactly() {
    let one = || q(1, 1);
    let zero = || Q(BigRational::zero());
    let tri = [
        ScanVertex {
            x: q(0, 1),
            y: q(0, 1),
            f: [one(), zero(), zero()],
        },
        ScanVertex {
            x: q(1, 1),
            y: q(5, 1),
            f: [zero(), one(), zero()],
        },
        ScanVertex {
            x: q(4, 1),
            y: q(2, 1),
            f: [zero(), zero(), one()],
        },
    ];
    let mut got = Vec::new();
    scanline_fill(
        &tri,
        SampleRule::IntegerPoints,
        (-10, 10),
        (-10, 10),
        |x, y, f| {
            got.push((x, y, f));
        },
    );
    let want = [
        (1, 1, [q(2, 3), q(1, 9), q(2, 9)]),
        (1, 2, [q(1, 2), q(1, 3), q(1, 6)]),
        (2, 2, [q(1, 3), q(2, 9), q(4, 9)]),
        (3, 2, [q(1, 6), q(1, 9), q(13, 18)]),
        (1, 3, [q(1, 3), q(5, 9), q(1, 9)]),
        (2, 3, [q(1, 6), q(4, 9), q(7, 18)]),
        (1, 4, [q(1, 6), q(7, 9), q(1, 18)]),
    ];
    assert_eq!(got.len(), want.len(), "{got:?}");
    for ((x, y, f), (wx, wy, wf)) in got.iter().zip(&want) {
        assert_eq!((x, y), (wx, wy));
        assert_eq!(f, wf, "at ({x}, {y})");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Same sampling rule, same coverage: on random triangles with fixed-point vertices (1/256
    /// pixel, the edge backend's grid, some snapped to pixel centres to hit the tie cases), the
    /// exact scanline fill covers exactly the pixels the edge-function rasterizer covers.
    #[test]
    fn scanline_and_edge_functions_cover_the_same_pixels(
        pts in prop::collection::vec((0_i64..32 * 256, 0_i64..32 * 256, any::<bool>()), 3),
    ) {
        const SIZE: u32 = 32;
        let fixed: Vec<(i64, i64)> = pts
            .iter()
            .map(|&(x, y, snap)| if snap { (x / 256 * 256 + 128, y / 256 * 256 + 128) } else { (x, y) })
            .collect();
        let area = (fixed[1].0 - fixed[0].0) * (fixed[2].1 - fixed[0].1)
            - (fixed[1].1 - fixed[0].1) * (fixed[2].0 - fixed[0].0);
        prop_assume!(area != 0);
        // Scanline, exact.
        let tri: Vec<ScanVertex<Q, 0>> = fixed
            .iter()
            .map(|&(x, y)| ScanVertex { x: q(x, 256), y: q(y, 256), f: [] })
            .collect();
        let mut scan = vec![0_u32; (SIZE * SIZE) as usize];
        scanline_fill(&tri, SampleRule::PixelCentres, (0, i64::from(SIZE)), (0, i64::from(SIZE)),
            |x, y, _| scan[(y * i64::from(SIZE) + x) as usize] += 1);
        // Edge functions, through the pipeline (clip coordinates exact for a 32² target).
        let vertices: Vec<Vec4> = fixed
            .iter()
            .map(|&(x, y)| {
                let (sx, sy) = (x as f32 / 256.0, y as f32 / 256.0);
                Vec4::new(sx / SIZE as f32 * 2.0 - 1.0, 1.0 - sy / SIZE as f32 * 2.0, 0.5, 1.0)
            })
            .collect();
        let counter = Counter::new(SIZE, SIZE);
        let mut fb = Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &TargetLimits::default()).expect("small");
        let state = PipelineState { cull: CullMode::None, depth_compare: None, ..PipelineState::default() };
        draw(&mut fb, &counter, &state, &vertices, &[0, 1, 2]);
        let edge: Vec<u32> = counter.counts.iter().map(|c| c.load(Ordering::Relaxed)).collect();
        prop_assert_eq!(scan, edge, "{:?}", fixed);
    }
}

#[test]
fn hostile_polygons_fill_nothing_or_stay_in_range() {
    let huge = [
        ScanVertex {
            x: -1e300,
            y: -1e300,
            f: [0.0],
        },
        ScanVertex {
            x: 1e300,
            y: 5.0,
            f: [1.0],
        },
        ScanVertex {
            x: 3.0,
            y: 1e300,
            f: [2.0],
        },
    ];
    let mut count = 0_u64;
    scanline_fill(
        &huge,
        SampleRule::PixelCentres,
        (0, 16),
        (0, 16),
        |x, y, _| {
            assert!((0..16).contains(&x) && (0..16).contains(&y));
            count += 1;
        },
    );
    assert!(count <= 256);
    let nan = [
        ScanVertex {
            x: f64::NAN,
            y: 0.0,
            f: [0.0],
        },
        ScanVertex {
            x: 1.0,
            y: 5.0,
            f: [1.0],
        },
        ScanVertex {
            x: 3.0,
            y: f64::INFINITY,
            f: [2.0],
        },
    ];
    scanline_fill(
        &nan,
        SampleRule::PixelCentres,
        (0, 16),
        (0, 16),
        |x, y, _| {
            assert!((0..16).contains(&x) && (0..16).contains(&y));
        },
    );
}
