//! The heat outputs of a wear run: heat.csv (the contact temperatures and the thermal gap at
//! the end), and the figures temperature.svg (the probes' and each body's largest
//! temperature per step) and contact_temperature.svg (along the contact at the end).

use super::{number, numbers, plot_error, write_csv, write_json, OutputError};
use crate::plot::{line_plot, Series};
use std::path::Path;

/// Write heat.csv, temperature.svg and contact_temperature.svg of `run` into `dir`; nothing
/// for a run without heat.
pub fn write_heat(dir: &Path, name: &str, run: &crate::driver::WearRun) -> Result<(), OutputError> {
    let h = &run.history;
    let Some(thermal) = &h.thermal else {
        return Ok(());
    };
    let x: Vec<f64> = run.contact.points.x.iter().map(|p| p[0]).collect();
    let rows: Vec<Vec<serde_json::Value>> = (0..x.len())
        .map(|i| {
            vec![
                number(x[i]),
                number(thermal.contact_temperature[0][i]),
                number(thermal.contact_temperature[1][i]),
                number(thermal.thermal_gap[i]),
            ]
        })
        .collect();
    write_csv(
        dir,
        "heat.csv",
        &[
            "x_mm",
            "contact_temperature_body1_C",
            "contact_temperature_body2_C",
            "thermal_gap_mm",
        ],
        &rows,
    )?;
    let [body1, body2] = run.body_names.clone();
    let max_labels = [format!("largest, {body1}"), format!("largest, {body2}")];
    let mut series: Vec<Series> = run
        .probes
        .iter()
        .enumerate()
        .map(|(k, (probe, _))| Series {
            label: probe,
            points: h
                .steps
                .iter()
                .filter_map(|s| Some((s.half_period as f64, *s.temperatures.get(k)?)))
                .collect(),
        })
        .collect();
    for (b, label) in max_labels.iter().enumerate() {
        series.push(Series {
            label,
            points: h
                .steps
                .iter()
                .filter_map(|s| Some((s.half_period as f64, s.max_temperature?[b])))
                .collect(),
        });
    }
    let path = dir.join("temperature.svg");
    line_plot(
        &path,
        &format!("{name}: temperature at the end of each step"),
        run.time_axis(),
        "temperature (°C)",
        &series,
    )
    .map_err(plot_error(&path))?;
    let profile = |v: &[f64]| x.iter().zip(v).map(|(&a, &b)| (a, b)).collect::<Vec<_>>();
    let labels = [
        format!("{body1} (contact points)"),
        format!("{body2} (partners)"),
    ];
    let series = [
        Series {
            label: &labels[0],
            points: profile(&thermal.contact_temperature[0]),
        },
        Series {
            label: &labels[1],
            points: profile(&thermal.contact_temperature[1]),
        },
    ];
    let path = dir.join("contact_temperature.svg");
    line_plot(
        &path,
        &format!("{name}: contact temperature at the end"),
        "x (mm)",
        "temperature (°C)",
        &series,
    )
    .map_err(plot_error(&path))
}

/// Add the periodic temperature of a steady state with heat to the steady state's files in
/// `dir`: summary.json's `heat` block, steady_heat.csv (the thermal gaps and the contact
/// temperatures at the start of each half cycle) and contact_temperature.svg.
pub fn write_steady_heat(
    dir: &Path,
    problem: &crate::problem::Problem,
    contact: &crate::contact::CondensedContact,
    heat: &crate::thermal_steady::PeriodicHeat,
) -> Result<(), OutputError> {
    let path = dir.join("summary.json");
    let mut summary: serde_json::Value = std::fs::read_to_string(&path)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_else(|| serde_json::json!({}));
    summary["heat"] = serde_json::json!({
        "thermal_gap_plus": numbers(&heat.thermal_gap[0]),
        "thermal_gap_minus": numbers(&heat.thermal_gap[1]),
        "contact_temperature_plus": { "body1": numbers(&heat.contact_temperature[0][0]), "body2": numbers(&heat.contact_temperature[0][1]) },
        "contact_temperature_minus": { "body1": numbers(&heat.contact_temperature[1][0]), "body2": numbers(&heat.contact_temperature[1][1]) },
        "passes": heat.passes,
        "pressure_change": number(heat.change),
    });
    write_json(dir, "summary.json", &summary)?;
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let rows: Vec<Vec<serde_json::Value>> = (0..x.len())
        .map(|i| {
            vec![
                number(x[i]),
                number(heat.thermal_gap[0][i]),
                number(heat.thermal_gap[1][i]),
                number(heat.contact_temperature[0][0][i]),
                number(heat.contact_temperature[1][0][i]),
            ]
        })
        .collect();
    write_csv(
        dir,
        "steady_heat.csv",
        &[
            "x_mm",
            "thermal_gap_plus_mm",
            "thermal_gap_minus_mm",
            "contact_temperature_plus_C",
            "contact_temperature_minus_C",
        ],
        &rows,
    )?;
    let name = crate::plot::problem_name(&problem.file);
    let profile = |v: &[f64]| x.iter().zip(v).map(|(&a, &b)| (a, b)).collect::<Vec<_>>();
    let series = [
        Series {
            label: "start of '+' half",
            points: profile(&heat.contact_temperature[0][0]),
        },
        Series {
            label: "start of '−' half",
            points: profile(&heat.contact_temperature[1][0]),
        },
    ];
    let path = dir.join("contact_temperature.svg");
    line_plot(
        &path,
        &format!("{name}: periodic contact temperature of the steady state"),
        "x (mm)",
        "temperature (°C)",
        &series,
    )
    .map_err(plot_error(&path))
}
