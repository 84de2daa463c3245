//! The adaptive schedule (`[wear.adaptive]`, src/wear/adaptive.rs): BDF2 with a
//! predictor–corrector error estimate (the default) and step doubling with Richardson
//! extrapolation. References: the steady state computed directly on the same mesh
//! (src/steady_state/steady.rs, checked against eq. 19 and 23 in tests/steady.rs) and, for
//! how fast the transient decays, the half-period scheme with k = 1 (one step per half
//! period, the closest the integration comes to the process itself).

use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::steady::SteadyStatus;
use wearfem::wear::{StopReason, WearHistory};

/// The bound of issue 9: within 0.5 % of the steady peak pressure.
const BOUND: f64 = 0.005;
const RECORD: &str = "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]";

/// punch-b40 with `elements` under the punch, `steps` steps, all recorded, `extra` appended
/// to `[wear]`.
fn punch(elements: usize, steps: usize, extra: &str) -> Problem {
    Problem::from_toml(&punch_text(elements, steps, extra), "adaptive test").expect("valid")
}

/// The problem file of [`punch`].
fn punch_text(elements: usize, steps: usize, extra: &str) -> String {
    let text = wearfem::examples::refined_punch("punch-b40", elements).expect("punch-b40");
    let list: Vec<String> = (1..=steps).map(|s| s.to_string()).collect();
    text.replace("steps = 1700 ", &format!("steps = {steps} "))
        .replace(RECORD, &format!("record = [{}]\n{extra}", list.join(", ")))
}

/// The steady pressures p⁺, p⁻ (MPa) of `elements` and their peak.
fn steady(elements: usize) -> (Vec<f64>, Vec<f64>, f64) {
    let (state, _, _) = driver::steady(&punch(elements, 1700, "")).expect("steady");
    assert_eq!(state.status, SteadyStatus::Solved);
    let peak = state
        .p_plus
        .iter()
        .chain(&state.p_minus)
        .fold(0.0f64, |a, p| a.max(*p));
    (state.p_plus, state.p_minus, peak)
}

fn run(problem: &Problem) -> WearHistory {
    let history = driver::wear(problem, None, |_| {}).expect("run").history;
    assert_eq!(history.failed_solves + history.unconverged_steps, 0);
    history
}

/// Half periods until the run is within BOUND of the steady state.
fn reach(history: &WearHistory, reference: &(Vec<f64>, Vec<f64>, f64)) -> f64 {
    let (plus, minus, peak) = reference;
    history
        .half_periods_to_reach(plus, minus, *peak, BOUND)
        .expect("the run reaches the steady state")
}

#[test]
fn richardson_extrapolation_removes_the_lag_of_large_steps() {
    let reference = steady(8);
    let process = reach(
        &run(&punch(8, 20_000, "extrapolation = [{ k = 1 }]")),
        &reference,
    );
    // Steps up to k = 64 (fine cycles of 32), where the first-order lag is large.
    let first_order = reach(
        &run(&punch(
            8,
            4000,
            "\n[wear.adaptive]\nmethod = \"step_doubling\"\nmax_factor = 64\nrichardson = false",
        )),
        &reference,
    );
    let adaptive = reach(
        &run(&punch(
            8,
            4000,
            "\n[wear.adaptive]\nmethod = \"step_doubling\"\nmax_factor = 64",
        )),
        &reference,
    );
    // A run is compared with the reference once per cycle, and a cycle spans up to
    // max_factor = 64 half periods: closer than that cannot be told. Backward Euler with
    // k = 32 decays a transient of time constant τ ≈ 2800 half periods about k/(2τ) ≈ 0.6 %
    // (≈ 90 half periods) too slowly; Richardson's error is O((k/τ)²).
    assert!(
        (adaptive - process).abs() <= 64.0,
        "adaptive {adaptive}, process {process} half periods"
    );
    assert!(
        first_order > process + 2.0 * 64.0,
        "first order {first_order}, process {process} half periods"
    );
}

