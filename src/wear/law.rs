//! The wear of one half period as a function of the contact pressure,
//! W(p) = Σ_l c_l p^b_l (mm, p in MPa, c_l = β̃_l ∫|v|^a_l dτ), and what Newton's methods need
//! of it: a slope to linearise with, and for a concave law (every b ≤ 1) the step taken in the
//! wear instead of the pressure.
//!
//! Why the wear: for b < 1 the law is concave with an infinite slope at p = 0. Newton's
//! method in the pressure overshoots there (from above the tangent reaches p(1 − 1/b) < 0, and
//! the active sets cycle); its secant W(p)/p instead converges only linearly, at a rate of
//! about 1 − b (b = 0.1: some 260 iterations). The pressure as a function of the wear,
//! p = W⁻¹(w), is convex with a zero slope at w = 0, and Newton's method in w converges
//! quadratically. A Newton step in w is the step in p with the tangent slope, followed by
//! moving the new pressure onto the law at the linear model's wear ([`step_in_wear`]).

/// Wear of one half period at pressure `p` (MPa; negative counts as 0), mm.
pub fn half_period_wear(terms: &[(f64, f64)], p: f64) -> f64 {
    let p = p.max(0.0);
    terms
        .iter()
        .map(|&(c, b)| if b == 1.0 { c * p } else { c * p.powf(b) })
        .sum()
}

/// Whether W is concave and not linear: every b ≤ 1 and some b < 1 (with c > 0). Then
/// Newton's method is taken in the wear ([`step_in_wear`]).
pub fn is_concave(terms: &[(f64, f64)]) -> bool {
    let wearing = || terms.iter().filter(|t| t.0 > 0.0);
    wearing().all(|t| t.1 <= 1.0) && wearing().any(|t| t.1 < 1.0)
}

/// The slope dW/dp (mm/MPa) Newton's method linearises W with at `p` (MPa).
///
/// - b = 1: the law's own slope.
/// - A concave law ([`is_concave`]): the tangent, the step being taken in the wear.
/// - b > 1: the tangent.
/// - b < 1 in a law that also has b > 1 terms: the secant W(p)/p, which stays positive where
///   the tangent in p overshoots (linear convergence at about 1 − b).
/// - At p = 0 the secant to the reference pressure `reference` (MPa, a mean contact
///   pressure): a point just brought into contact keeps a wear row that depends on its own
///   pressure, with a slope of the right size. `zero_slope_above_1` gives b > 1 terms a zero
///   slope there instead (their tangent). So does a concave law where its tangent overflows
///   (p^(b−1) beyond 1e308: only at subnormal pressures).
///
/// No floor is put under p for the tangent: at a zone's end with b = 0.1 pressures of 1e-18 of
/// the mean wear a few % of the most, and a secant to the mean there (as below a floor of
/// 1e-12 of it) asked for pressures of −1e-10 where the wear needed was positive.
pub fn newton_slope(terms: &[(f64, f64)], p: f64, reference: f64, zero_slope_above_1: bool) -> f64 {
    let p = p.max(0.0);
    let concave = is_concave(terms);
    if concave && p > 0.0 {
        let tangent: f64 = terms.iter().map(|&(c, b)| c * b * p.powf(b - 1.0)).sum();
        if tangent.is_finite() {
            return tangent;
        }
    }
    let from_reference = p == 0.0 || concave;
    terms
        .iter()
        .map(|&(c, b)| {
            if b == 1.0 {
                c
            } else if from_reference {
                if b > 1.0 && zero_slope_above_1 {
                    0.0
                } else {
                    c * reference.powf(b - 1.0)
                }
            } else if b > 1.0 {
                c * b * p.powf(b - 1.0)
            } else {
                c * p.powf(b - 1.0)
            }
        })
        .sum()
}

/// The chord slope W(p)/p (mm/MPa) through the origin, at p > 0 (MPa): a linear model with no
/// intercept, which converges more slowly than the tangent (at a rate of about 1 − b) but
/// does not send a point whose pressure should be nearly zero in and out of contact by
/// turns, as a concave tangent's positive intercept can. At p = 0, [`newton_slope`]'s.
pub fn chord_slope(terms: &[(f64, f64)], p: f64, reference: f64) -> f64 {
    if p > 0.0 {
        half_period_wear(terms, p) / p
    } else {
        newton_slope(terms, p, reference, true)
    }
}

