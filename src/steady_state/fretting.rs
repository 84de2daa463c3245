//! The final worn state of fretting in partial slip, directly: the worn shape at which the
//! points that carry pressure all stick, so that wear stops (Ciavarella and Hills).
//!
//! Points that stick through the whole cycle never wear; points that slip wear until they
//! carry no pressure. The final state therefore has its pressure on the set S of points that
//! never slip, with their unworn shape, and every other point worn just down to the deformed
//! partner: zero pressure, zero gap. For two bodies of one material under force control, S is
//! the unworn cycle's stick zone and stays so while the slip zones wear (Ciavarella–Jäger: the
//! stick zone is the contact of the reduced load P − Q/μ, which wear outside it does not
//! change).
//!
//! The solve: the contact problem with only S allowed to touch (every other point held open
//! by a large gap G), whose gaps give the others' wear, w_i = max(0, −d_i) with d_i their
//! deformed gap without G; then the cycle at that state. If a point of S that carries pressure
//! slips in it, S loses it and the solve is repeated (a fixed point on S; once under force
//! control for one material, as the theorem says).

use crate::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::fretting::{CoupledError, CycleModel, FrettingCycle};

/// The final state.
#[derive(Clone, Debug)]
pub struct FrettingFinalState {
    /// Contact pressure, MPa.
    pub pressure: Vec<f64>,
    /// The worn shape (both bodies' wear together), mm.
    pub shape: Vec<f64>,
    /// Whether each point belongs to the final contact's stick set S.
    pub stick: Vec<bool>,
    /// The cycle at the final state.
    pub cycle: FrettingCycle,
    /// The unworn state's cycle.
    pub first_cycle: FrettingCycle,
    /// The unworn pressure, MPa.
    pub initial_pressure: Vec<f64>,
    /// Fixed-point iterations.
    pub iterations: usize,
    /// Whether this is the periodic steady state of gross slip ([`gross_slip_steady`]), not
    /// the final state of partial slip.
    pub gross_slip: bool,
}

/// Why the final state was not found.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FinalStateError {
    /// A contact solve failed.
    #[error("a contact solve failed (complementarity residual {0:.3e})")]
    ContactSolve(f64),
    /// The cycle failed.
    #[error("{0}")]
    Cycle(CoupledError),
    /// Nothing sticks: gross slip, whose steady state is the periodic one of full slip.
    #[error("no point sticks through the cycle: that is gross slip, whose worn state is the periodic one of full slip, not a final state of partial slip")]
    GrossSlip,
    /// No point carries pressure under the normal load.
    #[error("no contact point carries pressure under the normal load: nothing frets (a held plate presses only by its position; check the loads, the plate and the initial gap)")]
    NoContact,
    /// The stick set (or, in gross slip, the pressure) kept changing.
    #[error("the fixed point did not settle in {0} iterations")]
    NotSettled(usize),
    /// The plate cannot approach the contact along one rigid motion: a steady state of gross
    /// slip needs one (the worn shape moves by it).
    #[error("a steady state of gross slip needs a plate that approaches the contact by one rigid motion (plate.motion = \"vertical\")")]
    PlateMotion,
    /// At the steady state's pressure some point sticks through the whole cycle.
    #[error("at the steady state's pressure some point sticks through the cycle: neither gross slip nor a final state of partial slip (a larger amplitude gives gross slip)")]
    GrossSlipLost,
    /// The worn shape did not give its pressure back.
    #[error("the contact solve of the steady worn shape did not give its pressure back (differs by {0:.3e} of the peak)")]
    ShapeCheck(f64),
}

/// Most fixed-point iterations on S.
const MAX_ITERATIONS: usize = 50;

