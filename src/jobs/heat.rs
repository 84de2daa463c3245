//! The heat problem of a job, from the problem file: the validated `[heat]` section, the two
//! contact bodies and the contact, handed to the wear stage's thermal model
//! ([`crate::wear::thermal`]).

use super::driver::JobError;
use crate::contact::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::jobs::json::{number, numbers};
use crate::problem::Problem;
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
    let probes = problem
        .spec
        .probes
        .values()
        .filter(|p| p.body == body1)
        .map(|p| p.at)
        .collect();
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

/// The `heat` block of a run's summary.json: the model's figures and the heat balance.
pub fn summary(info: &ThermalInfo, thermal: &ThermalHistory) -> Value {
    json!({
        "reference_temperature": number(info.reference),
        "unknowns": info.unknowns,
        "modes": info.modes,
        "shifts_per_s": numbers(&info.shifts),
        "interface_conductance": number(info.interface_conductance),
        "heat_can_leave": info.has_exit,
        "peclet": numbers(&info.peclet),
        "setup_seconds": info.seconds,
        "heated_seconds": number(thermal.time),
        "generated_mJ": number(thermal.generated),
        "stored_mJ": number(thermal.stored),
        "next_thermal_gap": numbers(&thermal.next_thermal_gap),
    })
}
