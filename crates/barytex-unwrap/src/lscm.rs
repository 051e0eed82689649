//! Least squares conformal maps (B. Lévy, S. Petitjean, N. Ray, J. Maillot, "Least squares
//! conformal maps for automatic texture atlas generation", *ACM Trans. Graph.* 21(3), 2002).
//!
//! Each triangle, laid flat, contributes `|Σ_j W_j U_j|² / d_T` (§3.3, eq. 8 of the paper):
//! `U_j = u_j + i v_j`, `W_j` the complex edge opposite corner `j`, `d_T` twice the area. The sum
//! is the conformal energy; it vanishes exactly on orientation-preserving similarities, so two
//! pinned vertices (four real unknowns) make the normal equations symmetric positive definite.
//!
//! # Accuracy
//! On a planar mesh the minimum is the identity up to a similarity: the result reproduces the
//! input up to a similarity with a relative error at most `1e-8` of the chart's size (tested in
//! `lscm_reproduces_a_planar_mesh`), the solver's residual being `1e-12`.

use glam::{DVec2, DVec3};

use crate::embed::{Embedding, TOLERANCE, worse};
use crate::geometry::{doubled_area_2d, flatten};
use crate::sparse::{CsrMatrix, SolveControl, SolveReport, Triplets, solve_spd, try_factor};
use crate::topology::{HalfEdgeMesh, NONE};
use crate::{UnwrapError, check};

/// LSCM of the disk `triangles` over `positions`, with the two boundary vertices farthest apart
/// (an approximate diameter, from two sweeps) pinned at `(0, 0)` and `(d, 0)`, `d` their 3-D
/// distance. A conformal map need not be injective: the result's flips are counted, not
/// excluded ([`crate::parameterize`] falls back to a mean-value embedding then).
///
/// ```
/// use barytex_unwrap::lscm;
/// use glam::DVec3;
///
/// let p = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let e = lscm(&p, &[[0, 1, 2], [0, 2, 3]]).expect("a disk");
/// assert_eq!(e.flips, 0);
/// // A unit square maps to a square: its diagonal is pinned, so the sides have length 1.
/// assert!(((e.uvs[1] - e.uvs[0]).length() - 1.0).abs() < 1e-9);
/// ```
///
/// # Errors
/// [`UnwrapError::NotADisk`] unless the triangles form one disk; the errors of
/// [`HalfEdgeMesh::from_triangles`].
pub fn lscm(positions: &[DVec3], triangles: &[[u32; 3]]) -> Result<Embedding, UnwrapError> {
    let n = u32::try_from(positions.len()).map_err(|_| UnwrapError::TooLarge {
        what: "vertices",
        requested: positions.len() as u64,
        limit: crate::MAX_VERTICES as u64,
    })?;
    let mesh = HalfEdgeMesh::from_triangles(n, triangles)?;
    let boundary = mesh.check_disk()?;
    lscm_with_boundary(positions, &mesh, &boundary)
}

/// The vertex of `candidates` farthest from `from`.
fn farthest(positions: &[DVec3], candidates: &[u32], from: u32) -> u32 {
    let p = positions[from as usize];
    let mut best = (from, -1.0);
    for &c in candidates {
        let d = (positions[c as usize] - p).length_squared();
        if d > best.1 {
            best = (c, d);
        }
    }
    best.0
}

