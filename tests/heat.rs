//! The paper's claims about heat (§1, §4, its ref. [15]) on punch-b40-heat, and the heat
//! balance. Each test names its reference and why its bound is what it is; the measured
//! values are in docs/validation.md ("Heat").

mod common;

use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::wear::non_rigid_part;

/// punch-b40-heat with the edits applied to its text.
fn heat_problem(edits: &[(&str, &str)]) -> Problem {
    common::problem("punch-b40-heat", edits)
}

/// Largest |a − b| relative to `scale`.
fn worst(a: &[f64], b: &[f64], scale: f64) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / scale
}

fn peak(p: &[&[f64]]) -> f64 {
    p.iter()
        .flat_map(|v| v.iter())
        .fold(0.0f64, |m, x| m.max(*x))
}

/// The difference of two shapes with the best rigid motion removed, relative to the first's
/// own non-rigid range.
fn shape_difference(
    a: &[f64],
    b: &[f64],
    contact: &wearfem::contact::CondensedContact,
) -> (f64, f64) {
    let r = contact.rigid_gap_matrix();
    let m = contact.rigid_modes.len();
    let w = &contact.points.weight;
    let all = vec![true; a.len()];
    let own = non_rigid_part(a, &all, &r, m, w);
    let range = own.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - own.iter().cloned().fold(f64::INFINITY, f64::min);
    let d: Vec<f64> = a.iter().zip(b).map(|(x, y)| x - y).collect();
    let d = non_rigid_part(&d, &all, &r, m, w);
    let size = d.iter().fold(0.0f64, |s, x| s.max(x.abs()));
    (size / range, range)
}

#[test]
fn steady_pressure_with_heat_is_the_one_without() {
    // Paper §1, §4: "in the steady wear state for reciprocal sliding, the contact pressure
    // reaches the same distribution as that obtained for the case of neglect of heat
    // generation, but the steady state contact shapes are different". The issue's bound is
    // 1 % of the peak. Measured 0.72 %: the half cycles see the temperature at their starts,
    // whose thermal gaps differ by the period's swing (91 nm at most against a thermal gap
    // of 8 µm across the contact), and the pressures answer to that difference
    // (docs/validation.md). The summed pressure p⁺ + p⁻ = 2p̃ (eq. 23a) holds with heat to
    // round-off, since it follows from the wear's rigidity alone.
    let with = heat_problem(&[]);
    let without = common::problem("punch-b40", &[]);
    let (hot, contact, _, heat) = driver::steady_with_heat(&with).unwrap();
    let (cold, _, _) = driver::steady(&without).unwrap();
    assert!(heat.is_some());
    let scale = peak(&[&cold.p_plus, &cold.p_minus]);
    let d = worst(&hot.p_plus, &cold.p_plus, scale).max(worst(&hot.p_minus, &cold.p_minus, scale));
    eprintln!("steady p with and without heat: {:.3e} of the peak", d);
    assert!(d < 0.01, "{d}");
    for i in 0..contact.len() {
        let sum = hot.p_plus[i] + hot.p_minus[i];
        assert!((sum - 33.332).abs() < 1e-6 * 33.332, "{i}: {sum}");
    }
    // The worn shapes differ by the thermal distortion (which the shape absorbs).
    let (difference, range) = shape_difference(&cold.shape, &hot.shape, &contact);
    eprintln!(
        "steady worn shape with heat differs by {:.3} of the range {:.3e} mm",
        difference, range
    );
    assert!(
        difference > 0.1,
        "the heat changes the worn shape: {difference}"
    );
}

#[test]
fn steady_pressure_with_heat_does_not_depend_on_the_wear_coefficient() {
    // Paper §4: the steady pressure "does not depend on the value of wear factor β̃₁ nor
    // generated temperature field". With heat, the thermal swing of a period does not
    // depend on β̃ (the heat does not), so the steady pressures at β̃ and 10 β̃ agree to
    // round-off; the bound is 0.5 %.
    let base = heat_problem(&[]);
    let ten = heat_problem(&[(
        "beta = 3.9269908169872414e-8",
        "beta = 3.9269908169872414e-7",
    )]);
    let (a, ..) = driver::steady_with_heat(&base).unwrap();
    let (b, ..) = driver::steady_with_heat(&ten).unwrap();
    let scale = peak(&[&a.p_plus, &a.p_minus]);
    let d = worst(&a.p_plus, &b.p_plus, scale).max(worst(&a.p_minus, &b.p_minus, scale));
    eprintln!("steady p at β̃ and 10 β̃: {d:.3e} of the peak");
    assert!(d < 0.005, "{d}");
}

