//! The `[heat]` section of a problem file and the materials' thermal properties: the schema,
//! the engineering units and their conversion, and the validated [`HeatSettings`] that the
//! heat stage takes.
//!
//! A problem has heat when it has a `[heat]` section; without one nothing of this module
//! runs and every result is what it was before heat existed.
//!
//! **Units in the file** (converted as [`crate::material::ThermalMaterial::from_engineering`]
//! says): conductivity W/(m·K), specific heat J/(kg·K), density kg/m³, expansion 1/K, film
//! coefficients W/(m²·K), temperatures °C.
//!
//! **Edges.** Every boundary edge of the two contact bodies is insulated unless
//! `[[heat.edges]]` names it (held `temperature`, `convection` with an `ambient`, or
//! `insulated`), or `heat.other_edges` gives the condition of every edge not named. Body 1's
//! contact edge exchanges heat with body 2 and takes no condition; the part of body 2's
//! contact edge that body 1 does not cover takes its named condition or `other_edges`.

use crate::conduction::{EdgeCondition, EdgePiece, FaceConvection};
use crate::material::{film_coefficient, ThermalMaterial};
use crate::mesh::Mesh;
use crate::problem::{Problem, ProblemError};
use serde::Deserialize;

/// Most temperature accepted, °C, in size: beyond it no solid keeps its properties (and the
/// linear model none of its meaning).
pub const MAX_TEMPERATURE: f64 = 1e4;

/// `[heat]`: frictional heating, conduction and thermal distortion.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatSpec {
    /// Stress-free temperature, °C (default 20).
    #[serde(default = "twenty")]
    pub reference_temperature: f64,
    /// Temperature of both bodies at the start, °C (default: the reference temperature).
    pub initial_temperature: Option<f64>,
    /// Ambient temperature of convection that names none, °C (default: the reference).
    pub ambient_temperature: Option<f64>,
    /// How the frictional heat is shared: "perfect" (default: perfect thermal contact, equal
    /// temperatures at partner points, the share solved) or the fraction (0 … 1) that goes
    /// into body 1.
    #[serde(default)]
    pub partition: Option<PartitionSpec>,
    /// The condition of every boundary edge that `edges` does not name (default insulated).
    pub other_edges: Option<ConditionSpec>,
    /// Convection from both faces of plane-stress bodies (a thin plate).
    pub faces: Option<ConditionSpec>,
    /// Conditions of named edges.
    #[serde(default)]
    pub edges: Vec<HeatEdgeSpec>,
    /// The temperature's polynomial space: "auto" (default: `analysis.space` in the elements
    /// along the contact, the trunk space elsewhere), "tensor" or "trunk" everywhere.
    pub space: Option<String>,
}

fn twenty() -> f64 {
    20.0
}

/// `heat.partition`: a name or a fraction.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged, expecting = "\"perfect\" or a fraction from 0 to 1")]
pub enum PartitionSpec {
    /// "perfect".
    Named(String),
    /// The fraction of the frictional heat that enters body 1.
    Fraction(f64),
}

/// An edge condition as written: exactly one of `temperature`, `convection` (with an optional
/// `ambient`) or `insulated = true`.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConditionSpec {
    /// Held temperature, °C.
    pub temperature: Option<f64>,
    /// Film coefficient h, W/(m²·K).
    pub convection: Option<f64>,
    /// Ambient temperature of the convection, °C (default `heat.ambient_temperature`).
    pub ambient: Option<f64>,
    /// No heat crosses the edge.
    pub insulated: Option<bool>,
}

/// `[[heat.edges]]`: the condition of one named edge.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatEdgeSpec {
    /// Body name.
    pub body: String,
    /// Edge name (block edge `names`).
    pub edge: String,
    /// Held temperature, °C.
    pub temperature: Option<f64>,
    /// Film coefficient h, W/(m²·K).
    pub convection: Option<f64>,
    /// Ambient temperature of the convection, °C.
    pub ambient: Option<f64>,
    /// No heat crosses the edge.
    pub insulated: Option<bool>,
}

/// The temperature's polynomial space (`heat.space`), at each element's displacement degree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HeatSpace {
    /// The displacement's space (`analysis.space`) in the elements along the contact, where
    /// the heat enters in a thin layer, and the trunk space elsewhere
    /// ([`crate::conduction::spaces`]).
    Auto,
    /// The tensor-product space in every element.
    Tensor,
    /// The trunk space in every element.
    Trunk,
}

/// How the frictional heat is shared between the bodies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Partition {
    /// Perfect thermal contact: equal temperatures at partner points; the share follows.
    Perfect,
    /// This fraction (0 … 1) of the heat enters body 1, the rest body 2; no heat crosses
    /// between them otherwise.
    Fraction(f64),
}

