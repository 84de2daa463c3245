//! Meshes of a problem's bodies: as the blocks give them, body 2's aligned to body 1's
//! element ends, and the named edges on them.

use super::{within, Problem, ProblemError, MAX_COORDINATE};
use crate::geometry::{Block, EdgeShape};
use crate::mesh::{Mesh, MeshBlock};
use crate::schema::LinesSpec;

impl Problem {
    /// Build the mesh of body `b`: as its blocks give it, and for the contact's body 2 with the
    /// lines [`Problem::target_alignment`] adds.
    pub fn mesh(&self, b: usize) -> Result<Mesh, ProblemError> {
        match self.target_alignment(b)? {
            Some((mesh, _)) => Ok(mesh),
            None => self.mesh_as_given(b),
        }
    }

    /// When body `b` is the contact's body 2 and `contact.align_target_mesh` is on (the
    /// default): its mesh with lines where the normals through body 1's element ends on the
    /// contact edge cross its contact edge, and how many lines that added to its blocks.
    /// None for any other body, or when the contact section cannot be read (the contact
    /// stage then reports it).
    pub fn target_alignment(&self, b: usize) -> Result<Option<(Mesh, usize)>, ProblemError> {
        let Some(c) = self.spec.contact.as_ref().filter(|c| c.align_target_mesh) else {
            return Ok(None);
        };
        let (Ok(b1), Ok(b2)) = (self.body_index(&c.body), self.body_index(&c.target_body)) else {
            return Ok(None);
        };
        if b2 != b || b1 == b2 {
            return Ok(None);
        }
        let (mesh1, mesh2) = (self.mesh_as_given(b1)?, self.mesh_as_given(b2)?);
        let (Ok(edges1), Ok(edges2)) = (
            self.named_edge(&mesh1, b1, &c.edge, "contact.edge"),
            self.named_edge(&mesh2, b2, &c.target_edge, "contact.target_edge"),
        ) else {
            return Ok(None);
        };
        let aligned = mesh2.aligned_to(edges2, &mesh1, edges1).map_err(|e| {
            self.error(
                "contact.align_target_mesh",
                format!(
                    "body {b2}'s mesh with lines added under body {b1}'s element ends: {e} \
                     (set align_target_mesh = false to keep it as given)"
                ),
            )
        })?;
        Ok(Some(aligned))
    }

    /// Build the mesh of body `b` from its blocks, as the problem file gives it.
    pub fn mesh_as_given(&self, b: usize) -> Result<Mesh, ProblemError> {
        let body = &self.spec.bodies[b];
        let material_names: Vec<&String> = self.spec.materials.keys().collect();
        let mut blocks = Vec::new();
        for (k, bs) in body.blocks.iter().enumerate() {
            let key = |field: &str| format!("bodies[{b}].blocks[{k}].{field}");
            let mut shapes = [
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
            ];
            for (i, arc) in bs.arcs.iter().enumerate() {
                if arc.edge > 3 {
                    return Err(
                        self.error(key("arcs"), format!("edge must be 0..=3, got {}", arc.edge))
                    );
                }
                if bs.arcs[..i].iter().any(|other| other.edge == arc.edge) {
                    // The later one would silently replace the earlier.
                    return Err(self.error(
                        key(&format!("arcs[{i}].edge")),
                        format!("edge {} already has an arc", arc.edge),
                    ));
                }
                shapes[arc.edge] = EdgeShape::ArcAbout(arc.center);
            }
            let coordinates = bs
                .corners
                .iter()
                .flatten()
                .chain(bs.arcs.iter().flat_map(|a| &a.center));
            if coordinates.clone().any(|c| !within(*c, MAX_COORDINATE)) {
                // Beyond this, double precision cannot resolve the elastic displacements.
                return Err(self.error(
                    key("corners"),
                    format!("coordinates (and arc centres) must be finite and within ±{MAX_COORDINATE:e} mm"),
                ));
            }
            let block = Block::new(bs.corners, shapes).map_err(|e| {
                use crate::geometry::GeometryError::*;
                // An arc that cannot pass through its corners is the arc's fault: name it.
                let arc = match e {
                    ArcRadiusMismatch { edge, .. }
                    | DegenerateArc { edge, .. }
                    | AmbiguousArc { edge, .. } => bs.arcs.iter().rposition(|a| a.edge == edge),
                    _ => None,
                };
                let field = arc.map_or("corners".into(), |i| format!("arcs[{i}].center"));
                self.error(key(&field), e.to_string())
            })?;
            let material = material_names
                .iter()
                .position(|m| **m == bs.material)
                .ok_or_else(|| {
                    self.error(
                        key("material"),
                        format!("no material named \"{}\"", bs.material),
                    )
                })?;
            let lines = |spec: &LinesSpec, field: &str| -> Result<Vec<f64>, ProblemError> {
                match spec {
                    LinesSpec::Count(0) => {
                        Err(self.error(key(field), "needs at least one division"))
                    }
                    LinesSpec::Count(n) if *n > 10_000 => {
                        Err(self.error(key(field), format!("{n} divisions is too many")))
                    }
                    LinesSpec::Count(n) => Ok((0..=*n).map(|i| i as f64 / *n as f64).collect()),
                    LinesSpec::List(v) => Ok(v.clone()),
                }
            };
            let n = &bs.names;
            blocks.push(MeshBlock {
                block,
                u_lines: lines(&bs.u, "u")?,
                v_lines: lines(&bs.v, "v")?,
                material,
                edge_names: [
                    n.bottom.clone(),
                    n.right.clone(),
                    n.top.clone(),
                    n.left.clone(),
                ],
            });
        }
        Mesh::build(blocks).map_err(|e| {
            use crate::mesh::MeshError;
            let key = match &e {
                MeshError::BadLines {
                    block, direction, ..
                }
                | MeshError::Thin {
                    block, direction, ..
                } => format!("bodies[{b}].blocks[{block}].{direction}"),
                MeshError::Overlap { block }
                | MeshError::Disconnected { block }
                | MeshError::Folded { block, .. } => format!("bodies[{b}].blocks[{block}]"),
                _ => format!("bodies[{b}].blocks"),
            };
            self.error(key, e.to_string())
        })
    }

    /// The (element, local edge) list of edge `name` of body `b`.
    pub fn named_edge<'m>(
        &self,
        mesh: &'m Mesh,
        b: usize,
        name: &str,
        key: &str,
    ) -> Result<&'m [(usize, usize)], ProblemError> {
        let edges = mesh.named_edges.get(name).ok_or_else(|| {
            self.error(
                key,
                format!(
                    "body \"{}\" has no edge named \"{name}\"",
                    self.spec.bodies[b].name
                ),
            )
        })?;
        // A block side between two blocks is inside the body: loads, supports and contact act
        // on its boundary only.
        if edges
            .iter()
            .any(|&(e, l)| mesh.edges[mesh.elements[e].edges[l]].elements.len() > 1)
        {
            return Err(self.error(
                key,
                format!(
                    "edge \"{name}\" of body \"{}\" lies inside the body (between two blocks); name a boundary edge",
                    self.spec.bodies[b].name
                ),
            ));
        }
        Ok(edges.as_slice())
    }
}
