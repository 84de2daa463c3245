//! Axisymmetric elasticity (`analysis.kind = "axisymmetric"`, issue 31, first step) against
//! closed forms: Lamé's thick cylinder with free ends, a hollow sphere under internal
//! pressure, and solid cylinders (elements on the axis) under homogeneous stress.

use wearfem::problem::Problem;

const YOUNG: f64 = 2.0e5;
const POISSON: f64 = 0.3;

fn problem(text: &str) -> Problem {
    Problem::from_toml(text, "axisymmetric-test").unwrap()
}

/// Displacement and (σ_rr, σ_zz, σ_rz, σ_θθ) at `x` of body 0 under its tractions.
fn solve_at(problem: &Problem, points: &[[f64; 2]]) -> Vec<([f64; 2], [f64; 4])> {
    let body = problem.elastic_body(0, &[]).unwrap();
    let load = problem.load_vector(0, &body, &[]).unwrap();
    let u = body.solve(&load).unwrap();
    points
        .iter()
        .map(|&x| {
            let v = body.values_at(&u, x).expect("inside");
            let s = v.stress;
            (v.displacement, [s[0], s[1], s[2], v.hoop[1]])
        })
        .collect()
}

fn tube(p: usize, radial: usize, axial: usize) -> String {
    format!(
        r#"title = "a thick tube, free ends, internal pressure"
[analysis]
kind = "axisymmetric"
p = {p}
[materials.steel]
young = {YOUNG}
poisson = {POISSON}
[[bodies]]
name = "tube"
[[bodies.blocks]]
corners = [[10.0, 0.0], [20.0, 0.0], [20.0, 10.0], [10.0, 10.0]]
u = {radial}
v = {axial}
material = "steel"
names = {{ bottom = "mid", left = "bore", right = "outside", top = "end" }}
[[bodies.tractions]]
edge = "bore"
normal = 100.0
[[bodies.supports]]
edge = "mid"
fix = ["z"]
"#
    )
}

#[test]
fn lames_tube_with_free_ends() {
    // A tube a = 10 to b = 20 mm under p = 100 MPa inside, its ends free, held in z on its
    // mid-plane: σ_rr = A − B/r², σ_θθ = A + B/r², σ_zz = 0 (A = pa²/(b² − a²),
    // B = pa²b²/(b² − a²)), u_r = r/E ((1 − ν)A + (1 + ν)B/r²), u_z = −2νAz/E: the exact 3D
    // solution. u_r holds 1/r, which degree 8 on elements 2.5 mm wide at r ≥ 10 mm resolves
    // to about 1e-10; the issue asks 1e-8 of the displacements, and the stresses (one
    // derivative more) are asked to 1e-6 of p here.
    let (a, b, p) = (10.0, 20.0, 100.0);
    let big_a = p * a * a / (b * b - a * a);
    let big_b = p * a * a * b * b / (b * b - a * a);
    for (degree, radial, axial) in [(8, 4, 2), (10, 3, 1)] {
        let problem = problem(&tube(degree, radial, axial));
        let points = [
            [10.0, 5.0],
            [13.3, 7.7],
            [16.1, 2.3],
            [20.0, 10.0],
            [11.7, 0.0],
        ];
        let scale = b / YOUNG * ((1.0 - POISSON) * big_a + (1.0 + POISSON) * big_b / (b * b));
        for (x, (u, s)) in points.iter().zip(solve_at(&problem, &points)) {
            let r = x[0];
            let ur = r / YOUNG * ((1.0 - POISSON) * big_a + (1.0 + POISSON) * big_b / (r * r));
            let uz = -2.0 * POISSON * big_a * x[1] / YOUNG;
            assert!(
                (u[0] - ur).abs() < 1e-8 * scale,
                "p = {degree}: u_r at {x:?}"
            );
            assert!(
                (u[1] - uz).abs() < 1e-8 * scale,
                "p = {degree}: u_z at {x:?}"
            );
            let exact = [big_a - big_b / (r * r), 0.0, 0.0, big_a + big_b / (r * r)];
            for (c, (got, want)) in s.iter().zip(exact).enumerate() {
                assert!(
                    (got - want).abs() < 1e-6 * p,
                    "p = {degree}: stress {c} at {x:?}: {got} against {want}"
                );
            }
        }
    }
}

