//! The validation cases of axisymmetric bodies (issue 31): Lamé's thick tube with free ends
//! and a hollow sphere under internal pressure, Hertz's ball, Sneddon's punch, and the thrust
//! washer turning about its axis (uniform wear, torque, Archard). The bounds are those of
//! tests/axisymmetric.rs, tests/axisymmetric_contact.rs and tests/axisymmetric_wear.rs.

use super::cases::{fail, push, Checks, Outcome};
use super::Bound;
use crate::driver;
use crate::problem::Problem;

const YOUNG: f64 = 2.0e5;
const POISSON: f64 = 0.3;

/// A steel tube (a = 10, b = 20 mm, 20 mm long, held in z on its mid-plane) under 100 MPa
/// inside, its ends free: u_r = r/E ((1 − ν)A + (1 + ν)B/r²), σ_θθ = A + B/r², the exact 3D
/// solution (A = pa²/(b² − a²), B = pa²b²/(b² − a²)).
pub fn tube(checks: &mut Checks) -> Outcome {
    let text = format!(
        "title = \"tube\"\n[analysis]\nkind = \"axisymmetric\"\np = 8\n\
        [materials.steel]\nyoung = {YOUNG}\npoisson = {POISSON}\n\
        [[bodies]]\nname = \"tube\"\n[[bodies.blocks]]\n\
        corners = [[10.0, 0.0], [20.0, 0.0], [20.0, 10.0], [10.0, 10.0]]\nu = 4\nv = 2\n\
        material = \"steel\"\nnames = {{ bottom = \"mid\", left = \"bore\" }}\n\
        [[bodies.tractions]]\nedge = \"bore\"\nnormal = 100.0\n\
        [[bodies.supports]]\nedge = \"mid\"\nfix = [\"z\"]\n\
        [probes]\nbore = {{ body = \"tube\", at = [10.0, 5.0] }}\n\
        outside = {{ body = \"tube\", at = [20.0, 5.0] }}\n"
    );
    let p = Problem::from_toml(&text, "axisymmetric-tube").map_err(|e| fail("tube", e))?;
    let result = driver::elastic(&p).map_err(|e| fail("tube", e))?;
    let (a, b, pressure) = (10.0f64, 20.0f64, 100.0);
    let big_a = pressure * a * a / (b * b - a * a);
    let big_b = pressure * a * a * b * b / (b * b - a * a);
    for (name, r) in [("bore", a), ("outside", b)] {
        let probe = &result["probes"][name];
        let u = probe["displacement"][0].as_f64().unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.tube_{name}"),
            format!("axisymmetric tube with free ends under internal pressure: u_r at r = {r} mm (p = 8)"),
            "mm",
            r / YOUNG * ((1.0 - POISSON) * big_a + (1.0 + POISSON) * big_b / (r * r)),
            "Lamé, free ends (σ_zz = 0)",
            u,
            Bound::Relative(1e-8),
        );
        let hoop = probe["hoop_stress"].as_f64().unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.tube_hoop_{name}"),
            format!("the same tube: hoop stress σ_θθ at r = {r} mm"),
            "MPa",
            big_a + big_b / (r * r),
            "Lamé: A + B/r²",
            hoop,
            Bound::Relative(1e-6),
        );
    }
    Ok(())
}

