//! Charts for the triangles that cannot be parameterized: a repeated vertex or zero area.

use glam::DVec2;

use crate::{Chart, UnwrapMesh};

pub(super) fn mean_edge_length(mesh: &UnwrapMesh) -> f64 {
    let p = mesh.positions();
    let (mut sum, mut count) = (0.0, 0usize);
    for t in mesh.triangles() {
        for i in 0..3 {
            let l = (p[t[i] as usize] - p[t[(i + 1) % 3] as usize]).length();
            if l.is_finite() {
                sum += l;
                count += 1;
            }
        }
    }
    let mean = sum / count.max(1) as f64;
    if mean > 0.0 && mean.is_finite() {
        mean
    } else {
        1.0
    }
}

/// A right triangle with both legs `leg`, clamped so its exact orientation is positive.
pub(super) fn right_triangle(leg: f64) -> [DVec2; 3] {
    let leg = if leg.is_finite() {
        leg.clamp(1e-100, 1e100)
    } else {
        1.0
    };
    [DVec2::ZERO, DVec2::new(leg, 0.0), DVec2::new(0.0, leg)]
}

pub(super) fn degenerate_chart(mesh: &UnwrapMesh, face: u32, mean_edge: f64) -> Chart {
    let t = mesh.triangles()[face as usize];
    let p = t.map(|v| mesh.positions()[v as usize]);
    let longest = (0..3)
        .map(|i| (p[i] - p[(i + 1) % 3]).length())
        .fold(0.0f64, f64::max);
    let leg = if longest > 0.0 && longest.is_finite() {
        longest
    } else {
        mean_edge
    };
    Chart {
        faces: vec![face],
        vertices: t.to_vec(),
        triangles: vec![[0, 1, 2]],
        uvs: right_triangle(leg).to_vec(),
    }
}
