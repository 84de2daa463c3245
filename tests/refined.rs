//! The wear integration on meshes the paper did not use: the contact refined to 16, 32 (and,
//! in docs/convergence.md, 64) elements under the punch with the strip's mesh lines matched,
//! and p from 4 to 12 on the shipped mesh. The reference is the steady state computed
//! directly on the same mesh (src/steady_state/steady.rs, itself checked against eq. 19 and 23 in
//! tests/steady.rs), which the 1700-step run of the shipped examples must approach.

mod common;
use common::problem;
use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::steady::{summed_pressure_theory, SteadyStatus};
use wearfem::wear::{non_rigid_part, StopReason};

/// Example `name` with `n` elements under the punch (strip lines matched), edits applied.
fn refined(name: &str, n: usize, edits: &[(&str, &str)]) -> Problem {
    let mut text = wearfem::examples::refined_punch(name, n).expect("a punch example");
    for (from, to) in edits {
        assert!(text.contains(from), "{name}: '{from}' not in the file");
        text = text.replace(from, to);
    }
    Problem::from_toml(&text, name).expect("valid problem")
}

/// Compare the 1700-step run with the steady state on the same problem, with the issue's
/// bounds: p⁺ and p⁻ within 1 % of the steady peak pressure, the shape within 2 % of its
/// range once rigid motion is removed, and (for `uniform_sum`) p⁺ + p⁻ uniform to 1 % away
/// from the two edge points.
fn assert_run_reaches_steady(
    problem: &Problem,
    case: &str,
    uniform_sum: bool,
    steps: Option<usize>,
) {
    let run = driver::wear(problem, steps, |_| {}).expect("run");
    let h = &run.history;
    assert!(h.stopped.is_none(), "{case}: stopped {:?}", h.stopped);
    assert_eq!(h.unconverged_steps + h.oscillating_steps, 0, "{case}");
    let (state, contact, _) = driver::steady(problem).expect("steady");
    assert_eq!(state.status, SteadyStatus::Solved, "{case}: the reference");
    let n = state.p_plus.len();
    let peak = state
        .p_plus
        .iter()
        .chain(&state.p_minus)
        .fold(0.0f64, |a, p| a.max(*p));
    for (name, ours, reference) in [
        ("p⁺", &h.p_plus, &state.p_plus),
        ("p⁻", &h.p_minus, &state.p_minus),
    ] {
        let (worst, at) = (0..n)
            .map(|i| ((ours[i] - reference[i]).abs(), i))
            .fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
        assert!(
            worst < 0.01 * peak,
            "{case}: {name} differs by {worst:.4} MPa at point {at} (peak {peak:.3})"
        );
    }
    // Shapes are defined up to a rigid motion: compare what no rigid motion explains.
    let in_contact: Vec<bool> = (0..n)
        .map(|i| state.p_plus[i] > 0.0 || state.p_minus[i] > 0.0)
        .collect();
    let r = contact.rigid_gap_matrix();
    let m = contact.rigid_modes.len();
    let w = &contact.points.weight;
    let wear: Vec<f64> = (0..n)
        .map(|i| h.shape[i] - contact.points.initial_gap[i])
        .collect();
    let reference = non_rigid_part(&state.shape, &in_contact, &r, m, w);
    let difference: Vec<f64> = (0..n).map(|i| wear[i] - state.shape[i]).collect();
    let difference = non_rigid_part(&difference, &in_contact, &r, m, w);
    let range = reference.iter().cloned().fold(f64::MIN, f64::max)
        - reference.iter().cloned().fold(f64::MAX, f64::min);
    let worst = difference.iter().fold(0.0f64, |a, d| a.max(d.abs()));
    assert!(
        worst < 0.02 * range,
        "{case}: shape differs by {worst:.3e} mm, range {range:.3e} mm"
    );
    if uniform_sum {
        let sums: Vec<f64> = (1..n - 1).map(|i| h.p_plus[i] + h.p_minus[i]).collect();
        let (lo, hi) = sums
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), s| (a.min(*s), b.max(*s)));
        assert!(
            hi - lo < 0.01 * hi,
            "{case}: p⁺ + p⁻ between {lo:.4} and {hi:.4} MPa"
        );
    }
    let distance = h.steady_distance.expect("a full cycle");
    assert!(distance.wear < 0.01, "{case}: {distance:?}");
    // ...and the run's own report says so.
    assert!(
        run.steady_check.reached(h),
        "{case}: {:?}",
        run.steady_check
    );
}

