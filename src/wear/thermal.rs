//! Frictional heat and thermal distortion in the wear integration (paper §4): the heat of
//! each step's pressure warms both bodies, and the normal thermal displacements of the two
//! contact surfaces enter the gap the way wear does.
//!
//! # The scheme (operator split, as the paper's §4)
//!
//! Per step n of k half periods in direction d:
//! 1. the contact is solved on the gap with the wear so far and the thermal gap of the
//!    temperature T_n at the step's start, g_th(T_n) = u_n⁽²⁾(T_n) − u_n⁽¹⁾(T_n);
//! 2. the wear increment of that pressure is added (the wear loop's own business);
//! 3. the heat problem is advanced over the step's k half periods from T_n under that
//!    pressure's frictional heat, q_i = μ p_i |v(t)| per unit area at each contact point;
//!    its end temperature T_{n+1} gives the next step's thermal gap.
//!
//! A step of k half periods stands for k half periods in which the real process alternates
//! directions; the heat of a step is therefore k half periods *alternating* between this
//! step's pressure and the last pressure of the other direction, ending with this step's
//! direction. For k = 1 (the paper's first steps, and every step of a run without
//! extrapolation) that is the step's own half period; for k ≫ 1 it gives the temperature the
//! process reaches, with its periodic ripple, instead of k half periods of one direction's
//! heat. Within a half period of reciprocating sliding the speed is u₀ω sin ωs, so the flux
//! is a half sine of amplitude μ p_i u₀ ω; the heat of a half period is μ p_i 2u₀ per unit
//! area, exactly.
//!
//! # The heat problem and its solution
//!
//! Both bodies are one heat problem ([`crate::conduction`]'s operators side by side). Under
//! perfect thermal contact, partner points are tied by an interface conductance h_c w_i t
//! (T⁽¹⁾_i − T⁽²⁾_i) so large ([`INTERFACE_CONDUCTANCE`]) that the temperatures are equal to
//! about 10⁻⁶ of the rise: the heat enters at body 1's trace and the tie shares it, so the
//! share is solved, not assumed. With a given fraction φ, body 1 takes φ of the heat and
//! body 2 the rest, and no heat crosses otherwise. Heat crosses at every pair of the named
//! contact edge, in contact or not (the pairs are fixed, as the contact's are).
//!
//! The problem is reduced ([`crate::conduction::reduced`]) to the space its inputs excite
//! (the flux at each contact point, the constant sources, the initial field) and integrated
//! exactly in time in its modes: no time step, no stability limit, and a step of k half
//! periods costs what one does. The thermal gap is linear in the temperature: per mode, the
//! gap of its temperature field through each body's elastic solve with the thermal load
//! ([`crate::elasticity::ThermalLoads`]), made once in set-up by the adjoint: with X = K⁻¹N
//! (N the normal traces of the contact points), the gap of a thermal load f is Xᵀf. Body 1 is
//! clamped at its plate edge as in the contact's condensation, so the plate's rigid motions
//! still follow from equilibrium.
//!
//! Under monotonic sliding body 2's material moves through the contact
//! ([`counterface`]): its heat problem carries that motion, K is not symmetric, and the reduced
//! state is stepped by the exact propagator of each step length instead of in modes
//! ([`crate::conduction::reduced::propagator`]).

use crate::complementarity::Direction;
use crate::conduction::reduced::{constant_gain, decay};

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
use faer::Mat;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

mod build;
pub mod counterface;
mod outputs;
pub use build::{CoupledSystem, ThermalBodies, ThermalError, SHIFTS};
pub use outputs::{GapOutput, Output};

/// Interface conductance of perfect thermal contact, relative to the largest conductance of
/// the bodies at the scale of the contact points' spacing (k/w): h_c = 10⁶ k_max / w_min.
/// The temperature jump across the interface is then about 10⁻⁶ of the temperature
/// difference across one spacing, and the matrices stay far from losing their digits (a
/// ratio of 10⁶ costs six of sixteen).
pub const INTERFACE_CONDUCTANCE: f64 = 1e6;

/// y = M a + c: an output of the reduced model.
#[derive(Clone, Debug)]
pub struct Affine {
    /// M (outputs × modes).
    pub matrix: Mat<f64>,
    /// c (outputs).
    pub offset: Vec<f64>,
}

