//! Bodies of revolution turning about their axis (issue 31): a thrust washer on a disc, whose
//! steady pressure makes pᵇ (ω r)ᵃ uniform (the clutch designer's "uniform wear"), against
//! closed forms; the run reaching it; the torque; Archard's volume over the surface of
//! revolution; and what a turn refuses.

use std::f64::consts::PI;
use wearfem::problem::Problem;

/// A washer of radii `inner` … `outer` (mm, 5 mm thick) pressed with `force` N on a disc of
/// radius 1.5 `outer` (10 mm thick, held at its base), turning at ω = 10 rad/s with friction
/// μ = 0.3; `law` the washer's wear law (TOML), `p` the degree, `elements` across the washer.
/// `aligned`: the disc's mesh lines under the washer's element ends (else the disc has its own
/// uniform lines, non-matching).
struct Washer {
    inner: f64,
    outer: f64,
    force: f64,
    law: &'static str,
    p: usize,
    elements: usize,
    aligned: bool,
    materials: [(f64, f64); 2],
}

impl Default for Washer {
    fn default() -> Self {
        Washer {
            inner: 10.0,
            outer: 20.0,
            force: 2000.0,
            law: "{ beta = 1.0e-8, a = 1.0, b = 1.0 }",
            p: 6,
            elements: 12,
            aligned: true,
            materials: [(1.1e5, 0.34), (2.1e5, 0.3)],
        }
    }
}

fn list(values: &[f64]) -> String {
    let v: Vec<String> = values.iter().map(|x| format!("{x:.15}")).collect();
    format!("[{}]", v.join(", "))
}

