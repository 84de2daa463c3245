//! The steady worn state found directly, without integrating the transient (paper §3, §4, §6).
//!
//! In a steady state the wear accumulated over one period must be a rigid-body motion of the
//! plate (paper eq. 16–18, A.5–A.13): Σ_halves W(p_i) = −(R c)_i at every contact point, with
//! W(p) = Σ_bodies β̃ ∫|v|ᵃdτ · pᵇ and c the rigid wear per period. For reciprocating sliding
//! the two half cycles see the same shape g but opposite friction, so the unknowns are
//! g, P⁺, P⁻, λ⁺, λ⁻ and c, and the equations are the two contact problems (Signorini and plate
//! equilibrium, eq. 8, 42–43) plus the wear compatibility and a gauge that fixes the rigid part
//! of g (g ⟂ range R). For monotonic sliding there is one contact problem.
//!
//! The system is solved by a semismooth Newton (primal–dual active-set) iteration on both
//! active sets at once: for b = 1 each iteration is one dense linear solve, and the iteration
//! stops when neither active set changes. The paper's §6 reaches the same state by a spline
//! optimisation (16 design variables, finite-difference gradients) or by a penalty iteration of
//! 300–500 steps; here the state is exact up to round-off and the discretisation.

use crate::contact::CondensedContact;
use crate::dense::DenseLu;

/// Settings of the steady-state solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadySettings {
    /// Most Newton / active-set iterations (default 100).
    pub max_iterations: usize,
    /// Relative residual at which a Newton step counts as converged for b ≠ 1 (default 1e-12).
    pub tolerance: f64,
}

impl Default for SteadySettings {
    fn default() -> Self {
        SteadySettings {
            max_iterations: 100,
            tolerance: 1e-12,
        }
    }
}

/// Why a steady state could not be computed.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum SteadyError {
    /// Without rigid-body freedom wear can only unload the contact: no steady state exists.
    #[error("a steady worn state needs a plate that can move (plate.motion = \"vertical\" or \"vertical_rotation\")")]
    NoRigidMotion,
    /// No wear law is active.
    #[error("no body wears (all β̃ are zero)")]
    NoWear,
}

/// Outcome of the steady-state solve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SteadyStatus {
    /// Active sets settled and residuals at round-off.
    Solved,
    /// Iteration limit reached; the last iterate is kept.
    MaxIterations,
    /// A linear system was singular; the last iterate is kept.
    Singular,
}

/// The steady (periodic) worn state.
#[derive(Clone, Debug)]
pub struct SteadyState {
    /// Worn shape g (mm) at the contact points, up to a rigid motion (g ⟂ range R).
    pub shape: Vec<f64>,
    /// Pressure of the '+' half cycle (the only one for monotonic sliding), MPa.
    pub p_plus: Vec<f64>,
    /// Pressure of the '−' half cycle (empty for monotonic sliding), MPa.
    pub p_minus: Vec<f64>,
    /// Rigid plate motion in each half cycle.
    pub rigid_plus: Vec<f64>,
    /// Rigid plate motion of the '−' half cycle.
    pub rigid_minus: Vec<f64>,
    /// Rigid wear per period (per step for monotonic sliding): λ_F in mm, λ_M in rad.
    pub rigid_wear: Vec<f64>,
    /// Status.
    pub status: SteadyStatus,
    /// Iterations.
    pub iterations: usize,
    /// Largest relative residual of the wear compatibility at the end.
    pub wear_residual: f64,
}

/// Wear of one half period at pressure p: Σ c pᵇ, and its derivative.
fn wear(terms: &[(f64, f64)], p: f64) -> (f64, f64) {
    let p = p.max(0.0);
    terms.iter().fold((0.0, 0.0), |(w, dw), &(c, b)| {
        let derivative = if p > 0.0 {
            c * b * p.powf(b - 1.0)
        } else if b == 1.0 {
            c
        } else {
            0.0
        };
        (w + c * p.powf(b), dw + derivative)
    })
}

