//! Rigid motions of a whole mesh, its exact geometry included: the sliding contact model moves
//! body 2 along its track (a translation along a straight track, a rotation about a ring's
//! centre) and meets body 1 with the moved copy, so that the mortar traces of every position
//! come from the same code as those at rest. The stiffness does not change under a rigid
//! motion once the dofs are rotated with it; a translation leaves them as they are, and a
//! rotation is only used where the stiffness is not needed again (see
//! [`crate::contact::track`]).

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

fn rotated_point(p: Point, center: Point, angle: f64) -> Point {
    let (sin, cos) = angle.sin_cos();
    let (dx, dz) = (p[0] - center[0], p[1] - center[1]);
    [
        center[0] + cos * dx - sin * dz,
        center[1] + sin * dx + cos * dz,
    ]
}

fn rotated_curve(curve: &Curve, center: Point, angle: f64) -> Curve {
    let turn = |p: Point| rotated_point(p, center, angle);
    match *curve {
        Curve::Line { start, end } => Curve::Line {
            start: turn(start),
            end: turn(end),
        },
        Curve::Arc {
            center: c,
            radius,
            start_angle,
            end_angle,
        } => Curve::Arc {
            center: turn(c),
            radius,
            start_angle: start_angle + angle,
            end_angle: end_angle + angle,
        },
        Curve::Quadratic { start, middle, end } => Curve::Quadratic {
            start: turn(start),
            middle: turn(middle),
            end: turn(end),
        },
    }
}

impl Mesh {
    /// The same mesh turned by `angle` (radians, counter-clockwise) about `center` ([x, z],
    /// mm): vertices and block geometry turned; elements, edges and names unchanged.
    pub fn rotated(&self, center: Point, angle: f64) -> Mesh {
        let mut mesh = self.clone();
        for v in &mut mesh.vertices {
            *v = rotated_point(*v, center, angle);
        }
        for b in &mut mesh.blocks {
            b.block = Block {
                corners: b.block.corners.map(|c| rotated_point(c, center, angle)),
                edges: std::array::from_fn(|e| rotated_curve(&b.block.edges[e], center, angle)),
            };
        }
        mesh
    }

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

    /// A block with an arc edge: the arc checks that its centre moves with the corners (a
    /// forgotten centre would bend the edge away from its moved ends).
    fn arc_mesh() -> Mesh {
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
        Mesh::build(vec![MeshBlock {
            block,
            u_lines: vec![0.0, 0.3, 0.7, 1.0],
            v_lines: vec![0.0, 0.5, 1.0],
            material: 0,
            edge_names: [None, None, None, None],
        }])
        .unwrap()
    }

    #[test]
    fn every_edge_point_turns_with_the_rotation() {
        let mesh = arc_mesh();
        let (center, angle) = ([3.0, -7.0], 0.7f64);
        let turned = mesh.rotated(center, angle);
        for e in 0..mesh.elements.len() {
            for local in 0..4 {
                for t in [-1.0, -0.3, 0.4, 1.0] {
                    let a = mesh.point_on_edge(e, local, t);
                    let b = turned.point_on_edge(e, local, t);
                    let (dx, dz) = (a[0] - center[0], a[1] - center[1]);
                    let expected = [
                        center[0] + angle.cos() * dx - angle.sin() * dz,
                        center[1] + angle.sin() * dx + angle.cos() * dz,
                    ];
                    assert!((b[0] - expected[0]).abs() < 1e-12, "{b:?} {expected:?}");
                    assert!((b[1] - expected[1]).abs() < 1e-12, "{b:?} {expected:?}");
                }
            }
        }
    }

    #[test]
    fn every_edge_point_moves_by_the_translation() {
        let mesh = arc_mesh();
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
