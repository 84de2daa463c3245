//! Output: the summary JSON and CSV files that every command writes, assembled from the
//! results of the earlier stages. This is the only module that touches the file system.

use serde_json::{json, Value};
use std::fs;
use std::io::Write;
use std::path::Path;

/// Errors writing results.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {source}")]
pub struct OutputError {
    /// The file.
    pub path: String,
    /// Why.
    pub source: std::io::Error,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |source| OutputError {
        path: path.display().to_string(),
        source,
    }
}

/// Write `value` as pretty JSON to `dir/name`, creating `dir`.
pub fn write_json(dir: &Path, name: &str, value: &Value) -> Result<(), OutputError> {
    fs::create_dir_all(dir).map_err(io(dir))?;
    let path = dir.join(name);
    let text = serde_json::to_string_pretty(value).expect("JSON values always serialise");
    fs::write(&path, text + "\n").map_err(io(&path))
}

/// Write a CSV file with a header and rows of numbers or strings.
pub fn write_csv(
    dir: &Path,
    name: &str,
    header: &[&str],
    rows: &[Vec<Value>],
) -> Result<(), OutputError> {
    fs::create_dir_all(dir).map_err(io(dir))?;
    let path = dir.join(name);
    let mut file = std::io::BufWriter::new(fs::File::create(&path).map_err(io(&path))?);
    let mut text = header.join(",");
    text.push('\n');
    for row in rows {
        let cells: Vec<String> = row
            .iter()
            .map(|v| match v {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            })
            .collect();
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    file.write_all(text.as_bytes()).map_err(io(&path))
}

pub use crate::report::json::{named, number, numbers};

mod heat;
mod stale;
pub use heat::{write_heat, write_steady_heat};
pub use stale::remove_earlier_outputs;

fn plot_error(path: &Path) -> impl Fn(String) -> OutputError + '_ {
    move |m| OutputError {
        path: path.display().to_string(),
        source: std::io::Error::other(m),
    }
}

/// Pressure profiles of one cycle and the worn shape at the contact points.
pub struct Profiles<'a> {
    /// x of the contact points, mm.
    pub x: &'a [f64],
    /// The figures' label of x ([`crate::contact::CondensedContact::position_label`]).
    pub x_label: &'static str,
    /// z of the contact points, mm, where the profiles are drawn against it (bodies of
    /// revolution touching along the axis, [`crate::contact::CondensedContact::profile_z`]):
    /// a `z_mm` column after `x_mm`, and the figures' abscissa.
    pub z: Option<&'a [f64]>,
    /// '+' half-cycle pressure, MPa.
    pub p_plus: &'a [f64],
    /// '−' half-cycle pressure, MPa (None for monotonic sliding).
    pub p_minus: Option<&'a [f64]>,
    /// Shape: the gap's profile, initial gap plus wear, mm.
    pub shape: &'a [f64],
    /// Wear: the shape minus the initial gap, mm (None for a steady state, whose shape is
    /// defined up to a rigid motion and has no initial state).
    pub wear: Option<&'a [f64]>,
    /// Each body's own wear, mm (material removed from body 1 and from body 2; None for a
    /// steady state).
    pub body_wear: Option<[&'a [f64]; 2]>,
}

