//! A small dense LU factorisation with partial pivoting that owns its storage, so that the
//! contact solver can refactorise and solve thousands of times without allocating. The
//! factorisation itself is faer's blocked, vectorised kernel; the two triangular sweeps of a
//! single right-hand side are plain loops over contiguous columns.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::factor::{lu_in_place, lu_in_place_scratch};
use faer::{MatMut, Par};

/// Σ a_i b_i over the shorter of the two slices, with eight partial sums so that the compiler
/// can vectorise it (a single running sum fixes the order of the additions and cannot be).
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut partial = [0.0f64; 8];
    let (a_chunks, b_chunks) = (a.chunks_exact(8), b.chunks_exact(8));
    let tail: f64 = a_chunks
        .remainder()
        .iter()
        .zip(b_chunks.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in a_chunks.zip(b_chunks) {
        for k in 0..8 {
            partial[k] += x[k] * y[k];
        }
    }
    partial.iter().sum::<f64>() + tail
}

/// LU = PA of a square matrix given row by row.
#[derive(Default)]
pub struct DenseLu {
    n: usize,
    /// The matrix as written by the caller (row-major); after [`DenseLu::factor_in_place`]
    /// the same n² numbers of the factors in the order the single-vector sweeps read them
    /// (see [`DenseLu::pack`]).
    input: Vec<f64>,
    /// L and U, column-major.
    lu: Vec<f64>,
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
    stack: Option<MemBuffer>,
}

impl std::fmt::Debug for DenseLu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DenseLu").field("n", &self.n).finish()
    }
}

impl DenseLu {
    /// Dimension of the last factorised matrix.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Row-major storage (n × n) to fill with the matrix before [`DenseLu::factor_in_place`].
    pub fn storage(&mut self, n: usize) -> &mut [f64] {
        self.n = n;
        self.input.clear();
        self.input.resize(n * n, 0.0);
        &mut self.input
    }

    /// Factorise the matrix written into [`DenseLu::storage`]; false if a pivot is zero or
    /// not finite (singular matrix).
    pub fn factor_in_place(&mut self) -> bool {
        let n = self.n;
        self.lu.clear();
        self.lu.resize(n * n, 0.0);
        for i in 0..n {
            for j in 0..n {
                self.lu[j * n + i] = self.input[i * n + j];
            }
        }
        self.perm.resize(n, 0);
        self.perm_inv.resize(n, 0);
        let need = lu_in_place_scratch::<usize, f64>(n, n, Par::Seq, Default::default());
        if self
            .stack
            .as_ref()
            .is_none_or(|s| s.len() < need.unaligned_bytes_required())
        {
            self.stack = Some(MemBuffer::new(need));
        }
        let stack = MemStack::new(self.stack.as_mut().expect("allocated above"));
        let matrix = MatMut::from_column_major_slice_mut(&mut self.lu, n, n);
        lu_in_place(
            matrix,
            &mut self.perm,
            &mut self.perm_inv,
            Par::Seq,
            stack,
            Default::default(),
        );
        self.pack();
        (0..n).all(|k| {
            let pivot = self.lu[k * n + k];
            pivot != 0.0 && pivot.is_finite()
        })
    }

    /// Copy the factors into `input` as the sweeps of [`DenseLu::solve_in_place`] read them:
    /// the strict lower part of each column of L, first to last, then each column of U down
    /// to its diagonal, last to first. Read in place, the two sweeps take every other run of
    /// each column-major column (the other triangle's part lies between): at 1025 contact
    /// points, where the factors of both sliding directions and their gap matrices (34 MB)
    /// no longer fit the 32 MB cache, one contiguous stream per sweep is a third faster,
    /// with the same operations in the same order.
    fn pack(&mut self) {
        let n = self.n;
        self.input.clear();
        for j in 0..n {
            self.input
                .extend_from_slice(&self.lu[j * n + j + 1..(j + 1) * n]);
        }
        for j in (0..n).rev() {
            self.input.extend_from_slice(&self.lu[j * n..j * n + j + 1]);
        }
    }

