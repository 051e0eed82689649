//! The Jacobi-preconditioned conjugate gradient method for symmetric positive definite systems.

use super::{CsrMatrix, SolveControl, SolveReport, dot, jacobi, norm};

/// Solves `A x = b` for a symmetric positive definite `A`, starting from the `x` given (a warm
/// start). Saad, *Iterative Methods for Sparse Linear Systems*, 2nd ed., algorithm 9.1.
pub(crate) fn conjugate_gradient(
    a: &CsrMatrix,
    b: &[f64],
    x: &mut [f64],
    control: SolveControl,
) -> SolveReport {
    let n = a.n();
    let b_norm = norm(b);
    if n == 0 {
        return SolveReport {
            converged: true,
            ..SolveReport::default()
        };
    }
    if b_norm == 0.0 {
        x.fill(0.0);
        return SolveReport {
            converged: true,
            ..SolveReport::default()
        };
    }
    let inv_diag = jacobi(a);
    let mut r = vec![0.0; n];
    a.mul(x, &mut r);
    for (r, b) in r.iter_mut().zip(b) {
        *r = b - *r;
    }
    let mut z: Vec<f64> = r.iter().zip(&inv_diag).map(|(r, d)| r * d).collect();
    let mut p = z.clone();
    let mut ap = vec![0.0; n];
    let mut rz = dot(&r, &z);
    let mut residual = norm(&r) / b_norm;
    let mut iterations = 0;
    while residual > control.tolerance && iterations < control.max_iterations {
        a.mul(&p, &mut ap);
        let pap = dot(&p, &ap);
        if !(pap > 0.0 && pap.is_finite()) {
            // Not positive definite along p (or broken down): stop with what we have.
            break;
        }
        let alpha = rz / pap;
        for i in 0..n {
            x[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
        }
        iterations += 1;
        residual = norm(&r) / b_norm;
        for i in 0..n {
            z[i] = r[i] * inv_diag[i];
        }
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for i in 0..n {
            p[i] = z[i] + beta * p[i];
        }
    }
    SolveReport {
        iterations,
        relative_residual: residual,
        converged: residual <= control.tolerance,
        direct: false,
    }
}