impl Profiles<'_> {
    /// Write `csv_name` (x, p⁺, p⁻, p⁺ + p⁻, shape) and the plots pressure.svg and shape.svg.
    pub fn write(&self, dir: &Path, csv_name: &str, title: &str) -> Result<(), OutputError> {
        use crate::plot::{line_plot, Series};
        let zero = vec![0.0; self.x.len()];
        let p_minus = self.p_minus.unwrap_or(&zero);
        let p_sum: Vec<f64> = self
            .p_plus
            .iter()
            .zip(p_minus)
            .map(|(a, b)| a + b)
            .collect();
        // Monotonic sliding has one pressure: no '−' or summed columns.
        let two = self.p_minus.is_some();
        let rows: Vec<Vec<Value>> = (0..self.x.len())
            .map(|i| {
                let mut row = vec![number(self.x[i])];
                if let Some(z) = self.z {
                    row.push(number(z[i]));
                }
                row.push(number(self.p_plus[i]));
                if two {
                    row.extend([number(p_minus[i]), number(p_sum[i])]);
                }
                row.push(number(self.shape[i]));
                if let Some(wear) = self.wear {
                    row.push(number(wear[i]));
                }
                if let Some([one, two]) = self.body_wear {
                    row.extend([number(one[i]), number(two[i])]);
                }
                row
            })
            .collect();
        let mut header = vec!["x_mm"];
        if self.z.is_some() {
            header.push("z_mm");
        }
        header.push("p_plus_MPa");
        if two {
            header.extend(["p_minus_MPa", "p_sum_MPa"]);
        }
        header.push("shape_mm");
        if self.wear.is_some() {
            header.push("wear_mm");
        }
        if self.body_wear.is_some() {
            header.extend(["wear_body1_mm", "wear_body2_mm"]);
        }
        write_csv(dir, csv_name, &header, &rows)?;
        let abscissa = self.z.unwrap_or(self.x);
        let profile = |v: &[f64], scale: f64| {
            abscissa
                .iter()
                .zip(v)
                .map(|(&a, &b)| (a, b * scale))
                .collect::<Vec<_>>()
        };
        let mut series = vec![Series {
            label: "p⁺ ('+' half cycle)",
            points: profile(self.p_plus, 1.0),
        }];
        if self.p_minus.is_some() {
            series.push(Series {
                label: "p⁻ ('−' half cycle)",
                points: profile(p_minus, 1.0),
            });
            series.push(Series {
                label: "p⁺ + p⁻ (summed)",
                points: profile(&p_sum, 1.0),
            });
        }
        let path = dir.join("pressure.svg");
        line_plot(
            &path,
            &format!("{title}: contact pressure"),
            self.x_label,
            "pressure (MPa)",
            &series,
        )
        .map_err(plot_error(&path))?;
        // Only the contact zone changes: over a whole named edge a curved body's initial gap
        // spans a range that hides micrometres of wear (a cylinder's 1 mm at its edge
        // against 17 µm worn at its crown).
        let window = contact_window(self.p_plus, self.p_minus);
        let (shape_title, shape_points) = match window {
            Some(range) if range.len() < self.x.len() => (
                format!("{title}: worn shape (wear gap) over the contact zone"),
                profile(self.shape, 1.0)[range].to_vec(),
            ),
            _ => (
                format!("{title}: worn shape (wear gap)"),
                profile(self.shape, 1.0),
            ),
        };
        let path = dir.join("shape.svg");
        let shape = [Series {
            label: "shape",
            points: shape_points,
        }];
        line_plot(&path, &shape_title, self.x_label, "shape (mm)", &shape)
            .map_err(plot_error(&path))
    }
}

/// The contact points that carry pressure in either half cycle, with one more on each side
/// (where the zone ends); None if none does.
pub fn contact_window(p_plus: &[f64], p_minus: Option<&[f64]>) -> Option<std::ops::Range<usize>> {
    let loaded = |i: usize| p_plus[i] > 0.0 || p_minus.is_some_and(|m| m[i] > 0.0);
    let first = (0..p_plus.len()).find(|&i| loaded(i))?;
    let last = (0..p_plus.len()).rev().find(|&i| loaded(i))?;
    Some(first.saturating_sub(1)..(last + 2).min(p_plus.len()))
}

/// Write everything a wear run produces into `dir`: summary.json, history.csv, final.csv,
/// snapshots.csv and the figures.
///
/// The summary holds the run's warnings, whose checks (the check in p sets the problem up
/// again at p + 2) take about as long as drawing the figures: the two are made side by side,
/// and the figures of the run's history beside those of its last cycle and of its heat.
pub fn write_wear(
    dir: &Path,
    problem: &crate::problem::Problem,
    run: &crate::driver::WearRun,
) -> Result<(), OutputError> {
    let (summary, (tables, figures)) = rayon::join(
        || write_json(dir, "summary.json", &run.summary(problem)),
        || {
            rayon::join(
                || write_wear_tables(dir, problem, run),
                || {
                    // The heat's table and figures beside the others (their own files).
                    let name = crate::plot::problem_name(&problem.file);
                    let (heat, figures) = rayon::join(
                        || write_heat(dir, &name, run),
                        || crate::plot::wear_figures(dir, &name, run).map_err(plot_error(dir)),
                    );
                    heat.and(figures)
                },
            )
        },
    );
    summary.and(tables).and(figures)
}

