//! Elasticity against closed-form solutions: patch tests (constant stress), the Lamé thick
//! cylinder and exponential p-convergence.

use wearfem::driver;
use wearfem::fields::strain_energy;
use wearfem::problem::Problem;

/// A square [0,10]² of four straight-sided, distorted blocks (interior vertex moved to
/// (5.7, 4.4)) under the traction of a constant stress state σ.
fn patch_problem(p: usize, sigma: [f64; 3], interior_arc: bool) -> String {
    let (sxx, szz, sxz) = (sigma[0], sigma[1], sigma[2]);
    // T = σ·n written as T = −p n + s τ (τ = n turned by +90°): p = −n·σ·n, s = τ·σ·n.
    let side = |n: [f64; 2]| {
        let t = [n[0] * sxx + n[1] * sxz, n[0] * sxz + n[1] * szz];
        let tau = [-n[1], n[0]];
        (-(n[0] * t[0] + n[1] * t[1]), tau[0] * t[0] + tau[1] * t[1])
    };
    let (pb, sb) = side([0.0, -1.0]);
    let (pr, sr) = side([1.0, 0.0]);
    let (pt, st) = side([0.0, 1.0]);
    let (pl, sl) = side([-1.0, 0.0]);
    let blocks = if interior_arc {
        // Two blocks joined along a circular arc: the elements next to it have a
        // non-polynomial blending map.
        r#"
[[bodies.blocks]]
corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 5.0], [0.0, 5.0]]
arcs = [{ edge = 2, center = [5.0, -20.0] }]
u = 2
v = 1
material = "m"
names = { bottom = "b", right = "r", left = "l" }

[[bodies.blocks]]
corners = [[0.0, 5.0], [10.0, 5.0], [10.0, 10.0], [0.0, 10.0]]
arcs = [{ edge = 0, center = [5.0, -20.0] }]
u = 2
v = 1
material = "m"
names = { right = "r", top = "t", left = "l" }
"#
    } else {
        r#"
[[bodies.blocks]]
corners = [[0.0, 0.0], [5.0, 0.0], [5.7, 4.4], [0.0, 5.0]]
u = 1
v = 1
material = "m"
names = { bottom = "b", left = "l" }

[[bodies.blocks]]
corners = [[5.0, 0.0], [10.0, 0.0], [10.0, 5.0], [5.7, 4.4]]
u = 1
v = 1
material = "m"
names = { bottom = "b", right = "r" }

[[bodies.blocks]]
corners = [[5.7, 4.4], [10.0, 5.0], [10.0, 10.0], [5.0, 10.0]]
u = 1
v = 1
material = "m"
names = { right = "r", top = "t" }

[[bodies.blocks]]
corners = [[0.0, 5.0], [5.7, 4.4], [5.0, 10.0], [0.0, 10.0]]
u = 1
v = 1
material = "m"
names = { top = "t", left = "l" }
"#
    };
    format!(
        r#"
[analysis]
kind = "plane_stress"
thickness = 2.0
p = {p}

[materials.m]
young = 1000.0
poisson = 0.25

[[bodies]]
name = "square"
{blocks}
[[bodies.supports]]
point = [0.0, 0.0]
fix = ["x", "z"]

[[bodies.supports]]
point = [10.0, 0.0]
fix = ["z"]

[[bodies.tractions]]
edge = "b"
normal = {pb}
shear = {sb}

[[bodies.tractions]]
edge = "r"
normal = {pr}
shear = {sr}

[[bodies.tractions]]
edge = "t"
normal = {pt}
shear = {st}

[[bodies.tractions]]
edge = "l"
normal = {pl}
shear = {sl}
"#
    )
}

/// Largest stress error (relative to |σ|) over a grid of points inside the square.
fn patch_stress_error(p: usize, interior_arc: bool) -> f64 {
    patch_stress_error_in(p, interior_arc, "tensor")
}

fn patch_stress_error_in(p: usize, interior_arc: bool, space: &str) -> f64 {
    let sigma = [3.0, -1.5, 0.8];
    let text = patch_problem(p, sigma, interior_arc).replace(
        "thickness = 2.0",
        &format!("thickness = 2.0\nspace = \"{space}\""),
    );
    let problem = Problem::from_toml(&text, "patch").unwrap();
    let body = problem.elastic_body(0, &[]).unwrap();
    let load = problem.load_vector(0, &body, &[]).unwrap();
    let u = body.solve(&load).unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..7 {
        for j in 0..7 {
            let x = [0.5 + 1.5 * i as f64, 0.5 + 1.5 * j as f64];
            let v = body.values_at(&u, x).expect("point inside");
            for (computed, exact) in v.stress.iter().zip(&sigma) {
                worst = worst.max((computed - exact).abs() / 3.0);
            }
        }
    }
    worst
}

