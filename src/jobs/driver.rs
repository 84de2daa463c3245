//! The three jobs of the command line as library functions: a static elastic solve, one
//! contact solve and a wear run. Each returns its results; the report stage
//! ([`crate::output`]) writes them, and this module uses nothing of it.

use crate::complementarity::{
    ContactSolution, ContactSolver, Direction, Method, SolveInfo, Status,
};
use crate::contact::CondensedContact;
use crate::problem::{Problem, ProblemError};
use crate::report::json::{number, numbers};
use crate::wear::WearIntegrator;
use serde_json::{json, Value};
use std::time::Instant;

pub use super::run::{wear, wear_checked, wear_until, WearRun};
pub use crate::checks::warnings::{
    coarse_zones_json, edge_ends_json, edge_ends_warning, fixed_plate_load_warning, model_warnings,
    penalty_warning, run_warnings, steady_edge_ends, steady_warnings, study_steady_warnings,
    target_mesh_json, target_mesh_note, zone_warnings, STROKE_LIMIT,
};

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
    let mut warnings: Vec<String> = Vec::new();
    for b in 0..problem.spec.bodies.len() {
        let body = problem.elastic_body(b, &[])?;
        let load = problem.load_vector(b, &body, &[])?;
        let u = body
            .solve(&load)
            .map_err(|e| problem.error("bodies", e.to_string()))?;
        // ½ uᵀKu with the supports' springs: ½ fᵀu counts no work of prescribed displacements.
        energy += body.stored_energy(&u);
        let strain = crate::checks::validity::largest_strain(&body, &u);
        warnings.extend(crate::checks::validity::strain_warning(
            problem,
            &body.name,
            strain,
            "its loads",
        ));
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
            let mut values = json!({ "displacement": numbers(&v.displacement), "stress": numbers(&v.stress), "strain": numbers(&v.strain) });
            if problem.analysis.is_axisymmetric() {
                values["hoop_strain"] = number(v.hoop[0]);
                values["hoop_stress"] = number(v.hoop[1]);
            }
            probes.insert(name.clone(), values);
            let materials = body.mesh.materials_at(probe.at);
            if materials.len() > 1 {
                let names: Vec<&str> = problem.spec.materials.keys().map(String::as_str).collect();
                let name_of = |m: usize| names.get(m).copied().unwrap_or("?");
                warnings.push(crate::checks::codes::warning(
                    "probe-interface",
                    &problem.file,
                    format!(
                        "probe \"{name}\" at ({}, {}) lies on the interface of materials \"{}\" and \"{}\": its stress and strain are taken on \"{}\"'s side",
                        probe.at[0], probe.at[1], name_of(materials[0]), name_of(materials[1]), name_of(materials[0])
                    ),
                ));
            }
        }
    }
    if !energy.is_finite() {
        // Only an input far outside the accepted ranges reaches here; a result with a strain
        // energy of NaN is not one.
        return Err(JobError::Compute(format!(
            "the elastic solve's strain energy is not finite ({energy}): the displacements overflowed; check the loads against the moduli and the supports (nothing was written)"
        )));
    }
    let mut summary = json!({
        "title": problem.spec.title,
        "wearfem_version": crate::VERSION,
        "dofs": dofs,
        "condensed_dofs": condensed,
        "strain_energy": number(energy),
        "probes": probes,
        "warnings": warnings,
        "seconds": start.elapsed().as_secs_f64(),
    });
    if problem.analysis.is_axisymmetric() {
        summary["axisymmetric"] = axisymmetric_json();
    }
    Ok(summary)
}

/// What summary.json says of a body of revolution's numbers, so that none is read per radian.
fn axisymmetric_json() -> Value {
    json!({
        "x": "the radius r, mm",
        "forces": "N for the whole circumference (2πr), as are the loads, the plate force and the strain energy",
        "stress_components": "σ_rr, σ_zz, σ_rz; the probes' hoop_stress is σ_θθ",
    })
}

