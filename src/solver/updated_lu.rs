//! A sequence of dense systems M x = b whose matrices differ from a factorised one in a few
//! rows, solved without refactorising: the Newton iterations of the steady state, where a
//! point that enters or leaves contact replaces its rows and nothing else changes (b = 1).
//!
//! With M = M₀ + U Dᵀ (U the unit columns of the k changed rows, the rows of Dᵀ their
//! change), the Sherman–Morrison–Woodbury formula gives
//!
//!   x = y − Z (I + Dᵀ Z)⁻¹ Dᵀ y,   y = M₀⁻¹ b,   Z = M₀⁻¹ U.
//!
//! The columns of Z depend only on M₀ and the row indices, so each is made once. A solve costs
//! one solve with M₀'s factors, k² dot products of length n and a k × k factorisation, against
//! (2/3) n³ for a new factorisation. The result is checked by its residual; a correction that
//! lost accuracy, or a change of more than [`MAX_CHANGED_FRACTION`] of the rows, makes the
//! current matrix the new M₀ instead.

use crate::dense::{dot, DenseLu};

/// Largest share of changed rows for which the update is used instead of a factorisation.
/// The update's work grows as k² n + k n² (new columns) against (2/3) n³.
pub const MAX_CHANGED_FRACTION: f64 = 0.2;

/// Relative residual ‖M x − b‖∞ / (‖M‖∞ ‖x‖∞ + ‖b‖∞) above which an updated solve is redone
/// by a factorisation: a backward-stable solve leaves about n ε (1e-12 at n = 3000); a
/// correction through an ill-conditioned capacitance matrix loses digits, and 1e-10 rejects it
/// long before the Newton iteration would notice.
const ACCEPTED_RESIDUAL: f64 = 1e-10;

/// How a solve was done.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// The matrix was factorised (first solve, many changed rows, or a rejected update).
    Factorised,
    /// The base factorisation, corrected for this many changed rows.
    Updated(usize),
}

/// The factorised base matrix, its solves with unit vectors, and the current matrix.
#[derive(Debug, Default)]
pub struct UpdatedLu {
    n: usize,
    base: DenseLu,
    /// Row-major copy of M₀.
    base_rows: Vec<f64>,
    /// M₀⁻¹ e_r, made on first use.
    columns: Vec<Option<Vec<f64>>>,
    matrix: Vec<f64>,
    changed: Vec<usize>,
    capacitance: DenseLu,
    scratch: Vec<f64>,
    y: Vec<f64>,
    multipliers: Vec<f64>,
}

impl UpdatedLu {
    /// Row-major storage (n × n, zeroed) for the current matrix.
    pub fn storage(&mut self, n: usize) -> &mut [f64] {
        if self.n != n {
            self.n = n;
            self.base_rows.clear();
            self.columns.clear();
        }
        self.matrix.clear();
        self.matrix.resize(n * n, 0.0);
        &mut self.matrix
    }

    /// Solve M x = b for the matrix written into [`UpdatedLu::storage`]; `b` becomes x.
    /// None if M is singular (a zero or non-finite pivot).
    pub fn solve(&mut self, b: &mut [f64]) -> Option<Route> {
        let n = self.n;
        self.scratch.resize(n, 0.0);
        if self.base_rows.len() == n * n {
            self.changed.clear();
            for r in 0..n {
                if self.matrix[r * n..(r + 1) * n] != self.base_rows[r * n..(r + 1) * n] {
                    self.changed.push(r);
                }
            }
            let k = self.changed.len();
            if (k as f64) <= MAX_CHANGED_FRACTION * n as f64 {
                self.y.clear();
                self.y.extend_from_slice(b);
                if self.update(k) && self.accurate(b) {
                    b.copy_from_slice(&self.y);
                    return Some(Route::Updated(k));
                }
            }
        }
        self.factorise()?;
        self.base.solve_in_place(b, &mut self.scratch);
        b.iter().all(|v| v.is_finite()).then_some(Route::Factorised)
    }

    /// Make the current matrix the base and factorise it.
    fn factorise(&mut self) -> Option<()> {
        let n = self.n;
        self.base.storage(n).copy_from_slice(&self.matrix);
        self.base_rows.clone_from(&self.matrix);
        self.columns.clear();
        self.columns.resize(n, None);
        self.base.factor_in_place().then_some(())
    }

