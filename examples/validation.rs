//! Prints the detailed figures of docs/validation.md (full Table 2, p-refinement tables,
//! "Beyond the paper"): `cargo run --release --example validation`. The PASS/FAIL table of the
//! same claims is `wearfem validate` (src/jobs/validate.rs).
//!
//! Every number is computed here from the built-in examples; the expected values are the
//! paper's (Table 2, §5.1.1) or closed-form theory (Lamé, eq. 19, eq. 23).

use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::driver;
use wearfem::problem::Problem;

fn problem(name: &str, edits: &[(&str, &str)]) -> Problem {
    let mut text = wearfem::examples::example(name).unwrap().to_string();
    for (a, b) in edits {
        text = text.replace(a, b);
    }
    Problem::from_toml(&text, name).unwrap()
}

fn p_m(run: &driver::WearRun, n: usize) -> f64 {
    let k = run.probes.iter().position(|(name, _)| name == "M").unwrap();
    run.history.steps[if n % 2 == 1 { n } else { n - 1 } - 1].probes[k]
}

fn main() {
    println!("## Lamé cylinder (p = 8, 2 × 2 elements)\n");
    let lame = driver::elastic(&problem("lame", &[])).unwrap();
    let exact = |r: f64| {
        let (a, b, p, e, nu) = (100.0f64, 200.0f64, 100.0f64, 2.0e5f64, 0.3f64);
        let (ca, cb) = (
            p * a * a / (b * b - a * a),
            p * a * a * b * b / (b * b - a * a),
        );
        (1.0 + nu) / e * ((1.0 - 2.0 * nu) * ca * r + cb / r)
    };
    println!("| probe | u_r wearfem (mm) | u_r Lamé (mm) | relative error |\n|---|---|---|---|");
    for (name, r) in [("inner", 100.0), ("outer", 200.0)] {
        let u = lame["probes"][name]["displacement"][0].as_f64().unwrap();
        println!(
            "| {name} | {u:.12} | {:.12} | {:.1e} |",
            exact(r),
            (u - exact(r)).abs() / exact(r)
        );
    }

    println!("\n## Convergence in p: Lamé cylinder, relative energy-norm error\n");
    println!("Exact strain energy U = ½ p u_r(a) (π a / 2) t; error = √((U − U_h)/U) (Galerkin orthogonality).\n");
    println!("| p | dofs (1 × 1 mesh) | error (1 × 1) | dofs (2 × 2 mesh) | error (2 × 2) |\n|---|---|---|---|---|");
    let u_exact = 0.5 * 100.0 * exact(100.0) * (std::f64::consts::FRAC_PI_2 * 100.0);
    for p in 1..=8 {
        let mut row = format!("| {p} |");
        for mesh in ["1", "2"] {
            let degree = format!("p = {p}");
            let (u_line, v_line) = (format!("u = {mesh} "), format!("v = {mesh} "));
            let pr = problem(
                "lame",
                &[("p = 8", &degree), ("u = 2 ", &u_line), ("v = 2 ", &v_line)],
            );
            let body = pr.elastic_body(0, &[]).unwrap();
            let load = pr.load_vector(0, &body, &[]).unwrap();
            let u = body.solve(&load).unwrap();
            let energy = wearfem::fields::strain_energy(&load, &u);
            let error = ((u_exact - energy) / u_exact).max(0.0).sqrt();
            row += &format!(" {} | {error:.3e} |", body.info.total_dofs);
        }
        println!("{row}");
    }

    println!("\n## Example 1, first contact solve (flat punch, '+' direction, no wear)\n");
    println!("| case | p(M) wearfem, MPa | paper Table 2, n = 1 |\n|---|---|---|");
    let paper = [
        ("punch-a", 148.41933),
        ("punch-b20", 100.87461),
        ("punch-b40", 138.37226),
    ];
    for (name, reference) in paper {
        let (contact, _, _) = CondensedContact::build(&problem(name, &[])).unwrap();
        let (sol, _) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        println!("| {name} | {:.3} | {reference:.3} |", sol.pressure[0]);
    }

    println!(
        "\nThe same first solve of punch-a under p-refinement (the edge value is singular):\n"
    );
    println!("| p | contact points | p(M), MPa |\n|---|---|---|");
    for p in [4, 6, 8, 10, 12] {
        let degree = format!("p = {p}");
        let (contact, _, _) =
            CondensedContact::build(&problem("punch-a", &[("p = 8", &degree)])).unwrap();
        let (sol, _) = ContactSolver::new(&contact, Method::ActiveSet)
            .solve(&contact.points.initial_gap, Direction::Plus);
        println!("| {p} | {} | {:.3} |", contact.len(), sol.pressure[0]);
    }

    println!("\n## Table 2: pressure at M (MPa) at the '+' half cycle of step n\n");
    let runs: Vec<driver::WearRun> = ["punch-a", "punch-b20", "punch-b40"]
        .iter()
        .map(|n| driver::wear(&problem(n, &[]), None, |_| {}).unwrap())
        .collect();
    let table: [(usize, usize, [f64; 3]); 15] = [
        (1, 1, [148.41933, 100.87461, 138.37226]),
        (50, 50, [114.70731, 87.926576, 107.45308]),
        (100, 300, [69.721237, 57.950338, 67.301651]),
        (200, 1300, [46.654939, 41.195687, 46.039272]),
        (300, 2300, [40.931186, 36.462991, 40.376545]),
        (400, 3300, [37.501127, 35.565594, 37.620120]),
        (500, 4300, [36.392637, 34.548895, 36.225178]),
        (600, 5300, [35.307986, 33.997961, 35.262677]),
        (700, 6300, [34.768942, 33.713578, 34.696425]),
        (800, 7300, [34.330459, 33.562469, 34.205548]),
        (900, 8300, [34.008547, 33.456073, 33.905548]),
        (1000, 9300, [33.529593, 33.394566, 33.758886]),
        (1100, 10300, [33.568957, 33.358149, 33.445945]),
        (1500, 15300, [33.403968, 33.307992, 33.345945]),
        (1700, 16300, [33.372654, 33.304515, 33.335945]),
    ];
    println!("| n | n_hp | p_n(λ_F) ours | paper | l_z = 20 ours | paper | l_z = 40 ours | paper |\n|---|---|---|---|---|---|---|---|");
    for (n, hp, paper) in table {
        println!(
            "| {n} | {hp} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} |",
            p_m(&runs[0], n),
            paper[0],
            p_m(&runs[1], n),
            paper[1],
            p_m(&runs[2], n),
            paper[2]
        );
    }

    println!("\n## Periodic steady state after 1700 steps\n");
    println!("| example | quantity | wearfem | theory / paper |\n|---|---|---|---|");
    for (name, run) in ["punch-a", "punch-b20", "punch-b40"].iter().zip(&runs) {
        let h = &run.history;
        let n = h.p_plus.len();
        let sums: Vec<f64> = (1..n - 1).map(|i| h.p_plus[i] + h.p_minus[i]).collect();
        let (lo, hi) = sums
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &s| {
                (a.min(s), b.max(s))
            });
        println!("| {name} | p⁺ + p⁻ (interior range), MPa | {lo:.3} … {hi:.3} | 2p̃ = 33.332 (eq. 23a) |");
    }
    for (name, b, paper_edge, paper_pm) in [
        ("punch-b40-b1.2", 1.2f64, 30.948, 17.369),
        ("punch-b40-b0.8", 0.8f64, 37.806, 15.8954),
    ] {
        let run = driver::wear(&problem(name, &[]), None, |_| {}).unwrap();
        let h = &run.history;
        let centre = run
            .contact
            .points
            .x
            .iter()
            .position(|x| (x[0] - 1100.0).abs() < 1e-9)
            .unwrap();
        let pm = h.p_plus[centre];
        println!("| {name} | p_m (centre), MPa | {pm:.4} | {paper_pm} (paper) |");
        println!("| {name} | edge p⁺(1070), MPa | {:.4} | {paper_edge} (paper); 2^(1/b) p_m = {:.4} (eq. 23c) |", h.p_plus[0], 2f64.powf(1.0 / b) * pm);
        let n = h.p_plus.len();
        let s: Vec<f64> = (1..n - 1)
            .map(|i| h.p_plus[i].powf(b) + h.p_minus[i].powf(b))
            .collect();
        let (lo, hi) = s
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), &v| {
                (a.min(v), c.max(v))
            });
        println!("| {name} | (p⁺)ᵇ + (p⁻)ᵇ interior range | {lo:.3} … {hi:.3} | 2p_mᵇ = {:.3} (eq. 23b) |", 2.0 * pm.powf(b));
    }
    for (name, loads) in [
        ("punch-b40-variant2", vec![(20.0, 10.0, 60.0)]),
        (
            "punch-b40-variant3",
            vec![(25.0, 30.0, 60.0), (12.5, 10.0, 30.0)],
        ),
        ("punch-b20-variant2", vec![(20.0, 10.0, 60.0)]),
    ] {
        let run = driver::wear(&problem(name, &[]), None, |_| {}).unwrap();
        let h = &run.history;
        let (l, t) = (60.0, 10.0);
        let f0: f64 = loads.iter().map(|&(p, a, b)| p * (b - a) * t).sum();
        let xf: f64 = loads
            .iter()
            .map(|&(p, a, b)| p * (b - a) * t * 0.5 * (a + b))
            .sum::<f64>()
            / f0;
        let sc = l * t;
        let c = f0 / sc - 3.0 * f0 * (-l + 2.0 * xf) / (l * sc);
        let slope = 6.0 * f0 * (-l + 2.0 * xf) / (l * l * sc);
        let line = |x: f64| 2.0 * (c + slope * (1130.0 - x));
        let n = h.p_plus.len();
        let worst = (1..n - 1)
            .map(|i| (h.p_plus[i] + h.p_minus[i] - line(run.contact.points.x[i][0])).abs())
            .fold(0.0, f64::max);
        println!("| {name} | largest deviation of p_Σ from eq. 19 (interior), MPa | {worst:.3} | 0; line from {:.2} to {:.2} MPa, x̃_F = {xf:.2} mm |", line(1130.0), line(1070.0));
    }

    println!("\n## Steady states computed directly (`wearfem steady`), against theory and the time integration\n");
    println!("| example | iterations | p⁺(M) or crown, MPa | steady p⁺+p⁻ vs theory (max abs, MPa) | max abs(steady − integrated) / peak |\n|---|---|---|---|---|");
    for name in [
        "punch-a",
        "punch-b20",
        "punch-b40",
        "punch-b40-b1.2",
        "punch-b40-variant2",
        "punch-b40-variant3",
        "brake",
    ] {
        let p = problem(name, &[]);
        let (state, contact, _) = driver::steady(&p).unwrap();
        // A state the Newton iteration did not finish is no reference.
        assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
        let run = driver::wear(&p, None, |_| {}).unwrap();
        let n = state.p_plus.len();
        let theory: Vec<f64> = (0..n)
            .map(|i| {
                let x = contact.points.x[i][0];
                match name {
                    "punch-b40-variant2" => {
                        2.0 * (10_000.0 / 600.0
                            * (1.0 + 12.0 * (35.0 - 30.0) * ((1130.0 - x) - 30.0) / 3600.0))
                    }
                    "punch-b40-variant3" => {
                        2.0 * (10_000.0 / 600.0
                            * (1.0 + 12.0 * (38.75 - 30.0) * ((1130.0 - x) - 30.0) / 3600.0))
                    }
                    "brake" => {
                        let alpha =
                            (-contact.points.normal[i][0]).atan2(-contact.points.normal[i][1]);
                        (state.p_plus[n / 2] + state.p_minus[n / 2]) * alpha.cos()
                    }
                    _ => 2.0 * 16.666,
                }
            })
            .collect();
        let dev = if name == "punch-b40-b1.2" {
            // Eq. 23b: (p⁺)ᵇ + (p⁻)ᵇ = 2 p_mᵇ with p_m the centre pressure.
            let pm = state.p_plus[n / 2];
            (0..n)
                .map(|i| {
                    (state.p_plus[i].powf(1.2) + state.p_minus[i].powf(1.2) - 2.0 * pm.powf(1.2))
                        .abs()
                })
                .fold(0.0, f64::max)
        } else {
            (0..n)
                .map(|i| (state.p_plus[i] + state.p_minus[i] - theory[i]).abs())
                .fold(0.0, f64::max)
        };
        let peak = state.p_plus.iter().cloned().fold(0.0, f64::max);
        let diff = (0..n)
            .map(|i| {
                (state.p_plus[i] - run.history.p_plus[i])
                    .abs()
                    .max((state.p_minus[i] - run.history.p_minus[i]).abs())
            })
            .fold(0.0, f64::max)
            / peak;
        let probe = driver::contact_probes(&p, &contact)[0].1;
        let dev_text = format!("{dev:.1e}");
        println!(
            "| {name} | {} | {:.4} | {dev_text} | {:.2} % |",
            state.iterations,
            state.p_plus[probe],
            100.0 * diff
        );
    }
    beyond_the_paper();
}

