//! Our versions of the paper's figures (Fig. 4–9, 11–25) as SVG and PNG:
//! `cargo run --release --example figures -- OUTDIR`. docs/figures.md shows them with the
//! paper's. The drawing is the crate's own (`wearfem::plot`, the same as `wearfem run` uses).

use std::path::{Path, PathBuf};
use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::monotonic_shape::{averaged_shape, AveragedReading};
use wearfem::paper_steady::{solve_steady, MethodOutcome, MethodSettings, SteadyMethod};
use wearfem::plot::{write_figure, Figure, Series};
use wearfem::problem::Problem;
use wearfem::wear::WearIntegrator;

/// One curve: legend and points. `dashed` marks a reference curve (the exact steady state);
/// the shared plotter draws every curve as a line with its own marker, so it only puts
/// "(reference)" in the legend.
struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    dashed: bool,
}

fn curve(label: &str, x: &[f64], y: &[f64], scale: f64) -> Curve {
    Curve {
        label: label.to_string(),
        points: x.iter().zip(y).map(|(a, b)| (*a, b * scale)).collect(),
        dashed: false,
    }
}

/// Write `curves` as `path` (SVG) and its PNG twin through the crate's plotter
/// (`wearfem::plot`, DejaVu Sans compiled in, so the PNG text needs no system fonts).
fn plot(path: &Path, title: &str, xl: &str, yl: &str, curves: &[Curve]) {
    plot_axes(path, title, xl, yl, curves, false);
}

/// [`plot`] with a logarithmic y axis when `log_y`.
fn plot_axes(path: &Path, title: &str, xl: &str, yl: &str, curves: &[Curve], log_y: bool) {
    let labels: Vec<String> = curves
        .iter()
        .map(|c| {
            if c.dashed {
                format!("{} (reference)", c.label)
            } else {
                c.label.clone()
            }
        })
        .collect();
    let figure = Figure {
        title: title.to_string(),
        x_label: xl,
        y_label: yl,
        series: curves
            .iter()
            .zip(&labels)
            .map(|(c, label)| Series {
                label,
                points: c.points.clone(),
            })
            .collect(),
        log_y,
        zero_y: false,
    };
    if let Err(e) = write_figure(path, &figure) {
        panic!("{e}");
    }
}

/// "Fig. 21" for the file stem "fig21", as the paper writes it.
fn caption(stem: &str) -> String {
    format!(
        "Fig. {}",
        stem.trim_start_matches("fig").trim_start_matches('0')
    )
}

struct Case {
    contact: CondensedContact,
    terms: Vec<(f64, f64)>,
    x: Vec<f64>,
}

fn case(name: &str) -> Case {
    let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    let x = contact.points.x.iter().map(|q| q[0]).collect();
    Case { contact, terms, x }
}

fn run(c: &Case, method: SteadyMethod, max_iterations: usize) -> MethodOutcome {
    let settings = MethodSettings {
        max_iterations,
        ..Default::default()
    };
    solve_steady(&c.contact, &c.terms, method, settings).unwrap()
}

/// `shape` shifted to zero at the contact point nearest `x0`.
fn zeroed(x: &[f64], shape: &[f64], x0: f64) -> Vec<f64> {
    let i = (0..x.len())
        .min_by(|&a, &b| (x[a] - x0).abs().total_cmp(&(x[b] - x0).abs()))
        .unwrap();
    shape.iter().map(|g| g - shape[i]).collect()
}

