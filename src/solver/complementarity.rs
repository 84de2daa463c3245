//! The contact solve: the mixed linear complementarity problem
//! P ≥ 0, d = A_s P + R λ + g ≥ 0, Pᵀd = 0, E P + L = 0 (paper eq. 8, 42–43)
//! on the condensed contact points.
//!
//! The primary method is a primal–dual active-set (semismooth Newton) iteration warm-started
//! from the last active set of the same sliding direction; when the set does not change the
//! factorisation of the reduced system is reused and a solve is two triangular sweeps. If the
//! iteration cycles or the reduced system is singular, Lemke's method takes over. In exact
//! arithmetic Lemke's method ends at the solution without friction (E = Rᵀ, A symmetric
//! positive definite: M is copositive-plus), and with friction while A stays positive definite
//! and the moment row allows it. In floating point it does not always: the plate's motions
//! are split into λ⁺ − λ⁻ (two opposite columns) and are scaled to A's size in the tableau
//! (`lemke_solve`); on random worn shapes under a rotating plate it then still failed in 53
//! of 112 000 solvable cases (919 unscaled; 52 of them at μ = 0.8, none without friction),
//! while the active set failed on none and fell back to Lemke in 2 % (red team 16,
//! docs/validation.md). Whatever method ends, the residuals are checked and a solve that does not meet [`ACCEPTED_RESIDUAL`] is reported as
//! [`Status::Failed`] with its last iterate. The paper's penalty method is the same LCP with
//! the compliance 1/(c_n w_i t) added to the diagonal: the penetration is then −p/c_n instead
//! of zero.

use crate::contact::CondensedContact;

mod iteration;
mod reduced;
mod types;
use reduced::{Factors, Route, KEPT_COMPLIANCES};
pub use types::{ContactSolution, Direction, Method, SolveInfo, Status};

/// Largest complementarity or equilibrium residual (relative, see [`SolveInfo`]) with which a
/// solve counts as [`Status::Solved`]. Exact solves reach 1e-13 or better on the paper's
/// mesh; the flexibility's condition number grows with refinement, and at 1025 contact points
/// (128 elements under the punch) round-off alone reaches 1e-8 in a wear step with a large
/// wear compliance. A wrong active set leaves a residual of order one, so 1e-6 still tells
/// the two apart by orders of magnitude.
pub const ACCEPTED_RESIDUAL: f64 = 1e-6;

/// A reusable solver for one condensed contact problem.
pub struct ContactSolver {
    n: usize,
    m: usize,
    method: Method,
    /// A_s per direction (with the penalty compliance and the current diagonal compliance on
    /// the diagonal), row-major N × N.
    a: [Vec<f64>; 2],
    /// The diagonal of A_s with the penalty compliance only, per direction.
    base_diagonal: [Vec<f64>; 2],
    /// E per direction, row-major m × N.
    e: [Vec<f64>; 2],
    /// R, row-major N × m.
    r: Vec<f64>,
    load: Vec<f64>,
    /// Converts a gap at point i into a pressure: 1/(A_nn(i,i) w_i t).
    gap_to_pressure: Vec<f64>,
    penalty_compliance: Vec<f64>,
    area: Vec<f64>,
    /// Factorisations per diagonal compliance, the current one first.
    factors: Vec<Factors>,
    rhs: Vec<f64>,
    scratch: Vec<f64>,
    index: Vec<usize>,
    inactive: Vec<usize>,
    /// Whether a solve may use the low-rank correction of the all-active factorisation
    /// (cleared for the retry of a solve whose corrected result missed the residuals).
    correct: bool,
    /// How the last reduced system was solved.
    route: Route,
    /// The first unknown of each block over which the residual bound measures x: 0 (the
    /// forces), then N, N + 1, … (each rigid unknown).
    blocks: Vec<usize>,
    /// A bound on each point's residual (see [`ContactSolver::solve_pressures_into`]).
    bound: Vec<f64>,
    /// Powers of two s_k that scale the rigid unknowns: the factorised systems are
    /// [A R S; S E 0] [P; S⁻¹λ] = [−g; −S L]. R and E have entries of order one (and the
    /// lever arms, mm), A of order 1e-5 mm/N: unscaled, partial pivoting takes E's rows as
    /// pivots for the force columns and the factors' |L||U| exceeds |K| by orders of
    /// magnitude, which spoils the residual bound. Scaled so that R S is of the order of
    /// A's diagonal it does not; powers of two make the scaling exact.
    rigid_scale: Vec<f64>,
    /// Most active-set iterations before Lemke's method takes over.
    pub max_iterations: usize,
    /// Points on the axis of a body of revolution, whose pressure is read from their
    /// neighbours' ([`crate::contact::AxisPoint`]).
    axis_points: Vec<crate::contact::AxisPoint>,
}

