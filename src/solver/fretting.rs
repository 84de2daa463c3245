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

use super::complementarity::{ContactSolution, ContactSolver, Direction, Status};
use super::partial_slip::{PartialSlip, PartialSlipError, TangentialControl, TangentialProblem};
use crate::contact::CondensedContact;

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
        let (cycle, _) = Self::run_stages(loading, |control, from| {
            let state = problem.solve_stage(control, from)?;
            Ok((state, problem.normal_force.to_vec()))
        })?;
        Ok(cycle)
    }

    /// The virgin loading to the peak and the 2n stages after it, `stage` solving one from
    /// the state before (None: the unloaded state) and giving the normal forces (N) at its
    /// end; with each state's normal forces.
    fn run_stages<E>(
        loading: &FrettingLoading,
        mut stage: impl FnMut(
            TangentialControl,
            Option<&PartialSlip>,
        ) -> Result<(PartialSlip, Vec<f64>), E>,
    ) -> Result<(FrettingCycle, Vec<Vec<f64>>), E> {
        let stages = loading.stages.max(1);
        let (peak, peak_forces) = stage(loading.at(0.0), None)?;
        let n = peak_forces.len();
        let mut half_slip = [vec![0.0; n], vec![0.0; n]];
        let mut never_slips: Vec<bool> = peak_forces.iter().map(|&f| f > 0.0).collect();
        let (mut dissipated, mut loop_area, mut gross_slip) = (0.0, 0.0, false);
        let mut states = Vec::with_capacity(2 * stages + 1);
        let mut pressures = Vec::with_capacity(2 * stages + 1);
        states.push(peak);
        pressures.push(peak_forces);
        for k in 1..=2 * stages {
            let phase = std::f64::consts::PI * k as f64 / stages as f64;
            let previous = states.last().expect("the peak is there");
            let (next, forces) = stage(loading.at(phase), Some(previous))?;
            let half = usize::from(k > stages);
            for i in 0..n {
                half_slip[half][i] += next.slip[i].abs();
                // Friction opposes the slip at |F| = μP through the stage: −F Δs ≥ 0.
                dissipated -= next.force[i] * next.slip[i];
                never_slips[i] &= next.stick[i];
            }
            loop_area += 0.5 * (next.load + previous.load) * (next.shift - previous.shift);
            gross_slip |= (0..n).all(|i| forces[i] <= 0.0 || !next.stick[i]);
            states.push(next);
            pressures.push(forces);
        }
        let slip_amplitude = (0..n)
            .map(|i| half_slip[0][i].max(half_slip[1][i]))
            .collect();
        let cycle = FrettingCycle {
            states,
            dissipated,
            loop_area,
            slip_amplitude,
            never_slips,
            gross_slip,
        };
        Ok((cycle, pressures))
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

    /// The cycle's wear per unit β̃ at each point, Σ_k p̄_kᵇ |Δs_k|ᵃ Δt^(1−a) with p̄_k the
    /// stage's mean pressure (`pressures`: each state's, MPa), written as `term`·pᵇ + `extra`
    /// so that it is exact at p = `reference` (MPa), the pressure the wear step takes as its
    /// unknown, and smooth in it. Where the cycle presses a point less than the reference
    /// does (the uncoupled cycle: equally), the stages' pressures are scaled with the
    /// reference: `term` = Σ (p̄_k/p_ref)ᵇ |Δs_k|ᵃ Δt^(1−a), `extra` = 0. Where it presses
    /// more, the excess is held: `term` = Σ |Δs_k|ᵃ Δt^(1−a), `extra` the rest, ≥ 0. A
    /// ratio p̄_k/p_ref would grow without bound at a point that the coupled cycle's shear
    /// presses and the reference hardly does (the contact's edge), and drop to nothing where
    /// the reference is zero; the held excess does neither.
    pub fn weighted_sliding_term(
        &self,
        (a, b): (f64, f64),
        omega: f64,
        pressures: &[Vec<f64>],
        reference: &[f64],
    ) -> (Vec<f64>, Vec<f64>) {
        let n = self.slip_amplitude.len();
        let stage_time = std::f64::consts::PI / (self.stages() as f64 * omega);
        let power = |p: f64| if b == 1.0 { p } else { p.max(0.0).powf(b) };
        let (mut term, mut extra) = (vec![0.0; n], vec![0.0; n]);
        for i in 0..n {
            let (mut plain, mut scaled, mut pressed) = (0.0, 0.0, 0.0);
            for (k, state) in self.states.iter().enumerate().skip(1) {
                let slip = state.slip[i].abs();
                let weight = if a == 1.0 {
                    slip
                } else {
                    slip.powf(a) * stage_time.powf(1.0 - a)
                };
                let mean = 0.5 * (pressures[k - 1][i] + pressures[k][i]);
                plain += weight;
                pressed += power(mean) * weight;
                if reference[i] > 0.0 {
                    scaled += power(mean / reference[i]) * weight;
                }
            }
            if reference[i] > 0.0 && scaled <= plain {
                term[i] = scaled;
            } else {
                term[i] = plain;
                extra[i] = (pressed - power(reference[i].max(0.0)) * plain).max(0.0);
            }
        }
        (term, extra)
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

/// The normal problem's answer to the tangential forces of a coupled cycle.
pub trait NormalResponse {
    /// The normal forces P (N, one per point) and the plate's rigid motion λ (mm, rad) when
    /// body 1 carries the tangential forces `force` (N along +τ).
    fn respond(&mut self, force: &[f64]) -> Result<(Vec<f64>, Vec<f64>), String>;
}

/// What couples the normal and the tangential problem.
pub struct Coupling<'a> {
    /// A_nt = n_iᵀ G τ_j, mm/N (N × N, row-major).
    pub a_nt: &'a [f64],
    /// n_i,x of each point.
    pub normal_x: &'a [f64],
    /// τ_i·φ_k(x_i), the tangential displacement per unit rigid motion λ_k (N × m, row-major).
    pub rigid_tangential: &'a [f64],
    /// The normal forces (N) and rigid motion after the normal loading.
    pub initial: (&'a [f64], &'a [f64]),
}

/// Why a coupled cycle failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CoupledError {
    /// The tangential problem failed.
    #[error("{0}")]
    Tangential(PartialSlipError),
    /// The normal solve failed.
    #[error("the normal solve failed: {0}")]
    Normal(String),
    /// The fixed point between the two problems did not converge.
    #[error("the normal and tangential problems did not agree in {iterations} iterations (the pressure still changed by {change:.3e} of its largest)")]
    NotConverged {
        /// Iterations made.
        iterations: usize,
        /// Last relative change of the normal forces.
        change: f64,
    },
}

