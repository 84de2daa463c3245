//! The validation cases of an engineer's own part (issue 28): supports with a prescribed
//! displacement and on a spring bed against closed forms, and each body's worn volume against
//! Archard's law. The bounds are tests/supports.rs's and tests/body_wear.rs's.

use super::cases::{fail, push, wear, Checks, Outcome};
use super::Bound;
use crate::problem::Problem;

/// A 100 × 20 mm steel block, plane stress, 10 mm thick, p = 4, with `extra` appended.
fn block(extra: &str) -> Result<Problem, super::ValidateError> {
    let text = format!(
        "title = \"block\"\n[analysis]\nkind = \"plane_stress\"\nthickness = 10.0\np = 4\n\
         [materials.steel]\nyoung = 2.0e5\npoisson = 0.3\n[[bodies]]\nname = \"block\"\n\
         [[bodies.blocks]]\ncorners = [[0.0, 0.0], [100.0, 0.0], [100.0, 20.0], [0.0, 20.0]]\n\
         u = 4\nv = 2\nmaterial = \"steel\"\n\
         names = {{ bottom = \"bottom\", right = \"right\", top = \"top\", left = \"left\" }}\n\
         [probes]\nmiddle = {{ body = \"block\", at = [37.0, 13.0] }}\n{extra}"
    );
    Problem::from_toml(&text, "block").map_err(|e| fail("block", e))
}

/// Supports: a prescribed shortening gives uniaxial stress; a bed of springs k_n under a
/// uniform pressure q lets the block sink by q/k_n + q h/E.
pub fn supports(checks: &mut Checks) -> Outcome {
    let (e, delta, length) = (2.0e5, 0.05, 100.0);
    let shortened = block(
        "[[bodies.supports]]\nedge = \"left\"\nfix = [\"x\"]\n\
         [[bodies.supports]]\npoint = [0.0, 0.0]\nfix = [\"z\"]\n\
         [[bodies.supports]]\nedge = \"right\"\nfix = [\"x\"]\ndisplacement = [-0.05, 0.0]\n",
    )?;
    let summary = crate::driver::elastic(&shortened).map_err(|e| fail("block", e))?;
    let stress = summary["probes"]["middle"]["stress"][0]
        .as_f64()
        .ok_or_else(|| fail("block", "no stress at the probe"))?;
    push(
        checks,
        "supports.prescribed",
        "a block shortened by δ = 0.05 mm: σ_xx at (37, 13)",
        "MPa",
        -e * delta / length,
        "uniaxial stress −E δ/L",
        stress,
        Bound::Relative(1e-10),
    );
    let (q, k, z) = (5.0, 0.8, 13.0);
    let bedded = block(&format!(
        "[[bodies.springs]]\nedge = \"bottom\"\nnormal = {k}\n\
         [[bodies.supports]]\nedge = \"left\"\nfix = [\"x\"]\n\
         [[bodies.tractions]]\nedge = \"top\"\nnormal = {q}\n"
    ))?;
    let summary = crate::driver::elastic(&bedded).map_err(|e| fail("block", e))?;
    let sink = summary["probes"]["middle"]["displacement"][1]
        .as_f64()
        .ok_or_else(|| fail("block", "no displacement at the probe"))?;
    // At z = 13 mm the block has shortened by q (h − 13)/E above the bed's q/k_n.
    push(
        checks,
        "supports.spring_bed",
        "a block on a bed k_n = 0.8 N/mm³ under 5 MPa: u_z at (37, 13)",
        "mm",
        -(q / k + q * z / e),
        "q/k_n + q z/E (z from the bed)",
        sink,
        Bound::Relative(1e-10),
    );
    Ok(())
}

/// Each body's worn volume: punch-a with both bodies wearing (a = b = 1) for 40 steps; the
/// volume of body i is β̃ᵢ F s.
pub fn body_volumes(checks: &mut Checks) -> Outcome {
    let beta1 = 3.9269908169872414e-8;
    let p = super::cases::problem(
        "punch-a",
        &[
            ("shape_zero_at = 1100.0", ""),
            (
                "body1 = { beta = 3.9269908169872414e-8, a = 1.0, b = 1.0 }",
                "body1 = { beta = 3.9269908169872414e-8, a = 1.0, b = 1.0 }\nbody2 = { beta = 1.9634954084936207e-8, a = 1.0, b = 1.0 }",
            ),
        ],
    )?;
    let run = wear(&p, Some(40))?;
    let sliding =
        run.history.steps.last().map_or(0, |s| s.half_period) as f64 * run.sliding_per_half_period;
    let force = 16.666 * 60.0 * 10.0;
    for (body, beta) in [(0, beta1), (1, 0.5 * beta1)] {
        let volume = crate::wear::worn_volume(
            &run.contact.points,
            &run.history.body_wear[body],
            run.contact.thickness,
        );
        push(
            checks,
            format!("wear.volume_body{}", body + 1),
            format!(
                "punch-a, both bodies wearing, 40 steps: volume worn off body {}",
                body + 1
            ),
            "mm³",
            beta * force * sliding,
            "Archard: β̃ᵢ F s",
            volume,
            Bound::Relative(1e-9),
        );
    }
    Ok(())
}