/// The thermal model of one contact body.
#[derive(Clone, Debug)]
pub struct BodyHeat {
    /// Index of the body in the problem.
    pub body: usize,
    /// Conditions of its boundary edges (its contact edge left out).
    pub edges: Vec<(EdgePiece, EdgeCondition)>,
    /// Its contact edge's element edges (element, local edge).
    pub contact_edge: Vec<(usize, usize)>,
    /// Body 2 only: the condition of the part of its contact edge that body 1 does not
    /// cover (None: insulated), and the key it was given by.
    pub uncovered: Option<EdgeCondition>,
    /// The key `uncovered` comes from (`heat.other_edges` or `heat.edges[k]`).
    pub uncovered_key: String,
}

/// The validated `[heat]` section.
#[derive(Clone, Debug)]
pub struct HeatSettings {
    /// Stress-free temperature, °C.
    pub reference: f64,
    /// Initial temperature, °C.
    pub initial: f64,
    /// Ambient temperature, °C: of the surroundings, and of the material entering a body
    /// that moves through the contact (monotonic sliding).
    pub ambient: f64,
    /// How the frictional heat is shared.
    pub partition: Partition,
    /// The temperature's polynomial space.
    pub space: HeatSpace,
    /// Convection from the faces of a plane-stress plate.
    pub faces: Option<FaceConvection>,
    /// Thermal properties of each material (in `spec.materials` order).
    pub materials: Vec<ThermalMaterial>,
    /// Body 1 and body 2 of the contact.
    pub bodies: [BodyHeat; 2],
}

/// The thermal properties of a material as written (`[materials.NAME]`'s thermal keys).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ThermalProperties {
    /// Conductivity k, W/(m·K).
    pub conductivity: Option<f64>,
    /// Specific heat c, J/(kg·K).
    pub specific_heat: Option<f64>,
    /// Density ρ, kg/m³.
    pub density: Option<f64>,
    /// Linear expansion coefficient α, 1/K.
    pub expansion: Option<f64>,
}

impl HeatSettings {
    /// The lowest temperature the problem imposes (°C): the initial temperature, the
    /// ambient one (of the surroundings and of material entering a moving body), and every
    /// held or convection temperature of an edge or the faces.
    pub fn lowest_imposed(&self) -> f64 {
        let of = |c: &EdgeCondition| match *c {
            EdgeCondition::Temperature(t) => t,
            EdgeCondition::Convection { ambient, .. } => ambient,
        };
        let edges = self.bodies.iter().flat_map(|b| {
            b.edges
                .iter()
                .map(|(_, c)| of(c))
                .chain(b.uncovered.as_ref().map(of))
        });
        edges
            .chain(self.faces.map(|f| f.ambient))
            .fold(self.initial.min(self.ambient), f64::min)
    }
}