#[test]
fn a_hollow_sphere_under_internal_pressure() {
    // The quarter of the sphere's meridian section (exact arcs), held in z on its equator;
    // the axis condition on its edge along r = 0 is implied. u_R = p a³/(E (b³ − a³))
    // ((1 − 2ν) R + (1 + ν) b³/(2R²)), radial.
    let (a, b, p): (f64, f64, f64) = (10.0, 20.0, 100.0);
    let text = format!(
        r#"title = "a hollow sphere"
[analysis]
kind = "axisymmetric"
p = 8
[materials.steel]
young = {YOUNG}
poisson = {POISSON}
[[bodies]]
name = "sphere"
[[bodies.blocks]]
corners = [[10.0, 0.0], [20.0, 0.0], [0.0, 20.0], [0.0, 10.0]]
arcs = [{{ edge = 1, center = [0.0, 0.0] }}, {{ edge = 3, center = [0.0, 0.0] }}]
u = 4
v = 4
material = "steel"
names = {{ bottom = "equator", left = "bore", right = "outside", top = "axis" }}
[[bodies.tractions]]
edge = "bore"
normal = {p}
[[bodies.supports]]
edge = "equator"
fix = ["z"]
"#
    );
    let problem = problem(&text);
    let displacement = |radius: f64| {
        p * a.powi(3) / (YOUNG * (b.powi(3) - a.powi(3)))
            * ((1.0 - 2.0 * POISSON) * radius
                + (1.0 + POISSON) * b.powi(3) / (2.0 * radius * radius))
    };
    let scale = displacement(a);
    let points = [
        [10.0, 0.0],
        [0.0, 15.0],
        [9.0, 12.0],
        [14.1421356237, 14.1421356237],
        [0.0, 10.0],
        [3.0, 18.5],
    ];
    for (x, (u, _)) in points.iter().zip(solve_at(&problem, &points)) {
        let radius = x[0].hypot(x[1]);
        let ur = displacement(radius);
        for c in 0..2 {
            let exact = ur * x[c] / radius;
            assert!(
                (u[c] - exact).abs() < 1e-8 * scale,
                "{x:?}, component {c}: {} against {exact}",
                u[c]
            );
        }
    }
}

/// A solid cylinder of radius 5 mm and height 10 mm (its elements on the axis), held in z at
/// its base, under `loads` (TOML tractions).
fn solid_cylinder(loads: &str) -> Problem {
    problem(&format!(
        r#"title = "a solid cylinder"
[analysis]
kind = "axisymmetric"
p = 4
[materials.steel]
young = {YOUNG}
poisson = {POISSON}
[[bodies]]
name = "rod"
[[bodies.blocks]]
corners = [[0.0, 0.0], [5.0, 0.0], [5.0, 10.0], [0.0, 10.0]]
u = [0.0, 0.3, 1.0]
v = 3
material = "steel"
names = {{ bottom = "base", right = "side", top = "top", left = "axis" }}
[[bodies.supports]]
edge = "base"
fix = ["z"]
{loads}
"#
    ))
}

#[test]
fn solid_cylinders_under_homogeneous_stress_hold_the_axis() {
    // Homogeneous states are exact in any p-version space: compression σ on the ends,
    // u_r = νσr/E, u_z = −σz/E; a pressure q on the side with free ends, σ_rr = σ_θθ = −q,
    // u_r = −(1 − ν) q r/E, u_z = 2νqz/E. The elements on the axis integrate u_r/r with
    // Gauss points off the axis: round-off only.
    let sigma = 50.0;
    let axial = solid_cylinder(&format!(
        "[[bodies.tractions]]\nedge = \"top\"\nnormal = {sigma}"
    ));
    let points = [
        [0.0, 10.0],
        [0.0, 3.0],
        [2.5, 7.0],
        [5.0, 10.0],
        [1e-3, 1.0],
        // Within the axis tolerance (1e-6 of the body's size): the hoop strain is ∂u_r/∂r.
        [1e-7, 4.0],
    ];
    for (x, (u, s)) in points.iter().zip(solve_at(&axial, &points)) {
        let expected = [POISSON * sigma * x[0] / YOUNG, -sigma * x[1] / YOUNG];
        for c in 0..2 {
            assert!((u[c] - expected[c]).abs() < 1e-11, "{x:?}: {u:?}");
        }
        let stress = [0.0, -sigma, 0.0, 0.0];
        for c in 0..4 {
            assert!((s[c] - stress[c]).abs() < 1e-9 * sigma, "{x:?}: {s:?}");
        }
    }
    let q = 30.0;
    let side = solid_cylinder(&format!(
        "[[bodies.tractions]]\nedge = \"side\"\nnormal = {q}"
    ));
    for (x, (u, s)) in points.iter().zip(solve_at(&side, &points)) {
        let expected = [
            -(1.0 - POISSON) * q * x[0] / YOUNG,
            2.0 * POISSON * q * x[1] / YOUNG,
        ];
        for c in 0..2 {
            assert!((u[c] - expected[c]).abs() < 1e-11, "{x:?}: {u:?}");
        }
        let stress = [-q, 0.0, 0.0, -q];
        for c in 0..4 {
            assert!((s[c] - stress[c]).abs() < 1e-9 * q, "{x:?}: {s:?}");
        }
    }
}

