//! The validation cases of fretting (issue 30): a fretting cycle's dissipated energy against
//! the closed-form tractions and slips, and the final state of partial slip against
//! Ciavarella and Hills' pressure. The bounds are tests/partial_slip.rs's and
//! tests/fretting.rs's.

use super::cases::{fail, push, Checks, Outcome};
use super::Bound;
use crate::fretting::{FrettingControl, FrettingCycle, FrettingLoading};
use std::f64::consts::PI;

/// `hertz` at half its load (a = 2 mm), p = 12, μ = 0.3, cycled at ±0.9 μP: the energy
/// 4μ ∫ p |s| dx over both slip zones, |s| = (μp₀/(E*a))[|x|√(x² − c²) − c² arcosh(|x|/c)].
pub fn cycle_energy(checks: &mut Checks) -> Outcome {
    let top = 17.2556;
    let hertz = super::partial_slip_cases::PressedHertz::new(&[
        ("p = 8", "p = 12"),
        ("normal = 38.825", "normal = 17.2556"),
    ])?;
    let (friction, ratio) = (0.3, 0.9);
    let problem = hertz.problem(friction);
    let force = &hertz.force;
    let total: f64 = force.iter().sum();
    let loading = FrettingLoading {
        control: FrettingControl::Force,
        amplitude: ratio * friction * total,
        stages: 16,
    };
    let cycle = FrettingCycle::solve(&problem, &loading).map_err(|e| fail("hertz", e))?;
    let (radius, load) = (500.0f64, top * 40.0);
    let e_star = 2.0e5 / (2.0 * (1.0 - 0.09));
    let a = (4.0 * load * radius / (PI * e_star)).sqrt();
    let p0 = 2.0 * load / (PI * a);
    let c = a * (1.0f64 - ratio).sqrt();
    let m = 4000;
    let h = (a - c) / m as f64;
    let integral: f64 = (0..m)
        .map(|k| {
            let x = c + (k as f64 + 0.5) * h;
            let slip = friction * p0 / (e_star * a)
                * (x * (x * x - c * c).sqrt() - c * c * (x / c).acosh());
            p0 * (1.0 - x * x / (a * a)).sqrt() * slip * h
        })
        .sum();
    push(
        checks,
        "fretting.cycle_energy",
        "hertz at half its load (a = 2 mm, p = 12), μ = 0.3, a cycle ±0.9 μP: the energy friction dissipates",
        "N·mm/mm",
        8.0 * friction * integral,
        "Mindlin–Deresiewicz's tractions and slips, 4μ∫p|s|dx by quadrature",
        cycle.dissipated,
        Bound::Relative(0.02),
    );
    Ok(())
}

/// `fretting-cylinder`'s final state: the pressure at the centre against Ciavarella and Hills'
/// (E*/(2R))c + (P − πE*c²/(4R))/(πc), with c the discrete stick zone's edge (midway between
/// its last point and the next).
pub fn final_state(checks: &mut Checks) -> Outcome {
    let p = super::cases::problem("fretting-cylinder", &[])?;
    let steady = crate::jobs::fretting::steady(&p).map_err(|e| fail("fretting-cylinder", e))?;
    let s = &steady.state;
    let x = steady.setup.x();
    let last = (0..x.len())
        .filter(|&i| s.pressure[i] > 0.0 && x[i] > 0.0)
        .max_by(|&i, &j| x[i].total_cmp(&x[j]))
        .ok_or_else(|| fail("fretting-cylinder", "no contact in the final state"))?;
    let c = 0.5 * (x[last] + x.get(last + 1).copied().unwrap_or(x[last]));
    let (radius, load, e_star) = (10.0f64, 27.62 * 2.0, 2.0e5 / (2.0 * (1.0 - 0.09)));
    let closed =
        e_star / (2.0 * radius) * c + (load - PI * e_star * c * c / (4.0 * radius)) / (PI * c);
    let centre = (0..x.len())
        .min_by(|&i, &j| x[i].abs().total_cmp(&x[j].abs()))
        .ok_or_else(|| fail("fretting-cylinder", "no contact points"))?;
    push(
        checks,
        "fretting.final_state_centre",
        "fretting-cylinder (Q₀ = 0.5 μP): the final state's pressure at the centre",
        "MPa",
        closed,
        "Ciavarella–Hills: the load on the stick zone's unworn profile",
        s.pressure[centre],
        Bound::Relative(0.02),
    );
    Ok(())
}

/// `fretting-dissimilar` (a soft pad on steel, Dundurs' β = 0.272, Q₀ = 0.5 μP): the centre
/// of the coupled stick zone at the peak against the independent half-plane solution
/// ([`super::half_plane`], 800 panels) of the same loading; Cattaneo's uncoupled zone would be
/// centred. The bound is tests/fretting_dissimilar.rs's: 0.5 % of a.
pub fn dissimilar_stick_zone(checks: &mut Checks) -> Outcome {
    let name = "fretting-dissimilar";
    let p = super::cases::problem(name, &[("stages = 16", "stages = 1")])?;
    let contact = crate::jobs::fretting::contact(&p).map_err(|e| fail(name, e))?;
    let (left, right) = contact
        .peak_stick_edges()
        .ok_or_else(|| fail(name, "fewer than three stick points at the peak"))?;
    let (radius, load, poisson) = (10.0f64, 2.6945, 0.3);
    let e_star = 1.0 / ((1.0 - poisson * poisson) * (1.0 / 5000.0 + 1.0 / 2.0e5));
    let a = (4.0 * load * radius / (PI * e_star)).sqrt();
    let shear = |e: f64| e / (2.0 * (1.0 + poisson));
    let kappa = 3.0 - 4.0 * poisson;
    let (compliant, stiff) = ((kappa - 1.0) / shear(5000.0), (kappa - 1.0) / shear(2.0e5));
    let beta = (compliant - stiff) / ((kappa + 1.0) / shear(5000.0) + (kappa + 1.0) / shear(2.0e5));
    let reference =
        super::half_plane::coupled_partial_slip(beta, 0.6, 0.5, 800).map_err(|e| fail(name, e))?;
    push(
        checks,
        "fretting.dissimilar_stick_centre",
        "fretting-dissimilar (β = 0.272, Q₀ = 0.5 μP, coupled): the stick zone's centre at the peak",
        "mm",
        reference.stick_centre() * a,
        "Nowell–Hills–Sackfield's two half-planes, solved by panels (validate::half_plane)",
        0.5 * (left + right),
        Bound::Absolute(0.005 * a),
    );
    Ok(())
}
