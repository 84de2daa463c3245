//! `wearfem run` on a problem with sliding pairs (`contact.pairs = "sliding"`): the set-up
//! of every position, the run, and what its summary.json says.

use super::driver::{check_contact_probes, contact_probes, direction, method, JobError};
use crate::complementarity::ContactSolver;
use crate::contact::track::{default_positions, SlidingContact, TrackShape};
use crate::contact::CondensedContact;
use crate::contact::MAX_POSITIONS;
use crate::problem::{Problem, ProblemError};
use crate::report::json::{number, numbers};
use crate::wear::sliding::{self, SlidingHistory, SlidingSettings};
use crate::wear::WearIntegrator;
use serde_json::{json, Value};
use std::time::Instant;

/// Largest estimated error of the last cycle's wear rate from resolving the stroke into its
/// positions (relative to the rate's peak, see [`SlidingRun::position_error`]) above which a
/// run warns that the positions are too few.
pub const POSITION_ERROR_LIMIT: f64 = 0.05;

/// A finished sliding-pairs run with its set-up.
pub struct SlidingRun {
    /// The positions' condensed contacts.
    pub contact: SlidingContact,
    /// What the run did.
    pub history: SlidingHistory,
    /// The run's settings.
    pub settings: SlidingSettings,
    /// Probe names on body 1 and their contact point indices.
    pub probes: Vec<(String, usize)>,
    /// Probe names on body 2 and their track coordinates (mm).
    pub track_probes: Vec<(String, f64)>,
    /// Seconds spent on the FE set-up and the positions' condensation.
    pub setup_seconds: f64,
    /// Seconds spent integrating.
    pub run_seconds: f64,
    /// Thickness t, mm.
    pub thickness: f64,
    /// The names of body 1 and body 2.
    pub body_names: [String; 2],
    /// Body 2's surface at rest at each track cell's centre: point and outward normal.
    pub track_surface: Vec<([f64; 2], [f64; 2])>,
}

/// Whether `problem` asks for sliding pairs.
pub fn is_sliding(problem: &Problem) -> bool {
    problem
        .spec
        .contact
        .as_ref()
        .is_some_and(|c| c.pairs == "sliding")
}

/// Refuse a job built for fixed pairs (`what`) on a problem with sliding pairs, naming the
/// key: it would otherwise compute the fixed pairs' answer in silence.
pub fn require_fixed_pairs(problem: &Problem, what: &str) -> Result<(), ProblemError> {
    if is_sliding(problem) {
        return Err(problem.error(
            "contact.pairs",
            format!("is \"sliding\", and {what} is only built for fixed pairs so far; `wearfem run` (Python: `Problem.run_sliding`) integrates sliding pairs, `wearfem steady` (Python: `Problem.steady`) finds the steady state of a ring turning under body 1 (a reciprocating stroke has none), and parameter studies are not built for them yet"),
        ));
    }
    Ok(())
}

/// The wear section as a sliding run's settings (`steps` overrides the duration).
fn settings(problem: &Problem, steps: Option<usize>) -> Result<SlidingSettings, ProblemError> {
    let spec = problem
        .spec
        .wear
        .clone()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let mut spec = crate::wear_units::resolve_duration(&spec)
        .map_err(|(key, message)| problem.error(key, message))?;
    if let Some(n) = steps {
        spec.steps = n;
        spec.record.retain(|&r| r <= n);
    }
    let integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| problem.error(key, message))?;
    Ok(SlidingSettings {
        laws: [integrator.law_of(0), integrator.law_of(1)],
        monotonic: integrator.is_monotonic(),
        speed: spec.speed,
        amplitude: spec.amplitude,
        omega: spec.omega,
        schedule: integrator.schedule().to_vec(),
        steps: spec.steps,
        record: spec.record.clone(),
        first_direction: direction(problem)?,
        probes: vec![],
        track_probes: vec![],
        tolerance: spec.tolerance,
        max_iterations: spec.max_iterations,
    })
}

