//! The paper's §6 methods (averaged shape, spline, penalty) against the exact steady state of
//! src/steady_state/steady.rs on Example 1 (`punch-a`) and Example 2 of §6.3 (`punch-b40`).

mod common;
use common::problem;
use wearfem::contact::CondensedContact;
use wearfem::paper_steady::{
    solve_steady, MethodOutcome, MethodSettings, Sensitivities, SteadyMethod,
};
use wearfem::steady::SteadyStatus;
use wearfem::wear::WearIntegrator;

fn solve(name: &str, method: SteadyMethod, settings: MethodSettings) -> MethodOutcome {
    let p = problem(name, &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    solve_steady(&contact, &terms, method, settings).unwrap()
}

/// Largest differences to the exact state: pressures over the peak pressure, shape over its
/// range (both shapes in the same gauge, Σ w R g = 0).
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
    let (lo, hi) = e
        .shape
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
            (l.min(v), h.max(v))
        });
    let ds = a
        .state
        .shape
        .iter()
        .zip(&e.shape)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    (dp / peak, ds / (hi - lo))
}

#[test]
fn exact_method_has_delta_w_at_round_off() {
    // Eq. 40 vanishes in the steady state; the exact solve reaches it to round-off: below
    // 1e-12 of the wear of a period, β̃ 2u₀ · 2p̃ (the bound).
    let wear_per_period = 3.9269908169872414e-8 * 3.0 * 33.332;
    for name in ["punch-a", "punch-b40"] {
        let e = solve(name, SteadyMethod::Exact, MethodSettings::default());
        assert_eq!(e.state.status, SteadyStatus::Solved);
        let max = e.delta_w.iter().cloned().fold(0.0, f64::max);
        assert!(max < 1e-12 * wear_per_period, "{name}: max δw = {max:e}");
        assert!(
            e.residual < 1e-12,
            "{name}: eq. 49 residual {:e}",
            e.residual
        );
    }
}

#[test]
fn penalty_iteration_converges_to_the_exact_state() {
    // The criterion: p⁺, p⁻ within 2 % of the peak pressure, shape within 2 % of its
    // range. The penalty iteration stops at an eq. 49 residual of 1e-3, which leaves it two
    // orders inside that.
    for name in ["punch-a", "punch-b40"] {
        let exact = solve(name, SteadyMethod::Exact, MethodSettings::default());
        let pen = solve(name, SteadyMethod::Penalty, MethodSettings::default());
        assert_eq!(pen.state.status, SteadyStatus::Solved, "{name}");
        let (dp, ds) = difference(&pen, &exact);
        assert!(dp < 0.02 && ds < 0.02, "{name}: Δp {dp:.4}, Δshape {ds:.4}");
        // The start, the averaged shape, is far from it (the corner peaks of Fig. 24b).
        let avg = solve(name, SteadyMethod::Averaged, MethodSettings::default());
        let (dp0, _) = difference(&avg, &exact);
        assert!(dp0 > 0.5, "{name}: averaged start already at {dp0}");
        // Fewer iterations than periods of the time integration, more than the exact Newton.
        assert!(pen.state.iterations > exact.state.iterations);
    }
}

#[test]
fn spline_method_reaches_the_exact_shape_and_both_sensitivities_agree() {
    // With 33 spline points too, on punch-b40 (where the paper's Δs stopped the finite
    // differences at 1.77 % of the peak from the exact state, the exact sensitivities at
    // 0.05 %) and on the pin.
    for name in ["punch-b40", "pin"] {
        let settings = |sensitivities| MethodSettings {
            sensitivities,
            spline_refinement: 1,
            ..Default::default()
        };
        let fd = solve(
            name,
            SteadyMethod::Spline,
            settings(Sensitivities::FiniteDifference),
        );
        let ex = solve(name, SteadyMethod::Spline, settings(Sensitivities::Exact));
        let (dp, ds) = difference(&fd, &ex);
        assert!(dp < 1e-3 && ds < 1e-3, "{name}: Δp {dp:e}, Δshape {ds:e}");
    }
    for name in ["punch-a", "punch-b40"] {
        let exact = solve(name, SteadyMethod::Exact, MethodSettings::default());
        let fd = solve(name, SteadyMethod::Spline, MethodSettings::default());
        let ex = solve(
            name,
            SteadyMethod::Spline,
            MethodSettings {
                sensitivities: Sensitivities::Exact,
                ..Default::default()
            },
        );
        // The 2 % of the shape's range is met (measured 0.86 % and 0.45 %).
        let (dp, ds) = difference(&ex, &exact);
        assert!(ds < 0.02, "{name}: Δshape {ds:.4}");
        // The pressures are not: 17 spline points cannot follow the steady shape's abrupt
        // change of curvature at x_cl / x_cr, where the pressures keep an error of 3–4 % of the peak
        // (measured 3.1 %, 3.6 %; the next-but-one test shows that 33 points remove it).
        assert!(dp < 0.05, "{name}: Δp {dp:.4}");
        // Finite differences (Δs = 2e-7 mm) and exact sensitivities end at the same
        // stationary point: the difference is the forward-difference error, O(Δs/range) ~ 1 %
        // of a step that is itself small at the end; 1e-3 of the peak and range.
        let (dp2, ds2) = difference(&fd, &ex);
        assert!(
            dp2 < 1e-3 && ds2 < 1e-3,
            "{name}: fd vs exact Δp {dp2:e}, Δshape {ds2:e}"
        );
        assert!(ex.contact_solves < fd.contact_solves, "{name}");
    }
}