#[test]
fn bdf2_has_no_first_order_lag() {
    // BDF2 with k up to 32 (cycles of 64 half periods), where backward Euler lags by more
    // than two cycles (previous test): its decay factor per step is e^(−z)(1 + O(z³)), so
    // it gets there with the process. The crossing is interpolated between cycles
    // (half_periods_to_reach), so this is measured to better than a cycle: 16 half periods
    // (0.1 % of the 14 654) allowed, 4 measured.
    let reference = steady(8);
    let process = reach(
        &run(&punch(8, 20_000, "extrapolation = [{ k = 1 }]")),
        &reference,
    );
    let bdf2 = reach(
        &run(&punch(8, 4000, "\n[wear.adaptive]\nmax_factor = 32")),
        &reference,
    );
    assert!(
        (bdf2 - process).abs() <= 16.0,
        "BDF2 {bdf2}, process {process} half periods"
    );
}

/// Issue 9: the adaptive schedule reaches the steady state in fewer half periods than the
/// paper's (k = 1, 5, 10, continued with 10), and stops there by itself.
fn fewer_half_periods_than_the_paper(elements: usize, keys: &str) {
    let reference = steady(elements);
    let paper = reach(&run(&punch(elements, 8000, "")), &reference);
    let history = run(&punch(
        elements,
        4000,
        &format!("\n[wear.adaptive]\n{keys}"),
    ));
    let adaptive = reach(&history, &reference);
    assert!(
        adaptive < paper,
        "{elements} elements: adaptive {adaptive}, paper {paper} half periods"
    );
    assert!(
        matches!(history.stopped, Some((_, StopReason::SteadyState))),
        "{elements} elements: {:?}",
        history.stopped
    );
    // Where it stops by itself: steady_tolerance = 1e-3 of the peak is the distance it
    // predicts (a geometric series of the last changes, an estimate, not a bound): 0.25 %.
    let (plus, minus, peak) = &reference;
    let worst = history
        .p_plus
        .iter()
        .zip(plus)
        .chain(history.p_minus.iter().zip(minus))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 0.0025 * peak,
        "{elements} elements: stops {worst:.4} MPa from the steady state (peak {peak:.3})"
    );
}

#[test]
fn adaptive_schedule_beats_the_papers_on_the_shipped_mesh() {
    fewer_half_periods_than_the_paper(8, "");
}

#[test]
fn adaptive_schedule_beats_the_papers_on_a_refined_mesh() {
    fewer_half_periods_than_the_paper(32, "");
}

#[test]
fn step_doubling_beats_the_papers_schedule_too() {
    fewer_half_periods_than_the_paper(8, "method = \"step_doubling\"");
}

#[test]
fn adaptive_runs_started_with_minus_sliding_reach_the_steady_state_as_fast() {
    // Red team 15: step doubling compared the coarse cycle's pressures stored by half with
    // the fine cycle's stored by direction, so a run started with '−' compared p⁺ with p⁻,
    // rejected every macro step and stayed at k = 1 (4000 steps: 4000 half periods of the
    // 14 654 needed). The mirror start differs from '+' by one half period of transient, and
    // a run is compared once per cycle of up to 64 half periods.
    let reference = steady(8);
    for method in ["step_doubling", "bdf2"] {
        let adaptive = format!("\n[wear.adaptive]\nmethod = \"{method}\"\nmax_factor = 32");
        let text = punch_text(8, 4000, &adaptive);
        assert!(text.contains("friction = 0.25\n"));
        let minus = text.replace("friction = 0.25\n", "friction = 0.25\ndirection = \"-\"\n");
        let plus = Problem::from_toml(&text, "plus").expect("valid problem");
        let minus = Problem::from_toml(&minus, "minus").expect("valid problem");
        let (from_plus, from_minus) = (
            reach(&run(&plus), &reference),
            reach(&run(&minus), &reference),
        );
        assert!(
            (from_plus - from_minus).abs() <= 64.0,
            "{method}: '+' {from_plus}, '−' {from_minus} half periods"
        );
    }
}

