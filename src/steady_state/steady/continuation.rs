//! Continuation for steady states that Newton's method does not reach from its start: the
//! problem is walked to from one it does solve, a stage at a time.

use super::starts::unworn_pressures;
use super::{frictionless_reciprocating, SteadySettings, SteadySliding, SteadyStatus, System};
use crate::contact::CondensedContact;
use crate::wear::WearTerms;

/// What a retry from the frictionless problem ([`from_frictionless`]) came to.
pub(super) struct Retry {
    pub status: SteadyStatus,
    pub iterations: usize,
    /// The iterate (the retry's start if it led nowhere).
    pub z: Vec<f64>,
    /// With friction, when the retry failed after finding the frictionless state: the
    /// friction coefficient up to which it was followed (0: not even 1/64 of μ).
    pub friction_reached: Option<f64>,
}

/// A second start for a steady state that Newton's method did not reach from a uniform
/// pressure. A load near one end leaves a steady zone a fraction of the edge long, and the
/// active sets from a uniform start cycle (red team 17: frictionless, zones under 3/8 of the
/// punch); the unworn frictionless contact's pressures lie on the right side. With friction,
/// μ is then walked to from none ([`walk`]). Should that fail with reciprocating sliding, the
/// walk starts again from the frictionless steady state solved as one half
/// (`frictionless_reciprocating`): as two halves, round-off parts their active sets where the
/// pressure vanishes at a zone's end (b = 0.1 with the load on the punch's last 5 mm: μ =
/// 1e-12 failed), while from the unworn pressures some cases are reached that the other
/// start misses (the same load at μ = 0.04). The contact is cloned only here.
pub(super) fn from_frictionless(
    system: &System,
    contact: &CondensedContact,
    sliding: SteadySliding,
    signs: &[f64],
    terms: &WearTerms,
    settings: SteadySettings,
) -> Retry {
    let mut frictionless = contact.clone();
    frictionless.friction = 0.0;
    let mut retry = Retry {
        status: SteadyStatus::MaxIterations,
        iterations: 0,
        z: Vec::new(),
        friction_reached: None,
    };
    let walk_to_friction = |retry: &mut Retry, mut z: Vec<f64>, mut active: Vec<Vec<bool>>| {
        let (status, iterations, reached) = walk(
            |t, z, active| {
                System::new(contact, signs, t)
                    .with_offset(&system.offset)
                    .newton(terms, z, active, settings)
            },
            &mut z,
            &mut active,
        );
        retry.iterations += iterations;
        retry.status = status;
        if status == SteadyStatus::Solved {
            retry.z = z;
        } else {
            let reached = reached * contact.friction;
            retry.friction_reached =
                Some(retry.friction_reached.map_or(reached, |r| r.max(reached)));
        }
    };
    if let Some(pressures) = unworn_pressures(&frictionless, signs) {
        let (mut z, mut active) = system.start(&pressures);
        let (status, iterations) = System::new(contact, signs, 0.0)
            .with_offset(&system.offset)
            .newton(terms, &mut z, &mut active, settings);
        retry.iterations += iterations;
        if contact.friction == 0.0 || status != SteadyStatus::Solved {
            (retry.status, retry.z) = (status, z);
        } else {
            walk_to_friction(&mut retry, z, active);
        }
    }
    if retry.status != SteadyStatus::Solved
        && contact.friction != 0.0
        && sliding == SteadySliding::Reciprocating
    {
        let mirror = frictionless_reciprocating(&frictionless, terms, settings, None);
        retry.iterations += mirror.iterations;
        if mirror.status == SteadyStatus::Solved {
            let (z, active) = system.start_from_state(&mirror);
            walk_to_friction(&mut retry, z, active);
        }
    }
    retry
}

/// Newton solves for the exponents 1 + t (b − 1), t from 0 to 1 ([`walk`]).
pub(super) fn in_exponents(
    system: &System,
    terms: &WearTerms,
    z: &mut Vec<f64>,
    active: &mut Vec<Vec<bool>>,
    settings: SteadySettings,
) -> (SteadyStatus, usize) {
    let stage = |t: f64| terms.map(|c, b| (c, 1.0 + t * (b - 1.0)));
    let (status, iterations) = system.newton(&stage(0.0), z, active, settings);
    if status != SteadyStatus::Solved {
        return (status, iterations);
    }
    let (status, more, _) = walk(
        |t, z, active| system.newton(&stage(t), z, active, settings),
        z,
        active,
    );
    (status, iterations + more)
}

/// Solves `stage(t)` for t from 0 (already solved in `z` and `active`) to 1, each stage
/// starting from the last converged one; a failed stage is retried with half the step, down
/// to 1/64. On failure the last converged stage is left in `z` and `active`; returns the
/// status, the iterations and the last t solved.
fn walk(
    stage: impl Fn(f64, &mut Vec<f64>, &mut Vec<Vec<bool>>) -> (SteadyStatus, usize),
    z: &mut Vec<f64>,
    active: &mut Vec<Vec<bool>>,
) -> (SteadyStatus, usize, f64) {
    let (mut status, mut iterations) = (SteadyStatus::Solved, 0);
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
    (status, iterations, t)
}
