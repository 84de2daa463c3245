//! Benchmarks of one contact solve of the built-in example punch-b40 (65 contact points,
//! 2 rigid plate unknowns) with the active-set method: `contact_solve_warm` (target < 10 µs)
//! and `contact_solve_cold` (target < 50 µs). Run with `cargo bench --bench contact`; figures
//! in docs/performance.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use wearfem::complementarity::{ContactSolution, ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// The built-in example punch-b40.
fn problem() -> Problem {
    Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap()
}

/// Number of distinct perturbed gaps the warm benchmark cycles through.
const GAPS: usize = 16;

/// The initial gap plus a tiny x-dependent perturbation, 1e-9 mm · k · (x − x̄)/half-width,
/// alternating in sign with k: small enough that the active set never changes, large enough
/// that every solve has a new right-hand side.
fn perturbed_gaps(contact: &CondensedContact) -> Vec<Vec<f64>> {
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
            (l.min(v), h.max(v))
        });
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    (1..=GAPS)
        .map(|k| {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            contact
                .points
                .initial_gap
                .iter()
                .zip(&x)
                .map(|(g, xi)| g + sign * 1e-9 * k as f64 * (1.0 + (xi - mid) / half))
                .collect()
        })
        .collect()
}

/// `contact_solve_warm` and `contact_solve_cold`.
///
/// Warm: `solve_into` after a first solve, with a slightly different gap each time so that
/// the active set stays (checked before timing: one active-set iteration, no factorisation).
/// Target: below 10 µs.
///
/// Cold: `reset()` then `solve_into`, i.e. from the all-active guess. Target: below 50 µs.
fn contact_solve(c: &mut Criterion) {
    let p = problem();
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let mut sol = ContactSolution::default();
    let base = contact.points.initial_gap.clone();
    let cold = solver.solve_into(&base, Direction::Plus, &mut sol);
    assert_eq!(cold.status, Status::Solved);
    let active = sol.active.clone();
    eprintln!(
        "cold solve: {} active-set iterations, {} factorisations, {} of {} points in contact",
        cold.iterations,
        cold.factorisations,
        active.iter().filter(|&&a| a).count(),
        active.len()
    );
    let gaps = perturbed_gaps(&contact);
    for g in &gaps {
        let info = solver.solve_into(g, Direction::Plus, &mut sol);
        assert_eq!(info.status, Status::Solved);
        assert_eq!(
            sol.active, active,
            "the perturbation changed the active set"
        );
        assert_eq!(
            (info.iterations, info.factorisations),
            (1, 0),
            "not a warm solve"
        );
    }
    eprintln!("warm solve: 1 active-set iteration, 0 factorisations (checked on every gap)");
    let mut k = 0;
    c.bench_function("contact_solve_warm", |b| {
        b.iter(|| {
            k = (k + 1) % GAPS;
            black_box(solver.solve_into(black_box(&gaps[k]), Direction::Plus, &mut sol))
        })
    });
    c.bench_function("contact_solve_cold", |b| {
        // reset() only clears the two cached active sets (no allocation, no deallocation).
        b.iter(|| {
            solver.reset();
            black_box(solver.solve_into(black_box(&base), Direction::Plus, &mut sol))
        })
    });
}

// Short measurements: the whole file runs in well under a minute.
criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(50)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = contact_solve
}
criterion_main!(benches);
