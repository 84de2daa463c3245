//! One fretting cycle of a pressed contact: the tangential loading Q₀ cos ωt (force control)
//! or δ₀ cos ωt (displacement control) followed stage by stage with
//! [`TangentialProblem::solve_stage`], and what the cycle leaves: the loop (Q against δ), the
//! energy friction dissipates, each point's slip and the points that never slip.
//!
//! The cycle starts at the peak (phase ωt = 0), reached from the unloaded state by one
//! monotonic stage (Cattaneo and Mindlin's loading), and runs through 2n stages of equal phase
//! π/n back to it. Under proportional loading the state at the peak is then the virgin one
//! again (Mindlin and Deresiewicz: the cycle closes after its first half), so the cycle
//! measured is the periodic one.
//!
//! Within a stage each slipping point slips one way and carries |F| = μP, so the energy
//! friction dissipates in it, Σ μ P_i |Δs_i|, is exact; the loop's own area (the trapezoid rule
//! on its 2n + 1 points) converges to it as the stages are refined, and is reported beside it.

use super::partial_slip::{PartialSlip, PartialSlipError, TangentialControl, TangentialProblem};

/// What drives the cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrettingControl {
    /// Q(t) = Q₀ cos ωt on body 1's plate; the amplitude in N.
    Force,
    /// δ(t) = δ₀ cos ωt, the plate's shift against body 2's supports; the amplitude in mm.
    Displacement,
}

/// The tangential loading of a fretting cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrettingLoading {
    /// Force or displacement control.
    pub control: FrettingControl,
    /// Q₀ (N) or δ₀ (mm), > 0.
    pub amplitude: f64,
    /// Stages per half cycle, n ≥ 1 (each a phase step of π/n).
    pub stages: usize,
}

impl FrettingLoading {
    /// The loading at phase `phase` (rad): Q₀ cos or δ₀ cos of it.
    pub fn at(&self, phase: f64) -> TangentialControl {
        let value = self.amplitude * phase.cos();
        match self.control {
            FrettingControl::Force => TangentialControl::Force(value),
            FrettingControl::Displacement => TangentialControl::Displacement(value),
        }
    }
}

/// One periodic cycle.
#[derive(Clone, Debug)]
pub struct FrettingCycle {
    /// The state at the start (phase 0, the peak) and after each of the 2n stages (phase
    /// kπ/n): forces (N), stick flags, the stage's slip (mm), the shift (mm) and load (N).
    pub states: Vec<PartialSlip>,
    /// Energy friction dissipates in the cycle, N·mm: Σ over stages and points of μP|Δs|.
    pub dissipated: f64,
    /// The loop's area ∮ Q dδ by the trapezoid rule over the stages, N·mm.
    pub loop_area: f64,
    /// Each point's slip in one half cycle, mm (its largest of the two halves).
    pub slip_amplitude: Vec<f64>,
    /// Whether each point carries pressure and sticks through the whole cycle.
    pub never_slips: Vec<bool>,
    /// Whether, at some stage, every point that carries pressure slipped (gross slip).
    pub gross_slip: bool,
}

impl FrettingCycle {
    /// The cycle of `problem` under `loading`.
    pub fn solve(
        problem: &TangentialProblem,
        loading: &FrettingLoading,
    ) -> Result<FrettingCycle, PartialSlipError> {
        let n = problem.normal_force.len();
        let stages = loading.stages.max(1);
        let peak = problem.solve_stage(loading.at(0.0), None)?;
        let mut states = Vec::with_capacity(2 * stages + 1);
        states.push(peak);
        let mut half_slip = [vec![0.0; n], vec![0.0; n]];
        let mut never_slips: Vec<bool> = problem.normal_force.iter().map(|&f| f > 0.0).collect();
        let (mut dissipated, mut loop_area, mut gross_slip) = (0.0, 0.0, false);
        for stage in 1..=2 * stages {
            let phase = std::f64::consts::PI * stage as f64 / stages as f64;
            let previous = states.last().expect("the peak is there");
            let next = problem.solve_stage(loading.at(phase), Some(previous))?;
            let half = usize::from(stage > stages);
            for i in 0..n {
                half_slip[half][i] += next.slip[i].abs();
                // Friction opposes the slip at |F| = μP through the stage: −F Δs ≥ 0.
                dissipated -= next.force[i] * next.slip[i];
                never_slips[i] &= next.stick[i];
            }
            loop_area += 0.5 * (next.load + previous.load) * (next.shift - previous.shift);
            gross_slip |= (0..n).all(|i| problem.normal_force[i] <= 0.0 || !next.stick[i]);
            states.push(next);
        }
        let slip_amplitude = (0..n)
            .map(|i| half_slip[0][i].max(half_slip[1][i]))
            .collect();
        Ok(FrettingCycle {
            states,
            dissipated,
            loop_area,
            slip_amplitude,
            never_slips,
            gross_slip,
        })
    }

    /// Stages per half cycle.
    pub fn stages(&self) -> usize {
        (self.states.len() - 1) / 2
    }

    /// Each point's ∫|ṡ|ᵃ dt over the cycle (mm^a s^(1−a)) at angular frequency `omega`
    /// (rad/s): Σ over stages of |Δs|ᵃ Δt^(1−a), the stage's slip taken at a uniform rate over
    /// its time Δt = π/(nω). Exact for a = 1 (then Σ|Δs|, whatever ω); for a ≠ 1 the rate
    /// within a stage is taken as uniform.
    pub fn sliding_term(&self, a: f64, omega: f64) -> Vec<f64> {
        let n = self.slip_amplitude.len();
        let stage_time = std::f64::consts::PI / (self.stages() as f64 * omega);
        let mut term = vec![0.0; n];
        for state in &self.states[1..] {
            for (t, s) in term.iter_mut().zip(&state.slip) {
                *t += if a == 1.0 {
                    s.abs()
                } else {
                    s.abs().powf(a) * stage_time.powf(1.0 - a)
                };
            }
        }
        term
    }

    /// The x extent (mm) of the points that never slip, from `x` (mm, one per point): None if
    /// every point slips at some instant.
    pub fn stick_extent(&self, x: &[f64]) -> Option<(f64, f64)> {
        let inside = || {
            x.iter()
                .zip(&self.never_slips)
                .filter(|(_, s)| **s)
                .map(|(x, _)| *x)
        };
        let low = inside().fold(f64::INFINITY, f64::min);
        let high = inside().fold(f64::NEG_INFINITY, f64::max);
        (low <= high).then_some((low, high))
    }
}
