//! The files of a study: `sweep.csv` (one row per variant), `sweep.json` (the same, with the
//! profiles) and `sweep.svg` (the '+' pressure and the worn shape of every variant).

use super::{Job, Outcome, Variant};
use crate::output::{number, numbers, write_csv, write_json, OutputError};
use serde_json::{json, Value};
use std::path::Path;

/// A CSV cell holding text: quoted (RFC 4180) when it holds a comma or a quote.
fn text_cell(s: &str) -> Value {
    if s.contains([',', '"', '\n']) {
        Value::String(format!("\"{}\"", s.replace('"', "\"\"")))
    } else {
        Value::String(s.to_string())
    }
}

/// Column names of `sweep.csv` for these outcomes (taken from the problem and the contact,
/// which every variant has whether or not it converged).
///
/// The probe and plate-unknown columns are the union over all variants, each name where it
/// first appears in variant order: an axis can change them (`probes`, `plate.motion`), and a
/// column taken from one variant alone would drop another's probe and leave its solved row
/// with empty cells, which mean "did not converge".
fn columns(job: Job, variants: &[Variant], outcomes: &[Outcome]) -> Columns {
    Columns {
        keys: variants[0]
            .overrides
            .iter()
            .map(|o| o.key.clone())
            .collect(),
        reciprocating: outcomes.iter().any(|o| o.reciprocating),
        probes: union(outcomes.iter().map(|o| o.probes.iter().map(|p| &p.0))),
        rigid: union(outcomes.iter().map(|o| o.rigid_names.iter())),
        run: job == Job::Run,
    }
}

/// The names of all lists, each once, in the order they first appear.
fn union<'a>(lists: impl Iterator<Item = impl Iterator<Item = &'a String>>) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for name in lists.flatten() {
        if !names.contains(name) {
            names.push(name.clone());
        }
    }
    names
}

struct Columns {
    keys: Vec<String>,
    reciprocating: bool,
    probes: Vec<String>,
    rigid: Vec<String>,
    /// A study of wear runs: each row says how far its run ended from the steady state.
    run: bool,
}

impl Columns {
    fn header(&self) -> Vec<String> {
        let mut h: Vec<String> = self.keys.clone();
        h.push("status".into());
        h.push("peak_p_plus_MPa".into());
        if self.reciprocating {
            h.push("peak_p_minus_MPa".into());
        }
        for p in &self.probes {
            h.push(format!("p_plus_{p}_MPa"));
            if self.reciprocating {
                h.push(format!("p_minus_{p}_MPa"));
            }
        }
        for r in &self.rigid {
            let unit = if r == "lambda_M" { "rad" } else { "mm" };
            h.push(format!("rigid_wear_per_period_{r}_{unit}"));
        }
        h.push("shape_range_mm".into());
        if self.run {
            h.push("steady_distance".into());
            h.push("steady_reached".into());
        }
        h.push("warnings".into());
        h.push("seconds".into());
        h
    }

    fn row(&self, v: &Variant, o: &Outcome) -> Vec<Value> {
        let mut r: Vec<Value> = v
            .overrides
            .iter()
            .map(|o| text_cell(&o.value_text()))
            .collect();
        r.push(text_cell(&o.status));
        // A variant without values (not converged) gets empty cells: nothing of a failed
        // solve is a result.
        let cell = |v: Option<f64>| v.map_or_else(|| Value::String(String::new()), number);
        r.push(cell(o.peak_p_plus()));
        if self.reciprocating {
            r.push(cell(o.peak_p_minus()));
        }
        for name in &self.probes {
            r.push(cell(o.probe_p_plus(name)));
            if self.reciprocating {
                r.push(cell(o.probe_p_minus(name)));
            }
        }
        for name in &self.rigid {
            r.push(cell(o.rigid_wear(name)));
        }
        r.push(cell(o.shape_range()));
        if self.run {
            r.push(cell(o.steady_distance()));
            r.push(
                o.steady_reached()
                    .map_or_else(|| Value::String(String::new()), Value::from),
            );
        }
        // How many warning lines the variant has; their texts are in sweep.json.
        r.push(json!(o.warnings.len()));
        r.push(number(o.seconds));
        r
    }
}

