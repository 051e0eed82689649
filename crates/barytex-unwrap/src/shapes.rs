//! Closed and open test surfaces, generated: a latitude–longitude sphere, a torus, a
//! subdivided cube and a height-field grid. Used by the tests, the fuzz target and the reports;
//! handy for trying the parameterization without a file.

use glam::DVec3;

use crate::UnwrapMesh;

/// A unit sphere with `rings ≥ 2` latitude bands and `segments ≥ 3` longitudes, one vertex at
/// each pole, counter-clockwise seen from outside. Closed, genus 0.
///
/// ```
/// let s = barytex_unwrap::shapes::sphere(8, 16);
/// assert_eq!(s.triangles().len(), 2 * 16 * (8 - 1));
/// ```
#[must_use]
pub fn sphere(rings: u32, segments: u32) -> UnwrapMesh {
    let (rings, segments) = (rings.clamp(2, 2048), segments.clamp(3, 2048));
    let mut p = vec![DVec3::Y];
    for r in 1..rings {
        let theta = core::f64::consts::PI * f64::from(r) / f64::from(rings);
        for s in 0..segments {
            let phi = core::f64::consts::TAU * f64::from(s) / f64::from(segments);
            p.push(DVec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                -theta.sin() * phi.sin(),
            ));
        }
    }
    p.push(-DVec3::Y);
    let south = p.len() as u32 - 1;
    let ring = |r: u32, s: u32| 1 + (r - 1) * segments + s % segments;
    let mut t = Vec::new();
    for s in 0..segments {
        t.push([0, ring(1, s), ring(1, s + 1)]);
        for r in 1..rings - 1 {
            let (a, b, c, d) = (
                ring(r, s),
                ring(r + 1, s),
                ring(r + 1, s + 1),
                ring(r, s + 1),
            );
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
        t.push([ring(rings - 1, s), south, ring(rings - 1, s + 1)]);
    }
    UnwrapMesh::new(p, t).unwrap_or_else(|_| unreachable!("indices in range"))
}

/// A torus around the y axis with radii `major > minor > 0`, `n ≥ 3` steps around the axis and
/// `m ≥ 3` around the tube, counter-clockwise seen from outside. Closed, genus 1.
///
/// ```
/// let t = barytex_unwrap::shapes::torus(1.0, 0.25, 32, 12);
/// assert_eq!(t.triangles().len(), 2 * 32 * 12);
/// ```
#[must_use]
pub fn torus(major: f64, minor: f64, n: u32, m: u32) -> UnwrapMesh {
    let (n, m) = (n.clamp(3, 2048), m.clamp(3, 2048));
    let mut p = Vec::new();
    for i in 0..n {
        let u = core::f64::consts::TAU * f64::from(i) / f64::from(n);
        for j in 0..m {
            let v = core::f64::consts::TAU * f64::from(j) / f64::from(m);
            let r = major + minor * v.cos();
            p.push(DVec3::new(r * u.cos(), minor * v.sin(), -r * u.sin()));
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + j % m;
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    UnwrapMesh::new(p, t).unwrap_or_else(|_| unreachable!("indices in range"))
}

/// The cube `[-1, 1]³` with each face split into `k × k` squares (`1 ≤ k ≤ 1024`), vertices
/// shared along the edges, counter-clockwise seen from outside. Closed, genus 0.
///
/// ```
/// let c = barytex_unwrap::shapes::cube(3);
/// assert_eq!(c.triangles().len(), 6 * 2 * 9);
/// ```
#[must_use]
pub fn cube(k: u32) -> UnwrapMesh {
    let k = k.clamp(1, 1024);
    let mut index = std::collections::HashMap::new();
    let mut p = Vec::new();
    let mut t = Vec::new();
    let mut vertex = |q: DVec3, p: &mut Vec<DVec3>| -> u32 {
        let r = (q * f64::from(k)).round();
        let key = [r.x as i64, r.y as i64, r.z as i64];
        *index.entry(key).or_insert_with(|| {
            p.push(q);
            p.len() as u32 - 1
        })
    };
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let n = DVec3::AXES[axis] * sign;
            let a = DVec3::AXES[(axis + 1) % 3];
            let b = n.cross(a);
            for i in 0..k {
                for j in 0..k {
                    let at = |i: u32, j: u32| {
                        let s = -1.0 + 2.0 * f64::from(i) / f64::from(k);
                        let r = -1.0 + 2.0 * f64::from(j) / f64::from(k);
                        n + a * s + b * r
                    };
                    let v00 = vertex(at(i, j), &mut p);
                    let v10 = vertex(at(i + 1, j), &mut p);
                    let v11 = vertex(at(i + 1, j + 1), &mut p);
                    let v01 = vertex(at(i, j + 1), &mut p);
                    t.push([v00, v10, v11]);
                    t.push([v00, v11, v01]);
                }
            }
        }
    }
    UnwrapMesh::new(p, t).unwrap_or_else(|_| unreachable!("indices in range"))
}

/// An `n × m`-square grid over `[0, 1]²` (`n, m ≥ 1`) lifted to `z = height(x, y)`, two triangles
/// per square, counter-clockwise seen from +z. A disk.
///
/// ```
/// let g = barytex_unwrap::shapes::grid(4, 3, |x, y| x * y);
/// assert_eq!((g.positions().len(), g.triangles().len()), (20, 24));
/// ```
#[must_use]
pub fn grid(n: u32, m: u32, height: impl Fn(f64, f64) -> f64) -> UnwrapMesh {
    let (n, m) = (n.clamp(1, 4096), m.clamp(1, 4096));
    let mut p = Vec::new();
    for j in 0..=m {
        for i in 0..=n {
            let (x, y) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(m));
            p.push(DVec3::new(x, y, height(x, y)));
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut t = Vec::new();
    for j in 0..m {
        for i in 0..n {
            t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    UnwrapMesh::new(p, t).unwrap_or_else(|_| unreachable!("indices in range"))
}
