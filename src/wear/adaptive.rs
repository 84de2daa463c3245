//! Error-controlled extrapolation: the factor k (half periods per step) chosen from a local
//! error estimate by step doubling, with local (Richardson) extrapolation.
//!
//! A step holds the wear rate at its end-of-step value for k half periods: backward Euler in
//! the worn shape, first order in k. Its error therefore lags the transient: a slow mode of
//! time constant τ (in half periods) decays by (1 + k/τ)^(−1) per step instead of e^(−k/τ), so
//! a run with large steps reaches the steady state later than the process does (about
//! k/(2τ) of the way later; at k = 64 on Example 1, 2–3 % more half periods).
//!
//! Step doubling measures and removes that error. A *macro step* is one cycle with factor 2k
//! (the coarse cycle, computed and thrown away) and two cycles with factor k (the fine ones,
//! which are the run's recorded steps). Both end at the same half period. With the shapes
//! g_c and g_f at that point,
//!
//! - the local error of the fine cycles is about g_f − g_c (first order: the coarse cycle's
//!   local error is twice the fine pair's), measured where it matters, in the pressure:
//!   e = max over both half cycles and all points of |p_f − p_c|;
//! - g = 2 g_f − g_c cancels that leading term (second order), and the next macro step starts
//!   from it. Its decay factor for a mode is 2/(1 + z/2)² − 1/(1 + z) with z = k/τ: within
//!   z²/… of e^(−z) for slow modes, and below 1 in magnitude for every z > 0, so the stiff
//!   modes of a fine mesh stay damped. A macro step whose e exceeds the allowance is not
//!   extrapolated (the fine cycles alone are backward Euler, stable at any k).
//!
//! The allowance is `tolerance` times the macro step's largest pressure (not the first
//! solve's: at a sharp corner that one is a singularity that grows with mesh refinement and
//! wears away). After every
//! macro step k moves on a ladder of powers of two (so that a factorisation made for one k
//! is reused whenever the run comes back to it): halved when e exceeds the allowance,
//! doubled when e is below a fifth of it (e grows as k², so a doubled k stays within it).
//!
//! The recorded steps and the final result are the fine cycles' own (each pressure belongs
//! to its shape); the extrapolated shape is only where the next macro step starts.
//!
//! The run stops when the steady state is reached. A slow transient changes the pressures by
//! less and less per macro step, so a small change alone does not mean being close: while k
//! is unchanged the changes of successive macro steps shrink by a ratio r, and the distance
//! still to go is about Δp r/(1 − r) summed geometrically. The run stops when that distance
//! is below `steady_tolerance` times the current peak pressure and the last cycle's wear is a rigid
//! motion to `steady_tolerance`.

use serde::{Deserialize, Serialize};

/// `[wear.adaptive]`: error-controlled extrapolation.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AdaptiveSpec {
    /// Local error allowed per macro step, as a pressure relative to the macro step's peak
    /// pressure (dimensionless; default 1e-2). It bounds the first-order error of the fine
    /// cycles; the extrapolated shape the run continues from is far closer (second order).
    #[serde(default = "default_local_tolerance")]
    pub tolerance: f64,
    /// The run stops when the last cycle's wear is a rigid motion to this relative accuracy
    /// ([`super::SteadyDistance::wear`]; default 1e-3).
    #[serde(default = "default_tolerance")]
    pub steady_tolerance: f64,
    /// Largest factor k of any step, the coarse cycles' included (default 32, at least 2).
    /// A run is compared with the steady state once per cycle, so this also sets how
    /// closely it can tell when the steady state is reached: with 32 (fine cycles of
    /// k ≤ 16) Example 1 gets within 0.5 % of it in fewer half periods than with the paper's
    /// schedule on every mesh tried, with 64 within one cycle of it (docs/convergence.md).
    #[serde(default = "default_max_factor")]
    pub max_factor: usize,
    /// Start each macro step from the Richardson extrapolation 2 g_f − g_c (default true).
    /// false keeps the fine cycles' first-order shape, to see what the extrapolation buys.
    #[serde(default = "default_richardson")]
    pub richardson: bool,
}

fn default_richardson() -> bool {
    true
}

fn default_tolerance() -> f64 {
    1e-3
}
fn default_local_tolerance() -> f64 {
    1e-2
}
fn default_max_factor() -> usize {
    32
}

impl Default for AdaptiveSpec {
    fn default() -> Self {
        AdaptiveSpec {
            tolerance: default_local_tolerance(),
            steady_tolerance: default_tolerance(),
            max_factor: default_max_factor(),
            richardson: default_richardson(),
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
        if !(2..=super::MAX_FACTOR).contains(&self.max_factor) {
            return Err((
                "max_factor".into(),
                format!("must be 2 … {}, got {}", super::MAX_FACTOR, self.max_factor),
            ));
        }
        Ok(())
    }
}

/// Macro steps over which the contraction ratio of the transient is measured.
const RATIO_WINDOW: usize = 4;

/// The controller's state during a run.
#[derive(Clone, Debug)]
pub struct Controller {
    spec: AdaptiveSpec,
    /// Factor k of the fine cycles (the coarse cycle's is 2k).
    pub factor: usize,
    /// The pressure changes (MPa) of the last macro steps made with the current k, oldest
    /// first, at most [`RATIO_WINDOW`] + 1 of them.
    changes: Vec<f64>,
}

impl Controller {
    /// Start with fine cycles of k = 1.
    pub fn new(spec: AdaptiveSpec) -> Controller {
        Controller {
            spec,
            factor: 1,
            changes: Vec::with_capacity(RATIO_WINDOW + 1),
        }
    }

    /// Whether a macro step with local error estimate `local_error` (MPa) may be
    /// extrapolated, its peak pressure being `peak` (MPa).
    pub fn accepts(&self, local_error: f64, peak: f64) -> bool {
        self.spec.richardson && local_error <= self.spec.tolerance * peak
    }

    /// At the end of a macro step with local error estimate `local_error`, pressure change
    /// `change` since the last one and peak pressure `peak` (all MPa), whose last cycle's
    /// wear is rigid to `wear_distance`: whether the steady state is reached; if not, choose
    /// k for the next macro step.
    pub fn end_macro_step(
        &mut self,
        local_error: f64,
        change: f64,
        peak: f64,
        wear_distance: f64,
    ) -> bool {
        self.changes.push(change);
        if self.changes.len() > RATIO_WINDOW + 1 {
            self.changes.remove(0);
        }
        if self.changes.len() == RATIO_WINDOW + 1 {
            // The contraction ratio per macro step over the whole window: one ratio of two
            // successive changes is noisy (points entering or leaving contact), and a low
            // one would stop the run early.
            let ratio = (change / self.changes[0]).powf(1.0 / RATIO_WINDOW as f64);
            if ratio < 1.0 {
                let to_go = change * ratio / (1.0 - ratio);
                if to_go <= self.spec.steady_tolerance * peak
                    && wear_distance <= self.spec.steady_tolerance
                {
                    return true;
                }
            }
        }
        let (factor, allowance) = (self.factor, self.spec.tolerance * peak);
        if local_error > allowance {
            self.factor = (self.factor / 2).max(1);
        } else if local_error < 0.2 * allowance {
            self.factor = (2 * self.factor).min(self.spec.max_factor / 2).max(1);
        }
        if self.factor != factor {
            self.changes.clear();
        }
        false
    }
}
