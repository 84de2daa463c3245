//! The command line's longer jobs, kept out of `main.rs`: `validate`, `sweep` and the
//! paper's §6 methods of `steady` (moved here unchanged).

use super::*;

/// `wearfem validate`: rerun every validation claim, print the table, write validation.md and
/// validation.json to `out` (and the table into `update_doc`); a FAIL is exit code 1.
pub(crate) fn validate(
    quick: bool,
    out: &Path,
    update_doc: Option<&Path>,
    perturb: Option<&str>,
) -> Result<(), Failure> {
    let perturb = match perturb {
        None => None,
        Some(text) => {
            let parsed = text
                .split_once('=')
                .and_then(|(id, v)| Some((id.to_string(), v.trim().parse::<f64>().ok()?)));
            Some(parsed.ok_or_else(|| {
                Failure::Input(format!("--perturb: expected ID=VALUE, got \"{text}\""))
            })?)
        }
    };
    let options = wearfem::validate::Options { quick, perturb };
    let report = wearfem::validate::run(&options).map_err(|e| match e {
        wearfem::validate::ValidateError::UnknownCheck(_) => Failure::Input(e.to_string()),
        other => Failure::Compute(other.to_string()),
    })?;
    let table = report.markdown();
    print!("{table}");
    write_text(out, "validation.md", &table)?;
    write_json(out, "validation.json", &report.json())?;
    if let Some(doc) = update_doc {
        let text = std::fs::read_to_string(doc)
            .map_err(|e| Failure::Input(format!("{}: cannot read: {e}", doc.display())))?;
        let new = wearfem::validate::splice(&text, &table).ok_or_else(|| {
            Failure::Input(format!(
                "{}: no table markers ({} … {})",
                doc.display(),
                wearfem::validate::DOC_BEGIN,
                wearfem::validate::DOC_END
            ))
        })?;
        std::fs::write(doc, new)
            .map_err(|e| Failure::Compute(format!("cannot write {}: {e}", doc.display())))?;
    }
    println!(
        "{:.1} s → {}",
        report.seconds,
        out.join("validation.md").display()
    );
    if !report.passed() {
        return Err(Failure::Compute(format!(
            "{} of {} validation checks failed (see the table)",
            report.failures(),
            report.checks.len()
        )));
    }
    Ok(())
}