/// Most fixed-point iterations of a coupled stage.
const COUPLED_ITERATIONS: usize = 200;

/// A coupled stage's agreement: the normal forces' change between iterations, relative to
/// the largest (the solves' round-off is some 1e-13).
const COUPLED_TOLERANCE: f64 = 1e-10;

/// A change below this that no longer falls is taken as agreement: a review found a stage
/// that reached 4.7e-10 and then repeated it for ever (a point turning in and out of contact
/// at round-off), which stopped a gross-slip run at a third of its cycles.
const STALLED_TOLERANCE: f64 = 1e-8;

impl FrettingCycle {
    /// The cycle of the coupled problem: at every stage the tangential forces enter the
    /// normal problem (the gap −A_nt F, the plate's equilibrium) and the normal forces' change
    /// enters the tangential one ([`crate::partial_slip::NormalChange`]), iterated to agreement
    /// (a fixed point: the coupling is of the order μ times Dundurs' β for a half-space pair,
    /// and the finite bodies' own). `problem` holds A_tt, the tangents and μ; its normal forces
    /// are replaced stage by stage. `normal_forces` of the result holds each state's.
    pub fn solve_coupled(
        problem: &TangentialProblem,
        coupling: &Coupling,
        normal: &mut dyn NormalResponse,
        loading: &FrettingLoading,
    ) -> Result<(FrettingCycle, Vec<Vec<f64>>), CoupledError> {
        let mut current = (coupling.initial.0.to_vec(), coupling.initial.1.to_vec());
        Self::run_stages(loading, |control, from| {
            let state = coupled_stage(problem, coupling, normal, control, from, &mut current)?;
            Ok((state, current.0.clone()))
        })
    }
}

