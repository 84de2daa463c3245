//! `wearfem run`: the wear integration of a problem with its set-up, and what its summary.json
//! says about it ([`WearRun`]).

use super::driver::{
    check_contact_probes, check_shape_zero, coarse_zones_json, contact_probes, direction,
    edge_ends_json, method, run_warnings, target_mesh_json, JobError,
};
use crate::complementarity::ContactSolver;
use crate::contact::CondensedContact;
use crate::problem::Problem;
use crate::report::json::{number, numbers};
use crate::wear::{WearHistory, WearIntegrator};
use serde_json::{json, Value};
use std::ops::ControlFlow;
use std::time::Instant;

mod console;
mod turn;

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
    /// Steps of `wear.record` that were not recorded because the run ended before them: past
    /// the end of a run shortened by the `steps` argument, or after the last completed step of
    /// a run that stopped early (an adaptive run at the steady state, a failed solve).
    pub records_past_end: Vec<usize>,
    /// Sliding distance of one half period (monotonic: of one step unit), mm; under a turn
    /// about the axis the angle turned, rad (the sliding at r = 1 mm).
    pub sliding_per_half_period: f64,
    /// Bodies of revolution turning about their axis: the turn (radii, μ) and its angular
    /// speed ω (rad/s; for a turn to and fro its amplitude θ₀ω, the peak).
    pub turn: Option<(crate::wear::AxisRotation, f64)>,
    /// Whether the sliding is monotonic: the steps' `half_period` counts step units
    /// (`wear.step_time` each) then.
    pub monotonic: bool,
    /// The last cycle against the steady state of the same problem (not in `run_seconds`).
    pub steady_check: crate::checks::steady_check::SteadyCheck,
    /// `wear.shape_zero_at` (mm): the reported wear is relative to the wear there.
    pub shape_zero_at: Option<f64>,
    /// The run's warnings ([`run_warnings`]), made on first use by [`WearRun::warnings`].
    warnings: std::sync::OnceLock<Vec<String>>,
    /// The check in p's raised solve, when it was made beside the integration
    /// ([`wear_checked`]); taken by the first call of [`WearRun::warnings`].
    raised: std::sync::Mutex<Option<Result<Option<crate::p_check::RaisedSolve>, String>>>,
    /// The names of body 1 and body 2 of the contact.
    pub body_names: [String; 2],
    /// With heat: the heat problem's set-up figures.
    pub heat: Option<crate::wear::thermal::ThermalInfo>,
    /// With heat: the heat problem (for the temperature fields of the ParaView files).
    pub heat_model: Option<std::sync::Arc<crate::wear::thermal::ThermalModel>>,
}

/// `wear.shape_zero_at` shifts the worn shape by a vertical rigid translation of the punch,
/// which only leaves the pressures unchanged if the plate can take it up through λ_F.
pub(crate) fn check_shape_zero_plate(
    problem: &Problem,
) -> Result<(), crate::problem::ProblemError> {
    let shifts = problem
        .spec
        .wear
        .as_ref()
        .is_some_and(|w| w.shape_zero_at.is_some());
    let plate_moves = problem
        .spec
        .plate
        .as_ref()
        .is_some_and(|p| p.motion != "fixed");
    if shifts && !plate_moves {
        return Err(problem.error(
            "wear.shape_zero_at",
            "shifting the shape needs a plate that moves vertically (plate.motion = \"vertical\" or \"vertical_rotation\"); remove the key or free the plate",
        ));
    }
    Ok(())
}

/// Run the wear integration of `problem` (optionally overriding the number of steps).
pub fn wear(
    problem: &Problem,
    steps: Option<usize>,
    mut on_step: impl FnMut(&crate::wear::StepRecord),
) -> Result<WearRun, JobError> {
    wear_until(problem, steps, |record| {
        on_step(record);
        ControlFlow::Continue(())
    })
}

