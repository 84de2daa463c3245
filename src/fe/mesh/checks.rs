//! The checks of a built mesh: lines, thickness, conformity, Jacobians and topology. A mesh
//! that passes them is one body of conforming, unfolded elements (see [`Mesh::build`]).

use super::{Mesh, MeshError, EDGE_ENDPOINTS};
use crate::geometry::Point;

/// Samples per element edge for the distance of a point from it.
const EDGE_SAMPLES: usize = 16;

/// Points along an element edge and the box around them ([`Mesh::edge_samples`]).
struct EdgeSamples {
    element: usize,
    local: usize,
    samples: Vec<(f64, Point)>,
    lo: Point,
    hi: Point,
}

/// Mesh lines of one block direction must rise from 0 to 1 by at least 1e-6 of the side:
/// thinner elements only make the stiffness matrix singular in floating point. The elements
/// must also be at least [`super::HANGING`] × the body's size across ([`Mesh::build`]).
pub(super) fn check_lines(
    block: usize,
    direction: &'static str,
    lines: &[f64],
) -> Result<(), MeshError> {
    let ok = lines.len() >= 2
        && lines[0] == 0.0
        && *lines.last().unwrap() == 1.0
        && lines.windows(2).all(|w| w[1] - w[0] >= 1e-6)
        && lines.iter().all(|l| l.is_finite());
    if ok {
        Ok(())
    } else {
        Err(MeshError::BadLines {
            block,
            direction,
            lines: lines.to_vec(),
        })
    }
}

impl Mesh {
    /// Each element edge is shared by at most two elements and no two elements have the same
    /// vertices (else blocks overlap, e.g. one listed twice); all elements connect through
    /// shared edges (a block touching the rest at one vertex would hinge about it).
    pub(super) fn check_topology(&self) -> Result<(), MeshError> {
        let mut seen = std::collections::HashSet::new();
        for el in &self.elements {
            let mut key = el.vertices;
            key.sort_unstable();
            if !seen.insert(key) {
                return Err(MeshError::Overlap { block: el.block });
            }
        }
        if let Some(edge) = self.edges.iter().find(|e| e.elements.len() > 2) {
            let block = self.elements[edge.elements[0].0].block;
            return Err(MeshError::Overlap { block });
        }
        // Flood fill over shared edges from element 0.
        let mut reached = vec![false; self.elements.len()];
        let mut stack = vec![0];
        while let Some(e) = stack.pop() {
            if std::mem::replace(&mut reached[e], true) {
                continue;
            }
            for &edge in &self.elements[e].edges {
                stack.extend(self.edges[edge].elements.iter().map(|&(n, _)| n));
            }
        }
        match reached.iter().position(|r| !r) {
            Some(e) => Err(MeshError::Disconnected {
                block: self.elements[e].block,
            }),
            None => Ok(()),
        }
    }

    /// Points along local edge `local` of `element` at 17 parameters t, and the box around
    /// them, widened by a sixteenth of the edge's chord for the bulge of a curved edge between
    /// samples, and by `near`: only a point inside the box can be within `near` of the edge.
    fn edge_samples(&self, element: usize, local: usize, near: f64) -> EdgeSamples {
        let samples: Vec<(f64, Point)> = (0..=EDGE_SAMPLES)
            .map(|k| {
                let t = -1.0 + 2.0 * k as f64 / EDGE_SAMPLES as f64;
                (t, self.point_on_edge(element, local, t))
            })
            .collect();
        let (first, last) = (samples[0].1, samples[EDGE_SAMPLES].1);
        let margin = near + (last[0] - first[0]).hypot(last[1] - first[1]) / EDGE_SAMPLES as f64;
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for (_, p) in &samples {
            for d in 0..2 {
                lo[d] = lo[d].min(p[d] - margin);
                hi[d] = hi[d].max(p[d] + margin);
            }
        }
        EdgeSamples {
            element,
            local,
            samples,
            lo,
            hi,
        }
    }

