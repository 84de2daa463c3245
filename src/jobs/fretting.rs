//! The fretting jobs: `contact` (the normal load, then one periodic fretting cycle with stick
//! and slip) and `run` (wear by the local slip over many cycles). A problem with a
//! `[fretting]` section takes these instead of the full-slip ones.
//!
//! The normal load is applied first, frictionless (Cattaneo's assumption: the tangential
//! forces do not change the pressure, exact for two bodies of one material in the half-space
//! limit), and μ acts in the tangential problem only ([`crate::partial_slip`]).

use super::driver::{method, JobError};
use crate::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::fretting::{
    Coupled, CoupledError, CycleModel, FrettingControl, FrettingCycle, Uncoupled,
};
use crate::fretting_input::FrettingSettings;
use crate::partial_slip::PartialSlipError;
use crate::problem::{Problem, ProblemError};
use crate::report::json::{number, numbers};
use crate::wear::fretting::{FrettingHistory, FrettingStep, FrettingStop, FrettingWearInput};
use serde_json::{json, Value};
use std::time::Instant;

/// Whether `problem` is a fretting problem (it has a `[fretting]` section).
pub fn is_fretting(problem: &Problem) -> bool {
    problem.spec.fretting.is_some()
}

/// Refuse a fretting problem in a job of full slip (`what`), which would otherwise solve it
/// with every point sliding and say nothing: the fretting jobs are this module's.
pub fn require_full_slip(problem: &Problem, what: &str) -> Result<(), ProblemError> {
    if is_fretting(problem) {
        return Err(problem.error("fretting", format!("this problem has a [fretting] section, and {what} would slide every point: use the fretting jobs (`wearfem contact`, `run`, `steady` choose them; library: wearfem::jobs::fretting)")));
    }
    Ok(())
}

/// A fretting problem's contact, ready for its cycles.
pub struct FrettingSetup {
    /// The settings.
    pub settings: FrettingSettings,
    /// The condensed contact, frictionless (the normal problem's).
    pub contact: CondensedContact,
    /// A_tt, mm/N.
    pub a_tt: Vec<f64>,
    /// Contact area of each point, mm².
    pub area: Vec<f64>,
    /// Set-up time, s.
    pub seconds: f64,
}

impl FrettingSetup {
    /// Condense the contact of `problem` and its tangential flexibility.
    pub fn new(problem: &Problem) -> Result<FrettingSetup, JobError> {
        let start = Instant::now();
        let settings = problem
            .fretting_settings()?
            .ok_or_else(|| problem.error("fretting", "this problem has no [fretting] section"))?;
        let (mut contact, body1, body2) = CondensedContact::build(problem)?;
        let a_tt = contact.tangential_flexibility(problem, &body1, &body2)?;
        // The normal load is applied without tangential traction.
        contact.friction = 0.0;
        let area = contact.areas();
        Ok(FrettingSetup {
            settings,
            contact,
            a_tt,
            area,
            seconds: start.elapsed().as_secs_f64(),
        })
    }

    /// The contact points' x, mm.
    pub fn x(&self) -> Vec<f64> {
        self.contact.points.x.iter().map(|p| p[0]).collect()
    }

    /// The tangents' x components.
    pub fn tangent_x(&self) -> Vec<f64> {
        self.contact.points.tangent.iter().map(|t| t[0]).collect()
    }

    /// The cycle model the settings ask for: coupled (its own frictionless solver) or not.
    pub fn model<'a>(
        &'a self,
        problem: &Problem,
        tangent_x: &'a [f64],
    ) -> Result<Box<dyn CycleModel + 'a>, ProblemError> {
        let s = &self.settings;
        Ok(if s.coupled {
            Box::new(Coupled {
                a_tt: &self.a_tt,
                friction: s.friction,
                loading: s.loading,
                contact: &self.contact,
                solver: ContactSolver::new(&self.contact, method(problem)?),
                solves: 0,
            })
        } else {
            Box::new(Uncoupled {
                a_tt: &self.a_tt,
                tangent_x,
                friction: s.friction,
                loading: s.loading,
            })
        })
    }
}

