//! The heat problem reduced to the few hundred shapes its inputs can excite, and integrated
//! exactly in time in them.
//!
//! # Why a reduced model
//!
//! A wear run takes thousands of steps, each a contact solve of a few microseconds. The heat
//! problem of punch-b40 has 7 000 unknowns with their internal modes; one sparse solve of it
//! costs more than a whole contact step, and a time integrator needs one or two per step, or
//! many more to be accurate over a step that spans ten half periods. But the heat enters
//! only through the n contact points (the frictional flux, one value per point) and a few
//! fixed sources (ambient, held edges, the initial field), and the run needs the temperature
//! only through linear functionals (the thermal gap and the temperatures at the contact
//! points and probes). So the field is sought in the space that those inputs excite.
//!
//! # The space: rational Krylov
//!
//! With B the input vectors (N × m), V spans (K + σ_i C)⁻¹ B for a few real shifts σ_i ≥ 0
//! (and (K⁻¹C) K⁻¹ B at σ = 0, a second moment): the Galerkin projection onto V reproduces
//! the transfer function H(s) = (K + sC)⁻¹ B of the full model and its derivative at every
//! shift (the projection of a symmetric pencil matches two moments per shift). σ = 0 makes
//! every stationary temperature under the inputs exact, so the steady state and the energy
//! balance of the reduced model are those of the full one. The shifts between 1/(the
//! slowest time of the problem) and 1/(the shortest step) place the reduced model's error
//! where the run does not look: a response faster than the shortest step has decayed by the
//! step's end. V is orthonormalised in the capacity inner product (twice, dropping the
//! directions of a new block of which less than a thousandth is new: the blocks of nearby
//! shifts are nearly parallel).
//!
//! # Cost
//!
//! A block of m inputs costs a factorisation, m solves and its Gram–Schmidt against the r
//! directions kept so far, 4 N r m flops a pass: the set-up grows as N r m, and r itself
//! grows with m (the blocks of all shifts together keep half to two thirds of their
//! directions). So the caller keeps m small: the run's contact heat enters as a few smooth
//! shapes along the contact, not one input per point (`wear::thermal::shapes`: 24 inputs
//! and 165 modes instead of 67 and 305 on punch-b40-heat), and N small: most elements'
//! temperature is in the trunk space (`super::spaces`: 3 953 unknowns instead of 6 809). The basis is built in
//! the module `krylov`: the shifts factorised and solved two at a time (as many as there are
//! threads), the dense products of the Gram–Schmidt, of VᵀKV and of the modes split by rows
//! among the threads.
//!
//! # The modes and their exact integration
//!
//! In V the pencil is VᵀKV a + ȧ = Vᵀ f (VᵀCV = I); its eigenvectors give modes Φ = V Q with
//! ΦᵀCΦ = I and ΦᵀKΦ = diag(λ_j). Each modal coordinate obeys ȧ_j = −λ_j a_j + φ_jᵀ f(t), which
//! is integrated in closed form for the time profiles of the run: a source held constant for
//! a time τ, a_j ← e^{−λ_j τ} a_j + (1 − e^{−λ_j τ})/λ_j φ_jᵀ f, and the frictional heat of a
//! half period of reciprocating sliding, whose speed u₀ω sin ωs makes the flux a half sine:
//! ∫₀^{π/ω} e^{−λ(π/ω − s)} sin ωs ds = ω (1 + e^{−λπ/ω})/(λ² + ω²). No time step enters: the
//! only approximation is the space, which the tests measure against the full model
//! ([`super::transient`]) on the shipped and on refined meshes.
//!
//! # A flowing body: no modes, an exact propagator
//!
//! Advection makes K non-symmetric (a body whose material moves through the contact under
//! monotonic sliding). The Krylov space is built the same way, with LU in place of Cholesky
//! (a one-sided projection then matches one moment per shift, not two), but VᵀKV = M has no
//! real orthogonal eigenvectors and may be far from normal, so it is not diagonalised: the
//! reduced state is V's coordinates, ȧ = −M a + Vᵀf, and a step of length τ under a source
//! held constant is a ↦ Φ a + Γ Vᵀf with Φ = e^{−Mτ} and Γ = ∫₀^τ e^{−Ms} ds, computed by
//! [`propagator`] (Taylor series after scaling, then squaring: robust to non-normality, and
//! exact to round-off). The sliding's speed is constant, so the step lengths are few and
//! each pair is computed once.

use super::blocks::{BlockOperator, PairedMatrices};
use super::krylov::{rows_product, symmetric_product, transpose_product, Basis};
use faer::{Mat, MatRef, Side};

