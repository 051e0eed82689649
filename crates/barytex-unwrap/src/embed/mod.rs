//! Fixed-boundary embeddings of a disk: the boundary is pinned to a convex curve, every interior
//! vertex is a weighted average of its neighbours.
//!
//! Tutte's theorem (W. T. Tutte, "How to draw a graph", *Proc. London Math. Soc.* 13, 1963),
//! extended to positive non-symmetric weights by Floater ("Parametrization and smooth
//! approximation of surface triangulations", *CAGD* 14, 1997; "One-to-one piecewise linear
//! mappings over triangulations", *Math. Comp.* 72, 2003): with positive weights and the boundary
//! mapped to a strictly convex polygon, the solution is a bijection — every triangle is
//! positively oriented. The solve is iterative, so the guarantee holds up to its residual
//! (relative 1e-12); [`crate::flipped_triangles`] checks the result exactly.

mod boundary;
mod weights;

pub use boundary::BoundaryShape;
pub use weights::Weights;

use glam::{DVec2, DVec3};

use crate::sparse::{
    CsrMatrix, SolveControl, SolveReport, Triplets, bicgstab, preconditioned_bicgstab, solve_spd,
    try_factor,
};
use crate::topology::{HalfEdgeMesh, NONE};
use crate::{UnwrapError, check};

/// Texture coordinates of a disk and how the solve went.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Embedding {
    /// One texture coordinate per vertex (unused vertices get the origin).
    pub uvs: Vec<DVec2>,
    /// The linear solve (for two coordinates, the worse of the two).
    pub solve: SolveReport,
    /// Triangles not positively oriented, decided exactly.
    pub flips: usize,
}

/// The relative residual the embeddings solve to.
pub(crate) const TOLERANCE: f64 = 1e-12;

/// Embeds the disk `triangles` (over `positions`) with `weights`, its boundary on `shape`.
///
/// The boundary loop is laid counter-clockwise by arc length; the interior solves
/// `Σ_j w_ij (u_i − u_j) = 0` by conjugate gradients (symmetric weights) or BiCGSTAB
/// (mean-value weights).
///
/// ```
/// use barytex_unwrap::{BoundaryShape, Weights, embed_disk};
/// use glam::DVec3;
///
/// // A square with a centre vertex, lifted into a tent.
/// let p = [
///     DVec3::new(-1.0, -1.0, 0.0), DVec3::new(1.0, -1.0, 0.0),
///     DVec3::new(1.0, 1.0, 0.0), DVec3::new(-1.0, 1.0, 0.0), DVec3::new(0.0, 0.0, 1.0),
/// ];
/// let t = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
/// let e = embed_disk(&p, &t, Weights::MeanValue, BoundaryShape::Circle).expect("a disk");
/// assert_eq!(e.flips, 0);
/// assert!(e.uvs[4].length() < 1e-12); // the centre, by symmetry
/// ```
///
/// # Accuracy
/// The linear system is solved to a relative residual `≤ 1e-12` (sparse Cholesky for the
/// symmetric weights, measured `5e-15` on a 51 200-triangle grid; for mean value, BiCGSTAB
/// preconditioned by the factored uniform-weight matrix, 11 iterations to `4.6e-13` there), the
/// boundary lies on the circle within `1e-12` of its radius
/// (`embed.rs::boundary_lies_on_the_circle_by_arc_length`). For [`Weights::Uniform`] and
/// [`Weights::MeanValue`] on a circle, every triangle is positively oriented by exact
/// `orient2d` on random Delaunay disks lifted onto height fields and on perturbed lifted grids
/// (`embed.rs::tutte_and_mean_value_on_random_delaunay_disks`, `…_on_perturbed_lifted_grids`);
/// [`Embedding::flips`] reports any exception exactly.
///
/// # Errors
/// [`UnwrapError::NotADisk`] unless the triangles form one disk; the errors of
/// [`HalfEdgeMesh::from_triangles`]; [`UnwrapError::IndexOutOfRange`] for an index past
/// `positions`.
pub fn embed_disk(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    weights: Weights,
    shape: BoundaryShape,
) -> Result<Embedding, UnwrapError> {
    let n = u32::try_from(positions.len()).map_err(|_| UnwrapError::TooLarge {
        what: "vertices",
        requested: positions.len() as u64,
        limit: crate::MAX_VERTICES as u64,
    })?;
    let mesh = HalfEdgeMesh::from_triangles(n, triangles)?;
    let boundary = mesh.check_disk()?;
    embed_with_boundary(positions, &mesh, &boundary, weights, shape)
}

