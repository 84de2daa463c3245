//! The reduced systems [A_II R_I S; S E_I 0] of an active set I and their factorisations:
//! per diagonal compliance and sliding direction the last active set's, the all-active one
//! and its low-rank correction, and the bound on the residual of a solve with them.

use super::{ContactSolution, ContactSolver, Direction, SolveInfo};
use crate::capacitance::{block_maxima, Capacitance};
use crate::dense::DenseLu;

pub(super) struct Cached {
    /// The last solve's final active set: where the next solve starts.
    pub(super) active: Vec<bool>,
    /// The points whose reduced system `lu` holds (ascending): an active set padded with
    /// [`padding`] points on either side of each of its runs along the edge, so that a zone
    /// that grows or shrinks by a few points is solved with `lu` and a correction for the
    /// padding out of contact instead of a refactorisation.
    pub(super) base: Vec<usize>,
    pub(super) lu: DenseLu,
    pub(super) valid: bool,
    /// The correction of `lu` for the base's points out of contact (indices into `base`).
    correction: Capacitance,
    /// The first unknown of each block of `lu`'s system (the forces, each rigid unknown).
    blocks: Vec<usize>,
    /// The correction's multipliers (gaps of the base's points out of contact), by position
    /// in `base`; the gaps used are recomputed from the solution.
    multipliers: Vec<f64>,
    /// Positions in `base` of the points out of contact.
    local_inactive: Vec<usize>,
}

impl Cached {
    pub(super) fn empty() -> Cached {
        Cached {
            active: vec![],
            base: vec![],
            lu: DenseLu::default(),
            valid: false,
            correction: Capacitance::default(),
            blocks: vec![],
            multipliers: vec![],
            local_inactive: vec![],
        }
    }

    /// Whether `lu` can solve active set `active`: every point in contact is in the base,
    /// and the base's points out of contact are few enough for the correction (at most a
    /// third of the base, or twice the padding: the columns of the padding are made once per
    /// factorisation and kept).
    fn covers(&self, active: &[bool], padding: usize) -> bool {
        if !self.valid {
            return false;
        }
        let mut in_base = 0;
        let mut base = self.base.iter().peekable();
        for (i, &a) in active.iter().enumerate() {
            let member = base.next_if_eq(&&i).is_some();
            if a && !member {
                return false;
            }
            in_base += usize::from(a && member);
        }
        let out = self.base.len() - in_base;
        out <= (self.base.len() / 3).max(2 * padding)
    }
}

/// Points of padding on either side of each run of points in contact: an eighth of an
/// element's points at p = 8 … 1/32 of the edge, at least 8 (see [`Cached::base`]).
fn padding(n: usize) -> usize {
    (n / 32).max(8)
}

/// The all-active reduced system of one direction, factorised on first use.
pub(super) enum Full {
    Unknown,
    Singular,
    Ready(Box<FullFactor>),
}

/// The all-active factorisation and what bounds the residual of a solve with it (see
/// [`ContactSolver::solve_pressures_into`]).
pub(super) struct FullFactor {
    pub(super) lu: DenseLu,
    /// Per block of unknowns (the N forces, then each rigid unknown): the row sums of
    /// Pᵀ|L||U| ([`DenseLu::abs_factor_row_sums`]).
    pub(super) factor_rows: Vec<Vec<f64>>,
    /// Per block, the row sums of |K|.
    pub(super) matrix_rows: Vec<Vec<f64>>,
    /// max_i |K_ij| of each column j.
    pub(super) column_max: Vec<f64>,
}

/// How the last reduced system was solved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Route {
    /// With the all-active factorisation (every point in contact).
    Full,
    /// With its capacitance correction.
    Corrected,
    /// With the reduced system's own factorisation.
    Reduced,
    /// With the factorisation of a padded set's reduced system and its capacitance
    /// correction for the padding out of contact.
    Padded,
}

impl Route {
    /// Whether a solve by this route is checked by computing every gap (the residual bound
    /// of [`ContactSolver::solve_pressures_into`] covers the all-active routes only).
    pub(super) fn checks_every_gap(self) -> bool {
        matches!(self, Route::Reduced | Route::Padded)
    }
}

/// The factorisations that belong to one diagonal compliance (see
/// [`ContactSolver::set_compliance`]): per direction the last active set's, the all-active
/// one and its correction for a few points out of contact.
pub(super) struct Factors {
    pub(super) compliance: Vec<f64>,
    pub(super) cache: [Cached; 2],
    pub(super) full: [Full; 2],
    pub(super) correction: [Capacitance; 2],
}

