//! One Newton step of the steady state, by block elimination of the system's structure
//! instead of a dense factorisation of all its 3N + 3m unknowns.
//!
//! Most of the Newton matrix is identity or diagonal: each gap row has g_i with coefficient
//! 1; a point out of contact in a half cycle has P_h,i = given; a wear row couples only the
//! point's own pressures (diagonal slopes) and the rigid wear c. So
//!
//! 1. the pressures of points out of contact are known;
//! 2. each wear row gives one of its point's pressures (the one with the larger slope) in
//!    terms of the other one, if that is in contact too ("kept"), and of c;
//! 3. one gap row per point gives g_i (the first half in contact, or for a point out of
//!    contact throughout the closest half's row that stands in its wear row);
//! 4. what is left is a dense system in the kept pressures, λ and c: the other gap row of each
//!    point in contact in both halves (minus the row that gave g_i), the plate equilibria and
//!    the gauge. That is N + 3m unknowns instead of 3N + 3m: 1/27 of the factorisation.
//!
//! The step is checked by its residual in the whole system; if that fails (or a slope is
//! zero), the whole system is factorised instead, as before this elimination existed.

use super::System;
use crate::dense::{dot, DenseLu};
use crate::updated_lu::UpdatedLu;

/// Relative residual ‖M x − b‖∞ / (‖M‖∞ ‖x‖∞ + ‖b‖∞) of an accepted step: the same bound as
/// [`UpdatedLu`]'s updated solves (a backward-stable solve of the whole system leaves about
/// n ε).
const ACCEPTED_RESIDUAL: f64 = 1e-10;

/// The Newton matrix of one iteration, held by its structure.
pub(super) struct Jacobian<'s, 'a> {
    pub system: &'s System<'a>,
    pub active: &'s [Vec<bool>],
    /// ∂W/∂P_h,i (wear per unit force, per half and point) of the wear rows of points in
    /// contact in some half.
    pub slope: Vec<Vec<f64>>,
    /// For each point out of contact in every half, the half whose gap row stands in for its
    /// wear row (the closest one).
    pub closest: Vec<usize>,
    /// Whether the reduced unknown of a point in contact in both halves is its wear in the
    /// other half (a concave law, see [`Jacobian::pressures`]) rather than its pressure there.
    pub in_wear: bool,
}

/// Storage kept from one Newton iteration to the next.
#[derive(Default)]
pub(super) struct Workspace {
    /// The reduced system (kept pressures, λ, c): an iteration that changes no active set
    /// solves with the last factorisation.
    reduced: UpdatedLu,
    /// The whole system, for the fallback.
    whole: DenseLu,
}

/// Each pressure P_h,j as κ + β Q + Σ_k γ_k c_k, Q a reduced unknown (if any).
struct Pressures {
    /// κ, half-major (h n + j).
    kappa: Vec<f64>,
    /// γ_k per k, half-major (so that a row's coefficient of c_k is one dot product).
    gamma: Vec<Vec<f64>>,
    /// Per half, the pressures with a Q: (point, reduced unknown, β).
    kept: Vec<Vec<(usize, usize, f64)>>,
    /// Per reduced unknown Q, its point.
    points: Vec<usize>,
}

impl Jacobian<'_, '_> {
    /// Solve M x = b in place (b becomes x); None if M is singular.
    pub fn solve(&self, b: &mut [f64], work: &mut Workspace) -> Option<()> {
        if let Some(x) = self.eliminate(b, &mut work.reduced) {
            if self.accurate(&x, b) {
                b.copy_from_slice(&x);
                return Some(());
            }
        }
        let size = self.system.size();
        self.write_dense(work.whole.storage(size));
        if !work.whole.factor_in_place() {
            return None;
        }
        let mut scratch = vec![0.0; size];
        work.whole.solve_in_place(b, &mut scratch);
        Some(())
    }

    fn in_contact(&self, i: usize) -> bool {
        self.active.iter().any(|a| a[i])
    }

    /// The half and the row whose gap equation gives g_i.
    fn defining_row(&self, i: usize) -> (usize, usize) {
        let s = self.system;
        match (0..s.halves).find(|&h| self.active[h][i]) {
            Some(h) => (h, h * s.n + i),
            None => (self.closest[i], s.halves * (s.n + s.m) + i),
        }
    }

