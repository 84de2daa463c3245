//! The validation cases: each computes our value and sets it beside its reference. This file
//! holds the shared helpers and the elastic and contact cases; the wear and steady-state cases
//! are in `wear_cases.rs`.
//!
//! References are closed forms evaluated here (Lamé, Hertz, eq. 19, 23, A.15, moment
//! equilibrium) or numbers printed in the paper (Table 2, §5.1.1); bounds are those of the
//! tests that assert the same claims (docs/validation.md gives the reasons).

use super::{Bound, Check, ValidateError};
use crate::complementarity::{ContactSolver, Direction, Method, Status};
use crate::contact::CondensedContact;
use crate::driver::{self, WearRun};
use crate::problem::Problem;

pub(super) type Checks = Vec<Check>;
pub(super) type Outcome = Result<(), ValidateError>;

pub(super) fn fail(case: &str, message: impl std::fmt::Display) -> ValidateError {
    ValidateError::Setup {
        case: case.to_string(),
        message: message.to_string(),
    }
}

/// Built-in example `name` with each (from, to) text edit applied.
pub(super) fn problem(name: &str, edits: &[(&str, &str)]) -> Result<Problem, ValidateError> {
    let mut text = crate::examples::example(name)
        .ok_or_else(|| fail(name, "no such built-in example"))?
        .to_string();
    for (from, to) in edits {
        if !text.contains(from) {
            return Err(fail(name, format!("'{from}' is not in the file")));
        }
        text = text.replace(from, to);
    }
    Problem::from_toml(&text, name).map_err(|e| fail(name, e))
}

pub(super) fn wear(p: &Problem, steps: Option<usize>) -> Result<WearRun, ValidateError> {
    let run = driver::wear(p, steps, |_| {}).map_err(|e| fail(&p.file, e))?;
    if run.history.failed_solves > 0 {
        return Err(fail(&p.file, "a contact solve failed during the wear run"));
    }
    Ok(run)
}

#[allow(clippy::too_many_arguments)]
pub(super) fn push(
    checks: &mut Checks,
    id: impl Into<String>,
    quantity: impl Into<String>,
    unit: &'static str,
    reference: f64,
    source: impl Into<String>,
    ours: f64,
    bound: Bound,
) {
    checks.push(Check {
        id: id.into(),
        quantity: quantity.into(),
        unit,
        reference,
        source: source.into(),
        ours,
        bound,
    });
}

/// Lamé: u_r of the thick cylinder a = 100, b = 200 mm, p = 100 MPa, E = 2e5 MPa, ν = 0.3
/// (plane strain), and the energy-norm error's fall with p.
pub fn elastic(checks: &mut Checks) -> Outcome {
    let exact = |r: f64| {
        let (a, b, p, e, nu) = (100.0f64, 200.0f64, 100.0f64, 2.0e5f64, 0.3f64);
        let (ca, cb) = (
            p * a * a / (b * b - a * a),
            p * a * a * b * b / (b * b - a * a),
        );
        (1.0 + nu) / e * ((1.0 - 2.0 * nu) * ca * r + cb / r)
    };
    let lame = driver::elastic(&problem("lame", &[])?).map_err(|e| fail("lame", e))?;
    for (name, r) in [("inner", 100.0), ("outer", 200.0)] {
        let u = lame["probes"][name]["displacement"][0]
            .as_f64()
            .unwrap_or(f64::NAN);
        // 1e-7: the arcs are mapped exactly and p = 8 resolves the 1/r field to ~1e-12.
        push(
            checks,
            format!("lame.{name}"),
            format!("Lamé cylinder: u_r at r = {r} mm (p = 8)"),
            "mm",
            exact(r),
            "closed form (Lamé)",
            u,
            Bound::Relative(1e-7),
        );
    }
    // Exact strain energy U = ½ p u_r(a) (π a / 2) t (quarter ring, t = 1 mm).
    let u_exact = 0.5 * 100.0 * exact(100.0) * std::f64::consts::FRAC_PI_2 * 100.0;
    let mut errors = vec![];
    for p in [4, 6, 8] {
        let degree = format!("p = {p}");
        let pr = problem("lame", &[("p = 8", &degree)])?;
        let body = pr.elastic_body(0, &[]).map_err(|e| fail("lame", e))?;
        let load = pr.load_vector(0, &body, &[]).map_err(|e| fail("lame", e))?;
        let energy =
            crate::fields::strain_energy(&load, &body.solve(&load).map_err(|e| fail("lame", e))?);
        errors.push(((u_exact - energy) / u_exact).max(0.0).sqrt());
    }
    let ratio = (errors[0] / errors[1]).min(errors[1] / errors[2]);
    push(
        checks,
        "lame.p_convergence",
        "Lamé: fall of the energy-norm error per two degrees (p = 4 → 6 → 8, smaller)",
        "",
        10.0,
        "exponential convergence of the p-version (docs/convergence.md)",
        ratio,
        Bound::AtLeast,
    );
    Ok(())
}