impl Washer {
    fn text(&self, wear: &str) -> String {
        let n = self.elements;
        // Graded towards both edges (a sine spacing), where the new washer's pressure is
        // singular.
        let u: Vec<f64> = (0..=n)
            .map(|i| 0.5 - 0.5 * (PI * i as f64 / n as f64).cos())
            .collect();
        let disc_radius = 1.5 * self.outer;
        let disc_u: Vec<f64> = if self.aligned {
            let mut lines = vec![0.0];
            lines.extend(
                u.iter()
                    .map(|t| (self.inner + t * (self.outer - self.inner)) / disc_radius),
            );
            lines.push(1.0);
            lines
        } else {
            (0..=37).map(|i| i as f64 / 37.0).collect()
        };
        let area = PI * (self.outer * self.outer - self.inner * self.inner);
        let ([e1, n1], [e2, n2]) = (
            [self.materials[0].0, self.materials[0].1],
            [self.materials[1].0, self.materials[1].1],
        );
        format!(
            r#"title = "a thrust washer"
[analysis]
kind = "axisymmetric"
p = {p}
[materials.washer]
young = {e1}
poisson = {n1}
[materials.disc]
young = {e2}
poisson = {n2}
[[bodies]]
name = "washer"
[[bodies.blocks]]
corners = [[{ri}, 0.0], [{ro}, 0.0], [{ro}, 5.0], [{ri}, 5.0]]
u = {u}
v = [0, 0.02, 0.08, 0.25, 0.6, 1]
material = "washer"
names = {{ bottom = "face", top = "back" }}
[[bodies.tractions]]
edge = "back"
normal = {traction}
[[bodies]]
name = "disc"
[[bodies.blocks]]
corners = [[0.0, -10.0], [{rd}, -10.0], [{rd}, 0.0], [0.0, 0.0]]
u = {disc_u}
v = [0, 0.4, 0.7, 0.9, 0.97, 1]
material = "disc"
names = {{ bottom = "base", top = "surface" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[contact]
body = "washer"
edge = "face"
target_body = "disc"
target_edge = "surface"
friction = 0.3
sliding_motion = "about_axis"
align_target_mesh = {aligned}
[plate]
edge = "back"
motion = "vertical"
[wear]
body1 = {law}
{wear}
"#,
            p = self.p,
            ri = self.inner,
            ro = self.outer,
            rd = disc_radius,
            u = list(&u),
            disc_u = list(&disc_u),
            traction = self.force / area,
            aligned = self.aligned,
            law = self.law,
        )
    }

    fn problem(&self, wear: &str) -> Problem {
        Problem::from_toml(&self.text(wear), "washer.toml").unwrap()
    }
}

const TURNING: &str = "sliding = \"monotonic\"\nangular_speed = 10.0\nstep_time = 5.0\nsteps = 300\nextrapolation = [{ until = 100, k = 1 }, { k = 10 }]";

/// The steady pressure and the contact points' radii.
fn steady(washer: &Washer, wear: &str) -> (Vec<f64>, Vec<f64>) {
    let (state, contact, _) = wearfem::driver::steady(&washer.problem(wear)).unwrap();
    assert_eq!(state.status, wearfem::steady::SteadyStatus::Solved);
    let r = contact.points.x.iter().map(|x| x[0]).collect();
    (r, state.p_plus)
}

/// The steady pressure makes pᵇ rᵃ uniform, with the constant the load sets: closed forms of
/// F = ∫ p 2πr dr for p = (K/rᵃ)^(1/b).
#[test]
fn the_steady_washer_wears_uniformly() {
    let (ri, ro, f) = (10.0f64, 20.0f64, 2000.0);
    // (a, b, K): F = 2π K^(1/b) ∫ r^(1 − a/b) dr.
    let cases: [(f64, f64, f64, &str); 4] = [
        (
            1.0,
            1.0,
            (f / (2.0 * PI * (ro - ri))),
            "{ beta = 1.0e-8, a = 1.0, b = 1.0 }",
        ),
        (
            1.0,
            2.0,
            (f / (2.0 * PI * (2.0 / 3.0) * (ro.powf(1.5) - ri.powf(1.5)))).powi(2),
            "{ beta = 1.0e-8, a = 1.0, b = 2.0 }",
        ),
        (
            2.0,
            1.0,
            f / (2.0 * PI * (ro / ri).ln()),
            "{ beta = 1.0e-10, a = 2.0, b = 1.0 }",
        ),
        (
            0.5,
            0.7,
            // ∫ r^(1 − 0.5/0.7) dr = [r^(2 − 5/7)/(2 − 5/7)].
            {
                let e = 2.0 - 0.5 / 0.7;
                (f / (2.0 * PI * (ro.powf(e) - ri.powf(e)) / e)).powf(0.7)
            },
            "{ beta = 1.0e-8, a = 0.5, b = 0.7 }",
        ),
    ];
    for (a, b, k, law) in cases {
        for (p, elements, aligned) in [(6, 12, true), (4, 20, false), (8, 6, true)] {
            let washer = Washer {
                law,
                p,
                elements,
                aligned,
                ..Default::default()
            };
            let (r, pressure) = steady(&washer, TURNING);
            for (ri_, pi_) in r.iter().zip(&pressure) {
                let uniform = pi_.powf(b) * ri_.powf(a);
                // The load's closed form is the discrete sum Σ 2π wᵢ K^(1/b) rᵢ^(1 − a/b) of the
                // ring areas: exact for a = b = 1 (Lobatto's weights add up to r_o − r_i), and
                // otherwise the Lobatto quadrature of the smooth r^(1 − a/b) on [10, 20] mm by
                // 6–20 elements of degree 4–8, below 1e-12. Measured: 1.5e-15 at most.
                let tolerance = 1e-9;
                assert!(
                    (uniform - k).abs() < tolerance * k,
                    "a = {a}, b = {b}, p = {p}, {elements} elements: pᵇrᵃ = {uniform} at r = {ri_}, closed form {k}"
                );
            }
        }
    }
}

/// The torque of the steady washer, ∫ μ p r dA = μF(r_o + r_i)/2 for a = b = 1 (exact for the
/// ring areas 2πrw: Lobatto integrates r exactly), and other materials and loads give the same
/// law (the pressure does not depend on them).
#[test]
fn the_steady_torque_is_the_uniform_wear_torque() {
    for (force, materials) in [
        (2000.0, [(1.1e5, 0.34), (2.1e5, 0.3)]),
        (500.0, [(3.0e3, 0.4), (7.0e4, 0.33)]),
    ] {
        let washer = Washer {
            force,
            materials,
            ..Default::default()
        };
        let run = wearfem::driver::wear(&washer.problem(TURNING), None, |_| {}).unwrap();
        let torque = run.history.steps.last().unwrap().torque.unwrap();
        let expected = 0.3 * force * (20.0 + 10.0) / 2.0;
        // 1 %: the issue's bound; the run is at the steady state to 1e-10 here.
        assert!(
            (torque - expected).abs() < 0.01 * expected,
            "F = {force}: torque {torque} N·mm, μF(r_o + r_i)/2 = {expected}"
        );
        let (r, steady_pressure) = steady(&washer, TURNING);
        let last = &run.history.p_plus;
        let peak = steady_pressure.iter().cloned().fold(0.0, f64::max);
        for i in 0..r.len() {
            // The run reaches the steady state: 300 steps, 2100 step units, where the
            // transient decays within some 50 (0.1 % of the peak: far inside).
            assert!(
                (last[i] - steady_pressure[i]).abs() < 1e-3 * peak,
                "r = {}: run {} steady {}",
                r[i],
                last[i],
                steady_pressure[i]
            );
        }
    }
}

/// The run reaches the steady state for the other exponents too.
#[test]
fn the_run_reaches_the_steady_state_for_other_laws() {
    for law in [
        "{ beta = 1.0e-8, a = 1.0, b = 2.0 }",
        "{ beta = 5.0e-11, a = 2.0, b = 1.0 }",
    ] {
        let washer = Washer {
            law,
            ..Default::default()
        };
        let problem = washer.problem(TURNING);
        let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
        let (_, steady_pressure) = steady(&washer, TURNING);
        let peak = steady_pressure.iter().cloned().fold(0.0, f64::max);
        let worst = run
            .history
            .p_plus
            .iter()
            .zip(&steady_pressure)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        // 1 % of the peak: the issue's bound for the run reaching the steady state.
        assert!(worst < 0.01 * peak, "{law}: {worst} of {peak}");
    }
}

/// Archard's law over the surface of revolution, a = b = 1: the washer's worn volume
/// 2π∫ w r dr equals β̃ ∫∫ p v dA dt, with v = ω r, i.e. β̃ ω ∫ (T/μ) dt from each step's torque
/// (each step holds its pressure over its k step units of `step_time`).
#[test]
fn the_worn_volume_is_archards() {
    for wear in [
        TURNING.to_string(),
        // A turn to and fro: ∫|v| over a half period is 2θ₀ r.
        "sliding = \"reciprocating\"\nangle = 0.5\nomega = 10.0\nsteps = 120\nextrapolation = [{ until = 40, k = 1 }, { k = 7 }]".to_string(),
    ] {
        let washer = Washer {
            aligned: false,
            p: 5,
            ..Default::default()
        };
        let problem = washer.problem(&wear);
        let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
        let (beta, mu) = (1.0e-8, 0.3);
        let per_unit_torque = if wear.contains("monotonic") {
            10.0 * 5.0 // ω × step_time: the angle of one step unit, rad
        } else {
            2.0 * 0.5 // 2θ₀ per half period, rad
        };
        let expected: f64 = run
            .history
            .steps
            .iter()
            .map(|s| beta * s.k as f64 * per_unit_torque * s.torque.unwrap() / mu)
            .sum();
        let worn = &run.history.body_wear[0];
        let volume =
            wearfem::wear::worn_volume(&run.contact.points, worn, run.contact.thickness);
        // 1e-6: the issue's bound; both sides are sums of the same per-step pressures, so
        // round-off only.
        assert!(
            (volume - expected).abs() < 1e-6 * expected,
            "{wear}: worn volume {volume} mm³, Archard {expected}"
        );
    }
}

/// What a turn refuses, by name.
#[test]
fn bad_turns_are_refused_by_name() {
    let washer = Washer::default();
    let key_of = |text: String| -> String {
        let problem = match Problem::from_toml(&text, "bad.toml") {
            Ok(p) => p,
            Err(e) => return e.key,
        };
        match wearfem::driver::wear(&problem, Some(2), |_| {}) {
            Ok(_) => "accepted".into(),
            Err(wearfem::driver::JobError::Problem(e)) => e.key,
            Err(e) => format!("other: {e}"),
        }
    };
    // A plane speed on a turning contact.
    let plane_speed =
        washer.text("sliding = \"monotonic\"\nspeed = 100.0\nstep_time = 5.0\nsteps = 3");
    assert_eq!(key_of(plane_speed), "wear.angular_speed");
    // Both speeds.
    let both = washer.text(&format!("{TURNING}\nspeed = 100.0"));
    assert_eq!(key_of(both), "wear.speed");
    // A turn has no sliding distance.
    let distance = washer
        .text("sliding = \"monotonic\"\nangular_speed = 10.0\nstep_time = 5.0\ndistance = 10.0");
    assert_eq!(key_of(distance), "wear.distance");
    // The angle of a turn to and fro on a turn one way.
    let angle = washer.text(&format!("{TURNING}\nangle = 0.5"));
    assert_eq!(key_of(angle), "wear.angle");
    // A turn's keys on a contact that does not turn.
    let not_turning = washer.text(TURNING).replace(
        "sliding_motion = \"about_axis\"",
        "sliding_motion = \"in_plane\"",
    );
    let key = key_of(not_turning);
    assert!(
        key == "contact.friction" || key == "contact.sliding_motion",
        "{key}"
    );
    let frictionless = washer
        .text(TURNING)
        .replace("sliding_motion = \"about_axis\"", "")
        .replace("friction = 0.3", "friction = 0.0");
    assert_eq!(key_of(frictionless), "contact.sliding_motion");
    // A plane analysis cannot turn about an axis.
    let plane = washer.text(TURNING).replace(
        "kind = \"axisymmetric\"",
        "kind = \"plane_strain\"\nthickness = 1.0",
    );
    assert_eq!(key_of(plane), "contact.sliding_motion");
    // A misspelt motion.
    let typo = washer
        .text(TURNING)
        .replace("\"about_axis\"", "\"about_the_axis\"");
    assert_eq!(key_of(typo), "contact.sliding_motion");
    // The paper's §6 methods are plane.
    let problem =
        washer.problem("sliding = \"reciprocating\"\nangle = 0.5\nomega = 10.0\nsteps = 3");
    let e = wearfem::driver::steady_by(
        &problem,
        wearfem::paper_steady::SteadyMethod::Spline,
        Default::default(),
    )
    .map(|_| ())
    .unwrap_err();
    assert!(e.to_string().contains("analysis.kind"), "{e}");
}

/// A punch turning on a block, its contact reaching the axis (`rotating-punch`): the steady
/// pressure is P/(2πa r) off the axis, where the disc the axis point stands for carries
/// its share of the load, and the torque μPa/2; both jobs warn `turn-on-axis`.
#[test]
fn a_punch_turning_to_its_axis_wears_uniformly_off_the_axis() {
    let problem = Problem::from_toml(
        wearfem::examples::example("rotating-punch").unwrap(),
        "rotating-punch",
    )
    .unwrap();
    let (state, contact, _) = wearfem::driver::steady(&problem).unwrap();
    let (force, radius, friction) = (100.0, 1.0, 0.3);
    let uniform = force / (2.0 * PI * radius);
    for (x, p) in contact.points.x.iter().zip(&state.p_plus).skip(1) {
        // 0.5 %: the axis point's disc (ρ = 7 µm) carries 0.17 % of the load, which the
        // rest lacks; the closed form has it carried by p r at r < ρ.
        assert!(
            (p * x[0] - uniform).abs() < 5e-3 * uniform,
            "r = {}: p r = {} against {uniform}",
            x[0],
            p * x[0]
        );
    }
    let turn = wearfem::wear::AxisRotation::new(&contact, friction);
    let torque = turn.torque(&state.p_plus, &contact.areas());
    let expected = friction * force * radius / 2.0;
    // 1 %: the issue's bound.
    assert!(
        (torque - expected).abs() < 0.01 * expected,
        "{torque} against {expected}"
    );
    let warnings = wearfem::driver::steady_warnings(&problem, &contact, &state);
    assert!(
        warnings.iter().any(|w| w.contains("turn-on-axis")),
        "{warnings:?}"
    );
}

/// A bronze ring (bore 10 mm, outside 15 mm, free ends: half of it, held in z on its
/// mid-plane) shrunk on a steel shaft with a radial overlap δ and reciprocating along the axis
/// (a seal or a bushing): the contact edge runs along the axis, and friction acts along it.
fn ring_on_shaft(friction: f64, law: &str, steps: usize, k: usize) -> String {
    let record: Vec<String> = (1..=steps).map(|s| s.to_string()).collect();
    let record = record.join(", ");
    format!(
        r#"title = "a ring on a shaft"
[analysis]
kind = "axisymmetric"
p = 6
[materials.steel]
young = 2.0e5
poisson = 0.3
[materials.bronze]
young = 1.1e5
poisson = 0.34
[[bodies]]
name = "ring"
[[bodies.blocks]]
corners = [[9.9999, 0.0], [15.0, 0.0], [15.0, 5.0], [9.9999, 5.0]]
u = 3
v = 4
material = "bronze"
names = {{ bottom = "mid", left = "bore" }}
[[bodies.supports]]
edge = "mid"
fix = ["z"]
[[bodies]]
name = "shaft"
[[bodies.blocks]]
corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 5.0], [0.0, 5.0]]
u = 3
v = 4
material = "steel"
names = {{ bottom = "mid", right = "surface" }}
[[bodies.supports]]
edge = "mid"
fix = ["z"]
[contact]
body = "ring"
edge = "bore"
target_body = "shaft"
target_edge = "surface"
friction = {friction}
[wear]
body1 = {law}
sliding = "reciprocating"
amplitude = 0.5
omega = 10.0
steps = {steps}
extrapolation = [{{ k = {k} }}]
record = [{record}]
[probes]
middle = {{ body = "ring", at = [9.9999, 2.5] }}
"#
    )
}

