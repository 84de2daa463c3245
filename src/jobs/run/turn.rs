//! What a run of bodies of revolution turning about their axis says of the turn: the angle
//! and revolutions turned, the friction torque about the axis and the power it dissipates
//! (summary.json's `turn`, history.csv's `torque_Nmm`).

use super::WearRun;
use crate::report::json::number;
use crate::wear::AxisRotation;
use serde_json::{json, Value};

impl WearRun {
    /// summary.json's `turn`: `omega` the angular speed (rad/s; the peak of a turn to and
    /// fro), `units` the half periods (step units) run.
    pub(super) fn turn_json(&self, turn: &AxisRotation, omega: f64, units: usize) -> Value {
        let angle = units as f64 * self.sliding_per_half_period;
        let torque = self.history.steps.last().and_then(|s| s.torque);
        let outer = turn.radius.iter().fold(0.0f64, |a, &r| a.max(r));
        json!({
            "friction": number(turn.friction),
            "angle_rad": number(angle),
            "revolutions": number(angle / std::f64::consts::TAU),
            "sliding_distance_at_outer_radius_m": number(angle * outer / 1000.0),
            "torque_Nmm": torque.map(number),
            // T ω in N·mm/s = mW.
            "power_W": torque.map(|t| number(t * omega / 1000.0)),
            "power_at": if self.monotonic { "constant angular speed" } else { "peak angular speed θ₀ω" },
        })
    }

    /// The console's words for the duration of a turn: the angle in revolutions.
    pub(super) fn turn_words(&self, units: usize) -> Option<String> {
        let (_, omega) = self.turn.as_ref()?;
        let revolutions = units as f64 * self.sliding_per_half_period / std::f64::consts::TAU;
        let torque = self.history.steps.last().and_then(|s| s.torque)?;
        Some(format!(
            "{revolutions:.1} revolutions; torque {:.4} N·m, {:.4} W",
            torque / 1000.0,
            torque * omega / 1000.0
        ))
    }
}
