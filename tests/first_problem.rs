//! docs/first-problem.md's part, run as the page runs it: what the page says must stay true.

use wearfem::driver;
use wearfem::problem::Problem;

fn problem(set: &[&str]) -> Problem {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/first-problem/pad-on-disc.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let overrides: Vec<_> = set
        .iter()
        .map(|s| wearfem::overrides::Override::parse(s).unwrap())
        .collect();
    Problem::with_overrides(&text, path, &overrides).unwrap()
}

fn middle(summary: &serde_json::Value) -> f64 {
    summary["probes"]["middle"].as_f64().unwrap()
}

#[test]
fn the_contact_is_clean_and_converged_in_p() {
    // No warnings; raising p from 8 to 10 moves the middle pressure by 1e-5 relative (the page
    // says 1.90990 against 1.90992; 1e-4 leaves room).
    let (summary, ..) = driver::contact(&problem(&[])).unwrap();
    assert_eq!(
        summary["warnings"].as_array().unwrap().len(),
        0,
        "{}",
        summary["warnings"]
    );
    let (raised, ..) = driver::contact(&problem(&["analysis.p=10"])).unwrap();
    let (a, b) = (middle(&summary), middle(&raised));
    assert!((a - 1.9099).abs() < 1e-3, "{a}");
    assert!((a - b).abs() < 1e-4 * a, "{a} vs {b}");
}

#[test]
fn the_pad_wears_evenly_by_archards_law() {
    // At the steady state the pad wears evenly at β̃ p̄ per mm (p̄ the mean of p⁺ and p⁻):
    // 5e-8 × 2.17 MPa × 90 000 mm = 9.76 µm; the run's early, uneven cycles wore a little
    // less in the middle (9.73 µm). 1 % covers that transient, and nothing else.
    let problem = problem(&[]);
    let run = driver::wear(&problem, None, |_| {}).unwrap();
    assert!(
        run.warnings(&problem).is_empty(),
        "{:?}",
        run.warnings(&problem)
    );
    assert!(run.steady_check.reached(&run.history));
    let h = &run.history;
    let i = h.body_wear[0].len() / 2;
    let mean = 0.5 * (h.p_plus[i] + h.p_minus[i]);
    let hand = 5.0e-8 * mean * 90_000.0;
    let ours = h.body_wear[0][i];
    assert!(
        (ours / hand - 1.0).abs() < 0.01,
        "{ours} mm vs {hand} mm by hand"
    );
    // The three record distances and the end, as the page lists them.
    let metres: Vec<f64> = h
        .snapshots
        .iter()
        .map(|s| s.half_period as f64 * 3.0 / 1000.0)
        .collect();
    assert_eq!(metres.len(), 3);
    for (m, e) in metres.iter().zip([1.5, 15.0, 45.0]) {
        assert!((m - e).abs() < 1e-9);
    }
}