/// Make `integrator`'s sliding the turn about the axis of `contact`'s bodies of revolution
/// when the contact says they turn (`contact.sliding_motion = "about_axis"`); the wear keys of
/// a turn (`angle`, `angular_speed`) without it are refused by name. Bodies of revolution that
/// do not turn slide in the (r, z) plane, along the contact edge, which must then run along
/// the axis (a pin or a ring in a bore; along a face the slide would be radial, all round).
pub fn attach_turn(
    problem: &Problem,
    integrator: &mut WearIntegrator,
    contact: &CondensedContact,
) -> Result<(), ProblemError> {
    if contact.axisymmetric && contact.friction_about_axis.is_none() && !contact.edge_along_axis() {
        return Err(problem.error(
            "contact.sliding_motion",
            "is \"in_plane\" on bodies of revolution, whose sliding in the (r, z) plane runs along the contact edge, and this edge runs across the axis (a face): a radial slide all round is no motion. Bodies turning about their axis (a thrust washer, a clutch) give \"about_axis\"; bodies sliding along it need a contact edge along the axis (a pin or a ring in a bore)",
        ));
    }
    match contact.friction_about_axis {
        Some(friction) => integrator
            .turn_about_axis(crate::wear::AxisRotation::new(contact, friction))
            .map_err(|(key, message)| problem.error(key, message)),
        None if integrator.spec.turns_about_axis() => {
            let key = if integrator.is_monotonic() {
                "wear.angular_speed"
            } else {
                "wear.angle"
            };
            Err(problem.error(key, "is a turn about the axis of bodies of revolution; give contact.sliding_motion = \"about_axis\" with analysis.kind = \"axisymmetric\", or the plane sliding's speed or amplitude"))
        }
        None => Ok(()),
    }
}

/// The solver method named in the problem's `[contact]` section
/// ([`Problem::contact_method`]).
pub fn method(problem: &Problem) -> Result<Method, ProblemError> {
    problem.contact_method()
}

