//! A rigid translation of a whole mesh, its exact geometry included: the sliding contact
//! model moves body 2 along its track and meets body 1 with the translated copy, so that the
//! mortar traces of every position come from the same code as those at rest. The stiffness
//! does not change under a translation, so a body's factorisation serves every copy.

use super::Mesh;
use crate::geometry::{Block, Curve, Point};

fn shifted(p: Point, by: Point) -> Point {
    [p[0] + by[0], p[1] + by[1]]
}

fn translated_curve(curve: &Curve, by: Point) -> Curve {
    match *curve {
        Curve::Line { start, end } => Curve::Line {
            start: shifted(start, by),
            end: shifted(end, by),
        },
        Curve::Arc {
            center,
            radius,
            start_angle,
            end_angle,
        } => Curve::Arc {
            center: shifted(center, by),
            radius,
            start_angle,
            end_angle,
        },
        Curve::Quadratic { start, middle, end } => Curve::Quadratic {
            start: shifted(start, by),
            middle: shifted(middle, by),
            end: shifted(end, by),
        },
    }
}

fn translated_block(block: &Block, by: Point) -> Block {
    Block {
        corners: block.corners.map(|c| shifted(c, by)),
        edges: std::array::from_fn(|e| translated_curve(&block.edges[e], by)),
    }
}

impl Mesh {
    /// The same mesh moved by `by` = [Δx, Δz] (mm): vertices and block geometry (corners,
    /// lines, arc centres, parabolas) translated; elements, edges and names unchanged.
    pub fn translated(&self, by: Point) -> Mesh {
        let mut mesh = self.clone();
        for v in &mut mesh.vertices {
            *v = shifted(*v, by);
        }
        for b in &mut mesh.blocks {
            b.block = translated_block(&b.block, by);
        }
        mesh
    }
}

#[cfg(test)]
mod tests {
    use crate::geometry::{Block, EdgeShape};
    use crate::mesh::{Mesh, MeshBlock};

    #[test]
    fn every_edge_point_moves_by_the_translation() {
        // An arc edge checks that the centre moves with the corners (a forgotten centre
        // would bend the edge away from its translated ends).
        let block = Block::new(
            [[0.0, 0.0], [10.0, 0.0], [10.0, 5.0], [0.0, 5.0]],
            [
                EdgeShape::ArcAbout([5.0, 100.0]),
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
            ],
        )
        .unwrap();
        let mesh = Mesh::build(vec![MeshBlock {
            block,
            u_lines: vec![0.0, 0.3, 0.7, 1.0],
            v_lines: vec![0.0, 0.5, 1.0],
            material: 0,
            edge_names: [None, None, None, None],
        }])
        .unwrap();
        let by = [2.5, -1.0];
        let moved = mesh.translated(by);
        for e in 0..mesh.elements.len() {
            for local in 0..4 {
                for t in [-1.0, -0.3, 0.4, 1.0] {
                    let a = mesh.point_on_edge(e, local, t);
                    let b = moved.point_on_edge(e, local, t);
                    // Round-off of one addition on coordinates of order 10 mm.
                    assert!((b[0] - a[0] - by[0]).abs() < 1e-12);
                    assert!((b[1] - a[1] - by[1]).abs() < 1e-12);
                }
            }
        }
    }
}
