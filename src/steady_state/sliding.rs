//! The periodic steady state of sliding pairs (`contact.pairs = "sliding"`): what it is, where
//! it exists, and how `wearfem steady` computes it where it does.
//!
//! # What a steady state is under a finite stroke
//!
//! Body 1's contact points sit at x along its (straight, horizontal) contact edge; the stroke
//! brings body 2's track coordinate X = x + u under them, u the offset of the position. At
//! position u the gap is
//!
//! g(x, u) = g₀(x, u) + w₁(x) + w₂(x + u) − c(u) − θ(u) x,
//!
//! g₀ the geometry of that position, w₁ and w₂ each body's wear, c and θ the plate's rigid
//! motions (set by equilibrium at each position). The state is periodic when one period
//! changes no position's pressure, i.e. (the flexibility being linear) when the period's wear
//! changes every position's gap by a rigid motion only:
//!
//! Δw₁(x) + Δw₂(x + u) = Δc(u) + Δθ(u) x   wherever p(x, u) > 0.            (S)
//!
//! Δw₁ does not depend on u, so on every window of the track the contact covers at some
//! position, Δw₂ is affine; overlapping windows make it one affine function over the track
//! the contact sweeps.
//!
//! **A closed track turning one way** (a ring, a disc, a drum under monotonic sliding): every
//! track point passes under the whole contact once a turn and collects
//! Δw₂ = β̃₂ v^(a−1) ∫ pᵇ dx per turn (dt = dx/v). If every position is alike (the ring's
//! geometry, mesh and supports the same all round, and the positions an even share of its
//! rim), the steady pressure is the same at every position, so Δw₂ is the same everywhere: the
//! ring deepens evenly, a rigid motion. (S) then asks body 1's own wear per turn to be a rigid
//! motion: β̃₁ v^a pᵇ = Δc + Δθ x over the contact. That is the fixed pairs' steady condition
//! with body 2's wear left out, solved by the same Newton method
//! ([`crate::steady::steady_state`]) on the contact at rest with body 1's wear term alone.
//! Whether the positions are alike is not assumed: [`position_spread`] solves every position
//! on the steady worn shape and measures how far their pressures stray from it.
//! A ring that does not wear (β̃₂ = 0) changes nothing of this.
//!
//! **A reciprocating stroke with body 2 wearing** (a straight track, or a ring swung to and
//! fro): the track's outermost points, X within ε of the last point the contact reaches, are
//! under the contact only at the positions within ε of the stroke's end, so they collect
//! β̃₂ ∫ pᵇ v^(a−1) du over a length ε of stroke per period, which vanishes with ε for any
//! integrable pressure (v^(a−1) too stays integrable at a reversal, where v → 0, for a > 0).
//! The middle of the track collects a finite depth every period (for a = b = 1 and positions
//! alike over a flat middle, β̃₂F/t per half period). So Δw₂ cannot be affine over the
//! track: (S) fails, and no periodic state exists. The depth between the track's middle and
//! its ends grows by the same amount every period: the trough deepens and its ends steepen
//! without bound, which is what a run tends to, and what `wearfem steady` says instead of
//! computing a state that does not exist. (A rounded slider adds a second reason: its worn
//! flat keeps widening as long as it wears, docs/sliding.md.)
//!
//! **A reciprocating stroke over a body 2 that does not wear**: (S) asks body 1's wear summed
//! over all positions of a period to be rigid, with each position's pressure from its own
//! geometry: a steady state exists, a problem in as many pressures as positions; not built
//! yet, and refused by name.

use crate::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::wear::WearLaw;

/// Whether sliding pairs have a periodic steady state (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FiniteStrokeSteady {
    /// Body 2 turns one way under body 1: it wears evenly, and body 1's own wear is rigid.
    EvenTrack,
    /// A reciprocating stroke over a wearing body 2: none exists; the track's ends steepen.
    EndsSteepen,
    /// A reciprocating stroke over a body 2 that does not wear: exists, not built.
    NotBuilt,
}

impl FiniteStrokeSteady {
    /// The case of a run: sliding one way (`monotonic`, only on a closed track) or to and
    /// fro, and whether body 2 wears.
    pub fn of(monotonic: bool, body2_wears: bool) -> FiniteStrokeSteady {
        match (monotonic, body2_wears) {
            (true, _) => FiniteStrokeSteady::EvenTrack,
            (false, true) => FiniteStrokeSteady::EndsSteepen,
            (false, false) => FiniteStrokeSteady::NotBuilt,
        }
    }

