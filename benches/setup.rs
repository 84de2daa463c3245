//! Benchmarks of the finite-element set-up of the built-in example punch-b40 (reference model
//! of Example 1, p = 8): `elastic_setup` (target < 0.05 s) and `flexibility` (target
//! < 0.05 s). Run with `cargo bench --bench setup`; figures in docs/performance.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// The built-in example punch-b40 (collocation contact, as its file says).
fn problem() -> Problem {
    Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap()
}

/// punch-b40 with `contact.discretisation = "mortar"`, for the mortar set-up's cost.
fn mortar_problem() -> Problem {
    let text = wearfem::examples::example("punch-b40").unwrap().replace(
        "discretisation = \"collocation\"",
        "discretisation = \"mortar\"",
    );
    Problem::from_toml(&text, "punch-b40").unwrap()
}

/// `elastic_setup`: mesh, element matrices, static condensation of the internal modes,
/// assembly and sparse Cholesky of punch and strip, i.e. `CondensedContact::bodies`
/// (about 14 000 unknowns before condensation). Target: below 0.05 s.
fn elastic_setup(c: &mut Criterion) {
    let p = problem();
    let (b1, b2) = CondensedContact::bodies(&p).unwrap();
    let mut total = 0;
    for b in [&b1, &b2] {
        let i = &b.info;
        total += i.total_dofs;
        eprintln!(
            "body {}: {} elements, total_dofs {}, condensed_dofs {}, distinct_elements {}, nonzeros {}",
            b.name,
            b.mesh.elements.len(),
            i.total_dofs,
            i.condensed_dofs,
            i.distinct_elements,
            i.nonzeros
        );
    }
    eprintln!("total_dofs of both bodies: {total}");
    c.bench_function("elastic_setup", |b| {
        b.iter(|| black_box(CondensedContact::bodies(black_box(&p)).unwrap()))
    });
}

/// `flexibility`: the condensed contact problem from two factorised bodies (built once,
/// outside the timed loop), i.e. `CondensedContact::from_bodies`: 2N = 130 right-hand sides
/// per body through the kept factorisations, traces and the N × N matrices A_nn, A_nt.
/// Target: below 0.05 s. `flexibility_mortar` is the same with mortar traces.
fn flexibility(c: &mut Criterion) {
    let p = problem();
    let (b1, b2) = CondensedContact::bodies(&p).unwrap();
    let contact = CondensedContact::from_bodies(&p, &b1, &b2).unwrap();
    eprintln!(
        "contact points N = {}, right-hand sides per body 2N = {}, rigid unknowns {}",
        contact.len(),
        2 * contact.len(),
        contact.rigid_modes.len()
    );
    c.bench_function("flexibility", |b| {
        b.iter(|| black_box(CondensedContact::from_bodies(black_box(&p), &b1, &b2).unwrap()))
    });
    let p = mortar_problem();
    c.bench_function("flexibility_mortar", |b| {
        b.iter(|| black_box(CondensedContact::from_bodies(black_box(&p), &b1, &b2).unwrap()))
    });
}

// Small samples and short measurements: the whole file runs in well under a minute.
criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    targets = elastic_setup, flexibility
}
criterion_main!(benches);
