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
//! active sets at once: for b = 1 each iteration is one linear solve, and the iteration
//! stops when neither active set changes. The solve eliminates the system's identity and
//! diagonal blocks first (`step`), which leaves a dense system in about N unknowns instead
//! of 3N + 3m. The paper's §6 reaches the same state by a spline
//! optimisation (16 design variables, finite-difference gradients) or by a penalty iteration of
//! 300–500 steps; here the state is exact up to round-off and the discretisation.

use crate::complementarity::Direction;
use crate::contact::CondensedContact;
use crate::dense::DenseLu;
use crate::wear::law;
use crate::wear::WearTerms;

mod continuation;
mod starts;
mod step;
use step::{Jacobian, Workspace};

/// Settings of the steady-state solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadySettings {
    /// Most Newton / active-set iterations per solve (default 100).
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

/// Which sliding the steady state belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SteadySliding {
    /// Reciprocating sliding: a '+' and a '−' half cycle per period.
    Reciprocating,
    /// Monotonic sliding in one direction.
    Monotonic(Direction),
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
    /// Iteration limit reached; the last iterate is kept. Besides a genuinely hard problem,
    /// this is what happens when no steady state of the assumed form exists: if the friction
    /// moment separates the contact zones of the two half cycles, the periodic state rocks
    /// on two facets with a different rigid wear per half cycle (integrate in time instead).
    MaxIterations,
    /// A linear system was singular; the last iterate is kept.
    Singular,
    /// One of the paper's §6 methods ended, but its result fails the acceptance rule of
    /// [`crate::paper_steady::accept`]: its eq. 49 residual is too large for a steady state,
    /// or nothing (no exact steady state) confirms it; or the exact iteration ended, but its
    /// final state's wear residual exceeds [`FINAL_WEAR_RESIDUAL`]. Not a result.
    NotSteady,
}

/// The largest relative wear residual of a state reported as [`SteadyStatus::Solved`]: the
/// solved states of the shipped examples and the reviews' sweeps reach 1e-15 … 1e-10 (the
/// iteration stops at round-off), so 1e-6 separates them from any state whose wear is not
/// rigid by orders of magnitude.
pub const FINAL_WEAR_RESIDUAL: f64 = 1e-6;

/// The steady (periodic) worn state.
#[derive(Clone, Debug)]
pub struct SteadyState {
    /// The sliding it belongs to.
    pub sliding: SteadySliding,
    /// Worn shape g (mm) at the contact points, up to a rigid motion (g ⟂ range R). Where a
    /// point is out of contact in every half cycle the shape is not unique; the one given
    /// makes the point just graze (zero gap) in the half cycle where it comes closest.
    pub shape: Vec<f64>,
    /// Pressure of the '+' half cycle, MPa; for monotonic sliding the pressure of its one
    /// direction, whichever it is (see `sliding`).
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
    /// Newton iterations.
    pub iterations: usize,
    /// Largest relative residual of the wear compatibility at the end (at points out of
    /// contact throughout: how far the rigid wear would close their gap).
    pub wear_residual: f64,
    /// When the iteration with friction failed but the frictionless steady state was found:
    /// the friction coefficient up to which it was followed by continuation in μ (0: not
    /// even 1/64 of the problem's); `None` otherwise.
    pub friction_reached: Option<f64>,
}

/// How close (relative to the size of its gap's terms) a point's gap in another half cycle
/// must be to its closest half's for a point the rigid wear brings back to enter both: wide
/// enough for the nearly mirror-image halves of a nearly frictionless contact (their gaps
/// differ by about μ of the terms), narrow against the halves of a frictional one. On the
/// shipped examples at b = 0.5, 1, 2 and μ = 0 … 0.25 the steady states and their
/// iteration counts are the same as with the closest half only.
const NEARLY_AS_CLOSE: f64 = 1e-3;

/// Wear of one half period at pressure p: Σ c pᵇ, and the slope Newton's method uses
/// ([`law::newton_slope`]: the tangent, except for b < 1 terms of a law with b > 1 terms too,
/// which take the secant; at p = 0 the secant to the reference pressure `p_ref` (MPa), so that
/// a point just brought into contact keeps a wear row that depends on its own pressure, since
/// with a zero slope several such rows would leave the system singular).
fn wear(terms: &[(f64, f64)], p: f64, p_ref: f64) -> (f64, f64) {
    (
        law::half_period_wear(terms, p),
        law::newton_slope(terms, p, p_ref, false),
    )
}