    /// Distance of `v` from the edge of `edge` (None outside its box): the nearest of the
    /// samples, refined by ternary search.
    fn distance_to_edge(&self, edge: &EdgeSamples, v: Point) -> Option<f64> {
        if (0..2).any(|d| v[d] < edge.lo[d] || v[d] > edge.hi[d]) {
            return None;
        }
        let distance = |t: f64| {
            let p = self.point_on_edge(edge.element, edge.local, t);
            (p[0] - v[0]).hypot(p[1] - v[1])
        };
        let best = edge
            .samples
            .iter()
            .map(|&(t, _)| t)
            .min_by(|&a, &b| distance(a).total_cmp(&distance(b)))
            .unwrap_or(0.0);
        let step = 2.0 / EDGE_SAMPLES as f64;
        let (mut a, mut b) = ((best - step).max(-1.0), (best + step).min(1.0));
        for _ in 0..60 {
            let (m1, m2) = (a + (b - a) / 3.0, b - (b - a) / 3.0);
            if distance(m1) < distance(m2) {
                b = m2;
            } else {
                a = m1;
            }
        }
        Some(distance(0.5 * (a + b)))
    }

    /// Every element at least `minimum` thick: each corner at least that far from the two
    /// edges it is not on. A thinner element's corner would lie within the conformity check's
    /// tolerance (the same `minimum`) of the element's own edge, or of its neighbour's, and be
    /// reported as a hanging vertex of a mesh that is conforming.
    pub(super) fn check_thickness(&self, minimum: f64) -> Result<(), MeshError> {
        for (id, el) in self.elements.iter().enumerate() {
            for (local, &(a, b)) in EDGE_ENDPOINTS.iter().enumerate() {
                let edge = self.edge_samples(id, local, minimum);
                for corner in (0..4).filter(|&c| c != a && c != b) {
                    let v = self.vertices[el.vertices[corner]];
                    let Some(width) = self.distance_to_edge(&edge, v) else {
                        continue;
                    };
                    if width < minimum {
                        // Edges 0 and 2 run along u: a corner near one is a v step too small.
                        let (direction, lines) = if local % 2 == 0 {
                            ("v", &self.blocks[el.block].v_lines)
                        } else {
                            ("u", &self.blocks[el.block].u_lines)
                        };
                        return Err(MeshError::Thin {
                            block: el.block,
                            direction,
                            width,
                            minimum,
                            lines: lines.clone(),
                        });
                    }
                }
            }
        }
        Ok(())
    }

    /// A boundary edge (one element) that has a mesh vertex in its interior betrays a hanging
    /// node: two blocks whose lines do not match along a shared side. The vertex may sit
    /// anywhere along the edge, so its distance to the edge's curve is found (the nearest of
    /// 16 samples, refined by ternary search), for the vertices inside the edge's box; closer
    /// than `near` is on the edge.
    pub(super) fn check_conforming(&self, near: f64) -> Result<(), MeshError> {
        for edge in self.edges.iter().filter(|e| e.elements.len() == 1) {
            let (element, local) = edge.elements[0];
            let samples = self.edge_samples(element, local, near);
            for (id, v) in self.vertices.iter().enumerate() {
                if edge.vertices.contains(&id) {
                    continue;
                }
                if self
                    .distance_to_edge(&samples, *v)
                    .is_some_and(|d| d < near)
                {
                    return Err(MeshError::Hanging { x: v[0], z: v[1] });
                }
            }
        }
        Ok(())
    }