/// The final state of `contact` (a frictionless solver `solver` on it) with the cycles of
/// `model`. In the coupled problem the points of S must stick at every instant of the cycle,
/// whose pressure moves: the fixed point on S sees that through the cycle.
pub fn final_state(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    model: &mut dyn CycleModel,
) -> Result<FrettingFinalState, FinalStateError> {
    let n = contact.len();
    let area = contact.areas();
    let mut cycle_of = |pressure: &[f64], shape: &[f64]| {
        let normal_force: Vec<f64> = pressure.iter().zip(&area).map(|(p, a)| p * a).collect();
        model
            .cycle(&normal_force, shape)
            .map(|(cycle, _)| cycle)
            .map_err(FinalStateError::Cycle)
    };
    let g0 = &contact.points.initial_gap;
    let mut out = ContactSolution::default();
    let initial_pressure = unworn_pressure(solver, contact, &mut out)?;
    let first_cycle = cycle_of(&initial_pressure, &vec![0.0; n])?;
    let mut stick: Vec<bool> = (0..n)
        .map(|i| initial_pressure[i] > 0.0 && first_cycle.never_slips[i])
        .collect();
    if !stick.iter().any(|s| *s) {
        return Err(FinalStateError::GrossSlip);
    }
    // A gap that holds the other points open: far beyond the gaps and the approach.
    let mut open = 1.0 + 10.0 * g0.iter().fold(0.0f64, |m, g| m.max(g.abs()));
    for iteration in 1..=MAX_ITERATIONS {
        let gap: Vec<f64> = (0..n)
            .map(|i| g0[i] + if stick[i] { 0.0 } else { open })
            .collect();
        let info = solver.solve_into(&gap, Direction::Plus, &mut out);
        if info.status != Status::Solved {
            return Err(FinalStateError::ContactSolve(info.complementarity));
        }
        if (0..n).any(|i| !stick[i] && out.pressure[i] > 0.0) {
            // The approach reached past the opening gap: open wider.
            open *= 10.0;
            continue;
        }
        let shape: Vec<f64> = (0..n)
            .map(|i| {
                if stick[i] {
                    0.0
                } else {
                    (open - out.gap[i]).max(0.0)
                }
            })
            .collect();
        let pressure = out.pressure.clone();
        let cycle = cycle_of(&pressure, &shape)?;
        let slipping: Vec<usize> = (0..n)
            .filter(|&i| pressure[i] > 0.0 && !cycle.never_slips[i])
            .collect();
        if slipping.is_empty() {
            return Ok(FrettingFinalState {
                pressure,
                shape,
                stick,
                cycle,
                first_cycle,
                initial_pressure,
                iterations: iteration,
                gross_slip: false,
            });
        }
        for i in slipping {
            stick[i] = false;
        }
        if !stick.iter().any(|s| *s) {
            return Err(FinalStateError::GrossSlip);
        }
    }
    Err(FinalStateError::NotSettled(MAX_ITERATIONS))
}

/// The steady state of gross-slip fretting: the periodic state of today's full slip, in which
/// every point wears by the slip of its own cycle and the worn shape no longer changes but by
/// the plate's approach, ẇ_i = c (n_i·φ(x_i)): Σ_l β̃_l T_l,i p_iᵇˡ = c ρ_i at every point of
/// the contact edge, the plate in equilibrium. `laws` are each wearing body's (β̃ MPa⁻¹, a,
/// b); T_l,i the point's ∫|ṡ|ᵃ dt over a cycle at angular frequency `omega` (rad/s).
///
/// The cycle depends on the pressure (the slip near a reversal does), so the solve is a fixed
/// point: the cycle at P, the pressure that wears each point at the approach's rate under it,
/// the plate's equilibrium fixing the rate, until P changes by less than 1e-10 of its largest.
/// The worn shape is then the one whose contact problem has that pressure, every gap closed:
/// w_i = ρ_i λ − g₀_i − (A_nn P)_i, λ making the least wear zero; a contact solve of it must give
/// the pressure back (checked). Uncoupled cycles only, and a plate with one rigid motion.
pub fn gross_slip_steady(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    model: &mut dyn CycleModel,
    laws: &[(f64, f64, f64)],
    omega: f64,
) -> Result<FrettingFinalState, FinalStateError> {
    let n = contact.len();
    let area = contact.areas();
    if contact.rigid_modes.len() != 1 {
        return Err(FinalStateError::PlateMotion);
    }
    // ρ_i = n_i·φ(x_i): the gap a unit approach closes (the rigid gap matrix is −ρ).
    let mut rho: Vec<f64> = contact.rigid_gap_matrix().iter().map(|r| -r).collect();
    let mut load = contact.plate_load[0];
    if rho.iter().all(|r| *r <= 0.0) {
        rho.iter_mut().for_each(|r| *r = -*r);
        load = -load;
    }
    if rho.iter().any(|r| *r <= 0.0) || load <= 0.0 {
        return Err(FinalStateError::PlateMotion);
    }
    let g0 = &contact.points.initial_gap;
    let mut out = ContactSolution::default();
    let initial_pressure = unworn_pressure(solver, contact, &mut out)?;
    let forces = |p: &[f64]| -> Vec<f64> { p.iter().zip(&area).map(|(p, a)| p * a).collect() };
    let first_cycle = model
        .cycle(&forces(&initial_pressure), &vec![0.0; n])
        .map_err(FinalStateError::Cycle)?
        .0;
    // Start from the load spread evenly over the edge.
    let spread: f64 = (0..n).map(|i| rho[i] * area[i]).sum();
    let mut pressure = vec![load / spread; n];
    for iteration in 1..=MAX_ITERATIONS {
        let (cycle, _) = model
            .cycle(&forces(&pressure), &vec![0.0; n])
            .map_err(FinalStateError::Cycle)?;
        let terms: Vec<Vec<(f64, f64)>> = (0..n)
            .map(|i| {
                (laws.iter())
                    .map(|&(beta, a, b)| (beta * cycle.sliding_term(a, omega)[i], b))
                    .collect()
            })
            .collect();
        if (0..n).any(|i| terms[i].iter().all(|t| t.0 <= 0.0)) {
            // A point that never slips never wears: not gross slip at this pressure.
            return Err(FinalStateError::GrossSlipLost);
        }
        let next = balanced_pressure(&terms, &rho, &area, load);
        let largest = next.iter().fold(0.0f64, |m, p| m.max(*p));
        let change = (0..n)
            .map(|i| (next[i] - pressure[i]).abs())
            .fold(0.0, f64::max);
        pressure = next;
        if change <= 1e-10 * largest {
            let shape = closing_shape(contact, &pressure, &area, &rho);
            let info = solver.solve_into(
                &(0..n).map(|i| g0[i] + shape[i]).collect::<Vec<_>>(),
                Direction::Plus,
                &mut out,
            );
            let back = (0..n)
                .map(|i| (out.pressure[i] - pressure[i]).abs())
                .fold(0.0, f64::max);
            if info.status != Status::Solved || back > 1e-6 * largest {
                return Err(FinalStateError::ShapeCheck(back / largest));
            }
            return Ok(FrettingFinalState {
                pressure,
                shape,
                stick: vec![false; n],
                cycle,
                first_cycle,
                initial_pressure,
                iterations: iteration,
                gross_slip: true,
            });
        }
    }
    Err(FinalStateError::NotSettled(MAX_ITERATIONS))
}

