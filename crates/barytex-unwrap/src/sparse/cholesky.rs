//! Sparse `L D Lᵀ` factorization of a symmetric positive definite matrix, after a nested
//! dissection ordering: the symbolic (elimination tree, column counts) and up-looking numeric
//! phases of T. A. Davis, "Algorithm 849: A concise sparse Cholesky factorization package",
//! *ACM Trans. Math. Softw.* 31(4), 2005 (also Davis, *Direct Methods for Sparse Linear
//! Systems*, SIAM 2006, §4). Factored once, it solves in two sparse triangular sweeps: the ARAP
//! global step reuses one factorization for every iteration.

use glam::DVec3;

use super::{CsrMatrix, ordering::nested_dissection};
use crate::UnwrapError;
use crate::alloc::try_vec_with_capacity;

const NO_PARENT: u32 = u32::MAX;

/// Largest factor attempted, in non-zeros (32 Mi: 384 MiB of rows and values); beyond it the
/// iterative solvers take over.
pub(crate) const MAX_FACTOR_NONZEROS: usize = 1 << 25;

/// `P A Pᵀ = L D Lᵀ` with unit lower-triangular `L` stored by columns.
#[derive(Clone, Debug)]
pub(crate) struct Cholesky {
    perm: Vec<u32>,
    col_start: Vec<usize>,
    rows: Vec<u32>,
    values: Vec<f64>,
    diag: Vec<f64>,
}

/// Why a factorization was not made.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FactorError {
    /// A pivot was not positive and finite: the matrix is not (numerically) positive definite.
    NotPositiveDefinite,
    /// The factor would exceed [`MAX_FACTOR_NONZEROS`].
    TooLarge,
    /// Memory.
    Alloc(UnwrapError),
}

impl Cholesky {
    /// Factors the symmetric `a` (both triangles stored), ordering by `coords` (one per row).
    pub(crate) fn factor(a: &CsrMatrix, coords: &[DVec3]) -> Result<Self, FactorError> {
        let n = a.n();
        let perm = nested_dissection(a, coords);
        let mut pinv = vec![0u32; n];
        for (k, &p) in perm.iter().enumerate() {
            pinv[p as usize] = k as u32;
        }
        // Symbolic: elimination tree and the count of each column of L.
        let mut parent = vec![NO_PARENT; n];
        let mut flag = vec![0u32; n];
        let mut count = vec![0usize; n];
        for k in 0..n {
            flag[k] = k as u32;
            let kk = perm[k] as usize;
            for &j in &a.columns[a.row_start[kk]..a.row_start[kk + 1]] {
                let mut i = pinv[j as usize] as usize;
                if i >= k {
                    continue;
                }
                while flag[i] != k as u32 {
                    if parent[i] == NO_PARENT {
                        parent[i] = k as u32;
                    }
                    count[i] += 1;
                    flag[i] = k as u32;
                    i = parent[i] as usize;
                }
            }
        }
        let total: usize = count.iter().sum();
        if total > MAX_FACTOR_NONZEROS {
            return Err(FactorError::TooLarge);
        }
        let mut col_start = try_vec_with_capacity(n + 1, "factor").map_err(FactorError::Alloc)?;
        col_start.push(0);
        for k in 0..n {
            col_start.push(col_start[k] + count[k]);
        }
        let mut rows = try_vec_with_capacity::<u32>(total, "factor").map_err(FactorError::Alloc)?;
        rows.resize(total, 0);
        let mut values =
            try_vec_with_capacity::<f64>(total, "factor").map_err(FactorError::Alloc)?;
        values.resize(total, 0.0);
        // Numeric, up-looking: row k of L from a sparse triangular solve.
        let mut diag = vec![0.0; n];
        let mut y = vec![0.0; n];
        let mut pattern = vec![0u32; n];
        let mut filled = vec![0usize; n];
        for k in 0..n {
            let mut top = n;
            flag[k] = k as u32;
            let kk = perm[k] as usize;
            let r = a.row_start[kk]..a.row_start[kk + 1];
            for (&j, &v) in a.columns[r.clone()].iter().zip(&a.values[r]) {
                let mut i = pinv[j as usize] as usize;
                if i > k {
                    continue;
                }
                y[i] += v;
                let mut len = 0;
                while flag[i] != k as u32 {
                    pattern[len] = i as u32;
                    len += 1;
                    flag[i] = k as u32;
                    i = parent[i] as usize;
                }
                while len > 0 {
                    top -= 1;
                    len -= 1;
                    pattern[top] = pattern[len];
                }
            }
            let mut d = y[k];
            y[k] = 0.0;
            for &i in &pattern[top..n] {
                let i = i as usize;
                let yi = y[i];
                y[i] = 0.0;
                let start = col_start[i];
                let end = start + filled[i];
                for p in start..end {
                    y[rows[p] as usize] -= values[p] * yi;
                }
                let l = yi / diag[i];
                d -= l * yi;
                rows[end] = k as u32;
                values[end] = l;
                filled[i] += 1;
            }
            if !(d > 0.0 && d.is_finite()) {
                return Err(FactorError::NotPositiveDefinite);
            }
            diag[k] = d;
        }
        Ok(Self {
            perm,
            col_start,
            rows,
            values,
            diag,
        })
    }

