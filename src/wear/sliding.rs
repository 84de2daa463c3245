//! The wear integration of sliding pairs ([`crate::contact::track`]): each half period is
//! resolved into the stroke's positions, each with its own contact solve, and both bodies'
//! wear accumulates over them: body 1's at its own points, body 2's along its track.
//!
//! # A step
//!
//! A step stands for k half periods (the extrapolation schedule, as for fixed pairs), sliding
//! '+' on odd steps and back on even ones (on a closed track turning one way, a step is k
//! turns, all '+'). It visits the positions in the order the stroke brings them (the reverse
//! order on the way back), and at each position j:
//!
//! 1. the gap of body 1's point i is the geometric gap there, g_ij (body 2 moved by s_j),
//!    plus body 1's wear w₁ᵢ plus the track's wear under the point's share of the edge (read
//!    in its middle, [`crate::contact::track`]), both as the last step left them;
//! 2. the contact solve gives the pressure p_ij, held over the position's interval
//!    [e_j, e_{j+1}] of the stroke;
//! 3. body 1's points wear by k β̃₁ p_ijᵇ S_j (S_j = ∫|v|ᵃ dτ over the interval, the same
//!    sliding integral as fixed pairs use, cut at the interval's phases), and each point's
//!    share of the edge deposits k β̃₂ p_ijᵇ S_j/|Δs_j| per millimetre of sliding onto the
//!    track cells it passes over ([`crate::contact::track::Track::sweep`]).
//!
//! # What each solve holds implicitly
//!
//! The fixed pairs' step solves its pressure on the shape at the step's end, the half
//! period's wear (k times) being a compliance in series with the bodies'
//! ([`ContactSolver::set_compliance`]): stable for any k on any mesh. Here each position's
//! solve does the same with the step's whole wear as its own pressure would make it: the
//! compliance c_i is k Σ_q β̃ pᵇ⁻¹ S_q over all the step's intervals q (b = 1: exact in the
//! pressure), for body 1 exactly what its point wears, for body 2 lumped (the track under
//! point i deepens by what every share passing over it deposits, β̃₂ pᵇ S where the pressure
//! varies little, not only point i's own share's deposit). Every position thus meets the
//! step's end shape as its own pressure makes it. With a vanishing stroke the positions are
//! alike and this is the fixed pairs' step; on a ring turning under a block every position
//! is alike and the ring wears evenly to round-off. The '+' steps also see the last '−' half
//! period's wear (k times, from the last cycle), as the fixed pairs' first half period
//! does, so that both halves of a cycle meet its end shape. For b ≠ 1 the wear is linearised
//! and each position solved by Newton's method until the linearisation meets `wear.tolerance`
//! (`implicit_position`), as the fixed pairs' step is; a position that does not converge
//! stops the run as a fixed-pairs step does.
//!
//! Three other choices failed, with k = 10 to 100 half periods per step:
//! - each position seeing the wear the step's earlier positions had laid down (the
//!   compliance holding only the rest of the step): on a ring the step's deposit then
//!   stands as a step of k turns' wear under the block, which moved the pressure to its
//!   leading edge and left the ring's wear 62 % uneven around it;
//! - the rest of the cycle taken from the last one, corrected explicitly by the difference
//!   of the positions' pressures: the tribometer's pressures oscillated from point to point;
//! - body 2's compliance holding only a point's own share's deposit under itself (the
//!   diagonal): the rest came explicitly and k times, with the same oscillation at the
//!   stroke's ends.
//!
//! Holding nothing of the step (each position on the last step's shape alone) left the
//! steady state depending on k: a vanishing stroke on punch-b40 0.4 % of the peak off the
//! fixed pairs' steady pressures at k = 10.

use super::{law, ScheduleEntry, StopReason, WearLaw};
use crate::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use crate::contact::track::{SlidingContact, Stroke, Track};
use crate::contact::CondensedContact;
use crate::kinematics::{factor, partial_sliding};
use serde::Serialize;

