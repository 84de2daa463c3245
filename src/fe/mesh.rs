//! Structured meshes: each block of a body is cut along its mesh lines into quadrilateral
//! elements; vertices are shared between neighbouring blocks, so the mesh is conforming.
//!
//! An element is a sub-rectangle `[u0, u1] × [v0, v1]` of its block's parameter square, so its
//! map is the block's exact blending map composed with an affine map: curved block edges stay
//! exact, and two elements sharing an edge share its geometry to the last bit.

use crate::geometry::{Block, Point};
use std::collections::HashMap;

mod align;

/// Errors found while building a mesh.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum MeshError {
    /// Mesh lines must start at 0, end at 1 and increase strictly.
    #[error(
        "block {block}: mesh lines along {direction} must rise from 0 to 1 in steps of at least 1e-6, got {lines:?}"
    )]
    BadLines {
        /// Block index in the body.
        block: usize,
        /// "u" or "v".
        direction: &'static str,
        /// The mesh lines given.
        lines: Vec<f64>,
    },
    /// An element is thinner than the tolerance within which a vertex counts as lying on an
    /// edge ([`Mesh::build`]): its corners could not be told from hanging vertices.
    #[error(
        "block {block}: mesh lines along {direction} make an element {width:.3e} mm thin; elements must be at least {minimum:.3e} mm across (1e-6 of the body's size), got lines {lines:?}"
    )]
    Thin {
        /// Block index in the body.
        block: usize,
        /// "u" or "v": the lines that are too close.
        direction: &'static str,
        /// The element's thickness: the least distance of a corner from an edge it is not on, mm.
        width: f64,
        /// The least thickness allowed, mm.
        minimum: f64,
        /// The block's mesh lines along `direction`.
        lines: Vec<f64>,
    },
    /// A vertex lies inside another element's edge: the blocks' mesh lines do not match.
    #[error("mesh is not conforming: vertex at ({x}, {z}) mm lies inside an element edge (do the mesh lines of neighbouring blocks match?)")]
    Hanging {
        /// x of the vertex, mm.
        x: f64,
        /// z of the vertex, mm.
        z: f64,
    },
    /// Two blocks overlap (an element edge shared by more than two elements, or two elements
    /// on the same vertices).
    #[error("block {block} overlaps another block (is a block listed twice?)")]
    Overlap {
        /// Block index in the body.
        block: usize,
    },
    /// Some elements do not connect to the rest through a shared edge.
    #[error("block {block} is not joined to the rest of the body along an edge (blocks of one body must share whole mesh edges)")]
    Disconnected {
        /// Block index in the body.
        block: usize,
    },
    /// Lines added to align the mesh with another kept spreading to neighbouring blocks.
    #[error("mesh lines added to match the other body's element ends did not settle after spreading through 256 rounds of neighbouring blocks (set contact.align_target_mesh = false)")]
    Unsettled,
    /// An element folds over (non-positive Jacobian) somewhere.
    #[error("element {element} of block {block} is folded (Jacobian determinant {det})")]
    Folded {
        /// Element index in the mesh.
        element: usize,
        /// Block index in the body.
        block: usize,
        /// A non-positive Jacobian determinant found in the element, mm².
        det: f64,
    },
}

/// One block of a body with its mesh lines, material and edge names.
#[derive(Clone, Debug)]
pub struct MeshBlock {
    /// The exact block geometry.
    pub block: Block,
    /// Mesh lines along u (block parameter, 0 = edge 3, 1 = edge 1), rising from 0 to 1.
    pub u_lines: Vec<f64>,
    /// Mesh lines along v (0 = edge 0, 1 = edge 2), rising from 0 to 1.
    pub v_lines: Vec<f64>,
    /// Material index (into the problem's material list).
    pub material: usize,
    /// Names of the block edges 0..4 (bottom v = 0, right u = 1, top v = 1, left u = 0).
    pub edge_names: [Option<String>; 4],
}