impl Problem {
    /// The validated `[heat]` section, or None without one. Edge names are resolved on the
    /// meshes the bodies are solved on.
    pub fn heat_settings(&self) -> Result<Option<HeatSettings>, ProblemError> {
        let Some(heat) = &self.spec.heat else {
            return Ok(None);
        };
        let Some(contact) = &self.spec.contact else {
            return Err(self.error(
                "heat",
                "heat needs a [contact] section: the frictional heat is made at the contact",
            ));
        };
        let temperature = |key: &str, v: f64| -> Result<f64, ProblemError> {
            if v.is_finite() && v.abs() <= MAX_TEMPERATURE && v > -273.15 {
                Ok(v)
            } else {
                Err(self.error(
                    key,
                    format!("must be a temperature in °C above −273.15 and at most {MAX_TEMPERATURE:e} in size, got {v}"),
                ))
            }
        };
        let reference = temperature("heat.reference_temperature", heat.reference_temperature)?;
        let initial = match heat.initial_temperature {
            Some(v) => temperature("heat.initial_temperature", v)?,
            None => reference,
        };
        let ambient = match heat.ambient_temperature {
            Some(v) => temperature("heat.ambient_temperature", v)?,
            None => reference,
        };
        let partition = match &heat.partition {
            None => Partition::Perfect,
            Some(PartitionSpec::Named(n)) if n == "perfect" => Partition::Perfect,
            Some(PartitionSpec::Fraction(f)) if (0.0..=1.0).contains(f) => Partition::Fraction(*f),
            Some(other) => {
                let got = match other {
                    PartitionSpec::Named(n) => format!("\"{n}\""),
                    PartitionSpec::Fraction(f) => f.to_string(),
                };
                return Err(self.error(
                    "heat.partition",
                    format!("must be \"perfect\" or the fraction of the frictional heat that enters body 1, from 0 to 1; got {got}"),
                ));
            }
        };
        let space = match heat.space.as_deref() {
            None | Some("auto") => HeatSpace::Auto,
            Some("tensor") => HeatSpace::Tensor,
            Some("trunk") => HeatSpace::Trunk,
            Some(other) => {
                return Err(self.error(
                    "heat.space",
                    format!("must be \"auto\", \"tensor\" or \"trunk\"; got \"{other}\""),
                ))
            }
        };
        let b1 = self.body_index(&contact.body).map_err(|e| ProblemError {
            key: "contact.body".into(),
            ..e
        })?;
        let b2 = self
            .body_index(&contact.target_body)
            .map_err(|e| ProblemError {
                key: "contact.target_body".into(),
                ..e
            })?;
        let materials = self.thermal_materials([b1, b2])?;
        let condition =
            |key: &str, c: &ConditionSpec| self.condition(key, c, ambient, &temperature);
        let faces = match &heat.faces {
            None => None,
            Some(c) => {
                if !matches!(self.analysis, crate::material::Analysis::PlaneStress { .. }) {
                    return Err(self.error("heat.faces", "convection from the faces is a thin plate's (plane stress); a plane-strain body is long out of its plane and has no faces to lose heat through"));
                }
                match condition("heat.faces", c)? {
                    None => None,
                    Some(EdgeCondition::Convection {
                        coefficient,
                        ambient,
                    }) => Some(FaceConvection {
                        coefficient,
                        ambient,
                    }),
                    Some(EdgeCondition::Temperature(_)) => return Err(self.error(
                        "heat.faces",
                        "faces can only convect (`convection`, `ambient`), not hold a temperature",
                    )),
                }
            }
        };
        let other = match &heat.other_edges {
            None => None,
            Some(c) => condition("heat.other_edges", c)?,
        };
        let mut bodies = Vec::new();
        for (which, b) in [b1, b2].into_iter().enumerate() {
            bodies.push(self.body_heat(heat, which, b, other, &condition)?);
        }
        for (k, e) in heat.edges.iter().enumerate() {
            if self.body_index(&e.body).is_err() || ![b1, b2].contains(&self.body_index(&e.body)?) {
                return Err(self.error(
                    format!("heat.edges[{k}].body"),
                    format!("\"{}\" is not one of the contact's bodies (\"{}\", \"{}\"); heat is computed in those two", e.body, contact.body, contact.target_body),
                ));
            }
        }
        let [body1, body2]: [BodyHeat; 2] = bodies.try_into().expect("two bodies");
        Ok(Some(HeatSettings {
            reference,
            initial,
            ambient,
            partition,
            space,
            faces,
            materials,
            bodies: [body1, body2],
        }))
    }

    /// Every material of the two bodies with all its thermal properties, converted.
    fn thermal_materials(&self, bodies: [usize; 2]) -> Result<Vec<ThermalMaterial>, ProblemError> {
        let used: Vec<&str> = bodies
            .iter()
            .flat_map(|&b| {
                let body = &self.spec.bodies[b];
                let gmsh = body.gmsh.iter().flat_map(|g| g.materials.values());
                body.blocks
                    .iter()
                    .map(|bl| &bl.material)
                    .chain(gmsh)
                    .map(String::as_str)
            })
            .collect();
        let mut out = Vec::new();
        for (name, m) in &self.spec.materials {
            let t = m.thermal();
            let needed = used.contains(&name.as_str());
            let value = |field: &str,
                         v: Option<f64>,
                         positive: bool|
             -> Result<f64, ProblemError> {
                let key = format!("materials.{name}.{field}");
                match v {
                    None if needed => Err(self.error(key, format!("is missing: material \"{name}\" is used by a contact body of a problem with heat, which needs its conductivity (W/(m·K)), specific_heat (J/(kg·K)), density (kg/m³) and expansion (1/K)"))),
                    None => Ok(0.0),
                    Some(v) if !v.is_finite() || (positive && v <= 0.0) || v.abs() > 1e9 => Err(self.error(key, format!("must be {}, finite and at most 1e9 in size, got {v:e}", if positive { "positive" } else { "a number" }))),
                    Some(v) => Ok(v),
                }
            };
            let k = value("conductivity", t.conductivity, true)?;
            let c = value("specific_heat", t.specific_heat, true)?;
            let rho = value("density", t.density, true)?;
            let alpha = value("expansion", t.expansion, false)?;
            if alpha.abs() > 1e-2 {
                return Err(self.error(format!("materials.{name}.expansion"), format!("{alpha} 1/K is not a linear expansion coefficient (solids: 1e-7 … 3e-4 1/K)")));
            }
            out.push(if needed || t.conductivity.is_some() {
                ThermalMaterial::from_engineering(k, c, rho, alpha)
            } else {
                ThermalMaterial {
                    conductivity: 0.0,
                    heat_capacity: 0.0,
                    expansion: 0.0,
                }
            });
        }
        Ok(out)
    }

