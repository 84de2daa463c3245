//! Wear time integration (paper §4, eq. 24–30): the Archard-type rule ẇ = β̃ pᵇ vᵃ (eq. 1)
//! integrated half period by half period, with the pressure held at its end-of-half-period
//! value (implicit, iterated to criterion eq. 27), the extrapolation factor k (eq. 29–30), and
//! the friction direction alternating every half period.
//!
//! The wear of both bodies is measured along n_c and accumulated into the gap g of the contact
//! points (paper eq. 25–26): body 1's wear where it happens; body 2's at the substrate point
//! paired with each contact point (the pairs do not move, reference model), i.e. the substrate
//! segment under the punch, which is what the paper's segment M̃Ñ describes.

use crate::complementarity::Direction;
pub use crate::kinematics::ScheduleEntry;
use crate::kinematics::{half_period_sliding, paper_schedule};

mod adaptive;
mod body_wear;
pub mod fretting;
pub mod kinematics;
pub mod law;
mod outcome;
pub mod rotation;
mod schemes;
pub mod sliding;
mod step;
pub mod terms;
pub mod thermal;
mod workspace;
mod zero_shift;
pub use adaptive::{AdaptiveMethod, AdaptiveSpec};
pub use body_wear::worn_volume;
pub use outcome::{non_rigid_part, steady_distance, SteadyDistance, StopReason};
pub use rotation::AxisRotation;
use serde::{Deserialize, Serialize};
pub use terms::WearTerms;
pub use zero_shift::wear_of_shape;

/// Wear law parameters of one body: ẇ = β̃ pᵇ vᵃ (mm/s with p in MPa and v in mm/s). A file
/// may give Archard's k or K with a hardness instead of β̃ ([`crate::wear_units`]).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(try_from = "crate::wear_units::WearLawInput")]
pub struct WearLaw {
    /// β̃ = β μᵇ, mm^(1−a) s^(a−1) MPa^(−b); 0 switches wear of this body off.
    pub beta: f64,
    /// Velocity exponent a (> 0; default 1).
    pub a: f64,
    /// Pressure exponent b (> 0; default 1).
    pub b: f64,
}