#[test]
fn a_long_run_reaches_the_steady_state_with_heat() {
    // `steady` against a run continued until wear and temperature are periodic: the
    // issue's bounds, 0.5 % of the peak for the pressures and 2 % of the range for the worn
    // shape with the rigid motion removed. The example's 16 300 half periods are five
    // thermal time constants of the strip (L²/a = 100²/13.9 s ≈ 2300 half periods).
    let problem = heat_problem(&[]);
    let run = common::run(&problem, None);
    let (state, contact, _, _) = driver::steady_with_heat(&problem).unwrap();
    let h = &run.history;
    let scale = peak(&[&state.p_plus, &state.p_minus]);
    let d = worst(&h.p_plus, &state.p_plus, scale).max(worst(&h.p_minus, &state.p_minus, scale));
    let (shape, _) = shape_difference(&state.shape, &h.shape, &contact);
    eprintln!("run against steady with heat: pressures {d:.3e} of the peak, shape {shape:.3e} of its range");
    assert!(d < 0.005, "{d}");
    assert!(shape < 0.02, "{shape}");
    // And the run's own check says so, against the steady state with heat.
    assert!(run.steady_check.reached(h), "{}", run.steady_check);
}

#[test]
fn the_transient_pressure_differs_with_heat() {
    // Paper §1 (ref. [15]): "the thermal distortion affects essentially ... the transient
    // contact pressure distribution". The first solve is the same (the bodies start at the
    // reference temperature); after it the heat of each half period bulges the contact.
    let hot = common::run(&heat_problem(&[]), Some(200));
    let cold = common::run(&common::problem("punch-b40", &[]), Some(200));
    let first = common::p_m_plus(&hot, 1) - common::p_m_plus(&cold, 1);
    assert!(first.abs() < 1e-9 * common::p_m_plus(&cold, 1), "{first}");
    let largest = (1..=200)
        .step_by(2)
        .map(|n| {
            (common::p_m_plus(&hot, n) - common::p_m_plus(&cold, n)).abs()
                / common::p_m_plus(&cold, n)
        })
        .fold(0.0, f64::max);
    eprintln!("transient p(M) with and without heat: up to {largest:.3e} apart");
    assert!(largest > 0.01, "{largest}");
}

/// p(M) and T(M) of `run`'s '+' steps after `from` against `reference` (a run with k = 1
/// throughout) at the same half period: where that ends a '−' half of the reference, the
/// mean of its '+' halves on either side. Returns the largest differences relative to
/// p(M) and to T(M)'s rise over the reference temperature.
fn against_k1(
    run: &wearfem::driver::WearRun,
    reference: &wearfem::driver::WearRun,
    from: usize,
) -> (f64, f64) {
    let heat = run.history.thermal.is_some();
    let k = run.probes.iter().position(|(n, _)| n == "M").unwrap();
    let at = |h: usize| &reference.history.steps[h - 1];
    let (mut p_error, mut t_error) = (0.0f64, 0.0f64);
    for s in run
        .history
        .steps
        .iter()
        .filter(|s| s.direction == "+" && s.step > from)
    {
        let h = s.half_period;
        if h >= reference.history.steps.len() {
            continue;
        }
        let temperature = |h: usize| if heat { at(h).temperatures[k] } else { 0.0 };
        let (p_ref, t_ref) = if h % 2 == 1 {
            (at(h).probes[k], temperature(h))
        } else {
            (
                0.5 * (at(h - 1).probes[k] + at(h + 1).probes[k]),
                0.5 * (temperature(h - 1) + temperature(h + 1)),
            )
        };
        assert_eq!(at(h | 1).direction, "+");
        p_error = p_error.max((s.probes[k] - p_ref).abs() / p_ref);
        if heat {
            t_error = t_error.max((s.temperatures[k] - t_ref).abs() / (t_ref - 20.0));
        }
    }
    (p_error, t_error)
}

