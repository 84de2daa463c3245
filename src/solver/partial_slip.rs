//! Coulomb friction with stick: the tangential contact problem of one tangential loading
//! (issue 30, its first step), after the normal problem.
//!
//! Unknowns: the tangential force F_j at each contact point that carries pressure (N, along
//! +τ_j on body 1 and −τ_j on body 2) and the plate's rigid shift δ along x (mm), under a
//! tangential load Q on body 1's plate (N along +x: force control). With A_tt the tangential
//! flexibility ([`crate::contact::CondensedContact::tangential_flexibility`]), body 1's slip
//! against body 2 at point i, measured from the normally loaded state, is
//!
//!   s_i = Σ_j A_tt,ij F_j + δ τ_i,x.
//!
//! Each point sticks, s_i = 0 and |F_i| ≤ μ P_i, or slips, F_i = −μ P_i sign(s_i); the plate
//! is in equilibrium, Σ F_j τ_j,x + Q = 0. The normal load is taken as applied first without
//! tangential traction, Cattaneo's assumption, exact where the normal loading makes no slip of
//! its own: two bodies of the same elastic constants in the half-space limit (Dundurs' β = 0).
//! A finite geometry's own slip under the normal load (A_ntᵀ P, nonzero for two blocks of
//! different shapes) is not counted: measured from the unloaded state it made the stick zone
//! of `hertz` lopsided by a tenth of its width and the shear 17 % of μp₀ off Cattaneo's.
//!
//! This is the loading of a contact from no tangential force to Q in one monotonic stage
//! (the slip zones only grow), for which the final state does not depend on the path: Cattaneo
//! and Mindlin's problem. The normal forces are taken as given (from the frictionless normal
//! solve): the tangential forces' effect on the pressure (A_nt F) is left out, which is exact
//! for two bodies of the same elastic constants in the half-space limit (Dundurs' β = 0) and
//! the caller's responsibility otherwise.
//!
//! The solve is a primal–dual active-set iteration on the stick set: solve the stick points'
//! equations with the slip points' forces at ±μP, move stick points whose force exceeds μP
//! to slip (in the force's direction) and slip points whose slip runs against their force
//! back to stick, until neither set changes. Each iteration is one dense solve of the stick
//! points and δ.

use crate::dense::DenseLu;

/// The solution of the tangential problem.
#[derive(Clone, Debug, PartialEq)]
pub struct PartialSlip {
    /// Tangential force at each contact point on body 1, N, along +τ (0 where P = 0).
    pub force: Vec<f64>,
    /// Whether each point sticks (false where it slips or carries no pressure).
    pub stick: Vec<bool>,
    /// Body 1's slip against body 2 along τ at each point, mm (0 where it sticks).
    pub slip: Vec<f64>,
    /// The plate's rigid shift along x, mm.
    pub shift: f64,
    /// Body 1's tangential displacement against body 2 at each point at the stage's end, mm,
    /// from the normally loaded state: the next stage's slip is measured from it.
    pub displacement: Vec<f64>,
    /// The tangential force on body 1's plate, N along +x (−Σ F_j τ_j,x: the load itself under
    /// force control, what the shift needs under displacement control).
    pub load: f64,
    /// Active-set iterations.
    pub iterations: usize,
}

/// Why the tangential problem has no partial-slip solution.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum PartialSlipError {
    /// The load reaches the friction limit: every point slips (gross slip). With μ = 0 the
    /// limit is 0: nothing holds any tangential load.
    #[error("the tangential load {load:.6e} N reaches the friction limit μ Σ P τ_x = {limit:.6e} N: that is gross slip, not partial slip")]
    GrossSlip {
        /// |Q|, N.
        load: f64,
        /// What friction can hold, N.
        limit: f64,
    },
    /// The active sets did not settle, or a stick system was singular.
    #[error("the stick/slip iteration did not settle in {iterations} iterations")]
    NotSettled {
        /// Iterations made.
        iterations: usize,
    },
}

/// How a stage's tangential loading is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TangentialControl {
    /// A tangential force Q on body 1's plate, N along +x (a fretting test under force
    /// control). Below the friction limit only: at it the shift is undetermined.
    Force(f64),
    /// The plate's shift δ against body 2's supports, mm along +x (displacement control).
    /// Any shift: beyond the gross-slip shift every point slips and the force is the limit,
    /// so that today's full slip comes out of the same solve.
    Displacement(f64),
}

/// The tangential problem's data: `a_tt` (mm/N, row-major N × N), the tangents' x
/// components `tangent_x`, the normal forces `normal_force` (N, ≥ 0) and μ.
pub struct TangentialProblem<'a> {
    /// A_tt, mm/N.
    pub a_tt: &'a [f64],
    /// τ_i,x of each contact point.
    pub tangent_x: &'a [f64],
    /// Normal contact force P_i at each point, N.
    pub normal_force: &'a [f64],
    /// Coulomb's μ.
    pub friction: f64,
    /// What the normal forces' change since the normal loading adds (the coupled problem of
    /// [`crate::fretting`]); None: nothing (Cattaneo's uncoupled problem).
    pub coupling: Option<NormalChange<'a>>,
}

