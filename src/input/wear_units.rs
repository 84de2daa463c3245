//! Wear input in the quantities engineers use, converted to the model's: Archard's wear
//! coefficients to β̃, and a duration in cycles or sliding distance to a number of steps.
//!
//! **Wear coefficients.** The model's rule is ẇ = β̃ pᵇ |v|ᵃ (paper eq. 1), with the wear rate
//! ẇ in mm/s, the contact pressure p in MPa and the sliding speed v in mm/s. The paper writes it
//! with the friction stress, ẇ = β (μ p)ᵇ |v|ᵃ, so β̃ = β μᵇ. Archard's law is written with the
//! *normal* pressure: worn volume V = k F s, or per unit area, wear depth w = k p s. For a = b = 1
//! it is the model's rule with β̃ in place of k: **μ does not enter the conversion** from
//! Archard's k to β̃ (it enters only between the paper's β and β̃; the paper's β = k / μ).
//!
//! - Dimensional coefficient k in mm³/(N·m) (the "specific wear rate" of tribometer data): with
//!   p in N/mm² and s in m, w = k p s is in mm³/(N·m) · N/mm² · m = mm. With the sliding in mm,
//!   s = s_mm / 1000, so w = (k / 1000) p s_mm and **β̃ = k / 1000** in MPa⁻¹ (mm²/N, i.e. mm of
//!   wear per mm of sliding per MPa).
//! - Dimensionless coefficient K with the hardness H (MPa) of the wearing body: V = K F s / H,
//!   w = (K / H) p s with s in mm, so **β̃ = K / H** in MPa⁻¹.
//!
//! Both forms are Archard's linear law, so they require a = b = 1.
//!
//! **Duration.** `wear.steps` counts numerical steps; step n stands for k(n) half periods
//! (the extrapolation schedule, paper eq. 29–30). Instead of `steps` a file may give
//! `cycles` (reciprocating: 2 half periods each) or `distance` (m of sliding: 2u₀ per half
//! period; monotonic: v · `step_time` per step unit), rounded to the nearest whole half period
//! (step unit). The steps are then those of the schedule that cover exactly that many half
//! periods. Monotonic: the last step's k is cut down to the remainder when the schedule would
//! overshoot. Reciprocating: steps alternate between the two directions and a step with factor
//! k stands for k half periods of its own, so the cut keeps the directions balanced (⌈H/2⌉
//! half periods in the first, ⌊H/2⌋ back; with the paper's schedule the last pair gets ⌈R/2⌉
//! and ⌊R/2⌋ of the R left, see [`steps_for`]). Cutting only the last step's k would leave up
//! to k − 1 more half periods in one direction than in the other, and the worn profile skewed.
//! `[wear.adaptive]` chooses k itself: it takes `steps` only.

use crate::kinematics::{paper_schedule, ScheduleEntry};
use crate::wear::{WearLaw, WearSpec, MAX_FACTOR, MAX_STEPS};
use serde::Deserialize;

/// A wear law as written in a problem file: one of `beta`, `k`, or `K` with `hardness`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WearLawInput {
    /// β̃ = β μᵇ, mm^(1−a) s^(a−1) MPa^(−b).
    pub beta: Option<f64>,
    /// Archard's dimensional wear coefficient, mm³/(N·m).
    pub k: Option<f64>,
    /// Archard's dimensionless wear coefficient (needs `hardness`).
    #[serde(rename = "K")]
    pub k_dimensionless: Option<f64>,
    /// Hardness H of the wearing body, MPa (with `K`).
    pub hardness: Option<f64>,
    /// Velocity exponent a (default 1).
    pub a: Option<f64>,
    /// Pressure exponent b (default 1).
    pub b: Option<f64>,
}

/// β̃ (MPa⁻¹) from Archard's dimensional coefficient k (mm³/(N·m)).
pub fn beta_from_archard_k(k: f64) -> f64 {
    k / 1000.0
}

