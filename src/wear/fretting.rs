//! Fretting wear: each contact point wears by the slip it undergoes, ẇ = β̃ pᵇ |ṡ|ᵃ, so that
//! points that stick do not wear, with jumps over many cycles under error control.
//!
//! A step takes the contact from its worn shape g through k cycles:
//!
//! 1. The cycle at the step's start (its frictionless pressure p): each point's wear per
//!    cycle as T_i pᵇ + E_i ([`FrettingCycle::weighted_sliding_term`]), exact at p: T_i the
//!    point's ∫|ṡ|ᵃ dt over a cycle, zero where the point sticks; in a coupled cycle, whose
//!    shear moves the pressure, each stage's slip weighted by that stage's pressure against
//!    p, and E_i ≥ 0 what the cycle presses a point beyond p (a point at the contact's edge
//!    that only the shear presses wears by E_i alone).
//! 2. The implicit step g⁺ = g + k Σ_l β̃_l (T_l,i p⁺_iᵇˡ + E_l,i) with the pressure p⁺ of the
//!    worn shape g⁺, solved as one contact problem with the wear as a compliance in series
//!    with the bodies' (b = 1), or by Newton's method on the linearised wear (b ≠ 1) as the
//!    sliding run's implicit step is ([`crate::wear::law`]). The slip terms are held from the
//!    step's start (they change slowly: the stick zone of a force-controlled cycle does not
//!    move at all for two bodies of one material, Ciavarella and Hills), the pressure is
//!    implicit: stable for any k, so that the pressure of a slip zone that wears out falls to
//!    zero instead of overshooting. E is held (explicit): the jump control bounds its change.
//! 3. The cycle at the step's end gives the next step's terms and the error estimate: half
//!    the change of the wear increment between the start's terms and the end's, both at p⁺,
//!    the difference between holding the terms and the trapezoid rule. A step whose estimate
//!    exceeds `tolerance` of its largest wear is taken again with fewer cycles; k grows by at
//!    most 2 per step. A shorter jump whose estimate does not fall (it falls with the jump
//!    where the terms change smoothly) has met a step change of the cycle itself, a point
//!    turning from stick to slip within a stage, which no jump resolves: it is taken.
//!
//! The run ends after `cycles` cycles, or as soon as no point that carries pressure slips:
//! wear has stopped (the final state of partial slip).

use crate::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::fretting::{CoupledError, CycleModel, FrettingCycle};
use crate::wear::{law, WearLaw};

/// What a fretting run needs beyond the contact.
pub struct FrettingWearInput<'a> {
    /// Each wearing body (0, 1) and its law.
    pub laws: &'a [(usize, WearLaw)],
    /// Angular frequency of the cycle, rad/s.
    pub omega: f64,
    /// Cycles to run.
    pub cycles: f64,
    /// Cycles after which the profiles are recorded.
    pub record_cycles: &'a [f64],
    /// Relative local error allowed per jump.
    pub tolerance: f64,
    /// Newton's iterations and tolerance (b ≠ 1).
    pub max_iterations: usize,
    /// Relative tolerance of the linearised wear.
    pub newton_tolerance: f64,
}

/// One step of a fretting run.
#[derive(Clone, Debug, PartialEq)]
pub struct FrettingStep {
    /// Step number, from 1.
    pub step: usize,
    /// Cycles done at the step's end.
    pub cycles: f64,
    /// Cycles this step jumped.
    pub k: f64,
    /// Largest contact pressure at the step's end, MPa.
    pub peak_pressure: f64,
    /// The x extent (mm) of the points that never slip in the step's end cycle.
    pub stick_extent: Option<(f64, f64)>,
    /// Energy dissipated per cycle at the step's end, N·mm.
    pub dissipated: f64,
    /// The tangential force at the cycle's peak, N.
    pub peak_load: f64,
    /// Each body's deepest wear so far, mm.
    pub deepest_wear: [f64; 2],
    /// Points carrying pressure that slip in the step's end cycle.
    pub slipping_points: usize,
    /// Error estimates of the jumps taken again.
    pub rejected: usize,
}

