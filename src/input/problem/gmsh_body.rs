//! A body meshed by Gmsh (`[bodies.gmsh]`): each quadrilateral of the file becomes a block of
//! one element, so the rest of wearfem sees the same kind of mesh as from `[[bodies.blocks]]`.
//!
//! - **Materials**: the body is the quadrilaterals of the physical surface groups that
//!   `materials` names, each with its group's material.
//! - **Edge names**: every physical curve names the element edges it covers.
//! - **Geometry**: the p-version converges exponentially only on the exact geometry. A
//!   physical curve listed in `arcs` is snapped: its nodes are moved onto the circle about the
//!   given centre (Gmsh puts them there to round-off; a spread beyond 1e-6 of the radius is
//!   refused as a wrong centre), and its element edges become exact arcs. Other edges of
//!   second-order elements (8 or 9 nodes) are parabolas through their mid-edge nodes, an
//!   approximation whose cost docs/validation.md measures; first-order elements are straight.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};

use super::{within, Problem, ProblemError, MAX_COORDINATE};
use crate::geometry::{Block, EdgeShape, Point};
use crate::gmsh::{GmshElement, GmshMesh};
use crate::mesh::MeshBlock;
use crate::schema::GmshSpec;

/// Nodes whose distance from a snapped arc's centre spreads by more than this (relative to the
/// radius) are not on one circle about it.
const ON_CIRCLE: f64 = 1e-6;

/// The blocks of body `b` from its Gmsh file, with the Gmsh tag of each block's element.
pub(super) struct GmshBlocks {
    /// One block per quadrilateral.
    pub blocks: Vec<MeshBlock>,
    /// The Gmsh element tag of each block.
    pub tags: Vec<usize>,
}

impl Problem {
    /// The `.msh` file of `spec`, relative to the problem file's folder.
    pub(super) fn gmsh_path(&self, spec: &GmshSpec) -> PathBuf {
        let file = Path::new(&spec.file);
        match Path::new(&self.file).parent() {
            Some(dir) if file.is_relative() => dir.join(file),
            _ => file.to_path_buf(),
        }
    }

    /// Read body `b`'s Gmsh file and make its blocks.
    pub(super) fn gmsh_blocks(
        &self,
        b: usize,
        spec: &GmshSpec,
    ) -> Result<GmshBlocks, ProblemError> {
        let key = |field: &str| format!("bodies[{b}].gmsh.{field}");
        let path = self.gmsh_path(spec);
        let mut mesh = crate::gmsh::read(&path)
            .map_err(|e| self.error(key("file"), format!("{}: {e}", path.display())))?;
        let snapped = self.snap_arcs(b, spec, &mut mesh)?;
        let quads = self.body_quadrilaterals(b, spec, &mesh)?;
        let curve_names = curve_names(&mesh);
        let mut blocks = Vec::with_capacity(quads.len());
        let mut tags = Vec::with_capacity(quads.len());
        for (element, material) in quads {
            let at = |n: usize| -> Result<Point, ProblemError> {
                mesh.nodes.get(&n).copied().ok_or_else(|| {
                    self.error(
                        key("file"),
                        format!(
                            "element {} uses node {n}, which the file does not list",
                            element.tag
                        ),
                    )
                })
            };
            let mut corners: Vec<usize> = element.nodes[..4].to_vec();
            // Mid-edge nodes of edges c0c1, c1c2, c2c3, c3c0 (8- and 9-node quadrangles).
            let mut middles: Option<Vec<usize>> =
                (element.nodes.len() >= 8).then(|| element.nodes[4..8].to_vec());
            let points = corners
                .iter()
                .map(|&n| at(n))
                .collect::<Result<Vec<_>, _>>()?;
            if points.iter().flatten().any(|&c| !within(c, MAX_COORDINATE)) {
                return Err(self.error(
                    key("file"),
                    format!(
                        "element {}: coordinates must lie within ±{MAX_COORDINATE:e} mm",
                        element.tag
                    ),
                ));
            }
            if signed_area(&points) < 0.0 {
                // Gmsh orients a surface by its normal: one drawn clockwise in x–y comes out
                // clockwise. Reverse it: c0 c3 c2 c1, with the middles of c0c3, c3c2, c2c1, c1c0.
                corners = vec![corners[0], corners[3], corners[2], corners[1]];
                middles = middles.map(|m| vec![m[3], m[2], m[1], m[0]]);
            }
            let corner_points: [Point; 4] = std::array::from_fn(|k| mesh.nodes[&corners[k]]);
            let mut shapes: [EdgeShape; 4] = std::array::from_fn(|_| EdgeShape::Straight);
            let mut names: [Option<String>; 4] = Default::default();
            for e in 0..4 {
                let pair = edge_key(corners[e], corners[(e + 1) % 4]);
                if let Some(center) = snapped.get(&pair) {
                    shapes[e] = EdgeShape::ArcAbout(*center);
                } else if let Some(m) = &middles {
                    let middle = at(m[e])?;
                    let (a, c) = (corner_points[e], corner_points[(e + 1) % 4]);
                    let chord = [0.5 * (a[0] + c[0]), 0.5 * (a[1] + c[1])];
                    let length = (c[0] - a[0]).hypot(c[1] - a[1]);
                    if (middle[0] - chord[0]).hypot(middle[1] - chord[1]) > 1e-12 * length {
                        shapes[e] = EdgeShape::Through(middle);
                    }
                }
                names[e] = match curve_names.get(&pair).map(|s| s.iter().collect::<Vec<_>>()) {
                    None => None,
                    Some(list) if list.len() == 1 => Some(list[0].clone()),
                    Some(list) => {
                        return Err(self.error(
                            key("file"),
                            format!(
                                "an edge of element {} lies in the physical curves {}; a wearfem edge has one name: put it in one of them",
                                element.tag,
                                quoted(&list)
                            ),
                        ))
                    }
                };
            }
            let block = Block::new(corner_points, shapes)
                .map_err(|e| self.error(key("file"), format!("element {}: {e}", element.tag)))?;
            blocks.push(MeshBlock {
                block,
                u_lines: vec![0.0, 1.0],
                v_lines: vec![0.0, 1.0],
                material,
                edge_names: names,
            });
            tags.push(element.tag);
        }
        Ok(GmshBlocks { blocks, tags })
    }

