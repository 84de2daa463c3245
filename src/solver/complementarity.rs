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

use crate::capacitance::{block_maxima, Capacitance};
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
    Ready(Box<FullFactor>),
}

/// The all-active factorisation and what bounds the residual of a solve with it (see
/// [`ContactSolver::solve_pressures_into`]).
struct FullFactor {
    lu: DenseLu,
    /// Per block of unknowns (the N forces, then each rigid unknown): the row sums of
    /// Pᵀ|L||U| ([`DenseLu::abs_factor_row_sums`]).
    factor_rows: Vec<Vec<f64>>,
    /// Per block, the row sums of |K|.
    matrix_rows: Vec<Vec<f64>>,
    /// max_i |K_ij| of each column j.
    column_max: Vec<f64>,
}

/// How the last reduced system was solved.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Route {
    /// With the all-active factorisation (every point in contact).
    Full,
    /// With its capacitance correction.
    Corrected,
    /// With the reduced system's own factorisation.
    Reduced,
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

/// Build and factorise the reduced system [A_II R_I S; S E_I 0] of the points `index` into
/// `lu` (S = diag `scale`, see [`ContactSolver::rigid_scale`]); false if it is singular.
fn reduced_system(
    lu: &mut DenseLu,
    a: &[f64],
    e: &[f64],
    r: &[f64],
    scale: &[f64],
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
        for (o, (v, s)) in out[na..]
            .iter_mut()
            .zip(r[i * m..(i + 1) * m].iter().zip(scale))
        {
            *o = v * s;
        }
    }
    for k in 0..m {
        for (col, &j) in index.iter().enumerate() {
            mat[(na + k) * size + col] = e[k * n + j] * scale[k];
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
    ///   error analysis of LU with pivoting, [`DenseLu::abs_factor_row_sums`]), so
    ///   |d_i| = |(K x̂ − b)_i| ≤ γ_3n Σ_b (Pᵀ|L||U| 1_b)_i max_{j in b} |x̂_j|, the blocks b
    ///   being the forces and each rigid unknown (whose scales differ by orders of
    ///   magnitude). A factorisation with large growth shows in the row sums.
    /// - *the capacitance correction* (a few points out of contact): the residual is an
    ///   exact sum of backward errors of the solves with K, the rounding of the sum
    ///   x₀ + Σ μ_i z_i and the leftovers set to zero ([`Capacitance::terms`]); the points
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
            if bounded && self.route != Route::Reduced {
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
        self.finish(direction, out, &mut info, false);
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
                &self.rigid_scale,
                &all,
                (self.n, self.m),
            );
            self.factors[0].full[dir] = if ok {
                Full::Ready(Box::new(self.full_factor(lu, dir)))
            } else {
                Full::Singular
            };
        }
        matches!(self.factors[0].full[dir], Full::Ready(_))
    }

    /// The all-active factorisation `lu` of direction `dir` with what bounds the residuals
    /// of solves with it: O(N²) once per factorisation.
    // Each row i fills entry i of several per-block arrays: an index reads best.
    #[allow(clippy::needless_range_loop)]
    fn full_factor(&self, lu: DenseLu, dir: usize) -> FullFactor {
        let (n, m) = (self.n, self.m);
        let size = n + m;
        let blocks = &self.blocks;
        let mut matrix_rows = vec![vec![0.0; size]; blocks.len()];
        let mut column_max = vec![0.0f64; size];
        // K = [A R; E 0]: rows of A and R, then rows of E.
        for i in 0..n {
            let row = &self.a[dir][i * n..(i + 1) * n];
            matrix_rows[0][i] = row.iter().map(|v| v.abs()).sum();
            for (c, v) in column_max.iter_mut().zip(row) {
                *c = c.max(v.abs());
            }
            for k in 0..m {
                let v = (self.r[i * m + k] * self.rigid_scale[k]).abs();
                matrix_rows[1 + k][i] += v;
                column_max[n + k] = column_max[n + k].max(v);
            }
        }
        for k in 0..m {
            let (row, s) = (&self.e[dir][k * n..(k + 1) * n], self.rigid_scale[k]);
            matrix_rows[0][n + k] = row.iter().map(|v| (v * s).abs()).sum();
            for (c, v) in column_max.iter_mut().zip(row) {
                *c = c.max((v * s).abs());
            }
        }
        FullFactor {
            factor_rows: lu.abs_factor_row_sums(blocks),
            matrix_rows,
            column_max,
            lu,
        }
    }

    /// Bound the residual of each point's row after a solve by the all-active
    /// factorisation or its correction ([`ContactSolver::solve_pressures_into`]) into
    /// `self.bound`, and set the gaps of the points in contact to zero (the points out of
    /// contact keep the correction's multipliers).
    fn residual_bound(&mut self, direction: Direction, out: &mut ContactSolution) {
        let (n, dir) = (self.n, direction.index());
        let size = n + self.m;
        let factors = &self.factors[0];
        let Full::Ready(full) = &factors.full[dir] else {
            unreachable!("solved by the all-active factorisation")
        };
        let eps = f64::EPSILON / 2.0;
        let gamma = |k: usize| k as f64 * eps / (1.0 - k as f64 * eps);
        let g_solve = gamma(3 * size);
        let (scale, g_sum, leftover) = if self.route == Route::Full {
            // The factorised system's unknowns: the forces and S⁻¹λ.
            let mut x = out.force.clone();
            x.extend(out.rigid.iter().zip(&self.rigid_scale).map(|(l, s)| l / s));
            (block_maxima(&x, &self.blocks), 0.0, 0.0)
        } else {
            let terms = factors.correction[dir].terms();
            let leftover: f64 = self
                .inactive
                .iter()
                .zip(terms.leftover)
                .map(|(&i, t)| t.abs() * full.column_max[i])
                .sum();
            (terms.scale.to_vec(), gamma(terms.columns + 1), leftover)
        };
        for i in 0..n {
            let mut b = leftover;
            for (blk, s) in scale.iter().enumerate() {
                b += (g_solve * full.factor_rows[blk][i] + g_sum * full.matrix_rows[blk][i]) * s;
            }
            self.bound[i] = 2.0 * b;
            if out.active[i] {
                out.gap[i] = -self.penalty_compliance[i] * out.force[i];
            }
        }
    }

    fn active_set(
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
                if !(bounded && self.route != Route::Reduced) {
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
            self.rhs
                .extend(self.load.iter().zip(&self.rigid_scale).map(|(l, s)| -l * s));
            let factors = &mut self.factors[0];
            let Full::Ready(full) = &factors.full[dir] else {
                unreachable!("full_ready said regular")
            };
            let solved = if k == 0 {
                full.lu.solve_in_place(&mut self.rhs, &mut self.scratch);
                self.rhs.iter().all(|v| v.is_finite())
            } else {
                factors.correction[dir].solve(
                    &full.lu,
                    &self.inactive,
                    &self.blocks,
                    &mut self.rhs,
                    &mut out.gap,
                    &mut self.scratch,
                )
            };
            self.route = if k == 0 {
                Route::Full
            } else {
                Route::Corrected
            };
            if solved {
                out.force.copy_from_slice(&self.rhs[..n]);
                for (o, (v, s)) in out
                    .rigid
                    .iter_mut()
                    .zip(self.rhs[n..].iter().zip(&self.rigid_scale))
                {
                    *o = v * s;
                }
                // The cached reduced factorisation no longer belongs to the set in use.
                factors.cache[dir].valid = false;
                return true;
            }
        }
        self.route = Route::Reduced;
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
        self.rhs
            .extend(self.load.iter().zip(&self.rigid_scale).map(|(l, s)| -l * s));
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
        for (o, (v, s)) in out.rigid.iter_mut().zip(
            self.rhs[self.index.len()..size]
                .iter()
                .zip(&self.rigid_scale),
        ) {
            *o = v * s;
        }
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
            &self.rigid_scale,
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

    /// The residual check. With `bounded`, each point's gap is known only to lie within
    /// `self.bound` of `out.gap` ([`ContactSolver::solve_pressures_into`]): the
    /// complementarity is then its largest value over that interval (|min(p, d)| is
    /// monotone in d on either side of its zero, so an end of the interval).
    fn finish(
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

#[cfg(test)]
mod tests;
