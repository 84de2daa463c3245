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
    let f: Vec<String> = x.iter().map(|v| format!("{:.12}", (v - lo) / (hi - lo))).collect();
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
        let e_one = if kind == "plane_strain" { e / (1.0 - nu * nu) } else { e };
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
            assert!((peak - p0).abs() < 0.02 * p0, "{kind} {h1}:{h2}: peak {peak:.3} MPa, Hertz {p0:.3}");
            assert!((a_fit - a).abs() < 0.02 * a, "{kind} {h1}:{h2}: half-width {a_fit:.4} mm, Hertz {a:.4}");
            // Point-to-point oscillation, judged where the profile is smooth (|x| < 0.8 a,
            // p > 0.6 p0): nearer the edges the square-root fall of the pressure is not a
            // polynomial inside an element, on matched meshes as well.
            let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
            let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
            assert!(osc < 0.01 * peak, "{kind} {h1}:{h2}: oscillation {osc:.3} MPa, peak {peak:.3}");
            // The same meshes with one partner point per contact point oscillate by more: the
            // check above can see the defect mortar removes.
            let (_, sol) = solve(&hertz(kind, h1, h2, "collocation"));
            let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
            assert!(osc > 0.01 * peak, "{kind} {h1}:{h2}: collocation oscillation only {osc:.3} MPa");
        }
    }
}