/// Power laws far from b = 1, a contact that lifts off for good, and one with no steady state.
fn beyond_the_paper() {
    println!("\n## Beyond the paper\n");
    println!("| case | solver | iterations / steps | check | value | theory |\n|---|---|---|---|---|---|");
    for b in [0.5f64, 2.0] {
        let bb = format!("a = 1.0, b = {b:.1} }}");
        let p = problem("punch-b40-b0.8", &[("a = 1.0, b = 0.8 }", &bb)]);
        let (state, _, _) = driver::steady(&p).unwrap();
        // A state the Newton iteration did not finish is no reference.
        assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
        let sums: Vec<f64> = (0..state.p_plus.len())
            .map(|i| state.p_plus[i].powf(b) + state.p_minus[i].powf(b))
            .collect();
        let spread = sums.iter().cloned().fold(f64::MIN, f64::max)
            - sums.iter().cloned().fold(f64::MAX, f64::min);
        let equal = (sums[0] / 2.0).powf(1.0 / b);
        let edge = state.p_plus[0].max(state.p_minus[0]);
        println!(
            "| b = {b}, punch-b40-b0.8 load | steady ({:?}) | {} | edge / p(p⁺ = p⁻); spread of (p⁺)ᵇ + (p⁻)ᵇ | {:.12}; {spread:.1e} | 2^(1/b) = {:.12}; 0 |",
            state.status,
            state.iterations,
            edge / equal,
            2f64.powf(1.0 / b)
        );
    }
    // b = 2 by the default implicit scheme (Newton's method per step), the case of
    // tests/table2.rs::power_law_edge_pressure_is_two_to_one_over_b_times_centre.
    let p = problem(
        "punch-b40-b0.8",
        &[("a = 1.0, b = 0.8 }", "a = 1.0, b = 2.0 }")],
    );
    let run = RunFigures::of(&p);
    println!(
        "| b = 2, time integration (scheme = \"implicit\", the default: Newton per step) | run | {} steps, {:.2} iterations per step, {} steps at the iteration limit | p⁺(M); last cycle max abs(run − steady) / peak | {:.4}; {} | 0 (1 % counts as at the steady state) |",
        run.steps, run.iterations_per_step, run.unconverged, run.p_m, run.distance
    );
    let quadratic = [
        ("a = 1.0, b = 0.8 }", "a = 1.0, b = 2.0 }"),
        (
            "tolerance = 0.01 ",
            "scheme = \"fixed_point\"\ncriterion = \"pointwise\"\ntolerance = 0.01 ",
        ),
    ];
    let p = problem("punch-b40-b0.8", &quadratic);
    let (state, _, _) = driver::steady(&p).unwrap();
    // A state the Newton iteration did not finish is no reference.
    assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
    let run = RunFigures::of(&p);
    println!(
        "| b = 2, time integration (scheme = \"fixed_point\", pointwise criterion, Aitken relaxation) | run | {} steps, {:.1} iterations per step, {} steps at the iteration limit, {} oscillating | p⁺(M); last cycle max abs(run − steady) / peak | {:.4}; {} | steady {:.4}; 0 (1 % counts as at the steady state) |",
        run.steps, run.iterations_per_step, run.unconverged, run.oscillating, run.p_m, run.distance, state.p_plus[0]
    );
    // Lift-off: variant 3 without its second window, μ = 0.05; triangle 66.67 MPa → 0 at 1115.
    let lift = [
        ("normal = 12.5", "normal = 0.0"),
        ("friction = 0.25", "friction = 0.05"),
    ];
    let p = problem("punch-b40-variant3", &lift);
    let (state, contact, _) = driver::steady(&p).unwrap();
    // A state the Newton iteration did not finish is no reference.
    assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
    let worst = (0..state.p_plus.len())
        .map(|i| {
            let triangle = (66.0f64 + 2.0 / 3.0) * ((1115.0 - contact.points.x[i][0]) / 45.0);
            (state.p_plus[i] + state.p_minus[i] - triangle.max(0.0)).abs()
        })
        .fold(0.0, f64::max);
    let run = driver::wear(&p, Some(5000), |_| {}).unwrap();
    let worst_run = (0..state.p_plus.len())
        .filter(|&i| contact.points.x[i][0] > 1071.0)
        .map(|i| {
            let triangle = (66.0f64 + 2.0 / 3.0) * ((1115.0 - contact.points.x[i][0]) / 45.0);
            (run.history.p_plus[i] + run.history.p_minus[i] - triangle.max(0.0)).abs()
        })
        .fold(0.0, f64::max);
    println!(
        "| lift-off: variant 3 load 25 MPa on [1070, 1100] only, μ = 0.05 | steady ({:?}) | {} | max abs(p⁺ + p⁻ − triangle), MPa | {worst:.1e} | 0 (triangle 66.67 → 0 at x = 1115) |",
        state.status, state.iterations
    );
    println!(
        "| same | run | 5000 steps | same, away from the corner point, MPa | {worst_run:.3} | 0 |"
    );
    let rocking = [("normal = 12.5", "normal = 0.0")];
    let p = problem("punch-b40-variant3", &rocking);
    let (state, _, _) = driver::steady(&p).unwrap();
    // No steady state exists here: the row reports that the iteration did not finish.
    assert_ne!(state.status, wearfem::steady::SteadyStatus::Solved);
    let run = driver::wear(&p, Some(5000), |_| {}).unwrap();
    let h = &run.history;
    let plus_end = h.p_plus.iter().rposition(|&v| v > 0.0).unwrap_or(0);
    let minus_start = h.p_minus.iter().position(|&v| v > 0.0).unwrap_or(0);
    println!(
        "| same with μ = 0.25 (μ l_z = 10 mm) | steady ({:?}) | {} | — | no state with one rigid wear per period | — |",
        state.status, state.iterations
    );
    println!(
        "| same | run | 5000 steps | contact zones '+' / '−' (x, mm) | {:.2}–{:.2} / {:.2}–{:.2} | rocks on two facets |",
        contact_x(&p, 0),
        contact_x(&p, plus_end),
        contact_x(&p, minus_start),
        contact_x(&p, h.p_minus.iter().rposition(|&v| v > 0.0).unwrap_or(0)),
    );
}