/// [`wear`], which `on_step` may stop by returning [`ControlFlow::Break`]: the run then ends
/// after that step with [`crate::wear::StopReason::Interrupted`] (what the Python layer does on
/// Ctrl-C or an error of a progress callback).
pub fn wear_until(
    problem: &Problem,
    steps: Option<usize>,
    on_step: impl FnMut(&crate::wear::StepRecord) -> ControlFlow<()>,
) -> Result<WearRun, JobError> {
    super::sliding::require_fixed_pairs(problem, "this run (the fixed pairs' integrator)")?;
    super::fretting::require_full_slip(problem, "this run (of full slip)")?;
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    // The file's duration and record points as steps, so that `steps` cuts the run the file
    // describes (its record points in metres, seconds or cycles included).
    let given_schedule = spec
        .extrapolation
        .clone()
        .unwrap_or_else(crate::kinematics::paper_schedule);
    let mut spec = crate::wear_units::resolve_duration(&spec)
        .map_err(|(key, message)| problem.error(key, message))?;
    let mut records_past_end = Vec::new();
    if steps.is_some_and(|n| n > spec.steps) && spec.adaptive.is_none() {
        // Past the end the file's duration was cut to, the steps follow the schedule as
        // given, not the cut's last factor (a remainder of 1 would make every further step
        // one half period).
        let end = spec.steps;
        if let Some(cut) = spec.extrapolation.as_mut() {
            if let Some(last) = cut.last_mut() {
                last.until = Some(end);
            }
            cut.extend(
                given_schedule
                    .into_iter()
                    .filter(|e| e.until.is_none_or(|u| u > end)),
            );
        }
    }
    if let Some(n) = steps {
        // `steps` replaces the file's duration; the snapshots it asks for past the new end are
        // reported in the result (`WearRun::records_past_end`), not dropped in silence.
        spec.steps = n;
        records_past_end = spec.record.iter().copied().filter(|&r| r > n).collect();
        spec.record.retain(|&r| r <= n);
    }
    let mut integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    integrator.first_direction = direction(problem)?;
    check_shape_zero_plate(problem)?;
    let start = Instant::now();
    let (contact, body1, body2) = CondensedContact::build(problem)?;
    check_contact_probes(problem, &contact)?;
    check_shape_zero(problem, &contact)?;
    super::driver::attach_turn(problem, &mut integrator, &contact)?;
    integrator.heat =
        super::heat::thermal_model(problem, &contact, [&body1, &body2])?.map(std::sync::Arc::new);
    let mut solver = ContactSolver::new(&contact, method(problem)?);
    let setup_seconds = start.elapsed().as_secs_f64();
    let probes = contact_probes(problem, &contact);
    let probe_index: Vec<usize> = probes.iter().map(|p| p.1).collect();
    let start = Instant::now();
    let history = integrator.run_until(
        &mut solver,
        &contact,
        &contact.points.initial_gap,
        &probe_index,
        on_step,
    );
    let run_seconds = start.elapsed().as_secs_f64();
    if history.stopped.is_some() {
        // A run that ended before its last step (an adaptive run at the steady state, or a
        // failed solve) did not reach the snapshots asked for after its last completed step:
        // listed like those past a shortened run's end, not dropped in silence.
        let last = history.steps.last().map_or(0, |s| s.step);
        records_past_end.extend(spec.record.iter().copied().filter(|&r| r > last));
        records_past_end.sort_unstable();
        records_past_end.dedup();
    }
    let steady_check = crate::checks::steady_check::check(&contact, &integrator, &history);
    let body_names = problem
        .spec
        .contact
        .as_ref()
        .map(|c| [c.body.clone(), c.target_body.clone()])
        .unwrap_or_default();
    Ok(WearRun {
        contact,
        history,
        probes,
        setup_seconds,
        run_seconds,
        records_past_end,
        sliding_per_half_period: integrator.sliding_per_half_period(),
        monotonic: integrator.is_monotonic(),
        turn: integrator.about_axis().map(|t| {
            let (angle, speed) = integrator.spec.sliding_scale();
            let omega = if integrator.is_monotonic() {
                speed
            } else {
                angle * integrator.spec.omega
            };
            (t.clone(), omega)
        }),
        steady_check,
        shape_zero_at: spec.shape_zero_at,
        warnings: std::sync::OnceLock::new(),
        raised: std::sync::Mutex::new(None),
        body_names,
        heat: integrator.heat.as_ref().map(|m| m.info.clone()),
        heat_model: integrator.heat.clone(),
    })
}