    /// One condition as written, checked and converted; None for insulated.
    fn condition(
        &self,
        key: &str,
        c: &ConditionSpec,
        default_ambient: f64,
        temperature: &impl Fn(&str, f64) -> Result<f64, ProblemError>,
    ) -> Result<Option<EdgeCondition>, ProblemError> {
        let given = usize::from(c.temperature.is_some())
            + usize::from(c.convection.is_some())
            + usize::from(c.insulated == Some(true));
        if given != 1 || c.insulated == Some(false) {
            return Err(self.error(key, "give exactly one of `temperature` (°C), `convection` (W/(m²·K), with `ambient` in °C) or `insulated = true`"));
        }
        if c.ambient.is_some() && c.convection.is_none() {
            return Err(self.error(
                format!("{key}.ambient"),
                "`ambient` belongs to a `convection` condition",
            ));
        }
        if let Some(t) = c.temperature {
            return Ok(Some(EdgeCondition::Temperature(temperature(
                &format!("{key}.temperature"),
                t,
            )?)));
        }
        if let Some(h) = c.convection {
            if !(h.is_finite() && (0.0..=1e8).contains(&h)) {
                return Err(self.error(
                    format!("{key}.convection"),
                    format!("must be a film coefficient from 0 to 1e8 W/(m²·K), got {h}"),
                ));
            }
            let ambient = match c.ambient {
                Some(a) => temperature(&format!("{key}.ambient"), a)?,
                None => default_ambient,
            };
            return Ok(Some(EdgeCondition::Convection {
                coefficient: film_coefficient(h),
                ambient,
            }));
        }
        Ok(None)
    }

    /// The edge conditions of contact body `which` (0: body 1, 1: body 2), problem body `b`.
    fn body_heat(
        &self,
        heat: &HeatSpec,
        which: usize,
        b: usize,
        other: Option<EdgeCondition>,
        condition: &impl Fn(&str, &ConditionSpec) -> Result<Option<EdgeCondition>, ProblemError>,
    ) -> Result<BodyHeat, ProblemError> {
        let contact = self.spec.contact.as_ref().expect("checked by the caller");
        let mesh = self.mesh(b)?;
        let (contact_name, contact_key) = if which == 0 {
            (&contact.edge, "contact.edge")
        } else {
            (&contact.target_edge, "contact.target_edge")
        };
        let contact_edge = self
            .named_edge(&mesh, b, contact_name, contact_key)?
            .to_vec();
        let mut named: Vec<((usize, usize), Option<EdgeCondition>)> = Vec::new();
        let mut uncovered = other;
        let mut uncovered_key = "heat.other_edges".to_string();
        for (k, e) in heat.edges.iter().enumerate() {
            if e.body != self.spec.bodies[b].name {
                continue;
            }
            let key = format!("heat.edges[{k}]");
            let c = condition(
                &key,
                &ConditionSpec {
                    temperature: e.temperature,
                    convection: e.convection,
                    ambient: e.ambient,
                    insulated: e.insulated,
                },
            )?;
            if e.edge == *contact_name {
                if which == 0 {
                    return Err(self.error(format!("{key}.edge"), format!("\"{}\" is body 1's contact edge, which exchanges heat with body 2 (heat.partition); give conditions to its other edges", e.edge)));
                }
                if matches!(c, Some(EdgeCondition::Temperature(_))) {
                    return Err(self.error(format!("{key}.temperature"), format!("\"{}\" is body 2's contact edge: its part under body 1 takes the frictional heat and cannot be held at a temperature; hold another edge", e.edge)));
                }
                uncovered = c;
                uncovered_key = key;
                continue;
            }
            let edges = self.named_edge(&mesh, b, &e.edge, &format!("{key}.edge"))?;
            named.extend(edges.iter().map(|&edge| (edge, c)));
        }
        let mut edges = Vec::new();
        for (element, local, _) in boundary_edges(&mesh) {
            if contact_edge.contains(&(element, local)) {
                continue;
            }
            let condition = match named.iter().find(|(edge, _)| *edge == (element, local)) {
                Some((_, c)) => *c,
                None => other,
            };
            if let Some(c) = condition {
                edges.push((EdgePiece::whole(element, local), c));
            }
        }
        Ok(BodyHeat {
            body: b,
            edges,
            contact_edge,
            uncovered: if which == 1 { uncovered } else { None },
            uncovered_key,
        })
    }
}

/// The boundary element edges of `mesh` (one element only): (element, local edge, mesh edge).
pub fn boundary_edges(mesh: &Mesh) -> Vec<(usize, usize, usize)> {
    let mut out = Vec::new();
    for (element, el) in mesh.elements.iter().enumerate() {
        for (local, &edge) in el.edges.iter().enumerate() {
            if mesh.edges[edge].elements.len() == 1 {
                out.push((element, local, edge));
            }
        }
    }
    out
}