impl Affine {
    /// The outputs at modal coordinates `a`.
    pub fn apply(&self, a: &[f64], out: &mut [f64]) {
        out.copy_from_slice(&self.offset);
        // Column by column: M is stored by columns, so each is one contiguous axpy.
        for (j, &aj) in a.iter().enumerate() {
            let column = self
                .matrix
                .col(j)
                .try_as_col_major()
                .expect("an owned matrix's columns are contiguous")
                .as_slice();
            for (o, m) in out.iter_mut().zip(column) {
                *o += m * aj;
            }
        }
    }

    /// The outputs at `a`, allocated.
    pub fn at(&self, a: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.offset.len()];
        self.apply(a, &mut out);
        out
    }
}

/// How the bodies slide, for the time profile of the frictional heat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sliding {
    /// u = −u₀ cos ωt: `amplitude` u₀ (mm), `omega` ω (rad/s).
    Reciprocating {
        /// u₀, mm.
        amplitude: f64,
        /// ω, rad/s.
        omega: f64,
    },
    /// Constant `speed` (mm/s), a step of `step_time` s.
    Monotonic {
        /// v, mm/s.
        speed: f64,
        /// Time of one step unit, s.
        step_time: f64,
    },
}

impl Sliding {
    /// Time of one half period (one monotonic step unit), s.
    pub fn half_period(&self) -> f64 {
        match *self {
            Sliding::Reciprocating { omega, .. } => std::f64::consts::PI / omega,
            Sliding::Monotonic { step_time, .. } => step_time,
        }
    }
}

/// (Φ, Γ) of one step length: a ↦ Φ a + Γ b ([`crate::conduction::reduced::propagator`]).
type Propagator = Arc<(Mat<f64>, Mat<f64>)>;

/// The propagators made so far, by step length in step units.
type Propagators = Mutex<HashMap<usize, Propagator>>;

/// How the reduced heat state moves in time.
#[derive(Debug)]
enum Dynamics {
    /// Bodies at rest: independent modes, each with its rate λ_j (1/s) and, over one half
    /// period (one step unit), e^{−λh}, the half-sine gain and the constant source's gain
    /// ([`crate::conduction::reduced`]).
    Modal {
        rates: Vec<f64>,
        half_period_gains: Vec<(f64, f64, f64)>,
    },
    /// A flowing body: ȧ = −M a + b in the C-orthonormal basis, stepped over k step units by
    /// (Φ, Γ) of that length, made when first needed and kept.
    Coupled {
        matrix: Mat<f64>,
        propagators: Propagators,
    },
}

/// The heat problem of a run, reduced and ready to step.
#[derive(Debug)]
pub struct ThermalModel {
    /// How the state moves.
    dynamics: Dynamics,
    /// Φᵀ F: the modal load of a unit flux density (mW/mm²) at each contact point
    /// (modes × points).
    flux_modal: Mat<f64>,
    /// Φᵀ f₀: the modal load of the constant sources (ambient, held edges), mW.
    source_modal: Vec<f64>,
    /// The modal coordinates of the initial field.
    initial: Vec<f64>,
    /// The thermal gap u_n⁽²⁾ − u_n⁽¹⁾ at each contact point, mm.
    pub gap: Affine,
    /// The temperature (°C) at each contact point on body 1 and at its partner on body 2.
    pub contact_temperature: [Affine; 2],
    /// The temperature (°C) at each probe.
    pub probes: Affine,
    /// The temperature (°C) at sample points of each body's boundary (the Lobatto points of
    /// its boundary edges), where the largest temperature of a body heated at its boundary
    /// lies.
    pub boundary: [Affine; 2],
    /// Heat stored in each body relative to the reference temperature, mJ.
    pub stored: [Affine; 2],
    /// Coulomb's μ.
    friction: f64,
    /// The sliding's time profile.
    sliding: Sliding,
    /// Contact area w_i t of each point, mm².
    area: Vec<f64>,
    /// Figures of the set-up.
    pub info: ThermalInfo,
    /// What the temperature fields are made of (for output).
    fields: ThermalFields,
}