    /// y ← M⁻¹ y by the correction of the base for the `k` changed rows; false if the
    /// capacitance matrix is singular.
    fn update(&mut self, k: usize) -> bool {
        let n = self.n;
        // The missing columns of Z in one blocked solve.
        let missing: Vec<usize> = self
            .changed
            .iter()
            .copied()
            .filter(|&r| self.columns[r].is_none())
            .collect();
        if !missing.is_empty() {
            let mut block = faer::Mat::<f64>::zeros(n, missing.len());
            for (j, &r) in missing.iter().enumerate() {
                block[(r, j)] = 1.0;
            }
            self.base.solve_columns_in_place(&mut block);
            for (j, &r) in missing.iter().enumerate() {
                self.columns[r] = Some(block.col(j).iter().copied().collect());
            }
        }
        self.base.solve_in_place(&mut self.y, &mut self.scratch);
        if k == 0 {
            return true;
        }
        let cap = self.capacitance.storage(k);
        self.multipliers.clear();
        let mut scale = 1.0f64;
        for (a, &ra) in self.changed.iter().enumerate() {
            // d_a = new row − old row, formed on the fly.
            let new = &self.matrix[ra * n..(ra + 1) * n];
            let old = &self.base_rows[ra * n..(ra + 1) * n];
            for (b, &rb) in self.changed.iter().enumerate() {
                let z = self.columns[rb].as_ref().expect("made above");
                let change = dot(new, z) - dot(old, z);
                scale = scale.max(change.abs());
                cap[a * k + b] = change + if a == b { 1.0 } else { 0.0 };
            }
            self.multipliers.push(dot(new, &self.y) - dot(old, &self.y));
        }
        // I + Dᵀ Z is singular exactly when M is; round-off leaves its pivot at ε times the
        // size of its terms instead of zero. 1e-12 of them counts as singular, and the
        // factorisation of M itself then decides.
        if !self.capacitance.factor_in_place() || self.capacitance.smallest_pivot() < 1e-12 * scale
        {
            return false;
        }
        self.capacitance
            .solve_in_place(&mut self.multipliers, &mut self.scratch[..k]);
        for (&r, &mu) in self.changed.iter().zip(&self.multipliers) {
            let z = self.columns[r].as_ref().expect("made above");
            for (yi, zi) in self.y.iter_mut().zip(z) {
                *yi -= mu * zi;
            }
        }
        self.y.iter().all(|v| v.is_finite())
    }

    /// Whether x = `self.y` solves the current system to [`ACCEPTED_RESIDUAL`].
    fn accurate(&self, b: &[f64]) -> bool {
        let n = self.n;
        let (mut residual, mut norm) = (0.0f64, 0.0f64);
        for (row, b_r) in self.matrix.chunks_exact(n).zip(b) {
            residual = residual.max((dot(row, &self.y) - b_r).abs());
            norm = norm.max(row.iter().map(|v| v.abs()).sum());
        }
        let x = self.y.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let scale = norm * x + b.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        residual <= ACCEPTED_RESIDUAL * scale.max(f64::MIN_POSITIVE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matrix(n: usize, shift: f64) -> Vec<f64> {
        (0..n * n)
            .map(|e| {
                let (i, j) = (e / n, e % n);
                if i == j {
                    8.0 + shift
                } else {
                    ((5 * i + 3 * j) % 7) as f64 / 7.0 - 0.45
                }
            })
            .collect()
    }

    fn residual(m: &[f64], x: &[f64], b: &[f64]) -> f64 {
        let n = b.len();
        (0..n)
            .map(|r| (dot(&m[r * n..(r + 1) * n], x) - b[r]).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn a_few_changed_rows_are_solved_by_the_update_and_exactly() {
        // Well-conditioned 20 × 20 systems: both routes solve to round-off, 1e-12 of |b| ~ 1.
        let n = 20;
        let base = matrix(n, 0.0);
        let b: Vec<f64> = (0..n).map(|i| (i as f64).cos()).collect();
        let mut solver = UpdatedLu::default();
        solver.storage(n).copy_from_slice(&base);
        let mut x = b.clone();
        assert_eq!(solver.solve(&mut x), Some(Route::Factorised));
        assert!(residual(&base, &x, &b) < 1e-12);
        // Rows 3 and 11 replaced (a point entering contact: its row becomes another one).
        let mut changed = base.clone();
        for j in 0..n {
            changed[3 * n + j] = if j == 3 { 1.0 } else { 0.0 };
            changed[11 * n + j] = (j as f64 * 0.3).sin();
        }
        changed[11 * n + 11] += 6.0;
        solver.storage(n).copy_from_slice(&changed);
        let mut x = b.clone();
        assert_eq!(solver.solve(&mut x), Some(Route::Updated(2)));
        assert!(residual(&changed, &x, &b) < 1e-12);
        // Back to the base: nothing changed, the base's own solve.
        solver.storage(n).copy_from_slice(&base);
        let mut x = b.clone();
        assert_eq!(solver.solve(&mut x), Some(Route::Updated(0)));
        assert!(residual(&base, &x, &b) < 1e-12);
        // Every row changed: a new factorisation.
        let shifted = matrix(n, 1.0);
        solver.storage(n).copy_from_slice(&shifted);
        let mut x = b.clone();
        assert_eq!(solver.solve(&mut x), Some(Route::Factorised));
        assert!(residual(&shifted, &x, &b) < 1e-12);
    }

    #[test]
    fn a_change_that_makes_the_matrix_singular_is_reported() {
        // Row 1 replaced by a copy of row 0: singular. The capacitance matrix is then singular
        // too (or its correction fails the residual), and the factorisation says so.
        let n = 6;
        let base = matrix(n, 0.0);
        let mut solver = UpdatedLu::default();
        solver.storage(n).copy_from_slice(&base);
        let mut x = vec![1.0; n];
        assert!(solver.solve(&mut x).is_some());
        let mut singular = base.clone();
        let (first, rest) = singular.split_at_mut(n);
        rest[..n].copy_from_slice(first);
        solver.storage(n).copy_from_slice(&singular);
        let mut x = vec![1.0; n];
        assert_eq!(solver.solve(&mut x), None);
    }
}
