//! The built-in `ball-on-flat` (a steel ball of R = 5 mm on a steel flat, 10 N, bodies of
//! revolution) under p-refinement and under refinement of the elements at the axis: the table
//! of docs/convergence.md ("A ball on a flat: refinement near the axis").
//!
//! `cargo run --release --example axisymmetric_refinement`: for p = 4 … 10 on the shipped
//! mesh, and for the contact region's elements (10 µm in the example) at 20, 10 and 5 µm at
//! p = 6, the pressure on the axis against Hertz's p₀ and the largest departure from
//! p₀√(1 − r²/a²) inside 0.9a, both relative to p₀; with the time of one contact solve, set-up
//! included.

use std::f64::consts::PI;
use std::time::Instant;
use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

/// The example with the contact region meshed in elements of `h` mm up to 0.08 mm (both
/// bodies) and degree `p`.
fn ball(h: f64, p: usize) -> Problem {
    let text = wearfem::examples::example("ball-on-flat").expect("built in");
    let fine: Vec<f64> = (0..)
        .map(|k| k as f64 * h)
        .take_while(|r| *r < 0.08 - 1e-9)
        .collect();
    let lines = |outer: &[f64], length: f64| {
        let all: Vec<String> = fine
            .iter()
            .chain(outer)
            .map(|r| format!("{:.10}", r / length))
            .collect();
        format!("u = [{}]", all.join(", "))
    };
    let mut out = String::new();
    let mut seen = 0;
    for line in text.lines() {
        if line.starts_with("u = ") {
            // The ball's line first, then the flat's.
            out += &if seen == 0 {
                lines(&[0.08, 0.1, 0.15, 0.3, 0.6, 1.0, 2.0], 2.0)
            } else {
                lines(&[0.08, 0.1, 0.15, 0.3, 0.6, 1.2, 2.4, 4.0], 4.0)
            };
            seen += 1;
        } else {
            out += line;
        }
        out.push('\n');
    }
    let out = out.replace("p = 8\n", &format!("p = {p}\n"));
    Problem::from_toml(&out, "ball-on-flat").expect("a valid problem")
}

fn main() {
    let modulus = 2.0e5 / (2.0 * (1.0 - 0.09));
    let (force, radius): (f64, f64) = (10.0, 5.0);
    let a = (3.0 * force * radius / (4.0 * modulus)).cbrt();
    let p0 = 3.0 * force / (2.0 * PI * a * a);
    println!("| elements at the axis | p | contact points | p(0)/p₀ − 1 | largest departure inside 0.9a / p₀ | one contact solve, set-up included |");
    println!("|---|---|---|---|---|---|");
    let cases: Vec<(f64, usize)> = [4, 6, 8, 10]
        .iter()
        .map(|&p| (0.01, p))
        .chain([0.02, 0.005].iter().map(|&h| (h, 6)))
        .collect();
    for (h, p) in cases {
        let problem = ball(h, p);
        let start = Instant::now();
        let (contact, _, _) = CondensedContact::build(&problem).expect("contact");
        let (solution, _) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        let seconds = start.elapsed().as_secs_f64();
        let r: Vec<f64> = contact.points.x.iter().map(|x| x[0]).collect();
        let departure = (r.iter().zip(&solution.pressure))
            .filter(|(ri, _)| **ri < 0.9 * a)
            .map(|(ri, pi)| (pi - p0 * (1.0 - ri * ri / (a * a)).sqrt()).abs())
            .fold(0.0f64, f64::max);
        println!(
            "| {:.0} µm | {p} | {} | {:+.2e} | {:.2e} | {:.3} s |",
            h * 1e3,
            r.len(),
            solution.pressure[0] / p0 - 1.0,
            departure / p0,
            seconds
        );
    }
}