#[test]
fn schedules_agree_with_single_half_periods() {
    // Accuracy in time: the paper's schedule (k = 1, 5, 10) and the adaptive one against
    // k = 1 throughout, for p(M) and the temperature at M (the bound: 1 %). The heat
    // of a step of k half periods alternates with the other direction's, so the temperature
    // ripple of the real process is kept.
    //
    // The paper's schedule misses 1 % in p(M) without heat already: the jump from k = 1 to
    // k = 5 at step 51 leaves its backward-Euler lag, 1.9 % at M on punch-b40
    // (docs/validation.md). So its bound is that of the same schedule without heat: the
    // heat must add no error of its own. The adaptive schedule controls its error: 1 %.
    let k1 = |name: &str| {
        common::run(
            &common::problem(
                name,
                &[(
                    "steps = 1700 ",
                    "steps = 16300 \nextrapolation = [{ k = 1 }]\n",
                )],
            ),
            None,
        )
    };
    let single = k1("punch-b40-heat");
    let paper = common::run(&heat_problem(&[]), None);
    let (p, t) = against_k1(&paper, &single, 0);
    let cold = common::run(&common::problem("punch-b40", &[]), None);
    let (p_cold, _) = against_k1(&cold, &k1("punch-b40"), 0);
    eprintln!(
        "paper schedule against k = 1: p(M) {p:.3e} ({p_cold:.3e} without heat), T(M) {t:.3e}"
    );
    assert!(p < p_cold.max(0.01) && t < 0.01, "{p} {t}");
    let adaptive = common::run(
        &heat_problem(&[
            ("steps = 1700 ", "steps = 16300 "),
            (
                "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
                "record = []\n\n[wear.adaptive]",
            ),
        ]),
        None,
    );
    let (p, t) = against_k1(&adaptive, &single, 0);
    eprintln!(
        "adaptive schedule ({} steps) against k = 1: p(M) {p:.3e}, T(M) {t:.3e}",
        adaptive.history.steps.len()
    );
    assert!(p < 0.01 && t < 0.01, "{p} {t}");
}

