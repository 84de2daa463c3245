//! Stepping the reduced heat state: the modes of bodies at rest over alternating half periods
//! (closed-form gains, geometric sums over cycles), the propagators of a flowing body, and the
//! periodic (stationary) state of the steady state.

use super::{Dynamics, Propagator, Propagators, Sliding, ThermalModel};
use crate::complementarity::Direction;
use crate::conduction::reduced::{constant_gain, decay};
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, MatMut, MatRef, Par};
use std::sync::Arc;

/// Column `j` of an owned (column-major) matrix.
fn column(matrix: &Mat<f64>, j: usize) -> &[f64] {
    matrix
        .col(j)
        .try_as_col_major()
        .expect("an owned matrix's columns are contiguous")
        .as_slice()
}

/// The stationary state M a = g of a flowing body's coupled dynamics; None where M is
/// singular (a body that keeps its heat: no stationary temperature) or the solve is not
/// accurate to 1e-8 of g.
fn stationary(matrix: &Mat<f64>, g: &[f64]) -> Option<Vec<f64>> {
    use faer::linalg::solvers::Solve;
    let rhs = Mat::from_fn(g.len(), 1, |i, _| g[i]);
    let a = matrix.as_ref().partial_piv_lu().solve(&rhs);
    let residual = matrix * &a - &rhs;
    let scale = rhs.norm_l2().max(f64::MIN_POSITIVE);
    let finite = (0..g.len()).all(|i| a[(i, 0)].is_finite());
    (finite && residual.norm_l2() <= 1e-8 * scale)
        .then(|| (0..g.len()).map(|i| a[(i, 0)]).collect())
}

/// Σ_{i<m} e^{−λPi} = (1 − e^{−λPm})/(1 − e^{−λP}), for rate λ (1/s), period P (s): the sum
/// of m cycles' contributions; m for λ = 0.
fn geometric_sum(rate: f64, period: f64, m: usize) -> f64 {
    let one = (-rate * period).exp_m1();
    if one == 0.0 {
        m as f64
    } else {
        (-rate * period * m as f64).exp_m1() / one
    }
}

/// The temperature state of a run: modal coordinates and the last heat of each direction.
///
/// Under reciprocating sliding the heat is integrated in whole cycles of strictly alternating
/// half periods (see the module docs): `cycle` is the temperature at the start of the
/// current cycle (the start of a half period of the cycle's first direction), `a` the one
/// the run stands at now: the cycle's start, or after its first step the start of a half
/// period of the second direction.
#[derive(Clone, Debug)]
pub struct ThermalState {
    /// Modal coordinates of the temperature now.
    pub a: Vec<f64>,
    /// Modal coordinates at the start of the current cycle.
    cycle: Vec<f64>,
    /// Time heated so far, s.
    pub time: f64,
    /// The half-period increment g_d of each direction's last heat ('+', '−'; see
    /// [`ThermalModel::half_period_increment`]); None before any step of that direction.
    last_increment: [Option<Vec<f64>>; 2],
    /// Heat made by friction so far, mJ, and at the start of the current cycle.
    pub generated: f64,
    cycle_generated: f64,
    /// The time at the start of the current cycle, s.
    cycle_time: f64,
    /// The heat of one half period of each direction's last pressure, mJ.
    last_heat: [f64; 2],
    /// The k of the current cycle's first step.
    first_k: usize,
    scratch: Vec<f64>,
    /// Per number of alternating pairs m met so far (a few: the schedule's k repeat), each
    /// mode's decay over m cycles and its geometric sum ([`ThermalModel::alternate`]): two
    /// exponentials per mode and step otherwise.
    cycle_sums: Vec<(usize, Vec<[f64; 2]>)>,
}

/// How many pair counts [`ThermalState`] keeps the sums of: a schedule has a few k, and each
/// k two pair counts (its cycle's first step and the whole cycle).
const KEPT_SUMS: usize = 8;

impl ThermalModel {
    /// The state at the start of a run.
    pub fn start(&self) -> ThermalState {
        ThermalState {
            a: self.initial.clone(),
            cycle: self.initial.clone(),
            time: 0.0,
            last_increment: [None, None],
            generated: 0.0,
            cycle_generated: 0.0,
            cycle_time: 0.0,
            last_heat: [0.0; 2],
            first_k: 0,
            scratch: vec![0.0; self.modes()],
            cycle_sums: Vec::new(),
        }
    }

    /// Number of modes.
    pub fn modes(&self) -> usize {
        self.initial.len()
    }

