//! Random disk meshes for the property tests.
#![allow(dead_code, unreachable_pub)]

use barytex_unwrap::UnwrapMesh;
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use spade::{DelaunayTriangulation, Point2, Triangulation};

/// A smooth random height field: a sum of three sine waves.
#[derive(Clone, Copy, Debug)]
pub struct Height {
    pub waves: [(f64, f64, f64, f64); 3],
}

impl Height {
    pub fn at(&self, p: DVec2) -> f64 {
        self.waves
            .iter()
            .map(|&(a, fx, fy, phase)| a * (fx * p.x + fy * p.y + phase).sin())
            .sum()
    }
}

pub fn height() -> impl Strategy<Value = Height> {
    prop::array::uniform3((-0.5..0.5f64, -6.0..6.0f64, -6.0..6.0f64, 0.0..6.3f64))
        .prop_map(|waves| Height { waves })
}

/// `(positions, triangles)` of the Delaunay triangulation of `points`, lifted by `h`.
pub fn delaunay_lifted(points: &[DVec2], h: &Height) -> Option<(Vec<DVec3>, Vec<[u32; 3]>)> {
    let pts: Vec<Point2<f64>> = points.iter().map(|p| Point2::new(p.x, p.y)).collect();
    let t = DelaunayTriangulation::<Point2<f64>>::bulk_load(pts).ok()?;
    let positions: Vec<DVec3> = t
        .vertices()
        .map(|v| {
            let p = v.position();
            let q = DVec2::new(p.x, p.y);
            q.extend(h.at(q))
        })
        .collect();
    let triangles: Vec<[u32; 3]> = t
        .inner_faces()
        .map(|f| f.vertices().map(|v| v.fix().index() as u32))
        .collect();
    (triangles.len() >= 2).then_some((positions, triangles))
}

/// Random points in the unit disk (at least 3 not collinear, almost surely).
pub fn disk_points() -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec((0.0..1.0f64, 0.0..core::f64::consts::TAU), 8..200).prop_map(|v| {
        v.into_iter()
            .map(|(r, a)| r.sqrt() * DVec2::new(a.cos(), a.sin()))
            .collect()
    })
}

/// A `n × m` grid over the unit square with interior vertices moved by up to 0.3 of a cell, lifted
/// by `h`.
pub fn perturbed_grid(
    n: u32,
    m: u32,
    jitter: &[(f64, f64)],
    h: &Height,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let grid = barytex_unwrap::shapes::grid(n, m, |_, _| 0.0);
    let mut k = 0;
    let positions = grid
        .positions()
        .iter()
        .map(|p| {
            let interior = p.x > 0.0 && p.x < 1.0 && p.y > 0.0 && p.y < 1.0;
            let mut q = p.truncate();
            if interior {
                let (dx, dy) = jitter[k % jitter.len()];
                k += 1;
                q += DVec2::new(0.3 * dx / f64::from(n), 0.3 * dy / f64::from(m));
            }
            q.extend(h.at(q))
        })
        .collect();
    (positions, grid.triangles().to_vec())
}

/// `(positions, triangles)` as an [`UnwrapMesh`].
pub fn mesh(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> UnwrapMesh {
    UnwrapMesh::new(positions, triangles).expect("valid mesh")
}
