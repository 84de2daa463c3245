//! The `[contact]` and `[plate]` sections of a problem file, as parsed (validated where the
//! contact problem is built).

use crate::geometry::Point;
use serde::Deserialize;

/// `[contact]` section of a problem file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// Body 1 (the punch, whose contact edge carries the contact points).
    pub body: String,
    /// Body 1's contact edge.
    pub edge: String,
    /// Body 2.
    pub target_body: String,
    /// Body 2's contact edge.
    pub target_edge: String,
    /// Coulomb friction coefficient μ (full slip), ≥ 0.
    #[serde(default)]
    pub friction: f64,
    /// Sliding direction of the first solve, "+" or "-" (friction on body 1 is s μ p τ).
    #[serde(default = "plus")]
    pub direction: String,
    /// "active_set" (default; Lemke fallback), "lemke" or "penalty".
    #[serde(default = "active_set")]
    pub method: String,
    /// Penalty parameter c_n (MPa/mm) for method = "penalty".
    pub penalty: Option<f64>,
    /// Optional circular initial shape of body 1: gap g = R − √(R² − (x − x₀)²).
    pub initial_shape: Option<CircleShape>,
    /// "mortar" (default; body 2 weighted over the overlapping segments, any meshes) or
    /// "collocation" (one partner point per contact point; needs matching mesh lines).
    #[serde(default = "mortar")]
    pub discretisation: String,
    /// Add mesh lines to body 2 where the normal lines through body 1's element ends on the
    /// contact edge cross body 2's contact edge (default true; see
    /// [`crate::mesh::Mesh::aligned_to`]). False keeps body 2's mesh as given.
    #[serde(default = "yes")]
    pub align_target_mesh: bool,
}

/// A circular initial gap (a cylinder of radius `radius` mm touching at x = `center_x`).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CircleShape {
    /// Radius R, mm.
    pub radius: f64,
    /// x₀ of the lowest point, mm.
    pub center_x: f64,
}

fn plus() -> String {
    "+".into()
}
fn active_set() -> String {
    "active_set".into()
}
fn yes() -> bool {
    true
}
fn mortar() -> String {
    "mortar".into()
}

/// `[plate]`: the rigid loading plate clamped to an edge of body 1.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlateSpec {
    /// Edge of body 1 clamped to the plate; tractions on it load the plate.
    pub edge: String,
    /// "fixed", "vertical" (λ_F) or "vertical_rotation" (λ_F, λ_M about `pin`).
    pub motion: String,
    /// Pin [x, z] (mm), needed for rotation; moments are taken about it.
    #[serde(default, deserialize_with = "crate::schema::exact::optional_pair")]
    pub pin: Option<Point>,
}
