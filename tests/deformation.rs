//! The displacement fields recovered from a contact solution (src/report/deformation.rs) are the
//! fields the condensation reduced: their normal displacements at the contact points, with the
//! undeformed gap, must give the solver's gap d = A_s P + R λ + g, and the plate's rigid modes
//! rebuilt from two points must be the modes at every contact point.

mod common;
use common::problem;
use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::deformation::{contact_fields, gap_of_fields, plate_motion};
use wearfem::problem::Problem;

/// Solve `p` from `gap` in `direction`; compare the gap the fields reproduce (from the
/// undeformed gap `geometric`) with the solution's.
fn check_gap(p: &Problem, geometric: &[f64], wear: &[f64], direction: Direction) {
    let (contact, body1, body2) = CondensedContact::build(p).unwrap();
    let gap: Vec<f64> = contact
        .points
        .initial_gap
        .iter()
        .zip(wear)
        .map(|(g, w)| g + w)
        .collect();
    let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet).solve(&gap, direction);
    assert_eq!(info.status, Status::Solved);
    let fields = contact_fields(p, (&body1, &body2), &contact, &sol, direction).unwrap();
    let undeformed: Vec<f64> = geometric.iter().zip(wear).map(|(g, w)| g + w).collect();
    let reproduced = gap_of_fields((&body1, &body2), &fields, &contact, &undeformed).unwrap();
    // Both are the same linear map of the same forces (flexibility columns versus one solve
    // with all forces), so they agree to round-off of the displacements (~1e-2 mm here).
    let worst = reproduced
        .iter()
        .zip(&sol.gap)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 1e-9,
        "{}: gap of the fields differs from the solution's by {worst:.3e} mm",
        p.file
    );
    // Not a trivial agreement: the bodies really move by much more than that.
    let largest = contact
        .points
        .x
        .iter()
        .map(|&x| {
            let u = fields[0].values_at(&body1, x).unwrap().displacement;
            u[0].hypot(u[1])
        })
        .fold(0.0, f64::max);
    assert!(largest > 1e-3, "punch displacement {largest} mm");
}

#[test]
fn fields_reproduce_the_gap_of_the_pinned_punch_in_both_directions() {
    let p = problem("punch-b40", &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    // No loads on the bodies but the plate's: the initial gap is the undeformed one.
    let geometric = contact.points.initial_gap.clone();
    let none = vec![0.0; contact.len()];
    // A worn shape that lifts the punch's right half off (parabola, 20 µm at the ends).
    let worn: Vec<f64> = contact
        .points
        .x
        .iter()
        .map(|x| 2e-2 * ((x[0] - 1085.0) / 45.0).powi(2))
        .collect();
    for direction in [Direction::Plus, Direction::Minus] {
        check_gap(&p, &geometric, &none, direction);
        check_gap(&p, &geometric, &worn, direction);
    }
}

#[test]
fn fields_include_the_bodies_own_loads() {
    // 2 MPa on the punch's left side and 5 MPa on the strip's right side: both move the contact
    // points before any contact force acts. The undeformed gap is that of the same problem
    // without these loads.
    let edits = [
        ("names = { bottom = \"contact\" }", "names = { bottom = \"contact\", left = \"side\" }"),
        ("names = { bottom = \"base\", top = \"surface\" }", "names = { bottom = \"base\", top = \"surface\", right = \"flank\" }"),
        ("[[bodies.tractions]]\nedge = \"top\"", "[[bodies.tractions]]\nedge = \"side\"\nnormal = 2.0\n\n[[bodies.tractions]]\nedge = \"top\""),
        ("[[bodies.supports]]\nedge = \"base\"", "[[bodies.tractions]]\nedge = \"flank\"\nnormal = 5.0\n\n[[bodies.supports]]\nedge = \"base\""),
    ];
    let loaded = problem("punch-b40", &edits);
    let plain = problem("punch-b40", &edits[..2]);
    let (contact, _, _) = CondensedContact::build(&plain).unwrap();
    let (loaded_contact, _, _) = CondensedContact::build(&loaded).unwrap();
    let moved = loaded_contact
        .points
        .initial_gap
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        moved > 1e-4,
        "the own loads must move the contact points ({moved:.2e} mm)"
    );
    let none = vec![0.0; contact.len()];
    check_gap(&loaded, &contact.points.initial_gap, &none, Direction::Plus);
}

#[test]
fn plate_modes_are_rebuilt_at_every_contact_point() {
    for name in ["punch-b40", "punch-a", "brake"] {
        let p = problem(name, &[]);
        let (contact, _, _) = CondensedContact::build(&p).unwrap();
        for (k, phi) in contact.rigid_modes.iter().enumerate() {
            let mut unit = vec![0.0; contact.rigid_modes.len()];
            unit[k] = 1.0;
            let motion = plate_motion(&contact, &unit);
            for (x, f) in contact.points.x.iter().zip(phi) {
                let u = motion.at(*x);
                assert!(
                    (u[0] - f[0]).abs() < 1e-9 && (u[1] - f[1]).abs() < 1e-9,
                    "{name} mode {k} at {x:?}: {u:?} vs {f:?}"
                );
            }
        }
    }
}

/// Mortar contact on a strip meshed independently of the punch (40 even elements of 5 mm
/// under the punch's 7.5 mm ones): body 2 takes the contact forces through its mortar traces.
/// Its fields then reproduce the solver's gap in the mortar constraints, and its surface
/// stress balances the contact pressure, σ_zz = −p (traction continuity, Cauchy), inside the
/// zone away from the punch's corners (whose singular stresses no mesh resolves at a point).
/// Until 2026-11-29 body 2 was loaded by point forces at the partner points, which on such a
/// mesh are loads inside its elements: σ_zz reached several times the pressure (red team C).
#[test]
fn body_2_on_an_independent_mesh_balances_the_contact_pressure() {
    let strip =
        "u = [0.0, 0.2, 0.35, 0.3875, 0.425, 0.4625, 0.5, 0.5375, 0.575, 0.6125, 0.65, 0.8, 1.0]";
    let p = problem(
        "punch-b40",
        &[
            (strip, "u = 40"),
            (
                "discretisation = \"collocation\"",
                "discretisation = \"mortar\"\nalign_target_mesh = false",
            ),
        ],
    );
    let (contact, body1, body2) = CondensedContact::build(&p).unwrap();
    let gap = contact.points.initial_gap.clone();
    for direction in [Direction::Plus, Direction::Minus] {
        check_gap(&p, &gap, &vec![0.0; contact.len()], direction);
        let (sol, _) = ContactSolver::new(&contact, Method::ActiveSet).solve(&gap, direction);
        let fields = contact_fields(&p, (&body1, &body2), &contact, &sol, direction).unwrap();
        let areas = contact.areas();
        let pressure: Vec<f64> = sol.force.iter().zip(&areas).map(|(f, a)| f / a).collect();
        let peak = pressure.iter().cloned().fold(0.0, f64::max);
        let mut worst: f64 = 0.0;
        for (i, x) in contact.points.x.iter().enumerate() {
            if (1080.0..=1120.0).contains(&x[0]) {
                let below = [x[0], x[1] - 1e-9];
                let stress = fields[1].values_at(&body2, below).unwrap().stress;
                worst = worst.max((stress[1] + pressure[i]).abs());
            }
        }
        // 1 % of the peak: matched meshes give 0.1–0.2 % (body 1 here too); the point forces
        // of before gave more than 100 %.
        assert!(
            worst < 0.01 * peak,
            "{direction:?}: |σ_zz + p| up to {worst:.3} MPa of {peak:.1}"
        );
    }
}
