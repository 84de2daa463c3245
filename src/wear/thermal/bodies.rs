//! What each body's heat problem is made of, from the `[heat]` section and the contact: its
//! edge conditions, the part of body 2's contact edge that body 1 does not cover, and under
//! monotonic sliding the motion of body 2's material.

use super::counterface::counterface_flow;
use super::{Sliding, ThermalBodies, ThermalError};
use crate::basis::Space;
use crate::conduction::{ConductionBody, ConductionSpec, EdgePiece};
use crate::contact::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::heat_input::HeatSpace;

/// The conduction spec of contact body `b`: its edge conditions, and for body 2 the part of
/// its contact edge that body 1 does not cover and, under monotonic sliding, the motion of its
/// material through the contact (entering at the ambient temperature).
pub(super) fn conduction_spec(
    input: &ThermalBodies<'_>,
    b: usize,
) -> Result<ConductionSpec, ThermalError> {
    let settings = input.settings;
    let body = input.elastic[b];
    let heat = &settings.bodies[b];
    let mut edges = heat.edges.clone();
    if let Some(condition) = heat.uncovered {
        edges.extend(
            uncovered_pieces(body, &heat.contact_edge, input.contact)
                .into_iter()
                .map(|p| (p, condition)),
        );
    }
    let flow = match input.sliding {
        Sliding::Monotonic { speed, .. } if b == 1 => {
            Some(counterface_flow(&input.contact.points, speed)?)
        }
        _ => None,
    };
    // The heat enters along the contact edge in a layer far thinner than an element: there
    // the temperature keeps the displacement's space by default ([`crate::conduction::spaces`]).
    let (space, tensor_elements) = match settings.space {
        HeatSpace::Tensor => (Space::TensorProduct, Vec::new()),
        HeatSpace::Trunk => (Space::Trunk, Vec::new()),
        HeatSpace::Auto if input.space == Space::Trunk => (Space::Trunk, Vec::new()),
        HeatSpace::Auto => (
            Space::Trunk,
            heat.contact_edge
                .iter()
                .map(|&(element, _)| element)
                .collect(),
        ),
    };
    Ok(ConductionSpec {
        name: body.name.clone(),
        p: body.dofs.p,
        space,
        tensor_elements,
        // Heat needs contact, which axisymmetric bodies do not have yet (refused with it).
        thickness: body
            .analysis
            .thickness()
            .expect("contact, and with it heat, is refused for axisymmetric bodies"),
        materials: settings.materials.iter().map(|m| Some(*m)).collect(),
        edges,
        faces: settings.faces,
        flow,
        inflow_temperature: settings.ambient,
    })
}

/// The parts of body 2's contact edge that no partner of a contact point lies on: the edge's
/// element edges are chained end to end, each partner placed on the chain (link i covers
/// positions i … i + 1), and what lies outside the smallest stretch holding every partner (an
/// arc of a closed chain, a ring's rim, may hold them across its seam) is uncovered. Judging
/// by a direction in the plane instead left the far side of a rim insulated.
fn uncovered_pieces(
    body: &ElasticBody,
    edge: &[(usize, usize)],
    contact: &CondensedContact,
) -> Vec<EdgePiece> {
    let mesh = &body.mesh;
    let pts = &contact.points;
    let (chain, closed) = chain_of(mesh, edge);
    let links = chain.len() as f64;
    let mut positions: Vec<f64> = (0..pts.x.len())
        .filter_map(|i| {
            let (_, e, l, t) = mesh.cross_edges(edge, pts.x[i], pts.normal[i])?;
            let k = chain.iter().position(|&(ce, cl, _)| ce == e && cl == l)?;
            let along = if chain[k].2 { -t } else { t };
            Some(k as f64 + 0.5 * (along + 1.0))
        })
        .collect();
    if positions.is_empty() {
        return Vec::new();
    }
    positions.sort_by(f64::total_cmp);
    // The covered stretch [from, to]: on a closed chain the complement of the widest empty
    // gap between neighbouring partners (the seam's gap included).
    let (mut from, mut to) = (positions[0], positions[positions.len() - 1]);
    if closed {
        let seam = positions[0] + links - to;
        let widest = positions
            .windows(2)
            .enumerate()
            .map(|(i, w)| (i, w[1] - w[0]))
            .fold(
                (usize::MAX, seam),
                |best, (i, g)| if g > best.1 { (i, g) } else { best },
            );
        if widest.0 != usize::MAX {
            from = positions[widest.0 + 1];
            to = positions[widest.0] + links;
        }
    }
    let covered = |s: f64| {
        let wrapped = if closed && s < from { s + links } else { s };
        wrapped >= from && wrapped <= to
    };
    let mut pieces = Vec::new();
    for (k, &(element, local, reversed)) in chain.iter().enumerate() {
        // Cut the link where the stretch ends inside it.
        let mut cuts = vec![0.0, 1.0];
        for end in [from, to] {
            let local_end = end.rem_euclid(links) - k as f64;
            if local_end > 0.0 && local_end < 1.0 {
                cuts.push(local_end);
            }
        }
        cuts.sort_by(f64::total_cmp);
        for w in cuts.windows(2) {
            if w[1] - w[0] < 1e-12 || covered(k as f64 + 0.5 * (w[0] + w[1])) {
                continue;
            }
            let t = |u: f64| {
                let along = 2.0 * u - 1.0;
                if reversed {
                    -along
                } else {
                    along
                }
            };
            let (a, b) = (t(w[0]), t(w[1]));
            pieces.push(EdgePiece {
                element,
                local,
                t: [a.min(b), a.max(b)],
            });
        }
    }
    pieces
}