/// `[wear]` section of a problem file.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct WearSpec {
    /// Wear of body 1 (the punch).
    pub body1: Option<WearLaw>,
    /// Wear of body 2 (the substrate).
    pub body2: Option<WearLaw>,
    /// "reciprocating" (u_τ = −u₀ cos ωτ) or "monotonic" (constant speed, '+' direction).
    #[serde(default = "reciprocating")]
    pub sliding: String,
    /// Reciprocating amplitude u₀, mm.
    #[serde(default)]
    pub amplitude: f64,
    /// Reciprocating angular frequency ω, rad/s.
    #[serde(default)]
    pub omega: f64,
    /// Monotonic sliding speed v, mm/s.
    #[serde(default)]
    pub speed: f64,
    /// Bodies of revolution turning about their axis (`contact.sliding_motion =
    /// "about_axis"`), monotonic: the angular speed ω, rad/s (a point at radius r slides at
    /// ω r). Replaces `speed`.
    pub angular_speed: Option<f64>,
    /// Bodies of revolution turning to and fro about their axis, reciprocating: the angle's
    /// amplitude θ₀, rad (θ = −θ₀ cos ωτ; a point at radius r slides θ₀ r each way).
    /// Replaces `amplitude`.
    pub angle: Option<f64>,
    /// Monotonic: time per step, s.
    #[serde(default)]
    pub step_time: f64,
    /// Number of steps n (0: not given; then `cycles` or `distance` sets it).
    #[serde(default)]
    pub steps: usize,
    /// Duration in cycles (reciprocating), instead of `steps`.
    pub cycles: Option<f64>,
    /// Duration as sliding distance, m, instead of `steps`.
    pub distance: Option<f64>,
    /// Duration as time, s, instead of `steps`: π/ω per half period (reciprocating),
    /// `step_time` per step unit (monotonic).
    pub time: Option<f64>,
    /// Extrapolation schedule (default: the paper's k = 1, 5, 10 after steps 50, 100).
    pub extrapolation: Option<Vec<ScheduleEntry>>,
    /// Error-controlled extrapolation instead of a schedule; the run then stops at the steady
    /// state (or after `steps`).
    pub adaptive: Option<AdaptiveSpec>,
    /// How a half-period step is solved: "implicit" (default: the backward-Euler step
    /// g⁺ = g + k ΔW(p⁺) solved as one complementarity problem, or by Newton's method for
    /// b ≠ 1; stable on any mesh and for any k) or "fixed_point" (the paper's iteration
    /// shape ← wear of the last pressure, checked by `criterion`; for reproducing the paper).
    #[serde(default = "implicit")]
    pub scheme: String,
    /// Tolerance of the step's iteration, percent (default 0.01): criterion eq. 27 (or the
    /// pointwise one) for the fixed-point scheme; for the implicit scheme with b ≠ 1 the
    /// largest error of the linearised wear at any point, relative to the largest wear.
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// "eq27" (default): the paper's integral criterion; "pointwise": the largest change of the
    /// wear increment at any point, relative to its largest value (percent).
    #[serde(default = "eq27")]
    pub criterion: String,
    /// Most implicit iterations per step (default 50).
    #[serde(default = "default_iterations")]
    pub max_iterations: usize,
    /// 0: the paper's half-period scheme; m > 0: plain explicit time stepping with m sub-steps
    /// per half period (for checking the scheme).
    #[serde(default)]
    pub substeps: usize,
    /// x (mm) of the point where the shape is shifted to zero after every full cycle, by a
    /// vertical rigid translation of body 1 (which leaves the pressures unchanged).
    pub shape_zero_at: Option<f64>,
    /// Steps at which whole pressure and shape profiles are recorded.
    #[serde(default)]
    pub record: Vec<usize>,
    /// Sliding distances (m) at which the profiles are recorded: the schedule's steps are cut
    /// so that a step ends at each (to the nearest whole half period or step unit).
    #[serde(default)]
    pub record_distance: Vec<f64>,
    /// Times (s) at which the profiles are recorded, as `record_distance`.
    #[serde(default)]
    pub record_time: Vec<f64>,
    /// Cycles (reciprocating) after which the profiles are recorded, as `record_distance`.
    #[serde(default)]
    pub record_cycles: Vec<f64>,
}

/// Whether `schedule` is a valid extrapolation schedule: every k in 1 … [`MAX_FACTOR`], and
/// `until` at least 1 and rising, only the last entry open. The message says what is wrong.
pub fn check_schedule(schedule: &[ScheduleEntry]) -> Result<(), String> {
    if schedule.is_empty() || schedule.iter().any(|e| !(1..=MAX_FACTOR).contains(&e.k)) {
        return Err(format!("needs entries with 1 ≤ k ≤ {MAX_FACTOR}"));
    }
    let bounds: Vec<usize> = schedule.iter().filter_map(|e| e.until).collect();
    if bounds.first() == Some(&0)
        || bounds.windows(2).any(|w| w[1] <= w[0])
        || schedule[..schedule.len() - 1]
            .iter()
            .any(|e| e.until.is_none())
    {
        return Err("`until` (the last step of an entry) must be at least 1 and rise from entry to entry; only the last entry may omit it".into());
    }
    Ok(())
}

fn implicit() -> String {
    "implicit".into()
}
fn reciprocating() -> String {
    "reciprocating".into()
}
fn eq27() -> String {
    "eq27".into()
}
fn default_tolerance() -> f64 {
    0.01
}
fn default_iterations() -> usize {
    50
}

