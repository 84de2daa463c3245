//! Error-controlled extrapolation: the factor k (half periods per step) chosen from a local
//! error estimate, by one of two second-order methods: variable-step BDF2 with a
//! predictor–corrector error estimate (the default, one contact solve per recorded step) or
//! step doubling with local (Richardson) extrapolation (1.5 solves per recorded step).
//!
//! # Why second order
//!
//! A step of the half-period scheme holds the wear rate at its end-of-step value for k half
//! periods: backward Euler in the worn shape, first order in k. Its error lags the
//! transient: a slow mode of time constant τ (in half periods) decays by (1 + k/τ)^(−1) per
//! step instead of e^(−k/τ), so a run with large steps reaches the steady state later than
//! the process does (about k/(2τ) of the way later; at k = 64 on Example 1, 2–3 % more half
//! periods). Both methods remove that lag; both keep the stiff modes of fine meshes damped.
//!
//! # BDF2 (`method = "bdf2"`)
//!
//! The unit of a step is the cycle (both half periods; one step under monotonic sliding):
//! with g_n the shape at the end of cycle n and F(g) = ΔW(p⁺) + ΔW(p⁻) the wear of one cycle
//! at shape g, a cycle with factor k is the BDF2 step of size h = k (in cycles)
//!
//! g_{n+1} = (4 g_n − g_v)/3 + (2/3) k F(g_{n+1}),
//!
//! g_v being the shape at t_n − k. It has exactly the structure of the backward-Euler cycle
//! g_{n+1} = g_n + k F(g_{n+1}) with a different known shape, (4 g_n − g_v)/3 instead of g_n,
//! and the wear weighted by (2/3) k instead of k: each half cycle is the same
//! complementarity problem (for b = 1 the wear is a diagonal compliance (2/3) k c/(w t) in
//! series with the flexibility; Newton's method for b ≠ 1), one contact solve per half
//! cycle, with the look-ahead of the first half cycle weighted alike.
//!
//! *Fixed leading coefficient.* The weight is (2/3) k whatever the past steps were, so the
//! compliance, and with it the factorisation of the contact system, depends on k alone and
//! is reused whenever the run comes back to a k (a new compliance costs two dense
//! factorisations, about 4 ms each at 513 points, as much as 20 contact solves). A changed
//! k instead changes g_v: it is a stored shape (t_n − k = t_{n−1} at constant k; the
//! controller doubles k only after two cycles with the same k, so a doubled k reaches back
//! exactly to t_{n−2}), and after a halving the quadratic through g_n, g_{n−1}, g_{n−2}
//! evaluated at t_n − k (error O(k³), the order of the step's own local error). The first
//! cycle, with nothing stored, is backward Euler (weight k).
//!
//! *Stability.* For a mode g' = λ g of the linearised wear (λ < 0: the wear evens out the
//! pressure) the step is (1 − (2/3) z) g_{n+1} = (4 g_n − g_{n−1})/3 with z = λ k: BDF2,
//! A-stable (both roots of (3 − 2z) r² − 4 r + 1 = 0 lie in the unit disc for Re z ≤ 0) and
//! L-stable (both tend to 0 as z → −∞). The stiff modes of a fine mesh (large |λ|: short
//! wavelengths of the shape, which the elastic bodies flatten at once) are therefore damped
//! at any k, as by backward Euler, rather than amplified or left oscillating (the
//! trapezoidal rule's root tends to −1). For the slow modes the root is
//! e^z (1 + O(z³)): the lag of backward Euler is gone. Doubling k (ratio 2 after two equal
//! steps) and halving it change only the known part: after a halving it uses
//! g_v = (3 g_n + 6 g_{n−1} − g_{n−2})/8, a perturbation of O(k³) of the slow modes for one
//! step, and the stiff limit is the same (the new shape's stiff part → 0 whatever the known
//! part); the following steps are constant-k BDF2 again.
//!
//! *Error estimate (Milne's device).* The predictor is the quadratic through the last three
//! cycles' pressures, extrapolated to the end of the current cycle; with the step sizes
//! h₀ = k, h₁, h₂ of the current and the two previous cycles its error is
//! −C_p p‴ with C_p = h₀(h₀ + h₁)(h₀ + h₁ + h₂)/6. The corrector (BDF2 with equal
//! virtual steps h₀) has the local error C_c p‴ with C_c = (2/9) h₀³. Their difference is
//! (C_c + C_p) p‴, so the corrector's error is estimated as
//! e = C_c/(C_c + C_p) · max |p_corrector − p_predictor| over both half cycles and all points
//! (2/11 of the difference at constant k). It is measured in the pressure, where the
//! tolerance is stated: for b = 1 and a fixed contact set the pressure is an affine function
//! of the shape, so its error is the shape's error mapped by that function; a point
//! entering or leaving contact makes the pressure history kink, the predictor then misses
//! and the estimate is larger, which is the cautious side. The predictor costs no solve.
//! Until three cycles are known there is no estimate and k stays 1. A step whose estimate
//! exceeds the allowance is kept (it is a stable BDF2 step) and k is halved for the next.
//!
//! # Step doubling (`method = "step_doubling"`)
//!
//! A *macro step* is one cycle with factor 2k (the coarse cycle, computed and thrown away)
//! and two cycles with factor k (the fine ones, which are the run's recorded steps). Both
//! end at the same half period. With the shapes g_c and g_f at that point,
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
//! The recorded steps and the final result are the fine cycles' own (each pressure belongs
//! to its shape); the extrapolated shape is only where the next macro step starts.
//!
//! # The ladder and the stop
//!
//! The allowance is `tolerance` times the step's largest pressure (not the first solve's: at
//! a sharp corner that one is a singularity that grows with mesh refinement and wears away).
//! After every cycle (BDF2) or macro step (step doubling) k moves on a ladder of powers of
//! two (so that a factorisation made for one k is reused whenever the run comes back to it):
//! halved when e exceeds the allowance, doubled when e is below a fifth (step doubling: e
//! grows as k²) or a tenth (BDF2: as k³) of it, up to `max_factor` for any contact solve.
//!
//! The run stops when the steady state is reached. A slow transient changes the pressures by
//! less and less per step, so a small change alone does not mean being close: while k
//! is unchanged the changes of successive steps shrink by a ratio r, and the distance
//! still to go is about Δp r/(1 − r) summed geometrically. The run stops when that distance
//! is below `steady_tolerance` times the current peak pressure and the last cycle's wear is
//! a rigid motion to `steady_tolerance` that closes no gap beside the contact zone by more
//! than `steady_tolerance` of the wear ([`super::SteadyDistance::unsettled`]): a zone that
//! grows one contact point at a time settles geometrically between two points, with its wear
//! rigid, while the gaps next to it still close (red team 22: a cylinder wearing its flat
//! stopped 198 % of the peak from the steady state).

