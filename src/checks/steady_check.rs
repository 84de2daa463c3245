//! Whether a wear run ended at the steady state, judged against the steady state itself.
//!
//! The run's own measures ([`crate::wear::SteadyDistance`]: the non-rigid part of the last
//! cycle's wear, δw, the spread of p⁺ + p⁻) say how much the last cycle still changes the
//! shape, not how far its pressures are from where they are heading: a slow mode (the
//! rotation of a pinned plate, the ends of a worn zone) can leave the pressures several
//! percent away while one cycle's wear is already rigid to 1e-3 (punch-b40 at μ = 0.36 after
//! 5000 steps: 2 % of the peak; after one step of k = 100 000: 9 %). The steady state of the
//! same condensed problem costs one Newton solve started from the run's last cycle, a few
//! percent of the run (0.07 s at 1025 points), so the run is compared with it point by point.

use crate::contact::CondensedContact;
use crate::steady::{steady_state_near, SteadySliding, SteadyStatus};
use crate::wear::{WearHistory, WearIntegrator};
use std::time::Instant;

/// The last cycle's pressures may differ from the steady state's by at most this fraction
/// of its peak for the run to count as at the steady state (issue 9's bound for "the run
/// ends at the steady state").
pub const STEADY_PRESSURE_LIMIT: f64 = 0.01;

/// A run's last cycle against the steady state of the same problem.
#[derive(Clone, Debug, PartialEq)]
pub enum SteadyCheck {
    /// Largest |p_run − p_steady| over the points and both half cycles (the one pressure of
    /// monotonic sliding), relative to the steady state's peak pressure (dimensionless).
    Compared {
        /// The relative distance.
        pressure: f64,
        /// Seconds the steady solve took.
        seconds: f64,
    },
    /// No steady state to compare with: the reason (a fixed plate has none of the form the
    /// steady solver finds; friction can rule one out).
    Unavailable(String),
    /// No steady state to compare with, and none to expect: the last cycle's two half cycles
    /// touch separate zones (they share at most one contact point), so each wears its own
    /// facet with its own rigid motion (the punch rocks) and no state with one rigid wear per
    /// period exists. The zones' first and last contact points, x in mm.
    SeparateZones {
        /// The '+' half cycle's zone.
        plus: [f64; 2],
        /// The '−' half cycle's zone.
        minus: [f64; 2],
    },
    /// The run's contact zone is still growing towards the steady state's wider one: the
    /// run is running in, and its distance from the steady state says how much of the zone
    /// is still to wear in, not how close it has come. With `unbounded`, the steady state
    /// itself fills the named edge to an end where body 1's surface goes on (a cylinder on a
    /// flat): no steady state exists on the surface, and the distance would depend on how
    /// much of it was named.
    Growing {
        /// The distance of [`SteadyCheck::Compared`] (dimensionless).
        pressure: f64,
        /// Seconds the steady solve took.
        seconds: f64,
        /// The run's contact zone in its last cycle: first and last x in contact, mm.
        run: [f64; 2],
        /// The steady state's zone, mm.
        steady: [f64; 2],
        /// Whether the steady zone reaches an end of the named edge where the surface goes on.
        unbounded: bool,
    },
    /// The run has no complete cycle to compare.
    NoCycle,
}

impl std::fmt::Display for SteadyCheck {
    /// What the check found, as the console says it.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SteadyCheck::Compared { pressure, seconds } => write!(
                f,
                "pressures {:.2} % of the peak from the steady state's (`wearfem steady`, computed in {seconds:.3} s)",
                100.0 * pressure
            ),
            SteadyCheck::Unavailable(why) => write!(f, "no steady state to compare with ({why})"),
            SteadyCheck::SeparateZones { plus, minus } => write!(
                f,
                "the half cycles touch separate zones (x = {:.2} … {:.2} mm in '+', {:.2} … {:.2} mm in '−'): each wears its own facet with its own rigid motion (the punch rocks), so no steady state with one rigid wear per period exists",
                plus[0], plus[1], minus[0], minus[1]
            ),
            SteadyCheck::Growing {
                run,
                steady,
                unbounded: true,
                ..
            } => write!(
                f,
                "the contact zone still grows (x = {:.3} … {:.3} mm in the last cycle) and no steady state exists on this surface: the steady state of the named edge fills it to its end (x = {:.3} … {:.3} mm) where body 1's surface goes on, so a distance from it would depend on how much of the surface was named",
                run[0], run[1], steady[0], steady[1]
            ),
            SteadyCheck::Growing {
                pressure,
                run,
                steady,
                unbounded: false,
                ..
            } => write!(
                f,
                "the contact zone still grows (x = {:.3} … {:.3} mm in the last cycle, x = {:.3} … {:.3} mm in the steady state): the run is running in, {:.2} % of the peak from the steady state's pressures, which it approaches only as the zone fills",
                run[0], run[1], steady[0], steady[1], 100.0 * pressure
            ),
            SteadyCheck::NoCycle => write!(f, "no complete cycle"),
        }
    }
}

