//! The heat problem of a job, from the problem file: the validated `[heat]` section, the two
//! contact bodies and the contact, handed to the wear stage's thermal model
//! ([`crate::wear::thermal`]).

use super::driver::JobError;
use crate::checks::codes::warning;
use crate::contact::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::problem::Problem;
use crate::report::json::{number, numbers};
use crate::wear::thermal::{Sliding, ThermalBodies, ThermalHistory, ThermalInfo, ThermalModel};
use serde_json::{json, Value};

/// The thermal model of `problem` (None without `[heat]`), built on the contact's bodies.
pub fn thermal_model(
    problem: &Problem,
    contact: &CondensedContact,
    bodies: [&ElasticBody; 2],
) -> Result<Option<ThermalModel>, JobError> {
    let Some(settings) = problem.heat_settings()? else {
        return Ok(None);
    };
    let wear = problem.spec.wear.as_ref().ok_or_else(|| {
        problem.error(
            "wear",
            "heat needs a [wear] section: the sliding makes the heat",
        )
    })?;
    let sliding = match wear.sliding.as_str() {
        "monotonic" => Sliding::Monotonic {
            speed: wear.speed,
            step_time: wear.step_time,
        },
        _ => Sliding::Reciprocating {
            amplitude: wear.amplitude,
            omega: wear.omega,
        },
    };
    let body1 = problem
        .spec
        .contact
        .as_ref()
        .map(|c| c.body.clone())
        .unwrap_or_default();
    let probes = probe_points(problem, contact, bodies[0], &body1)?;
    let model = ThermalModel::build(ThermalBodies {
        elastic: bodies,
        contact,
        settings: &settings,
        space: problem.discretisation.space,
        sliding,
        probes,
    })
    .map_err(|e| {
        JobError::Compute(format!(
            "the heat problem could not be set up: {e} (nothing was computed)"
        ))
    })?;
    Ok(Some(model))
}

/// Where the temperature of each probe on body 1 is taken: the probe's point when it lies in
/// body 1, else (a point given on the contact edge, a hair outside it: the arc of a brake
/// shoe rounded to four decimals) the contact point the probe's pressure is read at, which
/// lies on body 1's edge. In the order of [`super::driver::contact_probes`].
fn probe_points(
    problem: &Problem,
    contact: &CondensedContact,
    body: &ElasticBody,
    name: &str,
) -> Result<Vec<crate::geometry::Point>, JobError> {
    let nearest = super::driver::contact_probes(problem, contact);
    let mut points = Vec::new();
    for (key, probe) in problem.spec.probes.iter().filter(|(_, p)| p.body == name) {
        let on_edge = nearest
            .iter()
            .find(|(n, _)| n == key)
            .map(|&(_, i)| contact.points.x[i]);
        let point = [Some(probe.at), on_edge]
            .into_iter()
            .flatten()
            .find(|&x| body.mesh.locate(x).is_some())
            .ok_or_else(|| {
                problem.error(
                    format!("probes.{key}.at"),
                    format!(
                        "({}, {}) is not in body \"{name}\", and neither is the contact point nearest to it: its temperature cannot be taken",
                        probe.at[0], probe.at[1]
                    ),
                )
            })?;
        points.push(point);
    }
    Ok(points)
}

/// The `heat` block of a run's summary.json: the model's figures and the heat balance.
pub fn summary(info: &ThermalInfo, thermal: &ThermalHistory) -> Value {
    json!({
        "reference_temperature": number(info.reference),
        "unknowns": info.unknowns,
        "modes": info.modes,
        "shifts_per_s": numbers(&info.shifts),
        "interface_conductance": number(info.interface_conductance),
        "heat_can_leave": !info.trapped,
        "peclet": numbers(&info.peclet),
        "setup_seconds": info.seconds,
        "heated_seconds": number(thermal.time),
        "generated_mJ": number(thermal.generated),
        "stored_mJ": number(thermal.stored),
        "next_thermal_gap": numbers(&thermal.next_thermal_gap),
    })
}

/// Temperature (°C) above which the run warns that the materials' properties, taken as
/// constant, have changed: steels lose a tenth of their conductivity by 300 °C, and polymer
/// composites soften far below it.
pub const PROPERTY_TEMPERATURE: f64 = 300.0;

/// The undershoot below the lowest imposed temperature, as a share of the rise above it, past
/// which `heat-undershoot` warns: the shipped `brake-drag-heat`, whose contact temperature is
/// converged in p to 0.01 K (docs/heat.md), undershoots by 1.9 % (0.28 K) upstream of its
/// thin moving layer; a hundredfold lower conductivity on punch-b40-heat, by far more than
/// the rise.
pub const UNDERSHOOT: f64 = 0.05;

/// The undershoot (K) past which `heat-undershoot` warns whatever the rise.
pub const UNDERSHOOT_KELVIN: f64 = 5.0;

