//! The validation cases of sliding pairs (issue 29): a long stroke's trough against its closed
//! form, a ring turning under a block against its even depth, and Archard's volume of each
//! body on the tribometer. The bounds are tests/sliding.rs's.

use super::cases::{fail, push, Checks, Outcome};
use super::Bound;
use crate::jobs::sliding::{self, SlidingRun};
use crate::problem::Problem;

fn sliding_run(p: &Problem, steps: Option<usize>) -> Result<SlidingRun, super::ValidateError> {
    let run = sliding::wear(p, steps).map_err(|e| fail(&p.file, e))?;
    if let Some((step, reason)) = &run.history.stopped {
        return Err(fail(&p.file, format!("step {step}: {reason}")));
    }
    Ok(run)
}

/// A steel slider 10 mm wide (crowned, R = 5000 mm) on a steel flat 140 mm long, pressed
/// with 100 N/mm, sliding pairs, one half period of a 100 mm stroke, only the flat wearing
/// (β̃₂ = 10⁻⁶ MPa⁻¹): the trough's bottom is β̃₂ F/t whatever the pressure's shape.
pub fn trough(checks: &mut Checks) -> Outcome {
    let text = "title = \"trough\"\n[analysis]\nkind = \"plane_strain\"\nthickness = 10.0\np = 6\n\
        [materials.steel]\nyoung = 2.0e5\npoisson = 0.3\n\
        [[bodies]]\nname = \"slider\"\n[[bodies.blocks]]\n\
        corners = [[-5.0, 0.0], [5.0, 0.0], [5.0, 5.0], [-5.0, 5.0]]\nu = 16\nv = [0.0, 0.2, 0.5, 1.0]\n\
        material = \"steel\"\nnames = { bottom = \"contact\", top = \"top\" }\n\
        [[bodies.tractions]]\nedge = \"top\"\nnormal = 10.0\n\
        [[bodies]]\nname = \"flat\"\n[[bodies.blocks]]\n\
        corners = [[-70.0, -20.0], [70.0, -20.0], [70.0, 0.0], [-70.0, 0.0]]\nu = 210\n\
        v = [0.0, 0.5, 0.8, 1.0]\nmaterial = \"steel\"\nnames = { bottom = \"base\", top = \"surface\" }\n\
        [[bodies.supports]]\nedge = \"base\"\nfix = [\"x\", \"z\"]\n\
        [contact]\nbody = \"slider\"\nedge = \"contact\"\ntarget_body = \"flat\"\ntarget_edge = \"surface\"\n\
        friction = 0.3\npairs = \"sliding\"\ninitial_shape = { radius = 5000.0, center_x = 0.0 }\n\
        [plate]\nedge = \"top\"\nmotion = \"vertical\"\n\
        [wear]\nbody2 = { beta = 1.0e-6 }\nsliding = \"reciprocating\"\namplitude = 50.0\nomega = 10.0\n\
        steps = 1\nextrapolation = [{ k = 1 }]\n";
    let p = Problem::from_toml(text, "sliding-trough").map_err(|e| fail("sliding-trough", e))?;
    let run = sliding_run(&p, None)?;
    let depth = 1.0e-6 * 100.0;
    let track = &run.history.track;
    // The bottom's worst point within |x| < 30 mm, where the whole contact passes with its
    // pressure's shape unchanged.
    let worst = track
        .centres()
        .iter()
        .zip(&track.wear)
        .filter(|(x, _)| x.abs() < 30.0)
        .map(|(_, w)| *w)
        .max_by(|a, b| (a - depth).abs().total_cmp(&(b - depth).abs()))
        .unwrap_or(f64::NAN);
    push(
        checks,
        "sliding.trough",
        "sliding pairs, a 100 mm stroke over a 5 mm contact: the flat's trough bottom (worst point within ±30 mm of the middle)",
        "mm",
        depth,
        "β̃₂ F/t (∫ p dx = F/t)",
        worst,
        Bound::Relative(5e-3),
    );
    push(
        checks,
        "sliding.trough_volume",
        "the same: the flat's worn volume",
        "mm³",
        1.0e-6 * 1000.0 * 100.0,
        "Archard: β̃₂ F s",
        run.history
            .steps
            .last()
            .map_or(f64::NAN, |s| s.worn_area[1])
            * run.thickness,
        Bound::Relative(1e-6),
    );
    Ok(())
}

