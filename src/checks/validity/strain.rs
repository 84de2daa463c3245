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

/// The warning for `body` named `name` when its largest strain exceeds [`STRAIN_LIMIT`];
/// `under` says what strains it ("its loads", "the first contact solve").
pub fn strain_warning(
    problem: &Problem,
    name: &str,
    (strain, at): (f64, Point),
    under: &str,
) -> Option<String> {
    (strain.is_nan() || strain > STRAIN_LIMIT).then(|| crate::checks::codes::warning(
        "strain",
        &problem.file,
        format!(
            "body \"{name}\" is strained by {:.3e} ({:.0} %) at ({:.4}, {:.4}) under {under}: outside small strains",
            strain,
            100.0 * strain,
            at[0],
            at[1],
        ),
    ))
}

/// Share of [`STRAIN_LIMIT`] below which the largest load stress over the softest modulus
/// (see [`strain_could_be_large`]) passes without recomputing the bodies: a stress
/// concentration (a corner, a notch) multiplies that scale by a few, not by ten.
const LOAD_SCALE_SHARE: f64 = 0.1;

/// Whether the bodies' strains under a solved contact problem could come near the limit, from
/// two scales that cost nothing: the largest stress the loads apply (the peak contact
/// pressure, every traction's value) over the softest Young's modulus of the problem, the
/// strain of the softest material under the largest load wherever they are; and the
/// contact's elastic approach |A_s P| over both bodies' extent along the normal, the mean
/// strain of a body that takes all of it. Only then are the bodies assembled and solved again
/// (the shipped examples: 1e-3 and 1e-4 of the limit; recomputing them doubled a steady
/// variant of punch-b40, 20 → 37 ms).
fn strain_could_be_large(
    problem: &Problem,
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> bool {
    let softest = problem
        .spec
        .materials
        .values()
        .map(|m| m.young)
        .fold(f64::INFINITY, f64::min);
    let peak_pressure = solution
        .force
        .iter()
        .zip(contact.areas())
        .map(|(f, a)| f / a)
        .fold(0.0, f64::max);
    let largest_traction = problem
        .spec
        .bodies
        .iter()
        .flat_map(|b| &b.tractions)
        .flat_map(|t| t.normal.pair().into_iter().chain(t.shear.pair()))
        .map(f64::abs)
        .fold(0.0, f64::max);
    let load_strain = peak_pressure.max(largest_traction) / softest;
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
    let extent: f64 = (0..problem.spec.bodies.len())
        .filter_map(|b| problem.mesh(b).ok())
        .map(|mesh| {
            super::extent(
                mesh.vertices.iter().copied(),
                super::mean_normal(contact).unwrap_or([0.0, -1.0]),
            )
        })
        .sum();
    !(load_strain < LOAD_SCALE_SHARE * STRAIN_LIMIT && approach < 0.01 * STRAIN_LIMIT * extent)
}

/// The strain warnings of both bodies under a solved contact problem (`solution` in
/// `direction`), when the loads and the contact's deflection say they could matter: the
/// largest load stress over the softest modulus above a tenth of [`STRAIN_LIMIT`], or the
/// contact's approach over both bodies' extent above a hundredth of it.
pub fn contact_strain_warnings(
    problem: &Problem,
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> Vec<String> {
    if !strain_could_be_large(problem, contact, solution, direction) {
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
            strain_warning(
                problem,
                &body.name,
                largest_strain(body, &field.elastic),
                "the first contact solve",
            )
        })
        .collect()
}
