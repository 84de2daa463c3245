//! The checks of the model's own assumptions (src/checks/validity.rs): results whose equations
//! were solved exactly but which the equations no longer describe are reported.

use wearfem::complementarity::{ContactSolver, Direction};
use wearfem::driver;
use wearfem::overrides::Override;
use wearfem::problem::Problem;
use wearfem::validity::{self, HALF_PERIOD_CHANGE_LIMIT};
use wearfem::wear::WearIntegrator;

fn problem(text: &str, sets: &[&str]) -> Problem {
    let o: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    Problem::with_overrides(text, "validity test", &o).unwrap()
}

fn builtin(name: &str, sets: &[&str]) -> Problem {
    problem(wearfem::examples::example(name).unwrap(), sets)
}

/// The relative pressure change over one half period at the steady state of `p`.
fn steady_change(p: &Problem) -> f64 {
    let (state, contact, _) = driver::steady(p).unwrap();
    let mut solver = ContactSolver::new(&contact, driver::method(p).unwrap());
    let integrator = WearIntegrator::new(p.spec.wear.as_ref().unwrap()).unwrap();
    let pressures = [
        (Direction::Plus, &state.p_plus[..]),
        (Direction::Minus, &state.p_minus[..]),
    ];
    validity::half_period_pressure_change(&mut solver, &integrator, &state.shape, &pressures)
        .unwrap()
}

#[test]
fn shipped_examples_are_inside_the_model() {
    for name in ["punch-a", "punch-b40", "punch-b40-variant2", "brake", "pin"] {
        let p = builtin(name, &[]);
        let (state, contact, _) = driver::steady(&p).unwrap();
        let w = validity::steady_checks(&p, &contact, &state);
        assert!(w.is_empty(), "{name} steady: {w:?}");
        let run = driver::wear(&p, Some(200), |_| {}).unwrap();
        let w = validity::run_checks(&p, &run.contact, &run.history);
        assert!(w.is_empty(), "{name} run: {w:?}");
    }
}

/// For small wear per half period the change is a linear response to the wear, so it scales
/// with β̃ (the steady state itself does not depend on β̃ for b = 1): ten times β̃, ten times
/// the change, to the second-order term (measured 0.08006 % and 0.80058 %).
#[test]
fn the_change_over_a_half_period_is_linear_in_the_wear_coefficient() {
    let small = steady_change(&builtin("punch-b40", &[]));
    let ten = steady_change(&builtin(
        "punch-b40",
        &["wear.body1.beta=3.9269908169872414e-7"],
    ));
    assert!(small > 0.0 && small < HALF_PERIOD_CHANGE_LIMIT);
    // 1 %: the quadratic term at a change of 0.8 % is ~0.8 % of it.
    assert!((ten / small - 10.0).abs() < 0.1, "{small} -> {ten}");
}

