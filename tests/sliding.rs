//! Sliding contact pairs (`contact.pairs = "sliding"`, issue 29) against what must hold
//! whatever the meshes: Archard's law per body, the trough a long stroke paints on a flat,
//! and the fixed pairs' results as the stroke goes to zero.

use wearfem::jobs::sliding::{self, SlidingRun};
use wearfem::problem::Problem;

/// A cylinder of radius `radius` (contact.initial_shape) on a long steel flat, sliding pairs;
/// `wear` is the `[wear]` section's body, `extra` is added to `[contact]`.
fn slider_on_flat(radius: f64, wear: &str, extra: &str) -> String {
    format!(
        r#"
title = "a slider on a long flat"
[analysis]
kind = "plane_strain"
thickness = 10.0
p = 6
[materials.steel]
young = 2.0e5
poisson = 0.3
[materials.bronze]
young = 1.1e5
poisson = 0.34
[[bodies]]
name = "slider"
[[bodies.blocks]]
corners = [[-5.0, 0.0], [5.0, 0.0], [5.0, 5.0], [-5.0, 5.0]]
u = 16
v = [0.0, 0.2, 0.5, 1.0]
material = "bronze"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = 10.0
[[bodies]]
name = "flat"
[[bodies.blocks]]
corners = [[-70.0, -20.0], [70.0, -20.0], [70.0, 0.0], [-70.0, 0.0]]
u = 210
v = [0.0, 0.5, 0.8, 1.0]
material = "steel"
names = {{ bottom = "base", top = "surface" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[contact]
body = "slider"
edge = "contact"
target_body = "flat"
target_edge = "surface"
friction = 0.3
pairs = "sliding"
initial_shape = {{ radius = {radius}, center_x = 0.0 }}
{extra}
[plate]
edge = "top"
motion = "vertical"
[wear]
sliding = "reciprocating"
omega = 10.0
{wear}
"#
    )
}

fn run(text: &str) -> SlidingRun {
    let problem = Problem::from_toml(text, "sliding-test").unwrap();
    let run = sliding::wear(&problem, None).unwrap();
    assert!(run.history.stopped.is_none(), "{:?}", run.history.stopped);
    run
}

/// The load per unit thickness F/t, N/mm: 10 MPa over the slider's 10 mm top.
const LOAD_PER_THICKNESS: f64 = 100.0;

#[test]
fn each_body_wears_archards_volume_at_every_step() {
    // a = b = 1: body i's worn area (per unit thickness) is β̃ᵢ F s / t for the sliding
    // distance s, whatever the pressure: each position's pressures balance the load
    // exactly (Σ pᵢ wᵢ t = F on a flat edge, friction being tangential there), and the
    // positions' intervals add up to the stroke. Extrapolated steps (k = 5) included.
    let text = slider_on_flat(
        2000.0,
        "body1 = { beta = 2.0e-7, a = 1.0, b = 1.0 }\nbody2 = { beta = 5.0e-7, a = 1.0, b = 1.0 }\namplitude = 4.0\nsteps = 12\nextrapolation = [{ until = 4, k = 1 }, { k = 5 }]",
        "positions = 12",
    );
    let run = run(&text);
    let stroke = 8.0;
    for step in &run.history.steps {
        let s = stroke * step.half_period as f64;
        for (body, beta) in [(0, 2.0e-7), (1, 5.0e-7)] {
            let expected = beta * LOAD_PER_THICKNESS * s;
            let relative = (step.worn_area[body] - expected).abs() / expected;
            // The solver's equilibrium residual (1e-10 of the load and below) and the sums'
            // round-off; the issue asks 1e-6.
            assert!(
                relative < 1e-6,
                "step {}: body {} worn area {} against {expected} ({relative:.2e})",
                step.step,
                body + 1,
                step.worn_area[body]
            );
        }
    }
}

#[test]
fn a_long_stroke_paints_a_flat_bottomed_trough() {
    // Stroke 2u₀ = 100 mm against a contact about 5 mm wide, only the flat wearing, one half
    // period. Every track point passed over by the whole contact collects β̃₂ ∫ p dx =
    // β̃₂ F/t (whatever the pressure's shape); the trough ends in ramps as wide as the
    // contact at the stroke's ends, and nothing lies beyond them.
    let beta = 1.0e-6;
    let text = slider_on_flat(
        5000.0,
        "body2 = { beta = 1.0e-6, a = 1.0, b = 1.0 }\namplitude = 50.0\nsteps = 1\nextrapolation = [{ k = 1 }]",
        "",
    );
    let run = run(&text);
    let depth = beta * LOAD_PER_THICKNESS;
    let track = &run.history.track;
    let x = track.centres();
    let contact_edge = 10.0; // the slider's width bounds the contact zone
    for (xi, w) in x.iter().zip(&track.wear) {
        if xi.abs() < 30.0 {
            // Where the whole contact passes over a point with the pressure's shape
            // unchanged. Nearer the stroke's ends the flat's own ends (15–20 mm beyond)
            // change the pressure's shape along the stroke, and the depth with it (0.5 % at
            // x = 44.8 mm); the convolution below covers those points. 0.5 % is what the
            // issue asks of the trough.
            assert!(
                (w - depth).abs() < 5e-3 * depth,
                "x = {xi}: depth {w} against {depth}"
            );
        }
        if xi.abs() > 50.0 + contact_edge / 2.0 + track.cell {
            assert_eq!(*w, 0.0, "x = {xi}: wear beyond the stroke's reach");
        }
    }
    // Against the convolution of the position-resolved pressure with the stroke, evaluated
    // independently of the track's cells: at a track point X, Σ_j ∫ p_j(X + s) ds over
    // position j's interval, p_j the polynomial of degree p through each element's points
    // (the field the contact points' Lobatto weights integrate exactly), integrated by the
    // midpoint rule with 40 points per interval.
    let contact = &run.contact;
    let points: Vec<f64> = contact.contacts[0].points.x.iter().map(|p| p[0]).collect();
    let degree = 6;
    let pressure_at = |p: &[f64], x: f64| -> f64 {
        if x <= points[0] || x >= points[points.len() - 1] {
            return 0.0;
        }
        let element = (points.partition_point(|&xi| xi <= x) - 1) / degree;
        let nodes = element * degree..=element * degree + degree;
        nodes
            .clone()
            .map(|a| {
                let lagrange: f64 = nodes
                    .clone()
                    .filter(|&b| b != a)
                    .map(|b| (x - points[b]) / (points[a] - points[b]))
                    .product();
                lagrange * p[a]
            })
            .sum()
    };
    let forward = &run.history.last_cycle[0];
    let ends = &contact.stroke.ends;
    let mut worst = 0.0f64;
    for probe in [
        -52.0, -50.5, -48.0, -20.0, 0.0, 33.3, 48.7, 50.0, 51.5, 53.0,
    ] {
        let mut expected = 0.0;
        for (j, p) in forward.iter().enumerate() {
            let (a, b) = (ends[j], ends[j + 1]);
            let n = 40;
            for q in 0..n {
                let s = a + (b - a) * (q as f64 + 0.5) / n as f64;
                expected += pressure_at(p, probe + s) * (b - a) / n as f64;
            }
        }
        worst = worst.max((track.at(probe) - beta * expected).abs());
    }
    // 0.5 % of the trough's depth, as the issue asks.
    assert!(worst < 5e-3 * depth, "worst {worst} against depth {depth}");
}

/// punch-b40 on mortar traces, both bodies wearing, `shape_zero_at` removed (sliding pairs
/// have no shift), with the amplitude and body 2's law given.
fn punch(amplitude: f64, scale: f64, sliding: bool) -> Problem {
    let text = wearfem::examples::example("punch-b40").unwrap();
    let text = text
        .replace("discretisation = \"collocation\"", "discretisation = \"mortar\"")
        .replace("shape_zero_at = 1100.0", "")
        .replace("amplitude = 1.5 ", &format!("amplitude = {amplitude} "))
        .replace(
            "body1 = { beta = 3.9269908169872414e-8, a = 1.0, b = 1.0 }",
            &format!(
                "body1 = {{ beta = {}, a = 1.0, b = 1.0 }}\nbody2 = {{ beta = {}, a = 1.0, b = 1.0 }}",
                3.9269908169872414e-8 * scale,
                1.0e-8 * scale
            ),
        )
        .replace("steps = 1700 ", "steps = 300 ")
        .replace("record = [1, 2, 50, 100, 200, 500, 1000, 1699, 1700]", "");
    let text = if sliding {
        text.replace(
            "discretisation = \"mortar\"",
            "discretisation = \"mortar\"\npairs = \"sliding\"\npositions = 4",
        )
    } else {
        text
    };
    Problem::from_toml(&text, "punch-b40-variant").unwrap()
}

#[test]
fn a_vanishing_stroke_gives_the_fixed_pairs_results() {
    // The fixed pairs wear by β̃ p 2u₀ a half period; a stroke of 2 µm with β̃ 1500 times
    // larger wears as much, so both runs must end at the same pressures and shapes.
    let fixed = wearfem::driver::wear(&punch(1.5, 1.0, false), None, |_| {}).unwrap();
    let slide = sliding::wear(&punch(1.0e-3, 1500.0, true), None).unwrap();
    assert!(fixed.history.stopped.is_none() && slide.history.stopped.is_none());
    let h = &fixed.history;
    let peak = h.p_plus.iter().fold(0.0f64, |a, &b| a.max(b));
    // The last '+' half period ends at its last position (the stroke's end, 0.75 µm from
    // where the fixed pairs sit); '−' ends at the first.
    let m = slide.contact.len();
    let ends = [
        (&h.p_plus, &slide.history.last_cycle[0][m - 1]),
        (&h.p_minus, &slide.history.last_cycle[1][0]),
    ];
    for (fixed_p, slide_p) in ends {
        let worst = fixed_p
            .iter()
            .zip(slide_p)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        // The issue asks 0.1 % of the peak.
        assert!(
            worst < 1e-3 * peak,
            "pressure off by {worst} of peak {peak}"
        );
    }
    // Body 2's wear where each contact point reads it (the middle of its share of the edge:
    // the end points sit on the step a vanishing stroke leaves in the track).
    let body2: Vec<f64> = slide
        .contact
        .readings
        .iter()
        .map(|&x| slide.history.track.at(x))
        .collect();
    for (fixed_w, slide_w) in [
        (&h.body_wear[0], &slide.history.wear_body1),
        (&h.body_wear[1], &body2),
    ] {
        let range = fixed_w.iter().fold(0.0f64, |a, &b| a.max(b))
            - fixed_w.iter().fold(f64::INFINITY, |a, &b| a.min(b));
        let worst = fixed_w
            .iter()
            .zip(slide_w)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        // The issue asks 0.5 % of the worn shape's range.
        assert!(worst < 5e-3 * range, "wear off by {worst} of range {range}");
    }
}

#[test]
fn options_that_need_fixed_pairs_are_refused_by_name() {
    let base = slider_on_flat(
        2000.0,
        "body1 = { beta = 1e-7 }\namplitude = 4.0\nsteps = 2",
        "",
    );
    for (edit, key) in [
        (
            (
                "pairs = \"sliding\"",
                "pairs = \"sliding\"\ndiscretisation = \"collocation\"",
            ),
            "contact.discretisation",
        ),
        (
            ("pairs = \"sliding\"", "pairs = \"slipping\""),
            "contact.pairs",
        ),
        (
            ("pairs = \"sliding\"", "pairs = \"sliding\"\npositions = 0"),
            "contact.positions",
        ),
        (
            (
                "sliding = \"reciprocating\"",
                "sliding = \"monotonic\"\nspeed = 1.0\nstep_time = 1.0",
            ),
            "wear.sliding",
        ),
        (
            ("steps = 2", "steps = 2\nshape_zero_at = 0.0"),
            "wear.shape_zero_at",
        ),
        (
            ("pairs = \"sliding\"", "pairs = \"fixed\"\npositions = 3"),
            "contact.positions",
        ),
    ] {
        let text = base.replace(edit.0, edit.1);
        let problem = Problem::from_toml(&text, "bad.toml").unwrap();
        let error = sliding::wear(&problem, None)
            .err()
            .expect("refused")
            .to_string();
        assert!(error.contains(key), "{key}: {error}");
    }
    // A track too short for the stroke names the amplitude.
    let text = base.replace("amplitude = 4.0", "amplitude = 68.0");
    let problem = Problem::from_toml(&text, "bad.toml").unwrap();
    let error = sliding::wear(&problem, None)
        .err()
        .expect("refused")
        .to_string();
    assert!(error.contains("wear.amplitude"), "{error}");
}

#[test]
fn the_tribometer_runs_through_the_binary_and_other_jobs_refuse_sliding_pairs() {
    let dir = std::env::temp_dir().join(format!("wearfem-sliding-{}", std::process::id()));
    let wearfem = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .arg("--quiet")
            .args(args)
            .output()
            .unwrap()
    };
    let out = dir.join("run");
    let run = wearfem(&[
        "run",
        "tribometer",
        "--steps",
        "6",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    for file in [
        "summary.json",
        "history.csv",
        "track.csv",
        "body1.csv",
        "positions.csv",
        "track.png",
        "wear_body1.png",
        "positions.png",
    ] {
        assert!(out.join(file).exists(), "{file}");
    }
    for file in ["history.csv", "track.csv", "body1.csv", "positions.csv"] {
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        let mut lines = text.lines();
        let columns = lines.next().unwrap().split(',').count();
        for line in lines {
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(cells.len(), columns, "{file}: {line}");
            for c in cells {
                let number = c.parse::<f64>().map(f64::is_finite).unwrap_or(false);
                assert!(number || ["+", "-", "−"].contains(&c), "{file}: {c}");
            }
        }
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    // Archard per body after 6 half periods of 4 mm: k F s with F = 500 N.
    for (body, k) in [(0, 5.0e-7), (1, 1.0e-6)] {
        let volume = summary["worn_volume"][body].as_f64().unwrap();
        let expected = k * 500.0 * 0.024;
        assert!(
            (volume - expected).abs() < 1e-6 * expected,
            "{body}: {volume}"
        );
    }
    // ParaView: the worn track and slider of every recorded step and of the last, the
    // track drawn on the flat's top (z = 0) with the wear summary.json gives.
    let vtk = dir.join("vtk");
    let with_vtk = wearfem(&[
        "run",
        "tribometer",
        "--steps",
        "6",
        "--vtk",
        "--out",
        vtk.to_str().unwrap(),
    ]);
    assert!(with_vtk.status.success());
    let pvd = std::fs::read_to_string(vtk.join("results.pvd")).unwrap();
    assert!(pvd.contains("vtk/track_0000.vtu") && pvd.contains("vtk/slider_0000.vtu"));
    let last = pvd
        .lines()
        .filter_map(|l| l.split("file=\"").nth(1))
        .rfind(|f| f.starts_with("vtk/track_"))
        .unwrap()
        .trim_end_matches("\"/>");
    let track = std::fs::read_to_string(vtk.join(last)).unwrap();
    let array = |name: &str| -> Vec<f64> {
        let start = track.find(&format!("Name=\"{name}\"")).unwrap();
        let body = &track[start..];
        let body = &body[body.find('>').unwrap() + 1..body.find("</DataArray>").unwrap()];
        body.split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let written = array("wear_body2");
    let expected: Vec<f64> = summary["track"]["wear_body2"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(written.len(), expected.len());
    for (a, b) in written.iter().zip(&expected) {
        assert!((a - b).abs() <= 1e-12 * b.abs().max(1e-30), "{a} {b}");
    }
    let points = array("Points");
    assert!(
        points.chunks(3).all(|p| p[1] == 0.0),
        "the flat's top is z = 0"
    );
    let refused = dir.join("refused");
    let args = ["steady", "tribometer", "--out", refused.to_str().unwrap()];
    let result = wearfem(&args);
    assert_eq!(result.status.code(), Some(2), "{args:?}");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("contact.pairs"), "{args:?}: {stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A steel block pressed on a steel ring (R = 20 mm about (0, −20), 64 elements round, its hub
/// held) turning under it at 100 mm/s; `laws` is the `[wear]` section's laws.
fn block_on_ring(laws: &str) -> String {
    RING.replace("WEAR_LAWS", laws)
}

const RING: &str = r#"title = "a block on a rotating ring"
[analysis]
kind = "plane_strain"
thickness = 10.0
p = 4
[materials.steel]
young = 2.1e5
poisson = 0.3
[[bodies]]
name = "block"
[[bodies.blocks]]
corners = [[-3.0, 0.0], [3.0, 0.0], [3.0, 4.0], [-3.0, 4.0]]
u = 30
v = [0.0, 0.1, 0.3, 1.0]
material = "steel"
names = { bottom = "contact", top = "top" }
[[bodies.tractions]]
edge = "top"
normal = 16.666666666666668
[[bodies]]
name = "ring"
[[bodies.blocks]]
corners = [[10.0, -20.0], [20.0, -20.0], [0.0, 0.0], [0.0, -10.0]]
arcs = [{ edge = 1, center = [0.0, -20.0] }, { edge = 3, center = [0.0, -20.0] }]
u = [0.0, 0.5, 0.8, 0.95, 1.0]
v = 16
material = "steel"
names = { right = "rim", left = "hub" }
[[bodies.blocks]]
corners = [[0.0, -10.0], [0.0, 0.0], [-20.0, -20.0], [-10.0, -20.0]]
arcs = [{ edge = 1, center = [0.0, -20.0] }, { edge = 3, center = [0.0, -20.0] }]
u = [0.0, 0.5, 0.8, 0.95, 1.0]
v = 16
material = "steel"
names = { right = "rim", left = "hub" }
[[bodies.blocks]]
corners = [[-10.0, -20.0], [-20.0, -20.0], [0.0, -40.0], [0.0, -30.0]]
arcs = [{ edge = 1, center = [0.0, -20.0] }, { edge = 3, center = [0.0, -20.0] }]
u = [0.0, 0.5, 0.8, 0.95, 1.0]
v = 16
material = "steel"
names = { right = "rim", left = "hub" }
[[bodies.blocks]]
corners = [[0.0, -30.0], [0.0, -40.0], [20.0, -20.0], [10.0, -20.0]]
arcs = [{ edge = 1, center = [0.0, -20.0] }, { edge = 3, center = [0.0, -20.0] }]
u = [0.0, 0.5, 0.8, 0.95, 1.0]
v = 16
material = "steel"
names = { right = "rim", left = "hub" }
[[bodies.supports]]
edge = "hub"
fix = ["x", "z"]
[contact]
body = "block"
edge = "contact"
target_body = "ring"
target_edge = "rim"
friction = 0.3
pairs = "sliding"
[plate]
edge = "top"
motion = "vertical"
[wear]
WEAR_LAWS
sliding = "monotonic"
speed = 100.0
step_time = 1.2566370614359172
steps = 5
extrapolation = [{ until = 2, k = 1 }, { k = 10 }]
"#;

#[test]
fn probes_on_body_2_report_its_wear_where_they_are() {
    // A probe on the ring's side (a quarter turn from the top) and one on its bottom read
    // the even depth β̃₂ (F/t) × turns after every step.
    let text = block_on_ring("body2 = { beta = 1.0e-6 }")
        + "[probes]\nside = { body = \"ring\", at = [20.0, -20.0] }\nbottom = { body = \"ring\", at = [0.0, -40.0] }\n";
    let run = run(&text);
    assert_eq!(run.track_probes.len(), 2);
    for step in &run.history.steps {
        let depth = 1.0e-6 * LOAD_PER_THICKNESS * step.half_period as f64;
        for w in &step.track_probes {
            assert!(
                (w - depth).abs() < 1e-6 * depth,
                "step {}: {w} against {depth}",
                step.step
            );
        }
    }
    // Off the rim: refused by name.
    let text = block_on_ring("body2 = { beta = 1.0e-6 }")
        + "[probes]\ninside = { body = \"ring\", at = [15.0, -20.0] }\n";
    let problem = Problem::from_toml(&text, "bad.toml").unwrap();
    let error = sliding::wear(&problem, None)
        .err()
        .expect("refused")
        .to_string();
    assert!(error.contains("probes.inside.at"), "{error}");
}

#[test]
fn a_ring_turning_under_a_block_wears_evenly_all_round() {
    // Only the ring wears: every material point of its rim passes under the whole contact
    // once a turn, so after s of sliding its depth is β̃₂ (F/t) s / (2πR) all round, whatever
    // the pressure's shape (∫ p dx = F/t). The positions (one per element of the rim) are
    // alike up to the turn, so the evenness holds to round-off; 1e-6 is the issue's bound.
    let run = run(&block_on_ring("body2 = { beta = 1.0e-6 }"));
    let turns = run.history.steps.last().unwrap().half_period as f64;
    let depth = 1.0e-6 * LOAD_PER_THICKNESS * turns;
    for (k, w) in run.history.track.wear.iter().enumerate() {
        assert!(
            (w - depth).abs() < 1e-6 * depth,
            "cell {k}: {w} against {depth}"
        );
    }
    assert!(matches!(
        run.contact.shape,
        wearfem::contact::track::TrackShape::Ring { radius, .. } if (radius - 20.0).abs() < 1e-9
    ));
}

#[test]
fn block_and_ring_each_wear_archards_volume() {
    let run = run(&block_on_ring(
        "body1 = { beta = 3.0e-7 }\nbody2 = { beta = 1.0e-6 }",
    ));
    let circumference = std::f64::consts::TAU * 20.0;
    for step in &run.history.steps {
        let s = circumference * step.half_period as f64;
        for (body, beta) in [(0, 3.0e-7), (1, 1.0e-6)] {
            let expected = beta * LOAD_PER_THICKNESS * s;
            let relative = (step.worn_area[body] - expected).abs() / expected;
            // As for the straight track: the equilibrium residual and round-off.
            assert!(
                relative < 1e-6,
                "step {}: body {}: {relative:.2e}",
                step.step,
                body + 1
            );
        }
    }
}

#[test]
fn a_closed_track_must_be_a_circle_turned_once_a_step() {
    let good = block_on_ring("body2 = { beta = 1.0e-6 }");
    let refused = |text: &str, key: &str| {
        let problem = Problem::from_toml(text, "bad.toml").unwrap();
        let error = sliding::wear(&problem, None)
            .err()
            .expect("refused")
            .to_string();
        assert!(error.contains(key), "{key}: {error}");
    };
    // A step unit must be one turn: 2π × 20 mm at 100 mm/s.
    refused(
        &good.replace("step_time = 1.2566370614359172", "step_time = 1.0"),
        "wear.step_time",
    );
    // The ring's first quarter made square: its rim is still closed, but not a circle.
    refused(
        &good.replacen(
            "arcs = [{ edge = 1, center = [0.0, -20.0] }, { edge = 3, center = [0.0, -20.0] }]",
            "arcs = [{ edge = 3, center = [0.0, -20.0] }]",
            1,
        ),
        "contact.target_edge",
    );
}

#[test]
fn review_findings_stay_fixed() {
    // A misspelt `pairs` reached every job but the sliding run and ran fixed pairs, exit 0.
    let out = std::env::temp_dir().join(format!("wearfem-sliding-typo-{}", std::process::id()));
    for (set, key) in [
        ("contact.pairs=Sliding", "contact.pairs"),
        ("contact.pairs=fixed", "contact.positions"),
        ("wear.amplitude=0", "wear.amplitude"),
    ] {
        for job in ["run", "contact"] {
            let result = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
                .args(["--quiet", job, "tribometer", "--set", set, "--out"])
                .arg(&out)
                .output()
                .unwrap();
            let stderr = String::from_utf8_lossy(&result.stderr);
            if job == "contact" && set.starts_with("wear.") {
                continue;
            }
            assert_eq!(result.status.code(), Some(2), "{job} {set}: {stderr}");
            assert!(stderr.contains(key), "{job} {set}: {stderr}");
        }
    }
    let _ = std::fs::remove_dir_all(&out);
    // A probe on a straight track's flat was always refused: it reads the trough now.
    let text = slider_on_flat(
        5000.0,
        "body2 = { beta = 1.0e-6, a = 1.0, b = 1.0 }\namplitude = 50.0\nsteps = 1\nextrapolation = [{ k = 1 }]",
        "",
    ) + "[probes]\nmiddle = { body = \"flat\", at = [0.0, 0.0] }\n";
    let run = run(&text);
    let read = run.history.steps[0].track_probes[0];
    assert!((read - run.history.track.at(0.0)).abs() < 1e-15, "{read}");
    assert!(
        (read - 1.0e-6 * LOAD_PER_THICKNESS).abs() < 5e-3 * 1.0e-4,
        "{read}"
    );
    // Loads on a turning ring are refused by name (they were read in the wrong frame).
    let text = block_on_ring("body2 = { beta = 1.0e-6 }").replace(
        "[[bodies.supports]]\nedge = \"hub\"",
        "[[bodies.tractions]]\nedge = \"rim\"\nnormal = 5.0\n[[bodies.supports]]\nedge = \"hub\"",
    );
    assert!(text.contains("normal = 5.0"));
    let problem = Problem::from_toml(&text, "bad.toml").unwrap();
    let error = sliding::wear(&problem, None)
        .err()
        .expect("refused")
        .to_string();
    assert!(error.contains("bodies[1].tractions"), "{error}");
}
