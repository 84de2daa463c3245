//! The contact solve: the mixed linear complementarity problem
//! P ≥ 0, d = A_s P + R λ + g ≥ 0, Pᵀd = 0, E P + L = 0 (paper eq. 8, 42–43)
//! on the condensed contact points.
//!
//! The primary method is a primal–dual active-set (semismooth Newton) iteration warm-started
//! from the last active set of the same sliding direction; when the set does not change the
//! factorisation of the reduced system is reused and a solve is two triangular sweeps. If the
//! iteration cycles or the reduced system is singular, Lemke's method takes over. Lemke's
//! method always terminates; without friction (E = Rᵀ, A symmetric positive definite) it is
//! guaranteed to end at the solution. With friction A is not symmetric and the guarantee holds
//! only while friction is small enough for A to stay positive definite (μ below a bound set by
//! the elastic constants; the paper's μ = 0.3 is well inside it). Whatever method ends, the
//! residuals are checked and a solve that does not meet [`ACCEPTED_RESIDUAL`] is reported as
//! [`Status::Failed`] with its last iterate. The paper's penalty method is the same LCP with
//! the compliance 1/(c_n w_i t) added to the diagonal: the penetration is then −p/c_n instead
//! of zero.

use crate::capacitance::Capacitance;
use crate::contact::CondensedContact;
use crate::dense::{dot, DenseLu};
use crate::lemke::lemke;

mod types;
pub use types::{ContactSolution, Direction, Method, SolveInfo, Status};

/// Largest complementarity or equilibrium residual (relative, see [`SolveInfo`]) with which a
/// solve counts as [`Status::Solved`]. Exact solves reach 1e-13 or better on the paper's
/// mesh; the flexibility's condition number grows with refinement, and at 1025 contact points
/// (128 elements under the punch) round-off alone reaches 1e-8 in a wear step with a large
/// wear compliance. A wrong active set leaves a residual of order one, so 1e-6 still tells
/// the two apart by orders of magnitude.
pub const ACCEPTED_RESIDUAL: f64 = 1e-6;

struct Cached {
    active: Vec<bool>,
    lu: DenseLu,
    valid: bool,
}

impl Cached {
    fn empty() -> Cached {
        Cached {
            active: vec![],
            lu: DenseLu::default(),
            valid: false,
        }
    }
}

/// The all-active reduced system of one direction, factorised on first use.
enum Full {
    Unknown,
    Singular,
    Ready(DenseLu),
}

/// The factorisations that belong to one diagonal compliance (see
/// [`ContactSolver::set_compliance`]): per direction the last active set's, the all-active
/// one and its correction for a few points out of contact.
struct Factors {
    compliance: Vec<f64>,
    cache: [Cached; 2],
    full: [Full; 2],
    correction: [Capacitance; 2],
}

impl Factors {
    fn new(compliance: &[f64]) -> Factors {
        Factors {
            compliance: compliance.to_vec(),
            cache: [Cached::empty(), Cached::empty()],
            full: [Full::Unknown, Full::Unknown],
            correction: Default::default(),
        }
    }
}

/// How many compliances keep their factorisations: enough for the extrapolation factors of
/// a schedule (the paper's has three, an adaptive one climbs a ladder of powers of two).
const KEPT_COMPLIANCES: usize = 12;