fn main() {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "figures".into()));
    std::fs::create_dir_all(&out).unwrap();
    let um = "shape (µm)";
    // Fig. 15, 16: monotonic shapes and their average, against the steady shape.
    let a = case("punch-a");
    let avg = averaged_shape(&a.contact, &a.terms, AveragedReading::Mean).unwrap();
    let sum = averaged_shape(&a.contact, &a.terms, AveragedReading::Sum).unwrap();
    plot(
        &out.join("fig15.svg"),
        "Fig. 15: monotonic steady shapes (punch-a, plane stress)",
        "x (mm)",
        um,
        &[
            curve(
                "shape(l), leftward, g(1070) = 0",
                &a.x,
                &avg.left.shape,
                1e3,
            ),
            curve(
                "shape(r), rightward, g(1130) = 0",
                &a.x,
                &avg.right.shape,
                1e3,
            ),
            curve("Shape(a), mean reading", &a.x, &avg.shape, 1e3),
            curve("Shape(a), eq. 39 as printed (sum)", &a.x, &sum.shape, 1e3),
        ],
    );
    let exact = run(&a, SteadyMethod::Exact, 100);
    let steady = zeroed(&a.x, &exact.state.shape, 1100.0);
    plot(
        &out.join("fig16.svg"),
        "Fig. 16: averaged monotonic shape vs periodic steady shape (punch-a)",
        "x (mm)",
        um,
        &[
            curve("Shape(a), mean", &a.x, &avg.shape, 1e3),
            curve("Shape(a), sum (eq. 39)", &a.x, &sum.shape, 1e3),
            curve("periodic steady shape (exact)", &a.x, &steady, 1e3),
        ],
    );
    // Fig. 20: spline modifications m_s = 0 … 3 and the end.
    let mut curves = Vec::new();
    for (label, k) in [
        ("m_s = 0 (after eq. 44)", 0),
        ("m_s = 1", 1),
        ("m_s = 2", 2),
        ("m_s = 3", 3),
        ("end", 20),
    ] {
        let o = run(&a, SteadyMethod::Spline, k);
        curves.push(curve(
            label,
            &a.x,
            &zeroed(&a.x, &o.state.shape, 1100.0),
            1e3,
        ));
    }
    let mut e = curve("exact steady state", &a.x, &steady, 1e3);
    e.dashed = true;
    curves.push(e);
    plot(
        &out.join("fig20.svg"),
        "Fig. 20: spline modifications (punch-a, fd sensitivities)",
        "x (mm)",
        um,
        &curves,
    );
    // Fig. 19, 21, 22: the spline method's iterates, their shapes and pressures.
    let spline = run(&a, SteadyMethod::Spline, 20);
    let mut solver = ContactSolver::new(&a.contact, Method::ActiveSet);
    let mut pressure = |shape: &[f64], d: Direction| -> Vec<f64> {
        let gap: Vec<f64> = a
            .contact
            .points
            .initial_gap
            .iter()
            .zip(shape)
            .map(|(g, s)| g + s)
            .collect();
        solver.solve(&gap, d).0.pressure
    };
    let label = |k: usize| -> String {
        if k <= 7 {
            format!("m = {k}")
        } else {
            format!("m_s = {}", k - 8)
        }
    };
    let poly: Vec<&(usize, Vec<f64>)> = spline.iterates.iter().filter(|(k, _)| *k <= 7).collect();
    let newton: Vec<&(usize, Vec<f64>)> = spline
        .iterates
        .iter()
        .filter(|(k, _)| *k >= 8 && *k <= 11)
        .collect();
    let mut curves: Vec<Curve> = poly
        .iter()
        .map(|(k, g)| curve(&label(*k), &a.x, &zeroed(&a.x, g, 1100.0), 1e3))
        .collect();
    let mut e = curve("exact steady state", &a.x, &steady, 1e3);
    e.dashed = true;
    curves.push(e);
    plot(
        &out.join("fig19.svg"),
        "Fig. 19: polynomial iteration (eq. 44, q = 9, Δ = 0.0004 mm), punch-a",
        "x (mm)",
        um,
        &curves,
    );
    for (fig, set, what) in [
        ("fig21", &poly, "polynomial iteration"),
        ("fig22", &newton, "spline modifications"),
    ] {
        for (d, sub, dir) in [
            (Direction::Plus, "a", "rightward (+)"),
            (Direction::Minus, "b", "leftward (−)"),
        ] {
            let mut curves: Vec<Curve> = set
                .iter()
                .map(|(k, g)| curve(&label(*k), &a.x, &pressure(g, d), 1.0))
                .collect();
            let steady_p = if d == Direction::Plus {
                &exact.state.p_plus
            } else {
                &exact.state.p_minus
            };
            let mut e = curve("exact steady state", &a.x, steady_p, 1.0);
            e.dashed = true;
            curves.push(e);
            plot(
                &out.join(format!("{fig}{sub}.svg")),
                &format!(
                    "{}{sub}: pressure during the {what}, {dir} sliding (punch-a)",
                    caption(fig)
                ),
                "x (mm)",
                "p (MPa)",
                &curves,
            );
        }
    }
    // Fig. 22c (ours): the spline's end state near x_cl with the paper's 17 points and with
    // every interval bisected (33 points), against the exact pressures: where the 17-point
    // spline's 3 % error sits and that it is resolution.
    let fine = solve_steady(
        &a.contact,
        &a.terms,
        SteadyMethod::Spline,
        MethodSettings {
            spline_refinement: 1,
            ..Default::default()
        },
    )
    .unwrap();
    let near = |v: &[f64]| -> Vec<(f64, f64)> {
        a.x.iter()
            .zip(v)
            .filter(|(x, _)| **x <= 1085.0)
            .map(|(x, p)| (*x, *p))
            .collect()
    };
    let zoom = |label: &str, v: &[f64]| Curve {
        label: label.to_string(),
        points: near(v),
        dashed: false,
    };
    plot(
        &out.join("fig22c.svg"),
        "Fig. 22c (ours): spline end state near x_cl, 17 vs 33 spline points (punch-a)",
        "x (mm)",
        "p (MPa)",
        &[
            zoom("p+, 17 points (the paper's)", &spline.state.p_plus),
            zoom("p−, 17 points (the paper's)", &spline.state.p_minus),
            zoom("p+, 33 points", &fine.state.p_plus),
            zoom("p−, 33 points", &fine.state.p_minus),
            zoom("p+, exact steady state", &exact.state.p_plus),
            zoom("p−, exact steady state", &exact.state.p_minus),
        ],
    );
    // Fig. 23: steady pressures.
    plot(
        &out.join("fig23.svg"),
        "Fig. 23a: contact pressure in the periodic steady state (punch-a)",
        "x (mm)",
        "p (MPa)",
        &[
            curve("p+", &a.x, &exact.state.p_plus, 1.0),
            curve("p-", &a.x, &exact.state.p_minus, 1.0),
            curve(
                "p+ + p-",
                &a.x,
                &exact
                    .state
                    .p_plus
                    .iter()
                    .zip(&exact.state.p_minus)
                    .map(|(p, q)| p + q)
                    .collect::<Vec<_>>(),
                1.0,
            ),
        ],
    );
    // Fig. 24, 25: penalty iteration, shape and '+' pressure evolution.
    for (name, fig) in [("punch-a", "fig24"), ("punch-b40", "fig25")] {
        let c = case(name);
        let (mut shapes, mut pressures, mut sums) = (Vec::new(), Vec::new(), Vec::new());
        for k in [1, 50, 100, 200, 300, 500, 5000] {
            let o = run(&c, SteadyMethod::Penalty, k);
            let label = if k == 5000 {
                format!("converged ({})", o.state.iterations)
            } else {
                format!("i = {k}")
            };
            shapes.push(curve(
                &label,
                &c.x,
                &zeroed(&c.x, &o.state.shape, 1100.0),
                1e3,
            ));
            pressures.push(curve(&label, &c.x, &o.state.p_plus, 1.0));
            let s: Vec<f64> = o
                .state
                .p_plus
                .iter()
                .zip(&o.state.p_minus)
                .map(|(p, q)| p + q)
                .collect();
            sums.push(curve(&label, &c.x, &s, 1.0));
        }
        plot(
            &out.join(format!("{fig}a.svg")),
            &format!("{}a: penalty iteration, shape ({name})", caption(fig)),
            "x (mm)",
            um,
            &shapes,
        );
        plot(
            &out.join(format!("{fig}b.svg")),
            &format!("{}b: penalty iteration, p+ ({name})", caption(fig)),
            "x (mm)",
            "p+ (MPa)",
            &pressures,
        );
        plot(
            &out.join(format!("{fig}e.svg")),
            &format!("{}e: penalty iteration, p+ + p- ({name})", caption(fig)),
            "x (mm)",
            "p+ + p- (MPa)",
            &sums,
        );
    }
    // Fig. 14: brake, averaged monotonic shape vs steady shape, zeroed at the contact ends by
    // the plate's vertical motion (gap pattern cos α).
    let b = case("brake");
    let bavg = averaged_shape(&b.contact, &b.terms, AveragedReading::Mean).unwrap();
    let bsum = averaged_shape(&b.contact, &b.terms, AveragedReading::Sum).unwrap();
    let bex = run(&b, SteadyMethod::Exact, 100);
    let r = b.contact.rigid_gap_matrix();
    let ends = |g: &[f64]| -> Vec<f64> {
        g.iter()
            .enumerate()
            .map(|(i, v)| v - g[0] / r[0] * r[i])
            .collect()
    };
    plot(
        &out.join("fig14.svg"),
        "Fig. 14: brake, averaged monotonic vs steady shape (no accumulated wear)",
        "x (mm)",
        um,
        &[
            curve("averaged, mean", &b.x, &ends(&bavg.shape), 1e3),
            curve("averaged, sum (eq. 39)", &b.x, &ends(&bsum.shape), 1e3),
            curve(
                "periodic steady shape (exact)",
                &b.x,
                &ends(&bex.state.shape),
                1e3,
            ),
        ],
    );
    integration_figures(&out);
    println!("figures written to {}", out.display());
}