/// Profiles at one instant, one value per contact point.
#[derive(Clone, Debug, PartialEq)]
pub struct FrettingProfiles {
    /// Cycles done.
    pub cycles: f64,
    /// Contact pressure, MPa.
    pub pressure: Vec<f64>,
    /// The worn shape (the gap's growth: both bodies' wear), mm.
    pub shape: Vec<f64>,
    /// Each body's wear, mm.
    pub wear: [Vec<f64>; 2],
    /// Each point's slip in a half cycle, mm.
    pub slip_amplitude: Vec<f64>,
    /// Whether each point sticks through the cycle.
    pub never_slips: Vec<bool>,
    /// The fretting loop of the cycle: the shift (mm) and the tangential load (N) at the
    /// peak and after each of its 2n stages.
    pub cycle_loop: Vec<(f64, f64)>,
}

/// Why a fretting run stopped early.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FrettingStop {
    /// The normal contact solve failed.
    #[error("the contact solve failed (complementarity residual {complementarity:.3e}, equilibrium residual {equilibrium:.3e})")]
    ContactSolve {
        /// Residuals of the failed solve.
        complementarity: f64,
        /// Residual of the plate's equilibrium.
        equilibrium: f64,
    },
    /// The cycle failed.
    #[error("the fretting cycle failed: {0}")]
    Cycle(CoupledError),
    /// The run took [`MAX_STEPS`] steps without reaching its cycles.
    #[error("{MAX_STEPS} steps reached {cycles:.6e} cycles: the jump control kept the jumps short (the wear per cycle changes too fast from cycle to cycle for fretting.tolerance)")]
    TooManySteps {
        /// Cycles done.
        cycles: f64,
    },
    /// No contact point carries pressure under the normal load: nothing to fret.
    #[error("no contact point carries pressure under the normal load: nothing frets (a held plate presses only by its position; check the loads, the plate and the initial gap)")]
    NoContact,
    /// Newton's method of an implicit step (b ≠ 1) did not converge.
    #[error("Newton's method of the implicit step did not converge in {iterations} iterations (linearisation error {error:.3e} of the largest wear)")]
    Newton {
        /// Iterations made.
        iterations: usize,
        /// Relative error left.
        error: f64,
    },
}

/// A fretting run's results.
#[derive(Clone, Debug)]
pub struct FrettingHistory {
    /// One record per step.
    pub steps: Vec<FrettingStep>,
    /// The first cycle (unworn) and the last one.
    pub first_cycle: FrettingCycle,
    /// The cycle at the run's end.
    pub last_cycle: FrettingCycle,
    /// Profiles at the start, at each recorded cycle and at the end.
    pub records: Vec<FrettingProfiles>,
    /// The cycle after which no loaded point slipped (wear stopped), if it did.
    pub wear_stopped: Option<f64>,
    /// Why the run stopped before its cycles, with the step that failed.
    pub stopped: Option<(usize, FrettingStop)>,
    /// Contact solves made.
    pub solves: usize,
}

/// Most steps of a run: a run to its final state takes a few hundred.
pub const MAX_STEPS: usize = 100_000;

/// The largest error estimate, in tolerances, that a jump meeting a step change of the cycle
/// may keep (measured: up to 8 at a tolerance of 0.1 %, 1.3 at 1 %).
const STEP_CHANGE: f64 = 10.0;

/// Most cycles one step may jump.
const MAX_JUMP: f64 = 1e9;

/// The state a step starts from.
struct State {
    shape: Vec<f64>,
    wear: [Vec<f64>; 2],
    pressure: Vec<f64>,
    cycle: FrettingCycle,
    /// The pressure (MPa) of each state of the cycle.
    cycle_pressures: Vec<Vec<f64>>,
}

