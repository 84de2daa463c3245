//! `wearfem steady` on a problem with sliding pairs: the steady state of a ring or disc
//! turning one way under body 1, computed directly; a reciprocating stroke refused with the
//! reason ([`crate::steady_state::sliding`] derives both).

use super::driver::JobError;
use super::sliding::{setup, SlidingSetup};
use crate::problem::Problem;
use crate::report::json::number;
use crate::steady::{SteadySliding, SteadyState, SteadyStatus};
use crate::steady_state::sliding::{
    even_track_depth_per_turn, position_spread, FiniteStrokeSteady,
};
use serde_json::{json, Value};
use std::time::Instant;

/// Largest spread of the positions' pressures on the steady worn shape (relative to the
/// peak) below which the ring's positions count as alike, so that its even wear, on which
/// the steady state rests, holds. The issue asks a run and `steady` to agree to 1 % of the
/// peak; a spread of a quarter of that leaves the rest to the run's own error.
pub const POSITION_SPREAD_LIMIT: f64 = 2.5e-3;

/// The steady state of a turning ring, with what the ring does.
pub struct SlidingSteadyState {
    /// Body 1's steady state on the contact at rest (position 0): its pressure, its worn
    /// shape, and the plate's rigid wear per turn from body 1's wear alone.
    pub state: SteadyState,
    /// The set-up: every position's contact and solver.
    pub setup: SlidingSetup,
    /// The depth body 2 loses evenly per step (one turn), mm.
    pub body2_depth_per_turn: f64,
    /// The sliding distance of a turn, mm.
    pub turn: f64,
    /// How far the positions' pressures on the steady shape stray from the state's
    /// (relative to its peak; None if a position's solve failed).
    pub position_spread: Option<f64>,
    /// Seconds, set-up included.
    pub seconds: f64,
}

/// Compute the steady state of a sliding-pairs problem, or say why there is none.
pub fn steady(problem: &Problem) -> Result<SlidingSteadyState, JobError> {
    let start = Instant::now();
    let mut setup = setup(problem, None)?;
    let settings = setup.settings.clone();
    let case = FiniteStrokeSteady::of(settings.monotonic, settings.laws[1].is_some());
    let ends = &setup.contact.stroke.ends;
    let swing = (ends[ends.len() - 1] - ends[0]).abs();
    if let (false, Some(period)) = (settings.monotonic, setup.contact.shape.period()) {
        if swing >= period {
            // No track ends then, and the argument of the module docs does not apply; the
            // wear is not even either (the speed varies along the swing).
            return Err(problem
                .error(
                    "contact.pairs",
                    format!("a ring swung to and fro over {:.3} turns has no track ends, but its wear is not even (the speed varies along the swing): its steady state is not built yet; `wearfem run` integrates it", swing / period),
                )
                .into());
        }
    }
    if let Some(why) = case.refusal() {
        return Err(problem.error("contact.pairs", why).into());
    }
    let law = settings.laws[0].ok_or_else(|| {
        problem.error(
            "wear.body1",
            "body 1 does not wear: a ring turning under it wears evenly and changes no pressure, so every state is steady and the first contact solve's pressure stays; `wearfem run` gives it",
        )
    })?;
    let turn = settings.speed * step_time(problem);
    // Body 1's wear per turn: β̃₁ vᵃ pᵇ over the turn's time.
    let terms = [(
        law.beta * settings.speed.powf(law.a) * step_time(problem),
        law.b,
    )];
    let sliding = SteadySliding::Monotonic(settings.first_direction);
    let state = crate::steady::steady_state(
        &setup.contact.contacts[0],
        &terms,
        sliding,
        Default::default(),
    )
    .map_err(|e| problem.error("plate.motion", e.to_string()))?;
    let (body2_depth_per_turn, spread) = if state.status == SteadyStatus::Solved {
        let depth = settings.laws[1].map_or(0.0, |l| {
            let weight = &setup.contact.contacts[0].points.weight;
            even_track_depth_per_turn(l, settings.speed, weight, &state.p_plus)
        });
        let direction = settings.first_direction;
        let spread = position_spread(
            &setup.contact.contacts,
            &mut setup.solvers,
            &state.shape,
            &state.p_plus,
            direction,
        );
        (depth, spread)
    } else {
        (0.0, None)
    };
    Ok(SlidingSteadyState {
        state,
        setup,
        body2_depth_per_turn,
        turn,
        position_spread: spread,
        seconds: start.elapsed().as_secs_f64(),
    })
}

fn step_time(problem: &Problem) -> f64 {
    problem.spec.wear.as_ref().map_or(0.0, |w| w.step_time)
}

impl SlidingSteadyState {
    /// What summary.json adds for the track: body 2's even wear and the positions' spread.
    pub fn track_json(&self) -> Value {
        let per_metre = self.body2_depth_per_turn / (self.turn * 1e-3);
        json!({
            "pairs": "sliding",
            "positions": self.setup.contact.len(),
            "turn_mm": number(self.turn),
            "body2_depth_per_turn": number(self.body2_depth_per_turn),
            "body2_depth_per_metre": number(per_metre),
            "position_spread": self.position_spread.map(number),
        })
    }

    /// summary.json of the steady state: [`crate::output::steady_summary`]'s, with the
    /// warnings of the contact at rest and of the positions, and the track's own part.
    pub fn summary(&self, problem: &Problem) -> Value {
        let contact = &self.setup.contact.contacts[0];
        let mut warnings = super::driver::steady_warnings(problem, contact, &self.state);
        warnings.extend(self.warnings(problem));
        let mut summary =
            crate::output::steady_summary(problem, contact, &self.state, self.seconds, &warnings);
        summary["track"] = self.track_json();
        summary
    }

    /// The warning when the positions are not alike enough for the ring to wear evenly.
    pub fn warnings(&self, problem: &Problem) -> Vec<String> {
        match self.position_spread {
            Some(s) if s <= POSITION_SPREAD_LIMIT => vec![],
            spread => vec![crate::codes::warning(
                "uneven-ring",
                &problem.file,
                match spread {
                    Some(s) => format!("the ring's positions, each solved on the steady worn shape, give pressures up to {:.2} % of the peak apart: the ring is not alike all round (its mesh, supports or loads), so it does not wear evenly, and this steady state, which rests on even wear, is off by about as much at some positions (a run with many turns a step smooths the positions' differences too: end it with k = 1 to compare); mesh the rim evenly with contact.positions dividing its elements", 100.0 * s),
                    None => "a position of the ring could not be solved on the steady worn shape, so whether the ring wears evenly, on which this steady state rests, is not known".to_string(),
                },
            )],
        }
    }
}