/// The matrices of the coupled half-cycle contact problems and the unknown layout
/// g (n) | P_h (n each) | λ_h (m each) | c (m).
struct System<'a> {
    n: usize,
    m: usize,
    halves: usize,
    area: Vec<f64>,
    gap: Vec<Vec<f64>>,
    equilibrium: Vec<Vec<f64>>,
    rigid: Vec<f64>,
    load: &'a [f64],
    /// Mean contact pressure F/A (MPa): the scale of the secant slope at p = 0.
    reference_pressure: f64,
    /// A gap each half cycle sees besides the shape (mm, one per point; empty: none): the
    /// thermal distortion at the start of that half ([`steady_state_with_offsets`]).
    offset: Vec<Vec<f64>>,
}

impl System<'_> {
    fn size(&self) -> usize {
        self.n + self.halves * (self.n + self.m) + self.m
    }
    fn force(&self, h: usize, i: usize) -> usize {
        self.n + h * self.n + i
    }
    fn lambda(&self, h: usize, k: usize) -> usize {
        self.n + self.halves * self.n + h * self.m + k
    }
    fn wear_motion(&self, k: usize) -> usize {
        self.n + self.halves * (self.n + self.m) + k
    }
    /// Gap d_h,i = g_i + Σ_j A_ij P_j + Σ_k R_ik λ_k of half `h` at the iterate `z`.
    fn gap_at(&self, z: &[f64], h: usize, i: usize) -> f64 {
        let (n, m) = (self.n, self.m);
        let a = &self.gap[h][i * n..(i + 1) * n];
        z[i] + self.offset_at(h, i)
            + (0..n).map(|j| a[j] * z[self.force(h, j)]).sum::<f64>()
            + (0..m)
                .map(|k| self.rigid[i * m + k] * z[self.lambda(h, k)])
                .sum::<f64>()
    }
    /// The offset of half `h` at point `i` (mm).
    fn offset_at(&self, h: usize, i: usize) -> f64 {
        self.offset.get(h).map_or(0.0, |o| o[i])
    }
    /// Sum of the sizes of the terms of [`System::gap_at`] (mm): the scale of its round-off.
    fn gap_terms(&self, z: &[f64], h: usize, i: usize) -> f64 {
        let (n, m) = (self.n, self.m);
        let a = &self.gap[h][i * n..(i + 1) * n];
        z[i].abs()
            + self.offset_at(h, i).abs()
            + (0..n)
                .map(|j| (a[j] * z[self.force(h, j)]).abs())
                .sum::<f64>()
            + (0..m)
                .map(|k| (self.rigid[i * m + k] * z[self.lambda(h, k)]).abs())
                .sum::<f64>()
    }
    /// (R c)_i: how the rigid wear of one period changes the gap at point i.
    fn rigid_wear_gap(&self, z: &[f64], i: usize) -> f64 {
        (0..self.m)
            .map(|k| self.rigid[i * self.m + k] * z[self.wear_motion(k)])
            .sum()
    }
    fn out_of_contact(active: &[Vec<bool>], i: usize) -> bool {
        active.iter().all(|a| !a[i])
    }

    /// The Newton system at `z`: its matrix (by structure), its right-hand side (minus the
    /// residuals), and the largest relative residual of the wear rows with their scale.
    fn linearise<'s>(
        &'s self,
        terms: &WearTerms,
        z: &[f64],
        active: &'s [Vec<bool>],
    ) -> (Jacobian<'s, 's>, Vec<f64>, f64, f64, f64) {
        let (n, m, halves) = (self.n, self.m, self.halves);
        let mut rhs = Vec::with_capacity(self.size());
        // Gap rows d_h,i = 0 where in contact (linear, so their Newton rows are exact).
        for h in 0..halves {
            for i in 0..n {
                rhs.push(if active[h][i] {
                    -self.gap_at(z, h, i)
                } else {
                    -z[self.force(h, i)]
                });
            }
        }
        let mut unbalanced = 0.0f64;
        for h in 0..halves {
            for k in 0..m {
                let e = &self.equilibrium[h][k * n..(k + 1) * n];
                let f: f64 = self.load[k] + (0..n).map(|j| e[j] * z[self.force(h, j)]).sum::<f64>();
                let scale = self.load[k].abs()
                    + (0..n)
                        .map(|j| (e[j] * z[self.force(h, j)]).abs())
                        .sum::<f64>();
                unbalanced = unbalanced.max(f.abs() / scale.max(f64::MIN_POSITIVE));
                rhs.push(-f);
            }
        }
        // Wear compatibility Σ_h W(P_h,i / area_i) + (R c)_i = 0 where the point touches
        // in some half cycle. Where it touches in none it does not wear, its shape is free
        // and the row instead fixes that shape so that the point just grazes in the half
        // cycle where it comes closest.
        let mut slope = vec![vec![0.0; n]; halves];
        let mut closest = vec![0; n];
        let (mut wear_scale, mut residual) = (0.0f64, 0.0f64);
        for i in 0..n {
            if Self::out_of_contact(active, i) {
                closest[i] = (0..halves)
                    .min_by(|&a, &b| self.gap_at(z, a, i).total_cmp(&self.gap_at(z, b, i)))
                    .unwrap_or(0);
                rhs.push(-self.gap_at(z, closest[i], i));
                continue;
            }
            let mut f = self.rigid_wear_gap(z, i);
            for (h, slope) in slope.iter_mut().enumerate() {
                let (w, dw) = wear(
                    terms.at(i),
                    z[self.force(h, i)] / self.area[i],
                    self.reference_pressure,
                );
                f += w;
                wear_scale = wear_scale.max(w);
                slope[i] = dw / self.area[i];
            }
            rhs.push(-f);
            residual = residual.max(f.abs());
        }
        residual /= wear_scale.max(f64::MIN_POSITIVE);
        // Gauge: Σ_i w_i R_ik g_i = 0 fixes the rigid part of the shape.
        for k in 0..m {
            rhs.push(
                -(0..n)
                    .map(|i| self.area[i] * self.rigid[i * m + k] * z[i])
                    .sum::<f64>(),
            );
        }
        let jacobian = Jacobian {
            system: self,
            active,
            slope,
            closest,
            in_wear: terms.is_concave(),
        };
        (jacobian, rhs, residual, wear_scale, unbalanced)
    }

    /// Semismooth Newton on both active sets from `z`, `active`; returns the status and the
    /// number of iterations.
    fn newton(
        &self,
        terms: &WearTerms,
        z: &mut [f64],
        active: &mut [Vec<bool>],
        settings: SteadySettings,
    ) -> (SteadyStatus, usize) {
        let (n, halves) = (self.n, self.halves);
        let mut work = Workspace::default();
        let mut previous_step = f64::INFINITY;
        for iteration in 1..=settings.max_iterations {
            let (jacobian, mut rhs, residual, wear_scale, unbalanced) =
                self.linearise(terms, z, active);
            if jacobian.solve(&mut rhs, &mut work).is_none() {
                return (SteadyStatus::Singular, iteration);
            }
            // A pivot can be finite and still small enough for the solve to overflow: keep the
            // last finite iterate then.
            if rhs.iter().zip(z.iter()).any(|(d, v)| !(v + d).is_finite()) {
                return (SteadyStatus::Singular, iteration);
            }
            if terms.is_concave() {
                self.step_in_wear(terms, &jacobian, z, &mut rhs);
            }
            for (zi, d) in z.iter_mut().zip(&rhs) {
                *zi += d;
            }
            let changed = self.update_active_sets(terms, z, active, wear_scale);
            let step = (0..halves)
                .flat_map(|h| (0..n).map(move |i| (h, i)))
                .map(|(h, i)| rhs[self.force(h, i)].abs())
                .fold(0.0f64, f64::max);
            let force_scale = (0..halves)
                .flat_map(|h| (0..n).map(move |i| (h, i)))
                .map(|(h, i)| z[self.force(h, i)].abs())
                .fold(0.0f64, f64::max);
            // Newton's steps shrink quadratically until they reach the round-off of the
            // solve, about cond · ε of the forces: 4e-12 at 1025 contact points, above the
            // default tolerance of 1e-12, where they stop shrinking. A step below 1e-9 of the
            // forces that did not halve is that floor, not progress still to be made.
            let scale = force_scale.max(f64::MIN_POSITIVE);
            let at_round_off = step <= 1e-9 * scale && step >= 0.5 * previous_step;
            // The plate's equilibrium too: with every point out of contact nothing carries
            // the load, the Newton step cannot change that, and the empty state passed the
            // other tests (red team 21: monotonic sliding with the resultant off the punch,
            // "Solved" with no pressure and a rigid wear of 4e18 mm). Its rows are linear, so
            // at the iterate before the step they are off by at most round-off once the
            // active sets are right.
            if !changed
                && residual < settings.tolerance.max(1e-14) * 1e3
                && unbalanced < 1e-8
                && (step <= settings.tolerance * scale || at_round_off)
            {
                return (SteadyStatus::Solved, iteration);
            }
            previous_step = step;
        }
        (SteadyStatus::MaxIterations, settings.max_iterations)
    }

    /// For a concave law (every b ≤ 1), turn the step of the forces in contact into Newton's
    /// step in the wear ([`law::step_in_wear`]): quadratic convergence where the step in the
    /// pressure with a secant slope converged at a rate of 1 − b (b = 0.2: 92 iterations on
    /// punch-b40, b = 0.1: none in 100).
    fn step_in_wear(&self, terms: &WearTerms, jacobian: &Jacobian, z: &[f64], step: &mut [f64]) {
        for (h, active) in jacobian.active.iter().enumerate() {
            for i in (0..self.n).filter(|&i| active[i]) {
                let force = self.force(h, i);
                let area = self.area[i];
                let (p_hat, p) = (z[force] / area, (z[force] + step[force]) / area);
                let slope = jacobian.slope[h][i] * area;
                let next = law::step_in_wear(terms.at(i), p_hat, slope, p);
                step[force] = next * area - z[force];
            }
        }
    }

    /// Primal–dual active-set update; true if a set changed.
    fn update_active_sets(
        &self,
        terms: &WearTerms,
        z: &mut [f64],
        active: &mut [Vec<bool>],
        wear_scale: f64,
    ) -> bool {
        let (n, halves) = (self.n, self.halves);
        let mut changed = false;
        // A point out of contact in every half at the linearisation had no wear row: its shape
        // is free, and its row set it to graze in the half that was then the closest. After
        // the step another half may be the closer, with a negative gap there; that calls for
        // the shape to move (the next linearisation grazes in the new closest half), not for
        // contact. Only the rigid wear closing its gap (below) brings such a point back. Read
        // as contact, those gaps of a point far from the zone (the halves' gaps differ there
        // by the friction's part of the elastic displacement) brought 28 points in at once,
        // and the active sets cycled with period 6 (frictional short zones, punch-b40 loaded
        // on [1070, 1080] with mu = 0.02, 0.05: exit 1 where `run` reaches a steady state).
        let grazing: Vec<bool> = (0..n).map(|i| Self::out_of_contact(active, i)).collect();
        for h in 0..halves {
            let force_scale = (0..n)
                .map(|i| z[self.force(h, i)].abs())
                .fold(0.0, f64::max);
            for i in 0..n {
                let p = z[self.force(h, i)];
                let now = if active[h][i] {
                    p >= -1e-13 * force_scale
                } else if grazing[i] {
                    // Not converged while it penetrates here: the next linearisation grazes
                    // in this half instead, and the state written is then one whose points
                    // out of contact have no negative gap in any half (the pressures are the
                    // contact solution of the shape written).
                    if self.gap_at(z, h, i) < -1e-9 * self.gap_terms(z, h, i) {
                        changed = true;
                    }
                    false
                } else {
                    // A point in contact in another half has a wear row that fixes its shape:
                    // a gap below the round-off of its terms here is contact (red team 13:
                    // reading that round-off as contact brought every grazing point in at
                    // once, with b < 1 the iteration then cycled, 28 of 73 points in and out).
                    self.gap_at(z, h, i) * self.gap[h][i * n + i].recip() < -1e-13 * force_scale
                };
                changed |= now != active[h][i];
                active[h][i] = now;
                if !now {
                    z[self.force(h, i)] = 0.0;
                }
            }
        }
        // A point out of contact throughout stays so only if the rigid wear does not close its
        // gap; otherwise it comes back into contact in the half cycle where it is closest.
        for i in 0..n {
            if Self::out_of_contact(active, i) && self.rigid_wear_gap(z, i) < -1e-10 * wear_scale {
                // In the closest half, and in any other nearly as close: without friction the
                // halves are mirror images, and bringing the point into one of them only (as
                // round-off chose) broke the symmetry of the iterate, the halves' rigid motions
                // parted and the active sets cycled (red team 13, b < 1); with a little friction
                // (μ = 1e-10 … 1e-5, red team 14) the halves differ by about μ of the gap's
                // terms and the same happened. A half it should not touch in gets a negative
                // pressure at the next step and leaves again.
                let gaps: Vec<f64> = (0..halves).map(|h| self.gap_at(z, h, i)).collect();
                let closest = gaps.iter().copied().fold(f64::INFINITY, f64::min);
                let entering: Vec<usize> = (0..halves)
                    .filter(|&h| gaps[h] <= closest + NEARLY_AS_CLOSE * self.gap_terms(z, h, i))
                    .collect();
                for &h in &entering {
                    active[h][i] = true;
                }
                if terms.is_concave() {
                    // The point enters wearing what the rigid wear asks of it, shared by the
                    // halves it enters: for a concave law the pressure of that wear, not zero.
                    // From p = 0 (a secant to the mean pressure) its first step asked for far
                    // too much pressure, and at a zone's end with b = 0.1 the points there
                    // went in and out with period 5 (the load on the punch's last 5 mm).
                    let share = -self.rigid_wear_gap(z, i) / entering.len() as f64;
                    for &h in &entering {
                        z[self.force(h, i)] =
                            self.area[i] * law::pressure_of_wear(terms.at(i), share);
                    }
                }
                changed = true;
            }
        }
        changed
    }
}

