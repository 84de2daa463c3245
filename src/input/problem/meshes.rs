//! Meshes of a problem's bodies: as the blocks give them, body 2's aligned to body 1's
//! element ends, and the named edges on them.
//!
//! A problem's meshes are built once, when it is validated, and shared with every problem
//! built from the same inputs (the bodies' names and blocks, the materials' order, the
//! contact's edges): a study's variants that change friction, loads or the plate share one
//! set, instead of building each body's mesh four times per variant (0.5 ms of the 0.6 ms it
//! took to build a variant of punch-b40, docs/performance.md).

use std::sync::{Arc, Mutex};

use super::gmsh_body::GmshBlocks;
use super::{within, Problem, ProblemError, ProblemSpec, MAX_COORDINATE};
use crate::geometry::{Block, EdgeShape};
use crate::mesh::{Mesh, MeshBlock};
use crate::schema::{BlockSpec, GmshSpec, LinesSpec};

/// How many sets of meshes the process keeps for reuse (the most recently used).
const MEMO_SIZE: usize = 4;

/// Meshes built lately, most recent first. Entries are immutable and found only by inputs
/// equal to their own, so a hit is the mesh a fresh build would give.
static MEMO: Mutex<Vec<Arc<BuiltMeshes>>> = Mutex::new(Vec::new());

/// A Gmsh body's inputs: its section and its file's length and modification time (a file
/// written again in the same process, as a study or a Python session may, is read again).
type GmshInputs = Option<(GmshSpec, Option<(u64, std::time::SystemTime)>)>;

/// What a problem's meshes are built from and nothing else.
#[derive(Clone, Debug, PartialEq)]
struct MeshInputs {
    /// Each body's name (the contact names bodies), blocks and Gmsh file.
    bodies: Vec<(String, Vec<BlockSpec>, GmshInputs)>,
    /// Material names in order: a block's material is an index into them.
    materials: Vec<String>,
    /// The contact's body, edge, target body and target edge, when body 2 is aligned.
    alignment: Option<[String; 4]>,
}

impl MeshInputs {
    fn alignment_of(spec: &ProblemSpec) -> Option<[&String; 4]> {
        let c = spec.contact.as_ref().filter(|c| c.aligns_target_mesh())?;
        Some([&c.body, &c.edge, &c.target_body, &c.target_edge])
    }

    fn of(problem: &Problem) -> MeshInputs {
        let spec = &problem.spec;
        MeshInputs {
            bodies: spec
                .bodies
                .iter()
                .map(|b| {
                    (
                        b.name.clone(),
                        b.blocks.clone(),
                        gmsh_inputs(problem, &b.gmsh),
                    )
                })
                .collect(),
            materials: spec.materials.keys().cloned().collect(),
            alignment: MeshInputs::alignment_of(spec).map(|a| a.map(String::clone)),
        }
    }

    /// Whether `problem` gives these inputs (compared without copying its blocks).
    fn matches(&self, problem: &Problem) -> bool {
        let spec = &problem.spec;
        self.bodies.len() == spec.bodies.len()
            && self
                .bodies
                .iter()
                .zip(&spec.bodies)
                .all(|((name, blocks, gmsh), body)| {
                    *name == body.name
                        && *blocks == body.blocks
                        && *gmsh == gmsh_inputs(problem, &body.gmsh)
                })
            && self.materials.iter().eq(spec.materials.keys())
            && self.alignment.as_ref().map(|a| a.each_ref()) == MeshInputs::alignment_of(spec)
    }
}

fn gmsh_inputs(problem: &Problem, gmsh: &Option<GmshSpec>) -> GmshInputs {
    gmsh.as_ref().map(|g| {
        let stamp = std::fs::metadata(problem.gmsh_path(g))
            .ok()
            .and_then(|m| Some((m.len(), m.modified().ok()?)));
        (g.clone(), stamp)
    })
}