/// The probes on body 2, which must lie on its contact edge (within 1e-6 of the body's
/// size, or of the ring's radius): their track coordinates (mm), where a sliding run reports
/// body 2's wear.
fn track_probes(
    problem: &Problem,
    body2: &crate::elasticity::ElasticBody,
    shape: TrackShape,
) -> Result<Vec<(String, f64)>, ProblemError> {
    let c = problem.spec.contact.as_ref().expect("checked");
    let (_, edge) = crate::contact::target_edge(problem, body2)?;
    let mut out = Vec::new();
    for (name, probe) in problem
        .spec
        .probes
        .iter()
        .filter(|(_, p)| p.body == c.target_body)
    {
        let [x, z] = probe.at;
        let (coordinate, off) = match shape {
            TrackShape::Straight => {
                // Along −z, into body 2 (the search takes the surfaces facing the line's
                // direction: along +z it found none of a flat's top, review of 2026-11-29).
                let off = body2
                    .mesh
                    .cross_edges(edge, probe.at, [0.0, -1.0])
                    .map_or(f64::INFINITY, |(s, ..)| s.abs());
                (x, off)
            }
            TrackShape::Ring { center, radius } => {
                let (dx, dz) = (x - center[0], z - center[1]);
                let arc = radius * dx.atan2(dz);
                (
                    arc.rem_euclid(std::f64::consts::TAU * radius),
                    (dx.hypot(dz) - radius).abs(),
                )
            }
        };
        let size = match shape {
            TrackShape::Ring { radius, .. } => radius,
            TrackShape::Straight => body2
                .mesh
                .vertices
                .iter()
                .fold(0.0f64, |a, v| a.max(v[0].abs()).max(v[1].abs())),
        };
        if off > 1e-6 * size.max(1.0) {
            return Err(problem.error(
                format!("probes.{name}.at"),
                format!("({x}, {z}) is not on body 2's contact edge \"{}\": with sliding pairs a probe on body 2 reports its wear along the track there", c.target_edge),
            ));
        }
        out.push((name.clone(), coordinate));
    }
    Ok(out)
}

/// The number of element edges on body 2's contact edge.
fn ring_elements(
    problem: &Problem,
    body2: &crate::elasticity::ElasticBody,
) -> Result<usize, ProblemError> {
    Ok(crate::contact::target_edge(problem, body2)?.1.len())
}

/// On a closed track a step unit is one turn: `wear.step_time` must be the time of one turn
/// at `wear.speed`.
fn check_turn(
    problem: &Problem,
    settings: &SlidingSettings,
    period: f64,
) -> Result<(), ProblemError> {
    let step_time = problem.spec.wear.as_ref().map_or(0.0, |w| w.step_time);
    let turn = period / settings.speed;
    if (step_time - turn).abs() > 1e-9 * turn {
        return Err(problem.error(
            "wear.step_time",
            format!("on a closed track a step unit is one turn of body 2 ({period:.6} mm round), which takes {turn:.9} s at wear.speed = {} mm/s; got {step_time} s", settings.speed),
        ));
    }
    Ok(())
}

/// A sliding-pairs problem set up: every position condensed and its solver built, the
/// probes found; what [`wear`] integrates and [`crate::jobs::sliding_steady`] solves on.
pub struct SlidingSetup {
    /// The run's settings (probes filled in).
    pub settings: SlidingSettings,
    /// The positions' condensed contacts.
    pub contact: SlidingContact,
    /// One contact solver per position (in `contact.stroke.positions` order).
    pub solvers: Vec<ContactSolver>,
    /// Probe names on body 1 and their contact point indices.
    pub probes: Vec<(String, usize)>,
    /// Probe names on body 2 and their track coordinates (mm).
    pub track_probes: Vec<(String, f64)>,
    /// Seconds spent on the FE set-up and the positions' condensation.
    pub setup_seconds: f64,
    /// The names of body 1 and body 2.
    pub body_names: [String; 2],
    /// Body 2's surface at rest at each track cell's centre: point and outward normal.
    pub track_surface: Vec<([f64; 2], [f64; 2])>,
}

