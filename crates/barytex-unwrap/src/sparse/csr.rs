//! Compressed sparse row storage, assembled from triplets.

use crate::UnwrapError;
use crate::alloc::try_vec_with_capacity;

/// Entries `(row, column, value)` to be summed into a matrix.
#[derive(Debug, Default)]
pub(crate) struct Triplets {
    n: usize,
    entries: Vec<(u32, u32, f64)>,
}

impl Triplets {
    /// An empty `n × n` assembly with room for `capacity` entries.
    pub(crate) fn new(n: usize, capacity: usize) -> Result<Self, UnwrapError> {
        Ok(Self {
            n,
            entries: try_vec_with_capacity(capacity, "matrix entries")?,
        })
    }

    /// Adds `value` at `(row, col)`; duplicates are summed.
    pub(crate) fn add(&mut self, row: usize, col: usize, value: f64) {
        debug_assert!(row < self.n && col < self.n);
        self.entries.push((row as u32, col as u32, value));
    }
}

/// A square sparse matrix in compressed-sparse-row form.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CsrMatrix {
    pub(crate) row_start: Vec<usize>,
    pub(crate) columns: Vec<u32>,
    pub(crate) values: Vec<f64>,
}

impl CsrMatrix {
    /// Sums the triplets into rows sorted by column.
    pub(crate) fn from_triplets(mut t: Triplets) -> Result<Self, UnwrapError> {
        t.entries.sort_unstable_by_key(|e| (e.0, e.1));
        let mut row_start = try_vec_with_capacity(t.n + 1, "matrix rows")?;
        let mut columns = try_vec_with_capacity(t.entries.len(), "matrix entries")?;
        let mut values = try_vec_with_capacity(t.entries.len(), "matrix entries")?;
        row_start.push(0);
        let mut row = 0u32;
        let mut last: Option<(u32, u32)> = None;
        for &(r, c, v) in &t.entries {
            while row < r {
                row_start.push(columns.len());
                row += 1;
            }
            if last == Some((r, c)) {
                if let Some(x) = values.last_mut() {
                    *x += v;
                }
            } else {
                columns.push(c);
                values.push(v);
                last = Some((r, c));
            }
        }
        while row_start.len() < t.n + 1 {
            row_start.push(columns.len());
        }
        Ok(Self {
            row_start,
            columns,
            values,
        })
    }

    /// The number of rows (and columns).
    pub(crate) fn n(&self) -> usize {
        self.row_start.len() - 1
    }

    /// `y = A x`.
    pub(crate) fn mul(&self, x: &[f64], y: &mut [f64]) {
        for (r, y) in y.iter_mut().enumerate() {
            let range = self.row_start[r]..self.row_start[r + 1];
            *y = self.columns[range.clone()]
                .iter()
                .zip(&self.values[range])
                .map(|(&c, &v)| v * x[c as usize])
                .sum();
        }
    }

    /// The diagonal entries (0 where absent).
    pub(crate) fn diagonal(&self) -> Vec<f64> {
        (0..self.n())
            .map(|r| {
                let range = self.row_start[r]..self.row_start[r + 1];
                self.columns[range.clone()]
                    .iter()
                    .zip(&self.values[range])
                    .find(|&(&c, _)| c as usize == r)
                    .map_or(0.0, |(_, &v)| v)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_are_summed_and_rows_may_be_empty() {
        let mut t = Triplets::new(3, 4).expect("small");
        t.add(2, 0, 1.0);
        t.add(0, 0, 2.0);
        t.add(2, 0, 3.0);
        t.add(0, 2, -1.0);
        let a = CsrMatrix::from_triplets(t).expect("small");
        let mut y = [0.0; 3];
        a.mul(&[1.0, 10.0, 100.0], &mut y);
        assert_eq!(y, [2.0 - 100.0, 0.0, 4.0]);
        assert_eq!(a.diagonal(), vec![2.0, 0.0, 0.0]);
    }
}
