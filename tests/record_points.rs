//! Recording and stopping by sliding distance, time or cycles (issue 28, item 6): the schedule
//! is cut so that a step ends on each point.

use wearfem::driver;
use wearfem::problem::Problem;

const RECORD: &str = "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]";

fn punch_b40(wear_keys: &str) -> Problem {
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace("steps = 1700 ", "# steps")
        .replace(RECORD, wear_keys);
    Problem::from_toml(&text, "punch-b40, recorded by distance").unwrap()
}

/// (half periods, sliding distance in m) of every snapshot, and of the run's end.
fn recorded(problem: &Problem) -> (Vec<(usize, f64)>, (usize, f64)) {
    let run = driver::wear(problem, None, |_| {}).unwrap();
    let metres = |h: usize| h as f64 * run.sliding_per_half_period / 1000.0;
    let snapshots = run
        .history
        .snapshots
        .iter()
        .map(|s| (s.half_period, metres(s.half_period)))
        .collect();
    let end = run.history.steps.last().unwrap().half_period;
    (snapshots, (end, metres(end)))
}

#[test]
fn records_land_on_the_distances_under_the_paper_schedule() {
    // 2u₀ = 3 mm per half period: 0.3, 1.2 and 3.0 m are 100, 400 and 1000 half periods,
    // which the paper's schedule (k = 1, 5, 10) passes between its steps; the run ends at
    // 4.5 m. Whole half periods: the distances to round-off (1e-12 m).
    let problem = punch_b40("distance = 4.5\nrecord_distance = [3.0, 0.3, 1.2]");
    let (snapshots, end) = recorded(&problem);
    let expected = [(100, 0.3), (400, 1.2), (1000, 3.0)];
    assert_eq!(snapshots.len(), 3, "{snapshots:?}");
    for ((h, m), (eh, em)) in snapshots.iter().zip(expected) {
        assert_eq!(*h, eh);
        assert!((m - em).abs() < 1e-12, "{m} m vs {em} m");
    }
    assert_eq!(end.0, 1500);
    assert!((end.1 - 4.5).abs() < 1e-12);
}

#[test]
fn records_by_cycles_and_time_and_the_duration_by_time() {
    // ω = 10 rad/s: a half period lasts π/10 s. 10 cycles = 20 half periods; 2π s = 20 half
    // periods too (one point); 10π s = 100 half periods; the run lasts 20π s = 200.
    let pi = std::f64::consts::PI;
    let problem = punch_b40(&format!(
        "time = {}\nrecord_cycles = [10.0, 77.0]\nrecord_time = [{}, {}]",
        20.0 * pi,
        2.0 * pi,
        10.0 * pi
    ));
    let (snapshots, end) = recorded(&problem);
    let half: Vec<usize> = snapshots.iter().map(|s| s.0).collect();
    assert_eq!(half, [20, 100, 154]);
    assert_eq!(end.0, 200);
}

#[test]
fn a_block_on_a_turning_ring_records_at_its_distances() {
    // The brake shoe on its drum, sliding one way at 100 mm/s, 0.2 s per step unit (20 mm),
    // with k = 7 step units per step: 800, 1600, 2400 and 3600 mm land between steps and the
    // schedule is cut there (the block-on-ring distances, scaled by 1/1000 to keep
    // the test short). To round-off.
    let text = wearfem::examples::example("brake")
        .unwrap()
        .replace(
            "sliding = \"reciprocating\"",
            "sliding = \"monotonic\"\nspeed = 100.0\nstep_time = 0.2",
        )
        .replace(
            "steps = 12100 ",
            "extrapolation = [{ k = 7 }]\ndistance = 4.0\n# ",
        )
        .replace(
            "record = [1, 2, 1000, 4200, 6500, 12099, 12100]",
            "record_distance = [0.8, 1.6, 2.4, 3.6]",
        );
    let problem = Problem::from_toml(&text, "brake, monotonic").unwrap();
    let (snapshots, end) = recorded(&problem);
    let metres: Vec<f64> = snapshots.iter().map(|s| s.1).collect();
    for (m, expected) in metres.iter().zip([0.8, 1.6, 2.4, 3.6]) {
        assert!((m - expected).abs() < 1e-12, "{metres:?}");
    }
    assert_eq!(metres.len(), 4);
    assert!((end.1 - 4.0).abs() < 1e-12);
}