/// The first sliding direction named in the problem ([`Problem::first_direction`]).
pub fn direction(problem: &Problem) -> Result<Direction, ProblemError> {
    problem.first_direction()
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

/// Every probe must be on the contact body (see [`check_contact_probes`]); checked without the
/// contact points.
pub fn check_probe_bodies(problem: &Problem) -> Result<(), ProblemError> {
    let Some(c) = problem.spec.contact.as_ref() else {
        return Ok(());
    };
    for (name, probe) in &problem.spec.probes {
        if probe.body != c.body {
            return Err(problem.error(
                format!("probes.{name}.body"),
                format!("is on body \"{}\", but contact, run and steady report pressures on the contact body \"{}\" only; remove the probe or move it to the contact edge", probe.body, c.body),
            ));
        }
    }
    Ok(())
}

/// Every probe must be on the contact edge of the contact body: `contact`, `run` and `steady`
/// report the pressure at the contact point nearest to a probe, which is only the pressure
/// *at the probe* when it lies on that edge, within half the widest spacing of the points.
pub fn check_contact_probes(
    problem: &Problem,
    contact: &CondensedContact,
) -> Result<(), ProblemError> {
    let Some(c) = problem.spec.contact.as_ref() else {
        return Ok(());
    };
    check_probe_bodies(problem)?;
    let x = &contact.points.x;
    let spacing = x.windows(2).map(|w| dist(w[0], w[1])).fold(0.0, f64::max);
    for (name, probe) in &problem.spec.probes {
        let key = format!("probes.{name}");
        let nearest = x
            .iter()
            .map(|&p| dist(p, probe.at))
            .fold(f64::INFINITY, f64::min);
        // 5 % above half the chord: on an arc a probe midway between two points lies
        // 1/cos(θ/4) times half their chord from each (red team H: the brake's crown probe
        // at p = 3, 9.5191 against 9.516 mm, was refused).
        if nearest > 0.5 * spacing * 1.05 {
            return Err(problem.error(
                format!("{key}.at"),
                format!(
                    "({}, {}) is not on the contact edge \"{}\" (the nearest contact point is {nearest:.4} mm away); contact, run and steady report pressures on that edge",
                    probe.at[0], probe.at[1], c.edge
                ),
            ));
        }
    }
    Ok(())
}

/// `wear.shape_zero_at` must lie within the x range of the contact points: outside it, the
/// shift would be taken at the nearest point, not where the file says.
pub(super) fn check_shape_zero(
    problem: &Problem,
    contact: &CondensedContact,
) -> Result<(), ProblemError> {
    let Some(x0) = problem.spec.wear.as_ref().and_then(|w| w.shape_zero_at) else {
        return Ok(());
    };
    let (lo, hi) = contact
        .points
        .x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p[0]), b.max(p[0]))
        });
    let slack = 1e-9 * (hi - lo).abs().max(1.0);
    if !(x0 >= lo - slack && x0 <= hi + slack) {
        return Err(problem.error(
            "wear.shape_zero_at",
            format!("x = {x0} mm is outside the contact edge's x range [{lo}, {hi}] mm"),
        ));
    }
    Ok(())
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
    super::fretting::require_full_slip(problem, "this contact solve (full slip)")?;
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    check_contact_probes(problem, &contact)?;
    let setup = start.elapsed().as_secs_f64();
    let mut solver = ContactSolver::new(&contact, method(problem)?);
    let first = direction(problem)?;
    let (solution, info) = solver.solve(&contact.points.initial_gap, first);
    let rigid = crate::report::json::named(&contact.rigid_names, &solution.rigid);
    let probes: serde_json::Map<String, Value> = contact_probes(problem, &contact)
        .into_iter()
        .map(|(n, i)| (n, number(solution.pressure[i])))
        .collect();
    let summary = json!({
        "title": problem.spec.title,
        "wearfem_version": crate::VERSION,
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
        "edge_ends_in_contact": edge_ends_json(&contact.edge_ends_in_contact(&[&solution.pressure])),
        "coarse_partner_zones": coarse_zones_json(&contact.coarse_partner_zones(&[&solution.pressure])),
        "target_mesh": target_mesh_json(&contact),
        "setup_seconds": setup,
    });
    let mut summary = summary;
    if problem.analysis.is_axisymmetric() {
        summary["axisymmetric"] = axisymmetric_json();
    }
    if let (Some(friction), Status::Solved) = (contact.friction_about_axis, info.status) {
        // Bodies turning about their axis: the friction torque of this contact.
        let turn = crate::wear::AxisRotation::new(&contact, friction);
        summary["turn"] = json!({
            "friction": number(friction),
            "torque_Nmm": number(turn.torque(&solution.pressure, &contact.areas())),
        });
    }
    // A failed solve is returned too (status in `info`), with its residuals but none of its
    // values in the summary: nothing taken from a failed solve is a result.
    // The console's warning lines, also for Python: the zone diagnostics describe a
    // solution, so a failed solve gets none.
    let mut warnings: Vec<String> = penalty_warning(problem, &contact).into_iter().collect();
    warnings.extend(fixed_plate_load_warning(problem, &contact));
    warnings.extend(crate::checks::warnings::inclined_contact_warning(
        problem, &contact,
    ));
    if info.status == Status::Solved {
        warnings.extend(crate::checks::validity::plate_motion_warning(
            problem,
            &contact,
            &solution.rigid,
        ));
        warnings.extend(crate::checks::validity::contact_strain_warnings(
            problem, &contact, &solution, first,
        ));
        warnings.extend(zone_warnings(problem, &contact, &[&solution.pressure]));
        warnings.extend(crate::p_check::resolution_warnings(problem, &contact, true));
    }
    summary["warnings"] = json!(warnings);
    if info.status != Status::Solved {
        for key in ["pressure", "gap", "rigid", "probes"] {
            summary[key] = Value::Null;
        }
        summary["edge_ends_in_contact"] = json!([]);
        summary["coarse_partner_zones"] = json!([]);
    }
    Ok((summary, contact, solution, info))
}

