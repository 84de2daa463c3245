//! The check of the resolution in p (src/checks/p_check.rs): a mesh too coarse for the contact
//! that refining the contact edge cannot show is found by raising p.

use wearfem::driver;
use wearfem::overrides::Override;
use wearfem::p_check::{depth_warnings, p_check, P_CHANGE_LIMIT};
use wearfem::problem::Problem;

const RIGID_PUNCH: &str = include_str!("problems/rigid-punch-deep-layers.toml");

fn problem(text: &str, sets: &[&str]) -> Problem {
    let o: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    Problem::with_overrides(text, "p-check test", &o).unwrap()
}

/// The first contact solve's pressure at x = 0 (MPa), its warnings, and the p check's change.
fn centre_pressure(p: &Problem) -> (f64, Vec<String>, f64) {
    let (summary, contact, solution, _) = driver::contact(p).unwrap();
    let centre = (0..contact.len())
        .min_by(|&a, &b| {
            contact.points.x[a][0]
                .abs()
                .total_cmp(&contact.points.x[b][0].abs())
        })
        .unwrap();
    let warnings = summary["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect();
    let change = p_check(p, &contact).unwrap().unwrap().change;
    (solution.pressure[centre], warnings, change)
}

/// Red team 11, F1: a nearly rigid 40 mm punch (E = 1e9 MPa) pressed by 400 N/mm on a steel
/// block of 1000 × 500 mm, nearly a half plane, whose closed form is p(x) = P / (π √(a² − x²)),
/// p(0) = 400 / (20 π) = 6.3662 MPa. In layers 125 mm deep the block gives 5.962 MPa (6.4 %
/// low), the same for 8 and 128 contact elements, with no other warning; graded in depth it
/// gives 6.287 (1.2 % low) and, finer along x, 6.345 (0.3 %). The check must warn on the first
/// and on no graded one.
#[test]
fn a_block_coarse_in_depth_is_found_by_raising_p() {
    let closed_form = 400.0 / (20.0 * std::f64::consts::PI);
    let graded = "bodies[1].blocks[0].v=[0, 0.5, 0.8, 0.9, 0.95, 0.98, 0.99, 0.996, 1]";
    for (sets, error_at_least, error_at_most, warned) in [
        (&[][..], 0.05, 0.08, true),
        (&["bodies[0].blocks[0].u=128"][..], 0.05, 0.08, true),
        (&[graded][..], 0.0, 0.02, false),
        (
            &[graded, "bodies[1].blocks[0].u=100"][..],
            0.0,
            0.005,
            false,
        ),
    ] {
        let p = problem(RIGID_PUNCH, sets);
        let (centre, warnings, change) = centre_pressure(&p);
        let error = 1.0 - centre / closed_form;
        // The bands bracket the errors above; they only assert that the case is the one
        // described (coarse: well off; graded: close), not our own numbers to the digit.
        assert!(
            (error_at_least..error_at_most).contains(&error),
            "{sets:?}: p(0) = {centre}, {error}"
        );
        let said = warnings.iter().any(|w| w.contains("not converged in p"));
        assert_eq!(said, warned, "{sets:?}: change {change}, {warnings:?}");
        // The layers are 3.1 times as deep as the zone is long; graded, far less.
        let deep = warnings
            .iter()
            .any(|w| w.contains("mm deep under a contact zone"));
        assert_eq!(deep, warned, "{sets:?}: {warnings:?}");
        assert_eq!(change > P_CHANGE_LIMIT, warned, "{sets:?}: change {change}");
    }
}

/// The shipped examples pass (docs/validation.md quotes their changes), and a Hertz contact at
/// p = 2, 2.4 % off its closed form inside 0.8 a (red team 11, F5), is named.
#[test]
fn shipped_examples_pass_and_quadratic_hertz_is_named() {
    for name in wearfem::examples::EXAMPLES.iter().map(|e| e.0) {
        let p = problem(wearfem::examples::example(name).unwrap(), &[]);
        if p.spec.contact.is_none() {
            continue;
        }
        let (contact, _, _) = wearfem::contact::CondensedContact::build(&p).unwrap();
        let change = p_check(&p, &contact).unwrap().unwrap().change;
        if name == "tribometer" || name == "block-on-ring" {
            // Meshed for their worn states (a flat 0.57 mm wide on the cylinder, a scar about
            // 2.5 mm wide on the block), not for their first Hertz contacts (0.115 and 0.46
            // mm wide), as their descriptions say: the check must say so.
            assert!(change > P_CHANGE_LIMIT, "{name}: {change}");
            continue;
        }
        assert!(change < P_CHANGE_LIMIT, "{name}: {change}");
    }
    let hertz = problem(
        wearfem::examples::example("hertz").unwrap(),
        &["analysis.p=2"],
    );
    let (contact, _, _) = wearfem::contact::CondensedContact::build(&hertz).unwrap();
    let change = p_check(&hertz, &contact).unwrap().unwrap().change;
    assert!(change > P_CHANGE_LIMIT, "hertz p = 2: {change}");
}

/// Red team 12: where the pressure converges slowly in p, raising p by 2 understates the
/// error (the block in 2 layers, 250 mm under the 40 mm zone, at p = 10: change 1.6 %, error
/// 10 %; Hertz on a block one element, 100 mm, deep: 1.7 % against 4.5 %). The depth of the
/// elements under the zone names both; the shipped examples' elements are at most 0.56 times
/// as deep as their zones are long (the pin's flat), and name none.
#[test]
fn elements_deeper_than_the_zone_is_long_are_named() {
    let deep = |p: &Problem| {
        let (contact, _, _) = wearfem::contact::CondensedContact::build(p).unwrap();
        depth_warnings(p, &contact)
    };
    let two_layers = problem(RIGID_PUNCH, &["bodies[1].blocks[0].v=2", "analysis.p=10"]);
    assert!(
        deep(&two_layers).iter().any(|w| w.contains("250 mm deep")),
        "{:?}",
        deep(&two_layers)
    );
    let hertz = problem(
        wearfem::examples::example("hertz").unwrap(),
        &["bodies[1].blocks[0].v=1"],
    );
    assert!(
        deep(&hertz)
            .iter()
            .any(|w| w.contains("\"block\" has elements 100 mm deep")),
        "{:?}",
        deep(&hertz)
    );
    for name in wearfem::examples::EXAMPLES.iter().map(|e| e.0) {
        let p = problem(wearfem::examples::example(name).unwrap(), &[]);
        if p.spec.contact.is_some() {
            assert!(deep(&p).is_empty(), "{name}: {:?}", deep(&p));
        }
    }
}

/// Red team 12: at p = 19 the check compared with p = 20, odd against even, and warned of a
/// 6.4 % change on punch-b40 (17 against 19: 0.34 %); at p = 20 it said nothing. Where p + 2
/// passes 20 it compares with p − 2, of the same parity.
#[test]
fn the_highest_degrees_are_compared_with_p_minus_2() {
    for p in [19, 20] {
        let b40 = problem(
            wearfem::examples::example("punch-b40").unwrap(),
            &[&format!("analysis.p={p}")],
        );
        let (contact, _, _) = wearfem::contact::CondensedContact::build(&b40).unwrap();
        let check = p_check(&b40, &contact).unwrap().unwrap();
        assert!(
            check.degrees.iter().all(|d| d.2 == p - 2),
            "{:?}",
            check.degrees
        );
        assert!(check.change < P_CHANGE_LIMIT, "p = {p}: {}", check.change);
    }
}

/// `analysis.p_check = false` turns the check off in a single job; a study makes it only
/// where the key is true.
#[test]
fn the_check_follows_analysis_p_check() {
    let coarse = |value: Option<&str>| {
        let set = value.map(|v| format!("analysis.p_check={v}"));
        problem(
            RIGID_PUNCH,
            &set.iter().map(String::as_str).collect::<Vec<_>>(),
        )
    };
    let named = |w: &[String]| w.iter().any(|w| w.contains("not converged in p"));
    for (value, single, study) in [
        (None, true, false),
        (Some("false"), false, false),
        (Some("true"), true, true),
    ] {
        let p = coarse(value);
        let (state, contact, _) = driver::steady(&p).unwrap();
        assert_eq!(
            named(&driver::steady_warnings(&p, &contact, &state)),
            single,
            "{value:?}"
        );
        assert_eq!(
            named(&driver::study_steady_warnings(&p, &contact, &state)),
            study,
            "{value:?}"
        );
    }
}

/// The p-check judges the first contact; for a steady state its warning says so, since the
/// steady zones can be wider (red team J: punch-a with a 2 m crown warned of 5.1 %, while its
/// steady state is the flat punch's: equal to it to round-off here, and the flat one passes).
#[test]
fn a_steady_state_s_p_warning_says_it_measures_the_first_contact() {
    let text = wearfem::examples::example("punch-a").unwrap();
    let crowned = problem(
        text,
        &["contact.initial_shape={radius=2000.0, center_x=1100.0}"],
    );
    let (state, contact, _) = driver::steady(&crowned).unwrap();
    let warnings = driver::steady_warnings(&crowned, &contact, &state);
    let p_warning = warnings
        .iter()
        .find(|w| w.contains("not converged in p"))
        .expect("the first contact is not resolved");
    assert!(
        p_warning.contains("for a steady state this measures the first contact"),
        "{p_warning}"
    );
    let flat = problem(text, &[]);
    let (flat_state, flat_contact, _) = driver::steady(&flat).unwrap();
    let peak = flat_state.p_plus.iter().cloned().fold(0.0, f64::max);
    for (a, b) in state.p_plus.iter().zip(&flat_state.p_plus) {
        // The premise: the same steady state (1e-9 of the peak: the iteration's round-off).
        assert!((a - b).abs() < 1e-9 * peak, "{a} against {b}");
    }
    let flat_warnings = driver::steady_warnings(&flat, &flat_contact, &flat_state);
    assert!(!flat_warnings
        .iter()
        .any(|w| w.contains("not converged in p")));
    // The contact job's own warning is about the first contact and needs no such note.
    let (summary, ..) = driver::contact(&crowned).unwrap();
    assert!(!summary["warnings"]
        .to_string()
        .contains("For a steady state"));
}

#[test]
fn a_run_s_warning_says_its_zone_outgrew_the_one_checked() {
    // Red team 22's cylinder wearing its flat (tests/problems/cylinder-wears-its-flat.toml):
    // its first, Hertzian zone (0.29 mm over 0.8 mm deep elements) changes by 5 % from p = 8
    // to 10, while the flat it wears (6.6 mm) is far wider. The run's warning says which state
    // it measured and that the run's zone outgrew it (issue 28, item 7), so that it is not read
    // as a verdict on the worn state.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/cylinder-wears-its-flat.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let problem = wearfem::problem::Problem::from_toml(&text, path).unwrap();
    let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
    let first = wearfem::p_check::p_check(&problem, &run.contact)
        .unwrap()
        .unwrap();
    assert!(first.change > 0.02, "the first solve: {}", first.change);
    let warnings = run.warnings(&problem).join("\n");
    assert!(
        warnings.contains("the first contact solve's pressure")
            && warnings.contains("the run's zone grew to")
            && warnings.contains("it concerns the run's early states"),
        "{warnings}"
    );
    // The shipped punch, whose zone does not grow, is told nothing of the kind.
    let punch = wearfem::problem::Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap();
    let run = wearfem::driver::wear(&punch, Some(100), |_| {}).unwrap();
    assert!(
        run.warnings(&punch).is_empty(),
        "{:?}",
        run.warnings(&punch)
    );
}