/// The result of `contact` on a fretting problem.
pub struct FrettingContact {
    /// The set-up.
    pub setup: FrettingSetup,
    /// The normal solve.
    pub normal: ContactSolution,
    /// The periodic cycle.
    pub cycle: FrettingCycle,
    /// Each state's normal forces, N (the normal loading's throughout when uncoupled).
    pub cycle_forces: Vec<Vec<f64>>,
    /// The friction limit μ Σ P |τ_x|, N.
    pub limit: f64,
    /// Wall time of the solves, s.
    pub seconds: f64,
}

impl FrettingContact {
    /// The edges (mm) of the stick zone at the cycle's peak (the virgin loading to the
    /// amplitude), each between the points, fitted through the three outermost stick points
    /// on its side: the margin μp − |q| vanishes there like the square root of the distance
    /// ([`crate::checks::edge_fit::square_root_edge_one_sided`]). None with fewer than three
    /// stick points.
    pub fn peak_stick_edges(&self) -> Option<(f64, f64)> {
        let x = self.setup.x();
        let (peak, forces, area) = (
            &self.cycle.states[0],
            &self.cycle_forces[0],
            &self.setup.area,
        );
        let friction = self.setup.settings.friction;
        let mut stick: Vec<usize> = (0..x.len()).filter(|&i| peak.stick[i]).collect();
        if stick.len() < 3 {
            return None;
        }
        stick.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
        // In pressure: the points' forces carry their quadrature weights.
        let sample = |&i: &usize| (x[i], (friction * forces[i] - peak.force[i].abs()) / area[i]);
        let edge = |points: &[usize]| {
            crate::checks::edge_fit::square_root_edge_one_sided(points.iter().map(sample))
        };
        let k = stick.len();
        Some((edge(&stick[..3]), edge(&stick[k - 3..])))
    }
}

