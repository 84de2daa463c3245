//! The `[fretting]` section of a problem file: a tangential loading of the pressed contact by
//! a force or a displacement oscillating about zero, under which each contact point sticks or
//! slips (Coulomb friction with stick), and the validated [`FrettingSettings`] the fretting
//! jobs take.
//!
//! A problem is a fretting problem when it has a `[fretting]` section; without one nothing of
//! this module runs and every contact solve is full slip, as before.
//!
//! **Units.** `amplitude` is the force amplitude Q₀ in N (on body 1's plate, per the
//! analysis thickness like every force) under `loading = "force"`, or the displacement
//! amplitude δ₀ in mm (the plate's shift against body 2's supports) under
//! `loading = "displacement"`. The wear of a fretting run follows the `[wear]` laws
//! ẇ = β̃ pᵇ |ṡ|ᵃ with ṡ each point's own slip rate; `wear.omega` (rad/s) is the cycle's
//! angular frequency, `wear.cycles` its duration.

use crate::fretting::{FrettingControl, FrettingLoading};
use crate::problem::{Problem, ProblemError};
use crate::wear::WearLaw;
use serde::Deserialize;

/// Most stages per half cycle: far beyond what the loop needs (16 draw it to 1 %).
pub const MAX_STAGES: usize = 1000;

/// Most cycles a fretting run may cover (10¹⁰: a joint's life at 100 Hz for three years).
pub const MAX_CYCLES: f64 = 1e10;

/// `[fretting]`: the tangential loading of a pressed contact.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrettingSpec {
    /// "force" (Q(t) = Q₀ cos ωt on body 1's plate) or "displacement" (δ(t) = δ₀ cos ωt,
    /// the plate's shift against body 2's supports).
    pub loading: String,
    /// Q₀ in N (force) or δ₀ in mm (displacement), > 0.
    pub amplitude: Option<f64>,
    /// Stages per half cycle (default 16): the loop's resolution.
    #[serde(default = "sixteen")]
    pub stages: usize,
    /// The local error allowed in a jump over many cycles, percent of the jump's wear
    /// (default 1).
    #[serde(default = "one")]
    pub tolerance: f64,
    /// Whether the tangential forces act back on the pressure and the plate (true: exact;
    /// false: Cattaneo's uncoupled problem, the normal forces held, exact for two bodies of
    /// one material in the half-space limit). Default: coupled when the two bodies' materials
    /// differ (Dundurs' β ≠ 0), uncoupled when they are one material.
    pub coupled: Option<bool>,
}

fn sixteen() -> usize {
    16
}

fn one() -> f64 {
    1.0
}

/// The validated fretting settings.
#[derive(Clone, Debug, PartialEq)]
pub struct FrettingSettings {
    /// The tangential loading.
    pub loading: FrettingLoading,
    /// Coulomb's μ (from `contact.friction`), > 0.
    pub friction: f64,
    /// Relative local error allowed in a jump over many cycles.
    pub tolerance: f64,
    /// The coupled problem (the tangential forces act on the pressure and the plate).
    pub coupled: bool,
    /// The wear of a run, when the problem has a `[wear]` section.
    pub wear: Option<FrettingWearSettings>,
}

/// The wear of a fretting run.
#[derive(Clone, Debug, PartialEq)]
pub struct FrettingWearSettings {
    /// Each wearing body (0 or 1) and its law.
    pub laws: Vec<(usize, WearLaw)>,
    /// The cycle's angular frequency ω, rad/s (1 when every a = 1 and none is given: the
    /// wear does not depend on it then).
    pub omega: f64,
    /// Cycles to run.
    pub cycles: f64,
    /// Cycles after which the profiles are recorded.
    pub record_cycles: Vec<f64>,
    /// Most Newton iterations of an implicit step (b ≠ 1).
    pub max_iterations: usize,
    /// Relative tolerance of the linearised wear in an implicit step (b ≠ 1).
    pub newton_tolerance: f64,
}

/// `[wear]` keys of reciprocating or monotonic sliding that a fretting run has no use for:
/// its slip is computed, and its duration is `wear.cycles`.
const SLIDING_KEYS: [&str; 12] = [
    "amplitude",
    "speed",
    "angle",
    "angular_speed",
    "step_time",
    "steps",
    "distance",
    "time",
    "extrapolation",
    "adaptive",
    "record_distance",
    "record_time",
];