    /// Steps 1 and 2 of the module docs; None if a wear row has no usable pivot.
    fn pressures(&self, b: &[f64]) -> Option<Pressures> {
        let s = self.system;
        let (n, m, halves) = (s.n, s.m, s.halves);
        if halves > 2 {
            return None;
        }
        let mut p = Pressures {
            kappa: vec![0.0; halves * n],
            gamma: vec![vec![0.0; halves * n]; m],
            kept: vec![Vec::new(); halves],
            points: Vec::new(),
        };
        for j in 0..n {
            for h in (0..halves).filter(|&h| !self.active[h][j]) {
                p.kappa[h * n + j] = b[h * n + j];
            }
            if !self.in_contact(j) {
                continue;
            }
            let slope = |h: usize| self.slope[h][j];
            let pivot = (0..halves)
                .filter(|&h| self.active[h][j])
                .max_by(|&a, &c| slope(a).abs().total_cmp(&slope(c).abs()))?;
            let sp = slope(pivot);
            if sp == 0.0 || !sp.is_finite() {
                return None;
            }
            let mut r = b[halves * (n + m) + j];
            for h in (0..halves).filter(|&h| !self.active[h][j]) {
                r -= slope(h) * p.kappa[h * n + j];
            }
            p.kappa[pivot * n + j] = r / sp;
            for (k, gamma) in p.gamma.iter_mut().enumerate() {
                gamma[pivot * n + j] = -s.rigid[j * m + k] / sp;
            }
            if let Some(other) = (0..halves).find(|&h| h != pivot && self.active[h][j]) {
                let q = p.points.len();
                p.points.push(j);
                // For a concave law the unknown is the other half's wear s P, not P: at the end
                // of a zone the pressures fall to 1e-20 of the peak (b = 0.1: p = L(x)¹⁰) and
                // still wear a few % of the most, so a pressure solved to the round-off of the
                // peak would decide contact there by noise; the wear is solved to its own.
                let so = slope(other);
                if self.in_wear && so > 0.0 && so.is_finite() {
                    p.kept[other].push((j, q, so.recip()));
                    p.kept[pivot].push((j, q, -sp.recip()));
                } else {
                    p.kept[other].push((j, q, 1.0));
                    p.kept[pivot].push((j, q, -so / sp));
                }
            }
        }
        Some(p)
    }

    /// Add `scale` Σ_j a_j P_h,j to a reduced row (and its right-hand side `rhs`), the
    /// pressures substituted; `c0` is the column of c_0.
    fn add_pressure_terms(
        p: &Pressures,
        (h, scale, c0): (usize, f64, usize),
        a: &[f64],
        row: &mut [f64],
        rhs: &mut f64,
    ) {
        let n = a.len();
        *rhs -= scale * dot(a, &p.kappa[h * n..(h + 1) * n]);
        for (k, gamma) in p.gamma.iter().enumerate() {
            row[c0 + k] += scale * dot(a, &gamma[h * n..(h + 1) * n]);
        }
        for &(j, q, beta) in &p.kept[h] {
            row[q] += scale * a[j] * beta;
        }
    }

    /// Steps 1–4 and back substitution; None if the reduced system fails.
    fn eliminate(&self, b: &[f64], lu: &mut UpdatedLu) -> Option<Vec<f64>> {
        let s = self.system;
        let (n, m, halves) = (s.n, s.m, s.halves);
        let p = self.pressures(b)?;
        let nq = p.points.len();
        let size = nq + (halves + 1) * m;
        let (lambda0, c0) = (nq, nq + halves * m);
        let mut rhs = vec![0.0; size];
        let mat = lu.storage(size);
        // Differences of the two gap rows of each point in contact in both halves.
        for (q, &i) in p.points.iter().enumerate() {
            let (hd, rd) = self.defining_row(i);
            let row = &mut mat[q * size..(q + 1) * size];
            rhs[q] = b[(1 - hd) * n + i] - b[rd];
            for (h, sign) in [(1 - hd, 1.0), (hd, -1.0)] {
                let a = &s.gap[h][i * n..(i + 1) * n];
                Self::add_pressure_terms(&p, (h, sign, c0), a, row, &mut rhs[q]);
                for k in 0..m {
                    row[lambda0 + h * m + k] += sign * s.rigid[i * m + k];
                }
            }
        }
        for h in 0..halves {
            for k in 0..m {
                let r = nq + h * m + k;
                rhs[r] = b[halves * n + h * m + k];
                let a = &s.equilibrium[h][k * n..(k + 1) * n];
                let row = &mut mat[r * size..(r + 1) * size];
                Self::add_pressure_terms(&p, (h, 1.0, c0), a, row, &mut rhs[r]);
            }
        }
        self.gauge_rows(b, &p, &mut mat[(nq + halves * m) * size..], &mut rhs[c0..]);
        lu.solve(&mut rhs)?;
        Some(self.back_substitute(b, &p, &rhs))
    }