/// The element edges of `edge` ordered end to end, each with whether it is walked against
/// its parameter, and whether the chain closes on itself.
fn chain_of(
    mesh: &crate::mesh::Mesh,
    edge: &[(usize, usize)],
) -> (Vec<(usize, usize, bool)>, bool) {
    let ends = |&(e, l): &(usize, usize)| {
        let (a, b) = crate::mesh::EDGE_ENDPOINTS[l];
        (mesh.elements[e].vertices[a], mesh.elements[e].vertices[b])
    };
    let count = |v: usize| {
        edge.iter()
            .filter(|x| ends(x).0 == v || ends(x).1 == v)
            .count()
    };
    let mut left: Vec<(usize, usize)> = edge.to_vec();
    let start = left
        .iter()
        .position(|x| count(ends(x).0) == 1 || count(ends(x).1) == 1)
        .unwrap_or(0);
    let closed = !left
        .iter()
        .any(|x| count(ends(x).0) == 1 || count(ends(x).1) == 1);
    let first = left.remove(start);
    let (a, b) = ends(&first);
    let reversed = count(a) != 1 && count(b) == 1;
    let mut chain = vec![(first.0, first.1, reversed)];
    let mut tip = if reversed { a } else { b };
    while let Some(k) = left
        .iter()
        .position(|x| ends(x).0 == tip || ends(x).1 == tip)
    {
        let next = left.remove(k);
        let (a, b) = ends(&next);
        let reversed = b == tip;
        tip = if reversed { a } else { b };
        chain.push((next.0, next.1, reversed));
    }
    // Pieces the walk did not reach (an edge in several lines) are appended as they are.
    chain.extend(left.into_iter().map(|(e, l)| (e, l, false)));
    (chain, closed)
}

/// v_max L / (2 a) of body `b` at the contact (see [`super::ThermalInfo::peclet`]).
/// The smallest diffusivity (mm²/s) of body `b`'s materials along its contact edge: that of
/// the thinnest thermal layer there.
pub(super) fn contact_diffusivity(
    input: &ThermalBodies<'_>,
    body: &ConductionBody,
    b: usize,
) -> f64 {
    input.settings.bodies[b]
        .contact_edge
        .iter()
        .filter_map(|&(e, _)| body.mesh.elements.get(e))
        .map(|e| input.settings.materials[e.material].diffusivity())
        .fold(f64::INFINITY, f64::min)
}

pub(super) fn peclet(input: &ThermalBodies<'_>, body: &ConductionBody, b: usize) -> f64 {
    let speed = match input.sliding {
        Sliding::Reciprocating { amplitude, omega } => amplitude * omega,
        Sliding::Monotonic { speed, .. } => speed,
    };
    let length: f64 = input.contact.points.weight.iter().sum();
    let element = input.settings.bodies[b]
        .contact_edge
        .first()
        .map_or(0, |&(e, _)| e);
    let material = body.mesh.elements.get(element).map_or(0, |e| e.material);
    let diffusivity = input.settings.materials[material].diffusivity();
    speed * length / (2.0 * diffusivity)
}
