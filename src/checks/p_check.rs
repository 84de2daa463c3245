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

use super::codes::warning;
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

/// Largest depth, along the contact normal, of an element under the contact zone, as a
/// multiple of the zone's length, that passes without a warning ([`depth_warnings`]).
pub const DEPTH_LIMIT: f64 = 1.5;

/// For each body: its name, the largest depth (mm, along the mean contact normal) of its
/// elements whose contact edge overlaps the zone of `pressure` (MPa, at `contact`'s points),
/// and the zone's length (mm, along the edge). Empty without pressure.
pub fn depths_under_zone(
    problem: &Problem,
    contact: &CondensedContact,
    pressure: &[f64],
) -> Vec<(String, f64, f64)> {
    let Some(c) = problem.spec.contact.as_ref() else {
        return Vec::new();
    };
    let normal = contact
        .points
        .normal
        .iter()
        .fold([0.0, 0.0], |s, v| [s[0] + v[0], s[1] + v[1]]);
    let length = normal[0].hypot(normal[1]);
    if length == 0.0 {
        return Vec::new();
    }
    let normal = [normal[0] / length, normal[1] / length];
    let along = |x: [f64; 2]| -x[0] * normal[1] + x[1] * normal[0];
    let deep = |x: [f64; 2]| x[0] * normal[0] + x[1] * normal[1];
    let zone: Vec<f64> = (0..contact.len())
        .filter(|&i| pressure[i] > 0.0)
        .map(|i| along(contact.points.x[i]))
        .collect();
    let (lo, hi) = zone
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    if zone.is_empty() || hi <= lo {
        return Vec::new();
    }
    let mut out = Vec::new();
    for (name, edge) in [(&c.body, &c.edge), (&c.target_body, &c.target_edge)] {
        let Ok(mesh) = problem.body_index(name).and_then(|b| problem.mesh(b)) else {
            continue;
        };
        let Some(on_edge) = mesh.named_edges.get(edge) else {
            continue;
        };
        let mut depth: f64 = 0.0;
        for &(e, local) in on_edge {
            let element = &mesh.elements[e];
            let ends = crate::mesh::EDGE_ENDPOINTS[local];
            let (t0, t1) = (
                along(mesh.vertices[element.vertices[ends.0]]),
                along(mesh.vertices[element.vertices[ends.1]]),
            );
            if t0.max(t1) <= lo || t0.min(t1) >= hi {
                continue;
            }
            let d: Vec<f64> = element
                .vertices
                .iter()
                .map(|&v| deep(mesh.vertices[v]))
                .collect();
            let extent = d.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                - d.iter().cloned().fold(f64::INFINITY, f64::min);
            depth = depth.max(extent);
        }
        out.push((name.clone(), depth, hi - lo));
    }
    out
}

/// A warning for each body whose elements under the zone of the first contact solve are
/// deeper than [`DEPTH_LIMIT`] times the zone is long (red teams 11 and 12: a nearly rigid
/// punch on layers 3–6 times deeper than its 40 mm zone was 6–10 % low, and raising p by 2
/// changed it by only 1.6–3.3 %: a p-extension understates an error that converges slowly
/// in p, so depth is measured directly). Cheap: made in studies too.
pub fn depth_warnings(problem: &Problem, contact: &CondensedContact) -> Vec<String> {
    first_solve_depth_warnings(problem, contact, "")
}

/// [`depth_warnings`], `which` said after the zone's length.
fn first_solve_depth_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    which: &str,
) -> Vec<String> {
    let (Ok(direction), Ok(method)) = (problem.first_direction(), problem.contact_method()) else {
        return Vec::new();
    };
    let (solution, info) =
        ContactSolver::new(contact, method).solve(&contact.points.initial_gap, direction);
    if info.status != Status::Solved {
        return Vec::new();
    }
    depth_warnings_of(problem, contact, &solution.pressure, which)
}

/// The depth warnings of a run: of its last state (`last`, MPa at the contact points), and
/// of its first contact solve where the last state passes, said to concern the early states:
/// a run's zone can grow from a Hertzian start that its elements do not resolve into a worn
/// zone that they do.
pub fn run_depth_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    last: &[f64],
) -> Vec<String> {
    let at_end = depth_warnings_of(problem, contact, last, " in the run's last state");
    if !at_end.is_empty() {
        return at_end;
    }
    let zone = zone_of(&contact.points.x, last)
        .map(|z| format!(" (x = {} … {} mm)", short(z[0]), short(z[1])))
        .unwrap_or_default();
    first_solve_depth_warnings(problem, contact, " in the first contact solve")
        .into_iter()
        .map(|w| {
            format!(
                "{w}; the run's last zone{zone} is resolved, so it concerns the run's early states"
            )
        })
        .collect()
}