/// `name` refined to 32 elements under the punch with `edit` applied, run with the adaptive
/// schedule: it must stop by itself within 0.25 % of the peak of the directly computed
/// steady state (the same bound, and the same reason, as above), with no failed solve.
fn stops_at_the_steady_state(name: &str, edit: (&str, &str)) {
    let text = wearfem::examples::refined_punch(name, 32).expect("refines");
    assert!(text.contains(edit.0), "{name}: {}", edit.0);
    let text = text
        .replace(edit.0, edit.1)
        .replace("steps = 1700 ", "steps = 20000 ")
        .replace("steps = 2500 ", "steps = 20000 ");
    let start = text.find("record = [").expect("record");
    let end = start + text[start..].find(']').expect("record list") + 1;
    let text = format!(
        "{}record = []\n\n[wear.adaptive]{}",
        &text[..start],
        &text[end..]
    );
    let problem = Problem::from_toml(&text, name).unwrap();
    let history = run(&problem);
    assert!(
        matches!(history.stopped, Some((_, StopReason::SteadyState))),
        "{name}: {:?}",
        history.stopped
    );
    let (state, _, _) = driver::steady(&problem).expect("steady");
    assert_eq!(state.status, SteadyStatus::Solved);
    let peak = state
        .p_plus
        .iter()
        .chain(&state.p_minus)
        .fold(0.0f64, |a, p| a.max(*p));
    let worst = history
        .p_plus
        .iter()
        .zip(&state.p_plus)
        .chain(history.p_minus.iter().zip(&state.p_minus))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 0.0025 * peak,
        "{name} {edit:?}: {worst:.4} MPa of {peak:.3}"
    );
}

#[test]
fn adaptive_schedule_with_a_nonlinear_wear_law_on_a_refined_mesh() {
    // b = 1.2 (Newton inside every step).
    stops_at_the_steady_state("punch-b40-b1.2", ("", ""));
}

#[test]
fn adaptive_schedule_with_a_steep_wear_law_on_a_refined_mesh() {
    // b = 2: the wear term's slope grows with the pressure (the stiffest case of the three).
    stops_at_the_steady_state("punch-b40", ("a = 1.0, b = 1.0 }", "a = 1.0, b = 2.0 }"));
}

#[test]
fn adaptive_schedule_with_a_flat_wear_law_on_a_refined_mesh() {
    // b = 0.8: Newton with the secant slope.
    stops_at_the_steady_state("punch-b40-b0.8", ("", ""));
}

#[test]
fn adaptive_schedule_with_a_very_flat_wear_law_on_a_refined_mesh() {
    // b = 0.1: tiny pressures wear almost as much as large ones, and the step's Newton
    // iteration in the pressure needed wear.max_iterations = 300 (red team 21); in the wear it
    // converges in the default 50.
    stops_at_the_steady_state(
        "punch-b40-b0.8",
        ("a = 1.0, b = 0.8 }", "a = 1.0, b = 0.1 }"),
    );
}

#[test]
fn adaptive_schedule_with_both_bodies_wearing_on_a_refined_mesh() {
    stops_at_the_steady_state(
        "punch-b40",
        (
            "sliding = \"reciprocating\"",
            "body2 = { beta = 2e-8, a = 1.0, b = 1.0 }\nsliding = \"reciprocating\"",
        ),
    );
}

