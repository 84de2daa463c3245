//! Benchmarks of the speed targets of the issues, on the built-in example punch-b40
//! (reference model of Example 1, p = 8). Run with `cargo bench --bench pipeline`; the figures
//! and the machine are recorded in docs/performance.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use wearfem::complementarity::{ContactSolution, ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::driver;
use wearfem::kinematics::ScheduleEntry;
use wearfem::problem::Problem;

fn problem() -> Problem {
    Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap()
}

/// Assembly, static condensation and sparse Cholesky of punch and strip (target < 0.05 s).
fn elastic_setup(c: &mut Criterion) {
    let p = problem();
    c.bench_function("elastic_setup", |b| {
        b.iter(|| black_box(CondensedContact::bodies(&p).unwrap()))
    });
}

/// Flexibility (Green) matrices: 2N = 130 right-hand sides per body (target < 0.05 s).
fn flexibility(c: &mut Criterion) {
    let p = problem();
    let (b1, b2) = CondensedContact::bodies(&p).unwrap();
    c.bench_function("flexibility", |b| {
        b.iter(|| black_box(CondensedContact::from_bodies(&p, &b1, &b2).unwrap()))
    });
}

/// One contact solve, warm start with an unchanged active set (target < 10 µs) and cold start
/// from the all-active guess (target < 50 µs).
fn contact_solve(c: &mut Criterion) {
    let p = problem();
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let mut sol = ContactSolution::default();
    let base = contact.points.initial_gap.clone();
    solver.solve_into(&base, Direction::Plus, &mut sol);
    // Tiny shape changes (1 nm): the active set stays, only the right-hand side changes.
    let gaps: Vec<Vec<f64>> = (0..8)
        .map(|k| {
            base.iter()
                .enumerate()
                .map(|(i, g)| g + 1e-6 * ((i * (k + 1)) % 7) as f64)
                .collect()
        })
        .collect();
    let mut k = 0;
    c.bench_function("contact_solve_warm", |b| {
        b.iter(|| {
            k = (k + 1) % gaps.len();
            black_box(solver.solve_into(&gaps[k], Direction::Plus, &mut sol))
        })
    });
    c.bench_function("contact_solve_cold", |b| {
        // reset() only clears two cached active sets (no allocation), so timing it with the
        // solve overstates the cold solve by a few nanoseconds at most.
        b.iter(|| {
            solver.reset();
            black_box(solver.solve_into(&base, Direction::Plus, &mut sol))
        })
    });
}

/// The whole 1700-step run of punch-b40, FE set-up included (target < 0.1 s), and the same
/// 16 300 half periods without extrapolation (target < 0.5 s).
fn wear_runs(c: &mut Criterion) {
    let p = problem();
    let mut group = c.benchmark_group("wear");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    group.bench_function("run_1700_steps", |b| {
        b.iter(|| black_box(driver::wear(&p, None, |_| {}).unwrap()))
    });
    let mut plain = problem();
    let wear = plain.spec.wear.as_mut().unwrap();
    wear.extrapolation = Some(vec![ScheduleEntry { until: None, k: 1 }]);
    wear.steps = 16_300;
    group.bench_function("run_16300_half_periods_no_extrapolation", |b| {
        b.iter(|| black_box(driver::wear(&plain, None, |_| {}).unwrap()))
    });
    group.bench_function("steady_state_direct", |b| {
        b.iter(|| black_box(driver::steady(&p).unwrap()))
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = elastic_setup, flexibility, contact_solve, wear_runs
}
criterion_main!(benches);