/// What may lie behind a steady-state iteration that did not converge, for messages (one
/// sentence, no final period). With friction and a plate that turns, the state of the assumed
/// form may not exist (the friction moment can separate the half cycles' zones); without
/// either, it exists whenever the load can be balanced, and only the iteration failed (red
/// team 23: a translating punch at b = 0.15 was told about a friction moment it cannot have).
/// How far the frictionless state was followed in μ is said too: a failure at a μ far too
/// small to move the zones is the iteration's, not the friction moment's.
pub fn failure_hint(state: &SteadyState, contact: &CondensedContact) -> String {
    let turns = contact.rigid_names.contains(&"lambda_M");
    let hint = match state.sliding {
        _ if contact.friction == 0.0 || !turns => "A steady state of this form exists whenever the load can be balanced (no friction moment turns the plate); the iteration did not find it (please report the problem file)",
        SteadySliding::Reciprocating => "If the friction moment separates the contact zones of the two half cycles, no steady state with one rigid wear per period exists",
        SteadySliding::Monotonic(_) => "With monotonic sliding the friction moment about the pin grows with μ; if it tips the plate onto an edge, no steady state of one rigid wear per step exists",
    };
    let mu = contact.friction;
    let followed = match state.friction_reached {
        Some(reached) if mu != 0.0 && turns && reached > 0.0 => format!("The steady state without friction was found and followed up to μ = {reached:.3e} of the problem's {mu:.3e}, and no further"),
        Some(_) if mu != 0.0 && turns => format!("The steady state without friction was found but could not be followed even to μ = {:.3e} (1/64 of the problem's {mu:.3e})", mu / 64.0),
        _ => return hint.to_string(),
    };
    format!("{followed}. {hint}; a μ too small to move the zones points to the iteration instead (please report the problem file)")
}

