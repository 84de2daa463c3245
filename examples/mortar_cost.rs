//! What mortar contact adds to the set-up of punch-b40: the condensation onto the contact
//! points (`CondensedContact::from_bodies`) with mortar and with collocation partners, and the
//! bodies' assembly and factorisation (`CondensedContact::bodies`) for scale. Each figure is the
//! fastest of 40 interleaved runs, which filters out the load of a shared machine.
//!
//! `cargo run --release --example mortar_cost`; figures in docs/performance.md.

use std::time::Instant;
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

fn punch_b40(discretisation: &str) -> Problem {
    let text = wearfem::examples::example("punch-b40").unwrap().replace(
        "discretisation = \"collocation\"",
        &format!("discretisation = \"{discretisation}\""),
    );
    Problem::from_toml(&text, "punch-b40").unwrap()
}

fn main() {
    let (collocation, mortar) = (punch_b40("collocation"), punch_b40("mortar"));
    let (b1, b2) = CondensedContact::bodies(&mortar).unwrap();
    let mut best = [f64::INFINITY; 3];
    let mut time = |k: usize, f: &mut dyn FnMut()| {
        let start = Instant::now();
        f();
        best[k] = best[k].min(start.elapsed().as_secs_f64() * 1e3);
    };
    for _ in 0..40 {
        time(0, &mut || {
            CondensedContact::bodies(&mortar).unwrap();
        });
        time(1, &mut || {
            CondensedContact::from_bodies(&collocation, &b1, &b2).unwrap();
        });
        time(2, &mut || {
            CondensedContact::from_bodies(&mortar, &b1, &b2).unwrap();
        });
    }
    let (bodies, coll, mort) = (best[0], best[1], best[2]);
    println!("bodies (assembly, factorisation): {bodies:.2} ms");
    println!("condensation, collocation: {coll:.2} ms; mortar: {mort:.2} ms");
    println!(
        "set-up bodies + condensation: collocation {:.2} ms, mortar {:.2} ms (+{:.1} %)",
        bodies + coll,
        bodies + mort,
        100.0 * (mort - coll) / (bodies + coll)
    );
}
