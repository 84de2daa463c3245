//! The adaptive schedule's methods on variants of Example 1: wear exponents b ≠ 1, wear of
//! both bodies, fine meshes (stiff modes). For each: contact solves, failed solves,
//! unconverged steps, where the run stops and how far from the directly computed steady
//! state (largest pointwise pressure difference relative to the steady peak).
//!
//! `cargo run --release --example adaptive_variants [ELEMENTS…]` (default 32 64).

use std::time::Instant;
use wearfem::driver;
use wearfem::problem::Problem;

fn main() {
    let elements: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("numbers of elements"))
        .collect();
    let elements = if elements.is_empty() {
        vec![32, 64]
    } else {
        elements
    };
    let variants: [(&str, &str, &str, &str); 5] = [
        ("b = 1", "punch-b40", "", ""),
        ("b = 0.8", "punch-b40-b0.8", "", ""),
        ("b = 1.2", "punch-b40-b1.2", "", ""),
        (
            "b = 2",
            "punch-b40",
            "a = 1.0, b = 1.0 }   # 1.25π·10⁻⁸",
            "a = 1.0, b = 2.0 }",
        ),
        (
            "both bodies wear",
            "punch-b40",
            "sliding = \"reciprocating\"",
            "body2 = { beta = 2e-8, a = 1.0, b = 1.0 }\nsliding = \"reciprocating\"",
        ),
    ];
    println!("| E | case | method | steps | solves | failed | unconverged | stops at (half periods) | distance | run, s |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for &e in &elements {
        for (label, name, from, to) in variants {
            let text = wearfem::examples::refined_punch(name, e).expect("refines");
            let text = if from.is_empty() {
                text
            } else {
                assert!(text.contains(from), "{label}: {from}");
                text.replace(from, to)
            };
            let base = Problem::from_toml(&text, label).unwrap();
            let (state, _, _) = driver::steady(&base).expect("steady");
            let peak = state
                .p_plus
                .iter()
                .chain(&state.p_minus)
                .fold(0.0f64, |a, p| a.max(*p));
            for method in ["bdf2", "step_doubling"] {
                let adaptive = text
                    .replace("steps = 1700 ", "steps = 100000 ")
                    .replace("steps = 2500 ", "steps = 100000 ");
                let start = adaptive.find("record = [").unwrap();
                let end = start + adaptive[start..].find(']').unwrap() + 1;
                let adaptive = format!(
                    "{}record = []\n\n[wear.adaptive]\nmethod = \"{method}\"{}",
                    &adaptive[..start],
                    &adaptive[end..]
                );
                let problem = Problem::from_toml(&adaptive, label).unwrap();
                let t = Instant::now();
                let h = driver::wear(&problem, None, |_| {}).unwrap().history;
                let time = t.elapsed().as_secs_f64();
                let distance = h
                    .p_plus
                    .iter()
                    .zip(&state.p_plus)
                    .chain(h.p_minus.iter().zip(&state.p_minus))
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max)
                    / peak;
                let last = h.steps.last().unwrap();
                println!(
                    "| {e} | {label} | {method} | {} | {} | {} | {} | {} ({:?}) | {:.2} % ({:?}) | {time:.3} |",
                    h.steps.len(),
                    h.solves,
                    h.failed_solves,
                    h.unconverged_steps,
                    last.half_period,
                    h.stopped.as_ref().map(|s| s.1.to_string()),
                    100.0 * distance,
                    state.status,
                );
            }
        }
    }
}
