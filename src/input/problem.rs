//! Problem files: the TOML schema, its validation and the construction of the elastic bodies.
//!
//! Every error names the file and the key (`bodies[0].blocks[1].corners`) and says what is
//! wrong; nothing here panics on bad input. Units: mm, N, MPa, s.

use crate::basis::Space;
use crate::elasticity::{Constraints, Discretisation, ElasticBody};
use crate::loads::{Traction, Window};
use crate::material::{Analysis, Material};
use crate::mesh::Mesh;
pub use crate::schema::*;

mod contact_settings;
mod gmsh_body;
mod meshes;

use std::sync::Arc;

/// Largest coordinate, length or radius accepted, mm: a kilometre, beyond which double
/// precision no longer resolves elastic displacements of ordinary parts.
pub const MAX_COORDINATE: f64 = 1e6;
/// Largest modulus or traction accepted, MPa: 1000 times diamond's Young's modulus.
pub const MAX_STRESS: f64 = 1e9;
/// Smallest Young's modulus accepted, MPa: 1 Pa, softer than the softest hydrogels. Below it
/// nothing is a solid in mm, N and MPa, and values like 1e-300 made the stiffness underflow:
/// a strain energy of NaN under exit 0, or a "singular" matrix blamed on the supports.
pub const MIN_YOUNG: f64 = 1e-6;
/// Smallest thickness accepted, mm (a nanometre), for the same reason.
pub const MIN_THICKNESS: f64 = 1e-6;

/// Whether `value` is finite and at most `limit` in size.
fn within(value: f64, limit: f64) -> bool {
    value.is_finite() && value.abs() <= limit
}

/// A problem-file error: which file, which key, what is wrong.
#[derive(Debug, thiserror::Error)]
#[error("{file}: {key}: {message}")]
pub struct ProblemError {
    /// File name (or built-in example name).
    pub file: String,
    /// Dotted key path of the offending entry.
    pub key: String,
    /// What is wrong.
    pub message: String,
}

/// A validated problem: the parsed file plus the objects built from it.
#[derive(Clone, Debug)]
pub struct Problem {
    /// File name, for messages.
    pub file: String,
    /// The parsed file.
    pub spec: ProblemSpec,
    /// 2D idealisation with thickness.
    pub analysis: Analysis,
    /// Degree (`analysis.p`, the default of every body; see [`Problem::body_discretisation`])
    /// and space.
    pub discretisation: Discretisation,
    /// Materials in `spec.materials` order.
    pub materials: Vec<Material>,
    /// The bodies' meshes, built once on validation (see [`Problem::mesh`]); built again
    /// if `spec` has been changed since.
    meshes: Option<Arc<meshes::BuiltMeshes>>,
}

impl Problem {
    /// Make an error for key `key` of this file.
    pub fn error(&self, key: impl Into<String>, message: impl Into<String>) -> ProblemError {
        ProblemError {
            file: self.file.clone(),
            key: key.into(),
            message: message.into(),
        }
    }

    /// Parse and validate a problem file's text.
    pub fn from_toml(text: &str, file: &str) -> Result<Problem, ProblemError> {
        Problem::with_overrides(text, file, &[])
    }

    /// Parse a problem file's text, apply `overrides` (`--set KEY=VALUE`, see
    /// [`crate::overrides`] for the key syntax) and validate the result.
    pub fn with_overrides(
        text: &str,
        file: &str,
        overrides: &[crate::overrides::Override],
    ) -> Result<Problem, ProblemError> {
        let spec = crate::overrides::parse_spec(text, file, overrides)?;
        Problem::from_spec(spec, file)
    }