/// Pressure profiles and shape at one step.
#[derive(Clone, Debug, Serialize)]
pub struct Snapshot {
    /// Step number n.
    pub step: usize,
    /// Half periods done at the end of the step.
    pub half_period: usize,
    /// "+" or "−".
    pub direction: &'static str,
    /// Pressure at the end of the step, MPa.
    pub pressure: Vec<f64>,
    /// With heat: the modal coordinates of the temperature the step was solved with (its
    /// start's; not serialised: the ParaView writer makes fields of them).
    #[serde(skip)]
    pub thermal_state: Option<Vec<f64>>,
    /// Shape at the end of the step, mm: the initial gap plus the wear so far (shifted to
    /// zero at `shape_zero_at` after each full cycle). After a first half cycle it is the
    /// cycle's start shape plus k times that half period's wear, whatever the scheme.
    pub shape: Vec<f64>,
    /// The gap `pressure` is the contact solution of, mm: `shape` after a second half cycle;
    /// after a first half cycle the step's own shape plus the look-ahead (the wear the
    /// cycle's second half is about to add; for BDF2 also its known part). Not serialised:
    /// the ParaView writer re-solves from it so that its fields belong to `pressure`. With
    /// heat it includes the thermal gap the step was solved with.
    #[serde(skip)]
    pub contact_shape: Vec<f64>,
    /// The depth worn off body 1 and off body 2 at each contact point since the run's start,
    /// mm (material removed: not shifted by `shape_zero_at`; see [`WearHistory::body_wear`]).
    pub body_wear: [Vec<f64>; 2],
}

/// One row of the step history.
#[derive(Clone, Debug, Serialize)]
pub struct StepRecord {
    /// Step number n (1-based).
    pub step: usize,
    /// Half periods done at the end of the step (paper eq. 30).
    pub half_period: usize,
    /// "+" or "−".
    pub direction: &'static str,
    /// Extrapolation factor k.
    pub k: usize,
    /// Iterations of the step (1 for the implicit scheme with b = 1).
    pub iterations: usize,
    /// Contact solves in this step.
    pub solves: usize,
    /// Final criterion eq. 27, percent.
    pub criterion: f64,
    /// Wear dissipation of one half period, t∫ p Δwₙ dS (N·mm) (paper eq. 9, 13).
    pub dissipation: f64,
    /// Pressure at each probe (nearest contact point), MPa, in probe order.
    pub probes: Vec<f64>,
    /// Bodies of revolution turning about their axis: the friction torque about the axis at
    /// the step's pressure, T = ∫ μ p r dA, N·mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub torque: Option<f64>,
    /// Largest δw = Δw − min Δw over the cycle ending here (paper eq. 40), mm; 0 after '+' steps.
    pub delta_w: f64,
    /// With heat: the temperature at each probe at the step's end, °C, in probe order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub temperatures: Vec<f64>,
    /// With heat: the largest temperature of body 1 and of body 2 at the step's end, °C.
    /// Filled when the run ends (computed for many steps at once): None in the callback
    /// that sees each step as it is made.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_temperature: Option<[f64; 2]>,
}

