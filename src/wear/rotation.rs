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
