//! The iterations of a contact solve: the primal–dual active-set steps, Lemke's method when
//! they cycle, and the residual check that decides whether a solve counts as solved.

use super::{ContactSolution, ContactSolver, Direction, SolveInfo, Status, ACCEPTED_RESIDUAL};
use crate::dense::dot;
use crate::lemke::lemke;

/// The indices from the first to the last non-zero force (empty if none is).
pub(super) fn force_span(force: &[f64]) -> std::ops::Range<usize> {
    match force.iter().position(|&f| f != 0.0) {
        Some(first) => first..force.iter().rposition(|&f| f != 0.0).expect("one is") + 1,
        None => 0..0,
    }
}

impl ContactSolver {
    pub(super) fn active_set(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
        bounded: bool,
    ) -> bool {
        let n = self.n;
        let dir = direction.index();
        if self.factors[0].cache[dir].active.len() != n {
            self.factors[0].cache[dir].active = vec![true; n];
            self.factors[0].cache[dir].valid = false;
        }
        out.active
            .copy_from_slice(&self.factors[0].cache[dir].active);
        for _ in 0..self.max_iterations {
            info.iterations += 1;
            if !self.solve_reduced(gap, dir, out, info) {
                return false;
            }
            if !self.update_active(out) {
                if !bounded || self.route.checks_every_gap() {
                    self.compute_gap(gap, dir, out);
                }
                self.factors[0].cache[dir]
                    .active
                    .copy_from_slice(&out.active);
                return true;
            }
        }
        false
    }

    /// One active-set update: keep a point whose force is not negative, add one that
    /// penetrates (the gap is compared as a force, d/A_ii, so that both tests share one
    /// scale). Whether the set changed.
    pub(super) fn update_active(&self, out: &mut ContactSolution) -> bool {
        let force_scale = out.force.iter().fold(0.0f64, |a, f| a.max(f.abs()));
        let tolerance = 1e-13 * force_scale.max(1e-300);
        let mut changed = false;
        for i in 0..self.n {
            let now = if out.active[i] {
                out.force[i] >= -tolerance
            } else {
                out.gap[i] * self.gap_to_pressure[i] * self.area[i] < -tolerance
            };
            changed |= now != out.active[i];
            out.active[i] = now;
        }
        changed
    }

    /// d = A_s P + R λ + g at every point (the penalty compliance excluded: d is the true
    /// gap).
    pub(super) fn compute_gap(&self, gap: &[f64], dir: usize, out: &mut ContactSolution) {
        let span = force_span(&out.force);
        for i in 0..self.n {
            out.gap[i] = self.gap_at(gap, dir, out, i, span.clone());
        }
    }

    /// d_i = (A_s P + R λ + g)_i − c_i P_i (c the penalty compliance). `span` holds every
    /// non-zero force ([`force_span`]): A_s P is summed over it alone, so that a zone that
    /// covers a small part of a long contact edge (a pin's, early in its wear) costs its own
    /// length per gap, not the edge's.
    pub(super) fn gap_at(
        &self,
        gap: &[f64],
        dir: usize,
        out: &ContactSolution,
        i: usize,
        span: std::ops::Range<usize>,
    ) -> f64 {
        let (n, m) = (self.n, self.m);
        let row = &self.a[dir][i * n..(i + 1) * n];
        gap[i] - self.penalty_compliance[i] * out.force[i]
            + dot(&row[span.clone()], &out.force[span])
            + dot(&self.r[i * m..(i + 1) * m], &out.rigid)
    }