/// `wearfem sweep`: every variant is checked before any is solved; a variant whose input is
/// bad stops the study with exit code 2 and nothing written.
pub(crate) fn sweep(
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
    let job = if run { Job::Run } else { Job::Steady };
    let variants = Sweep::parse(set)
        .and_then(|s| s.prepare(&text, &file, job))
        .map_err(input)?;
    // The threads actually used (at most one per variant), as printed and in sweep.json.
    let threads = sweep::threads(jobs, variants.len());
    // An axis the job never reads gives the same row for every value: say so before the
    // work, and again in sweep.json.
    let study_warnings = sweep::unread::warnings(&file, job, &variants);
    for w in &study_warnings {
        eprintln!("{w}");
    }
    let start = std::time::Instant::now();
    let bar = progress::count_bar(variants.len(), "variants", quiet);
    let results = sweep::run(&variants, job, threads, &|_| bar.inc(1));
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();
    let outcomes = results
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(Failure::from)?;
    // The file's own title: a `title` axis would otherwise give the study its first variant's.
    // Read from the file's text alone, not its schema: a template completed only by the
    // study's overrides cannot be read on its own (red team: such a sweep solved every
    // variant, then exited 2).
    let title = &wearfem::overrides::file_title(&text);
    sweep::report::write(
        out,
        title,
        job,
        threads,
        &variants,
        &outcomes,
        seconds,
        &study_warnings,
    )?;
    let failed = outcomes.iter().filter(|o| !o.converged).count();
    println!(
        "{file}: {} variants on {threads} threads in {seconds:.2} s; {failed} did not converge → {}",
        variants.len(),
        out.join("sweep.csv").display()
    );
    let warned: Vec<String> = variants
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| !o.warnings.is_empty())
        .map(|(v, o)| format!("{} ({} warnings)", variant_name(v), o.warnings.len()))
        .collect();
    if !warned.is_empty() {
        // The lines `wearfem steady`/`run` would print for each: in sweep.json, counted in
        // the CSV's `warnings` column.
        eprintln!(
            "{}",
            wearfem::codes::warning(
                "variants-warned",
                &file,
                format!(
                    "{} of {} variants have warnings (their texts are in sweep.json): {}",
                    warned.len(),
                    variants.len(),
                    warned.join("; ")
                ),
            )
        );
    }
    let no_cycle: Vec<String> = variants
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| o.converged && o.status.contains(sweep::NO_CYCLE))
        .map(|(v, _)| variant_name(v))
        .collect();
    if !no_cycle.is_empty() {
        // Converged, as `wearfem run` (exit 0), but without a last cycle to report.
        eprintln!(
            "note: {file}: {} of {} variants completed no full cycle: their value cells are empty, as `wearfem run` writes no final profiles then: {}",
            no_cycle.len(),
            variants.len(),
            no_cycle.join("; ")
        );
    }
    if failed > 0 {
        // Name each failed variant by its overrides, so that nobody has to find them in the
        // table; their value cells hold nothing (empty in the CSV, null in the JSON).
        let names: Vec<String> = variants
            .iter()
            .zip(&outcomes)
            .filter(|(_, o)| !o.converged)
            .map(|(v, o)| format!("{} ({})", variant_name(v), o.status))
            .collect();
        return Err(Failure::Compute(format!(
            "{failed} of {} variants did not converge: {}; their value cells are left empty in {} (null in sweep.json): only their status and time are written",
            variants.len(),
            names.join("; "),
            out.join("sweep.csv").display()
        )));
    }
    Ok(())
}

/// A variant named by its overrides, `KEY=VALUE KEY=VALUE`, as on the command line.
fn variant_name(v: &wearfem::sweep::Variant) -> String {
    let sets: Vec<String> = v
        .overrides
        .iter()
        .map(|o| format!("{}={}", o.key, o.value_text()))
        .collect();
    sets.join(" ")
}

fn write_text(dir: &Path, name: &str, text: &str) -> Result<(), Failure> {
    let path = dir.join(name);
    std::fs::create_dir_all(dir)
        .and_then(|_| std::fs::write(&path, text))
        .map_err(|e| Failure::Compute(format!("cannot write {}: {e}", path.display())))
}

/// The options of `wearfem steady` that belong to the §6 methods, as given (`None`: not
/// given).
pub(crate) struct MethodOptions {
    pub reading: Option<String>,
    pub sensitivities: Option<String>,
    pub penalty: Option<f64>,
    pub spline_refinement: Option<u32>,
    pub tolerance: Option<f64>,
}

/// Which options each method uses; any other given option is an input error.
const METHOD_OPTIONS: &str = "exact takes none of them; averaged: --reading; spline: --reading, --sensitivities, --spline-refinement, --tolerance; penalty: --reading, --penalty, --tolerance";

