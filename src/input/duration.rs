//! Durations and record points given as sliding distance, time or cycles, turned into the
//! half-period counts the schedule must land on.
//!
//! A run's steps follow its extrapolation schedule, each step standing for k half periods
//! (step units, under monotonic sliding). A record point in metres, seconds or cycles is a
//! count of half periods H (rounded to the nearest whole one); for a step to end exactly
//! there, the schedule's steps are cut at each such H as they are at the run's end
//! ([`crate::wear_units::steps_for`]): each direction gets ⌈H/2⌉ and ⌊H/2⌋ of them.

use crate::kinematics::{factor, ScheduleEntry};
use crate::wear::{WearSpec, MAX_STEPS};

type KeyError = (String, String);

/// Steps that pass through given half-period counts: their number, the schedule that does it,
/// and the step that ends at each count.
pub struct Through {
    /// The number of steps.
    pub steps: usize,
    /// The schedule, cut where needed.
    pub schedule: Vec<ScheduleEntry>,
    /// The step that ends at each target.
    pub ends: Vec<usize>,
}

/// Half periods (step units) per unit of each way of giving a duration: per metre of
/// sliding, per second and per cycle. None where the sliding does not define it.
pub struct Units {
    /// Half periods per metre of sliding.
    pub per_metre: Option<f64>,
    /// Half periods per second.
    pub per_second: Option<f64>,
    /// Half periods per cycle (reciprocating only).
    pub per_cycle: Option<f64>,
}

impl Units {
    /// The units of `spec`'s sliding.
    pub fn of(spec: &WearSpec) -> Units {
        let positive = |v: f64| (v > 0.0 && v.is_finite()).then_some(v);
        if spec.sliding == "monotonic" {
            Units {
                per_metre: positive(1000.0 / (spec.speed * spec.step_time)),
                per_second: positive(1.0 / spec.step_time),
                per_cycle: None,
            }
        } else {
            Units {
                per_metre: positive(1000.0 / (2.0 * spec.amplitude)),
                // A half period lasts π/ω.
                per_second: positive(spec.omega / std::f64::consts::PI),
                per_cycle: Some(2.0),
            }
        }
    }
}

/// The record points of `spec` (`record_distance`, `record_time`, `record_cycles`) as half
/// periods, each with the key that gave it; errors name the key.
pub fn record_points(spec: &WearSpec) -> Result<Vec<(u64, String)>, KeyError> {
    let units = Units::of(spec);
    let lists = [
        (
            "record_distance",
            &spec.record_distance,
            units.per_metre,
            "needs the sliding (amplitude, or speed and step_time) to be given and positive",
        ),
        (
            "record_time",
            &spec.record_time,
            units.per_second,
            "needs omega (reciprocating) or step_time (monotonic) to be given and positive",
        ),
        (
            "record_cycles",
            &spec.record_cycles,
            units.per_cycle,
            "monotonic sliding has no cycles: give record_distance or record_time",
        ),
    ];
    let mut points = Vec::new();
    for (key, values, per_unit, missing) in lists {
        for (i, &value) in values.iter().enumerate() {
            let Some(per_unit) = per_unit else {
                return Err((format!("wear.{key}"), missing.to_string()));
            };
            let half_periods = (value * per_unit).round();
            if !(value.is_finite() && (1.0..=1e12).contains(&half_periods)) {
                return Err((
                    format!("wear.{key}[{i}]"),
                    format!(
                        "must lie at least one half period (step unit) into the run, got {value}"
                    ),
                ));
            }
            points.push((half_periods as u64, format!("wear.{key}[{i}]")));
        }
    }
    points.sort_by_key(|p| p.0);
    points.dedup_by_key(|p| p.0);
    Ok(points)
}

/// The half periods the first `steps` steps of `schedule` stand for.
pub fn half_periods_of(steps: usize, schedule: &[ScheduleEntry]) -> u64 {
    (1..=steps).fold(0u64, |sum, n| {
        sum.saturating_add(factor(schedule, n).max(1) as u64)
    })
}

