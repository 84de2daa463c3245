//! How far a wear run's last cycle is from the steady state, and why a run stopped.
//!
//! In the periodic (or monotonic) steady state the wear of one period is a rigid-body motion
//! of the plate (paper eq. 16–18): W⁺ + W⁻ = −R c at every point in contact, for some rigid
//! motion c. The distance of a cycle from that state is therefore the part of its wear that no
//! rigid motion explains: the residual r of the least-squares fit of −R c to the cycle wear
//! over the points in contact, relative to the largest cycle wear. Under a flat punch whose
//! plate translates, r is the cycle wear minus its mean, and max r − min r is the paper's δw
//! (eq. 40). For b = 1 the same residual divided by the wear coefficient is the non-uniform
//! part of the summed pressure p⁺ + p⁻ (eq. 23a says it vanishes).

use serde::Serialize;

/// Distance of a run's last cycle from the steady state (all relative quantities are
/// dimensionless).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SteadyDistance {
    /// Largest part of the last cycle's wear that no rigid motion of the plate explains,
    /// relative to the largest wear of that cycle. 0 in the steady state.
    pub wear: f64,
    /// Paper eq. 40 on the last cycle: max − min of the wear per period over the points in
    /// contact, mm per period (rigid rotations not removed).
    pub delta_w: f64,
    /// Spread (max − min) of p⁺ + p⁻ over the points in contact in both half cycles, relative
    /// to its largest value; 0 in the steady state of a flat contact whose plate translates
    /// (eq. 23a), not in general (curved contacts, b ≠ 1). For monotonic sliding: of p.
    pub summed_pressure: f64,
    /// How fast the last cycle's rigid wear closes the gap of a point out of contact in every
    /// half cycle, relative to the largest wear of the cycle: the rigid motion that fits the
    /// wear where the bodies touch moves the plate by as much where they do not, and such a
    /// point will touch. 0 in a steady state (there the rigid wear opens or keeps every gap
    /// outside the zone). A cylinder wearing its flat has a zone that grows by one contact
    /// point at a time: between two points the pressures settle and the wear is rigid, while
    /// the gaps next to the zone close at the full rate (red team 22: an adaptive run stopped
    /// there, 198 % of the peak from the steady state).
    pub closing: f64,
}

impl SteadyDistance {
    /// How far the cycle is from a steady state by its own measures: the larger of the
    /// non-rigid part of its wear and the closing of the gaps outside its contact zone.
    pub fn unsettled(&self) -> f64 {
        self.wear.max(self.closing)
    }
}

/// Why a run ended before its last step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum StopReason {
    /// A contact solve failed; nothing from it was kept.
    FailedSolve {
        /// Complementarity residual of the failed solve (relative to the peak pressure).
        complementarity: f64,
        /// Equilibrium residual of the failed solve (relative to the load).
        equilibrium: f64,
    },
    /// The implicit step's Newton iteration (b ≠ 1) did not meet `wear.tolerance` within
    /// `wear.max_iterations`; nothing of the step was kept.
    UnconvergedStep {
        /// Its final linearisation error, percent of the largest wear (as `criterion`).
        criterion: f64,
        /// `wear.tolerance`, percent.
        tolerance: f64,
        /// The step's extrapolation factor k.
        factor: usize,
        /// Whether the error stopped falling (a cycle: more iterations would not help).
        stalled: bool,
    },
    /// The wear stopped being finite (β̃ or the load far out of range).
    NonFiniteWear,
    /// The adaptive schedule found the steady state to its tolerance.
    SteadyState,
    /// The caller stopped the run after this step ([`crate::wear::WearIntegrator::run_until`]):
    /// an interrupt, or an error of its progress callback. The step is kept.
    Interrupted,
}

