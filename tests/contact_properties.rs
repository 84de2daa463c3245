//! Property tests of the contact solve on Example 1 (punch-b40): for random worn shapes the
//! solution must satisfy the complementarity conditions and the plate equilibrium it claims,
//! the warm-started active-set method must agree with Lemke's method from scratch, and the
//! pressures must not depend on the history of earlier solves. Cases the properties found
//! are kept as fixed tests at the end (and in `contact_properties.proptest-regressions`).

use proptest::prelude::*;
use std::sync::OnceLock;
use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// The condensed contact problem, built once (about 25 ms) for all cases.
fn contact() -> &'static CondensedContact {
    static CONTACT: OnceLock<CondensedContact> = OnceLock::new();
    CONTACT.get_or_init(|| {
        let text = wearfem::examples::example("punch-b40").unwrap();
        let problem = Problem::from_toml(text, "punch-b40").unwrap();
        CondensedContact::build(&problem).unwrap().0
    })
}

/// A worn shape: a smooth random profile (a few sines, amplitude up to 20 µm, which is of the
/// order of the elastic approach under the 10 kN load) plus a random tilt, added to the gap.
fn shape(contact: &CondensedContact, coefficients: &[f64], tilt: f64) -> Vec<f64> {
    contact
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
            g + 0.02 * wave + tilt * (s - 0.5)
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_worn_shapes_are_solved_exactly(
        coefficients in prop::collection::vec(-1.0f64..1.0, 4),
        tilt in -0.01f64..0.01,
        plus in any::<bool>(),
    ) {
        let contact = contact();
        let gap = shape(contact, &coefficients, tilt);
        let direction = if plus { Direction::Plus } else { Direction::Minus };
        let (exact, info) = ContactSolver::new(contact, Method::ActiveSet).solve(&gap, direction);
        prop_assert_eq!(info.status, Status::Solved);
        // The claimed residuals (1e-10: round-off of a 66 × 66 solve is ~1e-13).
        prop_assert!(info.complementarity < 1e-10 && info.equilibrium < 1e-10, "{:?}", info);
        // And independently of them: p ≥ 0, d ≥ 0 and p d = 0 point by point, with d in mm
        // and p in MPa scaled by the largest of each (round-off bounds again).
        let peak = exact.pressure.iter().cloned().fold(0.0, f64::max);
        // The gaps' scale is that of the worn shape, not of the solution's gaps: with every
        // point in contact those are all round-off (1e-17 mm), and a case proptest found
        // then failed d ≥ −1e-10 max|d| on round-off alone. 1 µm is a floor for a shape
        // that is nearly flat (the elastic approach under the load is about 10 µm).
        let span = exact
            .gap
            .iter()
            .chain(&gap)
            .fold(1e-3f64, |a, d| a.max(d.abs()));
        for (p, d) in exact.pressure.iter().zip(&exact.gap) {
            prop_assert!(*p >= -1e-10 * peak);
            prop_assert!(*d >= -1e-10 * span);
            prop_assert!((p / peak).min(d / span).abs() < 1e-9);
        }
        // Vertical balance, from the problem file rather than the solver's own load vector:
        // punch-b40 presses with 16.666 MPa on its 60 mm × 10 mm top. A flat contact takes it
        // all in normal forces (friction is horizontal there).
        let total: f64 = exact.force.iter().sum();
        prop_assert!((total - 16.666 * 600.0).abs() < 1e-9 * total, "Σ P = {}", total);
        // Lemke's method from scratch solves the same LCP.
        let (lemke, lemke_info) = ContactSolver::new(contact, Method::Lemke).solve(&gap, direction);
        prop_assert_eq!(lemke_info.status, Status::Solved);
        for (a, b) in exact.pressure.iter().zip(&lemke.pressure) {
            prop_assert!((a - b).abs() < 1e-8 * peak, "{} vs {}", a, b);
        }
    }

    #[test]
    fn warm_starts_do_not_change_the_solution(
        first in prop::collection::vec(-1.0f64..1.0, 4),
        second in prop::collection::vec(-1.0f64..1.0, 4),
    ) {
        // Solving shape A then shape B with one solver (warm start from A's active set and its
        // cached factorisation) must give B's pressures exactly as a fresh solver does.
        let contact = contact();
        let (a, b) = (shape(contact, &first, 0.0), shape(contact, &second, 0.0));
        let mut warm = ContactSolver::new(contact, Method::ActiveSet);
        warm.solve(&a, Direction::Plus);
        let (reused, _) = warm.solve(&b, Direction::Plus);
        let (fresh, _) = ContactSolver::new(contact, Method::ActiveSet).solve(&b, Direction::Plus);
        let peak = fresh.pressure.iter().cloned().fold(0.0, f64::max);
        for (x, y) in reused.pressure.iter().zip(&fresh.pressure) {
            prop_assert!((x - y).abs() < 1e-10 * peak);
        }
    }
}

/// Found by CI on 2026-11-24: two separate contact patches under '−' sliding. Lemke's path
/// reached the solution (z₀ at 3e-14 of its start) on pivot 34, did not let z₀ leave since
/// its ratio was not within round-off of the smallest, and went on to a secondary ray after
/// 63 pivots. Lemke's method is the active set's fallback, so this is a solve that would
/// have been reported as failed although it has a solution.
#[test]
fn lemke_stops_where_the_path_reaches_the_solution() {
    let contact = contact();
    let coefficients = [
        -0.5091722310644814,
        -0.5044690544564343,
        -0.46569135519606025,
        0.22994166239730013,
    ];
    let gap = shape(contact, &coefficients, 0.0);
    let (exact, info) =
        ContactSolver::new(contact, Method::ActiveSet).solve(&gap, Direction::Minus);
    assert_eq!(info.status, Status::Solved);
    let (lemke, lemke_info) =
        ContactSolver::new(contact, Method::Lemke).solve(&gap, Direction::Minus);
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