#[test]
fn heat_balance_in_a_transient_and_in_the_steady_state() {
    use wearfem::complementarity::Direction;
    use wearfem::wear::thermal::{CoupledSystem, Sliding, ThermalBodies, ThermalModel};
    // Energy (the bounds, 0.5 %): in a transient, the heat stored plus the heat
    // lost through held and convecting edges and the faces equals the frictional heat made;
    // in the periodic steady state what a period makes leaves. The full model is stepped by
    // SDIRK2 (32 steps a half period) with the losses integrated by the trapezoidal rule,
    // both second order: the balance closes to about 1e-4 (docs/validation.md).
    let HeatSetup {
        problem,
        settings,
        contact,
        bodies: [body1, body2],
        pressures,
    } = setup(&[]);
    let (amplitude, omega, mu) = (1.5, 10.0, contact.friction);
    let input = ThermalBodies {
        elastic: [&body1, &body2],
        contact: &contact,
        settings: &settings,
        space: problem.discretisation.space,
        sliding: Sliding::Reciprocating { amplitude, omega },
        probes: vec![],
    };
    let system = CoupledSystem::new(&input).unwrap();
    let area = contact.areas();
    let half_heat = |p: &[f64]| -> f64 {
        p.iter()
            .zip(&area)
            .map(|(p, a)| mu * p.max(0.0) * 2.0 * amplitude * a)
            .sum()
    };
    let stored = |t: &[f64]| system.stored[0].at(t)[0] + system.stored[1].at(t)[0];
    let substeps = 32;
    let h = std::f64::consts::PI / omega;
    let dt = h / substeps as f64;
    let stepper = system.stepper(dt).unwrap();
    let mut field = system.initial.clone();
    let start = stored(&field);
    let (mut generated, mut lost) = (0.0, 0.0);
    let halves = 10;
    for n in 0..halves {
        let p = &pressures[n % 2];
        generated += half_heat(p);
        let amplitudes: Vec<f64> = p
            .iter()
            .map(|p| mu * p.max(0.0) * amplitude * omega)
            .collect();
        let mut load = vec![0.0; system.len()];
        for (j, &q) in amplitudes.iter().enumerate() {
            for (i, l) in load.iter_mut().enumerate() {
                *l += system.flux[(i, j)] * q;
            }
        }
        for step in 0..substeps {
            let before = field.clone();
            stepper.advance(&mut field, step as f64 * dt, |tau| {
                let s = (omega * tau).sin();
                system
                    .source
                    .iter()
                    .zip(&load)
                    .map(|(f, l)| f + l * s)
                    .collect()
            });
            // The losses are linear in T: the trapezoid is their value at the mean field,
            // with the held edges' C Ṫ from the step's change.
            let mean: Vec<f64> = before
                .iter()
                .zip(&field)
                .map(|(a, b)| 0.5 * (a + b))
                .collect();
            let rate: Vec<f64> = before
                .iter()
                .zip(&field)
                .map(|(a, b)| (b - a) / dt)
                .collect();
            lost += system.heat_out(&mean, Some(&rate)) * dt;
        }
    }
    let gained = stored(&field) - start;
    let balance = (gained + lost - generated).abs() / generated;
    eprintln!(
        "transient: made {generated:.4e} mJ, stored {gained:.4e}, lost {lost:.4e}: balance {balance:.2e}"
    );
    assert!(balance < 5e-3, "{balance}");
    // The reduced model the runs use stores the same heat.
    let model = ThermalModel::from_system(
        &system,
        &system.shifts(h),
        &input,
        std::time::Instant::now(),
    )
    .unwrap();
    let mut state = model.start();
    for n in 0..halves {
        let d = if n % 2 == 0 {
            Direction::Plus
        } else {
            Direction::Minus
        };
        model.advance(&mut state, &pressures[n % 2], d, 1, n % 2 == 0);
    }
    let reduced = model.stored_heat(&state);
    eprintln!(
        "reduced model stores {reduced:.4e} mJ, made {:.4e}",
        state.generated
    );
    assert!(
        (reduced - gained).abs() < 5e-3 * gained,
        "{reduced} vs {gained}"
    );
    assert!((state.generated - generated).abs() < 1e-12 * generated);
    // Steady: the period's mean field solves K T̄ = f₀ + F q̄ with the mean flux density
    // q̄ = μ (p⁺ + p⁻) u₀ / h (a period makes μ p 2u₀ per unit area in each half), and what
    // leaves at T̄ is what a period makes, per unit time.
    let (steady, ..) = driver::steady_with_heat(&problem).unwrap();
    let mean_flux: Vec<f64> = steady
        .p_plus
        .iter()
        .zip(&steady.p_minus)
        .map(|(a, b)| mu * (a + b) * amplitude / h)
        .collect();
    let mut rhs = system.source.clone();
    for (j, &q) in mean_flux.iter().enumerate() {
        for (i, r) in rhs.iter_mut().enumerate() {
            *r += system.flux[(i, j)] * q;
        }
    }
    let mean = wearfem::conduction::transient::solve_spd(&system.matrices.first, &rhs).unwrap();
    let made: f64 = mean_flux.iter().zip(&area).map(|(q, a)| q * a).sum();
    let out = system.heat_out(&mean, None);
    eprintln!("steady: made {made:.4e} mW, lost {out:.4e} mW");
    assert!((out - made).abs() < 5e-3 * made, "{out} vs {made}");
}

#[test]
fn the_fields_reproduce_the_thermal_gap_the_contact_saw() {
    use wearfem::complementarity::{ContactSolver, Direction, Method};
    use wearfem::contact::CondensedContact;
    use wearfem::deformation::{contact_fields_with_heat, gap_of_fields};
    // The thermal gap of a run comes from the elastic adjoints (Xᵀ F T, set up once); the
    // ParaView fields from solving each body under its thermal load directly. Rebuilt from
    // the fields, the gap at each contact point must be the contact solve's: the two routes
    // agree to the solves' round-off (1e-9 of the gap's size, six orders below a micrometre
    // of the thermal gap), with mortar and with collocation, on a refined punch at p = 6.
    let mortar = heat_problem(&[(
        "discretisation = \"collocation\"",
        "discretisation = \"mortar\"",
    )]);
    let refined = Problem::from_toml(
        &wearfem::examples::refined_punch("punch-b40-heat", 12)
            .unwrap()
            .replace("p = 8", "p = 6"),
        "refined",
    )
    .unwrap();
    for problem in [heat_problem(&[]), mortar, refined] {
        let run = common::run(&problem, Some(120));
        let model = run.heat_model.clone().unwrap();
        let thermal = run.history.thermal.as_ref().unwrap();
        let (contact, body1, body2) = CondensedContact::build(&problem).unwrap();
        let direction = if run.history.steps.last().unwrap().direction == "+" {
            Direction::Plus
        } else {
            Direction::Minus
        };
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        let (solution, _) = solver.solve(&run.history.contact_shape, direction);
        let fields = contact_fields_with_heat(
            &problem,
            (&body1, &body2),
            &contact,
            &solution,
            direction,
            Some(model.temperature_fields(&thermal.solved_state)),
        )
        .unwrap();
        let geometric: Vec<f64> = run
            .history
            .contact_shape
            .iter()
            .zip(&thermal.thermal_gap)
            .map(|(c, t)| c - t)
            .collect();
        let rebuilt = gap_of_fields((&body1, &body2), &fields, &contact, &geometric).unwrap();
        let size = thermal
            .thermal_gap
            .iter()
            .fold(0.0f64, |m, g| m.max(g.abs()));
        let worst = rebuilt
            .iter()
            .zip(&solution.gap)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "{}: gap from the fields against the solve's: {worst:.3e} mm (thermal gap up to {size:.3e} mm)",
            problem.file
        );
        assert!(worst < 1e-9 * size.max(1e-3), "{worst}");
    }
}

