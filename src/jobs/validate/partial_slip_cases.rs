//! The validation cases of stick and partial slip (issue 30, first step): Cattaneo and
//! Mindlin's stick zone under a tangential force below μP, and Mindlin and Deresiewicz's
//! reversed slip on unloading, on the built-in `hertz` at p = 12 (a cylinder on a flat of the
//! same steel). The bounds are tests/partial_slip.rs's.

use super::cases::{fail, push, Checks, Outcome};
use super::Bound;
use crate::complementarity::{ContactSolver, Direction, Method, Status};
use crate::contact::CondensedContact;
use crate::partial_slip::{fitted_edge, TangentialProblem};

/// `hertz` (with `edits`) pressed by its normal load without friction: the normal forces
/// (N), pressures (MPa), areas (mm²), A_tt (mm/N), the points' x (mm) and τ_x.
pub(super) struct PressedHertz {
    pub force: Vec<f64>,
    pub pressure: Vec<f64>,
    pub area: Vec<f64>,
    pub a_tt: Vec<f64>,
    pub x: Vec<f64>,
    pub tangent_x: Vec<f64>,
}

impl PressedHertz {
    pub(super) fn new(edits: &[(&str, &str)]) -> Result<PressedHertz, super::ValidateError> {
        let p = super::cases::problem("hertz", edits)?;
        let (contact, body1, body2) = CondensedContact::build(&p).map_err(|e| fail("hertz", e))?;
        let (normal, info) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        if info.status != Status::Solved {
            return Err(fail("hertz", "the normal contact solve failed"));
        }
        let a_tt = contact
            .tangential_flexibility(&p, &body1, &body2)
            .map_err(|e| fail("hertz", e))?;
        let area = contact.areas();
        let force = (normal.pressure.iter().zip(&area))
            .map(|(p, a)| p * a)
            .collect();
        Ok(PressedHertz {
            force,
            pressure: normal.pressure,
            area,
            a_tt,
            x: contact.points.x.iter().map(|x| x[0]).collect(),
            tangent_x: contact.points.tangent.iter().map(|t| t[0]).collect(),
        })
    }

    /// The tangential problem at friction coefficient `friction`, uncoupled.
    pub(super) fn problem(&self, friction: f64) -> TangentialProblem<'_> {
        TangentialProblem {
            a_tt: &self.a_tt,
            tangent_x: &self.tangent_x,
            normal_force: &self.force,
            friction,
            coupling: None,
        }
    }
}

/// Loaded to Q* = 0.6 μP, then back to 0.2 μP, μ = 0.3: c = a√(1 − Q*/μP) and
/// c′ = a√(1 − (Q* − Q)/(2μP)), each from the line of d² against x² (d = μp − |q| while
/// loading, 2μp − |Δq| on unloading).
pub fn cattaneo(checks: &mut Checks) -> Outcome {
    let hertz = PressedHertz::new(&[("p = 8", "p = 12")])?;
    let (x, area, force) = (&hertz.x, &hertz.area, &hertz.force);
    let friction = 0.3;
    let problem = hertz.problem(friction);
    let total: f64 = force.iter().sum();
    let (peak, back) = (0.6, 0.2);
    let loaded = problem
        .solve(peak * friction * total)
        .map_err(|e| fail("hertz", e))?;
    let unloaded = problem
        .solve_from(back * friction * total, Some(&loaded))
        .map_err(|e| fail("hertz", e))?;
    let (radius, load, modulus) = (500.0f64, 38.825 * 40.0, 2.0e5 / (1.0 - 0.09));
    let a = (4.0 * load * radius / (std::f64::consts::PI * modulus / 2.0)).sqrt();
    let c = a * (1.0f64 - peak).sqrt();
    let c_back = a * (1.0f64 - (peak - back) / 2.0).sqrt();
    let d: Vec<f64> = (loaded.force.iter().zip(area).zip(&hertz.pressure))
        .map(|((f, a), p)| friction * p - (f / a).abs())
        .collect();
    push(
        checks,
        "partial_slip.cattaneo_c",
        "hertz (p = 12) under Q = 0.6 μP, μ = 0.3: the stick zone's half-width",
        "mm",
        c,
        "Cattaneo–Mindlin: a√(1 − Q/(μP))",
        fitted_edge(x, &d, &loaded.stick, c),
        Bound::Absolute(0.01 * a),
    );
    let d: Vec<f64> = ((unloaded.force.iter().zip(&loaded.force)).zip(area))
        .zip(&hertz.pressure)
        .map(|(((f, f0), a), p)| 2.0 * friction * p - ((f - f0) / a).abs())
        .collect();
    push(
        checks,
        "partial_slip.mindlin_deresiewicz_c",
        "the same, unloaded to Q = 0.2 μP: the half-width of the zone that does not slip back",
        "mm",
        c_back,
        "Mindlin–Deresiewicz: a√(1 − (Q* − Q)/(2μP))",
        fitted_edge(x, &d, &unloaded.stick, c_back),
        Bound::Absolute(0.01 * a),
    );
    Ok(())
}