/// Compute the steady worn state of `contact` for half-period wear `terms` (from
/// [`crate::wear::WearIntegrator::half_period_wear`]) under `sliding`.
///
/// For b < 1 the wear law pᵇ has an infinite slope at p = 0 and the iteration uses secant
/// slopes (see `wear`): b = 0.5 takes about 40 iterations instead of 6–10. Far from b = 1 the
/// full step from a uniform pressure can also wander between active sets; if it does not
/// converge, the solve is repeated by continuation in the exponents from b = 1.
pub fn steady_state(
    contact: &CondensedContact,
    terms: impl Into<WearTerms>,
    sliding: SteadySliding,
    settings: SteadySettings,
) -> Result<SteadyState, SteadyError> {
    steady_state_near(contact, terms, sliding, settings, None)
}

/// [`steady_state`], starting Newton's method from the pressures `near` (MPa, one profile
/// per half cycle: '+' then '−', or the one of monotonic sliding) and their contact sets
/// instead of a uniform pressure everywhere. A wear run's last cycle is such a start: for
/// b = 1 the steady conditions are linear once the contact sets are right, so Newton's method
/// then needs one or two steps instead of several active-set changes (the run's steady check
/// at 1025 points: 0.36 s cold). Should the start lead nowhere, the cold start follows.
pub fn steady_state_near(
    contact: &CondensedContact,
    terms: impl Into<WearTerms>,
    sliding: SteadySliding,
    settings: SteadySettings,
    near: Option<&[&[f64]]>,
) -> Result<SteadyState, SteadyError> {
    steady_state_with_offsets(contact, terms, sliding, settings, near, &[])
}

