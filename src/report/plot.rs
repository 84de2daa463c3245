//! Line plots of the results (pressure profiles, shapes, probe histories, wear dissipation) as
//! SVG and PNG, so that a run can be judged at a glance without other tools.
//!
//! The PNGs are drawn by plotters' bitmap backend with DejaVu Sans compiled into the binary
//! (`assets/fonts`, Bitstream Vera licence), so no system font library is needed. Curves are
//! told apart by colour and by a marker shape drawn at staggered points, so that a curve lying
//! on another still shows.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// One curve: legend label and (x, y) points.
pub struct Series<'a> {
    /// Legend text.
    pub label: &'a str,
    /// Points.
    pub points: Vec<(f64, f64)>,
}

/// A figure: title, axis labels with units, curves, and whether y is logarithmic.
pub struct Figure<'a> {
    /// Title (names the problem).
    pub title: String,
    /// x-axis label with unit.
    pub x_label: &'a str,
    /// y-axis label with unit.
    pub y_label: &'a str,
    /// The curves.
    pub series: Vec<Series<'a>>,
    /// Logarithmic y axis (non-positive values are left out).
    pub log_y: bool,
    /// Whether the y axis reaches 0 (for depths, whose size the reader judges from 0).
    pub zero_y: bool,
}

/// Pixel size of every figure.
pub const SIZE: (u32, u32) = (900, 560);

static FONT: Once = Once::new();

/// Register the compiled-in font as "sans-serif" (once): every plot calls this first.
pub(crate) fn register_font() {
    FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
        // The font is compiled in and known to parse; should it not, text is left out, not
        // the figure.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, bytes);
    });
}

/// A short name of the problem for titles: the example name or the file's stem.
pub fn problem_name(file: &str) -> String {
    match file.strip_prefix("built-in example ") {
        Some(name) => name.to_string(),
        None => Path::new(file)
            .file_stem()
            .map_or(file.to_string(), |s| s.to_string_lossy().into_owned()),
    }
}

/// Draw `series` into the SVG file `path` and a PNG twin beside it (same stem).
pub fn line_plot(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
) -> Result<(), String> {
    let figure = Figure {
        title: title.to_string(),
        x_label,
        y_label,
        series: series
            .iter()
            .map(|s| Series {
                label: s.label,
                points: s.points.clone(),
            })
            .collect(),
        log_y: false,
        zero_y: false,
    };
    write_figure(path, &figure)
}

/// Write `figure` as `path` (SVG) and as `path` with extension `png`.
pub fn write_figure(path: &Path, figure: &Figure) -> Result<(), String> {
    register_font();
    let e = |x: &dyn std::fmt::Display| format!("{}: {x}", path.display());
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|x| e(&x))?;
    }
    let svg = path.with_extension("svg");
    draw(SVGBackend::new(&svg, SIZE).into_drawing_area(), figure).map_err(|x| e(&x))?;
    let png = path.with_extension("png");
    draw(BitMapBackend::new(&png, SIZE).into_drawing_area(), figure).map_err(|x| e(&x))
}

type Points = Vec<(f64, f64)>;
/// A closed interval (lo, hi) of an axis.
type Range = (f64, f64);

