//! How many half periods the paper's schedule and the adaptive one need to come within 0.5 %
//! of the peak pressure of the steady state (issue 9), for Example 1 (punch-b40) with E
//! elements under the punch (p = 8, strip lines matched).
//!
//! `cargo run --release --example adaptive [ELEMENTS…]` (default 8 16 32 64). The paper's
//! schedule (k = 1, 5, 10) is continued with k = 10 beyond its 1700 steps until it gets
//! there; every step's pressure is compared with `wearfem steady` on the same mesh. A run
//! "gets there" at the first '−' step after which both the last '+' and the last '−'
//! pressures are within the bound at every contact point. The adaptive run is reported both
//! where it first gets there and where it stops by itself.

use wearfem::driver;
use wearfem::problem::Problem;

const BOUND: f64 = 0.005;

/// Half periods at which `snapshots` (every step) first come within BOUND of the steady
/// pressures, or None.
fn first_within(
    run: &wearfem::wear::WearHistory,
    plus: &[f64],
    minus: &[f64],
    peak: f64,
) -> Option<usize> {
    let worst = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
            / peak
    };
    let mut last_plus: Option<f64> = None;
    for s in &run.snapshots {
        if s.direction == "+" {
            last_plus = Some(worst(&s.pressure, plus));
        } else if let Some(p) = last_plus {
            if p.max(worst(&s.pressure, minus)) <= BOUND {
                return Some(s.half_period);
            }
        }
    }
    None
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
    println!("| E | points | paper's schedule: half periods to 0.5 % (steps) | adaptive: half periods to 0.5 % (steps) | adaptive stops at: half periods (steps), distance |");
    println!("|---|---|---|---|---|");
    for e in elements {
        let text = wearfem::examples::refined_punch("punch-b40", e).expect("punch-b40 refines");
        let steady_problem = Problem::from_toml(&text, "steady").unwrap();
        let (state, contact, _) = driver::steady(&steady_problem).unwrap();
        // A state the Newton iteration did not finish is no reference.
        assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
        let peak = state
            .p_plus
            .iter()
            .chain(&state.p_minus)
            .fold(0.0f64, |a, p| a.max(p.abs()));
        let all = |steps: usize| {
            let list: Vec<String> = (1..=steps).map(|s| s.to_string()).collect();
            format!("record = [{}]", list.join(", "))
        };
        let record = "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]";
        let paper = text
            .replace("steps = 1700 ", "steps = 8000 ")
            .replace(record, &all(8000));
        let run =
            driver::wear(&Problem::from_toml(&paper, "paper").unwrap(), None, |_| {}).unwrap();
        let paper_reach = first_within(&run.history, &state.p_plus, &state.p_minus, peak);
        let adaptive = text
            .replace("steps = 1700 ", "steps = 4000 ")
            .replace(record, &format!("{}\n\n[wear.adaptive]", all(4000)));
        let run = driver::wear(
            &Problem::from_toml(&adaptive, "adaptive").unwrap(),
            None,
            |_| {},
        )
        .unwrap();
        let h = &run.history;
        let adaptive_reach = first_within(h, &state.p_plus, &state.p_minus, peak);
        let last = h.steps.last().unwrap();
        let distance = h
            .p_plus
            .iter()
            .zip(&state.p_plus)
            .chain(h.p_minus.iter().zip(&state.p_minus))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / peak;
        let step_of = |hp: Option<usize>, history: Option<&wearfem::wear::WearHistory>| match hp {
            Some(hp) => match history.and_then(|h| h.steps.iter().find(|s| s.half_period == hp)) {
                Some(s) => format!("{hp} ({})", s.step),
                None => format!("{hp}"),
            },
            None => "not within 8000 steps".into(),
        };
        println!(
            "| {e} | {} | {} | {} | {} ({}), {:.2} % |",
            contact.len(),
            step_of(paper_reach, None),
            step_of(adaptive_reach, Some(h)),
            last.half_period,
            last.step,
            100.0 * distance
        );
    }
}