    /// Validate a parsed problem file.
    pub fn from_spec(spec: ProblemSpec, file: &str) -> Result<Problem, ProblemError> {
        let err = |key: &str, message: String| ProblemError {
            file: file.into(),
            key: key.into(),
            message,
        };
        let a = &spec.analysis;
        let thickness = || {
            match a.thickness {
            Some(t) if (MIN_THICKNESS..=MAX_COORDINATE).contains(&t) => Ok(t),
            Some(t) => Err(err(
                "analysis.thickness",
                format!("must be a length from {MIN_THICKNESS:e} to {MAX_COORDINATE:e} mm, got {t:?}"),
            )),
            None => Err(err(
                "analysis.thickness",
                format!("is required for kind = \"{}\" (mm: the plate's thickness, or the slice of a long body that forces are given for)", a.kind),
            )),
        }
        };
        let analysis = match a.kind.as_str() {
            "plane_stress" => Analysis::PlaneStress {
                thickness: thickness()?,
            },
            "plane_strain" => Analysis::PlaneStrain {
                thickness: thickness()?,
            },
            "axisymmetric" => {
                if a.thickness.is_some() {
                    return Err(err(
                        "analysis.thickness",
                        "a body of revolution has no thickness: its integrals are over the whole circle (2πr), and its loads and forces are for the whole circumference; remove the key".to_string(),
                    ));
                }
                Analysis::Axisymmetric
            }
            other => {
                return Err(err(
                    "analysis.kind",
                    format!("must be \"plane_stress\", \"plane_strain\" or \"axisymmetric\", got \"{other}\""),
                ))
            }
        };
        if a.p == 0 || a.p > 20 {
            return Err(err(
                "analysis.p",
                format!("polynomial degree must be 1..=20, got {}", a.p),
            ));
        }
        for (b, body) in spec.bodies.iter().enumerate() {
            if let Some(p) = body.p.filter(|&p| p == 0 || p > 20) {
                return Err(err(
                    &format!("bodies[{b}].p"),
                    format!("polynomial degree must be 1..=20, got {p}"),
                ));
            }
        }
        let space = match a.space.as_str() {
            "tensor" => Space::TensorProduct,
            "trunk" => Space::Trunk,
            other => {
                return Err(err(
                    "analysis.space",
                    format!("must be \"tensor\" or \"trunk\", got \"{other}\""),
                ))
            }
        };
        let mut materials = Vec::new();
        for (name, m) in &spec.materials {
            if !(m.young >= MIN_YOUNG && m.young <= MAX_STRESS) {
                return Err(err(
                    &format!("materials.{name}.young"),
                    format!(
                        "Young's modulus must lie from {MIN_YOUNG:e} to {MAX_STRESS:e} MPa, got {:?}",
                        m.young
                    ),
                ));
            }
            if !(m.poisson.is_finite() && m.poisson > -1.0 && m.poisson < 0.5) {
                return Err(err(
                    &format!("materials.{name}.poisson"),
                    format!("Poisson's ratio must lie in (-1, 0.5), got {:?}", m.poisson),
                ));
            }
            materials.push(Material {
                young: m.young,
                poisson: m.poisson,
            });
        }
        if spec.bodies.is_empty() {
            return Err(err("bodies", "at least one body is needed".into()));
        }
        for (b, body) in spec.bodies.iter().enumerate() {
            if body.blocks.is_empty() && body.gmsh.is_none() {
                return Err(err(
                    &format!("bodies[{b}].blocks"),
                    format!(
                        "body \"{}\" has no blocks: give [[bodies.blocks]] or a Gmsh mesh, [bodies.gmsh]",
                        body.name
                    ),
                ));
            }
            if !body.blocks.is_empty() && body.gmsh.is_some() {
                return Err(err(
                    &format!("bodies[{b}].gmsh"),
                    format!(
                        "body \"{}\" gives both blocks and a Gmsh mesh: give one",
                        body.name
                    ),
                ));
            }
            if spec.bodies[..b].iter().any(|other| other.name == body.name) {
                return Err(err(
                    &format!("bodies[{b}].name"),
                    format!("two bodies are called \"{}\"", body.name),
                ));
            }
        }
        if let Some(shape) = spec.contact.as_ref().and_then(|c| c.initial_shape) {
            if !(shape.radius > 0.0
                && shape.radius <= MAX_COORDINATE
                && shape.center_x.abs() <= MAX_COORDINATE)
            {
                return Err(err("contact.initial_shape", format!("radius must be a positive length of at most {MAX_COORDINATE:e} mm and center_x within ±{MAX_COORDINATE:e} mm, got radius {} and center_x {}", shape.radius, shape.center_x)));
            }
        }
        let mut problem = Problem {
            file: file.into(),
            analysis,
            discretisation: Discretisation { p: a.p, space },
            materials,
            spec,
            meshes: None,
        };
        // Every body's mesh is built before any traction window is checked: of a file with
        // a wrong window on body 1 and a wrong mesh on body 2, the mesh is reported (each
        // error is reported alone once the other is mended).
        let built = meshes::BuiltMeshes::of(&problem)?;
        for b in 0..problem.spec.bodies.len() {
            problem.check_traction_windows(b, built.mesh(b))?;
        }
        problem.meshes = Some(built);
        problem.heat_settings()?;
        problem.fretting_settings()?;
        for (name, probe) in &problem.spec.probes {
            problem.body_index(&probe.body).map_err(|_| {
                problem.error(
                    format!("probes.{name}.body"),
                    format!("no body named \"{}\"", probe.body),
                )
            })?;
            if !probe.at.iter().all(|c| c.abs() <= MAX_COORDINATE) {
                return Err(problem.error(
                    format!("probes.{name}.at"),
                    format!(
                        "must be coordinates [x, z] within ±{MAX_COORDINATE:e} mm, got {:?}",
                        probe.at
                    ),
                ));
            }
        }
        Ok(problem)
    }

