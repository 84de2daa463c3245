//! The files of the fretting jobs.
//!
//! - `contact`: summary.json, contact.csv (x, pressure, the shear at the cycle's four quarter
//!   instants, stick, slip amplitude), loop.csv (phase, tangential force, shift) and the
//!   figures loop and traction.
//! - `run`: summary.json, history.csv (one row per step: cycles, the stick zone, the energy
//!   per cycle, the deepest wear), profiles.csv (pressure and wear at the start, at each
//!   recorded cycle and at the end), loop.csv (the loop of each of those cycles), and the figures
//!   scar (the worn depth at the recorded cycles: the W-shaped scar), pressure, stick_zone and
//!   loop.
//! - `steady`: summary.json, final.csv and the figures final (pressure) and scar.

use crate::fretting::FrettingCycle;
use crate::jobs::fretting::{FrettingContact, FrettingRun, FrettingSteady};
use crate::output::{write_csv, write_json, OutputError};
use crate::plot::{line_plot, problem_name, Series};
use crate::problem::Problem;
use crate::report::json::number;
use serde_json::{json, Value};
use std::path::Path;

fn figure_error(dir: &Path) -> impl Fn(String) -> OutputError + '_ {
    move |e| OutputError {
        path: dir.display().to_string(),
        source: std::io::Error::other(e),
    }
}

/// loop.csv's rows of one cycle's loop ((shift mm, load N) per state) after `cycles` cycles.
fn loop_rows(cycles: f64, cycle_loop: &[(f64, f64)]) -> Vec<Vec<Value>> {
    let stages = ((cycle_loop.len() - 1) / 2).max(1) as f64;
    (cycle_loop.iter().enumerate())
        .map(|(k, (shift, load))| {
            vec![
                json!(cycles),
                json!(std::f64::consts::PI * k as f64 / stages),
                json!(load),
                json!(shift),
            ]
        })
        .collect()
}

/// The loop's points for a figure: shift in µm, load in N.
fn loop_points(cycle_loop: &[(f64, f64)]) -> Vec<(f64, f64)> {
    (cycle_loop.iter())
        .map(|(shift, load)| (1e3 * shift, *load))
        .collect()
}

/// A cycle's loop, (shift mm, load N) per state.
fn loop_of(cycle: &FrettingCycle) -> Vec<(f64, f64)> {
    cycle.states.iter().map(|s| (s.shift, s.load)).collect()
}

/// Write `contact`'s files into `dir`.
pub fn write_contact(
    dir: &Path,
    problem: &Problem,
    result: &FrettingContact,
) -> Result<(), OutputError> {
    let setup = &result.setup;
    let cycle = &result.cycle;
    let x = setup.x();
    let summary = result.summary(problem);
    write_json(dir, "summary.json", &summary)?;
    let n = x.len();
    let quarter = cycle.stages() / 2;
    let instants: Vec<usize> = if cycle.stages().is_multiple_of(2) {
        vec![0, quarter, 2 * quarter, 3 * quarter]
    } else {
        vec![0, cycle.stages()]
    };
    let rows: Vec<Vec<Value>> = (0..n)
        .map(|i| {
            let mut row = vec![json!(x[i]), json!(result.normal.pressure[i])];
            row.extend(
                instants
                    .iter()
                    .map(|&k| json!(cycle.states[k].force[i] / setup.area[i])),
            );
            row.push(json!(u8::from(cycle.never_slips[i])));
            row.push(json!(cycle.slip_amplitude[i]));
            row
        })
        .collect();
    let names: Vec<String> = instants
        .iter()
        .map(|&k| format!("shear_{}_MPa", phase_name(k, cycle.stages())))
        .collect();
    let mut header: Vec<&str> = vec!["x_mm", "pressure_MPa"];
    header.extend(names.iter().map(String::as_str));
    header.extend(["sticks", "slip_amplitude_mm"]);
    write_csv(dir, "contact.csv", &header, &rows)?;
    write_csv(
        dir,
        "loop.csv",
        &["cycle", "phase_rad", "load_N", "shift_mm"],
        &loop_rows(0.0, &loop_of(cycle)),
    )?;
    let name = problem_name(&problem.file);
    let e = figure_error(dir);
    line_plot(
        &dir.join("loop.svg"),
        &format!("{name}: the fretting loop"),
        "shift δ (µm)",
        "tangential force Q (N)",
        &[Series {
            label: "Q against δ",
            points: loop_points(&loop_of(cycle)),
        }],
    )
    .map_err(&e)?;
    let friction = setup.settings.friction;
    // The friction limits of the shear at the peak (−μp, Q along +x) and at the trough (+μp):
    // the coupled cycle's shear moves the pressure, so the normal loading's would not bound it.
    let pressure_at = |k: usize, i: usize| result.cycle_forces[k][i] / setup.area[i];
    let trough = cycle.stages();
    let inside = |i: &usize| {
        result.normal.pressure[*i] > 0.0
            || result.cycle_forces.iter().any(|f| f[*i] > 0.0)
            || x[*i].abs() < 1e-12
    };
    let loaded: Vec<usize> = (0..n).filter(inside).collect();
    let series_of = |f: &dyn Fn(usize) -> f64| loaded.iter().map(|&i| (x[i], f(i))).collect();
    let mut series = vec![
        Series {
            label: "μp at the trough",
            points: series_of(&|i| friction * pressure_at(trough, i)),
        },
        Series {
            label: "−μp at the peak",
            points: series_of(&|i| -friction * pressure_at(0, i)),
        },
    ];
    for (k, label) in instants.iter().zip(&names) {
        series.push(Series {
            label: label.as_str(),
            points: series_of(&|i| cycle.states[*k].force[i] / setup.area[i]),
        });
    }
    line_plot(
        &dir.join("traction.svg"),
        &format!("{name}: shear traction through the cycle"),
        "x (mm)",
        "shear traction on body 1 (MPa)",
        &series,
    )
    .map_err(&e)
}

