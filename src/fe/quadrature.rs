//! One-dimensional Gauss quadrature rules on the reference interval [-1, 1].
//!
//! Nodes are computed (not tabulated) by Newton iteration on Legendre
//! polynomials evaluated with the three-term recurrence, so any order can be
//! requested; the rules are accurate to round-off (~1e-15) for n up to at
//! least 40.

use std::f64::consts::PI;

/// A one-dimensional quadrature rule on the reference interval [-1, 1].
///
/// `points` are in ascending order and `weights[i]` belongs to `points[i]`;
/// the weights sum to 2 (the length of the interval), so
/// `∫_{-1}^{1} f(x) dx ≈ Σ_i weights[i] · f(points[i])`.
#[derive(Clone, Debug, PartialEq)]
pub struct Rule1d {
    /// Abscissae in [-1, 1], ascending.
    pub points: Vec<f64>,
    /// Weights, one per point.
    pub weights: Vec<f64>,
}

impl Rule1d {
    /// Number of points of the rule.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// True if the rule has no points (never the case for rules built here).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }
}

/// Legendre polynomial P_n(x) and its derivative P_n'(x), by the three-term
/// recurrence `(k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}`.
///
/// Returns `(P_n(x), P_n'(x))`. The derivative uses the recurrence
/// `P'_{k+1} = P'_{k-1} + (2k+1) P_k` rather than the closed form with
/// `1/(x² - 1)`, so it is valid at x = ±1 as well.
pub fn legendre(n: usize, x: f64) -> (f64, f64) {
    // (P_{k-1}, P_k) and (P'_{k-1}, P'_k), starting at k = 0 with P_{-1} := 0.
    let (mut p_prev, mut p) = (0.0, 1.0);
    let (mut d_prev, mut d) = (0.0, 0.0);
    for k in 0..n {
        let kf = k as f64;
        let p_next = ((2.0 * kf + 1.0) * x * p - kf * p_prev) / (kf + 1.0);
        let d_next = d_prev + (2.0 * kf + 1.0) * p;
        p_prev = p;
        p = p_next;
        d_prev = d;
        d = d_next;
    }
    (p, d)
}

/// Newton iteration budget; quadratic convergence from the Chebyshev-like
/// guesses needs well under 10 steps, the margin is only for safety.
const MAX_NEWTON: usize = 100;

/// Make a list of ascending nodes exactly antisymmetric about 0: the rule is
/// symmetric in exact arithmetic, and enforcing it keeps odd moments exactly 0.
fn symmetrize(points: &mut [f64], weights: &mut [f64]) {
    let n = points.len();
    for i in 0..n / 2 {
        let j = n - 1 - i;
        let x = 0.5 * (points[j] - points[i]);
        let w = 0.5 * (weights[i] + weights[j]);
        points[i] = -x;
        points[j] = x;
        weights[i] = w;
        weights[j] = w;
    }
    if n % 2 == 1 {
        points[n / 2] = 0.0;
    }
}