/// Sliding along the axis, frictionless: the shrink fit's pressure is Lamé's (a tube with free
/// ends on a solid cylinder with free ends, both exact 3D solutions under a uniform radial
/// pressure), p₀ = δ/(c_ring + c_shaft), and the ring's wear relieves the overlap:
/// dw/ds = β̃ p = β̃ p₀ (1 − w/δ), so p = p₀ exp(−β̃ s p₀/δ) over the sliding distance s.
#[test]
fn a_shrink_fit_sliding_along_its_axis_wears_loose_exponentially() {
    let text = ring_on_shaft(0.0, "{ beta = 1.0e-7, a = 1.0, b = 1.0 }", 400, 10);
    let problem = Problem::from_toml(&text, "ring.toml").unwrap();
    let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
    let (a, b, overlap) = (9.9999f64, 15.0f64, 1.0e-4);
    let (e1, n1, e2, n2) = (1.1e5, 0.34, 2.0e5, 0.3);
    // u_r at the bore of the ring per MPa inside, and of the shaft's surface per MPa outside.
    let ring =
        a / e1 * ((1.0 - n1) * a * a / (b * b - a * a) + (1.0 + n1) * b * b / (b * b - a * a));
    let shaft = (1.0 - n2) * 10.0 / e2;
    let p0 = overlap / (ring + shaft);
    let first = run.contact.points.x.len();
    let (solution, _) = wearfem::complementarity::ContactSolver::new(
        &run.contact,
        wearfem::complementarity::Method::ActiveSet,
    )
    .solve(
        &run.contact.points.initial_gap,
        wearfem::complementarity::Direction::Plus,
    );
    for p in &solution.pressure[..first] {
        // 1e-4: the linear theory's geometry (the overlap taken at r = 10 mm on a bore of
        // 9.9999 mm) is good to 1e-5; the discretisation of uniform fields is exact.
        assert!((p - p0).abs() < 1e-4 * p0, "p = {p}, Lamé {p0}");
    }
    let rate = 1.0e-7 * p0 / overlap; // per mm of sliding
    for step in &run.history.steps {
        let s = step.half_period as f64 * 2.0 * 0.5;
        let expected = p0 * (-rate * s).exp();
        // Each cycle of k = 10 is a backward-Euler step of 2k half periods in the sliding
        // (both halves see the cycle's end shape): h = 20 · β̃ p₀/δ · 1 mm = 6.6e-3, whose
        // error grows as n h²/2 · p, at most 0.44 % by s = 4000 mm (βs p₀/δ = 1.3), and half a
        // cycle's lag on a '+' step; 1 % holds both.
        assert!(
            (step.probes[0] - expected).abs() < 0.01 * expected,
            "s = {s} mm: p = {}, exp decay {expected}",
            step.probes[0]
        );
    }
}