/// Result of a wear run.
#[derive(Clone, Debug, Serialize)]
pub struct WearHistory {
    /// One record per step.
    pub steps: Vec<StepRecord>,
    /// Snapshots at the requested steps.
    pub snapshots: Vec<Snapshot>,
    /// Pressure of the last '+' step (of the last step for monotonic sliding), MPa.
    pub p_plus: Vec<f64>,
    /// Pressure of the last '−' step, MPa.
    pub p_minus: Vec<f64>,
    /// Shape after the last completed step, mm (as [`Snapshot::shape`]).
    pub shape: Vec<f64>,
    /// The gap the last completed step's pressure is the contact solution of, mm (as
    /// [`Snapshot::contact_shape`]).
    #[serde(skip)]
    pub contact_shape: Vec<f64>,
    /// The largest depth worn off body 1 and off body 2 at any contact point, mm: each
    /// point's wear summed over the steps (k half periods of the step's pressure each),
    /// including the wear that `shape_zero_at` shifts out of `shape`.
    pub worn_depth: [f64; 2],
    /// The depth worn off body 1 and off body 2 at each contact point (body 2's at the
    /// partner of each of body 1's points), mm: material removed, so not shifted by
    /// `shape_zero_at`. The two add up to the shape's change; how it divides follows each
    /// body's wear rule (module `body_wear`).
    pub body_wear: [Vec<f64>; 2],
    /// Total contact solves.
    pub solves: usize,
    /// Steps whose iteration did not meet its tolerance.
    pub unconverged_steps: usize,
    /// Fixed-point steps whose accepted wear differs from the wear of the pressure it
    /// produced by more than [`OSCILLATION_LIMIT`] at some point (the shape oscillates).
    pub oscillating_steps: usize,
    /// Contact solves that failed (the run stops at the first).
    pub failed_solves: usize,
    /// The step at which the run stopped early and why: nothing of that step is kept, except
    /// for [`StopReason::SteadyState`], where the step is the last one recorded.
    pub stopped: Option<(usize, StopReason)>,
    /// How far the last full cycle is from the steady state; None until a cycle is complete
    /// (then `p_plus`, `p_minus` are not results either).
    pub steady_distance: Option<SteadyDistance>,
    /// With heat: the temperatures and thermal gaps at the end.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal: Option<thermal::ThermalHistory>,
}

impl WearHistory {
    /// The half period at which the run first came within `bound` × `scale` (MPa) of the
    /// pressures `p_plus` and `p_minus` of a reference state (MPa, one per contact point),
    /// judged once per cycle: at the first '−' step whose pressures and those of the '+' step
    /// before it are within the bound at every point. The crossing is placed between that
    /// cycle and the one before by log-linear interpolation of the distance (the approach is
    /// an exponential decay of the slowest modes), so that runs whose cycles span 2 or 64
    /// half periods are measured alike rather than to the nearest cycle end. Reads the
    /// snapshots, so record every step. None if it never gets there (or the sliding is
    /// monotonic).
    pub fn half_periods_to_reach(
        &self,
        p_plus: &[f64],
        p_minus: &[f64],
        scale: f64,
        bound: f64,
    ) -> Option<f64> {
        let worst = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max)
                / scale
        };
        let mut last_plus: Option<f64> = None;
        // Half period and distance of the last cycle still outside the bound.
        let mut outside: Option<(f64, f64)> = None;
        for s in &self.snapshots {
            if s.direction == "+" {
                last_plus = Some(worst(&s.pressure, p_plus));
            } else if let Some(plus) = last_plus {
                let distance = plus.max(worst(&s.pressure, p_minus));
                let h = s.half_period as f64;
                if distance <= bound {
                    return Some(match outside {
                        Some((h0, d0)) if distance > 0.0 => {
                            h0 + (h - h0) * (d0 / bound).ln() / (d0 / distance).ln()
                        }
                        _ => h,
                    });
                }
                outside = Some((h, distance));
            }
        }
        None
    }
}

/// Largest pointwise difference, relative to the largest wear, between the wear a
/// fixed-point step applied and the wear of the pressure that wear produced, above which the
/// step counts as oscillating: the pressures then belong to a shape other than the one kept.
pub const OSCILLATION_LIMIT: f64 = 0.01;

/// Relative distance from the steady state ([`SteadyDistance::wear`]) up to which a run's
/// last cycle counts as steady in its report.
pub const STEADY_REPORT_LIMIT: f64 = 0.01;

/// Most steps a run may have (each keeps a record of about 100 bytes).
pub const MAX_STEPS: usize = 1_000_000;
/// Largest extrapolation factor k.
pub const MAX_FACTOR: usize = 1_000_000;