/// The warnings of [`depth_warnings`] for the zone of `pressure` (MPa at the contact
/// points), `which` saying whose zone it is (after "a contact zone").
fn depth_warnings_of(
    problem: &Problem,
    contact: &CondensedContact,
    pressure: &[f64],
    which: &str,
) -> Vec<String> {
    depths_under_zone(problem, contact, pressure)
        .into_iter()
        .filter(|(_, depth, zone)| *depth > DEPTH_LIMIT * zone)
        .map(|(name, depth, zone)| warning(
            "depth",
            &problem.file,
            format!(
                "body \"{name}\" has elements {} mm deep under a contact zone {} mm long{which} ({:.1} times, more than {DEPTH_LIMIT}): not resolved in depth",
                short(depth),
                short(zone),
                depth / zone
            ),
        ))
        .collect()
}

/// What the check measured.
#[derive(Clone, Debug, PartialEq)]
pub struct PCheck {
    /// Each body's name, degree, and the degree it was compared with.
    pub degrees: Vec<(String, usize, usize)>,
    /// Largest change of the pressure inside the zone, relative to its mean pressure.
    pub change: f64,
    /// The checked state's contact zone: x of its first and last point with pressure, mm.
    pub zone: [f64; 2],
}

/// Each body's name, degree, and its degree in `raised`.
fn degrees(problem: &Problem, raised: &Problem) -> Vec<(String, usize, usize)> {
    problem
        .spec
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| (b.name.clone(), degree(problem, i), degree(raised, i)))
        .collect()
}

/// x (mm) of the first and last of the points `x` with pressure; None without any.
pub fn zone_of(x: &[[f64; 2]], pressure: &[f64]) -> Option<[f64; 2]> {
    let first = pressure.iter().position(|&p| p > 0.0)?;
    let last = pressure.iter().rposition(|&p| p > 0.0)?;
    Some([x[first][0], x[last][0]])
}

/// The first contact solve of `problem` (its contact `contact`) against the same solve with
/// every degree raised by [`P_RAISE`]. `Ok(None)` when there is nothing to compare: every
/// degree is already 20, the solve at `problem`'s own degrees fails (its job reports that),
/// or no contact point lies inside the zone. `Err` says why the raised solve could not be made.
pub fn p_check(problem: &Problem, contact: &CondensedContact) -> Result<Option<PCheck>, String> {
    p_check_with(problem, contact, raised_first_solve(problem))
}

/// The first contact solve at the raised degrees: what [`p_check`] compares with. It needs
/// only the problem, so a job can make it beside its own work (`wearfem run` makes it during
/// the integration).
#[derive(Debug)]
pub struct RaisedSolve {
    /// Each body's name, degree, and raised degree.
    degrees: Vec<(String, usize, usize)>,
    /// The raised problem's contact points, mm.
    x: Vec<[f64; 2]>,
    /// The pressure there, MPa.
    pressure: Vec<f64>,
}

/// Set up `problem` at the raised degrees and solve its first contact; `Ok(None)` when every
/// degree is already 20; `Err` says why it could not be made.
pub fn raised_first_solve(problem: &Problem) -> Result<Option<RaisedSolve>, String> {
    let Some(raised) = raised_problem(problem)? else {
        return Ok(None);
    };
    let direction = problem.first_direction().map_err(|e| e.to_string())?;
    let method = problem.contact_method().map_err(|e| e.to_string())?;
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
    Ok(Some(RaisedSolve {
        degrees: degrees(problem, &raised),
        x: raised_contact.points.x,
        pressure: fine.pressure,
    }))
}

/// [`p_check`] with the raised solve made already (`raised`).
pub fn p_check_with(
    problem: &Problem,
    contact: &CondensedContact,
    raised: Result<Option<RaisedSolve>, String>,
) -> Result<Option<PCheck>, String> {
    let Some(raised) = raised? else {
        return Ok(None);
    };
    let direction = problem.first_direction().map_err(|e| e.to_string())?;
    let method = problem.contact_method().map_err(|e| e.to_string())?;
    let (base, info) =
        ContactSolver::new(contact, method).solve(&contact.points.initial_gap, direction);
    if info.status != Status::Solved {
        return Ok(None);
    }
    let fine_at = |x: [f64; 2]| on_polyline(&raised.x, &raised.pressure, x);
    let change = inner_change(
        &contact.points.x,
        &contact.points.weight,
        &base.pressure,
        fine_at,
    );
    let zone = zone_of(&contact.points.x, &base.pressure);
    Ok(change.zip(zone).map(|(change, zone)| PCheck {
        degrees: raised.degrees,
        change,
        zone,
    }))
}