/// What a change of the normal forces and of the plate's rigid motion since the normal loading
/// does to the tangential problem: a slip at every point and a force along x on body 1.
#[derive(Clone, Copy, Debug)]
pub struct NormalChange<'a> {
    /// Body 1's tangential displacement against body 2 at each point, mm: −Σ_j A_nt,ji ΔP_j
    /// (body 1 carries −n_j ΔP_j) plus τ_i·φ_k Δλ_k of the plate's rigid motion.
    pub slip: &'a [f64],
    /// The x force the normal forces' change puts on body 1, −Σ n_j,x ΔP_j, N.
    pub x_force: f64,
}

/// Most active-set iterations: each moves at least one point, and a loading from rest moves
/// each point at most once from stick to slip.
const MAX_ITERATIONS: usize = 500;

/// The relative margin of the active-set tests (a force beyond μP, a slip against its force):
/// far above the solves' round-off (1e-13 of the forces and displacements), far below any
/// physical excess.
const ROUND_OFF: f64 = 1e-10;

impl TangentialProblem<'_> {
    /// Solve for the tangential load `load` (N along +x on body 1's plate), loaded from the
    /// normally loaded state without tangential force.
    pub fn solve(&self, load: f64) -> Result<PartialSlip, PartialSlipError> {
        self.solve_from(load, None)
    }

    /// Solve for the tangential load `load` (N), reached from the state `from` by a monotonic
    /// change of the load (None: from no tangential force). The stick condition holds for the
    /// change: a point sticks when it does not slip in this stage, whatever it slipped before
    /// (Mindlin and Deresiewicz's unloading, a fretting cycle's half: the history matters);
    /// `slip` of the result is this stage's slip.
    pub fn solve_from(
        &self,
        load: f64,
        from: Option<&PartialSlip>,
    ) -> Result<PartialSlip, PartialSlipError> {
        self.solve_stage(TangentialControl::Force(load), from)
    }

    /// The stage of [`TangentialProblem::solve_from`] under either control: a force on the
    /// plate, or the plate's shift (then without a friction limit: a shift beyond the gross-slip
    /// one slips every point).
    pub fn solve_stage(
        &self,
        control: TangentialControl,
        from: Option<&PartialSlip>,
    ) -> Result<PartialSlip, PartialSlipError> {
        let n = self.normal_force.len();
        // The relative tangential displacement the previous state had: a stage's slip is
        // measured from it.
        let base = match from {
            Some(state) => state.displacement.clone(),
            None => vec![0.0; n],
        };
        let loaded: Vec<usize> = (0..n).filter(|&i| self.normal_force[i] > 0.0).collect();
        let limit: f64 = loaded
            .iter()
            .map(|&i| self.friction * self.normal_force[i] * self.tangent_x[i].abs())
            .sum();
        // (Round-off of the two sums must not turn the limit itself into partial slip.)
        if let TangentialControl::Force(load) = control {
            if load.abs() >= limit * (1.0 - 1e-12) {
                return Err(PartialSlipError::GrossSlip {
                    load: load.abs(),
                    limit,
                });
            }
        }
        // Slip direction of each point: 0 stick, ±1 the sign of its slip.
        let mut direction = vec![0i8; n];
        let mut force = vec![0.0; n];
        let mut shift = match control {
            TangentialControl::Displacement(shift) => shift,
            TangentialControl::Force(_) => 0.0,
        };
        let mut lu = DenseLu::default();
        for iteration in 1..=MAX_ITERATIONS {
            for &i in &loaded {
                if direction[i] != 0 {
                    force[i] = -f64::from(direction[i]) * self.friction * self.normal_force[i];
                }
            }
            let stick: Vec<usize> = loaded
                .iter()
                .copied()
                .filter(|&i| direction[i] == 0)
                .collect();
            self.solve_stick(&stick, (control, &base), &mut force, &mut shift, &mut lu)
                .ok_or(PartialSlipError::NotSettled {
                    iterations: iteration,
                })?;
            let slip: Vec<f64> = (self.displacement(&force, shift).iter())
                .zip(&base)
                .map(|(d, b)| d - b)
                .collect();
            // Points that slipped in an earlier stage sit at |F| = μP exactly, and a stage that
            // changes the load by nothing (a dwell, a peak recomputed) leaves them round-offs
            // from either test: without a margin they went in and out until the iteration
            // limit (a review: 0.6 μP → 0.6 μP, NotSettled after 500 iterations).
            let scale = (slip.iter().chain(&base))
                .chain(&self.displacement(&force, shift))
                .fold(0.0f64, |m, v| m.max(v.abs()));
            let slip_margin = ROUND_OFF * scale;
            let mut changed = false;
            for &i in &loaded {
                let bound = self.friction * self.normal_force[i];
                if direction[i] == 0 && force[i].abs() > bound * (1.0 + ROUND_OFF) {
                    // Friction opposes the slip: a force along +τ means slip along −τ.
                    direction[i] = if force[i] > 0.0 { -1 } else { 1 };
                    changed = true;
                } else if direction[i] != 0 && slip[i] * f64::from(direction[i]) < -slip_margin {
                    direction[i] = 0;
                    changed = true;
                }
            }
            if !changed {
                let stick = (0..n)
                    .map(|i| self.normal_force[i] > 0.0 && direction[i] == 0)
                    .collect();
                let slip = slip
                    .iter()
                    .enumerate()
                    .map(|(i, &s)| if direction[i] == 0 { 0.0 } else { s })
                    .collect();
                let load = -force
                    .iter()
                    .zip(self.tangent_x)
                    .map(|(f, t)| f * t)
                    .sum::<f64>()
                    - self.coupling.map_or(0.0, |c| c.x_force);
                let displacement = self.displacement(&force, shift);
                return Ok(PartialSlip {
                    force,
                    stick,
                    slip,
                    shift,
                    displacement,
                    load,
                    iterations: iteration,
                });
            }
        }
        Err(PartialSlipError::NotSettled {
            iterations: MAX_ITERATIONS,
        })
    }

    /// Body 1's tangential displacement against body 2 at every point for forces `force` and
    /// shift `shift`, mm, from the normally loaded state (elastic part and the plate's shift).
    fn displacement(&self, force: &[f64], shift: f64) -> Vec<f64> {
        let n = force.len();
        (0..n)
            .map(|i| {
                let row = &self.a_tt[i * n..(i + 1) * n];
                let tangential: f64 = row.iter().zip(force).map(|(a, f)| a * f).sum();
                let coupled = self.coupling.map_or(0.0, |c| c.slip[i]);
                tangential + shift * self.tangent_x[i] + coupled
            })
            .collect()
    }

    /// The stick points' forces (and under force control the shift), with the slip points'
    /// forces fixed in `force`: each stick point's displacement kept at `base` (no slip in this
    /// stage), and the plate's equilibrium under the load or its shift held. None if singular.
    fn solve_stick(
        &self,
        stick: &[usize],
        (control, base): (TangentialControl, &[f64]),
        force: &mut [f64],
        shift: &mut f64,
        lu: &mut DenseLu,
    ) -> Option<()> {
        let n = force.len();
        let force_control = matches!(control, TangentialControl::Force(_));
        // Under displacement control the shift is known and the equilibrium row goes.
        let m = stick.len() + usize::from(force_control);
        if m == 0 {
            return Some(());
        }
        let mut sticks = vec![false; n];
        for &i in stick {
            sticks[i] = true;
        }
        let matrix = lu.storage(m);
        let mut rhs = vec![0.0; m];
        for (r, &i) in stick.iter().enumerate() {
            for (c, &j) in stick.iter().enumerate() {
                matrix[r * m + c] = self.a_tt[i * n + j];
            }
            let fixed: f64 = (0..n)
                .filter(|&j| !sticks[j])
                .map(|j| self.a_tt[i * n + j] * force[j])
                .sum();
            rhs[r] = base[i] - fixed - self.coupling.map_or(0.0, |c| c.slip[i]);
            if force_control {
                matrix[r * m + m - 1] = self.tangent_x[i];
            } else {
                rhs[r] -= *shift * self.tangent_x[i];
            }
        }
        if let TangentialControl::Force(load) = control {
            for (c, &j) in stick.iter().enumerate() {
                matrix[(m - 1) * m + c] = self.tangent_x[j];
            }
            matrix[(m - 1) * m + m - 1] = 0.0;
            let slipping: f64 = (0..n)
                .filter(|&j| !sticks[j])
                .map(|j| force[j] * self.tangent_x[j])
                .sum();
            rhs[m - 1] = -load - slipping - self.coupling.map_or(0.0, |c| c.x_force);
        }
        if !lu.factor_in_place() {
            return None;
        }
        let mut scratch = vec![0.0; m];
        lu.solve_in_place(&mut rhs, &mut scratch);
        if !rhs.iter().all(|v| v.is_finite()) {
            return None;
        }
        for (r, &i) in stick.iter().enumerate() {
            force[i] = rhs[r];
        }
        if force_control {
            *shift = rhs[m - 1];
        }
        Some(())
    }
}

/// The edge c of a stick zone |x| < c from a margin that vanishes there like a square root,
/// d = D √(1 − x²/c²) (Cattaneo's μp − |q|, Mindlin and Deresiewicz's 2μp − |Δq|), by
/// [`crate::checks::edge_fit::square_root_edge`] through the stick points (`stick`) beyond
/// half of `guess` (mm). `x` in mm, `d` in any unit.
pub fn fitted_edge(x: &[f64], d: &[f64], stick: &[bool], guess: f64) -> f64 {
    let inside = (x.iter().zip(d).zip(stick))
        .filter(|((xi, _), st)| **st && xi.abs() > 0.5 * guess)
        .map(|((xi, di), _)| (*xi, *di));
    crate::checks::edge_fit::square_root_edge(inside)
}