/// The steps whose factors pass through every one of `targets` (half periods, rising) and end
/// at the last, the schedule that does it, and the step that ends at each target; `None` past
/// [`MAX_STEPS`], and an error message when a step would have nothing to do (a schedule that
/// changes k after an odd step can leave the direction whose turn it is with nothing due).
///
/// Between targets (and for a single target, [`crate::wear_units::steps_for`]) each step's k is cut to what
/// its direction still needs (⌈H/2⌉ and ⌊H/2⌋ of H half periods in all), and when one
/// direction is done the other's next step takes all it still needs.
pub fn steps_through(
    targets: &[u64],
    schedule: &[ScheduleEntry],
    alternating: bool,
) -> Result<Option<Through>, String> {
    let mut done = [0u64; 2];
    let mut factors: Vec<u64> = Vec::new();
    let mut ends = Vec::with_capacity(targets.len());
    let mut cut = false;
    for (i, &target) in targets.iter().enumerate() {
        // An odd target before another ends on a '+' step of one half period, so that the
        // next segment starts with the '−' step whose half period the odd count leaves due
        // (ending it on '−' left the next '+' step with nothing to do).
        let odd_between = alternating && target % 2 == 1 && i + 1 < targets.len();
        let segment_end = if odd_between { target - 1 } else { target };
        let goal = if alternating {
            [segment_end.div_ceil(2), segment_end / 2]
        } else {
            [segment_end, 0]
        };
        let mut due = [
            goal[0] - done[0].min(goal[0]),
            goal[1] - done[1].min(goal[1]),
        ];
        while due != [0, 0] {
            let n = factors.len() + 1;
            if n > MAX_STEPS {
                return Ok(None);
            }
            let scheduled = factor(schedule, n).max(1) as u64;
            let (own, other) = if alternating && n.is_multiple_of(2) {
                (1, 0)
            } else {
                (0, 1)
            };
            if due[own] == 0 {
                return Err(format!(
                    "step {n} would slide no half period: the extrapolation schedule changes k after an odd step, so its steps cannot land on {target} half periods in both directions; change k only after even steps"
                ));
            }
            let k = if alternating && due[other] == 0 {
                due[own]
            } else {
                due[own].min(scheduled)
            };
            cut |= k != scheduled;
            due[own] -= k;
            done[own] += k;
            factors.push(k);
        }
        if odd_between {
            if factors.len() % 2 == 1 {
                return Err(format!(
                    "the extrapolation schedule changes k after an odd step, so its steps cannot land on {target} half periods in both directions; change k only after even steps"
                ));
            }
            cut = true;
            done[0] += 1;
            factors.push(1);
        }
        ends.push(factors.len());
    }
    let steps = factors.len();
    if !cut {
        return Ok(Some(Through {
            steps,
            schedule: schedule.to_vec(),
            ends,
        }));
    }
    // The factors step by step, as entries (runs of equal k); the last one open.
    let mut entries: Vec<ScheduleEntry> = Vec::new();
    for (m, &k) in factors.iter().enumerate() {
        match entries.last_mut() {
            Some(e) if e.k as u64 == k => e.until = Some(m + 1),
            _ => entries.push(ScheduleEntry {
                until: Some(m + 1),
                k: usize::try_from(k).unwrap_or(usize::MAX),
            }),
        }
    }
    if let Some(last) = entries.last_mut() {
        last.until = None;
    }
    Ok(Some(Through {
        steps,
        schedule: entries,
        ends,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::paper_schedule;

    #[test]
    fn the_steps_end_on_every_target() {
        // The paper's schedule (k = 1, 5, 10 after steps 50, 100) through 333, 1000 and
        // 16 300 half periods: a step ends at each, and the run's last step at 16 300.
        let targets = [333, 1000, 16_300];
        let Through {
            steps,
            schedule,
            ends,
        } = steps_through(&targets, &paper_schedule(), true)
            .unwrap()
            .unwrap();
        assert_eq!(ends.len(), 3);
        assert_eq!(*ends.last().unwrap(), steps);
        for (&end, &target) in ends.iter().zip(&targets) {
            assert_eq!(half_periods_of(end, &schedule), target);
        }
        // Both directions are even at each even target, one apart at an odd one.
        let mut plus = 0;
        let mut minus = 0;
        for n in 1..=ends[1] {
            let k = factor(&schedule, n) as u64;
            if n % 2 == 1 {
                plus += k
            } else {
                minus += k
            }
            if n == ends[0] {
                assert_eq!((plus, minus), (167, 166));
            }
        }
        assert_eq!((plus, minus), (500, 500));
    }

    #[test]
    fn an_odd_target_before_the_next_half_period_ends_on_a_plus_step() {
        // 303 then 304 half periods (a review found the second refused): the odd one ends
        // with a '+' step of 1, and the '−' half period left is the next step.
        for schedule in [paper_schedule(), vec![ScheduleEntry { until: None, k: 10 }]] {
            let Through {
                schedule: cut,
                ends,
                ..
            } = steps_through(&[303, 304], &schedule, true)
                .unwrap()
                .unwrap();
            assert_eq!(half_periods_of(ends[0], &cut), 303);
            assert_eq!(half_periods_of(ends[1], &cut), 304);
            assert_eq!(ends[0] % 2, 1, "the odd target ends on a '+' step");
        }
    }

    #[test]
    fn monotonic_targets_cut_single_steps() {
        let schedule = vec![ScheduleEntry { until: None, k: 7 }];
        let Through {
            steps,
            schedule,
            ends,
        } = steps_through(&[10, 30], &schedule, false).unwrap().unwrap();
        assert_eq!(half_periods_of(ends[0], &schedule), 10);
        assert_eq!(half_periods_of(steps, &schedule), 30);
    }
}
