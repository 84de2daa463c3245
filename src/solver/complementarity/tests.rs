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

#[test]
fn a_growing_zone_is_solved_with_a_padded_factorisation_as_with_its_own() {
    // The pin's cap with its centre worn flatter solve by solve: the zone grows by a few
    // points at a time, most of the cap out of contact. The padded route solves the same
    // reduced systems as the exact one, so both agree to round-off (1e-9 of the peak, as
    // above), and it refactorises less often than the set changes.
    let problem = Problem::from_toml(crate::examples::example("pin").unwrap(), "pin").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let mut padded = ContactSolver::new(&contact, Method::ActiveSet);
    let mut exact = ContactSolver::new(&contact, Method::ActiveSet);
    exact.correct = false;
    let (mut padded_factorisations, mut exact_factorisations, mut routes) = (0, 0, Vec::new());
    for step in 0..12 {
        // Wear opens the gap at the centre, by up to 0.4 µm more per solve inside |x| < 3 mm.
        let depth = 4e-4 * step as f64;
        let gap: Vec<f64> = contact
            .points
            .x
            .iter()
            .zip(&contact.points.initial_gap)
            .map(|(x, g)| g + depth * (1.0 - (x[0] / 3.0).powi(2)).max(0.0))
            .collect();
        let (want, want_info) = exact.solve(&gap, Direction::Plus);
        let mut got = ContactSolution::default();
        let info = padded.solve_pressures_into(&gap, Direction::Plus, &mut got);
        assert_eq!(
            (info.status, want_info.status),
            (Status::Solved, Status::Solved)
        );
        assert_eq!(got.active, want.active, "solve {step}");
        let peak = want.pressure.iter().fold(0.0f64, |a, p| a.max(p.abs()));
        for (a, b) in got.pressure.iter().zip(&want.pressure) {
            assert!((a - b).abs() < 1e-9 * peak, "solve {step}: {a} vs {b}");
        }
        padded_factorisations += info.factorisations;
        exact_factorisations += want_info.factorisations;
        routes.push(padded.route);
        let out = got.active.iter().filter(|a| !**a).count();
        assert!(
            !Capacitance::applies(out, contact.len()),
            "most of the cap is out"
        );
    }
    assert!(routes.contains(&Route::Padded), "{routes:?}");
    assert!(
        padded_factorisations < exact_factorisations,
        "{padded_factorisations} vs {exact_factorisations}"
    );
}
