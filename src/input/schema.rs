//! The problem-file schema: the serde structures that a TOML problem file is read into.
//! Validation and the construction of the model are in [`crate::problem`].

use crate::geometry::Point;
use serde::Deserialize;
use std::collections::BTreeMap;

/// `[analysis]`: the 2D idealisation and the discretisation.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalysisSpec {
    /// "plane_stress", "plane_strain" or "axisymmetric".
    pub kind: String,
    /// Out-of-plane thickness, mm: required by the plane analyses, refused by the
    /// axisymmetric one (whose integrals are over the whole circle).
    #[serde(default)]
    pub thickness: Option<f64>,
    /// Polynomial degree p (1..=20).
    pub p: usize,
    /// "tensor" (default) or "trunk".
    #[serde(default = "default_space")]
    pub space: String,
    /// Whether to check the first contact solve against one with every degree raised by 2
    /// ([`crate::p_check`]); None: yes for `contact`, `run` and `steady`, no in studies.
    #[serde(default)]
    pub p_check: Option<bool>,
}

fn default_space() -> String {
    "tensor".into()
}

/// `[materials.NAME]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus, MPa (> 0).
    pub young: f64,
    /// Poisson's ratio (−1 < ν < 0.5).
    pub poisson: f64,
    /// Thermal conductivity k, W/(m·K) (problems with `[heat]`).
    pub conductivity: Option<f64>,
    /// Specific heat c, J/(kg·K) (problems with `[heat]`).
    pub specific_heat: Option<f64>,
    /// Density ρ, kg/m³ (problems with `[heat]`).
    pub density: Option<f64>,
    /// Linear thermal expansion coefficient α, 1/K (problems with `[heat]`).
    pub expansion: Option<f64>,
}

impl MaterialSpec {
    /// The thermal keys, together.
    pub fn thermal(&self) -> crate::heat_input::ThermalProperties {
        crate::heat_input::ThermalProperties {
            conductivity: self.conductivity,
            specific_heat: self.specific_heat,
            density: self.density,
            expansion: self.expansion,
        }
    }
}

/// One number, or two (start and end of a linear variation).
#[derive(Clone, Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "a number, or a list of two numbers (values at the window's bounds)"
)]
pub enum OneOrTwo {
    /// Constant value.
    One(f64),
    /// Values at the lower and upper window bound.
    Two(#[serde(deserialize_with = "exact::pair")] [f64; 2]),
}

impl OneOrTwo {
    /// The values at the lower and upper bound (equal for a constant).
    pub fn pair(&self) -> [f64; 2] {
        match *self {
            OneOrTwo::One(v) => [v, v],
            OneOrTwo::Two(v) => v,
        }
    }
}

/// Mesh lines along one block direction: a number of equal divisions, explicit parameters, or
/// a graded division.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(
    untagged,
    expecting = "a whole number of equal divisions, a list of rising parameters from 0 to 1, or a table { n = 20, ratio = 1.15 } (with both_ends = true to grade towards both ends)"
)]
pub enum LinesSpec {
    /// Equal divisions.
    Count(usize),
    /// Parameters in [0, 1], rising, 0 and 1 included.
    List(Vec<f64>),
    /// Graded divisions.
    Graded(GradedLines),
}

/// `{ n = 20, ratio = 1.15 }`: n divisions, each `ratio` times the one before it from the
/// block's first corner along the direction; `both_ends = true` grades from both ends towards
/// the middle instead.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GradedLines {
    /// Number of divisions.
    pub n: usize,
    /// Size of each division over the one before it (> 0).
    pub ratio: f64,
    /// Fine at both ends, growing by `ratio` towards the middle.
    #[serde(default)]
    pub both_ends: bool,
}

/// An arc edge of a block.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ArcSpec {
    /// Block edge 0..=3 (0: c0→c1, 1: c1→c2, 2: c2→c3, 3: c3→c0).
    pub edge: usize,
    /// Arc centre [x, z], mm.
    #[serde(deserialize_with = "exact::pair")]
    pub center: Point,
}