impl ContactSolver {
    /// Prepare the solver: the two direction-dependent matrices are formed once; the
    /// factorisations are made on first use and kept.
    pub fn new(contact: &CondensedContact, method: Method) -> ContactSolver {
        let n = contact.len();
        let m = contact.rigid_modes.len();
        let area = contact.areas();
        let penalty_compliance: Vec<f64> = match method {
            Method::Penalty { stiffness } => area.iter().map(|a| 1.0 / (stiffness * a)).collect(),
            _ => vec![0.0; n],
        };
        let make_a = |s: f64| {
            let mut a = contact.gap_matrix(s);
            for i in 0..n {
                a[i * n + i] += penalty_compliance[i];
            }
            a
        };
        let a = [make_a(1.0), make_a(-1.0)];
        let base_diagonal = [0, 1].map(|d| (0..n).map(|i| a[d][i * n + i]).collect());
        let gap_to_pressure = (0..n)
            .map(|i| 1.0 / (contact.a_nn[i * n + i] * area[i]))
            .collect();
        let r = contact.rigid_gap_matrix();
        let diagonal = (0..n).map(|i| a[0][i * n + i].abs()).sum::<f64>() / n.max(1) as f64;
        let rigid_scale = (0..m)
            .map(|k| {
                let largest = (0..n).fold(0.0f64, |acc, i| acc.max(r[i * m + k].abs()));
                let ratio = diagonal / largest;
                if ratio.is_finite() && ratio > 0.0 {
                    2f64.powi(ratio.log2().round() as i32)
                } else {
                    1.0
                }
            })
            .collect();
        ContactSolver {
            n,
            m,
            method,
            a,
            base_diagonal,
            e: [
                contact.equilibrium_matrix(1.0),
                contact.equilibrium_matrix(-1.0),
            ],
            r,
            load: contact.plate_load.clone(),
            gap_to_pressure,
            penalty_compliance,
            area,
            factors: vec![Factors::new(&vec![0.0; n])],
            rhs: Vec::with_capacity(n + m),
            scratch: vec![0.0; n + m],
            index: Vec::with_capacity(n),
            inactive: Vec::with_capacity(n),
            correct: true,
            axis_points: contact.axis_points.clone(),
            route: Route::Reduced,
            blocks: std::iter::once(0).chain(n..n + m).collect(),
            bound: vec![0.0; n],
            rigid_scale,
            max_iterations: 30 + n,
        }
    }

    /// Number of contact points.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Forget the warm-start active sets and factorisations (the next solve is a cold start).
    pub fn reset(&mut self) {
        for f in self.factors.iter_mut() {
            for c in f.cache.iter_mut() {
                c.active.clear();
                c.valid = false;
            }
        }
    }

    /// Whether the problem has no contact points.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Replace the plate's generalised load L (N, N·mm; one per rigid unknown): the coupled
    /// fretting cycle puts the tangential forces' share of the plate's equilibrium there. It
    /// enters the right-hand side only, so no factorisation changes.
    pub fn set_load(&mut self, load: &[f64]) {
        assert_eq!(load.len(), self.m, "one load per rigid unknown");
        self.load.copy_from_slice(load);
    }