/// β̃ (MPa⁻¹) from Archard's dimensionless K and the hardness H (MPa).
pub fn beta_from_archard_kh(k_dimensionless: f64, hardness: f64) -> f64 {
    k_dimensionless / hardness
}

impl TryFrom<WearLawInput> for WearLaw {
    type Error = String;

    fn try_from(w: WearLawInput) -> Result<WearLaw, String> {
        let (a, b) = (w.a.unwrap_or(1.0), w.b.unwrap_or(1.0));
        let archard = |what: &str, value: f64| {
            if a != 1.0 || b != 1.0 {
                return Err(format!("wear law: Archard's {what} is the linear law a = b = 1; give beta for a = {a}, b = {b}"));
            }
            if !(value.is_finite() && value >= 0.0) {
                return Err(format!(
                    "wear law: {what} must be finite and ≥ 0, got {value}"
                ));
            }
            Ok(())
        };
        let beta = match (w.beta, w.k, w.k_dimensionless, w.hardness) {
            (Some(beta), None, None, None) => beta,
            (None, Some(k), None, None) => {
                archard("k (mm³/(N·m))", k)?;
                beta_from_archard_k(k)
            }
            (None, None, Some(k), Some(h)) => {
                archard("K", k)?;
                if !(h.is_finite() && h > 0.0) {
                    return Err(format!("wear law: hardness must be > 0 (MPa), got {h}"));
                }
                beta_from_archard_kh(k, h)
            }
            (None, None, Some(_), None) => {
                return Err(
                    "wear law: K (dimensionless) needs the hardness H (MPa) of the wearing body"
                        .into(),
                )
            }
            (None, None, None, Some(_)) => {
                return Err("wear law: hardness is used only with K".into())
            }
            _ => return Err(
                "wear law: give exactly one of beta (β̃), k (Archard, mm³/(N·m)) or K with hardness"
                    .into(),
            ),
        };
        Ok(WearLaw { beta, a, b })
    }
}

type KeyError = (String, String);

/// The sliding's own keys, which a duration in metres, seconds or cycles is converted by:
/// named before the duration could be blamed for them (review of 2026-11-29: an amplitude of
/// 0 was reported as `wear.distance`).
fn check_kinematics(spec: &WearSpec) -> Result<(), KeyError> {
    let positive = |key: &str, value: f64, what: &str| {
        if value > 0.0 && value.is_finite() {
            Ok(())
        } else {
            Err((format!("wear.{key}"), format!("{what}, got {value}")))
        }
    };
    spec.check_turn()?;
    let (amplitude, speed) = spec.sliding_scale();
    match (spec.sliding.as_str(), spec.turns_about_axis()) {
        ("reciprocating", true) => {
            positive("angle", amplitude, "a turn to and fro needs θ₀ > 0 (rad)")?;
            return positive(
                "omega",
                spec.omega,
                "reciprocating sliding needs ω > 0 (rad/s)",
            );
        }
        ("monotonic", true) => {
            positive("angular_speed", speed, "a turn one way needs ω > 0 (rad/s)")?;
            return positive(
                "step_time",
                spec.step_time,
                "monotonic sliding needs a step time > 0 (s)",
            );
        }
        _ => {}
    }
    match spec.sliding.as_str() {
        "reciprocating" => {
            positive(
                "amplitude",
                spec.amplitude,
                "reciprocating sliding needs u₀ > 0 (mm)",
            )?;
            positive(
                "omega",
                spec.omega,
                "reciprocating sliding needs ω > 0 (rad/s)",
            )
        }
        "monotonic" => {
            positive(
                "speed",
                spec.speed,
                "monotonic sliding needs a speed v > 0 (mm/s)",
            )?;
            positive(
                "step_time",
                spec.step_time,
                "monotonic sliding needs a step time > 0 (s)",
            )
        }
        // Named by the integrator's own check.
        _ => Ok(()),
    }
}