/// punch-b40-heat with `edits`: its contact, bodies, validated `[heat]` section and the
/// pressures of its first '+' and '−' solves.
struct HeatSetup {
    problem: Problem,
    settings: wearfem::heat_input::HeatSettings,
    contact: wearfem::contact::CondensedContact,
    bodies: [wearfem::elasticity::ElasticBody; 2],
    pressures: Vec<Vec<f64>>,
}

fn setup(edits: &[(&str, &str)]) -> HeatSetup {
    use wearfem::complementarity::{ContactSolver, Direction, Method};
    let problem = heat_problem(edits);
    let settings = problem.heat_settings().unwrap().unwrap();
    let (contact, body1, body2) = wearfem::contact::CondensedContact::build(&problem).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let pressures = [Direction::Plus, Direction::Minus]
        .iter()
        .map(|&d| solver.solve(&contact.points.initial_gap, d).0.pressure)
        .collect();
    HeatSetup {
        problem,
        settings,
        contact,
        bodies: [body1, body2],
        pressures,
    }
}

#[test]
fn a_uniform_rise_closes_the_gap_by_the_free_expansion() {
    // Both bodies 10 K above the stress-free temperature: the punch (clamped at its plate
    // edge) grows down by Σ α h ΔT = (1.5e-5 · 20 + 1.2e-5 · 80) · 10 mm and the strip (held
    // at its base) up by 1.2e-5 · 100 · 10 mm, 24.6 µm in all, so the thermal gap is about
    // −24.6 µm: negative (the gap closes). The plate edge and the base, held sideways, take
    // a few percent off the free expansion: 10 %.
    let s = setup(&[(
        "reference_temperature = 20.0",
        "reference_temperature = 20.0\ninitial_temperature = 30.0",
    )]);
    let (contact, body1, body2) = wearfem::contact::CondensedContact::build(&s.problem).unwrap();
    let model = wearfem::jobs::heat::thermal_model(&s.problem, &contact, [&body1, &body2])
        .unwrap()
        .unwrap();
    let gap = model.gap.at(&model.start().a);
    let free = -(1.5e-5 * 20.0 + 1.2e-5 * 80.0 + 1.2e-5 * 100.0) * 10.0;
    let middle = gap[gap.len() / 2];
    eprintln!("uniform +10 K: thermal gap {middle:.4e} mm against {free:.4e} mm");
    assert!(gap.iter().all(|&g| g < 0.0));
    assert!(
        (middle - free).abs() < 0.1 * free.abs(),
        "{middle} vs {free}"
    );
}