/// What the b = 2 rows report of a wear run of `p`.
struct RunFigures {
    steps: usize,
    iterations_per_step: f64,
    unconverged: usize,
    oscillating: usize,
    /// p⁺ at the first contact point (M), MPa.
    p_m: f64,
    distance: String,
}

impl RunFigures {
    fn of(p: &Problem) -> RunFigures {
        let run = driver::wear(p, None, |_| {}).unwrap();
        let h = &run.history;
        let iterations: usize = h.steps.iter().map(|s| s.iterations).sum();
        RunFigures {
            steps: h.steps.len(),
            iterations_per_step: iterations as f64 / h.steps.len() as f64,
            unconverged: h.unconverged_steps,
            oscillating: h.oscillating_steps,
            p_m: h.p_plus[0],
            distance: distance(&run.steady_check),
        }
    }
}

/// A run's own check of its last cycle against the steady state (as `wearfem run` reports
/// it in `steady_distance.pressure`), in percent of the steady peak.
fn distance(check: &wearfem::steady_check::SteadyCheck) -> String {
    match check {
        wearfem::steady_check::SteadyCheck::Compared { pressure, .. } => {
            format!("{:.2} %", 100.0 * pressure)
        }
        other => format!("{other:?}"),
    }
}

fn contact_x(p: &Problem, i: usize) -> f64 {
    CondensedContact::build(p).unwrap().0.points.x[i][0]
}