/// Archard's law keeps a balance that holds whatever the pressure is: with b = a = 1, body 1
/// wearing alone and the plate carrying F, every half period removes the area
/// β̃ · 2u₀ · F / t from the punch, so the worn area after H half periods is H times that.
/// Every recorded shape of every scheme must meet it, at '+' steps (mid-cycle) as at '−'
/// ones. (BDF2 once wrote its mid-cycle working shape, (4 g_n − g_v)/3 + (2/3) k ΔW⁺, whose
/// area is k/3 half periods ahead: 11 % at step 3; review of 2026-11-24.)
#[test]
fn every_recorded_shape_holds_the_worn_area_of_its_half_periods() {
    let text = wearfem::examples::example("punch-a")
        .unwrap()
        .replace("shape_zero_at = 1100.0", "");
    let list: Vec<String> = (1..=200).map(|s| s.to_string()).collect();
    let record = format!("record = [{}]", list.join(", "));
    // F = 16.666 MPa on the 60 mm top edge, t = 10 mm (the problem's input).
    let (force, thickness) = (16.666 * 60.0 * 10.0, 10.0);
    for extra in [
        "",
        "adaptive = { method = \"bdf2\" }",
        "adaptive = { method = \"step_doubling\" }",
    ] {
        let text = text.replace(RECORD, &format!("{record}\n{extra}"));
        let problem = Problem::from_toml(&text, "punch-a, no shift").unwrap();
        let wear = problem.spec.wear.as_ref().unwrap();
        let per_half_period =
            wear.body1.as_ref().unwrap().beta * 2.0 * wear.amplitude * force / thickness;
        let run = driver::wear(&problem, Some(200), |_| {}).unwrap();
        let points = &run.contact.points;
        let h = &run.history;
        assert!(
            h.snapshots.len() > 100,
            "{extra}: {} snapshots",
            h.snapshots.len()
        );
        for s in &h.snapshots {
            let area: f64 = (0..points.x.len())
                .map(|i| points.weight[i] * (s.shape[i] - points.initial_gap[i]))
                .sum();
            let expected = s.half_period as f64 * per_half_period;
            // Round-off of a 65-term weighted sum: 1e-12 relative (measured 1e-15).
            assert!(
                (area / expected - 1.0).abs() < 1e-12,
                "{extra}: step {} ({}) after {} half periods: area {area:.6e}, expected {expected:.6e}",
                s.step,
                s.direction,
                s.half_period
            );
        }
    }
}

#[test]
fn a_growing_worn_flat_is_not_taken_for_the_steady_state() {
    // Red team 22, F2 (tests/problems/cylinder-wears-its-flat.toml): between two contact points
    // joining the flat the wear is rigid and the pressures settle geometrically, which the
    // stop criterion took for the steady state at 198 % of the peak from it. The rigid wear
    // still closes the gaps beside the zone there, which the criterion now also asks to be
    // nil. Theory for the steady state: the plate only translates (along z), so the wear of a
    // period, ∝ p⁺ + p⁻ (b = 1, both bodies), is the normal component of a translation:
    // p⁺ + p⁻ ∝ cos α on the whole arc (R = 20 mm about (0, 20)).
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/cylinder-wears-its-flat.toml"
    );
    let text = std::fs::read_to_string(path).expect("problem file");
    let problem = Problem::from_toml(&text, path).expect("problem");
    let wear_run = driver::wear(&problem, None, |_| {}).expect("run");
    let h = &wear_run.history;
    assert!(
        matches!(h.stopped, Some((_, StopReason::SteadyState))),
        "{:?}",
        h.stopped
    );
    let ratio: Vec<f64> = wear_run
        .contact
        .points
        .x
        .iter()
        .enumerate()
        .map(|(i, x)| (h.p_plus[i] + h.p_minus[i]) / (1.0 - (x[0] / 20.0).powi(2)).sqrt())
        .collect();
    let (lo, hi) = ratio
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    // The adaptive stop's tolerance is 1e-3 of the peak per remaining change; 1 % leaves room
    // and fails on any partial zone (there p⁺ + p⁻ = 0 at the points not yet worn flat).
    assert!(hi - lo < 0.01 * hi, "p_sum / cos(alpha) from {lo} to {hi}");
}