/// The pressure (MPa) whose wear is `w` (mm): W⁻¹(w) for an increasing W with W(0) = 0, to
/// round-off; 0 for w ≤ 0.
pub fn pressure_of_wear(terms: &[(f64, f64)], w: f64) -> f64 {
    if w <= 0.0 {
        return 0.0;
    }
    // No allocation: this runs per point and iteration.
    let wearing = || terms.iter().copied().filter(|t| t.0 > 0.0);
    if let (Some((c, b)), 1) = (wearing().next(), wearing().count()) {
        return (w / c).powf(b.recip());
    }
    // W reaches w before any one of its terms does, i.e. below the least (w/c)^(1/b); the
    // root is found by bisection (in ln p once the lower end is positive), which needs no
    // safeguards and costs some 60 evaluations at points where it is used at all.
    let mut high = wearing()
        .map(|(c, b)| (w / c).powf(b.recip()))
        .fold(f64::INFINITY, f64::min);
    let mut low = 0.0f64;
    for _ in 0..200 {
        let mid = if low > 0.0 {
            (low * high).sqrt()
        } else {
            0.5 * high
        };
        if half_period_wear(terms, mid) < w {
            low = mid;
        } else {
            high = mid;
        }
        if high - low <= 4.0 * f64::EPSILON * high {
            break;
        }
    }
    0.5 * (low + high)
}

/// The step in the wear for a concave law: linearised at `p_hat` (MPa) with the slope
/// `slope` (mm/MPa), the linear model W(p̂) + s (p − p̂) gave the pressure `p` (MPa). The next
/// pressure is the one that has the model's wear on the law, W⁻¹(W(p̂) + s (p − p̂)).
///
/// - With the tangent ([`newton_slope`]) this is Newton's method in the wear (the steady
///   solver's step, whose shape is free so that no elastic part of a point's own gap equation
///   holds it back; the run's step is [`balanced_step`]). The new pressure is ≥ p (the
///   tangent lies above a concave law) and can be positive where p is not.
/// - Where the model's wear is not positive, `p` itself (then ≤ 0: the point leaves the
///   contact).
/// - Other laws, and a linearisation at p̂ = 0 or with a slope that is not finite (there the
///   slope is the secant to the reference pressure, and W⁻¹ of its model would send a small p
///   to a vanishing one), keep `p`.
///
/// The step in w overshoots where the solution is far above p̂: W⁻¹ of the model's wear can
/// then be orders of magnitude too large. The new pressure is therefore kept within `GROWTH`
/// times the larger of p̂ and p, which the quadratic convergence near the solution never
/// reaches.
pub fn step_in_wear(terms: &[(f64, f64)], p_hat: f64, slope: f64, p: f64) -> f64 {
    const GROWTH: f64 = 4.0;
    if !is_concave(terms) || p_hat <= 0.0 || !slope.is_finite() {
        return p;
    }
    let model = half_period_wear(terms, p_hat) + slope * (p - p_hat);
    if model <= 0.0 {
        return p;
    }
    pressure_of_wear(terms, model).min(GROWTH * p_hat.max(p))
}