/// The wear run of built-in example `name`.
fn wear_run(name: &str) -> (wearfem::driver::WearRun, Vec<f64>) {
    let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
    let r = wearfem::driver::wear(&p, None, |_| {}).unwrap();
    let x = r.contact.points.x.iter().map(|q| q[0]).collect();
    (r, x)
}

/// Snapshot pressures and shapes of a run: one curve per recorded step.
fn snapshots(r: &wearfem::driver::WearRun, x: &[f64], shape: bool, zero_at: f64) -> Vec<Curve> {
    r.history
        .snapshots
        .iter()
        .map(|s| {
            let label = format!(
                "n = {} ({}, half period {})",
                s.step, s.direction, s.half_period
            );
            if shape {
                curve(&label, x, &zeroed(x, &s.shape, zero_at), 1e3)
            } else {
                curve(&label, x, &s.pressure, 1.0)
            }
        })
        .collect()
}

fn integration_figures(out: &Path) {
    let um = "shape (µm)";
    // Fig. 4: punch-b40, pressure snapshots and shape evolution.
    let (r, x) = wear_run("punch-b40");
    plot(
        &out.join("fig04a.svg"),
        "Fig. 4a: contact pressure at steps n (punch-b40)",
        "x (mm)",
        "p (MPa)",
        &snapshots(&r, &x, false, 1100.0),
    );
    plot(
        &out.join("fig04b.svg"),
        "Fig. 4b: shape evolution (punch-b40), zero at x = 1100",
        "x (mm)",
        um,
        &snapshots(&r, &x, true, 1100.0),
    );
    // Fig. 17, 18: dissipation per half period and δw per cycle (punch-a, as §6.1).
    let (ra, _) = wear_run("punch-a");
    let series = |dir: &str, f: &dyn Fn(&wearfem::wear::StepRecord) -> f64| -> Vec<(f64, f64)> {
        ra.history
            .steps
            .iter()
            .filter(|s| s.direction == dir)
            .map(|s| (s.half_period as f64, f(s)))
            .collect()
    };
    plot(
        &out.join("fig17.svg"),
        "Fig. 17: wear dissipation of a half period (punch-a)",
        "half period n",
        "E_w (N mm)",
        &[
            Curve {
                label: "'+' half periods".into(),
                points: series("+", &|s| s.dissipation),
                dashed: false,
            },
            Curve {
                label: "'−' half periods".into(),
                points: series("−", &|s| s.dissipation),
                dashed: false,
            },
        ],
    );
    plot_axes(
        &out.join("fig18.svg"),
        "Fig. 18: max δw of a cycle (eq. 40, punch-a)",
        "half period n",
        "max δw (mm)",
        &[Curve {
            label: "max δw".into(),
            points: series("−", &|s| s.delta_w),
            dashed: false,
        }],
        true,
    );
    // Fig. 5: the wear exponent b, steady states (exact method).
    let mut pressures = Vec::new();
    let mut shapes = Vec::new();
    for name in ["punch-b40-b0.8", "punch-b40", "punch-b40-b1.2"] {
        let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
        let (st, contact, _) = wearfem::driver::steady(&p).unwrap();
        // A state the Newton iteration did not finish is no reference.
        assert_eq!(st.status, wearfem::steady::SteadyStatus::Solved);
        let xs: Vec<f64> = contact.points.x.iter().map(|q| q[0]).collect();
        pressures.push(curve(&format!("{name}: p+"), &xs, &st.p_plus, 1.0));
        shapes.push(curve(name, &xs, &zeroed(&xs, &st.shape, 1100.0), 1e3));
    }
    plot(
        &out.join("fig05a.svg"),
        "Fig. 5a: steady pressure p+ for b = 0.8, 1, 1.2",
        "x (mm)",
        "p+ (MPa)",
        &pressures,
    );
    plot(
        &out.join("fig05b.svg"),
        "Fig. 5b: steady shape for b = 0.8, 1, 1.2",
        "x (mm)",
        um,
        &shapes,
    );
    // Fig. 6–9: load variants 2 and 3.
    for (name, fp, fs, label) in [
        ("punch-b40-variant2", "fig06", "fig07", "variant 2"),
        ("punch-b40-variant3", "fig08", "fig09", "variant 3"),
    ] {
        let (r, x) = wear_run(name);
        plot(
            &out.join(format!("{fp}.svg")),
            &format!("{}: contact pressure at steps n, load {label}", caption(fp)),
            "x (mm)",
            "p (MPa)",
            &snapshots(&r, &x, false, 1100.0),
        );
        let sum: Vec<f64> = r
            .history
            .p_plus
            .iter()
            .zip(&r.history.p_minus)
            .map(|(a, b)| a + b)
            .collect();
        plot(
            &out.join(format!("{fp}-sum.svg")),
            &format!(
                "{}: summed pressure of the last cycle, load {label}",
                caption(fp)
            ),
            "x (mm)",
            "p+ + p- (MPa)",
            &[curve("p+ + p-, n = 1699–1700", &x, &sum, 1.0)],
        );
        plot(
            &out.join(format!("{fs}.svg")),
            &format!(
                "{}: shape evolution, load {label}, zero at x = 1100",
                caption(fs)
            ),
            "x (mm)",
            um,
            &snapshots(&r, &x, true, 1100.0),
        );
    }
    // Fig. 11–13: brake.
    let (rb, xb) = wear_run("brake");
    plot(
        &out.join("fig11.svg"),
        "Fig. 11: brake, contact pressure at steps n",
        "x (mm)",
        "p (MPa)",
        &snapshots(&rb, &xb, false, 0.0),
    );
    let crown: Vec<(f64, f64)> = rb
        .history
        .steps
        .windows(2)
        .map(|w| (w[1].step as f64, w[0].probes[0] + w[1].probes[0]))
        .collect();
    plot(
        &out.join("fig12.svg"),
        "Fig. 12: brake, p_Σ(0) = p+ + p- at the crown",
        "step n",
        "p_Σ(0) (MPa)",
        &[Curve {
            label: "p_Σ(0)".into(),
            points: crown,
            dashed: false,
        }],
    );
    plot(
        &out.join("fig13.svg"),
        "Fig. 13: brake, shape evolution (zero at the crown)",
        "x (mm)",
        um,
        &snapshots(&rb, &xb, true, 0.0),
    );
}