#[test]
fn patch_test_is_exact_on_distorted_straight_elements() {
    // A bilinear map lies in the space for every p ≥ 1, so the linear displacement of a
    // constant stress state is reproduced exactly: only round-off of a 10³-conditioned system.
    for p in 1..=10 {
        let error = patch_stress_error(p, false);
        assert!(error < 1e-9, "p = {p}: stress error {error:.3e}");
    }
}

#[test]
fn patch_test_is_exact_in_the_trunk_space() {
    // The trunk space keeps all vertex and edge modes, so it too contains the bilinear map.
    for p in 1..=10 {
        let error = patch_stress_error_in(p, false, "trunk");
        assert!(error < 1e-9, "trunk p = {p}: stress error {error:.3e}");
    }
}

#[test]
fn patch_test_converges_exponentially_on_arc_elements() {
    // The blending map of an arc-bounded element is not polynomial: the linear field is not in
    // the space, but it is analytic, so the error falls exponentially with p.
    let errors: Vec<f64> = [2, 4, 6, 8]
        .iter()
        .map(|&p| patch_stress_error(p, true))
        .collect();
    for w in errors.windows(2) {
        assert!(
            w[1] < w[0] / 10.0,
            "errors do not fall tenfold per two degrees: {errors:?}"
        );
    }
    assert!(errors[3] < 1e-5, "p = 8 error {:.3e}", errors[3]);
}

/// Lamé: radial displacement of a thick cylinder (plane strain) under internal pressure.
fn lame_radial(r: f64) -> f64 {
    let (a, b, p, e, nu) = (100.0f64, 200.0f64, 100.0f64, 2.0e5f64, 0.3f64);
    let aa = p * a * a / (b * b - a * a);
    let bb = p * a * a * b * b / (b * b - a * a);
    (1.0 + nu) / e * ((1.0 - 2.0 * nu) * aa * r + bb / r)
}

#[test]
fn lame_cylinder_matches_closed_form() {
    let text = wearfem::examples::example("lame").unwrap();
    let problem = Problem::from_toml(text, "lame").unwrap();
    let summary = driver::elastic(&problem).unwrap();
    for (name, r) in [("inner", 100.0), ("outer", 200.0)] {
        let ur = summary["probes"][name]["displacement"][0].as_f64().unwrap();
        let exact = lame_radial(r);
        let rel = (ur - exact).abs() / exact;
        // The issue demands 1e-7: exact geometry, p = 8, smooth solution.
        assert!(
            rel < 1e-7,
            "{name}: u_r = {ur}, exact {exact}, relative error {rel:.3e}"
        );
    }
}

/// Relative energy-norm error of the Lamé problem on one element at degree p.
fn lame_energy_error(p: usize) -> f64 {
    let text = wearfem::examples::example("lame")
        .unwrap()
        .replace("p = 8", &format!("p = {p}"))
        .replace("u = 2 ", "u = 1 ")
        .replace("v = 2 ", "v = 1 ");
    let problem = Problem::from_toml(&text, "lame-1x1").unwrap();
    let body = problem.elastic_body(0, &[]).unwrap();
    let load = problem.load_vector(0, &body, &[]).unwrap();
    let u = body.solve(&load).unwrap();
    let energy = strain_energy(&load, &u);
    // Exact U = ½ ∫ p u_r dS over the inner quarter arc, thickness 1 mm.
    let exact = 0.5 * 100.0 * lame_radial(100.0) * (std::f64::consts::FRAC_PI_2 * 100.0);
    // Galerkin: U − U_h = ½‖u − u_h‖²_E ≥ 0, so the relative energy-norm error is √((U − U_h)/U).
    ((exact - energy) / exact).max(0.0).sqrt()
}

#[test]
fn energy_error_falls_exponentially_in_p() {
    let errors: Vec<(usize, f64)> = [2, 4, 6, 8]
        .iter()
        .map(|&p| (p, lame_energy_error(p)))
        .collect();
    for w in errors.windows(2) {
        assert!(
            w[1].1 < w[0].1 / 10.0,
            "energy-norm error did not fall tenfold from p = {} to {}: {errors:?}",
            w[0].0,
            w[1].0
        );
    }
}

/// A probe exactly on a material interface (the compound cylinder's r = 15 mm, two materials in
/// four arc blocks) gets one side's stress, which jumps there (σ_θ 129.3 against 42.2 MPa):
/// the summary says so, and names both materials; probes inside one material get no warning.
#[test]
fn a_probe_on_a_material_interface_is_named() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/compound-cylinder.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let problem = Problem::from_toml(&text, "compound-cylinder.toml").unwrap();
    let summary = driver::elastic(&problem).unwrap();
    let warnings: Vec<&str> = summary["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    for (w, probe) in warnings.iter().zip(["r15", "r15b"]) {
        assert!(w.contains(&format!("probe \"{probe}\"")), "{w}");
        assert!(w.contains("interface of materials"), "{w}");
    }
}
