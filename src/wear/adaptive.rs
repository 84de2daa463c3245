//! Error-controlled extrapolation: the factor k (half periods per step) chosen from a local
//! error estimate instead of a fixed schedule.
//!
//! A step holds the wear rate at its end-of-step value for k half periods (backward Euler in
//! the worn shape), so its local error is about half the change across the step. The
//! estimate is measured where it matters, in the pressure:
//!
//! e ≈ ½ max_i |p_i − p_i,before|,
//!
//! with p_before the pressure of the last step in the same direction. The allowed e is
//! `tolerance` times the largest pressure of the first solve. After every full cycle k moves
//! on a ladder of powers of two: halved when the cycle's largest e exceeds the allowance,
//! doubled when it is below 0.4 of it (both half cycles of a cycle share one k, so that a
//! cycle stays symmetric, and a factorisation made for one k is reused whenever the run comes
//! back to it).
//!
//! The run stops when the steady state is reached. A slow transient changes the pressures by
//! less and less per cycle, so a small change alone does not mean being close: while k is
//! unchanged the changes of successive cycles shrink by a ratio r, and the distance still to
//! go is about e_n r/(1 − r) summed geometrically. The run stops when that distance (with
//! r < 1 measured over two cycles of one k) is below `steady_tolerance` times the peak
//! pressure and the last cycle's wear is a rigid motion to `steady_tolerance`.

use serde::{Deserialize, Serialize};

/// `[wear.adaptive]`: error-controlled extrapolation.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AdaptiveSpec {
    /// Local error allowed per step, as a pressure relative to the peak pressure of the
    /// first solve (dimensionless; default 1e-3).
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// The run stops when the last cycle's wear is a rigid motion to this relative accuracy
    /// ([`super::SteadyDistance::wear`]; default 1e-3).
    #[serde(default = "default_tolerance")]
    pub steady_tolerance: f64,
    /// Largest factor k (default 64: larger factors let the contact-zone ends lag; at 32
    /// elements under the punch k ≤ 4096 stopped 1.7 % of the peak away, k ≤ 64 0.3 %).
    #[serde(default = "default_max_factor")]
    pub max_factor: usize,
}

fn default_tolerance() -> f64 {
    1e-3
}
fn default_max_factor() -> usize {
    64
}

impl Default for AdaptiveSpec {
    fn default() -> Self {
        AdaptiveSpec {
            tolerance: default_tolerance(),
            steady_tolerance: default_tolerance(),
            max_factor: default_max_factor(),
        }
    }
}

impl AdaptiveSpec {
    /// Check the ranges; the error names the key within `[wear.adaptive]`.
    pub fn validate(&self) -> Result<(), (String, String)> {
        for (key, value) in [
            ("tolerance", self.tolerance),
            ("steady_tolerance", self.steady_tolerance),
        ] {
            if !(value.is_finite() && value > 0.0 && value < 1.0) {
                return Err((key.into(), format!("must lie in (0, 1), got {value}")));
            }
        }
        if !(1..=super::MAX_FACTOR).contains(&self.max_factor) {
            return Err((
                "max_factor".into(),
                format!("must be 1 … {}, got {}", super::MAX_FACTOR, self.max_factor),
            ));
        }
        Ok(())
    }
}

/// The controller's state during a run.
#[derive(Clone, Debug)]
pub struct Controller {
    spec: AdaptiveSpec,
    /// Current factor k.
    pub factor: usize,
    /// Allowed local error, MPa (set from the first solve).
    allowance: f64,
    /// Largest estimate over the current cycle, MPa.
    cycle_error: f64,
    /// The previous cycle's estimate and its k.
    previous: Option<(f64, usize)>,
}

impl Controller {
    /// Start with k = 1.
    pub fn new(spec: AdaptiveSpec) -> Controller {
        Controller {
            spec,
            factor: 1,
            allowance: 0.0,
            cycle_error: 0.0,
            previous: None,
        }
    }

    /// Set the error allowance from the peak pressure (MPa) of the first solve.
    pub fn set_scale(&mut self, peak_pressure: f64) {
        self.allowance = self.spec.tolerance * peak_pressure;
    }

    /// Record a step's error estimate (MPa).
    pub fn record(&mut self, error: f64) {
        self.cycle_error = self.cycle_error.max(error);
    }

    /// At the end of a cycle whose wear is rigid to `wear_distance`: whether the steady
    /// state is reached; if not, choose k for the next cycle.
    pub fn end_cycle(&mut self, wear_distance: f64) -> bool {
        let error = self.cycle_error;
        let peak = self.allowance / self.spec.tolerance;
        if let Some((before, k)) = self.previous {
            if k == self.factor && before > 0.0 && error < before && self.allowance > 0.0 {
                let ratio = error / before;
                let to_go = 2.0 * error * ratio / (1.0 - ratio);
                if to_go <= self.spec.steady_tolerance * peak
                    && wear_distance <= self.spec.steady_tolerance
                {
                    return true;
                }
            }
        }
        self.previous = Some((error, self.factor));
        if self.allowance > 0.0 {
            if error > self.allowance {
                self.factor = (self.factor / 2).max(1);
            } else if error < 0.4 * self.allowance {
                self.factor = (2 * self.factor).min(self.spec.max_factor);
            }
        }
        self.cycle_error = 0.0;
        false
    }
}
