//! Mesh lines added to one body so that its element ends along a boundary meet another body's.
//!
//! Contact couples body 1's contact edge with body 2's. Where body 2's element ends miss body
//! 1's, a kink of body 2's surface displacement (the end of a contact zone, a punch corner)
//! falls inside a body 2 element, whose polynomial cannot follow it: on punch-b40 with an
//! evenly meshed strip the steady pressure is 2.3 % off the matched mesh's, and 0.09 % off
//! once the strip has lines at the punch's element ends (docs/validation.md). So body 2 gets a
//! mesh line wherever the normal line of one of body 1's element ends crosses its edge; each
//! new line runs through its whole block, and on through the neighbouring blocks until the
//! mesh is conforming again.

use super::{Mesh, MeshBlock, MeshError};
use crate::geometry::Point;

/// A line closer than this to an existing one (as a fraction of the element it would split)
/// is not added: a kink that close to an element end costs less than a sliver element.
const SKIP_FRACTION: f64 = 1e-3;

/// Two block parameters this close are the same line: lines must be at least 1e-6 apart
/// ([`Mesh::build`]), and a vertex that close to a line without merging with its vertex is a
/// hanging node the conformity check reports.
const SAME_LINE: f64 = 1e-6;

/// At most this many rounds of spreading lines to neighbouring blocks: each round crosses at
/// least one block, so a body of fewer blocks in a chain settles before.
const MAX_ROUNDS: usize = 256;

impl Mesh {
    /// The point of boundary `edges` (element, local edge) on the line x + s n (x and s in mm,
    /// n a unit vector) nearest to x among those whose outward normal faces against n:
    /// (s, element, local edge, edge parameter t ∈ [−1, 1]). None when the line misses.
    pub fn cross_edges(
        &self,
        edges: &[(usize, usize)],
        x: Point,
        n: Point,
    ) -> Option<(f64, usize, usize, f64)> {
        let mut best: Option<(f64, usize, usize, f64)> = None;
        for &(element, local) in edges {
            // Signed distance of edge point y(t) from the line: (y − x)·τ, τ ⟂ n; bisection.
            let side = |t: f64| {
                let y = self.point_on_edge(element, local, t);
                (y[0] - x[0]) * (-n[1]) + (y[1] - x[1]) * n[0]
            };
            let (fa, fb) = (side(-1.0), side(1.0));
            let scale = 1e-10 * (1.0 + x[0].abs() + x[1].abs());
            let t = if fa.abs() <= scale {
                -1.0
            } else if fb.abs() <= scale {
                1.0
            } else if fa * fb < 0.0 {
                crate::geometry::bisect(side, -1.0, 1.0, 80)
            } else {
                continue;
            };
            // Only a surface that faces x can be crossed first: its outward normal points back
            // against n (an edge on the far side of the body also crosses the line).
            let (_, outward) = self.edge_frame(element, local, t);
            if outward[0] * n[0] + outward[1] * n[1] >= 0.0 {
                continue;
            }
            let y = self.point_on_edge(element, local, t);
            let s = (y[0] - x[0]) * n[0] + (y[1] - x[1]) * n[1];
            if best.is_none_or(|b| s.abs() < b.0.abs()) {
                best = Some((s, element, local, t));
            }
        }
        best
    }

    /// This mesh with extra lines so that its element ends along `edges` meet the normal
    /// lines through `other`'s element ends along `other_edges` (both boundary edge lists of
    /// (element, local edge)), and the number of lines added to the blocks that carry `edges`
    /// ([`Mesh::added_lines`] counts those and the ones that spread to other blocks).
    /// Crossings within 1e-3 of an element from one of its ends add nothing; lines spread to
    /// neighbouring blocks until the mesh is conforming.
    pub fn aligned_to(
        &self,
        edges: &[(usize, usize)],
        other: &Mesh,
        other_edges: &[(usize, usize)],
    ) -> Result<(Mesh, usize), MeshError> {
        let mut blocks = self.blocks.clone();
        let mut added = 0;
        for &(element, local) in other_edges {
            for t in [-1.0, 1.0] {
                let x = other.point_on_edge(element, local, t);
                let (_, normal) = other.edge_frame(element, local, t);
                let Some((_, e2, l2, t2)) = self.cross_edges(edges, x, normal) else {
                    continue;
                };
                if 1.0 - t2.abs() < 2.0 * SKIP_FRACTION {
                    continue;
                }
                let el = &self.elements[e2];
                let (range, lines) = if l2 % 2 == 0 {
                    (el.u, &mut blocks[el.block].u_lines)
                } else {
                    (el.v, &mut blocks[el.block].v_lines)
                };
                let at = range[0] + 0.5 * (t2 + 1.0) * (range[1] - range[0]);
                added += usize::from(insert_line(lines, at));
            }
        }
        if added == 0 {
            return Ok((self.clone(), 0));
        }
        make_conforming(&mut blocks)?;
        let given: usize = self
            .blocks
            .iter()
            .map(|b| b.u_lines.len() + b.v_lines.len())
            .sum();
        let mut mesh = Mesh::build(blocks)?;
        let now: usize = mesh
            .blocks
            .iter()
            .map(|b| b.u_lines.len() + b.v_lines.len())
            .sum();
        mesh.added_lines = self.added_lines + now - given;
        Ok((mesh, added))
    }
}