/// Body 2's mesh with the lines added under body 1's element ends.
struct AlignedTarget {
    /// Index of body 2.
    body: usize,
    mesh: Mesh,
    /// How many lines were added to its blocks.
    added_lines: usize,
}

/// Every body's mesh, built from one set of inputs.
pub(super) struct BuiltMeshes {
    inputs: MeshInputs,
    /// As the blocks give them, in body order.
    given: Vec<Mesh>,
    aligned: Option<AlignedTarget>,
}

impl std::fmt::Debug for BuiltMeshes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // The meshes themselves would fill a screen in every `{:?}` of a problem.
        f.debug_struct("BuiltMeshes")
            .field("bodies", &self.given.len())
            .field("aligned", &self.aligned.as_ref().map(|a| a.added_lines))
            .finish()
    }
}

impl BuiltMeshes {
    fn build(problem: &Problem) -> Result<BuiltMeshes, ProblemError> {
        let given = (0..problem.spec.bodies.len())
            .map(|b| problem.build_as_given(b))
            .collect::<Result<Vec<_>, _>>()?;
        let aligned = problem.align_target(&given)?;
        Ok(BuiltMeshes {
            inputs: MeshInputs::of(problem),
            given,
            aligned,
        })
    }

    /// The mesh body `b` is solved on.
    pub(super) fn mesh(&self, b: usize) -> &Mesh {
        match &self.aligned {
            Some(a) if a.body == b => &a.mesh,
            _ => &self.given[b],
        }
    }

    /// The meshes of `problem`: a set built before from the same inputs, or built now (and
    /// kept for the next problem).
    pub(super) fn of(problem: &Problem) -> Result<Arc<BuiltMeshes>, ProblemError> {
        // A poisoned lock only means another thread panicked while holding it; the entries
        // are immutable, so the list is still sound.
        let memo = || MEMO.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(hit) = memo().iter().find(|m| m.inputs.matches(problem)) {
            return Ok(Arc::clone(hit));
        }
        // Built outside the lock: two threads may build the same set; both are equal.
        let built = Arc::new(BuiltMeshes::build(problem)?);
        let mut kept = memo();
        kept.insert(0, Arc::clone(&built));
        kept.truncate(MEMO_SIZE);
        Ok(built)
    }
}

impl Problem {
    /// This problem's meshes: those built when it was validated, unless its `spec` has been
    /// changed since (then built again from it).
    fn meshes(&self) -> Result<Arc<BuiltMeshes>, ProblemError> {
        match &self.meshes {
            Some(built) if built.inputs.matches(self) => Ok(Arc::clone(built)),
            _ => BuiltMeshes::of(self),
        }
    }

    /// The mesh of body `b`: as its blocks give it, and for the contact's body 2 with the
    /// lines [`Problem::target_alignment`] adds.
    pub fn mesh(&self, b: usize) -> Result<Mesh, ProblemError> {
        Ok(self.meshes()?.mesh(b).clone())
    }

    /// When body `b` is the contact's body 2 and `contact.align_target_mesh` is on (the
    /// default): its mesh with lines where the normals through body 1's element ends on the
    /// contact edge cross its contact edge, and how many lines that added to its blocks.
    /// None for any other body, or when the contact section cannot be read (the contact
    /// stage then reports it).
    pub fn target_alignment(&self, b: usize) -> Result<Option<(Mesh, usize)>, ProblemError> {
        let built = self.meshes()?;
        Ok(built
            .aligned
            .as_ref()
            .filter(|a| a.body == b)
            .map(|a| (a.mesh.clone(), a.added_lines)))
    }

    /// The mesh of body `b` as its blocks give it (without lines added for the contact).
    pub fn mesh_as_given(&self, b: usize) -> Result<Mesh, ProblemError> {
        Ok(self.meshes()?.given[b].clone())
    }