/// The heat problem's operators as the reduction needs them: K and C as blocks (for products
/// with the basis) and as sparse matrices on one pattern (for the factorisations of K + σC).
#[derive(Clone, Copy)]
pub struct HeatOperators<'a> {
    /// K (mW/K) as blocks.
    pub conductivity: &'a BlockOperator,
    /// C (mJ/K) as blocks.
    pub capacity: &'a BlockOperator,
    /// K and C assembled on their common pattern.
    pub matrices: &'a PairedMatrices,
    /// Whether K is symmetric (no body's material flows).
    pub symmetric: bool,
}

/// The modes of the reduced heat problem.
#[derive(Clone, Debug)]
pub struct ReducedModel {
    /// Φ (N × r): C-orthonormal, K-orthogonal modes over the free unknowns; with a flowing
    /// body, the C-orthonormal basis V.
    pub modes: Mat<f64>,
    /// λ_j (1/s), rising; 0 for a body that keeps its heat (no edge or face lets it out).
    /// Empty with a flowing body.
    pub rates: Vec<f64>,
    /// With a flowing body: M = VᵀKV (r × r, 1/s), the reduced problem being ȧ = −M a + Vᵀf.
    pub coupling: Option<Mat<f64>>,
}

/// Errors of the reduction.
#[derive(Debug, thiserror::Error)]
pub enum ReductionError {
    /// K + σC is not positive definite (singular, with a flowing body) at a shift.
    #[error("the heat problem's matrix K + {shift} C cannot be factorised (at σ = 0: no heat can leave; choose shifts > 0)")]
    NotDefinite {
        /// The shift σ, 1/s.
        shift: f64,
    },
    /// An eigendecomposition failed.
    #[error("the reduced heat problem's eigendecomposition failed")]
    Eigen,
}

impl ReducedModel {
    /// The reduced model of C Ṫ + K T = f over the space of `inputs` (N × m, one input per
    /// column) at `shifts` σ ≥ 0 (1/s), with the vectors `extra` added as they are (a
    /// constant field, the initial field). At σ = 0 the second moment K⁻¹ C K⁻¹ B is added too.
    pub fn new(
        operators: HeatOperators<'_>,
        inputs: MatRef<'_, f64>,
        shifts: &[f64],
        extra: &[Vec<f64>],
    ) -> Result<ReducedModel, ReductionError> {
        // V is C-orthonormal; the eigenvectors Q of VᵀKV make Φ = V Q K-orthogonal too.
        // V is read in place (an owned copy would be N r more values of fresh memory).
        let basis = Basis::krylov(operators, inputs, shifts, extra)?;
        let v = basis.view();
        let kv = operators.conductivity.apply_parallel(v);
        if !operators.symmetric {
            return Ok(ReducedModel {
                modes: v.to_owned(),
                rates: Vec::new(),
                coupling: Some(transpose_product(v, kv.as_ref())),
            });
        }
        // Its lower triangle is all the eigensolver reads.
        let reduced = symmetric_product(v, kv.as_ref());
        drop(kv);
        let eigen = reduced
            .self_adjoint_eigen(Side::Lower)
            .map_err(|_| ReductionError::Eigen)?;
        let s = eigen.S().column_vector();
        // Round-off leaves the rates of a body without exit at ±1e-16 of the largest.
        let largest = (0..s.nrows()).map(|i| s[i].abs()).fold(0.0f64, f64::max);
        let rates = (0..s.nrows())
            .map(|i| if s[i] < 1e-13 * largest { 0.0 } else { s[i] })
            .collect();
        Ok(ReducedModel {
            modes: rows_product(v, eigen.U()),
            rates,
            coupling: None,
        })
    }

    /// Number of modes r.
    pub fn len(&self) -> usize {
        self.modes.ncols()
    }

    /// Whether there are no modes.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Φᵀ f for each column f of `loads` (N × m): the modal loads (r × m). Loads on a few
    /// unknowns (the contact's heat: its traces) are projected over those rows only.
    pub fn project(&self, loads: MatRef<'_, f64>) -> Mat<f64> {
        let rows: Vec<usize> = (0..loads.nrows())
            .filter(|&i| loads.row(i).iter().any(|&x| x != 0.0))
            .collect();
        if 2 * rows.len() > loads.nrows() {
            return self.modes.transpose() * loads;
        }
        let modes = Mat::from_fn(rows.len(), self.len(), |i, j| self.modes[(rows[i], j)]);
        let loads = Mat::from_fn(rows.len(), loads.ncols(), |i, j| loads[(rows[i], j)]);
        modes.transpose() * loads
    }