/// Set up a sliding-pairs problem (`steps` overrides the duration).
pub fn setup(problem: &Problem, steps: Option<usize>) -> Result<SlidingSetup, JobError> {
    crate::contact::check_settings(problem)?;
    let mut settings = settings(problem, steps)?;
    let start = Instant::now();
    let (body1, mut body2) = CondensedContact::bodies(problem)?;
    let c = problem.spec.contact.as_ref().expect("checked");
    let shape = crate::contact::track::track_shape(problem, &body2)?;
    let count = match (c.positions, shape) {
        (Some(m), _) => m,
        (None, TrackShape::Ring { .. }) => ring_elements(problem, &body2)?.clamp(4, MAX_POSITIONS),
        (None, TrackShape::Straight) => {
            let (points, _) = CondensedContact::body1_points(problem, &body1)?;
            let x = &points.x;
            let edge = (x[x.len() - 1][0] - x[0][0]).abs();
            default_positions(2.0 * settings.amplitude, edge)
        }
    };
    let stroke = (!settings.monotonic).then_some(settings.amplitude);
    let contact = SlidingContact::build(
        problem,
        &body1,
        &mut body2,
        stroke,
        settings.first_direction.sign(),
        count,
    )?;
    if let (true, Some(period)) = (settings.monotonic, shape.period()) {
        check_turn(problem, &settings, period)?;
    }
    // Probes on body 2 report its wear along the track; those on body 1, its pressure.
    let track_probes = track_probes(problem, &body2, contact.shape)?;
    let mut on_body1 = problem.clone();
    on_body1.spec.probes.retain(|_, p| p.body != c.target_body);
    check_contact_probes(&on_body1, &contact.contacts[0])?;
    let method = method(problem)?;
    let solvers: Vec<ContactSolver> = contact
        .contacts
        .iter()
        .map(|c| ContactSolver::new(c, method))
        .collect();
    let probes = contact_probes(&on_body1, &contact.contacts[0]);
    let centres = contact.empty_track().centres();
    let track_surface =
        crate::contact::track::track_surface(problem, &body2, contact.shape, &centres)?;
    settings.probes = probes.iter().map(|p| p.1).collect();
    settings.track_probes = track_probes.iter().map(|p| p.1).collect();
    Ok(SlidingSetup {
        settings,
        contact,
        solvers,
        probes,
        track_probes,
        setup_seconds: start.elapsed().as_secs_f64(),
        body_names: [c.body.clone(), c.target_body.clone()],
        track_surface,
    })
}

/// Run the wear integration of a sliding-pairs problem.
pub fn wear(problem: &Problem, steps: Option<usize>) -> Result<SlidingRun, JobError> {
    let SlidingSetup {
        settings,
        contact,
        mut solvers,
        probes,
        track_probes,
        setup_seconds,
        body_names,
        track_surface,
    } = setup(problem, steps)?;
    let start = Instant::now();
    let history = sliding::run(&settings, &contact, &mut solvers);
    let run_seconds = start.elapsed().as_secs_f64();
    Ok(SlidingRun {
        thickness: contact.contacts[0].thickness,
        contact,
        history,
        settings,
        probes,
        track_probes,
        setup_seconds,
        run_seconds,
        body_names,
        track_surface,
    })
}

impl SlidingRun {
    /// Sliding distance of the completed steps, mm.
    pub fn distance(&self) -> f64 {
        let half_periods = self.history.steps.last().map_or(0, |s| s.half_period);
        self.stroke() * half_periods as f64
    }

    /// The sliding distance of one half period (reciprocating: 2u₀) or one turn (a closed
    /// track), mm.
    pub fn stroke(&self) -> f64 {
        let ends = &self.contact.stroke.ends;
        (ends[ends.len() - 1] - ends[0]).abs()
    }