impl std::fmt::Display for StopReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StopReason::FailedSolve {
                complementarity,
                equilibrium,
            } => write!(
                f,
                "a contact solve failed (complementarity residual {complementarity:.2e}, equilibrium residual {equilibrium:.2e}; a solve counts as solved below {:.0e})",
                crate::complementarity::ACCEPTED_RESIDUAL
            ),
            StopReason::UnconvergedStep {
                criterion,
                tolerance,
                factor,
                stalled,
            } => {
                write!(f, "the implicit step's iteration did not converge (linearisation error {criterion:.3e} % of the largest wear after wear.max_iterations iterations, tolerance {tolerance:e} %")?;
                match (stalled, factor) {
                    (false, _) => write!(f, "; for b far from 1 Newton's method may need more: raise wear.max_iterations, or lower the step factor k)"),
                    (true, k) if *k > 1 => write!(f, "; its error stopped falling, so more iterations will not help: lower the step factor k, {k} here)"),
                    (true, _) => write!(f, "; its error stopped falling and the step factor k is already 1: for b far below 1 on stiff bodies or short zones the step may find no pressure; see docs/problem-files.md, [wear])"),
                }
            }
            StopReason::NonFiniteWear => write!(f, "the wear stopped being finite"),
            StopReason::SteadyState => write!(f, "the steady state was reached"),
            StopReason::Interrupted => write!(f, "the run was interrupted by its caller"),
        }
    }
}

/// Least-squares residual of `wear` (one value per point) after removing the best rigid
/// motion −R c, over the points where `in_contact`; `r` is row-major N × m, `weight` the
/// points' integration weights. Returns the residual (zero outside contact).
pub fn non_rigid_part(
    wear: &[f64],
    in_contact: &[bool],
    r: &[f64],
    m: usize,
    weight: &[f64],
) -> Vec<f64> {
    let fitted = rigid_fit(wear, in_contact, r, m, weight);
    (0..wear.len())
        .map(|i| {
            if in_contact[i] {
                wear[i] - fitted[i]
            } else {
                0.0
            }
        })
        .collect()
}

/// The rigid motion's wear pattern R c that fits `wear` best (least squares) over the points
/// where `in_contact`, evaluated at every point (mm).
fn rigid_fit(wear: &[f64], in_contact: &[bool], r: &[f64], m: usize, weight: &[f64]) -> Vec<f64> {
    let n = wear.len();
    // Normal equations (Rᵀ W R) c = Rᵀ W w: m ≤ 2, so a tiny dense solve.
    let mut normal = vec![0.0; m * m];
    let mut rhs = vec![0.0; m];
    for i in (0..n).filter(|&i| in_contact[i]) {
        for a in 0..m {
            rhs[a] += weight[i] * r[i * m + a] * wear[i];
            for b in 0..m {
                normal[a * m + b] += weight[i] * r[i * m + a] * r[i * m + b];
            }
        }
    }
    let c = solve_small(&mut normal, &mut rhs, m);
    (0..n)
        .map(|i| (0..m).map(|a| r[i * m + a] * c[a]).sum::<f64>())
        .collect()
}

/// Solve the m × m symmetric system by Gaussian elimination; modes that the contact does not
/// see (a zero pivot: rotation with a single point in contact) get coefficient 0.
fn solve_small(a: &mut [f64], b: &mut [f64], m: usize) -> Vec<f64> {
    let scale = (0..m).map(|k| a[k * m + k].abs()).fold(0.0, f64::max);
    let mut c = vec![0.0; m];
    let mut usable = vec![true; m];
    for k in 0..m {
        if a[k * m + k].abs() <= 1e-12 * scale {
            usable[k] = false;
            continue;
        }
        for i in k + 1..m {
            let f = a[i * m + k] / a[k * m + k];
            for j in k..m {
                a[i * m + j] -= f * a[k * m + j];
            }
            b[i] -= f * b[k];
        }
    }
    for k in (0..m).rev() {
        if usable[k] {
            let s: f64 = (k + 1..m).map(|j| a[k * m + j] * c[j]).sum();
            c[k] = (b[k] - s) / a[k * m + k];
        }
    }
    c
}

