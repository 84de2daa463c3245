//! The monotonic steady shapes (paper eq. 38) and the averaged shape (eq. 39) of Example 1
//! against the ordinates the paper prints in §6.2.1, and of the brake (Fig. 14).

mod common;
use common::problem;
use wearfem::contact::CondensedContact;
use wearfem::monotonic_shape::{averaged_shape, AveragedReading};
use wearfem::wear::WearIntegrator;

/// The averaged monotonic shape of Example 1 as printed in §6.2.1 (x mm, Shape mm), typed in
/// from the paper's table (points 3–17; point 7 is illegible in our copy, 1 and 2 are not
/// printed).
const PRINTED: [(f64, f64); 14] = [
    (1071.5, 0.14934270e-2),
    (1073.63, 0.11869800e-2),
    (1075.75, 0.95190000e-3),
    (1077.88, 0.76108000e-3),
    (1090.0, 0.13810000e-3),
    (1100.0, 0.0),
    (1113.63, 0.26240500e-3),
    (1120.0, 0.60244000e-3),
    (1122.13, 0.76135000e-3),
    (1124.25, 0.95234000e-3),
    (1126.38, 0.11876850e-2),
    (1128.5, 0.14945845e-2),
    (1129.25, 0.16349025e-2),
    (1130.0, 0.18279500e-2),
];

fn averaged(name: &str, edits: &[(&str, &str)], reading: AveragedReading) -> (Vec<f64>, Vec<f64>) {
    let p = problem(name, edits);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    let avg = averaged_shape(&contact, &terms, reading).unwrap();
    (contact.points.x.iter().map(|q| q[0]).collect(), avg.shape)
}

/// Largest |ours − printed| over the printed ordinates, as a fraction of the largest printed.
fn misfit(kind: &str, reading: AveragedReading) -> f64 {
    let edit = [("kind = \"plane_stress\"", &*format!("kind = \"{kind}\""))];
    let (x, shape) = averaged("punch-a", &edit, reading);
    let largest = PRINTED.iter().map(|p| p.1).fold(0.0, f64::max);
    PRINTED
        .iter()
        .map(|&(xp, sp)| (wearfem::spline_method::interpolate(&x, &shape, xp) - sp).abs())
        .fold(0.0, f64::max)
        / largest
}

#[test]
fn printed_averaged_shape_is_the_mean_of_the_monotonic_shapes_in_plane_strain() {
    // The criterion: every printed ordinate to 3 % of the largest. The paper's mesh
    // and spline points are not ours, so a few per cent is what can be asked. Measured: 2.5 %
    // for the mean in plane strain; the mean in plane stress misses by 7.9 %, the sum by 95 %
    // (plane strain) and 116 % (plane stress), so the verdict does not hang on the tolerance.
    let fit = misfit("plane_strain", AveragedReading::Mean);
    eprintln!("plane_strain Mean: misfit {:.2} %", 100.0 * fit);
    assert!(
        fit < 0.03,
        "mean, plane strain: misfit {:.2} %",
        100.0 * fit
    );
    for (kind, reading) in [
        ("plane_stress", AveragedReading::Mean),
        ("plane_stress", AveragedReading::Sum),
        ("plane_strain", AveragedReading::Sum),
    ] {
        let m = misfit(kind, reading);
        eprintln!("{kind} {reading:?}: misfit {:.2} %", 100.0 * m);
        assert!(
            m > 0.05,
            "{kind} {reading:?}: misfit only {:.2} %",
            100.0 * m
        );
    }
}

