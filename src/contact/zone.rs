//! Contact zones cut by the model: a contact that reaches an end of the named contact edge where
//! body 1's surface goes on beyond it.
//!
//! At a corner of body 1 (the flat punch's edges), the end of the contact zone is physical: the
//! surface turns away from body 2 there, and a pressure peak at the corner is the answer. Where
//! the surface continues smoothly (an arc of which only part was named `contact`), the points
//! beyond the named edge cannot touch body 2 in the model even if they would in reality, so
//! the zone, and everything computed from it, depends on where the edge was cut. The surface
//! is taken to continue when a boundary edge of body 1 leaves the end turning by less than 45°
//! from the contact edge's direction (a right-angled corner turns by 90°, a smooth arc by 0°).

use super::mortar::ChainElement;
use super::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::mesh::EDGE_ENDPOINTS;

/// An end of the named contact edge that carries pressure although body 1's surface goes on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeEnd {
    /// Index of the end's contact point (0 or N − 1).
    pub point: usize,
    /// Its position [x, z], mm.
    pub x: Point,
    /// The largest pressure there over the profiles examined, MPa.
    pub pressure: f64,
}

/// A turn by less than this (cos 45°) counts as the surface going on.
const CONTINUES_COS: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// For the first and the last contact point: whether body 1's boundary continues beyond it.
pub(super) fn surface_continues(body: &ElasticBody, chain: &[ChainElement]) -> [bool; 2] {
    let (Some(first), Some(last)) = (
        chain.iter().min_by_key(|c| c.first_point),
        chain.iter().max_by_key(|c| c.first_point),
    ) else {
        return [false, false];
    };
    let in_chain: Vec<usize> = chain
        .iter()
        .map(|c| body.mesh.elements[c.element].edges[c.local])
        .collect();
    // The direction leaving the chain at its start (s = −1) and at its end (s = +1).
    let leaving = |c: &ChainElement, at_end: bool| -> (usize, Point) {
        let (a, b) = EDGE_ENDPOINTS[c.local];
        let vertices = body.mesh.elements[c.element].vertices;
        // s runs with t unless reversed; the vertex at s = ±1 and dx/ds there.
        let t = if at_end != c.reversed { 1.0 } else { -1.0 };
        let vertex = if t > 0.0 { vertices[b] } else { vertices[a] };
        let (tangent, _) = body.mesh.edge_frame(c.element, c.local, t);
        let sign = if c.reversed { -1.0 } else { 1.0 } * if at_end { 1.0 } else { -1.0 };
        (vertex, [sign * tangent[0], sign * tangent[1]])
    };
    let continues = |(vertex, out): (usize, Point)| {
        body.mesh.edges.iter().enumerate().any(|(id, edge)| {
            if edge.elements.len() != 1
                || in_chain.contains(&id)
                || !edge.vertices.contains(&vertex)
            {
                return false;
            }
            let (e, l) = edge.elements[0];
            let from_start = body.mesh.elements[e].vertices[EDGE_ENDPOINTS[l].0] == vertex;
            let (tangent, _) = body
                .mesh
                .edge_frame(e, l, if from_start { -1.0 } else { 1.0 });
            let dir = if from_start {
                tangent
            } else {
                [-tangent[0], -tangent[1]]
            };
            let cos =
                (dir[0] * out[0] + dir[1] * out[1]) / (dir[0].hypot(dir[1]) * out[0].hypot(out[1]));
            cos > CONTINUES_COS
        })
    };
    [
        continues(leaving(first, false)),
        continues(leaving(last, true)),
    ]
}

/// The ends that continue and carry pressure in any of `pressures`.
pub(super) fn ends_in_contact(contact: &CondensedContact, pressures: &[&[f64]]) -> Vec<EdgeEnd> {
    let n = contact.len();
    if n == 0 {
        return Vec::new();
    }
    let mut ends = Vec::new();
    for (k, point) in [0, n - 1].into_iter().enumerate() {
        if !contact.surface_continues[k] || (k == 1 && n == 1) {
            continue;
        }
        let pressure = pressures
            .iter()
            .filter(|p| {
                let peak = p.iter().cloned().fold(0.0, f64::max);
                p.get(point).is_some_and(|&v| v > 1e-6 * peak)
            })
            .map(|p| p[point])
            .fold(f64::NAN, f64::max);
        if pressure.is_finite() {
            ends.push(EdgeEnd {
                point,
                x: contact.points.x[point],
                pressure,
            });
        }
    }
    ends
}