/// One coupled stage from `from` under `control`; `current` holds the normal forces and the
/// rigid motion, updated to the stage's end.
fn coupled_stage(
    problem: &TangentialProblem,
    coupling: &Coupling,
    normal: &mut dyn NormalResponse,
    control: TangentialControl,
    from: Option<&PartialSlip>,
    current: &mut (Vec<f64>, Vec<f64>),
) -> Result<PartialSlip, CoupledError> {
    let n = problem.tangent_x.len();
    let m = coupling.initial.1.len();
    let mut change = f64::INFINITY;
    for _ in 0..COUPLED_ITERATIONS {
        let last_change = change;
        let (force, rigid) = (&current.0, &current.1);
        let delta: Vec<f64> = (0..n).map(|j| force[j] - coupling.initial.0[j]).collect();
        let slip: Vec<f64> = (0..n)
            .map(|i| {
                let normal_part: f64 = (0..n).map(|j| -coupling.a_nt[j * n + i] * delta[j]).sum();
                let rigid_part: f64 = (0..m)
                    .map(|k| {
                        coupling.rigid_tangential[i * m + k] * (rigid[k] - coupling.initial.1[k])
                    })
                    .sum();
                normal_part + rigid_part
            })
            .collect();
        let x_force = -(0..n).map(|j| coupling.normal_x[j] * delta[j]).sum::<f64>();
        let stage_problem = TangentialProblem {
            a_tt: problem.a_tt,
            tangent_x: problem.tangent_x,
            normal_force: force,
            friction: problem.friction,
            coupling: Some(super::partial_slip::NormalChange {
                slip: &slip,
                x_force,
            }),
        };
        let state = stage_problem
            .solve_stage(control, from)
            .map_err(CoupledError::Tangential)?;
        let (next_force, next_rigid) =
            normal.respond(&state.force).map_err(CoupledError::Normal)?;
        let largest = next_force.iter().fold(0.0f64, |a, f| a.max(f.abs()));
        change = (0..n)
            .map(|i| (next_force[i] - force[i]).abs())
            .fold(0.0, f64::max)
            / largest.max(f64::MIN_POSITIVE);
        *current = (next_force, next_rigid);
        let stalled = change <= STALLED_TOLERANCE && change >= 0.5 * last_change;
        if change <= COUPLED_TOLERANCE || stalled {
            return Ok(state);
        }
    }
    Err(CoupledError::NotConverged {
        iterations: COUPLED_ITERATIONS,
        change,
    })
}

/// The periodic cycle of a worn contact, as the fretting run and the final state ask for it:
/// uncoupled ([`Uncoupled`], the normal forces held) or coupled ([`Coupled`]).
pub trait CycleModel {
    /// The cycle at the normal forces `normal_force` (N; those of the frictionless solve of
    /// worn shape `shape`, mm), with each state's normal forces (N).
    fn cycle(
        &mut self,
        normal_force: &[f64],
        shape: &[f64],
    ) -> Result<(FrettingCycle, Vec<Vec<f64>>), CoupledError>;
}

/// Cattaneo's uncoupled cycle: the normal forces stay those of the normal loading.
pub struct Uncoupled<'a> {
    /// A_tt, mm/N.
    pub a_tt: &'a [f64],
    /// τ_i,x.
    pub tangent_x: &'a [f64],
    /// μ.
    pub friction: f64,
    /// The loading.
    pub loading: FrettingLoading,
}

impl CycleModel for Uncoupled<'_> {
    fn cycle(
        &mut self,
        normal_force: &[f64],
        _shape: &[f64],
    ) -> Result<(FrettingCycle, Vec<Vec<f64>>), CoupledError> {
        let problem = TangentialProblem {
            a_tt: self.a_tt,
            tangent_x: self.tangent_x,
            normal_force,
            friction: self.friction,
            coupling: None,
        };
        let cycle =
            FrettingCycle::solve(&problem, &self.loading).map_err(CoupledError::Tangential)?;
        let pressures = vec![normal_force.to_vec(); cycle.states.len()];
        Ok((cycle, pressures))
    }
}