impl Problem {
    /// The validated `[fretting]` settings, None without the section.
    pub fn fretting_settings(&self) -> Result<Option<FrettingSettings>, ProblemError> {
        let Some(spec) = &self.spec.fretting else {
            return Ok(None);
        };
        let control = match spec.loading.as_str() {
            "force" => FrettingControl::Force,
            "displacement" => FrettingControl::Displacement,
            other => {
                return Err(self.error(
                    "fretting.loading",
                    format!("must be \"force\" (Q₀ cos ωt on body 1's plate) or \"displacement\" (δ₀ cos ωt, the plate's shift), got \"{other}\""),
                ))
            }
        };
        let unit = match control {
            FrettingControl::Force => "Q₀ in N, the tangential force's amplitude on body 1's plate",
            FrettingControl::Displacement => {
                "δ₀ in mm, the amplitude of the plate's shift against body 2's supports"
            }
        };
        let amplitude = match spec.amplitude {
            Some(v) if v.is_finite() && v > 0.0 && v < 1e12 => v,
            Some(v) => {
                return Err(self.error(
                    "fretting.amplitude",
                    format!("must be positive ({unit}), got {v}"),
                ))
            }
            None => {
                return Err(self.error("fretting.amplitude", format!("is missing: give {unit}")))
            }
        };
        if !(1..=MAX_STAGES).contains(&spec.stages) {
            return Err(self.error(
                "fretting.stages",
                format!(
                    "must be from 1 to {MAX_STAGES} (stages per half cycle), got {}",
                    spec.stages
                ),
            ));
        }
        if !(spec.tolerance.is_finite() && spec.tolerance > 0.0 && spec.tolerance <= 50.0) {
            return Err(self.error(
                "fretting.tolerance",
                format!(
                    "must lie in (0, 50] (percent of a jump's wear), got {}",
                    spec.tolerance
                ),
            ));
        }
        let coupled = spec
            .coupled
            .unwrap_or_else(|| !self.one_material_in_contact());
        self.check_fretting_model(control, coupled)?;
        let friction = self.spec.contact.as_ref().map_or(0.0, |c| c.friction);
        if friction <= 0.0 {
            return Err(self.error(
                "contact.friction",
                "is 0 (or missing) in a fretting problem: without friction nothing sticks and no tangential load is carried; give Coulomb's μ > 0",
            ));
        }
        Ok(Some(FrettingSettings {
            loading: FrettingLoading {
                control,
                amplitude,
                stages: spec.stages,
            },
            friction,
            tolerance: spec.tolerance / 100.0,
            coupled,
            wear: self.fretting_wear()?,
        }))
    }

    /// What the fretting model needs of the rest of the problem: a plate that translates or is
    /// held, a plane analysis, one fixed contact without heat.
    fn check_fretting_model(
        &self,
        control: FrettingControl,
        coupled: bool,
    ) -> Result<(), ProblemError> {
        if self.analysis.is_axisymmetric() {
            return Err(self.error("fretting", "fretting of bodies of revolution is not built: an axisymmetric contact's tangential loading (a torsion or an axial shift) needs the tangential problem in (r, z, θ); use a plane analysis"));
        }
        if self.spec.heat.is_some() {
            return Err(self.error("heat", "frictional heat in fretting is not built: remove [heat] (the heat of a fretting cycle is small: μ p |ṡ| over a slip of micrometres)"));
        }
        let contact = self.spec.contact.as_ref();
        if contact.is_some_and(|c| c.pairs != "fixed") {
            return Err(self.error("contact.pairs", "sliding pairs (a finite stroke) and fretting exclude each other: fretting's slip is micrometres at fixed partners"));
        }
        let Some(plate) = &self.spec.plate else {
            return Err(self.error("plate", "fretting needs a [plate] on body 1: its shift against body 2's supports (or the force on it) is the tangential loading"));
        };
        match (plate.motion.as_str(), control) {
            ("vertical", _) | ("fixed", FrettingControl::Displacement) => Ok(()),
            ("vertical_rotation", _) if coupled => Ok(()),
            ("vertical_rotation", _) => Err(self.error("plate.motion", "is \"vertical_rotation\" and the fretting problem is uncoupled (fretting.coupled = false, as given or as the default for bodies of one material): a plate that rotates turns under the tangential force, which only the coupled problem carries; set fretting.coupled = true")),
            ("fixed", FrettingControl::Force) => Err(self.error("plate.motion", "is \"fixed\" and the fretting loading is a force: a held plate takes the force itself and nothing reaches the contact. Give plate.motion = \"vertical\" (the plate then shifts under the force), or fretting.loading = \"displacement\" (the held plate's shift)")),
            (other, _) => Err(self.error("plate.motion", format!("must be \"vertical\", \"vertical_rotation\" or \"fixed\", got \"{other}\""))),
        }
    }

    /// Whether the two contact bodies are of one elastic material (every block of both names
    /// materials of the same E and ν; a Gmsh body counts as not).
    fn one_material_in_contact(&self) -> bool {
        let Some(contact) = &self.spec.contact else {
            return false;
        };
        let names: Vec<String> = self.spec.materials.keys().cloned().collect();
        let mut constants = Vec::new();
        for body in [&contact.body, &contact.target_body] {
            let Some(spec) = self.spec.bodies.iter().find(|b| &b.name == body) else {
                return false;
            };
            if spec.gmsh.is_some() {
                return false;
            }
            for block in &spec.blocks {
                match names.iter().position(|n| n == &block.material) {
                    Some(m) => constants.push((self.materials[m].young, self.materials[m].poisson)),
                    None => return false,
                }
            }
        }
        constants.windows(2).all(|w| w[0] == w[1])
    }

