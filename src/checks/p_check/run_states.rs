//! The check in p of a wear run: its first contact solve and its last state, because a run's
//! contact can grow out of the zone it started on (a cylinder wearing a flat: the first,
//! Hertzian zone is a few elements wide and may be unresolved while the worn zone is well
//! resolved, or the other way round).
//!
//! The last state's gap at p + 2 is the raised problem's own initial gap plus the run's
//! change of the gap (wear, thermal distortion), carried to the raised contact points by the
//! degree-p polynomial through each contact element's Lobatto points (the points of one
//! element are its p + 1 Lobatto points, shared at the ends); where the points are not laid
//! out so, linearly between the nearest two.

use super::{inner_change, on_polyline, raised_problem, PCheck};
use crate::complementarity::{ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::problem::Problem;

/// The check in p of a run's first contact solve and of its last state.
pub struct RunPCheck {
    /// The first contact solve's check (None: nothing to compare).
    pub first: Option<PCheck>,
    /// The last state's check (None: nothing to compare).
    pub last: Option<PCheck>,
}

/// Check the first contact solve of `contact` (on its initial gap, in the first direction)
/// and the state `last_gap` (mm at the contact points) solved in `last_direction`.
pub fn p_check_run(
    problem: &Problem,
    contact: &CondensedContact,
    last_gap: &[f64],
    last_direction: Direction,
) -> Result<RunPCheck, String> {
    let Some(raised) = raised_problem(problem)? else {
        return Ok(RunPCheck {
            first: None,
            last: None,
        });
    };
    let direction = problem.first_direction().map_err(|e| e.to_string())?;
    let method = problem.contact_method().map_err(|e| e.to_string())?;
    let (raised_contact, _, _) =
        CondensedContact::build(&raised).map_err(|e| format!("the set-up at p + 2: {e}"))?;
    let degrees = super::degrees(problem, &raised);
    let check = |gap: &[f64], raised_gap: &[f64], direction: Direction| {
        let (base, info) = ContactSolver::new(contact, method).solve(gap, direction);
        if info.status != Status::Solved {
            return Ok(None);
        }
        let (fine, info) = ContactSolver::new(&raised_contact, method).solve(raised_gap, direction);
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
        let zone = super::zone_of(&contact.points.x, &base.pressure);
        Ok(change.zip(zone).map(|(change, zone)| PCheck {
            degrees: degrees.clone(),
            change,
            zone,
        }))
    };
    let first = check(
        &contact.points.initial_gap,
        &raised_contact.points.initial_gap,
        direction,
    )?;
    let change: Vec<f64> = last_gap
        .iter()
        .zip(&contact.points.initial_gap)
        .map(|(g, g0)| g - g0)
        .collect();
    let carried = carry(&contact.points.x, &raised_contact.points.x, &change);
    let raised_gap: Vec<f64> = raised_contact
        .points
        .initial_gap
        .iter()
        .zip(&carried)
        .map(|(g0, d)| g0 + d)
        .collect();
    let last = check(last_gap, &raised_gap, last_direction)?;
    Ok(RunPCheck { first, last })
}

/// `values` at `from`'s contact points carried to `to`'s: per contact element by the
/// polynomial through its Lobatto points when both are laid out as p + 1 and p ± 2 + 1
/// Lobatto points per element over the same elements, else linearly along the edge.
fn carry(from: &[[f64; 2]], to: &[[f64; 2]], values: &[f64]) -> Vec<f64> {
    let (n, m) = (from.len(), to.len());
    let layout = (1..=20usize).find_map(|p| {
        let elements = (n - 1) / p;
        let q = (m - 1).checked_div(elements)?;
        (elements > 0
            && q > 0
            && elements * p == n - 1
            && elements * q == m - 1
            && q.abs_diff(p) == super::P_RAISE)
            .then_some((elements, p, q))
    });
    let Some((elements, p, q)) = layout else {
        return to.iter().map(|&x| on_polyline(from, values, x)).collect();
    };
    let nodes = crate::quadrature::gauss_lobatto(p + 1).points;
    let targets = crate::quadrature::gauss_lobatto(q + 1).points;
    let mut out = vec![0.0; m];
    for e in 0..elements {
        let local = &values[e * p..=e * p + p];
        for (j, &s) in targets.iter().enumerate() {
            out[e * q + j] = lagrange(&nodes, local, s);
        }
    }
    out
}

/// The polynomial through (`nodes`, `values`) at `s`.
fn lagrange(nodes: &[f64], values: &[f64], s: f64) -> f64 {
    (0..nodes.len())
        .map(|i| {
            let basis: f64 = (0..nodes.len())
                .filter(|&j| j != i)
                .map(|j| (s - nodes[j]) / (nodes[i] - nodes[j]))
                .product();
            basis * values[i]
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points at the Lobatto points of degree `p` on each of the unit elements [e, e + 1].
    fn lobatto_points(elements: usize, p: usize) -> Vec<[f64; 2]> {
        let nodes = crate::quadrature::gauss_lobatto(p + 1).points;
        let mut x = vec![[0.0, 0.0]];
        for e in 0..elements {
            for s in &nodes[1..] {
                x.push([e as f64 + 0.5 * (s + 1.0), 0.0]);
            }
        }
        x
    }

    #[test]
    fn a_polynomial_of_the_degree_is_carried_exactly() {
        // A quartic per element (degree p = 4) carried to p = 6: exact to round-off; a
        // kinked profile (|x − 1.5|, kink inside element 1) is carried by its polynomial.
        let (from, to) = (lobatto_points(3, 4), lobatto_points(3, 6));
        let quartic = |x: f64| 1.0 + x - 0.3 * x.powi(2) + 0.05 * x.powi(4);
        let values: Vec<f64> = from.iter().map(|x| quartic(x[0])).collect();
        for (x, v) in to.iter().zip(carry(&from, &to, &values)) {
            assert!((v - quartic(x[0])).abs() < 1e-12, "{x:?}: {v}");
        }
        // Points not laid out by elements: linear between neighbours.
        let odd = [[0.0, 0.0], [0.3, 0.0], [1.0, 0.0]];
        let carried = carry(&odd, &[[0.65, 0.0]], &[0.0, 3.0, 10.0]);
        assert!((carried[0] - 6.5).abs() < 1e-12);
    }
}
