//! Frictional contact against theory: equilibrium, complementarity, Hertz's line contact, the
//! symmetric frictionless flat punch, the friction-induced shift and the penalty limit.

use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::overrides::Override;
use wearfem::problem::Problem;

fn example(name: &str) -> Problem {
    Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap()
}

fn with_friction(name: &str, mu: f64) -> Problem {
    let text = wearfem::examples::example(name)
        .unwrap()
        .replace("friction = 0.25", &format!("friction = {mu}"));
    Problem::from_toml(&text, name).unwrap()
}

#[test]
fn example_1_balances_the_load_and_is_complementary() {
    for name in ["punch-a", "punch-b20", "punch-b40"] {
        let (contact, _, _) = CondensedContact::build(&example(name)).unwrap();
        assert_eq!(contact.len(), 65, "reference model: 65 Lobatto points");
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        for dir in [Direction::Plus, Direction::Minus] {
            let (sol, info) = solver.solve(&contact.points.initial_gap, dir);
            assert_eq!(info.status, Status::Solved);
            // The bounds: 1e-10 relative (the reduced system is solved directly).
            assert!(
                info.equilibrium < 1e-10,
                "{name}: equilibrium {:.2e}",
                info.equilibrium
            );
            assert!(
                info.complementarity < 1e-10,
                "{name}: complementarity {:.2e}",
                info.complementarity
            );
            // Vertical equilibrium by hand: Σ P_i = F0 = 16.666 MPa × 60 mm × 10 mm.
            let total: f64 = sol.force.iter().sum();
            assert!(
                (total - 9999.6).abs() < 1e-8 * 9999.6,
                "{name}: ΣP = {total}"
            );
            assert!(sol.pressure.iter().all(|&p| p >= -1e-10 * 100.0));
        }
    }
}

#[test]
fn friction_moment_shifts_the_pressure_centre_by_mu_lz() {
    // Moment equilibrium about the pin (paper eq. 8): Σ (x − 1100) P = −s μ l_z F0, so the
    // pressure centre lies at 1100 ∓ μ l_z — towards M (x = 1070) in the '+' half cycle, the
    // direction of Figure 4.
    for (name, lz) in [("punch-b20", 20.0), ("punch-b40", 40.0)] {
        let (contact, _, _) = CondensedContact::build(&example(name)).unwrap();
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        for dir in [Direction::Plus, Direction::Minus] {
            let (sol, _) = solver.solve(&contact.points.initial_gap, dir);
            let total: f64 = sol.force.iter().sum();
            let centre: f64 = contact
                .points
                .x
                .iter()
                .zip(&sol.force)
                .map(|(x, f)| x[0] * f)
                .sum::<f64>()
                / total;
            let expected = 1100.0 - dir.sign() * 0.25 * lz;
            assert!(
                (centre - expected).abs() < 1e-9 * 1100.0,
                "{name} {dir:?}: centre {centre}, expected {expected}"
            );
            let (left, right) = (sol.pressure[0], sol.pressure[contact.len() - 1]);
            assert_eq!(
                left > right,
                dir == Direction::Plus,
                "{name} {dir:?}: edge pressures {left} / {right}"
            );
        }
    }
}

#[test]
fn frictionless_flat_punch_is_symmetric_with_edge_maxima() {
    let (contact, _, _) = CondensedContact::build(&with_friction("punch-a", 0.0)).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let (sol, _) = solver.solve(&contact.points.initial_gap, Direction::Plus);
    let n = contact.len();
    let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
    for i in 0..n {
        // The mesh and load are symmetric about x = 1100: only round-off breaks symmetry.
        assert!(
            (sol.pressure[i] - sol.pressure[n - 1 - i]).abs() < 1e-8 * peak,
            "asymmetry at {i}"
        );
    }
    assert_eq!(
        peak,
        sol.pressure[0].max(sol.pressure[n - 1]),
        "maximum not at an edge"
    );
    let mid = sol.pressure[n / 2];
    assert!(
        sol.pressure[0] > 2.0 * mid,
        "edge {} vs centre {mid}: no edge concentration",
        sol.pressure[0]
    );
}