    /// The quadrilaterals of body `b`'s physical surface groups, each with its material index.
    fn body_quadrilaterals<'m>(
        &self,
        b: usize,
        spec: &GmshSpec,
        mesh: &'m GmshMesh,
    ) -> Result<Vec<(&'m GmshElement, usize)>, ProblemError> {
        let surfaces = mesh.groups(2);
        let material_names: Vec<&String> = self.spec.materials.keys().collect();
        let mut wanted: HashMap<&str, usize> = HashMap::new();
        for (group, material) in &spec.materials {
            let field = format!("bodies[{b}].gmsh.materials.{group}");
            if !surfaces.contains_key(group.as_str()) {
                let mut known: Vec<&str> = surfaces.keys().copied().collect();
                known.sort_unstable();
                return Err(self.error(
                    field,
                    format!(
                        "the file has no physical surface named \"{group}\" (it has {})",
                        if known.is_empty() {
                            "none".to_string()
                        } else {
                            quoted(&known)
                        }
                    ),
                ));
            }
            let index = material_names
                .iter()
                .position(|m| *m == material)
                .ok_or_else(|| self.error(&field, format!("no material named \"{material}\"")))?;
            wanted.insert(group.as_str(), index);
        }
        if wanted.is_empty() {
            return Err(self.error(
                format!("bodies[{b}].gmsh.materials"),
                "names no physical surface: give { GROUP = \"MATERIAL\" } for each of the body's surfaces",
            ));
        }
        let mut quads = Vec::new();
        for element in mesh.elements.iter().filter(|e| e.dim == 2) {
            let groups: Vec<&str> = mesh
                .element_groups(element)
                .into_iter()
                .filter(|g| wanted.contains_key(g))
                .collect();
            let Some(&first) = groups.first() else {
                continue;
            };
            if groups.iter().any(|g| wanted[g] != wanted[first]) {
                return Err(self.error(
                    format!("bodies[{b}].gmsh.materials"),
                    format!(
                        "element {} lies in the physical surfaces {}, which have different materials",
                        element.tag,
                        quoted(&groups)
                    ),
                ));
            }
            if !matches!(element.kind, 3 | 10 | 16) {
                return Err(self.error(
                    format!("bodies[{b}].gmsh.file"),
                    format!(
                        "element {} of physical surface \"{first}\" is a triangle (Gmsh type {}): wearfem's elements are quadrilaterals; recombine the mesh (Mesh.RecombineAll = 1, or transfinite surfaces with Recombine)",
                        element.tag, element.kind
                    ),
                ));
            }
            quads.push((element, wanted[first]));
        }
        if quads.is_empty() {
            return Err(self.error(
                format!("bodies[{b}].gmsh.materials"),
                "its physical surfaces hold no elements: was the mesh generated (gmsh -2) before it was saved?",
            ));
        }
        Ok(quads)
    }

    /// Move the nodes of each physical curve in `spec.arcs` onto its circle, and return the
    /// element edges (corner-node pairs) that are arcs, with their centres.
    fn snap_arcs(
        &self,
        b: usize,
        spec: &GmshSpec,
        mesh: &mut GmshMesh,
    ) -> Result<HashMap<(usize, usize), Point>, ProblemError> {
        let mut snapped = HashMap::new();
        // Each node's circle: a node on two arcs of different centres cannot lie on both.
        let mut circle_of: HashMap<usize, (Point, usize)> = HashMap::new();
        for (k, arc) in spec.arcs.iter().enumerate() {
            let field = format!("bodies[{b}].gmsh.arcs[{k}]");
            let Some(&group) = mesh.groups(1).get(arc.edge.as_str()) else {
                return Err(self.error(
                    format!("{field}.edge"),
                    format!("the file has no physical curve named \"{}\"", arc.edge),
                ));
            };
            let lines: Vec<GmshElement> = mesh
                .elements
                .iter()
                .filter(|e| e.dim == 1)
                .filter(|e| {
                    mesh.entity_groups
                        .get(&(1, e.entity))
                        .is_some_and(|g| g.contains(&group))
                })
                .cloned()
                .collect();
            let nodes: BTreeSet<usize> =
                lines.iter().flat_map(|e| e.nodes.iter().copied()).collect();
            let c = arc.center;
            let radii: Vec<f64> = nodes
                .iter()
                .filter_map(|n| mesh.nodes.get(n))
                .map(|x| (x[0] - c[0]).hypot(x[1] - c[1]))
                .collect();
            let (lo, hi) = radii.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &r| {
                (lo.min(r), hi.max(r))
            });
            if radii.is_empty() || lo <= 0.0 || hi - lo > ON_CIRCLE * hi {
                return Err(self.error(
                    format!("{field}.center"),
                    format!(
                        "the nodes of \"{}\" lie between {lo:.9} and {hi:.9} mm from ({}, {}): not on one circle about it (is the centre right?)",
                        arc.edge, c[0], c[1]
                    ),
                ));
            }
            for &n in &nodes {
                match circle_of.get(&n) {
                    Some(&(other, j)) if other != arc.center => {
                        return Err(self.error(
                            format!("{field}.center"),
                            format!(
                                "node {n} lies on \"{}\" and on \"{}\" (arcs[{j}]), whose centres differ: it cannot lie on both circles",
                                arc.edge, spec.arcs[j].edge
                            ),
                        ))
                    }
                    _ => {
                        circle_of.insert(n, (arc.center, k));
                    }
                }
            }
            let radius = radii.iter().sum::<f64>() / radii.len() as f64;
            for n in &nodes {
                if let Some(x) = mesh.nodes.get_mut(n) {
                    let r = (x[0] - c[0]).hypot(x[1] - c[1]);
                    *x = [
                        c[0] + (x[0] - c[0]) * radius / r,
                        c[1] + (x[1] - c[1]) * radius / r,
                    ];
                }
            }
            for line in lines {
                snapped.insert(edge_key(line.nodes[0], line.nodes[1]), c);
            }
        }
        Ok(snapped)
    }
}

/// The names of the physical curves each element edge (corner-node pair) lies in.
fn curve_names(mesh: &GmshMesh) -> HashMap<(usize, usize), BTreeSet<String>> {
    let mut names: HashMap<(usize, usize), BTreeSet<String>> = HashMap::new();
    for line in mesh.elements.iter().filter(|e| e.dim == 1) {
        for group in mesh.element_groups(line) {
            names
                .entry(edge_key(line.nodes[0], line.nodes[1]))
                .or_default()
                .insert(group.to_string());
        }
    }
    names
}

fn edge_key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

/// Twice the signed area of the polygon through `points` (positive counter-clockwise).
fn signed_area(points: &[Point]) -> f64 {
    (0..points.len())
        .map(|i| {
            let (a, c) = (points[i], points[(i + 1) % points.len()]);
            a[0] * c[1] - c[0] * a[1]
        })
        .sum()
}

fn quoted<S: AsRef<str>>(names: &[S]) -> String {
    names
        .iter()
        .map(|n| format!("\"{}\"", n.as_ref()))
        .collect::<Vec<_>>()
        .join(", ")
}
