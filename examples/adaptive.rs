//! How many half periods, steps and contact solves each schedule needs to come within 0.5 %
//! of the peak pressure of the steady state (issue 9), for Example 1 (punch-b40) with E
//! elements under the punch (p = 8, strip lines matched).
//!
//! `cargo run --release --example adaptive [ELEMENTS…]` (default 8 16 32 64). Schedules:
//! - *process*: k = 1 throughout, one step per half period: the half-period scheme without
//!   extrapolation, the closest the integration gets to the process itself;
//! - *paper*: k = 1, 5, 10, continued with k = 10 beyond its 1700 steps until it gets there;
//! - *step doubling, first order*: `[wear.adaptive]` with `method = "step_doubling"` and
//!   `richardson = false`;
//! - *step doubling*: `method = "step_doubling"` (with Richardson extrapolation);
//! - *BDF2*: `[wear.adaptive]` as shipped (`method = "bdf2"`).
//!
//! Every step's pressure is compared with `wearfem steady` on the same mesh
//! ([`wearfem::wear::WearHistory::half_periods_to_reach`]). The adaptive runs are also
//! reported where they stop by themselves. `ADAPTIVE_EXTRA="max_factor = 32"` adds keys to
//! `[wear.adaptive]` of all three.

use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::wear::WearHistory;

const BOUND: f64 = 0.005;
const RECORD: &str = "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]";

/// `text` with `steps` steps, every one recorded, and `extra` after the record line.
fn every_step(text: &str, steps: usize, extra: &str) -> Problem {
    let list: Vec<String> = (1..=steps).map(|s| s.to_string()).collect();
    let edited = text
        .replace("steps = 1700 ", &format!("steps = {steps} "))
        .replace(RECORD, &format!("record = [{}]\n{extra}", list.join(", ")));
    Problem::from_toml(&edited, "adaptive example").unwrap()
}

/// "half periods (steps, solves)" where `history` first gets within the bound.
fn reach(history: &WearHistory, plus: &[f64], minus: &[f64], peak: f64) -> String {
    match history.half_periods_to_reach(plus, minus, peak, BOUND) {
        Some(hp) => {
            // The step whose cycle the crossing falls in (the half period is interpolated).
            let step = history
                .steps
                .iter()
                .find(|s| s.half_period as f64 >= hp)
                .unwrap();
            let solves: usize = history.steps[..step.step].iter().map(|s| s.solves).sum();
            format!("{hp:.0} ({}, {solves})", step.step)
        }
        None => "not reached".into(),
    }
}

fn main() {
    let elements: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("numbers of elements"))
        .collect();
    let elements = if elements.is_empty() {
        vec![8, 16, 32, 64]
    } else {
        elements
    };
    let extra = std::env::var("ADAPTIVE_EXTRA").unwrap_or_default();
    println!("Half periods (steps, contact solves) to 0.5 % of the steady peak pressure:\n");
    println!("| E | points | process (k = 1) | paper's schedule | step doubling, first order | step doubling | BDF2 | step doubling stops at, distance | BDF2 stops at, distance |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for e in elements {
        let text = wearfem::examples::refined_punch("punch-b40", e).expect("punch-b40 refines");
        let (state, contact, _) =
            driver::steady(&Problem::from_toml(&text, "steady").unwrap()).expect("steady state");
        // A state the Newton iteration did not finish is no reference.
        assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
        let (plus, minus) = (&state.p_plus, &state.p_minus);
        let peak = plus.iter().chain(minus).fold(0.0f64, |a, p| a.max(p.abs()));
        let run = |problem: Problem| driver::wear(&problem, None, |_| {}).unwrap().history;
        let process = run(every_step(&text, 20_000, "extrapolation = [{ k = 1 }]"));
        let paper = run(every_step(&text, 8000, ""));
        let adaptive = |keys: &str| {
            run(every_step(
                &text,
                4000,
                &format!("\n[wear.adaptive]\n{keys}\n{extra}"),
            ))
        };
        let first_order = adaptive("method = \"step_doubling\"\nrichardson = false");
        let doubling = adaptive("method = \"step_doubling\"");
        let bdf2 = adaptive("");
        // Where a run stops: "half periods (steps, solves), distance from the steady state".
        let stop = |history: &WearHistory| {
            let last = history.steps.last().unwrap();
            let distance = history
                .p_plus
                .iter()
                .zip(plus)
                .chain(history.p_minus.iter().zip(minus))
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
                / peak;
            format!(
                "{} ({}, {}), {:.2} %",
                last.half_period,
                last.step,
                history.solves,
                100.0 * distance
            )
        };
        println!(
            "| {e} | {} | {} | {} | {} | {} | {} | {} | {} |",
            contact.len(),
            reach(&process, plus, minus, peak),
            reach(&paper, plus, minus, peak),
            reach(&first_order, plus, minus, peak),
            reach(&doubling, plus, minus, peak),
            reach(&bdf2, plus, minus, peak),
            stop(&doubling),
            stop(&bdf2),
        );
    }
}
