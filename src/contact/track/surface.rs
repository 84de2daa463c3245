//! Where body 2's track lies at rest: a point and the outward normal of its surface at each
//! track coordinate, for drawing the worn track (ParaView).

use super::TrackShape;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

/// The surface of body 2 at track coordinates `x` (mm): points (mm) and unit outward normals.
/// On a straight track the point of the contact edge below (or above) x, found along z; on a
/// ring the point of its circle at arc length x from its top, turning clockwise (+x at the
/// top), as [`crate::contact::track`] measures it.
pub fn track_surface(
    problem: &Problem,
    body2: &ElasticBody,
    shape: TrackShape,
    x: &[f64],
) -> Result<Vec<(Point, Point)>, ProblemError> {
    let (_, edge) = crate::contact::target_edge(problem, body2)?;
    let mesh = &body2.mesh;
    let top = mesh.vertices.iter().fold(f64::MIN, |a, v| a.max(v[1]));
    Ok(x.iter()
        .map(|&x| match shape {
            TrackShape::Ring { center, radius } => {
                let angle = x / radius;
                let normal = [angle.sin(), angle.cos()];
                (
                    [
                        center[0] + radius * normal[0],
                        center[1] + radius * normal[1],
                    ],
                    normal,
                )
            }
            TrackShape::Straight => {
                let from = [x, top + 1.0];
                match mesh.cross_edges(edge, from, [0.0, -1.0]) {
                    Some((s, element, local, t)) => {
                        ([x, from[1] - s], mesh.edge_frame(element, local, t).1)
                    }
                    // Beyond the edge's ends (a track cell overhanging them): drawn at the
                    // body's top, facing up.
                    None => ([x, top], [0.0, 1.0]),
                }
            }
        })
        .collect())
}