/// `spec` with `steps` (and, when the schedule overshoots, `extrapolation`) worked out from
/// whichever of `steps`, `cycles`, `distance` and `time` it gives, cut to land on its record
/// points in metres, seconds or cycles (module [`crate::input::duration`]), which join
/// `record` as steps. The error names the key.
pub fn resolve_duration(spec: &WearSpec) -> Result<WearSpec, KeyError> {
    use crate::input::duration::{half_periods_of, record_points, steps_through, Units};
    let bad = |k: &str, m: String| Err((format!("wear.{k}"), m));
    // A turn's own keys first: its distance is no duration at all, not one too many.
    spec.check_turn()?;
    let given = [
        spec.steps > 0,
        spec.cycles.is_some(),
        spec.distance.is_some(),
        spec.time.is_some(),
    ];
    match given.iter().filter(|g| **g).count() {
        0 => return bad(
            "steps",
            "give the duration: steps (at least 1; 0 counts as not given), cycles, distance (m) or time (s)"
                .into(),
        ),
        1 => {}
        _ => {
            return bad(
                "steps",
                "give only one of steps, cycles, distance (m) and time (s)".into(),
            )
        }
    }
    check_kinematics(spec)?;
    let points = record_points(spec)?;
    if spec.steps > 0 && points.is_empty() {
        return Ok(spec.clone());
    }
    let monotonic = spec.sliding == "monotonic";
    if let (Some(adaptive_key), Some(_)) = (points.first().map(|p| &p.1), &spec.adaptive) {
        // The controller chooses k itself: there is no schedule to cut at the record points.
        return Err((
            adaptive_key.clone(),
            "[wear.adaptive] chooses k itself and cannot land on given distances, times or cycles: record by wear.record (steps), or give a schedule".into(),
        ));
    }
    let schedule = spec.extrapolation.clone().unwrap_or_else(paper_schedule);
    // The schedule as given is checked before it is cut: a cut one is rebuilt from its steps'
    // factors and would hide what was wrong with it.
    crate::wear::check_schedule(&schedule).map_err(|m| ("wear.extrapolation".to_string(), m))?;
    if spec.steps > MAX_STEPS {
        return bad(
            "steps",
            format!("must be 1 … {MAX_STEPS}, got {}", spec.steps),
        );
    }
    let (key, end) = if spec.steps > 0 {
        ("steps", half_periods_of(spec.steps, &schedule) as f64)
    } else {
        let units = Units::of(spec);
        let (key, value, per_unit, missing) = match (spec.cycles, spec.distance, spec.time) {
            (Some(c), _, _) => (
                "cycles",
                c,
                units.per_cycle,
                "monotonic sliding has no cycles: give distance (m), time (s) or steps",
            ),
            (_, Some(d), _) => (
                "distance",
                d,
                units.per_metre,
                "needs the sliding (amplitude, or speed and step_time) to be given and positive",
            ),
            (_, _, Some(t)) => (
                "time",
                t,
                units.per_second,
                "needs omega (reciprocating) or step_time (monotonic) to be given and positive",
            ),
            _ => unreachable!("one of the four is given"),
        };
        let Some(per_unit) = per_unit else {
            return bad(key, missing.into());
        };
        let half_periods = (value * per_unit).round();
        if !(value.is_finite() && (1.0..=1e12).contains(&half_periods)) {
            return bad(
                key,
                format!("must give at least one half period (and at most 1e12), got {value}"),
            );
        }
        if spec.adaptive.is_some() {
            // The controller chooses k itself and the run ends at the steady state; a schedule
            // cut to a duration has nothing to cut.
            return bad(
                key,
                "[wear.adaptive] chooses k itself and stops at the steady state: give the most steps it may take as wear.steps".into(),
            );
        }
        (key, half_periods)
    };
    let end = end as u64;
    if let Some((beyond, point_key)) = points.iter().find(|p| p.0 > end) {
        return Err((
            point_key.clone(),
            format!("lies {beyond} half periods (step units) into the run, past its end at {end}"),
        ));
    }
    let mut targets: Vec<u64> = points.iter().map(|p| p.0).filter(|&h| h < end).collect();
    targets.push(end);
    let crate::input::duration::Through {
        steps,
        schedule,
        ends,
    } = steps_through(&targets, &schedule, !monotonic)
        .map_err(|m| (format!("wear.{key}"), m))?
        .ok_or_else(|| {
            (
                format!("wear.{key}"),
                format!("needs more than {MAX_STEPS} steps with this extrapolation schedule"),
            )
        })?;
    if let Some(e) = schedule.iter().find(|e| e.k > MAX_FACTOR) {
        // Only a schedule whose k alternates unevenly between the directions gets here: the
        // last step takes all its direction still needs.
        return bad(
            key,
            format!("the last step would need k = {} > {MAX_FACTOR} to balance the two directions with this extrapolation schedule", e.k),
        );
    }
    // The steps that end at the record points (a point at the run's end is its last step).
    let mut record = spec.record.clone();
    for (point, _) in &points {
        let at = targets
            .iter()
            .position(|t| t == point)
            .map_or(steps, |i| ends[i]);
        record.push(at);
    }
    record.sort_unstable();
    record.dedup();
    // Resolved: the steps and the record steps say it all, and resolving again changes
    // nothing.
    Ok(WearSpec {
        steps,
        extrapolation: Some(schedule),
        record,
        cycles: None,
        distance: None,
        time: None,
        record_distance: vec![],
        record_time: vec![],
        record_cycles: vec![],
        ..spec.clone()
    })
}