/// A quadrilateral element: a parameter sub-rectangle of one block.
#[derive(Clone, Debug)]
pub struct Element {
    /// Index of the block in [`Mesh::blocks`].
    pub block: usize,
    /// Block parameter interval along the element's ξ direction.
    pub u: [f64; 2],
    /// Block parameter interval along the element's η direction.
    pub v: [f64; 2],
    /// Global vertex ids: v0 = (u0, v0), v1 = (u1, v0), v2 = (u1, v1), v3 = (u0, v1) (counter-clockwise).
    pub vertices: [usize; 4],
    /// Global edge ids of the local edges 0..4 (see [`crate::basis`] for the local convention).
    pub edges: [usize; 4],
    /// Material index.
    pub material: usize,
}

/// A global mesh edge, oriented from its lower to its higher vertex id.
#[derive(Clone, Debug)]
pub struct MeshEdge {
    /// Start and end vertex (start < end).
    pub vertices: [usize; 2],
    /// Elements that share this edge with their local edge number.
    pub elements: Vec<(usize, usize)>,
}

/// A conforming quadrilateral mesh of one body.
#[derive(Clone, Debug)]
pub struct Mesh {
    /// The blocks the mesh was cut from.
    pub blocks: Vec<MeshBlock>,
    /// Vertex coordinates [x, z] in mm.
    pub vertices: Vec<Point>,
    /// Elements.
    pub elements: Vec<Element>,
    /// Edges, each listed once.
    pub edges: Vec<MeshEdge>,
    /// Named boundary parts: name → (element, local edge) pairs.
    pub named_edges: HashMap<String, Vec<(usize, usize)>>,
    /// Mesh lines added to the blocks as given, to align this mesh with another body's
    /// ([`Mesh::aligned_to`]; those that spread to neighbouring blocks included); 0 as built.
    pub added_lines: usize,
}

/// A vertex closer than this to a boundary element edge (relative to the body's size: the
/// larger side of the box around its blocks) lies on it: a hanging vertex, unless it is one
/// of the edge's ends. Elements must be at least this thick, so that no corner of a genuine
/// element is taken for one. Vertices closer than [`MERGE`] × the size are the same vertex.
const HANGING: f64 = 1e-6;
/// Vertices this close (relative to the body's size) are merged into one.
const MERGE: f64 = 1e-9;

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

/// Local edge → (start, end) local vertex, in the element-edge convention of [`crate::basis`].
pub const EDGE_ENDPOINTS: [(usize, usize); 4] = [(0, 1), (1, 2), (3, 2), (0, 3)];