/// The edge end at which a failed contact solve left all its pressure, if it did: "first" or
/// "last" contact point. That is the signature of loads that cannot be balanced on this
/// contact edge (the friction moment about the pin, or an eccentric load, needs the pressure
/// resultant beyond the edge: the punch would tip); the solver ends with every force on one
/// corner point and a complementarity residual it cannot reduce. Refining the mesh does not
/// help then, so the "too few contact points" advice of [`zone_warnings`] would mislead.
/// Only used to explain a failure: the pressures of a failed solve are never a result.
pub fn pressure_at_one_end(pressure: &[f64]) -> Option<&'static str> {
    let n = pressure.len();
    let peak = pressure.iter().cloned().fold(0.0, f64::max);
    // `f64::max` skips NaN, so `peak` is 0 unless some pressure is positive.
    if n < 2 || peak <= 0.0 {
        return None;
    }
    // Pressures below 1e-9 of the peak are round-off of the active-set solve.
    let carrying: Vec<usize> = (0..n).filter(|&i| pressure[i] > 1e-9 * peak).collect();
    match carrying[..] {
        [0] => Some("first"),
        [i] if i == n - 1 => Some("last"),
        _ => None,
    }
}

/// What [`pressure_at_one_end`] means for the user: the loads cannot be balanced on the
/// contact edge (`end`: "first" or "last" contact point), and what to change.
pub fn unbalanced_explanation(end: &str) -> String {
    format!("the loads cannot be balanced on this contact edge. The solver ended with all the pressure on the {end} contact point, the edge's corner: the moment of the load and of friction (μ·l_z with a pin) needs the pressure resultant beyond the edge, so the punch would tip. Refining the mesh does not help; lower contact.friction, move plate.pin closer to the contact, or centre the load")
}

/// Why a run or a steady state of `problem` that failed could not succeed, if the reason is
/// loads that cannot be balanced: the first contact solve of each direction the problem
/// slides in (the first only, under monotonic sliding), at the initial shape, failing with
/// all its pressure at one end of the edge ([`pressure_at_one_end`]). The direction's symbol
/// and [`unbalanced_explanation`]; None when every first solve succeeds or fails otherwise.
/// Only used to explain a failure.
pub fn unbalanced_loads(problem: &Problem, contact: &CondensedContact) -> Option<String> {
    let first = direction(problem).ok()?;
    let integrator = WearIntegrator::new(problem.spec.wear.as_ref()?).ok()?;
    let directions = if integrator.is_monotonic() {
        vec![first]
    } else {
        vec![Direction::Plus, Direction::Minus]
    };
    let mut solver = ContactSolver::new(contact, method(problem).ok()?);
    directions.into_iter().find_map(|d| {
        let (solution, info) = solver.solve(&contact.points.initial_gap, d);
        if info.status == Status::Solved {
            return None;
        }
        let end = pressure_at_one_end(&solution.pressure)?;
        Some(format!(
            "the first contact solve of the '{}' half cycle fails: {}",
            d.symbol(),
            unbalanced_explanation(end)
        ))
    })
}

/// The steady worn state of `problem` computed directly (no time integration), with the
/// condensed contact problem it was computed on.
pub fn steady(
    problem: &Problem,
) -> Result<(crate::steady::SteadyState, CondensedContact, f64), JobError> {
    let (state, contact, seconds, _) = steady_with_heat(problem)?;
    Ok((state, contact, seconds))
}

/// [`steady`], with the periodic temperature of a problem with `[heat]` (None without): the
/// steady state of the wear and the heat together ([`crate::thermal_steady`]).
pub fn steady_with_heat(
    problem: &Problem,
) -> Result<
    (
        crate::steady::SteadyState,
        CondensedContact,
        f64,
        Option<crate::thermal_steady::PeriodicHeat>,
    ),
    JobError,
