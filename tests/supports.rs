//! Supports beyond a zero displacement (issue 28, item 3): a prescribed displacement and a bed
//! of springs, against closed forms.

use wearfem::driver;
use wearfem::problem::Problem;

/// A 100 × 20 mm steel block (plane stress, 10 mm thick, p = 4, 4 × 2 elements), with the
/// supports and loads of `extra` appended.
fn block(extra: &str) -> Problem {
    let text = format!(
        r#"title = "block"
[analysis]
kind = "plane_stress"
thickness = 10.0
p = 4

[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "block"

[[bodies.blocks]]
corners = [[0.0, 0.0], [100.0, 0.0], [100.0, 20.0], [0.0, 20.0]]
u = 4
v = 2
material = "steel"
names = {{ bottom = "bottom", right = "right", top = "top", left = "left" }}

[probes]
middle = {{ body = "block", at = [37.0, 13.0] }}
corner = {{ body = "block", at = [100.0, 20.0] }}
{extra}"#
    );
    Problem::from_toml(&text, "block").unwrap()
}

fn probe(summary: &serde_json::Value, name: &str, what: &str) -> Vec<f64> {
    summary["probes"][name][what]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect()
}

#[test]
fn a_block_shortened_by_a_prescribed_displacement_is_in_uniaxial_stress() {
    // The left edge held in x, one corner in z, the right edge pushed in by δ = 0.05 mm:
    // u_x = −δ x/L, u_z = ν δ z/L (plane stress), σ_xx = −E δ/L, everything else zero, and
    // the stored energy ½ E (δ/L)² × volume. Linear fields are in the space: round-off only,
    // the issue's 1e-10 (relative to σ_xx and to the displacements' size).
    let problem = block(
        r#"
[[bodies.supports]]
edge = "left"
fix = ["x"]

[[bodies.supports]]
point = [0.0, 0.0]
fix = ["z"]

[[bodies.supports]]
edge = "right"
fix = ["x"]
displacement = [-0.05, 0.0]
"#,
    );
    let summary = driver::elastic(&problem).unwrap();
    let (e, nu, delta, length) = (2.0e5, 0.3, 0.05, 100.0);
    let sigma = -e * delta / length;
    for (name, x) in [("middle", [37.0, 13.0]), ("corner", [100.0, 20.0])] {
        let u = probe(&summary, name, "displacement");
        let exact = [-delta * x[0] / length, nu * delta * x[1] / length];
        for c in 0..2 {
            assert!(
                (u[c] - exact[c]).abs() < 1e-10 * delta,
                "{name}: {u:?} vs {exact:?}"
            );
        }
        let s = probe(&summary, name, "stress");
        assert!((s[0] - sigma).abs() < 1e-10 * sigma.abs(), "{name}: {s:?}");
        for &other in &s[1..3] {
            assert!(other.abs() < 1e-10 * sigma.abs(), "{name}: {s:?}");
        }
    }
    let energy = summary["strain_energy"].as_f64().unwrap();
    let exact = 0.5 * e * (delta / length).powi(2) * 100.0 * 20.0 * 10.0;
    assert!(
        (energy - exact).abs() < 1e-10 * exact,
        "{energy} vs {exact}"
    );
}

#[test]
fn a_block_on_a_spring_bed_settles_by_the_load_over_the_modulus() {
    // A uniform pressure q on top, a bed k_n under the bottom and the left edge's x held: the
    // bed compresses by q/k_n and the block by q h/E; the top sinks by q/k_n + q h/E and
    // spreads sideways by ν q x/E. (A tangential bed would resist that spreading and shear the
    // block, so it has none here.) Linear: round-off, 1e-10.
    let (q, k, e, nu, h) = (5.0, 0.8, 2.0e5, 0.3, 20.0);
    let problem = block(&format!(
        r#"
[[bodies.springs]]
edge = "bottom"
normal = {k}

[[bodies.supports]]
edge = "left"
fix = ["x"]

[[bodies.tractions]]
edge = "top"
normal = {q}
"#
    ));
    let summary = driver::elastic(&problem).unwrap();
    let u = probe(&summary, "corner", "displacement");
    let exact = [nu * q * 100.0 / e, -(q / k + q * h / e)];
    for c in 0..2 {
        assert!(
            (u[c] - exact[c]).abs() < 1e-10 * exact[1].abs(),
            "{u:?} vs {exact:?}"
        );
    }
    // ½ fᵀu: the pressure's work is what the block and the bed store.
    let energy = summary["strain_energy"].as_f64().unwrap();
    let work = 0.5 * q * 100.0 * 10.0 * (q / k + q * h / e);
    assert!((energy - work).abs() < 1e-9 * work, "{energy} vs {work}");
}

#[test]
fn a_long_strip_on_a_spring_bed_bends_as_hetenyis_beam() {
    // A line load P at the middle of a long strip resting on a Winkler bed (Hetényi 1946):
    // w(x) = P β/(2k) e^{−β|x|}(cos β|x| + sin β|x|), β = (k/(4EI))^{1/4}, k = k_n t the bed's
    // stiffness per unit length, EI = E t h³/12. The strip is 5 mm deep, βh = 0.03: the
    // continuum's shear and the bed's offset from the neutral axis differ from Euler–Bernoulli
    // by about (βh)² ≈ 1e-3; the load is spread over 2 mm (β × 1 mm = 6e-3). The issue asks
    // 1 % against a closed form.
    let (e, t, h, kn, half): (f64, f64, f64, f64, f64) = (2.0e5, 10.0, 5.0, 0.01, 1000.0);
    let (pressure, width) = (0.5, 2.0);
    let load = pressure * width * t;
    let text = format!(
        r#"title = "strip on a bed"
[analysis]
kind = "plane_stress"
thickness = {t}
p = 8

[materials.steel]
young = {e}
poisson = 0.3

[[bodies]]
name = "strip"

[[bodies.blocks]]
corners = [[-{half}, 0.0], [-1.0, 0.0], [-1.0, {h}], [-{half}, {h}]]
u = {{ n = 24, ratio = 0.88 }}
v = 1
material = "steel"
names = {{ bottom = "bed", top = "free" }}

[[bodies.blocks]]
corners = [[-1.0, 0.0], [1.0, 0.0], [1.0, {h}], [-1.0, {h}]]
u = 1
v = 1
material = "steel"
names = {{ bottom = "bed", top = "loaded" }}

[[bodies.blocks]]
corners = [[1.0, 0.0], [{half}, 0.0], [{half}, {h}], [1.0, {h}]]
u = {{ n = 24, ratio = 1.136 }}
v = 1
material = "steel"
names = {{ bottom = "bed", top = "free" }}

[[bodies.springs]]
edge = "bed"
normal = {kn}

# A bed of normal springs does not hold the strip sideways; one point does, and with no
# sideways load its reaction is zero.
[[bodies.supports]]
point = [-1.0, 0.0]
fix = ["x"]

[[bodies.tractions]]
edge = "loaded"
normal = {pressure}

[probes]
middle = {{ body = "strip", at = [0.0, 2.5] }}
quarter = {{ body = "strip", at = [100.0, 2.5] }}
"#
    );
    let problem = Problem::from_toml(&text, "beam-on-bed").unwrap();
    let summary = driver::elastic(&problem).unwrap();
    let k = kn * t;
    let inertia = e * t * h.powi(3) / 12.0;
    let beta = (k / (4.0 * inertia)).powf(0.25);
    let w = |x: f64| {
        let bx = beta * x.abs();
        load * beta / (2.0 * k) * (-bx).exp() * (bx.cos() + bx.sin())
    };
    for (name, x) in [("middle", 0.0), ("quarter", 100.0)] {
        let ours = -probe(&summary, name, "displacement")[1];
        let exact = w(x);
        eprintln!("{name}: {ours:.6e} vs Hetényi {exact:.6e}");
        assert!(
            (ours - exact).abs() < 0.01 * w(0.0),
            "{name}: {ours} vs {exact}"
        );
    }
}

#[test]
fn lifting_the_base_by_a_prescribed_displacement_moves_the_plate_and_keeps_the_pressure() {
    // Hertz's contact (examples/hertz.toml) with the lower block's base raised by δ instead of
    // held at zero: the lower block translates rigidly by δ, so the contact pressure is the
    // same and the plate, whose motion equilibrium closes, rises by δ. Both are linear in the
    // held values: round-off, 1e-9 of the peak pressure and of δ.
    use wearfem::complementarity::{ContactSolver, Direction, Method};
    use wearfem::contact::CondensedContact;
    let text = wearfem::examples::example("hertz").unwrap();
    let delta = 0.02;
    let lifted = text.replace(
        "edge = \"base\"\nfix = [\"x\", \"z\"]",
        &format!("edge = \"base\"\nfix = [\"x\", \"z\"]\ndisplacement = [0.0, {delta}]"),
    );
    assert_ne!(text, lifted, "the example's base support moved");
    let solve = |text: &str| {
        let problem = Problem::from_toml(text, "hertz").unwrap();
        let (contact, _, _) = CondensedContact::build(&problem).unwrap();
        let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
        solver.solve(&contact.points.initial_gap, Direction::Plus).0
    };
    let (held, raised) = (solve(text), solve(&lifted));
    let peak = held.pressure.iter().cloned().fold(0.0, f64::max);
    for (a, b) in held.pressure.iter().zip(&raised.pressure) {
        assert!((a - b).abs() < 1e-9 * peak, "{a} vs {b}");
    }
    // The plate's translation λ_F is counted towards body 2, here downwards.
    let rise = held.rigid[0] - raised.rigid[0];
    assert!(
        (rise - delta).abs() < 1e-9 * delta,
        "the plate rose by {rise}"
    );
}

#[test]
fn a_punch_pushed_down_onto_a_block_on_a_spring_bed_presses_by_the_closed_form() {
    // A 40 × 20 mm punch whose top is pushed down by δ (a prescribed displacement; no plate:
    // body 1 is held by its own supports) onto a 40 × 30 mm block of the same steel resting
    // on a bed k_n (plane stress, frictionless). Equal widths and materials, free to spread
    // sideways (one point of each body held in x): both are in uniaxial stress σ, the contact
    // pressure is uniform, and δ = σ/k_n + σ (h₁ + h₂)/E gives it. Linear fields: round-off,
    // 1e-9.
    use wearfem::complementarity::{ContactSolver, Direction, Method};
    use wearfem::contact::CondensedContact;
    let (e, k, delta, width, t, h1, h2) = (2.0e5, 2.0, 0.05, 40.0, 10.0, 20.0, 30.0);
    let text = format!(
        r#"title = "punch on a spring bed"
[analysis]
kind = "plane_stress"
thickness = {t}
p = 4

[materials.steel]
young = {e}
poisson = 0.3

[[bodies]]
name = "punch"
[[bodies.blocks]]
corners = [[0.0, 0.0], [{width}, 0.0], [{width}, {h1}], [0.0, {h1}]]
u = 4
v = 2
material = "steel"
names = {{ bottom = "contact", top = "top" }}
[[bodies.supports]]
edge = "top"
fix = ["z"]
displacement = [0.0, -{delta}]
[[bodies.supports]]
point = [0.0, {h1}]
fix = ["x"]

[[bodies]]
name = "block"
[[bodies.blocks]]
corners = [[0.0, -{h2}], [{width}, -{h2}], [{width}, 0.0], [0.0, 0.0]]
u = 4
v = 3
material = "steel"
names = {{ bottom = "bed", top = "surface" }}
[[bodies.springs]]
edge = "bed"
normal = {k}
[[bodies.supports]]
point = [0.0, -{h2}]
fix = ["x"]

[contact]
body = "punch"
edge = "contact"
target_body = "block"
target_edge = "surface"
friction = 0.0
"#
    );
    let problem = Problem::from_toml(&text, "punch-on-bed").unwrap();
    let (contact, _, _) = CondensedContact::build(&problem).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let (solution, _) = solver.solve(&contact.points.initial_gap, Direction::Plus);
    let sigma = delta / (1.0 / k + (h1 + h2) / e);
    for &p in &solution.pressure {
        assert!((p - sigma).abs() < 1e-9 * sigma, "pressure {p} vs {sigma}");
    }
}