/// The settings of `wearfem steady --method ...` from its options: each checked, and each
/// given for a method that does not use it refused (it would be ignored in silence).
pub(crate) fn method_settings(
    method: SteadyMethod,
    o: &MethodOptions,
) -> Result<MethodSettings, Failure> {
    use SteadyMethod::*;
    let given = [
        (
            "--reading",
            o.reading.is_some(),
            &[Averaged, Spline, Penalty][..],
        ),
        ("--sensitivities", o.sensitivities.is_some(), &[Spline][..]),
        ("--penalty", o.penalty.is_some(), &[Penalty][..]),
        (
            "--spline-refinement",
            o.spline_refinement.is_some(),
            &[Spline][..],
        ),
        ("--tolerance", o.tolerance.is_some(), &[Spline, Penalty][..]),
    ];
    for (name, is_given, methods) in given {
        if is_given && !methods.contains(&method) {
            return Err(Failure::Input(format!(
                "{name}: does not apply to --method {} ({METHOD_OPTIONS})",
                method.name()
            )));
        }
    }
    let defaults = MethodSettings::default();
    let reading = match o.reading.as_deref() {
        None => defaults.reading,
        Some("mean") => AveragedReading::Mean,
        Some("sum") => AveragedReading::Sum,
        Some(other) => {
            return Err(Failure::Input(format!(
                "--reading: must be mean or sum, got \"{other}\""
            )))
        }
    };
    let sensitivities = match o.sensitivities.as_deref() {
        None => defaults.sensitivities,
        Some("fd") => Sensitivities::FiniteDifference,
        Some("exact") => Sensitivities::Exact,
        Some(other) => {
            return Err(Failure::Input(format!(
                "--sensitivities: must be fd or exact, got \"{other}\""
            )))
        }
    };
    if o.penalty.is_some_and(|c| !(c.is_finite() && c > 0.0)) {
        return Err(Failure::Input(
            "--penalty: must be a finite c_n > 0 (MPa/mm)".into(),
        ));
    }
    let tolerance = o.tolerance.unwrap_or(defaults.tolerance);
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
        return Err(Failure::Input(format!(
            "--tolerance: must lie in (0, 1), got {tolerance}"
        )));
    }
    Ok(MethodSettings {
        reading,
        sensitivities,
        penalty_stiffness: o.penalty,
        tolerance,
        spline_refinement: o.spline_refinement.unwrap_or(defaults.spline_refinement),
        ..defaults
    })
}

/// `wearfem steady` for reciprocating sliding, by any method.
pub(crate) fn steady_by(
    p: &Problem,
    method: SteadyMethod,
    settings: MethodSettings,
    out: &Path,
    vtk: bool,
) -> Result<(), Failure> {
    let (outcome, contact, setup) = driver::steady_by(p, method, settings)?;
    if outcome.state.status == wearfem::steady::SteadyStatus::NotSteady {
        // The method ended, but its result fails the acceptance rule: not a steady state, and
        // nothing of it is written.
        let why = outcome.not_steady.as_deref().unwrap_or_default();
        return Err(Failure::Compute(format!("the {} method gave no steady state ({} iterations): {why}; nothing was written (docs/validation.md, \"The four steady-state methods\")", method.name(), outcome.state.iterations)));
    }
    if outcome.state.status != wearfem::steady::SteadyStatus::Solved {
        // Nothing from a failed solve is written as a result.
        return Err(Failure::Compute(format!("the {} method did not converge in {} iterations ({:?}, eq. 49 residual {:.3e}); nothing was written", method.name(), outcome.state.iterations, outcome.state.status, outcome.residual)));
    }
    let state = &outcome.state;
    // The exact method's warnings on the model and the mesh, for this state: a §6 method
    // solves the same model (a red team found the strain, half-period and stroke warnings
    // printed by `--method exact` missing from the others).
    let mut warnings = driver::steady_warnings(p, &contact, state);
    match outcome.distance_from_exact {
        Some(d) if d > wearfem::steady_check::STEADY_PRESSURE_LIMIT => {
            warnings.push(wearfem::codes::warning(
                "method-distance",
                &p.file,
                format!(
                    "the {} method's pressures are {:.2} % of the peak from the exact steady state (`--method exact`)",
                    method.name(),
                    100.0 * d
                ),
            ))
        }
        Some(_) => {}
        None => eprintln!(
            "note: {}: the exact steady state could not be computed to compare the {} method with",
            p.file,
            method.name()
        ),
    }
    wearfem::output::write_steady_method(out, p, &contact, &outcome, setup, &warnings)?;
    if let Some(note) = driver::target_mesh_note(p, &contact) {
        println!("{note}");
    }
    if vtk {
        wearfem::vtk::write_steady(out, p, &outcome.state, None)?;
    }
    for w in &warnings {
        eprintln!("{w}");
    }
    // The written state's δw, as in summary.json (the last history record of the penalty
    // method is of the shape before that period's corrections).
    let max_delta_w = outcome.delta_w.iter().cloned().fold(0.0, f64::max);
    println!(
        "{}: steady state by the {} method: {} iterations, {} contact solves, {:.4} s (+{:.4} s set-up); eq. 49 residual {:.2e}, max δw {:.2e} mm; {} → {}",
        p.file,
        method.name(),
        outcome.state.iterations,
        outcome.contact_solves,
        outcome.seconds,
        setup,
        outcome.residual,
        max_delta_w,
        outcome
            .distance_from_exact
            .map_or(
                "no exact steady state to compare the pressures with".to_string(),
                |d| format!("pressures {:.2} % of the peak from the exact steady state", 100.0 * d)
            ),
        out.display()
    );
    Ok(())
}

