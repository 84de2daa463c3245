//! The validation cases of axisymmetric bodies (issue 31): Lamé's thick tube with free ends
//! and a hollow sphere under internal pressure, both in the (r, z) half-plane. The bounds are
//! tests/axisymmetric.rs's.

use super::cases::{fail, push, Checks, Outcome};
use super::Bound;
use crate::driver;
use crate::problem::Problem;

const YOUNG: f64 = 2.0e5;
const POISSON: f64 = 0.3;

/// A steel tube (a = 10, b = 20 mm, 20 mm long, held in z on its mid-plane) under 100 MPa
/// inside, its ends free: u_r = r/E ((1 − ν)A + (1 + ν)B/r²), σ_θθ = A + B/r², the exact 3D
/// solution (A = pa²/(b² − a²), B = pa²b²/(b² − a²)).
pub fn tube(checks: &mut Checks) -> Outcome {
    let text = format!(
        "title = \"tube\"\n[analysis]\nkind = \"axisymmetric\"\np = 8\n\
        [materials.steel]\nyoung = {YOUNG}\npoisson = {POISSON}\n\
        [[bodies]]\nname = \"tube\"\n[[bodies.blocks]]\n\
        corners = [[10.0, 0.0], [20.0, 0.0], [20.0, 10.0], [10.0, 10.0]]\nu = 4\nv = 2\n\
        material = \"steel\"\nnames = {{ bottom = \"mid\", left = \"bore\" }}\n\
        [[bodies.tractions]]\nedge = \"bore\"\nnormal = 100.0\n\
        [[bodies.supports]]\nedge = \"mid\"\nfix = [\"z\"]\n\
        [probes]\nbore = {{ body = \"tube\", at = [10.0, 5.0] }}\n\
        outside = {{ body = \"tube\", at = [20.0, 5.0] }}\n"
    );
    let p = Problem::from_toml(&text, "axisymmetric-tube").map_err(|e| fail("tube", e))?;
    let result = driver::elastic(&p).map_err(|e| fail("tube", e))?;
    let (a, b, pressure) = (10.0f64, 20.0f64, 100.0);
    let big_a = pressure * a * a / (b * b - a * a);
    let big_b = pressure * a * a * b * b / (b * b - a * a);
    for (name, r) in [("bore", a), ("outside", b)] {
        let probe = &result["probes"][name];
        let u = probe["displacement"][0].as_f64().unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.tube_{name}"),
            format!("axisymmetric tube with free ends under internal pressure: u_r at r = {r} mm (p = 8)"),
            "mm",
            r / YOUNG * ((1.0 - POISSON) * big_a + (1.0 + POISSON) * big_b / (r * r)),
            "Lamé, free ends (σ_zz = 0)",
            u,
            Bound::Relative(1e-8),
        );
        let hoop = probe["hoop_stress"].as_f64().unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.tube_hoop_{name}"),
            format!("the same tube: hoop stress σ_θθ at r = {r} mm"),
            "MPa",
            big_a + big_b / (r * r),
            "Lamé: A + B/r²",
            hoop,
            Bound::Relative(1e-6),
        );
    }
    Ok(())
}

/// A hollow steel sphere (a = 10, b = 20 mm; a quarter of its meridian section, exact arcs,
/// the axis condition implied) under 100 MPa inside:
/// u_R = p a³/(E (b³ − a³)) ((1 − 2ν) R + (1 + ν) b³/(2R²)).
pub fn sphere(checks: &mut Checks) -> Outcome {
    let text = format!(
        "title = \"sphere\"\n[analysis]\nkind = \"axisymmetric\"\np = 8\n\
        [materials.steel]\nyoung = {YOUNG}\npoisson = {POISSON}\n\
        [[bodies]]\nname = \"sphere\"\n[[bodies.blocks]]\n\
        corners = [[10.0, 0.0], [20.0, 0.0], [0.0, 20.0], [0.0, 10.0]]\n\
        arcs = [{{ edge = 1, center = [0.0, 0.0] }}, {{ edge = 3, center = [0.0, 0.0] }}]\n\
        u = 4\nv = 4\nmaterial = \"steel\"\nnames = {{ bottom = \"equator\", left = \"bore\" }}\n\
        [[bodies.tractions]]\nedge = \"bore\"\nnormal = 100.0\n\
        [[bodies.supports]]\nedge = \"equator\"\nfix = [\"z\"]\n\
        [probes]\npole = {{ body = \"sphere\", at = [0.0, 10.0] }}\n\
        equator = {{ body = \"sphere\", at = [20.0, 0.0] }}\n"
    );
    let p = Problem::from_toml(&text, "axisymmetric-sphere").map_err(|e| fail("sphere", e))?;
    let result = driver::elastic(&p).map_err(|e| fail("sphere", e))?;
    let (a, b, pressure) = (10.0f64, 20.0f64, 100.0);
    let radial = |radius: f64| {
        pressure * a.powi(3) / (YOUNG * (b.powi(3) - a.powi(3)))
            * ((1.0 - 2.0 * POISSON) * radius + (1.0 + POISSON) * b.powi(3) / (2.0 * radius * radius))
    };
    for (name, component, radius, what) in [
        ("pole", 1, a, "u_z at the inner pole (on the axis)"),
        ("equator", 0, b, "u_r at the outer equator"),
    ] {
        let u = result["probes"][name]["displacement"][component]
            .as_f64()
            .unwrap_or(f64::NAN);
        push(
            checks,
            format!("axisymmetric.sphere_{name}"),
            format!("axisymmetric hollow sphere under internal pressure: {what} (p = 8)"),
            "mm",
            radial(radius),
            "Lamé's sphere",
            u,
            Bound::Relative(1e-8),
        );
    }
    Ok(())
}
