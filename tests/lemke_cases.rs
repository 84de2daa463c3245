//! Solvable contacts on which Lemke's method (`contact.method = "lemke"`, and the active
//! set's fallback) failed or was inexact, found by red team 16's fuzz campaign of random worn
//! shapes (docs/validation.md, sixteenth review). Each worn gap (mm, round-trip exact floats)
//! is in tests/lemke-cases/*.gap. The active set's solution is checked independently of its
//! own residuals, and Lemke's method must find the same pressures. All five failed before the
//! plate's motions were scaled in Lemke's tableau.

use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::overrides::Override;
use wearfem::problem::Problem;

fn build(text: &str, sets: &[&str]) -> CondensedContact {
    let sets: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    let problem = Problem::with_overrides(text, "case", &sets).unwrap();
    CondensedContact::build(&problem).unwrap().0
}

fn gap(name: &str) -> Vec<f64> {
    std::fs::read_to_string(format!(
        "{}/tests/lemke-cases/{name}.gap",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
    .lines()
    .map(|l| l.parse().unwrap())
    .collect()
}

/// Active set and Lemke on one case: the active set's solution is checked independently
/// (p ≥ 0, d ≥ 0, p d = 0 with d recomputed from A_nn, A_nt, R; plate balance), then Lemke
/// must give the same pressures.
fn check(c: &CondensedContact, g: &[f64], dir: Direction) {
    let (exact, info) = ContactSolver::new(c, Method::ActiveSet).solve(g, dir);
    assert_eq!(info.status, Status::Solved);
    let n = c.len();
    let s = dir.sign();
    let peak = exact.pressure.iter().cloned().fold(0.0, f64::max);
    for (i, &gap_i) in g.iter().enumerate() {
        let mut d = gap_i;
        for j in 0..n {
            d += (c.a_nn[i * n + j] - s * c.friction * c.a_nt[i * n + j]) * exact.force[j];
        }
        for k in 0..c.rigid_modes.len() {
            let (phi, nn) = (c.rigid_modes[k][i], c.points.normal[i]);
            d -= (nn[0] * phi[0] + nn[1] * phi[1]) * exact.rigid[k];
        }
        // The gap as a pressure through the point's own compliance; 1e-9 of the peak is the
        // round-off of a sum of n ≈ 65 products against the solver's accepted 1e-10.
        let dp = d / (c.a_nn[i * n + i] * c.areas()[i]);
        assert!(exact.pressure[i] >= -1e-12 * peak && dp >= -1e-9 * peak);
        assert!(exact.pressure[i].min(dp).abs() < 1e-9 * peak);
    }
    let (lemke, linfo) = ContactSolver::new(c, Method::Lemke).solve(g, dir);
    assert_eq!(
        linfo.status,
        Status::Solved,
        "Lemke on a solvable case: {linfo:?}"
    );
    // Two solutions of one LCP, each within the accepted residual: they agree to its
    // round-off, and a negative pressure is not round-off beyond 1e-10 of the peak.
    for (a, b) in exact.pressure.iter().zip(&lemke.pressure) {
        assert!((a - b).abs() < 1e-8 * peak, "{a} vs {b}");
        assert!(
            *b >= -1e-10 * peak,
            "Lemke accepted a negative pressure {b} (peak {peak})"
        );
    }
}

fn b20() -> String {
    wearfem::examples::example("punch-b20").unwrap().to_string()
}

/// Frictionless (M positive semi-definite, where Lemke's method is guaranteed in exact
/// arithmetic): punch-b20 in plane strain with ν = 0.49, a steep tilt (the plate's rotation
/// takes it up). Lemke ends on a secondary ray after 143 pivots.
#[test]
fn frictionless_lemke_ray() {
    let c = build(
        &b20(),
        &[
            "contact.friction=0.0",
            "materials.steel.poisson=0.49",
            "materials.composite.poisson=0.49",
            "analysis.kind=\"plane_strain\"",
        ],
    );
    check(&c, &gap("b20-nu049-strain-mu0-44-plus"), Direction::Plus);
}

/// punch-b20 exactly as shipped (μ = 0.25, collocation) with a tilted worn shape: Lemke
/// ends on a ray ('−') — `contact.method = "lemke"` reports a solvable contact as failed.
#[test]
fn punch_b20_lemke_ray_minus() {
    let c = build(&b20(), &[]);
    check(
        &c,
        &gap("b20-mu0.25-collocation-37-minus"),
        Direction::Minus,
    );
}

/// Same shape, '+': Lemke runs out of pivots (3450).
#[test]
fn punch_b20_lemke_max_pivots_plus() {
    let c = build(&b20(), &[]);
    check(&c, &gap("b20-mu0.25-collocation-37-plus"), Direction::Plus);
}

/// punch-b20 scaled by 7 (every length; findings/punch-b20-x7.toml) with a smooth worn
/// shape: Lemke's path stops early (z₀ leaves at 1e-12 in its normalised units), the
/// polished result has complementarity 3e-3 and the solve is reported failed. The same case
/// unscaled is solved by Lemke.
#[test]
fn scaled_model_lemke_stops_early() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/lemke-cases/punch-b20-x7.toml"
    ))
    .unwrap();
    let c = build(&text, &[]);
    check(
        &c,
        &gap("b20-mu0.25-collocation-T0_0-k7-0-minus"),
        Direction::Minus,
    );
}

/// brake, μ = 0.5: Lemke's answer is accepted (complementarity 2.8e-7 < 1e-6) with a
/// pressure of −2.8e-7 of the peak; the active set's is exact.
#[test]
fn brake_lemke_accepts_negative_pressure() {
    let c = build(
        wearfem::examples::example("brake").unwrap(),
        &["contact.friction=0.5"],
    );
    check(&c, &gap("brake-mu0.5-426-minus"), Direction::Minus);
}