    /// Body 2's mesh aligned to body 1's element ends (see [`Problem::target_alignment`]),
    /// from the meshes as `given`.
    fn align_target(&self, given: &[Mesh]) -> Result<Option<AlignedTarget>, ProblemError> {
        let Some(c) = self
            .spec
            .contact
            .as_ref()
            .filter(|c| c.aligns_target_mesh())
        else {
            return Ok(None);
        };
        let (Ok(b1), Ok(b2)) = (self.body_index(&c.body), self.body_index(&c.target_body)) else {
            return Ok(None);
        };
        // A Gmsh mesh is kept as it is: lines cannot be cut through unstructured elements.
        if b1 == b2 || self.spec.bodies[b2].gmsh.is_some() {
            return Ok(None);
        }
        let (mesh1, mesh2) = (&given[b1], &given[b2]);
        let (Ok(edges1), Ok(edges2)) = (
            self.named_edge(mesh1, b1, &c.edge, "contact.edge"),
            self.named_edge(mesh2, b2, &c.target_edge, "contact.target_edge"),
        ) else {
            return Ok(None);
        };
        let (mesh, added_lines) = mesh2.aligned_to(edges2, mesh1, edges1).map_err(|e| {
            self.error(
                "contact.align_target_mesh",
                format!(
                    "body {b2}'s mesh with lines added under body {b1}'s element ends: {e} \
                     (set align_target_mesh = false to keep it as given)"
                ),
            )
        })?;
        Ok(Some(AlignedTarget {
            body: b2,
            mesh,
            added_lines,
        }))
    }

    /// Build the mesh of body `b` from its blocks, as the problem file gives it.
    fn build_as_given(&self, b: usize) -> Result<Mesh, ProblemError> {
        let body = &self.spec.bodies[b];
        match (&body.gmsh, body.blocks.is_empty()) {
            (Some(gmsh), true) => return self.build_from_gmsh(b, gmsh),
            (Some(_), false) => {
                return Err(self.error(
                    format!("bodies[{b}]"),
                    "gives both blocks and a gmsh mesh: give one",
                ))
            }
            (None, true) => {
                return Err(self.error(
                    format!("bodies[{b}]"),
                    "has no mesh: give [[bodies.blocks]] or [bodies.gmsh]",
                ))
            }
            (None, false) => {}
        }
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
                    LinesSpec::Count(n) => Ok(crate::mesh::equal_lines(*n)),
                    LinesSpec::List(v) => Ok(v.clone()),
                    LinesSpec::Graded(g) => {
                        if g.n == 0 || g.n > 10_000 {
                            return Err(self.error(
                                format!("{}.n", key(field)),
                                format!("{} divisions: give 1 to 10 000", g.n),
                            ));
                        }
                        if !(g.ratio.is_finite() && g.ratio > 0.0) {
                            return Err(self.error(
                                format!("{}.ratio", key(field)),
                                format!(
                                    "{} is not a positive ratio of neighbouring divisions",
                                    g.ratio
                                ),
                            ));
                        }
                        Ok(crate::mesh::graded_lines(g.n, g.ratio, g.both_ends))
                    }
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

    /// Build the mesh of body `b` from its Gmsh file; errors name the Gmsh element.
    fn build_from_gmsh(&self, b: usize, spec: &GmshSpec) -> Result<Mesh, ProblemError> {
        let GmshBlocks { blocks, tags } = self.gmsh_blocks(b, spec)?;
        Mesh::build(blocks).map_err(|e| {
            use crate::mesh::MeshError;
            let key = format!("bodies[{b}].gmsh.file");
            let message = match &e {
                MeshError::Hanging { x, z } => format!(
                    "the mesh is not conforming: a node at ({x}, {z}) mm lies inside an element edge (do neighbouring surfaces share their curve's nodes? in Gmsh, fragment the surfaces: BooleanFragments, or Coherence)"
                ),
                MeshError::Overlap { block }
                | MeshError::Disconnected { block }
                | MeshError::Folded { block, .. } => {
                    format!("element {}: {}", tags[*block], e.to_string().replacen(&format!("block {block}"), "it", 1))
                }
                _ => e.to_string(),
            };
            self.error(key, message)
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