/// The modes over both bodies' unknowns and the bodies, for the temperature fields.
#[derive(Debug)]
struct ThermalFields {
    modes: Mat<f64>,
    bodies: [crate::conduction::ConductionBody; 2],
    offsets: [usize; 2],
    loads: [std::sync::Arc<crate::elasticity::ThermalLoads>; 2],
    reference: f64,
}

impl ThermalModel {
    /// The temperature (°C) of both bodies' free unknowns (body 1's first) at modal
    /// coordinates `a`: Φ a.
    pub fn free_field(&self, a: &[f64]) -> Vec<f64> {
        let f = &self.fields;
        (0..f.modes.nrows())
            .map(|i| (0..a.len()).map(|j| f.modes[(i, j)] * a[j]).sum())
            .collect()
    }

    /// The temperature fields of body 1 and body 2 at modal coordinates `a`, for their
    /// thermal stresses and for output ([`crate::fields::TemperatureField`]).
    pub fn temperature_fields(&self, a: &[f64]) -> [crate::fields::TemperatureField; 2] {
        let f = &self.fields;
        let free = self.free_field(a);
        [0, 1].map(|b| {
            let body = &f.bodies[b];
            let full = body.expand(&free[f.offsets[b]..f.offsets[b] + body.n_free()]);
            let uniform = body.uniform(f.reference);
            crate::fields::TemperatureField {
                rise: (0..body.mesh.elements.len())
                    .map(|e| {
                        body.element_unknowns(e)
                            .iter()
                            .map(|&(g, s)| s * (full[g] - uniform[g]))
                            .collect()
                    })
                    .collect(),
                reference: f.reference,
                loads: std::sync::Arc::clone(&f.loads[b]),
            }
        })
    }
}

