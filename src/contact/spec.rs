//! The `[contact]` and `[plate]` sections of a problem file, as parsed, and the checks of
//! what they name and set. [`check_settings`] runs the checks that need no assembly, so that
//! a study can refuse a bad variant before it solves any; the checks that need the contact
//! points (a point without a partner, a crown on an inclined edge) run where the contact
//! problem is built.

use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};
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
    /// "fixed" (default; the paper's model: each contact point of body 1 always faces the same
    /// point of body 2) or "sliding" (body 2 moves along its track under body 1, and wears
    /// where the stroke brings it; [`crate::contact::track`]).
    #[serde(default = "fixed")]
    pub pairs: String,
    /// Sliding pairs: positions of the stroke resolved per half period (default: enough for
    /// steps of at most 1/16 of body 1's contact edge, at least 4; see
    /// [`crate::contact::track::default_positions`]).
    pub positions: Option<usize>,
    /// How the bodies slide: "in_plane" (default; along the contact edge, friction in the
    /// plane of the section) or "about_axis" (bodies of revolution turning about their axis:
    /// friction is circumferential, out of the (r, z) plane, and sets only the torque).
    #[serde(default = "in_plane")]
    pub sliding_motion: String,
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
impl ContactSpec {
    /// Whether body 2's mesh gets lines under body 1's element ends: with fixed pairs, as
    /// `align_target_mesh` says; never with sliding pairs, where body 2 moves under body 1
    /// (lines under its ends at rest would only break the track's evenness: on a ring, the
    /// positions' equality, and with it the evenness of its wear).
    pub fn aligns_target_mesh(&self) -> bool {
        self.align_target_mesh && self.pairs != "sliding"
    }
}

