//! Error-controlled extrapolation: the factor k (half periods per step) chosen from a local
//! error estimate instead of a fixed schedule.
//!
//! A step holds the wear rate at its end-of-step value for k half periods (backward Euler in
//! the worn shape), and alternates the sliding direction step by step. Both approximations
//! err by about half the change of the wear rate across the step, times k:
//!
//! e ≈ (k/2) · |ΔW_this − ΔW_previous|,
//!
//! where ΔW is the wear of one half period at the end of a step and the previous step is the
//! one before it (the other direction under reciprocating sliding, so the estimate also sees
//! the error of lumping k '+' half periods before k '−' ones). Only the part of e that no
//! rigid plate motion explains changes a pressure, so e is measured after removing the best
//! rigid motion. The allowed e is `tolerance` times the elastic normal approach of the first
//! solve (the size of the deformations that shape the pressure). After every full cycle k
//! moves on a ladder of powers of two: halved when e exceeds the allowance, doubled when e is
//! below 0.4 of it (both half cycles of a cycle share one k, so that a cycle stays symmetric,
//! and a factorisation made for one k is reused whenever the run comes back to it).
//! The run stops when the last cycle's wear is rigid to `steady_tolerance`.

use serde::{Deserialize, Serialize};

/// `[wear.adaptive]`: error-controlled extrapolation.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AdaptiveSpec {
    /// Local error allowed per step, relative to the elastic normal approach at the contact
    /// (dimensionless; default 1e-3).
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// The run stops when the last cycle's wear is a rigid motion to this relative accuracy
    /// ([`super::SteadyDistance::wear`]; default 1e-3).
    #[serde(default = "default_tolerance")]
    pub steady_tolerance: f64,
    /// Largest factor k (default 4096).
    #[serde(default = "default_max_factor")]
    pub max_factor: usize,
}

fn default_tolerance() -> f64 {
    1e-3
}
fn default_max_factor() -> usize {
    4096
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
    /// Allowed local error, mm (set from the first solve).
    allowance: f64,
    /// Largest estimate over the current cycle, mm.
    cycle_error: f64,
}

impl Controller {
    /// Start with k = 1.
    pub fn new(spec: AdaptiveSpec) -> Controller {
        Controller {
            spec,
            factor: 1,
            allowance: 0.0,
            cycle_error: 0.0,
        }
    }

    /// Set the error allowance from the elastic normal approach (mm) of the first solve.
    pub fn set_scale(&mut self, elastic_approach: f64) {
        self.allowance = self.spec.tolerance * elastic_approach;
    }

    /// Whether a cycle with this distance from the steady state ends the run.
    pub fn is_steady(&self, distance: f64) -> bool {
        distance <= self.spec.steady_tolerance
    }

    /// Record a step's error estimate (mm).
    pub fn record(&mut self, error: f64) {
        self.cycle_error = self.cycle_error.max(error);
    }

    /// At the end of a cycle: choose k for the next one.
    pub fn end_cycle(&mut self) {
        if self.allowance > 0.0 {
            if self.cycle_error > self.allowance {
                self.factor = (self.factor / 2).max(1);
            } else if self.cycle_error < 0.4 * self.allowance {
                self.factor = (2 * self.factor).min(self.spec.max_factor);
            }
        }
        self.cycle_error = 0.0;
    }
}
