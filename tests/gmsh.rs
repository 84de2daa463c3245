//! Bodies meshed by Gmsh (issue 28, item 1): the meshes in tests/gmsh/ were made by the gmsh
//! Python package (tests/gmsh/make_meshes.py).

use std::path::PathBuf;
use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::driver;
use wearfem::problem::Problem;

fn mesh(name: &str) -> String {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "gmsh", name]
        .iter()
        .collect();
    path.display().to_string()
}

/// The built-in example `hertz` with both bodies from `file`, `arcs` added to the cylinder's
/// `[bodies.gmsh]`, and `initial_shape` as given (None: removed).
fn hertz_from(file: &str, arcs: &str, initial_shape: bool) -> Problem {
    let shape = if initial_shape {
        "initial_shape = { radius = 500.0, center_x = 0.0 }"
    } else {
        ""
    };
    let text = format!(
        r#"title = "Hertz from Gmsh"
[analysis]
kind = "plane_strain"
thickness = 1.0
p = 8

[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "cylinder"
[bodies.gmsh]
file = "{file}"
materials = {{ cylinder = "steel" }}
{arcs}
[[bodies.tractions]]
edge = "top"
normal = 38.825

[[bodies]]
name = "block"
[bodies.gmsh]
file = "{file}"
materials = {{ block = "steel" }}
[[bodies.supports]]
edge = "base"
fix = ["x", "z"]

[contact]
body = "cylinder"
edge = "contact"
target_body = "block"
target_edge = "surface"
{shape}

[plate]
edge = "top"
motion = "vertical"
"#
    );
    Problem::from_toml(&text, "hertz-gmsh").unwrap()
}

fn pressures(problem: &Problem) -> (Vec<[f64; 2]>, Vec<f64>) {
    let (contact, _, _) = CondensedContact::build(problem).unwrap();
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let (solution, _) = solver.solve(&contact.points.initial_gap, Direction::Plus);
    (contact.points.x.clone(), solution.pressure)
}

fn builtin_hertz() -> (Vec<[f64; 2]>, Vec<f64>) {
    let text = wearfem::examples::example("hertz").unwrap();
    pressures(&Problem::from_toml(text, "hertz").unwrap())
}

#[test]
fn the_example_s_own_mesh_from_gmsh_gives_its_pressure() {
    // The same elements as the example's blocks, read from Gmsh's ASCII and binary files:
    // the same contact points and pressures, to round-off (1e-9 of p₀).
    let (x0, p0) = builtin_hertz();
    let peak = p0.iter().cloned().fold(0.0, f64::max);
    for file in ["hertz-blocks.msh", "hertz-blocks-binary.msh"] {
        let (x, p) = pressures(&hertz_from(&mesh(file), "", true));
        assert_eq!(x.len(), x0.len(), "{file}");
        for i in 0..x.len() {
            assert!((x[i][0] - x0[i][0]).abs() < 1e-9, "{file}: point {i}");
            assert!(
                (p[i] - p0[i]).abs() < 1e-9 * peak,
                "{file}: {} vs {}",
                p[i],
                p0[i]
            );
        }
    }
}

#[test]
fn a_real_arc_snapped_gives_the_example_s_pressure() {
    // The cylinder's curvature as geometry (an arc of radius 500 mm) instead of an initial
    // gap on a flat block: the gap differs by x⁴/8R³ (8e-8 mm at the zone's edge, against an
    // approach of 0.018 mm) and the normals tilt by x/R ≤ 0.006: the pressures agree within
    // the issue's 0.1 % of p₀ (measured 8.8e-4, at the point next to the zone's end, where the
    // pressure falls by some 600 MPa/mm and a shift of the end by 5e-4 mm makes it). Second-order geometry instead of the snapped arc: its error
    // is reported (docs/validation.md), and bounded here by the same 0.1 % on this radius.
    let (x0, p0) = builtin_hertz();
    let peak = p0.iter().cloned().fold(0.0, f64::max);
    let arcs = "arcs = [{ edge = \"contact\", center = [0.0, 500.0] }]";
    for (file, arcs) in [
        ("hertz-arc.msh", arcs),
        ("hertz-arc-order2.msh", arcs),
        ("hertz-arc-order2.msh", ""),
    ] {
        let (x, p) = pressures(&hertz_from(&mesh(file), arcs, false));
        assert_eq!(x.len(), x0.len());
        let worst = (0..x.len())
            .map(|i| (p[i] - p0[i]).abs())
            .fold(0.0, f64::max);
        let at = (0..x.len())
            .max_by(|&i, &j| (p[i] - p0[i]).abs().total_cmp(&(p[j] - p0[j]).abs()))
            .unwrap();
        eprintln!(
            "{file} {arcs:?}: largest difference {:.3e} of p₀ at x = {:.3} ({:.4} vs {:.4} MPa)",
            worst / peak,
            x[at][0],
            p[at],
            p0[at]
        );
        assert!(
            worst < 1e-3 * peak,
            "{file} {arcs}: {:.3e} of p₀",
            worst / peak
        );
    }
}

/// The built-in example `lame` on the Gmsh mesh `file` (2 × 2 quadrangles of the ring), with
/// `arcs` in its `[bodies.gmsh]`: u_r at the inner and outer radius.
fn lame_from(file: &str, arcs: &str) -> [f64; 2] {
    let text = format!(
        r#"title = "Lamé from Gmsh"
[analysis]
kind = "plane_strain"
thickness = 1.0
p = 8

[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "ring"
[bodies.gmsh]
file = "{file}"
materials = {{ ring = "steel" }}
{arcs}
[[bodies.supports]]
edge = "x_axis"
fix = ["z"]
[[bodies.supports]]
edge = "z_axis"
fix = ["x"]
[[bodies.tractions]]
edge = "inner"
normal = 100.0

[probes]
inner = {{ body = "ring", at = [100.0, 0.0] }}
outer = {{ body = "ring", at = [200.0, 0.0] }}
"#
    );
    let problem = Problem::from_toml(&text, "lame-gmsh").unwrap();
    let summary = driver::elastic(&problem).unwrap();
    ["inner", "outer"].map(|n| summary["probes"][n]["displacement"][0].as_f64().unwrap())
}

fn lame_radial(r: f64) -> f64 {
    let (a, b, p, e, nu) = (100.0f64, 200.0f64, 100.0f64, 2.0e5f64, 0.3f64);
    let aa = p * a * a / (b * b - a * a);
    let bb = p * a * a * b * b / (b * b - a * a);
    (1.0 + nu) / e * ((1.0 - 2.0 * nu) * aa * r + bb / r)
}

#[test]
fn snapped_arcs_are_exact_and_second_order_geometry_costs_its_error() {
    // Lamé's cylinder on 2 × 2 quadrangles of 45°: with both arcs snapped the geometry is
    // exact and the built-in example's 1e-7 holds; as parabolas through the 9-node
    // elements' mid nodes the rings are off by up to about 1e-4 of the radius, and so is u_r
    // (measured 1e-4 to 1e-3; docs/validation.md) — the cost of not snapping.
    let file = mesh("lame-order2.msh");
    let snapped = lame_from(
        &file,
        "arcs = [{ edge = \"inner\", center = [0.0, 0.0] }, { edge = \"outer\", center = [0.0, 0.0] }]",
    );
    let parabolas = lame_from(&file, "");
    for (k, r) in [100.0, 200.0].into_iter().enumerate() {
        let exact = lame_radial(r);
        let snapped_error = (snapped[k] - exact).abs() / exact;
        let parabola_error = (parabolas[k] - exact).abs() / exact;
        eprintln!("r = {r}: snapped {snapped_error:.2e}, second order {parabola_error:.2e}");
        assert!(
            snapped_error < 1e-7,
            "snapped, r = {r}: {snapped_error:.3e}"
        );
        assert!(
            parabola_error > 100.0 * snapped_error,
            "the geometry error shows"
        );
        assert!(parabola_error < 1e-2, "r = {r}: {parabola_error:.3e}");
    }
}

fn error_of(text: &str) -> String {
    Problem::from_toml(text, "bad-gmsh")
        .and_then(|p| {
            driver::elastic(&p).map(|_| ()).map_err(|e| match e {
                driver::JobError::Problem(p) => p,
                other => panic!("{other}"),
            })
        })
        .expect_err("must be refused")
        .to_string()
}

fn ring_problem(file: &str, materials: &str, arcs: &str) -> String {
    format!(
        r#"title = "ring"
[analysis]
kind = "plane_strain"
thickness = 1.0
p = 4
[materials.steel]
young = 2.0e5
poisson = 0.3
[[bodies]]
name = "ring"
[bodies.gmsh]
file = "{file}"
materials = {materials}
{arcs}
[[bodies.supports]]
edge = "x_axis"
fix = ["z"]
[[bodies.supports]]
edge = "z_axis"
fix = ["x"]
"#
    )
}

#[test]
fn wrong_meshes_and_groups_are_refused_by_name() {
    let ring = mesh("lame-order2.msh");
    let err = error_of(&ring_problem(&ring, "{ washer = \"steel\" }", ""));
    assert!(
        err.contains("bodies[0].gmsh.materials.washer") && err.contains("\"ring\""),
        "{err}"
    );
    let err = error_of(&ring_problem(&ring, "{ ring = \"bronze\" }", ""));
    assert!(err.contains("no material named \"bronze\""), "{err}");
    let err = error_of(&ring_problem(
        &ring,
        "{ ring = \"steel\" }",
        "arcs = [{ edge = \"inner\", center = [1.0, 0.0] }]",
    ));
    assert!(
        err.contains("bodies[0].gmsh.arcs[0].center") && err.contains("not on one circle"),
        "{err}"
    );
    let err = error_of(&ring_problem(
        &ring,
        "{ ring = \"steel\" }",
        "arcs = [{ edge = \"rim\", center = [0.0, 0.0] }]",
    ));
    assert!(
        err.contains("bodies[0].gmsh.arcs[0].edge") && err.contains("\"rim\""),
        "{err}"
    );
    let err = error_of(&ring_problem(
        &mesh("lame-triangles.msh"),
        "{ ring = \"steel\" }",
        "",
    ));
    assert!(
        err.contains("bodies[0].gmsh.file") && err.contains("triangle") && err.contains("element"),
        "{err}"
    );
    let err = error_of(&ring_problem(
        &mesh("no-such-file.msh"),
        "{ ring = \"steel\" }",
        "",
    ));
    assert!(
        err.contains("bodies[0].gmsh.file") && err.contains("no-such-file.msh"),
        "{err}"
    );
    let text = ring_problem(&mesh("two-blocks-hanging.msh"), "{ plate = \"steel\" }", "")
        .replace("x_axis", "nowhere")
        .replace("z_axis", "nowhere");
    let err = error_of(&text);
    assert!(err.contains("not conforming"), "{err}");
    // A contact edge the file does not name.
    let text = ring_problem(&ring, "{ ring = \"steel\" }", "")
        .replace("edge = \"x_axis\"", "edge = \"bottom\"");
    let err = error_of(&text);
    assert!(
        err.contains("bodies[0].supports[0].edge") && err.contains("\"bottom\""),
        "{err}"
    );
}

#[test]
fn the_worn_depth_check_measures_through_a_gmsh_body() {
    // A Gmsh body's blocks are single elements (0.05 to 26 mm deep here); the worn-depth
    // warning must measure the body under its contact edge instead: 40 mm for the cylinder
    // and 100 mm for the block, as for the example's one-block bodies (round-off, 1e-9).
    let text = wearfem::examples::example("hertz").unwrap();
    let builtin = Problem::from_toml(text, "hertz").unwrap();
    let gmsh = hertz_from(&mesh("hertz-blocks.msh"), "", true);
    for (which, depth) in [(0, 40.0), (1, 100.0)] {
        let ours = wearfem::validity::worn_blocks_depth(&gmsh, which)
            .unwrap()
            .1;
        let blocks = wearfem::validity::worn_blocks_depth(&builtin, which)
            .unwrap()
            .1;
        assert!(
            (ours - depth).abs() < 1e-9 * depth,
            "body {}: {ours}",
            which + 1
        );
        assert!(
            (blocks - depth).abs() < 1e-9 * depth,
            "body {}: {blocks}",
            which + 1
        );
    }
}