/// The coupled cycle on a frictionless contact and its own solver (the run's solver carries
/// the wear's compliance).
pub struct Coupled<'a> {
    /// A_tt, mm/N.
    pub a_tt: &'a [f64],
    /// μ.
    pub friction: f64,
    /// The loading.
    pub loading: FrettingLoading,
    /// The contact, frictionless.
    pub contact: &'a CondensedContact,
    /// A frictionless solver of it.
    pub solver: ContactSolver,
    /// Normal solves made.
    pub solves: usize,
}

impl CycleModel for Coupled<'_> {
    fn cycle(
        &mut self,
        _normal_force: &[f64],
        shape: &[f64],
    ) -> Result<(FrettingCycle, Vec<Vec<f64>>), CoupledError> {
        let c = self.contact;
        let n = c.len();
        let tangent_x: Vec<f64> = c.points.tangent.iter().map(|t| t[0]).collect();
        let normal_x: Vec<f64> = c.points.normal.iter().map(|t| t[0]).collect();
        let rigid = rigid_tangential(c);
        let mut response = SolverResponse {
            solver: &mut self.solver,
            contact: c,
            shape,
            solves: 0,
        };
        let initial = response
            .respond(&vec![0.0; n])
            .map_err(CoupledError::Normal)?;
        let problem = TangentialProblem {
            a_tt: self.a_tt,
            tangent_x: &tangent_x,
            normal_force: &initial.0,
            friction: self.friction,
            coupling: None,
        };
        let coupling = Coupling {
            a_nt: &c.a_nt,
            normal_x: &normal_x,
            rigid_tangential: &rigid,
            initial: (&initial.0, &initial.1),
        };
        let result =
            FrettingCycle::solve_coupled(&problem, &coupling, &mut response, &self.loading);
        self.solves += response.solves;
        result
    }
}

/// The frictionless normal solve of a worn contact answering the tangential forces of a
/// coupled cycle ([`crate::fretting::NormalResponse`]): the gap g₀ + shape − A_nt F, and the
/// plate's load L + Σ_j (φ_k·τ_j) F_j (the tangential forces' share of its equilibrium).
pub struct SolverResponse<'a> {
    /// The frictionless solver.
    pub solver: &'a mut ContactSolver,
    /// The contact (frictionless).
    pub contact: &'a CondensedContact,
    /// The worn shape, mm.
    pub shape: &'a [f64],
    /// Solves made.
    pub solves: usize,
}

impl NormalResponse for SolverResponse<'_> {
    fn respond(&mut self, force: &[f64]) -> Result<(Vec<f64>, Vec<f64>), String> {
        let c = self.contact;
        let n = c.len();
        let gap: Vec<f64> = (0..n)
            .map(|i| {
                let tangential: f64 = (0..n).map(|j| c.a_nt[i * n + j] * force[j]).sum();
                c.points.initial_gap[i] + self.shape[i] - tangential
            })
            .collect();
        let load: Vec<f64> = (c.plate_load.iter().enumerate())
            .map(|(k, l)| {
                l + (0..n)
                    .map(|j| {
                        let (phi, t) = (c.rigid_modes[k][j], c.points.tangent[j]);
                        (phi[0] * t[0] + phi[1] * t[1]) * force[j]
                    })
                    .sum::<f64>()
            })
            .collect();
        self.solver.set_load(&load);
        let mut out = ContactSolution::default();
        let info = self.solver.solve_into(&gap, Direction::Plus, &mut out);
        self.solves += 1;
        if info.status != Status::Solved {
            return Err(format!(
                "complementarity residual {:.3e}, equilibrium residual {:.3e}",
                info.complementarity, info.equilibrium
            ));
        }
        Ok((out.force.clone(), out.rigid.clone()))
    }
}

/// τ_i·φ_k(x_i) of `contact` (N × m, row-major): the tangential displacement of each point per
/// unit rigid motion of the plate.
pub fn rigid_tangential(contact: &CondensedContact) -> Vec<f64> {
    let (n, m) = (contact.len(), contact.rigid_modes.len());
    let mut r = vec![0.0; n * m];
    for i in 0..n {
        for k in 0..m {
            let (phi, t) = (contact.rigid_modes[k][i], contact.points.tangent[i]);
            r[i * m + k] = phi[0] * t[0] + phi[1] * t[1];
        }
    }
    r
}