/// The block-on-ring example with the block's wear off: the ring's wear, its least and its
/// largest depth, against k₂ F s / (2π R t) after the first 40 steps (1 570 turns).
pub fn ring(checks: &mut Checks) -> Outcome {
    let p = super::cases::problem("block-on-ring", &[("body1 = { k = 1.0e-5 }", "")])?;
    let run = sliding_run(&p, Some(40))?;
    let s = run.distance();
    let (radius, t) = (17.5, 15.75);
    let depth = 1.0e-8 / 1000.0 * 133.4 * s / (std::f64::consts::TAU * radius * t);
    let wear = &run.history.track.wear;
    for (id, which, value) in [
        (
            "sliding.ring_least",
            "least",
            wear.iter().cloned().fold(f64::INFINITY, f64::min),
        ),
        (
            "sliding.ring_largest",
            "largest",
            wear.iter().cloned().fold(0.0, f64::max),
        ),
    ] {
        push(
            checks,
            id,
            format!("block-on-ring, only the ring wearing, 40 steps: the ring's {which} depth"),
            "mm",
            depth,
            "k₂ F s / (2π R t), even all round",
            value,
            Bound::Relative(1e-6),
        );
    }
    Ok(())
}

/// The tribometer example, 60 steps (both bodies wearing): each body's worn volume k F s.
pub fn tribometer_volumes(checks: &mut Checks) -> Outcome {
    let p = super::cases::problem("tribometer", &[])?;
    let run = sliding_run(&p, Some(60))?;
    let s = run.distance() / 1000.0;
    let last = run
        .history
        .steps
        .last()
        .map_or([f64::NAN; 2], |s| s.worn_area);
    for (body, k) in [(0, 5.0e-7), (1, 1.0e-6)] {
        push(
            checks,
            format!("sliding.volume_body{}", body + 1),
            format!("tribometer, 60 steps: volume worn off body {}", body + 1),
            "mm³",
            k * 500.0 * s,
            "Archard: k F s",
            last[body] * run.thickness,
            Bound::Relative(1e-6),
        );
    }
    Ok(())
}

/// The block-on-ring example's steady state (`wearfem steady`) with the plate free to tilt
/// about a pin 1 mm above the block's face: the block's own wear per turn must be rigid, so
/// the pressure is linear, p(x) = F/(Lt) (1 − 12 μ h x/L²), and the ring loses k₂ F/(2πRt)
/// per metre, evenly (module docs of `steady_state::sliding`).
pub fn ring_steady(checks: &mut Checks) -> Outcome {
    let p = super::cases::problem(
        "block-on-ring",
        &[(
            "motion = \"vertical\"",
            "motion = \"vertical_rotation\"\npin = [0.0, 1.0]",
        )],
    )?;
    let steady = crate::jobs::sliding_steady::steady(&p).map_err(|e| fail(&p.file, e))?;
    if steady.state.status != crate::steady::SteadyStatus::Solved {
        return Err(fail(&p.file, format!("{:?}", steady.state.status)));
    }
    let (length, t, radius, friction, pin) = (6.35, 15.75, 17.5, 0.35, 1.0);
    let mean = 133.4 / (length * t);
    let slope = 12.0 * friction * pin / (length * length);
    let points = &steady.setup.contact.contacts[0].points;
    let worst = (points.x.iter().zip(&steady.state.p_plus))
        .map(|(x, p)| mean * (1.0 - slope * x[0]) - p)
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(f64::NAN);
    push(
        checks,
        "sliding.ring_steady_pressure",
        "block-on-ring tilting about a pin 1 mm above its face, steady state: the pressure's largest departure from the line",
        "MPa",
        0.0,
        "F/(Lt) (1 − 12 μ h x/L²)",
        worst,
        Bound::Absolute(1e-6 * mean),
    );
    let per_metre = steady.body2_depth_per_turn / (steady.turn * 1e-3);
    push(
        checks,
        "sliding.ring_steady_depth",
        "block-on-ring steady state: the ring's even depth per metre",
        "mm/m",
        1.0e-8 * 133.4 / (std::f64::consts::TAU * radius * t),
        "k₂ F / (2π R t)",
        per_metre,
        Bound::Relative(1e-6),
    );
    Ok(())
}
