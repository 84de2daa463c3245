//! Windowed tractions on curved edges: the resultant of a uniform pressure on the part of an
//! arc inside a coordinate window, against the closed form, for meshes that put the arc's
//! turning point (where the window coordinate turns back) inside an element or on a vertex.
//!
//! A uniform pressure q on a curve from A to B has the resultant q t (B − A) turned by 90°:
//! on the pieces of a circle symmetric about its turning point the resultant lies along the
//! window's axis, q t times the pieces' total extent across it.

use wearfem::problem::Problem;

const THICKNESS: f64 = 10.0;
const PRESSURE: f64 = 1.0;

/// One block 60 × 40 mm with arc edges: the top edge a crown about (30, −50) through the
/// corners (0, 40) and (60, 40) (apex z = −50 + R at x = 30), the left edge bulging out about
/// (8, 20) through (0, 0) and (0, 40). Loaded by `traction` (a TOML inline table) on `edge`.
fn block(u: usize, v: usize, edge: &str, window: &str) -> String {
    format!(
        r#"
title = "arc windows"
[analysis]
kind = "plane_strain"
thickness = {THICKNESS}
p = 4
[materials.m]
young = 2.0e5
poisson = 0.3
[[bodies]]
name = "block"
[[bodies.blocks]]
corners = [[0.0, 0.0], [60.0, 0.0], [60.0, 40.0], [0.0, 40.0]]
arcs = [{{ edge = 2, center = [30.0, -50.0] }}, {{ edge = 3, center = [8.0, 20.0] }}]
u = {u}
v = {v}
material = "m"
names = {{ bottom = "base", top = "crown", left = "bulge" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[[bodies.tractions]]
edge = "{edge}"
normal = {PRESSURE}
window = {window}
"#
    )
}

fn resultant(text: &str, edge: &str) -> [f64; 2] {
    let problem = Problem::from_toml(text, "arc windows").expect("a valid problem");
    let mesh = problem.mesh(0).expect("a mesh");
    let edges = problem
        .named_edge(&mesh, 0, edge, "edge")
        .expect("the edge");
    let traction = &problem.tractions(0).expect("tractions")[0];
    let analysis = wearfem::material::Analysis::PlaneStress {
        thickness: THICKNESS,
    };
    traction.resultant(&mesh, edges, 4, analysis, [0.0, 0.0]).0
}

/// The half-width of a circle of radius `radius` about `center` at `offset` from it, measured
/// across: √(R² − d²).
fn half_chord(radius: f64, offset: f64) -> f64 {
    (radius * radius - offset * offset).sqrt()
}

/// The resultant `force` (N) is `expected` along axis `along` (0: x, 1: z) and zero across,
/// to 1e-9 of the load: Gauss quadrature on each piece of an exact arc is round-off.
fn assert_resultant(force: [f64; 2], expected: f64, along: usize, case: &str) {
    let tolerance = 1e-9 * expected.abs();
    assert!(
        (force[along] - expected).abs() < tolerance,
        "{case}: {} N, exact {expected} N",
        force[along]
    );
    assert!(
        force[1 - along].abs() < tolerance,
        "{case}: {} N across",
        force[1 - along]
    );
}

#[test]
fn a_z_window_over_a_crown_loads_the_arc_inside_it_whatever_the_mesh() {
    let radius = 30.0f64.hypot(90.0);
    let apex = -50.0 + radius;
    // Windows below the apex (two pieces), across it (one piece), and from the corners' level.
    for (lo, hi) in [(44.0, 44.5), (44.5, 44.9), (41.0, 44.6), (40.0, 44.0)] {
        let width = |z: f64| 2.0 * half_chord(radius, z.min(apex) + 50.0);
        let expected = -PRESSURE * THICKNESS * (width(lo) - width(hi));
        // u = 1 and 3 put the apex inside an element; 2 and 4 on a vertex.
        for u in [1, 2, 3, 4, 5] {
            let window = format!("{{ z = [{lo}, {hi}] }}");
            let force = resultant(&block(u, 2, "crown", &window), "crown");
            assert_resultant(
                force,
                expected,
                1,
                &format!("window [{lo}, {hi}], u = {u}: F_z"),
            );
        }
    }
}

#[test]
fn an_x_window_over_a_bulge_loads_both_pieces() {
    let radius = 8.0f64.hypot(20.0);
    let leftmost = 8.0 - radius;
    for (lo, hi) in [(-2.5, -1.0), (-3.0, -2.0), (leftmost - 1.0, -2.0)] {
        // The pieces' extent in z: where the circle's x lies in [lo, hi].
        let height = |x: f64| 2.0 * half_chord(radius, 8.0 - x.max(leftmost));
        // The pressure pushes into the body: +x on the left edge.
        let expected = PRESSURE * THICKNESS * (height(hi) - height(lo));
        for v in [1, 2, 3, 5] {
            let window = format!("{{ x = [{lo}, {hi}] }}");
            let force = resultant(&block(2, v, "bulge", &window), "bulge");
            assert_resultant(
                force,
                expected,
                0,
                &format!("window [{lo}, {hi}], v = {v}: F_x"),
            );
        }
    }
}

#[test]
fn a_window_over_an_apex_is_not_refused() {
    // One element on the crown: both ends at z = 40, the apex at 44.87 between them. Reading
    // the coordinate at the ends only called this window "acting nowhere".
    let text = block(1, 1, "crown", "{ z = [44.5, 44.8] }");
    assert!(Problem::from_toml(&text, "arc windows").is_ok());
}

#[test]
fn an_x_window_over_a_bulge_whose_apex_is_an_element_centre() {
    // The right side bulges about (39, 10) through (40, 0) and (40, 20), its apex at z = 10:
    // for an odd number of equal elements it is the middle element's centre, where the search
    // for turning points samples the tangent exactly at its zero (red team 14: +125 %).
    let radius = 1.0f64.hypot(10.0);
    let half_height = |x: f64| half_chord(radius, x - 39.0);
    for v in [1, 3, 5] {
        let text = format!(
            r#"
title = "bulge"
[analysis]
kind = "plane_stress"
thickness = {THICKNESS}
p = 4
[materials.m]
young = 2.0e5
poisson = 0.3
[[bodies]]
name = "pad"
[[bodies.blocks]]
corners = [[0.0, 0.0], [40.0, 0.0], [40.0, 20.0], [0.0, 20.0]]
arcs = [{{ edge = 1, center = [39.0, 10.0] }}]
u = 2
v = {v}
material = "m"
names = {{ bottom = "base", right = "side" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]
[[bodies.tractions]]
edge = "side"
normal = {PRESSURE}
window = {{ x = [42.0, 48.0] }}
"#
        );
        let force = resultant(&text, "side");
        // The pressure pushes into the body, −x on the right side, over the two pieces'
        // extent in z.
        let expected = -PRESSURE * THICKNESS * 2.0 * (half_height(42.0) - half_height(48.0));
        assert_resultant(force, expected, 0, &format!("v = {v}: F_x"));
    }
}