/// `[bodies.gmsh]`: a body's mesh from a Gmsh file (format 4.1, ASCII or binary).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GmshSpec {
    /// The `.msh` file, relative to the problem file's folder (or absolute).
    pub file: String,
    /// The body's physical surface groups and the material of each: group name → material
    /// name. The body is the quadrilaterals of these groups.
    pub materials: BTreeMap<String, String>,
    /// Physical curves whose nodes lie on circles, snapped to exact arcs about the given
    /// centres; other curved edges take the second-order elements' geometry.
    #[serde(default)]
    pub arcs: Vec<GmshArcSpec>,
}

/// A physical curve of a Gmsh mesh that is an arc of a circle.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GmshArcSpec {
    /// The physical curve's name.
    pub edge: String,
    /// The circle's centre [x, z], mm.
    #[serde(deserialize_with = "exact::pair")]
    pub center: Point,
}

/// Names of block edges.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct EdgeNames {
    /// Edge 0 (c0→c1).
    pub bottom: Option<String>,
    /// Edge 1 (c1→c2).
    pub right: Option<String>,
    /// Edge 2 (c2→c3).
    pub top: Option<String>,
    /// Edge 3 (c3→c0).
    pub left: Option<String>,
}

/// `[[bodies.blocks]]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BlockSpec {
    /// Four corners [x, z] (mm), counter-clockwise.
    #[serde(deserialize_with = "exact::corners")]
    pub corners: [Point; 4],
    /// Arc edges (others are straight).
    #[serde(default)]
    pub arcs: Vec<ArcSpec>,
    /// Mesh lines along c0→c1.
    pub u: LinesSpec,
    /// Mesh lines along c0→c3.
    pub v: LinesSpec,
    /// Material name.
    pub material: String,
    /// Edge names.
    #[serde(default)]
    pub names: EdgeNames,
}

/// `[[bodies.supports]]`: zero displacement on a named edge or at a vertex.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SupportSpec {
    /// Named edge (give `edge` or `point`).
    pub edge: Option<String>,
    /// A mesh vertex [x, z], mm.
    #[serde(default, deserialize_with = "exact::optional_pair")]
    pub point: Option<Point>,
    /// Components held: any of "x", "z".
    pub fix: Vec<String>,
    /// The displacement [u_x, u_z] the held components take, mm (default zero); an entry for
    /// a component that is not held must be 0.
    #[serde(default, deserialize_with = "exact::optional_pair")]
    pub displacement: Option<[f64; 2]>,
}

/// `[[bodies.springs]]`: an elastic support (a bed of springs) along a named edge.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpringSpec {
    /// Named edge.
    pub edge: String,
    /// Normal modulus, N/mm³ (MPa of traction per mm of normal displacement).
    #[serde(default)]
    pub normal: f64,
    /// Tangential modulus, N/mm³.
    #[serde(default)]
    pub tangential: f64,
}

/// A coordinate window: exactly one of x or z.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WindowSpec {
    /// x range, mm.
    #[serde(default, deserialize_with = "exact::optional_pair")]
    pub x: Option<[f64; 2]>,
    /// z range, mm.
    #[serde(default, deserialize_with = "exact::optional_pair")]
    pub z: Option<[f64; 2]>,
}

/// `[[bodies.tractions]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TractionSpec {
    /// Named edge.
    pub edge: String,
    /// Normal pressure, MPa (positive pushes into the body); two values vary linearly over the window.
    #[serde(default = "zero")]
    pub normal: OneOrTwo,
    /// Shear along the counter-clockwise boundary tangent, MPa.
    #[serde(default = "zero")]
    pub shear: OneOrTwo,
    /// Optional window.
    pub window: Option<WindowSpec>,
}

fn zero() -> OneOrTwo {
    OneOrTwo::One(0.0)
}