    /// Why there is no steady state to compute (None for [`FiniteStrokeSteady::EvenTrack`]).
    pub fn refusal(&self) -> Option<&'static str> {
        match self {
            FiniteStrokeSteady::EvenTrack => None,
            FiniteStrokeSteady::EndsSteepen => Some(
                "with a finite reciprocating stroke and body 2 wearing there is no periodic steady state: the track's outermost points are under the contact only at the very ends of the stroke and wear ever less than its middle, so the trough deepens and its ends steepen without bound (docs/sliding.md, \"The steady state\"); `wearfem run` shows what it tends to",
            ),
            FiniteStrokeSteady::NotBuilt => Some(
                "with a finite reciprocating stroke over a body 2 that does not wear, the steady state (body 1's wear summed over every position rigid) exists but is not built yet; `wearfem run` integrates it",
            ),
        }
    }
}

/// The depth body 2 loses per turn when it turns one way under body 1 at the steady pressure
/// `pressure` (MPa at body 1's contact points, integration weights `weight` in mm): every
/// point of it passes under the whole contact, β̃₂ v^(a−1) ∫ pᵇ dx, mm. `speed` v in mm/s.
pub fn even_track_depth_per_turn(
    law: WearLaw,
    speed: f64,
    weight: &[f64],
    pressure: &[f64],
) -> f64 {
    let integral: f64 = weight
        .iter()
        .zip(pressure)
        .map(|(w, p)| w * p.max(0.0).powf(law.b))
        .sum();
    law.beta * speed.powf(law.a - 1.0) * integral
}

/// How far the positions of a turning ring stray from the steady state computed at rest:
/// each position solved on body 1's steady worn shape (the shape at rest, `shape`, minus the
/// geometry at rest, plus the position's own geometry; the ring's even wear is a rigid
/// motion and drops out). The largest difference from `pressure` relative to its peak, or
/// None if a position's solve fails.
pub fn position_spread(
    contacts: &[CondensedContact],
    solvers: &mut [ContactSolver],
    shape: &[f64],
    pressure: &[f64],
    direction: Direction,
) -> Option<f64> {
    let at_rest = &contacts.first()?.points.initial_gap;
    let peak = pressure.iter().fold(0.0f64, |a, &b| a.max(b));
    let mut solution = ContactSolution::default();
    let mut spread = 0.0f64;
    for (contact, solver) in contacts.iter().zip(solvers.iter_mut()) {
        let gap: Vec<f64> = (contact.points.initial_gap.iter())
            .zip(shape.iter().zip(at_rest))
            .map(|(own, (g, rest))| own + g - rest)
            .collect();
        solver.set_compliance(&vec![0.0; gap.len()]);
        let info = solver.solve_pressures_into(&gap, direction, &mut solution);
        if info.status != Status::Solved {
            return None;
        }
        spread = (solution.pressure.iter().zip(pressure))
            .map(|(a, b)| (a - b).abs())
            .fold(spread, f64::max);
    }
    (peak > 0.0).then(|| spread / peak)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn even_depth_is_archards_for_a_equal_b_equal_one() {
        // a = b = 1: β̃₂ ∫ p dx = β̃₂ F/t whatever the speed.
        let law = WearLaw {
            beta: 2e-6,
            a: 1.0,
            b: 1.0,
        };
        let weight = [0.25, 0.5, 0.25];
        let pressure = [4.0, 8.0, 4.0];
        let depth = even_track_depth_per_turn(law, 361.0, &weight, &pressure);
        assert!((depth - 2e-6 * 6.0).abs() < 1e-20);
    }

    #[test]
    fn only_a_turning_track_has_a_steady_state_here() {
        assert!(FiniteStrokeSteady::of(true, true).refusal().is_none());
        assert!(FiniteStrokeSteady::of(true, false).refusal().is_none());
        assert!(FiniteStrokeSteady::of(false, true)
            .refusal()
            .unwrap()
            .contains("no periodic steady state"));
        assert!(FiniteStrokeSteady::of(false, false)
            .refusal()
            .unwrap()
            .contains("not built"));
    }
}