    /// Add the diagonal compliance `compliance` (mm/N, one per point, ≥ 0) to A_s, so that the
    /// solve becomes d = (A_s + diag c) P + R λ + g. The wear step uses it: wear that is
    /// linear in the pressure, Δg_i = c_i P_i, is a compliance in series with the bodies'.
    /// The gap `d` returned then includes that wear. The factorisations of the last few
    /// compliances are kept, so that switching back and forth refactorises nothing.
    pub fn set_compliance(&mut self, compliance: &[f64]) {
        assert_eq!(compliance.len(), self.n, "one compliance per contact point");
        if self.factors[0].compliance == compliance {
            return;
        }
        let slot = match self.factors.iter().position(|f| f.compliance == compliance) {
            Some(k) => self.factors.remove(k),
            None => {
                self.factors.truncate(KEPT_COMPLIANCES - 1);
                let mut fresh = Factors::new(compliance);
                // The new compliance's first solve starts from the last solve's active set,
                // not from every point in contact: Newton's method for b ≠ 1 changes the
                // compliance at every iteration, and from all points in contact on a shape
                // worn 100 times deeper than the elastic gaps the primal–dual iteration
                // dropped the zone itself, ended on one point (a singular system) and left
                // every solve to Lemke's method, which then failed on a ray (a pinned
                // plate's load near one end, b = 2: the run stopped at the steady state).
                if let Some(last) = self.factors.first() {
                    for (cache, previous) in fresh.cache.iter_mut().zip(&last.cache) {
                        cache.active.clone_from(&previous.active);
                    }
                }
                fresh
            }
        };
        self.factors.insert(0, slot);
        let n = self.n;
        for (a, base) in self.a.iter_mut().zip(&self.base_diagonal) {
            for i in 0..n {
                a[i * n + i] = base[i] + compliance[i];
            }
        }
    }

    /// Solve for initial gap `gap` (mm, one per point) in sliding direction `direction`,
    /// writing into `out` (resized as needed; no allocation once sized).
    pub fn solve_into(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
    ) -> SolveInfo {
        self.solve_checked(gap, direction, out, false)
    }

    /// [`ContactSolver::solve_into`] for a caller that needs the pressures and the rigid
    /// motion, not the gaps of the points in contact: those are left at their exact value
    /// (zero; the penetration −P_i/(c_n w_i t) with the penalty method), the others are
    /// the solve's own. The same pressures, bit for bit; what it
    /// spares is the gap pass, N² operations that stream the N × N gap matrix once, as
    /// much as the solve itself.
    ///
    /// # Why the check is as safe
    ///
    /// The full pass serves the residual check: a solve is accepted only if
    /// |min(p_i, d_i)| (d_i the gap as a pressure) is at round-off for every point. Here
    /// d_i is not computed but bounded, rigorously, and the solve is accepted only if the
    /// check passes for *every* d_i within the bound; otherwise the gaps are computed and
    /// checked as by [`ContactSolver::solve_into`]. So a solve that the full check would
    /// reject is never accepted (up to the full check's own rounding, which is of the
    /// order of the bound's γ terms), and a solve the bound cannot vouch for costs what
    /// it did before. The bound applies to the two routes that solve with the all-active
    /// factorisation K:
    ///
    /// - *all points in contact*: the computed x̂ of K x = b satisfies (K + ΔK) x̂ = b with
    ///   |ΔK| ≤ γ_3n Pᵀ|L||U| for the computed factors, whatever their growth (backward
    ///   error analysis of LU with pivoting, [`crate::dense::DenseLu::abs_factor_row_sums`]), so
    ///   |d_i| = |(K x̂ − b)_i| ≤ γ_3n Σ_b (Pᵀ|L||U| 1_b)_i max_{j in b} |x̂_j|, the blocks b
    ///   being the forces and each rigid unknown (whose scales differ by orders of
    ///   magnitude). A factorisation with large growth shows in the row sums.
    /// - *the capacitance correction* (a few points out of contact): the residual is an
    ///   exact sum of backward errors of the solves with K, the rounding of the sum
    ///   x₀ + Σ μ_i z_i and the leftovers set to zero ([`crate::capacitance::Capacitance::terms`]); the points
    ///   out of contact get the multipliers μ_i as gaps, within the same bound. This is the
    ///   case the full pass was kept for: the correction loses accuracy when K is far worse
    ///   conditioned than the reduced system, which shows as large μ_i, z_i or leftovers,
    ///   so large a bound that the gaps are then computed and checked in full (and the
    ///   solve redone without the correction if they miss, as before).
    ///
    /// The computed bound is doubled against the rounding of its own evaluation and the
    /// second-order terms. The solves with a reduced system's own factorisation and by
    /// Lemke's method compute every gap as before.
    pub fn solve_pressures_into(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
    ) -> SolveInfo {
        self.solve_checked(gap, direction, out, true)
    }