fn phase_name(k: usize, stages: usize) -> &'static str {
    match (2 * k) / stages.max(1) {
        0 => "peak",
        1 => "quarter",
        2 => "trough",
        _ => "three_quarters",
    }
}

/// Write `run`'s files into `dir`.
pub fn write_run(dir: &Path, problem: &Problem, run: &FrettingRun) -> Result<(), OutputError> {
    let h = &run.history;
    let setup = &run.setup;
    let x = setup.x();
    let summary = run.summary(problem);
    write_json(dir, "summary.json", &summary)?;
    let rows: Vec<Vec<Value>> = h
        .steps
        .iter()
        .map(|s| {
            let (lo, hi) = s.stick_extent.unwrap_or((f64::NAN, f64::NAN));
            vec![
                json!(s.step),
                json!(s.cycles),
                json!(s.k),
                json!(s.peak_pressure),
                number(lo),
                number(hi),
                json!(s.slipping_points),
                json!(s.dissipated),
                json!(s.peak_load),
                json!(s.deepest_wear[0]),
                json!(s.deepest_wear[1]),
                json!(s.rejected),
            ]
        })
        .collect();
    write_csv(
        dir,
        "history.csv",
        &[
            "step",
            "cycles",
            "k",
            "peak_pressure_MPa",
            "stick_from_mm",
            "stick_to_mm",
            "slipping_points",
            "dissipated_per_cycle_Nmm",
            "peak_load_N",
            "deepest_wear_body1_mm",
            "deepest_wear_body2_mm",
            "rejected_jumps",
        ],
        &rows,
    )?;
    let mut rows = Vec::new();
    for r in &h.records {
        for (i, xi) in x.iter().enumerate() {
            rows.push(vec![
                json!(r.cycles),
                json!(xi),
                json!(r.pressure[i]),
                json!(r.shape[i]),
                json!(r.wear[0][i]),
                json!(r.wear[1][i]),
                json!(u8::from(r.never_slips[i])),
                json!(r.slip_amplitude[i]),
            ]);
        }
    }
    write_csv(
        dir,
        "profiles.csv",
        &[
            "cycles",
            "x_mm",
            "pressure_MPa",
            "worn_depth_mm",
            "wear_body1_mm",
            "wear_body2_mm",
            "sticks",
            "slip_amplitude_mm",
        ],
        &rows,
    )?;
    let rows: Vec<Vec<Value>> = (h.records.iter())
        .flat_map(|r| loop_rows(r.cycles, &r.cycle_loop))
        .collect();
    write_csv(
        dir,
        "loop.csv",
        &["cycle", "phase_rad", "load_N", "shift_mm"],
        &rows,
    )?;
    run_figures(dir, problem, run).map_err(figure_error(dir))
}

/// The x range the figures show: the first contact, widened by a fifth.
fn shown(x: &[f64], pressure: &[f64]) -> (f64, f64) {
    let touching = || (0..x.len()).filter(|&i| pressure[i] > 0.0).map(|i| x[i]);
    let lo = touching().fold(f64::INFINITY, f64::min);
    let hi = touching().fold(f64::NEG_INFINITY, f64::max);
    let pad = 0.2 * (hi - lo).max(1e-9);
    // Ends on a round step, so that the axis' ticks fall on round numbers (0 among them).
    let step = 10f64.powf((hi - lo + 2.0 * pad).log10().floor() - 1.0);
    (
        ((lo - pad) / step).floor() * step,
        ((hi + pad) / step).ceil() * step,
    )
}

