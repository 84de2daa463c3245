//! Each body's own wear (issue 28, item 4): the depth worn off body 1 and off body 2, and the
//! worn volumes, against Archard's law integrated by hand.

use wearfem::driver;
use wearfem::problem::Problem;

const BODY1: &str = "body1 = { beta = 3.9269908169872414e-8, a = 1.0, b = 1.0 }   # 1.25π·10⁻⁸";
const RECORD: &str = "record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]";

/// The built-in example `name` with body 2 wearing by `body2` (a wear-law table) beside body
/// 1, every one of `steps` steps recorded, and `extra` appended to `[wear]`.
fn both_wearing(name: &str, body2: &str, steps: usize, extra: &str) -> Problem {
    let text = wearfem::examples::example(name).unwrap().to_string();
    both_wearing_in(&text, name, body2, steps, extra)
}

/// [`both_wearing`] on the problem file `text`.
fn both_wearing_in(text: &str, name: &str, body2: &str, steps: usize, extra: &str) -> Problem {
    assert!(
        text.contains(BODY1) && text.contains(RECORD),
        "{name} changed"
    );
    let list: Vec<String> = (1..=steps).map(|s| s.to_string()).collect();
    let text = text
        .replace(BODY1, &format!("{BODY1}\nbody2 = {body2}"))
        .replace(RECORD, &format!("record = [{}]\n{extra}", list.join(", ")));
    Problem::from_toml(&text, name).unwrap()
}

/// The punch's load F = 16.666 MPa × 60 mm × t (N) and the thickness t (mm) of punch-a/b.
const FORCE: f64 = 16.666 * 60.0 * 10.0;
const THICKNESS: f64 = 10.0;
const BETA1: f64 = 3.9269908169872414e-8;