/// Figures of a thermal model's set-up, for the summary.
#[derive(Clone, Debug, Default)]
pub struct ThermalInfo {
    /// Unknowns of the full heat problem (both bodies, held ones excluded).
    pub unknowns: usize,
    /// Modes of the reduced model.
    pub modes: usize,
    /// Shifts of the reduction, 1/s.
    pub shifts: Vec<f64>,
    /// Interface conductance h_c of perfect contact, mW/(mm²·K) (0 with a given share).
    pub interface_conductance: f64,
    /// Whether every part of the heat problem can lose heat (through a held or convecting
    /// edge or the faces); when not, its conductivity is singular (a constant temperature
    /// of a sealed body is a mode of rate 0).
    pub has_exit: bool,
    /// Whether frictional heat enters a body that cannot lose it: its temperature rises
    /// without end, and there is no steady state.
    pub trapped: bool,
    /// Contact points whose heat-receiving trace touches an edge held at a temperature:
    /// the share of their heat on the held unknowns goes straight into the held edge.
    pub held_points: usize,
    /// Péclet number of each body, v_max L / (2 a): the largest sliding speed times half the
    /// contact length over the material's diffusivity at the contact. Above about 1 the
    /// heat moves with the sliding faster than it spreads.
    pub peclet: [f64; 2],
    /// Reference (stress-free) temperature, °C.
    pub reference: f64,
    /// Seconds spent building the model.
    pub seconds: f64,
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
}

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
        out.iter_mut().for_each(|o| *o = 0.0);
        for (i, &p) in pressure.iter().enumerate() {
            let q = self.friction * p.max(0.0);
            if q == 0.0 {
                continue;
            }
            let column = self
                .flux_modal
                .col(i)
                .try_as_col_major()
                .expect("an owned matrix's columns are contiguous")
                .as_slice();
            for (o, f) in out.iter_mut().zip(column) {
                *o += f * q;
            }
        }
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
        to: &mut [f64],
    ) {
        let h = self.sliding.half_period();
        let pairs = halves / 2;
        let (rates, gains) = self.modal();
        for j in 0..rates.len() {
            let rate = rates[j];
            let e = gains[j].0;
            let mut a = from[j];
            if pairs > 0 {
                a = decay(rate, 2.0 * h * pairs as f64) * a
                    + geometric_sum(rate, 2.0 * h, pairs) * (e * first[j] + second[j]);
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
                    self.alternate(&state.cycle, &increment, &other, halves, &mut to);
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
                    self.alternate(&state.cycle, &other, &increment, halves, &mut to);
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

    /// The largest temperature on each body's boundary, °C.
    pub fn max_temperatures(&self, state: &ThermalState) -> [f64; 2] {
        [0, 1].map(|b| {
            self.boundary[b]
                .at(&state.a)
                .into_iter()
                .fold(f64::NEG_INFINITY, f64::max)
        })
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

/// The heat of one wear run as the step loop sees it: the state, the thermal gap of the next
/// contact solve, and the change of that gap over the current cycle.
pub(super) struct HeatRun<'a> {
    pub model: &'a ThermalModel,
    pub state: ThermalState,
    /// The thermal gap of the temperature now (mm): what the next contact solve sees.
    pub gap: Vec<f64>,
    /// The thermal gap at the start of the current cycle.
    cycle_start: Vec<f64>,
    /// The thermal gap's change over the last complete cycle (mm).
    pub cycle_change: Vec<f64>,
}

impl<'a> HeatRun<'a> {
    pub fn new(model: &'a ThermalModel) -> HeatRun<'a> {
        let state = model.start();
        let mut gap = vec![0.0; model.gap.offset.len()];
        model.thermal_gap(&state, &mut gap);
        HeatRun {
            model,
            state,
            cycle_start: gap.clone(),
            cycle_change: vec![0.0; gap.len()],
            gap,
        }
    }

    /// Advance over a kept step and return the probes' temperatures and each body's
    /// largest temperature (°C) at its end.
    pub fn after_step(
        &mut self,
        pressure: &[f64],
        direction: Direction,
        k: usize,
        first_half: bool,
    ) -> (Vec<f64>, [f64; 2]) {
        self.model
            .advance(&mut self.state, pressure, direction, k, first_half);
        self.model.thermal_gap(&self.state, &mut self.gap);
        (
            self.model.probes.at(&self.state.a),
            self.model.max_temperatures(&self.state),
        )
    }

    /// The largest change of the thermal gap over the cycle that ends now (mm), and start
    /// the next cycle.
    pub fn end_cycle(&mut self) -> f64 {
        for ((c, a), b) in self
            .cycle_change
            .iter_mut()
            .zip(&self.gap)
            .zip(&self.cycle_start)
        {
            *c = a - b;
        }
        self.cycle_start.copy_from_slice(&self.gap);
        self.cycle_change.iter().fold(0.0, |m, c| m.max(c.abs()))
    }
}

/// What a run's heat left at its end.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ThermalHistory {
    /// Temperature at each contact point of body 1 and at its partner on body 2 at the end
    /// of the last completed step, °C.
    pub contact_temperature: [Vec<f64>; 2],
    /// The thermal gap u_n⁽²⁾ − u_n⁽¹⁾ (mm) the last completed step's pressure was solved with.
    pub thermal_gap: Vec<f64>,
    /// The thermal gap of the end temperature (the next step's), mm.
    pub next_thermal_gap: Vec<f64>,
    /// Modal coordinates of the end state (for fields and restarts).
    #[serde(skip)]
    pub state: Vec<f64>,
    /// Modal coordinates of the temperature the last completed step was solved with.
    #[serde(skip)]
    pub solved_state: Vec<f64>,
    /// Heat made by friction over the run, mJ.
    pub generated: f64,
    /// Heat stored in the bodies at the end relative to the reference temperature, mJ.
    pub stored: f64,
    /// Time heated, s.
    pub time: f64,
}

impl HeatRun<'_> {
    /// The end of the run, `solved_gap` being the thermal gap of the last kept solve.
    pub fn finish(&self, solved_gap: Vec<f64>, solved_state: Vec<f64>) -> ThermalHistory {
        let a = &self.state.a;
        ThermalHistory {
            contact_temperature: [
                self.model.contact_temperature[0].at(a),
                self.model.contact_temperature[1].at(a),
            ],
            thermal_gap: solved_gap,
            next_thermal_gap: self.gap.clone(),
            state: a.clone(),
            solved_state,
            generated: self.state.generated,
            stored: self.model.stored_heat(&self.state),
            time: self.state.time,
        }
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
                    start_plus[j] = (e * g_plus + g_minus)
                        / (-(-2.0 * rates[j] * self.sliding.half_period()).exp_m1());
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