/// Compute the steady worn state of `contact` for half-period wear `terms` (from
/// [`crate::wear::WearIntegrator::half_period_wear`]); `monotonic` selects one sliding direction.
pub fn steady_state(
    contact: &CondensedContact,
    terms: &[(f64, f64)],
    monotonic: bool,
    settings: SteadySettings,
) -> Result<SteadyState, SteadyError> {
    let (n, m) = (contact.len(), contact.rigid_modes.len());
    if m == 0 {
        return Err(SteadyError::NoRigidMotion);
    }
    if terms.iter().all(|t| t.0 == 0.0) {
        return Err(SteadyError::NoWear);
    }
    let halves = if monotonic { 1 } else { 2 };
    let area = contact.areas();
    let signs = [1.0, -1.0];
    let a: Vec<Vec<f64>> = (0..halves).map(|h| contact.gap_matrix(signs[h])).collect();
    let e: Vec<Vec<f64>> = (0..halves)
        .map(|h| contact.equilibrium_matrix(signs[h]))
        .collect();
    let r = contact.rigid_gap_matrix();
    let load = &contact.plate_load;
    // Unknown layout: g (n) | P_h (n each) | λ_h (m each) | c (m).
    let (off_p, off_l, off_c) = (n, n + halves * n, n + halves * n + halves * m);
    let size = off_c + m;
    let mut z = vec![0.0; size];
    let mut active = vec![vec![true; n]; halves];
    let mut lu = DenseLu::default();
    let mut scratch = vec![0.0; size];
    let mut status = SteadyStatus::MaxIterations;
    let mut iterations = 0;
    // Start from uniform pressure F/A in both halves (the monotonic optimum of a flat punch).
    let total_area: f64 = area.iter().sum();
    let mean_force = load.first().copied().unwrap_or(0.0).abs() / total_area;
    for h in 0..halves {
        for i in 0..n {
            z[off_p + h * n + i] = mean_force * area[i];
        }
    }
    for _ in 0..settings.max_iterations {
        iterations += 1;
        // Newton system J Δz = −F for the current active sets.
        let mat = lu.storage(size);
        let mut rhs = vec![0.0; size];
        let mut row = 0;
        for h in 0..halves {
            for i in 0..n {
                if active[h][i] {
                    // d_i = Σ_j A_ij P_j + Σ_k R_ik λ_k + g_i = 0
                    let mut d = z[i];
                    mat[row * size + i] = 1.0;
                    for j in 0..n {
                        mat[row * size + off_p + h * n + j] = a[h][i * n + j];
                        d += a[h][i * n + j] * z[off_p + h * n + j];
                    }
                    for k in 0..m {
                        mat[row * size + off_l + h * m + k] = r[i * m + k];
                        d += r[i * m + k] * z[off_l + h * m + k];
                    }
                    rhs[row] = -d;
                } else {
                    mat[row * size + off_p + h * n + i] = 1.0;
                    rhs[row] = -z[off_p + h * n + i];
                }
                row += 1;
            }
        }
        for h in 0..halves {
            for k in 0..m {
                let mut f = load[k];
                for j in 0..n {
                    mat[row * size + off_p + h * n + j] = e[h][k * n + j];
                    f += e[h][k * n + j] * z[off_p + h * n + j];
                }
                rhs[row] = -f;
                row += 1;
            }
        }
        // Wear compatibility: Σ_h W(P_h,i / area_i) + (R c)_i = 0.
        let mut wear_scale = 0.0f64;
        for i in 0..n {
            let mut f = 0.0;
            for h in 0..halves {
                let (w, dw) = wear(terms, z[off_p + h * n + i] / area[i]);
                f += w;
                wear_scale = wear_scale.max(w);
                mat[row * size + off_p + h * n + i] = dw / area[i];
            }
            for k in 0..m {
                mat[row * size + off_c + k] = r[i * m + k];
                f += r[i * m + k] * z[off_c + k];
            }
            rhs[row] = -f;
            row += 1;
        }
        // Gauge: Σ_i w_i R_ik g_i = 0 fixes the rigid part of the shape.
        for k in 0..m {
            let mut f = 0.0;
            for i in 0..n {
                mat[row * size + i] = area[i] * r[i * m + k];
                f += area[i] * r[i * m + k] * z[i];
            }
            rhs[row] = -f;
            row += 1;
        }
        let residual = rhs
            .iter()
            .skip(halves * n + halves * m)
            .take(n)
            .fold(0.0f64, |x, v| x.max(v.abs()))
            / wear_scale.max(f64::MIN_POSITIVE);
        if !lu.factor_in_place() {
            status = SteadyStatus::Singular;
            break;
        }
        lu.solve_in_place(&mut rhs, &mut scratch);
        for (zi, d) in z.iter_mut().zip(&rhs) {
            *zi += d;
        }
        // Active-set update from the new iterate.
        let mut changed = false;
        for h in 0..halves {
            let force_scale = (0..n)
                .map(|i| z[off_p + h * n + i].abs())
                .fold(0.0, f64::max);
            for i in 0..n {
                let p = z[off_p + h * n + i];
                let now = if active[h][i] {
                    p >= -1e-13 * force_scale
                } else {
                    let mut d = z[i];
                    for j in 0..n {
                        d += a[h][i * n + j] * z[off_p + h * n + j];
                    }
                    for k in 0..m {
                        d += r[i * m + k] * z[off_l + h * m + k];
                    }
                    d * a[h][i * n + i].recip() < -1e-13 * force_scale
                };
                changed |= now != active[h][i];
                active[h][i] = now;
                if !now {
                    z[off_p + h * n + i] = 0.0;
                }
            }
        }
        let step = rhs
            .iter()
            .skip(off_p)
            .take(halves * n)
            .fold(0.0f64, |x, v| x.max(v.abs()));
        let force_scale = z[off_p..off_l].iter().fold(0.0f64, |x, v| x.max(v.abs()));
        if !changed
            && residual < settings.tolerance.max(1e-14) * 1e3
            && step <= settings.tolerance * force_scale.max(f64::MIN_POSITIVE)
        {
            status = SteadyStatus::Solved;
            break;
        }
    }
    let pressure = |h: usize| {
        (0..n)
            .map(|i| z[off_p + h * n + i].max(0.0) / area[i])
            .collect::<Vec<f64>>()
    };
    let p_plus = pressure(0);
    let p_minus = if halves == 2 { pressure(1) } else { Vec::new() };
    let mut wear_residual = 0.0f64;
    let mut wear_scale = 0.0f64;
    for i in 0..n {
        let mut w = wear(terms, p_plus[i]).0;
        if halves == 2 {
            w += wear(terms, p_minus[i]).0;
        }
        wear_scale = wear_scale.max(w);
        let rc: f64 = (0..m).map(|k| r[i * m + k] * z[off_c + k]).sum();
        wear_residual = wear_residual.max((w + rc).abs());
    }
    Ok(SteadyState {
        shape: z[..n].to_vec(),
        p_plus,
        p_minus,
        rigid_plus: z[off_l..off_l + m].to_vec(),
        rigid_minus: if halves == 2 {
            z[off_l + m..off_l + 2 * m].to_vec()
        } else {
            Vec::new()
        },
        rigid_wear: z[off_c..off_c + m].to_vec(),
        status,
        iterations,
        wear_residual: wear_residual / wear_scale.max(f64::MIN_POSITIVE),
    })
}