/// A fretting run on `contact` (whose solve `solver` is frictionless: the normal load is
/// applied without tangential traction) from its unworn shape. `on_step` sees every step.
pub fn run(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    model: &mut dyn CycleModel,
    input: &FrettingWearInput,
    mut on_step: impl FnMut(&FrettingStep),
) -> Result<FrettingHistory, FrettingStop> {
    let n = contact.len();
    let area = contact.areas();
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let mut solves = 0;
    let shape = vec![0.0; n];
    let pressure = normal_solve(solver, contact, &shape, &mut solves)?;
    if pressure.iter().all(|p| *p <= 0.0) {
        return Err(FrettingStop::NoContact);
    }
    let (cycle, cycle_pressures) = cycle_at(model, &pressure, &shape, &area)?;
    let mut state = State {
        shape,
        wear: [vec![0.0; n], vec![0.0; n]],
        pressure,
        cycle,
        cycle_pressures,
    };
    let mut history = FrettingHistory {
        steps: vec![],
        first_cycle: state.cycle.clone(),
        last_cycle: state.cycle.clone(),
        records: vec![profiles(0.0, &state)],
        wear_stopped: None,
        stopped: None,
        solves: 0,
    };
    let mut done = 0.0;
    let mut k = 1.0f64;
    let mut records = input.record_cycles.iter().copied().peekable();
    let mut step = 0;
    while done < input.cycles {
        if !slips(&state) {
            history.wear_stopped = Some(done);
            break;
        }
        if step == MAX_STEPS {
            // The jump control never settles on a jump: say so rather than step for ever.
            history.stopped = Some((step + 1, FrettingStop::TooManySteps { cycles: done }));
            break;
        }
        step += 1;
        // A step ends at each recorded cycle and at the run's end.
        while records.peek().is_some_and(|&r| r <= done) {
            records.next();
        }
        let limit = records
            .peek()
            .copied()
            .unwrap_or(input.cycles)
            .min(input.cycles);
        let mut rejected = 0;
        let mut last_attempt: Option<(f64, f64)> = None;
        let (next, jump) = loop {
            let jump = k.min(limit - done).max(1.0);
            let attempt = (|| {
                let next = implicit_step(solver, contact, input, &state, jump, &area, &mut solves)?;
                let (cycle, cycle_pressures) = cycle_at(model, &next.pressure, &next.shape, &area)?;
                Ok::<_, FrettingStop>(State {
                    cycle,
                    cycle_pressures,
                    ..next
                })
            })();
            let next = match attempt {
                Ok(next) => next,
                Err(stop) => {
                    history.stopped = Some((step, stop));
                    history.last_cycle = state.cycle.clone();
                    history.records.push(profiles(done, &state));
                    history.solves = solves;
                    return Ok(history);
                }
            };
            let error = jump_error(input, (&state, &next), jump);
            let factor = if error > 0.0 {
                (0.9 * (input.tolerance / error).sqrt()).clamp(0.2, 2.0)
            } else {
                2.0
            };
            if error <= input.tolerance || jump <= 1.0 {
                k = (jump * factor).clamp(1.0, MAX_JUMP).round();
                break (next, jump);
            }
            let stepped = last_attempt.is_some_and(|(j, e)| {
                jump <= 0.5 * j
                    && error > e * (jump / j).sqrt()
                    && error <= STEP_CHANGE * input.tolerance
            });
            if stepped {
                // A jump at most half as long left the estimate well above what a smooth change
                // gives (it falls in proportion to the jump): the cycle changed by a step of
                // its own, a point turning from stick to slip within a stage, which no jump
                // resolves. Taken, if its estimate is within STEP_CHANGE tolerances; the jump
                // kept.
                k = jump;
                break (next, jump);
            }
            last_attempt = Some((jump, error));
            rejected += 1;
            // At least halved, so that a retry tells a step change from a smooth one.
            k = (jump * factor.min(0.5)).max(1.0).floor();
        };
        done += jump;
        state = next;
        let record = FrettingStep {
            step,
            cycles: done,
            k: jump,
            peak_pressure: state.pressure.iter().fold(0.0f64, |m, p| m.max(*p)),
            stick_extent: state.cycle.stick_extent(&x),
            dissipated: state.cycle.dissipated,
            peak_load: state.cycle.states[0].load,
            deepest_wear: [0, 1].map(|b| state.wear[b].iter().fold(0.0f64, |m, w| m.max(*w))),
            slipping_points: slipping(&state),
            rejected,
        };
        on_step(&record);
        history.steps.push(record);
        if records.peek() == Some(&done) {
            history.records.push(profiles(done, &state));
        }
    }
    history.last_cycle = state.cycle.clone();
    if history.records.last().map(|r| r.cycles) != Some(done) {
        history.records.push(profiles(done, &state));
    }
    history.solves = solves;
    Ok(history)
}

/// Whether some point that carries pressure slips in the state's cycle.
fn slips(state: &State) -> bool {
    slipping(state) > 0
}

/// A pressure below this fraction of the largest counts as none: a worn-out slip zone keeps
/// pressures of 1e-17 of the peak (a review: 30 such points kept a run of 10⁹ cycles
/// stepping, and with a = 0.5 their slips of round-off size held the jumps at a few cycles).
pub const RESIDUAL_PRESSURE: f64 = 1e-9;