    fn solve_checked(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        bounded: bool,
    ) -> SolveInfo {
        let info = self.solve_core(gap, direction, out, bounded);
        if info.status == Status::Solved {
            for axis in &self.axis_points {
                out.pressure[axis.point] = axis.pressure(&out.pressure);
            }
        }
        info
    }

    fn solve_core(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        bounded: bool,
    ) -> SolveInfo {
        let (n, m) = (self.n, self.m);
        out.pressure.resize(n, 0.0);
        out.force.resize(n, 0.0);
        out.gap.resize(n, 0.0);
        out.rigid.resize(m, 0.0);
        out.active.resize(n, true);
        let mut info = SolveInfo {
            status: Status::Failed,
            iterations: 0,
            factorisations: 0,
            lemke_pivots: 0,
            complementarity: f64::INFINITY,
            equilibrium: f64::INFINITY,
        };
        if self.method != Method::Lemke && self.active_set(gap, direction, out, &mut info, bounded)
        {
            info.status = Status::Solved;
            if bounded && !self.route.checks_every_gap() {
                self.residual_bound(direction, out);
                self.finish(direction, out, &mut info, true);
                if info.status == Status::Solved {
                    return info;
                }
                // The bound cannot vouch for the solve: check it in full.
                info.status = Status::Solved;
                self.compute_gap(gap, direction.index(), out);
            }
            self.finish(direction, out, &mut info, false);
            if info.status == Status::Solved {
                return info;
            }
            // The low-rank correction can lose what the reduced system's own factorisation
            // keeps when K is far worse conditioned than the reduced system: try without.
            self.correct = false;
            let direct = self.active_set(gap, direction, out, &mut info, false);
            self.correct = true;
            if direct {
                info.status = Status::Solved;
                self.finish(direction, out, &mut info, false);
                if info.status == Status::Solved {
                    return info;
                }
            }
        }
        self.lemke_solve(gap, direction, out, &mut info);
        if info.status == Status::Failed && out.force.iter().all(|f| f.is_finite()) {
            // Lemke's method failed and left the active set's last iterate in `out`, which
            // may already be the solution: the active set stops at its iteration limit when
            // it cycles between sets that differ only at a point with p ≈ 0 and d ≈ 0 (red
            // team 21: "failed" with residuals of 1e-12 quoted, at a run's steady state). The
            // residual check is the acceptance rule of every method: let it judge.
            info.status = Status::Solved;
        }
        self.finish(direction, out, &mut info, false);
        info
    }

    /// Convenience wrapper of [`ContactSolver::solve_into`] that allocates the solution.
    pub fn solve(&mut self, gap: &[f64], direction: Direction) -> (ContactSolution, SolveInfo) {
        let mut out = ContactSolution::default();
        let info = self.solve_into(gap, direction, &mut out);
        (out, info)
    }
}

#[cfg(test)]
mod tests;