/// [`wear_until`] for a job of its own (`wearfem run`, Python's `Problem.run`): when the
/// problem asks for the check in p (`analysis.p_check`, true unless set false), its solve at
/// the raised degrees is made on a second thread while this one integrates, so that on two
/// cores the check costs little of the run's time (at 513 contact points it took 0.31 s of a
/// 0.74 s run, made after it).
pub fn wear_checked(
    problem: &Problem,
    steps: Option<usize>,
    on_step: impl FnMut(&crate::wear::StepRecord) -> ControlFlow<()>,
) -> Result<WearRun, JobError> {
    if !problem.spec.analysis.p_check.unwrap_or(true) {
        return wear_until(problem, steps, on_step);
    }
    let (run, raised) = std::thread::scope(|scope| {
        let raised = scope.spawn(|| crate::p_check::raised_first_solve(problem));
        let run = wear_until(problem, steps, on_step);
        // A panic of the check's thread is a bug: made again on this one, it reports itself.
        let raised = raised
            .join()
            .unwrap_or_else(|_| crate::p_check::raised_first_solve(problem));
        (run, raised)
    });
    let run = run?;
    if let Ok(mut slot) = run.raised.lock() {
        *slot = Some(raised);
    }
    Ok(run)
}

impl WearRun {
    /// The label of the figures' time axis: half periods, or the step units of monotonic
    /// sliding.
    pub fn time_axis(&self) -> &'static str {
        if self.monotonic {
            "step units (wear.step_time each)"
        } else {
            "half periods"
        }
    }

    /// Every warning about this run ([`run_warnings`]; its checks cost a few contact solves,
    /// made once): the console's warning lines and summary.json's `warnings`.
    /// With the check of the resolution in p ([`crate::p_check`]) unless `analysis.p_check`
    /// is false.
    pub fn warnings(&self, problem: &Problem) -> &[String] {
        self.warnings.get_or_init(|| {
            let mut warnings = self.model_warnings(problem);
            warnings.extend(self.resolution_warnings(problem, true));
            warnings
        })
    }

    /// The warnings about the contact, the model and the heat of this run.
    fn model_warnings(&self, problem: &Problem) -> Vec<String> {
        let mut warnings = run_warnings(problem, &self.contact, &self.history);
        warnings.extend(super::heat::run_warnings(problem, self));
        warnings
    }

    /// The depth warnings, and the check in p of the first contact solve when
    /// `analysis.p_check` (else `p_check_default`) asks for it, said against the run's last
    /// zone.
    fn resolution_warnings(&self, problem: &Problem, p_check_default: bool) -> Vec<String> {
        let h = &self.history;
        // The pressure of the last step: its direction's profile.
        let last_pressure = match h.steps.last().map(|s| s.direction) {
            Some("−") => Some(&h.p_minus),
            Some(_) => Some(&h.p_plus),
            None => None,
        };
        let mut warnings = match last_pressure {
            Some(p) => crate::p_check::run_depth_warnings(problem, &self.contact, p),
            None => crate::p_check::depth_warnings(problem, &self.contact),
        };
        if !problem.spec.analysis.p_check.unwrap_or(p_check_default) {
            return warnings;
        }
        // The check solves the first contact again at p + 2; a run's later states are not
        // checked so (their worn gap carried to the raised points by each element's
        // polynomial was measured 4.1 % off on punch-b40 after 100 steps where the runs at
        // p = 8 and 10 themselves differ by 0.4 %), so the warning says which state it
        // measured and whether the run's zone outgrew it.
        let last_zone =
            last_pressure.and_then(|p| crate::p_check::zone_of(&self.contact.points.x, p));
        let made = self.raised.lock().ok().and_then(|mut r| r.take());
        let check = match made {
            Some(raised) => crate::p_check::p_check_with(problem, &self.contact, raised),
            None => crate::p_check::p_check(problem, &self.contact),
        };
        let check = crate::p_check::run_p_check_warning(problem, check, last_zone);
        warnings.extend(check);
        warnings
    }

    /// The warnings of a study's run: as [`WearRun::warnings`], but the resolution in p is
    /// checked only where `analysis.p_check` is true (it costs a set-up at p + 2).
    pub fn study_warnings(&self, problem: &Problem) -> Vec<String> {
        let mut warnings = self.model_warnings(problem);
        warnings.extend(self.resolution_warnings(problem, false));
        warnings
    }

    /// The wear in `shape` (a shape of this run, mm): `shape` minus the initial gap (the
    /// bodies' geometric gap and `contact.initial_shape`), so 0 where nothing was worn; with
    /// `wear.shape_zero_at`, relative to the wear there ([`crate::wear::wear_of_shape`]).
    pub fn wear_of(&self, shape: &[f64]) -> Vec<f64> {
        crate::wear::wear_of_shape(&self.contact.points, shape, self.shape_zero_at)
    }

    /// Whether every step slid the same way (monotonic sliding, or a one-step run).
    pub fn is_monotonic(&self) -> bool {
        let h = &self.history.steps;
        h.windows(2).all(|w| w[0].direction == w[1].direction)
    }

    /// Why `steady_distance.summed_pressure` (the spread of p⁺ + p⁻ over the points in
    /// contact in both half cycles of the last cycle) means nothing for this run, if it does
    /// not: monotonic sliding has one half cycle (and no δw either, eq. 40 compares the two),
    /// and with fewer than two points in contact in both half cycles the spread is 0 whatever
    /// the state (red-team review 4, F6).
    pub fn summed_pressure_unavailable(&self) -> Option<String> {
        if self.is_monotonic() {
            return Some(
                "monotonic sliding has one half cycle per period: no p⁺ + p⁻ and no δw".into(),
            );
        }
        let h = &self.history;
        let both = h
            .p_plus
            .iter()
            .zip(&h.p_minus)
            .filter(|(a, b)| **a > 0.0 && **b > 0.0)
            .count();
        (both < 2).then(|| {
            format!("{both} contact point(s) carry pressure in both half cycles of the last cycle: no spread of p⁺ + p⁻ to measure")
        })
    }

    /// The edge ends in contact in the last cycle of the run (either half cycle).
    pub fn edge_ends(&self) -> Vec<crate::contact::EdgeEnd> {
        self.contact
            .edge_ends_in_contact(&[&self.history.p_plus, &self.history.p_minus])
    }

    /// The summary JSON of the run.
    pub fn summary(&self, problem: &Problem) -> Value {
        let h = &self.history;
        let monotonic = self.is_monotonic();
        let steps: Vec<Value> = h
            .steps
            .iter()
            .map(|s| {
                let probes: serde_json::Map<String, Value> = self.probes.iter().zip(&s.probes).map(|((n, _), v)| (n.clone(), number(*v))).collect();
                {
                    let mut step = json!({ "step": s.step, "half_period": s.half_period, "direction": s.direction, "k": s.k, "iterations": s.iterations, "solves": s.solves, "criterion": number(s.criterion), "dissipation": number(s.dissipation), "delta_w": number(s.delta_w), "probes": probes });
                    if monotonic {
                        // δw compares the two half cycles of a period: none in one direction.
                        step.as_object_mut().map(|o| o.remove("delta_w"));
                    }
                    if let Some(torque) = s.torque {
                        step["torque"] = number(torque);
                    }
                    if let Some(max) = s.max_temperature {
                        let temperatures: serde_json::Map<String, Value> = self.probes.iter().zip(&s.temperatures).map(|((n, _), v)| (n.clone(), number(*v))).collect();
                        step["temperatures"] = Value::Object(temperatures);
                        step["max_temperature"] = json!(numbers(&max));
                    }
                    step
                }
            })
            .collect();
        let p_sum: Vec<f64> = h
            .p_plus
            .iter()
            .zip(&h.p_minus)
            .map(|(a, b)| a + b)
            .collect();
        let half_periods = h.steps.last().map_or(0, |s| s.half_period);
        let mut summary = json!({
            "title": problem.spec.title,
            "wearfem_version": crate::VERSION,
            "points": self.contact.len(),
            "steps": steps,
            "final": {
                "x": self.contact.points.x.iter().map(|p| number(p[0])).collect::<Vec<_>>(),
                "p_plus": numbers(&h.p_plus),
                "p_minus": numbers(&h.p_minus),
                "p_sum": numbers(&p_sum),
                "shape": numbers(&h.shape),
                "wear": numbers(&self.wear_of(&h.shape)),
                "wear_body1": numbers(&h.body_wear[0]),
                "wear_body2": numbers(&h.body_wear[1]),
            },
            "snapshots": h.snapshots.iter().map(|s| json!({ "step": s.step, "half_period": s.half_period, "direction": s.direction, "pressure": numbers(&s.pressure), "shape": numbers(&s.shape), "wear": numbers(&self.wear_of(&s.shape)), "wear_body1": numbers(&s.body_wear[0]), "wear_body2": numbers(&s.body_wear[1]) })).collect::<Vec<_>>(),
            "edge_ends_in_contact": edge_ends_json(&self.edge_ends()),
            "coarse_partner_zones": coarse_zones_json(&self.contact.coarse_partner_zones(&[&h.p_plus, &h.p_minus])),
            "target_mesh": target_mesh_json(&self.contact),
            "solves": h.solves,
            "failed_solves": h.failed_solves,
            "unconverged_steps": h.unconverged_steps,
            "oscillating_steps": h.oscillating_steps,
            "worn_depth": numbers(&h.worn_depth),
            "worn_volume": numbers(&h.body_wear.each_ref().map(|w| crate::wear::worn_volume(&self.contact.points, w, self.contact.thickness))),
            "warnings": self.warnings(problem),
            "setup_seconds": self.setup_seconds,
            "run_seconds": self.run_seconds,
            "sliding_distance_m": number(half_periods as f64 * self.sliding_per_half_period / 1000.0),
        });
        if let (Some(z), Some(f)) = (self.contact.profile_z(), summary["final"].as_object_mut()) {
            // Bodies of revolution touching along their axis: every point has the same r.
            f.insert("z".into(), numbers(&z));
        }
        if let Some((turn, omega)) = &self.turn {
            summary["sliding_distance_m"] = Value::Null;
            summary["turn"] = self.turn_json(turn, *omega, half_periods);
        }
        if monotonic {
            // One direction only: there is no '−' pressure and no sum of the two.
            if let Some(f) = summary["final"].as_object_mut() {
                f.remove("p_minus");
                f.remove("p_sum");
            }
        }
        if !self.records_past_end.is_empty() {
            summary["records_past_end"] = json!(self.records_past_end);
        }
        if let (Some(info), Some(thermal)) = (&self.heat, &h.thermal) {
            summary["heat"] = super::heat::summary(info, thermal);
            if let Some(f) = summary["final"].as_object_mut() {
                f.insert("contact_temperature".into(), json!({ "body1": numbers(&thermal.contact_temperature[0]), "body2": numbers(&thermal.contact_temperature[1]) }));
                f.insert("thermal_gap".into(), numbers(&thermal.thermal_gap));
            }
        }
        match &h.steady_distance {
            Some(d) => {
                use crate::checks::steady_check::SteadyCheck;
                let (pressure, check) = match &self.steady_check {
                    SteadyCheck::Compared { pressure, .. } => {
                        (number(*pressure), json!("compared"))
                    }
                    SteadyCheck::Unavailable(why) => (Value::Null, json!(why)),
                    SteadyCheck::SeparateZones { .. } => {
                        (Value::Null, json!(self.steady_check.to_string()))
                    }
                    SteadyCheck::NoCycle => (Value::Null, json!("no complete cycle")),
                    // A distance from a state the run is not yet heading for, or that does
                    // not exist on the surface, is not a result: said in words instead.
                    SteadyCheck::Growing { .. } => {
                        (Value::Null, json!(self.steady_check.to_string()))
                    }
                };
                summary["steady_distance"] = json!({
                    "pressure": pressure,
                    "wear": number(d.wear),
                    "delta_w": number(d.delta_w),
                    "summed_pressure": number(d.summed_pressure),
                    "closing": number(d.closing),
                });
                if let Some(why) = self.summed_pressure_unavailable() {
                    // Both compare the two half cycles of a period; a spread over fewer than
                    // two points is 0 whatever the state. Null, not a number that reads as
                    // "steady".
                    let sd = &mut summary["steady_distance"];
                    sd["summed_pressure"] = Value::Null;
                    sd["summed_pressure_note"] = json!(why);
                    if monotonic {
                        sd["delta_w"] = Value::Null;
                    }
                }
                summary["steady_check"] = check;
                summary["steady_reached"] = json!(self.steady_check.reached(h));
            }
            None => {
                // No full cycle: the profiles of `final` are not results.
                if let Some(map) = summary.as_object_mut() {
                    map.remove("final");
                }
            }
        }
        if let Some((step, reason)) = &h.stopped {
            // Only present when the run ended early: at this step, for this reason.
            summary["stopped_at_step"] = json!(step);
            summary["stop_reason"] = json!(reason.to_string());
        }
        summary
    }
}