/// The finite points of each series (positive y only on a log axis) and the padded ranges.
fn prepare(figure: &Figure) -> Option<(Vec<Points>, Range, Range)> {
    let keep = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite() && (!figure.log_y || p.1 > 0.0);
    let points: Vec<Points> = figure
        .series
        .iter()
        .map(|s| s.points.iter().cloned().filter(keep).collect())
        .collect();
    let all = || points.iter().flatten();
    let range = |v: &mut dyn Iterator<Item = f64>| {
        v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        })
    };
    let (x0, x1) = range(&mut all().map(|p| p.0));
    let (mut y0, mut y1) = range(&mut all().map(|p| p.1));
    if !(x0.is_finite() && y0.is_finite()) {
        return None;
    }
    if figure.zero_y && !figure.log_y {
        (y0, y1) = (y0.min(0.0), y1.max(0.0));
    }
    let pad = |lo: f64, hi: f64| {
        let d = if hi > lo {
            0.05 * (hi - lo)
        } else {
            0.5 * lo.abs().max(1.0)
        };
        (lo - d, hi + d)
    };
    // Room above the curves for the legend (about 18 px per entry of a plot about 440 px
    // high), so that it never covers data.
    let f = ((18 * figure.series.len() + 16) as f64 / 440.0).min(0.6);
    let grow = f / (1.0 - f);
    let y = if figure.log_y {
        let (lo, hi) = (y0 / 1.5, y1 * 1.5);
        (lo, hi * (hi / lo).powf(grow))
    } else {
        let (lo, hi) = pad(y0, y1);
        (lo, hi + grow * (hi - lo))
    };
    Some((points, pad(x0, x1), y))
}

const COLOURS: [RGBColor; 10] = [
    RGBColor(0, 90, 200),
    RGBColor(220, 50, 32),
    RGBColor(0, 0, 0),
    RGBColor(0, 150, 60),
    RGBColor(170, 60, 180),
    RGBColor(230, 140, 0),
    RGBColor(0, 170, 190),
    RGBColor(120, 80, 40),
    RGBColor(128, 128, 128),
    RGBColor(200, 0, 120),
];

/// Marker `kind` of size `s` at pixel offset (x, y).
fn marker(kind: usize, (x, y): (i32, i32), s: i32, colour: RGBColor) -> PathElement<(i32, i32)> {
    let style = colour.stroke_width(2);
    let shape: Vec<(i32, i32)> = match kind % 4 {
        0 => vec![
            (x - s, y - s),
            (x + s, y - s),
            (x + s, y + s),
            (x - s, y + s),
            (x - s, y - s),
        ],
        1 => vec![
            (x, y - s - 1),
            (x + s + 1, y + s),
            (x - s - 1, y + s),
            (x, y - s - 1),
        ],
        2 => vec![
            (x, y - s - 1),
            (x + s + 1, y),
            (x, y + s + 1),
            (x - s - 1, y),
            (x, y - s - 1),
        ],
        _ => vec![
            (x - s, y - s),
            (x + s, y + s),
            (x, y),
            (x + s, y - s),
            (x - s, y + s),
        ],
    };
    PathElement::new(shape, style)
}

/// Tick label: powers of ten on a log axis, otherwise the shortest exact text.
fn tick(v: f64, log: bool) -> String {
    if log {
        format!("{v:.0e}")
    } else {
        // Rounded to 10 significant digits so that 0.1 + 0.2 shows as 0.3.
        let digits = 9 - v.abs().log10().floor().clamp(-20.0, 20.0) as i32;
        let scale = 10f64.powi(digits.max(0));
        format!("{}", (v * scale).round() / scale)
    }
}

/// `v` with a round-off of 0 made 0: a tick meant to be 0, computed as lo + k·step, can come
/// out as −1.4e-18 on an axis spanning `span` (0: leave `v` as it is).
fn snap(v: f64, span: f64) -> f64 {
    if v.abs() < 1e-12 * span {
        0.0
    } else {
        v
    }
}