/// Build and factorise the reduced system [A_II R_I; E_I 0] of the points `index` into `lu`;
/// false if it is singular.
fn reduced_system(
    lu: &mut DenseLu,
    a: &[f64],
    e: &[f64],
    r: &[f64],
    index: &[usize],
    (n, m): (usize, usize),
) -> bool {
    let na = index.len();
    let size = na + m;
    let mat = lu.storage(size);
    for (row, &i) in index.iter().enumerate() {
        let (a_row, out) = (
            &a[i * n..(i + 1) * n],
            &mut mat[row * size..(row + 1) * size],
        );
        for (col, &j) in index.iter().enumerate() {
            out[col] = a_row[j];
        }
        out[na..].copy_from_slice(&r[i * m..(i + 1) * m]);
    }
    for k in 0..m {
        for (col, &j) in index.iter().enumerate() {
            mat[(na + k) * size + col] = e[k * n + j];
        }
    }
    lu.factor_in_place()
}

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
    /// Most active-set iterations before Lemke's method takes over.
    pub max_iterations: usize,
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
            r: contact.rigid_gap_matrix(),
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
                Factors::new(compliance)
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
        if self.method != Method::Lemke && self.active_set(gap, direction, out, &mut info) {
            info.status = Status::Solved;
            self.finish(direction, out, &mut info);
            if info.status == Status::Solved {
                return info;
            }
            // The low-rank correction can lose what the reduced system's own factorisation
            // keeps when K is far worse conditioned than the reduced system: try without.
            self.correct = false;
            let direct = self.active_set(gap, direction, out, &mut info);
            self.correct = true;
            if direct {
                info.status = Status::Solved;
                self.finish(direction, out, &mut info);
                if info.status == Status::Solved {
                    return info;
                }
            }
        }
        self.lemke_solve(gap, direction, out, &mut info);
        self.finish(direction, out, &mut info);
        info
    }

    /// Convenience wrapper of [`ContactSolver::solve_into`] that allocates the solution.
    pub fn solve(&mut self, gap: &[f64], direction: Direction) -> (ContactSolution, SolveInfo) {
        let mut out = ContactSolution::default();
        let info = self.solve_into(gap, direction, &mut out);
        (out, info)
    }

    /// Make sure the all-active system of `dir` is factorised; whether it is regular.
    fn full_ready(&mut self, dir: usize) -> bool {
        if let Full::Unknown = self.factors[0].full[dir] {
            let all: Vec<usize> = (0..self.n).collect();
            let mut lu = DenseLu::default();
            let ok = reduced_system(
                &mut lu,
                &self.a[dir],
                &self.e[dir],
                &self.r,
                &all,
                (self.n, self.m),
            );
            self.factors[0].full[dir] = if ok { Full::Ready(lu) } else { Full::Singular };
        }
        matches!(self.factors[0].full[dir], Full::Ready(_))
    }

    fn active_set(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
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
                self.compute_gap(gap, dir, out);
                self.factors[0].cache[dir]
                    .active
                    .copy_from_slice(&out.active);
                return true;
            }
        }
        false
    }

    /// P and λ of the reduced system of the active set `out.active`, and the gaps of the
    /// points out of contact (the others' are zero by construction; [`Self::compute_gap`]
    /// recomputes all of them once the set is final). False if the reduced system is
    /// singular.
    fn solve_reduced(
        &mut self,
        gap: &[f64],
        dir: usize,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
    ) -> bool {
        let (n, m) = (self.n, self.m);
        self.inactive.clear();
        self.inactive.extend((0..n).filter(|&i| !out.active[i]));
        let k = self.inactive.len();
        let full_regular = self.full_ready(dir);
        if full_regular && (k == 0 || (self.correct && Capacitance::applies(k, n))) {
            self.rhs.clear();
            self.rhs.extend(gap.iter().map(|g| -g));
            self.rhs.extend(self.load.iter().map(|l| -l));
            let factors = &mut self.factors[0];
            let Full::Ready(full) = &factors.full[dir] else {
                unreachable!("full_ready said regular")
            };
            let solved = if k == 0 {
                full.solve_in_place(&mut self.rhs, &mut self.scratch);
                self.rhs.iter().all(|v| v.is_finite())
            } else {
                factors.correction[dir].solve(
                    full,
                    &self.inactive,
                    &mut self.rhs,
                    &mut out.gap,
                    &mut self.scratch,
                )
            };
            if solved {
                out.force.copy_from_slice(&self.rhs[..n]);
                out.rigid.copy_from_slice(&self.rhs[n..n + m]);
                // The cached reduced factorisation no longer belongs to the set in use.
                factors.cache[dir].valid = false;
                return true;
            }
        }
        let cached = &self.factors[0].cache[dir];
        if !cached.valid || cached.active != out.active {
            let active = std::mem::take(&mut out.active);
            self.factorise(dir, &active);
            out.active = active;
            info.factorisations += 1;
            if !self.factors[0].cache[dir].valid {
                return false;
            }
        }
        // Right-hand side [−g_A; −L] and solve.
        self.index.clear();
        self.index.extend((0..n).filter(|&i| out.active[i]));
        self.rhs.clear();
        self.rhs.extend(self.index.iter().map(|&i| -gap[i]));
        self.rhs.extend(self.load.iter().map(|l| -l));
        let size = self.index.len() + m;
        self.factors[0].cache[dir]
            .lu
            .solve_in_place(&mut self.rhs, &mut self.scratch[..size]);
        if self.rhs.iter().any(|v| !v.is_finite()) {
            return false;
        }
        out.force.iter_mut().for_each(|f| *f = 0.0);
        for (k, &i) in self.index.iter().enumerate() {
            out.force[i] = self.rhs[k];
        }
        out.rigid.copy_from_slice(&self.rhs[self.index.len()..size]);
        for &i in &self.inactive {
            out.gap[i] = self.gap_at(gap, dir, out, i);
        }
        true
    }

    /// One active-set update: keep a point whose force is not negative, add one that
    /// penetrates (the gap is compared as a force, d/A_ii, so that both tests share one
    /// scale). Whether the set changed.
    fn update_active(&self, out: &mut ContactSolution) -> bool {
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

    /// Build and factorise the reduced system [A_AA R_A; E_A 0] for active set `active`.
    fn factorise(&mut self, dir: usize, active: &[bool]) {
        self.index.clear();
        self.index.extend((0..self.n).filter(|&i| active[i]));
        let cache = &mut self.factors[0].cache[dir];
        cache.valid = reduced_system(
            &mut cache.lu,
            &self.a[dir],
            &self.e[dir],
            &self.r,
            &self.index,
            (self.n, self.m),
        );
        cache.active.clear();
        cache.active.extend_from_slice(active);
    }

    /// d = A_s P + R λ + g at every point (the penalty compliance excluded: d is the true
    /// gap).
    fn compute_gap(&self, gap: &[f64], dir: usize, out: &mut ContactSolution) {
        for i in 0..self.n {
            out.gap[i] = self.gap_at(gap, dir, out, i);
        }
    }

    /// d_i = (A_s P + R λ + g)_i − c_i P_i (c the penalty compliance).
    fn gap_at(&self, gap: &[f64], dir: usize, out: &ContactSolution, i: usize) -> f64 {
        let (n, m) = (self.n, self.m);
        let row = &self.a[dir][i * n..(i + 1) * n];
        gap[i] - self.penalty_compliance[i] * out.force[i]
            + dot(row, &out.force)
            + dot(&self.r[i * m..(i + 1) * m], &out.rigid)
    }

    fn lemke_solve(
        &mut self,
        gap: &[f64],
        direction: Direction,
        out: &mut ContactSolution,
        info: &mut SolveInfo,
    ) {
        // z = (P, λ⁺, λ⁻); M = [[A, R, −R], [−E, 0, 0], [E, 0, 0]], q = [g, −L, L]: with E = Rᵀ
        // (no friction) M is positive semi-definite, so Lemke's method finds the solution.
        let (n, m) = (self.n, self.m);
        let dir = direction.index();
        let size = n + 2 * m;
        let mut mm = vec![0.0; size * size];
        let mut q = vec![0.0; size];
        for i in 0..n {
            mm[i * size..i * size + n].copy_from_slice(&self.a[dir][i * n..(i + 1) * n]);
            for k in 0..m {
                mm[i * size + n + k] = self.r[i * m + k];
                mm[i * size + n + m + k] = -self.r[i * m + k];
            }
            q[i] = gap[i];
        }
        for k in 0..m {
            for j in 0..n {
                mm[(n + k) * size + j] = -self.e[dir][k * n + j];
                mm[(n + m + k) * size + j] = self.e[dir][k * n + j];
            }
            q[n + k] = -self.load[k];
            q[n + m + k] = self.load[k];
        }
        match lemke(&mm, &q, 50 * size) {
            Ok(sol) => {
                info.lemke_pivots = sol.pivots;
                info.status = Status::Solved;
                out.force.copy_from_slice(&sol.z[..n]);
                for k in 0..m {
                    out.rigid[k] = sol.z[n + k] - sol.z[n + m + k];
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

    fn finish(&self, direction: Direction, out: &mut ContactSolution, info: &mut SolveInfo) {
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
        let a = &self.a[direction.index()];
        for i in 0..n {
            let d = out.gap[i] + self.penalty_compliance[i] * out.force[i];
            // A gap as a pressure through the point's own compliance, the wear's included: a
            // large wear compliance scales the round-off of d with it.
            let to_pressure = 1.0
                / (a[i * n + i].max(1.0 / self.gap_to_pressure[i] / self.area[i]) * self.area[i]);
            comp = comp.max(out.pressure[i].min(d * to_pressure).abs());
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

#[cfg(test)]
mod tests;