/// [`embed_disk`] on a checked mesh and its boundary loop.
pub(crate) fn embed_with_boundary(
    positions: &[DVec3],
    mesh: &HalfEdgeMesh,
    boundary: &[u32],
    weights: Weights,
    shape: BoundaryShape,
) -> Result<Embedding, UnwrapError> {
    let n = positions.len();
    let mut uvs = vec![DVec2::ZERO; n];
    let placed = boundary::place_boundary(positions, boundary, shape);
    for (&v, &p) in boundary.iter().zip(&placed) {
        uvs[v as usize] = p;
    }
    // Unknowns: the used interior vertices.
    let (index, unknowns) = mesh.number_vertices(|v| !mesh.is_boundary_vertex(v));
    let mut solve = SolveReport::NOTHING_TO_SOLVE;
    if unknowns > 0 {
        let (a, rhs) = assemble(positions, mesh, weights, &index, unknowns, &uvs)?;
        let control = SolveControl::for_size(unknowns, TOLERANCE);
        let mut coords = vec![DVec3::ZERO; unknowns];
        for v in 0..n {
            if index[v] != NONE {
                coords[index[v] as usize] = positions[v];
            }
        }
        // Symmetric weights: one factorization of the matrix for both coordinates. Mean value:
        // the uniform-weight (Tutte) matrix on the same unknowns, factored, preconditions
        // BiCGSTAB — both are graph Laplacians of the same mesh with the same boundary.
        let factor = if weights == Weights::MeanValue {
            let (tutte, _) = assemble(positions, mesh, Weights::Uniform, &index, unknowns, &uvs)?;
            try_factor(&tutte, &coords)
        } else {
            try_factor(&a, &coords)
        };
        for axis in 0..2 {
            let b: Vec<f64> = rhs.iter().map(|r| r[axis]).collect();
            let mut x = vec![0.0; unknowns];
            let report = match weights {
                Weights::MeanValue => match &factor {
                    Some(f) => {
                        let r = preconditioned_bicgstab(&a, &b, &mut x, control, &|r, z| {
                            f.solve(r, z);
                        });
                        if r.converged {
                            r
                        } else {
                            // Start the Jacobi fallback afresh: the failed attempt may have left
                            // non-finite values.
                            x.fill(0.0);
                            bicgstab(&a, &b, &mut x, control)
                        }
                    }
                    None => bicgstab(&a, &b, &mut x, control),
                },
                Weights::Uniform | Weights::Cotangent => {
                    solve_spd(&a, factor.as_ref(), &b, &mut x, control)
                }
            };
            for v in 0..n {
                if index[v] != NONE {
                    uvs[v][axis] = x[index[v] as usize];
                }
            }
            solve = worse(solve, report);
        }
    }
    let flips = check::count_flips(&uvs, mesh.triangles());
    Ok(Embedding { uvs, solve, flips })
}

/// The matrix of `Σ_j w_ij (u_i − u_j) = 0` over the `unknowns` interior vertices (`index`),
/// and its right-hand side from the placed boundary `uvs`.
fn assemble(
    positions: &[DVec3],
    mesh: &HalfEdgeMesh,
    weights: Weights,
    index: &[u32],
    unknowns: usize,
    uvs: &[DVec2],
) -> Result<(CsrMatrix, Vec<DVec2>), UnwrapError> {
    let w = weights::directed_weights(positions, mesh, weights);
    let mut t = Triplets::new(unknowns, 2 * w.len())?;
    let mut rhs = vec![DVec2::ZERO; unknowns];
    for &(i, j, wij) in &w {
        let ri = index[i as usize];
        if ri == NONE {
            continue;
        }
        t.add(ri as usize, ri as usize, wij);
        let cj = index[j as usize];
        if cj == NONE {
            rhs[ri as usize] += wij * uvs[j as usize];
        } else {
            t.add(ri as usize, cj as usize, -wij);
        }
    }
    Ok((CsrMatrix::from_triplets(t)?, rhs))
}

/// The report of the less successful of two solves.
pub(crate) fn worse(a: SolveReport, b: SolveReport) -> SolveReport {
    SolveReport {
        iterations: a.iterations.max(b.iterations),
        direct: a.direct && b.direct,
        relative_residual: a.relative_residual.max(b.relative_residual),
        converged: a.converged && b.converged,
    }
}