/// [`steady_state_near`] where half cycle h sees the gap g + `offsets[h]` (mm, one per point;
/// an empty list: no offset) instead of the shape g alone: the thermal distortion of the
/// temperature at each half's start. A common part of the offsets is absorbed by the shape
/// (the state's `shape` is g, what the offsets are added to); only their difference changes
/// the pressures.
pub fn steady_state_with_offsets(
    contact: &CondensedContact,
    terms: impl Into<WearTerms>,
    sliding: SteadySliding,
    settings: SteadySettings,
    near: Option<&[&[f64]]>,
    offsets: &[Vec<f64>],
) -> Result<SteadyState, SteadyError> {
    let mut state = solve(contact, &terms.into(), sliding, settings, near, offsets)?;
    // On bodies of revolution the axis point's force says nothing of the pressure there: it
    // is read from its neighbours, as the contact solve reads it ([`crate::contact::AxisPoint`]).
    for axis in &contact.axis_points {
        for pressure in [&mut state.p_plus, &mut state.p_minus] {
            if !pressure.is_empty() {
                pressure[axis.point] = axis.pressure(pressure);
            }
        }
    }
    Ok(state)
}

/// [`steady_state_with_offsets`] as solved, the axis points' pressure left as the solve's.
fn solve(
    contact: &CondensedContact,
    terms: &WearTerms,
    sliding: SteadySliding,
    settings: SteadySettings,
    near: Option<&[&[f64]]>,
    offsets: &[Vec<f64>],
) -> Result<SteadyState, SteadyError> {
    let (n, m) = (contact.len(), contact.rigid_modes.len());
    if m == 0 {
        return Err(SteadyError::NoRigidMotion);
    }
    if terms.none_wear() {
        return Err(SteadyError::NoWear);
    }
    // Without friction the halves are one problem, unless their offsets differ.
    let same_offsets = offsets.windows(2).all(|w| w[0] == w[1]);
    if sliding == SteadySliding::Reciprocating && contact.friction == 0.0 && same_offsets {
        let mut state = frictionless_reciprocating(contact, terms, settings, near);
        if let Some(offset) = offsets.first() {
            // Solved without it: the shape that sees g + offset is g − offset.
            for (g, o) in state.shape.iter_mut().zip(offset) {
                *g -= o;
            }
        }
        return Ok(state);
    }
    let signs: Vec<f64> = match sliding {
        SteadySliding::Reciprocating => vec![1.0, -1.0],
        SteadySliding::Monotonic(direction) => vec![direction.sign()],
    };
    let system = System::new(contact, &signs, 1.0).with_offset(offsets);
    let start = system.uniform_start();
    let mut used = 0;
    if let Some(near) = near.filter(|p| p.len() == system.halves && p.iter().all(|q| q.len() == n))
    {
        let (mut z, mut active) = system.start(near);
        let (status, iterations) = system.newton(terms, &mut z, &mut active, settings);
        if status == SteadyStatus::Solved {
            return Ok(system.state(sliding, terms, &z, status, iterations));
        }
        used = iterations;
    }
    let (mut z, mut active) = start.clone();
    let (mut status, iterations) = system.newton(terms, &mut z, &mut active, settings);
    used += iterations;
    if status != SteadyStatus::Solved && terms.is_nonlinear() {
        // Far from b = 1 the full Newton step from a uniform pressure can wander between
        // active sets; walk there from the linear problem instead.
        (z, active) = start.clone();
        let (retry, iterations) =
            continuation::in_exponents(&system, terms, &mut z, &mut active, settings);
        (status, used) = (retry, used + iterations);
    }
    let mut friction_reached = None;
    if status != SteadyStatus::Solved {
        let retry =
            continuation::from_frictionless(&system, contact, sliding, &signs, terms, settings);
        // (The continuation's systems carry the offsets; its mirror-image start has none,
        // which only makes it a worse start.)
        used += retry.iterations;
        if retry.status == SteadyStatus::Solved {
            (z, status) = (retry.z, retry.status);
        }
        friction_reached = retry.friction_reached;
    }
    let mut state = system.state(sliding, terms, &z, status, used);
    state.friction_reached = friction_reached;
    Ok(state)
}

