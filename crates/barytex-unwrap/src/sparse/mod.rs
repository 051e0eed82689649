//! Sparse linear algebra: a compressed-sparse-row matrix, a sparse `L D Lᵀ` factorization and two
//! Krylov solvers.
//!
//! # Why hand-written solvers
//! Every system this crate solves is a discrete Laplacian or the LSCM normal equations, both
//! sparse with about seven non-zeros per row. The symmetric ones (Tutte with uniform weights,
//! harmonic, the LSCM normal equations, the ARAP global step) are symmetric positive definite
//! once the boundary or the pins are removed, so the preconditioned conjugate gradient method
//! (Hestenes and Stiefel 1952; Saad, *Iterative Methods for Sparse Linear Systems*, 2nd ed.,
//! 2003, algorithm 9.1) converges; Floater's mean-value weights make the matrix non-symmetric
//! (but an M-matrix), solved with BiCGSTAB (van der Vorst 1992; Saad algorithm 7.7). The
//! symmetric systems are factored by a sparse `L D Lᵀ` (Davis 2005) after nested dissection, with
//! Jacobi-preconditioned CG as fallback; BiCGSTAB is preconditioned by the factored uniform-weight
//! matrix of the same mesh, with Jacobi as fallback.
//!
//! faer's sparse Cholesky/LU was the alternative: it would add 95 crates to this crate's
//! `cargo tree` (which CI counts) and about 170 s of CPU per clean release build to a 2-core CI;
//! the measurements that decided are in the crate README ("Solver").

mod bicgstab;
mod cg;
mod cholesky;
mod csr;
mod ordering;

pub(crate) use bicgstab::{bicgstab, preconditioned_bicgstab};
pub(crate) use cg::conjugate_gradient;
pub(crate) use cholesky::Cholesky;
pub(crate) use csr::{CsrMatrix, Triplets};

/// How an iterative solve ended.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SolveReport {
    /// Iterations run.
    pub iterations: u32,
    /// The final relative residual `‖b − A x‖ / ‖b‖` (0 for `b = 0`).
    pub relative_residual: f64,
    /// Whether the residual reached the tolerance.
    pub converged: bool,
    /// Whether a sparse Cholesky factorization solved it (`iterations` then counts iterative
    /// refinement steps).
    pub direct: bool,
}

impl SolveReport {
    /// The report of a system with no unknowns: nothing to solve is a converged, exact solve.
    pub(crate) const NOTHING_TO_SOLVE: Self = Self {
        iterations: 0,
        relative_residual: 0.0,
        converged: true,
        direct: true,
    };
}

/// Stopping rule of the iterative solvers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SolveControl {
    /// Target relative residual.
    pub(crate) tolerance: f64,
    /// Iteration cap.
    pub(crate) max_iterations: u32,
}

impl SolveControl {
    /// The default for a system of `n` unknowns: relative residual 1e-12, at most
    /// `max(2000, 4 n)` iterations (Jacobi-preconditioned CG on a 2-D Laplacian needs
    /// O(√n) to O(n) iterations).
    pub(crate) fn for_size(n: usize, tolerance: f64) -> Self {
        let cap = (4 * n).clamp(2000, u32::MAX as usize) as u32;
        Self {
            tolerance,
            max_iterations: cap,
        }
    }
}

/// Solves the symmetric positive definite `A x = b` with a factorization when given one (plus up
/// to two steps of iterative refinement), falling back to conjugate gradients from the result
/// when the residual is still above the tolerance (or without a factorization).
pub(crate) fn solve_spd(
    a: &CsrMatrix,
    factor: Option<&Cholesky>,
    b: &[f64],
    x: &mut [f64],
    control: SolveControl,
) -> SolveReport {
    let Some(factor) = factor else {
        return conjugate_gradient(a, b, x, control);
    };
    let b_norm = norm(b);
    factor.solve(b, x);
    let mut r = vec![0.0; b.len()];
    let mut dx = vec![0.0; b.len()];
    let mut refinements = 0;
    loop {
        a.mul(x, &mut r);
        for (r, b) in r.iter_mut().zip(b) {
            *r = b - *r;
        }
        let residual = if b_norm > 0.0 {
            norm(&r) / b_norm
        } else {
            norm(&r)
        };
        if residual <= control.tolerance {
            return SolveReport {
                iterations: refinements,
                relative_residual: residual,
                converged: true,
                direct: true,
            };
        }
        if refinements == 2 || !residual.is_finite() {
            if !residual.is_finite() {
                x.fill(0.0);
            }
            return conjugate_gradient(a, b, x, control);
        }
        factor.solve(&r, &mut dx);
        for (x, d) in x.iter_mut().zip(&dx) {
            *x += d;
        }
        refinements += 1;
    }
}

/// A factorization of `a` ordered by `coords`, or `None` when it is not positive definite
/// numerically, too large, or does not fit in memory (the callers then iterate).
pub(crate) fn try_factor(a: &CsrMatrix, coords: &[glam::DVec3]) -> Option<Cholesky> {
    Cholesky::factor(a, coords).ok()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// The inverse diagonal for the Jacobi preconditioner (1 where the diagonal is not a positive
/// finite number, so the preconditioner stays defined).
fn jacobi(a: &CsrMatrix) -> Vec<f64> {
    a.diagonal()
        .into_iter()
        .map(|d| {
            if d > 0.0 && d.is_finite() {
                1.0 / d
            } else {
                1.0
            }
        })
        .collect()
}