    /// The modal coordinates of a field given over the free unknowns: Φᵀ C x.
    pub fn coordinates(&self, capacity: &BlockOperator, field: &[f64]) -> Vec<f64> {
        let cx = capacity.apply_vector(field);
        (0..self.len())
            .map(|j| (0..field.len()).map(|i| self.modes[(i, j)] * cx[i]).sum())
            .collect()
    }

    /// The field (free unknowns) of modal coordinates `a`: Φ a.
    pub fn field(&self, a: &[f64]) -> Vec<f64> {
        (0..self.modes.nrows())
            .map(|i| (0..self.len()).map(|j| self.modes[(i, j)] * a[j]).sum())
            .collect()
    }
}

/// Φ = e^{−Mτ} and Γ = ∫₀^τ e^{−Ms} ds for a square M (1/s) and a time τ (s): the exact map
/// a ↦ Φ a + Γ b of ȧ = −M a + b over τ with b held constant. M is scaled by 2^{−s} until
/// ‖Mτ‖₁ 2^{−s} ≤ 1/2, where the Taylor series of Γ/τ = Σ (−Mτ)ⁿ/(n+1)! to n = 16 leaves
/// 2e-21 (Horner's scheme), Φ = I − Mτ·Γ/τ; then s doublings Γ(2τ) = (I + Φ(τ))Γ(τ),
/// Φ(2τ) = Φ(τ)². A singular M (a body that keeps its heat) needs no special case.
pub fn propagator(matrix: MatRef<'_, f64>, time: f64) -> (Mat<f64>, Mat<f64>) {
    let r = matrix.nrows();
    let norm = (0..r)
        .map(|j| (0..r).map(|i| matrix[(i, j)].abs()).sum::<f64>())
        .fold(0.0f64, f64::max)
        * time;
    let doublings = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let step = time / 2f64.powi(doublings);
    let scaled = Mat::from_fn(r, r, |i, j| -step * matrix[(i, j)]);
    let identity = Mat::<f64>::identity(r, r);
    // P = Σ_{n=0}^{16} Aⁿ/(n+1)!, A = −Mτ', by Horner: P ← I/(n+1)! + A P.
    let terms = 16;
    let factorial = |n: usize| (1..=n).map(|k| k as f64).product::<f64>();
    let mut series = &identity * (1.0 / factorial(terms + 1));
    for n in (0..terms).rev() {
        series = &identity * (1.0 / factorial(n + 1)) + &scaled * &series;
    }
    let mut phi = &identity + &scaled * &series;
    let mut gamma = series * step;
    for _ in 0..doublings {
        gamma = &gamma + &phi * &gamma;
        phi = &phi * &phi;
    }
    (phi, gamma)
}

/// The propagator of `k` steps of the one `single` is the propagator of (k ≥ 1): by binary
/// powering, 2 log₂ k products of pairs instead of a new series; a step `a` then a step `b`
/// is (Φ_b Φ_a, Φ_b Γ_a + Γ_b).
pub fn propagator_power(single: &(Mat<f64>, Mat<f64>), k: usize) -> (Mat<f64>, Mat<f64>) {
    let compose =
        |a: &(Mat<f64>, Mat<f64>), b: &(Mat<f64>, Mat<f64>)| (&b.0 * &a.0, &b.0 * &a.1 + &b.1);
    let mut result: Option<(Mat<f64>, Mat<f64>)> = None;
    let mut base = single.clone();
    let mut k = k;
    while k > 0 {
        if k & 1 == 1 {
            result = Some(match result {
                None => base.clone(),
                Some(r) => compose(&r, &base),
            });
        }
        k >>= 1;
        if k > 0 {
            base = compose(&base, &base);
        }
    }
    result.unwrap_or_else(|| {
        let r = single.0.nrows();
        (Mat::identity(r, r), Mat::zeros(r, r))
    })
}

/// e^{−λτ} for a rate λ (1/s) and a time τ (s).
pub fn decay(rate: f64, time: f64) -> f64 {
    (-rate * time).exp()
}

/// ∫₀^τ e^{−λ(τ − s)} ds = (1 − e^{−λτ})/λ (s): the response after τ to a unit source held
/// constant; τ itself for λ = 0.
pub fn constant_gain(rate: f64, time: f64) -> f64 {
    let x = rate * time;
    if x < 1e-8 {
        // The series 1 − x/2 + x²/6: the closed form loses its digits for small x.
        time * (1.0 - 0.5 * x)
    } else {
        -(-x).exp_m1() / rate
    }
}