macro_rules! draw_chart {
    ($root:expr, $figure:expr, $points:expr, $x:expr, $y:expr, $spans:expr) => {{
        let mut chart = ChartBuilder::on(&$root)
            .caption(&$figure.title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d($x, $y)?;
        chart
            .configure_mesh()
            .x_desc($figure.x_label)
            .y_desc($figure.y_label)
            .label_style(("sans-serif", 14))
            .y_label_formatter(&|v: &f64| tick(snap(*v, $spans.1), $figure.log_y))
            .x_label_formatter(&|v: &f64| tick(snap(*v, $spans.0), false))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;
        for (k, (s, pts)) in $figure.series.iter().zip($points.iter()).enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            chart
                .draw_series(LineSeries::new(pts.iter().cloned(), colour.stroke_width(2)))?
                .label(s.label)
                .legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (24, 0)], colour.stroke_width(2))
                        + marker(k, (12, 0), 4, colour)
                });
            // About 12 markers per curve, staggered between curves so that coinciding curves
            // show each one's markers.
            let n = $figure.series.len().max(1);
            let every = (pts.len() / 12).max(1);
            let offset = (k * every) / n;
            chart.draw_series(
                pts.iter()
                    .skip(offset)
                    .step_by(every)
                    .map(|&p| EmptyElement::at(p) + marker(k, (0, 0), 4, colour)),
            )?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font(("sans-serif", 14))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
    }};
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    figure: &Figure,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let Some((points, (x0, x1), (y0, y1))) = prepare(figure) else {
        root.titled(&figure.title, ("sans-serif", 20))?;
        return Ok(root.present()?);
    };
    if figure.log_y {
        draw_chart!(
            root,
            figure,
            points,
            x0..x1,
            (y0..y1).log_scale(),
            (x1 - x0, 0.0)
        );
    } else {
        draw_chart!(root, figure, points, x0..x1, y0..y1, (x1 - x0, y1 - y0));
    }
    root.present()?;
    Ok(())
}

/// The figures of a wear run beyond the last cycle's profiles, mirroring the paper's: the
/// pressure at the recorded steps for each sliding direction (`pressure_plus`,
/// `pressure_minus`), the shape at the recorded steps (`shape_evolution`), the wear
/// dissipation per half period (`dissipation`) and the cycle's wear non-uniformity δw
/// (`delta_w`), each as SVG and PNG in `dir`. `name` names the problem in the titles.
pub fn wear_figures(dir: &Path, name: &str, run: &crate::driver::WearRun) -> Result<(), String> {
    let h = &run.history;
    // Along z where bodies of revolution touch along their axis (every point at one r).
    let x = run.contact.profile();
    let labels: Vec<String> = h
        .snapshots
        .iter()
        .map(|s| match s.half_period {
            1 => format!("step {} (1 half period)", s.step),
            n => format!("step {} ({n} half periods)", s.step),
        })
        .collect();
    let profile = |v: &[f64]| x.iter().cloned().zip(v.iter().cloned()).collect::<Vec<_>>();
    for (direction, stem, text) in [
        ("+", "pressure_plus", "'+'"),
        ("−", "pressure_minus", "'−'"),
    ] {
        let series: Vec<Series> = h
            .snapshots
            .iter()
            .zip(&labels)
            .filter(|(s, _)| s.direction == direction)
            .map(|(s, label)| Series {
                label,
                points: profile(&s.pressure),
            })
            .collect();
        if series.is_empty() {
            continue;
        }
        let figure = Figure {
            title: format!("{name}: contact pressure at the recorded steps, {text} half cycles"),
            x_label: run.contact.position_label(),
            y_label: "pressure (MPa)",
            series,
            log_y: false,
            zero_y: false,
        };
        write_figure(&dir.join(format!("{stem}.svg")), &figure)?;
    }
    let series: Vec<Series> = h
        .snapshots
        .iter()
        .zip(&labels)
        .map(|(s, label)| Series {
            label,
            points: profile(&s.shape),
        })
        .collect();
    if !series.is_empty() {
        let figure = Figure {
            title: format!("{name}: shape (wear gap) at the recorded steps"),
            x_label: run.contact.position_label(),
            y_label: "shape (mm)",
            series,
            log_y: false,
            zero_y: false,
        };
        write_figure(&dir.join("shape_evolution.svg"), &figure)?;
    }
    wear_figure(dir, name, (&x, run.contact.position_label()), h)?;
    if run.turn.is_some() {
        torque_figure(dir, name, run)?;
    }
    let by_direction = |d: &str, value: &dyn Fn(&crate::wear::StepRecord) -> f64| {
        h.steps
            .iter()
            .filter(|s| s.direction == d)
            .map(|s| (s.half_period as f64, value(s)))
            .collect::<Vec<_>>()
    };
    let mut series = vec![Series {
        label: "'+' half cycles",
        points: by_direction("+", &|s| s.dissipation),
    }];
    let minus = by_direction("−", &|s| s.dissipation);
    if !minus.is_empty() {
        series.push(Series {
            label: "'−' half cycles",
            points: minus,
        });
    }
    let figure = Figure {
        title: format!("{name}: wear dissipation per half period"),
        x_label: run.time_axis(),
        y_label: "wear dissipation (N·mm)",
        series,
        log_y: false,
        zero_y: false,
    };
    write_figure(&dir.join("dissipation.svg"), &figure)?;
    let delta: Vec<(f64, f64)> = h
        .steps
        .iter()
        .filter(|s| s.delta_w > 0.0)
        .map(|s| (s.half_period as f64, s.delta_w))
        .collect();
    let figure = Figure {
        title: format!("{name}: non-uniformity of the cycle's wear, δw"),
        x_label: run.time_axis(),
        y_label: "δw (mm)",
        series: vec![Series {
            label: "δw = max (Δw − min Δw) over the cycle (eq. 40)",
            points: delta,
        }],
        log_y: true,
        zero_y: false,
    };
    write_figure(&dir.join("delta_w.svg"), &figure)
}

