//! The heat problem of a job, from the problem file: the validated `[heat]` section, the two
//! contact bodies and the contact, handed to the wear stage's thermal model
//! ([`crate::wear::thermal`]).

use super::driver::JobError;
use crate::contact::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::problem::Problem;
use crate::wear::thermal::{Sliding, ThermalBodies, ThermalModel};

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
