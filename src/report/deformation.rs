//! The deformed state of both bodies behind one contact solve: the displacement fields that
//! the condensation of [`crate::contact`] reduced to the contact points, recovered in full for
//! post-processing (ParaView output, stresses anywhere).
//!
//! With the contact forces F_i = P_i (−n_i + s μ τ_i) (N) of a [`ContactSolution`] on body 1 at
//! its contact points and −F_i on body 2 at the partner points (paper eq. 2–3, 42):
//! - body 1 = rigid plate motion Σ λ_k φ_k(x) + the elastic field of body 1 with its plate
//!   edge clamped under F and its own loads (all tractions except the plate edge's);
//! - body 2 = the elastic field of body 2 on its supports under −F and its own loads.
//!
//! These are exactly the fields whose normal components at the contact points make up the
//! condensed gap d = A_s P + R λ + g, so the gap they reproduce is the solution's gap.

use crate::complementarity::{ContactSolution, Direction};
use crate::contact::CondensedContact;
use crate::elasticity::{Displacement, ElasticBody};
use crate::fields::PointValues;
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

/// A small (linearised) plane rigid-body motion u(x) = t + θ (z, −x): θ is a rotation about
/// +y (rad, clockwise on an x–z plot, as λ_M), t a translation (mm).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RigidMotion {
    /// Translation [t_x, t_z], mm.
    pub translation: Point,
    /// Rotation θ about +y, rad.
    pub rotation: f64,
}

impl RigidMotion {
    /// Displacement at `x` (mm).
    pub fn at(&self, x: Point) -> Point {
        [
            self.translation[0] + self.rotation * x[1],
            self.translation[1] - self.rotation * x[0],
        ]
    }

    /// The rigid motion that takes the values `u0`, `u1` at the distinct points `x0`, `x1`
    /// (a rigid motion is fixed by two points). Used to rebuild the plate modes φ_k from
    /// their values at the contact points, so their definition lives in one place only.
    pub fn through(x0: Point, u0: Point, x1: Point, u1: Point) -> RigidMotion {
        let d = [x1[0] - x0[0], x1[1] - x0[1]];
        let du = [u1[0] - u0[0], u1[1] - u0[1]];
        let rotation = (du[0] * d[1] - du[1] * d[0]) / (d[0] * d[0] + d[1] * d[1]);
        let translation = [u0[0] - rotation * x0[1], u0[1] + rotation * x0[0]];
        RigidMotion {
            translation,
            rotation,
        }
    }
}

/// The displacement field of one body: an elastic part (finite element coefficients) plus a
/// rigid motion (zero for body 2), which adds no strain.
#[derive(Clone, Debug)]
pub struct BodyField {
    /// Elastic part, mm.
    pub elastic: Displacement,
    /// Rigid part, mm (the plate's motion for body 1).
    pub rigid: RigidMotion,
}

impl BodyField {
    /// Displacement (mm), strain and stress (MPa) at reference point (ξ, η) of `element`.
    pub fn values_at_reference(
        &self,
        body: &ElasticBody,
        element: usize,
        xi: f64,
        eta: f64,
    ) -> PointValues {
        let mut v = body.values_at_reference(&self.elastic, element, xi, eta);
        let r = self.rigid.at(body.mesh.map(element, xi, eta));
        v.displacement[0] += r[0];
        v.displacement[1] += r[1];
        v
    }

    /// Values at physical point `x` (mm); `None` outside the body.
    pub fn values_at(&self, body: &ElasticBody, x: Point) -> Option<PointValues> {
        let (element, xi, eta) = body.mesh.locate(x)?;
        Some(self.values_at_reference(body, element, xi, eta))
    }
}

/// Add the point force `force` (N) at the boundary point `x` of `body` to the global load
/// vector `load`. Only boundary modes are non-zero on the boundary, and those are the global
/// dofs; `None` if `x` is not in the body.
fn add_point_force(body: &ElasticBody, x: Point, force: Point, load: &mut [f64]) -> Option<()> {
    let (element, xi, eta) = body.mesh.locate(x)?;
    let tab = body.basis.tabulate(&[xi], &[eta]);
    let dofs = body.dofs.element_dofs(&body.mesh, element);
    for a in 0..body.basis.n_boundary() {
        for c in 0..2 {
            load[dofs.global[2 * a + c]] += dofs.sign[2 * a + c] * tab.values[a] * force[c];
        }
    }
    Some(())
}