    /// The rates and half-period gains of the modes. Only a body at rest has modes, and only
    /// monotonic sliding moves a body's material through the contact, so reciprocating
    /// sliding always finds them.
    fn modal(&self) -> (&[f64], &[(f64, f64, f64)]) {
        match &self.dynamics {
            Dynamics::Modal {
                rates,
                half_period_gains,
            } => (rates, half_period_gains),
            Dynamics::Coupled { .. } => {
                unreachable!("reciprocating sliding moves no material through the contact")
            }
        }
    }

    /// Φ and Γ of `k` step units of a flowing body's coupled dynamics `matrix`.
    fn propagator(&self, matrix: &Mat<f64>, propagators: &Propagators, k: usize) -> Propagator {
        // A poisoned lock only means another thread panicked while inserting: the map is
        // still a map of finished propagators.
        let mut cache = propagators.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(found) = cache.get(&k) {
            return Arc::clone(found);
        }
        let single = Arc::clone(cache.entry(1).or_insert_with(|| {
            let time = self.sliding.half_period();
            Arc::new(crate::conduction::reduced::propagator(
                matrix.as_ref(),
                time,
            ))
        }));
        let pair = Arc::new(crate::conduction::reduced::propagator_power(&single, k));
        cache.insert(k, Arc::clone(&pair));
        pair
    }

    /// The thermal gap (mm) of `state` into `out`.
    pub fn thermal_gap(&self, state: &ThermalState, out: &mut [f64]) {
        self.gap.apply(&state.a, out);
    }

    /// The modal load of the frictional flux of `pressure` (MPa) per unit sliding speed:
    /// Φᵀ F (μ p), mW·s/mm per mm/s of speed.
    fn modal_flux(&self, pressure: &[f64], out: &mut [f64]) {
        let q: Vec<f64> = pressure
            .iter()
            .map(|&p| self.friction * p.max(0.0))
            .collect();
        out.iter_mut().for_each(|o| *o = 0.0);
        let modes = out.len();
        matmul(
            MatMut::from_column_major_slice_mut(out, modes, 1),
            Accum::Add,
            self.flux_modal.as_ref(),
            MatRef::from_column_major_slice(&q, q.len(), 1),
            1.0,
            Par::Seq,
        );
    }

    /// What one half period of reciprocating sliding at `pressure` adds to each modal
    /// coordinate (a ↦ e a + g): the half-sine frictional heat and the constant sources.
    fn half_period_increment(&self, pressure: &[f64], out: &mut [f64]) {
        self.modal_flux(pressure, out);
        let speed = match self.sliding {
            Sliding::Reciprocating { amplitude, omega } => amplitude * omega,
            Sliding::Monotonic { speed, .. } => speed,
        };
        let (_, gains) = self.modal();
        for ((o, &(_, sine, constant)), s) in out.iter_mut().zip(gains).zip(&self.source_modal) {
            *o = sine * speed * *o + constant * s;
        }
    }

    /// `halves` half periods alternating from `first` (increments g of
    /// [`ThermalModel::half_period_increment`]) to `second`, from `from` into `to`: m pairs
    /// (first, second), a ↦ e²a + (e g₁ + g₂) summed geometrically, then one more `first` if
    /// `halves` is odd.
    fn alternate(
        &self,
        from: &[f64],
        first: &[f64],
        second: &[f64],
        halves: usize,
        sums: &mut Vec<(usize, Vec<[f64; 2]>)>,
        to: &mut [f64],
    ) {
        let h = self.sliding.half_period();
        let pairs = halves / 2;
        let (rates, gains) = self.modal();
        let kept = match sums.iter().position(|(m, _)| *m == pairs) {
            Some(i) => i,
            None => {
                if sums.len() == KEPT_SUMS {
                    sums.remove(0);
                }
                let period = 2.0 * h;
                let each = rates
                    .iter()
                    .map(|&rate| {
                        [
                            decay(rate, period * pairs as f64),
                            geometric_sum(rate, period, pairs),
                        ]
                    })
                    .collect();
                sums.push((pairs, each));
                sums.len() - 1
            }
        };
        let cycle = &sums[kept].1;
        for j in 0..rates.len() {
            let e = gains[j].0;
            let mut a = from[j];
            if pairs > 0 {
                let [decayed, summed] = cycle[j];
                a = decayed * a + summed * (e * first[j] + second[j]);
            }
            if halves % 2 == 1 {
                a = e * a + first[j];
            }
            to[j] = a;
        }
    }