/// What a sliding-pairs run needs to know of the wear section, validated.
#[derive(Clone, Debug)]
pub struct SlidingSettings {
    /// Each body's wear law (None: it does not wear).
    pub laws: [Option<WearLaw>; 2],
    /// Whether body 2 turns one way (a closed track; a step is then k turns) rather than
    /// reciprocating.
    pub monotonic: bool,
    /// Monotonic sliding speed v, mm/s.
    pub speed: f64,
    /// Reciprocating amplitude u₀, mm.
    pub amplitude: f64,
    /// Angular frequency ω, rad/s.
    pub omega: f64,
    /// Extrapolation schedule.
    pub schedule: Vec<ScheduleEntry>,
    /// Number of steps.
    pub steps: usize,
    /// Steps at which whole profiles are recorded.
    pub record: Vec<usize>,
    /// Sliding direction of the odd steps.
    pub first_direction: Direction,
    /// Contact points whose pressure each step reports (indices).
    pub probes: Vec<usize>,
    /// Track coordinates (mm) where each step reports body 2's wear.
    pub track_probes: Vec<f64>,
    /// Tolerance of a position's Newton iteration for b ≠ 1: the largest error of the
    /// linearised wear at any point, relative to the largest wear, percent (`wear.tolerance`).
    pub tolerance: f64,
    /// Most Newton iterations per position (`wear.max_iterations`).
    pub max_iterations: usize,
}

/// One step of a sliding-pairs run.
#[derive(Clone, Debug, Serialize)]
pub struct SlidingStep {
    /// Step number n (1-based).
    pub step: usize,
    /// Half periods done at the end of the step.
    pub half_period: usize,
    /// "+" or "−".
    pub direction: &'static str,
    /// Extrapolation factor k.
    pub k: usize,
    /// Pressure at each probe at the step's last position (a reversal), MPa.
    pub probes: Vec<f64>,
    /// Body 2's wear at each of its probes (`track_probes`), mm.
    pub track_probes: Vec<f64>,
    /// Largest pressure over the step's positions, MPa.
    pub peak_pressure: f64,
    /// Worn area of body 1 and of body 2 (∫ w ds, mm²; times the thickness, the volume).
    pub worn_area: [f64; 2],
    /// Largest wear depth of body 1 and of body 2, mm.
    pub largest_wear: [f64; 2],
}

/// The profiles at a recorded step.
#[derive(Clone, Debug, Serialize)]
pub struct SlidingSnapshot {
    /// Step number.
    pub step: usize,
    /// Half periods done.
    pub half_period: usize,
    /// Body 1's wear at each contact point, mm.
    pub wear_body1: Vec<f64>,
    /// Body 2's wear in each track cell, mm.
    pub track: Vec<f64>,
    /// The pressure at each position of the step (in `stroke.positions` order), MPa.
    pub pressures: Vec<Vec<f64>>,
}

/// The result of a sliding-pairs run.
#[derive(Clone, Debug)]
pub struct SlidingHistory {
    /// One record per completed step.
    pub steps: Vec<SlidingStep>,
    /// Profiles at the recorded steps.
    pub snapshots: Vec<SlidingSnapshot>,
    /// Body 1's wear at each contact point after the last completed step, mm.
    pub wear_body1: Vec<f64>,
    /// Body 2's track after the last completed step.
    pub track: Track,
    /// The pressures of the last '+' and '−' half periods at each position (in
    /// `stroke.positions` order), MPa; empty until the direction has been slid.
    pub last_cycle: [Vec<Vec<f64>>; 2],
    /// Contact solves made.
    pub solves: usize,
    /// The step at which the run stopped early and why; nothing of that step is kept.
    pub stopped: Option<(usize, StopReason)>,
}

/// Each body's wear, as a whole or as a part of it: body 1's at its points, body 2's along
/// the track.
#[derive(Clone)]
struct Wear {
    body1: Vec<f64>,
    track: Track,
}

impl Wear {
    fn zero(&mut self) {
        self.body1.fill(0.0);
        self.track.wear.fill(0.0);
    }

    /// self += factor × other.
    fn add(&mut self, factor: f64, other: &Wear) {
        for (a, b) in self.body1.iter_mut().zip(&other.body1) {
            *a += factor * b;
        }
        for (a, b) in self.track.wear.iter_mut().zip(&other.track.wear) {
            *a += factor * b;
        }
    }

    /// The gap's part at point i reading the track at x.
    fn at(&self, i: usize, x: f64) -> f64 {
        self.body1[i] + self.track.at(x)
    }
}

/// What one step keeps for the next and for the results.
struct State {
    /// The wear of the completed steps.
    done: Wear,
    /// The wear of the step under way.
    step: Wear,
    /// The last '−' half period's wear per unit k, once one is complete.
    back: Option<Wear>,
    /// The pressure at each position in each direction, last visit ('+', '−').
    last: [Vec<Vec<f64>>; 2],
}

