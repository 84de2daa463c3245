//! The command line's fretting jobs (a problem with a `[fretting]` section): `contact`, `run`
//! and `steady`, each a library job, its files and one console line.

use super::*;

/// Options of the full-slip jobs that a fretting problem has no use for are refused.
fn refuse_vtk(p: &Problem, vtk: bool) -> Result<(), Failure> {
    if vtk {
        return Err(Failure::Input(format!("{}: ParaView files of fretting are not written yet; run without --vtk (and without output.vtk)", p.file)));
    }
    Ok(())
}

/// `wearfem contact` on a fretting problem: the normal load, then one periodic cycle.
pub(crate) fn contact(p: &Problem, out: &Path, vtk: bool) -> Result<(), Failure> {
    refuse_vtk(p, vtk)?;
    let result = wearfem::jobs::fretting::contact(p)?;
    wearfem::report::fretting::write_contact(out, p, &result)?;
    print_warnings(p, &result.setup, &result.cycle);
    let x = result.setup.x();
    let stick = match result.cycle.stick_extent(&x) {
        Some((a, b)) => format!("stick zone {a:.4} … {b:.4} mm"),
        None if result.cycle.gross_slip => {
            "gross slip (every point in contact slips at some instant of the cycle)".into()
        }
        // The summary's gross_slip is false: some point sticks at every instant, but the
        // stick zone moves (a rocking plate), so none sticks through the whole cycle.
        None => "partial slip with a moving stick zone (no point sticks through the whole cycle, but at every instant some point sticks)".into(),
    };
    println!(
        "{}: {} contact points, peak pressure {:.4} MPa, friction limit μP = {:.4e} N; fretting cycle: peak force {:.4e} N at shift {:.4e} mm, {stick}, {:.4e} N·mm dissipated per cycle → {}",
        p.file,
        x.len(),
        result.normal.pressure.iter().fold(0.0f64, |m, v| m.max(*v)),
        result.limit,
        result.cycle.states[0].load,
        result.cycle.states[0].shift,
        result.cycle.dissipated,
        out.display()
    );
    Ok(())
}

/// `wearfem run` on a fretting problem: wear by the local slip over `wear.cycles` cycles.
pub(crate) fn run(p: &Problem, out: &Path, steps: Option<usize>, vtk: bool) -> Result<(), Failure> {
    refuse_vtk(p, vtk)?;
    if steps.is_some() {
        return Err(Failure::Input(format!("{}: --steps does not apply to fretting, whose steps jump over cycles under error control; give the duration as --set wear.cycles=N", p.file)));
    }
    let run = wearfem::jobs::fretting::run(p, None, |_| {})?;
    wearfem::report::fretting::write_run(out, p, &run)?;
    print_warnings(p, &run.setup, &run.history.first_cycle);
    let h = &run.history;
    let last = h.steps.last();
    let ended = match h.wear_stopped {
        Some(c) => format!("wear stopped after {c:.4e} cycles (no point that carries pressure slips: the final state)"),
        None => format!("{:.4e} cycles", last.map_or(0.0, |s| s.cycles)),
    };
    println!(
        "{}: fretting, {} steps, {ended}; deepest wear {:.4e} mm of body 1 and {:.4e} mm of body 2; set-up {:.2} s, run {:.2} s → {}",
        p.file,
        h.steps.len(),
        last.map_or(0.0, |s| s.deepest_wear[0]),
        last.map_or(0.0, |s| s.deepest_wear[1]),
        run.setup.seconds,
        run.seconds,
        out.display()
    );
    if let Some((step, reason)) = &h.stopped {
        return Err(Failure::Compute(format!("step {step}: {reason}; the run stopped there, and the {} steps before it were written to {} (nothing from step {step})", step - 1, out.display())));
    }
    Ok(())
}

/// `wearfem steady` on a fretting problem: the final state of partial slip, or the periodic
/// steady state of gross slip.
pub(crate) fn steady(p: &Problem, out: &Path, vtk: bool) -> Result<(), Failure> {
    refuse_vtk(p, vtk)?;
    let result = wearfem::jobs::fretting::steady(p)?;
    wearfem::report::fretting::write_steady(out, p, &result)?;
    print_warnings(p, &result.setup, &result.state.first_cycle);
    let s = &result.state;
    let x = result.setup.x();
    let touching: Vec<f64> = (0..x.len())
        .filter(|&i| s.pressure[i] > 0.0)
        .map(|i| x[i])
        .collect();
    println!(
        "{}: {}: contact {:.4} … {:.4} mm, peak pressure {:.4} MPa, deepest wear {:.4e} mm, {} iterations, {:.3} s → {}",
        p.file,
        if s.gross_slip {
            "the periodic steady state of gross slip"
        } else {
            "the final state of partial slip"
        },
        touching.first().copied().unwrap_or(f64::NAN),
        touching.last().copied().unwrap_or(f64::NAN),
        s.pressure.iter().fold(0.0f64, |m, v| m.max(*v)),
        s.shape.iter().fold(0.0f64, |m, v| m.max(*v)),
        s.iterations,
        result.seconds,
        out.display()
    );
    Ok(())
}

/// The fretting cycle's warnings on stderr, one line each, as the other jobs print theirs.
fn print_warnings(
    p: &Problem,
    setup: &wearfem::jobs::fretting::FrettingSetup,
    cycle: &wearfem::solver::fretting::FrettingCycle,
) {
    for line in wearfem::jobs::fretting::cycle_warnings(p, setup, cycle) {
        eprintln!("{line}");
    }
}