/// Insert `at` into the rising `lines` unless it is already there; whether it was added.
fn insert_line(lines: &mut Vec<f64>, at: f64) -> bool {
    let i = lines.partition_point(|&l| l < at);
    let near = |j: usize| lines.get(j).is_some_and(|&l| (l - at).abs() <= SAME_LINE);
    if near(i) || (i > 0 && near(i - 1)) {
        return false;
    }
    lines.insert(i, at);
    true
}

/// The points where a block's lines meet its four sides.
fn side_points(mb: &MeshBlock) -> Vec<Point> {
    let b = &mb.block;
    let mut points = Vec::new();
    for &u in &mb.u_lines {
        points.push(b.map(u, 0.0));
        points.push(b.map(u, 1.0));
    }
    for &v in &mb.v_lines {
        points.push(b.map(0.0, v));
        points.push(b.map(1.0, v));
    }
    points
}

/// A box around a block: its sides sampled at 33 points each, widened by a sixteenth of its
/// size for a curved side's bulge between samples (the inverse map then decides).
fn bounding_box(block: &crate::geometry::Block) -> [Point; 2] {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for k in 0..=32 {
        let s = k as f64 / 32.0;
        for x in [
            block.map(s, 0.0),
            block.map(s, 1.0),
            block.map(0.0, s),
            block.map(1.0, s),
        ] {
            for d in 0..2 {
                lo[d] = lo[d].min(x[d]);
                hi[d] = hi[d].max(x[d]);
            }
        }
    }
    let margin = (hi[0] - lo[0]).max(hi[1] - lo[1]) / 16.0;
    [
        [lo[0] - margin, lo[1] - margin],
        [hi[0] + margin, hi[1] + margin],
    ]
}