#[test]
fn a_step_of_k_half_periods_is_k_single_ones() {
    use wearfem::complementarity::Direction;
    // The heat of a cycle of two steps of k half periods (summed geometrically per mode) is
    // that of k single cycles with the same pressures, to round-off, for k odd and even;
    // and after the first step the state is the single cycles' after 2⌈k/2⌉ − 1 half periods.
    let s = setup(&[]);
    let (contact, body1, body2) = wearfem::contact::CondensedContact::build(&s.problem).unwrap();
    let model = wearfem::jobs::heat::thermal_model(&s.problem, &contact, [&body1, &body2])
        .unwrap()
        .unwrap();
    let (plus, minus) = (&s.pressures[0], &s.pressures[1]);
    // One single cycle first, so that the first step of the k-cycle knows the '−' pressure.
    let warm = || {
        let mut state = model.start();
        model.advance(&mut state, plus, Direction::Plus, 1, true);
        model.advance(&mut state, minus, Direction::Minus, 1, false);
        state
    };
    for k in [4, 5] {
        let mut singles = warm();
        let mut mid_single = Vec::new();
        let mids = if k % 2 == 1 { k } else { k - 1 };
        for n in 0..2 * k {
            let (p, d) = if n % 2 == 0 {
                (plus, Direction::Plus)
            } else {
                (minus, Direction::Minus)
            };
            model.advance(&mut singles, p, d, 1, n % 2 == 0);
            if n + 1 == mids {
                mid_single = singles.a.clone();
            }
        }
        let mut cycle = warm();
        model.advance(&mut cycle, plus, Direction::Plus, k, true);
        let mid_cycle = cycle.a.clone();
        model.advance(&mut cycle, minus, Direction::Minus, k, false);
        let scale = singles.a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let worst = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max)
                / scale
        };
        assert!(
            worst(&cycle.a, &singles.a) < 1e-10,
            "k = {k}: {}",
            worst(&cycle.a, &singles.a)
        );
        assert!(worst(&mid_cycle, &mid_single) < 1e-10, "k = {k}, mid-cycle");
        assert!((cycle.generated - singles.generated).abs() < 1e-10 * singles.generated);
        assert!((cycle.time - singles.time).abs() < 1e-12 * singles.time);
    }
}

#[test]
fn the_periodic_temperature_repeats_under_the_full_model() {
    // The periodic state of the steady state, in closed form per mode of the reduced model:
    // stepped over one period by the full model (SDIRK2, 32 steps a half period) from that
    // temperature, the full model comes back to it, and loses in the period the heat the
    // period makes. The reduced model's own error (docs/convergence.md: 1e-3 of the rise)
    // bounds the first; the second holds to the integration's 1e-4 (the transient balance).
    let s = setup(&[]);
    let (contact, [body1, body2], settings) = (&s.contact, &s.bodies, &s.settings);
    let input = wearfem::wear::thermal::ThermalBodies {
        elastic: [body1, body2],
        contact,
        settings,
        space: s.problem.discretisation.space,
        sliding: wearfem::wear::thermal::Sliding::Reciprocating {
            amplitude: 1.5,
            omega: 10.0,
        },
        probes: vec![],
    };
    let system = wearfem::wear::thermal::CoupledSystem::new(&input).unwrap();
    let h = std::f64::consts::PI / 10.0;
    let model = wearfem::wear::thermal::ThermalModel::from_system(
        &system,
        &system.shifts(h),
        &input,
        std::time::Instant::now(),
    )
    .unwrap();
    let (plus, minus) = (&s.pressures[0], &s.pressures[1]);
    let [start, _] = model.periodic_state(plus, minus).unwrap();
    let mut field = model.free_field(&start);
    let initial = field.clone();
    let substeps = 32;
    let dt = h / substeps as f64;
    let stepper = system.stepper(dt).unwrap();
    let mu = contact.friction;
    let area = contact.areas();
    let (mut made, mut lost) = (0.0, 0.0);
    for p in [plus, minus] {
        made += p
            .iter()
            .zip(&area)
            .map(|(p, a)| mu * p.max(0.0) * 3.0 * a)
            .sum::<f64>();
        let mut load = vec![0.0; system.len()];
        for (j, q) in p.iter().map(|p| mu * p.max(0.0) * 15.0).enumerate() {
            for (i, l) in load.iter_mut().enumerate() {
                *l += system.flux[(i, j)] * q;
            }
        }
        for step in 0..substeps {
            let before = field.clone();
            stepper.advance(&mut field, step as f64 * dt, |tau| {
                let s = (10.0 * tau).sin();
                system
                    .source
                    .iter()
                    .zip(&load)
                    .map(|(f, l)| f + l * s)
                    .collect()
            });
            let mean: Vec<f64> = before
                .iter()
                .zip(&field)
                .map(|(a, b)| 0.5 * (a + b))
                .collect();
            let rate: Vec<f64> = before
                .iter()
                .zip(&field)
                .map(|(a, b)| (b - a) / dt)
                .collect();
            lost += system.heat_out(&mean, Some(&rate)) * dt;
        }
    }
    let t_start = system.contact_temperature[0].at(&initial);
    let t_end = system.contact_temperature[0].at(&field);
    let rise = t_start.iter().fold(0.0f64, |m, t| m.max(t - 20.0));
    let drift = t_start
        .iter()
        .zip(&t_end)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
        / rise;
    eprintln!("one period of the full model from the periodic state: contact temperature drifts {drift:.2e} of the rise; made {made:.4e} mJ, lost {lost:.4e} mJ");
    assert!(drift < 3e-3, "{drift}");
    assert!((lost - made).abs() < 5e-3 * made, "{lost} vs {made}");
}

