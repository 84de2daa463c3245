//! The periodic steady state with heat (paper §4, its ref. \[15\]): the worn shape, the
//! pressures of both half cycles and the periodic temperature that they make together.
//!
//! In the steady state the temperature is periodic too. Each half cycle h sees the shape g
//! plus the thermal gap θ_h of the temperature at its start (the operator split of the run:
//! [`crate::wear::thermal`]), and the periodic temperature is that of the two half cycles'
//! frictional heat ([`ThermalModel::periodic_state`]). A common part of θ₊ and θ₋ is absorbed
//! by the shape: the pressures see only their difference, the thermal gap's swing over a
//! period. So the paper's claim, that the steady pressure does not depend on the heat while
//! the worn shape does, holds where the swing is negligible; where it is not, the pressures
//! differ and this computes by how much.
//!
//! The coupled problem is solved by a fixed-point iteration on the pressures: from the steady
//! state without heat, the periodic thermal gaps of the current pressures, then the steady
//! state with the half cycles' gaps offset by them ([`crate::steady::steady_state_with_offsets`]),
//! until the pressures change by less than 1e-10 of their peak. The swing depends on the
//! pressures only through a half period's diffusion, so each pass shrinks the change by
//! orders of magnitude (two or three passes on punch-b40-heat).

use crate::contact::CondensedContact;
use crate::steady::{
    steady_state_near, steady_state_with_offsets, SteadyError, SteadySettings, SteadySliding,
    SteadyState, SteadyStatus,
};
use crate::wear::thermal::ThermalModel;

/// Largest number of fixed-point passes. Two or three on punch-b40-heat; a thermal layer far
/// thinner than the elements (conductivities a hundred times lower, the heat-undershoot
/// warning's case) contracts by only 0.7 a pass and takes about 55.
pub const MAX_PASSES: usize = 100;
/// The pressures' change between passes, relative to their peak, at which the iteration stops.
pub const PASS_TOLERANCE: f64 = 1e-10;

/// The steady state with heat.
#[derive(Clone, Debug)]
pub struct ThermalSteadyState {
    /// The steady state: `shape` is the worn shape (without the thermal distortion).
    pub state: SteadyState,
    /// The periodic temperature that goes with it.
    pub heat: PeriodicHeat,
}

/// The periodic temperature of a steady state with heat.
#[derive(Clone, Debug)]
pub struct PeriodicHeat {
    /// The thermal gap u_n⁽²⁾ − u_n⁽¹⁾ (mm) that the '+' and the '−' half cycles see (the
    /// temperature at their starts).
    pub thermal_gap: [Vec<f64>; 2],
    /// Temperatures (°C) at the contact points of body 1 and at their partners on body 2,
    /// at the start of the '+' half and at the start of the '−' half: `[half][body]`.
    pub contact_temperature: [[Vec<f64>; 2]; 2],
    /// The modal coordinates of the periodic temperature at the start of each half.
    pub modal: [Vec<f64>; 2],
    /// Fixed-point passes made.
    pub passes: usize,
    /// The pressures' change in the last pass, relative to their peak.
    pub change: f64,
    /// The heat problem (for the temperature fields of the ParaView files).
    pub model: std::sync::Arc<ThermalModel>,
}

/// Why there is no steady state with heat.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum ThermalSteadyError {
    /// The wear problem has none.
    #[error(transparent)]
    Steady(#[from] SteadyError),
    /// The heat cannot leave the bodies: their temperature rises for ever.
    #[error("frictional heat enters a body that cannot lose it (its edges insulated, its faces not convecting, or under a given share no exit of its own), so its temperature rises without end and there is no steady state; hold an edge of that body at a temperature or let its edges or faces convect ([heat.edges], heat.other_edges, heat.faces), or give it no share of the heat (heat.partition)")]
    NoExit,
}

/// The steady state of `contact` with the heat of `model` (see the module docs).
pub fn steady_state_with_heat(
    contact: &CondensedContact,
    terms: &[(f64, f64)],
    sliding: SteadySliding,
    settings: SteadySettings,
    model: &std::sync::Arc<ThermalModel>,
) -> Result<ThermalSteadyState, ThermalSteadyError> {
    if model.info.trapped {
        return Err(ThermalSteadyError::NoExit);
    }
    let mut state = steady_state_near(contact, terms, sliding, settings, None)?;
    let reciprocating = sliding == SteadySliding::Reciprocating;
    let (mut passes, mut change) = (0, f64::INFINITY);
    let mut modal = [Vec::new(), Vec::new()];
    let mut gaps = [Vec::new(), Vec::new()];
    while passes < MAX_PASSES && state.status == SteadyStatus::Solved {
        passes += 1;
        let minus = if reciprocating {
            &state.p_minus
        } else {
            &state.p_plus
        };
        modal = model
            .periodic_state(&state.p_plus, minus)
            .ok_or(ThermalSteadyError::NoExit)?;
        gaps = [model.gap.at(&modal[0]), model.gap.at(&modal[1])];
        // Offsets relative to the '+' half's gap, which the shape absorbs.
        let offsets: Vec<Vec<f64>> = if reciprocating {
            vec![
                vec![0.0; contact.len()],
                gaps[1].iter().zip(&gaps[0]).map(|(m, p)| m - p).collect(),
            ]
        } else {
            Vec::new()
        };
        let near: Vec<&[f64]> = if reciprocating {
            vec![&state.p_plus, &state.p_minus]
        } else {
            vec![&state.p_plus]
        };
        let next =
            steady_state_with_offsets(contact, terms, sliding, settings, Some(&near), &offsets)?;
        let peak = next
            .p_plus
            .iter()
            .chain(&next.p_minus)
            .fold(0.0f64, |m, p| m.max(p.abs()));
        change = next
            .p_plus
            .iter()
            .zip(&state.p_plus)
            .chain(next.p_minus.iter().zip(&state.p_minus))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / peak.max(f64::MIN_POSITIVE);
        state = next;
        if change <= PASS_TOLERANCE {
            break;
        }
    }
    if state.status == SteadyStatus::Solved && change > PASS_TOLERANCE {
        state.status = SteadyStatus::MaxIterations;
    }
    // The shape that sees g + θ₊ is the worn shape plus θ₊: the worn shape is g − θ₊.
    if !gaps[0].is_empty() {
        for (g, t) in state.shape.iter_mut().zip(&gaps[0]) {
            *g -= t;
        }
    }
    let temperatures = |a: &[f64]| {
        if a.is_empty() {
            [Vec::new(), Vec::new()]
        } else {
            [
                model.contact_temperature[0].at(a),
                model.contact_temperature[1].at(a),
            ]
        }
    };
    Ok(ThermalSteadyState {
        state,
        heat: PeriodicHeat {
            contact_temperature: [temperatures(&modal[0]), temperatures(&modal[1])],
            thermal_gap: gaps,
            modal,
            passes,
            change,
            model: std::sync::Arc::clone(model),
        },
    })
}
