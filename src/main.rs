//! `wearfem`: the command line. Every job is a library call ([`wearfem::driver`]); this file
//! only reads arguments, loads the problem and writes the results.

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use wearfem::driver::{self, JobError};
use wearfem::examples::EXAMPLES;
use wearfem::monotonic_shape::AveragedReading;
use wearfem::output::write_json;
use wearfem::paper_steady::{MethodSettings, Sensitivities, SteadyMethod};
use wearfem::problem::Problem;

#[derive(Parser)]
#[command(
    name = "wearfem",
    version,
    about = "Steady sliding wear by p-version finite elements (mm, N, MPa, s)"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Solve a static elastic problem; writes DIR/summary.json.
    Elastic {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// One contact solve of the initial configuration (no wear); writes DIR/summary.json.
    Contact {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// Integrate wear over the problem's steps; writes summary.json, history.csv, final.csv.
    Run {
        /// Problem file (TOML) or built-in example name (default: punch-b40).
        problem: Option<String>,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Override the number of steps.
        #[arg(long)]
        steps: Option<usize>,
    },
    /// Compute the steady worn state directly (no time integration); writes summary.json,
    /// steady.csv and pressure.svg, shape.svg (and iterations.csv for reciprocating sliding).
    Steady {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// exact (semismooth Newton, default), or the paper's §6: averaged (eq. 39), spline
        /// (§6.2), penalty (§6.3).
        #[arg(long, default_value = "exact")]
        method: String,
        /// Reading of eq. 39: mean (what the paper's printed ordinates are) or sum (as printed).
        #[arg(long, default_value = "mean")]
        reading: String,
        /// Spline sensitivities: fd (finite differences, eq. 46) or exact.
        #[arg(long, default_value = "fd")]
        sensitivities: String,
        /// Penalty parameter c_n of the penalty method, MPa/mm (default: the contact stiffness).
        #[arg(long)]
        penalty: Option<f64>,
        /// Convergence tolerance of the spline and penalty methods on eq. 49 (relative).
        #[arg(long, default_value_t = 1e-3)]
        tolerance: f64,
    },
    /// List the built-in examples, or print one (`wearfem examples show NAME`).
    Examples {
        /// "show".
        action: Option<String>,
        /// Example name.
        name: Option<String>,
    },
}

/// Failures: bad input exits 2, a failed computation 1.
enum Failure {
    Input(String),
    Compute(String),
}

impl From<JobError> for Failure {
    fn from(e: JobError) -> Self {
        match e {
            JobError::Problem(_) => Failure::Input(e.to_string()),
            JobError::Compute(m) => Failure::Compute(m),
        }
    }
}

impl From<wearfem::output::OutputError> for Failure {
    fn from(e: wearfem::output::OutputError) -> Self {
        Failure::Compute(e.to_string())
    }
}

fn load(name: &str) -> Result<Problem, Failure> {
    let (text, file) = if Path::new(name).exists() {
        let text = std::fs::read_to_string(name)
            .map_err(|e| Failure::Input(format!("{name}: cannot read: {e}")))?;
        (text, name.to_string())
    } else if let Some(text) = wearfem::examples::example(name) {
        (text.to_string(), format!("built-in example {name}"))
    } else {
        let names: Vec<&str> = EXAMPLES.iter().map(|e| e.0).collect();
        return Err(Failure::Input(format!(
            "{name}: no such file, and no built-in example of that name (examples: {})",
            names.join(", ")
        )));
    };
    Problem::from_toml(&text, &file).map_err(|e| Failure::Input(e.to_string()))
}

fn run(cli: Cli) -> Result<(), Failure> {
    let command = cli.command.unwrap_or(Command::Run {
        problem: None,
        out: PathBuf::from("out"),
        steps: None,
    });
    match command {
        Command::Elastic { problem, out } => {
            let p = load(&problem)?;
            let summary = driver::elastic(&p)?;
            write_json(&out, "summary.json", &summary)?;
            println!(
                "{}: {} dofs, strain energy {:.9e} N·mm → {}",
                p.file,
                summary["dofs"],
                summary["strain_energy"].as_f64().unwrap_or(f64::NAN),
                out.join("summary.json").display()
            );
        }
        Command::Contact { problem, out } => {
            let p = load(&problem)?;
            let (summary, contact, solution, info) = driver::contact(&p)?;
            wearfem::output::write_contact(&out, &summary, &contact, &solution)?;
            let peak = solution.pressure.iter().cloned().fold(0.0, f64::max);
            println!("{}: {} contact points, peak pressure {:.4} MPa, {} iterations, complementarity {:.1e}, equilibrium {:.1e} → {}", p.file, contact.len(), peak, info.iterations, info.complementarity, info.equilibrium, out.display());
            if info.status == wearfem::complementarity::Status::Failed {
                return Err(Failure::Compute(format!("the contact solve did not converge (complementarity residual {:.3e}, equilibrium residual {:.3e}); the last iterate was written. A solution may not exist: with a plate that rotates about a pin, friction moves the pressure resultant by μ·l_z, and if that leaves the contact the plate tips", info.complementarity, info.equilibrium)));
            }
        }
        Command::Run {
            problem,
            out,
            steps,
        } => {
            let name = problem.unwrap_or_else(|| "punch-b40".to_string());
            let p = load(&name)?;
            let total = steps.or(p.spec.wear.as_ref().map(|w| w.steps)).unwrap_or(0);
            let mut last_report = std::time::Instant::now();
            let result = driver::wear(&p, steps, |s| {
                if last_report.elapsed().as_secs_f64() > 1.0 {
                    eprintln!("step {}/{} (half period {})", s.step, total, s.half_period);
                    last_report = std::time::Instant::now();
                }
            })?;
            wearfem::output::write_wear(&out, &p, &result)?;
            let h = &result.history;
            // Report the last half cycle in the first step's direction ('+' unless a monotonic
            // or reversed run starts with '-'), so the figure always exists.
            let first = h.steps.first().map_or("+", |s| s.direction);
            let last_first = h.steps.iter().rev().find(|s| s.direction == first);
            let probe_text: Vec<String> = match last_first {
                Some(step) => result
                    .probes
                    .iter()
                    .zip(&step.probes)
                    .map(|((n, _), value)| format!("p({n}) = {value:.4} MPa"))
                    .collect(),
                None => vec!["no steps".to_string()],
            };
            println!("{}: {} steps ({} half periods), {} contact solves in {:.3} s (+{:.3} s set-up); last '{first}' half cycle: {} → {}", p.file, h.steps.len(), h.steps.last().map_or(0, |s| s.half_period), h.solves, result.run_seconds, result.setup_seconds, probe_text.join(", "), out.display());
            if let Some(step) = h.stopped_at {
                return Err(Failure::Compute(format!("the wear increment of step {step} is not finite (β̃, the exponents or the load are far out of range); the run stopped there and the steps before it were written to {}", out.display())));
            }
            if h.failed_solves > 0 || h.unconverged_steps > 0 {
                return Err(Failure::Compute(format!("{} contact solves failed and {} steps missed the implicit criterion (wear.criterion); results kept in {}", h.failed_solves, h.unconverged_steps, out.display())));
            }
        }
        Command::Steady {
            problem,
            out,
            method,
            reading,
            sensitivities,
            penalty,
            tolerance,
        } => {
            let p = load(&problem)?;
            let reciprocating = p
                .spec
                .wear
                .as_ref()
                .is_some_and(|w| w.sliding == "reciprocating");
            if method != "exact" || reciprocating {
                let settings = method_settings(&reading, &sensitivities, penalty, tolerance)?;
                let method = SteadyMethod::parse(&method).ok_or_else(|| {
                    Failure::Input(format!(
                        "--method: must be exact, averaged, spline or penalty, got \"{method}\""
                    ))
                })?;
                return steady_by(&p, method, settings, &out);
            }
            let (state, contact, seconds) = driver::steady(&p)?;
            wearfem::output::write_steady(&out, &p, &contact, &state, seconds)?;
            let probes: Vec<String> = driver::contact_probes(&p, &contact)
                .iter()
                .map(|(n, i)| {
                    let label = match state.sliding {
                        wearfem::steady::SteadySliding::Reciprocating => "p⁺",
                        wearfem::steady::SteadySliding::Monotonic(_) => "p",
                    };
                    format!("{label}({n}) = {:.4} MPa", state.p_plus[*i])
                })
                .collect();
            println!(
                "{}: steady state in {} iterations, {:.4} s (set-up included); {} → {}",
                p.file,
                state.iterations,
                seconds,
                probes.join(", "),
                out.display()
            );
            if state.status != wearfem::steady::SteadyStatus::Solved {
                return Err(Failure::Compute(format!("the steady-state iteration did not converge ({:?}, wear residual {:.3e}); the last iterate was written. If the friction moment separates the contact zones of the two half cycles, no steady state with one rigid wear per period exists: run the time integration (wearfem run) instead", state.status, state.wear_residual)));
            }
        }
        Command::Examples { action, name } => match (action.as_deref(), name) {
            (None, _) => {
                for (n, text) in EXAMPLES {
                    let title = text
                        .lines()
                        .find_map(|l| l.strip_prefix("title = "))
                        .unwrap_or("")
                        .trim_matches('"');
                    println!("{n:22} {title}");
                }
            }
            (Some("show"), Some(n)) => match wearfem::examples::example(&n) {
                Some(text) => print!("{text}"),
                None => {
                    return Err(Failure::Input(format!(
                        "{n}: no built-in example of that name"
                    )))
                }
            },
            _ => return Err(Failure::Input("usage: wearfem examples [show NAME]".into())),
        },
    }
    Ok(())
}

/// The settings of `wearfem steady --method ...` from its options.
fn method_settings(
    reading: &str,
    sensitivities: &str,
    penalty: Option<f64>,
    tolerance: f64,
) -> Result<MethodSettings, Failure> {
    let reading = match reading {
        "mean" => AveragedReading::Mean,
        "sum" => AveragedReading::Sum,
        other => {
            return Err(Failure::Input(format!(
                "--reading: must be mean or sum, got \"{other}\""
            )))
        }
    };
    let sensitivities = match sensitivities {
        "fd" => Sensitivities::FiniteDifference,
        "exact" => Sensitivities::Exact,
        other => {
            return Err(Failure::Input(format!(
                "--sensitivities: must be fd or exact, got \"{other}\""
            )))
        }
    };
    if penalty.is_some_and(|c| !(c.is_finite() && c > 0.0)) {
        return Err(Failure::Input(
            "--penalty: must be a finite c_n > 0 (MPa/mm)".into(),
        ));
    }
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
        return Err(Failure::Input(format!(
            "--tolerance: must lie in (0, 1), got {tolerance}"
        )));
    }
    Ok(MethodSettings {
        reading,
        sensitivities,
        penalty_stiffness: penalty,
        tolerance,
        ..Default::default()
    })
}