/// A hollow steel sphere (a = 10, b = 20 mm; a quarter of its meridian section, exact arcs,
/// the axis condition implied) under 100 MPa inside:
/// u_R = p a³/(E (b³ − a³)) ((1 − 2ν) R + (1 + ν) b³/(2R²)).
pub fn sphere(checks: &mut Checks) -> Outcome {
    let text = format!(
        "title = \"sphere\"\n[analysis]\nkind = \"axisymmetric\"\np = 8\n\
        [materials.steel]\nyoung = {YOUNG}\npoisson = {POISSON}\n\
        [[bodies]]\nname = \"sphere\"\n[[bodies.blocks]]\n\
        corners = [[10.0, 0.0], [20.0, 0.0], [0.0, 20.0], [0.0, 10.0]]\n\
        arcs = [{{ edge = 1, center = [0.0, 0.0] }}, {{ edge = 3, center = [0.0, 0.0] }}]\n\
        u = 4\nv = 4\nmaterial = \"steel\"\nnames = {{ bottom = \"equator\", left = \"bore\" }}\n\
        [[bodies.tractions]]\nedge = \"bore\"\nnormal = 100.0\n\
        [[bodies.supports]]\nedge = \"equator\"\nfix = [\"z\"]\n\
        [probes]\npole = {{ body = \"sphere\", at = [0.0, 10.0] }}\n\
        equator = {{ body = \"sphere\", at = [20.0, 0.0] }}\n"
    );
    let p = Problem::from_toml(&text, "axisymmetric-sphere").map_err(|e| fail("sphere", e))?;
    let result = driver::elastic(&p).map_err(|e| fail("sphere", e))?;
    let (a, b, pressure) = (10.0f64, 20.0f64, 100.0);
    let radial = |radius: f64| {
        pressure * a.powi(3) / (YOUNG * (b.powi(3) - a.powi(3)))
            * ((1.0 - 2.0 * POISSON) * radius
                + (1.0 + POISSON) * b.powi(3) / (2.0 * radius * radius))
    };
    for (name, component, radius, what) in [
        ("pole", 1, a, "u_z at the inner pole (on the axis)"),
        ("equator", 0, b, "u_r at the outer equator"),
    ] {
        let u = result["probes"][name]["displacement"][component]
            .as_f64()
            .unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.sphere_{name}"),
            format!("axisymmetric hollow sphere under internal pressure: {what} (p = 8)"),
            "mm",
            radial(radius),
            "Lamé's sphere",
            u,
            Bound::Relative(1e-8),
        );
    }
    Ok(())
}

