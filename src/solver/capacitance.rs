//! The reduced system of an active set solved through the factorisation of the all-active
//! one, corrected by a small capacitance system (Sherman–Morrison–Woodbury): a change of a
//! few contact points costs one solve per new point, not a refactorisation.
//!
//! Let K x = b be the all-active system [A R; E 0] [P; λ] = [−g; −L] and I the k points out
//! of contact. The reduced system of the active set drops the rows of I and fixes P_I = 0.
//! Give each dropped row a free multiplier μ_i, K x = b + U μ (U the unit columns of I), and
//! demand x_I = 0: with Z = K⁻¹ U and x₀ = K⁻¹ b,
//!
//!   x = x₀ + Z μ,   C μ = −(x₀)_I,   C = Uᵀ K⁻¹ U = Z_I (k × k).
//!
//! Row i of K x − b is then μ_i, and that row is A P + R λ + g at point i: μ is the gap of
//! the points out of contact, which the active-set update needs and gets for free. C is
//! regular exactly when the reduced system is (det of the reduced system = ± det K · det C).
//! The columns z_i depend only on K, so they are kept for as long as K is: a point that
//! leaves contact costs one solve with K's factors once, and the set of a later step that
//! contains it costs nothing more than the k × k factorisation of C.
//!
//! Cost per solve: one solve with K's factors (N² operations), k columns added (N k) and the
//! solve with C (k²); per change of the set, the factorisation of C (k³/3). Worth it while k
//! is small against N; beyond [`MAX_FRACTION`] of the points the caller factorises the reduced
//! system itself.

use crate::dense::DenseLu;

/// Largest share of the contact points out of contact for which the correction is used.
/// The correction's columns take k (N + m) numbers of memory and C's factorisation k³/3
/// operations per change of the set; refactorising the reduced system costs (2/3)(N − k)³.
/// A third keeps the correction both cheaper and small in memory (at N = 1025: 2.8 MB per
/// kept factorisation).
pub const MAX_FRACTION: f64 = 1.0 / 3.0;

/// The correction of one all-active factorisation (one compliance and direction).
#[derive(Debug, Default)]
pub struct Capacitance {
    /// z_i = K⁻¹ e_i, made on first use (length N + m each).
    columns: Vec<Option<Vec<f64>>>,
    /// The points out of contact of the factorised C, ascending.
    inactive: Vec<usize>,
    lu: DenseLu,
    valid: bool,
    multipliers: Vec<f64>,
    /// Per column z_i: max |z_i| over each block of unknowns (see [`Capacitance::solve`]).
    column_maxima: Vec<Vec<f64>>,
    /// Of the last solve, per block of unknowns: max |x₀| + Σ_i |μ_i| max |z_i| over the
    /// block, which bounds every term of the corrected solution (see [`Capacitance::bound`]).
    scale: Vec<f64>,
    /// Of the last solve: x_i just before it was set to zero, per point out of contact.
    leftover: Vec<f64>,
}

/// What the last corrected solve leaves for an a-posteriori bound on its residual
/// ([`crate::complementarity::ContactSolver::solve_pressures_into`]).
pub struct CorrectionTerms<'a> {
    /// Per block of unknowns, max |x₀| + Σ_i |μ_i| max |z_i| over the block.
    pub scale: &'a [f64],
    /// x_i just before it was set to zero, per point out of contact (in `inactive`'s order).
    pub leftover: &'a [f64],
    /// The number of columns added to x₀.
    pub columns: usize,
}

impl Capacitance {
    /// Whether the correction applies to `inactive` of `n` points.
    pub fn applies(inactive: usize, n: usize) -> bool {
        inactive > 0 && (inactive as f64) <= MAX_FRACTION * n as f64
    }