impl SteadyCheck {
    /// Whether the run counts as at the steady state: against the steady state when there is
    /// one, else by its own last cycle's wear ([`crate::wear::STEADY_REPORT_LIMIT`]).
    pub fn reached(&self, history: &WearHistory) -> bool {
        match self {
            SteadyCheck::Compared { pressure, .. } => *pressure <= STEADY_PRESSURE_LIMIT,
            _ => history
                .steady_distance
                .is_some_and(|d| d.unsettled() <= crate::wear::STEADY_REPORT_LIMIT),
        }
    }
}

/// How [`SteadyCheck::Unavailable`]'s reason begins where no steady state exists at all.
pub const NONE_EXISTS: &str = "no steady state exists";

/// Compare the last cycle of `history` with the steady state of `contact` under the wear law
/// and sliding of `integrator`.
pub fn check(
    contact: &CondensedContact,
    integrator: &WearIntegrator,
    history: &WearHistory,
) -> SteadyCheck {
    if history.steady_distance.is_none() {
        return SteadyCheck::NoCycle;
    }
    if contact.axisymmetric && contact.rigid_modes.is_empty() {
        // (The plane message names "vertical_rotation", which a body of revolution's plate
        // cannot have.)
        return SteadyCheck::Unavailable(format!(
            "{NONE_EXISTS} while the plate is held: the wear only relieves the contact (a body of revolution's plate can move along the axis only, plate.motion = \"vertical\")"
        ));
    }
    let collapsing = (0..2).any(|body| integrator.law_of(body).is_some_and(|l| l.a >= 2.0 * l.b));
    if integrator.about_axis().is_some() && !contact.axis_points.is_empty() && collapsing {
        // A turn whose steady pressure p ∝ r^(−a/b) cannot carry a load reaching the axis:
        // no steady state exists, and a solve would give a mesh's answer.
        return SteadyCheck::Unavailable(format!(
            "{NONE_EXISTS}: the bodies turn about their axis, touch on it, and a ≥ 2b (see the turn-on-axis warning)"
        ));
    }
    let start = Instant::now();
    let sliding = if integrator.is_monotonic() {
        SteadySliding::Monotonic(integrator.first_direction)
    } else {
        SteadySliding::Reciprocating
    };
    // The run's last cycle is a close start for Newton's method.
    let near: Vec<&[f64]> = if integrator.is_monotonic() {
        vec![if history.p_plus.is_empty() {
            &history.p_minus
        } else {
            &history.p_plus
        }]
    } else {
        vec![&history.p_plus, &history.p_minus]
    };
    // With heat the steady state is the one with the periodic temperature.
    let solved = match integrator.heat.as_ref() {
        None => steady_state_near(
            contact,
            integrator.wear_terms(),
            sliding,
            Default::default(),
            Some(&near),
        )
        .map_err(|e| e.to_string()),
        Some(model) => crate::thermal_steady::steady_state_with_heat(
            contact,
            &integrator.half_period_wear(),
            sliding,
            Default::default(),
            model,
        )
        .map(|s| s.state)
        .map_err(|e| e.to_string()),
    };
    let state = match solved {
        Ok(state) => state,
        Err(e) => return SteadyCheck::Unavailable(e),
    };
    if state.status != SteadyStatus::Solved {
        if !integrator.is_monotonic() {
            if let Some((plus, minus)) = separate_zones(contact, &history.p_plus, &history.p_minus)
            {
                return SteadyCheck::SeparateZones { plus, minus };
            }
        }
        return SteadyCheck::Unavailable(format!(
            "the steady solve ended with {:?} ({})",
            state.status,
            crate::steady::failure_hint(&state, contact)
        ));
    }
    let pairs: Vec<(&[f64], &[f64])> = if integrator.is_monotonic() {
        // One direction: the run keeps it in whichever profile that direction fills.
        let run = if history.p_plus.is_empty() {
            &history.p_minus
        } else {
            &history.p_plus
        };
        vec![(run, &state.p_plus)]
    } else {
        vec![
            (&history.p_plus, &state.p_plus),
            (&history.p_minus, &state.p_minus),
        ]
    };
    let Some(pressure) = relative_difference(&pairs) else {
        return SteadyCheck::Unavailable("the steady state carries no pressure".into());
    };
    let seconds = start.elapsed().as_secs_f64();
    let run: Vec<&[f64]> = pairs.iter().map(|(run, _)| *run).collect();
    let steady: Vec<&[f64]> = pairs.iter().map(|(_, steady)| *steady).collect();
    let closing = history.steady_distance.map_or(0.0, |d| d.closing);
    match (zone(&run), zone(&steady)) {
        // Zones by contact-point index: the points follow body 1's edge, not always x.
        (Some(r), Some(s))
            if closing > crate::wear::STEADY_REPORT_LIMIT && (s[0] < r[0] || s[1] > r[1]) =>
        {
            let x = |i: usize| contact.points.x[i][0];
            SteadyCheck::Growing {
                pressure,
                seconds,
                run: [x(r[0]), x(r[1])],
                steady: [x(s[0]), x(s[1])],
                unbounded: !contact.edge_ends_in_contact(&steady).is_empty(),
            }
        }
        _ => SteadyCheck::Compared { pressure, seconds },
    }
}

