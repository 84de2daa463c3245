//! The figures of heat on punch-b40-heat (docs/figures.md, "Heat"): p(M) with and without
//! heat, the steady worn shape with and without heat (and the thermal gap it takes up), the
//! temperature history and the contact temperature at the end.
//!
//! `cargo run --release --example heat_figures -- OUTDIR` (default `docs/figures`).

use std::path::Path;
use wearfem::driver;
use wearfem::plot::{line_plot, Series};
use wearfem::problem::Problem;
use wearfem::wear::non_rigid_part;

fn problem(name: &str) -> Problem {
    Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap()
}

fn main() {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "docs/figures".into());
    let dir = Path::new(&out);
    std::fs::create_dir_all(dir).unwrap();
    let hot = problem("punch-b40-heat");
    let cold = problem("punch-b40");
    let run_hot = driver::wear(&hot, None, |_| {}).unwrap();
    let run_cold = driver::wear(&cold, None, |_| {}).unwrap();
    let m = run_hot.probes.iter().position(|(n, _)| n == "M").unwrap();
    let history = |run: &driver::WearRun| -> Vec<(f64, f64)> {
        run.history
            .steps
            .iter()
            .filter(|s| s.direction == "+")
            .map(|s| (s.half_period as f64, s.probes[m]))
            .collect()
    };
    line_plot(
        &dir.join("heat-pM.svg"),
        "punch-b40 with and without heat: p(M), '+' half cycles",
        "half periods",
        "pressure at M (MPa)",
        &[
            Series {
                label: "with heat (punch-b40-heat)",
                points: history(&run_hot),
            },
            Series {
                label: "without heat (punch-b40)",
                points: history(&run_cold),
            },
        ],
    )
    .unwrap();
    // The steady worn shapes, each with its rigid part removed (a shape is defined up to a
    // rigid motion of the plate), and the thermal gap of the '+' half cycle likewise.
    let (with, contact, _, heat) = driver::steady_with_heat(&hot).unwrap();
    let (without, ..) = driver::steady(&cold).unwrap();
    let heat = heat.unwrap();
    let r = contact.rigid_gap_matrix();
    let k = contact.rigid_modes.len();
    let w = &contact.points.weight;
    let all = vec![true; contact.len()];
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let curve = |v: &[f64]| -> Vec<(f64, f64)> {
        let v = non_rigid_part(v, &all, &r, k, w);
        x.iter().zip(&v).map(|(a, b)| (*a, b * 1e3)).collect()
    };
    let thermal: Vec<f64> = heat.thermal_gap[0].iter().map(|t| -t).collect();
    line_plot(
        &dir.join("heat-shape.svg"),
        "punch-b40 steady worn shape with and without heat (rigid part removed)",
        "x (mm)",
        "shape (µm)",
        &[
            Series {
                label: "with heat",
                points: curve(&with.shape),
            },
            Series {
                label: "without heat",
                points: curve(&without.shape),
            },
            Series {
                label: "minus the thermal gap of the '+' half",
                points: curve(&thermal),
            },
        ],
    )
    .unwrap();
    let thermal_end = run_hot.history.thermal.as_ref().unwrap();
    line_plot(
        &dir.join("heat-contact-temperature.svg"),
        "punch-b40-heat: contact temperature after 16 300 half periods",
        "x (mm)",
        "temperature (°C)",
        &[
            Series {
                label: "punch (contact points)",
                points: x
                    .iter()
                    .zip(&thermal_end.contact_temperature[0])
                    .map(|(a, b)| (*a, *b))
                    .collect(),
            },
            Series {
                label: "steady state, start of '+' half",
                points: x
                    .iter()
                    .zip(&heat.contact_temperature[0][0])
                    .map(|(a, b)| (*a, *b))
                    .collect(),
            },
        ],
    )
    .unwrap();
    let series = |f: &dyn Fn(&wearfem::wear::StepRecord) -> f64| -> Vec<(f64, f64)> {
        run_hot
            .history
            .steps
            .iter()
            .filter(|s| s.direction == "+")
            .map(|s| (s.half_period as f64, f(s)))
            .collect()
    };
    line_plot(
        &dir.join("heat-temperature.svg"),
        "punch-b40-heat: temperature at the end of each '+' step",
        "half periods",
        "temperature (°C)",
        &[
            Series {
                label: "M (punch's left edge)",
                points: series(&|s| s.temperatures[m]),
            },
            Series {
                label: "largest, punch",
                points: series(&|s| s.max_temperature.unwrap()[0]),
            },
        ],
    )
    .unwrap();
    println!("figures written to {}", dir.display());
}