/// The number of steps whose factors sum to exactly `half_periods`, and the schedule that
/// does it (`schedule` itself when no step needs cutting); `None` past [`MAX_STEPS`]. Entries
/// with a bad k are left for the validation to report.
///
/// Monotonic sliding (`alternating` false): steps as scheduled, the last one's k cut to the
/// remainder. Reciprocating (`alternating` true): odd steps slide in the first direction and
/// even ones back, and a step with factor k stands for k half periods of its own direction,
/// so of H half periods ⌈H/2⌉ must be first-direction steps' and ⌊H/2⌋ the others'. Each
/// step's k is cut to what its direction still needs, and when one direction is done, the
/// other's next step (the last) takes all it still needs. With a schedule whose k changes only
/// after even steps (the paper's) only the last pair is cut: with R < 2k half periods left,
/// its steps get ⌈R/2⌉ and ⌊R/2⌋ (a single step when R = 1).
pub fn steps_for(
    half_periods: u64,
    schedule: &[ScheduleEntry],
    alternating: bool,
) -> Option<(usize, Vec<ScheduleEntry>)> {
    // One target: the record points' cut with none between (its error, a step with nothing
    // due, cannot arise when the steps start from nothing).
    crate::input::duration::steps_through(&[half_periods], schedule, alternating)
        .ok()
        .flatten()
        .map(|t| (t.steps, t.schedule))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::factor;

    /// Hand calculation: Archard's k = 2·10⁻⁶ mm³/(N·m) (a hard steel pair). Over s = 1 m at
    /// p = 10 MPa the wear depth is w = k p s = 2·10⁻⁶ · 10 · 1 = 2·10⁻⁵ mm. The model's rule over
    /// 1000 mm of sliding: w = β̃ p s_mm, so β̃ = 2·10⁻⁵ / (10 · 1000) = 2·10⁻⁹ MPa⁻¹.
    #[test]
    fn archard_k_by_hand() {
        let beta = beta_from_archard_k(2e-6);
        assert!((beta - 2e-9).abs() <= 1e-24, "{beta}");
        let depth = beta * 10.0 * 1000.0;
        assert!((depth - 2e-5).abs() <= 1e-19);
    }

    /// Hand calculation: K = 10⁻⁴ (mild wear), H = 2000 MPa. V = K F s / H: F = 100 N on
    /// 10 mm² (p = 10 MPa), s = 500 mm gives V = 10⁻⁴ · 100 · 500 / 2000 = 2.5·10⁻³ mm³, a
    /// depth of 2.5·10⁻⁴ mm; β̃ p s = 5·10⁻⁸ · 10 · 500 = 2.5·10⁻⁴ mm.
    #[test]
    fn archard_dimensionless_by_hand() {
        let beta = beta_from_archard_kh(1e-4, 2000.0);
        assert!((beta - 5e-8).abs() <= 1e-22);
        let law: WearLaw = toml::from_str::<WearLawInput>("K = 1e-4\nhardness = 2000.0")
            .unwrap()
            .try_into()
            .unwrap();
        assert_eq!(
            law,
            WearLaw {
                beta,
                a: 1.0,
                b: 1.0
            }
        );
    }

    #[test]
    fn bad_combinations_are_rejected() {
        for text in [
            "beta = 1e-8\nk = 1e-6",
            "K = 1e-4",
            "hardness = 100.0",
            "k = 1e-6\nb = 1.2",
            "K = 1e-4\nhardness = 0.0",
            "k = -1.0",
            "a = 1.0",
        ] {
            let w: WearLawInput = toml::from_str(text).unwrap();
            assert!(WearLaw::try_from(w).is_err(), "{text}");
        }
    }

    /// Paper schedule: 50 steps of k = 1, 50 of k = 5 (300 half periods after step 100), then
    /// k = 10. 16 300 half periods (8150 cycles) are step 100 + 1600 = 1700, the paper's run.
    #[test]
    fn cycles_to_steps_with_the_paper_schedule() {
        let (n, schedule) = steps_for(16_300, &paper_schedule(), true).unwrap();
        assert_eq!(n, 1700);
        assert_eq!(schedule, paper_schedule());
        // 303 half periods: step 100 ends at 300, the pair 101–102 would end at 320. The 3 left
        // are 2 '+' and 1 '−' half periods: 152 and 151 in all (303 = 2 · 151 + 1).
        let (n, schedule) = steps_for(303, &paper_schedule(), true).unwrap();
        assert_eq!(n, 102);
        assert_eq!(factor(&schedule, 101), 2);
        assert_eq!(factor(&schedule, 102), 1);
        assert_eq!((1..=100).map(|m| factor(&schedule, m)).sum::<usize>(), 300);
        // 333 (distance = 1 m at u₀ = 1.5 mm): step 102 ends at 320, then 7 '+' and 6 '−'
        // (167 and 166), not '+' 10 and '−' 3 (170 and 163).
        let (n, schedule) = steps_for(333, &paper_schedule(), true).unwrap();
        assert_eq!(n, 104);
        assert_eq!((factor(&schedule, 103), factor(&schedule, 104)), (7, 6));
        // Monotonic sliding has one direction: the last step takes the remainder.
        let (n, schedule) = steps_for(303, &paper_schedule(), false).unwrap();
        assert_eq!(n, 101);
        assert_eq!(factor(&schedule, 101), 3);
    }

    /// The half periods of each direction, from the steps' factors (odd steps the first
    /// direction): reciprocating sliding over H half periods slides ⌈H/2⌉ of them in the first
    /// direction and ⌊H/2⌋ back, whatever the schedule. Also: the factors sum to H, a
    /// schedule whose k changes only after even steps is never raised, only its last pair cut
    /// (to ⌈R/2⌉ and ⌊R/2⌋ of the R left), and the schedule is returned as given when nothing
    /// is cut.
    #[test]
    fn a_duration_keeps_the_two_directions_balanced() {
        let entry = |until, k| ScheduleEntry { until, k };
        let schedules = [
            (paper_schedule(), true),
            (vec![entry(Some(2), 1), entry(None, 7)], true),
            (vec![entry(None, 1)], true),
            (
                vec![entry(Some(4), 3), entry(Some(10), 1), entry(None, 6)],
                true,
            ),
            // k changes after odd steps: pairs are unequal even as scheduled.
            (vec![entry(Some(1), 1), entry(None, 7)], false),
            (vec![entry(Some(3), 7), entry(None, 1)], false),
            (
                vec![entry(Some(1), 5), entry(Some(2), 1), entry(None, 4)],
                false,
            ),
        ];
        for (schedule, even_pairs) in &schedules {
            for h in 1..=700u64 {
                let (n, cut) = steps_for(h, schedule, true).unwrap();
                let k: Vec<u64> = (1..=n).map(|m| factor(&cut, m) as u64).collect();
                let first: u64 = k.iter().step_by(2).sum();
                let back: u64 = k.iter().skip(1).step_by(2).sum();
                assert_eq!(
                    (first, back),
                    (h.div_ceil(2), h / 2),
                    "H = {h}, {schedule:?}: {k:?}"
                );
                assert!(k.iter().all(|&k| k >= 1), "H = {h}: {k:?}");
                if *even_pairs {
                    // Before the last pair (or the last single step) as scheduled, then the
                    // R left split ⌈R/2⌉, ⌊R/2⌋ (R = 1: one step).
                    let last = if n % 2 == 0 { n - 2 } else { n - 1 };
                    for m in 1..=last {
                        assert_eq!(k[m - 1], factor(schedule, m) as u64, "H = {h}: {k:?}");
                    }
                    let r = h - k[..last].iter().sum::<u64>();
                    if n % 2 == 0 {
                        assert_eq!((k[n - 2], k[n - 1]), (r.div_ceil(2), r / 2), "H = {h}");
                    } else {
                        assert_eq!(r, 1, "H = {h}: {k:?}");
                    }
                    assert!(r <= 2 * factor(schedule, last + 1) as u64, "H = {h}: {k:?}");
                }
                if k.iter()
                    .enumerate()
                    .all(|(m, &k)| k == factor(schedule, m + 1) as u64)
                {
                    assert_eq!(&cut, schedule, "H = {h}");
                }
            }
        }
    }

    /// Monotonic sliding: the factors sum to H and only the last step is cut.
    #[test]
    fn a_monotonic_duration_cuts_the_last_step() {
        for h in 1..=500u64 {
            let (n, cut) = steps_for(h, &paper_schedule(), false).unwrap();
            let k: Vec<u64> = (1..=n).map(|m| factor(&cut, m) as u64).collect();
            assert_eq!(k.iter().sum::<u64>(), h);
            for m in 1..n {
                assert_eq!(k[m - 1], factor(&paper_schedule(), m) as u64);
            }
            assert!(k[n - 1] <= factor(&paper_schedule(), n) as u64);
        }
    }

    /// `[wear.adaptive]` chooses k itself: a duration is an error naming the key, not the
    /// schedule it would have been turned into.
    #[test]
    fn adaptive_runs_take_steps_only() {
        let text = crate::examples::example("punch-b40").unwrap();
        let mut spec = toml::from_str::<crate::schema::ProblemSpec>(text)
            .unwrap()
            .wear
            .unwrap();
        spec.steps = 0;
        spec.cycles = Some(100.0);
        spec.adaptive = Some(toml::from_str("method = \"bdf2\"").unwrap());
        let (key, message) = resolve_duration(&spec).unwrap_err();
        assert_eq!(key, "wear.cycles");
        assert!(message.contains("wear.steps"), "{message}");
    }

    #[test]
    fn distance_to_steps() {
        // 2u₀ = 3 mm per half period: 48.9 m is 16 300 half periods, the paper's run.
        let text = crate::examples::example("punch-b40").unwrap();
        let mut spec = toml::from_str::<crate::schema::ProblemSpec>(text)
            .unwrap()
            .wear
            .unwrap();
        spec.steps = 0;
        spec.distance = Some(48.9);
        assert_eq!(resolve_duration(&spec).unwrap().steps, 1700);
        spec.distance = None;
        spec.cycles = Some(8150.0);
        assert_eq!(resolve_duration(&spec).unwrap().steps, 1700);
        spec.steps = 5;
        assert_eq!(resolve_duration(&spec).unwrap_err().0, "wear.steps");
    }
}
