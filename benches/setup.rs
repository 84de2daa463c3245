//! Benchmarks of the finite-element set-up of the built-in example punch-b40 (reference model
//! of Example 1, p = 8): `elastic_setup` (target < 0.05 s) and `flexibility` (target
//! < 0.05 s), and what a study pays per variant before solving it (`variant_build`). Run with
//! `cargo bench --bench setup`; figures in docs/performance.md.

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

/// `variant_build`: one variant of a study of punch-b40 read, validated and checked as
/// `wearfem sweep` and Python's `study()` do (`Problem::with_overrides` with friction and pin,
/// then `sweep::check_settings`); its meshes are those of the variants before (same
/// geometry). `variant_build_new_geometry`: the same with the punch's lowest block cut into
/// another number of rows each time, so that every variant builds its meshes.
fn variant_build(c: &mut Criterion) {
    use wearfem::overrides::{parse_value, Override};
    use wearfem::sweep::{check_settings, Job};
    let text = wearfem::examples::example("punch-b40").unwrap();
    let set = |key: &str, value: &str| Override::new(key, parse_value(value)).unwrap();
    let overrides = [
        set("contact.friction", "0.2"),
        set("plate.pin", "[1100.0, 120.0]"),
    ];
    let build = |overrides: &[Override]| {
        let p = Problem::with_overrides(text, "punch-b40", overrides).unwrap();
        check_settings(&p, Job::Steady).unwrap();
        p
    };
    c.bench_function("variant_build", |b| {
        b.iter(|| black_box(build(black_box(&overrides))))
    });
    let mut rows = 0;
    c.bench_function("variant_build_new_geometry", |b| {
        b.iter(|| {
            // Nine row counts, more than the four sets of meshes a process keeps.
            rows = rows % 9 + 1;
            let mut with_rows = overrides.to_vec();
            with_rows.push(set("bodies[0].blocks[0].v", &rows.to_string()));
            black_box(build(&with_rows))
        })
    });
}

// Small samples and short measurements: the whole file runs in well under a minute.
criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    targets = elastic_setup, flexibility, variant_build
}
criterion_main!(benches);