/// The distance of one cycle from the steady state: `cycle_wear` is the wear of the cycle per
/// point (mm), `p_plus`, `p_minus` its pressures (MPa; `p_minus` empty for monotonic sliding).
pub fn steady_distance(
    cycle_wear: &[f64],
    p_plus: &[f64],
    p_minus: &[f64],
    r: &[f64],
    m: usize,
    weight: &[f64],
) -> SteadyDistance {
    let n = cycle_wear.len();
    let minus = |i: usize| p_minus.get(i).copied().unwrap_or(0.0);
    let in_contact: Vec<bool> = (0..n).map(|i| p_plus[i] > 0.0 || minus(i) > 0.0).collect();
    let fitted = rigid_fit(cycle_wear, &in_contact, r, m, weight);
    let largest = cycle_wear.iter().fold(0.0f64, |a, w| a.max(w.abs()));
    let worst = (0..n)
        .filter(|&i| in_contact[i])
        .fold(0.0f64, |a, i| a.max((cycle_wear[i] - fitted[i]).abs()));
    // Out of contact a point does not wear: the plate's rigid wear changes its gap by
    // −fitted, closing it where fitted > 0.
    let closing = (0..n)
        .filter(|&i| !in_contact[i])
        .fold(0.0f64, |a, i| a.max(fitted[i]));
    let contact_values = |f: &dyn Fn(usize) -> f64, only_both: bool| -> (f64, f64) {
        (0..n)
            .filter(|&i| {
                if only_both && !p_minus.is_empty() {
                    p_plus[i] > 0.0 && minus(i) > 0.0
                } else {
                    in_contact[i]
                }
            })
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let (w_lo, w_hi) = contact_values(&|i| cycle_wear[i], false);
    let (s_lo, s_hi) = contact_values(&|i| p_plus[i] + minus(i), true);
    let relative = |lo: f64, hi: f64| {
        if hi > 0.0 && hi.is_finite() {
            (hi - lo) / hi
        } else {
            0.0
        }
    };
    SteadyDistance {
        wear: if largest > 0.0 { worst / largest } else { 0.0 },
        delta_w: if w_hi.is_finite() { w_hi - w_lo } else { 0.0 },
        summed_pressure: relative(s_lo, s_hi),
        closing: if largest > 0.0 {
            closing / largest
        } else {
            0.0
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rigid_wear_is_at_distance_zero() {
        // Translation and rotation modes of a flat punch: R = [−1, −(x − x_pin)] per point.
        let x: Vec<f64> = (0..11).map(|i| i as f64).collect();
        let r: Vec<f64> = x.iter().flat_map(|&x| [-1.0, -(x - 5.0)]).collect();
        let weight = vec![1.0; 11];
        let p = vec![1.0; 11];
        let rigid: Vec<f64> = x.iter().map(|&x| 2.0 + 0.1 * x).collect();
        let d = steady_distance(&rigid, &p, &p, &r, 2, &weight);
        // Exact in exact arithmetic; round-off of an 11-point fit.
        assert!(d.wear < 1e-14, "{}", d.wear);
        assert!((d.delta_w - 1.0).abs() < 1e-14);
        // A bump of 0.1 on a wear of about 3: the residual is about 0.1 less its fit.
        let mut bumped = rigid.clone();
        bumped[5] += 0.1;
        let d = steady_distance(&bumped, &p, &p, &r, 2, &weight);
        assert!(d.wear > 0.02 && d.wear < 0.04, "{}", d.wear);
    }

    #[test]
    fn points_out_of_contact_do_not_count() {
        let r = vec![-1.0; 4];
        let wear = [1.0, 1.0, 1.0, 0.0];
        let p = [1.0, 1.0, 1.0, 0.0];
        let d = steady_distance(&wear, &p, &[], &r, 1, &[1.0; 4]);
        assert_eq!(d.wear, 0.0);
        assert_eq!(d.delta_w, 0.0);
    }
}