/// Integrate the sliding pairs' wear over `settings.steps` steps; `solvers` holds one solver
/// per position of `contact` (in `stroke.positions` order).
pub fn run(
    settings: &SlidingSettings,
    contact: &SlidingContact,
    solvers: &mut [ContactSolver],
) -> SlidingHistory {
    let m = contact.len();
    let n = contact.contacts[0].len();
    let sliding = interval_sliding(settings, &contact.stroke);
    let unworn = Wear {
        body1: vec![0.0; n],
        track: contact.empty_track(),
    };
    let mut state = State {
        done: unworn.clone(),
        step: unworn.clone(),
        back: None,
        last: [vec![vec![]; m], vec![vec![]; m]],
    };
    let mut history = SlidingHistory {
        steps: Vec::with_capacity(settings.steps.min(100_000)),
        snapshots: vec![],
        wear_body1: vec![],
        track: unworn.track.clone(),
        last_cycle: [vec![], vec![]],
        solves: 0,
        stopped: None,
    };
    let mut half_periods = 0;
    let mut solution = ContactSolution::default();
    let mut gap = vec![0.0; n];
    let mut scratch = Scratch::new(n);
    let terms = step_terms(settings, &sliding);
    for step in 1..=settings.steps {
        let forward = settings.monotonic || step % 2 == 1;
        let direction = if forward {
            settings.first_direction
        } else {
            settings.first_direction.reversed()
        };
        let k = factor(&settings.schedule, step);
        state.step.zero();
        let d = usize::from(!forward);
        let order: Vec<usize> = if forward {
            (0..m).collect()
        } else {
            (0..m).rev().collect()
        };
        let mut peak = 0.0f64;
        let mut failure = None;
        for &j in &order {
            let c = &contact.contacts[j];
            let s = contact.stroke.positions[j];
            let kf = k as f64;
            let last = &state.last[d][j];
            for (i, g) in gap.iter_mut().enumerate() {
                let x = contact.readings[i] - s;
                *g = c.points.initial_gap[i] + state.done.at(i, x);
                if let (true, Some(back)) = (forward, &state.back) {
                    *g += kf * back.at(i, x);
                }
            }
            // The step's whole wear, held implicitly at this position's pressure (module
            // docs), by Newton's method for b ≠ 1.
            let solved = implicit_position(
                c,
                &terms,
                last,
                &gap,
                ImplicitSolve {
                    solver: &mut solvers[j],
                    direction,
                    factor: k,
                    tolerance: settings.tolerance / 100.0,
                    max_iterations: settings.max_iterations,
                },
                &mut scratch,
                &mut solution,
            );
            history.solves += solved.as_ref().map_or(1, |n| *n);
            if let Err(reason) = solved {
                failure = Some(reason);
                break;
            }
            add_wear(
                settings,
                contact,
                j,
                k,
                &sliding[j],
                &solution.pressure,
                &mut state.step,
            );
            peak = solution.pressure.iter().fold(peak, |a, &b| a.max(b));
            state.last[d][j].clone_from(&solution.pressure);
        }
        let finite = (state.step.body1.iter())
            .chain(&state.step.track.wear)
            .all(|w| w.is_finite());
        if failure.is_none() && !finite {
            failure = Some(StopReason::NonFiniteWear);
        }
        if let Some(reason) = failure {
            // Nothing of this step is kept.
            history.stopped = Some((step, reason));
            break;
        }
        state.done.add(1.0, &state.step);
        if !forward && !settings.monotonic {
            let back = state.back.get_or_insert_with(|| state.step.clone());
            back.zero();
            back.add(1.0 / k as f64, &state.step);
        }
        half_periods += k;
        let last_position = *order.last().unwrap_or(&0);
        let pressures = &state.last[d];
        let record = SlidingStep {
            step,
            half_period: half_periods,
            direction: direction.symbol(),
            k,
            probes: settings
                .probes
                .iter()
                .map(|&i| pressures[last_position][i])
                .collect(),
            track_probes: settings
                .track_probes
                .iter()
                .map(|&x| state.done.track.at(x))
                .collect(),
            peak_pressure: peak,
            worn_area: worn_area(contact, &state),
            largest_wear: [
                state.done.body1.iter().fold(0.0, |a: f64, &b| a.max(b)),
                state
                    .done
                    .track
                    .wear
                    .iter()
                    .fold(0.0, |a: f64, &b| a.max(b)),
            ],
        };
        history.steps.push(record);
        if settings.record.contains(&step) {
            history.snapshots.push(SlidingSnapshot {
                step,
                half_period: half_periods,
                wear_body1: state.done.body1.clone(),
                track: state.done.track.wear.clone(),
                pressures: pressures.clone(),
            });
        }
    }
    history.wear_body1 = state.done.body1;
    history.track = state.done.track;
    history.last_cycle = state.last;
    history
}