/// The normal solve, then one periodic fretting cycle.
pub fn contact(problem: &Problem) -> Result<FrettingContact, JobError> {
    let setup = FrettingSetup::new(problem)?;
    let start = Instant::now();
    let mut solver = ContactSolver::new(&setup.contact, method(problem)?);
    let (normal, info) = solver.solve(&setup.contact.points.initial_gap, Direction::Plus);
    if info.status != Status::Solved {
        return Err(JobError::Compute(format!("the normal contact solve did not converge (complementarity residual {:.3e}, equilibrium residual {:.3e}); nothing was written", info.complementarity, info.equilibrium)));
    }
    if normal.pressure.iter().all(|p| *p <= 0.0) {
        return Err(no_contact(problem));
    }
    let normal_force: Vec<f64> = (normal.pressure.iter().zip(&setup.area))
        .map(|(p, a)| p * a)
        .collect();
    let tangent_x = setup.tangent_x();
    let (cycle, cycle_forces) = {
        let mut model = setup.model(problem, &tangent_x)?;
        model
            .cycle(&normal_force, &vec![0.0; normal_force.len()])
            .map_err(|e| cycle_error(problem, &setup.settings, e))?
    };
    let limit = setup.settings.friction
        * (normal_force.iter().zip(&tangent_x))
            .map(|(f, t)| f * t.abs())
            .sum::<f64>();
    Ok(FrettingContact {
        setup,
        normal,
        cycle,
        cycle_forces,
        limit,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// What a cycle's failure means: under force control a load at the friction limit is bad
/// input (gross slip, exit 2), anything else a failed computation.
fn cycle_error(problem: &Problem, settings: &FrettingSettings, error: CoupledError) -> JobError {
    match (&error, settings.loading.control) {
        (
            CoupledError::Tangential(PartialSlipError::GrossSlip { load, limit }),
            FrettingControl::Force,
        ) => JobError::Problem(gross_slip_error(problem, *load, *limit)),
        _ => JobError::Compute(format!("the fretting cycle: {error}; nothing was written")),
    }
}

/// No contact under the normal load: the problem presses nothing (bad input, exit 2).
fn no_contact(problem: &Problem) -> JobError {
    problem
        .error("fretting", FrettingStop::NoContact.to_string())
        .into()
}

fn gross_slip_error(problem: &Problem, load: f64, limit: f64) -> ProblemError {
    problem.error("fretting.amplitude", format!("Q₀ = {load:.6e} N reaches the friction limit μP = {limit:.6e} N: that is gross slip, under which a force-controlled cycle has no defined shift. Give Q₀ < μP for partial slip, or fretting.loading = \"displacement\" with δ₀ beyond the gross-slip shift for gross slip"))
}

/// A fretting run's results.
pub struct FrettingRun {
    /// The set-up.
    pub setup: FrettingSetup,
    /// The history.
    pub history: FrettingHistory,
    /// Run time, s.
    pub seconds: f64,
}

/// The fretting wear run of `problem`; `cycles` overrides `wear.cycles`.
pub fn run(
    problem: &Problem,
    cycles: Option<f64>,
    on_step: impl FnMut(&FrettingStep),
) -> Result<FrettingRun, JobError> {
    let setup = FrettingSetup::new(problem)?;
    let wear = setup.settings.wear.clone().ok_or_else(|| {
        problem.error(
            "wear",
            "this fretting problem has no [wear] section: give the wear laws (wear.body1, wear.body2) and wear.cycles",
        )
    })?;
    let start = Instant::now();
    let mut solver = ContactSolver::new(&setup.contact, method(problem)?);
    let tangent_x = setup.tangent_x();
    let mut model = setup.model(problem, &tangent_x)?;
    let input = FrettingWearInput {
        laws: &wear.laws,
        omega: wear.omega,
        cycles: cycles.unwrap_or(wear.cycles),
        record_cycles: &wear.record_cycles,
        tolerance: setup.settings.tolerance,
        max_iterations: wear.max_iterations,
        newton_tolerance: wear.newton_tolerance,
    };
    let history =
        crate::wear::fretting::run(&mut solver, &setup.contact, model.as_mut(), &input, on_step)
            .map_err(|stop| match stop {
                FrettingStop::Cycle(e) => cycle_error(problem, &setup.settings, e),
                // Bad input, as `contact` and `steady` say it (exit 2, the key).
                FrettingStop::NoContact => problem
                    .error("fretting", FrettingStop::NoContact.to_string())
                    .into(),
                other => {
                    JobError::Compute(format!("the first cycle: {other}; nothing was written"))
                }
            });
    drop(model);
    let history = history?;
    Ok(FrettingRun {
        setup,
        history,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The result of `steady` on a fretting problem: the final worn state of partial slip.
pub struct FrettingSteady {
    /// The set-up.
    pub setup: FrettingSetup,
    /// The final state.
    pub state: crate::steady_state::fretting::FrettingFinalState,
    /// Solve time, s.
    pub seconds: f64,
}

/// The final worn state of `problem` in partial slip, directly; in gross slip (nothing sticks
/// through the cycle) the periodic steady state.
pub fn steady(problem: &Problem) -> Result<FrettingSteady, JobError> {
    use crate::steady_state::fretting::{final_state, gross_slip_steady, FinalStateError};
    let setup = FrettingSetup::new(problem)?;
    if setup.settings.coupled {
        return Err(problem.error("fretting.coupled", "the final state of the coupled problem is not built: its worn points must stay open at every instant of the cycle, whose shear moves the pressure (`wearfem run` integrates it). fretting.coupled = false gives Cattaneo's uncoupled final state (exact for one material in the half-space limit); the coupled problem is the default when the bodies' materials differ").into());
    }
    let start = Instant::now();
    let mut solver = ContactSolver::new(&setup.contact, method(problem)?);
    let tangent_x = setup.tangent_x();
    let mut model = setup.model(problem, &tangent_x)?;
    let state = match final_state(&mut solver, &setup.contact, model.as_mut()) {
        // Nothing sticks through the cycle: the periodic steady state of gross slip.
        Err(FinalStateError::GrossSlip) => {
            let wear = setup.settings.wear.as_ref().ok_or_else(|| {
                problem.error(
                    "wear",
                    "this fretting problem is in gross slip, whose steady state needs the wear laws: give [wear] (wear.body1, wear.body2)",
                )
            })?;
            let laws: Vec<(f64, f64, f64)> =
                wear.laws.iter().map(|(_, l)| (l.beta, l.a, l.b)).collect();
            gross_slip_steady(
                &mut solver,
                &setup.contact,
                model.as_mut(),
                &laws,
                wear.omega,
            )
        }
        other => other,
    }
    .map_err(|e| match e {
        FinalStateError::Cycle(e) => cycle_error(problem, &setup.settings, e),
        FinalStateError::NoContact => no_contact(problem),
        FinalStateError::PlateMotion => JobError::Problem(problem.error("plate.motion", e.to_string())),
        FinalStateError::GrossSlipLost => JobError::Problem(problem.error("fretting.amplitude", e.to_string())),
        other => JobError::Compute(format!("the steady state: {other}; nothing was written")),
    });
    drop(model);
    let state = state?;
    Ok(FrettingSteady {
        setup,
        state,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// What summary.json says of the loading and a cycle.
pub fn cycle_json(setup: &FrettingSetup, cycle: &FrettingCycle) -> Value {
    let loading = &setup.settings.loading;
    let x = setup.x();
    json!({
        "loading": match loading.control { FrettingControl::Force => "force", FrettingControl::Displacement => "displacement" },
        "amplitude": number(loading.amplitude),
        "amplitude_unit": match loading.control { FrettingControl::Force => "N", FrettingControl::Displacement => "mm" },
        "stages_per_half_cycle": loading.stages,
        "friction": number(setup.settings.friction),
        "peak_load_N": number(cycle.states[0].load),
        "peak_shift_mm": number(cycle.states[0].shift),
        "dissipated_per_cycle_Nmm": number(cycle.dissipated),
        "loop_area_Nmm": number(cycle.loop_area),
        "stick_zone_mm": cycle.stick_extent(&x).map(|(a, b)| json!([number(a), number(b)])),
        "gross_slip": cycle.gross_slip,
    })
}

/// The share of the contact zone's width past which the cycle's largest shift breaks the
/// fixed contact pairs that fretting assumes (its slip small against the contact), as the
/// sliding model's `stroke` warning does for a stroke against the contact edge.
pub const STROKE_SHARE: f64 = 0.1;

/// The warnings of a fretting cycle: `fretting-stroke` when the plate's largest shift over the
/// cycle exceeds [`STROKE_SHARE`] of the zone that carries shear at the cycle's peak.
pub fn cycle_warnings(
    problem: &Problem,
    setup: &FrettingSetup,
    cycle: &FrettingCycle,
) -> Vec<String> {
    let x = setup.x();
    let Some(peak) = cycle.states.first() else {
        return Vec::new();
    };
    let carrying = || (0..x.len()).filter(|&i| peak.force[i] != 0.0).map(|i| x[i]);
    let width =
        carrying().fold(f64::NEG_INFINITY, f64::max) - carrying().fold(f64::INFINITY, f64::min);
    let shift = cycle
        .states
        .iter()
        .fold(0.0f64, |m, s| m.max(s.shift.abs()));
    if width > 0.0 && shift > STROKE_SHARE * width {
        vec![crate::checks::codes::warning(
            "fretting-stroke",
            &problem.file,
            format!("fretting: the plate shifts by up to {shift:.4e} mm in the cycle, {:.0} % of the {width:.4} mm contact zone: fretting's contact pairs are fixed (its slip small against the contact), which a shift of that size is not; the results are those of fixed partners", 100.0 * shift / width),
        )]
    } else {
        Vec::new()
    }
}

impl FrettingContact {
    /// What `wearfem contact` writes as summary.json (and Python's `fretting_contact`
    /// returns): the cycle's figures and the profiles along the contact (x mm, the normal
    /// loading's pressure MPa, the shear at the peak MPa, whether each point sticks, its slip
    /// in a half cycle mm).
    pub fn summary(&self, problem: &Problem) -> Value {
        let setup = &self.setup;
        let peak = &self.cycle.states[0];
        let shear: Vec<f64> = (peak.force.iter().zip(&setup.area))
            .map(|(f, a)| f / a)
            .collect();
        json!({
            "title": problem.spec.title,
            "wearfem_version": crate::VERSION,
            "points": setup.contact.len(),
            "coupled": setup.settings.coupled,
            "peak_pressure_MPa": number(self.normal.pressure.iter().fold(0.0f64, |m, p| m.max(*p))),
            "friction_limit_N": number(self.limit),
            "fretting": cycle_json(setup, &self.cycle),
            "x": numbers(&setup.x()),
            "pressure": numbers(&self.normal.pressure),
            "shear_at_peak": numbers(&shear),
            "sticks": self.cycle.never_slips,
            "slip_amplitude": numbers(&self.cycle.slip_amplitude),
            "setup_seconds": setup.seconds,
            "seconds": self.seconds,
            "warnings": cycle_warnings(problem, setup, &self.cycle),
        })
    }
}

impl FrettingRun {
    /// What `wearfem run` writes as summary.json (and Python's `fretting_run` returns), with
    /// the final profiles (x mm, pressure MPa, worn depth mm, each body's wear mm).
    pub fn summary(&self, problem: &Problem) -> Value {
        let h = &self.history;
        let setup = &self.setup;
        let last = h.steps.last();
        let end = h.records.last();
        json!({
            "title": problem.spec.title,
            "wearfem_version": crate::VERSION,
            "points": setup.contact.len(),
            "cycles": last.map_or(0.0, |s| s.cycles),
            "steps": h.steps.len(),
            "solves": h.solves,
            "wear_stopped_at_cycle": h.wear_stopped,
            "stopped": h.stopped.as_ref().map(|(step, why)| json!({"step": step, "reason": why.to_string()})),
            "first_cycle": cycle_json(setup, &h.first_cycle),
            "last_cycle": cycle_json(setup, &h.last_cycle),
            "deepest_wear_mm": last.map(|s| numbers(&s.deepest_wear)),
            "final": end.map(|r| json!({
                "cycles": r.cycles,
                "x": numbers(&setup.x()),
                "pressure": numbers(&r.pressure),
                "worn_depth": numbers(&r.shape),
                "wear_body1": numbers(&r.wear[0]),
                "wear_body2": numbers(&r.wear[1]),
                "sticks": r.never_slips,
            })),
            "setup_seconds": setup.seconds,
            "seconds": self.seconds,
            "warnings": cycle_warnings(problem, setup, &h.first_cycle),
        })
    }
}

impl FrettingSteady {
    /// What `wearfem steady` writes as summary.json (and Python's `fretting_steady` returns),
    /// with the final state's profiles (x mm, pressure MPa, worn depth mm, the stick set).
    pub fn summary(&self, problem: &Problem) -> Value {
        let s = &self.state;
        let setup = &self.setup;
        json!({
            "title": problem.spec.title,
            "wearfem_version": crate::VERSION,
            "status": if s.gross_slip { "gross_slip_steady_state" } else { "final_state" },
            "points": setup.contact.len(),
            "iterations": s.iterations,
            "peak_pressure_MPa": number(s.pressure.iter().fold(0.0f64, |m, p| m.max(*p))),
            "deepest_wear_mm": number(s.shape.iter().fold(0.0f64, |m, w| m.max(*w))),
            "first_cycle": cycle_json(setup, &s.first_cycle),
            "final_cycle": cycle_json(setup, &s.cycle),
            "x": numbers(&setup.x()),
            "initial_pressure": numbers(&s.initial_pressure),
            "pressure": numbers(&s.pressure),
            "worn_depth": numbers(&s.shape),
            "in_final_stick_set": s.stick,
            "setup_seconds": setup.seconds,
            "seconds": self.seconds,
            "warnings": cycle_warnings(problem, setup, &s.first_cycle),
        })
    }
}
