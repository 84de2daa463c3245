//! A problem's meshes are built once and shared with problems built from the same inputs
//! (`src/input/problem/meshes.rs`). These tests make sure that sharing never hands a problem
//! the mesh of another: each variant's mesh is checked against what its own geometry says it
//! must be (element counts from its divisions, body 2's contact-edge vertices from its own
//! lines and body 1's element ends), across more geometries than the process keeps, from
//! two threads, and after the spec of a validated problem is changed.

use wearfem::overrides::{parse_value, Override};
use wearfem::problem::{LinesSpec, Problem};

/// Example 1 (punch-b40): the punch's two blocks are 8 (u) × 3 (v) and 8 × 4 elements, the
/// strip's contact edge at z = 100 has lines at these x (mm).
fn punch() -> Problem {
    let text = wearfem::examples::example("punch-b40").expect("built-in example");
    Problem::from_toml(text, "punch-b40").expect("valid problem")
}

const STRIP_LINES: [f64; 13] = [
    1000.0, 1040.0, 1070.0, 1077.5, 1085.0, 1092.5, 1100.0, 1107.5, 1115.0, 1122.5, 1130.0, 1160.0,
    1200.0,
];

/// Example 1 with the punch cut into `u` columns (both blocks) and its lowest block into `v`
/// rows.
fn variant(u: usize, v: usize) -> Problem {
    let text = wearfem::examples::example("punch-b40").expect("built-in example");
    let set = |key: &str, value: usize| {
        Override::new(key, parse_value(&value.to_string())).expect("a valid override")
    };
    let overrides = [
        set("bodies[0].blocks[0].u", u),
        set("bodies[0].blocks[1].u", u),
        set("bodies[0].blocks[0].v", v),
    ];
    Problem::with_overrides(text, "punch-b40", &overrides).expect("a valid variant")
}

/// The x of the strip's vertices on its contact edge (z = 100 mm), sorted.
fn strip_surface_x(problem: &Problem) -> Vec<f64> {
    let mesh = problem.mesh(1).expect("the strip's mesh");
    let mut x: Vec<f64> = mesh
        .vertices
        .iter()
        .filter(|v| (v[1] - 100.0).abs() < 1e-9)
        .map(|v| v[0])
        .collect();
    x.sort_by(f64::total_cmp);
    x
}

/// What the strip's contact edge must have: its own lines and the punch's element ends
/// (1070 + 60 i/u mm), each once (1e-9 mm: the merge tolerance of coincident lines is far
/// larger, 1e-9 of the body's size, and far smaller than any spacing here).
fn expected_surface_x(u: usize) -> Vec<f64> {
    let mut x: Vec<f64> = STRIP_LINES.to_vec();
    for i in 0..=u {
        let end = 1070.0 + 60.0 * i as f64 / u as f64;
        if x.iter().all(|&s| (s - end).abs() > 1e-6) {
            x.push(end);
        }
    }
    x.sort_by(f64::total_cmp);
    x
}

/// Whether two sorted vertex lists agree to 1e-9 mm (the added lines are placed by
/// parameter, so their x carries round-off of 1e-12 mm).
fn assert_same_x(surface: &[f64], expected: &[f64], what: &str) {
    assert_eq!(
        surface.len(),
        expected.len(),
        "{what}: {surface:?} against {expected:?}"
    );
    for (got, want) in surface.iter().zip(expected) {
        assert!(
            (got - want).abs() < 1e-9,
            "{what}: {surface:?} against {expected:?}"
        );
    }
}

fn check_variant(u: usize, v: usize) {
    let problem = variant(u, v);
    let punch_elements = problem.mesh(0).expect("the punch's mesh").elements.len();
    assert_eq!(punch_elements, u * v + u * 4, "punch of {u} × {v}");
    let what = format!("strip under a punch of {u} columns");
    assert_same_x(&strip_surface_x(&problem), &expected_surface_x(u), &what);
}

#[test]
fn each_variant_has_the_meshes_of_its_own_geometry() {
    // Seven geometries, more than the four sets the process keeps, visited twice in
    // different orders: every hit and every rebuild must give the variant's own meshes.
    let geometries = [(8, 3), (5, 3), (6, 2), (7, 3), (3, 5), (4, 1), (5, 2)];
    for &(u, v) in geometries.iter().chain(geometries.iter().rev()) {
        check_variant(u, v);
    }
}

