//! Fretting of dissimilar materials (issue 30): the coupled problem's stick zone against an
//! independent reference, the coupled partial slip of two half-planes
//! (`wearfem::validate::half_plane`: Nowell, Hills and Sackfield's problem solved by panels
//! with the half-plane's influence functions, sharing nothing with the FE code).

use wearfem::overrides::Override;
use wearfem::problem::Problem;
use wearfem::validate::half_plane;

/// `fretting-dissimilar` (a pad the steel flat's mirror image, so that only Dundurs' β
/// couples) with pad modulus `young_pad` (MPa), Q₀ = `ratio` μP at μ = 0.6 and degree
/// `degree`, its load set for Hertz's a = 0.08 mm. With β and a.
fn dissimilar(young_pad: f64, ratio: f64, degree: usize) -> (Problem, f64, f64) {
    let (radius, a, friction, poisson, young) = (10.0f64, 0.08f64, 0.6, 0.3, 2.0e5);
    let e_star = 1.0 / ((1.0 - poisson * poisson) * (1.0 / young_pad + 1.0 / young));
    let load = std::f64::consts::PI * a * a * e_star / (4.0 * radius);
    let shear = |e: f64| e / (2.0 * (1.0 + poisson));
    let (g1, g2) = (shear(young_pad), shear(young));
    let kappa = 3.0 - 4.0 * poisson;
    let beta =
        ((kappa - 1.0) / g1 - (kappa - 1.0) / g2) / ((kappa + 1.0) / g1 + (kappa + 1.0) / g2);
    let sets = [
        format!("materials.pad.young={young_pad}"),
        format!("bodies[0].tractions[0].normal={}", load / 10.0),
        format!("fretting.amplitude={}", ratio * friction * load),
        format!("analysis.p={degree}"),
        "fretting.stages=1".to_string(),
    ];
    let sets: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    let text = wearfem::examples::example("fretting-dissimilar").unwrap();
    let p = Problem::with_overrides(text, "fretting-dissimilar", &sets).unwrap();
    assert!(p.fretting_settings().unwrap().unwrap().coupled);
    (p, beta, a)
}

/// The edges of the stick zone at the cycle's peak (the virgin loading to Q₀), mm, each
/// fitted through the three outermost stick points on its side: the margin μp − |q| vanishes
/// there like the square root of the distance, so that its square is a line through them.
fn fe_stick_edges(contact: &wearfem::jobs::fretting::FrettingContact) -> (f64, f64) {
    let x = contact.setup.x();
    let (peak, forces, area) = (
        &contact.cycle.states[0],
        &contact.cycle_forces[0],
        &contact.setup.area,
    );
    let friction = contact.setup.settings.friction;
    let mut stick: Vec<usize> = (0..x.len()).filter(|&i| peak.stick[i]).collect();
    stick.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
    // In pressure: the points' forces carry their quadrature weights.
    let margin_squared =
        |i: usize| ((friction * forces[i] - peak.force[i].abs()) / area[i]).powi(2);
    let edge = |points: &[usize]| {
        let n = points.len() as f64;
        let (sx, sy, sxx, sxy) = points.iter().fold((0.0, 0.0, 0.0, 0.0), |s, &i| {
            let (u, v) = (x[i], margin_squared(i));
            (s.0 + u, s.1 + v, s.2 + u * u, s.3 + u * v)
        });
        let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        -(sy - slope * sx) / n / slope
    };
    let k = stick.len();
    (edge(&stick[..3]), edge(&stick[k - 3..]))
}

/// A pad of E₁ = 5000 MPa (β = 0.272) under 0.5 and 0.7 μP, and of 70 000 MPa (β = 0.138)
/// under 0.5 μP, at p = 10 (the example's) and 14: the stick zone moves along +x, the way Q
/// pushes the more compliant pad, as the half-planes' does.
///
/// Measured (edges and centre in a; the half-planes' first): p = 10: [−0.6467, 0.7811]
/// against [−0.6435, 0.7811], [−0.4588, 0.6454] against [−0.4567, 0.6479], [−0.6749,
/// 0.7487] against [−0.6742, 0.7421]; p = 14 within 0.0073 a of them. Bounds: each edge
/// within 1 % of a (the bound for Cattaneo's edges; the reference's own scatter is
/// 0.2 % of a, the FE edge fit's 0.3–0.7 % between degrees), the centre within 0.5 % of a
/// against offsets of 3.4–9.6 % of a (so that the coupling's effect is checked to a
/// tenth or better). At p = 8 and 12 the left edge under 0.7 μP is 3.5 % and 1.4 % of a
/// off (the other edges within 0.7 %): that edge lies 1.7 point spacings from an element
/// end (x = −0.04 mm), where the three-point fit is least stable; not asserted.
#[test]
fn the_coupled_stick_zone_moves_as_the_half_planes_does() {
    for degree in [10, 14] {
        for (young_pad, ratio) in [(5000.0, 0.5), (5000.0, 0.7), (7.0e4, 0.5)] {
            let (p, beta, a) = dissimilar(young_pad, ratio, degree);
            let contact = wearfem::jobs::fretting::contact(&p).unwrap();
            let (left, right) = fe_stick_edges(&contact);
            let (left, right) = (left / a, right / a);
            let reference = half_plane::coupled_partial_slip(beta, 0.6, ratio, 800).unwrap();
            let centre = 0.5 * (left + right);
            eprintln!(
                "p = {degree}, E1 = {young_pad}, β = {beta:.4}, Q/μP = {ratio}: FE stick [{left:.4}, {right:.4}] a, half-planes [{:.4}, {:.4}] a; centre {centre:.4} against {:.4}",
                reference.stick_left,
                reference.stick_right,
                reference.stick_centre()
            );
            assert!((left - reference.stick_left).abs() < 0.01, "p = {degree}");
            assert!((right - reference.stick_right).abs() < 0.01, "p = {degree}");
            assert!(
                (centre - reference.stick_centre()).abs() < 0.005,
                "p = {degree}"
            );
            assert!(reference.stick_centre() > 0.03);
        }
    }
}