/// The integrator: wear laws, kinematics and schedule, validated.
#[derive(Clone, Debug)]
pub struct WearIntegrator {
    /// The validated specification.
    pub spec: WearSpec,
    schedule: Vec<ScheduleEntry>,
    laws: Vec<WearLaw>,
    /// Which body (0: body 1, 1: body 2) each of `laws` wears.
    law_bodies: Vec<usize>,
    /// Sliding direction of the first (odd) steps; default '+'.
    pub first_direction: Direction,
    /// The heat problem, for a problem with `[heat]` (see [`thermal`]).
    pub heat: Option<std::sync::Arc<thermal::ThermalModel>>,
    /// Bodies of revolution turning about their axis: where the points lie from it
    /// ([`WearIntegrator::turn_about_axis`]).
    about_axis: Option<AxisRotation>,
    /// With `about_axis`: each law's sliding factor rᵃ at each point (one row per law).
    point_factor: Vec<Vec<f64>>,
}

impl WearIntegrator {
    /// Validate `spec`; the error names the key.
    pub fn new(spec: &WearSpec) -> Result<WearIntegrator, (String, String)> {
        let spec = &crate::wear_units::resolve_duration(spec)?;
        let bad = |k: &str, m: String| Err((format!("wear.{k}"), m));
        let mut laws = Vec::new();
        let mut law_bodies = Vec::new();
        for (body, (name, law)) in [("body1", spec.body1), ("body2", spec.body2)]
            .into_iter()
            .enumerate()
        {
            if let Some(l) = law {
                if !(l.beta.is_finite() && l.beta >= 0.0) {
                    return bad(
                        &format!("{name}.beta"),
                        format!("must be ≥ 0, got {}", l.beta),
                    );
                }
                // Measured exponents lie between about 0.3 and 4; beyond 10 only overflow waits.
                if !(l.a > 0.0 && l.a <= 10.0 && l.b > 0.0 && l.b <= 10.0) {
                    return bad(
                        name,
                        format!(
                            "exponents a and b must lie in (0, 10], got a = {}, b = {}",
                            l.a, l.b
                        ),
                    );
                }
                if l.beta > 0.0 {
                    laws.push(l);
                    law_bodies.push(body);
                }
            }
        }
        spec.check_turn()?;
        let (amplitude, speed) = spec.sliding_scale();
        let turn = spec.turns_about_axis();
        match spec.sliding.as_str() {
            "reciprocating" => {
                if !(amplitude > 0.0 && amplitude.is_finite()) {
                    return if turn {
                        bad(
                            "angle",
                            format!("a turn to and fro needs θ₀ > 0 (rad), got {amplitude}"),
                        )
                    } else {
                        bad(
                            "amplitude",
                            format!("reciprocating sliding needs u₀ > 0 (mm), got {amplitude}"),
                        )
                    };
                }
                if !(spec.omega > 0.0 && spec.omega.is_finite()) {
                    return bad(
                        "omega",
                        format!(
                            "reciprocating sliding needs ω > 0 (rad/s), got {}",
                            spec.omega
                        ),
                    );
                }
            }
            "monotonic" => {
                if turn && !(speed > 0.0 && speed.is_finite()) {
                    return bad(
                        "angular_speed",
                        format!("a turn one way needs ω > 0 (rad/s), got {speed}"),
                    );
                }
                if !(speed > 0.0
                    && spec.step_time > 0.0
                    && speed.is_finite()
                    && spec.step_time.is_finite())
                {
                    return bad("speed", format!("monotonic sliding needs speed > 0 (mm/s) and step_time > 0 (s), got {} and {}", spec.speed, spec.step_time));
                }
            }
            other => {
                return bad(
                    "sliding",
                    format!("must be \"reciprocating\" or \"monotonic\", got \"{other}\""),
                )
            }
        }
        if !(spec.tolerance.is_finite() && spec.tolerance > 0.0) {
            return bad(
                "tolerance",
                format!("must be positive (percent), got {}", spec.tolerance),
            );
        }
        if spec.criterion != "eq27" && spec.criterion != "pointwise" {
            return bad(
                "criterion",
                format!(
                    "must be \"eq27\" or \"pointwise\", got \"{}\"",
                    spec.criterion
                ),
            );
        }
        if spec.criterion != "eq27" && spec.scheme != "fixed_point" {
            // The implicit scheme has no such criterion: a choice it would ignore is an error.
            return bad("criterion", format!("\"{}\" applies to scheme = \"fixed_point\" only, and the scheme is \"{}\"; remove the key or set wear.scheme = \"fixed_point\"", spec.criterion, spec.scheme));
        }
        // Upper limits far beyond any use, so that a typo cannot exhaust memory (one record per
        // step), run for days, or overflow the half-period counter.
        if !(1..=MAX_STEPS).contains(&spec.steps) {
            return bad(
                "steps",
                format!("must be 1 … {MAX_STEPS}, got {}", spec.steps),
            );
        }
        if let Some(r) = spec.record.iter().find(|&&r| r == 0 || r > spec.steps) {
            // A snapshot outside the run would silently be missing from the output.
            return bad(
                "record",
                format!("step {r} is outside the run's steps 1 … {}", spec.steps),
            );
        }
        if !(1..=10_000).contains(&spec.max_iterations) {
            return bad(
                "max_iterations",
                format!("must be 1 … 10000, got {}", spec.max_iterations),
            );
        }
        if spec.substeps > 10_000 {
            return bad(
                "substeps",
                format!("must be 0 … 10000, got {}", spec.substeps),
            );
        }
        if spec.scheme != "implicit" && spec.scheme != "fixed_point" {
            return bad(
                "scheme",
                format!(
                    "must be \"implicit\" or \"fixed_point\", got \"{}\"",
                    spec.scheme
                ),
            );
        }
        if let Some(adaptive) = &spec.adaptive {
            if spec.extrapolation.is_some() {
                return bad(
                    "adaptive",
                    "give either an extrapolation schedule or [wear.adaptive], not both".into(),
                );
            }
            if spec.substeps > 0 || spec.scheme != "implicit" {
                return bad(
                    "adaptive",
                    "the adaptive schedule needs the implicit scheme (scheme = \"implicit\", substeps = 0)".into(),
                );
            }
            adaptive
                .validate()
                .map_err(|(k, m)| (format!("wear.adaptive.{k}"), m))?;
        }
        let schedule = spec.extrapolation.clone().unwrap_or_else(paper_schedule);
        check_schedule(&schedule).map_err(|m| ("wear.extrapolation".to_string(), m))?;
        if spec.shape_zero_at.is_some_and(|x| !x.is_finite()) {
            return bad("shape_zero_at", "must be a finite x coordinate (mm)".into());
        }
        let integrator = WearIntegrator {
            spec: spec.clone(),
            schedule,
            laws,
            law_bodies,
            first_direction: Direction::Plus,
            heat: None,
            about_axis: None,
            point_factor: Vec::new(),
        };
        for (name, law) in [("body1", spec.body1), ("body2", spec.body2)] {
            if let Some(l) = law {
                let per_half_period = l.beta * integrator.sliding(l.a);
                if !per_half_period.is_finite() {
                    return bad(
                        &format!("{name}.beta"),
                        format!("β̃ ∫|v|ᵃ dτ overflows ({per_half_period}): β̃, a or the sliding amplitude/speed is out of range"),
                    );
                }
                // A body given a wear law must wear: an integral that underflows to zero (or
                // to a subnormal, which loses its digits) would be taken for β̃ = 0 (red team
                // 23: a = 10 with u₀ = 1e-40 mm, "no body wears (all β̃ are zero)").
                if l.beta > 0.0 && per_half_period < f64::MIN_POSITIVE {
                    return bad(
                        &format!("{name}.beta"),
                        format!("β̃ ∫|v|ᵃ dτ underflows ({per_half_period:e}, β̃ = {:e}): a or the sliding amplitude/speed is out of range (β̃ = 0 switches the wear off)", l.beta),
                    );
                }
            }
        }
        Ok(integrator)
    }

