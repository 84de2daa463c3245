//! The steady-state system of a contact and the iterates Newton's method starts from: a
//! uniform pressure, a given one, or the unworn contact's.

use super::System;
use crate::complementarity::Direction;
use crate::contact::CondensedContact;

/// The plate's first load over the contact area (MPa): the mean contact pressure F/A.
fn mean_pressure(load: &[f64], area: &[f64]) -> f64 {
    load.first().copied().unwrap_or(0.0).abs() / area.iter().sum::<f64>()
}

/// The pressures (MPa) of the contact solves on the unworn shape, one per half cycle; None if
/// one of them fails.
pub(super) fn unworn_pressures(contact: &CondensedContact, signs: &[f64]) -> Option<Vec<Vec<f64>>> {
    use crate::complementarity::{ContactSolver, Method, Status};
    let mut solver = ContactSolver::new(contact, Method::ActiveSet);
    signs
        .iter()
        .map(|&s| {
            let direction = if s > 0.0 {
                Direction::Plus
            } else {
                Direction::Minus
            };
            let (solution, info) = solver.solve(&contact.points.initial_gap, direction);
            (info.status == Status::Solved).then_some(solution.pressure)
        })
        .collect()
}

impl<'a> System<'a> {
    /// The system of `contact` for the half cycles of `signs`, with the friction coefficient
    /// scaled by `friction_scale` (1: the problem's own).
    pub(super) fn new(
        contact: &'a CondensedContact,
        signs: &[f64],
        friction_scale: f64,
    ) -> System<'a> {
        let area = contact.areas();
        let mean = mean_pressure(&contact.plate_load, &area);
        // Friction enters the matrices as s μ: scaling s scales μ.
        let scaled: Vec<f64> = signs.iter().map(|s| s * friction_scale).collect();
        System {
            n: contact.len(),
            m: contact.rigid_modes.len(),
            halves: signs.len(),
            area,
            gap: scaled.iter().map(|&s| contact.gap_matrix(s)).collect(),
            equilibrium: scaled
                .iter()
                .map(|&s| contact.equilibrium_matrix(s))
                .collect(),
            rigid: contact.rigid_gap_matrix(),
            load: &contact.plate_load,
            reference_pressure: if mean > 0.0 && mean.is_finite() {
                mean
            } else {
                1.0
            },
            offset: Vec::new(),
        }
    }

    /// This system with half h seeing the gap offset `offsets[h]` (mm; empty: none).
    pub(super) fn with_offset(mut self, offsets: &[Vec<f64>]) -> System<'a> {
        self.offset = offsets.to_vec();
        self
    }

    /// Uniform pressure F/A in every half, every point in contact (the monotonic optimum of a
    /// flat punch): the cold start.
    pub(super) fn uniform_start(&self) -> (Vec<f64>, Vec<Vec<bool>>) {
        let mean = mean_pressure(self.load, &self.area);
        let mut z = vec![0.0; self.size()];
        for h in 0..self.halves {
            for i in 0..self.n {
                z[self.force(h, i)] = mean * self.area[i];
            }
        }
        (z, vec![vec![true; self.n]; self.halves])
    }

    /// The iterate and active sets of a steady `state` of the same contact: shape, the forces
    /// and rigid motions of each half cycle (a one-half state gives both halves its own, the
    /// frictionless mirror image), the rigid wear.
    pub(super) fn start_from_state(
        &self,
        state: &super::SteadyState,
    ) -> (Vec<f64>, Vec<Vec<bool>>) {
        let halves: Vec<(&Vec<f64>, &Vec<f64>)> = (0..self.halves)
            .map(|h| {
                if h == 1 && !state.p_minus.is_empty() {
                    (&state.p_minus, &state.rigid_minus)
                } else {
                    (&state.p_plus, &state.rigid_plus)
                }
            })
            .collect();
        let pressures: Vec<&Vec<f64>> = halves.iter().map(|h| h.0).collect();
        let (mut z, active) = self.start(&pressures);
        z[..self.n].copy_from_slice(&state.shape);
        for (h, (_, rigid)) in halves.iter().enumerate() {
            for (k, &lambda) in rigid.iter().enumerate() {
                z[self.lambda(h, k)] = lambda;
            }
        }
        for (k, &w) in state.rigid_wear.iter().enumerate() {
            z[self.wear_motion(k)] = w;
        }
        (z, active)
    }

    /// The iterate and active sets of `pressures` (MPa, one profile per half cycle).
    pub(super) fn start<P: AsRef<[f64]>>(&self, pressures: &[P]) -> (Vec<f64>, Vec<Vec<bool>>) {
        let mut z = vec![0.0; self.size()];
        let mut active = vec![vec![true; self.n]; self.halves];
        for (h, pressure) in pressures.iter().enumerate() {
            for (i, &p) in pressure.as_ref().iter().enumerate() {
                active[h][i] = p > 0.0;
                z[self.force(h, i)] = p.max(0.0) * self.area[i];
            }
        }
        (z, active)
    }
}