    /// Row sums of Pᵀ|L||U| over column blocks, in the rows of the matrix as given (before
    /// pivoting): entry `[b][i]` is Σ_{j in block b} (Pᵀ|L||U|)_ij, block b being the
    /// columns `starts[b] .. starts[b + 1]` (the last one up to n). They bound the residual
    /// of a solve by these factors: the computed x̂ of A x = b satisfies (A + ΔA) x̂ = b with
    /// |ΔA| ≤ γ_3n Pᵀ|L||U| componentwise (Higham, *Accuracy and Stability of Numerical
    /// Algorithms*, 2nd ed., Thm 9.4; the factorisation by any ordering of the
    /// eliminations' inner products, blocked ones included, §9.3 and §13.2), so
    /// |A x̂ − b|_i ≤ γ_3n Σ_b (row sum b)_i max_{j in b} |x̂_j|. O(n²) per block, once per
    /// factorisation.
    pub fn abs_factor_row_sums(&self, starts: &[usize]) -> Vec<Vec<f64>> {
        let n = self.n;
        starts
            .iter()
            .enumerate()
            .map(|(b, &start)| {
                let end = starts.get(b + 1).copied().unwrap_or(n);
                // t = |U| 1_block: U's entries (i, j), i ≤ j, are lu[j n + i].
                let mut t = vec![0.0; n];
                for j in start..end {
                    for (ti, u) in t.iter_mut().zip(&self.lu[j * n..j * n + j + 1]) {
                        *ti += u.abs();
                    }
                }
                // s = |L| t with L's unit diagonal; L's entries (i, j), i > j, are lu[j n + i].
                let mut s = t.clone();
                for j in 0..n {
                    let tj = t[j];
                    if tj != 0.0 {
                        for (si, l) in s[j + 1..]
                            .iter_mut()
                            .zip(&self.lu[j * n + j + 1..(j + 1) * n])
                        {
                            *si += l.abs() * tj;
                        }
                    }
                }
                // Row i of LU is row perm[i] of the matrix.
                let mut rows = vec![0.0; n];
                for (i, &p) in self.perm.iter().enumerate() {
                    rows[p] = s[i];
                }
                rows
            })
            .collect()
    }

    /// The smallest |u_kk| of the factorisation (0 for an empty matrix).
    pub fn smallest_pivot(&self) -> f64 {
        let n = self.n;
        (0..n)
            .map(|k| self.lu[k * n + k].abs())
            .reduce(f64::min)
            .unwrap_or(0.0)
    }

    /// Solve A X = B in place for the columns of `rhs` (n × k, B becomes X) by faer's blocked
    /// triangular solves: for many right-hand sides several times faster than k calls of
    /// [`DenseLu::solve_in_place`], whose single-vector sweeps are bound by the memory
    /// traffic of reading the factors once per column.
    pub fn solve_columns_in_place(&self, rhs: &mut faer::Mat<f64>) {
        let n = self.n;
        assert_eq!(rhs.nrows(), n, "one row per unknown");
        let mut permuted = faer::Mat::<f64>::from_fn(n, rhs.ncols(), |i, j| rhs[(self.perm[i], j)]);
        let factors = faer::MatRef::from_column_major_slice(&self.lu, n, n);
        faer::linalg::triangular_solve::solve_unit_lower_triangular_in_place(
            factors,
            permuted.as_mut(),
            Par::Seq,
        );
        faer::linalg::triangular_solve::solve_upper_triangular_in_place(
            factors,
            permuted.as_mut(),
            Par::Seq,
        );
        *rhs = permuted;
    }