    /// The wear of one half period (one monotonic step) as terms (c, b): Δw = Σ c pᵇ, with
    /// c = β̃ ∫|v|ᵃ dτ (mm MPa⁻ᵇ), one term per wearing body.
    pub fn half_period_wear(&self) -> Vec<(f64, f64)> {
        self.laws
            .iter()
            .map(|l| (l.beta * self.sliding(l.a), l.b))
            .collect()
    }

    /// The wear of one half period (step) at every contact point ([`WearTerms`]): the same
    /// terms everywhere, or under a turn about the axis each point's own (c rᵃ).
    pub fn wear_terms(&self) -> WearTerms {
        let terms = self.half_period_wear();
        if self.about_axis.is_some() {
            WearTerms::scaled_per_point(&terms, &self.point_factor)
        } else {
            WearTerms::uniform(&terms)
        }
    }

    /// Make the sliding a turn about the axis of bodies of revolution: point i slides
    /// `rotation.factor(i, a)` times the sliding of `wear.angle` or `wear.angular_speed`.
    /// The error names the key: a spec without those keys is not a turn.
    pub fn turn_about_axis(&mut self, rotation: AxisRotation) -> Result<(), (String, String)> {
        if !self.spec.turns_about_axis() {
            let key = if self.is_monotonic() {
                "wear.angular_speed"
            } else {
                "wear.angle"
            };
            return Err((key.into(), "the bodies turn about their axis (contact.sliding_motion = \"about_axis\"): give the turn's angular_speed (rad/s, sliding = \"monotonic\") or angle (rad, sliding = \"reciprocating\") instead of speed or amplitude".into()));
        }
        self.point_factor = self.laws.iter().map(|l| rotation.factors(l.a)).collect();
        self.about_axis = Some(rotation);
        Ok(())
    }

