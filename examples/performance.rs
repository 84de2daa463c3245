//! Sizes and a phase-by-phase timing of one run of punch-b40, for docs/performance.md:
//! `cargo run --release --example performance`. (The statistically sound figures come from
//! `cargo bench` (benches/setup.rs, contact.rs, wear.rs); this prints what the benchmarks cannot: problem sizes, solves
//! and iterations per step.)

// The allocator of the `wearfem` binary (src/cli/main.rs), so that the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::time::Instant;
use wearfem::complementarity::{ContactSolver, Method};
use wearfem::contact::CondensedContact;
use wearfem::driver;
use wearfem::problem::Problem;

fn main() {
    // An optional problem file, or `NAME@E` for a built-in punch example with E elements under
    // the punch (the cost-growth table); punch-b40 by default.
    let p = match std::env::args().nth(1) {
        Some(spec) if spec.contains('@') => {
            let (name, elements) = spec.split_once('@').unwrap();
            let mut text = wearfem::examples::refined_punch(name, elements.parse().unwrap())
                .expect("a punch example and a positive number of elements");
            // WEARFEM_ADAPTIVE=1: the adaptive schedule instead of the paper's; any other value
            // is added to `[wear.adaptive]` (e.g. WEARFEM_ADAPTIVE='method = "step_doubling"').
            if let Ok(keys) = std::env::var("WEARFEM_ADAPTIVE") {
                let keys = if keys == "1" { String::new() } else { keys };
                text = text.replace("steps = 1700 ", "steps = 100000 ").replace(
                    "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
                    &format!("record = []\n\n[wear.adaptive]\n{keys}"),
                );
            }
            Problem::from_toml(&text, &spec).unwrap()
        }
        Some(path) => Problem::from_toml(&std::fs::read_to_string(&path).unwrap(), &path).unwrap(),
        None => Problem::from_toml(
            wearfem::examples::example("punch-b40").unwrap(),
            "punch-b40",
        )
        .unwrap(),
    };
    let t = Instant::now();
    let (b1, b2) = CondensedContact::bodies(&p).unwrap();
    let bodies = t.elapsed().as_secs_f64();
    for b in [&b1, &b2] {
        let i = &b.info;
        println!("body {:6}: {} elements, {} unknowns before condensation, {} condensed, {} distinct element matrices, {} non-zeros", b.name, b.mesh.elements.len(), i.total_dofs, i.condensed_dofs, i.distinct_elements, i.nonzeros);
    }
    println!(
        "total unknowns before condensation: {}",
        b1.info.total_dofs + b2.info.total_dofs
    );
    let t = Instant::now();
    let contact = CondensedContact::from_bodies(&p, &b1, &b2).unwrap();
    let flexibility = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let _solver = ContactSolver::new(&contact, Method::ActiveSet);
    let solver_setup = t.elapsed().as_secs_f64();
    println!(
        "contact points: {}, rigid unknowns: {}",
        contact.len(),
        contact.rigid_modes.len()
    );
    println!("phase times (one run, s): bodies {bodies:.4}, flexibility {flexibility:.4}, solver set-up {solver_setup:.5}");
    let run = driver::wear(&p, None, |_| {}).unwrap();
    let h = &run.history;
    let steps = h.steps.len() as f64;
    let iterations: usize = h.steps.iter().map(|s| s.iterations).sum();
    println!("wear run: {} steps, {} half periods, {} contact solves ({:.2} per step), {:.2} implicit iterations per step", h.steps.len(), h.steps.last().unwrap().half_period, h.solves, h.solves as f64 / steps, iterations as f64 / steps);
    println!("wear run: set-up {:.4} s, integration {:.4} s, {:.2} µs per contact solve including the wear update", run.setup_seconds, run.run_seconds, 1e6 * run.run_seconds / h.solves as f64);
    let t = Instant::now();
    match driver::steady(&p) {
        Ok((state, _, seconds)) => println!(
            "steady: {} Newton iterations, {:?}, {seconds:.4} s with set-up (wall clock here: {:.4} s)",
            state.iterations,
            state.status,
            t.elapsed().as_secs_f64()
        ),
        Err(e) => println!("steady: {e}"),
    }
}