/// The first contact of a built-in example: contact points' r (mm), pressures (MPa) and the
/// plate's motion λ_F (mm).
fn first_contact(name: &str) -> Result<(Vec<f64>, Vec<f64>, f64), super::ValidateError> {
    use crate::complementarity::{ContactSolver, Direction, Method, Status};
    let p = super::cases::problem(name, &[])?;
    let (contact, _, _) = crate::contact::CondensedContact::build(&p).map_err(|e| fail(name, e))?;
    let (solution, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    if info.status != Status::Solved {
        return Err(fail(name, "the contact solve failed"));
    }
    let r = contact.points.x.iter().map(|x| x[0]).collect();
    Ok((r, solution.pressure, solution.rigid[0]))
}

/// The built-in `ball-on-flat`: a steel ball (R = 5 mm) on a steel flat with 10 N, Hertz's
/// p₀ = 3P/(2πa²) at the axis and a³ = 3PR/(4E*), the zone's radius measured where the
/// least-squares line of p² against r² (inside 0.9 of the zone) reaches zero.
pub fn ball(checks: &mut Checks) -> Outcome {
    let (r, pressure, _) = first_contact("ball-on-flat")?;
    let (force, radius) = (10.0, 5.0);
    let modulus = YOUNG / (2.0 * (1.0 - POISSON * POISSON));
    let a = (3.0 * force * radius / (4.0 * modulus)).cbrt();
    let p0 = 3.0 * force / (2.0 * std::f64::consts::PI * a * a);
    push(
        checks,
        "axisymmetric.hertz_p0",
        "ball-on-flat (p = 8): the pressure on the axis",
        "MPa",
        p0,
        "Hertz: 3P/(2πa²)",
        pressure[0],
        Bound::Relative(0.01),
    );
    let last = pressure.iter().rposition(|&p| p > 0.0).unwrap_or(0);
    let inside = (r.iter().zip(&pressure))
        .filter(|(ri, _)| **ri < 0.9 * r[last])
        .map(|(ri, pi)| (*ri, *pi));
    let measured = crate::checks::edge_fit::square_root_edge(inside);
    push(
        checks,
        "axisymmetric.hertz_a",
        "ball-on-flat: the contact radius (where p² against r² reaches zero)",
        "mm",
        a,
        "Hertz: a³ = 3PR/(4E*)",
        measured,
        Bound::Relative(0.01),
    );
    Ok(())
}

/// The built-in `axisymmetric-punch`: a rigid flat-ended cylinder (a = 1 mm, 1000 N) on a
/// block 200a across and deep: Sneddon's pressure at r = a/2 and indentation.
pub fn punch(checks: &mut Checks) -> Outcome {
    let (r, pressure, approach) = first_contact("axisymmetric-punch")?;
    let (force, a, young, poisson) = (1000.0, 1.0, 1.0e5, 0.3);
    // The contact point nearest r = a/2.
    let near = (0..r.len())
        .min_by(|&i, &j| (r[i] - 0.5 * a).abs().total_cmp(&(r[j] - 0.5 * a).abs()))
        .unwrap_or(0);
    push(
        checks,
        "axisymmetric.sneddon_pressure",
        format!(
            "axisymmetric-punch (p = 8): the pressure at r = {:.4} mm",
            r[near]
        ),
        "MPa",
        force / (2.0 * std::f64::consts::PI * a * (a * a - r[near] * r[near]).sqrt()),
        "Sneddon: P/(2πa√(a² − r²))",
        pressure[near],
        Bound::Relative(0.01),
    );
    push(
        checks,
        "axisymmetric.sneddon_indentation",
        "axisymmetric-punch: the indentation (the plate's λ_F)",
        "mm",
        force * (1.0 - poisson * poisson) / (2.0 * a * young),
        "Sneddon: P(1 − ν²)/(2aE), half-space",
        approach,
        Bound::Relative(0.01),
    );
    Ok(())
}

/// The built-in `thrust-washer` (r = 10 … 20 mm, F = 2000 N, ω = 10 rad/s, μ = 0.3), turning
/// about its axis: the steady pressure makes pᵇ rᵃ uniform, with the constant the load sets
/// (a = b = 1: p r = F/(2π(r_o − r_i)); a = 2, b = 1: p r² = F/(2π ln(r_o/r_i))); the run's
/// torque tends to μF(r_o + r_i)/2, and its worn volume is Archard's β̃ ∫∫ p ω r dA dt. The
/// bounds are tests/axisymmetric_wear.rs's.
pub fn washer(checks: &mut Checks) -> Outcome {
    let (inner, outer, force, friction) = (10.0f64, 20.0f64, 2000.0, 0.3);
    let laws = [
        ("1", "{ beta = 1.0e-8, a = 1.0, b = 1.0 }", 1.0, "N/mm", {
            force / (std::f64::consts::TAU * (outer - inner))
        }),
        ("2", "{ beta = 1.0e-10, a = 2.0, b = 1.0 }", 2.0, "N", {
            force / (std::f64::consts::TAU * (outer / inner).ln())
        }),
    ];
    for (id, law, a, unit, constant) in laws {
        let p = super::cases::problem(
            "thrust-washer",
            &[("{ beta = 1.0e-8, a = 1.0, b = 1.0 }", law)],
        )?;
        let (state, contact, _) = driver::steady(&p).map_err(|e| fail("thrust-washer", e))?;
        if state.status != crate::steady::SteadyStatus::Solved {
            return Err(fail("thrust-washer", "the steady state was not found"));
        }
        // The point whose p rᵃ lies farthest from the closed form.
        let worst = (contact.points.x.iter().zip(&state.p_plus))
            .map(|(x, pressure)| pressure * x[0].powf(a))
            .max_by(|u, v| (u - constant).abs().total_cmp(&(v - constant).abs()))
            .unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.washer_uniform_wear_a{id}"),
            format!(
                "thrust-washer turning, a = {a}, b = 1: the steady p r^{a} farthest from uniform"
            ),
            unit,
            constant,
            format!("uniform wear: F = ∫ p 2πr dr with p r^{a} constant"),
            worst,
            Bound::Relative(1e-8),
        );
    }
    let p = super::cases::problem("thrust-washer", &[])?;
    let run = super::cases::wear(&p, None)?;
    let torque = run.history.steps.last().and_then(|s| s.torque);
    push(
        checks,
        "axisymmetric.washer_torque",
        "thrust-washer, the run's last step: the friction torque about the axis",
        "N·mm",
        friction * force * (outer + inner) / 2.0,
        "uniform wear: μF(r_o + r_i)/2",
        torque.unwrap_or(f64::NAN),
        Bound::Relative(0.01),
    );
    // Each step holds its pressure over k step units of 5 s at 10 rad/s.
    let archard: f64 = (run.history.steps.iter())
        .map(|s| 1.0e-8 * s.k as f64 * 50.0 * s.torque.unwrap_or(f64::NAN) / friction)
        .sum();
    let worn = crate::wear::worn_volume(
        &run.contact.points,
        &run.history.body_wear[0],
        run.contact.thickness,
    );
    push(
        checks,
        "axisymmetric.washer_archard",
        "thrust-washer: the washer's worn volume 2π∫ w r dr",
        "mm³",
        archard,
        "Archard: β̃ ∫∫ p ω r dA dt",
        worn,
        Bound::Relative(1e-6),
    );
    Ok(())
}