/// Hertz line contact (built-in example `hertz`): a cylinder R = 500 mm on a block, both
/// steel, F = 38.825 · 40 N/mm: peak pressure p₀ = 2F/(π a) and half-width a = √(4 F R / (π E*)).
pub fn hertz(checks: &mut Checks) -> Outcome {
    for kind in ["plane_strain", "plane_stress"] {
        let pr = problem(
            "hertz",
            &[("kind = \"plane_strain\"", &format!("kind = \"{kind}\""))],
        )?;
        let (contact, _, _) = CondensedContact::build(&pr).map_err(|e| fail("hertz", e))?;
        let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        if info.status != Status::Solved {
            return Err(fail("hertz", "the contact solve failed"));
        }
        let force = 38.825 * 40.0;
        let e_one = if kind == "plane_strain" {
            2.0e5 / (1.0 - 0.09)
        } else {
            2.0e5
        };
        let e_star = e_one / 2.0; // two equal bodies: 1/E* = 2/E'
        let a = (4.0 * force * 500.0 / (std::f64::consts::PI * e_star)).sqrt();
        let p0 = 2.0 * force / (std::f64::consts::PI * a);
        let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
        let a_fit = super::hertz_half_width(&contact, &sol);
        let label = kind.replace('_', " ");
        // 2 %: the finite bodies (2a ≈ 6 mm against 40 and 100 mm) stiffen the response by
        // well under that.
        push(
            checks,
            format!("hertz.{kind}.peak"),
            format!("Hertz line contact ({label}): peak pressure"),
            "MPa",
            p0,
            "Hertz: p₀ = 2F/(πa)",
            peak,
            Bound::Relative(0.02),
        );
        push(
            checks,
            format!("hertz.{kind}.half_width"),
            format!("Hertz line contact ({label}): half-width"),
            "mm",
            a,
            "Hertz: a = √(4FR/(πE*))",
            a_fit,
            Bound::Relative(0.02),
        );
    }
    Ok(())
}

/// First contact solve of the pinned punch: moment equilibrium about the pin (eq. 8) puts the
/// pressure centre at 1100 − s μ l_z.
pub fn first_solve(checks: &mut Checks) -> Outcome {
    for (name, lz) in [("punch-b20", 20.0), ("punch-b40", 40.0)] {
        let (contact, _, _) =
            CondensedContact::build(&problem(name, &[])?).map_err(|e| fail(name, e))?;
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        for dir in [Direction::Plus, Direction::Minus] {
            let (sol, _) = solver.solve(&contact.points.initial_gap, dir);
            let total: f64 = sol.force.iter().sum();
            let centre = contact
                .points
                .x
                .iter()
                .zip(&sol.force)
                .map(|(x, f)| x[0] * f)
                .sum::<f64>()
                / total;
            // 1e-6 mm: equilibrium holds to round-off (≈1e-10 mm).
            push(
                checks,
                format!(
                    "{name}.centre.{}",
                    if dir == Direction::Plus {
                        "plus"
                    } else {
                        "minus"
                    }
                ),
                format!("{name}, first solve, '{}': pressure centre x", dir.symbol()),
                "mm",
                1100.0 - dir.sign() * 0.25 * lz,
                "eq. 8: 1100 ∓ μ l_z",
                centre,
                Bound::Absolute(1e-6),
            );
        }
    }
    Ok(())
}