/// history.csv, final.csv, snapshots.csv and the figures of the last cycle and the probes.
fn write_wear_tables(
    dir: &Path,
    problem: &crate::problem::Problem,
    run: &crate::driver::WearRun,
) -> Result<(), OutputError> {
    use crate::plot::{line_plot, Series};
    let h = &run.history;
    let mut header: Vec<String> = [
        "step",
        "half_period",
        "direction",
        "k",
        "iterations",
        "solves",
        "criterion_percent",
        "dissipation_Nmm",
        "delta_w_mm",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let monotonic = run.is_monotonic();
    if monotonic {
        // δw compares the two half cycles of a period: there is none in one direction.
        header.pop();
    }
    header.extend(run.probes.iter().map(|(n, _)| format!("p_{n}_MPa")));
    let turn = run.turn.is_some();
    if turn {
        header.push("torque_Nmm".into());
    }
    let heat = h.thermal.is_some();
    if heat {
        header.extend(run.probes.iter().map(|(n, _)| format!("T_{n}_C")));
        header.extend(run.body_names.iter().map(|b| format!("max_T_{b}_C")));
    }
    let rows: Vec<Vec<Value>> = h
        .steps
        .iter()
        .map(|s| {
            let mut r = vec![
                json!(s.step),
                json!(s.half_period),
                json!(s.direction),
                json!(s.k),
                json!(s.iterations),
                json!(s.solves),
                number(s.criterion),
                number(s.dissipation),
            ];
            if !monotonic {
                r.push(number(s.delta_w));
            }
            r.extend(s.probes.iter().map(|&v| number(v)));
            if turn {
                r.push(number(s.torque.unwrap_or(f64::NAN)));
            }
            if heat {
                r.extend(s.temperatures.iter().map(|&v| number(v)));
                r.extend(s.max_temperature.unwrap_or([f64::NAN; 2]).map(number));
            }
            r
        })
        .collect();
    let header_refs: Vec<&str> = header.iter().map(|s| s.as_str()).collect();
    write_csv(dir, "history.csv", &header_refs, &rows)?;
    let x: Vec<f64> = run.contact.points.x.iter().map(|p| p[0]).collect();
    let along_z = run.contact.profile_z();
    let final_wear = run.wear_of(&h.shape);
    let profiles = Profiles {
        x: &x,
        x_label: run.contact.position_label(),
        z: along_z.as_deref(),
        p_plus: &h.p_plus,
        p_minus: (!monotonic).then_some(&h.p_minus[..]),
        shape: &h.shape,
        wear: Some(&final_wear),
        body_wear: Some([&h.body_wear[0], &h.body_wear[1]]),
    };
    let name = crate::plot::problem_name(&problem.file);
    if h.steady_distance.is_some() {
        // Only a completed cycle has profiles worth writing.
        profiles.write(dir, "final.csv", &format!("{name}, last cycle"))?;
    }
    // The wear of a snapshot is `run.wear_of`, as in summary.json and the ParaView files: with
    // `wear.shape_zero_at` it is re-zeroed at x₀, which the shape of a '+' step (mid cycle, not
    // shifted) is not, so shape minus initial gap would differ from the other files there.
    let rows: Vec<Vec<Value>> = h
        .snapshots
        .iter()
        .flat_map(|s| {
            let wear = run.wear_of(&s.shape);
            (0..x.len())
                .map(|i| {
                    let mut row = vec![
                        json!(s.step),
                        json!(s.half_period),
                        json!(s.direction),
                        number(x[i]),
                    ];
                    if let Some(z) = &along_z {
                        row.push(number(z[i]));
                    }
                    row.extend([
                        number(s.pressure[i]),
                        number(s.shape[i]),
                        number(wear[i]),
                        number(s.body_wear[0][i]),
                        number(s.body_wear[1][i]),
                    ]);
                    row
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let mut header = vec!["step", "half_period", "direction", "x_mm"];
    if along_z.is_some() {
        header.push("z_mm");
    }
    header.extend([
        "pressure_MPa",
        "shape_mm",
        "wear_mm",
        "wear_body1_mm",
        "wear_body2_mm",
    ]);
    write_csv(dir, "snapshots.csv", &header, &rows)?;
    let series: Vec<Series> = run
        .probes
        .iter()
        .enumerate()
        .map(|(k, (name, _))| Series {
            label: name,
            points: h
                .steps
                .iter()
                .filter(|s| s.direction == "+")
                .map(|s| (s.half_period as f64, s.probes[k]))
                .collect(),
        })
        .collect();
    let path = dir.join("history.svg");
    line_plot(
        &path,
        &format!("{name}: pressure at the probes, '+' half cycles"),
        run.time_axis(),
        "pressure (MPa)",
        &series,
    )
    .map_err(plot_error(&path))
}

/// The summary JSON of a steady state (what `wearfem steady` writes as summary.json):
/// status, sliding, iterations, wear residual, profiles x (mm), p_plus, p_minus, p_sum (MPa),
/// shape (mm), rigid wear per period (mm, rad) and seconds.
pub fn steady_summary(
    problem: &crate::problem::Problem,
    contact: &crate::contact::CondensedContact,
    state: &crate::steady::SteadyState,
    seconds: f64,
    warnings: &[String],
) -> Value {
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let p_minus = (!state.p_minus.is_empty()).then_some(&state.p_minus[..]);
    let p_sum: Vec<f64> = match p_minus {
        Some(m) => state.p_plus.iter().zip(m).map(|(a, b)| a + b).collect(),
        None => state.p_plus.clone(),
    };
    let summary = json!({
        "title": problem.spec.title,
        "wearfem_version": crate::VERSION,
        "status": format!("{:?}", state.status),
        "sliding": match state.sliding {
            crate::steady::SteadySliding::Reciprocating => "reciprocating".to_string(),
            crate::steady::SteadySliding::Monotonic(d) => format!("monotonic {}", d.symbol()),
        },
        "iterations": state.iterations,
        "wear_residual": number(state.wear_residual),
        "x": numbers(&x),
        "p_plus": numbers(&state.p_plus),
        "p_minus": numbers(p_minus.unwrap_or(&[])),
        "p_sum": numbers(&p_sum),
        "shape": numbers(&state.shape),
        "rigid_wear_per_period": named(&contact.rigid_names, &state.rigid_wear),
        "edge_ends_in_contact": crate::driver::edge_ends_json(&crate::driver::steady_edge_ends(contact, state)),
        "coarse_partner_zones": crate::driver::coarse_zones_json(&contact.coarse_partner_zones(&[&state.p_plus, &state.p_minus])),
        "target_mesh": crate::driver::target_mesh_json(contact),
        "warnings": warnings,
        "seconds": seconds,
    });
    let mut summary = summary;
    if let Some(z) = contact.profile_z() {
        // Bodies of revolution touching along their axis: every point has the same r.
        summary["z"] = numbers(&z);
    }
    if let Some(friction) = contact.friction_about_axis {
        // Bodies of revolution turning about their axis: the steady friction torque (the same
        // in both halves of a turn to and fro, whose friction leaves the (r, z) problem).
        let turn = crate::wear::AxisRotation::new(contact, friction);
        summary["turn"] = json!({
            "friction": number(friction),
            "torque_Nmm": number(turn.torque(&state.p_plus, &contact.areas())),
        });
    }
    if p_minus.is_none() {
        // Monotonic sliding has one pressure: no '−' or summed profiles.
        if let Some(s) = summary.as_object_mut() {
            s.remove("p_minus");
            s.remove("p_sum");
        }
    }
    summary
}

/// Write a steady state: summary.json, steady.csv, pressure.svg and shape.svg.
pub fn write_steady(
    dir: &Path,
    problem: &crate::problem::Problem,
    contact: &crate::contact::CondensedContact,
    state: &crate::steady::SteadyState,
    seconds: f64,
    warnings: &[String],
) -> Result<(), OutputError> {
    let summary = steady_summary(problem, contact, state, seconds, warnings);
    write_steady_summary(dir, problem, contact, state, &summary)
}

/// [`write_steady`] with its summary given (a job that adds to [`steady_summary`]'s).
pub fn write_steady_summary(
    dir: &Path,
    problem: &crate::problem::Problem,
    contact: &crate::contact::CondensedContact,
    state: &crate::steady::SteadyState,
    summary: &Value,
) -> Result<(), OutputError> {
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let p_minus = (!state.p_minus.is_empty()).then_some(&state.p_minus[..]);
    write_json(dir, "summary.json", summary)?;
    Profiles {
        x: &x,
        x_label: contact.position_label(),
        z: contact.profile_z().as_deref(),
        p_plus: &state.p_plus,
        p_minus,
        shape: &state.shape,
        wear: None,
        body_wear: None,
    }
    .write(
        dir,
        "steady.csv",
        &format!("{}, steady state", crate::plot::problem_name(&problem.file)),
    )
}

/// Write one contact solve: summary.json, contact.csv (x, z, pressure, gap) and pressure.svg
/// (and .png); `name` names the problem in the plot's title.
pub fn write_contact(
    dir: &Path,
    name: &str,
    summary: &Value,
    contact: &crate::contact::CondensedContact,
    solution: &crate::complementarity::ContactSolution,
) -> Result<(), OutputError> {
    use crate::plot::{line_plot, Series};
    write_json(dir, "summary.json", summary)?;
    let x = &contact.points.x;
    let rows: Vec<Vec<Value>> = (0..x.len())
        .map(|i| {
            vec![
                number(x[i][0]),
                number(x[i][1]),
                number(solution.pressure[i]),
                number(solution.gap[i]),
            ]
        })
        .collect();
    write_csv(
        dir,
        "contact.csv",
        &["x_mm", "z_mm", "pressure_MPa", "gap_mm"],
        &rows,
    )?;
    let points = x
        .iter()
        .zip(&solution.pressure)
        .map(|(x, &p)| (x[0], p))
        .collect();
    let path = dir.join("pressure.svg");
    // A body of revolution's x is its radius (its summary says so).
    let along = if summary.get("axisymmetric").is_some() {
        "r (mm)"
    } else {
        "x (mm)"
    };
    line_plot(
        &path,
        &format!("{name}: contact pressure"),
        along,
        "pressure (MPa)",
        &[Series {
            label: "pressure",
            points,
        }],
    )
    .map_err(plot_error(&path))
}

/// Write a steady state found by [`crate::paper_steady::solve_steady`]: the keys and files of
/// [`write_steady`] plus the method, its history of I_δw, max δw and the eq. 49 residual
/// (also as iterations.csv), δw, the contact solves and the times (`seconds` with the set-up,
/// `setup_seconds`, `method_seconds` without it).
pub fn write_steady_method(
    dir: &Path,
    problem: &crate::problem::Problem,
    contact: &crate::contact::CondensedContact,
    outcome: &crate::paper_steady::MethodOutcome,
    setup_seconds: f64,
    warnings: &[String],
) -> Result<(), OutputError> {
    // `seconds` keeps its meaning of `wearfem steady` before the methods: set-up included.
    write_steady(
        dir,
        problem,
        contact,
        &outcome.state,
        setup_seconds + outcome.seconds,
        warnings,
    )?;
    let path = dir.join("summary.json");
    let text = fs::read_to_string(&path).map_err(io(&path))?;
    let mut summary: Value = serde_json::from_str(&text).map_err(|e| OutputError {
        path: path.display().to_string(),
        source: std::io::Error::other(e),
    })?;
    let history: Vec<Value> = outcome
        .history
        .iter()
        .map(|r| json!({ "iteration": r.iteration, "i_delta_w": number(r.i_delta_w), "max_delta_w": number(r.max_delta_w), "residual_eq49": number(r.residual) }))
        .collect();
    summary["method"] = json!(outcome.method.name());
    summary["residual_eq49"] = number(outcome.residual);
    summary["delta_w"] = numbers(&outcome.delta_w);
    summary["max_delta_w"] = number(outcome.delta_w.iter().cloned().fold(0.0, f64::max));
    summary["history"] = Value::Array(history);
    summary["contact_solves"] = json!(outcome.contact_solves);
    summary["distance_from_exact"] = outcome.distance_from_exact.map_or(Value::Null, number);
    if let Some(c_n) = outcome.penalty_stiffness {
        summary["penalty_stiffness"] = number(c_n);
    }
    summary["setup_seconds"] = json!(setup_seconds);
    summary["method_seconds"] = json!(outcome.seconds);
    write_json(dir, "summary.json", &summary)?;
    let rows: Vec<Vec<Value>> = outcome
        .history
        .iter()
        .map(|r| {
            vec![
                json!(r.iteration),
                number(r.i_delta_w),
                number(r.max_delta_w),
                number(r.residual),
            ]
        })
        .collect();
    write_csv(
        dir,
        "iterations.csv",
        &[
            "iteration",
            "i_delta_w_mm3",
            "max_delta_w_mm",
            "residual_eq49",
        ],
        &rows,
    )
}