/// `wearfem run` on sliding pairs: the run, its files, and the console's account of it.
pub(crate) fn run_sliding(
    p: &wearfem::problem::Problem,
    out: &Path,
    steps: Option<usize>,
    vtk: bool,
) -> Result<(), Failure> {
    let run = wearfem::jobs::sliding::wear(p, steps)?;
    wearfem::report::sliding::write(out, p, &run)?;
    if vtk {
        wearfem::vtk::write_sliding(out, &run)?;
    }
    let h = &run.history;
    let volume = h
        .steps
        .last()
        .map_or([0.0; 2], |s| s.worn_area.map(|a| a * run.thickness));
    println!(
        "{}: sliding pairs, {} positions per half period, {} steps ({} half periods, {:.4} m), worn volume {:.4e} mm³ of \"{}\" and {:.4e} mm³ of \"{}\", set-up {:.2} s, run {:.2} s → {}",
        p.file,
        run.contact.len(),
        h.steps.len(),
        h.steps.last().map_or(0, |s| s.half_period),
        run.distance() / 1e3,
        volume[0],
        run.body_names[0],
        volume[1],
        run.body_names[1],
        run.setup_seconds,
        run.run_seconds,
        out.display()
    );
    for w in run.warnings(p) {
        eprintln!("{w}");
    }
    if let Some((step, reason)) = &h.stopped {
        return Err(Failure::Compute(format!("step {step}: {reason}; the run stopped there, and the {} steps before it were written to {} (nothing from step {step})", step - 1, out.display())));
    }
    Ok(())
}

/// `wearfem steady` on sliding pairs: a ring turning under body 1 (the reciprocating stroke is
/// refused with the reason, `wearfem::steady_state::sliding`).
pub(crate) fn steady_sliding(
    p: &wearfem::problem::Problem,
    out: &Path,
    vtk: bool,
) -> Result<(), Failure> {
    if vtk {
        return Err(Failure::Input(format!("{}: ParaView files of a steady state of sliding pairs are not written yet (`wearfem run --vtk` writes the worn track); run without --vtk (and without output.vtk)", p.file)));
    }
    let steady = wearfem::jobs::sliding_steady::steady(p)?;
    let state = &steady.state;
    if state.status != wearfem::steady::SteadyStatus::Solved {
        // Nothing from an unconverged iteration is written as a result.
        return Err(Failure::Compute(format!("the steady-state iteration did not converge ({:?}, wear residual {:.3e}); nothing was written. Run the time integration (wearfem run) instead", state.status, state.wear_residual)));
    }
    let contact = &steady.setup.contact.contacts[0];
    let summary = steady.summary(p);
    wearfem::output::write_steady_summary(out, p, contact, state, &summary)?;
    let peak = state.p_plus.iter().fold(0.0f64, |a, &b| a.max(b));
    println!(
        "{}: steady state of a ring turning under body 1 ({} positions a turn), {} iterations, {:.4} s (set-up included); peak pressure {:.4} MPa, body 2 worn evenly by {:.4e} mm a turn ({:.4e} mm/m) → {}",
        p.file,
        steady.setup.contact.len(),
        state.iterations,
        steady.seconds,
        peak,
        steady.body2_depth_per_turn,
        steady.body2_depth_per_turn / (steady.turn * 1e-3),
        out.display()
    );
    for w in summary["warnings"].as_array().into_iter().flatten() {
        eprintln!("{}", w.as_str().unwrap_or_default());
    }
    Ok(())
}