/// Red-team finding: a run whose last cycle's wear is already a rigid motion to 1e-2 (the
/// run's own measure) can still be several percent of the peak pressure from the steady
/// state (a slow mode: the pinned plate's rotation, the worn zone's ends). The report compares
/// with the steady state itself: neither run below is called steady, and the distance it
/// gives is the largest pressure difference from `steady` computed here.
#[test]
fn a_run_that_settles_slowly_is_not_called_steady() {
    use wearfem::steady_check::SteadyCheck;
    for (case, edits, steps) in [
        (
            "μ = 0.36, 5000 steps",
            vec![("friction = 0.25", "friction = 0.36")],
            5000,
        ),
        (
            "one step of k = 100 000 per cycle, 40 steps",
            vec![("[wear]", "[wear]\nextrapolation = [{ k = 100000 }]")],
            40,
        ),
    ] {
        let problem = common::problem("punch-b40", &edits);
        let run = driver::wear(&problem, Some(steps), |_| {}).expect("run");
        let h = &run.history;
        let own = h.steady_distance.expect("a full cycle");
        assert!(own.wear < 0.01, "{case}: the run's own measure {own:?}");
        let (state, _, _) = driver::steady(&problem).expect("steady");
        let peak = state
            .p_plus
            .iter()
            .chain(&state.p_minus)
            .fold(0.0f64, |a, p| a.max(*p));
        let worst = h
            .p_plus
            .iter()
            .zip(&state.p_plus)
            .chain(h.p_minus.iter().zip(&state.p_minus))
            .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        assert!(worst > 0.01 * peak, "{case}: {worst} MPa, peak {peak}");
        match run.steady_check {
            SteadyCheck::Compared { pressure, .. } => {
                // The same numbers in the same order: round-off only.
                assert!(
                    (pressure - worst / peak).abs() < 1e-12,
                    "{case}: {pressure}"
                );
            }
            ref other => panic!("{case}: {other:?}"),
        }
        assert!(!run.steady_check.reached(h), "{case}");
        let summary = run.summary(&problem);
        assert_eq!(
            summary["steady_reached"],
            serde_json::json!(false),
            "{case}"
        );
    }
}

#[test]
fn pinned_punch_reaches_the_steady_state_on_refined_meshes() {
    for n in [8, 16, 32] {
        let case = format!("b40, {n} el.");
        assert_run_reaches_steady(&refined("punch-b40", n, &[]), &case, true, None);
    }
}

#[test]
fn steady_state_converges_at_1025_contact_points() {
    // 128 elements under the punch: the Newton steps stop shrinking at about 4e-12 of the
    // forces (the solve's round-off), above the default tolerance of 1e-12; the iteration
    // used to run into its limit of 100 iterations here. It must end as solved, in a few
    // iterations, on the summed-pressure theory (eq. 19). Where both half cycles touch and
    // b = 1, eq. 19 holds for the discrete equations themselves, so the direct state meets it
    // to round-off: 1e-9 of the sum leaves the flexibility's condition number (about 1e6 at
    // this size) room. The elements next to the two edges are left out: there one half
    // cycle's contact ends.
    let problem = refined("punch-b40", 128, &[]);
    let (state, contact, _) = driver::steady(&problem).expect("steady");
    assert_eq!(state.status, SteadyStatus::Solved);
    assert!(state.iterations <= 30, "{} iterations", state.iterations);
    let theory = summed_pressure_theory(&contact).unwrap();
    let n = theory.len();
    let sums = state.p_plus.iter().zip(&state.p_minus).map(|(a, b)| a + b);
    for (i, (sum, expected)) in sums.zip(&theory).enumerate().take(n - 8).skip(8) {
        assert!(
            (sum - expected).abs() < 1e-9 * expected,
            "point {i}: p⁺ + p⁻ = {sum}, eq. 19 {expected}"
        );
    }
}

#[test]
fn translating_punch_and_load_variant_3_on_a_refined_mesh() {
    assert_run_reaches_steady(&refined("punch-a", 32, &[]), "punch-a, 32 el.", true, None);
    // Variant 3 has an eccentric load: p⁺ + p⁻ is linear (eq. 19), not uniform. Its transient
    // is slower: after the shipped 1700 steps it is still 1.9 % of the peak away on the
    // paper's mesh and 2.1 % on this one (docs/convergence.md), a property of the process,
    // not of the mesh; 5000 steps (48 300 half periods) bring both within the bound.
    assert_run_reaches_steady(
        &refined("punch-b40-variant3", 32, &[]),
        "variant 3, 32 el.",
        false,
        Some(5000),
    );
}