/// Sliding along the axis with friction: Archard's volume over the surface of revolution
/// (2π∫ w r dz = β̃ ∫∫ p |v| dA dt, a = b = 1), and friction across a face is refused.
#[test]
fn a_ring_sliding_along_its_axis_with_friction_wears_by_archard() {
    let text = ring_on_shaft(0.3, "{ beta = 1.0e-7, a = 1.0, b = 1.0 }", 60, 3);
    let problem = Problem::from_toml(&text, "ring.toml").unwrap();
    let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
    assert_eq!(run.history.failed_solves, 0);
    let area = run.contact.areas();
    // Every step is recorded (below), so each step's pressure is known: it is held over the
    // step's k half periods of 2u₀ = 1 mm of sliding each.
    let archard: f64 = (run.history.snapshots.iter())
        .map(|snapshot| {
            let force: f64 = snapshot
                .pressure
                .iter()
                .zip(&area)
                .map(|(p, a)| p * a)
                .sum();
            1.0e-7 * 3.0 * 1.0 * force
        })
        .sum();
    assert_eq!(run.history.snapshots.len(), 60);
    let worn = &run.history.body_wear[0];
    let volume = wearfem::wear::worn_volume(&run.contact.points, worn, run.contact.thickness);
    // 1e-6: the issue's bound; both are sums of the same pressures (round-off).
    assert!(
        (volume - archard).abs() < 1e-6 * archard,
        "worn volume {volume} mm³, Archard {archard}"
    );
    // A face with friction in the (r, z) plane is refused: the slip would be radial.
    let face = Washer::default().text(TURNING).replace(
        "sliding_motion = \"about_axis\"",
        "sliding_motion = \"in_plane\"",
    );
    let problem = Problem::from_toml(&face, "face.toml").unwrap();
    let e = wearfem::contact::CondensedContact::build(&problem)
        .map(|_| ())
        .unwrap_err();
    assert_eq!(e.key, "contact.friction", "{e}");
}

