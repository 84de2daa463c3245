//! # wearfem
//!
//! Sliding wear of two elastic bodies in contact, after Páczelt & Mróz, *Analysis of steady
//! wear processes for periodic sliding*: p-version finite elements, exact frictional contact on
//! the condensed contact points, and the Archard-type wear rule integrated over thousands of
//! half periods of reciprocating sliding.
//!
//! The modules form a pipeline, grouped in folders by stage (`fe`, `input`, `contact` with
//! `solver`, `wear` and `steady_state`, `jobs`, `report`); each module is also reachable at
//! the crate root under its own name:
//!
//! | stage | module | entry type |
//! |---|---|---|
//! | quadrature rules | [`quadrature`] | [`quadrature::Rule1d`] |
//! | shape functions | [`basis`] | [`basis::QuadBasis`] |
//! | exact geometry | [`geometry`] | [`geometry::Block`] |
//! | mesh | [`mesh`] | [`mesh::Mesh`] |
//! | materials | [`material`] | [`material::Material`] |
//! | dof numbering | [`dofs`] | [`dofs::DofMap`] |
//! | elasticity, condensation, factorisation | [`elasticity`] | [`elasticity::ElasticBody`] |
//! | loads, post-processing | [`loads`], [`fields`] | [`loads::Traction`] |
//! | problem files: schema, validation, model | [`schema`], [`problem`] | [`problem::Problem`] |
//! | overrides (`--set KEY=VALUE`) | [`overrides`] | [`overrides::Override`] |
//! | contact condensation | [`contact`] | [`contact::CondensedContact`] |
//! | small dense LU, Lemke's method | [`dense`], [`lemke`] | [`dense::DenseLu`] |
//! | contact solve | [`complementarity`] | [`complementarity::ContactSolver`] |
//! | sliding kinematics, extrapolation | [`kinematics`] | [`kinematics::ScheduleEntry`] |
//! | wear integration | [`wear`] | [`wear::WearIntegrator`] |
//! | wear input in engineering units | [`wear_units`] | [`wear_units::WearLawInput`] |
//! | steady worn state, directly | [`steady`] | [`steady::steady_state`] |
//! | the paper's §6: monotonic and averaged shapes | [`monotonic_shape`] | [`monotonic_shape::averaged_shape`] |
//! | the paper's §6: spline and penalty methods | [`paper_steady`], [`spline_method`] | [`paper_steady::solve_steady`] |
//! | jobs (elastic, contact, run, steady) | [`driver`] | [`driver::WearRun`] |
//! | deformed bodies behind a contact solve | [`deformation`] | [`deformation::contact_fields`] |
//! | parameter studies | [`sweep`] | [`sweep::Sweep`] |
//! | output files and plots | [`output`], [`plot`] | [`output::write_wear`] |
//! | ParaView files | [`vtk`] | [`vtk::write_run`] |
//! | validation report | [`validate`] | [`validate::run`] |
//!
//! Units everywhere: mm, N, MPa (N/mm²), s.
//!
//! ## Load, override, run, read the profiles
//!
//! ```
//! use wearfem::{driver, overrides::Override, problem::Problem};
//!
//! let text = wearfem::examples::example("punch-b40").unwrap(); // or std::fs::read_to_string
//! let sets = [Override::parse("contact.friction=0.1")?, Override::parse("plate.pin=[1100, 120]")?];
//! let problem = Problem::with_overrides(text, "punch-b40", &sets)?;
//!
//! // The steady worn state, directly: pressures in MPa, shape in mm, one per contact point.
//! let (state, contact, _seconds) = driver::steady(&problem)?;
//! let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
//! assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
//! assert_eq!(x.len(), state.p_plus.len());
//! // Paper eq. 23a: p⁺ + p⁻ = 2p̃ = 33.332 MPa in the steady state.
//! assert!((state.p_plus[10] + state.p_minus[10] - 33.332).abs() < 1e-6);
//!
//! // Or the wear time integration, here 20 steps, with a callback after each step.
//! let run = driver::wear(&problem, Some(20), |step| assert!(step.criterion.is_finite()))?;
//! let summary = run.summary(&problem); // what `wearfem run` writes as summary.json
//! assert_eq!(summary["steps"].as_array().unwrap().len(), 20);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

/// The version of this build: the crate version, plus `+g<commit>` (12 hex digits) when it
/// was built from a git checkout (`build.rs`), e.g. `0.1.0+g1a2b3c4d5e6f`. Every summary.json
/// carries it as `wearfem_version`, and Python has it as `wearfem.__version__`, so that results
/// can be traced to the source that computed them.
pub const VERSION: &str = env!("WEARFEM_VERSION");

pub mod checks;
pub mod contact;
pub mod fe;
pub mod input;
pub mod jobs;
pub mod report;
pub mod solver;
pub mod steady_state;
pub mod wear;

// Every stage's modules stay reachable at the crate root (`wearfem::basis`, …), as before the
// folders grouped them.
pub use checks::{codes, p_check, steady_check, validity, warnings};
pub use fe::{
    basis, conduction, dofs, elasticity, fields, geometry, loads, material, mesh, quadrature,
};
pub use input::{
    examples, fretting as fretting_input, gmsh, heat as heat_input, overrides, problem, schema,
    wear_units,
};
pub use jobs::{driver, sweep, validate};
pub use report::{deformation, output, plot, vtk};
pub use solver::{capacitance, complementarity, dense, fretting, lemke, partial_slip, updated_lu};
pub use steady_state::{
    monotonic_shape, paper_steady, spline_method, steady, thermal as thermal_steady,
};
pub use wear::kinematics;
