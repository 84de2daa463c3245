use super::*;
use crate::capacitance::Capacitance;
use crate::problem::Problem;

#[test]
fn the_low_rank_route_equals_the_reduced_systems_own_factorisation() {
    // punch-b40 with its two ends lifted by a smooth gap, so that a few points (but under
    // a third) leave contact: the corrected all-active factorisation and the reduced
    // system's own factorisation solve the same equations, so they agree to round-off
    // (1e-9 of the peak leaves the flexibility's condition number, about 1e5, room).
    let problem =
        Problem::from_toml(crate::examples::example("punch-b40").unwrap(), "b40").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let gap: Vec<f64> = contact
        .points
        .x
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(x, g)| g + 2e-3 * ((x[0] - 1100.0) / 30.0).powi(8))
        .collect();
    let mut routes = Vec::new();
    for correct in [true, false] {
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        solver.correct = correct;
        for direction in [Direction::Plus, Direction::Minus] {
            let (solution, info) = solver.solve(&gap, direction);
            assert_eq!(info.status, Status::Solved);
            routes.push(solution);
        }
    }
    let out = routes[0].active.iter().filter(|a| !**a).count();
    assert!(
        out > 0 && Capacitance::applies(out, contact.len()),
        "{out} points out of contact: the case must use the correction"
    );
    for (corrected, direct) in routes[..2].iter().zip(&routes[2..]) {
        assert_eq!(corrected.active, direct.active);
        let peak = direct.pressure.iter().fold(0.0f64, |a, p| a.max(p.abs()));
        for (a, b) in corrected.pressure.iter().zip(&direct.pressure) {
            assert!((a - b).abs() < 1e-9 * peak, "{a} vs {b}");
        }
    }
}

#[test]
fn bounded_check_gives_the_same_pressures_and_a_bound_above_the_full_check() {
    // punch-b40 flat (every point in contact: the all-active factorisation) and with its
    // ends lifted (a few points out: the capacitance correction): the solve without the gap
    // pass returns the same pressures bit for bit; its complementarity is a bound, at least
    // the full check's and still far below the accepted residual; the gaps it reports are
    // zero in contact and within that bound of the full pass's elsewhere.
    let problem =
        Problem::from_toml(crate::examples::example("punch-b40").unwrap(), "b40").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let lifted: Vec<f64> = contact
        .points
        .x
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(x, g)| g + 2e-3 * ((x[0] - 1100.0) / 30.0).powi(8))
        .collect();
    // Ends pressed harder: every point in contact.
    let pressed: Vec<f64> = contact
        .points
        .x
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(x, g)| g - 2e-3 * ((x[0] - 1100.0) / 30.0).powi(2))
        .collect();
    for (gap, route) in [(&pressed, Route::Full), (&lifted, Route::Corrected)] {
        let mut full = ContactSolver::new(&contact, Method::ActiveSet);
        let mut bounded = ContactSolver::new(&contact, Method::ActiveSet);
        // A wear compliance as in a step, then back to none: both factorisations in use.
        let compliance: Vec<f64> = contact.areas().iter().map(|a| 1e-4 / a).collect();
        for c in [&compliance, &vec![0.0; contact.len()]] {
            full.set_compliance(c);
            bounded.set_compliance(c);
            for direction in [Direction::Plus, Direction::Minus] {
                let (want, info) = full.solve(gap, direction);
                let mut got = ContactSolution::default();
                let checked = bounded.solve_pressures_into(gap, direction, &mut got);
                assert_eq!(bounded.route, route, "{:?}", got.active);
                assert_eq!(info.status, Status::Solved);
                assert_eq!(checked.status, Status::Solved);
                assert_eq!(got.pressure, want.pressure);
                assert_eq!(got.rigid, want.rigid);
                assert!(checked.complementarity >= info.complementarity);
                assert!(checked.complementarity < 1e-3 * ACCEPTED_RESIDUAL);
                for i in 0..contact.len() {
                    if got.active[i] {
                        assert_eq!(got.gap[i], 0.0);
                    } else {
                        assert!((got.gap[i] - want.gap[i]).abs() <= bounded.bound[i]);
                    }
                }
            }
        }
    }
}
