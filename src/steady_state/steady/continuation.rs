//! Continuation for steady states that Newton's method does not reach from its start: the
//! problem is walked to from one it does solve, a stage at a time.

use super::{SteadySettings, SteadyStatus, System};

/// Newton solves for the exponents 1 + t (b − 1), t from 0 to 1, each stage starting from
/// the last converged one; a failed stage is retried with half the step, down to 1/64.
pub(super) fn continuation(
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
    let (mut status, mut iterations) = system.newton(&stage(0.0), z, active, settings);
    let (mut t, mut step) = (0.0f64, 0.25f64);
    while status == SteadyStatus::Solved && t < 1.0 {
        let target = (t + step).min(1.0);
        let (mut trial_z, mut trial_active) = (z.clone(), active.clone());
        let (stage_status, used) =
            system.newton(&stage(target), &mut trial_z, &mut trial_active, settings);
        iterations += used;
        if stage_status == SteadyStatus::Solved {
            (*z, *active, t) = (trial_z, trial_active, target);
        } else if step > 1.0 / 64.0 {
            step *= 0.5;
        } else {
            // The last converged stage is kept; the requested exponents were not reached.
            status = stage_status;
        }
    }
    (status, iterations)
}