#[test]
fn variants_built_on_two_threads_have_their_own_meshes() {
    let left = std::thread::spawn(|| {
        for round in 0..5 {
            check_variant(5 + round % 2, 3);
        }
    });
    for round in 0..5 {
        check_variant(7 + round % 2, 2);
    }
    left.join().expect("the other thread's variants");
}

#[test]
fn a_changed_spec_gets_meshes_of_its_own() {
    let mut problem = punch();
    assert_eq!(problem.mesh(0).expect("mesh").elements.len(), 8 * 3 + 8 * 4);
    // A library user may edit a validated problem's spec: the meshes follow it.
    problem.spec.bodies[0].blocks[0].v = LinesSpec::Count(6);
    assert_eq!(problem.mesh(0).expect("mesh").elements.len(), 8 * 6 + 8 * 4);
    for block in &mut problem.spec.bodies[0].blocks {
        block.u = LinesSpec::Count(5);
    }
    assert_eq!(problem.mesh(0).expect("mesh").elements.len(), 5 * 6 + 5 * 4);
    let surface = strip_surface_x(&problem);
    assert_same_x(&surface, &expected_surface_x(5), "edited spec, 5 columns");
    // Without alignment the strip keeps its own lines.
    problem
        .spec
        .contact
        .as_mut()
        .expect("contact")
        .align_target_mesh = false;
    assert_same_x(
        &strip_surface_x(&problem),
        &STRIP_LINES,
        "edited spec, not aligned",
    );
    // And the original problem is untouched by all this.
    assert_same_x(
        &strip_surface_x(&punch()),
        &expected_surface_x(8),
        "example",
    );
}

/// The materials' order and the bodies' names are part of what a mesh is built from: a block's
/// material is an index into the materials in name order, and the contact names its bodies.
/// Built in the same process as punch-b40 itself, each must get meshes of its own:
/// - punch-b40 with an unused material "aluminium" (E = 7e4 MPa), first in name order: the
///   blocks are the same, their materials' indices shift, and every element of the punch's
///   lowest block must still have the composite's E = 1.3e5 MPa (the file's), the others
///   steel's 2e5;
/// - punch-b40 with the punch in 5 columns (its strip then gets lines at the punch's element
///   ends) and its bodies' names swapped: the contact now names the strip's blocks as body 1,
///   which have no edge "contact", so no lines are added to body 2, and the strip's blocks
///   (named "punch") keep only their own lines.
#[test]
fn material_order_and_body_names_reach_the_meshes() {
    let text = wearfem::examples::example("punch-b40").expect("built-in example");
    let materials = |problem: &Problem| {
        let mesh = problem.mesh(0).expect("the punch's mesh");
        for element in &mesh.elements {
            let young = problem.materials[element.material].young;
            let expected = if element.block == 0 { 1.3e5 } else { 2.0e5 };
            assert_eq!(young, expected, "block {}", element.block);
        }
    };
    let with_aluminium = text.replace(
        "[materials.composite]",
        "[materials.aluminium]\nyoung = 7.0e4\npoisson = 0.33\n\n[materials.composite]",
    );
    // The punch in 5 columns, so that aligning the strip to it adds lines (with 8 it adds
    // none, and an aligned strip could not be told from one as given).
    let five = text.replace("\nu = 8", "\nu = 5");
    assert_eq!(five.matches("\nu = 5").count(), 2, "the punch's two blocks");
    let swapped = five
        .replace("name = \"punch\"", "name = \"x\"")
        .replace("name = \"strip\"", "name = \"punch\"")
        .replace("name = \"x\"", "name = \"strip\"");
    for _ in 0..2 {
        let original = Problem::from_toml(text, "punch-b40").expect("valid");
        materials(&original);
        assert_same_x(
            &strip_surface_x(&original),
            &expected_surface_x(8),
            "original",
        );
        let other = Problem::from_toml(&with_aluminium, "aluminium").expect("valid");
        assert_eq!(
            other.spec.materials.keys().next().map(String::as_str),
            Some("aluminium")
        );
        materials(&other);
        let aligned = Problem::from_toml(&five, "five columns").expect("valid");
        assert_same_x(
            &strip_surface_x(&aligned),
            &expected_surface_x(5),
            "five columns",
        );
        let swapped = Problem::from_toml(&swapped, "swapped").expect("valid");
        assert_eq!(swapped.spec.bodies[1].name, "punch");
        assert_same_x(&strip_surface_x(&swapped), &STRIP_LINES, "names swapped");
    }
}
