//! The pin-on-flat example (examples/pin.toml): the run approaches the steady state, and
//! contact zones cut by the named contact edge are reported, on cases built for each answer.

use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;

fn pin() -> Problem {
    Problem::from_toml(wearfem::examples::example("pin").unwrap(), "pin").unwrap()
}

/// The pin's end as one arc of radius 4000 mm from x = −20 to 20 mm in three blocks, of which
/// only the middle one (|x| ≤ `half`) is named `cap`: the surface goes on beyond both ends.
fn continuing_arc(half: f64) -> Problem {
    Problem::from_toml(&continuing_arc_text(half), "continuing-arc").unwrap()
}

fn continuing_arc_text(half: f64) -> String {
    let text = wearfem::examples::example("pin").unwrap();
    let z = |x: f64| 4000.0 - (4000.0f64 * 4000.0 - x * x).sqrt();
    let start = text.find("[[bodies.blocks]]").unwrap();
    let end = text.find("[[bodies.tractions]]").unwrap();
    let block = |x0: f64, x1: f64, u: usize, names: &str| {
        format!(
            "[[bodies.blocks]]\ncorners = [[{x0}, {}], [{x1}, {}], [{x1}, 30.0], [{x0}, 30.0]]\narcs = [{{ edge = 0, center = [0.0, 4000.0] }}]\nu = {u}\nv = [0.0, 0.05, 0.15, 0.4, 1.0]\nmaterial = \"steel\"\nnames = {names}\n\n",
            z(x0),
            z(x1)
        )
    };
    let blocks = block(-20.0, -half, 4, "{ top = \"top\" }")
        + &block(-half, half, 20, "{ bottom = \"cap\", top = \"top\" }")
        + &block(half, 20.0, 4, "{ top = \"top\" }");
    format!("{}{}{}", &text[..start], blocks, &text[end..])
}

fn first_solve_ends(problem: &Problem) -> Vec<wearfem::contact::EdgeEnd> {
    let (contact, _, _) = CondensedContact::build(problem).unwrap();
    let (sol, _) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    contact.edge_ends_in_contact(&[&sol.pressure])
}

fn steady_ends(problem: &Problem) -> Vec<wearfem::contact::EdgeEnd> {
    let (state, contact, _) = wearfem::driver::steady(problem).unwrap();
    wearfem::driver::steady_edge_ends(&contact, &state)
}

#[test]
fn first_contact_is_reported_cut_only_when_it_reaches_a_continuing_end() {
    // Hertz half-width a = √(4 F R/(π E*)) ≈ 4.6 mm (F = 418.7 N/mm, R = 4000 mm, E* = 10⁵ MPa).
    // Named cap ±10.5 mm ending at the pin's corners: the zone lies inside, nothing to report.
    assert!(first_solve_ends(&pin()).is_empty());
    // A continuing arc named over ±10 mm: the zone (±4.6 mm) still lies inside.
    assert!(first_solve_ends(&continuing_arc(10.0)).is_empty());
    // Named over ±2 mm only: the contact reaches both ends, where the arc goes on.
    let ends = first_solve_ends(&continuing_arc(2.0));
    assert_eq!(ends.len(), 2, "{ends:?}");
    assert!(ends
        .iter()
        .all(|e| (e.x[0].abs() - 2.0).abs() < 1e-9 && e.pressure > 0.0));
}

#[test]
fn steady_contact_is_reported_cut_on_a_continuing_arc_not_at_corners() {
    // The plate only translates: in the steady state every point in contact wears at the same
    // rate, so the worn zone is the whole named cap, with pressure at both of its ends.
    // At the pin's corners (the cap turns by 87° into the sides) that is the answer itself.
    assert!(steady_ends(&pin()).is_empty());
    // On a continuing arc it is where the edge was cut: reported at both ends.
    let ends = steady_ends(&continuing_arc(10.0));
    assert_eq!(ends.len(), 2, "{ends:?}");
}

#[test]
fn run_approaches_the_steady_state_as_it_lengthens() {
    let problem = pin();
    let (steady, _, _) = wearfem::driver::steady(&problem).unwrap();
    let mut previous = f64::INFINITY;
    for steps in [1000, 4000, 8000] {
        let run = wearfem::driver::wear(&problem, Some(steps), |_| {}).unwrap();
        let h = &run.history;
        assert_eq!((h.failed_solves, h.unconverged_steps), (0, 0));
        let distance = h
            .p_plus
            .iter()
            .zip(&steady.p_plus)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            distance < previous,
            "{steps} steps: {distance:.3} MPa, before {previous:.3}"
        );
        previous = distance;
        assert!(run.edge_ends().is_empty());
    }
    // At 8000 steps (39 800 half periods) the cap is worn flat: p⁺ within 1 % of its peak,
    // 2 × 20 MPa (the run's last half cycle against the exact periodic state; the remaining
    // difference sits where p⁺ falls to zero and its slope jumps).
    assert!(
        previous < 0.01 * 40.0,
        "p⁺ differs from the steady state by {previous:.3} MPa"
    );
}

#[test]
fn the_command_line_warns_and_writes_the_cut_ends() {
    // `wearfem contact` on the ±2 mm cap: a warning line on stderr, both ends in summary.json;
    // on the shipped pin neither.
    let dir = std::env::temp_dir().join(format!("wearfem-pin-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (text, cut) in [
        (continuing_arc_text(2.0), true),
        (
            wearfem::examples::example("pin").unwrap().to_string(),
            false,
        ),
    ] {
        let file = dir.join("pin.toml");
        std::fs::write(&file, text).unwrap();
        let out = dir.join("out");
        let result = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .arg("contact")
            .arg(&file)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert!(result.status.success());
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(
            stderr.contains("warning[edge-end]") && stderr.contains("\"cap\""),
            cut,
            "{stderr}"
        );
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap();
        let ends = summary["edge_ends_in_contact"].as_array().unwrap();
        assert_eq!(ends.len(), if cut { 2 } else { 0 });
    }
    std::fs::remove_dir_all(&dir).ok();
}