#[test]
fn the_difference_is_the_swings() {
    use wearfem::steady::{steady_state_with_offsets, SteadySliding};
    // The steady pressure with heat differs from the one without because the two half cycles
    // start at different temperatures: the thermal gap's swing δ = θ₋ − θ₊ over a period. The
    // difference answers to δ linearly (δ is 91 nm against the bodies' micrometres): half
    // the swing makes half the difference (to 5 %, the second order of a 1 % change), and no
    // swing none (round-off).
    let problem = heat_problem(&[]);
    let (with, contact, _, heat) = driver::steady_with_heat(&problem).unwrap();
    let heat = heat.unwrap();
    let (without, ..) = driver::steady(&common::problem("punch-b40", &[])).unwrap();
    let integrator =
        wearfem::wear::WearIntegrator::new(problem.spec.wear.as_ref().unwrap()).unwrap();
    let terms = integrator.half_period_wear();
    let swing: Vec<f64> = heat.thermal_gap[1]
        .iter()
        .zip(&heat.thermal_gap[0])
        .map(|(m, p)| m - p)
        .collect();
    let scale = peak(&[&without.p_plus, &without.p_minus]);
    let off = |state: &wearfem::steady::SteadyState| {
        worst(&state.p_plus, &without.p_plus, scale).max(worst(
            &state.p_minus,
            &without.p_minus,
            scale,
        ))
    };
    let with_swing = |s: f64| {
        let offsets = vec![
            vec![0.0; contact.len()],
            swing.iter().map(|d| s * d).collect(),
        ];
        steady_state_with_offsets(
            &contact,
            &terms,
            SteadySliding::Reciprocating,
            Default::default(),
            None,
            &offsets,
        )
        .unwrap()
    };
    let full = off(&with);
    let half = off(&with_swing(0.5));
    let none = off(&with_swing(0.0));
    eprintln!("the swing's effect: full {full:.3e}, half {half:.3e}, none {none:.3e}");
    assert!(
        (half / full - 0.5).abs() < 0.05 * 0.5,
        "{half} against {full}"
    );
    assert!(none < 1e-9, "{none}");
}

#[test]
fn the_default_spaces_give_the_tensor_product_temperatures() {
    // `heat.space = "auto"` keeps the tensor-product space in the elements along the contact
    // and takes the trunk space elsewhere (wearfem::conduction::spaces). The reference is the
    // tensor-product space everywhere, whose space holds both others: over 60 half periods
    // the probe's temperature at M and the largest temperature of each body must agree to
    // 1e-4 of the rise (measured 5e-6 over 1700 steps, docs/convergence.md; the rest of the
    // bound is margin for round-off in the reduction). The trunk space everywhere misses the
    // thin heated layer at the punch's corners (3e-3 of the rise at M after the first half
    // period): it must fail the same bound, or the comparison could not tell them apart.
    let steps = Some(60);
    let tensor = common::run(
        &heat_problem(&[("[heat]", "[heat]\nspace = \"tensor\"")]),
        steps,
    );
    let auto = common::run(&heat_problem(&[]), steps);
    let trunk = common::run(
        &heat_problem(&[("[heat]", "[heat]\nspace = \"trunk\"")]),
        steps,
    );
    let series = |run: &driver::WearRun| -> Vec<f64> {
        run.history
            .steps
            .iter()
            .flat_map(|s| {
                let high = s.max_temperature.expect("a run with heat");
                s.temperatures.iter().copied().chain(high)
            })
            .collect()
    };
    let reference = series(&tensor);
    let rise = reference.iter().fold(0.0f64, |m, t| m.max(t - 20.0));
    let auto_error = worst(&series(&auto), &reference, rise);
    let trunk_error = worst(&series(&trunk), &reference, rise);
    eprintln!("against the tensor-product space: auto {auto_error:.2e}, trunk {trunk_error:.2e} of the rise {rise:.2} K");
    assert!(auto_error < 1e-4, "{auto_error}");
    assert!(trunk_error > 1e-3, "{trunk_error}");
}