/// Gauss–Legendre rule with `n >= 1` points (ascending), exact for
/// polynomials of degree `2n - 1`.
///
/// Nodes are the roots of P_n, weights `2 / ((1 - x²) P_n'(x)²)`.
///
/// # Panics
/// If `n == 0` (callers are expected to validate the order).
pub fn gauss_legendre(n: usize) -> Rule1d {
    assert!(n >= 1, "gauss_legendre needs at least one point");
    let mut points = vec![0.0; n];
    let mut weights = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n {
        // Tricomi-style guess cos(π(i + 3/4)/(n + 1/2)) lies within the
        // Newton basin of the i-th largest root; store it ascending.
        let mut x = -(PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        for _ in 0..MAX_NEWTON {
            let (p, dp) = legendre(n, x);
            let dx = p / dp;
            x -= dx;
            if dx.abs() <= 1e-16 * x.abs().max(1.0) {
                break;
            }
        }
        // One more derivative evaluation at the converged node for the weight.
        let (_, dp) = legendre(n, x);
        points[i] = x;
        weights[i] = 2.0 / ((1.0 - x) * (1.0 + x) * dp * dp);
    }
    symmetrize(&mut points, &mut weights);
    Rule1d { points, weights }
}

/// Gauss–Lobatto rule with `n >= 2` points including -1 and +1 (ascending),
/// exact for polynomials of degree `2n - 3`.
///
/// Interior nodes are the roots of P'_{n-1}; all weights are
/// `2 / (n (n-1) P_{n-1}(x)²)` (which gives `2/(n(n-1))` at the end points).
///
/// # Panics
/// If `n < 2` (callers are expected to validate the order).
pub fn gauss_lobatto(n: usize) -> Rule1d {
    assert!(n >= 2, "gauss_lobatto needs at least two points");
    let m = n - 1; // polynomial degree whose derivative's roots we need
    let mf = m as f64;
    let mut points = vec![0.0; n];
    points[0] = -1.0;
    points[m] = 1.0;
    for (i, point) in points.iter_mut().enumerate().take(m).skip(1) {
        // Chebyshev–Gauss–Lobatto nodes interlace the Legendre–Lobatto ones
        // closely enough for Newton to converge to the right root.
        let mut x = -(PI * i as f64 / mf).cos();
        for _ in 0..MAX_NEWTON {
            let (p, dp) = legendre(m, x);
            // P'' from Legendre's ODE; safe because interior x stays away from ±1.
            let ddp = (2.0 * x * dp - mf * (mf + 1.0) * p) / (1.0 - x * x);
            let dx = dp / ddp;
            x -= dx;
            if dx.abs() <= 1e-16 * x.abs().max(1.0) {
                break;
            }
        }
        *point = x;
    }
    let scale = 2.0 / (n as f64 * mf);
    let mut weights: Vec<f64> = points
        .iter()
        .map(|&x| {
            let (p, _) = legendre(m, x);
            scale / (p * p)
        })
        .collect();
    symmetrize(&mut points, &mut weights);
    Rule1d { points, weights }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact ∫_{-1}^{1} x^k dx.
    fn monomial_integral(k: usize) -> f64 {
        if k % 2 == 1 {
            0.0
        } else {
            2.0 / (k as f64 + 1.0)
        }
    }

    fn integrate(rule: &Rule1d, k: usize) -> f64 {
        rule.points
            .iter()
            .zip(&rule.weights)
            .map(|(&x, &w)| w * x.powi(k as i32))
            .sum()
    }

    // Round-off bound: the sums have at most 40 positive weights times
    // |x^k| <= 1, so accumulated error is a few tens of ulps of 2; 1e-14
    // leaves margin while still catching any wrong node/weight digit.
    const TOL: f64 = 1e-14;

    #[test]
    fn legendre_matches_closed_forms() {
        for &x in &[-1.0, -0.7, 0.0, 0.3, 1.0] {
            let (p2, d2) = legendre(2, x);
            assert!((p2 - 0.5 * (3.0 * x * x - 1.0)).abs() < TOL);
            assert!((d2 - 3.0 * x).abs() < TOL);
            let (p3, d3) = legendre(3, x);
            assert!((p3 - 0.5 * (5.0 * x * x * x - 3.0 * x)).abs() < TOL);
            assert!((d3 - 0.5 * (15.0 * x * x - 3.0)).abs() < TOL);
        }
        // P_n'(1) = n(n+1)/2 checks the derivative recurrence at the end point.
        let (p, d) = legendre(10, 1.0);
        assert!((p - 1.0).abs() < TOL && (d - 55.0).abs() < 1e-12);
    }

    #[test]
    fn weights_sum_to_two_and_points_ascend() {
        for n in 1..=40 {
            for rule in [gauss_legendre(n), gauss_lobatto(n.max(2))] {
                let s: f64 = rule.weights.iter().sum();
                assert!((s - 2.0).abs() < TOL, "n={n} sum={s}");
                assert!(rule.points.windows(2).all(|w| w[0] < w[1]));
                assert!(rule.weights.iter().all(|&w| w > 0.0));
                assert!(!rule.is_empty());
            }
        }
    }

    #[test]
    fn legendre_rule_exactness() {
        for n in 1..=40 {
            let rule = gauss_legendre(n);
            assert_eq!(rule.len(), n);
            for k in 0..=2 * n - 1 {
                let err = (integrate(&rule, k) - monomial_integral(k)).abs();
                assert!(err < TOL, "GL n={n} k={k} err={err}");
            }
            // Degree 2n is no longer exact; the error for x^{2n} is about
            // π/4^n, so it is only distinguishable from round-off for
            // moderate n (3e-9 at n = 15).
            let k = 2 * n;
            if n <= 15 {
                assert!((integrate(&rule, k) - monomial_integral(k)).abs() > 1e-10);
            }
        }
    }

    #[test]
    fn lobatto_rule_exactness() {
        for n in 2..=40 {
            let rule = gauss_lobatto(n);
            assert_eq!(rule.len(), n);
            assert_eq!((rule.points[0], rule.points[n - 1]), (-1.0, 1.0));
            for k in 0..=2 * n - 3 {
                let err = (integrate(&rule, k) - monomial_integral(k)).abs();
                assert!(err < TOL, "GLL n={n} k={k} err={err}");
            }
            // Same decay argument as for Gauss–Legendre, the Lobatto error is larger.
            let k = 2 * n - 2;
            if n <= 15 {
                assert!((integrate(&rule, k) - monomial_integral(k)).abs() > 1e-10);
            }
        }
    }

    #[test]
    fn nodes_are_roots_and_symmetric() {
        for n in [5, 17, 40] {
            let gl = gauss_legendre(n);
            let gll = gauss_lobatto(n);
            for i in 0..n {
                assert_eq!(gl.points[i], -gl.points[n - 1 - i]);
                assert_eq!(gl.weights[i], gl.weights[n - 1 - i]);
                assert_eq!(gll.points[i], -gll.points[n - 1 - i]);
                assert_eq!(gll.weights[i], gll.weights[n - 1 - i]);
                // Raw residuals grow like n² (GL) or n⁴ (Lobatto) near the ends,
                // so check the implied root error (one Newton step) instead;
                // 1e-14 is a few ulps of the node plus recurrence round-off.
                let (p, dp) = legendre(n, gl.points[i]);
                assert!((p / dp).abs() < 1e-14);
                if i > 0 && i < n - 1 {
                    let (x, m) = (gll.points[i], (n - 1) as f64);
                    let (p, dp) = legendre(n - 1, x);
                    let ddp = (2.0 * x * dp - m * (m + 1.0) * p) / (1.0 - x * x);
                    assert!((dp / ddp).abs() < 1e-14);
                }
            }
        }
    }

    #[test]
    fn closed_form_small_rules() {
        let gl = gauss_legendre(3);
        let a = (3.0f64 / 5.0).sqrt();
        let expected = [(-a, 5.0 / 9.0), (0.0, 8.0 / 9.0), (a, 5.0 / 9.0)];
        for (i, &(x, w)) in expected.iter().enumerate() {
            assert!((gl.points[i] - x).abs() < 1e-15);
            assert!((gl.weights[i] - w).abs() < 1e-15);
        }
        let gll = gauss_lobatto(4);
        let b = 1.0 / 5.0f64.sqrt();
        let expected = [
            (-1.0, 1.0 / 6.0),
            (-b, 5.0 / 6.0),
            (b, 5.0 / 6.0),
            (1.0, 1.0 / 6.0),
        ];
        for (i, &(x, w)) in expected.iter().enumerate() {
            assert!((gll.points[i] - x).abs() < 1e-15);
            assert!((gll.weights[i] - w).abs() < 1e-15);
        }
    }
}
