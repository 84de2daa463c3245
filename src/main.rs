//! `wearfem`: the command line. Every job is a library call ([`wearfem::driver`]); this file
//! only reads arguments, loads the problem and writes the results.

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use wearfem::driver::{self, JobError};
use wearfem::examples::EXAMPLES;
use wearfem::output::write_json;
use wearfem::overrides::Override;
use wearfem::problem::Problem;

mod progress;

#[derive(Parser)]
#[command(
    name = "wearfem",
    version,
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
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// One contact solve of the initial configuration (no wear); writes DIR/summary.json.
    Contact {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
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
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Compute the steady worn state directly (no time integration); writes summary.json,
    /// steady.csv and pressure.svg, shape.svg.
    Steady {
        /// Problem file (TOML) or built-in example name.
        problem: String,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Override a key of the problem file: KEY=VALUE, e.g. contact.friction=0.3 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
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
        /// Variants solved at once (default: one per core).
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
}

/// Failures: bad input exits 2, a failed computation 1.
enum Failure {
    Input(String),
    Compute(String),
}

impl From<JobError> for Failure {
    fn from(e: JobError) -> Self {
        Failure::Input(e.to_string())
    }
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
        set: vec![],
    });
    let quiet = cli.quiet;
    match command {
        Command::Elastic { problem, out, set } => {
            let p = load(&problem, &set)?;
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
        Command::Contact { problem, out, set } => {
            let p = load(&problem, &set)?;
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
            set,
        } => {
            let name = problem.unwrap_or_else(|| "punch-b40".to_string());
            let p = load(&name, &set)?;
            let bar = progress::StepBar::new(&p, steps, quiet);
            let result = driver::wear(&p, steps, |s| bar.step(s));
            bar.finish();
            let result = result?;
            wearfem::output::write_wear(&out, &p, &result)?;
            if !result.records_past_end.is_empty() {
                eprintln!(
                    "note: wear.record asks for steps {:?}, past the last step of this run (--steps); they are listed as records_past_end in summary.json",
                    result.records_past_end
                );
            }
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
        Command::Steady { problem, out, set } => {
            let p = load(&problem, &set)?;
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

/// `wearfem sweep`: every variant is checked before any is solved; a variant whose input is
/// bad stops the study with exit code 2 and nothing written.
fn sweep(
    name: &str,
    set: &[String],
    run: bool,
    jobs: usize,
    out: &Path,
    quiet: bool,
) -> Result<(), Failure> {
    use wearfem::sweep::{self, Job, Sweep};
    let (text, file) = read(name)?;
    let input = |e: wearfem::problem::ProblemError| Failure::Input(e.to_string());
    let variants = Sweep::parse(set)
        .and_then(|s| s.prepare(&text, &file))
        .map_err(input)?;
    let job = if run { Job::Run } else { Job::Steady };
    let threads = if jobs == 0 {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    } else {
        jobs
    };
    let start = std::time::Instant::now();
    let bar = progress::count_bar(variants.len(), "variants", quiet);
    let results = sweep::run(&variants, job, threads, &|_| bar.inc(1));
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();
    let outcomes = results
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(Failure::from)?;
    let title = &variants[0].problem.spec.title;
    sweep::report::write(out, title, job, threads, &variants, &outcomes, seconds)?;
    let failed = outcomes.iter().filter(|o| !o.converged).count();
    println!(
        "{file}: {} variants on {threads} threads in {seconds:.2} s; {failed} did not converge → {}",
        variants.len(),
        out.join("sweep.csv").display()
    );
    if failed > 0 {
        return Err(Failure::Compute(format!("{failed} of {} variants did not converge (see the status column of {}); all rows were written", variants.len(), out.join("sweep.csv").display())));
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
