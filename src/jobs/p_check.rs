//! The check of a result's resolution in p: the first contact solve made again with every
//! body's degree raised by [`P_RAISE`], compared away from the zone's ends.
//!
//! The mesh checks of [`crate::contact`] look along the contact edge (element lengths, zone
//! ends, steps in length). They cannot see a body 2 that is coarse *in depth*: a nearly rigid
//! 40 mm punch on a block meshed in 125 mm layers gave a centre pressure 6.3 % below the
//! half-plane value 6.366 MPa, the same to 2e-4 for 8, 32 and 128 contact elements, with no
//! warning (red team 11). Refining the contact edge looked converged; raising p did not. The
//! p-version's own error indicator is that: the change of the result when p is raised.
//!
//! The comparison leaves out a tenth of the zone at each end. A punch's corner is singular,
//! and its pressure there grows with every p on any mesh (punch-b40 on the paper's mesh
//! changes by 15 % of its peak there from p = 8 to 10), while inside the zone it changes by
//! 1.2 % of the mean pressure; the coarse-in-depth block above changes by 2.8 % there.

use crate::complementarity::{ContactSolver, Status};
use crate::contact::CondensedContact;
use crate::problem::Problem;

/// How much the check raises every degree (at most to 20). By 2, not 1: with p + 1 the
/// contact points of odd and even degrees interleave differently, and punch-b40 changed by
/// 8 % inside its zone from p = 8 to 9 but 1.2 % from 8 to 10.
pub const P_RAISE: usize = 2;

/// Largest change of the pressure inside the zone (a tenth of the zone from either end left
/// out), relative to its mean pressure, that passes without a warning. The shipped examples
/// change by at most 1.5 % (punch-b40-variant3; `tests/p_check.rs`, docs/validation.md,
/// "Convergence in p").
pub const P_CHANGE_LIMIT: f64 = 0.02;

/// Highest degree the problem files accept.
const MAX_DEGREE: usize = 20;

/// What the check measured.
#[derive(Clone, Debug, PartialEq)]
pub struct PCheck {
    /// Each body's name, degree, and the degree it was compared with.
    pub degrees: Vec<(String, usize, usize)>,
    /// Largest change of the pressure inside the zone, relative to its mean pressure.
    pub change: f64,
}

/// The first contact solve of `problem` (its contact `contact`) against the same solve with
/// every degree raised by [`P_RAISE`]. `Ok(None)` when there is nothing to compare: every
/// degree is already 20, the solve at `problem`'s own degrees fails (its job reports that),
/// or no contact point lies inside the zone. `Err` says why the raised solve could not be made.
pub fn p_check(problem: &Problem, contact: &CondensedContact) -> Result<Option<PCheck>, String> {
    let Some(raised) = raised_problem(problem)? else {
        return Ok(None);
    };
    let direction = crate::driver::direction(problem).map_err(|e| e.to_string())?;
    let method = crate::driver::method(problem).map_err(|e| e.to_string())?;
    let (base, info) =
        ContactSolver::new(contact, method).solve(&contact.points.initial_gap, direction);
    if info.status != Status::Solved {
        return Ok(None);
    }
    let (raised_contact, _, _) =
        CondensedContact::build(&raised).map_err(|e| format!("the set-up at p + 2: {e}"))?;
    let (fine, info) = ContactSolver::new(&raised_contact, method)
        .solve(&raised_contact.points.initial_gap, direction);
    if info.status != Status::Solved {
        return Err(format!(
            "the contact solve at p + 2 failed (complementarity residual {:.3e})",
            info.complementarity
        ));
    }
    let fine_at = |x: [f64; 2]| on_polyline(&raised_contact.points.x, &fine.pressure, x);
    let change = inner_change(
        &contact.points.x,
        &contact.points.weight,
        &base.pressure,
        fine_at,
    );
    let degrees = problem
        .spec
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| (b.name.clone(), degree(problem, i), degree(&raised, i)))
        .collect();
    Ok(change.map(|change| PCheck { degrees, change }))
}

/// The warning for a [`p_check`] above [`P_CHANGE_LIMIT`], or for one that could not be made.
pub fn p_check_warning(problem: &Problem, check: Result<Option<PCheck>, String>) -> Option<String> {
    let check = match check {
        Ok(check) => check?,
        Err(why) => {
            return Some(format!(
                "warning: {}: analysis.p_check: could not check the resolution in p: {why}",
                problem.file
            ))
        }
    };
    let d = &check.degrees;
    let raised = if d.iter().all(|b| (b.1, b.2) == (d[0].1, d[0].2)) {
        format!("the degree from {} to {}", d[0].1, d[0].2)
    } else {
        let each: Vec<String> = d
            .iter()
            .map(|b| format!("{} {} → {}", b.0, b.1, b.2))
            .collect();
        format!("the degrees ({})", each.join(", "))
    };
    (check.change > P_CHANGE_LIMIT).then(|| format!(
        "warning: {}: the contact pressure is not converged in p: raising {raised} changes the first contact solve's pressure inside the zone by {:.1} % of its mean pressure (more than {:.0} %), and the error of this mesh is likely at least that. The mesh does not resolve the bodies under the contact (for example, a body 2 whose elements are much deeper than the contact is long), and refining only the contact edge does not show it: grade the blocks under the contact in depth, or raise the degrees (docs/validation.md, \"Convergence in p\"; analysis.p_check = false turns this check off)",
        problem.file,
        100.0 * check.change,
        100.0 * P_CHANGE_LIMIT,
    ))
}