    pub(super) fn lemke_solve(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
    ) {
        // z = (P, λ⁺, λ⁻); M = [[A, R, −R], [−E, 0, 0], [E, 0, 0]], q = [g, −L, L]: with E = Rᵀ
        // (no friction) M is positive semi-definite, so Lemke's method finds the solution in
        // exact arithmetic. The plate's motions are scaled, λ_k = s_k λ'_k (D M D, D q with
        // D = diag(1, s, s) keep the complementarity), so that the columns s_k R_k are of
        // the size of A's: unscaled, R (mm per mm or rad) is 1e6 or more times A (mm per N),
        // A's entries fell below the pivot tolerances, and the path depended on the units
        // (red team 16: 0.8 % of solvable shapes failed under a rotating plate, 5 times more
        // on the model scaled by 7).
        let (n, m) = (self.n, self.m);
        let dir = direction.index();
        let size = n + 2 * m;
        let a_scale = self.a[dir].iter().fold(0.0f64, |s, v| s.max(v.abs()));
        let scale: Vec<f64> = (0..m)
            .map(|k| {
                let r_scale = (0..n).fold(0.0f64, |s, i| s.max(self.r[i * m + k].abs()));
                if r_scale > 0.0 && a_scale > 0.0 {
                    a_scale / r_scale
                } else {
                    1.0
                }
            })
            .collect();
        let mut mm = vec![0.0; size * size];
        let mut q = vec![0.0; size];
        for i in 0..n {
            mm[i * size..i * size + n].copy_from_slice(&self.a[dir][i * n..(i + 1) * n]);
            for k in 0..m {
                mm[i * size + n + k] = scale[k] * self.r[i * m + k];
                mm[i * size + n + m + k] = -scale[k] * self.r[i * m + k];
            }
            q[i] = gap[i];
        }
        for k in 0..m {
            for j in 0..n {
                mm[(n + k) * size + j] = -scale[k] * self.e[dir][k * n + j];
                mm[(n + m + k) * size + j] = scale[k] * self.e[dir][k * n + j];
            }
            q[n + k] = -scale[k] * self.load[k];
            q[n + m + k] = scale[k] * self.load[k];
        }
        match lemke(&mm, &q, 50 * size) {
            Ok(sol) => {
                info.lemke_pivots = sol.pivots;
                info.status = Status::Solved;
                out.force.copy_from_slice(&sol.z[..n]);
                for (k, s) in scale.iter().enumerate() {
                    out.rigid[k] = s * (sol.z[n + k] - sol.z[n + m + k]);
                }
                for i in 0..n {
                    out.active[i] = out.force[i] > 0.0;
                }
                let cache = &mut self.factors[0].cache[dir];
                cache.active.clear();
                cache.active.extend_from_slice(&out.active);
                cache.valid = false;
            }
            Err(_) => info.status = Status::Failed,
        }
        self.compute_gap(gap, dir, out);
    }

    /// The residual check. With `bounded`, each point's gap is known only to lie within
    /// `self.bound` of `out.gap` ([`ContactSolver::solve_pressures_into`]): the
    /// complementarity is then its largest value over that interval (|min(p, d)| is
    /// monotone in d on either side of its zero, so an end of the interval).
    pub(super) fn finish(
        &self,
        direction: Direction,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
        bounded: bool,
    ) {
        let (n, m) = (self.n, self.m);
        for i in 0..n {
            out.pressure[i] = out.force[i] / self.area[i];
        }
        let peak = out
            .pressure
            .iter()
            .fold(0.0f64, |a, p| a.max(p.abs()))
            .max(1e-300);
        let mut comp = 0.0f64;
        let (base, compliance) = (
            &self.base_diagonal[direction.index()],
            &self.factors[0].compliance,
        );
        for i in 0..n {
            let d = out.gap[i] + self.penalty_compliance[i] * out.force[i];
            // A gap as a pressure through the point's own compliance, the wear's included: a
            // large wear compliance scales the round-off of d with it. A_s's diagonal is
            // base + compliance, as `set_compliance` wrote it (read from here rather than
            // from A_s, whose diagonal is one cache line per point).
            let diagonal = base[i] + compliance[i];
            let to_pressure =
                1.0 / (diagonal.max(1.0 / self.gap_to_pressure[i] / self.area[i]) * self.area[i]);
            if bounded {
                let b = self.bound[i];
                comp = comp
                    .max(out.pressure[i].min((d - b) * to_pressure).abs())
                    .max(out.pressure[i].min((d + b) * to_pressure).abs());
            } else {
                comp = comp.max(out.pressure[i].min(d * to_pressure).abs());
            }
        }
        info.complementarity = comp / peak;
        let e = &self.e[direction.index()];
        let mut eq = 0.0f64;
        let mut scale = 0.0f64;
        for k in 0..m {
            let s: f64 = (0..n).map(|j| e[k * n + j] * out.force[j]).sum();
            eq = eq.max((s + self.load[k]).abs());
            scale = scale.max(self.load[k].abs()).max(
                (0..n)
                    .map(|j| (e[k * n + j] * out.force[j]).abs())
                    .sum::<f64>(),
            );
        }
        info.equilibrium = if m == 0 { 0.0 } else { eq / scale.max(1e-300) };
        // A method that claims success is trusted only if the residuals say so: Lemke's
        // pivoting can end on a ray or lose accuracy on an ill-conditioned tableau.
        let accurate = info.complementarity <= ACCEPTED_RESIDUAL
            && info.equilibrium <= ACCEPTED_RESIDUAL
            && out.pressure.iter().all(|p| p.is_finite())
            && out.rigid.iter().all(|r| r.is_finite());
        if !accurate {
            info.status = Status::Failed;
        }
    }
}