#[test]
fn the_largest_temperatures_computed_in_chunks_are_each_steps_own() {
    // Each body's largest temperature per step is computed after the run, many steps at a
    // time (one matrix product per chunk of steps). A snapshot keeps the modal state its
    // step was solved with, the end state of the step before: the model's extremes of that
    // state must be that step's record, to round-off (1e-12 of the temperature), on both
    // sides of the chunks' boundaries (128 steps) and in the last, partial chunk.
    let problem = heat_problem(&[(
        "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]",
        "record = [2, 128, 129, 130, 256, 257, 300]",
    )]);
    let run = common::run(&problem, Some(300));
    let model = run.heat_model.as_ref().expect("a run with heat");
    for snapshot in &run.history.snapshots {
        let state = snapshot.thermal_state.as_ref().expect("a state with heat");
        let expected = model.max_temperatures(state);
        let record = &run.history.steps[snapshot.step - 2];
        let got = record.max_temperature.expect("filled at the end");
        for b in 0..2 {
            assert!(
                (got[b] - expected[b]).abs() < 1e-12 * expected[b].abs(),
                "step {}: {got:?} vs {expected:?}",
                record.step
            );
        }
    }
    assert!(run
        .history
        .steps
        .iter()
        .all(|s| s.max_temperature.is_some()));
}

#[test]
fn the_reduced_model_follows_the_full_one_at_slow_and_fast_sliding() {
    use wearfem::complementarity::Direction;
    use wearfem::wear::thermal::{CoupledSystem, Sliding, ThermalBodies, ThermalModel};
    // The contact's heat enters the reduction in fewer shapes than points, as many as the
    // thermal layer of a half period needs (wearfem::wear::thermal::shapes): the faster the
    // sliding, the thinner the layer and the more local each point's response. Against the
    // full model (SDIRK2, 32 steps a half period: 3e-5 of the rise, docs/convergence.md) over
    // six half periods at ω = 10 (the example, 22 shapes), 30 (32 shapes) and 100 rad/s (one
    // input per point), the contact temperature within 5e-3 of its rise: half the issue's
    // 1 % for the temperature, measured 1e-3 or less. A third as many shapes whatever the
    // speed was 2.5e-2 off at ω = 100 (a review's finding).
    let HeatSetup {
        problem,
        settings,
        contact,
        bodies: [body1, body2],
        pressures,
    } = setup(&[]);
    let amplitude = 1.5;
    for omega in [10.0, 30.0, 100.0] {
        let input = ThermalBodies {
            elastic: [&body1, &body2],
            contact: &contact,
            settings: &settings,
            space: problem.discretisation.space,
            sliding: Sliding::Reciprocating { amplitude, omega },
            probes: vec![],
        };
        let system = CoupledSystem::new(&input).unwrap();
        let h = std::f64::consts::PI / omega;
        let model = ThermalModel::from_system(
            &system,
            &system.shifts(h),
            &input,
            std::time::Instant::now(),
        )
        .unwrap();
        let substeps = 32;
        let stepper = system.stepper(h / substeps as f64).unwrap();
        let mut field = system.initial.clone();
        let mut state = model.start();
        let (mut worst_difference, mut rise) = (0.0f64, 0.0f64);
        for n in 0..6 {
            let p = &pressures[n % 2];
            let amplitudes: Vec<f64> = p
                .iter()
                .map(|p| contact.friction * p.max(0.0) * amplitude * omega)
                .collect();
            system.reference_half_period(&mut field, &stepper, &amplitudes, omega, substeps);
            let direction = [Direction::Plus, Direction::Minus][n % 2];
            model.advance(&mut state, p, direction, 1, n % 2 == 0);
            let full = system.contact_temperature[0].at(&field);
            let reduced = model.contact_temperature[0].at(&state.a);
            for (f, r) in full.iter().zip(&reduced) {
                rise = rise.max(f - settings.reference);
                worst_difference = worst_difference.max((f - r).abs());
            }
        }
        let error = worst_difference / rise;
        eprintln!(
            "ω = {omega}: {} modes, contact temperature within {error:.2e} of the rise {rise:.2} K",
            model.modes()
        );
        assert!(error < 5e-3, "ω = {omega}: {error}");
    }
}