/// What the heat of a run says beyond its numbers: heat that cannot leave, heat crossing
/// between points that are not in contact, temperatures beyond constant properties or below
/// what the problem imposes.
pub fn run_warnings(problem: &Problem, run: &super::driver::WearRun) -> Vec<String> {
    let (Some(info), Some(thermal)) = (&run.heat, &run.history.thermal) else {
        return Vec::new();
    };
    let file = &problem.file;
    let mut warnings = Vec::new();
    if info.trapped {
        warnings.push(warning("heat-no-exit", file, "heat: frictional heat enters a body that cannot lose it (insulated edges, no face convection): its temperature rises without end"));
    }
    if info.held_points > 0 {
        warnings.push(warning("heat-held-edge", file, format!("heat: {} contact point(s) lie where the contact edge meets an edge held at a temperature: the contact there stays cooler", info.held_points)));
    }
    let h = &run.history;
    if info.interface_conductance > 0.0 && !h.p_plus.is_empty() {
        let x = &run.contact.points.x;
        let apart: Vec<usize> = (0..x.len())
            .filter(|&i| h.p_plus[i] <= 0.0 && h.p_minus.get(i).is_none_or(|&p| p <= 0.0))
            .collect();
        if let (Some(&first), Some(&last)) = (apart.first(), apart.last()) {
            warnings.push(warning(
                "heat-open-points",
                file,
                format!(
                    "heat: perfect thermal contact, and {} of the {} points carry no pressure in the last cycle (x = {:.3} … {:.3} mm): heat crosses there as if they touched",
                    apart.len(),
                    x.len(),
                    x[first][0],
                    x[last][0]
                ),
            ));
        }
    }
    let hottest = h
        .steps
        .iter()
        .filter_map(|s| s.max_temperature)
        .flatten()
        .fold(f64::NEG_INFINITY, f64::max);
    warnings.extend(temperature_warnings(
        file,
        thermal.lowest,
        hottest,
        info.floor,
    ));
    warnings
}

/// `heat-hot` above [`PROPERTY_TEMPERATURE`], and `heat-undershoot` when the lowest
/// temperature on the boundary samples falls below the lowest the problem imposes (`floor`)
/// by more than [`UNDERSHOOT`] of the rise above it or [`UNDERSHOOT_KELVIN`] (and 1 mK): frictional heat cannot cool
/// anything, so that is the discretisation's oscillation in a thermal layer thinner than its
/// elements resolve, and the temperatures near it are off by as much.
fn temperature_warnings(file: &str, lowest: f64, hottest: f64, floor: f64) -> Vec<String> {
    let mut warnings = Vec::new();
    if hottest > PROPERTY_TEMPERATURE {
        warnings.push(warning("heat-hot", file, format!("heat: the bodies reach {hottest:.0} °C, where the material properties held constant differ from their room-temperature values")));
    }
    let rise = (hottest - floor).max(0.0);
    // The oscillation inflates the peak too (the rise of a run undershooting by 290 K was
    // 19 000 K): past UNDERSHOOT_KELVIN it warns whatever the rise.
    let allowed = (UNDERSHOOT * rise).clamp(1e-3, UNDERSHOOT_KELVIN);
    if lowest.is_finite() && lowest < floor - allowed {
        warnings.push(warning("heat-undershoot", file, format!("heat: the temperature falls to {lowest:.2} °C on a boundary, {:.2} K below the lowest the problem imposes ({floor} °C: its start, ambient and held temperatures), which frictional heat cannot do: the elements at the contact do not resolve its thermal layer, and the temperatures and the thermal distortion there oscillate by as much; refine the elements at the contact or raise p", floor - lowest)));
    }
    warnings
}

/// What the steady state with heat says beyond its numbers: heat crossing between points
/// that are not in contact in either half cycle, temperatures beyond constant properties or
/// below what the problem imposes.
pub fn steady_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    state: &crate::steady::SteadyState,
    heat: &crate::thermal_steady::PeriodicHeat,
) -> Vec<String> {
    let info = &heat.model.info;
    let mut warnings = Vec::new();
    let file = &problem.file;
    if info.interface_conductance > 0.0 {
        let x = &contact.points.x;
        let apart: Vec<usize> = (0..x.len())
            .filter(|&i| state.p_plus[i] <= 0.0 && state.p_minus.get(i).is_none_or(|&p| p <= 0.0))
            .collect();
        if let (Some(&first), Some(&last)) = (apart.first(), apart.last()) {
            warnings.push(warning(
                "heat-open-points",
                file,
                format!(
                    "heat: perfect thermal contact, and {} of the {} points carry no pressure in the steady state (x = {:.3} … {:.3} mm): heat crosses there as if they touched",
                    apart.len(),
                    x.len(),
                    x[first][0],
                    x[last][0]
                ),
            ));
        }
    }
    if info.held_points > 0 {
        warnings.push(warning("heat-held-edge", file, format!("heat: {} contact point(s) lie where the contact edge meets an edge held at a temperature: the contact there stays cooler", info.held_points)));
    }
    // The periodic temperature at the start of each half cycle, as the run samples its
    // steps' ends.
    let extremes = heat
        .modal
        .iter()
        .flat_map(|a| heat.model.boundary_extremes(a));
    let (lowest, hottest) = extremes.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), [a, b]| {
        (l.min(a), h.max(b))
    });
    warnings.extend(temperature_warnings(file, lowest, hottest, info.floor));
    warnings
}