#[test]
fn penalty_solution_tends_to_the_exact_one() {
    let problem = example("punch-b40");
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let exact = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus)
        .0;
    let peak = exact.pressure.iter().cloned().fold(0.0, f64::max);
    let mut previous = f64::INFINITY;
    for c in [1e4, 1e5, 1e6, 1e7, 1e8] {
        let (sol, info) = ContactSolver::new(&contact, Method::Penalty { stiffness: c })
            .solve(&contact.points.initial_gap, Direction::Plus);
        assert_eq!(info.status, Status::Solved);
        let error = sol
            .pressure
            .iter()
            .zip(&exact.pressure)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / peak;
        assert!(
            error < previous,
            "c_n = {c:e}: error {error:.3e} did not fall (previous {previous:.3e})"
        );
        previous = error;
    }
    // Penetration p/c_n vanishes like 1/c_n: at 1e8 MPa/mm the pressures agree to ~1e-3.
    assert!(
        previous < 1e-2,
        "penalty error at c_n = 1e8: {previous:.3e}"
    );
}

#[test]
fn lemke_and_active_set_agree() {
    let problem = example("punch-b40");
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let a = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    let l = ContactSolver::new(&contact, Method::Lemke)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(l.1.status, Status::Solved);
    let peak = a.0.pressure.iter().cloned().fold(0.0, f64::max);
    for (x, y) in a.0.pressure.iter().zip(&l.0.pressure) {
        // Both solve the same LCP exactly; the difference is round-off of two pivot sequences.
        assert!((x - y).abs() < 1e-8 * peak);
    }
}

#[test]
fn hertz_line_contact() {
    for kind in ["plane_strain", "plane_stress"] {
        // The built-in example `hertz` (plane strain) in either idealisation.
        let kind_set = Override::parse(&format!("analysis.kind={kind}")).unwrap();
        let text = wearfem::examples::example("hertz").unwrap();
        let problem = Problem::with_overrides(text, "hertz", &[kind_set]).unwrap();
        let (contact, _, _) = CondensedContact::build(&problem).unwrap();
        let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        assert_eq!(info.status, Status::Solved);
        let force_per_length = 38.825 * 40.0; // N/mm (thickness 1 mm)
        let (e, nu) = (2.0e5f64, 0.3f64);
        let e_one = if kind == "plane_strain" {
            e / (1.0 - nu * nu)
        } else {
            e
        };
        let e_star = e_one / 2.0; // two equal bodies: 1/E* = 2/E'
        let radius = 500.0;
        let a = (4.0 * force_per_length * radius / (std::f64::consts::PI * e_star)).sqrt();
        let p0 = 2.0 * force_per_length / (std::f64::consts::PI * a);
        let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
        let a_fit = wearfem::validate::hertz_half_width(&contact, &sol);
        // 2 %: the bound; the finite bodies (contact 2a ≈ 6 mm against 40 and 100 mm)
        // stiffen the response by well under that.
        assert!(
            (peak - p0).abs() < 0.02 * p0,
            "{kind}: peak {peak:.3} MPa, Hertz {p0:.3} MPa"
        );
        assert!(
            (a_fit - a).abs() < 0.02 * a,
            "{kind}: half-width {a_fit:.4} mm, Hertz {a:.4} mm"
        );
    }
}

