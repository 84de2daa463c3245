//! Which states each command writes for ParaView, and the re-solve that recovers them.
//!
//! A wear run keeps the pressure and the shape of its recorded steps, not the plate motion, so
//! each state is solved once more from its gap (the recorded shape) and its sliding
//! direction; [`crate::deformation::contact_fields`] then recovers both bodies. The recorded
//! pressure is written beside the re-solved one (`pressure_recorded`): they differ by no more
//! than the wear step's implicit tolerance.

use super::{write_bodies, write_contact, write_pvd, PvdEntry, VtkBody, VtkContact};
use crate::complementarity::{ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::deformation::{contact_fields_with_heat, BodyField, RigidMotion};
use crate::driver::{direction, method, WearRun};
use crate::output::OutputError;
use crate::problem::{Problem, ProblemError};
use crate::steady::{SteadySliding, SteadyState};
use crate::thermal_steady::PeriodicHeat;
use crate::wear::thermal::ThermalModel;
use std::path::Path;

/// Name of the collection file written into the output directory.
pub const PVD_NAME: &str = "results.pvd";

/// Errors writing the ParaView files.
#[derive(Debug, thiserror::Error)]
pub enum VtkError {
    /// The problem could not be set up again (cannot happen after a successful job).
    #[error(transparent)]
    Problem(#[from] ProblemError),
    /// A file could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The contact solve of a state failed again; its files were not written.
    #[error("ParaView output: the contact solve of the state at time {time} failed (complementarity residual {residual:.3e}); its files were not written")]
    Unsolved {
        /// The state's time (half periods).
        time: f64,
        /// The failed solve's complementarity residual.
        residual: f64,
    },
}

/// One contact state to write.
pub struct ContactState {
    /// Time shown by ParaView: half periods done (0 for the initial state).
    pub time: f64,
    /// Sliding direction of the state's half cycle.
    pub direction: Direction,
    /// Gap g given to the contact solver (initial gap plus wear; after a run's first half
    /// cycle also the look-ahead, [`crate::wear::Snapshot::contact_shape`]), mm.
    pub gap: Vec<f64>,
    /// The worn shape reported for this state (initial gap plus wear), mm; `wear` is this
    /// minus the initial gap.
    pub shape: Vec<f64>,
    /// Pressure recorded by the run at this state, MPa, if any.
    pub recorded_pressure: Option<Vec<f64>>,
    /// With heat: the modal coordinates of the temperature the state was solved with.
    pub temperature: Option<Vec<f64>>,
    /// The depth worn off body 1 and off body 2 at each contact point, mm, where a run
    /// recorded it.
    pub body_wear: Option<[Vec<f64>; 2]>,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |source| OutputError {
        path: path.display().to_string(),
        source,
    }
}

/// Write `states` of `problem`'s contact pair into `dir`: `vtk/bodies_NNNN.vtu`,
/// `vtk/contact_NNNN.vtu` per state and the collection `results.pvd`.
pub fn write_contact_states(
    dir: &Path,
    problem: &Problem,
    states: &[ContactState],
    heat: Option<&ThermalModel>,
) -> Result<(), VtkError> {
    let (contact, body1, body2) = CondensedContact::build(problem)?;
    let mut solver = ContactSolver::new(&contact, method(problem)?);
    let mut entries = Vec::new();
    let mut unsolved = None;
    for (k, state) in states.iter().enumerate() {
        let (solution, info) = solver.solve(&state.gap, state.direction);
        if info.status != Status::Solved {
            // Fields from a failed solve would look like results; leave the state out.
            unsolved.get_or_insert(VtkError::Unsolved {
                time: state.time,
                residual: info.complementarity,
            });
            continue;
        }
        let temperatures = heat
            .zip(state.temperature.as_ref())
            .map(|(model, a)| model.temperature_fields(a));
        let fields = contact_fields_with_heat(
            problem,
            (&body1, &body2),
            &contact,
            &solution,
            state.direction,
            temperatures,
        )?;
        let bodies_file = format!("vtk/bodies_{k:04}.vtu");
        let path = dir.join(&bodies_file);
        let bodies = [
            VtkBody {
                body: &body1,
                field: &fields[0],
                id: 1,
            },
            VtkBody {
                body: &body2,
                field: &fields[1],
                id: 2,
            },
        ];
        write_bodies(&path, &bodies).map_err(io(&path))?;
        let displacement: Vec<[f64; 2]> = contact
            .points
            .x
            .iter()
            .map(|&x| {
                fields[0]
                    .values_at(&body1, x)
                    .map_or([0.0; 2], |v| v.displacement)
            })
            .collect();
        let zero_at = problem.spec.wear.as_ref().and_then(|w| w.shape_zero_at);
        let wear = crate::wear::wear_of_shape(&contact.points, &state.shape, zero_at);
        let mut values = vec![
            ("pressure", &solution.pressure[..]),
            ("gap", &solution.gap[..]),
            ("wear", &wear[..]),
            ("shape", &state.shape[..]),
        ];
        if let Some(p) = &state.recorded_pressure {
            values.push(("pressure_recorded", &p[..]));
        }
        if let Some([one, two]) = &state.body_wear {
            values.push(("wear_body1", &one[..]));
            values.push(("wear_body2", &two[..]));
        }
        let heat_values = heat.zip(state.temperature.as_ref()).map(|(model, a)| {
            (
                model.contact_temperature[0].at(a),
                model.contact_temperature[1].at(a),
                model.gap.at(a),
            )
        });
        if let Some((t1, t2, gap)) = &heat_values {
            values.push(("temperature", &t1[..]));
            values.push(("temperature_partner", &t2[..]));
            values.push(("thermal_gap", &gap[..]));
        }
        let contact_file = format!("vtk/contact_{k:04}.vtu");
        let path = dir.join(&contact_file);
        let line = VtkContact {
            x: &contact.points.x,
            displacement: &displacement,
            values,
        };
        write_contact(&path, &line).map_err(io(&path))?;
        entries.push(PvdEntry {
            time: state.time,
            part: 0,
            file: bodies_file,
        });
        entries.push(PvdEntry {
            time: state.time,
            part: 1,
            file: contact_file,
        });
    }
    let path = dir.join(PVD_NAME);
    write_pvd(&path, &entries).map_err(io(&path))?;
    unsolved.map_or(Ok(()), Err)
}

/// ParaView files of `wearfem contact`: the initial contact solve.
pub fn write_contact_job(dir: &Path, problem: &Problem) -> Result<(), VtkError> {
    let (contact, _, _) = CondensedContact::build(problem)?;
    let state = ContactState {
        time: 0.0,
        direction: direction(problem)?,
        gap: contact.points.initial_gap.clone(),
        shape: contact.points.initial_gap.clone(),
        recorded_pressure: None,
        temperature: None,
        body_wear: None,
    };
    write_contact_states(dir, problem, &[state], None)
}

/// ParaView files of `wearfem run`: the initial state (time 0), every recorded step
/// (`wear.record`) and the last step, at their half periods.
pub fn write_run(dir: &Path, problem: &Problem, run: &WearRun) -> Result<(), VtkError> {
    let first = direction(problem)?;
    let parse = |s: &str| {
        if s == "+" {
            Direction::Plus
        } else {
            Direction::Minus
        }
    };
    let heat = run.heat_model.as_deref();
    let mut states = vec![ContactState {
        time: 0.0,
        direction: first,
        gap: run.contact.points.initial_gap.clone(),
        shape: run.contact.points.initial_gap.clone(),
        recorded_pressure: None,
        temperature: heat.map(|m| m.start().a),
        body_wear: Some([vec![0.0; run.contact.len()], vec![0.0; run.contact.len()]]),
    }];
    let h = &run.history;
    for s in &h.snapshots {
        states.push(ContactState {
            time: s.half_period as f64,
            direction: parse(s.direction),
            gap: s.contact_shape.clone(),
            shape: s.shape.clone(),
            recorded_pressure: Some(s.pressure.clone()),
            temperature: s.thermal_state.clone(),
            body_wear: Some(s.body_wear.clone()),
        });
    }
    if let Some(last) = h.steps.last() {
        if h.snapshots.last().is_none_or(|s| s.step != last.step) {
            let d = parse(last.direction);
            let pressure = if d == Direction::Plus {
                &h.p_plus
            } else {
                &h.p_minus
            };
            states.push(ContactState {
                time: last.half_period as f64,
                direction: d,
                gap: h.contact_shape.clone(),
                shape: h.shape.clone(),
                recorded_pressure: Some(pressure.clone()),
                temperature: h.thermal.as_ref().map(|t| t.solved_state.clone()),
                body_wear: Some(h.body_wear.clone()),
            });
        }
    }
    write_contact_states(dir, problem, &states, heat)
}

/// ParaView files of `wearfem steady`: the steady shape in the '+' half cycle (time 0) and
/// the '−' half cycle (time 1); under monotonic sliding the one direction. With heat
/// (`heat`), each half cycle at the periodic temperature of its start, its gap the shape plus
/// that temperature's thermal gap.
pub fn write_steady(
    dir: &Path,
    problem: &Problem,
    state: &SteadyState,
    heat: Option<&PeriodicHeat>,
) -> Result<(), VtkError> {
    let mut states = vec![];
    match state.sliding {
        SteadySliding::Monotonic(d) => states.push((d, &state.p_plus)),
        SteadySliding::Reciprocating => {
            states.push((Direction::Plus, &state.p_plus));
            states.push((Direction::Minus, &state.p_minus));
        }
    }
    let states: Vec<ContactState> = states
        .into_iter()
        .enumerate()
        .map(|(k, (d, p))| {
            let mut gap = state.shape.clone();
            if let Some(heat) = heat {
                for (g, t) in gap.iter_mut().zip(&heat.thermal_gap[k]) {
                    *g += t;
                }
            }
            ContactState {
                time: k as f64,
                direction: d,
                gap,
                shape: state.shape.clone(),
                recorded_pressure: Some(p.clone()),
                temperature: heat.map(|h| h.modal[k].clone()),
                body_wear: None,
            }
        })
        .collect();
    write_contact_states(dir, problem, &states, heat.map(|h| &*h.model))
}

/// ParaView files of `wearfem elastic`: every body on its own supports under its own loads.
pub fn write_elastic(dir: &Path, problem: &Problem) -> Result<(), VtkError> {
    let mut bodies = vec![];
    for b in 0..problem.spec.bodies.len() {
        let body = problem.elastic_body(b, &[])?;
        let load = problem.load_vector(b, &body, &[])?;
        let field = BodyField {
            elastic: body
                .solve(&load)
                .map_err(|e| problem.error("bodies", e.to_string()))?,
            rigid: RigidMotion::default(),
            temperature: None,
        };
        bodies.push((body, field));
    }
    let list: Vec<VtkBody> = bodies
        .iter()
        .enumerate()
        .map(|(b, (body, field))| VtkBody {
            body,
            field,
            id: b as i32 + 1,
        })
        .collect();
    let file = "vtk/bodies_0000.vtu".to_string();
    let path = dir.join(&file);
    write_bodies(&path, &list).map_err(io(&path))?;
    let path = dir.join(PVD_NAME);
    write_pvd(
        &path,
        &[PvdEntry {
            time: 0.0,
            part: 0,
            file,
        }],
    )
    .map_err(io(&path))?;
    Ok(())
}