    /// The gauge rows Σ_i w_i R_ik g_i = b with g_i from its defining row (step 3).
    fn gauge_rows(&self, b: &[f64], p: &Pressures, rows: &mut [f64], rhs: &mut [f64]) {
        let s = self.system;
        let (n, m, halves) = (s.n, s.m, s.halves);
        let size = p.points.len() + (halves + 1) * m;
        let (lambda0, c0) = (p.points.len(), p.points.len() + halves * m);
        for k in 0..m {
            let row = &mut rows[k * size..(k + 1) * size];
            rhs[k] = b[halves * (n + m) + n + k];
            // −Σ_i w_ik A_hd(i)[i, :] per half, and the λ coefficients.
            let mut a = vec![vec![0.0; n]; halves];
            for i in 0..n {
                let w = s.area[i] * s.rigid[i * m + k];
                let (hd, rd) = self.defining_row(i);
                rhs[k] -= w * b[rd];
                for (acc, v) in a[hd].iter_mut().zip(&s.gap[hd][i * n..(i + 1) * n]) {
                    *acc -= w * v;
                }
                for l in 0..m {
                    row[lambda0 + hd * m + l] -= w * s.rigid[i * m + l];
                }
            }
            for (h, a) in a.iter().enumerate() {
                Self::add_pressure_terms(p, (h, 1.0, c0), a, row, &mut rhs[k]);
            }
        }
    }

    /// The whole step from the reduced solution `y` (kept pressures, λ, c).
    fn back_substitute(&self, b: &[f64], p: &Pressures, y: &[f64]) -> Vec<f64> {
        let s = self.system;
        let (n, m, halves) = (s.n, s.m, s.halves);
        let nq = p.points.len();
        let c = &y[nq + halves * m..];
        let mut x = vec![0.0; s.size()];
        for e in 0..halves * n {
            x[n + e] = p.kappa[e] + (0..m).map(|k| p.gamma[k][e] * c[k]).sum::<f64>();
        }
        for (h, kept) in p.kept.iter().enumerate() {
            for &(j, q, beta) in kept {
                x[n + h * n + j] += beta * y[q];
            }
        }
        x[n + halves * n..].copy_from_slice(&y[nq..]);
        for i in 0..n {
            let (hd, rd) = self.defining_row(i);
            let pressure = &x[n + hd * n..n + (hd + 1) * n];
            let lambda = &y[nq + hd * m..nq + (hd + 1) * m];
            let value = b[rd]
                - dot(&s.gap[hd][i * n..(i + 1) * n], pressure)
                - dot(&s.rigid[i * m..(i + 1) * m], lambda);
            x[i] = value;
        }
        x
    }

    /// The row of M (as (column, value) runs) applied to x, and the row's absolute sum.
    fn row_times(&self, row: usize, x: &[f64]) -> (f64, f64) {
        let s = self.system;
        let (n, m, halves) = (s.n, s.m, s.halves);
        let abs_sum = |v: &[f64]| v.iter().map(|a| a.abs()).sum::<f64>();
        let gap = |h: usize, i: usize| {
            let a = &s.gap[h][i * n..(i + 1) * n];
            let r = &s.rigid[i * m..(i + 1) * m];
            let value = x[i] + dot(a, &x[s.force(h, 0)..]) + dot(r, &x[s.lambda(h, 0)..]);
            (value, 1.0 + abs_sum(a) + abs_sum(r))
        };
        if row < halves * n {
            let (h, i) = (row / n, row % n);
            return if self.active[h][i] {
                gap(h, i)
            } else {
                (x[s.force(h, i)], 1.0)
            };
        }
        let row = row - halves * n;
        if row < halves * m {
            let (h, k) = (row / m, row % m);
            let e = &s.equilibrium[h][k * n..(k + 1) * n];
            return (dot(e, &x[s.force(h, 0)..]), abs_sum(e));
        }
        let row = row - halves * m;
        if row < n {
            let i = row;
            if !self.in_contact(i) {
                return gap(self.closest[i], i);
            }
            let r = &s.rigid[i * m..(i + 1) * m];
            let mut value = dot(r, &x[s.wear_motion(0)..]);
            let mut sum = abs_sum(r);
            for h in 0..halves {
                value += self.slope[h][i] * x[s.force(h, i)];
                sum += self.slope[h][i].abs();
            }
            return (value, sum);
        }
        let k = row - n;
        let (mut value, mut sum) = (0.0, 0.0);
        for (i, xi) in x[..n].iter().enumerate() {
            let w = s.area[i] * s.rigid[i * m + k];
            value += w * xi;
            sum += w.abs();
        }
        (value, sum)
    }

    /// Whether x solves M x = b to [`ACCEPTED_RESIDUAL`].
    fn accurate(&self, x: &[f64], b: &[f64]) -> bool {
        let (mut residual, mut norm) = (0.0f64, 0.0f64);
        for (row, &b_r) in b.iter().enumerate() {
            let (value, sum) = self.row_times(row, x);
            residual = residual.max((value - b_r).abs());
            norm = norm.max(sum);
        }
        let largest = |v: &[f64]| v.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let scale = norm * largest(x) + largest(b);
        // NaN fails the comparison: a broken step is redone by the factorisation.
        residual <= ACCEPTED_RESIDUAL * scale.max(f64::MIN_POSITIVE)
    }