/// The contact zone of `profiles` (pressures, MPa, at the contact points): the first and
/// last point where any of them carries more than 1e-9 of their peak (below, the round-off
/// of a zone's end).
fn zone(profiles: &[&[f64]]) -> Option<[usize; 2]> {
    let peak = profiles
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, &v| m.max(v));
    let touching = |i: usize| profiles.iter().any(|p| p[i] > 1e-9 * peak);
    let n = profiles.first()?.len();
    let first = (0..n).find(|&i| touching(i))?;
    let last = (0..n).rev().find(|&i| touching(i))?;
    Some([first, last])
}

/// The x ranges (mm) of the two half cycles' contact zones when they share at most one
/// contact point (a rocking punch, [`SteadyCheck::SeparateZones`]); None otherwise, or when a
/// half carries no pressure.
fn separate_zones(
    contact: &CondensedContact,
    p_plus: &[f64],
    p_minus: &[f64],
) -> Option<([f64; 2], [f64; 2])> {
    let peak = p_plus.iter().chain(p_minus).fold(0.0f64, |m, &p| m.max(p));
    // Pressures below 1e-9 of the peak are the round-off of a zone's end.
    let touching =
        |p: &[f64]| -> Vec<usize> { (0..p.len()).filter(|&i| p[i] > 1e-9 * peak).collect() };
    let (plus, minus) = (touching(p_plus), touching(p_minus));
    let shared = plus.iter().filter(|i| minus.contains(i)).count();
    let range = |zone: &[usize]| -> Option<[f64; 2]> {
        let x = |i: usize| contact.points.x[i][0];
        Some([x(*zone.first()?), x(*zone.last()?)])
    };
    (shared <= 1).then(|| Some((range(&plus)?, range(&minus)?)))?
}

/// Largest |profile − reference| over the (profile, reference) pairs, relative to the
/// references' peak pressure; None when the references carry no pressure or a pair differs
/// in length.
fn relative_difference(pairs: &[(&[f64], &[f64])]) -> Option<f64> {
    let peak = pairs
        .iter()
        .flat_map(|(_, reference)| reference.iter())
        .fold(0.0f64, |m, &v| m.max(v));
    let worst = pairs
        .iter()
        .flat_map(|(a, b)| a.iter().zip(b.iter()).map(|(x, y)| (x - y).abs()))
        .fold(0.0f64, f64::max);
    let same = pairs.iter().all(|(a, b)| a.len() == b.len());
    (same && peak > 0.0 && peak.is_finite() && worst.is_finite()).then(|| worst / peak)
}

/// Largest difference of `a`'s p⁺ and p⁻ from `reference`'s, relative to the reference's
/// peak pressure (None when the reference carries no pressure or the profiles differ in size).
pub fn pressure_distance(
    a: &crate::steady::SteadyState,
    reference: &crate::steady::SteadyState,
) -> Option<f64> {
    relative_difference(&[
        (&a.p_plus, &reference.p_plus),
        (&a.p_minus, &reference.p_minus),
    ])
}