    /// Solve A x = b in place (b becomes x); `scratch` must have length n.
    pub fn solve_in_place(&self, b: &mut [f64], scratch: &mut [f64]) {
        let n = self.n;
        for i in 0..n {
            scratch[i] = b[self.perm[i]];
        }
        let (lower, upper) = self.input.split_at(n * (n - n.min(1)) / 2);
        let mut columns = lower;
        for j in 0..n {
            let (column, rest) = columns.split_at(n - j - 1);
            columns = rest;
            let xj = scratch[j];
            if xj != 0.0 {
                for (x, l) in scratch[j + 1..n].iter_mut().zip(column) {
                    *x -= l * xj;
                }
            }
        }
        let mut columns = upper;
        for j in (0..n).rev() {
            let (column, rest) = columns.split_at(j + 1);
            columns = rest;
            scratch[j] /= column[j];
            let xj = scratch[j];
            for (x, u) in scratch[..j].iter_mut().zip(column) {
                *x -= u * xj;
            }
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
    fn solves_a_larger_random_system() {
        // A diagonally dominant 70 × 70 system (the contact solver's size): residual ~ n ε.
        let n = 70;
        let mut seed = 12345u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % 10_000) as f64 / 10_000.0 - 0.5
        };
        let a: Vec<f64> = (0..n * n)
            .map(|k| if k % (n + 1) == 0 { 40.0 } else { next() })
            .collect();
        let x: Vec<f64> = (0..n).map(|_| next()).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum())
            .collect();
        let mut lu = DenseLu::default();
        lu.storage(n).copy_from_slice(&a);
        assert!(lu.factor_in_place());
        let mut scratch = vec![0.0; n];
        lu.solve_in_place(&mut b, &mut scratch);
        for i in 0..n {
            assert!((b[i] - x[i]).abs() < 1e-13, "{i}: {} vs {}", b[i], x[i]);
        }
    }

    #[test]
    fn dot_sums_every_product_whatever_the_length() {
        // Integers: exact in any order of summation.
        for n in [0, 1, 7, 8, 9, 23] {
            let a: Vec<f64> = (0..n).map(|i| i as f64).collect();
            let b: Vec<f64> = (0..n).map(|i| (2 * i + 1) as f64).collect();
            let want: f64 = (0..n).map(|i| (i * (2 * i + 1)) as f64).sum();
            assert_eq!(dot(&a, &b), want, "n = {n}");
        }
    }

    #[test]
    fn many_columns_at_once_equal_one_at_a_time() {
        // A 40 × 40 nonsymmetric system with pivoting, 7 right-hand sides: the blocked and the
        // vector sweeps do the same arithmetic in another order, so they agree to round-off.
        let n = 40;
        let a: Vec<f64> = (0..n * n)
            .map(|e| {
                let (i, j) = (e / n, e % n);
                ((7 * i + 3 * j) % 13) as f64 / 13.0 - 0.5
                    + if i == (j + 5) % n { 9.0 } else { 0.0 }
            })
            .collect();
        let mut lu = DenseLu::default();
        lu.storage(n).copy_from_slice(&a);
        assert!(lu.factor_in_place());
        let mut block = faer::Mat::<f64>::from_fn(n, 7, |i, j| ((i * (j + 1)) as f64).sin());
        let columns: Vec<Vec<f64>> = (0..7)
            .map(|j| (0..n).map(|i| block[(i, j)]).collect())
            .collect();
        lu.solve_columns_in_place(&mut block);
        let mut scratch = vec![0.0; n];
        for (j, mut x) in columns.into_iter().enumerate() {
            lu.solve_in_place(&mut x, &mut scratch);
            for i in 0..n {
                assert!((x[i] - block[(i, j)]).abs() < 1e-12, "({i}, {j})");
            }
        }
    }

    #[test]
    fn absolute_factor_row_sums_bound_the_residual() {
        // A 30 × 30 nonsymmetric system whose pivoting exchanges rows: the row sums equal
        // Pᵀ|L||U| formed entry by entry, and they bound the residual of a solve.
        let n = 30;
        let a: Vec<f64> = (0..n * n)
            .map(|e| {
                let (i, j) = (e / n, e % n);
                ((5 * i + 11 * j) % 17) as f64 / 17.0 - 0.45
                    + if i == (j + 3) % n { 4.0 } else { 0.0 }
            })
            .collect();
        let mut lu = DenseLu::default();
        lu.storage(n).copy_from_slice(&a);
        assert!(lu.factor_in_place());
        let starts = [0, 20, 29];
        let sums = lu.abs_factor_row_sums(&starts);
        let (l, u) = (
            |i: usize, j: usize| lu.lu[j * n + i],
            |i: usize, j: usize| lu.lu[j * n + i],
        );
        for (i, &row) in lu.perm.iter().enumerate() {
            for (b, &start) in starts.iter().enumerate() {
                let end = starts.get(b + 1).copied().unwrap_or(n);
                let want: f64 = (start..end)
                    .map(|j| {
                        (0..=i.min(j))
                            .map(|k| if k == i { 1.0 } else { l(i, k).abs() } * u(k, j).abs())
                            .sum::<f64>()
                    })
                    .sum();
                assert!(
                    (sums[b][row] - want).abs() <= 1e-12 * want,
                    "row {row} block {b}"
                );
            }
        }
        let x: Vec<f64> = (0..n).map(|i| (i as f64 * 1.3).cos() * 1e3).collect();
        let b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum())
            .collect();
        let mut solved = b.clone();
        lu.solve_in_place(&mut solved, &mut vec![0.0; n]);
        let gamma = 3.0 * n as f64 * f64::EPSILON / 2.0;
        for i in 0..n {
            let residual: f64 = (0..n).map(|j| a[i * n + j] * solved[j]).sum::<f64>() - b[i];
            let bound: f64 = starts
                .iter()
                .enumerate()
                .map(|(blk, &start)| {
                    let end = starts.get(blk + 1).copied().unwrap_or(n);
                    let largest = solved[start..end]
                        .iter()
                        .fold(0.0f64, |m, v| m.max(v.abs()));
                    gamma * sums[blk][i] * largest
                })
                .sum();
            // The residual as evaluated here carries its own rounding, n ε |A||x|.
            assert!(
                residual.abs() <= 2.0 * bound,
                "row {i}: {residual} > {bound}"
            );
        }
    }

    #[test]
    fn reports_singular_matrices() {
        let mut lu = DenseLu::default();
        lu.storage(2).copy_from_slice(&[1.0, 2.0, 2.0, 4.0]);
        assert!(!lu.factor_in_place());
    }
}
