//! The four steady-state methods (exact, and the paper's §6: averaged, spline, penalty) on
//! punch-a and punch-b40, for the tables of docs/validation.md and docs/performance.md:
//! `cargo run --release --example paper_methods [REPEATS]`. Each method is run REPEATS times
//! (default 20) on one condensed contact problem; the median time is printed.
//! `cargo run --release --example paper_methods spline-study` prints the spline method's error
//! against the number of spline points instead.

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

/// The condensed contact of built-in example `name` and its wear per half period
/// ((β̃ ∫|v|ᵃ dτ, b) per law).
fn load(name: &str) -> (CondensedContact, Vec<(f64, f64)>) {
    let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    (contact, terms)
}

/// The spline method with the paper's 17 points and with every interval bisected once and
/// twice (33, 65 points), exact sensitivities: how far the corner error is the spline's
/// resolution.
fn spline_study() {
    println!("| case | spline points | Newton steps | contact solves | max Δp / peak | at x (mm) | max Δshape / range | eq. 49 residual |");
    println!("|---|---|---|---|---|---|---|---|");
    for name in ["punch-a", "punch-b40"] {
        let (contact, terms) = load(name);
        let exact =
            solve_steady(&contact, &terms, SteadyMethod::Exact, Default::default()).unwrap();
        // The ends of the zone where both half cycles are in contact (the paper's x_cl, x_cr).
        let x: Vec<f64> = contact.points.x.iter().map(|q| q[0]).collect();
        let both: Vec<usize> = (0..x.len())
            .filter(|&i| exact.state.p_plus[i] > 0.0 && exact.state.p_minus[i] > 0.0)
            .collect();
        println!(
            "{name}: both half cycles in contact on x = {:.2} … {:.2} mm",
            x[both[0]],
            x[both[both.len() - 1]]
        );
        for refinement in 0..=2u32 {
            let settings = MethodSettings {
                sensitivities: Sensitivities::Exact,
                spline_refinement: refinement,
                ..Default::default()
            };
            let o = solve_steady(&contact, &terms, SteadyMethod::Spline, settings).unwrap();
            let (dp, ds) = difference(&o, &exact);
            let e = &exact.state;
            let worst = (0..e.p_plus.len())
                .max_by(|&i, &j| {
                    let d = |k: usize| {
                        (o.state.p_plus[k] - e.p_plus[k])
                            .abs()
                            .max((o.state.p_minus[k] - e.p_minus[k]).abs())
                    };
                    d(i).total_cmp(&d(j))
                })
                .unwrap();
            println!(
                "| {name} | {} | {} | {} | {:.4} | {:.2} | {:.4} | {:.1e} |",
                wearfem::spline_method::knot_positions(refinement).len(),
                o.state.iterations - 8,
                o.contact_solves,
                dp,
                contact.points.x[worst][0],
                ds,
                o.residual
            );
        }
    }
}

/// The penalty iteration with c_n = f · λ_max (λ_max: the largest eigenvalue of the contact
/// stiffness, the default c_n) and with the contact discretised by elements of order p = 4, 6,
/// 8 (33, 49, 65 contact points): periods to the eq. 49 tolerance, periods until the state is
/// within the 2 % of the exact one, and the paper's objective I_δw · max δw.
fn penalty_study() {
    println!("| case | p (contact points) | c_n / λ_max | c_n, MPa/mm | periods to eq. 49 ≤ 1e-3 | periods to 2 % | I_δw·max δw at 1, 100, 300, end (mm⁴) |");
    println!("|---|---|---|---|---|---|---|");
    for name in ["punch-a", "punch-b40"] {
        for (order, factors) in [(4, &[1.0][..]), (6, &[1.0][..]), (8, &[1.0, 0.9, 0.75][..])] {
            let text = wearfem::examples::example(name)
                .unwrap()
                .replace("\np = 8", &format!("\np = {order}"));
            let p = Problem::from_toml(&text, name).unwrap();
            let (contact, _, _) = CondensedContact::build(&p).unwrap();
            let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
                .unwrap()
                .half_period_wear();
            let exact =
                solve_steady(&contact, &terms, SteadyMethod::Exact, Default::default()).unwrap();
            let lambda = wearfem::paper_steady::contact_stiffness(&contact);
            for &f in factors {
                let settings = |k: usize| MethodSettings {
                    penalty_stiffness: Some(f * lambda),
                    max_iterations: k,
                    ..Default::default()
                };
                let run =
                    |k: usize| solve_steady(&contact, &terms, SteadyMethod::Penalty, settings(k));
                let head = format!(
                    "| {name} | {order} ({}) | {f} | {:.3e} |",
                    contact.len(),
                    f * lambda
                );
                let o = match run(3000) {
                    Ok(o) if o.state.status == wearfem::steady::SteadyStatus::Solved => o,
                    _ => {
                        println!("{head} not in 3000 (oscillates) | | |");
                        continue;
                    }
                };
                // Bisection on the first period whose state is within 2 % (monotone in practice).
                let within = |k: usize| {
                    run(k).is_ok_and(|o| {
                        let (dp, ds) = difference(&o, &exact);
                        dp < 0.02 && ds < 0.02
                    })
                };
                let (mut lo, mut hi) = (0, o.state.iterations);
                while hi - lo > 1 {
                    let m = (lo + hi) / 2;
                    if within(m) {
                        hi = m
                    } else {
                        lo = m
                    }
                }
                let obj = |k: usize| {
                    o.history
                        .get(k.min(o.history.len()) - 1)
                        .map_or(f64::NAN, |r| r.i_delta_w * r.max_delta_w)
                };
                println!(
                    "{head} {} | {hi} | {:.1e}, {:.1e}, {:.1e}, {:.1e} |",
                    o.state.iterations,
                    obj(1),
                    obj(100),
                    obj(300),
                    obj(o.history.len())
                );
            }
        }
    }
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("spline-study") {
        return spline_study();
    }
    if std::env::args().nth(1).as_deref() == Some("penalty-study") {
        return penalty_study();
    }
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    println!("| case | method | iterations | contact solves | median time, ms | max δw, mm | max δw / wear per period | eq. 49 residual | max Δp / peak | max Δshape / range |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for name in ["punch-a", "punch-b40"] {
        let (contact, terms) = load(name);
        // β̃ 2u₀ (p⁺ + p⁻) with p⁺ + p⁻ = 2p̃ = 33.332 MPa.
        let wear_per_period = terms.iter().map(|t| t.0).sum::<f64>() * 33.332;
        let exact =
            solve_steady(&contact, &terms, SteadyMethod::Exact, Default::default()).unwrap();
        let runs = [
            (
                "exact",
                SteadyMethod::Exact,
                Sensitivities::FiniteDifference,
                0,
            ),
            (
                "averaged (mean)",
                SteadyMethod::Averaged,
                Sensitivities::FiniteDifference,
                0,
            ),
            (
                "spline, fd sensitivities",
                SteadyMethod::Spline,
                Sensitivities::FiniteDifference,
                0,
            ),
            (
                "spline, exact sensitivities",
                SteadyMethod::Spline,
                Sensitivities::Exact,
                0,
            ),
            (
                "spline, 33 points, exact sensitivities",
                SteadyMethod::Spline,
                Sensitivities::Exact,
                1,
            ),
            (
                "penalty",
                SteadyMethod::Penalty,
                Sensitivities::FiniteDifference,
                0,
            ),
        ];
        for (label, method, sensitivities, spline_refinement) in runs {
            let settings = MethodSettings {
                sensitivities,
                spline_refinement,
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