fn in_plane() -> String {
    "in_plane".into()
}
fn fixed() -> String {
    "fixed".into()
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

/// What `[contact]` and `[plate]` name or set, checked on the meshes alone (nothing is
/// assembled): the bodies, edges, friction, discretisation and plate that
/// [`crate::contact::CondensedContact::build`] would refuse, with the same messages.
pub fn check_settings(problem: &Problem) -> Result<(), ProblemError> {
    let (c, b1, b2) = contact_section(problem)?;
    check_plate_edge(problem, c)?;
    match c.discretisation.as_str() {
        "mortar" => {}
        "collocation" => check_collocation_degrees(
            problem,
            problem.body_discretisation(b1).p,
            problem.body_discretisation(b2).p,
        )?,
        other => return Err(unknown_discretisation(problem, other)),
    }
    // The meshes as given: the lines added to body 2 under body 1's element ends change no
    // edge's name or whether it lies on the boundary, and would cost three more mesh builds.
    let mesh1 = problem.mesh_as_given(b1)?;
    problem.named_edge(&mesh1, b1, &c.edge, "contact.edge")?;
    let mesh2 = problem.mesh_as_given(b2)?;
    problem.named_edge(&mesh2, b2, &c.target_edge, "contact.target_edge")?;
    if let Some(plate) = &problem.spec.plate {
        problem.named_edge(&mesh1, b1, &plate.edge, "plate.edge")?;
        check_plate(problem, plate)?;
    }
    Ok(())
}

/// Most positions per half period accepted for sliding pairs: each is a condensed contact
/// problem of its own (N² numbers), so 400 of them at 513 points would hold 1.7 GB.
pub const MAX_POSITIONS: usize = 400;

/// `contact.pairs` and what the sliding model cannot be combined with (yet).
fn check_pairs(problem: &Problem, c: &ContactSpec) -> Result<(), ProblemError> {
    match c.pairs.as_str() {
        "fixed" => {
            if c.positions.is_some() {
                return Err(problem.error(
                    "contact.positions",
                    "sets the positions along the stroke of sliding pairs; with contact.pairs = \"fixed\" (the default) there are none: remove it or set pairs = \"sliding\"",
                ));
            }
            Ok(())
        }
        "sliding" => check_sliding(problem, c),
        other => Err(problem.error(
            "contact.pairs",
            format!("must be \"fixed\" or \"sliding\", got \"{other}\""),
        )),
    }
}

/// What sliding pairs need: mortar traces (body 2 meets body 1 anywhere along its track),
/// reciprocating sliding, the implicit scheme on a fixed schedule, and no heat.
fn check_sliding(problem: &Problem, c: &ContactSpec) -> Result<(), ProblemError> {
    let needs_fixed = |key: &str, why: &str| {
        problem.error(
            key,
            format!("is not available with contact.pairs = \"sliding\": {why}"),
        )
    };
    if c.discretisation != "mortar" {
        return Err(needs_fixed(
            "contact.discretisation",
            "\"collocation\" pairs each contact point with one point of body 2 for good; sliding pairs need \"mortar\", which couples body 1's points with whatever part of body 2 the stroke brings under them",
        ));
    }
    if let Some(m) = c.positions {
        if !(1..=MAX_POSITIONS).contains(&m) {
            return Err(problem.error(
                "contact.positions",
                format!("must lie from 1 to {MAX_POSITIONS}, got {m}"),
            ));
        }
    }
    if problem.spec.heat.is_some() {
        return Err(needs_fixed(
            "heat",
            "the frictional heat of a moving slider (a moving source on body 2's track) is not built yet; use fixed pairs for heat",
        ));
    }
    let Some(w) = &problem.spec.wear else {
        return Ok(());
    };
    if w.adaptive.is_some() {
        return Err(needs_fixed(
            "wear.adaptive",
            "the error-controlled schedule measures the fixed pairs' half-period wear; give a schedule (wear.extrapolation) instead",
        ));
    }
    if w.scheme != "implicit" {
        return Err(needs_fixed(
            "wear.scheme",
            "sliding pairs integrate each position implicitly; the paper's fixed-point iteration is for fixed pairs",
        ));
    }
    if w.substeps != 0 {
        return Err(needs_fixed(
            "wear.substeps",
            "sliding pairs resolve the half period into positions along the stroke (contact.positions) instead",
        ));
    }
    if w.shape_zero_at.is_some() {
        return Err(needs_fixed(
            "wear.shape_zero_at",
            "body 2's track is its own profile, which a shift of body 1 cannot zero",
        ));
    }
    Ok(())
}

/// Largest Coulomb coefficient accepted.
pub const MAX_FRICTION: f64 = 10.0;

/// The contact section and the indices of body 1 and body 2, checked.
pub(super) fn contact_section(
    problem: &Problem,
) -> Result<(&ContactSpec, usize, usize), ProblemError> {
    let c = problem
        .spec
        .contact
        .as_ref()
        .ok_or_else(|| problem.error("contact", "this problem has no [contact] section"))?;
    match c.sliding_motion.as_str() {
        "in_plane" => {}
        "about_axis" if problem.analysis.is_axisymmetric() => {}
        "about_axis" => {
            return Err(problem.error(
                "contact.sliding_motion",
                "\"about_axis\" is a turn of bodies of revolution about their axis, and this analysis is plane; give analysis.kind = \"axisymmetric\" or \"in_plane\"",
            ))
        }
        other => {
            return Err(problem.error(
                "contact.sliding_motion",
                format!("must be \"in_plane\" or \"about_axis\", got \"{other}\""),
            ))
        }
    }
    if problem.analysis.is_axisymmetric() {
        check_axisymmetric(problem, c)?;
    }
    // Measured dry friction stays below about 2 (clean metals in vacuum, rubber); 10 leaves
    // room for any model while refusing values like 1e300, whose failing solves took 7–41 s
    // before exit 1 (red team 19).
    if !(c.friction.is_finite() && (0.0..=MAX_FRICTION).contains(&c.friction)) {
        return Err(problem.error(
            "contact.friction",
            format!("must lie from 0 to {MAX_FRICTION}, got {:?}", c.friction),
        ));
    }
    let b1 = problem
        .body_index(&c.body)
        .map_err(|_| problem.error("contact.body", format!("no body named \"{}\"", c.body)))?;
    let b2 = problem.body_index(&c.target_body).map_err(|_| {
        problem.error(
            "contact.target_body",
            format!("no body named \"{}\"", c.target_body),
        )
    })?;
    if b1 == b2 {
        return Err(problem.error("contact.target_body", "must differ from contact.body"));
    }
    // Every job reads the contact section here: a misspelt `pairs` must not run fixed pairs
    // in silence (review of 2026-11-29: "Sliding" and "slide" did, exit 0).
    check_pairs(problem, c)?;
    if problem.spec.plate.is_some() && !problem.spec.bodies[b1].supports.is_empty() {
        // The plate equilibrium counts every load on body 1; a support would take some.
        return Err(problem.error(
            format!("bodies[{b1}].supports"),
            "body 1 is held by the [plate]; it may not have supports of its own",
        ));
    }
    Ok((c, b1, b2))
}

/// The plate may not clamp the contact edge.
pub(super) fn check_plate_edge(problem: &Problem, c: &ContactSpec) -> Result<(), ProblemError> {
    if problem
        .spec
        .plate
        .as_ref()
        .is_some_and(|p| p.edge == c.edge)
    {
        return Err(problem.error(
            "plate.edge",
            "must differ from contact.edge: the plate clamps its edge, the contact edge must be free to deform",
        ));
    }
    Ok(())
}

pub(super) fn unknown_discretisation(problem: &Problem, other: &str) -> ProblemError {
    problem.error(
        "contact.discretisation",
        format!("must be \"mortar\" or \"collocation\", got \"{other}\""),
    )
}

/// Collocation needs both bodies at the same degree.
pub(super) fn check_collocation_degrees(
    problem: &Problem,
    p1: usize,
    p2: usize,
) -> Result<(), ProblemError> {
    if p1 != p2 {
        // One point partner per contact point samples body 2's trace; on a richer trace than
        // body 1's the point forces raise a ripple at every element vertex (p₂ = 12 against
        // p₁ = 8: 16 % of the pressure, review of 2026-11-24).
        return Err(problem.error(
            "contact.discretisation",
            format!("\"collocation\" needs both bodies at the same degree (body 1 has p = {p1}, body 2 p = {p2}); use the default \"mortar\", which couples any two degrees"),
        ));
    }
    Ok(())
}

pub(super) fn unknown_motion(problem: &Problem, other: &str) -> ProblemError {
    problem.error(
        "plate.motion",
        format!("must be \"fixed\", \"vertical\" or \"vertical_rotation\", got \"{other}\""),
    )
}

/// Bodies of revolution sliding in the (r, z) plane (`contact.sliding_motion = "in_plane"`)
/// slide along the contact edge's tangent, which must then run along the axis (a pin or a
/// ring in a bore): along a face (a radial tangent) the slip would be outwards or inwards all
/// round, which no motion makes (a review: a ball on an aluminium flat pressed 25 % less or
/// 34 % more at its centre with μ = 0.5, in silence). `tangents` are the contact points'
/// unit tangents; `what` names the friction or the wear that needs the sliding, for the
/// message (key `contact.friction` or `contact.sliding_motion`).
pub(super) fn along_axis_friction(
    problem: &Problem,
    tangents: &[crate::geometry::Point],
    key: &str,
    what: &str,
) -> Result<(), ProblemError> {
    // The same tolerance as "on the axis": 1e-6 of the direction.
    if let Some(t) = tangents
        .iter()
        .find(|t| t[0].abs() > crate::material::AXIS_TOLERANCE)
    {
        return Err(problem.error(
            key,
            format!("{what} of bodies of revolution in the (r, z) plane acts along the contact edge, which must then run along the axis (a pin or a ring in a bore, sliding along it); this edge runs across it (a tangent ({:.3}, {:.3})), where the slip would be outwards or inwards all round, which no motion makes. Give 0 friction for a face pressed along the axis, or contact.sliding_motion = \"about_axis\" for bodies turning about their axis", t[0], t[1]),
        ));
    }
    Ok(())
}

/// The plate's motion is one of the three, and a rotation has a pin within range.
pub(super) fn check_plate(problem: &Problem, plate: &PlateSpec) -> Result<(), ProblemError> {
    if !matches!(
        plate.motion.as_str(),
        "fixed" | "vertical" | "vertical_rotation"
    ) {
        return Err(unknown_motion(problem, &plate.motion));
    }
    match plate.pin {
        None if plate.motion == "vertical_rotation" => {
            Err(problem.error("plate.pin", "rotation needs a pin [x, z]"))
        }
        Some(p) if !p.iter().all(|c| c.abs() <= crate::problem::MAX_COORDINATE) => {
            Err(problem.error("plate.pin", "must be coordinates [x, z] within ±1e6 mm"))
        }
        _ => Ok(()),
    }
}

/// What contact between bodies of revolution supports so far (issue 31, built in steps): the
/// contact solve with the plate translating along the axis or held, frictionless, turning
/// about the axis (`contact.sliding_motion = "about_axis"`, whose friction is
/// circumferential) or sliding along it on a contact edge along the axis
/// ([`along_axis_friction`]), and the wear of both. A plate that turns is not axisymmetric;
/// heat and sliding pairs of bodies of revolution are not built yet.
fn check_axisymmetric(problem: &Problem, c: &ContactSpec) -> Result<(), ProblemError> {
    if let Some(plate) = &problem.spec.plate {
        if plate.motion != "vertical" && plate.motion != "fixed" {
            return Err(problem.error(
                "plate.motion",
                format!("\"{}\": a body of revolution's plate can only translate along the axis (\"vertical\") or be held (\"fixed\"); a turn of the plate is not axisymmetric", plate.motion),
            ));
        }
    }
    if c.pairs == "sliding" {
        return Err(problem.error(
            "contact.pairs",
            "sliding pairs of bodies of revolution are not built yet",
        ));
    }
    if problem.spec.heat.is_some() {
        return Err(problem.error("heat", "heat in bodies of revolution is not built yet"));
    }
    Ok(())
}
