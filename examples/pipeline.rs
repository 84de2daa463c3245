//! # The wearfem pipeline, one stage at a time
//!
//! `cargo run --release --example pipeline`
//!
//! The command line (`wearfem run`, `wearfem steady`) hides the stages; this program walks
//! through them with the library on the paper's Example 1 (`punch-b40`: a composite punch
//! pressed by a plate hinged 40 mm above the contact onto a steel strip that slides back and
//! forth). Each stage prints what it made, so that the output reads as a short report.
//!
//! geometry → mesh → basis & quadrature → elasticity → condensation → contact → wear → steady

use wearfem::complementarity::{ContactSolver, Direction, Method};
use wearfem::contact::CondensedContact;
use wearfem::problem::Problem;
use wearfem::steady::{steady_state, summed_pressure_theory, SteadySettings, SteadySliding};
use wearfem::wear::WearIntegrator;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // ## 1. The problem file
    //
    // Everything the model needs is in one TOML file; `from_toml` validates it (every error
    // names the file and the key) and builds the meshes once to check them.
    let text = wearfem::examples::example("punch-b40").ok_or("no built-in punch-b40")?;
    let problem = Problem::from_toml(text, "punch-b40")?;
    println!("1. problem: {}", problem.spec.title);

    // ## 2. Two elastic bodies
    //
    // Each body is meshed along its blocks' mesh lines, every element gets the integrated
    // Legendre basis of degree p on its exact (blended) geometry, the internal modes are
    // condensed element by element, and the condensed stiffness is factorised once by a
    // sparse Cholesky. The punch is clamped to the plate along its top edge.
    let (punch, strip) = CondensedContact::bodies(&problem)?;
    for body in [&punch, &strip] {
        let info = &body.info;
        println!(
            "2. {}: {} unknowns, {} after condensing the internal modes; {} distinct element matrices computed",
            body.name, info.total_dofs, info.condensed_dofs, info.distinct_elements
        );
    }

    // ## 3. Condensation onto the contact points
    //
    // The contact is enforced at the Gauss–Lobatto points of the punch's bottom elements.
    // Solving both bodies for unit forces at those points (2N right-hand sides, no new
    // factorisation) gives the flexibility matrices: from here on, the finite element model
    // is a small dense matrix, and wear never touches it again.
    let contact = CondensedContact::from_bodies(&problem, &punch, &strip)?;
    println!(
        "3. {} contact points, plate unknowns {:?}",
        contact.len(),
        contact.rigid_names
    );

    // ## 4. One contact solve per sliding direction
    //
    // Signorini conditions, Coulomb friction in full slip and the plate equilibrium form a
    // mixed complementarity problem; the active-set method solves it exactly.
    let mut solver = ContactSolver::new(&contact, Method::ActiveSet);
    let gap = contact.points.initial_gap.clone();
    for direction in [Direction::Plus, Direction::Minus] {
        let (solution, info) = solver.solve(&gap, direction);
        let n = solution.pressure.len();
        println!(
            "4. '{}': p = {:.1} | {:.1} | {:.1} MPa at the left edge, centre and right edge; {} iterations, complementarity {:.0e}, equilibrium {:.0e}",
            direction.symbol(),
            solution.pressure[0],
            solution.pressure[n / 2],
            solution.pressure[n - 1],
            info.iterations,
            info.complementarity,
            info.equilibrium
        );
    }

    // ## 5. Wear, half period by half period
    //
    // The wear rule ẇ = β̃ p v integrated with the paper's half-period scheme: the pressure at
    // the end of each half period, iterated to criterion eq. 27, and the extrapolation factor
    // k = 1, 5, 10. Each step costs a few contact solves with the same factorisations.
    let spec = problem.spec.wear.clone().ok_or("no [wear] section")?;
    let integrator =
        WearIntegrator::new(&spec).map_err(|(key, message)| format!("{key}: {message}"))?;
    let start = std::time::Instant::now();
    let history = integrator.run(&mut solver, &contact, &gap, &[0], |_| {});
    let last = history.steps.last().ok_or("no steps")?;
    println!(
        "5. {} steps = {} half periods in {:.1} ms ({} contact solves); p(M) = {:.3} MPa at the last step",
        history.steps.len(),
        last.half_period,
        1e3 * start.elapsed().as_secs_f64(),
        history.solves,
        history.p_plus[0]
    );

    // ## 6. The steady state, directly
    //
    // In the periodic steady state the wear of a period is a rigid-body motion of the plate:
    // the summed pressure p⁺ + p⁻ follows from the load alone (paper eq. 19), and the steady
    // shape solves one coupled system for both half cycles.
    let start = std::time::Instant::now();
    let state = steady_state(
        &contact,
        &integrator.half_period_wear(),
        SteadySliding::Reciprocating,
        SteadySettings::default(),
    )?;
    let theory = summed_pressure_theory(&contact).ok_or("the plate cannot move")?;
    let deviation = (0..contact.len())
        .map(|i| (state.p_plus[i] + state.p_minus[i] - theory[i]).abs())
        .fold(0.0, f64::max);
    let integrated = (0..contact.len())
        .map(|i| (state.p_plus[i] - history.p_plus[i]).abs())
        .fold(0.0, f64::max);
    println!(
        "6. steady state ({:?}) in {} iterations, {:.1} ms: p⁺ + p⁻ meets eq. 19 to {:.0e} MPa; the 1700-step integration is within {:.2} MPa of it",
        state.status,
        state.iterations,
        1e3 * start.elapsed().as_secs_f64(),
        deviation,
        integrated
    );
    Ok(())
}