/// Points that carry pressure (above [`RESIDUAL_PRESSURE`] of the largest, at some instant of
/// the cycle: the coupled cycle's shear presses points the normal load alone leaves open)
/// and slip in the state's cycle.
fn slipping(state: &State) -> usize {
    let n = state.pressure.len();
    let largest_at = |i: usize| {
        (state.cycle_pressures.iter())
            .map(|p| p[i])
            .fold(state.pressure[i], f64::max)
    };
    let largest = (0..n).map(largest_at).fold(0.0f64, f64::max);
    (0..n)
        .filter(|&i| largest_at(i) > RESIDUAL_PRESSURE * largest && !state.cycle.never_slips[i])
        .count()
}

fn profiles(cycles: f64, state: &State) -> FrettingProfiles {
    FrettingProfiles {
        cycles,
        pressure: state.pressure.clone(),
        shape: state.shape.clone(),
        wear: state.wear.clone(),
        slip_amplitude: state.cycle.slip_amplitude.clone(),
        never_slips: state.cycle.never_slips.clone(),
        cycle_loop: state
            .cycle
            .states
            .iter()
            .map(|s| (s.shift, s.load))
            .collect(),
    }
}

/// The frictionless normal solve of worn shape `shape`: the pressure, MPa.
fn normal_solve(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    shape: &[f64],
    solves: &mut usize,
) -> Result<Vec<f64>, FrettingStop> {
    let n = contact.len();
    solver.set_compliance(&vec![0.0; n]);
    let gap: Vec<f64> = (contact.points.initial_gap.iter().zip(shape))
        .map(|(g, s)| g + s)
        .collect();
    let mut out = ContactSolution::default();
    let info = solver.solve_into(&gap, Direction::Plus, &mut out);
    *solves += 1;
    if info.status != Status::Solved {
        return Err(FrettingStop::ContactSolve {
            complementarity: info.complementarity,
            equilibrium: info.equilibrium,
        });
    }
    Ok(out.pressure)
}

/// The periodic cycle of worn shape `shape` at pressure `pressure` (MPa).
fn cycle_at(
    model: &mut dyn CycleModel,
    pressure: &[f64],
    shape: &[f64],
    area: &[f64],
) -> Result<(FrettingCycle, Vec<Vec<f64>>), FrettingStop> {
    let normal_force: Vec<f64> = pressure.iter().zip(area).map(|(p, a)| p * a).collect();
    let (cycle, forces) = model
        .cycle(&normal_force, shape)
        .map_err(FrettingStop::Cycle)?;
    let pressures = forces
        .iter()
        .map(|f| f.iter().zip(area).map(|(f, a)| f / a).collect())
        .collect();
    Ok((cycle, pressures))
}

/// Each law's wear at each point over `jump` cycles as W = c pᵇ + e in the pressure p
/// (MPa) of the frictionless solve, exact at the state's own: c and e are jump β̃ times
/// [`FrettingCycle::weighted_sliding_term`]'s term and extra.
fn step_terms(input: &FrettingWearInput, state: &State, jump: f64) -> Vec<StepTerms> {
    input
        .laws
        .iter()
        .map(|(_, l)| {
            let (term, extra) = state.cycle.weighted_sliding_term(
                (l.a, l.b),
                input.omega,
                &state.cycle_pressures,
                &state.pressure,
            );
            let scale = |v: Vec<f64>| v.iter().map(|t| jump * l.beta * t).collect();
            StepTerms {
                coefficient: scale(term),
                held: scale(extra),
            }
        })
        .collect()
}

/// One law's wear over a step, W_i = c_i pᵇ + e_i.
struct StepTerms {
    /// c_i, mm/MPaᵇ.
    coefficient: Vec<f64>,
    /// e_i, mm: the wear of the cycle's pressure beyond the frictionless solve's, held.
    held: Vec<f64>,
}

impl StepTerms {
    /// The wear at point `i` under pressure `p` (MPa), mm.
    fn wear(&self, i: usize, b: f64, p: f64) -> f64 {
        law::half_period_wear(&[(self.coefficient[i], b)], p) + self.held[i]
    }
}

