//! BiCGSTAB with a Jacobi preconditioner, for the non-symmetric mean-value system.

use super::{CsrMatrix, SolveControl, SolveReport, dot, jacobi, norm};

/// Solves `A x = b` for a non-singular (not necessarily symmetric) `A`, from the `x` given.
/// H. A. van der Vorst, "Bi-CGSTAB: a fast and smoothly converging variant of Bi-CG for the
/// solution of nonsymmetric linear systems", *SIAM J. Sci. Stat. Comput.* 13(2), 1992; right
/// preconditioned as in Saad, *Iterative Methods for Sparse Linear Systems*, 2nd ed., §9.3.
pub(crate) fn bicgstab(
    a: &CsrMatrix,
    b: &[f64],
    x: &mut [f64],
    control: SolveControl,
) -> SolveReport {
    let inv_diag = jacobi(a);
    preconditioned_bicgstab(a, b, x, control, &|r: &[f64], z: &mut [f64]| {
        for ((z, r), d) in z.iter_mut().zip(r).zip(&inv_diag) {
            *z = r * d;
        }
    })
}

/// [`bicgstab`] with the right preconditioner `z = M⁻¹ r`.
pub(crate) fn preconditioned_bicgstab(
    a: &CsrMatrix,
    b: &[f64],
    x: &mut [f64],
    control: SolveControl,
    precondition: &dyn Fn(&[f64], &mut [f64]),
) -> SolveReport {
    let n = a.n();
    let b_norm = norm(b);
    if n == 0 || b_norm == 0.0 {
        if b_norm == 0.0 {
            x.fill(0.0);
        }
        return SolveReport {
            converged: true,
            ..SolveReport::default()
        };
    }
    let mut r = vec![0.0; n];
    a.mul(x, &mut r);
    for (r, b) in r.iter_mut().zip(b) {
        *r = b - *r;
    }
    let r_hat = r.clone();
    let (mut rho, mut alpha, mut omega) = (1.0, 1.0, 1.0);
    let mut v = vec![0.0; n];
    let mut p = vec![0.0; n];
    let mut y = vec![0.0; n];
    let mut s = vec![0.0; n];
    let mut z = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut residual = norm(&r) / b_norm;
    let mut iterations = 0;
    while residual > control.tolerance && iterations < control.max_iterations {
        let rho_new = dot(&r_hat, &r);
        if rho_new == 0.0 || !rho_new.is_finite() || omega == 0.0 {
            break;
        }
        let beta = (rho_new / rho) * (alpha / omega);
        rho = rho_new;
        for i in 0..n {
            p[i] = r[i] + beta * (p[i] - omega * v[i]);
        }
        precondition(&p, &mut y);
        a.mul(&y, &mut v);
        let rv = dot(&r_hat, &v);
        if rv == 0.0 || !rv.is_finite() {
            break;
        }
        alpha = rho / rv;
        for i in 0..n {
            s[i] = r[i] - alpha * v[i];
        }
        iterations += 1;
        if norm(&s) / b_norm <= control.tolerance {
            for i in 0..n {
                x[i] += alpha * y[i];
            }
            r.copy_from_slice(&s);
            residual = norm(&r) / b_norm;
            break;
        }
        precondition(&s, &mut z);
        a.mul(&z, &mut t);
        let tt = dot(&t, &t);
        omega = if tt > 0.0 { dot(&t, &s) / tt } else { 0.0 };
        for i in 0..n {
            x[i] += alpha * y[i] + omega * z[i];
            r[i] = s[i] - omega * t[i];
        }
        residual = norm(&r) / b_norm;
    }
    SolveReport {
        iterations,
        relative_residual: residual,
        converged: residual <= control.tolerance,
        direct: false,
    }
}