impl Factors {
    pub(super) fn new(compliance: &[f64]) -> Factors {
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
pub(super) const KEPT_COMPLIANCES: usize = 12;

/// Build and factorise the reduced system [A_II R_I S; S E_I 0] of the points `index` into
/// `lu` (S = diag `scale`, see [`ContactSolver::rigid_scale`]); false if it is singular.
pub(super) fn reduced_system(
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

impl ContactSolver {
    /// Make sure the all-active system of `dir` is factorised; whether it is regular.
    pub(super) fn full_ready(&mut self, dir: usize) -> bool {
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
    pub(super) fn full_factor(&self, lu: DenseLu, dir: usize) -> FullFactor {
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
    pub(super) fn residual_bound(&mut self, direction: Direction, out: &mut ContactSolution) {
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

    /// P and λ of the reduced system of the active set `out.active`, and the gaps of the
    /// points out of contact (the others' are zero by construction; [`Self::compute_gap`]
    /// recomputes all of them once the set is final). False if the reduced system is
    /// singular.
    pub(super) fn solve_reduced(
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
        // Without the correction (the retry of a corrected solve that missed), the reduced
        // system of exactly the active set; so too with no more points in contact than rigid
        // unknowns, where the reduced system is singular by its structure: its own LU finds
        // an exact zero pivot, the correction only a small C that round-off leaves regular
        // (a tipping punch then iterated on garbage instead of stopping).
        let padded = self.correct && out.active.iter().filter(|&&a| a).count() > m;
        let usable = if padded {
            self.factors[0].cache[dir].covers(&out.active, padding(n))
        } else {
            let cached = &self.factors[0].cache[dir];
            cached.valid && cached.base.iter().all(|&i| out.active[i]) && {
                cached.base.len() == out.active.iter().filter(|&&a| a).count()
            }
        };
        if !usable {
            let active = std::mem::take(&mut out.active);
            self.factorise(dir, &active, padded);
            out.active = active;
            info.factorisations += 1;
            if !self.factors[0].cache[dir].valid {
                return false;
            }
        }
        // Right-hand side [−g_B; −L] over the base B and solve; the base's points out of
        // contact through the correction.
        let cache = &mut self.factors[0].cache[dir];
        self.rhs.clear();
        self.rhs.extend(cache.base.iter().map(|&i| -gap[i]));
        self.rhs
            .extend(self.load.iter().zip(&self.rigid_scale).map(|(l, s)| -l * s));
        let size = cache.base.len() + m;
        cache.local_inactive.clear();
        cache
            .local_inactive
            .extend((0..cache.base.len()).filter(|&k| !out.active[cache.base[k]]));
        if cache.local_inactive.is_empty() {
            cache
                .lu
                .solve_in_place(&mut self.rhs, &mut self.scratch[..size]);
        } else {
            self.route = Route::Padded;
            cache.multipliers.resize(cache.base.len(), 0.0);
            let solved = cache.correction.solve(
                &cache.lu,
                &cache.local_inactive,
                &cache.blocks,
                &mut self.rhs,
                &mut cache.multipliers,
                &mut self.scratch[..size],
            );
            if !solved {
                return false;
            }
        }
        if self.rhs.iter().any(|v| !v.is_finite()) {
            return false;
        }
        out.force.iter_mut().for_each(|f| *f = 0.0);
        self.index.clear();
        self.index.extend_from_slice(&cache.base);
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
        let span = super::iteration::force_span(&out.force);
        for &i in &self.inactive {
            out.gap[i] = self.gap_at(gap, dir, out, i, span.clone());
        }
        true
    }

    /// Build and factorise the reduced system [A_BB R_B; E_B 0] of the base B of active
    /// set `active`: the set padded along the edge ([`Cached::base`]) if `padded`, else or
    /// where the padded system is singular the set itself.
    pub(super) fn factorise(&mut self, dir: usize, active: &[bool], padded: bool) {
        let n = self.n;
        let exact: Vec<usize> = (0..n).filter(|&i| active[i]).collect();
        let mut bases = vec![exact.clone()];
        if padded {
            let pad = padding(n);
            let mut padded = vec![false; n];
            for &i in &exact {
                for flag in &mut padded[i.saturating_sub(pad)..(i + pad + 1).min(n)] {
                    *flag = true;
                }
            }
            let padded: Vec<usize> = (0..n).filter(|&i| padded[i]).collect();
            if padded.len() > exact.len() {
                bases.insert(0, padded);
            }
        }
        let cache = &mut self.factors[0].cache[dir];
        for base in bases {
            cache.valid = reduced_system(
                &mut cache.lu,
                &self.a[dir],
                &self.e[dir],
                &self.r,
                &self.rigid_scale,
                &base,
                (n, self.m),
            );
            cache.blocks.clear();
            cache.blocks.push(0);
            cache.blocks.extend(base.len()..base.len() + self.m);
            cache.base = base;
            cache.correction = Capacitance::default();
            if cache.valid {
                break;
            }
        }
        cache.active.clear();
        cache.active.extend_from_slice(active);
    }
}
