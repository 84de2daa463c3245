//! Monotonic sliding reaches the steady state of paper §3 (Class 1): the wear rate is
//! compatible with the rigid-body wear velocity, so for b = 1 the pressure is uniform when the
//! plate only translates and linear when it may rotate about the pin, with its resultant F0 and
//! its centre shifted by μ l_z by the friction moment (eq. 8).

mod common;
use common::{problem, run};
use wearfem::wear::StopReason;

const MONOTONIC: (&str, &str) = (
    "sliding = \"reciprocating\"",
    "sliding = \"monotonic\"\nspeed = 15.0\nstep_time = 0.2",
);

#[test]
fn translating_punch_wears_to_uniform_pressure() {
    // 3 mm of sliding per step, as one half period of Example 1. The tilt mode decays slowly
    // (the plate holds rotation), hence 5000 steps (49 300 × 3 mm).
    let r = run(&problem("punch-a", &[MONOTONIC]), Some(5000));
    let p_tilde = 16.666;
    for (i, p) in r.history.p_plus.iter().enumerate() {
        // 0.1 %: the remaining tilt after 5000 steps is 0.02 %.
        assert!(
            (p - p_tilde).abs() < 1e-3 * p_tilde,
            "point {i}: p = {p:.4} MPa"
        );
    }
}

#[test]
fn pinned_punch_wears_to_the_linear_pressure_of_the_rigid_wear_velocity() {
    let r = run(&problem("punch-b20", &[MONOTONIC]), None);
    // Linear p with mean p̃ and centre at 1100 − μ l_z = 1095: p = p̃ (1 + 12 e (x − 1100)/L²).
    let (p_tilde, e, l) = (16.666, -0.25 * 20.0, 60.0);
    for (x, p) in r.contact.points.x.iter().zip(&r.history.p_plus) {
        let expected = p_tilde * (1.0 + 12.0 * e * (x[0] - 1100.0) / (l * l));
        // 0.1 % of p̃: the steady state is reached well within 1700 steps here.
        assert!(
            (p - expected).abs() < 1e-3 * p_tilde,
            "x = {}: p = {p:.4}, theory {expected:.4}",
            x[0]
        );
    }
}

#[test]
fn adaptive_schedule_finds_the_uniform_pressure_under_monotonic_sliding() {
    // Under monotonic sliding every step is a cycle: one BDF2 step, or for step doubling
    // a coarse single step of 2k and two fine ones. The run must stop by itself at the
    // steady state of eq. 8 (uniform p̃), with either method.
    for method in ["bdf2", "step_doubling"] {
        let adaptive = format!("record = []\n\n[wear.adaptive]\nmethod = \"{method}\"");
        let r = run(
            &problem(
                "punch-a",
                &[
                    MONOTONIC,
                    ("steps = 1700 ", "steps = 100000 "),
                    (
                        "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
                        adaptive.as_str(),
                    ),
                ],
            ),
            None,
        );
        let h = &r.history;
        assert!(
            matches!(h.stopped, Some((_, StopReason::SteadyState))),
            "{method}: {:?}",
            h.stopped
        );
        assert_eq!(h.failed_solves, 0, "{method}");
        let p_tilde = 16.666;
        for (i, p) in h.p_plus.iter().enumerate() {
            // 0.5 %: the run stops when the distance it predicts is below
            // steady_tolerance = 0.1 % of the peak; the prediction is an estimate, not a bound.
            assert!(
                (p - p_tilde).abs() < 5e-3 * p_tilde,
                "{method}, point {i}: p = {p:.4} MPa"
            );
        }
    }
}
