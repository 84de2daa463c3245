//! The reduced heat model against the full one (docs/convergence.md, "The reduced heat
//! model"): punch-b40-heat's heat problem under the pressures of its first '+' and '−'
//! contact solves, stepped half period by half period by the full model in the tensor-product
//! space everywhere (SDIRK2, 32 steps per half period) and by reduced models in the run's
//! spaces (`heat.space`, default "auto": [`wearfem::conduction::spaces`]; `HEAT_SPACE=tensor`
//! or `trunk` to change it) at several sets of shifts; the largest differences of the contact
//! temperature (relative to its largest rise) and of the thermal gap (relative to its range)
//! over the run, and the set-up time of each reduced model. The differences are the
//! reduction's error plus that of the spaces.
//!
//! `cargo run --release --example heat_reduction [ELEMENTS] [HALF_PERIODS]` (default 8, 60).

use std::time::Instant;
use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::heat_input::{HeatSettings, HeatSpace};
use wearfem::problem::Problem;
use wearfem::wear::thermal::{
    CoupledSystem, Sliding, ThermalBodies, ThermalModel, FLOWING_SHIFTS, SHIFTS,
};

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let elements = args.first().copied().unwrap_or(8);
    let half_periods = args.get(1).copied().unwrap_or(60);
    let text = wearfem::examples::refined_punch("punch-b40-heat", elements).unwrap();
    let problem = Problem::from_toml(&text, "punch-b40-heat").unwrap();
    let settings = problem.heat_settings().unwrap().unwrap();
    let full_space = HeatSettings {
        space: HeatSpace::Tensor,
        ..settings.clone()
    };
    let reduced_settings = HeatSettings {
        space: match std::env::var("HEAT_SPACE").as_deref() {
            Ok("tensor") => HeatSpace::Tensor,
            Ok("trunk") => HeatSpace::Trunk,
            _ => settings.space,
        },
        ..settings.clone()
    };
    let (contact, body1, body2) = CondensedContact::build(&problem).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let pressures: Vec<Vec<f64>> = [Direction::Plus, Direction::Minus]
        .iter()
        .map(|&d| solver.solve(&contact.points.initial_gap, d).0.pressure)
        .collect();
    let (amplitude, omega) = (1.5, 10.0);
    let input_with = |settings| ThermalBodies {
        elastic: [&body1, &body2],
        contact: &contact,
        settings,
        space: problem.discretisation.space,
        sliding: Sliding::Reciprocating { amplitude, omega },
        probes: vec![],
    };
    let t = Instant::now();
    let system = CoupledSystem::new(&input_with(&full_space)).unwrap();
    let input = || input_with(&reduced_settings);
    let reduced_system = CoupledSystem::new(&input()).unwrap();
    println!(
        "{elements} elements: {} unknowns ({} in the reduced model's spaces), {} contact points; full system built in {:.3} s",
        system.len(),
        reduced_system.len(),
        contact.len(),
        t.elapsed().as_secs_f64()
    );
    // The full model's reference, at the end of every half period.
    let substeps: usize = std::env::var("SUBSTEPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(32);
    let h = std::f64::consts::PI / omega;
    let stepper = system.stepper(h / substeps as f64).unwrap();
    let mut field = system.initial.clone();
    let mut reference = Vec::new();
    let t = Instant::now();
    for n in 0..half_periods {
        let p = &pressures[n % 2];
        let amplitudes: Vec<f64> = p
            .iter()
            .map(|p| contact.friction * p.max(0.0) * amplitude * omega)
            .collect();
        system.reference_half_period(&mut field, &stepper, &amplitudes, omega, substeps);
        reference.push((
            system.contact_temperature[0].at(&field),
            system.gap.at(&field),
        ));
    }
    println!(
        "full model: {half_periods} half periods in {:.1} s",
        t.elapsed().as_secs_f64()
    );
    let rise = reference
        .iter()
        .flat_map(|(t, _)| t.iter())
        .fold(0.0f64, |m, t| m.max(t - settings.reference));
    let gap_range = reference
        .iter()
        .flat_map(|(_, g)| g.iter())
        .fold(0.0f64, |m, g| m.max(g.abs()));
    println!(
        "largest rise {rise:.3} K, largest thermal gap {:.3} µm",
        gap_range * 1e3
    );
    println!(
        "| shifts (× 1/h) | modes | set-up (s) | temperature error / rise | gap error / range | after 10 half periods: temperature, gap |"
    );
    println!("|---|---|---|---|---|---|");
    // The default first, then the set before it (the flowing body's), then fewer shifts.
    let sets: Vec<Vec<f64>> = vec![
        SHIFTS.to_vec(),
        FLOWING_SHIFTS.to_vec(),
        vec![1.0 / 1024.0, 1.0 / 64.0, 1.0 / 8.0, 1.0 / 2.0],
        vec![1.0 / 256.0, 1.0 / 16.0, 1.0 / 2.0, 4.0],
        vec![1.0 / 64.0, 1.0, 8.0],
    ];
    for set in sets {
        let mut shifts = vec![0.0];
        shifts.extend(set.iter().map(|s| s / h));
        let t = Instant::now();
        let model =
            ThermalModel::from_system(&reduced_system, &shifts, &input(), Instant::now()).unwrap();
        let setup = t.elapsed().as_secs_f64();
        let mut state = model.start();
        let (mut temperature_error, mut gap_error) = (0.0f64, 0.0f64);
        let (mut late_t, mut late_g) = (0.0f64, 0.0f64);
        for (n, (t_ref, g_ref)) in reference.iter().enumerate() {
            let d = if n % 2 == 0 {
                Direction::Plus
            } else {
                Direction::Minus
            };
            model.advance(&mut state, &pressures[n % 2], d, 1, n % 2 == 0);
            let t = model.contact_temperature[0].at(&state.a);
            let g = model.gap.at(&state.a);
            for i in 0..t.len() {
                temperature_error = temperature_error.max((t[i] - t_ref[i]).abs() / rise);
                gap_error = gap_error.max((g[i] - g_ref[i]).abs() / gap_range);
                if n >= 10 {
                    late_t = late_t.max((t[i] - t_ref[i]).abs() / rise);
                    late_g = late_g.max((g[i] - g_ref[i]).abs() / gap_range);
                }
            }
        }
        println!(
            "| {:?} | {} | {setup:.3} | {temperature_error:.2e} | {gap_error:.2e} | {late_t:.2e}, {late_g:.2e} |",
            set,
            model.modes()
        );
    }
}