fn run_figures(dir: &Path, problem: &Problem, run: &FrettingRun) -> Result<(), String> {
    let name = problem_name(&problem.file);
    let h = &run.history;
    let x = run.setup.x();
    let first = &h.records[0];
    let last = h.records.last().expect("the start is recorded");
    let (lo, hi) = shown(&x, &first.pressure);
    let within = |values: &[f64]| -> Vec<(f64, f64)> {
        (0..x.len())
            .filter(|&i| x[i] >= lo && x[i] <= hi)
            .map(|i| (x[i], values[i]))
            .collect()
    };
    let labels: Vec<String> = h
        .records
        .iter()
        .map(|r| format!("{:.3e} cycles", r.cycles))
        .collect();
    let depth: Vec<Series> = (h.records.iter().zip(&labels))
        .skip(1)
        .map(|(r, label)| Series {
            label: label.as_str(),
            points: within(&r.shape.iter().map(|w| -1e3 * w).collect::<Vec<_>>()),
        })
        .collect();
    line_plot(
        &dir.join("scar.svg"),
        &format!("{name}: the fretting scar (both bodies' wear)"),
        "x (mm)",
        "worn depth (µm, downwards)",
        &depth,
    )?;
    line_plot(
        &dir.join("pressure.svg"),
        &format!("{name}: contact pressure"),
        "x (mm)",
        "pressure (MPa)",
        &[
            Series {
                label: "unworn",
                points: within(&first.pressure),
            },
            Series {
                label: &labels[labels.len() - 1],
                points: within(&last.pressure),
            },
        ],
    )?;
    let width: Vec<(f64, f64)> = h
        .steps
        .iter()
        .filter_map(|s| s.stick_extent.map(|(a, b)| (s.cycles.log10(), b - a)))
        .collect();
    line_plot(
        &dir.join("stick_zone.svg"),
        &format!("{name}: width of the zone that never slips"),
        "log10(cycles)",
        "stick zone width (mm)",
        &[Series {
            label: "points that stick through the cycle",
            points: width,
        }],
    )?;
    let loops: Vec<Series> = (h.records.iter().zip(&labels))
        .map(|(r, label)| Series {
            label: label.as_str(),
            points: loop_points(&r.cycle_loop),
        })
        .collect();
    line_plot(
        &dir.join("loop.svg"),
        &format!("{name}: the fretting loop of each recorded cycle"),
        "shift δ (µm)",
        "tangential force Q (N)",
        &loops,
    )
}

/// Write `steady`'s files into `dir`.
pub fn write_steady(
    dir: &Path,
    problem: &Problem,
    result: &FrettingSteady,
) -> Result<(), OutputError> {
    let s = &result.state;
    let setup = &result.setup;
    let x = setup.x();
    let summary = result.summary(problem);
    write_json(dir, "summary.json", &summary)?;
    let rows: Vec<Vec<Value>> = (0..x.len())
        .map(|i| {
            vec![
                json!(x[i]),
                json!(s.initial_pressure[i]),
                json!(s.pressure[i]),
                json!(s.shape[i]),
                json!(u8::from(s.stick[i])),
            ]
        })
        .collect();
    write_csv(
        dir,
        "final.csv",
        &[
            "x_mm",
            "initial_pressure_MPa",
            "pressure_MPa",
            "worn_depth_mm",
            "in_final_stick_set",
        ],
        &rows,
    )?;
    // Gross slip's steady contact spreads beyond the first one: show all of it.
    let (lo, hi) = shown(
        &x,
        if s.gross_slip {
            &s.pressure
        } else {
            &s.initial_pressure
        },
    );
    let within = |values: &[f64], scale: f64| -> Vec<(f64, f64)> {
        (0..x.len())
            .filter(|&i| x[i] >= lo && x[i] <= hi)
            .map(|i| (x[i], scale * values[i]))
            .collect()
    };
    let name = problem_name(&problem.file);
    let e = figure_error(dir);
    line_plot(
        &dir.join("final.svg"),
        &format!(
            "{name}: {}",
            if s.gross_slip {
                "the steady state of gross slip"
            } else {
                "the final state of partial slip"
            }
        ),
        "x (mm)",
        "pressure (MPa)",
        &[
            Series {
                label: "unworn",
                points: within(&s.initial_pressure, 1.0),
            },
            Series {
                label: if s.gross_slip {
                    "steady: every point worn at the plate's approach"
                } else {
                    "final: the stick zone carries the load"
                },
                points: within(&s.pressure, 1.0),
            },
        ],
    )
    .map_err(&e)?;
    line_plot(
        &dir.join("scar.svg"),
        &format!(
            "{name}: the {} scar (both bodies' wear)",
            if s.gross_slip { "steady" } else { "final" }
        ),
        "x (mm)",
        "worn depth (µm, downwards)",
        &[Series {
            label: if s.gross_slip {
                "steady state"
            } else {
                "final state"
            },
            points: within(&s.shape, -1e3),
        }],
    )
    .map_err(&e)
}