/// `wearfem steady punch-a` with `args`; returns the exit code and the output directory.
fn cli(args: &[&str], tag: &str) -> (i32, std::path::PathBuf) {
    let dir =
        std::env::temp_dir().join(format!("wearfem-paper-steady-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(["steady", "punch-a", "--out", dir.to_str().unwrap()])
        .args(args)
        .output()
        .unwrap();
    (out.status.code().unwrap_or(-1), dir)
}

#[test]
fn the_papers_methods_write_the_same_keys_and_bad_options_are_refused() {
    let keys = |dir: &std::path::Path| -> Vec<String> {
        let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        k.retain(|k| k != "penalty_stiffness");
        k.sort();
        k
    };
    let mut first: Option<Vec<String>> = None;
    // The exact method (the default) keeps its own summary: the state, no iteration history.
    let (code, dir) = cli(&["--method", "exact"], "exact");
    assert_eq!(code, 0);
    assert!(dir.join("steady.csv").exists());
    assert!(["status", "p_plus", "p_minus", "shape"]
        .iter()
        .all(|key| keys(&dir).iter().any(|x| x == key)));
    let _ = std::fs::remove_dir_all(&dir);
    for method in ["averaged", "spline", "penalty"] {
        let (code, dir) = cli(&["--method", method], method);
        assert_eq!(code, 0, "{method}");
        assert!(dir.join("iterations.csv").exists() && dir.join("steady.csv").exists());
        let k = keys(&dir);
        for key in [
            "method",
            "history",
            "residual_eq49",
            "delta_w",
            "max_delta_w",
            "seconds",
        ] {
            assert!(k.iter().any(|x| x == key), "{method}: no {key}");
        }
        match &first {
            None => first = Some(k),
            Some(f) => assert_eq!(f, &k, "{method}"),
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
    // Bad options: exit 2. A penalty far below the contact stiffness overshoots and diverges:
    // exit 1 and nothing written.
    for (args, tag) in [
        (&["--method", "newton"][..], "bad-method"),
        (
            &["--method", "averaged", "--reading", "half"][..],
            "bad-reading",
        ),
        (
            &["--method", "spline", "--sensitivities", "adjoint"][..],
            "bad-sens",
        ),
        (&["--method", "penalty", "--tolerance", "2"][..], "bad-tol"),
    ] {
        assert_eq!(cli(args, tag).0, 2, "{args:?}");
    }
    let (code, dir) = cli(&["--method", "penalty", "--penalty", "1000"], "diverges");
    assert_eq!(code, 1);
    assert!(!dir.join("summary.json").exists());
}

#[test]
fn spline_error_is_its_resolution_at_the_ends_of_the_two_sided_contact_zone() {
    // With the paper's 17 spline points the pressures stay 3–4 % of the peak off the exact
    // state (the issue asks 2 %); bisecting every interval between them (33 points) must
    // bring both pressure and shape inside the 2 %, so the residual error is the
    // spline's resolution, not a wrong equation. Measured: 3.1 % → 0.03 % (punch-a),
    // 3.6 % → 0.05 % (punch-b40).
    for name in ["punch-a", "punch-b40"] {
        let exact = solve(name, SteadyMethod::Exact, MethodSettings::default());
        let settings = |refinement| MethodSettings {
            sensitivities: Sensitivities::Exact,
            spline_refinement: refinement,
            ..Default::default()
        };
        let coarse = solve(name, SteadyMethod::Spline, settings(0));
        let fine = solve(name, SteadyMethod::Spline, settings(1));
        let (dp0, _) = difference(&coarse, &exact);
        let (dp1, ds1) = difference(&fine, &exact);
        assert!(
            dp1 < 0.02 && ds1 < 0.02,
            "{name}: 33 points Δp {dp1:.4}, Δshape {ds1:.4}"
        );
        assert!(dp1 < dp0, "{name}: 17 points {dp0:.4}, 33 points {dp1:.4}");
        // Where the 17-point spline misses: at x_cl or x_cr, where one half cycle's pressure
        // rises steeply from zero and the steady shape's curvature changes abruptly (a cubic
        // spline is C², knots 2.1 mm apart there). Within one knot spacing of x_cl or x_cr.
        let e = &exact.state;
        let x: Vec<f64> = p_x(name);
        let both: Vec<usize> = (0..x.len())
            .filter(|&i| e.p_plus[i] > 0.0 && e.p_minus[i] > 0.0)
            .collect();
        let (x_cl, x_cr) = (x[both[0]], x[both[both.len() - 1]]);
        let err = |i: usize| {
            (coarse.state.p_plus[i] - e.p_plus[i])
                .abs()
                .max((coarse.state.p_minus[i] - e.p_minus[i]).abs())
        };
        let worst = (0..x.len())
            .max_by(|&i, &j| err(i).total_cmp(&err(j)))
            .unwrap();
        let gap = (x[worst] - x_cl).abs().min((x[worst] - x_cr).abs());
        assert!(
            gap < 2.2,
            "{name}: worst at x = {}, x_cl {x_cl}, x_cr {x_cr}",
            x[worst]
        );
    }
}

/// x of the contact points of built-in example `name`, mm.
fn p_x(name: &str) -> Vec<f64> {
    let p = problem(name, &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    contact.points.x.iter().map(|q| q[0]).collect()
}

#[test]
fn penalty_iteration_count_is_set_by_the_contact_discretisation() {
    // The penalty iteration is a fixed-step descent: its stable step 1/c_n is bounded by the
    // stiffest gap pattern of the contact (c_n ≥ λ_max of diag(1/area) A_nn⁻¹), its slowest
    // mode by the softest, so the count grows with the number of contact points. Element
    // order p = 4 (33 points) must need fewer periods than p = 8 (65 points); measured 517
    // against 950 (punch-a). The paper does not print its mesh at the contact or its c_n.
    let count = |order: &str| {
        let p = problem("punch-a", &[("\np = 8", order)]);
        let (contact, _, _) = CondensedContact::build(&p).unwrap();
        let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
            .unwrap()
            .half_period_wear();
        let o = solve_steady(&contact, &terms, SteadyMethod::Penalty, Default::default()).unwrap();
        assert_eq!(o.state.status, SteadyStatus::Solved, "{order}");
        (o.state.iterations, o.penalty_stiffness.unwrap())
    };
    let (coarse, c4) = count("\np = 4");
    let (fine, c8) = count("\np = 8");
    assert!(c4 < c8, "λ_max {c4:e} vs {c8:e}");
    assert!(coarse < fine, "{coarse} vs {fine} periods");
    // Below λ_max the corrections overshoot on the stiffest pattern and the iteration does
    // not settle: 0.9 λ_max stays above the eq. 49 tolerance for 3000 periods (3 × the
    // count at λ_max).
    let p = problem("punch-a", &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    let o = solve_steady(
        &contact,
        &terms,
        SteadyMethod::Penalty,
        MethodSettings {
            penalty_stiffness: Some(0.9 * c8),
            max_iterations: 3000,
            ..Default::default()
        },
    );
    assert!(
        o.map_or(true, |o| o.state.status != SteadyStatus::Solved),
        "0.9 λ_max converged"
    );
}

#[test]
fn a_huge_spline_refinement_is_capped_at_the_contact_resolution() {
    // Bad input must not panic or exhaust memory: u32::MAX bisections are capped at 2 (65
    // spline points on 65 contact points), so the result equals that of refinement 2 exactly
    // (the same computation).
    let settings = |spline_refinement| MethodSettings {
        sensitivities: Sensitivities::Exact,
        spline_refinement,
        ..Default::default()
    };
    let capped = solve("punch-a", SteadyMethod::Spline, settings(u32::MAX));
    let two = solve("punch-a", SteadyMethod::Spline, settings(2));
    assert_eq!(capped.state.shape, two.state.shape);
    assert!(capped.state.shape.iter().all(|g| g.is_finite()));
}

#[test]
fn a_method_result_that_is_not_a_steady_state_is_not_reported_as_one() {
    // Red-team review 4, F3: on the small punch with μ = 0.5 no steady state of one rigid wear
    // per period exists (the exact method does not converge). The spline method stopped at a
    // stationary point with an eq. 49 residual of 1.00 and the averaged shape has 4.98; both
    // said "Solved", exit 0. With μ = 0 (exact answer: uniform 10 MPa) the spline ended at
    // 1.00 as well. The acceptance rule (paper_steady::accept) rejects the first two: exit 1,
    // the residual in the message, nothing written. The same problem's default (μ = 0.25)
    // still passes with every method, well inside the rule (spline 2e-3, penalty 4e-4).
    // Since the spline's steps scale with the bodies' deflection (fixed millimetres were
    // too large a Δ for the small punch), μ = 0 is solved: p⁺ + p⁻ within 1 % of 2 · 10 MPa
    // (measured 0.13 %: the spline's resolution, 1–4 % on the shipped punches).
    let problem = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/small-punch.toml"
    );
    let run = |args: &[&str], tag: &str| {
        let dir = std::env::temp_dir().join(format!(
            "wearfem-paper-steady-accept-{tag}-{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .args(["steady", problem, "--quiet", "--out", dir.to_str().unwrap()])
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        (out.status.code().unwrap_or(-1), err, dir)
    };
    for (mu, method, residual) in [("0.5", "spline", "1.000e0"), ("0.5", "averaged", "4.976e0")] {
        let set = format!("contact.friction={mu}");
        let (code, err, dir) = run(&["--method", method, "--set", &set], method);
        assert_eq!(code, 1, "μ = {mu}, {method}: {err}");
        assert!(
            err.contains("gave no steady state") && err.contains(residual),
            "μ = {mu}, {method}: {err}"
        );
        assert!(!dir.exists(), "μ = {mu}, {method}: something was written");
    }
    for method in ["averaged", "spline", "penalty"] {
        let (code, err, dir) = run(&["--method", method], method);
        assert_eq!(code, 0, "{method}: {err}");
        assert!(dir.join("summary.json").exists());
        let _ = std::fs::remove_dir_all(&dir);
    }
    let (code, err, dir) = run(
        &["--method", "spline", "--set", "contact.friction=0"],
        "spline-mu0",
    );
    assert_eq!(code, 0, "μ = 0, spline: {err}");
    let csv = std::fs::read_to_string(dir.join("steady.csv")).unwrap();
    let column = csv
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "p_sum_MPa");
    for line in csv.lines().skip(1) {
        let p_sum: f64 = line
            .split(',')
            .nth(column.unwrap())
            .unwrap()
            .parse()
            .unwrap();
        assert!((p_sum - 20.0).abs() < 0.2, "μ = 0, spline: p_Σ {p_sum}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `solve` of the built-in `name` with `edits`, the error kept.
fn try_solve(
    name: &str,
    edits: &[(&str, &str)],
    method: SteadyMethod,
    settings: MethodSettings,
) -> Result<MethodOutcome, wearfem::paper_steady::MethodError> {
    let p = problem(name, edits);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    solve_steady(&contact, &terms, method, settings)
}

#[test]
fn the_methods_write_the_gap_initial_gap_included_on_a_curved_contact() {
    // Red team 17, F1: on the pin (an arc cap 13.7 µm deep) the §6 methods wrote the wear
    // part of the shape only, 12 µm of range against the exact state's 1.6 µm, while their
    // pressures were within 0.12 % of it. Both are the same state, so their gaps agree as
    // closely as their pressures: the penalty method to its tolerance (1 % of the range
    // allowed, 0.07 % measured).
    let exact = solve("pin", SteadyMethod::Exact, MethodSettings::default());
    let penalty = solve("pin", SteadyMethod::Penalty, MethodSettings::default());
    let (dp, ds) = difference(&penalty, &exact);
    assert!(dp < 0.005, "pressures {dp}");
    assert!(ds < 0.01, "shape {ds} of the exact range");
}

#[test]
fn the_methods_refuse_a_load_whose_steady_contact_lifts_off() {
    // Red team 17, F3: punch-b40-variant3 with only its 25 MPa on [1070, 1100]: F = 7.5 kN
    // at 15 mm from the left end, so without friction the steady p⁺ + p⁻ is the triangle of
    // eq. 19 over 3 × 15 = 45 mm of the 60, and the linear p_Σ the methods aim at is negative
    // beyond. The spline method said "Solved" with 1.1–2.5 times the exact rigid wear; now
    // both iterative methods and the averaged shape refuse, naming the lift-off.
    let edits = [
        ("normal = 12.5", "normal = 0.0"),
        ("friction = 0.25", "friction = 0.05"),
    ];
    for method in [
        SteadyMethod::Averaged,
        SteadyMethod::Spline,
        SteadyMethod::Penalty,
    ] {
        let err = try_solve(
            "punch-b40-variant3",
            &edits,
            method,
            MethodSettings::default(),
        )
        .err()
        .unwrap_or_else(|| panic!("{method:?} accepted a lift-off load"));
        assert!(
            matches!(err, wearfem::paper_steady::MethodError::LiftOff { .. }),
            "{method:?}: {err}"
        );
    }
    // The exact method solves it, and its state does lift off at the right end.
    let exact = try_solve(
        "punch-b40-variant3",
        &edits,
        SteadyMethod::Exact,
        MethodSettings::default(),
    )
    .unwrap();
    assert_eq!(exact.state.status, SteadyStatus::Solved);
    let last = exact.state.p_plus.len() - 1;
    assert_eq!(exact.state.p_plus[last] + exact.state.p_minus[last], 0.0);
}

#[test]
fn a_solved_penalty_iteration_writes_a_state_within_its_tolerance() {
    // Red team 17, F4: convergence was tested on the state before a period's corrections and
    // the state after them written, "Solved" with an eq. 49 residual up to 1.6 times the
    // tolerance (brake at 5e-3: 6.5e-3).
    for (name, tolerance) in [
        ("brake", 5e-3),
        ("pin", 1e-3),
        ("pin", 3e-3),
        ("punch-a", 2e-3),
        ("punch-b40", 4e-3),
    ] {
        let settings = MethodSettings {
            tolerance,
            ..Default::default()
        };
        let out = solve(name, SteadyMethod::Penalty, settings);
        assert_eq!(out.state.status, SteadyStatus::Solved, "{name} {tolerance}");
        assert!(
            out.residual <= tolerance,
            "{name}: written residual {} above the tolerance {tolerance}",
            out.residual
        );
    }
}

#[test]
fn the_papers_methods_do_not_depend_on_the_stiffness_or_load_scale() {
    // Linear elasticity: E × s and the load × f multiply every displacement by f/s and every
    // pressure by f, so the steady pressures are × f and the shape × f/s, whatever method. A
    // step in millimetres (the paper's Δ and Δs) would break this: with E × 1000 or the load
    // × 0.01 the spline method failed, at a tenth of the load it was 8.6 % off instead of
    // 3.6 %. Pressures to 1e-9 of the peak, shapes to 1e-9 of their range: the iterations
    // take the same path, up to round-off amplified by some 20 least-squares solves.
    let solve_scaled = |s: f64, f: f64, method: SteadyMethod| {
        let composite = format!("young = {}", 1.3e5 * s);
        let steel = format!("young = {}", 2.0e5 * s);
        let load = format!("normal = {}", 16.666 * f);
        let p = problem(
            "punch-b40",
            &[
                ("young = 1.3e5", &composite),
                ("young = 2.0e5", &steel),
                ("normal = 16.666", &load),
            ],
        );
        let (contact, _, _) = CondensedContact::build(&p).unwrap();
        let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
            .unwrap()
            .half_period_wear();
        solve_steady(&contact, &terms, method, MethodSettings::default()).unwrap()
    };
    for method in [SteadyMethod::Spline, SteadyMethod::Penalty] {
        let base = solve_scaled(1.0, 1.0, method);
        for (s, f) in [(1e3, 1.0), (1e-3, 1.0), (1.0, 1e-2)] {
            let mut scaled = solve_scaled(s, f, method);
            let case = format!("{method:?}, E × {s}, load × {f}");
            assert_eq!(scaled.state.status, base.state.status, "{case}");
            assert_eq!(scaled.history.len(), base.history.len(), "{case}");
            for v in scaled.state.shape.iter_mut() {
                *v *= s / f;
            }
            let state = &mut scaled.state;
            for v in state.p_plus.iter_mut().chain(state.p_minus.iter_mut()) {
                *v /= f;
            }
            let (dp, ds) = difference(&scaled, &base);
            assert!(dp < 1e-9 && ds < 1e-9, "{case}: Δp {dp:e}, Δshape {ds:e}");
        }
    }
}

/// `driver::steady_by` on the test problem `file` with the edits `edits`.
fn steady_by_file(
    file: &str,
    edits: &[(&str, &str)],
    method: SteadyMethod,
    settings: MethodSettings,
) -> MethodOutcome {
    let path = format!("{}/tests/problems/{file}", env!("CARGO_MANIFEST_DIR"));
    let mut text = std::fs::read_to_string(&path).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{file}: '{from}' not in the file");
        text = text.replace(from, to);
    }
    let p = wearfem::problem::Problem::from_toml(&text, &path).unwrap();
    wearfem::driver::steady_by(&p, method, settings).unwrap().0
}

#[test]
fn the_spline_method_on_red_team_28s_problems() {
    // F1: without friction the averaged start is the steady state itself, and every m ≥ 1 of
    // the polynomial iteration lifted the corners off: a rigid punch on deep layers was
    // refused (eq. 49 residual 1.000; its file has μ = 0). The start is now a candidate. F3: a strip as wide as
    // the punch with ν = 0 does not bend under a uniform pressure, so the steps in proportion
    // to that bending were round-off and the fd spline failed; they now follow the bending
    // under the same pressure with one half cycle's friction.
    // Both within 1 % of the peak of the exact state (measured 0.52 % and 0.16 %: the 17
    // spline points' resolution, 3–4 % on the shipped punches).
    for file in ["rigid-punch-deep-layers.toml", "same-width-nu0.toml"] {
        let out = steady_by_file(file, &[], SteadyMethod::Spline, MethodSettings::default());
        assert_eq!(out.state.status, SteadyStatus::Solved, "{file}");
        let distance = out.distance_from_exact.unwrap();
        assert!(distance < 0.01, "{file}: {distance}");
    }
    // F2: at a tenth of the paper's Δs the finite differences ended 3.2 % of the peak from
    // where the exact sensitivities end on punch-b40 at p = 10; now at the same state.
    let at_p10 = |sensitivities| {
        let settings = MethodSettings {
            sensitivities,
            ..Default::default()
        };
        try_solve(
            "punch-b40",
            &[("p = 8", "p = 10")],
            SteadyMethod::Spline,
            settings,
        )
        .unwrap()
    };
    let (dp, ds) = difference(
        &at_p10(Sensitivities::FiniteDifference),
        &at_p10(Sensitivities::Exact),
    );
    assert!(dp < 1e-3 && ds < 1e-3, "p = 10: Δp {dp:e}, Δshape {ds:e}");
}

/// The §6 methods solve the exact method's model, so they must say what it says about the
/// model's validity (a red team found the small-strain, half-period and stroke warnings of
/// `--method exact` missing from the others): the pin's stroke is 14 % of its contact, and
/// punch-b40 with a steel of E = 1 GPa strains both bodies by 5 %. Each warning of the exact
/// method must be among each method's (by its first 60 characters: the figures after them
/// may be the method's own state's).
#[test]
fn every_method_gives_the_exact_method_s_model_warnings() {
    let warnings = |name: &str, sets: &[&str], method: &str| -> Vec<String> {
        let dir = std::env::temp_dir().join(format!(
            "wearfem-method-warnings-{name}-{method}-{}",
            std::process::id()
        ));
        let mut args = vec![
            "steady",
            name,
            "--method",
            method,
            "--out",
            dir.to_str().unwrap(),
        ];
        for s in sets {
            args.extend(["--set", s]);
        }
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{name} {method}");
        let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w.as_str().unwrap().to_string())
            .collect()
    };
    for (name, sets, expected) in [
        ("pin", vec![], "wear.amplitude"),
        (
            "punch-b40",
            vec!["materials.steel.young=1e3"],
            "is strained by",
        ),
    ] {
        let exact = warnings(name, &sets, "exact");
        assert!(
            exact.iter().any(|w| w.contains(expected)),
            "{name}: {exact:?}"
        );
        for method in ["averaged", "spline", "penalty"] {
            let theirs = warnings(name, &sets, method);
            for w in &exact {
                let head: String = w.chars().take(60).collect();
                assert!(
                    theirs.iter().any(|t| t.starts_with(&head)),
                    "{name} --method {method} lacks \"{head}…\": {theirs:?}"
                );
            }
        }
    }
}