use serde::{Deserialize, Serialize};

/// `[wear.adaptive]`: error-controlled extrapolation.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AdaptiveSpec {
    /// Local error allowed per step, as a pressure relative to the step's peak pressure
    /// (dimensionless; default 1e-2). BDF2: the estimated error of the cycle itself (second
    /// order). Step doubling: the first-order error of the fine cycles of a macro step; the
    /// extrapolated shape the run continues from is far closer (second order).
    #[serde(default = "default_local_tolerance")]
    pub tolerance: f64,
    /// The run stops when the last cycle's wear is a rigid motion to this relative accuracy
    /// and closes the gaps beside the zone by no more ([`super::SteadyDistance::unsettled`];
    /// default 1e-3).
    #[serde(default = "default_tolerance")]
    pub steady_tolerance: f64,
    /// Largest factor k of any contact solve (at least 2). Default 32 for both methods (step
    /// doubling's coarse cycles use twice the k of its recorded fine ones, so its recorded
    /// cycles use k ≤ 16). With BDF2 and k ≤ 32 Example 1 gets within 0.5 % of the steady
    /// state within 11 half periods of the k = 1 integration and 45–50 half periods before
    /// the paper's schedule, on 8 to 64 elements under the punch, with 483–605 contact solves
    /// (docs/convergence.md; the crossing interpolated between cycles,
    /// [`crate::wear::WearHistory::half_periods_to_reach`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_factor: Option<usize>,
    /// Step doubling only: start each macro step from the Richardson extrapolation
    /// 2 g_f − g_c (default true). false keeps the fine cycles' first-order shape, to see
    /// what the extrapolation buys.
    #[serde(default = "default_richardson")]
    pub richardson: bool,
    /// How the shape is advanced and the local error estimated: "bdf2" (default; one
    /// contact solve per recorded step) or "step_doubling" (1.5).
    #[serde(default)]
    pub method: AdaptiveMethod,
}

/// `method` of `[wear.adaptive]`.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum AdaptiveMethod {
    /// Variable-step BDF2 with a predictor–corrector (Milne) error estimate: one contact
    /// solve per recorded step.
    #[default]
    Bdf2,
    /// Step doubling with Richardson extrapolation: 1.5 contact solves per recorded step.
    StepDoubling,
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

impl Default for AdaptiveSpec {
    fn default() -> Self {
        AdaptiveSpec {
            tolerance: default_local_tolerance(),
            steady_tolerance: default_tolerance(),
            max_factor: None,
            richardson: default_richardson(),
            method: AdaptiveMethod::default(),
        }
    }
}

impl AdaptiveSpec {
    /// `max_factor`, or its default for the method.
    pub fn largest_factor(&self) -> usize {
        self.max_factor.unwrap_or(32)
    }

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
        if !self.richardson && self.method != AdaptiveMethod::StepDoubling {
            return Err((
                "richardson".into(),
                "applies to method = \"step_doubling\" only".into(),
            ));
        }
        if !(2..=super::MAX_FACTOR).contains(&self.largest_factor()) {
            return Err((
                "max_factor".into(),
                format!(
                    "must be 2 … {}, got {}",
                    super::MAX_FACTOR,
                    self.largest_factor()
                ),
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
        // A doubled k multiplies the estimate by 2^order: grow only when that stays inside.
        let grow_below = match self.spec.method {
            AdaptiveMethod::StepDoubling => 0.2,
            AdaptiveMethod::Bdf2 => 0.1,
        };
        if local_error.is_nan() {
            // No estimate yet (the first cycles of BDF2): keep k.
        } else if local_error > allowance {
            self.factor = (self.factor / 2).max(1);
        } else if local_error < grow_below * allowance
            && (self.spec.method == AdaptiveMethod::StepDoubling || self.changes.len() >= 2)
        {
            let largest = match self.spec.method {
                AdaptiveMethod::StepDoubling => self.spec.largest_factor() / 2,
                AdaptiveMethod::Bdf2 => self.spec.largest_factor(),
            };
            self.factor = (2 * self.factor).min(largest).max(1);
        }
        if self.factor != factor {
            self.changes.clear();
        }
        false
    }
}
