//! Benchmarks of the heat stage on the built-in example punch-b40-heat, FE set-up and the
//! heat problem's reduction included: `heat_run_1700` (`driver::wear`, the example's 1700
//! steps) and `heat_steady` (`driver::steady_with_heat`). The targets are 3 × the
//! same jobs without heat (benches/wear.rs). Run with `cargo bench --bench heat`; figures in
//! docs/performance.md (Heat).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use wearfem::driver;
use wearfem::problem::Problem;

fn problem() -> Problem {
    Problem::from_toml(
        wearfem::examples::example("punch-b40-heat").unwrap(),
        "punch-b40-heat",
    )
    .unwrap()
}

/// Print the heat problem's size and the driver's split into set-up and integration.
fn report(p: &Problem) {
    let run = driver::wear(p, None, |_| {}).unwrap();
    let info = run.heat.as_ref().unwrap();
    eprintln!(
        "heat_run_1700: {} unknowns, {} modes, heat set-up {:.3} s; set-up {:.3} s, integration {:.3} s ({:.1} µs per step)",
        info.unknowns,
        info.modes,
        info.seconds,
        run.setup_seconds,
        run.run_seconds,
        1e6 * run.run_seconds / run.history.steps.len() as f64
    );
}

fn heat_run_1700(c: &mut Criterion) {
    let p = problem();
    report(&p);
    c.bench_function("heat_run_1700", |b| {
        b.iter(|| black_box(driver::wear(black_box(&p), None, |_| {}).unwrap()))
    });
}

fn heat_steady(c: &mut Criterion) {
    let p = problem();
    c.bench_function("heat_steady", |b| {
        b.iter(|| black_box(driver::steady_with_heat(black_box(&p)).unwrap()))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(8));
    targets = heat_run_1700, heat_steady
}
criterion_main!(benches);