/// Mesh lines of one block direction must rise from 0 to 1 by at least 1e-6 of the side:
/// thinner elements only make the stiffness matrix singular in floating point. The elements
/// must also be at least [`HANGING`] × the body's size across ([`Mesh::build`]).
fn check_lines(block: usize, direction: &'static str, lines: &[f64]) -> Result<(), MeshError> {
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

impl Element {
    /// Map reference coordinates (ξ, η) ∈ [-1, 1]² to the element's block parameters (u, v).
    pub fn block_parameters(&self, xi: f64, eta: f64) -> (f64, f64) {
        (
            self.u[0] + 0.5 * (xi + 1.0) * (self.u[1] - self.u[0]),
            self.v[0] + 0.5 * (eta + 1.0) * (self.v[1] - self.v[0]),
        )
    }
}

impl Mesh {
    /// Cut every block along its mesh lines and join the pieces into one conforming mesh.
    pub fn build(blocks: Vec<MeshBlock>) -> Result<Mesh, MeshError> {
        let mut mesh = Mesh {
            blocks,
            vertices: Vec::new(),
            elements: Vec::new(),
            edges: Vec::new(),
            named_edges: HashMap::new(),
            added_lines: 0,
        };
        let scale = mesh.bounding_size().max(1e-300);
        let merge_tolerance = MERGE * scale;
        let mut vertex_index: HashMap<(i64, i64), usize> = HashMap::new();
        let mut edge_index: HashMap<(usize, usize), usize> = HashMap::new();
        for (block_id, mb) in mesh.blocks.clone().iter().enumerate() {
            check_lines(block_id, "u", &mb.u_lines)?;
            check_lines(block_id, "v", &mb.v_lines)?;
            let nu = mb.u_lines.len() - 1;
            let nv = mb.v_lines.len() - 1;
            for j in 0..nv {
                for i in 0..nu {
                    let u = [mb.u_lines[i], mb.u_lines[i + 1]];
                    let v = [mb.v_lines[j], mb.v_lines[j + 1]];
                    let params = [(u[0], v[0]), (u[1], v[0]), (u[1], v[1]), (u[0], v[1])];
                    let mut vertices = [0usize; 4];
                    for (k, &(pu, pv)) in params.iter().enumerate() {
                        let x = mb.block.map(pu, pv);
                        vertices[k] = mesh.vertex_id(x, merge_tolerance, &mut vertex_index);
                    }
                    let element_id = mesh.elements.len();
                    let mut edges = [0usize; 4];
                    for (local, &(a, b)) in EDGE_ENDPOINTS.iter().enumerate() {
                        let key = (vertices[a].min(vertices[b]), vertices[a].max(vertices[b]));
                        let id = *edge_index.entry(key).or_insert_with(|| {
                            mesh.edges.push(MeshEdge {
                                vertices: [key.0, key.1],
                                elements: Vec::new(),
                            });
                            mesh.edges.len() - 1
                        });
                        mesh.edges[id].elements.push((element_id, local));
                        edges[local] = id;
                    }
                    // Local edge e of an element on the block boundary is block edge e.
                    let on_boundary = [j == 0, i == nu - 1, j == nv - 1, i == 0];
                    for (e, (&boundary, name)) in on_boundary.iter().zip(&mb.edge_names).enumerate()
                    {
                        if let (true, Some(name)) = (boundary, name) {
                            mesh.named_edges
                                .entry(name.clone())
                                .or_default()
                                .push((element_id, e));
                        }
                    }
                    mesh.elements.push(Element {
                        block: block_id,
                        u,
                        v,
                        vertices,
                        edges,
                        material: mb.material,
                    });
                }
            }
        }
        mesh.check_thickness(HANGING * scale)?;
        mesh.check_conforming(HANGING * scale)?;
        mesh.check_jacobians()?;
        mesh.check_topology()?;
        Ok(mesh)
    }

    /// Each element edge is shared by at most two elements and no two elements have the same
    /// vertices (else blocks overlap, e.g. one listed twice); all elements connect through
    /// shared edges (a block touching the rest at one vertex would hinge about it).
    fn check_topology(&self) -> Result<(), MeshError> {
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

    fn bounding_size(&self) -> f64 {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for b in &self.blocks {
            for c in &b.block.corners {
                for d in 0..2 {
                    lo[d] = lo[d].min(c[d]);
                    hi[d] = hi[d].max(c[d]);
                }
            }
        }
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }

    fn vertex_id(
        &mut self,
        x: Point,
        tolerance: f64,
        index: &mut HashMap<(i64, i64), usize>,
    ) -> usize {
        // Quantise to a grid of the merge tolerance and look in the neighbouring cells too, so
        // that points within tolerance on either side of a cell boundary still merge.
        let key = |x: f64| (x / tolerance).round() as i64;
        let (kx, kz) = (key(x[0]), key(x[1]));
        for dx in -1..=1 {
            for dz in -1..=1 {
                if let Some(&id) = index.get(&(kx + dx, kz + dz)) {
                    let y = self.vertices[id];
                    if (y[0] - x[0]).abs() <= tolerance && (y[1] - x[1]).abs() <= tolerance {
                        return id;
                    }
                }
            }
        }
        self.vertices.push(x);
        index.insert((kx, kz), self.vertices.len() - 1);
        self.vertices.len() - 1
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
    fn check_thickness(&self, minimum: f64) -> Result<(), MeshError> {
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
    fn check_conforming(&self, near: f64) -> Result<(), MeshError> {
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

    fn check_jacobians(&self) -> Result<(), MeshError> {
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

    /// Physical point [x, z] (mm) of element `element` at reference coordinates (ξ, η).
    pub fn map(&self, element: usize, xi: f64, eta: f64) -> Point {
        let el = &self.elements[element];
        let (u, v) = el.block_parameters(xi, eta);
        self.blocks[el.block].block.map(u, v)
    }

    /// Jacobian [[∂x/∂ξ, ∂x/∂η], [∂z/∂ξ, ∂z/∂η]] (mm) and its determinant (mm²).
    pub fn jacobian(&self, element: usize, xi: f64, eta: f64) -> ([[f64; 2]; 2], f64) {
        let el = &self.elements[element];
        let (u, v) = el.block_parameters(xi, eta);
        let jb = self.blocks[el.block].block.jacobian(u, v);
        let su = 0.5 * (el.u[1] - el.u[0]);
        let sv = 0.5 * (el.v[1] - el.v[0]);
        let j = [
            [jb[0][0] * su, jb[0][1] * sv],
            [jb[1][0] * su, jb[1][1] * sv],
        ];
        (j, j[0][0] * j[1][1] - j[0][1] * j[1][0])
    }

    /// Reference coordinates (ξ, η) of the point at parameter t ∈ [-1, 1] of local edge `local`,
    /// where t runs along increasing ξ (edges 0, 2) or η (edges 1, 3).
    pub fn edge_reference_point(local: usize, t: f64) -> (f64, f64) {
        match local {
            0 => (t, -1.0),
            1 => (1.0, t),
            2 => (t, 1.0),
            _ => (-1.0, t),
        }
    }

    /// Physical point on local edge `local` of `element` at edge parameter t ∈ [-1, 1].
    pub fn point_on_edge(&self, element: usize, local: usize, t: f64) -> Point {
        let (xi, eta) = Self::edge_reference_point(local, t);
        self.map(element, xi, eta)
    }

    /// Tangent d x / d t (mm) and outward unit normal on local edge `local` at parameter t.
    pub fn edge_frame(&self, element: usize, local: usize, t: f64) -> (Point, Point) {
        let (xi, eta) = Self::edge_reference_point(local, t);
        let (j, _) = self.jacobian(element, xi, eta);
        let col = if local == 0 || local == 2 { 0 } else { 1 };
        let tangent = [j[0][col], j[1][col]];
        let len = tangent[0].hypot(tangent[1]);
        // Edges 0 and 1 run counter-clockwise around the element, 2 and 3 clockwise; the
        // outward normal is the counter-clockwise tangent turned clockwise by 90°.
        let ccw = if local < 2 { 1.0 } else { -1.0 };
        let normal = [ccw * tangent[1] / len, -ccw * tangent[0] / len];
        (tangent, normal)
    }

    /// Find the element containing point `x` and its reference coordinates.
    pub fn locate(&self, x: Point) -> Option<(usize, f64, f64)> {
        for (id, el) in self.elements.iter().enumerate() {
            let block = &self.blocks[el.block].block;
            if let Some((u, v)) = block.inverse(x) {
                let tol = 1e-9;
                if u >= el.u[0] - tol
                    && u <= el.u[1] + tol
                    && v >= el.v[0] - tol
                    && v <= el.v[1] + tol
                {
                    let xi = 2.0 * (u - el.u[0]) / (el.u[1] - el.u[0]) - 1.0;
                    let eta = 2.0 * (v - el.v[0]) / (el.v[1] - el.v[0]) - 1.0;
                    return Some((id, xi.clamp(-1.0, 1.0), eta.clamp(-1.0, 1.0)));
                }
            }
        }
        None
    }

    /// The materials of every element that contains `x` (on an edge or vertex, several), each
    /// once, in element order: more than one means `x` lies on a material interface, where
    /// stresses and strains jump.
    pub fn materials_at(&self, x: Point) -> Vec<usize> {
        let mut materials = Vec::new();
        for el in &self.elements {
            let tol = 1e-9;
            let inside = self.blocks[el.block]
                .block
                .inverse(x)
                .is_some_and(|(u, v)| {
                    u >= el.u[0] - tol
                        && u <= el.u[1] + tol
                        && v >= el.v[0] - tol
                        && v <= el.v[1] + tol
                });
            if inside && !materials.contains(&el.material) {
                materials.push(el.material);
            }
        }
        materials
    }

    /// The vertex at `x` (within 1e-6 of the mesh size), if any.
    pub fn vertex_at(&self, x: Point) -> Option<usize> {
        let tol = 1e-6 * self.bounding_size();
        self.vertices
            .iter()
            .position(|v| (v[0] - x[0]).hypot(v[1] - x[1]) <= tol)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::EdgeShape;

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
