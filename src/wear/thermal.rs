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
//! (the contact's flux in smooth shapes along the contact ([`shapes`]), the constant
//! sources, the initial field) and integrated
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
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, MatMut, MatRef, Par};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

mod bodies;
mod build;
pub mod counterface;
mod outputs;
pub mod shapes;
mod stepping;
pub use build::{CoupledSystem, ThermalBodies, ThermalError, FLOWING_SHIFTS, SHIFTS};
pub use outputs::{GapOutput, Output};
pub use stepping::ThermalState;

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
        // One matrix–vector product by faer's SIMD kernels: the per-step outputs (the gap,
        // the probes, some 300 boundary samples over 200 modes) were a third of a step's
        // cost as a plain loop.
        let rows = out.len();
        matmul(
            MatMut::from_column_major_slice_mut(out, rows, 1),
            Accum::Add,
            self.matrix.as_ref(),
            MatRef::from_column_major_slice(a, a.len(), 1),
            1.0,
            Par::Seq,
        );
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
    /// The lowest temperature the problem imposes anywhere (°C): its initial temperature,
    /// and every held, ambient and entering temperature. Frictional heat only adds heat, so
    /// a temperature below it is the discretisation's undershoot, not physics.
    pub floor: f64,
    /// Seconds spent building the model.
    pub seconds: f64,
}

/// The heat of one wear run as the step loop sees it: the state, the thermal gap of the next
/// contact solve, and the change of that gap over the current cycle.
///
/// Each body's largest temperature per step is looked for on a few hundred boundary samples
/// ([`ThermalModel::boundary`]): as a product per step it cost as much as the rest of the
/// step's heat. Nothing in the run needs it before the end, so the steps' modal states are
/// kept in chunks of [`EXTREMES_CHUNK`] and the samples of a chunk are one matrix product.
pub(super) struct HeatRun<'a> {
    pub model: &'a ThermalModel,
    pub state: ThermalState,
    /// The thermal gap of the temperature now (mm): what the next contact solve sees.
    pub gap: Vec<f64>,
    /// The thermal gap at the start of the current cycle.
    cycle_start: Vec<f64>,
    /// The lowest temperature on either body's boundary samples at the end of any step
    /// whose chunk is done, °C.
    lowest: f64,
    /// The thermal gap's change over the last complete cycle (mm).
    pub cycle_change: Vec<f64>,
    /// The modal states of the steps whose extremes are not yet computed (modes × steps,
    /// column by column), and how many steps they are (a model without modes has states
    /// of no values).
    pending: Vec<f64>,
    pending_steps: usize,
    /// Each step's largest temperature of body 1 and body 2 (°C), for the chunks done.
    maxima: Vec<[f64; 2]>,
}

/// How many steps' boundary extremes are computed as one matrix product (a 300 × 165 × 128
/// product on punch-b40-heat; its states take 170 kB).
const EXTREMES_CHUNK: usize = 128;

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
            lowest: f64::INFINITY,
            pending: Vec::new(),
            pending_steps: 0,
            maxima: Vec::new(),
        }
    }

    /// Advance over a kept step and return the probes' temperatures (°C) at its end; its
    /// bodies' largest temperatures follow in [`HeatRun::maxima`].
    pub fn after_step(
        &mut self,
        pressure: &[f64],
        direction: Direction,
        k: usize,
        first_half: bool,
    ) -> Vec<f64> {
        self.model
            .advance(&mut self.state, pressure, direction, k, first_half);
        self.model.thermal_gap(&self.state, &mut self.gap);
        self.pending.extend_from_slice(&self.state.a);
        self.pending_steps += 1;
        if self.pending_steps == EXTREMES_CHUNK {
            self.flush_extremes();
        }
        self.model.probes.at(&self.state.a)
    }

    /// The boundary extremes of the pending steps.
    fn flush_extremes(&mut self) {
        if self.pending_steps == 0 {
            return;
        }
        let modes = self.state.a.len();
        let states = MatRef::from_column_major_slice(&self.pending, modes, self.pending_steps);
        let extremes = self.model.boundary_extremes_of(states);
        for [[low1, high1], [low2, high2]] in extremes {
            self.lowest = self.lowest.min(low1).min(low2);
            self.maxima.push([high1, high2]);
        }
        self.pending.clear();
        self.pending_steps = 0;
    }

    /// Each kept step's largest temperature of body 1 and of body 2 (°C), in step order.
    pub fn maxima(&mut self) -> &[[f64; 2]] {
        self.flush_extremes();
        &self.maxima
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
    /// The lowest temperature on the boundary samples at the end of any step, °C.
    #[serde(skip)]
    pub lowest: f64,
}

impl HeatRun<'_> {
    /// The end of the run, `solved_gap` being the thermal gap of the last kept solve.
    pub fn finish(&mut self, solved_gap: Vec<f64>, solved_state: Vec<f64>) -> ThermalHistory {
        self.flush_extremes();
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
            lowest: self.lowest,
        }
    }
}