    /// Non-zeros of `L` (below the diagonal).
    #[cfg(test)]
    pub(crate) fn nonzeros(&self) -> usize {
        self.values.len()
    }

    /// Solves `A x = b`.
    pub(crate) fn solve(&self, b: &[f64], x: &mut [f64]) {
        let n = self.diag.len();
        let mut w: Vec<f64> = self.perm.iter().map(|&p| b[p as usize]).collect();
        for j in 0..n {
            let wj = w[j];
            for p in self.col_start[j]..self.col_start[j + 1] {
                w[self.rows[p] as usize] -= self.values[p] * wj;
            }
        }
        for (w, d) in w.iter_mut().zip(&self.diag) {
            *w /= d;
        }
        for j in (0..n).rev() {
            let mut s = w[j];
            for p in self.col_start[j]..self.col_start[j + 1] {
                s -= self.values[p] * w[self.rows[p] as usize];
            }
            w[j] = s;
        }
        for (k, &p) in self.perm.iter().enumerate() {
            x[p as usize] = w[k];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sparse::Triplets;

    #[test]
    fn solves_a_grid_laplacian_exactly() {
        // 1-D Laplacian on a 30 × 30 grid plus identity: SPD.
        let m = 30;
        let n = m * m;
        let mut t = Triplets::new(n, 5 * n).expect("small");
        let mut coords = Vec::new();
        for j in 0..m {
            for i in 0..m {
                let k = j * m + i;
                coords.push(DVec3::new(i as f64, j as f64, 0.0));
                t.add(k, k, 4.5);
                if i > 0 {
                    t.add(k, k - 1, -1.0);
                }
                if i + 1 < m {
                    t.add(k, k + 1, -1.0);
                }
                if j > 0 {
                    t.add(k, k - m, -1.0);
                }
                if j + 1 < m {
                    t.add(k, k + m, -1.0);
                }
            }
        }
        let a = CsrMatrix::from_triplets(t).expect("small");
        let c = Cholesky::factor(&a, &coords).expect("SPD");
        let truth: Vec<f64> = (0..n).map(|k| (k as f64 * 0.37).sin()).collect();
        let mut b = vec![0.0; n];
        a.mul(&truth, &mut b);
        let mut x = vec![0.0; n];
        c.solve(&b, &mut x);
        let err = x
            .iter()
            .zip(&truth)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-12, "{err}");
        // Nested dissection keeps the fill well below the dense n²/2.
        assert!(c.nonzeros() < n * 40, "{}", c.nonzeros());
    }

    #[test]
    fn indefinite_matrices_are_refused() {
        let mut t = Triplets::new(2, 4).expect("small");
        t.add(0, 0, 1.0);
        t.add(1, 1, -1.0);
        let a = CsrMatrix::from_triplets(t).expect("small");
        let e = Cholesky::factor(&a, &[DVec3::ZERO, DVec3::X]).map(|_| ());
        assert_eq!(e, Err(FactorError::NotPositiveDefinite));
    }
}