    /// The wear of a fretting run from `[wear]`: the laws, ω and the duration in cycles.
    fn fretting_wear(&self) -> Result<Option<FrettingWearSettings>, ProblemError> {
        let Some(wear) = &self.spec.wear else {
            return Ok(None);
        };
        let given = serde_json::to_value(wear).unwrap_or_default();
        for key in SLIDING_KEYS {
            let value = &given[key];
            let set = match value {
                serde_json::Value::Null => false,
                serde_json::Value::Number(v) => v.as_f64() != Some(0.0),
                serde_json::Value::Array(v) => !v.is_empty(),
                _ => true,
            };
            if set {
                return Err(self.error(format!("wear.{key}"), "does not apply to fretting: each point's slip comes from the tangential loading ([fretting]), and the run's duration is wear.cycles"));
            }
        }
        if wear.sliding != "reciprocating" {
            return Err(self.error(
                "wear.sliding",
                format!(
                    "is \"{}\": fretting is an oscillation (leave the key out)",
                    wear.sliding
                ),
            ));
        }
        if wear.scheme != "implicit" {
            return Err(self.error("wear.scheme", "a fretting run takes implicit steps only (the fixed-point scheme is the paper's, for its sliding)"));
        }
        if !wear.record.is_empty() || wear.shape_zero_at.is_some() || wear.substeps != 0 {
            let key = if !wear.record.is_empty() {
                "record"
            } else if wear.shape_zero_at.is_some() {
                "shape_zero_at"
            } else {
                "substeps"
            };
            return Err(self.error(
                format!("wear.{key}"),
                "does not apply to fretting (its records are wear.record_cycles)",
            ));
        }
        let mut laws = Vec::new();
        for (body, (name, law)) in [("body1", wear.body1), ("body2", wear.body2)]
            .into_iter()
            .enumerate()
        {
            let Some(law) = law else { continue };
            if !(law.beta.is_finite() && law.beta >= 0.0) {
                return Err(self.error(
                    format!("wear.{name}.beta"),
                    format!("must be ≥ 0, got {}", law.beta),
                ));
            }
            if !(law.a > 0.0 && law.a <= 10.0 && law.b > 0.0 && law.b <= 10.0) {
                return Err(self.error(
                    format!("wear.{name}"),
                    format!(
                        "exponents a and b must lie in (0, 10], got a = {}, b = {}",
                        law.a, law.b
                    ),
                ));
            }
            if law.beta > 0.0 {
                laws.push((body, law));
            }
        }
        let needs_omega = laws.iter().any(|(_, l)| l.a != 1.0);
        let omega = if wear.omega > 0.0 && wear.omega.is_finite() {
            wear.omega
        } else if wear.omega == 0.0 && !needs_omega {
            1.0
        } else {
            return Err(self.error(
                "wear.omega",
                format!(
                    "must be the fretting cycle's angular frequency ω > 0 (rad/s){}, got {}",
                    if needs_omega {
                        ", which a velocity exponent a ≠ 1 needs"
                    } else {
                        ""
                    },
                    wear.omega
                ),
            ));
        };
        let cycles = match wear.cycles {
            Some(c) if (1.0..=MAX_CYCLES).contains(&c) => c.round(),
            Some(c) => {
                return Err(self.error(
                    "wear.cycles",
                    format!("must be from 1 to {MAX_CYCLES:e} (cycles of fretting), got {c}"),
                ))
            }
            None => {
                return Err(self.error(
                    "wear.cycles",
                    "is missing: a fretting run's duration is its number of cycles",
                ))
            }
        };
        let mut record_cycles = wear.record_cycles.clone();
        if let Some(bad) = record_cycles
            .iter()
            .find(|c| !(c.is_finite() && **c >= 1.0))
        {
            return Err(self.error(
                "wear.record_cycles",
                format!("each must be a cycle count ≥ 1, got {bad}"),
            ));
        }
        record_cycles.sort_by(f64::total_cmp);
        record_cycles.dedup();
        if !(1..=1000).contains(&wear.max_iterations) {
            return Err(self.error(
                "wear.max_iterations",
                format!("must be from 1 to 1000, got {}", wear.max_iterations),
            ));
        }
        if !(wear.tolerance.is_finite() && wear.tolerance > 0.0) {
            return Err(self.error(
                "wear.tolerance",
                format!("must be positive (percent), got {}", wear.tolerance),
            ));
        }
        Ok(Some(FrettingWearSettings {
            laws,
            omega,
            cycles,
            record_cycles: record_cycles.iter().map(|c| c.round()).collect(),
            max_iterations: wear.max_iterations,
            newton_tolerance: wear.tolerance / 100.0,
        }))
    }
}