/// The warnings of the check when it is wanted: `analysis.p_check`, else `default` (true for
/// the single jobs, false in studies, where it would cost a set-up at p + 2 per variant).
pub fn p_check_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    default: bool,
) -> Vec<String> {
    if !problem.spec.analysis.p_check.unwrap_or(default) {
        return Vec::new();
    }
    p_check_warning(problem, p_check(problem, contact))
        .into_iter()
        .collect()
}

/// `problem` with every degree raised by [`P_RAISE`] (at most to 20); None if none can be.
fn raised_problem(problem: &Problem) -> Result<Option<Problem>, String> {
    let raise = |p: usize| (p + P_RAISE).min(MAX_DEGREE);
    let mut spec = problem.spec.clone();
    spec.analysis.p = raise(spec.analysis.p);
    for body in &mut spec.bodies {
        body.p = body.p.map(raise);
    }
    let raised = Problem::from_spec(spec, &problem.file).map_err(|e| e.to_string())?;
    let any_raised =
        (0..problem.spec.bodies.len()).any(|i| degree(&raised, i) > degree(problem, i));
    Ok(any_raised.then_some(raised))
}

/// The degree of body `index`.
fn degree(problem: &Problem, index: usize) -> usize {
    problem.spec.bodies[index]
        .p
        .unwrap_or(problem.spec.analysis.p)
}

/// The pressure of points `x` (in order along the edge) at `at`, linear between the two
/// points of the nearest segment.
fn on_polyline(x: &[[f64; 2]], pressure: &[f64], at: [f64; 2]) -> f64 {
    let mut best = (f64::INFINITY, 0.0);
    for i in 0..x.len().saturating_sub(1) {
        let (a, b) = (x[i], x[i + 1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let length2 = d[0] * d[0] + d[1] * d[1];
        let t = if length2 > 0.0 {
            (((at[0] - a[0]) * d[0] + (at[1] - a[1]) * d[1]) / length2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let distance = (a[0] + t * d[0] - at[0]).hypot(a[1] + t * d[1] - at[1]);
        if distance < best.0 {
            best = (distance, pressure[i] + t * (pressure[i + 1] - pressure[i]));
        }
    }
    best.1
}

/// Largest |p − fine(x)| over the points inside the zone (the span from the first to the last
/// point with pressure, less a tenth of it at each end), relative to the mean pressure over
/// the points with pressure (weights `weight`). None without points inside.
fn inner_change(
    x: &[[f64; 2]],
    weight: &[f64],
    pressure: &[f64],
    fine: impl Fn([f64; 2]) -> f64,
) -> Option<f64> {
    let first = pressure.iter().position(|&p| p > 0.0)?;
    let last = pressure.iter().rposition(|&p| p > 0.0)?;
    let mut along = vec![0.0; x.len()];
    for i in 1..x.len() {
        along[i] = along[i - 1] + (x[i][0] - x[i - 1][0]).hypot(x[i][1] - x[i - 1][1]);
    }
    let margin = 0.1 * (along[last] - along[first]);
    let (mut force, mut length) = (0.0, 0.0);
    for i in first..=last {
        if pressure[i] > 0.0 {
            force += weight[i] * pressure[i];
            length += weight[i];
        }
    }
    let mean = force / length;
    let inside = (first..=last)
        .filter(|&i| along[i] > along[first] + margin && along[i] < along[last] - margin);
    let largest = inside
        .map(|i| (pressure[i] - fine(x[i])).abs())
        .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))))?;
    (mean > 0.0 && largest.is_finite()).then(|| largest / mean)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pressure_read_on_a_finer_polyline_is_interpolated() {
        let x = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]];
        let p = [1.0, 3.0, 5.0];
        assert_eq!(on_polyline(&x, &p, [0.5, 0.2]), 2.0);
        assert!((on_polyline(&x, &p, [1.5, 0.5]) - 4.0).abs() < 1e-12);
    }

    #[test]
    fn the_change_leaves_out_the_ends_of_the_zone() {
        let x: Vec<[f64; 2]> = (0..=10).map(|i| [i as f64, 0.0]).collect();
        let weight = [1.0; 11];
        let pressure = [
            0.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 0.0,
        ];
        // A change at the zone's end (x = 1) is not counted; one of 0.3 at x = 5 is 3 %.
        let fine = |at: [f64; 2]| match at[0] as usize {
            1 => 50.0,
            5 => 10.3,
            _ => 10.0,
        };
        let change = inner_change(&x, &weight, &pressure, fine).unwrap();
        assert!((change - 0.03).abs() < 1e-12, "{change}");
    }
}