/// Review findings: a turn reaching the axis with a ≥ 2b has no steady state (p ∝ r^(−a/b)
/// carries no finite load): `steady` refuses it by name and the run says none exists; a ring
/// in a bore writes its profiles against z (every point has the same r).
#[test]
fn turn_review_findings_stay_fixed() {
    let text = wearfem::examples::example("rotating-punch")
        .unwrap()
        .replace(
            "beta = 1.0e-9, a = 1.0, b = 1.0",
            "beta = 1.0e-12, a = 2.0, b = 1.0",
        )
        .replace("steps = 400", "steps = 20")
        .replace("record = [1, 10, 100, 200, 400]", "record = [1, 10]");
    let problem = Problem::from_toml(&text, "collapse.toml").unwrap();
    let e = wearfem::driver::steady(&problem).map(|_| ()).unwrap_err();
    assert!(e.to_string().contains("wear.body1"), "{e}");
    let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
    let said = run.steady_check.to_string();
    assert!(said.contains("no steady state exists"), "{said}");
    let warnings = run.warnings(&problem);
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("turn-on-axis") && w.contains("no steady state exists")),
        "{warnings:?}"
    );
    // The ring in a bore: its contact points share one r, and z is the profiles' coordinate.
    let ring = ring_on_shaft(0.3, "{ beta = 1.0e-7, a = 1.0, b = 1.0 }", 4, 1);
    let problem = Problem::from_toml(&ring, "ring.toml").unwrap();
    let run = wearfem::driver::wear(&problem, None, |_| {}).unwrap();
    let z = run.contact.profile_z().expect("a contact along the axis");
    assert!(z.windows(2).all(|w| w[1] > w[0]), "{z:?}");
    assert_eq!(run.contact.position_label(), "z (mm)");
    let summary = run.summary(&problem);
    assert_eq!(summary["final"]["z"].as_array().unwrap().len(), z.len());
}