> {
    super::sliding::require_fixed_pairs(problem, "the steady state")?;
    super::fretting::require_full_slip(problem, "this steady state (of full slip)")?;
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let mut integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    // The steady state solves no single contact problem, so neither the method nor (for
    // reciprocating sliding) the first direction is used; a bad name is refused all the same,
    // as by every other job and by a study.
    method(problem)?;
    direction(problem)?;
    let start = Instant::now();
    let (contact, body1, body2) = CondensedContact::build(problem)?;
    check_contact_probes(problem, &contact)?;
    check_shape_zero(problem, &contact)?;
    attach_turn(problem, &mut integrator, &contact)?;
    let sliding = if integrator.is_monotonic() {
        crate::steady::SteadySliding::Monotonic(direction(problem)?)
    } else {
        crate::steady::SteadySliding::Reciprocating
    };
    let steady_error = |e: crate::steady::SteadyError| {
        let key = match e {
            crate::steady::SteadyError::NoRigidMotion => "plate.motion",
            crate::steady::SteadyError::NoWear => "wear.body1.beta",
        };
        if contact.axisymmetric && e == crate::steady::SteadyError::NoRigidMotion {
            // A body of revolution's plate can only translate along the axis.
            return problem.error(key, "a steady worn state needs a plate that can move, and a body of revolution's plate moves along the axis only (plate.motion = \"vertical\"); bodies pressed by an overlap (a shrink fit) with the plate held have none: their wear only relieves the fit");
        }
        problem.error(key, e.to_string())
    };
    if let (Some(_), false, Some((name, a, b))) = (
        contact.friction_about_axis,
        contact.axis_points.is_empty(),
        crate::checks::warnings::collapsing_law(&spec),
    ) {
        return Err(problem
            .error(
                format!("wear.{name}"),
                format!("a = {a} ≥ 2b = {}: the bodies turn about their axis and touch on it, and the steady pressure of a turn, p ∝ r^(−a/b), cannot carry a load that reaches the axis (∫ p r dr diverges at r = 0): no steady state exists (the worn contact draws its load ever closer to the axis). `wearfem run` integrates the transient, with a warning", 2.0 * b),
            )
            .into());
    }
    let terms = integrator.wear_terms();
    let (state, heat) = match super::heat::thermal_model(problem, &contact, [&body1, &body2])? {
        None => (
            crate::steady::steady_state(&contact, &terms, sliding, Default::default())
                .map_err(steady_error)?,
            None,
        ),
        Some(model) => {
            let model = std::sync::Arc::new(model);
            // (Heat is plane only, [`crate::contact`]: the same terms at every point.)
            let solved = crate::thermal_steady::steady_state_with_heat(
                &contact,
                &integrator.half_period_wear(),
                sliding,
                Default::default(),
                &model,
            )
            .map_err(|e| match e {
                crate::thermal_steady::ThermalSteadyError::Steady(e) => steady_error(e),
                no_exit => problem.error("heat", no_exit.to_string()),
            })?;
            (solved.state, Some(solved.heat))
        }
    };
    Ok((state, contact, start.elapsed().as_secs_f64(), heat))
}