#[test]
fn loads_on_body_1_outside_the_plate_enter_the_plate_equilibrium() {
    // 2 MPa on the punch's left side (x = 1070, 100 ≤ z ≤ 120) pushes it by F_x = 400 N at
    // z = 110, a moment of (110 − 140)·400 = −12 000 N·mm about the pin. Moment equilibrium
    // (eq. 8) then puts the pressure centre at 1100 − μ l_z + M/F0.
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace("names = { bottom = \"contact\" }", "names = { bottom = \"contact\", left = \"side\" }")
        .replace("[[bodies.tractions]]\nedge = \"top\"", "[[bodies.tractions]]\nedge = \"side\"\nnormal = 2.0\n\n[[bodies.tractions]]\nedge = \"top\"");
    let problem = Problem::from_toml(&text, "side-load").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(info.status, Status::Solved);
    let total: f64 = sol.force.iter().sum();
    assert!(
        (total - 9999.6).abs() < 1e-8 * 9999.6,
        "ΣP = {total}: a horizontal load must not change it"
    );
    let centre: f64 = contact
        .points
        .x
        .iter()
        .zip(&sol.force)
        .map(|(x, f)| x[0] * f)
        .sum::<f64>()
        / total;
    let expected = 1100.0 - 0.25 * 40.0 - 12_000.0 / 9999.6;
    assert!(
        (centre - expected).abs() < 1e-9 * 1100.0,
        "centre {centre}, expected {expected}"
    );
}

#[test]
fn no_solution_is_reported_as_failed_not_solved() {
    // A plate on a pin 40 mm above the contact: the friction moment μ F l_z moves the pressure
    // resultant by μ l_z from the load line (x = 1100), and the punch is 30 mm either side. At
    // μ = 0.7 (28 mm) the punch still balances on its edge region; at μ = 0.8 (32 mm) no
    // contact pressure ≥ 0 can balance the moment, so any "solution" would be wrong and the
    // solver must say that it failed (whichever method ends, Lemke included).
    for (mu, exists) in [(0.7, true), (0.8, false)] {
        let contact = CondensedContact::build(&with_friction("punch-b40", mu))
            .unwrap()
            .0;
        for method in [Method::ActiveSet, Method::Lemke] {
            let (sol, info) = ContactSolver::new(&contact, method)
                .solve(&contact.points.initial_gap, Direction::Plus);
            let solved = info.status == Status::Solved;
            assert_eq!(solved, exists, "μ = {mu}, {method:?}: {info:?}");
            if solved {
                assert!(info.complementarity < 1e-10 && info.equilibrium < 1e-10);
            }
            assert!(sol.pressure.iter().all(|p| p.is_finite()));
        }
    }
}

/// Body 1 below body 2, pressed up into it (punch-b40 turned upside down, z → 200 − z; a
/// red-team case the plate's translation once refused as "not pressing onto body 2"). By
/// symmetry its '+' half cycle is the original's '−' one (the tangent turns with the normal),
/// which for punch-b40 is the '+' profile mirrored in x: the first contact solve must be the
/// original's reversed, the plate's unknowns the same, and the steady p⁺ the original p⁻.
#[test]
fn a_punch_pressed_up_into_its_partner_is_the_mirror_image() {
    let text = include_str!("problems/punch-b40-upside-down.toml");
    let upside_down = Problem::from_toml(text, "punch-b40-upside-down.toml").unwrap();
    let original = Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap();
    let (_, _, up, up_info) = wearfem::driver::contact(&upside_down).unwrap();
    let (_, _, down, _) = wearfem::driver::contact(&original).unwrap();
    assert_eq!(up_info.status, Status::Solved);
    let peak = down.pressure.iter().cloned().fold(0.0, f64::max);
    let mirrored: Vec<f64> = down.pressure.iter().rev().copied().collect();
    // Round-off of two solves of the same linear system, assembled in other orders.
    let worst = up
        .pressure
        .iter()
        .zip(&mirrored)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(worst < 1e-9 * peak, "first solve differs by {worst} MPa");
    for (a, b) in up.rigid.iter().zip(&down.rigid) {
        assert!(
            (a - b).abs() < 1e-9 * b.abs(),
            "plate unknowns {:?} against {:?}",
            up.rigid,
            down.rigid
        );
    }
    let (up_steady, _, _) = wearfem::driver::steady(&upside_down).unwrap();
    let (down_steady, _, _) = wearfem::driver::steady(&original).unwrap();
    // The '−' half cycle of the original, point for point (not mirrored).
    let worst = up_steady
        .p_plus
        .iter()
        .zip(&down_steady.p_minus)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(worst < 1e-9 * peak, "steady p⁺ differs by {worst} MPa");
}