/// The contact force on body 1 at each contact point, F_i = P_i (−n_i + s μ τ_i), N.
pub fn contact_forces(
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> Vec<Point> {
    let s = direction.sign() * contact.friction;
    let pts = &contact.points;
    (0..contact.len())
        .map(|i| {
            let (n, t, p) = (pts.normal[i], pts.tangent[i], solution.force[i]);
            [p * (-n[0] + s * t[0]), p * (-n[1] + s * t[1])]
        })
        .collect()
}

/// The plate's rigid motion Σ λ_k φ_k, rebuilt from the modes' values at the contact points.
pub fn plate_motion(contact: &CondensedContact, rigid: &[f64]) -> RigidMotion {
    let last = contact.len().saturating_sub(1);
    let x = &contact.points.x;
    let mut motion = RigidMotion::default();
    for (phi, &lambda) in contact.rigid_modes.iter().zip(rigid) {
        let mode = RigidMotion::through(x[0], phi[0], x[last], phi[last]);
        motion.translation[0] += lambda * mode.translation[0];
        motion.translation[1] += lambda * mode.translation[1];
        motion.rotation += lambda * mode.rotation;
    }
    motion
}

/// Recover the displacement fields of body 1 and body 2 from a contact solution.
///
/// `body1` and `body2` are the factorised bodies of [`CondensedContact::bodies`] (body 1 with
/// its plate edge clamped), `contact` their condensation, `solution` a solve in `direction`.
/// Each body is solved once more with the contact forces and its own loads.
pub fn contact_fields(
    problem: &Problem,
    (body1, body2): (&ElasticBody, &ElasticBody),
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> Result<[BodyField; 2], ProblemError> {
    let spec = problem
        .spec
        .contact
        .as_ref()
        .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
    let b1 = problem.body_index(&spec.body)?;
    let b2 = problem.body_index(&spec.target_body)?;
    // As in the condensation: tractions on the plate edge load the plate, not body 1.
    let plate_edge: Vec<&str> = problem.spec.plate.iter().map(|p| p.edge.as_str()).collect();
    let mut load1 = problem.load_vector(b1, body1, &plate_edge)?;
    let mut load2 = problem.load_vector(b2, body2, &plate_edge)?;
    let forces = contact_forces(contact, solution, direction);
    let pts = &contact.points;
    for (i, f) in forces.iter().enumerate() {
        let missing = |body: &str, x: Point| {
            problem.error(
                "contact",
                format!(
                    "contact point ({:.6}, {:.6}) is not inside body \"{body}\"",
                    x[0], x[1]
                ),
            )
        };
        add_point_force(body1, pts.x[i], *f, &mut load1)
            .ok_or_else(|| missing(&body1.name, pts.x[i]))?;
        add_point_force(body2, pts.partner[i], [-f[0], -f[1]], &mut load2)
            .ok_or_else(|| missing(&body2.name, pts.partner[i]))?;
    }
    Ok([
        BodyField {
            elastic: body1
                .solve(&load1)
                .map_err(|e| problem.error("bodies", e.to_string()))?,
            rigid: plate_motion(contact, &solution.rigid),
        },
        BodyField {
            elastic: body2
                .solve(&load2)
                .map_err(|e| problem.error("bodies", e.to_string()))?,
            rigid: RigidMotion::default(),
        },
    ])
}

/// The gap n_i·(u²(y_i) − u¹(x_i)) + `geometric_gap[i]` at each contact point that the
/// fields reproduce (mm), with y_i the partner point; `geometric_gap` is the gap of the
/// undeformed bodies along n_c (plus any initial shape and wear).
pub fn gap_of_fields(
    (body1, body2): (&ElasticBody, &ElasticBody),
    fields: &[BodyField; 2],
    contact: &CondensedContact,
    geometric_gap: &[f64],
) -> Option<Vec<f64>> {
    let pts = &contact.points;
    (0..contact.len())
        .map(|i| {
            let u1 = fields[0].values_at(body1, pts.x[i])?.displacement;
            let u2 = fields[1].values_at(body2, pts.partner[i])?.displacement;
            let n = pts.normal[i];
            Some(n[0] * (u2[0] - u1[0]) + n[1] * (u2[1] - u1[1]) + geometric_gap[i])
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rigid_motion_through_two_points_reproduces_a_rotation_about_a_pin() {
        // Rotation about the pin (1100, 140): φ(x) = (z − 140, −(x − 1100)).
        let phi = |x: Point| [x[1] - 140.0, -(x[0] - 1100.0)];
        let (a, b) = ([1070.0, 100.0], [1130.0, 100.0]);
        let m = RigidMotion::through(a, phi(a), b, phi(b));
        for x in [[0.0, 0.0], [1100.0, 140.0], [1234.5, -17.0]] {
            let (u, v) = (m.at(x), phi(x));
            assert!((u[0] - v[0]).abs() < 1e-9 && (u[1] - v[1]).abs() < 1e-9);
        }
    }
}
