//! *Small strains.* Linear elasticity holds while the bodies' strains are small. The plate
//! motion check ([`super::plate_motion_warning`]) sees a soft body only through the plate;
//! a body without a plate, a thin soft layer under a stiff punch (a 2 mm rubber layer
//! compressed by 75 % moved the plate by 1.5 % of the punch), or the `elastic` command (a
//! Lamé cylinder with E × 1e-5 strained 95 times over) passed in silence (red team 27). This
//! measures the strains themselves: in every element, at the 3 × 3 Gauss points (inside the
//! element, so that the integrable singularity at a punch corner is sampled at a distance).

use crate::complementarity::{ContactSolution, Direction};
use crate::contact::CondensedContact;
use crate::elasticity::{Displacement, ElasticBody};
use crate::geometry::Point;
use crate::problem::Problem;

/// Largest principal strain (absolute) that passes without a warning: beyond it the
/// linearised strains and the undeformed geometry of linear elasticity err by about as much.
pub const STRAIN_LIMIT: f64 = 0.05;

/// The largest absolute principal strain of `body` under `u` at the 3 × 3 Gauss points of
/// its elements, and where (mm). Rigid motions add none.
pub fn largest_strain(body: &ElasticBody, u: &Displacement) -> (f64, Point) {
    let gauss = [-(0.6f64.sqrt()), 0.0, 0.6f64.sqrt()];
    let mut largest = (0.0, [f64::NAN, f64::NAN]);
    for element in 0..body.mesh.elements.len() {
        for &xi in &gauss {
            for &eta in &gauss {
                let [exx, ezz, gxz] = body.values_at_reference(u, element, xi, eta).strain;
                let (mean, radius) = (
                    0.5 * (exx + ezz),
                    (0.25 * (exx - ezz).powi(2) + 0.25 * gxz * gxz).sqrt(),
                );
                let principal = mean.abs() + radius;
                // NaN must win, so that an overflowed field is reported, not passed.
                if principal.is_nan() || principal > largest.0 {
                    largest = (principal, body.mesh.map(element, xi, eta));
                }
            }
        }
    }
    largest
}

/// The warning for `body` named `name` when its largest strain exceeds [`STRAIN_LIMIT`].
pub fn strain_warning(problem: &Problem, name: &str, (strain, at): (f64, Point)) -> Option<String> {
    (strain.is_nan() || strain > STRAIN_LIMIT).then(|| format!(
        "warning: {}: body \"{name}\" is strained by {:.3e} ({:.0} %) at ({:.4}, {:.4}) under the first contact solve or the loads; linear elasticity assumes small strains, so these results are outside its range (they err by about as much). Check the Young's moduli and the loads (units: MPa and mm)",
        problem.file,
        strain,
        100.0 * strain,
        at[0],
        at[1],
    ))
}

/// The strain warnings of both bodies under a solved contact problem (`solution` in
/// `direction`). The bodies are assembled again only when the contact's own deflection
/// could mean a strain near the limit: the elastic approach of the surfaces, |A_s P|, over
/// the depth of the thinner body's contact blocks is the mean strain of that body were it
/// to take all of it; corners concentrate strain, so the bodies are checked from a hundredth
/// of the limit on (the shipped examples stay below a thousandth and cost nothing), and
/// always when a body carries loads of its own (tractions other than the plate edge's).
pub fn contact_strain_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> Vec<String> {
    let n = contact.len();
    let flexibility = contact.gap_matrix(direction.sign());
    let approach = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| flexibility[i * n + j] * solution.force[j])
                .sum::<f64>()
                .abs()
        })
        .fold(0.0, f64::max);
    let depth = (0..2)
        .filter_map(|b| super::worn_blocks_depth(problem, contact, b).map(|(_, d)| d))
        .fold(f64::INFINITY, f64::min);
    // Loads on the bodies other than the plate's strain them whatever the contact does (red
    // team D: a soft arm of body 2 stretched 9 % by its own load passed in silence).
    let plate_edge = problem.spec.plate.as_ref().map(|p| p.edge.as_str());
    let own_loads = problem.spec.bodies.iter().any(|b| {
        b.tractions
            .iter()
            .any(|t| Some(t.edge.as_str()) != plate_edge)
    });
    if !own_loads && approach.is_finite() && approach < 0.01 * STRAIN_LIMIT * depth {
        return Vec::new();
    }
    let Ok((body1, body2)) = CondensedContact::bodies(problem) else {
        return Vec::new();
    };
    let Ok(fields) =
        crate::deformation::contact_fields(problem, (&body1, &body2), contact, solution, direction)
    else {
        return Vec::new();
    };
    [(&body1, &fields[0]), (&body2, &fields[1])]
        .iter()
        .filter_map(|(body, field)| {
            strain_warning(problem, &body.name, largest_strain(body, &field.elastic))
        })
        .collect()
}