/// `wearfem steady` for reciprocating sliding, by any method.
fn steady_by(
    p: &Problem,
    method: SteadyMethod,
    settings: MethodSettings,
    out: &Path,
) -> Result<(), Failure> {
    let (outcome, contact, setup) = driver::steady_by(p, method, settings)?;
    if outcome.state.status != wearfem::steady::SteadyStatus::Solved {
        // Nothing from a failed solve is written as a result.
        return Err(Failure::Compute(format!("the {} method did not converge in {} iterations ({:?}, eq. 49 residual {:.3e}); nothing was written", method.name(), outcome.state.iterations, outcome.state.status, outcome.residual)));
    }
    wearfem::output::write_steady_method(out, p, &contact, &outcome, setup)?;
    let last = outcome.history.last();
    println!(
        "{}: steady state by the {} method: {} iterations, {} contact solves, {:.4} s (+{:.4} s set-up); eq. 49 residual {:.2e}, max δw {:.2e} mm → {}",
        p.file,
        method.name(),
        outcome.state.iterations,
        outcome.contact_solves,
        outcome.seconds,
        setup,
        outcome.residual,
        last.map_or(f64::NAN, |r| r.max_delta_w),
        out.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(2)
        }
        Err(Failure::Compute(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(1)
        }
    }
}
