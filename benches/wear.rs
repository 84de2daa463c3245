//! Benchmarks of whole wear runs of the built-in example punch-b40, FE set-up included:
//! `wear_run_1700` (the example's 1700 steps, target < 0.1 s) and `wear_run_no_extrapolation`
//! (16 300 steps with k = 1, target < 0.5 s), plus `steady_state_direct` for comparison (no
//! target). Run with `cargo bench --bench wear`; figures in docs/performance.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use wearfem::driver;
use wearfem::kinematics::ScheduleEntry;
use wearfem::problem::Problem;

/// The built-in example punch-b40.
fn problem() -> Problem {
    Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap()
}

/// punch-b40 without extrapolation: k = 1 throughout, 16 300 steps (the same 16 300 half
/// periods as the example's 1700 extrapolated steps).
fn problem_no_extrapolation() -> Problem {
    let mut p = problem();
    let wear = p.spec.wear.as_mut().unwrap();
    wear.extrapolation = Some(vec![ScheduleEntry { until: None, k: 1 }]);
    wear.steps = 16_300;
    p
}

/// Print what one run does: steps, half periods, contact solves and implicit iterations per
/// step, and the driver's own split into set-up and integration time.
fn report(name: &str, p: &Problem) {
    let run = driver::wear(p, None, |_| {}).unwrap();
    let h = &run.history;
    let steps = h.steps.len();
    let iterations: usize = h.steps.iter().map(|s| s.iterations).sum();
    let max_iterations = h.steps.iter().map(|s| s.iterations).max().unwrap_or(0);
    eprintln!(
        "{name}: {steps} steps, {} half periods, {} contact solves ({:.3} per step), \
         {:.3} wear iterations per step (max {max_iterations}), {} unconverged steps, \
         {} failed solves; set-up {:.4} s, integration {:.4} s ({:.2} µs per solve)",
        h.steps.last().map_or(0, |s| s.half_period),
        h.solves,
        h.solves as f64 / steps as f64,
        iterations as f64 / steps as f64,
        h.unconverged_steps,
        h.failed_solves,
        run.setup_seconds,
        run.run_seconds,
        1e6 * run.run_seconds / h.solves as f64,
    );
}

/// `wear_run_1700`: `driver::wear` on punch-b40 as shipped (1700 steps, the paper's
/// extrapolation schedule, 16 300 half periods), FE set-up and condensation included, no
/// output. Target: below 0.1 s.
fn wear_run_1700(c: &mut Criterion) {
    let p = problem();
    report("wear_run_1700", &p);
    c.bench_function("wear_run_1700", |b| {
        b.iter(|| black_box(driver::wear(black_box(&p), None, |_| {}).unwrap()))
    });
}

/// `wear_run_no_extrapolation`: `driver::wear` on punch-b40 with k = 1 throughout and
/// 16 300 steps, FE set-up included. Target: below 0.5 s.
fn wear_run_no_extrapolation(c: &mut Criterion) {
    let p = problem_no_extrapolation();
    report("wear_run_no_extrapolation", &p);
    c.bench_function("wear_run_no_extrapolation", |b| {
        b.iter(|| black_box(driver::wear(black_box(&p), None, |_| {}).unwrap()))
    });
}

/// `steady_state_direct`: `driver::steady` on punch-b40, the periodic steady state computed
/// directly (FE set-up included). No target; for comparison with the time integration.
fn steady_state_direct(c: &mut Criterion) {
    let p = problem();
    c.bench_function("steady_state_direct", |b| {
        b.iter(|| black_box(driver::steady(black_box(&p)).unwrap()))
    });
}

// Ten samples each: criterion's linear sampling needs 55 iterations at least, about 11 s for
// the slowest benchmark.
criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    targets = wear_run_1700, wear_run_no_extrapolation, steady_state_direct
}
criterion_main!(benches);