    /// M, row-major, into `mat` (zeroed, size × size).
    fn write_dense(&self, mat: &mut [f64]) {
        let s = self.system;
        let (n, m, halves, size) = (s.n, s.m, s.halves, s.size());
        let gap_row = |out: &mut [f64], h: usize, i: usize| {
            out[i] = 1.0;
            out[s.force(h, 0)..s.force(h, 0) + n].copy_from_slice(&s.gap[h][i * n..(i + 1) * n]);
            out[s.lambda(h, 0)..s.lambda(h, 0) + m].copy_from_slice(&s.rigid[i * m..(i + 1) * m]);
        };
        let mut rows = mat.chunks_exact_mut(size);
        for h in 0..halves {
            for i in 0..n {
                let out = rows.next().expect("size rows");
                if self.active[h][i] {
                    gap_row(out, h, i);
                } else {
                    out[s.force(h, i)] = 1.0;
                }
            }
        }
        for h in 0..halves {
            for k in 0..m {
                let out = rows.next().expect("size rows");
                out[s.force(h, 0)..s.force(h, 0) + n]
                    .copy_from_slice(&s.equilibrium[h][k * n..(k + 1) * n]);
            }
        }
        for i in 0..n {
            let out = rows.next().expect("size rows");
            if !self.in_contact(i) {
                gap_row(out, self.closest[i], i);
                continue;
            }
            for h in 0..halves {
                out[s.force(h, i)] = self.slope[h][i];
            }
            for k in 0..m {
                out[s.wear_motion(k)] = s.rigid[i * m + k];
            }
        }
        for k in 0..m {
            let out = rows.next().expect("size rows");
            for (i, v) in out[..n].iter_mut().enumerate() {
                *v = s.area[i] * s.rigid[i * m + k];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A made-up well-conditioned system: 7 points, 2 rigid unknowns, both halves.
    fn system(load: &[f64]) -> System<'_> {
        let (n, m) = (7, 2);
        let entry = |seed: usize, i: usize, j: usize| {
            let v = ((seed * 31 + 7 * i + 3 * j) % 11) as f64 / 11.0 - 0.5;
            if i == j {
                4.0 + v
            } else {
                0.3 * v
            }
        };
        System {
            n,
            m,
            halves: 2,
            area: (0..n).map(|i| 1.0 + 0.1 * i as f64).collect(),
            gap: (0..2)
                .map(|h| (0..n * n).map(|e| entry(h + 1, e / n, e % n)).collect())
                .collect(),
            equilibrium: (0..2)
                .map(|h| {
                    (0..m * n)
                        .map(|e| -1.0 + entry(h + 5, e / n, e % n) * 0.1)
                        .collect()
                })
                .collect(),
            rigid: (0..n * m)
                .map(|e| {
                    if e % m == 0 {
                        -1.0
                    } else {
                        e as f64 / 7.0 - 1.0
                    }
                })
                .collect(),
            load,
            reference_pressure: 1.0,
            offset: Vec::new(),
        }
    }

    #[test]
    fn elimination_equals_the_dense_factorisation() {
        // Points in contact in both halves, in one, and in none (rows 5 and 6), with unequal
        // slopes (b ≠ 1): the reduced system and the whole one give the same step.
        let load = [3.0, 0.5];
        let s = system(&load);
        let active = vec![
            vec![true, true, false, true, true, false, false],
            vec![true, false, true, true, true, false, false],
        ];
        // The reduced unknowns as pressures, and as wears (a concave law's choice): the same.
        for in_wear in [false, true] {
            let jacobian = Jacobian {
                system: &s,
                active: &active,
                slope: vec![
                    (0..7).map(|i| 0.5 + 0.2 * i as f64).collect(),
                    (0..7).map(|i| 1.5 - 0.1 * i as f64).collect(),
                ],
                closest: vec![0, 0, 0, 0, 0, 1, 0],
                in_wear,
            };
            let b: Vec<f64> = (0..s.size()).map(|r| (r as f64 * 0.7).sin()).collect();
            let x = jacobian
                .eliminate(&b, &mut UpdatedLu::default())
                .expect("nonsingular");
            let mut whole = DenseLu::default();
            jacobian.write_dense(whole.storage(s.size()));
            assert!(whole.factor_in_place());
            let mut y = b.clone();
            whole.solve_in_place(&mut y, &mut vec![0.0; s.size()]);
            for (r, (a, c)) in x.iter().zip(&y).enumerate() {
                assert!(
                    (a - c).abs() < 1e-12 * (1.0 + c.abs()),
                    "{in_wear} {r}: {a} vs {c}"
                );
            }
            assert!(jacobian.accurate(&x, &b));
        }
    }
}