    /// An estimate of the error that resolving the stroke into positions makes in the last
    /// cycle's wear rate (relative to its peak; None before a full cycle). The rate at each
    /// contact point is the sum over the positions of both half periods of p Δs (Archard's
    /// rule with a = b = 1); the same sum over every other position, each standing for two
    /// intervals, is the rate with half the positions, and the two differ by about the
    /// error of the coarser one (the rule holds each pressure over its interval: first
    /// order). On the tribometer example 24, 48, 96 and 192 positions give 11.8, 5.7, 2.4 and
    /// 1.2 %; the accumulated wear converges faster (docs/sliding.md).
    pub fn position_error(&self) -> Option<f64> {
        // A closed track turning one way has no '−' half period: its cycle is one turn.
        let directions = if self.settings.monotonic { 1 } else { 2 };
        let cycle = &self.history.last_cycle[..directions];
        if cycle.iter().any(|d| d.iter().any(|p| p.is_empty())) || self.contact.len() < 2 {
            return None;
        }
        let n = cycle[0][0].len();
        let (mut all, mut half) = (vec![0.0; n], vec![0.0; n]);
        for direction in cycle {
            for (j, pressure) in direction.iter().enumerate() {
                for i in 0..n {
                    all[i] += pressure[i];
                    if j % 2 == 0 {
                        // The last of an odd count stands for its own interval only.
                        let weight = if j + 1 < direction.len() { 2.0 } else { 1.0 };
                        half[i] += weight * pressure[i];
                    }
                }
            }
        }
        let peak = all.iter().fold(0.0f64, |a, &b| a.max(b));
        let error = all
            .iter()
            .zip(&half)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f64, f64::max);
        (peak > 0.0).then(|| error / peak)
    }

    /// One-line warnings about the run: the contact zones of the last cycle at every
    /// position (each code once, at the first position that gives it), the resolution in p
    /// of the first contact (at rest), and the positions' resolution.
    pub fn warnings(&self, problem: &Problem) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        let code = |w: &str| w.split(']').next().unwrap_or_default().to_string();
        for (j, contact) in self.contact.contacts.iter().enumerate() {
            let pressures: Vec<&[f64]> = self
                .history
                .last_cycle
                .iter()
                .filter_map(|d| d.get(j).map(Vec::as_slice))
                .filter(|p| !p.is_empty())
                .collect();
            if pressures.is_empty() {
                continue;
            }
            for w in crate::warnings::zone_warnings(problem, contact, &pressures) {
                if !out.iter().any(|o| code(o) == code(&w)) {
                    out.push(w);
                }
            }
        }
        if problem.spec.analysis.p_check.unwrap_or(true) {
            match CondensedContact::build(problem) {
                Ok((at_rest, _, _)) => out.extend(crate::p_check::p_check_warning(
                    problem,
                    crate::p_check::p_check(problem, &at_rest),
                )),
                Err(e) => out.push(format!(
                    "the check in p could not build the contact at rest: {e}"
                )),
            }
        }
        if self.contact.len() < 2 {
            out.push(crate::codes::warning(
                "few-positions",
                &problem.file,
                "contact.positions = 1: one pressure is held over the whole half period (or turn), and no estimate of what that costs can be made; give at least 2",
            ));
        }
        if let Some(error) = self.position_error() {
            if error > POSITION_ERROR_LIMIT {
                out.push(crate::codes::warning(
                    "few-positions",
                    &problem.file,
                    format!(
                        "contact.positions: the last cycle's wear rate changes by {:.1} % of its peak when every other of the stroke's {} positions per half period is left out; the rate is that uncertain: raise contact.positions",
                        100.0 * error,
                        self.contact.len()
                    ),
                ));
            }
        }
        out
    }

    /// summary.json of the run.
    pub fn summary(&self, problem: &Problem) -> Value {
        let h = &self.history;
        let points = &self.contact.contacts[0].points;
        let t = self.thickness;
        let area = h.steps.last().map_or([0.0; 2], |s| s.worn_area);
        let stopped = h
            .stopped
            .as_ref()
            .map(|(step, reason)| json!({"step": step, "reason": reason.to_string()}));
        let track_x = h.track.centres();
        json!({
            "problem": problem.file,
            "pairs": "sliding",
            "positions_per_half_period": self.contact.len(),
            "stroke": number(self.stroke()),
            "track_shape": match self.contact.shape {
                TrackShape::Straight => json!("straight"),
                TrackShape::Ring { center, radius } => json!({"ring": {"center": numbers(&center), "radius": number(radius)}}),
            },
            "positions": numbers(&self.contact.stroke.positions),
            "steps": h.steps.len(),
            "half_periods": h.steps.last().map_or(0, |s| s.half_period),
            "sliding_distance": number(self.distance()),
            "solves": h.solves,
            "setup_seconds": number(self.setup_seconds),
            "run_seconds": number(self.run_seconds),
            "stopped": stopped,
            "bodies": self.body_names,
            "worn_volume": [number(area[0] * t), number(area[1] * t)],
            "position_error": self.position_error().map(number),
            "probes": self.probes.iter().map(|(name, i)| json!({"name": name, "point": i, "x": numbers(&points.x[*i])})).collect::<Vec<_>>(),
            "track_probes": self.track_probes.iter().map(|(name, x)| json!({"name": name, "track_x": number(*x)})).collect::<Vec<_>>(),
            "history": h.steps,
            "final": {
                "x": points.x.iter().map(|p| number(p[0])).collect::<Vec<_>>(),
                "wear_body1": numbers(&h.wear_body1),
                "p_plus": h.last_cycle[0].iter().map(|p| numbers(p)).collect::<Vec<_>>(),
                "p_minus": h.last_cycle[1].iter().map(|p| numbers(p)).collect::<Vec<_>>(),
            },
            "track": {
                "x": numbers(&track_x),
                "wear_body2": numbers(&h.track.wear),
            },
            "steady_state": self.steady_state_json(),
            "warnings": self.warnings(problem),
        })
    }

    /// Whether a periodic steady state exists for this run ([`crate::steady_state::sliding`])
    /// and, where none does, what the run tends to: the track's deepest point against the
    /// depth a flat-bottomed trough gains per half period (β̃₂F/t, for a = b = 1), and the
    /// steepest slope of the track, which grows without bound at its ends.
    fn steady_state_json(&self) -> Value {
        use crate::steady_state::sliding::FiniteStrokeSteady;
        let case = FiniteStrokeSteady::of(self.settings.monotonic, self.settings.laws[1].is_some());
        if self.settings.monotonic && self.settings.laws[0].is_none() {
            // The ring wears evenly and changes nothing (a review found "computed by wearfem
            // steady" here, which refuses the case: there is nothing to compute).
            return json!({"exists": true, "why": "body 1 does not wear: every state is steady, the first pressure stays"});
        }
        let Some(why) = case.refusal() else {
            return json!({"exists": true, "computed_by": "wearfem steady"});
        };
        if case == FiniteStrokeSteady::NotBuilt {
            return json!({"exists": true, "computed_by": null, "why": why});
        }
        let ends = &self.contact.stroke.ends;
        let swing = (ends[ends.len() - 1] - ends[0]).abs();
        if self
            .contact
            .shape
            .period()
            .is_some_and(|period| swing >= period)
        {
            // No track ends, and every point passes the contact more than once a half
            // period: neither the argument nor the flat trough's figure applies.
            return json!({"exists": null, "why": "a ring swung over a turn or more has no track ends, but its wear is not even (the speed varies along the swing): its steady state is not built"});
        }
        let steps = &self.history.steps;
        let deepening = match steps.len() {
            n if n >= 2 => {
                let (a, b) = (&steps[n - 2], &steps[n - 1]);
                let half_periods = (b.half_period - a.half_period) as f64;
                Some((b.largest_wear[1] - a.largest_wear[1]) / half_periods)
            }
            _ => None,
        };
        let trough = self.settings.laws[1]
            .filter(|l| l.a == 1.0 && l.b == 1.0)
            .map(|l| l.beta * self.load_per_thickness());
        let track = &self.history.track;
        let centres = track.centres();
        let slope = (centres.windows(2).zip(track.wear.windows(2)))
            .map(|(x, w)| ((w[1] - w[0]) / (x[1] - x[0])).abs())
            .fold(0.0f64, f64::max);
        json!({
            "exists": false,
            "why": why,
            "track_deepest_per_half_period": deepening.map(number),
            "flat_trough_per_half_period": trough.map(number),
            "track_steepest_slope": number(slope),
        })
    }

    /// The normal load per unit thickness the contact carries, F/t in N/mm: the first
    /// position's pressure of the last cycle integrated over body 1's contact edge.
    fn load_per_thickness(&self) -> f64 {
        let weight = &self.contact.contacts[0].points.weight;
        self.history.last_cycle[0]
            .first()
            .map_or(0.0, |p| weight.iter().zip(p).map(|(w, p)| w * p).sum())
    }
}