/// ∫₀^{π/ω} e^{−λ(π/ω − s)} sin ωs ds = ω (1 + e^{−λπ/ω})/(λ² + ω²) (s): the response at the
/// end of a half period to a source of amplitude 1 whose time profile is sin ωs.
pub fn half_sine_gain(rate: f64, omega: f64) -> f64 {
    omega * (1.0 + decay(rate, std::f64::consts::PI / omega)) / (rate * rate + omega * omega)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Simpson's rule of the convolution, fine enough to judge the closed forms to 1e-10.
    fn convolve(rate: f64, time: f64, profile: impl Fn(f64) -> f64) -> f64 {
        let n = 20_000;
        let h = time / n as f64;
        (0..=n)
            .map(|k| {
                let s = k as f64 * h;
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * (-rate * (time - s)).exp() * profile(s)
            })
            .sum::<f64>()
            * h
            / 3.0
    }

    #[test]
    fn propagator_of_a_diagonalisable_matrix_is_its_modal_map() {
        // M = Q diag(λ) Q⁻¹ with a non-orthogonal Q (far from normal) and λ from 0 (a
        // sealed body) to 1e4 1/s (stiff): Φ = Q e^{−λτ} Q⁻¹, Γ = Q diag(constant_gain) Q⁻¹.
        // Round-off grows with the doublings (20 of them at ‖M‖τ = 4e5) and with Q's
        // condition: measured 2.3e-9 of Φ's largest entry at τ = 40 s; 1e-8 of it bounds that,
        // far below the 1e-3 the reduced model itself is accurate to.
        let rates = [0.0, 0.3, 7.0, 250.0, 1.0e4];
        let q = Mat::from_fn(5, 5, |i, j| {
            if i == j {
                1.0
            } else {
                0.9f64.powi((i + 2 * j) as i32)
            }
        });
        use faer::linalg::solvers::DenseSolveCore;
        let q_inverse = q.as_ref().partial_piv_lu().inverse();
        let diagonal = |f: &dyn Fn(f64) -> f64| {
            let d = Mat::from_fn(5, 5, |i, j| if i == j { f(rates[i]) } else { 0.0 });
            &q * d * &q_inverse
        };
        let matrix = diagonal(&|l| l);
        for time in [1e-3, 0.5, 40.0] {
            let (phi, gamma) = propagator(matrix.as_ref(), time);
            // And as 7 steps of a seventh.
            let (phi7, gamma7) = propagator_power(&propagator(matrix.as_ref(), time / 7.0), 7);
            let exact_phi = diagonal(&|l| decay(l, time));
            let exact_gamma = diagonal(&|l| constant_gain(l, time));
            for i in 0..5 {
                for j in 0..5 {
                    let largest = exact_phi.norm_max();
                    assert!(
                        (phi[(i, j)] - exact_phi[(i, j)]).abs() < 1e-8 * largest,
                        "Φ at {time}: {} vs {}",
                        phi[(i, j)],
                        exact_phi[(i, j)]
                    );
                    assert!(
                        (phi7[(i, j)] - exact_phi[(i, j)]).abs() < 1e-8 * largest,
                        "Φ⁷ at {time}"
                    );
                    assert!(
                        (gamma7[(i, j)] - exact_gamma[(i, j)]).abs()
                            < 1e-8 * exact_gamma.norm_max(),
                        "Γ⁷ at {time}"
                    );
                    let scale = exact_gamma.norm_max();
                    assert!(
                        (gamma[(i, j)] - exact_gamma[(i, j)]).abs() < 1e-8 * scale,
                        "Γ at {time}: {} vs {}",
                        gamma[(i, j)],
                        exact_gamma[(i, j)]
                    );
                }
            }
        }
    }

    #[test]
    fn gains_are_the_convolutions() {
        for rate in [0.0, 1e-9, 0.3, 10.0, 400.0] {
            let tau = 0.7;
            let numeric = convolve(rate, tau, |_| 1.0);
            assert!(
                (constant_gain(rate, tau) - numeric).abs() < 1e-10 * tau,
                "{rate}"
            );
            let omega = 10.0;
            let half = std::f64::consts::PI / omega;
            let numeric = convolve(rate, half, |s| (omega * s).sin());
            assert!(
                (half_sine_gain(rate, omega) - numeric).abs() < 1e-10,
                "{rate}"
            );
        }
    }
}