/// The frictionless pressure (MPa) of the unworn contact; an error if it fails or presses
/// nothing.
fn unworn_pressure(
    solver: &mut ContactSolver,
    contact: &CondensedContact,
    out: &mut ContactSolution,
) -> Result<Vec<f64>, FinalStateError> {
    solver.set_compliance(&vec![0.0; contact.len()]);
    let info = solver.solve_into(&contact.points.initial_gap, Direction::Plus, out);
    if info.status != Status::Solved {
        return Err(FinalStateError::ContactSolve(info.complementarity));
    }
    if out.pressure.iter().all(|p| *p <= 0.0) {
        return Err(FinalStateError::NoContact);
    }
    Ok(out.pressure.clone())
}

/// The pressures (MPa) at which each point's wear per cycle, Σ c pᵇ over its `terms`, is
/// c ρ_i, with the rate c that balances the plate, Σ ρ_i a_i p_i = `load` (N).
fn balanced_pressure(terms: &[Vec<(f64, f64)>], rho: &[f64], area: &[f64], load: f64) -> Vec<f64> {
    let at = |rate: f64| -> Vec<f64> {
        (0..rho.len())
            .map(|i| wear_inverse(&terms[i], rate * rho[i]))
            .collect()
    };
    let carried = |p: &[f64]| (0..p.len()).map(|i| rho[i] * area[i] * p[i]).sum::<f64>();
    at(increasing_root(|rate| carried(&at(rate)), load))
}

/// The pressure p ≥ 0 at which Σ c pᵇ over `terms` equals `wear` (the sum grows with p).
fn wear_inverse(terms: &[(f64, f64)], wear: f64) -> f64 {
    if let [(c, b)] = terms {
        return if *b == 1.0 {
            wear / c
        } else {
            (wear / c).powf(1.0 / b)
        };
    }
    increasing_root(|p| crate::wear::law::half_period_wear(terms, p), wear)
}

/// The x ≥ 0 at which `f` (increasing, f(0) ≤ `target`) reaches `target`: bracketed by
/// doubling, then bisected to round-off.
fn increasing_root(f: impl Fn(f64) -> f64, target: f64) -> f64 {
    let (mut low, mut high) = (0.0, 1.0);
    while f(high) < target && high < f64::MAX / 4.0 {
        high *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if f(mid) < target {
            low = mid;
        } else {
            high = mid;
        }
        if high - low <= 1e-15 * high {
            break;
        }
    }
    0.5 * (low + high)
}

/// The worn shape (mm) whose contact problem has `pressure` (MPa) with every gap closed,
/// the least wear zero.
fn closing_shape(
    contact: &CondensedContact,
    pressure: &[f64],
    area: &[f64],
    rho: &[f64],
) -> Vec<f64> {
    let n = pressure.len();
    let g0 = &contact.points.initial_gap;
    let unshifted: Vec<f64> = (0..n)
        .map(|i| {
            let elastic: f64 = (0..n)
                .map(|j| contact.a_nn[i * n + j] * pressure[j] * area[j])
                .sum();
            -g0[i] - elastic
        })
        .collect();
    // λ: the least λ ρ_i + unshifted_i is zero.
    let lambda = (0..n)
        .map(|i| -unshifted[i] / rho[i])
        .fold(f64::NEG_INFINITY, f64::max);
    (0..n).map(|i| lambda * rho[i] + unshifted[i]).collect()
}