/// Where the quasi-static half period fails, the steady state is wrong and says so. The
/// reference is independent of the half-period scheme: explicit time stepping with 200
/// sub-steps per half period (`wear.substeps`), the pressure updated within each half
/// period, run (k = 1) until its cycle's wear is rigid. At β̃ × 1000 on punch-b40 (no shift
/// to zero, so the wear accumulates) its periodic state is 8.5 % of the peak from
/// `wearfem steady`; the change over a half period is 60 % there.
#[test]
fn a_steady_state_outside_the_quasi_static_half_period_is_reported() {
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace("shape_zero_at = 1100.0", "");
    let beta = "wear.body1.beta=3.9269908169872414e-5";
    let steady_problem = problem(&text, &[beta]);
    let (state, contact, _) = driver::steady(&steady_problem).unwrap();
    let warnings = validity::steady_checks(&steady_problem, &contact, &state);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("one half period's wear changes the contact pressure"));
    // The same line is in summary.json (and so in Python's result), with the others.
    let summary = wearfem::output::steady_summary(
        &steady_problem,
        &contact,
        &state,
        0.0,
        &driver::steady_warnings(&steady_problem, &contact, &state),
    );
    assert!(summary["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w.as_str().unwrap().contains("one half period's wear")));
    let reference = problem(
        &text,
        &[
            beta,
            "wear.extrapolation=[{k=1}]",
            "wear.substeps=200",
            "wear.record=[]",
        ],
    );
    let run = driver::wear(&reference, Some(60), |_| {}).unwrap();
    let h = &run.history;
    // The reference has settled: its cycle's wear is rigid to 1e-6.
    assert!(h.steady_distance.unwrap().wear < 1e-6);
    let peak = state.p_plus.iter().cloned().fold(0.0, f64::max);
    let off = state
        .p_plus
        .iter()
        .zip(&h.p_plus)
        .chain(state.p_minus.iter().zip(&h.p_minus))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(off > 0.02 * peak, "the steady state is only {off} MPa off");
}

/// A worn depth beyond a tenth of body 1 (k = 10⁶: 300 steps wear ~500 mm off a 40 mm punch)
/// and a plate displacement beyond a tenth of the contact edge (E = 10⁻³ MPa) are reported;
/// the same run at the shipped values is not.
#[test]
fn wear_through_the_body_and_huge_displacements_are_reported() {
    let base = r#"
[analysis]
kind = "plane_stress"
thickness = 10.0
p = 4
[materials.steel]
young = 2.0e5
poisson = 0.30
[[bodies]]
name = "punch"
[[bodies.blocks]]
corners = [[-30.0, 0.0], [30.0, 0.0], [30.0, 40.0], [-30.0, 40.0]]
u = 8
v = 4
material = "steel"
names = { bottom = "contact", top = "top" }
[[bodies.tractions]]
edge = "top"
normal = 10.0
[[bodies]]
name = "strip"
[[bodies.blocks]]
corners = [[-60.0, -40.0], [60.0, -40.0], [60.0, 0.0], [-60.0, 0.0]]
u = 16
v = 4
material = "steel"
names = { bottom = "base", top = "surface" }
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[contact]
body = "punch"
edge = "contact"
target_body = "strip"
target_edge = "surface"
friction = 0.25
[plate]
edge = "top"
motion = "vertical_rotation"
pin = [0.0, 40.0]
[wear]
body1 = { beta = 4e-8, a = 1.0, b = 1.0 }
amplitude = 1.0
omega = 10.0
steps = 300
shape_zero_at = 0.0
"#;
    let warnings = |sets: &[&str]| {
        let p = problem(base, sets);
        let run = driver::wear(&p, None, |_| {}).unwrap();
        validity::run_checks(&p, &run.contact, &run.history)
    };
    assert!(warnings(&[]).is_empty());
    let deep = warnings(&["wear.extrapolation=[{k=1000000}]"]);
    assert!(
        deep.iter().any(|w| w.contains("the run wore up to")),
        "{deep:?}"
    );
    let soft = warnings(&["materials.steel.young=1e-3"]);
    assert!(
        soft.iter()
            .any(|w| w.contains("the plate moves body 1's contact edge by")),
        "{soft:?}"
    );
}

fn from_file(name: &str, sets: &[&str]) -> Problem {
    let path = format!("{}/tests/problems/{name}", env!("CARGO_MANIFEST_DIR"));
    let o: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    let text = std::fs::read_to_string(&path).unwrap();
    Problem::with_overrides(&text, name, &o).unwrap()
}

/// Each body's worn depth is its own (summed over the steps at each point, not a bound) and
/// is measured against the blocks that carry its contact edge: a 1 mm pad worn 1.8 mm and a
/// 2 mm strip worn 1 mm are reported, the strip as body 2; a 0.5 mm wear of a 400 mm strip
/// under a thin punch that does not wear is not; and a 2 m rod that moves the plate 2 mm at a
/// strain of 1e-3 raises no displacement warning (review 2026-11-24).
#[test]
fn worn_depth_is_judged_per_body_against_its_own_blocks() {
    let warnings = |name: &str, sets: &[&str]| {
        let p = from_file(name, sets);
        let run = driver::wear(&p, None, |_| {}).unwrap();
        (
            validity::run_checks(&p, &run.contact, &run.history),
            run.history.worn_depth,
        )
    };
    let (pad, depth) = warnings("pad-worn-through.toml", &[]);
    assert!(depth[0] > 1.0 && depth[1] == 0.0, "{depth:?}");
    assert!(pad.iter().any(|w| w.contains("off body 1")), "{pad:?}");
    let (strip, depth) = warnings("thin-strip-worn.toml", &[]);
    assert!(depth[0] == 0.0 && depth[1] > 0.5, "{depth:?}");
    assert!(strip.iter().any(|w| w.contains("off body 2")), "{strip:?}");
    let (quiet, depth) = warnings("thin-punch-strip-wears.toml", &[]);
    assert!(depth[1] > 0.4, "{depth:?}");
    assert!(quiet.is_empty(), "{quiet:?}");
    let (rod, _) = warnings("long-rod.toml", &["wear.amplitude=0.2"]);
    assert!(rod.is_empty(), "{rod:?}");
}

/// The worn depth is the wear at the deepest point, summed over the steps: on the flat punch
/// with a vertical plate and μ = 0 (uniform pressure F/(l t)), every point wears
/// H β̃ 2u₀ F/(l t) after H half periods (Archard), which the run's worn_depth must equal.
#[test]
fn worn_depth_is_archards_on_a_uniform_pressure() {
    let p = builtin(
        "punch-a",
        &[
            "contact.friction=0",
            "wear.extrapolation=[{k=1}]",
            "wear.record=[]",
        ],
    );
    let run = driver::wear(&p, Some(40), |_| {}).unwrap();
    let wear = p.spec.wear.as_ref().unwrap();
    let pressure = 16.666; // MPa: F/(l t) of punch-a, its traction on the top edge
    let expected = 40.0 * wear.body1.unwrap().beta * 2.0 * wear.amplitude * pressure;
    let depth = run.history.worn_depth[0];
    // The punch's corners carry more than F/(l t) in the first solves (the flat punch's edge
    // singularity before wear evens it out), so the deepest point wears more: between 1 and
    // 3 times the mean.
    assert!(
        depth >= expected * (1.0 - 1e-9) && depth < 3.0 * expected,
        "{depth} against {expected}"
    );
}

/// `contact` checks the plate motion too (review 2026-11-24: E = 10⁻³ MPa moved the plate
/// 2.3 km in `wearfem contact` without a word while `run` and `steady` warned).
#[test]
fn the_contact_job_checks_the_plate_motion() {
    let soft = builtin("punch-b40", &["materials.steel.young=1e-3"]);
    let (summary, _, _, _) = driver::contact(&soft).unwrap();
    let warnings = summary["warnings"].as_array().unwrap();
    assert!(
        warnings.iter().any(|w| w
            .as_str()
            .unwrap()
            .contains("the plate moves body 1's contact edge by")),
        "{warnings:?}"
    );
    let (summary, _, _, _) = driver::contact(&builtin("punch-b40", &[])).unwrap();
    assert!(summary["warnings"].as_array().unwrap().is_empty());
}

/// The plate's motion is judged where it carries the contact, not at the pin (red team B: a
/// pin 1 m to the side gave λ_F = 233 mm and a warning while the punch moved 0.014 mm; here a
/// pin 0.9 km to the side of punch-b40 gives λ_F ≈ 30 mm, above a tenth of the punch). A
/// pin moved along x spans the same rigid motions (a rotation about it differs from one
/// about the old pin by a vertical translation), so the pressures are the same (1e-6 of the
/// peak: the far pin's λ_F and λ_M nearly cancel at the punch, 1e5 times larger than their
/// sum) and so is the plate's motion at the contact edge: no warning.
#[test]
fn the_plate_motion_is_measured_at_the_contact_not_at_a_far_pin() {
    let near = builtin("punch-b40", &[]);
    let far = builtin("punch-b40", &["plate.pin=[900000.0, 140.0]"]);
    let (near_summary, ..) = driver::contact(&near).unwrap();
    let (far_summary, ..) = driver::contact(&far).unwrap();
    assert!(
        far_summary["warnings"].as_array().unwrap().is_empty(),
        "{:?}",
        far_summary["warnings"]
    );
    let lambda_f = far_summary["rigid"]["lambda_F"].as_f64().unwrap();
    assert!(lambda_f.abs() > 10.0, "the pin's own motion {lambda_f}");
    let pressures = |s: &serde_json::Value| -> Vec<f64> {
        s["pressure"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    let (a, b) = (pressures(&near_summary), pressures(&far_summary));
    let peak = a.iter().cloned().fold(0.0, f64::max);
    let worst = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-6 * peak, "{worst} of {peak}");
}

/// Linear elements: Hertz (the example's 2 mm layers under a 6 mm zone) at p = 1 is several
/// percent above the closed form p₀ = 329.6 MPa (Johnson §4.3, as in tests/mortar.rs) and says
/// so; at p = 2 on the same mesh it is within the 2 % Hertz bound of the mortar tests (1.0 %
/// measured) and says nothing about the degree.
#[test]
fn linear_elements_in_contact_are_named() {
    let p0 = 329.61;
    let degree_warning = |p: usize| {
        let (summary, ..) =
            driver::contact(&builtin("hertz", &[&format!("analysis.p={p}")])).unwrap();
        let peak = summary["pressure"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .fold(0.0, f64::max);
        let named = summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().contains("p = 1 (linear elements)"));
        (peak / p0 - 1.0, named)
    };
    let (error, named) = degree_warning(1);
    assert!(
        error > 0.03 && named,
        "p = 1: {error:.4} off, named {named}"
    );
    let (error, named) = degree_warning(2);
    assert!(
        error.abs() < 0.02 && !named,
        "p = 2: {error:.4} off, named {named}"
    );
}

/// A review's punch cut into elements of 18, 0.6, 11.4 and 30 mm (a 30 : 1 step at x = 1088):
/// one contact point's pressure falls to about 40 % of its neighbours' mean, on a strip of 200
/// even elements (body 2 is not the cause). The contact summary names the step; the shipped
/// punch (8 equal elements) and a 6 : 1 step (the review saw no dip there) are not named.
#[test]
fn a_steep_step_in_body_1s_element_lengths_is_named() {
    let solve = |u: &str| {
        let sets = [
            format!("bodies[0].blocks[0].u={u}"),
            format!("bodies[0].blocks[1].u={u}"),
            "bodies[1].blocks[0].u=200".to_string(),
            "contact.discretisation=mortar".to_string(),
        ];
        let sets: Vec<&str> = sets.iter().map(String::as_str).collect();
        driver::contact(&builtin("punch-b40", &sets)).unwrap().0
    };
    let named = |summary: &serde_json::Value| {
        summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().contains("change length by"))
    };
    let steep = solve("[0.0, 0.3, 0.31, 0.5, 1.0]");
    let p: Vec<f64> = steep["pressure"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let dip = (1..p.len() - 1)
        .map(|i| p[i] / (0.5 * (p[i - 1] + p[i + 1])))
        .fold(f64::INFINITY, f64::min);
    // Away from the corners the flat punch's pressure is smooth: no point below 90 % of its
    // neighbours' mean. The steep step's dip is far below that (0.41 measured).
    assert!(dip < 0.6, "smallest ratio to the neighbours' mean {dip}");
    assert!(named(&steep));
    let gentle = solve("[0.0, 0.3, 0.35, 0.5, 1.0]");
    assert!(!named(&gentle), "6 : 1 named: {}", gentle["warnings"]);
    let shipped = driver::contact(&builtin("punch-b40", &[])).unwrap().0;
    assert!(!named(&shipped));
}

/// A wear so large that the check's own contact solves fail (β̃ = 1e200: one half period
/// wears ~1e201 mm) is where the half-period assumption fails worst: the check must say that
/// it could not be made, and why, not vanish (review 10, F11). Both jobs, steady and run.
#[test]
fn a_half_period_check_that_cannot_be_made_says_so() {
    let huge = builtin("punch-b40", &["wear.body1.beta=1e200"]);
    let (state, contact, _) = driver::steady(&huge).unwrap();
    let steady = validity::steady_checks(&huge, &contact, &state);
    let run = driver::wear(&huge, Some(60), |_| {}).unwrap();
    let run = validity::run_checks(&huge, &run.contact, &run.history);
    for (job, warnings) in [("steady", steady), ("run", run)] {
        let half_period: Vec<&String> = warnings
            .iter()
            .filter(|w| w.contains("one half period's wear changes the contact pressure"))
            .collect();
        assert_eq!(half_period.len(), 1, "{job}: {warnings:?}");
        // Either measured (far above the limit) or not measured, with the reason.
        let w = half_period[0];
        assert!(
            w.contains("could not check") && w.contains("failed") || w.contains("% of its peak"),
            "{job}: {w}"
        );
    }
}

/// The reason of a check that cannot be made reaches the warning: a non-finite wear (here a
/// pressure that is not finite) is named, and is not a change of 0.
#[test]
fn a_non_finite_half_period_wear_is_reported_as_unchecked() {
    let p = builtin("punch-b40", &[]);
    let (state, contact, _) = driver::steady(&p).unwrap();
    let mut solver = ContactSolver::new(&contact, driver::method(&p).unwrap());
    let integrator = WearIntegrator::new(p.spec.wear.as_ref().unwrap()).unwrap();
    let infinite = vec![f64::INFINITY; state.p_plus.len()];
    let pressures = [(Direction::Plus, &infinite[..])];
    let why =
        validity::half_period_pressure_change(&mut solver, &integrator, &state.shape, &pressures)
            .unwrap_err();
    assert!(why.contains("not finite"), "{why}");
    let warning = validity::half_period_warning(&p, Err(why.clone())).unwrap();
    assert!(
        warning.starts_with(&format!(
            "warning[half-period-unchecked]: {}: wear: could not check",
            p.file
        )) && warning.contains(&why),
        "{warning}"
    );
}

/// The largest principal strain of the Lamé cylinder (examples/lame.toml), whose closed form
/// is ε_θ = (1+ν)/E [(1−2ν)A + B/r²], ε_r = (1+ν)/E [(1−2ν)A − B/r²]. At E = 2 MPa the
/// strain is far beyond small (the cylinder's 95 mm inner displacement on a 100 mm radius):
/// the warning names it, with the value of the closed form at the point it names; at the
/// example's E = 2e5 MPa (strain below 1e-3) nothing is said.
#[test]
fn large_strains_of_an_elastic_body_are_reported_with_their_value() {
    let lame = |young: &str| {
        let text =
            std::fs::read_to_string(format!("{}/examples/lame.toml", env!("CARGO_MANIFEST_DIR")))
                .unwrap();
        let p = problem(&text, &[&format!("materials.steel.young={young}")]);
        driver::elastic(&p).unwrap()["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w.as_str().unwrap().to_string())
            .collect::<Vec<_>>()
    };
    assert!(lame("2.0e5").is_empty());
    let warnings = lame("2.0");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    // "... is strained by 8.633e1 (8633 %) at (x, z) ..."
    let w = &warnings[0];
    let number = |after: &str, until: char| -> Vec<f64> {
        let start = w.find(after).unwrap() + after.len();
        let end = start + w[start..].find(until).unwrap();
        w[start..end]
            .split(", ")
            .map(|s| s.parse().unwrap())
            .collect()
    };
    let strain = number("strained by ", ' ')[0];
    let at = number(") at (", ')');
    let (nu, young, a, b, pressure) = (0.3, 2.0, 100.0f64, 200.0f64, 100.0);
    let big_a = pressure * a * a / (b * b - a * a);
    let big_b = pressure * a * a * b * b / (b * b - a * a);
    let r2 = at[0] * at[0] + at[1] * at[1];
    let hoop = (1.0 + nu) / young * ((1.0 - 2.0 * nu) * big_a + big_b / r2);
    let radial = (1.0 + nu) / young * ((1.0 - 2.0 * nu) * big_a - big_b / r2);
    let expected = hoop.abs().max(radial.abs());
    // 1e-3: the warning prints 4 significant digits and the point to 1e-4 mm; p = 8 on the
    // exact arcs reproduces the Lamé field to 1e-7 (tests/elastic.rs).
    assert!(
        (strain / expected - 1.0).abs() < 1e-3,
        "{strain} against {expected}"
    );
}

/// A soft layer 2 mm thick under a 40 mm punch: the plate moves by a small fraction of the
/// punch (no displacement warning), but the layer's strain is large. Away from the punch's
/// ends a layer much thinner than the contact is in uniaxial strain, ε = p (1+ν)(1−2ν) /
/// (E (1−ν)) under the mean pressure p = 10 MPa, so the largest strain is at least that, and
/// with E = 100 MPa (0.074) it is reported; at E = 10⁴ MPa (7.4e-4) it is not.
#[test]
fn a_strained_thin_layer_is_reported_although_the_plate_barely_moves() {
    let warnings = |young: f64| {
        let p = from_file(
            "thin-soft-layer.toml",
            &[&format!("materials.layer.young={young}")],
        );
        let (summary, ..) = driver::contact(&p).unwrap();
        summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w.as_str().unwrap().to_string())
            .filter(|w| !w.starts_with("note"))
            .collect::<Vec<_>>()
    };
    assert!(warnings(1e4).is_empty(), "{:?}", warnings(1e4));
    let soft = warnings(100.0);
    assert_eq!(soft.len(), 1, "{soft:?}");
    assert!(soft[0].contains("body \"base\" is strained by"), "{soft:?}");
    let start = soft[0].find("strained by ").unwrap() + "strained by ".len();
    let strain: f64 = soft[0][start..].split(' ').next().unwrap().parse().unwrap();
    let uniaxial = 10.0 * 1.3 * 0.4 / (100.0 * 0.7);
    // The punch's ends concentrate strain (a corner of the contact), so above the uniaxial
    // value, but by less than a factor 2 at the Gauss points of this mesh.
    assert!(
        strain >= uniaxial && strain < 2.0 * uniaxial,
        "{strain} against {uniaxial}"
    );
    // The same check runs in `run` and `steady` through the first contact solve.
    let p = from_file("thin-soft-layer.toml", &["materials.layer.young=100"]);
    let (state, contact, _) = driver::steady(&p).unwrap();
    let steady = validity::steady_checks(&p, &contact, &state);
    assert!(
        steady.iter().any(|w| w.contains("is strained by")),
        "{steady:?}"
    );
}

/// The depth the worn-depth check compares with is the depth of the blocks that carry the
/// contact edge, across them from the edge: the brake's shoe is a ring sector from r = 200 to
/// 240 mm and its disc from 120 to 200 mm (the file's corners), so 40 and 80 mm, where their
/// corners projected on the contact's mean normal gave 34.6 and 40 mm (a red team's bush
/// 15 mm thick was called 7.5 mm); the punch's lowest block is 20 mm tall, the strip 100 mm.
#[test]
fn the_worn_depth_is_compared_with_the_block_s_depth_across_it() {
    // Round-off of the arcs' blending map only (both sides of a ring sector are exact arcs).
    let close = |got: Option<(String, f64)>, name: &str, depth: f64| {
        let (got_name, got_depth) = got.expect("a depth");
        assert_eq!(got_name, name);
        assert!(
            (got_depth - depth).abs() < 1e-9 * depth,
            "{name}: {got_depth} against {depth}"
        );
    };
    let brake = builtin("brake", &[]);
    close(validity::worn_blocks_depth(&brake, 0), "shoe", 40.0);
    close(validity::worn_blocks_depth(&brake, 1), "disc", 80.0);
    let punch = builtin("punch-b40", &[]);
    close(validity::worn_blocks_depth(&punch, 0), "punch", 20.0);
    close(validity::worn_blocks_depth(&punch, 1), "strip", 100.0);
}

/// The depth is the least along the whole contact edge, not at the elements' middles (red
/// team K): a pad tapered from 20 to 1 mm over one element is 1 mm deep at its thin end (its
/// corners), and 98 % of that worn off was silent when the depth was taken 10.5 mm at the
/// middle; a pad whose top is an arc of radius 37.5 mm about (0, 42.5) dips to 42.5 − 37.5 =
/// 5 mm at x = 0, an element end when cut in two.
#[test]
fn the_worn_depth_is_the_least_along_the_contact_edge() {
    let tapered = from_file("pad-tapered-to-1mm.toml", &[]);
    let (_, depth) = validity::worn_blocks_depth(&tapered, 0).expect("a depth");
    // Exact corners on a straight side: round-off only.
    assert!((depth - 1.0).abs() < 1e-12, "{depth}");
    let dipped = from_file(
        "pad-tapered-to-1mm.toml",
        &[
            "bodies[0].blocks[0].corners=[[-30.0, 0.0], [30.0, 0.0], [30.0, 20.0], [-30.0, 20.0]]",
            "bodies[0].blocks[0].arcs=[{ edge = 2, center = [0.0, 42.5] }]",
            "bodies[0].blocks[0].u=2",
        ],
    );
    let (_, depth) = validity::worn_blocks_depth(&dipped, 0).expect("a depth");
    // The arc's lowest point lies at the symmetric parameter u = 1/2: round-off of its map.
    assert!((depth - 5.0).abs() < 1e-9, "{depth}");
}

/// The trunk space on elements mapped from arcs: a steel roller (R = 50 mm, its arc exact) on
/// an aluminium flat in plane stress, P = 46 MPa × 40 mm per mm of thickness. Hertz (Johnson
/// §4.3): 1/E* = 1/E₁ + 1/E₂, a = √(4PR/(πE*)), p(x) = p₀√(1 − x²/a²), p₀ = 2P/(πa). The
/// tensor space is within 0.5 % of p₀ inside 0.8 a (a finite flat's offset, 0.18 %). The
/// trunk space's bound is not from theory but the weakness measured (2.75 % in a red team's
/// run, L): more than 1 % off somewhere there, which is why it is warned about; the built-in Hertz, flat blocks, is not (the trunk space is as good on
/// parallelograms).
#[test]
fn the_trunk_space_on_arcs_is_warned_about() {
    let (e_star, force, radius) = (1.0 / (1.0 / 2.1e5 + 1.0 / 7.0e4), 46.0 * 40.0, 50.0);
    let a = (4.0 * force * radius / (std::f64::consts::PI * e_star)).sqrt();
    let p0 = 2.0 * force / (std::f64::consts::PI * a);
    let off_hertz = |space: &str| {
        let problem = from_file(
            "roller-on-flat-arcs.toml",
            &[
                &format!("analysis.space=\"{space}\""),
                "analysis.p_check=false",
            ],
        );
        let (summary, contact, solution, _) = driver::contact(&problem).unwrap();
        let error = contact
            .points
            .x
            .iter()
            .zip(&solution.pressure)
            .filter(|(x, _)| x[0].abs() < 0.8 * a)
            .map(|(x, p)| (p - p0 * (1.0 - (x[0] / a).powi(2)).sqrt()).abs() / p0)
            .fold(0.0, f64::max);
        let warned = summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().contains("analysis.space = \"trunk\""));
        (error, warned)
    };
    let (tensor, tensor_warned) = off_hertz("tensor");
    assert!(tensor < 0.005 && !tensor_warned, "tensor: {tensor}");
    let (trunk, trunk_warned) = off_hertz("trunk");
    assert!(trunk > 0.01 && trunk_warned, "trunk: {trunk}");
    let flat = builtin(
        "hertz",
        &["analysis.space=\"trunk\"", "analysis.p_check=false"],
    );
    let (summary, ..) = driver::contact(&flat).unwrap();
    assert!(
        !summary["warnings"].to_string().contains("trunk"),
        "{summary}"
    );
}
