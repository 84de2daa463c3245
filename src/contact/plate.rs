//! The rigid loading plate: its rigid-body modes (vertical translation, rotation about the pin),
//! and the generalised loads L_k that the tractions on body 1 apply to them.

use super::{ContactPoints, PlateSpec};
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

/// Rigid modes at the contact points, their names, the loads L_k, and the resultant force (N)
/// and moment (N·mm) of the plate-edge tractions.
pub(super) type PlateModes = (Vec<Vec<Point>>, Vec<&'static str>, Vec<f64>, (Point, f64));

/// The plate's rigid-body modes and loads for plate `pl` of body 1 (`b1`).
pub(super) fn plate_modes(
    problem: &Problem,
    b1: usize,
    body1: &ElasticBody,
    pl: &PlateSpec,
    points: &ContactPoints,
) -> Result<PlateModes, ProblemError> {
    let plate_edges = problem.named_edge(&body1.mesh, b1, &pl.edge, "plate.edge")?;
    super::spec::check_plate(problem, pl)?;
    let pin = match pl.pin {
        Some(p) => p,
        None => {
            // Without a pin, moments are reported about the plate edge's centroid.
            let (mut sum, mut length) = ([0.0; 2], 0.0);
            for &(e, l) in plate_edges {
                for (t, ds) in crate::loads::edge_quadrature(&body1.mesh, e, l, None, 4) {
                    let x = body1.mesh.point_on_edge(e, l, t);
                    sum = [sum[0] + x[0] * ds, sum[1] + x[1] * ds];
                    length += ds;
                }
            }
            [sum[0] / length, sum[1] / length]
        }
    };
    // λ_F translates the plate towards body 2: down when body 2 lies below body 1 (the
    // paper's punch on a strip), up when it lies above (the normals n_c point into body 2).
    let facing_up: f64 = points
        .normal
        .iter()
        .zip(&points.weight)
        .map(|(n, w)| n[1] * w)
        .sum();
    let toward = if facing_up > 0.0 { 1.0 } else { -1.0 };
    let length: f64 = points.weight.iter().sum();
    if pl.motion != "fixed"
        && facing_up.abs() <= 1e-9 * length
        && problem.analysis.is_axisymmetric()
    {
        return Err(problem.error(
            "plate.motion",
            format!(
                "the contact edge \"{}\" faces the axis or away from it (a pin in a bore, a ring on a shaft), and the plate of a body of revolution moves only along the axis: it cannot press the bodies together. Hold the plate (motion = \"fixed\") and press them by an overlap of their geometry or by loads on their other edges",
                problem.spec.contact.as_ref().map_or("", |c| c.edge.as_str())
            ),
        ));
    }
    if pl.motion != "fixed" && facing_up.abs() <= 1e-9 * length {
        // Body 2 lies beside body 1 (the contact's normals horizontal on the whole): a plate
        // that moves only vertically can neither press body 1 onto it nor balance the load.
        return Err(problem.error(
            "plate.motion",
            format!(
                "the contact edge \"{}\" faces sideways (its normals are horizontal on average), but the plate moves only vertically and cannot press body 1 onto body 2; turn the model so that body 2 lies below or above body 1, or hold the plate (motion = \"fixed\")",
                problem.spec.contact.as_ref().map_or("", |c| c.edge.as_str())
            ),
        ));
    }
    let translation = move |_: Point| [0.0, toward];
    let rotation = move |x: Point| [x[1] - pin[1], -(x[0] - pin[0])];
    type Mode = (&'static str, Box<dyn Fn(Point) -> Point>);
    let modes: Vec<Mode> = match pl.motion.as_str() {
        "fixed" => vec![],
        "vertical" => vec![("lambda_F", Box::new(translation))],
        "vertical_rotation" => vec![
            ("lambda_F", Box::new(translation)),
            ("lambda_M", Box::new(rotation)),
        ],
        other => return Err(super::spec::unknown_motion(problem, other)),
    };
    let mut force = [0.0; 2];
    let mut moment = 0.0;
    let mut load = vec![0.0; modes.len()];
    // Every load on body 1 reaches the plate (body 1 is clamped to it): all enter L_k.
    for (k, tr) in problem.tractions(b1)?.iter().enumerate() {
        let edges = problem.named_edge(
            &body1.mesh,
            b1,
            &tr.edge,
            &format!("bodies[{b1}].tractions[{k}].edge"),
        )?;
        tr.for_each_point(
            &body1.mesh,
            edges,
            body1.dofs.p,
            problem.analysis,
            |_, _, _, x, trac, w| {
                force[0] += trac[0] * w;
                force[1] += trac[1] * w;
                moment += ((x[1] - pin[1]) * trac[0] - (x[0] - pin[0]) * trac[1]) * w;
                for (k, (_, phi)) in modes.iter().enumerate() {
                    let f = phi(x);
                    load[k] += (trac[0] * f[0] + trac[1] * f[1]) * w;
                }
            },
        );
    }
    // load[0] is the work of the loads on the translation towards body 2: positive when they
    // press body 1 onto body 2. Otherwise a plate free to move lifts off and no contact exists.
    if !modes.is_empty() && (load[0].is_nan() || load[0] <= 0.0) {
        return Err(problem.error(
            format!("bodies[{b1}].tractions"),
            format!(
                "the loads on body 1 do not press it onto body 2 (vertical resultant {:+.4e} N, + = up; body 2 lies {} body 1), so a plate free to move lifts it off",
                force[1],
                if toward > 0.0 { "above" } else { "below" }
            ),
        ));
    }
    let names = modes.iter().map(|m| m.0).collect();
    let phis: Vec<Vec<Point>> = modes
        .iter()
        .map(|(_, phi)| points.x.iter().map(|&x| phi(x)).collect())
        .collect();
    if phis.len() == 2 && moves_together(&phis, points) {
        return Err(problem.error(
            "plate.pin",
            format!(
                "turning the plate about the pin at ({}, {}) moves the contact points along their normals in the same pattern as its vertical translation (or not at all: the pin is at the contact edge's centre of curvature), so no contact pressure resists one combination of the two, and the plate would move freely (red team 22: a rotation of 5e8 rad, pressures 25 % off); move the pin, or use motion = \"vertical\"",
                pin[0], pin[1]
            ),
        ));
    }
    if problem.analysis.is_axisymmetric() {
        // Loads all round a circle have no net radial force and no moment in the (r, z)
        // plane: what the sums give there is an artefact of the half-plane (a review found
        // −942 478 N reported for a tube under external pressure).
        force[0] = 0.0;
        moment = 0.0;
    }
    Ok((phis, names, load, (force, moment)))
}

/// Whether the two plate modes' normal displacements at the contact points are linearly
/// dependent (to round-off): the Gram matrix of the patterns n·φ_k, weighted by the points'
/// lengths, is then singular.
fn moves_together(phis: &[Vec<Point>], points: &ContactPoints) -> bool {
    let normal_part = |k: usize, i: usize| {
        let (phi, n) = (phis[k][i], points.normal[i]);
        phi[0] * n[0] + phi[1] * n[1]
    };
    let gram = |k: usize, l: usize| -> f64 {
        (0..points.x.len())
            .map(|i| points.weight[i] * normal_part(k, i) * normal_part(l, i))
            .sum()
    };
    let (a, b, c) = (gram(0, 0), gram(0, 1), gram(1, 1));
    // Against the size of the modes' whole displacements, not of their normal parts: a pin
    // at the centre of curvature leaves the rotation's normal part at round-off, whose
    // direction is arbitrary. Exact geometry puts it near 1e-30 of the scale, a real lever
    // arm far above 1e-10.
    let size = |k: usize| -> f64 {
        (0..points.x.len())
            .map(|i| points.weight[i] * (phis[k][i][0].powi(2) + phis[k][i][1].powi(2)))
            .sum()
    };
    a * c - b * b <= 1e-10 * size(0) * size(1)
}