/// The summed-pressure theory (paper eq. 16–19, A.13–A.16) for b = 1: in the periodic steady
/// state p⁺ + p⁻ is a rigid-body wear pattern, p_Σ,i = Σ_k a_k r_k(i) with r_k(i) = −R(i,k)
/// (1 under a flat punch, x̃ for the rotation, cos α on an arc), whose amplitudes a_k follow
/// from the equilibrium of the summed loads with the friction terms dropped (exact for a flat
/// contact, where they cancel; Remark 3 of Appendix A otherwise). Returns p_Σ in MPa at every
/// contact point, or `None` without rigid-body freedom.
pub fn summed_pressure_theory(contact: &CondensedContact) -> Option<Vec<f64>> {
    let (n, m) = (contact.len(), contact.rigid_modes.len());
    if m == 0 {
        return None;
    }
    let area = contact.areas();
    let r = contact.rigid_gap_matrix();
    // Frictionless summed equilibrium: Σ_i −R(i,k) S_i area_i = 2 L_k with S_i = Σ_l a_l (−R(i,l)),
    // since E = Rᵀ when μ = 0 and the plate carries twice its load over a period.
    let mut lu = DenseLu::default();
    let mat = lu.storage(m);
    for k in 0..m {
        for l in 0..m {
            mat[k * m + l] = (0..n).map(|i| r[i * m + k] * r[i * m + l] * area[i]).sum();
        }
    }
    if !lu.factor_in_place() {
        return None;
    }
    let mut amplitude: Vec<f64> = contact.plate_load.iter().map(|l| 2.0 * l).collect();
    let mut scratch = vec![0.0; m];
    lu.solve_in_place(&mut amplitude, &mut scratch);
    Some(
        (0..n)
            .map(|i| -(0..m).map(|k| r[i * m + k] * amplitude[k]).sum::<f64>())
            .collect(),
    )
}