#[test]
fn each_bodys_worn_volume_is_its_own_archard_volume() {
    // a = b = 1: each body loses β̃ᵢ p |v| per unit area and time, so over the run its volume
    // is β̃ᵢ F s (s the sliding distance, mm), whatever the pressure's distribution: the flat
    // punch's contact forces sum to F. Both laws have the same exponent, so each body's
    // share is the same at every point, and the split is exact for every scheme: round-off
    // of a 65-term sum, 1e-9 (the issue asks 1e-6). Without `shape_zero_at`, so that the
    // total comes from the shape the scheme integrated, not from the summed wear.
    let beta2 = 0.6 * BETA1;
    let text = wearfem::examples::example("punch-a")
        .unwrap()
        .replace("shape_zero_at = 1100.0", "");
    for extra in [
        "",
        "adaptive = { method = \"bdf2\" }",
        "adaptive = { method = \"step_doubling\" }",
    ] {
        let problem = both_wearing_in(
            &text,
            "punch-a, no shift",
            &format!("{{ beta = {beta2}, a = 1.0, b = 1.0 }}"),
            120,
            extra,
        );
        let run = driver::wear(&problem, Some(120), |_| {}).unwrap();
        let summary = run.summary(&problem);
        let sliding = summary["sliding_distance_m"].as_f64().unwrap() * 1000.0;
        let volumes: Vec<f64> = summary["worn_volume"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        for (body, beta) in [(0, BETA1), (1, beta2)] {
            let expected = beta * FORCE * sliding;
            assert!(
                (volumes[body] / expected - 1.0).abs() < 1e-9,
                "{extra:?}: body {}: {:.9e} mm³ against β̃ F s = {expected:.9e}",
                body + 1,
                volumes[body]
            );
            // Per unit thickness, as the issue states it.
            let per_thickness = volumes[body] / THICKNESS;
            assert!((per_thickness / (beta * FORCE * sliding / THICKNESS) - 1.0).abs() < 1e-9);
        }
        // Pointwise: the two add up to the shape's change, in the laws' ratio.
        let h = &run.history;
        let wear = run.wear_of(&h.shape);
        let largest = wear.iter().cloned().fold(0.0, f64::max);
        for (i, total) in wear.iter().enumerate() {
            let [one, two] = [h.body_wear[0][i], h.body_wear[1][i]];
            assert!((one + two - total).abs() < 1e-12 * largest);
            assert!((two - 0.6 * one).abs() < 1e-12 * largest);
        }
    }
}

#[test]
fn shifting_the_shape_to_zero_removes_no_material() {
    // punch-b40 shifts its shape to zero at the pin after every cycle (wear.shape_zero_at): a
    // rigid translation of the punch, which the plate takes up. The material each body loses
    // is the same with and without it; the implicit scheme's summed wear is exact, so to
    // round-off (1e-9 of the deepest wear).
    let law = format!("{{ beta = {}, a = 1.0, b = 1.0 }}", 0.3 * BETA1);
    let shifted = both_wearing("punch-b40", &law, 60, "");
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace(BODY1, &format!("{BODY1}\nbody2 = {law}"))
        .replace("shape_zero_at = 1100.0", "");
    let plain = Problem::from_toml(&text, "punch-b40, no shift").unwrap();
    let a = driver::wear(&shifted, Some(60), |_| {}).unwrap().history;
    let b = driver::wear(&plain, Some(60), |_| {}).unwrap().history;
    let deepest = b.body_wear[0].iter().cloned().fold(0.0, f64::max);
    assert!(deepest > 0.0);
    for body in 0..2 {
        for (x, y) in a.body_wear[body].iter().zip(&b.body_wear[body]) {
            assert!(
                (x - y).abs() < 1e-9 * deepest,
                "body {}: {x} vs {y}",
                body + 1
            );
        }
    }
}

#[test]
fn a_body_with_its_own_exponent_wears_by_its_own_law() {
    // Body 2 wears by p² (b = 2), body 1 by p: body 2's volume is then β̃₂ t Σ_steps k s_h
    // Σᵢ wᵢ pᵢ², which the recorded pressures of every step give by hand (s_h = 2u₀ per half
    // period). The wear each step applies is that of the pressure it records (measured
    // agreement 1e-10); 1e-6 leaves room for round-off over 80 steps, and is far below what
    // a body worn by the other's law would give (a factor of p̄ ≈ 17 MPa).
    let beta2 = 2.0e-10;
    let problem = both_wearing(
        "punch-a",
        &format!("{{ beta = {beta2}, a = 1.0, b = 2.0 }}"),
        80,
        "",
    );
    let run = driver::wear(&problem, Some(80), |_| {}).unwrap();
    let h = &run.history;
    let points = &run.contact.points;
    let sliding = 2.0 * problem.spec.wear.as_ref().unwrap().amplitude;
    let mut half_periods = 0;
    let mut by_hand = 0.0;
    for s in &h.snapshots {
        let k = (s.half_period - half_periods) as f64;
        half_periods = s.half_period;
        let sum: f64 = (0..points.x.len())
            .map(|i| points.weight[i] * s.pressure[i].max(0.0).powi(2))
            .sum();
        by_hand += k * beta2 * sliding * THICKNESS * sum;
    }
    assert_eq!(h.snapshots.len(), 80);
    let ours = wearfem::wear::worn_volume(points, &h.body_wear[1], THICKNESS);
    eprintln!("body 2: {ours:.9e} mm³, by hand {by_hand:.9e}");
    assert!(
        (ours / by_hand - 1.0).abs() < 1e-6,
        "body 2: {ours:.6e} mm³ against {by_hand:.6e} by hand"
    );
    // Body 1's by a = b = 1: β̃₁ F s.
    let ours = wearfem::wear::worn_volume(points, &h.body_wear[0], THICKNESS);
    let expected = BETA1 * FORCE * sliding * half_periods as f64;
    assert!(
        (ours / expected - 1.0).abs() < 1e-3,
        "body 1: {ours} vs {expected}"
    );
}
