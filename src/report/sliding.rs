//! The files of a sliding-pairs run: summary.json, history.csv, track.csv (body 2's worn
//! profile along its track), body1.csv (body 1's wear and the last cycle's pressures at its
//! reversals), positions.csv (the pressure at every position of the last cycle), and figures
//! of each body's wear and of the pressure as the slider moves.

use crate::jobs::sliding::SlidingRun;
use crate::output::{write_csv, write_json, OutputError};
use crate::plot::{line_plot, problem_name, write_figure, Figure, Series};
use crate::problem::Problem;
use serde_json::{json, Value};
use std::path::Path;

/// Write every file of `run` into `dir`.
pub fn write(dir: &Path, problem: &Problem, run: &SlidingRun) -> Result<(), OutputError> {
    write_json(dir, "summary.json", &run.summary(problem))?;
    let h = &run.history;
    let header: Vec<String> = ["step", "half_period", "direction", "k", "peak_pressure_MPa"]
        .into_iter()
        .map(String::from)
        .chain(run.probes.iter().map(|(name, _)| format!("p_{name}_MPa")))
        .chain(
            run.track_probes
                .iter()
                .map(|(name, _)| format!("wear_{name}_mm")),
        )
        .chain(["worn_volume_body1_mm3", "worn_volume_body2_mm3"].map(String::from))
        .collect();
    let rows: Vec<Vec<Value>> = h
        .steps
        .iter()
        .map(|s| {
            let mut row = vec![
                json!(s.step),
                json!(s.half_period),
                json!(s.direction),
                json!(s.k),
                json!(s.peak_pressure),
            ];
            row.extend(s.probes.iter().map(|p| json!(p)));
            row.extend(s.track_probes.iter().map(|w| json!(w)));
            row.extend(s.worn_area.iter().map(|a| json!(a * run.thickness)));
            row
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    write_csv(dir, "history.csv", &header, &rows)?;
    let track_x = h.track.centres();
    let rows: Vec<Vec<Value>> = track_x
        .iter()
        .zip(&h.track.wear)
        .map(|(x, w)| vec![json!(x), json!(w)])
        .collect();
    write_csv(dir, "track.csv", &["x_mm", "wear_body2_mm"], &rows)?;
    let points = &run.contact.contacts[0].points;
    let rows: Vec<Vec<Value>> = (0..points.x.len())
        .map(|i| vec![json!(points.x[i][0]), json!(h.wear_body1[i])])
        .collect();
    write_csv(dir, "body1.csv", &["x_mm", "wear_body1_mm"], &rows)?;
    let mut rows = Vec::new();
    for (d, name) in h.last_cycle.iter().zip(["+", "-"]) {
        for (j, pressure) in d.iter().enumerate() {
            for (i, p) in pressure.iter().enumerate() {
                let s = run.contact.stroke.positions[j];
                rows.push(vec![
                    json!(name),
                    json!(s),
                    json!(points.x[i][0]),
                    json!(points.x[i][0] - s),
                    json!(p),
                ]);
            }
        }
    }
    write_csv(
        dir,
        "positions.csv",
        &[
            "direction",
            "offset_mm",
            "x_mm",
            "track_x_mm",
            "pressure_MPa",
        ],
        &rows,
    )?;
    figures(dir, problem, run).map_err(|e| OutputError {
        path: dir.display().to_string(),
        source: std::io::Error::other(e),
    })
}

fn figures(dir: &Path, problem: &Problem, run: &SlidingRun) -> Result<(), String> {
    let name = problem_name(&problem.file);
    let h = &run.history;
    let track: Vec<(f64, f64)> = h
        .track
        .centres()
        .into_iter()
        .zip(h.track.wear.iter().map(|w| 1e3 * w))
        .collect();
    let points = &run.contact.contacts[0].points;
    let body1: Vec<(f64, f64)> = points
        .x
        .iter()
        .zip(&h.wear_body1)
        .map(|(x, w)| (x[0], 1e3 * w))
        .collect();
    let half_periods = h.steps.last().map_or(0, |s| s.half_period);
    // Two figures: the bodies' depths can differ by orders of magnitude (a polymer block on a
    // steel ring: 48 µm against 0.0008 µm).
    // Depths from zero: a ring's even wear, uneven at round-off, would otherwise fill the
    // axis with its 1e-10 ripple.
    let depth = |file: &str, title: String, x_label: &'static str, label: &'static str, points| {
        write_figure(
            &dir.join(file),
            &Figure {
                title,
                x_label,
                y_label: "wear depth (µm)",
                series: vec![Series { label, points }],
                log_y: false,
                zero_y: true,
            },
        )
    };
    depth(
        "track.svg",
        format!("{name}: body 2's wear along its track after {half_periods} half periods"),
        "x on body 2's track (mm; at rest, or arc length on a ring)",
        "body 2",
        track,
    )?;
    depth(
        "wear_body1.svg",
        format!("{name}: body 1's wear after {half_periods} half periods"),
        "x (mm)",
        "body 1 at its contact points",
        body1,
    )?;
    // The pressure at a few positions of the last '+' half period: over body 2's straight
    // track, where it shows the slider's travel; over body 1 on a closed track, where the
    // positions are alike and would otherwise straddle the track's seam.
    let closed = run.contact.shape.period().is_some();
    let along = |x: f64, s: f64| if closed { x } else { x - s };
    let axis = if closed {
        "x on body 1 (mm)"
    } else {
        "x on body 2's track (mm)"
    };
    let forward = &h.last_cycle[0];
    if forward.iter().all(|p| !p.is_empty()) && !forward.is_empty() {
        let m = forward.len();
        let picks: Vec<usize> = if m <= 5 {
            (0..m).collect()
        } else {
            (0..5).map(|k| k * (m - 1) / 4).collect()
        };
        let labels: Vec<String> = picks
            .iter()
            .map(|&j| format!("offset {:+.3} mm", run.contact.stroke.positions[j]))
            .collect();
        let series: Vec<Series> = picks
            .iter()
            .zip(&labels)
            .map(|(&j, label)| Series {
                label,
                points: points
                    .x
                    .iter()
                    .zip(&forward[j])
                    .map(|(x, p)| (along(x[0], run.contact.stroke.positions[j]), *p))
                    .collect(),
            })
            .collect();
        line_plot(
            &dir.join("positions.svg"),
            &format!("{name}: the pressure as the slider moves (last '+' half period)"),
            axis,
            "contact pressure (MPa)",
            &series,
        )?;
    }
    Ok(())
}