/// Per position: the interval's length of offset |Δs_j| (mm) and each body's sliding integral
/// S_j = ∫|v|ᵃ dτ over it (mm^a s^(1−a); = |Δs_j| for a = 1).
struct IntervalSliding {
    length: f64,
    per_body: [f64; 2],
}

fn interval_sliding(settings: &SlidingSettings, stroke: &Stroke) -> Vec<IntervalSliding> {
    let m = stroke.positions.len();
    if settings.monotonic {
        // At the constant speed v: ∫|v|ᵃ dτ = vᵃ⁻¹ |Δs|.
        return stroke
            .ends
            .windows(2)
            .map(|e| {
                let length = (e[1] - e[0]).abs();
                IntervalSliding {
                    length,
                    per_body: settings
                        .laws
                        .map(|law| law.map_or(0.0, |l| settings.speed.powf(l.a - 1.0) * length)),
                }
            })
            .collect();
    }
    // The offset −u₀ cos θ cut into m equal parts: cos θ_j = 1 − 2j/m.
    let theta = |j: usize| (1.0 - 2.0 * j as f64 / m as f64).clamp(-1.0, 1.0).acos();
    (0..m)
        .map(|j| {
            let phases = [theta(j), theta(j + 1)];
            let per_body = settings.laws.map(|law| {
                law.map_or(0.0, |l| {
                    partial_sliding(settings.amplitude, settings.omega, l.a, phases)
                })
            });
            IntervalSliding {
                length: 2.0 * settings.amplitude / m as f64,
                per_body,
            }
        })
        .collect()
}

/// The wear one half period (or turn) lays down at a pressure p, both bodies together, as
/// the terms (c, b) of W(p) = Σ c pᵇ (mm): c = β̃ S summed over the step's intervals. For body
/// 2 this lumps what every share of the edge passing over a point deposits under it (module
/// docs).
fn step_terms(settings: &SlidingSettings, sliding: &[IntervalSliding]) -> Vec<(f64, f64)> {
    (0..2)
        .filter_map(|body| {
            let law = settings.laws[body]?;
            let summed: f64 = sliding.iter().map(|q| q.per_body[body]).sum();
            Some((law.beta * summed, law.b))
        })
        .collect()
}

/// A position's solver and how its Newton iteration stops.
struct ImplicitSolve<'a> {
    solver: &'a mut ContactSolver,
    direction: Direction,
    /// The step's extrapolation factor k.
    factor: usize,
    /// Largest error of the linearised wear, relative to the largest wear.
    tolerance: f64,
    max_iterations: usize,
}

/// Per-point work arrays of [`implicit_position`], allocated once a run.
struct Scratch {
    compliance: Vec<f64>,
    trial: Vec<f64>,
    slope: Vec<f64>,
    linear_wear: Vec<f64>,
    linearised_at: Vec<f64>,
    chord: Vec<bool>,
}

impl Scratch {
    fn new(n: usize) -> Scratch {
        Scratch {
            compliance: vec![0.0; n],
            trial: vec![0.0; n],
            slope: vec![0.0; n],
            linear_wear: vec![0.0; n],
            linearised_at: vec![0.0; n],
            chord: vec![false; n],
        }
    }
}

