//! Helpers shared by the integration tests: run a built-in example (optionally edited).

#![allow(dead_code)]

use wearfem::driver::{self, WearRun};
use wearfem::problem::Problem;

/// Parse built-in example `name` after replacing each (from, to) pair in its text.
pub fn problem(name: &str, edits: &[(&str, &str)]) -> Problem {
    let mut text = wearfem::examples::example(name)
        .expect("built-in example")
        .to_string();
    for (from, to) in edits {
        assert!(text.contains(from), "{name}: '{from}' not in the file");
        text = text.replace(from, to);
    }
    Problem::from_toml(&text, name).expect("valid problem")
}

/// Run the wear integration of a problem.
pub fn run(problem: &Problem, steps: Option<usize>) -> WearRun {
    let run = driver::wear(problem, steps, |_| {}).expect("wear run");
    assert_eq!(run.history.failed_solves, 0, "a contact solve failed");
    run
}

/// Pressure at probe M at the last '+' step at or before step n (Table 2 lists the '+' half
/// cycle, in which M, the left edge, is loaded; in '−' half cycles p(M) → 0).
pub fn p_m_plus(run: &WearRun, n: usize) -> f64 {
    let k = run
        .probes
        .iter()
        .position(|(name, _)| name == "M")
        .expect("probe M");
    let step = if n % 2 == 1 { n } else { n - 1 };
    let rec = &run.history.steps[step - 1];
    assert_eq!(rec.direction, "+");
    rec.probes[k]
}
