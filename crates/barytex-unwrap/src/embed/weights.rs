//! Edge weights of the convex-combination (and harmonic) embeddings.

use glam::DVec3;

use crate::topology::{HalfEdgeMesh, NONE};

/// The weights `w_ij` of the equations `Σ_j w_ij (u_i − u_j) = 0` at interior vertices.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Weights {
    /// `w_ij = 1` for every edge: Tutte's barycentric embedding (Tutte 1963). Symmetric.
    Uniform,
    /// Floater's mean-value weights `w_ij = (tan(α_ij / 2) + tan(β_ij / 2)) / |x_i − x_j|`, with
    /// `α_ij`, `β_ij` the angles at `x_i` beside the edge (Floater 2003, "Mean value
    /// coordinates", eq. 3.1). Positive, so a convex combination; not symmetric.
    #[default]
    MeanValue,
    /// Cotangent (harmonic) weights `w_ij = (cot γ_ij + cot δ_ij) / 2`, with `γ_ij`, `δ_ij` the
    /// angles opposite the edge (Pinkall and Polthier 1993; Eck et al. 1995). Symmetric, but
    /// negative where `γ + δ > π`: then the result is not a convex combination and Tutte's
    /// theorem no longer guarantees a bijection — flips are possible and counted.
    Cotangent,
}

/// `tan(θ/2)` of the angle between `a` and `b`, without cancellation on either side of π/2.
fn half_angle_tan(a: DVec3, b: DVec3) -> f64 {
    let cross = a.cross(b).length();
    let dot = a.dot(b);
    let ab = a.length() * b.length();
    if dot >= 0.0 {
        cross / (ab + dot)
    } else {
        (ab - dot) / cross
    }
}

/// `cot θ` of the angle between `a` and `b`.
fn cotangent(a: DVec3, b: DVec3) -> f64 {
    a.dot(b) / a.cross(b).length()
}

/// Directed weights `(i, j, w_ij)` of `mesh` for `kind` (a pair may appear several times; the
/// entries are summed).
pub(crate) fn directed_weights(
    positions: &[DVec3],
    mesh: &HalfEdgeMesh,
    kind: Weights,
) -> Vec<(u32, u32, f64)> {
    let tris = mesh.triangles();
    let mut out = Vec::with_capacity(6 * tris.len());
    match kind {
        Weights::Uniform => {
            for h in 0..3 * tris.len() as u32 {
                let t = mesh.twin(h);
                if t == NONE || h < t {
                    let (a, b) = (mesh.origin(h), mesh.target(h));
                    out.push((a, b, 1.0));
                    out.push((b, a, 1.0));
                }
            }
        }
        Weights::Cotangent => {
            for t in tris {
                for k in 0..3 {
                    let (i, j, o) = (t[(k + 1) % 3], t[(k + 2) % 3], t[k]);
                    let po = positions[o as usize];
                    let w = 0.5 * cotangent(positions[i as usize] - po, positions[j as usize] - po);
                    out.push((i, j, w));
                    out.push((j, i, w));
                }
            }
        }
        Weights::MeanValue => {
            for t in tris {
                for k in 0..3 {
                    let (i, j, l) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
                    let pi = positions[i as usize];
                    let (a, b) = (positions[j as usize] - pi, positions[l as usize] - pi);
                    let tan = half_angle_tan(a, b);
                    out.push((i, j, tan / a.length()));
                    out.push((i, l, tan / b.length()));
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_angle_tangent_on_both_sides_of_a_right_angle() {
        for deg in [1.0f64, 45.0, 90.0, 135.0, 179.0] {
            let th = deg.to_radians();
            let t = half_angle_tan(DVec3::X, DVec3::new(th.cos(), th.sin(), 0.0));
            assert!((t - (th / 2.0).tan()).abs() <= 1e-13 * t, "{deg}: {t}");
        }
    }
}