#[test]
fn other_polynomial_degrees_on_the_shipped_mesh() {
    for p in [4, 10, 12] {
        let replacement = format!("p = {p}");
        let problem = problem("punch-b40", &[("p = 8", &replacement)]);
        assert_run_reaches_steady(&problem, &format!("b40, p = {p}"), true, None);
    }
}

#[test]
fn fixed_point_iteration_fails_on_a_fine_mesh_where_the_implicit_step_does_not() {
    // 32 elements, k = 10 after step 100: the fixed-point map's contraction factor is about
    // k ΔW'(p) over the flexibility's smallest eigenvalue, above one on this mesh. The run
    // must not pass that off as a result: its steps are counted as oscillating.
    let steps = 200;
    let fixed = refined(
        "punch-b40",
        32,
        &[(
            "tolerance = 0.01 ",
            "scheme = \"fixed_point\"\ntolerance = 0.01 ",
        )],
    );
    let run = driver::wear(&fixed, Some(steps), |_| {}).expect("run");
    assert!(
        run.history.oscillating_steps > 0 || run.history.unconverged_steps > 0,
        "the fixed-point iteration was expected to fail on this mesh"
    );
    let implicit = driver::wear(&refined("punch-b40", 32, &[]), Some(steps), |_| {}).unwrap();
    let h = &implicit.history;
    assert_eq!(
        h.oscillating_steps + h.unconverged_steps + h.failed_solves,
        0
    );
    // After 200 steps the transient is far from over, but the pressures are smooth and
    // positive: no point-to-point oscillation of more than 5 % of the peak between
    // neighbours inside the contact (the steady profile changes by < 1 % per point there).
    let peak = h.p_plus.iter().fold(0.0f64, |a, p| a.max(*p));
    for w in h.p_plus.windows(3) {
        let kink = (w[0] - 2.0 * w[1] + w[2]).abs();
        if w.iter().all(|p| *p > 0.05 * peak) {
            assert!(kink < 0.05 * peak, "oscillation {kink:.3} MPa in {w:?}");
        }
    }
}

#[test]
fn a_failed_contact_solve_stops_the_run_and_keeps_nothing_of_it() {
    // μ = 5 with the pin 40 mm above the contact: μ l_z = 200 mm puts the pressure centre far
    // outside the 60 mm punch, so no contact state exists in the first half cycle.
    let problem = common::problem("punch-b40", &[("friction = 0.25", "friction = 5.0")]);
    let run = driver::wear(&problem, None, |_| {}).expect("run");
    let h = &run.history;
    match &h.stopped {
        Some((
            1,
            StopReason::FailedSolve {
                complementarity, ..
            },
        )) => {
            assert!(*complementarity > wearfem::complementarity::ACCEPTED_RESIDUAL)
        }
        other => panic!("expected a failed solve at step 1, got {other:?}"),
    }
    assert!(h.steps.is_empty() && h.steady_distance.is_none());
}

#[test]
fn no_output_of_a_failing_run_holds_a_negative_pressure() {
    // Through the binary, as a user meets it: exit 1, a message naming the step and the
    // residual, and no negative pressure or NaN in anything written.
    let dir = std::env::temp_dir().join(format!("wearfem-mu5-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace("friction = 0.25", "friction = 5.0");
    let file = dir.join("mu5.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let result = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args([
            "run",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(result.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(
        stderr.contains("step 1") && stderr.contains("complementarity residual"),
        "{stderr}"
    );
    for entry in std::fs::read_dir(&out).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(!text.contains("NaN") && !text.contains("null"), "{path:?}");
        if path.extension().is_some_and(|e| e == "csv") {
            for line in text.lines().skip(1) {
                assert!(
                    !line
                        .split(',')
                        .any(|v| v.parse::<f64>().is_ok_and(|x| x < 0.0) && !v.is_empty()),
                    "{path:?}: {line}"
                );
            }
        }
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(
        summary.get("final").is_none(),
        "profiles written without a full cycle"
    );
    assert_eq!(summary["stopped_at_step"], 1);
    let _ = std::fs::remove_dir_all(&dir);
}
