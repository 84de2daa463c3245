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
    /// Fixed-point iterations on S.
    pub iterations: usize,
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
    /// The stick set kept changing.
    #[error("the stick set did not settle in {0} iterations")]
    NotSettled(usize),
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
    solver.set_compliance(&vec![0.0; n]);
    let g0 = &contact.points.initial_gap;
    let mut out = ContactSolution::default();
    let info = solver.solve_into(g0, Direction::Plus, &mut out);
    if info.status != Status::Solved {
        return Err(FinalStateError::ContactSolve(info.complementarity));
    }
    let initial_pressure = out.pressure.clone();
    if initial_pressure.iter().all(|p| *p <= 0.0) {
        return Err(FinalStateError::NoContact);
    }
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