/// Solve position `contact` on `gap` plus k times the step's wear W(p) at its own pressure:
/// W in series with the flexibility as a compliance. For b = 1 that is one complementarity
/// problem, exact. For b ≠ 1 Newton's method linearises W at the pressure p̂ of the
/// position's last visit (`last`; zero at the first), W(p) ≈ W(p̂) + s (p − p̂), and solves
/// again until the linearisation error is below the tolerance at every point: the fixed
/// pairs' implicit step ([`crate::wear::law`]'s slopes and steps), point for point. The
/// secant of the last visit alone, held without iterating, let b = 2 on a ring run away at
/// k = 10 (a block worn 50 mm deep in 14 000 turns, its pressures hopping from point to
/// point). Returns the contact solves made, or why the position failed.
#[allow(clippy::needless_range_loop)]
fn implicit_position(
    contact: &CondensedContact,
    terms: &[(f64, f64)],
    last: &[f64],
    gap: &[f64],
    solve: ImplicitSolve,
    ws: &mut Scratch,
    solution: &mut ContactSolution,
) -> Result<usize, StopReason> {
    let n = gap.len();
    let k = solve.factor;
    let kf = k as f64;
    let area = |i: usize| contact.points.weight[i] * contact.thickness;
    let linear = terms.iter().all(|t| t.1 == 1.0);
    if last.is_empty() {
        ws.linearised_at.fill(0.0);
    } else {
        ws.linearised_at.copy_from_slice(last);
    }
    let reference = {
        let (sum, count) = (ws.linearised_at.iter())
            .filter(|&&p| p > 0.0)
            .fold((0.0, 0usize), |(s, c), p| (s + p, c + 1));
        if count > 0 {
            sum / count as f64
        } else {
            1.0
        }
    };
    ws.chord.fill(false);
    let concave = law::is_concave(terms);
    let (mut iterations, mut error) = (0, f64::INFINITY);
    let mut least = [f64::INFINITY; 2];
    while iterations < solve.max_iterations.max(1) {
        iterations += 1;
        for i in 0..n {
            let p = ws.linearised_at[i];
            let slope = if ws.chord[i] {
                law::chord_slope(terms, p, reference)
            } else {
                law::newton_slope(terms, p, reference, true)
            };
            let w = law::half_period_wear(terms, p);
            ws.compliance[i] = kf * slope / area(i);
            ws.trial[i] = gap[i] + kf * (w - slope * p);
            ws.slope[i] = slope;
            ws.linear_wear[i] = w - slope * p;
        }
        solve.solver.set_compliance(&ws.compliance);
        let info = solve
            .solver
            .solve_pressures_into(&ws.trial, solve.direction, solution);
        if info.status != Status::Solved {
            return Err(StopReason::FailedSolve {
                complementarity: info.complementarity,
                equilibrium: info.equilibrium,
            });
        }
        if linear {
            return Ok(iterations);
        }
        let pressure = &solution.pressure;
        let (mut worst, mut largest) = (0.0f64, 0.0f64);
        for i in 0..n {
            let exact = law::half_period_wear(terms, pressure[i]);
            let model = ws.linear_wear[i] + ws.slope[i] * pressure[i];
            worst = worst.max((exact - model).abs());
            largest = largest.max(exact);
        }
        error = worst / largest.max(f64::MIN_POSITIVE);
        let half = usize::from(2 * iterations > solve.max_iterations);
        least[half] = least[half].min(error);
        for i in 0..n {
            let p = pressure[i];
            // As in the fixed pairs' step: a point a tangent sent out of contact takes the
            // chord, whose model has no intercept to send it out again.
            if p <= 0.0 && ws.linearised_at[i] > 0.0 && concave {
                ws.chord[i] = true;
            }
            let own = contact.a_nn[i * n + i] * area(i) / kf;
            ws.linearised_at[i] = if p > 0.0 {
                law::balanced_step(terms, ws.linearised_at[i], ws.slope[i], p, own)
            } else {
                p
            };
        }
        if error <= solve.tolerance {
            return Ok(iterations);
        }
    }
    Err(StopReason::UnconvergedStep {
        criterion: 100.0 * error,
        tolerance: 100.0 * solve.tolerance,
        factor: k,
        stalled: iterations >= 4 && least[1] > 0.5 * least[0],
    })
}

/// Both bodies' wear of position j's interval under `pressure` (MPa), k half periods of it.
fn add_wear(
    settings: &SlidingSettings,
    contact: &SlidingContact,
    j: usize,
    k: usize,
    sliding: &IntervalSliding,
    pressure: &[f64],
    wear: &mut Wear,
) {
    let c = &contact.contacts[j];
    let shift = [contact.stroke.ends[j], contact.stroke.ends[j + 1]];
    let k = k as f64;
    if let Some(law) = settings.laws[0] {
        for (w, &p) in wear.body1.iter_mut().zip(pressure) {
            *w += k * law.beta * p.powf(law.b) * sliding.per_body[0];
        }
    }
    if let Some(law) = settings.laws[1] {
        for (i, &p) in pressure.iter().enumerate() {
            if p <= 0.0 {
                continue;
            }
            let (from, to) = (contact.cells[i], contact.cells[i + 1]);
            // Point i's wear spread over its share of the edge, per mm of sliding.
            let spread = c.points.weight[i] / (to - from);
            let rate = k * law.beta * p.powf(law.b) * sliding.per_body[1] / sliding.length;
            wear.track.sweep(from, to, shift, rate * spread);
        }
    }
}

fn worn_area(contact: &SlidingContact, state: &State) -> [f64; 2] {
    let weight = &contact.contacts[0].points.weight;
    [
        state
            .done
            .body1
            .iter()
            .zip(weight)
            .map(|(w, l)| w * l)
            .sum(),
        state.done.track.area(),
    ]
}
