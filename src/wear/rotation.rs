//! Bodies of revolution turning about their axis (thrust washers, clutch facings, face seals,
//! a rotating punch): each contact point slides circumferentially at ω r, so its wear per
//! half period (or step) is the plane law's with the sliding scaled by rᵃ:
//! Δw = β̃ pᵇ ∫|ω r|ᵃ dτ = rᵃ · β̃ pᵇ ∫|ω|ᵃ dτ.
//!
//! The friction shear μ p is circumferential: it leaves the (r, z) problem untouched (the
//! contact stage solves it frictionless, [`crate::contact::CondensedContact::friction`]) and
//! sets the torque T = ∫ μ p r dA about the axis and the power ω T the friction dissipates.
//!
//! A contact point on the axis stands for the disc of radius ρ about it
//! ([`crate::contact::AxisPoint`], area πρ²): its sliding is the disc's mean,
//! (1/πρ²) ∫₀^ρ rᵃ 2πr dr = 2ρᵃ/(a + 2).

use super::WearSpec;
use crate::contact::CondensedContact;

/// Where each contact point lies from the axis, for the sliding of a turn about it.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisRotation {
    /// Radius r of each contact point, mm (0 on the axis).
    pub radius: Vec<f64>,
    /// For a point on the axis, the radius ρ of the disc it stands for (mm); None elsewhere.
    disc: Vec<Option<f64>>,
    /// Circumferential friction coefficient μ.
    pub friction: f64,
}

impl AxisRotation {
    /// The turn of `contact`'s bodies about their axis, with friction coefficient
    /// `friction` (μ of the circumferential shear).
    pub fn new(contact: &CondensedContact, friction: f64) -> AxisRotation {
        let radius: Vec<f64> = contact.points.x.iter().map(|x| x[0].max(0.0)).collect();
        let mut disc = vec![None; radius.len()];
        for axis in &contact.axis_points {
            let area = contact.points.weight[axis.point];
            disc[axis.point] = Some((area / std::f64::consts::PI).sqrt());
        }
        // A point on the axis with too few neighbours for the axis pressure is still a disc
        // (its area is πρ², [`crate::contact`]).
        let size = radius.iter().fold(0.0f64, |a, &r| a.max(r));
        for (i, d) in disc.iter_mut().enumerate() {
            if d.is_none() && crate::material::on_axis(radius[i], size) {
                *d = Some((contact.points.weight[i] / std::f64::consts::PI).sqrt());
            }
        }
        AxisRotation {
            radius,
            disc,
            friction,
        }
    }

    /// The factor rᵃ by which point `i`'s sliding integral exceeds that of a point at 1 mm
    /// (mm^a): the disc's mean 2ρᵃ/(a + 2) on the axis.
    pub fn factor(&self, i: usize, a: f64) -> f64 {
        match self.disc[i] {
            Some(rho) => 2.0 * rho.powf(a) / (a + 2.0),
            None if a == 1.0 => self.radius[i],
            None => self.radius[i].powf(a),
        }
    }

    /// The factors of every point for velocity exponent `a`.
    pub fn factors(&self, a: f64) -> Vec<f64> {
        (0..self.radius.len()).map(|i| self.factor(i, a)).collect()
    }

    /// The friction torque about the axis, T = Σ μ p_i r_i A_i (N·mm), at pressures
    /// `pressure` (MPa) on the contact areas `area` (mm², whole rings). On the axis the disc's
    /// mean radius 2ρ/3.
    pub fn torque(&self, pressure: &[f64], area: &[f64]) -> f64 {
        pressure
            .iter()
            .zip(area)
            .enumerate()
            .map(|(i, (p, a))| self.friction * p.max(0.0) * a * self.factor(i, 1.0))
            .sum()
    }
}

impl WearSpec {
    /// Whether the bodies turn about their axis (`angular_speed` or `angle` given).
    pub fn turns_about_axis(&self) -> bool {
        self.angular_speed.is_some() || self.angle.is_some()
    }

    /// The sliding's amplitude and speed as the kinematics use them: u₀ (mm) and v (mm/s),
    /// or for a turn about the axis θ₀ (rad) and ω (rad/s), the sliding of a point at 1 mm.
    pub fn sliding_scale(&self) -> (f64, f64) {
        if self.turns_about_axis() {
            (self.angle.unwrap_or(0.0), self.angular_speed.unwrap_or(0.0))
        } else {
            (self.amplitude, self.speed)
        }
    }

    /// A turn's keys against the plane sliding's: `angle` (rad) replaces `amplitude`,
    /// `angular_speed` (rad/s) replaces `speed`, each belongs to its own kind of sliding, and a
    /// turn has no sliding distance (it is ω r: it depends on the radius). The error names the
    /// key.
    pub fn check_turn(&self) -> Result<(), (String, String)> {
        let bad = |k: &str, m: &str| Err((format!("wear.{k}"), m.to_string()));
        if !self.turns_about_axis() {
            return Ok(());
        }
        let monotonic = self.sliding == "monotonic";
        if self.angle.is_some() && monotonic {
            return bad("angle", "is the amplitude of a turn to and fro (sliding = \"reciprocating\"); a turn one way gives angular_speed (rad/s)");
        }
        if self.angular_speed.is_some() && !monotonic {
            return bad("angular_speed", "is the speed of a turn one way (sliding = \"monotonic\"); a turn to and fro gives angle (rad) and omega (rad/s)");
        }
        if self.amplitude != 0.0 {
            return bad(
                "amplitude",
                "a turn about the axis gives its amplitude as angle (rad); remove amplitude",
            );
        }
        if self.speed != 0.0 {
            return bad(
                "speed",
                "a turn about the axis gives its speed as angular_speed (rad/s); remove speed",
            );
        }
        if self.distance.is_some() {
            return bad("distance", "a turn's sliding distance depends on the radius (ω r): give its duration as steps, cycles or time (s)");
        }
        if !self.record_distance.is_empty() {
            return bad("record_distance", "a turn's sliding distance depends on the radius (ω r): record by record_time (s), record_cycles or record (steps)");
        }
        Ok(())
    }
}
