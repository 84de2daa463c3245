//! Worn shapes that once broke a contact solve, kept as fixed cases beside the property
//! tests that found them (`tests/contact_properties.rs` draws new ones on every run).

use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// Example 1 (punch-b40, μ = 0.25) worn by the sines of `tests/contact_properties.rs`.
fn worn_punch(coefficients: &[f64]) -> (CondensedContact, Vec<f64>) {
    let text = wearfem::examples::example("punch-b40").unwrap();
    let problem = Problem::from_toml(text, "punch-b40").unwrap();
    let contact = CondensedContact::build(&problem).unwrap().0;
    let gap = contact
        .points
        .x
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(x, g)| {
            let s = (x[0] - 1070.0) / 60.0;
            let wave: f64 = coefficients
                .iter()
                .enumerate()
                .map(|(k, c)| c * (std::f64::consts::PI * (k + 1) as f64 * s).sin())
                .sum();
            g + 0.02 * wave
        })
        .collect();
    (contact, gap)
}

/// Found by CI on 2026-11-24: two separate contact patches under '−' sliding. Lemke's path
/// reached the solution (z₀ at 3e-14 of its start) on pivot 34, did not let z₀ leave since
/// its ratio was not within round-off of the smallest, and went on to a secondary ray after
/// 63 pivots. Lemke's method is the active set's fallback, so this is a solve that would
/// have been reported as failed although it has a solution.
#[test]
fn lemke_stops_where_the_path_reaches_the_solution() {
    let (contact, gap) = worn_punch(&[
        -0.5091722310644814,
        -0.5044690544564343,
        -0.46569135519606025,
        0.22994166239730013,
    ]);
    let (exact, info) =
        ContactSolver::new(&contact, Method::ActiveSet).solve(&gap, Direction::Minus);
    assert_eq!(info.status, Status::Solved);
    let (lemke, lemke_info) =
        ContactSolver::new(&contact, Method::Lemke).solve(&gap, Direction::Minus);
    assert_eq!(lemke_info.status, Status::Solved, "{lemke_info:?}");
    // Both are checked against the complementarity residual 1e-10 by the solver itself;
    // two solutions of one LCP with a unique solution agree to that round-off.
    let peak = exact.pressure.iter().cloned().fold(0.0, f64::max);
    for (a, b) in exact.pressure.iter().zip(&lemke.pressure) {
        assert!((a - b).abs() < 1e-8 * peak, "{a} vs {b}");
    }
    // Two patches: the case is the one CI drew, not a single-zone one.
    let patches = exact
        .pressure
        .windows(2)
        .filter(|w| w[0] == 0.0 && w[1] > 0.0)
        .count();
    assert_eq!(patches, 2);
}