/// [`lscm`] on a checked mesh and its boundary loop.
pub(crate) fn lscm_with_boundary(
    positions: &[DVec3],
    mesh: &HalfEdgeMesh,
    boundary: &[u32],
) -> Result<Embedding, UnwrapError> {
    let n = positions.len();
    let a = farthest(positions, boundary, boundary[0]);
    let b = farthest(positions, boundary, a);
    let mut uvs = vec![DVec2::ZERO; n];
    let d = (positions[b as usize] - positions[a as usize]).length();
    uvs[b as usize] = DVec2::new(if d > 0.0 && d.is_finite() { d } else { 1.0 }, 0.0);
    let (index, unknowns) = mesh.number_vertices(|v| v != a && v != b);
    let mut solve = SolveReport::NOTHING_TO_SOLVE;
    if unknowns > 0 {
        let m = 2 * unknowns;
        let mut t = Triplets::new(m, 36 * mesh.triangles().len())?;
        let mut rhs = vec![0.0; m];
        for tri in mesh.triangles() {
            let q = flatten(tri.map(|v| positions[v as usize]));
            let dt = doubled_area_2d(q);
            if !(dt > 0.0 && dt.is_finite()) {
                continue;
            }
            let s = dt.sqrt().recip();
            // Rows of the real form of Σ W_j U_j / √d_T over [u0, v0, u1, v1, u2, v2].
            let mut re = [0.0; 6];
            let mut im = [0.0; 6];
            for j in 0..3 {
                let w = (q[(j + 2) % 3] - q[(j + 1) % 3]) * s;
                re[2 * j] = w.x;
                re[2 * j + 1] = -w.y;
                im[2 * j] = w.y;
                im[2 * j + 1] = w.x;
            }
            let dof = |k: usize| -> (u32, usize) { (tri[k / 2], k % 2) };
            for r in 0..6 {
                let (vr, cr) = dof(r);
                let ir = index[vr as usize];
                if ir == NONE {
                    continue;
                }
                let row = 2 * ir as usize + cr;
                for c in 0..6 {
                    let k = re[r] * re[c] + im[r] * im[c];
                    let (vc, cc) = dof(c);
                    let ic = index[vc as usize];
                    if ic == NONE {
                        rhs[row] -= k * uvs[vc as usize][cc];
                    } else {
                        t.add(row, 2 * ic as usize + cc, k);
                    }
                }
            }
        }
        let matrix = CsrMatrix::from_triplets(t)?;
        let mut x = initial_guess(positions, mesh.triangles(), &index, unknowns, a, b, &uvs);
        let mut coords = vec![DVec3::ZERO; m];
        for v in 0..n {
            let i = index[v];
            if i != NONE {
                coords[2 * i as usize] = positions[v];
                coords[2 * i as usize + 1] = positions[v];
            }
        }
        let factor = try_factor(&matrix, &coords);
        let control = SolveControl::for_size(m, TOLERANCE);
        let report = solve_spd(&matrix, factor.as_ref(), &rhs, &mut x, control);
        for v in 0..n {
            let i = index[v];
            if i != NONE {
                uvs[v] = DVec2::new(x[2 * i as usize], x[2 * i as usize + 1]);
            }
        }
        solve = worse(solve, report);
    }
    let flips = check::count_flips(&uvs, mesh.triangles());
    Ok(Embedding { uvs, solve, flips })
}

/// A warm start: the vertices projected onto the plane through pin `a` spanned by the pin
/// direction and the mesh's mean normal, in the pins' frame. Exact for a planar mesh up to
/// rounding, close for a nearly flat chart, so conjugate gradients start near the answer.
fn initial_guess(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    index: &[u32],
    unknowns: usize,
    a: u32,
    b: u32,
    uvs: &[DVec2],
) -> Vec<f64> {
    let mut x = vec![0.0; 2 * unknowns];
    let pa = positions[a as usize];
    let axis = positions[b as usize] - pa;
    let scale = uvs[b as usize].x / axis.length().max(f64::MIN_POSITIVE);
    let xaxis = axis.normalize_or_zero();
    // The area-weighted mean normal, oriented by the triangles.
    let normal: DVec3 = triangles
        .iter()
        .map(|t| {
            let p = t.map(|v| positions[v as usize]);
            (p[1] - p[0]).cross(p[2] - p[0])
        })
        .sum();
    let yaxis = normal.cross(xaxis).normalize_or_zero();
    if yaxis == DVec3::ZERO || !(scale.is_finite()) {
        return x;
    }
    for (v, &i) in index.iter().enumerate() {
        if i != NONE {
            let d = positions[v] - pa;
            x[2 * i as usize] = scale * d.dot(xaxis);
            x[2 * i as usize + 1] = scale * d.dot(yaxis);
        }
    }
    x
}
