//! Contact between bodies of revolution (`analysis.kind = "axisymmetric"`, issue 31) against
//! closed forms: Hertz's sphere on a flat and Boussinesq–Sneddon's flat-ended cylindrical
//! punch; and what is refused until the sliding of bodies of revolution is built.

use std::f64::consts::PI;
use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// Solve the first contact of `text`: contact points' r, pressures (MPa), the plate's motion
/// λ_F (mm).
fn solve(text: &str) -> (Vec<f64>, Vec<f64>, f64) {
    let problem = Problem::from_toml(text, "axisymmetric-contact").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let (solution, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(info.status, Status::Solved);
    let r = contact.points.x.iter().map(|x| x[0]).collect();
    (r, solution.pressure, solution.rigid[0])
}

fn fractions(values: &[f64], length: f64) -> String {
    let f: Vec<String> = values
        .iter()
        .map(|v| format!("{:.10}", v / length))
        .collect();
    format!("[{}]", f.join(", "))
}

/// A ball (radius `radius`, as `contact.initial_shape` on the flat end of a cylinder 10 mm
/// across the radius) of material 1 pressed with `force` N on a flat block (20 mm radius and
/// depth) of material 2, frictionless.
fn ball(radius: f64, force: f64, materials: [(f64, f64); 2], p: usize) -> String {
    let ball_r = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.5, 3.0, 6.0, 10.0];
    let flat_r = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.5, 3.0, 6.0, 12.0, 20.0];
    let flat_z = [0.0, 8.0, 14.0, 17.0, 19.0, 19.5, 19.8, 20.0];
    format!(
        r#"title = "a ball on a flat"
[analysis]
kind = "axisymmetric"
p = {p}
[materials.one]
young = {e1}
poisson = {n1}
[materials.two]
young = {e2}
poisson = {n2}
[[bodies]]
name = "ball"
[[bodies.blocks]]
corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
u = {u1}
v = [0.0, 0.02, 0.05, 0.1, 0.3, 1.0]
material = "one"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = {traction}
[[bodies]]
name = "flat"
[[bodies.blocks]]
corners = [[0.0, -20.0], [20.0, -20.0], [20.0, 0.0], [0.0, 0.0]]
u = {u2}
v = {v2}
material = "two"
names = {{ bottom = "base", top = "surface" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[contact]
body = "ball"
edge = "contact"
target_body = "flat"
target_edge = "surface"
friction = 0.0
initial_shape = {{ radius = {radius}, center_x = 0.0 }}
[plate]
edge = "top"
motion = "vertical"
"#,
        e1 = materials[0].0,
        n1 = materials[0].1,
        e2 = materials[1].0,
        n2 = materials[1].1,
        u1 = fractions(&ball_r, 10.0),
        u2 = fractions(&flat_r, 20.0),
        v2 = fractions(&flat_z, 20.0),
        traction = force / (PI * 100.0),
    )
}

#[test]
fn a_ball_on_a_flat_is_hertzian() {
    // a³ = 3PR/(4E*), p₀ = 3P/(2πa²), p = p₀√(1 − r²/a²), E* = 1/((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂).
    // The bodies are 14 and 28 contact radii across: the issue asks 1 % for a and p₀, and
    // we ask 1 % of p₀ for the pressure inside 0.9a. The zone's radius is read where
    // p² (linear in r² near the edge of a Hertzian zone) reaches zero between the last two
    // points in contact.
    let steel = (2.0e5, 0.3);
    let aluminium = (7.0e4, 0.33);
    for (radius, force, materials, p) in [
        (50.0, 1000.0, [steel, steel], 8),
        (20.0, 300.0, [steel, aluminium], 8),
        (50.0, 1000.0, [steel, steel], 6),
    ] {
        let (r, pressure, _) = solve(&ball(radius, force, materials, p));
        let modulus = 1.0
            / materials
                .iter()
                .map(|(e, nu)| (1.0 - nu * nu) / e)
                .sum::<f64>();
        let a = (3.0 * force * radius / (4.0 * modulus)).cbrt();
        let p0 = 3.0 * force / (2.0 * PI * a * a);
        let case = format!("R = {radius}, P = {force}, p = {p}");
        assert!(
            (pressure[0] - p0).abs() < 0.01 * p0,
            "{case}: p(0) = {}, p₀ = {p0}",
            pressure[0]
        );
        for (ri, pi) in r.iter().zip(&pressure).filter(|(ri, _)| **ri < 0.9 * a) {
            let exact = p0 * (1.0 - ri * ri / (a * a)).sqrt();
            assert!(
                (pi - exact).abs() < 0.01 * p0,
                "{case}: p({ri}) = {pi}, Hertz {exact}"
            );
        }
        // The zone ends between the last point in contact and the next (to 1 % of a).
        let last = pressure.iter().rposition(|&p| p > 0.0).unwrap();
        let (inner, outer) = (r[last], r[last + 1]);
        assert!(
            inner <= 1.01 * a && a <= outer,
            "{case}: zone ends in [{inner}, {outer}], Hertz {a}"
        );
        // Its radius as measured from the pressure's shape: p² is linear in r² with its zero
        // at a² (least squares over the points inside 0.9 of the last one in contact).
        let inside = (r.iter().zip(&pressure))
            .filter(|(ri, _)| **ri < 0.9 * r[last])
            .map(|(ri, pi)| (*ri, *pi));
        let measured = wearfem::checks::edge_fit::square_root_edge(inside);
        assert!(
            (measured - a).abs() < 0.01 * a,
            "{case}: zone radius {measured}, Hertz {a}"
        );
    }
}

#[test]
fn a_flat_ended_punch_presses_as_sneddon_said() {
    // A flat-ended cylinder of radius a = 1 mm, 10⁴ times stiffer than the block it presses
    // (radius and depth 200a, held at its base) with P = 1000 N: p = P/(2πa√(a² − r²)),
    // δ = P(1 − ν²)/(2aE). The issue asks 1 % for the pressure inside 0.9a and for δ; the
    // finite block takes about 0.4 % off δ (its held base 200a down), the punch's own
    // compression 1e-4.
    let block_r = [
        0.0, 0.25, 0.5, 0.75, 0.9, 0.97, 0.99, 1.0, 1.01, 1.03, 1.1, 1.3, 2.0, 4.0, 10.0, 30.0,
        80.0, 200.0,
    ];
    let block_z = [
        0.0, 120.0, 170.0, 190.0, 196.0, 198.0, 199.0, 199.7, 199.9, 199.97, 199.99, 200.0,
    ];
    let text = format!(
        r#"title = "Sneddon's punch"
[analysis]
kind = "axisymmetric"
p = 8
[materials.block]
young = 1.0e5
poisson = 0.3
[materials.punch]
young = 1.0e9
poisson = 0.3
[[bodies]]
name = "punch"
[[bodies.blocks]]
corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
u = [0.0, 0.5, 0.8, 0.93, 0.98, 0.995, 1.0]
v = [0.0, 0.01, 0.03, 0.1, 0.3, 1.0]
material = "punch"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = {traction}
[[bodies]]
name = "block"
[[bodies.blocks]]
corners = [[0.0, -200.0], [200.0, -200.0], [200.0, 0.0], [0.0, 0.0]]
u = {u}
v = {v}
material = "block"
names = {{ bottom = "base", top = "surface" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[contact]
body = "punch"
edge = "contact"
target_body = "block"
target_edge = "surface"
friction = 0.0
[plate]
edge = "top"
motion = "vertical"
"#,
        traction = 1000.0 / PI,
        u = fractions(&block_r, 200.0),
        v = fractions(&block_z, 200.0),
    );
    let (r, pressure, approach) = solve(&text);
    let (force, a, young, poisson) = (1000.0, 1.0, 1.0e5, 0.3);
    for (ri, pi) in r.iter().zip(&pressure).filter(|(ri, _)| **ri < 0.9 * a) {
        let exact = force / (2.0 * PI * a * (a * a - ri * ri).sqrt());
        assert!(
            (pi - exact).abs() < 0.01 * exact,
            "p({ri}) = {pi}, Sneddon {exact}"
        );
    }
    let delta = force * (1.0 - poisson * poisson) / (2.0 * a * young);
    assert!(
        (approach - delta).abs() < 0.01 * delta,
        "δ = {approach}, Sneddon {delta}"
    );
    assert!(pressure.iter().all(|p| p.is_finite() && *p >= 0.0));
}

#[test]
fn what_is_not_built_for_bodies_of_revolution_is_refused_by_name() {
    let text = ball(50.0, 1000.0, [(2.0e5, 0.3), (2.0e5, 0.3)], 4);
    // A plate that turns is not axisymmetric.
    let turning = text.replace(
        "motion = \"vertical\"",
        "motion = \"vertical_rotation\"\npin = [0.0, 10.0]",
    );
    let problem = Problem::from_toml(&turning, "turning.toml").unwrap();
    let e = CondensedContact::build(&problem)
        .map(|_| ())
        .expect_err("refused");
    assert_eq!(e.key, "plate.motion");
    // Wear runs and steady states of bodies sliding along their axis are not built yet.
    let worn = format!(
        "{text}[wear]\nbody1 = {{ beta = 1.0e-6 }}\nsliding = \"reciprocating\"\namplitude = 1.0\nomega = 10.0\nsteps = 2\n"
    );
    let problem = Problem::from_toml(&worn, "worn.toml").unwrap();
    let run = wearfem::driver::wear(&problem, None, |_| {}).map(|_| ());
    assert!(run
        .unwrap_err()
        .to_string()
        .contains("contact.sliding_motion"));
    let steady = wearfem::driver::steady(&problem).map(|_| ());
    assert!(steady
        .unwrap_err()
        .to_string()
        .contains("contact.sliding_motion"));
}

#[test]
fn review_findings_stay_fixed() {
    // A ball whose axis is 1e-7 mm off r = 0 (as meshes from CAD give): one tolerance says
    // it is on the axis everywhere, and it presses as Hertz says (it pressed 10 % too hard).
    let steel = (2.0e5, 0.3);
    let exact = ball(50.0, 1000.0, [steel, steel], 6);
    let off = exact.replace(
        "[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]",
        "[[1e-7, 0.0], [10.0, 0.0], [10.0, 10.0], [1e-7, 10.0]]",
    );
    assert_ne!(off, exact);
    let (_, on_axis, _) = solve(&exact);
    let (_, near_axis, _) = solve(&off);
    // The same problem to the offset's order (1e-8 of the radius).
    assert!(
        (on_axis[0] - near_axis[0]).abs() < 1e-4 * on_axis[0],
        "{} {}",
        on_axis[0],
        near_axis[0]
    );
    // Friction between bodies of revolution sliding along their axis is refused until that
    // sliding is built.
    let rough = exact.replace("friction = 0.0", "friction = 0.5");
    let problem = Problem::from_toml(&rough, "rough.toml").unwrap();
    let e = CondensedContact::build(&problem)
        .map(|_| ())
        .expect_err("refused");
    assert_eq!(e.key, "contact.friction");
    // A traction on an edge along the axis acts on nothing: refused.
    let on_axis_load = exact.replace(
        "names = { bottom = \"contact\", top = \"top\" }",
        "names = { bottom = \"contact\", top = \"top\", left = \"axis\" }\n[[bodies.tractions]]\nedge = \"axis\"\nnormal = 100.0",
    );
    let e = Problem::from_toml(&on_axis_load, "axis-load.toml")
        .map(|_| ())
        .expect_err("refused");
    assert_eq!(e.key, "bodies[0].tractions[0].edge", "{e}");
    // A plate of a body of revolution reports no radial force and no moment.
    let problem = Problem::from_toml(&exact, "ball.toml").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    assert_eq!(contact.plate_resultant.0[0], 0.0);
    assert_eq!(contact.plate_resultant.1, 0.0);
}
