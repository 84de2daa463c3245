//! Sliding kinematics and the extrapolation schedule of the wear integration: how far the
//! bodies slide in a half period (paper eq. 11, 20, 33–35) and how many half periods one
//! numerical step stands for (eq. 29–30).

use serde::{Deserialize, Serialize};

/// One entry of the extrapolation schedule: factor `k` for steps up to `until` (inclusive;
/// omitted on the last entry = for ever).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ScheduleEntry {
    /// Last step of this entry.
    pub until: Option<usize>,
    /// Extrapolation factor k ≥ 1 (half periods per step).
    pub k: usize,
}

/// The paper's schedule (eq. 30): k = 1 for n ≤ 50, 5 for n ≤ 100, 10 after.
pub fn paper_schedule() -> Vec<ScheduleEntry> {
    vec![
        ScheduleEntry {
            until: Some(50),
            k: 1,
        },
        ScheduleEntry {
            until: Some(100),
            k: 5,
        },
        ScheduleEntry { until: None, k: 10 },
    ]
}

/// Extrapolation factor of step n (1-based).
pub fn factor(schedule: &[ScheduleEntry], n: usize) -> usize {
    schedule
        .iter()
        .find(|e| e.until.is_none_or(|u| n <= u))
        .map_or(1, |e| e.k)
}

/// Γ(x) for x > 0 (Lanczos, g = 7, 9 terms: relative error ~1e-15).
fn gamma(x: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        return std::f64::consts::PI / ((std::f64::consts::PI * x).sin() * gamma(1.0 - x));
    }
    let x = x - 1.0;
    let t = x + 7.5;
    let sum: f64 = G[0]
        + G.iter()
            .enumerate()
            .skip(1)
            .map(|(i, g)| g / (x + i as f64))
            .sum::<f64>();
    (2.0 * std::f64::consts::PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * sum
}

/// ∫ over one half period of |v|ᵃ dτ for u_τ = −u₀ cos ωτ: (u₀ω)ᵃ/ω · √π Γ((a+1)/2)/Γ(a/2+1)
/// (mm^a s^(1−a)); equals 2u₀ for a = 1 (paper eq. 11).
pub fn half_period_sliding(amplitude: f64, omega: f64, a: f64) -> f64 {
    (amplitude * omega).powf(a) / omega * std::f64::consts::PI.sqrt() * gamma(0.5 * (a + 1.0))
        / gamma(0.5 * a + 1.0)
}

/// The same integral over the sub-interval ωτ ∈ [θ₀, θ₁] ⊂ [0, π] (exact closed form for
/// a = 1). sinᵃ θ behaves as θᵃ at both ends of the half period, a singular derivative that
/// plain Gauss–Legendre integrated to about 1e-4 at a = 0.2 (red team B: Archard's area of an
/// explicitly sub-stepped run 1.1e-4 off): integrated in Gauss pieces halving towards the ends.
pub fn partial_sliding(amplitude: f64, omega: f64, a: f64, theta: [f64; 2]) -> f64 {
    if a == 1.0 {
        return amplitude * (theta[0].cos() - theta[1].cos());
    }
    let half_pi = std::f64::consts::FRAC_PI_2;
    // sin is symmetric about π/2: the part beyond it is the mirror image of one before it.
    let mirrored = |t: f64| std::f64::consts::PI - t;
    let integral = if theta[1] <= half_pi {
        sin_power_integral(a, theta[0], theta[1])
    } else if theta[0] >= half_pi {
        sin_power_integral(a, mirrored(theta[1]), mirrored(theta[0]))
    } else {
        sin_power_integral(a, theta[0], half_pi)
            + sin_power_integral(a, mirrored(theta[1]), half_pi)
    };
    (amplitude * omega).powf(a) / omega * integral
}

/// ∫ sinᵃ θ dθ over [lo, hi] ⊂ [0, π/2], 24 Gauss–Legendre points on each of pieces halving
/// towards 0 ([hi/2, hi], [hi/4, hi/2], …), so that each piece lies at least its own length
/// from the singular θ = 0 (the rule's error there is far below round-off), down to lo, or
/// for lo = 0 to hi/2²⁰, below which sinᵃ θ = θᵃ (1 − aθ²/6 + O(θ⁴)) is integrated in
/// closed form.
fn sin_power_integral(a: f64, lo: f64, hi: f64) -> f64 {
    const HALVINGS: usize = 20;
    let rule = crate::quadrature::gauss_legendre(24);
    let gauss = |lo: f64, hi: f64| {
        let half = 0.5 * (hi - lo);
        half * rule
            .points
            .iter()
            .zip(&rule.weights)
            .map(|(x, w)| w * (lo + half * (x + 1.0)).sin().powf(a))
            .sum::<f64>()
    };
    let mut sum = 0.0;
    let mut top = hi;
    for _ in 0..HALVINGS {
        if lo >= 0.5 * top {
            return sum + gauss(lo, top);
        }
        sum += gauss(0.5 * top, top);
        top *= 0.5;
    }
    if lo > 0.0 {
        return sum + gauss(lo, top);
    }
    sum + top.powf(a + 1.0) * (1.0 / (a + 1.0) - a * top * top / (6.0 * (a + 3.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sliding_integral_is_two_amplitudes_for_a_equal_one() {
        // Paper eq. 11: ∫|v| over a half period = 2u₀; Lanczos Γ is good to ~1e-15.
        assert!((half_period_sliding(1.5, 10.0, 1.0) - 3.0).abs() < 1e-12);
        // a = 2: (u₀ω)²/ω · π/2.
        let exact = (1.5f64 * 10.0).powi(2) / 10.0 * std::f64::consts::FRAC_PI_2;
        assert!((half_period_sliding(1.5, 10.0, 2.0) - exact).abs() < 1e-12 * exact);
        // The partial integral over the whole half period agrees with the closed form.
        let whole = partial_sliding(1.5, 10.0, 2.0, [0.0, std::f64::consts::PI]);
        assert!((whole - exact).abs() < 1e-12 * exact);
    }

    /// Sub-steps of a half period add up to the closed form of the whole (Γ functions), also
    /// for a < 1, where sinᵃ has singular derivatives at both ends (1e-4 before, red team B).
    #[test]
    fn sub_intervals_add_up_to_the_half_period_for_any_exponent() {
        for a in [0.05, 0.2, 0.5, 0.8, 1.5, 2.5] {
            let exact = half_period_sliding(1.5, 10.0, a);
            for m in [1, 2, 3, 7, 200] {
                let step = std::f64::consts::PI / m as f64;
                let sum: f64 = (0..m)
                    .map(|j| {
                        partial_sliding(1.5, 10.0, a, [j as f64 * step, (j + 1) as f64 * step])
                    })
                    .sum();
                // 1e-12: the Lanczos Γ is good to ~1e-15, the graded Gauss pieces to round-off;
                // 200 sub-steps add 200 round-offs.
                assert!(
                    (sum - exact).abs() < 1e-12 * exact,
                    "a = {a}, {m} sub-steps: {sum} against {exact}"
                );
            }
        }
    }

    #[test]
    fn paper_schedule_counts_half_periods() {
        // Eq. 30: step 100 ends half period 300, step 1700 ends 16 300.
        let s = paper_schedule();
        let count = |n: usize| (1..=n).map(|i| factor(&s, i)).sum::<usize>();
        assert_eq!(count(50), 50);
        assert_eq!(count(100), 300);
        assert_eq!(count(1700), 16_300);
    }
}
