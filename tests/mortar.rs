//! Mortar contact on meshes made independently: Hertz line contact against the closed form,
//! the contact patch test, and the flat punch with an evenly spaced strip against the matched
//! mesh.

use wearfem::complementarity::{ContactSolution, ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// Mesh lines (as fractions of [lo, hi]) with cells of `h` mm over [−span, span] shifted by
/// `offset`, and the coarse lines `outer` (mm, ascending, outside the span) added.
fn lines(lo: f64, hi: f64, h: f64, span: f64, offset: f64, outer: &[f64]) -> String {
    let mut x: Vec<f64> = outer.to_vec();
    let mut k = (-(span - offset) / h).floor() as i64;
    loop {
        let v = offset + k as f64 * h;
        if v > span {
            break;
        }
        if v >= -span {
            x.push(v);
        }
        k += 1;
    }
    x.push(lo);
    x.push(hi);
    x.sort_by(f64::total_cmp);
    let f: Vec<String> = x
        .iter()
        .map(|v| format!("{:.12}", (v - lo) / (hi - lo)))
        .collect();
    format!("[{}]", f.join(", "))
}

/// Hertz: a block of 1 mm elements near x = 0 with a circular initial gap of radius 500 mm,
/// pressed on a large block whose elements near x = 0 are `h2` mm wide, shifted by 0.37 mm.
fn hertz(kind: &str, h1: f64, h2: f64, discretisation: &str) -> Problem {
    let u1 = lines(-20.0, 20.0, h1, 5.0, 0.0, &[-12.0, -7.0, 7.0, 12.0]);
    let u2 = lines(-100.0, 100.0, h2, 13.0, 0.37, &[-50.0, -25.0, 25.0, 50.0]);
    let text = format!(
        r#"
[analysis]
kind = "{kind}"
thickness = 1.0
p = 8

[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "cylinder"
[[bodies.blocks]]
corners = [[-20.0, 0.0], [20.0, 0.0], [20.0, 40.0], [-20.0, 40.0]]
u = {u1}
v = [0.0, 0.05, 0.15, 0.35, 1.0]
material = "steel"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = 38.825

[[bodies]]
name = "block"
[[bodies.blocks]]
corners = [[-100.0, -100.0], [100.0, -100.0], [100.0, 0.0], [-100.0, 0.0]]
u = {u2}
v = [0.0, 0.5, 0.8, 0.92, 0.98, 1.0]
material = "steel"
names = {{ bottom = "base", top = "surface" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]

[contact]
body = "cylinder"
edge = "contact"
target_body = "block"
target_edge = "surface"
initial_shape = {{ radius = 500.0, center_x = 0.0 }}
discretisation = "{discretisation}"

[plate]
edge = "top"
motion = "vertical"
"#
    );
    Problem::from_toml(&text, "hertz").unwrap()
}

fn solve(problem: &Problem) -> (CondensedContact, ContactSolution) {
    let (contact, _, _) = CondensedContact::build(problem).unwrap();
    let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(info.status, Status::Solved);
    (contact, sol)
}

/// Largest distance of a pressure from the least-squares parabola through it and its two
/// neighbours on each side: a smooth profile sits on it, a point-to-point zigzag does not.
fn oscillation(x: &[f64], p: &[f64], keep: impl Fn(f64) -> bool) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 2..p.len().saturating_sub(2) {
        if !(i - 2..=i + 2).all(|j| keep(p[j])) {
            continue;
        }
        // Fit c0 + c1 ξ + c2 ξ² (ξ = x − x_i) by the normal equations (3 × 3, Cramer).
        let mut m = [[0.0; 3]; 3];
        let mut r = [0.0; 3];
        for j in i - 2..=i + 2 {
            let xi = x[j] - x[i];
            let basis = [1.0, xi, xi * xi];
            for a in 0..3 {
                r[a] += basis[a] * p[j];
                for b in 0..3 {
                    m[a][b] += basis[a] * basis[b];
                }
            }
        }
        let det = |m: &[[f64; 3]; 3]| {
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        };
        let d = det(&m);
        let mut c = [0.0; 3];
        for (a, ca) in c.iter_mut().enumerate() {
            let mut ma = m;
            for (row, rv) in ma.iter_mut().zip(r) {
                row[a] = rv;
            }
            *ca = det(&ma) / d;
        }
        for j in i - 2..=i + 2 {
            let xi = x[j] - x[i];
            worst = worst.max((p[j] - (c[0] + c[1] * xi + c[2] * xi * xi)).abs());
        }
    }
    worst
}

/// Half-width of the elliptic profile p² = p0²(1 − x²/a²), linear in x², fitted through the
/// loaded points that are not next to the contact edges (p > 0.3 peak).
fn half_width(contact: &CondensedContact, sol: &ContactSolution) -> f64 {
    let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
    let pts: Vec<(f64, f64)> = contact
        .points
        .x
        .iter()
        .zip(&sol.pressure)
        .filter(|(_, &p)| p > 0.3 * peak)
        .map(|(x, &p)| (x[0] * x[0], p * p))
        .collect();
    let n = pts.len() as f64;
    let sx: f64 = pts.iter().map(|p| p.0).sum();
    let sy: f64 = pts.iter().map(|p| p.1).sum();
    let sxx: f64 = pts.iter().map(|p| p.0 * p.0).sum();
    let sxy: f64 = pts.iter().map(|p| p.0 * p.1).sum();
    let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    let intercept = (sy - slope * sx) / n;
    (-intercept / slope).sqrt()
}

#[test]
fn hertz_line_contact_on_non_matching_meshes() {
    for kind in ["plane_strain", "plane_stress"] {
        // Hertz (Johnson, Contact Mechanics, §4.3): two equal bodies, 1/E* = 2/E',
        // a = √(4 F R / (π E*)), p0 = 2F / (π a); F = 38.825 MPa × 40 mm per mm of thickness.
        let force = 38.825 * 40.0;
        let (e, nu) = (2.0e5f64, 0.3f64);
        let e_one = if kind == "plane_strain" {
            e / (1.0 - nu * nu)
        } else {
            e
        };
        let e_star = e_one / 2.0;
        let a = (4.0 * force * 500.0 / (std::f64::consts::PI * e_star)).sqrt();
        let p0 = 2.0 * force / (std::f64::consts::PI * a);
        // Element sizes (mm) near the contact of body 1 and body 2, ratios 1 : 1.3 and 1 : 2.7
        // each way round; body 2's lines are shifted by 0.37 mm, so no two edges meet. With
        // 1 mm against 2.7 mm the contact (2a ≈ 6 mm) would span two elements of body 2 and the
        // square-root edges of the pressure would sit inside them (docs/validation.md).
        for (h1, h2) in [(1.0, 1.3), (0.5, 1.35), (1.3, 1.0), (2.7, 1.0)] {
            let (contact, sol) = solve(&hertz(kind, h1, h2, "mortar"));
            let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
            let a_fit = half_width(&contact, &sol);
            // 2 %: the issue's bound; the finite bodies (2a ≈ 6 mm against 40 and 100 mm)
            // change the closed form by well under that.
            assert!(
                (peak - p0).abs() < 0.02 * p0,
                "{kind} {h1}:{h2}: peak {peak:.3} MPa, Hertz {p0:.3}"
            );
            assert!(
                (a_fit - a).abs() < 0.02 * a,
                "{kind} {h1}:{h2}: half-width {a_fit:.4} mm, Hertz {a:.4}"
            );
            // Point-to-point oscillation, judged where the profile is smooth (|x| < 0.8 a,
            // p > 0.6 p0): nearer the edges the square-root fall of the pressure is not a
            // polynomial inside an element, on matched meshes as well.
            let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
            let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
            assert!(
                osc < 0.01 * peak,
                "{kind} {h1}:{h2}: oscillation {osc:.3} MPa, peak {peak:.3}"
            );
            // The same meshes with one partner point per contact point oscillate by more: the
            // check above can see the defect mortar removes.
            let (_, sol) = solve(&hertz(kind, h1, h2, "collocation"));
            let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
            assert!(
                osc > 0.01 * peak,
                "{kind} {h1}:{h2}: collocation oscillation only {osc:.3} MPa"
            );
        }
    }
}

/// Two blocks 10 mm wide, meshed independently (3 and 4 uneven elements across), the upper
/// one (ν = 0, so that the plate clamping its top edge does not restrain it) pressed with
/// `load` MPa on the lower one (ν = 0.3, on rollers: base held in z, left side in x).
fn patch(discretisation: &str, p: usize) -> Problem {
    let text = format!(
        r#"
[analysis]
kind = "plane_stress"
thickness = 2.0
p = {p}

[materials.soft]
young = 7.0e4
poisson = 0.0
[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "upper"
[[bodies.blocks]]
corners = [[0.0, 10.0], [10.0, 10.0], [10.0, 16.0], [0.0, 16.0]]
u = [0.0, 0.23, 0.61, 1.0]
v = 2
material = "soft"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = 10.0

[[bodies]]
name = "lower"
[[bodies.blocks]]
corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
u = [0.0, 0.17, 0.45, 0.52, 1.0]
v = 3
material = "steel"
names = {{ bottom = "base", top = "surface", left = "side" }}
[[bodies.supports]]
edge = "base"
fix = ["z"]
[[bodies.supports]]
edge = "side"
fix = ["x"]

[contact]
body = "upper"
edge = "contact"
target_body = "lower"
target_edge = "surface"
discretisation = "{discretisation}"

[plate]
edge = "top"
motion = "vertical"
"#
    );
    Problem::from_toml(&text, "patch").unwrap()
}

#[test]
fn patch_test_uniform_pressure_crosses_non_matching_meshes() {
    // The exact solution is a uniform stress σ_zz = −10 MPa in both blocks, a linear
    // displacement: inside every finite element space, so a consistent contact discretisation
    // must reproduce it to round-off. 1e-8: the issue's bound (round-off is ~1e-12 here).
    for p in [2, 5, 8] {
        let (_, sol) = solve(&patch("mortar", p));
        let worst = sol
            .pressure
            .iter()
            .map(|v| (v - 10.0).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-8 * 10.0,
            "p = {p}: pressure off by {worst:.3e} MPa"
        );
    }
    // Collocation loads body 2 with point forces at the partner points, which are not the
    // consistent loads of a uniform pressure across body 2's element ends: it fails the test.
    let (_, sol) = solve(&patch("collocation", 8));
    let worst = sol
        .pressure
        .iter()
        .map(|v| (v - 10.0).abs())
        .fold(0.0, f64::max);
    assert!(
        worst > 1e-4 * 10.0,
        "collocation passes the patch test ({worst:.3e} MPa)"
    );
}

fn punch(even: bool, discretisation: &str) -> Problem {
    let mut text = wearfem::examples::example("punch-b40").unwrap().to_string();
    if even {
        text = text.replace(
            "u = [0.0, 0.2, 0.35, 0.3875, 0.425, 0.4625, 0.5, 0.5375, 0.575, 0.6125, 0.65, 0.8, 1.0]",
            "u = 12",
        );
    }
    text = text.replace(
        "discretisation = \"collocation\"",
        &format!("discretisation = \"{discretisation}\""),
    );
    Problem::from_toml(&text, "punch-b40").unwrap()
}

/// Largest difference at the points that are not among the first or last `skip`, and the
/// root-mean-square difference over all points.
fn differences(a: &[f64], b: &[f64], skip: usize) -> (f64, f64) {
    let n = a.len();
    let max = (skip..n - skip)
        .map(|i| (a[i] - b[i]).abs())
        .fold(0.0, f64::max);
    let rms = (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>() / n as f64).sqrt();
    (max, rms)
}

#[test]
fn punch_on_an_evenly_meshed_strip_matches_the_matched_mesh() {
    // Same contact points on body 1 in both models; only the strip's mesh differs (12 even
    // elements of 16.7 mm whose lines miss the punch corners, against lines at the corners).
    let (contact, matched) = solve(&punch(false, "collocation"));
    let (_, even) = solve(&punch(true, "mortar"));
    let peak = matched.pressure.iter().cloned().fold(0.0, f64::max);
    // 2 % of the peak away from the corners. The four points within 2.4 mm of the left
    // corner (1070) are excluded: there the pressure is singular and a 16.7 mm strip element
    // spanning the corner cannot resolve the strip's response (it differs by 6 % of the peak at
    // the second point, with collocation just as with mortar: a resolution limit of body 2, not
    // of the coupling; docs/validation.md).
    let (max, _) = differences(&even.pressure, &matched.pressure, 4);
    assert!(
        max < 0.02 * peak,
        "first solve: {max:.3} MPa off, peak {peak:.3}"
    );
    assert_eq!(contact.len(), 65);
    // The steady state: p⁺ + p⁻ = 2p̃ = 33.333 MPa holds on any mesh (paper eq. 23a); p⁺ itself
    // within 1 % r.m.s. of the peak 2p̃ (pointwise up to 3 % at the two ends of the p⁺ zone,
    // where its slope jumps inside a strip element).
    let st_matched = wearfem::driver::steady(&punch(false, "collocation"))
        .unwrap()
        .0;
    let st_even = wearfem::driver::steady(&punch(true, "mortar")).unwrap().0;
    let sum = |s: &wearfem::steady::SteadyState| -> Vec<f64> {
        s.p_plus
            .iter()
            .zip(&s.p_minus)
            .map(|(a, b)| a + b)
            .collect()
    };
    let (max, _) = differences(&sum(&st_even), &sum(&st_matched), 0);
    assert!(
        max < 1e-6 * 33.333,
        "steady p⁺ + p⁻ differs by {max:.3e} MPa"
    );
    let (max, rms) = differences(&st_even.p_plus, &st_matched.p_plus, 0);
    assert!(
        rms < 0.01 * 33.333 && max < 0.03 * 33.333,
        "steady p⁺: max {max:.3} MPa, r.m.s. {rms:.3} MPa"
    );
    // The 1700-step run's last cycle, judged the same way (pointwise up to 3.1 % at the p⁺
    // zone's ends here, 4 % allowed).
    let run = |p: &Problem| wearfem::driver::wear(p, None, |_| {}).unwrap().history;
    let (h_matched, h_even) = (
        run(&punch(false, "collocation")),
        run(&punch(true, "mortar")),
    );
    let (max, rms) = differences(&h_even.p_plus, &h_matched.p_plus, 0);
    assert!(
        rms < 0.01 * 33.333 && max < 0.04 * 33.333,
        "run p⁺: max {max:.3} MPa, r.m.s. {rms:.3} MPa"
    );
}

#[test]
fn on_matched_meshes_mortar_is_collocation() {
    // Where body 2's trace is a polynomial of degree p on each element of body 1 (same mesh
    // lines, same p, straight edges), biorthogonality returns its point values exactly, and
    // D_ii = ∫ N_i ds is the Lobatto weight: the two methods differ by round-off only.
    let (c_col, s_col) = solve(&punch(false, "collocation"));
    let (c_mor, s_mor) = solve(&punch(false, "mortar"));
    for (a, b) in c_col.points.weight.iter().zip(&c_mor.points.weight) {
        assert!((a - b).abs() < 1e-12 * a, "weights {a} / {b}");
    }
    let peak = s_col.pressure.iter().cloned().fold(0.0, f64::max);
    let (max, _) = differences(&s_mor.pressure, &s_col.pressure, 0);
    // Round-off of two different sums of ~1e3 terms through a 65 × 65 solve: 1e-9 of peak.
    assert!(max < 1e-9 * peak, "pressures differ by {max:.3e} MPa");
}
