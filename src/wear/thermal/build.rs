//! The set-up of a run's heat problem: both bodies' conduction operators side by side with
//! the interface of perfect contact ([`CoupledSystem`]: the full model, which the tests step
//! as the reference), and its reduction to the modes the run steps ([`ThermalModel`]).

use super::bodies::{conduction_spec, contact_diffusivity, peclet};
use super::outputs::{boundary_samples, stored_output, thermal_gap, GapOutput, Output};
use super::{Dynamics, Sliding, ThermalFields, ThermalInfo, ThermalModel, INTERFACE_CONDUCTANCE};
use crate::basis::Space;
use crate::conduction::blocks::{assemble_pair, Block, BlockOperator, PairedMatrices};
use crate::conduction::reduced::{
    constant_gain, decay, half_sine_gain, HeatOperators, ReducedModel,
};
use crate::conduction::transient::Sdirk2;
use crate::conduction::ConductionBody;
use crate::contact::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::elasticity::ThermalLoads;
use crate::geometry::Point;
use crate::heat_input::{HeatSettings, Partition};
use faer::Mat;
use std::sync::Arc;
use std::time::Instant;

/// Errors of the heat problem's set-up.
#[derive(Debug, thiserror::Error)]
pub enum ThermalError {
    /// A body's conduction operators could not be built.
    #[error(transparent)]
    Conduction(#[from] crate::conduction::ConductionError),
    /// The reduction failed.
    #[error(transparent)]
    Reduction(#[from] crate::conduction::reduced::ReductionError),
    /// The thermal load or the elastic solve of a body failed.
    #[error("body \"{body}\": {message}")]
    Elastic {
        /// Body name.
        body: String,
        /// What failed.
        message: String,
    },
    /// Body 2's material cannot move through the contact as a rigid body.
    #[error("heat under monotonic sliding: body 2's material moves through the contact, but {0}; a strip (straight contact edge) or a ring or disc (circular one) can")]
    Counterface(String),
    /// A probe is not inside body 1.
    #[error("probe at ({}, {}) is not inside body 1", .0[0], .0[1])]
    Probe(Point),
}

/// What the heat problem of a run is built from: the two elastic bodies of the contact (for
/// their meshes and the thermal gap), the condensed contact (points, partners, traces), the
/// validated `[heat]` section, and the sliding.
pub struct ThermalBodies<'a> {
    /// Body 1 and body 2, as the contact stage built them (body 1 clamped at its plate edge).
    pub elastic: [&'a ElasticBody; 2],
    /// The contact.
    pub contact: &'a CondensedContact,
    /// The `[heat]` section.
    pub settings: &'a HeatSettings,
    /// The displacement's polynomial space (`analysis.space`); the temperature's follows
    /// from it and `heat.space` ([`crate::heat_input::HeatSpace`]).
    pub space: Space,
    /// The sliding (time profile of the heat).
    pub sliding: Sliding,
    /// Points where the temperature of body 1 is reported, mm.
    pub probes: Vec<Point>,
}

/// Shifts of the reduction as multiples of 1/h (h the half period): from a thousand half
/// periods (the bodies' slow warming; σ = 0 adds the stationary response) to a thirtieth of
/// one (the ripple within a half period, which the run samples at its ends), eight apart
/// below 1/h and four above. With the contact's heat in a third as many shapes as points
/// ([`super::shapes`]) this set keeps the contact temperature within 1.2e-3 of its rise and
/// the thermal gap within 9e-4 of its size on punch-b40-heat (165 modes), where the set
/// before it, [`FLOWING_SHIFTS`] with half as many shapes, left 1.7e-3 and 7e-4 with 202
/// modes (docs/convergence.md, "The reduced heat model").
pub const SHIFTS: [f64; 7] = [
    1.0 / 1024.0,
    1.0 / 128.0,
    1.0 / 16.0,
    1.0 / 2.0,
    2.0,
    8.0,
    32.0,
];

/// The shifts of a body whose material flows through the contact (monotonic sliding), before
/// the geometric means between them that its non-symmetric projection adds
/// ([`CoupledSystem::shifts`]); measured in tests/heat_monotonic.rs.
pub const FLOWING_SHIFTS: [f64; 6] = [1.0 / 1024.0, 1.0 / 64.0, 1.0 / 8.0, 1.0 / 2.0, 2.0, 8.0];

/// The heat problem of a run in full: C Ṫ + K T = f₀ + F q(t) over both bodies' free
/// unknowns (body 1's first), and its outputs.
pub struct CoupledSystem {
    /// K (mW/K) as blocks: both bodies' and the interface's.
    pub conductivity: BlockOperator,
    /// C (mJ/K) as blocks.
    pub capacity: BlockOperator,
    /// K and C assembled on their common pattern (both triangles).
    pub matrices: PairedMatrices,
    /// f₀: the constant sources, mW.
    pub source: Vec<f64>,
    /// F: the load of a unit flux density (mW/mm²) at each contact point (unknowns × points).
    pub flux: Mat<f64>,
    /// The initial field.
    pub initial: Vec<f64>,
    /// The thermal gap (mm) at each contact point.
    pub gap: GapOutput,
    /// The temperature at each contact point of body 1 and at its partner on body 2.
    pub contact_temperature: [Output; 2],
    /// The temperature at each probe.
    pub probes: Output,
    /// The temperature at each body's boundary samples.
    pub boundary: [Output; 2],
    /// The heat stored in each body relative to the reference temperature, mJ.
    pub stored: [Output; 2],
    /// Constant vectors of each body (1 on its free unknowns' uniform field).
    constants: [Vec<f64>; 2],
    /// Whether every part of the heat problem can lose heat (K regular).
    pub has_exit: bool,
    /// Whether K is symmetric (no body's material flows through the contact).
    pub symmetric: bool,
    /// Whether frictional heat enters a body that cannot lose it.
    pub trapped: bool,
    /// Contact points whose trace on the body receiving their heat touches a held
    /// temperature (a corner of the contact on a held edge).
    pub held_points: usize,
    /// Interface conductance, mW/(mm²·K).
    pub conductance: f64,
    /// Péclet numbers.
    peclet: [f64; 2],
    /// Contact areas w_i t, mm².
    area: Vec<f64>,
    /// The shapes (points × m) in which the contact's heat enters the reduction, or None:
    /// one input per point ([`super::shapes`]).
    shapes: Option<Mat<f64>>,
    /// The two bodies' conduction operators, and where each one's free unknowns start.
    bodies: [ConductionBody; 2],
    offsets: [usize; 2],
    /// The two bodies' thermal load operators.
    loads: [Arc<ThermalLoads>; 2],
    /// The stress-free temperature, °C.
    reference: f64,
}

/// A trace over one body's full unknowns as (combined free index, coefficient) pairs and the
/// held part's value.
struct Split {
    free: Vec<(usize, f64)>,
    held: f64,
    /// Whether some of the trace's unknowns are held.
    touches_held: bool,
}

fn split(body: &ConductionBody, held: &[f64], offset: usize, trace: &[(usize, f64)]) -> Split {
    let mut out = Split {
        free: Vec::with_capacity(trace.len()),
        held: 0.0,
        touches_held: false,
    };
    for &(g, c) in trace {
        match body.free_index(g) {
            Some(f) => out.free.push((offset + f, c)),
            None => {
                out.held += c * held[g];
                out.touches_held |= c != 0.0;
            }
        }
    }
    out
}

/// The scalar trace of a contact constraint from its displacement trace: the scalar boundary
/// numbering is the vector one halved ([`crate::dofs::DofMap::scalar`]), and the shape
/// function values are the same.
fn scalar_trace(trace: &crate::contact::Trace) -> Vec<(usize, f64)> {
    trace
        .iter()
        .map(|&(g, c)| {
            debug_assert!(
                g[1] == g[0] + 1 && g[0] % 2 == 0,
                "a vector DofMap's x, z pair"
            );
            (g[0] / 2, c)
        })
        .collect()
}

impl CoupledSystem {
    /// The full heat problem of a run.
    pub fn new(input: &ThermalBodies<'_>) -> Result<CoupledSystem, ThermalError> {
        let settings = input.settings;
        let contact = input.contact;
        let n = contact.len();
        let specs = [conduction_spec(input, 0)?, conduction_spec(input, 1)?];
        let (first, second) = rayon::join(
            || ConductionBody::new(&input.elastic[0].mesh, &specs[0]),
            || ConductionBody::new(&input.elastic[1].mesh, &specs[1]),
        );
        let thermal = [first?, second?];
        let held = [0, 1].map(|b| thermal[b].expand(&vec![0.0; thermal[b].n_free()]));
        let (n1, n2) = (thermal[0].n_free(), thermal[1].n_free());
        let size = n1 + n2;
        let offsets = [0, n1];
        let traces: [Vec<Split>; 2] = [0, 1].map(|b| {
            contact.traces[b]
                .iter()
                .map(|t| split(&thermal[b], &held[b], offsets[b], &scalar_trace(t)))
                .collect()
        });
        let mut conductivity = BlockOperator {
            size,
            blocks: Vec::new(),
        };
        let mut capacity = conductivity.clone();
        let mut source = vec![0.0; size];
        for b in 0..2 {
            let (k, c) = thermal[b].free_operators(offsets[b], size);
            conductivity.blocks.extend(k.blocks);
            capacity.blocks.extend(c.blocks);
            source[offsets[b]..offsets[b] + thermal[b].n_free()].copy_from_slice(&thermal[b].load);
        }
        let area = contact.areas();
        let conductance = match settings.partition {
            Partition::Perfect => {
                let k_max = settings
                    .materials
                    .iter()
                    .map(|m| m.conductivity)
                    .fold(0.0, f64::max);
                let w_min = contact
                    .points
                    .weight
                    .iter()
                    .cloned()
                    .fold(f64::INFINITY, f64::min);
                INTERFACE_CONDUCTANCE * k_max / w_min
            }
            Partition::Fraction(_) => 0.0,
        };
        if conductance > 0.0 {
            for i in 0..n {
                // h_c w t (e₁ − e₂)(e₁ − e₂)ᵀ, the held parts moved to the sources.
                let weight = conductance * area[i];
                let mut e: Vec<(usize, f64)> = traces[0][i].free.clone();
                e.extend(traces[1][i].free.iter().map(|&(g, c)| (g, -c)));
                for &(a, ca) in &e {
                    source[a] -= weight * ca * (traces[0][i].held - traces[1][i].held);
                }
                let matrix = Mat::from_fn(e.len(), e.len(), |a, b| weight * e[a].1 * e[b].1);
                conductivity.blocks.push(Block {
                    unknowns: e.iter().map(|&(g, _)| (g, 1.0)).collect(),
                    matrix: std::sync::Arc::new(matrix),
                });
            }
        }
        // A unit flux density at point i: w_i t on the receiving body's trace (body 1's under
        // perfect contact: the tie shares it).
        let share = match settings.partition {
            Partition::Perfect => 1.0,
            Partition::Fraction(f) => f,
        };
        let held_points = (0..n)
            .filter(|&i| {
                [(0, share), (1, 1.0 - share)]
                    .iter()
                    .any(|&(b, part)| part > 0.0 && traces[b][i].touches_held)
            })
            .count();
        let mut flux = Mat::<f64>::zeros(size, n);
        for i in 0..n {
            for (b, part) in [(0, share), (1, 1.0 - share)] {
                if part == 0.0 {
                    continue;
                }
                for &(g, c) in &traces[b][i].free {
                    flux[(g, i)] += part * c * area[i];
                }
            }
        }
        let body_vector = |b: usize, field: Vec<f64>| {
            let mut v = vec![0.0; size];
            v[offsets[b]..offsets[b] + field.len()].copy_from_slice(&field);
            v
        };
        let initial: Vec<f64> = [0, 1]
            .iter()
            .flat_map(|&b| thermal[b].restrict(&thermal[b].uniform(settings.initial)))
            .collect();
        let constants =
            [0, 1].map(|b| body_vector(b, thermal[b].restrict(&thermal[b].uniform(1.0))));
        // K is regular when every body that is a heat problem of its own can lose heat (one
        // problem under perfect contact, two with a given share); the frictional heat is
        // trapped when a body that receives some has no way out.
        let has_exit = match settings.partition {
            Partition::Perfect => thermal[0].has_exit || thermal[1].has_exit,
            Partition::Fraction(_) => thermal[0].has_exit && thermal[1].has_exit,
        };
        let trapped = match settings.partition {
            Partition::Perfect => !has_exit,
            Partition::Fraction(f) => {
                (f > 0.0 && !thermal[0].has_exit) || (f < 1.0 && !thermal[1].has_exit)
            }
        };
        // The sparse assembly and the thermal gap's elastic set-up are independent: on two
        // threads.
        let (matrices, loads_and_gap) = rayon::join(
            || assemble_pair(&conductivity, &capacity),
            || thermal_loads_and_gap(input, &thermal, offsets),
        );
        let (loads, gap) = loads_and_gap?;
        let contact_temperature = [0, 1].map(|b| of_traces(&traces[b]));
        let mut probe_traces = Vec::new();
        for &x in &input.probes {
            let (element, xi, eta) = thermal[0].mesh.locate(x).ok_or(ThermalError::Probe(x))?;
            probe_traces.push(split(
                &thermal[0],
                &held[0],
                0,
                &thermal[0].point_trace(element, xi, eta),
            ));
        }
        let probes = of_traces(&probe_traces);
        let boundary = [0, 1].map(|b| {
            let samples = boundary_samples(&thermal[b], &settings.bodies[b].contact_edge);
            let splits: Vec<Split> = samples
                .iter()
                .map(|t| split(&thermal[b], &held[b], offsets[b], t))
                .collect();
            of_traces(&splits)
        });
        let stored =
            [0, 1].map(|b| stored_output(&thermal[b], &held[b], offsets[b], settings.reference));
        let peclet = [0, 1].map(|b| peclet(input, &thermal[b], b));
        let symmetric = thermal[0].is_symmetric() && thermal[1].is_symmetric();
        Ok(CoupledSystem {
            conductivity,
            capacity,
            matrices,
            source,
            flux,
            initial,
            gap,
            contact_temperature,
            probes,
            boundary,
            stored,
            constants,
            has_exit,
            symmetric,
            trapped,
            held_points,
            conductance,
            peclet,
            area,
            // A flowing body's heat stays with its point (see the shapes' module).
            shapes: if symmetric {
                let diffusivity = [0, 1]
                    .map(|b| contact_diffusivity(input, &thermal[b], b))
                    .into_iter()
                    .fold(f64::INFINITY, f64::min);
                let depth = (diffusivity * input.sliding.half_period()).sqrt();
                super::shapes::shapes(&contact.points.x, depth)
            } else {
                None
            },
            bodies: thermal,
            offsets,
            loads,
            reference: settings.reference,
        })
    }

    /// The heat leaving both bodies (mW) at `field` (combined free unknowns, °C): through
    /// convecting edges and faces and held edges ([`ConductionBody::heat_out`]), `rate` being
    /// dT/dt (K/s) for a transient. Heat crossing between the bodies is internal.
    pub fn heat_out(&self, field: &[f64], rate: Option<&[f64]>) -> f64 {
        (0..2)
            .map(|b| {
                let body = &self.bodies[b];
                let range = self.offsets[b]..self.offsets[b] + body.n_free();
                let full = body.expand(&field[range.clone()]);
                // A rate is zero at held unknowns.
                let rate = rate.map(|r| {
                    let mut full = body.expand(&r[range]);
                    let held = body.expand(&vec![0.0; body.n_free()]);
                    for (f, h) in full.iter_mut().zip(held) {
                        *f -= h;
                    }
                    full
                });
                body.heat_out(&full, rate.as_deref()).total()
            })
            .sum()
    }

    /// Number of unknowns.
    pub fn len(&self) -> usize {
        self.source.len()
    }

    /// Whether there are no unknowns.
    pub fn is_empty(&self) -> bool {
        self.source.is_empty()
    }

    /// Advance the full model by one half period of reciprocating sliding at `omega` (rad/s)
    /// in `substeps` SDIRK2 steps of `stepper` (made for that sub-step length), the frictional
    /// flux being `amplitude` (mW/mm², one per contact point) times sin ωt: the reference the
    /// reduced model is checked against.
    pub fn reference_half_period(
        &self,
        t: &mut [f64],
        stepper: &Sdirk2,
        amplitude: &[f64],
        omega: f64,
        substeps: usize,
    ) {
        let mut load = vec![0.0; self.len()];
        for (j, &q) in amplitude.iter().enumerate() {
            for (i, l) in load.iter_mut().enumerate() {
                *l += self.flux[(i, j)] * q;
            }
        }
        let h = std::f64::consts::PI / omega / substeps as f64;
        for step in 0..substeps {
            stepper.advance(t, step as f64 * h, |tau| {
                let s = (omega * tau).sin();
                self.source
                    .iter()
                    .zip(&load)
                    .map(|(f, l)| f + l * s)
                    .collect()
            });
        }
    }

    /// A stepper of the full model for steps of `step` s.
    pub fn stepper(&self, step: f64) -> Option<Sdirk2> {
        Sdirk2::with_symmetry(
            &self.matrices.first,
            &self.matrices.second,
            step,
            self.symmetric,
        )
    }

    /// The shifts of the reduction for half periods (step units) of `half_period` s.
    pub fn shifts(&self, half_period: f64) -> Vec<f64> {
        let mut shifts: Vec<f64> = if self.has_exit { vec![0.0] } else { vec![] };
        if self.symmetric {
            shifts.extend(SHIFTS.iter().map(|s| s / half_period));
            return shifts;
        }
        for (i, s) in FLOWING_SHIFTS.iter().enumerate() {
            shifts.push(s / half_period);
            // A non-symmetric projection matches one moment per shift, not two: twice as
            // many shifts, at the geometric means of the symmetric ones (on punch-b40-heat
            // under monotonic sliding: 436 modes instead of 321, the contact temperature over
            // 20 steps within 5e-5 of the rise instead of 2e-3; tests/heat_monotonic.rs).
            if let Some(next) = FLOWING_SHIFTS.get(i + 1) {
                shifts.push((s * next).sqrt() / half_period);
            }
        }
        shifts
    }

    /// The reduced model of this system at `shifts` (1/s).
    pub fn reduce(&self, shifts: &[f64]) -> Result<ReducedModel, ThermalError> {
        // The contact's heat in its shapes, F S, or one input per point, F.
        let shaped = self.shapes.as_ref().map(|s| &self.flux * s);
        let flux = shaped.as_ref().unwrap_or(&self.flux);
        let n = flux.ncols();
        let size = self.len();
        let mut inputs = Mat::<f64>::zeros(size, n + 2);
        let c_initial = self.capacity.apply_vector(&self.initial);
        for i in 0..size {
            for j in 0..n {
                inputs[(i, j)] = flux[(i, j)];
            }
            inputs[(i, n)] = self.source[i];
            inputs[(i, n + 1)] = c_initial[i];
        }
        let mut extra: Vec<Vec<f64>> = self.constants.to_vec();
        extra.push(self.initial.clone());
        let operators = HeatOperators {
            conductivity: &self.conductivity,
            capacity: &self.capacity,
            matrices: &self.matrices,
            symmetric: self.symmetric,
        };
        Ok(ReducedModel::new(
            operators,
            inputs.as_ref(),
            shifts,
            &extra,
        )?)
    }
}

impl ThermalModel {
    /// Build the heat problem of a run: the full system, reduced at the default shifts.
    pub fn build(input: ThermalBodies<'_>) -> Result<ThermalModel, ThermalError> {
        let start = Instant::now();
        let system = CoupledSystem::new(&input)?;
        let shifts = system.shifts(input.sliding.half_period());
        Self::from_system(&system, &shifts, &input, start)
    }

    /// The reduced model of `system` at `shifts` (1/s).
    pub fn from_system(
        system: &CoupledSystem,
        shifts: &[f64],
        input: &ThermalBodies<'_>,
        start: Instant,
    ) -> Result<ThermalModel, ThermalError> {
        let model = system.reduce(shifts)?;
        let flux_modal = model.project(system.flux.as_ref());
        let source_col = Mat::from_fn(system.len(), 1, |i, _| system.source[i]);
        let source_modal = model
            .project(source_col.as_ref())
            .col(0)
            .iter()
            .copied()
            .collect();
        let initial = model.coordinates(&system.capacity, &system.initial);
        let info = ThermalInfo {
            unknowns: system.len(),
            modes: model.len(),
            shifts: shifts.to_vec(),
            interface_conductance: system.conductance,
            has_exit: system.has_exit,
            trapped: system.trapped,
            held_points: system.held_points,
            peclet: system.peclet,
            reference: input.settings.reference,
            floor: input.settings.lowest_imposed(),
            seconds: start.elapsed().as_secs_f64(),
        };
        let h = input.sliding.half_period();
        let omega = match input.sliding {
            Sliding::Reciprocating { omega, .. } => omega,
            Sliding::Monotonic { .. } => 0.0,
        };
        let dynamics = match &model.coupling {
            None => Dynamics::Modal {
                rates: model.rates.clone(),
                half_period_gains: model
                    .rates
                    .iter()
                    .map(|&rate| {
                        let sine = if omega > 0.0 {
                            half_sine_gain(rate, omega)
                        } else {
                            0.0
                        };
                        (decay(rate, h), sine, constant_gain(rate, h))
                    })
                    .collect(),
            },
            Some(matrix) => Dynamics::Coupled {
                matrix: matrix.clone(),
                propagators: Default::default(),
            },
        };
        // The outputs in the modes first: the modes then move into the fields (a copy was
        // N r values of fresh memory, 11 MB on punch-b40-heat).
        let (gap, (contact_temperature, probes, boundary, stored)) = rayon::join(
            || system.gap.reduce(&model),
            || {
                (
                    [0, 1].map(|b| system.contact_temperature[b].reduce(&model)),
                    system.probes.reduce(&model),
                    [0, 1].map(|b| system.boundary[b].reduce(&model)),
                    [0, 1].map(|b| system.stored[b].reduce(&model)),
                )
            },
        );
        let fields = ThermalFields {
            modes: model.modes,
            bodies: system.bodies.clone(),
            offsets: system.offsets,
            loads: [Arc::clone(&system.loads[0]), Arc::clone(&system.loads[1])],
            reference: system.reference,
        };
        Ok(ThermalModel {
            fields,
            dynamics,
            flux_modal,
            source_modal,
            initial,
            gap,
            contact_temperature,
            probes,
            boundary,
            stored,
            friction: input.contact.friction,
            sliding: input.sliding,
            area: system.area.clone(),
            info,
        })
    }
}

/// Both bodies' thermal load operators (each on a thread of its own) and the thermal gap.
fn thermal_loads_and_gap(
    input: &ThermalBodies<'_>,
    thermal: &[ConductionBody; 2],
    offsets: [usize; 2],
) -> Result<([Arc<ThermalLoads>; 2], GapOutput), ThermalError> {
    let settings = input.settings;
    let expansion: Vec<f64> = settings.materials.iter().map(|m| m.expansion).collect();
    let of_body = |body: &ElasticBody, heat: &ConductionBody| {
        body.thermal_loads(&expansion, &heat.spaces.each())
            .map(Arc::new)
            .map_err(|e| ThermalError::Elastic {
                body: body.name.clone(),
                message: e.to_string(),
            })
    };
    let (first, second) = rayon::join(
        || of_body(input.elastic[0], &thermal[0]),
        || of_body(input.elastic[1], &thermal[1]),
    );
    let loads: [Arc<ThermalLoads>; 2] = [first?, second?];
    let gap = thermal_gap(
        input.elastic,
        thermal,
        input.contact,
        offsets,
        [&loads[0], &loads[1]],
        settings.reference,
    )
    .map_err(|(body, message)| ThermalError::Elastic { body, message })?;
    Ok((loads, gap))
}

/// The sparse output of traces.
fn of_traces(traces: &[Split]) -> Output {
    Output {
        rows: traces.iter().map(|s| s.free.clone()).collect(),
        offset: traces.iter().map(|s| s.held).collect(),
    }
}