    /// Solve the reduced system of the active set whose complement is `inactive` (ascending):
    /// on entry `x` holds b = [−g; −L] for all N points (length N + m), on exit the solution
    /// with x_i = 0 on `inactive`; `gap[i]` for i in `inactive` receives that point's gap
    /// (mm; the other entries are left alone). False if C is singular (the reduced system
    /// is), or the result is not finite.
    ///
    /// `blocks` are the first unknowns of the blocks (ascending, the first 0) over which
    /// [`Capacitance::terms`] measures the solution's terms.
    pub fn solve(
        &mut self,
        full: &DenseLu,
        inactive: &[usize],
        blocks: &[usize],
        x: &mut [f64],
        gap: &mut [f64],
        scratch: &mut [f64],
    ) -> bool {
        let size = full.dim();
        if self.columns.len() != size {
            self.columns = vec![None; size];
            self.column_maxima = vec![Vec::new(); size];
        }
        // The missing columns in one blocked solve (a cold start may need many).
        let missing: Vec<usize> = inactive
            .iter()
            .copied()
            .filter(|&i| self.columns[i].is_none())
            .collect();
        if !missing.is_empty() {
            let mut block = faer::Mat::<f64>::zeros(size, missing.len());
            for (j, &i) in missing.iter().enumerate() {
                block[(i, j)] = 1.0;
            }
            full.solve_columns_in_place(&mut block);
            for (j, &i) in missing.iter().enumerate() {
                let column: Vec<f64> = block.col(j).iter().copied().collect();
                self.column_maxima[i] = block_maxima(&column, blocks);
                self.columns[i] = Some(column);
            }
        }
        if !self.valid || self.inactive != inactive {
            self.factorise(inactive);
        }
        if !self.valid {
            return false;
        }
        full.solve_in_place(x, &mut scratch[..size]);
        self.scale = block_maxima(x, blocks);
        let k = inactive.len();
        self.multipliers.clear();
        self.multipliers.extend(inactive.iter().map(|&i| -x[i]));
        self.lu
            .solve_in_place(&mut self.multipliers, &mut scratch[..k]);
        for (&i, &mu) in inactive.iter().zip(&self.multipliers) {
            let z = self.columns[i].as_ref().expect("made above");
            for (xj, zj) in x.iter_mut().zip(z) {
                *xj += mu * zj;
            }
            gap[i] = mu;
            for (s, z) in self.scale.iter_mut().zip(&self.column_maxima[i]) {
                *s += mu.abs() * z;
            }
        }
        // Round-off leaves x_i at about ε |x|: the set says it is zero.
        self.leftover.clear();
        for &i in inactive {
            self.leftover.push(x[i]);
            x[i] = 0.0;
        }
        self.multipliers.iter().all(|m| m.is_finite()) && x.iter().all(|v| v.is_finite())
    }

    /// What the last solve leaves for a bound on its residual. With x₀ = K⁻¹ b and the
    /// columns z_i as computed (each with a backward error ΔK bounded as in
    /// [`DenseLu::abs_factor_row_sums`]), the sum x = x₀ + Σ μ_i z_i with its rounding δ and
    /// the leftovers t_i set to zero, the residual is exactly
    ///
    ///   K x − b = −ΔK₀ x₀ − Σ μ_i ΔK_i z_i + K δ − Σ_i t_i K e_i + Σ_i μ_i e_i,
    ///
    /// whatever μ the capacitance solve gave: in the rows of the active set every term but
    /// the last is bounded by the factors' row sums times [`CorrectionTerms::scale`], by
    /// |K|'s row sums times the same with γ_{k+1}, and by Σ |t_i| max |K e_i|; in the rows
    /// out of contact the same bound holds for the residual's distance from μ_i (the gap
    /// the solve reports). A correction gone wrong (K far worse conditioned than the
    /// reduced system: large μ and z, cancellation) shows as a large scale or leftover.
    pub fn terms(&self) -> CorrectionTerms<'_> {
        CorrectionTerms {
            scale: &self.scale,
            leftover: &self.leftover,
            columns: self.inactive.len(),
        }
    }

    fn factorise(&mut self, inactive: &[usize]) {
        let k = inactive.len();
        let matrix = self.lu.storage(k);
        for (row, &i) in inactive.iter().enumerate() {
            for (col, &j) in inactive.iter().enumerate() {
                matrix[row * k + col] = self.columns[j].as_ref().expect("made before")[i];
            }
        }
        self.valid = self.lu.factor_in_place();
        self.inactive.clear();
        self.inactive.extend_from_slice(inactive);
    }
}