/// The implicit step of `jump` cycles from `state` with the slip terms of its cycle.
fn implicit_step(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    input: &FrettingWearInput,
    state: &State,
    jump: f64,
    area: &[f64],
    solves: &mut usize,
) -> Result<State, FrettingStop> {
    let n = contact.len();
    let coefficients = step_terms(input, state, jump);
    let terms_at = |i: usize| -> Vec<(f64, f64)> {
        (input.laws.iter().zip(&coefficients))
            .map(|((_, l), c)| (c.coefficient[i], l.b))
            .collect()
    };
    let loaded: Vec<f64> = state
        .pressure
        .iter()
        .copied()
        .filter(|p| *p > 0.0)
        .collect();
    let reference = loaded.iter().sum::<f64>() / loaded.len().max(1) as f64;
    let linear = input.laws.iter().all(|(_, l)| l.b == 1.0);
    let mut guess = state.pressure.clone();
    let mut compliance = vec![0.0; n];
    let mut gap = vec![0.0; n];
    let mut out = ContactSolution::default();
    for iteration in 1..=input.max_iterations {
        let mut slopes = vec![0.0; n];
        for i in 0..n {
            let terms = terms_at(i);
            let slope = if linear {
                terms.iter().map(|t| t.0).sum()
            } else {
                law::newton_slope(&terms, guess[i], reference, false)
            };
            let wear = law::half_period_wear(&terms, guess[i]);
            slopes[i] = slope;
            compliance[i] = slope / area[i];
            let held: f64 = coefficients.iter().map(|c| c.held[i]).sum();
            gap[i] = contact.points.initial_gap[i]
                + state.shape[i]
                + held
                + if linear { 0.0 } else { wear - slope * guess[i] };
        }
        solver.set_compliance(&compliance);
        let info = solver.solve_into(&gap, Direction::Plus, &mut out);
        *solves += 1;
        if info.status != Status::Solved {
            return Err(FrettingStop::ContactSolve {
                complementarity: info.complementarity,
                equilibrium: info.equilibrium,
            });
        }
        // The linear model's wear against the law's at the new pressure.
        let mut largest = 0.0f64;
        let mut error = 0.0f64;
        for i in 0..n {
            let terms = terms_at(i);
            let model =
                law::half_period_wear(&terms, guess[i]) + slopes[i] * (out.pressure[i] - guess[i]);
            let actual = law::half_period_wear(&terms, out.pressure[i]);
            largest = largest.max(actual.abs());
            error = error.max((actual - model).abs());
        }
        let converged = linear || error <= input.newton_tolerance * largest;
        if converged {
            let mut next_wear = state.wear.clone();
            let mut shape = state.shape.clone();
            for ((body, l), c) in input.laws.iter().zip(&coefficients) {
                for i in 0..n {
                    let w = c.wear(i, l.b, out.pressure[i]);
                    next_wear[*body][i] += w;
                    shape[i] += w;
                }
            }
            return Ok(State {
                shape,
                wear: next_wear,
                pressure: out.pressure.clone(),
                cycle: state.cycle.clone(),
                cycle_pressures: state.cycle_pressures.clone(),
            });
        }
        for i in 0..n {
            // A concave law's next linearisation point as the sliding run's step takes it:
            // the point's own gap equation with the model's wear (its own flexibility, the
            // terms holding the jump already).
            let own = contact.a_nn[i * n + i] * area[i];
            let p = out.pressure[i];
            guess[i] = if p > 0.0 {
                law::balanced_step(&terms_at(i), guess[i], slopes[i], p, own)
            } else {
                p
            };
        }
        if iteration == input.max_iterations {
            return Err(FrettingStop::Newton {
                iterations: iteration,
                error: error / largest.max(f64::MIN_POSITIVE),
            });
        }
    }
    unreachable!("the loop returns at its last iteration")
}

/// The jump's local error estimate, relative to its largest wear: half the change of the
/// wear increment between the terms of the step's start and of its end, at the end pressure.
fn jump_error(input: &FrettingWearInput, (start, end): (&State, &State), jump: f64) -> f64 {
    // The start's slip terms (weighted against the start's own pressure) and the end's, both
    // taken at the end's pressure.
    let before = step_terms(input, start, jump);
    let after = step_terms(input, end, jump);
    let n = end.pressure.len();
    let (mut largest, mut error) = (0.0f64, 0.0f64);
    for i in 0..n {
        let (mut held, mut ended) = (0.0, 0.0);
        for (((_, l), c0), c1) in input.laws.iter().zip(&before).zip(&after) {
            held += c0.wear(i, l.b, end.pressure[i]);
            ended += c1.wear(i, l.b, end.pressure[i]);
        }
        largest = largest.max(held);
        error = error.max(0.5 * (ended - held).abs());
    }
    if largest > 0.0 {
        error / largest
    } else {
        0.0
    }
}
