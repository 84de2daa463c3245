//! A small dense LU factorisation with partial pivoting that owns its storage, so that the
//! contact solver can refactorise and solve thousands of times without allocating.

/// LU = PA of a square row-major matrix.
#[derive(Clone, Debug, Default)]
pub struct DenseLu {
    n: usize,
    lu: Vec<f64>,
    pivot: Vec<usize>,
}

impl DenseLu {
    /// Dimension of the last factorised matrix.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Row-major storage to fill with the matrix before [`DenseLu::factor_in_place`].
    pub fn storage(&mut self, n: usize) -> &mut [f64] {
        self.n = n;
        self.lu.clear();
        self.lu.resize(n * n, 0.0);
        &mut self.lu
    }

    /// Factorise the matrix written into [`DenseLu::storage`]; false if a pivot is zero or
    /// not finite (singular matrix).
    pub fn factor_in_place(&mut self) -> bool {
        let n = self.n;
        self.pivot.clear();
        self.pivot.extend(0..n);
        let a = &mut self.lu;
        for k in 0..n {
            let (mut best, mut row) = (0.0, k);
            for i in k..n {
                let v = a[i * n + k].abs();
                if v > best {
                    best = v;
                    row = i;
                }
            }
            if best == 0.0 || !best.is_finite() {
                return false;
            }
            if row != k {
                for j in 0..n {
                    a.swap(k * n + j, row * n + j);
                }
                self.pivot.swap(k, row);
            }
            let inv = 1.0 / a[k * n + k];
            let (top, bottom) = a.split_at_mut((k + 1) * n);
            let pivot_row = &top[k * n + k + 1..k * n + n];
            for i in 0..n - k - 1 {
                let row = &mut bottom[i * n..(i + 1) * n];
                let l = row[k] * inv;
                row[k] = l;
                if l != 0.0 {
                    for (x, &y) in row[k + 1..].iter_mut().zip(pivot_row) {
                        *x -= l * y;
                    }
                }
            }
        }
        true
    }

    /// Solve A x = b in place (b becomes x); `scratch` must have length n.
    pub fn solve_in_place(&self, b: &mut [f64], scratch: &mut [f64]) {
        let n = self.n;
        for i in 0..n {
            scratch[i] = b[self.pivot[i]];
        }
        let a = &self.lu;
        for i in 0..n {
            let row = &a[i * n..i * n + i];
            let s: f64 = row.iter().zip(&scratch[..i]).map(|(l, x)| l * x).sum();
            scratch[i] -= s;
        }
        for i in (0..n).rev() {
            let row = &a[i * n + i + 1..(i + 1) * n];
            let s: f64 = row.iter().zip(&scratch[i + 1..n]).map(|(u, x)| u * x).sum();
            scratch[i] = (scratch[i] - s) / a[i * n + i];
        }
        b[..n].copy_from_slice(&scratch[..n]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_nonsymmetric_system_with_pivoting() {
        // Zero leading entry forces a row exchange.
        let a = [0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let x = [1.0, -2.0, 0.5];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
            .collect();
        let mut lu = DenseLu::default();
        lu.storage(3).copy_from_slice(&a);
        assert!(lu.factor_in_place());
        let mut scratch = vec![0.0; 3];
        lu.solve_in_place(&mut b, &mut scratch);
        // A 3×3 well-conditioned system: a few ulps.
        for i in 0..3 {
            assert!((b[i] - x[i]).abs() < 1e-14);
        }
    }

    #[test]
    fn reports_singular_matrices() {
        let mut lu = DenseLu::default();
        lu.storage(2).copy_from_slice(&[1.0, 2.0, 2.0, 4.0]);
        assert!(!lu.factor_in_place());
    }
}
