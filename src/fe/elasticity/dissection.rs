//! A geometric nested-dissection order of a body's mesh entities, for the factorisation with
//! the contact trace ordered last ([`super::schur`]).
//!
//! Approximate minimum degree chooses each pivot by its local fill and cannot see that the
//! trace, eliminated last, couples the whole contact edge: with the trace last it left 2.7 to
//! 5 times the fill of the unconstrained factorisation. Nested dissection cuts the body by
//! mesh lines instead, recursively, and eliminates each half before the line that separates
//! them; the trace rows of the factor then fill only below the separators, whose number grows
//! with the depth of the recursion, not with the number of entities.
//!
//! The cut is geometric: the entities (vertices, and edges at their midpoints) are split at the
//! median of the longer side of their bounding box, and the separator is the set of entities
//! of the upper half that share an element with the lower half. Any order gives the same
//! factorisation up to round-off; this one only changes its cost.

use crate::mesh::Mesh;

/// Entities per leaf of the recursion, ordered as they come (about 2 elements' worth at p = 8:
/// small enough for the dense elimination of a leaf to cost nothing).
const LEAF: usize = 16;

/// The entities of `mesh` in nested-dissection order, restricted to those for which
/// `include(entity)` holds (vertices first in the numbering, then edges, as in
/// [`crate::dofs::DofMap`]).
pub fn entity_order(mesh: &Mesh, include: impl Fn(usize) -> bool) -> Vec<usize> {
    let n_vertices = mesh.vertices.len();
    let n = n_vertices + mesh.edges.len();
    let centre: Vec<[f64; 2]> = (0..n)
        .map(|e| {
            if e < n_vertices {
                mesh.vertices[e]
            } else {
                let [a, b] = mesh.edges[e - n_vertices].vertices;
                let (a, b) = (mesh.vertices[a], mesh.vertices[b]);
                [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
            }
        })
        .collect();
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); n];
    for element in &mesh.elements {
        let entities: Vec<usize> = element
            .vertices
            .iter()
            .copied()
            .chain(element.edges.iter().map(|&e| n_vertices + e))
            .collect();
        for &a in &entities {
            neighbours[a].extend(entities.iter().copied().filter(|&b| b != a));
        }
    }
    for list in neighbours.iter_mut() {
        list.sort_unstable();
        list.dedup();
    }
    let set: Vec<usize> = (0..n).filter(|&e| include(e)).collect();
    let mut side = vec![0u8; n];
    let mut order = Vec::with_capacity(set.len());
    dissect(set, &centre, &neighbours, &mut side, &mut order);
    order
}

/// Append the order of `set` to `order`: both halves, then their separator. `side` is scratch
/// (all 0 between uses).
fn dissect(
    mut set: Vec<usize>,
    centre: &[[f64; 2]],
    neighbours: &[Vec<usize>],
    side: &mut [u8],
    order: &mut Vec<usize>,
) {
    if set.len() <= LEAF {
        order.extend(set);
        return;
    }
    // Cut across each axis in turn and keep the cut with the smaller separator: the longer
    // side of the box is not always the one with the shorter cut (a mesh graded in one
    // direction, a body taller in millimetres than in elements).
    let mut best: Option<(Vec<usize>, Vec<usize>, Vec<usize>)> = None;
    for axis in [0, 1] {
        set.sort_by(|&a, &b| centre[a][axis].total_cmp(&centre[b][axis]));
        // Entities on one mesh line share its coordinate: keep them on one side, so that the
        // separator is that line and not a jagged band around it.
        let median = centre[set[set.len() / 2]][axis];
        let mut cut = set.partition_point(|&e| centre[e][axis] < median);
        if cut == 0 {
            cut = set.partition_point(|&e| centre[e][axis] <= median);
        }
        if cut == set.len() {
            continue;
        }
        let (lower, upper) = set.split_at(cut);
        for &e in lower {
            side[e] = 1;
        }
        let (separator, upper): (Vec<usize>, Vec<usize>) = upper
            .iter()
            .partition(|&&e| neighbours[e].iter().any(|&f| side[f] == 1));
        for &e in lower {
            side[e] = 0;
        }
        if best.as_ref().is_none_or(|b| separator.len() < b.2.len()) {
            best = Some((lower.to_vec(), upper, separator));
        }
    }
    let Some((lower, upper, separator)) = best else {
        // Every entity at one point of both axes: nothing to cut.
        order.extend(set);
        return;
    };
    if upper.is_empty() || lower.is_empty() {
        // Nothing left to cut (all of one half touches the other): eliminate as it comes.
        order.extend(lower);
        order.extend(upper);
        order.extend(separator);
        return;
    }
    dissect(lower, centre, neighbours, side, order);
    dissect(upper, centre, neighbours, side, order);
    order.extend(separator);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::Problem;

    #[test]
    fn every_included_entity_exactly_once() {
        let problem =
            Problem::from_toml(crate::examples::example("punch-b40").unwrap(), "b40").unwrap();
        let body = problem.elastic_body(1, &[]).unwrap();
        let mesh = &body.mesh;
        let n = mesh.vertices.len() + mesh.edges.len();
        let order = entity_order(mesh, |e| e % 7 != 3);
        let mut seen = vec![false; n];
        for &e in &order {
            assert!(!seen[e], "entity {e} twice");
            seen[e] = true;
        }
        for (e, &s) in seen.iter().enumerate() {
            assert_eq!(s, e % 7 != 3, "entity {e}");
        }
    }
}
