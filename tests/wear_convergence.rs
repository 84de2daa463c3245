//! Numerical convergence of the wear integration: extrapolation factors, polynomial degree,
//! and the half-period scheme against plain sub-stepping.

mod common;
use common::{p_m_plus, problem, run};

#[test]
fn halving_the_extrapolation_factors_changes_little() {
    let base = run(&problem("punch-b40", &[]), None);
    // k = 1, 2, 5 instead of 1, 5, 10, over the same 16 300 half periods: 50 + 125·2 + 3200·5.
    let halved = problem("punch-b40", &[("steps = 1700 ", "steps = 3375 \nextrapolation = [{ until = 50, k = 1 }, { until = 175, k = 2 }, { k = 5 }]\n")]);
    let fine = run(&halved, None);
    assert_eq!(fine.history.steps.last().unwrap().half_period, 16_300);
    let (a, b) = (p_m_plus(&base, 1700), p_m_plus(&fine, 3375));
    // The bound: 0.2 %.
    assert!(
        (a - b).abs() < 0.002 * a,
        "p(M): {a:.5} (k = 1, 5, 10) vs {b:.5} (k = 1, 2, 5)"
    );
}

#[test]
fn raising_p_from_8_to_10_changes_little() {
    let p8 = run(&problem("punch-b40", &[]), None);
    let p10 = run(&problem("punch-b40", &[("p = 8", "p = 10")]), None);
    let (a, b) = (p_m_plus(&p8, 1700), p_m_plus(&p10, 1700));
    // The bound: 0.2 % (the steady pressure is smooth; only the edge point's
    // approach to it depends on the resolution).
    assert!(
        (a - b).abs() < 0.002 * a,
        "p(M): {a:.5} (p = 8) vs {b:.5} (p = 10)"
    );
}

#[test]
fn half_period_scheme_agrees_with_sub_stepping() {
    let scheme = run(&problem("punch-b40", &[]), Some(200));
    let stepped = run(
        &problem(
            "punch-b40",
            &[("tolerance = 0.01 ", "substeps = 20\ntolerance = 0.01 ")],
        ),
        Some(200),
    );
    let (a, b) = (&scheme.history, &stepped.history);
    let peak = a.p_plus.iter().cloned().fold(0.0, f64::max);
    for (name, x, y) in [("p⁺", &a.p_plus, &b.p_plus), ("p⁻", &a.p_minus, &b.p_minus)] {
        let worst = x
            .iter()
            .zip(y.iter())
            .map(|(u, v)| (u - v).abs())
            .fold(0.0, f64::max);
        // The bound: 0.5 % in pressure after 200 steps.
        assert!(
            worst < 0.005 * peak,
            "{name}: largest difference {worst:.4} MPa of {peak:.3}"
        );
    }
}

#[test]
fn fixed_point_criteria_agree_with_the_implicit_step_on_the_papers_mesh() {
    // On the paper's mesh the fixed-point iteration contracts: eq. 27 is met after one
    // corrector for b = 1 (equilibrium fixes ∫p dS), iterating pointwise to 0.01 % must not
    // change the result, and both must agree with the directly solved backward-Euler step.
    let fixed = "scheme = \"fixed_point\"\ntolerance = 0.01 ";
    let pointwise = "scheme = \"fixed_point\"\ncriterion = \"pointwise\"\ntolerance = 0.01 ";
    let implicit = run(&problem("punch-b40", &[]), None);
    let paper = run(&problem("punch-b40", &[("tolerance = 0.01 ", fixed)]), None);
    let strict = run(
        &problem("punch-b40", &[("tolerance = 0.01 ", pointwise)]),
        None,
    );
    assert_eq!(strict.history.unconverged_steps, 0);
    assert!(
        strict.history.steps.iter().any(|s| s.iterations > 1),
        "pointwise never iterated"
    );
    assert!(implicit.history.steps.iter().all(|s| s.iterations == 1));
    let a = p_m_plus(&implicit, 1700);
    for (name, other) in [("eq. 27", &paper), ("pointwise", &strict)] {
        let b = p_m_plus(other, 1700);
        // The bound for a change of the iteration: 0.2 %.
        assert!(
            (a - b).abs() < 0.002 * a,
            "p(M): {a:.5} (implicit) vs {b:.5} (fixed point, {name})"
        );
    }
}

#[test]
fn substrate_wear_adds_to_punch_wear_in_the_gap() {
    // Both bodies' normal wear enters the same gap (reference model: the point pairs do not
    // move), so half the wear coefficient on each body must reproduce the punch-only run.
    let punch = run(&problem("punch-a", &[]), Some(300));
    let split = run(&problem("punch-a", &[("body1 = { beta = 3.9269908169872414e-8, a = 1.0, b = 1.0 }", "body1 = { beta = 1.9634954084936207e-8, a = 1.0, b = 1.0 }\nbody2 = { beta = 1.9634954084936207e-8 }")]), Some(300));
    for (a, b) in punch.history.p_plus.iter().zip(&split.history.p_plus) {
        // Same arithmetic up to the order of two additions: round-off only.
        assert!((a - b).abs() < 1e-9 * a.abs().max(1.0), "{a} vs {b}");
    }
}

#[test]
fn run_starts_in_the_problems_sliding_direction() {
    let r = run(
        &problem(
            "punch-b40",
            &[("friction = 0.25", "friction = 0.25\ndirection = \"-\"")],
        ),
        Some(4),
    );
    let directions: Vec<&str> = r.history.steps.iter().map(|s| s.direction).collect();
    assert_eq!(directions, ["−", "+", "−", "+"]);
}
