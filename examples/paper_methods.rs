//! The four steady-state methods (exact, and the paper's §6: averaged, spline, penalty) on
//! punch-a and punch-b40, for the tables of docs/validation.md and docs/performance.md:
//! `cargo run --release --example paper_methods [REPEATS]`. Each method is run REPEATS times
//! (default 20) on one condensed contact problem; the median time is printed.

use wearfem::contact::CondensedContact;
use wearfem::paper_steady::{
    solve_steady, MethodOutcome, MethodSettings, Sensitivities, SteadyMethod,
};
use wearfem::problem::Problem;
use wearfem::wear::WearIntegrator;

fn difference(a: &MethodOutcome, exact: &MethodOutcome) -> (f64, f64) {
    let e = &exact.state;
    let peak = e
        .p_plus
        .iter()
        .chain(&e.p_minus)
        .cloned()
        .fold(0.0, f64::max);
    let dp = (0..e.p_plus.len())
        .map(|i| {
            (a.state.p_plus[i] - e.p_plus[i])
                .abs()
                .max((a.state.p_minus[i] - e.p_minus[i]).abs())
        })
        .fold(0.0, f64::max);
    let lo = e.shape.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = e.shape.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let ds = a
        .state
        .shape
        .iter()
        .zip(&e.shape)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    (dp / peak, ds / (hi - lo))
}

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    println!("| case | method | iterations | contact solves | median time, ms | max δw, mm | max δw / wear per period | eq. 49 residual | max Δp / peak | max Δshape / range |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for name in ["punch-a", "punch-b40"] {
        let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
        let (contact, _, _) = CondensedContact::build(&p).unwrap();
        let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
            .unwrap()
            .half_period_wear();
        // β̃ 2u₀ (p⁺ + p⁻) with p⁺ + p⁻ = 2p̃ = 33.332 MPa.
        let wear_per_period = terms.iter().map(|t| t.0).sum::<f64>() * 33.332;
        let exact =
            solve_steady(&contact, &terms, SteadyMethod::Exact, Default::default()).unwrap();
        let runs = [
            (
                "exact",
                SteadyMethod::Exact,
                Sensitivities::FiniteDifference,
            ),
            (
                "averaged (mean)",
                SteadyMethod::Averaged,
                Sensitivities::FiniteDifference,
            ),
            (
                "spline, fd sensitivities",
                SteadyMethod::Spline,
                Sensitivities::FiniteDifference,
            ),
            (
                "spline, exact sensitivities",
                SteadyMethod::Spline,
                Sensitivities::Exact,
            ),
            (
                "penalty",
                SteadyMethod::Penalty,
                Sensitivities::FiniteDifference,
            ),
        ];
        for (label, method, sensitivities) in runs {
            let settings = MethodSettings {
                sensitivities,
                ..Default::default()
            };
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..repeats {
                let o = solve_steady(&contact, &terms, method, settings).unwrap();
                times.push(o.seconds);
                last = Some(o);
            }
            times.sort_by(f64::total_cmp);
            let o = last.unwrap();
            let (dp, ds) = difference(&o, &exact);
            let max_dw = o.delta_w.iter().cloned().fold(0.0, f64::max);
            println!(
                "| {name} | {label} | {} | {} | {:.2} | {:.2e} | {:.1e} | {:.1e} | {:.4} | {:.4} |",
                o.state.iterations,
                o.contact_solves,
                1e3 * times[times.len() / 2],
                max_dw,
                max_dw / wear_per_period,
                o.residual,
                dp,
                ds
            );
        }
    }
}