    /// Advance `state` over a kept step of `k` half periods (monotonic: step units) in
    /// `direction`, with the frictional heat of `pressure` (MPa, one per contact point);
    /// `first_half` says whether the step is the first of its cycle.
    ///
    /// Reciprocating sliding: a cycle of two steps of k half periods each stands for k
    /// periods of the process, 2k half periods alternating between the two directions. After
    /// the cycle's first step the state moves to the start of a half period of the second
    /// direction: k alternating half periods from the cycle's start (k − 1 if k is even, so
    /// that they end with the first direction), the second direction's halves at its last
    /// pressure. After the second step the cycle is done again from its start, its k₁ + k₂
    /// half periods (the two steps' k, equal unless a schedule changes k between them) with
    /// both directions' pressures of this cycle, and the next cycle starts there.
    pub fn advance(
        &self,
        state: &mut ThermalState,
        pressure: &[f64],
        direction: Direction,
        k: usize,
        first_half: bool,
    ) {
        let slot = usize::from(direction == Direction::Minus);
        let heat: f64 = pressure
            .iter()
            .zip(&self.area)
            .map(|(p, a)| self.friction * p.max(0.0) * a)
            .sum();
        let h = self.sliding.half_period();
        let mut increment = std::mem::take(&mut state.scratch);
        match self.sliding {
            Sliding::Reciprocating { amplitude, .. } => {
                self.half_period_increment(pressure, &mut increment);
                let other = state.last_increment[1 - slot]
                    .clone()
                    .unwrap_or_else(|| increment.clone());
                let half_heat = heat * 2.0 * amplitude;
                if first_half {
                    state.first_k = k;
                    let halves = if k % 2 == 1 { k } else { k - 1 };
                    let mut to = std::mem::take(&mut state.a);
                    let sums = &mut state.cycle_sums;
                    self.alternate(&state.cycle, &increment, &other, halves, sums, &mut to);
                    state.a = to;
                    let others = (halves / 2) as f64;
                    state.generated = state.cycle_generated
                        + half_heat * (halves - halves / 2) as f64
                        + state.last_heat[1 - slot] * others;
                    state.time = state.cycle_time + h * halves as f64;
                } else {
                    // The cycle's half periods: the first step's k and this one's (they differ
                    // where a schedule changes k between the two).
                    let halves = state.first_k.max(1) + k;
                    let mut to = std::mem::take(&mut state.a);
                    let sums = &mut state.cycle_sums;
                    self.alternate(&state.cycle, &other, &increment, halves, sums, &mut to);
                    state.a = to;
                    state.cycle.copy_from_slice(&state.a);
                    let (firsts, seconds) = (halves - halves / 2, halves / 2);
                    state.cycle_generated +=
                        state.last_heat[1 - slot] * firsts as f64 + half_heat * seconds as f64;
                    state.generated = state.cycle_generated;
                    state.cycle_time += h * halves as f64;
                    state.time = state.cycle_time;
                }
                state.last_heat[slot] = half_heat;
                match &mut state.last_increment[slot] {
                    Some(last) => last.copy_from_slice(&increment),
                    none => *none = Some(increment.clone()),
                }
            }
            Sliding::Monotonic { speed, step_time } => {
                self.modal_flux(pressure, &mut increment);
                let time = step_time * k as f64;
                state.cycle_generated += heat * speed * time;
                state.generated = state.cycle_generated;
                for (f, s) in increment.iter_mut().zip(&self.source_modal) {
                    *f = speed * *f + s;
                }
                match &self.dynamics {
                    Dynamics::Modal { rates, .. } => {
                        for ((a, &rate), f) in state.a.iter_mut().zip(rates).zip(&increment) {
                            *a = decay(rate, time) * *a + constant_gain(rate, time) * f;
                        }
                    }
                    Dynamics::Coupled {
                        matrix,
                        propagators,
                    } => {
                        let pair = self.propagator(matrix, propagators, k);
                        let (phi, gamma) = (&pair.0, &pair.1);
                        // a ← Φ a + Γ g, column by column (the matrices are column-major).
                        let mut next = vec![0.0; state.a.len()];
                        for (j, (&aj, &gj)) in state.a.iter().zip(&increment).enumerate() {
                            for ((n, p), g) in
                                next.iter_mut().zip(column(phi, j)).zip(column(gamma, j))
                            {
                                *n += p * aj + g * gj;
                            }
                        }
                        state.a.copy_from_slice(&next);
                    }
                }
                state.cycle.copy_from_slice(&state.a);
                state.cycle_time += time;
                state.time = state.cycle_time;
            }
        }
        state.scratch = increment;
    }

    /// The largest temperature on each body's boundary samples at modal coordinates `a`, °C.
    pub fn max_temperatures(&self, a: &[f64]) -> [f64; 2] {
        self.boundary_extremes(a).map(|[_, high]| high)
    }

