//! What mortar contact adds to the set-up of punch-b40: the condensation onto the contact
//! points (`CondensedContact::from_bodies`) with mortar and with collocation partners, the
//! bodies' assembly and factorisation (`CondensedContact::bodies`) for scale, and the check for
//! lines to add to the strip under the punch's element ends (`contact.align_target_mesh`; none
//! are needed on this matched mesh, so it costs one more mesh build of each body). Each figure is the
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
    let mut best = [f64::INFINITY; 5];
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
        time(3, &mut || {
            mortar.mesh_as_given(1).unwrap();
        });
        time(4, &mut || {
            mortar.mesh(1).unwrap();
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
    println!(
        "strip mesh as given {:.3} ms, with the alignment check {:.3} ms (+{:.1} % of the set-up)",
        best[3],
        best[4],
        100.0 * (best[4] - best[3]) / (bodies + coll)
    );
}
