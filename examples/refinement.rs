//! Example 1 (punch-b40) under mesh refinement and p-refinement: the tables of
//! docs/convergence.md ("Refining the contact") and the cost-growth table of
//! docs/performance.md.
//!
//! `cargo run --release --example refinement [ELEMENTS…]` (default 8 16 32 64): for each number
//! of elements under the punch (p = 8, strip lines matched) and for p = 4 … 12 on the shipped
//! mesh, the default 1700-step run, the adaptive run and the steady state on the same mesh,
//! compared point by point. Times are wall clock of one run (see docs/performance.md for the
//! machine); memory is the process's peak resident set so far (it only grows).

// The allocator of the `wearfem` binary (src/cli/main.rs), so that the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::time::Instant;
use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::wear::non_rigid_part;

fn peak_memory_mb() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

/// Largest |a − b| over the points, relative to `peak`.
fn worst(a: &[f64], b: &[f64], peak: f64) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / peak
}

fn study(label: &str, text: &str) {
    let problem = Problem::from_toml(text, label).unwrap();
    let t = Instant::now();
    let run = driver::wear(&problem, None, |_| {}).unwrap();
    let run_total = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let (state, contact, _) = driver::steady(&problem).unwrap();
    // A state the Newton iteration did not finish is no reference.
    assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
    let steady_total = t.elapsed().as_secs_f64();
    // ADAPTIVE_EXTRA adds keys to `[wear.adaptive]` (e.g. `method = "step_doubling"`).
    let extra = std::env::var("ADAPTIVE_EXTRA").unwrap_or_default();
    let adaptive_text = text.replace("steps = 1700 ", "steps = 100000 ").replace(
        "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
        &format!("record = []\n\n[wear.adaptive]\n{extra}"),
    );
    let adaptive_problem = Problem::from_toml(&adaptive_text, label).unwrap();
    let t = Instant::now();
    let adaptive = driver::wear(&adaptive_problem, None, |_| {}).unwrap();
    let adaptive_total = t.elapsed().as_secs_f64();
    let h = &run.history;
    let n = h.p_plus.len();
    let m_index = run.probes.iter().find(|(p, _)| p == "M").unwrap().1;
    let peak = state
        .p_plus
        .iter()
        .chain(&state.p_minus)
        .fold(0.0f64, |a, p| a.max(*p));
    let first_m = h.steps[0].probes[0];
    let last_plus = h.steps.iter().rev().find(|s| s.direction == "+").unwrap();
    let in_contact: Vec<bool> = (0..n)
        .map(|i| state.p_plus[i] > 0.0 || state.p_minus[i] > 0.0)
        .collect();
    let r = contact.rigid_gap_matrix();
    let m = contact.rigid_modes.len();
    let w = &contact.points.weight;
    let reference = non_rigid_part(&state.shape, &in_contact, &r, m, w);
    let range = reference.iter().cloned().fold(f64::MIN, f64::max)
        - reference.iter().cloned().fold(f64::MAX, f64::min);
    let shape_error = |shape: &[f64]| {
        let d: Vec<f64> = (0..n)
            .map(|i| shape[i] - contact.points.initial_gap[i] - state.shape[i])
            .collect();
        non_rigid_part(&d, &in_contact, &r, m, w)
            .iter()
            .fold(0.0f64, |a, x| a.max(x.abs()))
            / range
    };
    let a = &adaptive.history;
    // Both runs end by comparing their last cycle with the steady state (a Newton solve).
    let check = |r: &driver::WearRun| match r.steady_check {
        wearfem::steady_check::SteadyCheck::Compared { seconds, .. } => seconds,
        _ => 0.0,
    };
    println!(
        "| {label} | {n} | {first_m:.2} | {:.4} | {:.4} | {:.2} % | {:.2} % | {:.2} % | {} / {} | {:.2} % | {:.2} % | {:.3} | {:.3} ({:.3}) | {:.3} ({:.3}) | {:.3} | {:.0} |",
        last_plus.probes[0],
        state.p_plus[m_index],
        100.0 * worst(&h.p_plus, &state.p_plus, peak),
        100.0 * worst(&h.p_minus, &state.p_minus, peak),
        100.0 * shape_error(&h.shape),
        a.steps.len(),
        a.steps.last().unwrap().half_period,
        100.0 * worst(&a.p_plus, &state.p_plus, peak).max(worst(&a.p_minus, &state.p_minus, peak)),
        100.0 * shape_error(&a.shape),
        run.setup_seconds,
        run_total,
        check(&run),
        adaptive_total,
        check(&adaptive),
        steady_total,
        peak_memory_mb(),
    );
}

fn main() {
    let elements: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let elements = if elements.is_empty() {
        vec![8, 16, 32, 64]
    } else {
        elements
    };
    println!("| case | points | p(M) n = 1 (MPa) | p(M) n = 1700 | steady p⁺(M) | run p⁺ − steady (of peak) | run p⁻ − steady | run shape − steady (of range) | adaptive steps / half periods | adaptive p − steady | adaptive shape − steady | set-up (s) | 1700 steps incl. set-up (of which the steady check) (s) | adaptive incl. set-up (of which the steady check) (s) | steady incl. set-up (s) | peak memory so far (MB) |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &e in &elements {
        let text = wearfem::examples::refined_punch("punch-b40", e).unwrap();
        study(&format!("{e} el., p = 8"), &text);
    }
    if std::env::args().len() <= 1 {
        for p in [4, 6, 10, 12] {
            let text = wearfem::examples::example("punch-b40")
                .unwrap()
                .replace("p = 8", &format!("p = {p}"));
            study(&format!("8 el., p = {p}"), &text);
        }
    }
}