    /// The turn about the axis, if the sliding is one.
    pub fn about_axis(&self) -> Option<&AxisRotation> {
        self.about_axis.as_ref()
    }

    /// Law `law`'s sliding factor at point `i`: 1, or rᵃ under a turn about the axis.
    fn factor(&self, law: usize, i: usize) -> f64 {
        self.point_factor.get(law).map_or(1.0, |f| f[i])
    }

    /// The wear law of body `body` (0: body 1, 1: body 2), if it wears (β̃ > 0).
    pub fn law_of(&self, body: usize) -> Option<WearLaw> {
        self.law_bodies
            .iter()
            .position(|&b| b == body)
            .map(|k| self.laws[k])
    }

    /// The extrapolation schedule (validated).
    pub fn schedule(&self) -> &[ScheduleEntry] {
        &self.schedule
    }

    /// Whether the sliding is monotonic (one direction) rather than reciprocating.
    pub fn is_monotonic(&self) -> bool {
        self.spec.sliding == "monotonic"
    }

    /// Sliding distance of one half period (monotonic: of one step unit, `step_time`), mm.
    pub fn sliding_per_half_period(&self) -> f64 {
        self.sliding(1.0)
    }

    /// Sliding integral ∫|v|ᵃ dτ of one half period (or one monotonic step).
    fn sliding(&self, a: f64) -> f64 {
        if self.spec.sliding == "monotonic" {
            let (_, speed) = self.spec.sliding_scale();
            speed.powf(a) * self.spec.step_time
        } else {
            let (amplitude, _) = self.spec.sliding_scale();
            half_period_sliding(amplitude, self.spec.omega, a)
        }
    }

    /// Wear gap increment of one half period at pressures `p` (mm), scaled by `scale`.
    fn wear_increment(&self, p: &[f64], sliding: &[f64], scale: f64, out: &mut [f64]) {
        out.iter_mut().for_each(|w| *w = 0.0);
        for (l, (law, s)) in self.laws.iter().zip(sliding).enumerate() {
            for (i, (w, &pi)) in out.iter_mut().zip(p).enumerate() {
                // pow(x, 1) is x exactly: the linear law (every adaptive step) skips the call.
                let pb = if law.b == 1.0 {
                    pi.max(0.0)
                } else {
                    pi.max(0.0).powf(law.b)
                };
                *w += scale * law.beta * pb * s * self.factor(l, i);
            }
        }
    }
}