#[test]
fn record_points_that_cannot_be_met_are_refused_by_key() {
    let refuse = |keys: &str, key: &str| {
        let text = wearfem::examples::example("punch-b40")
            .unwrap()
            .replace("steps = 1700 ", "# steps")
            .replace(RECORD, keys);
        let err = Problem::from_toml(&text, "bad records")
            .and_then(|p| {
                driver::wear(&p, None, |_| {})
                    .map(|_| ())
                    .map_err(|e| match e {
                        driver::JobError::Problem(p) => p,
                        other => panic!("{other}"),
                    })
            })
            .expect_err(keys);
        assert!(err.key.starts_with(key), "{keys}: {err}");
    };
    // Past the end, below one half period, with the adaptive schedule, two durations.
    refuse(
        "distance = 1.0\nrecord_distance = [2.0]",
        "wear.record_distance[0]",
    );
    refuse(
        "distance = 1.0\nrecord_distance = [0.0001]",
        "wear.record_distance[0]",
    );
    refuse("steps = 100\nrecord_time = [-1.0]", "wear.record_time[0]");
    refuse(
        "steps = 100\nrecord_distance = [0.3]\n[wear.adaptive]\nmethod = \"bdf2\"",
        "wear.record_distance",
    );
    refuse("distance = 1.0\ntime = 3.0", "wear.steps");
}

#[test]
fn a_review_s_cases_land_or_are_refused_by_the_right_key() {
    let text = |keys: &str| {
        wearfem::examples::example("punch-b40")
            .unwrap()
            .replace("steps = 1700 ", "# steps")
            .replace(RECORD, keys)
    };
    // 151.5 cycles recorded in a run of 152 (303 then 304 half periods), also with k = 10.
    for keys in [
        "cycles = 152\nrecord_cycles = [151.5]",
        "extrapolation = [{ k = 10 }]\ncycles = 3\nrecord_cycles = [2.5]",
    ] {
        let problem = Problem::from_toml(&text(keys), "odd record").unwrap();
        let (snapshots, _) = recorded(&problem);
        assert_eq!(snapshots.len(), 1, "{keys}");
        assert_eq!(
            snapshots[0].0 % 2,
            1,
            "{keys}: an odd number of half periods"
        );
    }
    // A schedule that is wrong as given is refused as such, though a cut would hide it.
    let refused = |keys: &str| {
        let problem = Problem::from_toml(&text(keys), "bad").unwrap();
        match driver::wear(&problem, None, |_| {}) {
            Err(driver::JobError::Problem(e)) => e.key,
            Err(other) => panic!("{other}"),
            Ok(_) => panic!("{keys}: accepted"),
        }
    };
    assert_eq!(
        refused("steps = 20\nextrapolation = [{ until = 10, k = 3 }, { until = 4, k = 1 }, { k = 2 }]\nrecord_cycles = [2.5]"),
        "wear.extrapolation"
    );
    assert_eq!(
        refused("steps = 100000000000000\nrecord_cycles = [1.0]"),
        "wear.steps"
    );
}

#[test]
fn steps_past_a_cut_end_follow_the_schedule_as_given() {
    // 166.5 cycles (333 half periods) cut the paper's schedule at steps 103 (k = 7) and 104
    // (k = 6); `--steps 108` goes on with the paper's k = 10, not the cut's 6.
    let problem = punch_b40("cycles = 166.5");
    let run = driver::wear(&problem, Some(108), |_| {}).unwrap();
    let k: Vec<usize> = run.history.steps[104..].iter().map(|s| s.k).collect();
    assert_eq!(k, [10, 10, 10, 10]);
}
