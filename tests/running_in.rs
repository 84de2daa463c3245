//! Runs whose contact zone still grows (issue 28, item 5): no steady-state advice and no
//! distance from a steady state the run is not yet heading for, or that does not exist.

use wearfem::driver;
use wearfem::problem::Problem;
use wearfem::steady_check::SteadyCheck;

#[test]
fn a_crowned_block_wearing_flat_is_running_in() {
    // The hertz example's crowned block (R = 500 mm as an initial gap) sliding one way: its
    // worn zone grows from Hertz's ±3 mm towards the whole 40 mm face, whose steady state
    // exists (the face ends at the block's corners). The run says it is running in, with both
    // zones, gives no advice to run longer, and writes no distance as a result.
    let text = format!(
        "{}\n[wear]\nbody1 = {{ beta = 1.0e-7, a = 1.0, b = 1.0 }}\nsliding = \"monotonic\"\nspeed = 100.0\nstep_time = 1.0\nsteps = 30\n",
        wearfem::examples::example("hertz").unwrap()
    );
    let problem = Problem::from_toml(&text, "crowned block").unwrap();
    let run = driver::wear(&problem, None, |_| {}).unwrap();
    let SteadyCheck::Growing {
        run: zone,
        steady,
        unbounded,
        ..
    } = run.steady_check.clone()
    else {
        panic!("{:?}", run.steady_check)
    };
    assert!(!unbounded);
    assert!(
        zone[1] - zone[0] < 0.5 * (steady[1] - steady[0]),
        "{zone:?} {steady:?}"
    );
    let line = run.console_cycle(false).unwrap();
    assert!(
        line.contains("running in") && !line.contains("run longer"),
        "{line}"
    );
    assert!(
        line.starts_with("last step:"),
        "monotonic runs speak of steps: {line}"
    );
    let summary = run.summary(&problem);
    assert!(summary["steady_distance"]["pressure"].is_null());
    assert_eq!(summary["steady_reached"], false);
}

#[test]
fn a_cylinder_named_on_a_piece_of_its_arc_has_no_steady_state() {
    // Red team 22's cylinder, its contact edge named on the middle block only (±3.3°) of an
    // arc that goes on: the steady state of the named edge fills it to its ends, where the
    // surface continues, so none exists on the surface, and none is measured against.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/cylinder-wears-its-flat.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let mut blocks: Vec<String> = text.split("[[bodies.blocks]]").map(String::from).collect();
    for side in [1, 3] {
        blocks[side] = blocks[side].replace("bottom = \"contact\"", "bottom = \"rest\"");
    }
    let text = blocks
        .join("[[bodies.blocks]]")
        .replace("steps = 30000\n[wear.adaptive]\n", "steps = 60\n");
    let problem = Problem::from_toml(&text, "cylinder, a piece of its arc").unwrap();
    let run = driver::wear(&problem, None, |_| {}).unwrap();
    assert!(
        matches!(
            run.steady_check,
            SteadyCheck::Growing {
                unbounded: true,
                ..
            }
        ),
        "{:?}",
        run.steady_check
    );
    let line = run.console_cycle(false).unwrap();
    assert!(
        line.contains("no steady state exists on this surface") && !line.contains("% of the peak"),
        "{line}"
    );
}