/// Without friction the two half cycles of reciprocating sliding are one contact problem on
/// the same shape, whose solution is unique: p⁺ = p⁻, and the period's wear is twice one
/// half's. So the steady state is the one-direction state of the doubled law, solved with
/// one half's unknowns. Solved as two halves, round-off parted the halves' active sets where
/// the pressures fall to nothing at a zone's end (b = 0.1, the load on the punch's last 5 mm:
/// p = L(x)¹⁰, 1e-20 of the peak, still wearing a few % of the most), and they cycled.
fn frictionless_reciprocating(
    contact: &CondensedContact,
    terms: &WearTerms,
    settings: SteadySettings,
    near: Option<&[&[f64]]>,
) -> SteadyState {
    let doubled = terms.scaled(2.0);
    let one_half = SteadySliding::Monotonic(Direction::Plus);
    let near = near.and_then(|p| p.get(..1));
    let mut state = steady_state_near(contact, &doubled, one_half, settings, near)
        .expect("the checks of the two-half solve hold for one half");
    state.sliding = SteadySliding::Reciprocating;
    state.p_minus = state.p_plus.clone();
    state.rigid_minus = state.rigid_plus.clone();
    state
}

impl System<'_> {
    /// Pressures, rigid motions and the final wear residual of the iterate `z`.
    fn state(
        &self,
        sliding: SteadySliding,
        terms: &WearTerms,
        z: &[f64],
        status: SteadyStatus,
        iterations: usize,
    ) -> SteadyState {
        let (n, m, halves) = (self.n, self.m, self.halves);
        let pressure = |h: usize| {
            (0..n)
                .map(|i| z[self.force(h, i)].max(0.0) / self.area[i])
                .collect::<Vec<f64>>()
        };
        let p_plus = pressure(0);
        let p_minus = if halves == 2 { pressure(1) } else { Vec::new() };
        let mut wear_residual = 0.0f64;
        let mut wear_scale = 0.0f64;
        for i in 0..n {
            let mut w = law::half_period_wear(terms.at(i), p_plus[i]);
            if halves == 2 {
                w += law::half_period_wear(terms.at(i), p_minus[i]);
            }
            wear_scale = wear_scale.max(w);
            let closing = w + self.rigid_wear_gap(z, i);
            // Where nothing wears, a gap that opens is allowed; only closing is an error.
            let violation = if w > 0.0 {
                closing.abs()
            } else {
                (-closing).max(0.0)
            };
            // NaN must survive (f64::max would drop it) so that a broken state never looks clean.
            if violation.is_nan() || violation > wear_residual {
                wear_residual = violation;
            }
        }
        let wear_residual = wear_residual / wear_scale.max(f64::MIN_POSITIVE);
        // The iteration judges convergence at its last linearisation; the state written is the
        // one after the last step, with negative pressures cut to zero. Where that state's own
        // wear is not rigid, it is no steady state, whatever the iteration concluded (while
        // b < 1 was reworked, a final step of round-off size at a zone's end gave "Solved"
        // with a wear residual of 4 %).
        let status = if status == SteadyStatus::Solved
            && (wear_residual.is_nan() || wear_residual > FINAL_WEAR_RESIDUAL)
        {
            SteadyStatus::NotSteady
        } else {
            status
        };
        let lambdas = |h: usize| (0..m).map(|k| z[self.lambda(h, k)]).collect::<Vec<f64>>();
        SteadyState {
            sliding,
            shape: z[..n].to_vec(),
            p_plus,
            p_minus,
            rigid_plus: lambdas(0),
            rigid_minus: if halves == 2 { lambdas(1) } else { Vec::new() },
            rigid_wear: (0..m).map(|k| z[self.wear_motion(k)]).collect(),
            status,
            iterations,
            wear_residual,
            friction_reached: None,
        }
    }
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