/// max |v_j| over each block of `v`, the blocks starting at `blocks` (ascending).
pub fn block_maxima(v: &[f64], blocks: &[usize]) -> Vec<f64> {
    blocks
        .iter()
        .enumerate()
        .map(|(b, &start)| {
            let end = blocks.get(b + 1).copied().unwrap_or(v.len());
            v[start..end].iter().fold(0.0f64, |a, x| a.max(x.abs()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reduced system solved directly: rows and columns of `keep` of the row-major `k`.
    fn reduced_direct(k: &[f64], n: usize, keep: &[usize], b: &[f64]) -> Vec<f64> {
        let size = keep.len();
        let mut lu = DenseLu::default();
        let mat = lu.storage(size);
        for (r, &i) in keep.iter().enumerate() {
            for (c, &j) in keep.iter().enumerate() {
                mat[r * size + c] = k[i * n + j];
            }
        }
        assert!(lu.factor_in_place());
        let mut x: Vec<f64> = keep.iter().map(|&i| b[i]).collect();
        let mut scratch = vec![0.0; size];
        lu.solve_in_place(&mut x, &mut scratch);
        x
    }

    #[test]
    fn equals_the_reduced_system_and_returns_the_dropped_rows_residuals() {
        // A nonsymmetric, diagonally dominant 12 × 12 system: both routes are exact, so they
        // agree to round-off (1e-12 of |x| leaves a few hundred ulps for the two solves).
        let n = 12;
        let k: Vec<f64> = (0..n * n)
            .map(|e| {
                let (i, j) = (e / n, e % n);
                if i == j {
                    10.0 + i as f64
                } else {
                    ((3 * i + 7 * j) % 11) as f64 / 11.0 - 0.4
                }
            })
            .collect();
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut full = DenseLu::default();
        full.storage(n).copy_from_slice(&k);
        assert!(full.factor_in_place());
        let mut correction = Capacitance::default();
        let mut scratch = vec![0.0; n];
        for inactive in [vec![3usize], vec![1, 3, 8], vec![1, 8], vec![0, 5, 6, 11]] {
            let keep: Vec<usize> = (0..n).filter(|i| !inactive.contains(i)).collect();
            let direct = reduced_direct(&k, n, &keep, &b);
            let mut x = b.clone();
            let mut gap = vec![f64::NAN; n];
            assert!(correction.solve(&full, &inactive, &[0], &mut x, &mut gap, &mut scratch));
            for (r, &i) in keep.iter().enumerate() {
                assert!((x[i] - direct[r]).abs() < 1e-12, "{inactive:?} x[{i}]");
            }
            for &i in &inactive {
                assert_eq!(x[i], 0.0);
                // The dropped row's residual (K x − b)_i is the multiplier.
                let residual: f64 = (0..n).map(|j| k[i * n + j] * x[j]).sum::<f64>() - b[i];
                assert!((gap[i] - residual).abs() < 1e-12, "{inactive:?} gap[{i}]");
            }
        }
    }

    #[test]
    fn reports_a_singular_reduced_system() {
        // K = [[1, 1, 0], [1, 1, 1], [0, 1, 1]] is regular (det −1), but without point 2 it
        // leaves [[1, 1], [1, 1]]: C = (K⁻¹)₂₂ = 0, and in these small integers the LU
        // computes it exactly.
        let mut full = DenseLu::default();
        full.storage(3)
            .copy_from_slice(&[1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0]);
        assert!(full.factor_in_place());
        let mut correction = Capacitance::default();
        let (mut gap, mut scratch) = (vec![0.0; 3], vec![0.0; 3]);
        let mut x = vec![1.0, 1.0, 1.0];
        assert!(!correction.solve(&full, &[2], &[0], &mut x, &mut gap, &mut scratch));
        // Without point 0 it leaves [[1, 1], [1, 1]] as well; without point 1, [[1, 0], [0, 1]].
        let mut x = vec![1.0, 1.0, 1.0];
        assert!(correction.solve(&full, &[1], &[0], &mut x, &mut gap, &mut scratch));
        // Exact solution [1, 0, 1]; entries of order one: a few ulps.
        for (got, want) in x.iter().zip([1.0, 0.0, 1.0]) {
            assert!((got - want).abs() < 1e-14, "{x:?}");
        }
    }
}
