//! Continuation for steady states that Newton's method does not reach from its start: the
//! problem is walked to from one it does solve, a stage at a time.

use super::{SteadySettings, SteadyStatus, System};
use crate::contact::CondensedContact;

/// Newton solves for the exponents 1 + t (b − 1), t from 0 to 1 ([`walk`]).
pub(super) fn in_exponents(
    system: &System,
    terms: &[(f64, f64)],
    z: &mut Vec<f64>,
    active: &mut Vec<Vec<bool>>,
    settings: SteadySettings,
) -> (SteadyStatus, usize) {
    let stage = |t: f64| -> Vec<(f64, f64)> {
        terms
            .iter()
            .map(|&(c, b)| (c, 1.0 + t * (b - 1.0)))
            .collect()
    };
    walk(
        |t, z, active| system.newton(&stage(t), z, active, settings),
        z,
        active,
    )
}

/// Newton solves for the friction coefficient t μ, t from 0 to 1 ([`walk`]): without friction
/// the two half cycles are mirror images and Newton's method finds their state from a
/// contact solve's pressures; friction then shifts it a little at each stage.
pub(super) fn in_friction(
    contact: &CondensedContact,
    signs: &[f64],
    terms: &[(f64, f64)],
    z: &mut Vec<f64>,
    active: &mut Vec<Vec<bool>>,
    settings: SteadySettings,
) -> (SteadyStatus, usize) {
    walk(
        |t, z, active| System::new(contact, signs, t).newton(terms, z, active, settings),
        z,
        active,
    )
}

/// Solves `stage(t)` for t from 0 to 1, each stage starting from the last converged one; a
/// failed stage is retried with half the step, down to 1/64. On failure the last converged
/// stage is left in `z` and `active`.
fn walk(
    stage: impl Fn(f64, &mut Vec<f64>, &mut Vec<Vec<bool>>) -> (SteadyStatus, usize),
    z: &mut Vec<f64>,
    active: &mut Vec<Vec<bool>>,
) -> (SteadyStatus, usize) {
    let (mut status, mut iterations) = stage(0.0, z, active);
    let (mut t, mut step) = (0.0f64, 0.25f64);
    while status == SteadyStatus::Solved && t < 1.0 {
        let target = (t + step).min(1.0);
        let (mut trial_z, mut trial_active) = (z.clone(), active.clone());
        let (stage_status, used) = stage(target, &mut trial_z, &mut trial_active);
        iterations += used;
        if stage_status == SteadyStatus::Solved {
            (*z, *active, t) = (trial_z, trial_active, target);
        } else if step > 1.0 / 64.0 {
            step *= 0.5;
        } else {
            status = stage_status;
        }
    }
    (status, iterations)
}