/// The next linearisation point of a point in contact in the run's implicit step, for a
/// concave law: the pressure that satisfies the point's own gap equation with the linear
/// model's right-hand side, e p + W(p) = e p_lin + W(p̂) + s (p_lin − p̂), where e (mm/MPa) is
/// the point's own elastic flexibility (its pressure's normal approach) over the step factor k.
///
/// Where the wear outweighs the elastic part (e p ≪ W(p), the end of a zone with b ≪ 1) this
/// is the step in the wear ([`step_in_wear`]), which lands on the wear the point needs; where
/// the elastic part outweighs the wear, it is p_lin itself, which the step in the wear would
/// instead raise to the power 1/b (b = 0.1: the edge points of a short zone oscillated over
/// two decades). `p` > 0 and `p_hat` > 0 (MPa), `slope` the one linearised with.
pub fn balanced_step(terms: &[(f64, f64)], p_hat: f64, slope: f64, p: f64, elastic: f64) -> f64 {
    if !is_concave(terms)
        || p_hat <= 0.0
        || p <= 0.0
        || !slope.is_finite()
        || elastic.is_nan()
        || elastic < 0.0
    {
        return p;
    }
    let target = elastic * p + half_period_wear(terms, p_hat) + slope * (p - p_hat);
    // f(q) = e q + W(q) − target is increasing and concave: Newton's method from a point where
    // f ≤ 0 rises monotonically to the root without passing it.
    let f = |q: f64| elastic * q + half_period_wear(terms, q) - target;
    // Halving reaches a point with f ≤ 0 (f(0) = −target < 0) within the 1100 halvings that
    // take any finite p to zero.
    let mut q = p;
    let mut halvings = 0;
    while f(q) > 0.0 {
        q *= 0.5;
        halvings += 1;
        if halvings > 1100 {
            return p;
        }
    }
    for _ in 0..100 {
        let derivative = elastic
            + terms
                .iter()
                .map(|&(c, b)| c * b * q.powf(b - 1.0))
                .sum::<f64>();
        let next = q - f(q) / derivative;
        if next.is_nan() || next <= q || !next.is_finite() {
            break;
        }
        let converged = next - q <= 4.0 * f64::EPSILON * next;
        q = next;
        if converged {
            break;
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_inverse_returns_the_pressure() {
        for terms in [
            vec![(2e-3, 0.1)],
            vec![(2e-3, 0.5), (1e-4, 1.0)],
            vec![(2e-3, 0.3), (5e-3, 0.7), (0.0, 3.0)],
        ] {
            for p in [1e-9, 1e-3, 0.7, 33.3, 1e4] {
                let w = half_period_wear(&terms, p);
                let back = pressure_of_wear(&terms, w);
                // Bisection to 4 ε of p; the single power's closed form to a few ε.
                assert!((back - p).abs() <= 1e-13 * p, "{terms:?} {p} {back}");
            }
        }
    }

    #[test]
    fn a_newton_step_in_the_wear_lands_on_a_linear_targets_solution() {
        // One point whose wear must equal w* (the wear row alone): in w the equation is
        // linear, so one step from anywhere gives the exact pressure W⁻¹(w*), while the step in
        // p with the tangent falls short (b < 1: p(1 − 1/b) < 0 from far above).
        let terms = [(1e-3, 0.1)];
        let target = half_period_wear(&terms, 10.0);
        for p_hat in [9.0, 11.0, 30.0] {
            let slope = newton_slope(&terms, p_hat, 1.0, false);
            let p_linear = p_hat + (target - half_period_wear(&terms, p_hat)) / slope;
            let next = step_in_wear(&terms, p_hat, slope, p_linear);
            assert!((next - 10.0).abs() < 1e-12 * 10.0, "{p_hat}: {next}");
        }
    }

    #[test]
    fn the_balanced_step_is_the_step_in_the_wear_or_the_pressure_at_its_limits() {
        let terms = [(1e-3, 0.1)];
        let (p_hat, p) = (2.0, 3.0);
        let slope = newton_slope(&terms, p_hat, 1.0, false);
        let in_wear = step_in_wear(&terms, p_hat, slope, p);
        let rigid_bodies = balanced_step(&terms, p_hat, slope, p, 0.0);
        assert!(
            (rigid_bodies - in_wear).abs() < 1e-12 * in_wear,
            "{rigid_bodies} vs {in_wear}"
        );
        let stiff_wear = balanced_step(&terms, p_hat, slope, p, 1e6);
        assert!((stiff_wear - p).abs() < 1e-6 * p, "{stiff_wear} vs {p}");
        // In between, the point's own equation holds.
        let e = 1e-3;
        let q = balanced_step(&terms, p_hat, slope, p, e);
        let model = half_period_wear(&terms, p_hat) + slope * (p - p_hat);
        let balance = e * q + half_period_wear(&terms, q) - (e * p + model);
        assert!(balance.abs() < 1e-14 * (e * p + model), "{balance}");
    }

    #[test]
    fn which_laws_are_concave() {
        assert!(is_concave(&[(1.0, 0.5)]));
        assert!(is_concave(&[(1.0, 0.5), (2.0, 1.0)]));
        assert!(!is_concave(&[(1.0, 1.0)]));
        assert!(!is_concave(&[(1.0, 0.5), (2.0, 1.5)]));
        // A body that does not wear does not count.
        assert!(is_concave(&[(1.0, 0.5), (0.0, 1.5)]));
    }
}