/// The summary JSON of a study.
pub fn summary(
    title: &str,
    job: Job,
    jobs: usize,
    variants: &[Variant],
    outcomes: &[Outcome],
    seconds: f64,
) -> Value {
    let rows: Vec<Value> = variants
        .iter()
        .zip(outcomes)
        .map(|(v, o)| {
            let overrides: serde_json::Map<String, Value> = v
                .overrides
                .iter()
                .map(|o| (o.key.clone(), json!(o.value)))
                .collect();
            // JSON null for every value of a variant that did not converge.
            let value = |v: Option<f64>| v.map_or(Value::Null, number);
            let probes = |f: &dyn Fn(&str) -> Option<f64>| -> serde_json::Map<String, Value> {
                o.probes
                    .iter()
                    .map(|(n, _)| (n.clone(), value(f(n))))
                    .collect()
            };
            let values = o.values.as_ref();
            let mut row = json!({
                "overrides": overrides,
                "status": o.status,
                "converged": o.converged,
                "peak_p_plus": value(o.peak_p_plus()),
                "probes_p_plus": probes(&|n| o.probe_p_plus(n)),
                "shape_range": value(o.shape_range()),
                "warnings": o.warnings,
                "seconds": o.seconds,
                "x": numbers(&o.x),
                "p_plus": values.map_or(Value::Null, |v| numbers(&v.p_plus)),
                "shape": values.map_or(Value::Null, |v| numbers(&v.shape)),
            });
            if job == Job::Run {
                row["steady_distance"] = value(o.steady_distance());
                row["steady_reached"] = json!(o.steady_reached());
            }
            if o.reciprocating {
                row["peak_p_minus"] = value(o.peak_p_minus());
                row["probes_p_minus"] = json!(probes(&|n| o.probe_p_minus(n)));
                row["p_minus"] = values
                    .and_then(|v| v.p_minus.as_ref())
                    .map_or(Value::Null, |m| numbers(m));
            }
            if !o.rigid_names.is_empty() {
                row["rigid_wear_per_period"] = Value::Object(
                    o.rigid_names
                        .iter()
                        .map(|n| (n.clone(), value(o.rigid_wear(n))))
                        .collect(),
                );
            }
            row
        })
        .collect();
    json!({
        "title": title,
        "wearfem_version": crate::VERSION,
        "job": match job { Job::Steady => "steady", Job::Run => "run" },
        "threads": jobs,
        "variants": rows,
        "seconds": seconds,
    })
}

/// Write `sweep.csv`, `sweep.json` and `sweep.svg` into `dir`. `outcomes` are in variant
/// order and must not be empty. `warnings` are the study's own warning lines (an axis the job
/// does not read, [`super::unread::warnings`]), put in sweep.json's `warnings`; each variant's
/// are in its row.
#[allow(clippy::too_many_arguments)]
pub fn write(
    dir: &Path,
    title: &str,
    job: Job,
    jobs: usize,
    variants: &[Variant],
    outcomes: &[Outcome],
    seconds: f64,
    warnings: &[String],
) -> Result<(), OutputError> {
    let columns = columns(job, variants, outcomes);
    let header = columns.header();
    let header: Vec<&str> = header.iter().map(|s| s.as_str()).collect();
    let rows: Vec<Vec<Value>> = variants
        .iter()
        .zip(outcomes)
        .map(|(v, o)| columns.row(v, o))
        .collect();
    write_csv(dir, "sweep.csv", &header, &rows)?;
    let mut json = summary(title, job, jobs, variants, outcomes, seconds);
    json["warnings"] = json!(warnings);
    write_json(dir, "sweep.json", &json)?;
    let path = dir.join("sweep.svg");
    plot(&path, title, variants, outcomes).map_err(|m| OutputError {
        path: path.display().to_string(),
        source: std::io::Error::other(m),
    })
}