/// The warning for a [`p_check`] above [`P_CHANGE_LIMIT`], or for one that could not be made.
pub fn p_check_warning(problem: &Problem, check: Result<Option<PCheck>, String>) -> Option<String> {
    let check = match check {
        Ok(check) => check?,
        Err(why) => {
            return Some(warning(
                "p-check-failed",
                &problem.file,
                format!("analysis.p_check: could not check the resolution in p: {why}"),
            ))
        }
    };
    let raised = raised_text(&check.degrees);
    (check.change > P_CHANGE_LIMIT).then(|| warning(
        "p-check",
        &problem.file,
        format!(
            "the contact pressure is not converged in p: raising {raised} changes the first contact solve's pressure inside the zone by {:.1} % of its mean pressure (more than {:.0} %)",
            100.0 * check.change,
            100.0 * P_CHANGE_LIMIT,
        ),
    ))
}

/// "the degree from 8 to 10", or each body's when they differ.
fn raised_text(d: &[(String, usize, usize)]) -> String {
    if d.iter().all(|b| (b.1, b.2) == (d[0].1, d[0].2)) {
        format!("the degree from {} to {}", d[0].1, d[0].2)
    } else {
        let each: Vec<String> = d
            .iter()
            .map(|b| format!("{} {} → {}", b.0, b.1, b.2))
            .collect();
        format!("the degrees ({})", each.join(", "))
    }
}

/// The warning of a run's check in p: [`p_check_warning`], and when it warns and the run's
/// contact zone in its last state (`last_zone`, x in mm) outgrew the zone of the first
/// contact solve that the check measured, that it concerns the run's early states: a
/// cylinder's Hertzian start can be unresolved while the flat it wears into is resolved.
pub fn run_p_check_warning(
    problem: &Problem,
    check: Result<Option<PCheck>, String>,
    last_zone: Option<[f64; 2]>,
) -> Option<String> {
    let first_zone = check.as_ref().ok().and_then(|c| c.as_ref()).map(|c| c.zone);
    let warning = p_check_warning(problem, check)?;
    let grown = match (first_zone, last_zone) {
        (Some(first), Some(last)) => {
            let (a, b) = (first[1] - first[0], last[1] - last[0]);
            // Outgrown: the last zone is a third longer, or reaches past either end.
            (b > 1.33 * a || last[0] < first[0] - 0.1 * a || last[1] > first[1] + 0.1 * a)
                .then_some((first, last))
        }
        _ => None,
    };
    Some(match grown {
        Some((first, last)) => format!(
            "{warning} (zone x = {} … {} mm); the run's zone grew to x = {} … {} mm, which this check does not measure: it concerns the run's early states",
            short(first[0]),
            short(first[1]),
            short(last[0]),
            short(last[1])
        ),
        None => warning,
    })
}

/// The warnings about the resolution under the contact: [`depth_warnings`] always, and
/// [`p_check`]'s when it is wanted: `analysis.p_check`, else `default` (true for the single
/// jobs, false in studies, where it would cost a set-up at p ± 2 per variant).
pub fn resolution_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    p_check_default: bool,
) -> Vec<String> {
    let mut warnings = depth_warnings(problem, contact);
    if problem.spec.analysis.p_check.unwrap_or(p_check_default) {
        warnings.extend(p_check_warning(problem, p_check(problem, contact)));
    }
    warnings
}

/// `x` with four decimals at most, without trailing zeros (125, 5.6772).
fn short(x: f64) -> String {
    let text = format!("{x:.4}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// `problem` with every degree raised by [`P_RAISE`], or lowered by it where a degree would
/// pass 20: the comparison must keep the parity (p = 19 against 20 differed by 6.4 % at an
/// element vertex of punch-b40, 17 against 19 by 0.34 %; red team 12). Lowered, the change
/// measures the error at p − 2, which bounds the one at p from above. Err if neither can be
/// made (a degree of 1 or 2 beside one of 19 or 20).
fn raised_problem(problem: &Problem) -> Result<Option<Problem>, String> {
    let degrees: Vec<usize> = (0..problem.spec.bodies.len())
        .map(|i| degree(problem, i))
        .collect();
    let up = degrees.iter().all(|&p| p + P_RAISE <= MAX_DEGREE);
    let down = degrees.iter().all(|&p| p > P_RAISE);
    if !up && !down {
        return Err(format!(
            "the degrees {degrees:?} can be neither raised by {P_RAISE} (at most to {MAX_DEGREE}) nor lowered by it"
        ));
    }
    let change = |p: usize| if up { p + P_RAISE } else { p - P_RAISE };
    let mut spec = problem.spec.clone();
    spec.analysis.p = if up {
        (spec.analysis.p + P_RAISE).min(MAX_DEGREE)
    } else {
        spec.analysis.p.saturating_sub(P_RAISE).max(1)
    };
    for body in &mut spec.bodies {
        body.p = body.p.map(change);
    }
    Problem::from_spec(spec, &problem.file)
        .map(Some)
        .map_err(|e| e.to_string())
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