/// `[[bodies]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Body name.
    pub name: String,
    /// Polynomial degree of this body's elements; `analysis.p` when absent. A body may be
    /// given a higher degree than its partner, e.g. a coarse body 2 under a finely meshed
    /// body 1 (mortar contact couples any two degrees).
    #[serde(default)]
    pub p: Option<usize>,
    /// Blocks (give these or `gmsh`).
    #[serde(default)]
    pub blocks: Vec<BlockSpec>,
    /// A mesh from Gmsh (give this or `blocks`).
    #[serde(default)]
    pub gmsh: Option<GmshSpec>,
    /// Supports.
    #[serde(default)]
    pub supports: Vec<SupportSpec>,
    /// Elastic supports.
    #[serde(default)]
    pub springs: Vec<SpringSpec>,
    /// Tractions.
    #[serde(default)]
    pub tractions: Vec<TractionSpec>,
}

/// `[probes.NAME]`: a point where results are reported.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeSpec {
    /// Body name.
    pub body: String,
    /// Point [x, z], mm.
    #[serde(deserialize_with = "exact::pair")]
    pub at: Point,
}

/// The whole problem file. Contact and wear sections are read by later stages.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProblemSpec {
    /// Short title.
    #[serde(default)]
    pub title: String,
    /// What the problem is and where its numbers come from.
    #[serde(default)]
    pub description: String,
    /// Analysis settings.
    pub analysis: AnalysisSpec,
    /// Materials by name.
    pub materials: BTreeMap<String, MaterialSpec>,
    /// Bodies.
    pub bodies: Vec<BodySpec>,
    /// Probes by name.
    #[serde(default)]
    pub probes: BTreeMap<String, ProbeSpec>,
    /// Contact settings (see [`crate::contact`]).
    pub contact: Option<crate::contact::ContactSpec>,
    /// Rigid loading plate (see [`crate::contact`]).
    pub plate: Option<crate::contact::PlateSpec>,
    /// Wear settings (see [`crate::wear`]).
    pub wear: Option<crate::wear::WearSpec>,
    /// Frictional heat, conduction and thermal distortion (see [`crate::heat_input`]).
    pub heat: Option<crate::heat_input::HeatSpec>,
    /// A tangential loading under which points stick or slip (see [`crate::fretting_input`]).
    pub fretting: Option<crate::fretting_input::FrettingSpec>,
    /// Output settings.
    pub output: Option<OutputSpec>,
}

/// `[output]`: optional outputs, each also available as a command-line flag.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Write ParaView files (`results.pvd`, `vtk/*.vtu`), as `--vtk` does. Default false.
    #[serde(default)]
    pub vtk: bool,
}

/// Fixed-length arrays read strictly: the TOML reader fills `[f64; 2]` from the first two
/// entries of a longer array and drops the rest, so `[x, z, junk]` would pass unnoticed.
pub mod exact {
    use serde::de::Error;
    use serde::{Deserialize, Deserializer};

    fn to_pair<E: Error>(values: &[f64]) -> Result<[f64; 2], E> {
        match values {
            [x, z] => Ok([*x, *z]),
            _ => Err(E::custom(format!(
                "expected two numbers [x, z], got {} ({values:?})",
                values.len()
            ))),
        }
    }

    /// Exactly two numbers.
    pub fn pair<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
        to_pair(&Vec::<f64>::deserialize(d)?)
    }

    /// Exactly two numbers, if present.
    pub fn optional_pair<'de, D: Deserializer<'de>>(d: D) -> Result<Option<[f64; 2]>, D::Error> {
        Option::<Vec<f64>>::deserialize(d)?
            .map(|v| to_pair(&v))
            .transpose()
    }

    /// Exactly four pairs.
    pub fn corners<'de, D: Deserializer<'de>>(d: D) -> Result<[[f64; 2]; 4], D::Error> {
        let corners = Vec::<Vec<f64>>::deserialize(d)?;
        if corners.len() != 4 {
            return Err(D::Error::custom(format!(
                "expected four corners [x, z], got {}",
                corners.len()
            )));
        }
        let mut out = [[0.0; 2]; 4];
        for (o, c) in out.iter_mut().zip(&corners) {
            *o = to_pair(c)?;
        }
        Ok(out)
    }
}