#[test]
fn translating_punch_monotonic_shapes_are_mirror_images_under_uniform_pressure() {
    let p = problem("punch-a", &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    let sum = averaged_shape(&contact, &terms, AveragedReading::Sum).unwrap();
    let mean = averaged_shape(&contact, &terms, AveragedReading::Mean).unwrap();
    // §6.1: the monotonic optimum of a translating flat punch is the uniform p̃ = F₀/(L t);
    // the steady solve is exact, so round-off only.
    let p_tilde = 16.666;
    for shape in [&sum.left, &sum.right] {
        for p in &shape.pressure {
            assert!((p - p_tilde).abs() < 1e-9 * p_tilde, "{p}");
        }
    }
    // The model is symmetric about x = 1100 (punch, strip mesh, load), and reversing the
    // sliding mirrors the friction: shape⁽ʳ⁾(x) = shape⁽ˡ⁾(2200 − x), the contact points being
    // symmetric too. Round-off of the condensed flexibility, hence 1e-8 of the range.
    let n = contact.len();
    let range = sum.left.shape.iter().cloned().fold(0.0, f64::max);
    assert!(range > 0.0);
    for i in 0..n {
        let mirror = n - 1 - i;
        assert!((contact.points.x[i][0] + contact.points.x[mirror][0] - 2200.0).abs() < 1e-9);
        let (l, r) = (sum.left.shape[i], sum.right.shape[mirror]);
        assert!((l - r).abs() < 1e-8 * range, "point {i}: {l} vs {r}");
    }
    // Zeroing as the paper does: g(1070) = 0 leftward, g(1130) = 0 rightward, Shape⁽ᵃ⁾(1100) = 0.
    assert_eq!(sum.left.shape[0], 0.0);
    assert_eq!(sum.right.shape[n - 1], 0.0);
    assert!(sum.shape[sum.mid].abs() < 1e-15);
    assert!((contact.points.x[sum.mid][0] - 1100.0).abs() < 1e-9);
    for (s, m) in sum.shape.iter().zip(&mean.shape) {
        assert!((s - 2.0 * m).abs() < 1e-15);
    }
}

#[test]
fn brake_averaged_shape_does_not_depend_on_friction_and_overestimates_the_steady_shape() {
    // §5.2: "the shape does not depend on the coefficient of friction" ([13]) and "the
    // averaging technique ... provides an overestimated wear form" (Fig. 14). Both shapes are
    // moved by the plate's vertical motion (gap pattern cos α) to zero at the contact ends, so
    // that the crown value is the depth of the worn form.
    let mut crowns = Vec::new();
    for mu in ["0.25", "0.0", "0.5"] {
        let p = problem(
            "brake",
            &[("friction = 0.25", &*format!("friction = {mu}"))],
        );
        let (contact, _, _) = CondensedContact::build(&p).unwrap();
        let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
            .unwrap()
            .half_period_wear();
        let avg = averaged_shape(&contact, &terms, AveragedReading::Mean).unwrap();
        let (exact, _, _) = wearfem::driver::steady(&p).unwrap();
        let r = contact.rigid_gap_matrix();
        let from_ends = |g: &[f64]| g[avg.mid] - g[0] / r[0] * r[avg.mid];
        let (a, e) = (from_ends(&avg.shape), from_ends(&exact.shape));
        assert!(a.abs() > e.abs(), "μ = {mu}: averaged {a:e} vs exact {e:e}");
        crowns.push(a);
    }
    // Friction cancels between the two directions: round-off of the flexibility only.
    for c in &crowns[1..] {
        assert!((c - crowns[0]).abs() < 1e-9 * crowns[0].abs(), "{crowns:?}");
    }
}

#[test]
fn brake_fig14_level_is_of_the_order_of_the_accumulated_wear_not_of_an_elastic_shape() {
    // The paper's Fig. 14 crown values (0.07503 mm averaged, 0.07456 mm from time
    // integration) are 50 times any elastic shape of this brake: the monotonic shapes' crown
    // depth is below 3 µm and so is the plate's elastic approach under 10 kN.
    let p = problem("brake", &[]);
    let (contact, _, _) = CondensedContact::build(&p).unwrap();
    let terms = WearIntegrator::new(p.spec.wear.as_ref().unwrap())
        .unwrap()
        .half_period_wear();
    let avg = averaged_shape(&contact, &terms, AveragedReading::Sum).unwrap();
    let r = contact.rigid_gap_matrix();
    let crown = (avg.shape[avg.mid] - avg.shape[0] / r[0] * r[avg.mid]).abs();
    assert!(crown < 0.1 * 0.07456, "averaged crown depth {crown:e} mm");
    // The wear accumulated at the crown over the paper's run (12 100 steps, eq. 30: 120 300
    // half periods) is of the paper's order. Theory: at the steady rate every period wears
    // β̃ 2u₀ · 2p_m^C at the crown (eq. 35b–37, 2p_m^C = 10.4235 MPa by eq. A.15), 60 150
    // periods. The integrated value differs by the transient (p_Σ(0) rises from 9.7 MPa to
    // its steady value over the first ~5000 steps): 2 % bounds that.
    let run = common::run(&p, None);
    let c: f64 = terms.iter().map(|t| t.0).sum(); // β̃ 2u₀, mm/MPa per half period
    let integrated: f64 = run
        .history
        .steps
        .iter()
        .map(|s| s.k as f64 * c * s.probes[0])
        .sum();
    let half_periods = run.history.steps.last().unwrap().half_period as f64;
    assert_eq!(half_periods, 120_300.0);
    let theory = c * 10.4235 * half_periods / 2.0;
    assert!(
        (integrated - theory).abs() < 0.02 * theory,
        "crown wear {integrated:e} mm vs steady-rate {theory:e} mm"
    );
    // With the printed β̃₁ = 0.5π·10⁻⁸ that is 0.029 mm, 2.5 times below the paper's
    // 0.0746 mm; β̃₁ = 1.25π·10⁻⁸ (Example 1's) would give 0.073 mm. Recorded, not asserted
    // as an explanation: the bound only checks the factor between 2 and 3.
    let ratio = 0.07456 / integrated;
    assert!(ratio > 2.0 && ratio < 3.0, "paper / ours = {ratio}");
}