#[test]
fn bad_axisymmetric_input_is_refused_by_name() {
    let error = |text: &str| {
        Problem::from_toml(text, "bad.toml")
            .and_then(|p| p.elastic_body(0, &[]).map(|_| ()))
            .expect_err("refused")
    };
    // A thickness has no meaning for a body of revolution; a plane body needs one.
    let with_thickness = tube(4, 2, 1).replace("p = 4", "thickness = 10.0\np = 4");
    assert_eq!(error(&with_thickness).key, "analysis.thickness");
    let plane = tube(4, 2, 1).replace("\"axisymmetric\"", "\"plane_strain\"");
    let e = error(&plane);
    assert_eq!(e.key, "analysis.thickness");
    assert!(e.message.contains("required"));
    // A body reaching r < 0.
    let crossing = tube(4, 2, 1).replace(
        "[[10.0, 0.0], [20.0, 0.0], [20.0, 10.0], [10.0, 10.0]]",
        "[[-1.0, 0.0], [20.0, 0.0], [20.0, 10.0], [-1.0, 10.0]]",
    );
    assert_eq!(error(&crossing).key, "bodies[0].blocks");
    // A support that moves the axis radially contradicts the axis condition.
    let moved = solid_cylinder(
        "[[bodies.supports]]\nedge = \"axis\"\nfix = [\"x\"]\ndisplacement = [0.01, 0.0]",
    );
    let e = moved.elastic_body(0, &[]).err().expect("refused");
    assert_eq!(e.key, "bodies[0].supports[1]", "{e}");
    assert!(e.message.contains("the axis"), "{e}");
}

#[test]
fn summaries_say_that_forces_are_for_the_whole_circle() {
    let tube = problem(&tube(4, 2, 1));
    let summary = wearfem::driver::elastic(&tube).unwrap();
    let said = summary["axisymmetric"]["forces"].as_str().unwrap();
    assert!(said.contains("whole circumference"), "{said}");
    // A plane problem's summary is as before: no such key.
    let lame = Problem::from_toml(wearfem::examples::example("lame").unwrap(), "lame").unwrap();
    assert!(wearfem::driver::elastic(&lame)
        .unwrap()
        .get("axisymmetric")
        .is_none());
}

#[test]
fn supports_that_make_no_sense_on_the_axis_are_refused() {
    // Holding z along the axis is a line support in 3D (no answer in the continuum); a spring
    // bed on the axis holds nothing. Holding x there is what the axis condition does anyway.
    let held_z = solid_cylinder("[[bodies.supports]]\nedge = \"axis\"\nfix = [\"z\"]");
    let e = held_z.elastic_body(0, &[]).err().expect("refused");
    assert_eq!(e.key, "bodies[0].supports[1].fix", "{e}");
    let held_x = solid_cylinder("[[bodies.supports]]\nedge = \"axis\"\nfix = [\"x\"]");
    assert!(held_x.elastic_body(0, &[]).is_ok());
    let bed = solid_cylinder("[[bodies.springs]]\nedge = \"axis\"\nnormal = 100.0");
    let e = bed.elastic_body(0, &[]).err().expect("refused");
    assert_eq!(e.key, "bodies[0].springs[0].edge", "{e}");
}