/// Two panels side by side: the '+' pressure and the worn shape of every variant, one colour
/// each (evenly spaced hues, so that nine or more variants stay apart).
fn plot(
    path: &Path,
    title: &str,
    variants: &[Variant],
    outcomes: &[Outcome],
) -> Result<(), String> {
    use plotters::prelude::*;
    // Without it the text of the figure fails with FontUnavailable (no system fonts are used).
    crate::plot::register_font();
    let e = |e: &dyn std::fmt::Display| e.to_string();
    // Only variants with values are drawn: not those that did not converge, nor runs that
    // completed no full cycle (converged, but without a last cycle).
    let failed = outcomes.iter().filter(|o| !o.converged).count();
    let no_cycle = outcomes
        .iter()
        .filter(|o| o.converged && o.values.is_none())
        .count();
    let heading = match (failed, no_cycle) {
        (0, 0) => format!("{title}: parameter study"),
        (m, 0) => format!("{title}: parameter study ({m} variants did not converge and are not drawn)"),
        (0, c) => format!("{title}: parameter study ({c} variants completed no full cycle and are not drawn)"),
        (m, c) => format!("{title}: parameter study (not drawn: {m} variants did not converge, {c} completed no full cycle)"),
    };
    let legend_rows = outcomes
        .iter()
        .filter(|o| o.values.is_some())
        .count()
        .div_ceil(3);
    let height = 560 + 24 * legend_rows as u32;
    let root = SVGBackend::new(path, (1400, height)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let root = root
        .titled(&heading, ("sans-serif", 22))
        .map_err(|x| e(&x))?;
    // The legend goes below the panels, where it hides no curve.
    let (upper, legend) = root.split_vertically(530);
    let panels = upper.split_evenly((1, 2));
    let label = |v: &&Variant| {
        v.overrides
            .iter()
            .map(|o| format!("{} = {}", o.key, o.value_text()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    // A variant without values is listed in the CSV with its status and empty cells, and not
    // drawn.
    let drawn: Vec<usize> = (0..outcomes.len())
        .filter(|&k| outcomes[k].values.is_some())
        .collect();
    let (variants, outcomes): (Vec<&Variant>, Vec<&Outcome>) =
        drawn.iter().map(|&k| (&variants[k], &outcomes[k])).unzip();
    let n = outcomes.len().max(1) as f64;
    let colour = |k: usize| HSLColor(k as f64 / n * 0.85, 0.8, 0.42);
    let curves = [
        ("'+' half-cycle pressure", "p+ (MPa)", 1.0),
        ("worn shape (wear gap)", "g (µm)", 1000.0),
    ];
    for (panel, (name, y_label, scale)) in panels.iter().zip(curves) {
        // Only variants with values are drawn.
        let value = |o: &&Outcome, i: usize| match &o.values {
            Some(v) if scale == 1.0 => v.p_plus[i],
            Some(v) => v.shape[i] * scale,
            None => f64::NAN,
        };
        let points: Vec<Vec<(f64, f64)>> = outcomes
            .iter()
            .map(|o| {
                (0..o.x.len())
                    .map(|i| (o.x[i], value(o, i)))
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .collect()
            })
            .collect();
        let all = points.iter().flatten();
        let (x0, x1, y0, y1) = all.fold(
            (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ),
            |(a, b, c, d), p| (a.min(p.0), b.max(p.0), c.min(p.1), d.max(p.1)),
        );
        if !(x0.is_finite() && y0.is_finite()) {
            continue;
        }
        let pad = |lo: f64, hi: f64| {
            let d = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            (lo - d, hi + d)
        };
        let ((x0, x1), (y0, y1)) = (pad(x0, x1), pad(y0, y1));
        let mut chart = ChartBuilder::on(panel)
            .caption(name, ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .x_desc("x (mm)")
            .y_desc(y_label)
            .draw()
            .map_err(|x| e(&x))?;
        for (k, pts) in points.into_iter().enumerate() {
            let c = colour(k);
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(2)))
                .map_err(|x| e(&x))?;
        }
    }
    for (k, v) in variants.iter().enumerate() {
        let (x, y) = (40 + 450 * (k % 3) as i32, 10 + 24 * (k / 3) as i32);
        let c = colour(k);
        legend
            .draw(&PathElement::new(
                vec![(x, y + 7), (x + 30, y + 7)],
                c.stroke_width(3),
            ))
            .map_err(|x| e(&x))?;
        legend
            .draw(&Text::new(label(v), (x + 40, y), ("sans-serif", 14)))
            .map_err(|x| e(&x))?;
    }
    root.present().map_err(|x| e(&x))
}