/// The periodic steady state of `problem` by one of the paper's §6 methods or the exact one
/// ([`crate::paper_steady`]), with the condensed contact problem and the set-up time (s).
/// A §6 result that fails [`crate::paper_steady::accept`] has status `NotSteady`.
pub fn steady_by(
    problem: &Problem,
    method: crate::paper_steady::SteadyMethod,
    settings: crate::paper_steady::MethodSettings,
) -> Result<(crate::paper_steady::MethodOutcome, CondensedContact, f64), JobError> {
    super::sliding::require_fixed_pairs(problem, "the steady state")?;
    super::fretting::require_full_slip(problem, "this steady state (of full slip)")?;
    if problem.analysis.is_axisymmetric() && method != crate::paper_steady::SteadyMethod::Exact {
        // Their splines and averages are laid out along a plane edge with one sliding
        // distance; the exact method knows each point's own.
        return Err(problem
            .error(
                "analysis.kind",
                "is \"axisymmetric\": the paper's §6 methods (averaged, spline, penalty) are for plane problems; use --method exact (the default)",
            )
            .into());
    }
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
    if problem.spec.heat.is_some() && method != crate::paper_steady::SteadyMethod::Exact {
        // The spline and penalty iterations and the averaged shape know no temperature: a
        // steady state of theirs would be the one without heat, under a problem with heat.
        return Err(problem
            .error(
                "heat",
                "the paper's §6 methods (averaged, spline, penalty) leave the heat out; the steady state with heat is the exact method's (--method exact, the default)",
            )
            .into());
    }
    self::method(problem)?;
    direction(problem)?;
    let start = Instant::now();
    let (contact, _, _) = CondensedContact::build(problem)?;
    // The same checks as the exact method's (red team 28: a probe off the contact edge or
    // `shape_zero_at` outside it passed in silence with the §6 methods).
    check_contact_probes(problem, &contact)?;
    check_shape_zero(problem, &contact)?;
    let setup = start.elapsed().as_secs_f64();
    let most = crate::spline_method::max_refinement(contact.len());
    if method == crate::paper_steady::SteadyMethod::Spline && settings.spline_refinement > most {
        // The library caps it (a spline with more points than the contact has cannot be
        // determined); asked for explicitly, the cap would go unnoticed.
        return Err(ProblemError {
            file: problem.file.clone(),
            key: "--spline-refinement".into(),
            message: format!(
                "{} asks for {} spline points, more than the {} contact points determine; the largest allowed value is {most} ({} spline points)",
                settings.spline_refinement,
                (16u64 << settings.spline_refinement.min(40)) + 1,
                contact.len(),
                (16usize << most) + 1
            ),
        }
        .into());
    }
    let outcome = crate::paper_steady::solve_steady(
        &contact,
        &integrator.half_period_wear(),
        method,
        settings,
    )
    .map_err(|e| {
        use crate::paper_steady::MethodError;
        let key = match e {
            MethodError::ContactFailed { .. } | MethodError::LiftOff { .. } => {
                return JobError::Compute(format!("{}: {e}; nothing was written", problem.file))
            }
            MethodError::Steady(crate::steady::SteadyError::NoWear)
            | MethodError::Unsupported(_) => "wear.body1",
            MethodError::Steady(crate::steady::SteadyError::NoRigidMotion) => "plate.motion",
        };
        JobError::Problem(problem.error(key, e.to_string()))
    })?;
    // The §6 methods approximate the steady state; the exact one (one Newton solve) says by
    // how much.
    let mut outcome = outcome;
    if outcome.state.status == crate::steady::SteadyStatus::Solved {
        let exact = crate::steady::steady_state(
            &contact,
            &integrator.half_period_wear(),
            crate::steady::SteadySliding::Reciprocating,
            Default::default(),
        );
        if let Ok(exact) = exact.as_ref().map_err(|_| ()).and_then(|e| {
            (e.status == crate::steady::SteadyStatus::Solved)
                .then_some(e)
                .ok_or(())
        }) {
            outcome.distance_from_exact =
                crate::checks::steady_check::pressure_distance(&outcome.state, exact);
        }
        // A result that fails the acceptance rule is not a steady state: its status says so,
        // and callers write none of its values.
        outcome.not_steady = crate::paper_steady::accept(&outcome, settings.tolerance);
        if outcome.not_steady.is_some() {
            outcome.state.status = crate::steady::SteadyStatus::NotSteady;
        }
    }
    Ok((outcome, contact, setup))
}
