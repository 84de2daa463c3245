//! Coulomb friction with stick (issue 30, first step): a cylinder on a flat of the same
//! material under a tangential force below μP, against Cattaneo and Mindlin.

use wearfem::complementarity::{ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::partial_slip::{fitted_edge, PartialSlipError, TangentialProblem};
use wearfem::problem::Problem;

/// The tangential problem of `hertz` at degree `p` with μ = `friction`, and the contact
/// points' x, pressures (MPa), areas (mm²) and the total normal force (N).
struct Setup {
    a_tt: Vec<f64>,
    tangent_x: Vec<f64>,
    normal_force: Vec<f64>,
    x: Vec<f64>,
    pressure: Vec<f64>,
    area: Vec<f64>,
}

fn setup(p: usize) -> Setup {
    setup_with(p, &[])
}

/// [`setup`] of `hertz` with its text's `replacements` made.
fn setup_with(p: usize, replacements: &[(&str, &str)]) -> Setup {
    let mut text = wearfem::examples::example("hertz")
        .unwrap()
        .replace("p = 8", &format!("p = {p}"));
    for (from, to) in replacements {
        text = text.replace(from, to);
    }
    let problem = Problem::from_toml(&text, "hertz").unwrap();
    let (contact, body1, body2) = CondensedContact::build(&problem).unwrap();
    let (normal, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(info.status, Status::Solved);
    let area = contact.areas();
    Setup {
        a_tt: contact
            .tangential_flexibility(&problem, &body1, &body2)
            .unwrap(),
        tangent_x: contact.points.tangent.iter().map(|t| t[0]).collect(),
        normal_force: normal
            .pressure
            .iter()
            .zip(&area)
            .map(|(p, a)| p * a)
            .collect(),
        x: contact.points.x.iter().map(|x| x[0]).collect(),
        pressure: normal.pressure,
        area,
    }
}

impl Setup {
    fn problem(&self, friction: f64) -> TangentialProblem<'_> {
        TangentialProblem {
            a_tt: &self.a_tt,
            tangent_x: &self.tangent_x,
            normal_force: &self.normal_force,
            friction,
            coupling: None,
        }
    }
}

/// Mindlin and Deresiewicz: loaded to Q* and unloaded to Q, the outer annulus slips back:
/// c′ = a√(1 − (Q* − Q)/(2μP)), q = μp₀[√(1 − x²/a²) − 2(c′/a)√(1 − x²/c′²) + (c/a)√(1 −
/// x²/c²)] (each term inside its own zone), and inside c′ the change of the shear Δq = q − q* is
/// 2μp₀[√(1 − x²/a²) − (c′/a)√(1 − x²/c′²)] (2μp in the reversed slip zone), so
/// 2μp − Δq = 2μp₀ (c′/a)√(1 − x²/c′²) there and the line of its square against x² gives c′.
#[test]
fn unloading_slips_back_as_mindlin_and_deresiewicz_say() {
    let s = setup(12);
    let friction = 0.3;
    let problem = s.problem(friction);
    let total: f64 = s.normal_force.iter().sum();
    let (radius, load, modulus) = (500.0f64, 38.825 * 40.0, 2.0e5 / (1.0 - 0.09));
    let a = (4.0 * load * radius / (std::f64::consts::PI * modulus / 2.0)).sqrt();
    let p0 = 2.0 * load / (std::f64::consts::PI * a);
    for (peak, back) in [(0.6, 0.2), (0.8, -0.4), (0.5, 0.4)] {
        let loaded = problem.solve(peak * friction * total).unwrap();
        let unloaded = problem
            .solve_from(back * friction * total, Some(&loaded))
            .unwrap();
        let c = a * (1.0f64 - peak).sqrt();
        let c_back = a * (1.0f64 - (peak - back) / 2.0).sqrt();
        let change: Vec<f64> = (unloaded.force.iter().zip(&loaded.force))
            .zip(&s.area)
            .map(|((f, f0), area)| (f - f0) / area)
            .collect();
        let d: Vec<f64> = change
            .iter()
            .zip(&s.pressure)
            .map(|(dq, p)| 2.0 * friction * p - dq.abs())
            .collect();
        let fitted = fitted_edge(&s.x, &d, &unloaded.stick, c_back);
        // 1 % of a, the bound.
        assert!(
            (fitted - c_back).abs() < 0.01 * a,
            "Q* = {peak} μP → {back} μP: c′ = {fitted}, Mindlin–Deresiewicz {c_back}"
        );
        // The shear against the closed form, inside 0.9a (as for the loading) and a point
        // spacing (0.12 mm at p = 12 on 1 mm elements) away from the stick zones' edges c and
        // c′, where the closed form has a square-root kink that the discrete solution
        // resolves only to that spacing (3 % of μp₀ at the point next to c′ of the first
        // case; the edge itself is checked above).
        let closed = |x: f64| {
            let part = |r: f64| {
                if x.abs() < r {
                    (r / a) * (1.0 - x * x / (r * r)).sqrt()
                } else {
                    0.0
                }
            };
            friction * p0 * (part(a) - 2.0 * part(c_back) + part(c))
        };
        for ((xi, fi), area) in s.x.iter().zip(&unloaded.force).zip(&s.area) {
            let near_edge = (xi.abs() - c).abs() < 0.12 || (xi.abs() - c_back).abs() < 0.12;
            if xi.abs() <= 0.9 * a && !near_edge {
                let q = fi / area;
                // 2 % of μp₀, the bound for the shear.
                assert!(
                    (q - closed(*xi)).abs() < 0.02 * friction * p0,
                    "Q* = {peak} → {back}: q({xi}) = {q}, closed form {}",
                    closed(*xi)
                );
            }
        }
    }
}

/// The tangential solution of `hertz` (R = 500 mm, F = 1553 N/mm, steel on steel) under a
/// tangential force `ratio` μF, μ = `friction`: (x, shear traction q = F_t/area in MPa,
/// pressure p in MPa, stick flags).
fn cattaneo(ratio: f64, friction: f64, p: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<bool>) {
    let s = setup(p);
    let total: f64 = s.normal_force.iter().sum();
    let solution = s.problem(friction).solve(ratio * friction * total).unwrap();
    let q = solution
        .force
        .iter()
        .zip(&s.area)
        .map(|(f, a)| f / a)
        .collect();
    (s.x, q, s.pressure, solution.stick)
}

/// Cattaneo–Mindlin, a cylinder on a flat of the same material (plane strain), a tangential
/// force Q < μP after the normal load: the stick zone |x| < c = a√(1 − Q/(μP)) and the shear
/// traction q = −μp₀ [√(1 − x²/a²) − (c/a)√(1 − x²/c²)] (the friction on body 1 opposes the
/// load along +x; the second term inside the stick zone only).
#[test]
fn the_stick_zone_and_the_shear_are_cattaneos() {
    let (radius, load, modulus) = (500.0f64, 38.825 * 40.0, 2.0e5 / (1.0 - 0.09));
    // Two equal half-spaces, plane strain: E* = E'/2.
    let a = (4.0 * load * radius / (std::f64::consts::PI * modulus / 2.0)).sqrt();
    let p0 = 2.0 * load / (std::f64::consts::PI * a);
    for (ratio, friction) in [(0.5, 0.3), (0.2, 0.5), (0.8, 0.3)] {
        let (x, q, pressure, stick) = cattaneo(ratio, friction, 12);
        let c = a * (1.0f64 - ratio).sqrt();
        let closed = |x: f64| {
            let outer = if x.abs() < a {
                (1.0 - x * x / (a * a)).sqrt()
            } else {
                0.0
            };
            let inner = if x.abs() < c {
                (c / a) * (1.0 - x * x / (c * c)).sqrt()
            } else {
                0.0
            };
            -friction * p0 * (outer - inner)
        };
        for (xi, qi) in x.iter().zip(&q).filter(|(x, _)| x.abs() <= 0.9 * a) {
            // 2 % of μp₀, the bound, inside 0.9a as for Hertz's pressure (nearer the
            // zone's edge the slip zone's q = μp carries the normal solve's own error there,
            // 2.1 % of μp₀ at p = 12). Measured: 0.9–1.4 %, at the stick zone's edge, where
            // the shear has a kink between two contact points.
            assert!(
                (qi - closed(*xi)).abs() < 0.02 * friction * p0,
                "Q/μP = {ratio}, μ = {friction}: q({xi}) = {qi}, Cattaneo {}",
                closed(*xi)
            );
        }
        // The stick zone is symmetric and lies inside ±c, reaching to within a contact point
        // spacing of it.
        let inside: Vec<f64> = x
            .iter()
            .zip(&stick)
            .filter(|(_, s)| **s)
            .map(|(x, _)| *x)
            .collect();
        let (lo, hi) = (inside[0], inside[inside.len() - 1]);
        assert!(
            (lo + hi).abs() < 1e-9 * a && hi < c && hi > c - 0.1 * a,
            "{lo} … {hi}, c = {c}"
        );
        // The edge itself: μp − |q| = μp₀ (c/a) √(1 − x²/c²) inside the stick zone, so its
        // square is linear in x² and vanishes at x² = c²; the least-squares line through the
        // stick points of the zone's outer half gives c.
        let d: Vec<f64> = (pressure.iter().zip(&q))
            .map(|(p, q)| friction * p - q.abs())
            .collect();
        let fitted = fitted_edge(&x, &d, &stick, c);
        // 1 % of a, the bound; measured 0.15–0.42 %.
        assert!(
            (fitted - c).abs() < 0.01 * a,
            "Q/μP = {ratio}: c = {fitted}, Cattaneo {c}"
        );
    }
}

#[test]
fn a_load_at_the_friction_limit_is_gross_slip() {
    let s = setup(8);
    let total: f64 = s.normal_force.iter().sum();
    assert!(matches!(
        s.problem(0.3).solve(0.3 * total),
        Err(PartialSlipError::GrossSlip { .. })
    ));
    // Just below it, partial slip with a stick zone still there.
    let solution = s.problem(0.3).solve(0.99 * 0.3 * total).unwrap();
    assert!(solution.stick.iter().any(|&st| st));
}

/// A review's findings: a stage that changes the load by nothing (a dwell) settles with no
/// slip and the same forces (it cycled to the iteration limit), and a fretting cycle 0 → Q* → −Q* → Q* closes:
/// the third stage's state is the first's, the second its mirror image.
#[test]
fn a_dwell_settles_and_a_fretting_cycle_closes() {
    for p in [8, 12] {
        let s = setup(p);
        let problem = s.problem(0.3);
        let total: f64 = s.normal_force.iter().sum();
        let peak = 0.6 * 0.3 * total;
        let first = problem.solve(peak).unwrap();
        for again in [peak, peak * (1.0 - 1e-12)] {
            let dwell = problem.solve_from(again, Some(&first)).unwrap();
            // Nothing slips in a dwell (every loaded point sticks in it) and the forces stay:
            // round-off, the displacements some 1e-3 mm, the forces some 1e2 N, the solves
            // good to 1e-13 of them.
            assert!(dwell.slip.iter().all(|s| s.abs() < 1e-12), "p = {p}");
            let largest = first.force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
            for (f, f0) in dwell.force.iter().zip(&first.force) {
                assert!((f - f0).abs() < 1e-9 * largest, "p = {p}: {f} against {f0}");
            }
        }
        let back = problem.solve_from(-peak, Some(&first)).unwrap();
        let again = problem.solve_from(peak, Some(&back)).unwrap();
        let largest = first.force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
        for i in 0..first.force.len() {
            // 1e-9 of the largest force: a few dense solves' round-off.
            assert!((back.force[i] + first.force[i]).abs() < 1e-9 * largest);
            assert!((again.force[i] - first.force[i]).abs() < 1e-9 * largest);
        }
        assert_eq!(again.stick, first.stick);
    }
}

/// The energy a fretting cycle ±Q* dissipates, against the closed-form tractions and slips
/// integrated by quadrature. In a half cycle Q* → −Q* the shear changes by twice Cattaneo's
/// (Mindlin and Deresiewicz with c′ = c), so each point of c < |x| < a slips twice Cattaneo's
/// slip, |s(x)| = (μp₀/(E* a))[|x|√(x² − c²) − c² arcosh(|x|/c)] (the relative surface
/// displacement of two equal half-spaces, ds/dx = (2/(πE*)) PV∫ q(ξ)/(x − ξ) dξ, integrated
/// from the stick zone's edge), against |q| = μp: W = 4μ ∫_{c<|x|<a} p |s| dx per cycle and mm
/// of thickness.
///
/// `hertz` with half its load (a = 2 mm, on a mesh line), p = 12 and 16. At its own load
/// (a = 3 mm) the cycle dissipates 2.1–3.3 % less than the closed form: the slip in the slip
/// zone is 1.3–1.5 % below the half-space's there (the 200 × 100 mm lower block, meshed
/// coarsely beyond 6 mm, against a half-space), and at Q*/μP = 0.3 the slip zone is 0.16a wide
/// and carries four contact points (docs/fretting.md has the table).
#[test]
fn a_fretting_cycle_dissipates_what_the_closed_form_tractions_do() {
    use wearfem::fretting::{FrettingControl, FrettingCycle, FrettingLoading};
    let top = 17.2556;
    for p in [12, 16] {
        let s = setup_with(p, &[("normal = 38.825", &format!("normal = {top}"))]);
        let friction = 0.3;
        let problem = s.problem(friction);
        let total: f64 = s.normal_force.iter().sum();
        let (radius, load) = (500.0f64, top * 40.0);
        let e_star = 2.0e5 / (2.0 * (1.0 - 0.09));
        let a = (4.0 * load * radius / (std::f64::consts::PI * e_star)).sqrt();
        let p0 = 2.0 * load / (std::f64::consts::PI * a);
        for ratio in [0.6, 0.9] {
            let loading = FrettingLoading {
                control: FrettingControl::Force,
                amplitude: ratio * friction * total,
                stages: 16,
            };
            let cycle = FrettingCycle::solve(&problem, &loading).unwrap();
            let c = a * (1.0f64 - ratio).sqrt();
            // The midpoint rule on 4000 intervals of (c, a): the integrand vanishes at both
            // ends like (x − c)^(3/2) and √(a − x), so it is good to 1e-6 of the integral.
            let m = 4000;
            let h = (a - c) / m as f64;
            let integral: f64 = (0..m)
                .map(|k| {
                    let x = c + (k as f64 + 0.5) * h;
                    let pressure = p0 * (1.0 - x * x / (a * a)).sqrt();
                    let slip = friction * p0 / (e_star * a)
                        * (x * (x * x - c * c).sqrt() - c * c * (x / c).acosh());
                    pressure * slip * h
                })
                .sum();
            // Both sides of the contact.
            let closed = 4.0 * friction * 2.0 * integral;
            // 2 %, the bound; measured 0.8–1.2 % (the finite blocks' slip).
            assert!(
                (cycle.dissipated - closed).abs() < 0.02 * closed,
                "p = {p}, Q*/μP = {ratio}: {} N·mm dissipated, closed form {closed}",
                cycle.dissipated
            );
            // The loop's own area by the trapezoid rule on 33 points: within 1 % of it
            // (measured 0.5–0.7 %: the loop's ends bend within a stage).
            assert!(
                (cycle.loop_area - cycle.dissipated).abs() < 0.01 * cycle.dissipated,
                "loop {} against {}",
                cycle.loop_area,
                cycle.dissipated
            );
        }
    }
}

/// Displacement control: the peak shift of a force-controlled cycle imposed gives its peak
/// force back, and a shift beyond the gross-slip one slips every point at the friction limit.
#[test]
fn displacement_control_meets_force_control_and_reaches_gross_slip() {
    use wearfem::fretting::{FrettingControl, FrettingCycle, FrettingLoading};
    use wearfem::partial_slip::TangentialControl;
    let s = setup(8);
    let friction = 0.3;
    let problem = s.problem(friction);
    let total: f64 = s.normal_force.iter().sum();
    let forced = problem.solve(0.6 * friction * total).unwrap();
    let held = problem
        .solve_stage(TangentialControl::Displacement(forced.shift), None)
        .unwrap();
    // Round-off of two dense solves of the same system.
    assert!((held.load - forced.load).abs() < 1e-9 * forced.load.abs());
    assert_eq!(held.stick, forced.stick);
    let loading = FrettingLoading {
        control: FrettingControl::Displacement,
        amplitude: 10.0 * forced.shift.abs(),
        stages: 8,
    };
    let cycle = FrettingCycle::solve(&problem, &loading).unwrap();
    assert!(cycle.gross_slip && cycle.never_slips.iter().all(|s| !s));
    // At the peak every point slips at μP: the load is the limit, to round-off.
    let limit = friction * total;
    assert!((cycle.states[0].load.abs() - limit).abs() < 1e-12 * limit);
}

/// Refinement: the stick zone's edge (Q = 0.5 μP, μ = 0.3) as the degree rises, against
/// Cattaneo's c = a√(1 − Q/(μP)); docs/fretting.md has the table this prints.
#[test]
fn the_stick_zone_edge_converges_as_the_contact_is_refined() {
    let (radius, load, modulus) = (500.0f64, 38.825 * 40.0, 2.0e5 / (1.0 - 0.09));
    let a = (4.0 * load * radius / (std::f64::consts::PI * modulus / 2.0)).sqrt();
    let c = a * 0.5f64.sqrt();
    let mut errors = Vec::new();
    for p in [4, 6, 8, 10, 12, 14] {
        let (x, q, pressure, stick) = cattaneo(0.5, 0.3, p);
        let d: Vec<f64> = (pressure.iter().zip(&q))
            .map(|(p, q)| 0.3 * p - q.abs())
            .collect();
        let fitted = fitted_edge(&x, &d, &stick, c);
        let points = stick.len();
        eprintln!(
            "p = {p:2}: {points} contact points, c = {fitted:.5} mm, error {:.3} % of a",
            100.0 * (fitted - c).abs() / a
        );
        errors.push((fitted - c).abs() / a);
    }
    // From p = 8 on within the 1 % of a, and the finest at least three times closer
    // than the coarsest (the edge of the finite blocks' own solution, not the half-space's,
    // is what the fit converges to, so the error levels off near 0.1–0.4 %).
    assert!(errors[2..].iter().all(|e| *e < 0.01), "{errors:?}");
    assert!(errors[5] < errors[0] / 3.0, "{errors:?}");
}