/// `torque.svg`: the friction torque about the axis of bodies of revolution turning about it,
/// step by step (N·m).
fn torque_figure(dir: &Path, name: &str, run: &crate::driver::WearRun) -> Result<(), String> {
    let points: Vec<(f64, f64)> = run
        .history
        .steps
        .iter()
        .filter_map(|s| Some((s.half_period as f64, s.torque? / 1000.0)))
        .collect();
    let figure = Figure {
        title: format!("{name}: friction torque about the axis"),
        x_label: run.time_axis(),
        y_label: "torque (N·m)",
        series: vec![Series {
            label: "T = ∫ μ p r dA",
            points,
        }],
        log_y: false,
        zero_y: false,
    };
    write_figure(&dir.join("torque.svg"), &figure)
}

/// `wear.svg`: the depth worn off each body that wears, and their sum, at the end of the run,
/// in µm when the largest is below 0.1 mm: the wear's own scale, which the shape's (the
/// initial gap plus the wear) hides on a curved body.
fn wear_figure(
    dir: &Path,
    name: &str,
    (x, x_label): (&[f64], &'static str),
    h: &crate::wear::WearHistory,
) -> Result<(), String> {
    let [one, two] = &h.body_wear;
    let largest = one
        .iter()
        .zip(two)
        .map(|(a, b)| (a + b).abs())
        .fold(0.0f64, f64::max);
    if largest == 0.0 || !largest.is_finite() {
        return Ok(());
    }
    let (scale, unit) = if largest < 0.1 {
        (1000.0, "wear (µm)")
    } else {
        (1.0, "wear (mm)")
    };
    let curve = |v: &dyn Fn(usize) -> f64| {
        (0..x.len())
            .map(|i| (x[i], scale * v(i)))
            .collect::<Vec<_>>()
    };
    let wears = |w: &[f64]| w.iter().any(|&v| v != 0.0);
    let mut series = Vec::new();
    if wears(one) {
        series.push(Series {
            label: "body 1",
            points: curve(&|i| one[i]),
        });
    }
    if wears(two) {
        series.push(Series {
            label: "body 2 (at the partner points)",
            points: curve(&|i| two[i]),
        });
    }
    if series.len() == 2 {
        series.push(Series {
            label: "both bodies",
            points: curve(&|i| one[i] + two[i]),
        });
    }
    let figure = Figure {
        title: format!("{name}: depth worn off each body"),
        x_label,
        y_label: unit,
        series,
        log_y: false,
        zero_y: true,
    };
    write_figure(&dir.join("wear.svg"), &figure)
}
