//! The three jobs of the command line as library functions: a static elastic solve, one
//! contact solve and a wear run. Each returns its results; [`crate::output`] writes them.

use crate::complementarity::{
    ContactSolution, ContactSolver, Direction, Method, SolveInfo, Status,
};
use crate::contact::CondensedContact;
use crate::fields::strain_energy;
use crate::output::{number, numbers};
use crate::problem::{Problem, ProblemError};
use crate::wear::{WearHistory, WearIntegrator};
use serde_json::{json, Value};
use std::time::Instant;

/// Errors of a job: bad input, or a computation that could not be carried out.
#[derive(Debug, thiserror::Error)]
pub enum JobError {
    /// The problem file is wrong.
    #[error(transparent)]
    Problem(#[from] ProblemError),
    /// The input is fine but the computation failed (a contact solve inside a §6 method).
    #[error("{0}")]
    Compute(String),
}

/// Static elastic solve of every body: dofs, strain energy and probe values.
pub fn elastic(problem: &Problem) -> Result<Value, JobError> {
    let start = Instant::now();
    let mut energy = 0.0;
    let mut dofs = 0;
    let mut condensed = 0;
    let mut probes = serde_json::Map::new();
    for b in 0..problem.spec.bodies.len() {
        let body = problem.elastic_body(b, &[])?;
        let load = problem.load_vector(b, &body, &[])?;
        let u = body.solve(&load);
        energy += strain_energy(&load, &u);
        dofs += body.info.total_dofs;
        condensed += body.info.condensed_dofs;
        for (name, probe) in &problem.spec.probes {
            if probe.body != body.name {
                continue;
            }
            let v = body.values_at(&u, probe.at).ok_or_else(|| {
                problem.error(
                    format!("probes.{name}.at"),
                    format!(
                        "({}, {}) is not inside body \"{}\"",
                        probe.at[0], probe.at[1], probe.body
                    ),
                )
            })?;
            probes.insert(name.clone(), json!({ "displacement": numbers(&v.displacement), "stress": numbers(&v.stress), "strain": numbers(&v.strain) }));
        }
    }
    Ok(json!({
        "title": problem.spec.title,
        "dofs": dofs,
        "condensed_dofs": condensed,
        "strain_energy": number(energy),
        "probes": probes,
        "seconds": start.elapsed().as_secs_f64(),
    }))
}

/// The solver method named in the problem's `[contact]` section.
pub fn method(problem: &Problem) -> Result<Method, ProblemError> {
    let c = problem
        .spec
        .contact
        .as_ref()
        .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
    match c.method.as_str() {
        "active_set" => Ok(Method::ActiveSet),
        "lemke" => Ok(Method::Lemke),
        "penalty" => match c.penalty {
            Some(k) if k.is_finite() && k > 0.0 => Ok(Method::Penalty { stiffness: k }),
            other => Err(problem.error(
                "contact.penalty",
                match other {
                    Some(k) => format!("method \"penalty\" needs penalty > 0 (MPa/mm), got {k}"),
                    None => {
                        "method \"penalty\" needs penalty > 0 (MPa/mm), which is missing".into()
                    }
                },
            )),
        },
        other => Err(problem.error(
            "contact.method",
            format!("must be \"active_set\", \"lemke\" or \"penalty\", got \"{other}\""),
        )),
    }
}

/// The first sliding direction named in the problem.
pub fn direction(problem: &Problem) -> Result<Direction, ProblemError> {
    let c = problem
        .spec
        .contact
        .as_ref()
        .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
    match c.direction.as_str() {
        "+" => Ok(Direction::Plus),
        "-" | "−" => Ok(Direction::Minus),
        other => Err(problem.error(
            "contact.direction",
            format!("must be \"+\" or \"-\", got \"{other}\""),
        )),
    }
}

/// Indices of the contact points nearest to the problem's probes on the contact body.
pub fn contact_probes(problem: &Problem, contact: &CondensedContact) -> Vec<(String, usize)> {
    let body = problem
        .spec
        .contact
        .as_ref()
        .map(|c| c.body.clone())
        .unwrap_or_default();
    problem
        .spec
        .probes
        .iter()
        .filter(|(_, p)| p.body == body)
        .map(|(name, p)| {
            let i = (0..contact.len())
                .min_by(|&i, &j| {
                    dist(contact.points.x[i], p.at).total_cmp(&dist(contact.points.x[j], p.at))
                })
                .unwrap_or(0);
            (name.clone(), i)
        })
        .collect()
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn info_json(info: &SolveInfo) -> Value {
    json!({
        "status": if info.status == Status::Solved { "solved" } else { "failed" },
        "iterations": info.iterations,
        "factorisations": info.factorisations,
        "lemke_pivots": info.lemke_pivots,
        "complementarity": number(info.complementarity),
        "equilibrium": number(info.equilibrium),
    })
}

/// One contact solve of the initial configuration.
pub fn contact(
    problem: &Problem,
) -> Result<(Value, CondensedContact, ContactSolution, SolveInfo), JobError> {
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    let setup = start.elapsed().as_secs_f64();
    let mut solver = ContactSolver::new(&contact, method(problem)?);
    let (solution, info) = solver.solve(&contact.points.initial_gap, direction(problem)?);
    let rigid = crate::output::named(&contact.rigid_names, &solution.rigid);
    let probes: serde_json::Map<String, Value> = contact_probes(problem, &contact)
        .into_iter()
        .map(|(n, i)| (n, number(solution.pressure[i])))
        .collect();
    let summary = json!({
        "title": problem.spec.title,
        "points": contact.len(),
        "x": contact.points.x.iter().map(|p| number(p[0])).collect::<Vec<_>>(),
        "z": contact.points.x.iter().map(|p| number(p[1])).collect::<Vec<_>>(),
        "pressure": numbers(&solution.pressure),
        "gap": numbers(&solution.gap),
        "rigid": rigid,
        "probes": probes,
        "iterations": info.iterations,
        "residuals": { "complementarity": number(info.complementarity), "equilibrium": number(info.equilibrium) },
        "solve": info_json(&info),
        "plate_force": numbers(&contact.plate_resultant.0),
        "plate_moment": number(contact.plate_resultant.1),
        "setup_seconds": setup,
    });
    // A failed solve is returned too (status in `info`): the caller writes it and says so.
    Ok((summary, contact, solution, info))
}

/// A finished wear run with its set-up.
pub struct WearRun {
    /// The condensed contact problem.
    pub contact: CondensedContact,
    /// Step history and final profiles.
    pub history: WearHistory,
    /// Probe names and their contact point indices.
    pub probes: Vec<(String, usize)>,
    /// Seconds spent on the FE set-up and condensation.
    pub setup_seconds: f64,
    /// Seconds spent integrating.
    pub run_seconds: f64,
}

/// Run the wear integration of `problem` (optionally overriding the number of steps).
pub fn wear(
    problem: &Problem,
    steps: Option<usize>,
    on_step: impl FnMut(&crate::wear::StepRecord),
) -> Result<WearRun, JobError> {
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let mut spec = spec;
    if let Some(n) = steps {
        spec.steps = n;
    }
    let mut integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    integrator.first_direction = direction(problem)?;
    let plate_moves = problem
        .spec
        .plate
        .as_ref()
        .is_some_and(|p| p.motion != "fixed");
    if spec.shape_zero_at.is_some() && !plate_moves {
        // The shift is a vertical rigid translation of the punch, which only leaves the
        // pressures unchanged if the plate can take it up through λ_F.
        return Err(problem
            .error(
                "wear.shape_zero_at",
                "shifting the shape needs a plate that moves vertically (plate.motion = \"vertical\" or \"vertical_rotation\"); remove the key or free the plate",
            )
            .into());
    }
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    let mut solver = ContactSolver::new(&contact, method(problem)?);
    let setup_seconds = start.elapsed().as_secs_f64();
    let probes = contact_probes(problem, &contact);
    let probe_index: Vec<usize> = probes.iter().map(|p| p.1).collect();
    let start = Instant::now();
    let history = integrator.run(
        &mut solver,
        &contact,
        &contact.points.initial_gap,
        &probe_index,
        on_step,
    );
    let run_seconds = start.elapsed().as_secs_f64();
    Ok(WearRun {
        contact,
        history,
        probes,
        setup_seconds,
        run_seconds,
    })
}

impl WearRun {
    /// The summary JSON of the run.
    pub fn summary(&self, problem: &Problem) -> Value {
        let h = &self.history;
        let steps: Vec<Value> = h
            .steps
            .iter()
            .map(|s| {
                let probes: serde_json::Map<String, Value> = self.probes.iter().zip(&s.probes).map(|((n, _), v)| (n.clone(), number(*v))).collect();
                json!({ "step": s.step, "half_period": s.half_period, "direction": s.direction, "k": s.k, "iterations": s.iterations, "criterion": number(s.criterion), "dissipation": number(s.dissipation), "delta_w": number(s.delta_w), "probes": probes })
            })
            .collect();
        let p_sum: Vec<f64> = h
            .p_plus
            .iter()
            .zip(&h.p_minus)
            .map(|(a, b)| a + b)
            .collect();
        let mut summary = json!({
            "title": problem.spec.title,
            "points": self.contact.len(),
            "steps": steps,
            "final": {
                "x": self.contact.points.x.iter().map(|p| number(p[0])).collect::<Vec<_>>(),
                "p_plus": numbers(&h.p_plus),
                "p_minus": numbers(&h.p_minus),
                "p_sum": numbers(&p_sum),
                "shape": numbers(&h.shape),
            },
            "snapshots": h.snapshots.iter().map(|s| json!({ "step": s.step, "half_period": s.half_period, "direction": s.direction, "pressure": numbers(&s.pressure), "shape": numbers(&s.shape) })).collect::<Vec<_>>(),
            "solves": h.solves,
            "failed_solves": h.failed_solves,
            "unconverged_steps": h.unconverged_steps,
            "setup_seconds": self.setup_seconds,
            "run_seconds": self.run_seconds,
        });
        if let Some(step) = h.stopped_at {
            // Only present when the wear overflowed: the run ended before this step.
            summary["stopped_at_step"] = json!(step);
        }
        summary
    }
}

/// The steady worn state of `problem` computed directly (no time integration), with the
/// condensed contact problem it was computed on.
pub fn steady(
    problem: &Problem,
) -> Result<(crate::steady::SteadyState, CondensedContact, f64), JobError> {
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    let state = crate::steady::steady_state(
        &contact,
        &integrator.half_period_wear(),
        if integrator.is_monotonic() {
            crate::steady::SteadySliding::Monotonic(direction(problem)?)
        } else {
            crate::steady::SteadySliding::Reciprocating
        },
        Default::default(),
    )
    .map_err(|e| {
        let key = match e {
            crate::steady::SteadyError::NoRigidMotion => "plate.motion",
            crate::steady::SteadyError::NoWear => "wear.body1.beta",
        };
        problem.error(key, e.to_string())
    })?;
    Ok((state, contact, start.elapsed().as_secs_f64()))
}

/// The periodic steady state of `problem` by one of the paper's §6 methods or the exact one
/// ([`crate::paper_steady`]), with the condensed contact problem and the set-up time (s).
pub fn steady_by(
    problem: &Problem,
    method: crate::paper_steady::SteadyMethod,
    settings: crate::paper_steady::MethodSettings,
) -> Result<(crate::paper_steady::MethodOutcome, CondensedContact, f64), JobError> {
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    if integrator.is_monotonic() {
        return Err(problem
            .error(
                "wear.sliding",
                "the paper's §6 methods are for reciprocating sliding; use --method exact",
            )
            .into());
    }
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    let setup = start.elapsed().as_secs_f64();
    let outcome = crate::paper_steady::solve_steady(
        &contact,
        &integrator.half_period_wear(),
        method,
        settings,
    )
    .map_err(|e| {
        use crate::paper_steady::MethodError;
        let key = match e {
            MethodError::ContactFailed(_) => {
                return JobError::Compute(format!("{}: {e}; nothing was written", problem.file))
            }
            MethodError::Steady(crate::steady::SteadyError::NoWear)
            | MethodError::Unsupported(_) => "wear.body1",
            MethodError::Steady(crate::steady::SteadyError::NoRigidMotion) => "plate.motion",
        };
        JobError::Problem(problem.error(key, e.to_string()))
    })?;
    Ok((outcome, contact, setup))
}