/// Add to every block a line through each point of another block's sides that lies on one of
/// its own sides, until no block gains one: the lines of neighbouring blocks then match.
fn make_conforming(blocks: &mut [MeshBlock]) -> Result<(), MeshError> {
    let boxes: Vec<[Point; 2]> = blocks.iter().map(|mb| bounding_box(&mb.block)).collect();
    for _ in 0..MAX_ROUNDS {
        let points: Vec<(usize, Point)> = blocks
            .iter()
            .enumerate()
            .flat_map(|(k, mb)| side_points(mb).into_iter().map(move |x| (k, x)))
            .collect();
        let mut changed = false;
        for (k, mb) in blocks.iter_mut().enumerate() {
            let [lo, hi] = boxes[k];
            let inside = |x: &Point| (0..2).all(|d| x[d] >= lo[d] && x[d] <= hi[d]);
            for &(_, x) in points.iter().filter(|(o, x)| *o != k && inside(x)) {
                let Some((u, v)) = mb.block.inverse(x) else {
                    continue;
                };
                let on = |s: f64| s <= SAME_LINE || s >= 1.0 - SAME_LINE;
                // Only a point on a side matters; a corner is on two sides and on lines already.
                if on(v) && !on(u) {
                    changed |= insert_line(&mut mb.u_lines, u);
                } else if on(u) && !on(v) {
                    changed |= insert_line(&mut mb.v_lines, v);
                }
            }
        }
        if !changed {
            return Ok(());
        }
    }
    Err(MeshError::Unsettled)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Block, EdgeShape};

    fn block(x0: f64, z0: f64, x1: f64, z1: f64, u: Vec<f64>, v: Vec<f64>) -> MeshBlock {
        MeshBlock {
            block: Block::new(
                [[x0, z0], [x1, z0], [x1, z1], [x0, z1]],
                [
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                ],
            )
            .unwrap(),
            u_lines: u,
            v_lines: v,
            material: 0,
            edge_names: [None, None, None, None],
        }
    }

    fn even(n: usize) -> Vec<f64> {
        (0..=n).map(|i| i as f64 / n as f64).collect()
    }

    fn boundary(mesh: &Mesh, block: usize, local: usize) -> Vec<(usize, usize)> {
        let on = |e: &super::super::Element| match local {
            0 => e.v[0] == 0.0,
            1 => e.u[1] == 1.0,
            2 => e.v[1] == 1.0,
            _ => e.u[0] == 0.0,
        };
        (0..mesh.elements.len())
            .filter(|&e| mesh.elements[e].block == block && on(&mesh.elements[e]))
            .map(|e| (e, local))
            .collect()
    }

    #[test]
    fn lines_land_under_the_other_bodys_element_ends_and_spread_to_the_neighbours() {
        // Body 2: two blocks stacked (0..10 × 0..2 over 0..10 × −3..0), 3 even columns;
        // body 1 above, 1..7 in 4 columns: ends at 1, 2.5, 4, 5.5, 7.
        let body2 = Mesh::build(vec![
            block(0.0, 0.0, 10.0, 2.0, even(3), even(1)),
            block(0.0, -3.0, 10.0, 0.0, even(3), even(2)),
        ])
        .unwrap();
        let body1 = Mesh::build(vec![block(1.0, 2.0, 7.0, 4.0, even(4), even(1))]).unwrap();
        let (aligned, added) = body2
            .aligned_to(&boundary(&body2, 0, 2), &body1, &boundary(&body1, 0, 0))
            .unwrap();
        assert_eq!(added, 5);
        for mb in &aligned.blocks {
            let x: Vec<f64> = mb.u_lines.iter().map(|u| 10.0 * u).collect();
            let expected = [0.0, 1.0, 2.5, 10.0 / 3.0, 4.0, 5.5, 20.0 / 3.0, 7.0, 10.0];
            assert_eq!(x.len(), expected.len(), "{x:?}");
            for (a, b) in x.iter().zip(expected) {
                assert!((a - b).abs() < 1e-12, "{x:?}");
            }
        }
        // The other way, body 1 gains body 2's own lines inside it (10/3 and 20/3), not the
        // ones now shared, nor 0 and 10 whose normals miss it.
        let (_, back) = body1
            .aligned_to(&boundary(&body1, 0, 0), &aligned, &boundary(&aligned, 0, 2))
            .unwrap();
        assert_eq!(back, 2);
    }

    #[test]
    fn lines_spread_from_two_blocks_side_by_side_into_the_block_under_both() {
        // Body 2: blocks [0, 4] and [4, 10] side by side on top of one block [0, 10] × [−3, 0]
        // whose line at 4 makes the mesh conforming as given; body 1's ends at 1 … 7.
        let body2 = Mesh::build(vec![
            block(0.0, 0.0, 4.0, 2.0, even(1), even(1)),
            block(4.0, 0.0, 10.0, 2.0, even(1), even(1)),
            block(0.0, -3.0, 10.0, 0.0, vec![0.0, 0.4, 1.0], even(1)),
        ])
        .unwrap();
        let top: Vec<(usize, usize)> = [boundary(&body2, 0, 2), boundary(&body2, 1, 2)].concat();
        let body1 = Mesh::build(vec![block(1.0, 2.0, 7.0, 4.0, even(4), even(1))]).unwrap();
        let (aligned, added) = body2
            .aligned_to(&top, &body1, &boundary(&body1, 0, 0))
            .unwrap();
        // 1 and 2.5 in the left block, 5.5 and 7 in the right one (4 is there already); the
        // block under both gains the four, which makes eight.
        assert_eq!(added, 4);
        assert_eq!(aligned.added_lines, 8);
        let x = |k: usize, width: f64, x0: f64| -> Vec<f64> {
            aligned.blocks[k]
                .u_lines
                .iter()
                .map(|u| x0 + width * u)
                .collect()
        };
        let close = |a: &[f64], b: &[f64]| {
            a.len() == b.len() && a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-12)
        };
        assert!(close(&x(0, 4.0, 0.0), &[0.0, 1.0, 2.5, 4.0]));
        assert!(close(&x(1, 6.0, 4.0), &[4.0, 5.5, 7.0, 10.0]));
        assert!(close(
            &x(2, 10.0, 0.0),
            &[0.0, 1.0, 2.5, 4.0, 5.5, 7.0, 10.0]
        ));
    }

    #[test]
    fn a_crossing_next_to_a_line_adds_nothing() {
        let body2 = Mesh::build(vec![block(0.0, 0.0, 10.0, 2.0, even(2), even(1))]).unwrap();
        // Body 1's ends at 5.000001 (1e-7 of body 2's element away from its line at 5) and 0.
        let body1 = Mesh::build(vec![block(0.0, 2.0, 5.000001, 4.0, even(1), even(1))]).unwrap();
        let (_, added) = body2
            .aligned_to(&boundary(&body2, 0, 2), &body1, &boundary(&body1, 0, 0))
            .unwrap();
        assert_eq!(added, 0);
    }
}
