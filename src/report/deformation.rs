//! The deformed state of both bodies behind one contact solve: the displacement fields that
//! the condensation of [`crate::contact`] reduced to the contact points, recovered in full for
//! post-processing (ParaView output, stresses anywhere).
//!
//! With the contact forces F_i = P_i (−n_i + s μ τ_i) (N) of a [`ContactSolution`] on body 1 at
//! its contact points and −F_i on body 2 (paper eq. 2–3, 42), each applied through the
//! constraint's trace on that body ([`CondensedContact::traces`]: at the partner point for
//! collocation, spread as body 2's mortar average for mortar contact):
//! - body 1 = rigid plate motion Σ λ_k φ_k(x) + the elastic field of body 1 with its plate
//!   edge clamped under F and its own loads (all tractions except the plate edge's);
//! - body 2 = the elastic field of body 2 on its supports under −F and its own loads.
//!
//! These are exactly the fields whose normal components in the constraints make up the
//! condensed gap d = A_s P + R λ + g, so the gap they reproduce is the solution's gap. (Before
//! 2026-11-29 body 2 took −F_i as point forces at the partner points on mortar contact too:
//! on a body 2 meshed finer than body 1 its surface stresses were several times the
//! pressure, growing with p, red team C.)

use crate::complementarity::{ContactSolution, Direction};
use crate::contact::{CondensedContact, Trace};
use crate::elasticity::{Displacement, ElasticBody};
use crate::fields::PointValues;
pub use crate::fields::TemperatureField;
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
    /// With heat: the temperature the body is at (its thermal strain is in `elastic`, its
    /// thermal stress taken off the stress).
    pub temperature: Option<TemperatureField>,
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
        if let Some(t) = &self.temperature {
            // σ = D (ε − ε_th): the thermal strain is part of ε and carries no stress.
            let rise = t.rise_at_reference(body, element, xi, eta);
            let thermal = body.thermal_stress(&t.loads, element, rise);
            for (s, th) in v.stress.iter_mut().zip(thermal) {
                *s -= th;
            }
        }
        v
    }

    /// E α ΔT (MPa) at reference point (ξ, η) of `element` in plane strain, the out-of-plane
    /// stress that ε_yy = 0 adds where the body is heated; 0 in plane stress or without heat.
    pub fn held_back_stress(&self, body: &ElasticBody, element: usize, xi: f64, eta: f64) -> f64 {
        match (&self.temperature, body.analysis) {
            (Some(t), crate::material::Analysis::PlaneStrain { .. }) => {
                let m = body.mesh.elements[element].material;
                body.materials[m].young
                    * t.loads.expansion[m]
                    * t.rise_at_reference(body, element, xi, eta)
            }
            _ => 0.0,
        }
    }

    /// The temperature (°C) at reference point (ξ, η) of `element`, None without heat.
    pub fn temperature_at_reference(
        &self,
        body: &ElasticBody,
        element: usize,
        xi: f64,
        eta: f64,
    ) -> Option<f64> {
        self.temperature
            .as_ref()
            .map(|t| t.reference + t.rise_at_reference(body, element, xi, eta))
    }

    /// Values at physical point `x` (mm); `None` outside the body.
    pub fn values_at(&self, body: &ElasticBody, x: Point) -> Option<PointValues> {
        let (element, xi, eta) = body.mesh.locate(x)?;
        Some(self.values_at_reference(body, element, xi, eta))
    }
}

/// Add the contact force `force` (N) of constraint `trace` to the global load vector `load`:
/// the load that does the work F · u_trace, the one the condensation's flexibilities assume.
fn add_trace_force(trace: &Trace, force: Point, load: &mut [f64]) {
    for &(dofs, coef) in trace {
        for c in 0..2 {
            load[dofs[c]] += coef * force[c];
        }
    }
}

/// The displacement of constraint `trace` under the boundary dofs `u` (mm).
fn trace_value(trace: &Trace, u: &[f64]) -> Point {
    trace.iter().fold([0.0, 0.0], |sum, &(dofs, coef)| {
        [sum[0] + coef * u[dofs[0]], sum[1] + coef * u[dofs[1]]]
    })
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
    bodies: (&ElasticBody, &ElasticBody),
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
) -> Result<[BodyField; 2], ProblemError> {
    contact_fields_with_heat(problem, bodies, contact, solution, direction, None)
}

/// [`contact_fields`] with the bodies at `temperatures` (body 1, body 2): each body is also
/// loaded by its thermal strain, its internal modes recovered with it, and its stresses are
/// D (ε − ε_th).
pub fn contact_fields_with_heat(
    problem: &Problem,
    (body1, body2): (&ElasticBody, &ElasticBody),
    contact: &CondensedContact,
    solution: &ContactSolution,
    direction: Direction,
    temperatures: Option<[TemperatureField; 2]>,
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
    let [traces1, traces2] = &contact.traces;
    for (i, f) in forces.iter().enumerate() {
        add_trace_force(&traces1[i], *f, &mut load1);
        add_trace_force(&traces2[i], [-f[0], -f[1]], &mut load2);
    }
    let [t1, t2] = match temperatures {
        Some([a, b]) => [Some(a), Some(b)],
        None => [None, None],
    };
    let solve = |body: &ElasticBody, mut load: Vec<f64>, t: &Option<TemperatureField>| {
        let error = |e: crate::elasticity::ElasticityError| problem.error("bodies", e.to_string());
        let Some(t) = t else {
            return body.solve(&load).map_err(error);
        };
        let thermal = body.thermal_load_vector(&t.loads, |e| t.rise[e].clone());
        for (l, f) in load.iter_mut().zip(thermal) {
            *l += f;
        }
        let boundary = body.solve_boundary(&load).map_err(error)?;
        Ok(body.recover_thermal(boundary, &t.loads, |e| t.rise[e].clone()))
    };
    Ok([
        BodyField {
            elastic: solve(body1, load1, &t1)?,
            rigid: plate_motion(contact, &solution.rigid),
            temperature: t1,
        },
        BodyField {
            elastic: solve(body2, load2, &t2)?,
            rigid: RigidMotion::default(),
            temperature: t2,
        },
    ])
}

/// The gap n_i·(u²_i − u¹_i) + `geometric_gap[i]` at each contact point that the fields
/// reproduce (mm), with u^b_i body b's displacement in constraint i (its value at the point or
/// at its partner; body 2's mortar average on mortar contact: [`CondensedContact::traces`]);
/// `geometric_gap` is the gap of the undeformed bodies along n_c (plus any initial shape and
/// wear). `None` if a field does not match its body.
pub fn gap_of_fields(
    (body1, body2): (&ElasticBody, &ElasticBody),
    fields: &[BodyField; 2],
    contact: &CondensedContact,
    geometric_gap: &[f64],
) -> Option<Vec<f64>> {
    let pts = &contact.points;
    let [traces1, traces2] = &contact.traces;
    let sizes_match = fields[0].elastic.boundary.len() == body1.dofs.n_dofs()
        && fields[1].elastic.boundary.len() == body2.dofs.n_dofs();
    sizes_match.then(|| {
        (0..contact.len())
            .map(|i| {
                let rigid = fields[0].rigid.at(pts.x[i]);
                let e1 = trace_value(&traces1[i], &fields[0].elastic.boundary);
                let u1 = [e1[0] + rigid[0], e1[1] + rigid[1]];
                let u2 = trace_value(&traces2[i], &fields[1].elastic.boundary);
                let n = pts.normal[i];
                n[0] * (u2[0] - u1[0]) + n[1] * (u2[1] - u1[1]) + geometric_gap[i]
            })
            .collect()
    })
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
