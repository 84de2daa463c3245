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
use crate::fretting::{FrettingControl, FrettingCycle};
use crate::fretting_input::FrettingSettings;
use crate::partial_slip::{PartialSlipError, TangentialProblem};
use crate::problem::{Problem, ProblemError};
use crate::wear::fretting::{FrettingHistory, FrettingStep, FrettingStop, FrettingWearInput};
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
}

/// The result of `contact` on a fretting problem.
pub struct FrettingContact {
    /// The set-up.
    pub setup: FrettingSetup,
    /// The normal solve.
    pub normal: ContactSolution,
    /// The periodic cycle.
    pub cycle: FrettingCycle,
    /// The friction limit μ Σ P |τ_x|, N.
    pub limit: f64,
    /// Wall time of the solves, s.
    pub seconds: f64,
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
    let normal_force: Vec<f64> = (normal.pressure.iter().zip(&setup.area))
        .map(|(p, a)| p * a)
        .collect();
    let tangent_x = setup.tangent_x();
    let problem_t = TangentialProblem {
        a_tt: &setup.a_tt,
        tangent_x: &tangent_x,
        normal_force: &normal_force,
        friction: setup.settings.friction,
    };
    let cycle = FrettingCycle::solve(&problem_t, &setup.settings.loading)
        .map_err(|e| tangential_error(problem, &setup.settings, e))?;
    let limit = setup.settings.friction
        * (normal_force.iter().zip(&tangent_x))
            .map(|(f, t)| f * t.abs())
            .sum::<f64>();
    Ok(FrettingContact {
        setup,
        normal,
        cycle,
        limit,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// What the tangential problem's failure means: under force control a load at the friction
/// limit is bad input (gross slip, exit 2), anything else a failed computation.
fn tangential_error(
    problem: &Problem,
    settings: &FrettingSettings,
    error: PartialSlipError,
) -> JobError {
    match (&error, settings.loading.control) {
        (PartialSlipError::GrossSlip { load, limit }, FrettingControl::Force) => {
            JobError::Problem(gross_slip_error(problem, *load, *limit))
        }
        _ => JobError::Compute(format!("{error}; nothing was written")),
    }
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
    let input = FrettingWearInput {
        a_tt: &setup.a_tt,
        loading: setup.settings.loading,
        friction: setup.settings.friction,
        laws: &wear.laws,
        omega: wear.omega,
        cycles: cycles.unwrap_or(wear.cycles),
        record_cycles: &wear.record_cycles,
        tolerance: setup.settings.tolerance,
        max_iterations: wear.max_iterations,
        newton_tolerance: wear.newton_tolerance,
    };
    let history = crate::wear::fretting::run(&mut solver, &setup.contact, &input, on_step)
        .map_err(|stop| match stop {
            FrettingStop::Tangential(e) => tangential_error(problem, &setup.settings, e),
            other => JobError::Compute(format!("the first cycle: {other}; nothing was written")),
        })?;
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

/// The final worn state of `problem` in partial slip, directly.
pub fn steady(problem: &Problem) -> Result<FrettingSteady, JobError> {
    use crate::steady_state::fretting::{final_state, FinalStateError};
    let setup = FrettingSetup::new(problem)?;
    let start = Instant::now();
    let mut solver = ContactSolver::new(&setup.contact, method(problem)?);
    let state = final_state(
        &mut solver,
        &setup.contact,
        &setup.a_tt,
        setup.settings.friction,
        &setup.settings.loading,
    )
    .map_err(|e| match e {
        FinalStateError::Tangential(e) => tangential_error(problem, &setup.settings, e),
        FinalStateError::GrossSlip => JobError::Problem(problem.error("fretting.amplitude", format!("{}: `wearfem run` integrates it (a steady state of gross-slip fretting is not built yet)", FinalStateError::GrossSlip))),
        other => JobError::Compute(format!("the final state: {other}; nothing was written")),
    })?;
    Ok(FrettingSteady {
        setup,
        state,
        seconds: start.elapsed().as_secs_f64(),
    })
}
