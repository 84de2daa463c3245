//! `wearfem`: the command line. Every job is a library call ([`wearfem::driver`]); this file
//! only reads arguments, loads the problem and writes the results.

/// Large dense buffers (factors of 2 MB and more) are allocated and freed many times; glibc's
/// malloc hands each back to the operating system and faults it in again, mimalloc reuses them.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use wearfem::driver::{self, JobError};
use wearfem::examples::EXAMPLES;
use wearfem::monotonic_shape::AveragedReading;
use wearfem::output::write_json;
use wearfem::overrides::Override;
use wearfem::paper_steady::{MethodSettings, Sensitivities, SteadyMethod};
use wearfem::problem::Problem;

mod commands;
mod fretting;
mod progress;

use commands::{method_settings, steady_by, sweep, validate};

#[derive(Parser)]
#[command(
    name = "wearfem",
    version = wearfem::VERSION,
    about = "Steady sliding wear by p-version finite elements (mm, N, MPa, s)"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Show no progress bar (it is also hidden when stderr is not a terminal).
    #[arg(long, global = true)]
    quiet: bool,
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
        /// Also write ParaView files (results.pvd, vtk/*.vtu); same as `[output] vtk = true`.
        #[arg(long)]
        vtk: bool,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// One contact solve of the initial configuration (no wear); writes DIR/summary.json, contact.csv and the pressure figure.
    Contact {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Also write ParaView files (results.pvd, vtk/*.vtu); same as `[output] vtk = true`.
        #[arg(long)]
        vtk: bool,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Integrate wear over the problem's steps; writes summary.json, history.csv, final.csv,
    /// snapshots.csv and the figures of docs/figures.md (PNG and SVG).
    Run {
        /// Problem file (TOML) or built-in example name (default: punch-b40).
        problem: Option<String>,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Override the number of steps.
        #[arg(long)]
        steps: Option<usize>,
        /// Also write ParaView files (results.pvd, vtk/*.vtu); same as `[output] vtk = true`.
        #[arg(long)]
        vtk: bool,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Compute the steady worn state directly (no time integration); writes summary.json,
    /// steady.csv and the figures pressure and shape (PNG and SVG); with --method averaged,
    /// spline or penalty (the paper's §6 methods) also iterations.csv.
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
        /// averaged, spline, penalty: reading of eq. 39, mean (default; what the paper's
        /// printed ordinates are) or sum (as printed).
        #[arg(long)]
        reading: Option<String>,
        /// spline: sensitivities, fd (default; finite differences, eq. 46) or exact.
        #[arg(long)]
        sensitivities: Option<String>,
        /// penalty: penalty parameter c_n, MPa/mm (default: the contact stiffness).
        #[arg(long)]
        penalty: Option<f64>,
        /// spline: bisect every interval between the paper's 17 spline points this many times
        /// (default 0: the paper's 17 points; 1: 33 points). On the shipped 65-point meshes
        /// 17 points are 3-4 % off the exact state at the ends of the both-halves contact
        /// zone and 33 within 0.05 %; on finer meshes the corner peaks are sharper and more
        /// are needed (257 points: 33 %, 8.6 %, then 0.8 % and 0.06 % with 2 and 3). The
        /// distance is printed. At most as many spline points as contact points.
        #[arg(long)]
        spline_refinement: Option<u32>,
        /// spline, penalty: convergence tolerance on eq. 49 (relative; default 1e-3).
        #[arg(long)]
        tolerance: Option<f64>,
        /// Also write ParaView files (results.pvd, vtk/*.vtu); same as `[output] vtk = true`.
        #[arg(long)]
        vtk: bool,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Rerun every validation claim (closed forms, the paper's numbers, steady vs transient);
    /// prints the table, writes DIR/validation.md and DIR/validation.json, exits 1 on a FAIL.
    Validate {
        /// Skip the long transient runs (about 0.7 s instead of 1.3 s).
        #[arg(long)]
        quick: bool,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Also replace the table between the markers of this Markdown file
        /// (docs/validation.md).
        #[arg(long, value_name = "FILE")]
        update_doc: Option<PathBuf>,
        /// Replace the reference value of one check, ID=VALUE (tests the failure path).
        #[arg(long, hide = true)]
        perturb: Option<String>,
    },
    /// A parameter study: the Cartesian product of the --set lists, solved in parallel; writes
    /// sweep.csv (one row per variant), sweep.json and sweep.svg.
    Sweep {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// KEY=[V1, V2, …]: the values of one key (a TOML array; repeatable, first key slowest).
        #[arg(long = "set", value_name = "KEY=[V1, V2, …]", required = true)]
        set: Vec<String>,
        /// Solve the steady state of each variant (the default).
        #[arg(long, conflicts_with = "run")]
        steady: bool,
        /// Run the wear integration of each variant.
        #[arg(long)]
        run: bool,
        /// Variants solved at once, on as many threads (default 0: one per core). More than
        /// the study's variants would only start idle threads: N is lowered to the number of
        /// variants, and the number used is printed and given as `threads` in sweep.json.
        #[arg(short = 'j', long = "jobs", default_value_t = 0)]
        jobs: usize,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// List the built-in examples, or print one (`wearfem examples show NAME`).
    Examples {
        /// "show".
        action: Option<String>,
        /// Example name.
        name: Option<String>,
    },
    /// Explain a warning code (`warning[CODE]: …`), or list the codes.
    Explain {
        /// The code, as the warning gives it.
        code: Option<String>,
    },
}

impl Command {
    /// The output directory of a command that writes one.
    fn out(&self) -> Option<&Path> {
        match self {
            Command::Elastic { out, .. }
            | Command::Contact { out, .. }
            | Command::Run { out, .. }
            | Command::Steady { out, .. }
            | Command::Validate { out, .. }
            | Command::Sweep { out, .. } => Some(out),
            Command::Examples { .. } | Command::Explain { .. } => None,
        }
    }
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

impl From<wearfem::vtk::VtkError> for Failure {
    fn from(e: wearfem::vtk::VtkError) -> Self {
        match e {
            wearfem::vtk::VtkError::Problem(e) => Failure::Input(e.to_string()),
            wearfem::vtk::VtkError::Output(e) => Failure::Compute(e.to_string()),
            other => Failure::Compute(other.to_string()),
        }
    }
}

/// ParaView output is asked for by `--vtk` or by `[output] vtk = true`.
fn wants_vtk(flag: bool, p: &Problem) -> bool {
    flag || p.spec.output.as_ref().is_some_and(|o| o.vtk)
}

impl From<wearfem::output::OutputError> for Failure {
    fn from(e: wearfem::output::OutputError) -> Self {
        Failure::Compute(e.to_string())
    }
}

fn load(name: &str, set: &[String]) -> Result<Problem, Failure> {
    let (text, file) = read(name)?;
    let overrides = set
        .iter()
        .map(|s| Override::parse(s))
        .collect::<Result<Vec<_>, _>>()
        .and_then(|o| wearfem::overrides::check_together(&o).map(|_| o))
        .map_err(|e| Failure::Input(e.to_string()))?;
    Problem::with_overrides(&text, &file, &overrides).map_err(|e| Failure::Input(e.to_string()))
}

/// The text of a problem file or built-in example, and its name for messages.
fn read(name: &str) -> Result<(String, String), Failure> {
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
    Ok((text, file))
}

fn run(cli: Cli) -> Result<(), Failure> {
    let command = cli.command.unwrap_or(Command::Run {
        problem: None,
        out: PathBuf::from("out"),
        steps: None,
        vtk: false,
        set: vec![],
    });
    let quiet = cli.quiet;
    if let Some(out) = command.out() {
        // Before anything can fail: DIR then never holds an earlier command's results beside
        // or instead of this one's, whether this one succeeds, fails or is refused.
        wearfem::output::remove_earlier_outputs(out)?;
    }
    match command {
        Command::Elastic {
            problem,
            out,
            vtk,
            set,
        } => {
            let p = load(&problem, &set)?;
            let summary = driver::elastic(&p)?;
            write_json(&out, "summary.json", &summary)?;
            if wants_vtk(vtk, &p) {
                wearfem::vtk::write_elastic(&out, &p)?;
            }
            for w in summary["warnings"].as_array().into_iter().flatten() {
                eprintln!("{}", w.as_str().unwrap_or_default());
            }
            println!(
                "{}: {} dofs, strain energy {:.9e} N·mm → {}",
                p.file,
                summary["dofs"],
                summary["strain_energy"].as_f64().unwrap_or(f64::NAN),
                out.join("summary.json").display()
            );
        }
        Command::Contact {
            problem,
            out,
            vtk,
            set,
        } => {
            let p = load(&problem, &set)?;
            if wearfem::jobs::fretting::is_fretting(&p) {
                return fretting::contact(&p, &out, wants_vtk(vtk, &p));
            }
            let (summary, contact, solution, info) = driver::contact(&p)?;
            let solved = info.status == wearfem::complementarity::Status::Solved;
            if solved {
                wearfem::output::write_contact(
                    &out,
                    &wearfem::plot::problem_name(&p.file),
                    &summary,
                    &contact,
                    &solution,
                )?;
            } else {
                // Only the status and residuals: no CSV or figure of a failed solve.
                wearfem::output::write_json(&out, "summary.json", &summary)?;
            }
            // A failed solve gets no ParaView files (its message follows).
            if wants_vtk(vtk, &p) && solved {
                wearfem::vtk::write_contact_job(&out, &p)?;
            }
            let peak = solution.pressure.iter().cloned().fold(0.0, f64::max);
            // The zone diagnostics describe a solution: a failed solve gets none (its
            // pressures are not one), only what its failure says about the loads.
            for w in summary["warnings"].as_array().into_iter().flatten() {
                eprintln!("{}", w.as_str().unwrap_or_default());
            }
            let unbalanced = (!solved)
                .then(|| driver::pressure_at_one_end(&solution.pressure))
                .flatten();
            if let Some(note) = driver::target_mesh_note(&p, &contact) {
                println!("{note}");
            }
            if solved {
                println!("{}: {} contact points, peak pressure {:.4} MPa, {} iterations, complementarity {:.1e}, equilibrium {:.1e} → {}", p.file, contact.len(), peak, info.iterations, info.complementarity, info.equilibrium, out.display());
            }
            if let (false, Some(end)) = (solved, unbalanced) {
                return Err(Failure::Compute(format!("the contact solve did not converge (complementarity residual {:.3e}, equilibrium residual {:.3e}): {}. summary.json holds the status and residuals, and no values of the failed solve were written", info.complementarity, info.equilibrium, driver::unbalanced_explanation(end))));
            }
            if info.status == wearfem::complementarity::Status::Failed {
                return Err(Failure::Compute(format!("the contact solve did not converge (complementarity residual {:.3e}, equilibrium residual {:.3e}); summary.json holds the status and residuals, and no values of the failed solve were written. A solution may not exist: with a plate that rotates about a pin, friction moves the pressure resultant by μ·l_z, and if that leaves the contact the plate tips", info.complementarity, info.equilibrium)));
            }
        }
        Command::Run {
            problem,
            out,
            steps,
            vtk,
            set,
        } => {
            let name = problem.unwrap_or_else(|| "punch-b40".to_string());
            let p = load(&name, &set)?;
            if wearfem::jobs::sliding::is_sliding(&p) {
                return commands::run_sliding(&p, &out, steps, wants_vtk(vtk, &p));
            }
            if wearfem::jobs::fretting::is_fretting(&p) {
                return fretting::run(&p, &out, steps, wants_vtk(vtk, &p));
            }
            let bar = progress::StepBar::new(&p, steps, quiet);
            let result = driver::wear_checked(&p, steps, |s| {
                bar.step(s);
                std::ops::ControlFlow::Continue(())
            });
            bar.finish();
            let result = result?;
            wearfem::output::write_wear(&out, &p, &result)?;
            if wants_vtk(vtk, &p) {
                wearfem::vtk::write_run(&out, &p, &result)?;
            }
            if !result.records_past_end.is_empty() {
                eprintln!(
                    "note: the recording asks for steps {:?} (wear.record, or the steps the record distances, times or cycles fall on), past the last step of this run ({}); they are not recorded and are listed as records_past_end in summary.json",
                    result.records_past_end,
                    match &result.history.stopped {
                        Some((step, reason)) => format!("it stopped at step {step}: {reason}"),
                        None => "--steps".to_string(),
                    }
                );
            }
            let h = &result.history;
            if let Some(note) = driver::target_mesh_note(&p, &result.contact) {
                println!("{note}");
            }
            println!("{}", result.console_summary(&p, &out.display().to_string()));
            let penalty = matches!(
                driver::method(&p),
                Ok(wearfem::complementarity::Method::Penalty { .. })
            );
            match result.console_cycle(penalty) {
                Some(line) => println!("{line}"),
                None => println!("no full cycle completed: no final profiles written"),
            }
            for w in result.warnings(&p) {
                eprintln!("{w}");
            }
            match &h.stopped {
                Some((step, wearfem::wear::StopReason::SteadyState)) => {
                    if result.steady_check.reached(h) {
                        println!("adaptive schedule: steady state reached at step {step}");
                    } else {
                        // Its own estimate and the check against the steady state disagree:
                        // the check wins, and the user hears both.
                        eprintln!("{}", wearfem::codes::warning("adaptive-stop", &p.file, format!("the adaptive schedule stopped at step {step} by its own estimate, but the last cycle is NOT at the steady state (above)")));
                    }
                }
                Some((step, reason)) => {
                    // A first step that fails on loads no pressure can balance says so.
                    let why = match (step, reason) {
                        (1, wearfem::wear::StopReason::FailedSolve { .. }) => {
                            driver::unbalanced_loads(&p, &result.contact)
                                .map(|why| format!(": {why}"))
                        }
                        _ => None,
                    };
                    return Err(Failure::Compute(format!("step {step}: {reason}; the run stopped there, and the {} steps before it were written to {} (nothing from step {step}){}", step - 1, out.display(), why.unwrap_or_default())));
                }
                None => {}
            }
            if h.unconverged_steps > 0 || h.oscillating_steps > 0 {
                // Only the paper's fixed-point scheme keeps such steps (an implicit step that
                // misses its tolerance stops the run above): say how far they missed it.
                let (worst_step, worst) = h
                    .steps
                    .iter()
                    .map(|s| (s.step, s.criterion))
                    .fold((0, 0.0f64), |a, b| if b.1 > a.1 { b } else { a });
                let wear = p.spec.wear.as_ref();
                let tolerance = wear.map_or(f64::NAN, |w| w.tolerance);
                // Name the criterion the run used (red team 23: "eq. 27" was printed for
                // `pointwise`), and only the failures that happened.
                let criterion = match wear.map(|w| w.criterion.as_str()) {
                    Some("pointwise") => "the pointwise change",
                    _ => "eq. 27",
                };
                let mut failures = Vec::new();
                if h.unconverged_steps > 0 {
                    failures.push(format!("{} steps missed their iteration tolerance (wear.tolerance = {tolerance} %; the largest criterion, {criterion}, was {worst:.3} % at step {worst_step})", h.unconverged_steps));
                }
                if h.oscillating_steps > 0 {
                    failures.push(format!("{} fixed-point steps kept a shape whose pressure wears it differently by more than {} % (the shape oscillates; use wear.scheme = \"implicit\")", h.oscillating_steps, 100.0 * wearfem::wear::OSCILLATION_LIMIT));
                }
                return Err(Failure::Compute(format!("{}; the paper's scheme keeps such steps, as the paper does: results kept in {}", failures.join(", and "), out.display())));
            }
        }
        Command::Steady {
            problem,
            out,
            vtk,
            set,
            method,
            reading,
            sensitivities,
            penalty,
            spline_refinement,
            tolerance,
        } => {
            let method = SteadyMethod::parse(&method).ok_or_else(|| {
                Failure::Input(format!(
                    "--method: must be exact, averaged, spline or penalty, got \"{method}\""
                ))
            })?;
            // An option the chosen method does not use is an error, not ignored.
            let options = commands::MethodOptions {
                reading,
                sensitivities,
                penalty,
                spline_refinement,
                tolerance,
            };
            let settings = method_settings(method, &options)?;
            let p = load(&problem, &set)?;
            // The paper's §6 methods; `exact` keeps the direct path below (any b, either
            // sliding, ParaView output), whose summary the Python layer reproduces.
            if wearfem::jobs::fretting::is_fretting(&p) {
                if method != SteadyMethod::Exact {
                    return Err(Failure::Input(format!("{}: --method applies to the paper's steady state of reciprocating sliding; a fretting problem's steady state is the final state of partial slip, found directly (leave --method out)", p.file)));
                }
                return fretting::steady(&p, &out, wants_vtk(vtk, &p));
            }
            if method != SteadyMethod::Exact {
                return steady_by(&p, method, settings, &out, wants_vtk(vtk, &p));
            }
            if wearfem::jobs::sliding::is_sliding(&p) {
                return commands::steady_sliding(&p, &out, wants_vtk(vtk, &p));
            }
            let (state, contact, seconds, heat) = driver::steady_with_heat(&p)?;
            if state.status != wearfem::steady::SteadyStatus::Solved {
                // Nothing from an unconverged iteration is written as a result.
                let hint = wearfem::steady::failure_hint(&state, &contact);
                if let Some(why) = driver::unbalanced_loads(&p, &contact) {
                    // No steady state and no run either: say why, not "run instead".
                    return Err(Failure::Compute(format!("the steady-state iteration did not converge ({:?}, wear residual {:.3e}); nothing was written, because {why}", state.status, state.wear_residual)));
                }
                return Err(Failure::Compute(format!("the steady-state iteration did not converge ({:?}, wear residual {:.3e}); nothing was written. {hint}: run the time integration (wearfem run) instead", state.status, state.wear_residual)));
            }
            let mut warnings = driver::steady_warnings(&p, &contact, &state);
            if let Some(heat) = &heat {
                warnings.extend(wearfem::jobs::heat::steady_warnings(
                    &p, &contact, &state, heat,
                ));
            }
            wearfem::output::write_steady(&out, &p, &contact, &state, seconds, &warnings)?;
            if let Some(heat) = &heat {
                wearfem::output::write_steady_heat(&out, &p, &contact, heat)?;
            }
            if let Some(note) = driver::target_mesh_note(&p, &contact) {
                println!("{note}");
            }
            if wants_vtk(vtk, &p) {
                wearfem::vtk::write_steady(&out, &p, &state, heat.as_ref())?;
            }
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
            // Without probes the line ends at the time (it read "…;  → out").
            let probes = if probes.is_empty() {
                String::new()
            } else {
                format!("; {}", probes.join(", "))
            };
            println!(
                "{}: steady state in {} iterations, {:.4} s (set-up included){probes} → {}",
                p.file,
                state.iterations,
                seconds,
                out.display()
            );
            for w in &warnings {
                eprintln!("{w}");
            }
        }
        Command::Validate {
            quick,
            out,
            update_doc,
            perturb,
        } => validate(quick, &out, update_doc.as_deref(), perturb.as_deref())?,
        Command::Sweep {
            problem,
            set,
            steady: _,
            run,
            jobs,
            out,
        } => sweep(&problem, &set, run, jobs, &out, quiet)?,
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
                    let names: Vec<&str> = EXAMPLES.iter().map(|e| e.0).collect();
                    return Err(Failure::Input(format!(
                        "{n}: no built-in example of that name (examples: {})",
                        names.join(", ")
                    )));
                }
            },
            _ => return Err(Failure::Input("usage: wearfem examples [show NAME]".into())),
        },
        Command::Explain { code: None } => {
            for code in wearfem::codes::codes() {
                println!("{code}");
            }
        }
        Command::Explain { code: Some(code) } => match wearfem::codes::explain(&code) {
            Some(text) => println!("{code}\n\n{text}"),
            None => {
                return Err(Failure::Input(format!(
                    "{code}: no warning has that code (codes: {})",
                    wearfem::codes::codes().join(", ")
                )))
            }
        },
    }
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
