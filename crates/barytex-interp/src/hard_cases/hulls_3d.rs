//! Hard cases for the 3D convex hull and `orient3d`: points on a sphere (every point a corner),
//! grids with coplanar faces and collinear runs, all points equal, clouds one ulp apart,
//! coordinates near 1e30 and 1e-30, and nearly coplanar slabs.

use alloc::vec::Vec;

use glam::Vec3;

/// A named 3D point cloud.
#[derive(Clone, Debug, PartialEq)]
pub struct Hull3dCase {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter (scale, count, …), 0 when it has none.
    pub parameter: f32,
    /// The input.
    pub points: Vec<Vec3>,
    /// The number of strict hull corners when the construction pins it down.
    pub corners: Option<usize>,
}

/// A tiny xorshift so the table needs no dependency and is the same everywhere.
struct Bits(u64);

impl Bits {
    fn unit(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 40) as f32 / (1u32 << 24) as f32 * 2.0 - 1.0
    }
}

/// `n` points near the unit sphere (directions from a seeded cube, normalized in f64, rounded
/// to f32): all are corners of their hull, almost surely, but the table does not promise it.
fn sphere(n: usize, seed: u64) -> Vec<Vec3> {
    let mut bits = Bits(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let p = Vec3::new(bits.unit(), bits.unit(), bits.unit()).as_dvec3();
        let len2 = p.length_squared();
        if len2 > 1e-4 && len2 <= 1.0 {
            out.push((p / crate::math::sqrt(len2)).as_vec3());
        }
    }
    out
}

/// The integer grid `0..n` in each axis: a cube with 8 corners and n² coplanar points per face.
fn grid(n: u32) -> Vec<Vec3> {
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                out.push(Vec3::new(i as f32, j as f32, k as f32));
            }
        }
    }
    out
}

/// The grid `(1 + i ulp, 1 + j ulp, 1 + k ulp)`, `i, j, k` in `0..n`: a cube of side `(n − 1)`
/// ulps of 1.0.
fn ulp_grid(n: u32) -> Vec<Vec3> {
    let base = 1.0f32.to_bits();
    let f = |i: u32| f32::from_bits(base + i);
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                out.push(Vec3::new(f(i), f(j), f(k)));
            }
        }
    }
    out
}

/// The 3D hull table.
pub fn hulls_3d() -> impl Iterator<Item = Hull3dCase> {
    let mut cases = Vec::new();
    let mut case = |name, parameter, points, corners| {
        cases.push(Hull3dCase {
            name,
            parameter,
            points,
            corners,
        });
    };
    case("sphere", 2000.0, sphere(2000, 0x5e4e), None);
    case("grid with coplanar faces", 6.0, grid(6), Some(8));
    let mut dup = grid(2);
    dup.extend(grid(2));
    dup.extend([
        Vec3::splat(0.5),
        Vec3::new(0.5, 0.5, 1.0),
        Vec3::new(0.5, 0.0, 0.0),
    ]);
    case(
        "cube, duplicates, face and edge midpoints",
        0.0,
        dup,
        Some(8),
    );
    case(
        "all equal",
        0.0,
        alloc::vec![Vec3::new(0.1, 0.2, 0.3); 50],
        Some(1),
    );
    case("last-ulp grid", 4.0, ulp_grid(4), Some(8));
    let mut bits = Bits(0x0bad);
    let base = 1.0f32.to_bits();
    let mut ulp_cloud: Vec<Vec3> = (0..200)
        .map(|_| {
            let mut k = || f32::from_bits(base + ((bits.unit() + 1.0) * 1.5) as u32);
            Vec3::new(k(), k(), k())
        })
        .collect();
    ulp_cloud.extend(ulp_grid(4).into_iter().filter(|p| {
        [p.x, p.y, p.z]
            .iter()
            .all(|c| c.to_bits() == base || c.to_bits() == base + 3)
    }));
    case("last-ulp cloud in a 3-ulp cube", 3.0, ulp_cloud, Some(8));
    for scale in [1e30f32, 1e-30] {
        case(
            "sphere scaled",
            scale,
            sphere(300, 0x1e30).iter().map(|&p| p * scale).collect(),
            None,
        );
        case(
            "grid scaled",
            scale,
            grid(4).iter().map(|&p| p * scale).collect(),
            Some(8),
        );
    }
    // A slab: points exactly on the plane z = x + y (small integers, exact), then the same points
    // one ulp above and below: the hull's top and bottom are nearly coplanar sheets.
    let plane: Vec<Vec3> = (0..8)
        .flat_map(|i| (0..8).map(move |j| Vec3::new(i as f32, j as f32, (i + j) as f32)))
        .collect();
    case("coplanar grid (polygon)", 8.0, plane.clone(), Some(4));
    let mut slab = plane.clone();
    slab.extend(plane.iter().map(|p| Vec3::new(p.x, p.y, p.z.next_up())));
    slab.extend(plane.iter().map(|p| Vec3::new(p.x, p.y, p.z.next_down())));
    case("nearly coplanar slab", 1.0, slab, None);
    // A tilted, inexact plane: a + u(b − a) + v(c − a) rounded to f32 lies within an ulp of it.
    let (a, b, c) = (
        Vec3::new(0.1, 0.2, 0.3),
        Vec3::new(1.7, -0.4, 0.9),
        Vec3::new(-0.3, 1.3, 2.1),
    );
    let tilted: Vec<Vec3> = (0..10)
        .flat_map(|i| {
            (0..10).map(move |j| a + (b - a) * (i as f32 / 9.0) + (c - a) * (j as f32 / 9.0))
        })
        .collect();
    case("rounded tilted plane", 100.0, tilted, None);
    let line: Vec<Vec3> = (0..40)
        .map(|i| Vec3::new(i as f32, 2.0 * i as f32, 3.0 * i as f32))
        .collect();
    case("collinear", 40.0, line, Some(2));
    cases.into_iter()
}