    /// Index of the body called `name`.
    pub fn body_index(&self, name: &str) -> Result<usize, ProblemError> {
        self.spec
            .bodies
            .iter()
            .position(|b| b.name == name)
            .ok_or_else(|| self.error("bodies", format!("no body named \"{name}\"")))
    }

    /// Every traction of body `b` must act on some length of its edge: a window that misses
    /// the edge (or a z window on a horizontal edge) would silently load nothing.
    fn check_traction_windows(&self, b: usize, mesh: &Mesh) -> Result<(), ProblemError> {
        for (k, traction) in self.tractions(b)?.iter().enumerate() {
            let key = format!("bodies[{b}].tractions[{k}]");
            let edges = self.named_edge(mesh, b, &traction.edge, &format!("{key}.edge"))?;
            let mut length = 0.0;
            let unit = Analysis::PlaneStrain { thickness: 1.0 };
            traction.for_each_point(mesh, edges, 1, unit, |_, _, _, _, _, ds| length += ds);
            if length <= 0.0 && traction.window.is_some() {
                return Err(self.error(
                    format!("{key}.window"),
                    format!(
                        "does not overlap edge \"{}\": the traction would act nowhere",
                        traction.edge
                    ),
                ));
            }
            if self.analysis.is_axisymmetric() {
                let size = mesh
                    .vertices
                    .iter()
                    .fold(0.0f64, |a, v| a.max(v[0].abs()).max(v[1].abs()));
                let mut off_axis = false;
                traction.for_each_point(mesh, edges, 1, unit, |_, _, _, x, _, _| {
                    off_axis |= !crate::material::on_axis(x[0], size);
                });
                if !off_axis {
                    return Err(self.error(
                        format!("{key}.edge"),
                        format!("\"{}\" lies on the axis (r = 0), where a body of revolution has no surface: a traction there acts on nothing (its 2πr weight is zero)", traction.edge),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The tractions of body `b` as library objects.
    pub fn tractions(&self, b: usize) -> Result<Vec<Traction>, ProblemError> {
        let mut out = Vec::new();
        for (k, t) in self.spec.bodies[b].tractions.iter().enumerate() {
            let key = |f: &str| format!("bodies[{b}].tractions[{k}].{f}");
            let window = match &t.window {
                None => None,
                Some(WindowSpec {
                    x: Some(r),
                    z: None,
                }) => Some(Window { axis: 0, range: *r }),
                Some(WindowSpec {
                    x: None,
                    z: Some(r),
                }) => Some(Window { axis: 1, range: *r }),
                Some(_) => return Err(self.error(key("window"), "give exactly one of x or z")),
            };
            if let Some(w) = window {
                if !(w.range[0].is_finite() && w.range[1].is_finite() && w.range[1] > w.range[0]) {
                    return Err(
                        self.error(key("window"), format!("range must rise, got {:?}", w.range))
                    );
                }
            }
            let (normal, shear) = (t.normal.pair(), t.shear.pair());
            for (name, values) in [("normal", normal), ("shear", shear)] {
                if values.iter().any(|v| !within(*v, MAX_STRESS)) {
                    return Err(self.error(
                        key(name),
                        format!("values must be finite and at most {MAX_STRESS:e} MPa in size, got {values:?}"),
                    ));
                }
                if window.is_none() && values[0] != values[1] {
                    return Err(self.error(key(name), "a linear variation needs a window"));
                }
            }
            out.push(Traction {
                edge: t.edge.clone(),
                normal,
                shear,
                window,
            });
        }
        Ok(out)
    }

    /// Supports of body `b`: held global dofs (with their prescribed displacements) and
    /// elastic supports, plus `extra_clamped` edges held in x and z.
    pub fn constraints(
        &self,
        b: usize,
        mesh: &Mesh,
        dofs: &crate::dofs::DofMap,
        basis: &crate::basis::QuadBasis,
        extra_clamped: &[&str],
    ) -> Result<Constraints, ProblemError> {
        // Every held dof with its value and the key that held it, to name conflicts.
        let mut held: std::collections::BTreeMap<usize, (f64, String)> = Default::default();
        let mut hold = |d: usize, value: f64, key: &str| -> Result<(), ProblemError> {
            match held.get(&d) {
                Some((v, other)) if *v != value => Err(self.error(
                    key,
                    format!(
                        "holds a point of the body at {value} mm where {other} holds it at {v} mm"
                    ),
                )),
                _ => {
                    held.entry(d).or_insert((value, key.to_string()));
                    Ok(())
                }
            }
        };
        if self.analysis.is_axisymmetric() {
            // First, so that a support contradicting it is the one named.
            self.hold_axis(b, mesh, dofs, basis, &mut hold)?;
        }
        for (k, s) in self.spec.bodies[b].supports.iter().enumerate() {
            let key = format!("bodies[{b}].supports[{k}]");
            let mut comps = Vec::new();
            for c in &s.fix {
                match c.as_str() {
                    "x" => comps.push(0),
                    "z" => comps.push(1),
                    other => {
                        return Err(self.error(
                            format!("{key}.fix"),
                            format!("components are \"x\" and \"z\", got \"{other}\""),
                        ))
                    }
                }
            }
            if comps.is_empty() {
                return Err(self.error(
                    format!("{key}.fix"),
                    "lists no component: give \"x\", \"z\" or both",
                ));
            }
            let displacement = s.displacement.unwrap_or([0.0, 0.0]);
            for c in 0..2 {
                if !displacement[c].is_finite() {
                    return Err(self.error(format!("{key}.displacement"), "must be finite"));
                }
                if displacement[c] != 0.0 && !comps.contains(&c) {
                    return Err(self.error(
                        format!("{key}.displacement"),
                        format!(
                            "gives {} mm in {} but `fix` does not hold {}",
                            displacement[c],
                            ["x", "z"][c],
                            ["x", "z"][c]
                        ),
                    ));
                }
            }
            match (&s.edge, s.point) {
                (Some(edge), None) => {
                    let edges = self.named_edge(mesh, b, edge, &format!("{key}.edge"))?;
                    if comps.contains(&1) && self.lies_on_axis(mesh, edges) {
                        return Err(self.error(
                            format!("{key}.fix"),
                            format!("holds z along \"{edge}\", which lies on the axis: a line of a body of revolution has no area, and holding it is a line load in 3D that the continuum has no answer for (the result would depend on the mesh); hold a face (an end, a shoulder) instead. Its radial displacement is held there anyway"),
                        ));
                    }
                    for &(element, local) in edges {
                        // A constant along the edge: its vertex modes take the value, its edge
                        // modes zero.
                        let trace = crate::loads::trace_dofs(dofs, mesh, basis, element, local);
                        for (m, (g, _)) in trace.iter().enumerate() {
                            for &c in &comps {
                                let value = if m < 2 { displacement[c] } else { 0.0 };
                                hold(g[c], value, &key)?;
                            }
                        }
                    }
                }
                (None, Some(point)) => {
                    let v = mesh.vertex_at(point).ok_or_else(|| {
                        self.error(
                            format!("{key}.point"),
                            format!("({}, {}) is not a mesh vertex", point[0], point[1]),
                        )
                    })?;
                    for &c in &comps {
                        hold(dofs.vertex_dof(v, c), displacement[c], &key)?;
                    }
                }
                _ => return Err(self.error(key, "give exactly one of edge or point")),
            }
        }
        for name in extra_clamped {
            for &(element, local) in self.named_edge(mesh, b, name, "plate.edge")? {
                for (g, _) in crate::loads::trace_dofs(dofs, mesh, basis, element, local) {
                    hold(g[0], 0.0, "plate.edge")?;
                    hold(g[1], 0.0, "plate.edge")?;
                }
            }
        }
        let mut springs = Vec::new();
        for (k, s) in self.spec.bodies[b].springs.iter().enumerate() {
            let key = format!("bodies[{b}].springs[{k}]");
            for (name, value) in [("normal", s.normal), ("tangential", s.tangential)] {
                if !(value.is_finite() && value >= 0.0) {
                    return Err(self.error(
                        format!("{key}.{name}"),
                        format!("{value} is not a stiffness: give a modulus ≥ 0 in N/mm³"),
                    ));
                }
            }
            if s.normal == 0.0 && s.tangential == 0.0 {
                return Err(self.error(key, "has no stiffness: give normal or tangential (N/mm³)"));
            }
            let edges = self.named_edge(mesh, b, &s.edge, &format!("{key}.edge"))?;
            if self.lies_on_axis(mesh, edges) {
                return Err(self.error(
                    format!("{key}.edge"),
                    format!("\"{}\" lies on the axis (r = 0), where a body of revolution has no surface: a spring bed there holds nothing (its 2πr weight is zero)", s.edge),
                ));
            }
            for &(element, local) in edges {
                springs.push(crate::elasticity::Spring {
                    element,
                    local,
                    normal: s.normal,
                    tangential: s.tangential,
                });
            }
        }
        Ok(Constraints {
            fixed: held.keys().copied().collect(),
            prescribed: held
                .iter()
                .filter(|(_, (v, _))| *v != 0.0)
                .map(|(&d, (v, _))| (d, *v))
                .collect(),
            springs,
        })
    }

    /// Whether the element edges `edges` of a body of revolution all lie on its axis.
    fn lies_on_axis(&self, mesh: &Mesh, edges: &[(usize, usize)]) -> bool {
        if !self.analysis.is_axisymmetric() || edges.is_empty() {
            return false;
        }
        let size = mesh
            .vertices
            .iter()
            .fold(0.0f64, |a, v| a.max(v[0].abs()).max(v[1].abs()));
        edges.iter().all(|&(element, local)| {
            [-1.0, 0.0, 1.0]
                .iter()
                .all(|&t| crate::material::on_axis(mesh.point_on_edge(element, local, t)[0], size))
        })
    }

    /// A body of revolution lies at r = x ≥ 0, and on the axis its radial displacement is zero
    /// (the axis condition, implied rather than given: u_r/r must stay finite there). Hold
    /// the radial dofs of the boundary edges along the axis and of the vertices on it.
    fn hold_axis(
        &self,
        b: usize,
        mesh: &Mesh,
        dofs: &crate::dofs::DofMap,
        basis: &crate::basis::QuadBasis,
        hold: &mut impl FnMut(usize, f64, &str) -> Result<(), ProblemError>,
    ) -> Result<(), ProblemError> {
        let size = mesh
            .vertices
            .iter()
            .fold(0.0f64, |a, v| a.max(v[0].abs()).max(v[1].abs()));
        let on_axis = |r: f64| crate::material::on_axis(r, size);
        let edges = crate::input::heat::boundary_edges(mesh);
        for &(element, local, _) in &edges {
            for t in [-1.0, -0.5, 0.0, 0.5, 1.0] {
                let x = mesh.point_on_edge(element, local, t);
                if x[0] < 0.0 && !on_axis(x[0]) {
                    return Err(self.error(
                        format!("bodies[{b}].blocks"),
                        format!("body \"{}\" reaches r = x = {:.6} mm at z = {:.6} mm: a body of revolution (analysis.kind = \"axisymmetric\") lies at r ≥ 0, x being the radius", self.spec.bodies[b].name, x[0], x[1]),
                    ));
                }
            }
        }
        const AXIS: &str =
            "the axis (r = 0, where an axisymmetric body's radial displacement is zero)";
        for &(element, local, _) in &edges {
            let along = [-1.0, 0.0, 1.0]
                .iter()
                .all(|&t| on_axis(mesh.point_on_edge(element, local, t)[0]));
            if along {
                for (g, _) in crate::loads::trace_dofs(dofs, mesh, basis, element, local) {
                    hold(g[0], 0.0, AXIS)?;
                }
            }
        }
        for (v, x) in mesh.vertices.iter().enumerate() {
            if on_axis(x[0]) {
                hold(dofs.vertex_dof(v, 0), 0.0, AXIS)?;
            }
        }
        Ok(())
    }

    /// Degree and space of body `b`: its own `p` if given, else `analysis.p`.
    pub fn body_discretisation(&self, b: usize) -> Discretisation {
        Discretisation {
            p: self.spec.bodies[b].p.unwrap_or(self.discretisation.p),
            ..self.discretisation
        }
    }

    /// Build, assemble and factorise body `b`; `extra_clamped` edges are held (rigid plate).
    pub fn elastic_body(
        &self,
        b: usize,
        extra_clamped: &[&str],
    ) -> Result<ElasticBody, ProblemError> {
        let mesh = self.mesh(b)?;
        let discretisation = self.body_discretisation(b);
        let dofs = crate::dofs::DofMap::new(&mesh, discretisation.p);
        let basis = crate::basis::QuadBasis::new(discretisation.p, discretisation.space);
        let constraints = self.constraints(b, &mesh, &dofs, &basis, extra_clamped)?;
        let name = &self.spec.bodies[b].name;
        ElasticBody::new(
            name,
            mesh,
            self.materials.clone(),
            self.analysis,
            discretisation,
            &constraints,
        )
        .map_err(|e| self.error(format!("bodies[{b}].supports"), e.to_string()))
    }

    /// The global load vector of body `b` from its tractions (edges in `skip` excluded).
    pub fn load_vector(
        &self,
        b: usize,
        body: &ElasticBody,
        skip: &[&str],
    ) -> Result<Vec<f64>, ProblemError> {
        let mut load = vec![0.0; body.dofs.n_dofs()];
        for (k, t) in self.tractions(b)?.iter().enumerate() {
            if skip.contains(&t.edge.as_str()) {
                continue;
            }
            let edges = self.named_edge(
                &body.mesh,
                b,
                &t.edge,
                &format!("bodies[{b}].tractions[{k}].edge"),
            )?;
            t.add_to_load(
                &body.mesh,
                edges,
                &body.dofs,
                &body.basis,
                self.analysis,
                &mut load,
            );
        }
        Ok(load)
    }
}
