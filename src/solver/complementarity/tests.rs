use super::*;
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