    /// The lowest and the largest temperature (°C) on each body's boundary samples at
    /// modal coordinates `a`: `[body][low, high]`.
    pub fn boundary_extremes(&self, a: &[f64]) -> [[f64; 2]; 2] {
        [0, 1].map(|b| {
            self.boundary[b]
                .at(a)
                .into_iter()
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[low, high], t| {
                    [low.min(t), high.max(t)]
                })
        })
    }

    /// [`ThermalModel::boundary_extremes`] of each column of `states` (modes × states), by
    /// one matrix product per body.
    pub fn boundary_extremes_of(&self, states: MatRef<'_, f64>) -> Vec<[[f64; 2]; 2]> {
        let mut extremes = vec![[[f64::INFINITY, f64::NEG_INFINITY]; 2]; states.ncols()];
        for (b, output) in self.boundary.iter().enumerate() {
            let mut values = Mat::<f64>::zeros(output.offset.len(), states.ncols());
            matmul(
                values.as_mut(),
                Accum::Replace,
                output.matrix.as_ref(),
                states,
                1.0,
                Par::Seq,
            );
            for (j, e) in extremes.iter_mut().enumerate() {
                for (v, c) in values.col(j).iter().zip(&output.offset) {
                    let t = v + c;
                    e[b] = [e[b][0].min(t), e[b][1].max(t)];
                }
            }
        }
        extremes
    }

    /// Heat stored in both bodies relative to the reference temperature, mJ.
    pub fn stored_heat(&self, state: &ThermalState) -> f64 {
        self.stored[0].at(&state.a)[0] + self.stored[1].at(&state.a)[0]
    }

    /// The sliding's profile.
    pub fn sliding(&self) -> Sliding {
        self.sliding
    }
}

impl ThermalModel {
    /// The periodic temperature of reciprocating sliding whose half cycles have the steady
    /// pressures `p_plus` and `p_minus` (MPa): the modal coordinates at the start of a '+'
    /// half (the end of a '−' one) and at the start of a '−' half. Per mode, with the
    /// half-period map a ↦ e a + g_d, a₊ = (e g₊ + g₋)/(1 − e²) and a₋ = e a₊ + g₊. Under
    /// monotonic sliding both are the stationary state under `p_plus`. A mode of rate 0 (a
    /// body that cannot lose heat) keeps its initial value if a period brings it no net heat;
    /// if one does, its temperature rises for ever and there is no periodic state: None.
    pub fn periodic_state(&self, p_plus: &[f64], p_minus: &[f64]) -> Option<[Vec<f64>; 2]> {
        let r = self.modes();
        let mut plus = vec![0.0; r];
        let mut minus = vec![0.0; r];
        self.modal_flux(p_plus, &mut plus);
        match self.sliding {
            Sliding::Reciprocating { amplitude, omega } => {
                self.modal_flux(p_minus, &mut minus);
                let speed = amplitude * omega;
                let mut start_plus = vec![0.0; r];
                let mut start_minus = vec![0.0; r];
                let (rates, gains) = self.modal();
                for j in 0..r {
                    let (e, sine, constant) = gains[j];
                    let source = constant * self.source_modal[j];
                    let g_plus = sine * speed * plus[j] + source;
                    let g_minus = sine * speed * minus[j] + source;
                    if rates[j] > 0.0 {
                        start_plus[j] = (e * g_plus + g_minus)
                            / (-(-2.0 * rates[j] * self.sliding.half_period()).exp_m1());
                    } else {
                        // A body that keeps its heat (rate 0): periodic only if it receives
                        // none over a period (a share of 0 for it), and then it keeps what it
                        // had at the start.
                        let net = g_plus + g_minus;
                        let scale = g_plus.abs() + g_minus.abs() + self.initial[j].abs();
                        if net.abs() > 1e-9 * scale {
                            return None;
                        }
                        start_plus[j] = self.initial[j];
                    }
                    start_minus[j] = e * start_plus[j] + g_plus;
                }
                Some([start_plus, start_minus])
            }
            Sliding::Monotonic { speed, .. } => {
                let g: Vec<f64> = (0..r)
                    .map(|j| speed * plus[j] + self.source_modal[j])
                    .collect();
                let a = match &self.dynamics {
                    Dynamics::Modal { rates, .. } => {
                        let mut a = vec![0.0; r];
                        for j in 0..r {
                            a[j] = if rates[j] > 0.0 {
                                g[j] / rates[j]
                            } else if g[j].abs() <= 1e-9 * (g[j].abs() + self.initial[j].abs()) {
                                self.initial[j]
                            } else {
                                return None;
                            };
                        }
                        a
                    }
                    Dynamics::Coupled { matrix, .. } => stationary(matrix, &g)?,
                };
                Some([a.clone(), a])
            }
        }
    }
}
