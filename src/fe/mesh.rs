//! Structured meshes: each block of a body is cut along its mesh lines into quadrilateral
//! elements; vertices are shared between neighbouring blocks, so the mesh is conforming.
//!
//! An element is a sub-rectangle `[u0, u1] × [v0, v1]` of its block's parameter square, so its
//! map is the block's exact blending map composed with an affine map: curved block edges stay
//! exact, and two elements sharing an edge share its geometry to the last bit.

use crate::geometry::{Block, Point};
use std::collections::HashMap;

mod align;
mod checks;
pub mod lines;
mod translate;
use checks::check_lines;
pub use lines::{equal_lines, graded_lines};

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

/// Local edge → (start, end) local vertex, in the element-edge convention of [`crate::basis`].
pub const EDGE_ENDPOINTS: [(usize, usize); 4] = [(0, 1), (1, 2), (3, 2), (0, 3)];

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