    pub(super) fn check_jacobians(&self) -> Result<(), MeshError> {
        for (id, el) in self.elements.iter().enumerate() {
            for &xi in &[-1.0, 0.0, 1.0] {
                for &eta in &[-1.0, 0.0, 1.0] {
                    let det = self.jacobian(id, xi, eta).1;
                    if det.is_nan() || det <= 0.0 {
                        return Err(MeshError::Folded {
                            element: id,
                            block: el.block,
                            det,
                        });
                    }
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Block, EdgeShape};
    use crate::mesh::MeshBlock;

    /// The punch of Example 1 as two blocks, 60 × 20 mm under 60 × 80 mm (the body is 100 mm
    /// in size: a vertex within 1e-4 mm of an edge lies on it), the upper one starting at z.
    fn punch(lower_u: &[f64], upper_u: &[f64], lower_v: &[f64], z: f64) -> Result<Mesh, MeshError> {
        let block = |z0: f64, z1: f64, u: &[f64], v: &[f64]| MeshBlock {
            block: Block::new(
                [[1070.0, z0], [1130.0, z0], [1130.0, z1], [1070.0, z1]],
                [const { EdgeShape::Straight }; 4],
            )
            .unwrap(),
            u_lines: u.to_vec(),
            v_lines: v.to_vec(),
            material: 0,
            edge_names: [None, None, None, None],
        };
        Mesh::build(vec![
            block(100.0, 120.0, lower_u, lower_v),
            block(z, 200.0, upper_u, &[0.0, 0.5, 1.0]),
        ])
    }

    const V: [f64; 3] = [0.0, 0.25, 1.0];

    /// Lines 1e-6 apart (legal as parameters) on the 60 mm side make elements 6e-5 mm wide,
    /// closer than the 1e-4 mm within which a vertex lies on an edge: the mesh is conforming,
    /// and the error says what is wrong (it said "not conforming" before).
    #[test]
    fn an_element_thinner_than_the_hanging_tolerance_is_named() {
        let u = [0.0, 1e-6, 0.5, 1.0];
        match punch(&u, &u, &V, 120.0) {
            Err(MeshError::Thin {
                block,
                direction,
                width,
                minimum,
                ..
            }) => {
                assert_eq!((block, direction), (0, "u"));
                // 1e-6 · 60 mm; the minimum is 1e-6 of the body's 100 mm.
                assert!((width - 6e-5).abs() < 1e-12, "{width}");
                assert!((minimum - 1e-4).abs() < 1e-18, "{minimum}");
            }
            other => panic!("{other:?}"),
        }
        // The same along v: 1e-6 of the lower block's 20 mm.
        let v = [0.0, 1e-6, 1.0];
        match punch(&[0.0, 1.0], &[0.0, 1.0], &v, 120.0) {
            Err(MeshError::Thin {
                block: 0,
                direction: "v",
                width,
                ..
            }) => assert!((width - 2e-5).abs() < 1e-12, "{width}"),
            other => panic!("{other:?}"),
        }
    }

    /// At 1.7e-6 of the side the elements are 1.02e-4 mm wide: accepted, conforming.
    #[test]
    fn an_element_just_above_the_minimum_is_accepted() {
        let u = [0.0, 1.7e-6, 0.5, 1.0];
        let mesh = punch(&u, &u, &V, 120.0).unwrap();
        assert_eq!(mesh.elements.len(), 3 * 2 + 3 * 2);
    }

    /// Genuinely non-conforming meshes with such thin elements are still rejected: a line the
    /// upper block lacks (its vertex hangs in the upper block's bottom edge), and a crack of
    /// 5e-5 mm between the blocks (every vertex of the upper block's bottom lies 5e-5 mm from
    /// the lower block's top edges, closer than 1e-4 mm, and none merges).
    #[test]
    fn non_conforming_meshes_with_thin_elements_are_still_rejected() {
        let thin = [0.0, 1.7e-6, 1.0];
        match punch(&[0.0, 1.7e-6, 0.3, 1.0], &thin, &V, 120.0) {
            Err(MeshError::Hanging { x, z }) => {
                assert!((x - 1088.0).abs() < 1e-9 && z == 120.0, "({x}, {z})")
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            punch(&thin, &thin, &V, 120.00005),
            Err(MeshError::Hanging { .. })
        ));
    }
}
