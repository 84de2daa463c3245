//! Closed forms of heat conduction that the checks compare with (Carslaw & Jaeger): Jaeger's
//! band heat source moving over a half-space, evaluated by quadrature of its integral, and the
//! modified Bessel function K₀ it needs; and the finite-element case that is checked against
//! it.

use super::{ConductionBody, ConductionError, ConductionSpec, EdgeCondition, EdgePiece, Flow};
use crate::basis::Space;
use crate::geometry::{Block, EdgeShape};
use crate::material::ThermalMaterial;
use crate::mesh::{Mesh, MeshBlock};

/// e^x K₀(x) for x > 0 (Abramowitz & Stegun 9.8.5–9.8.6, relative error below 2e-7): scaled,
/// so that the kernel of a moving source, e^{s x} K₀(s|x|), neither overflows downstream nor
/// underflows needlessly.
pub fn scaled_k0(x: f64) -> f64 {
    if x <= 2.0 {
        let t = x / 3.75;
        let t2 = t * t;
        let i0 = 1.0
            + t2 * (3.5156229
                + t2 * (3.0899424
                    + t2 * (1.2067492 + t2 * (0.2659732 + t2 * (0.0360768 + t2 * 0.0045813)))));
        let y = x * x / 4.0;
        let k0 = -(x / 2.0).ln() * i0 - 0.57721566
            + y * (0.42278420
                + y * (0.23069756
                    + y * (0.03488590 + y * (0.00262698 + y * (0.00010750 + y * 0.00000740)))));
        k0 * x.exp()
    } else {
        let y = 2.0 / x;
        (1.25331414
            + y * (-0.07832358
                + y * (0.02189568
                    + y * (-0.01062446 + y * (0.00587872 + y * (-0.00251540 + y * 0.00053208))))))
            / x.sqrt()
    }
}

/// The steady surface temperature rise (K) at `x` (mm) of a half-space whose insulated surface
/// takes a flux `q` (mW/mm²) on the band −`half_width` ≤ ξ ≤ `half_width`, while its material
/// flows past in +x at `speed` (mm/s); `conductivity` k (mW/(mm·K)), `diffusivity` κ (mm²/s).
/// Jaeger (1942), Carslaw & Jaeger §10.7: with s = V/(2κ),
/// T(x) = q/(π k) ∫ e^{s(x − ξ)} K₀(s|x − ξ|) dξ, the line source's kernel doubled by the
/// insulated surface. The logarithmic singularity at ξ = x is taken out by ξ = x ∓ d·u²
/// on either side (Gauss–Legendre, 48 points a side: 1e-6 of the result).
pub fn moving_band_temperature(
    x: f64,
    q: f64,
    half_width: f64,
    speed: f64,
    conductivity: f64,
    diffusivity: f64,
) -> f64 {
    let s = speed / (2.0 * diffusivity);
    let rule = crate::quadrature::gauss_legendre(48);
    let kernel = |d: f64| {
        // e^{s d} K₀(s|d|) with d = x − ξ.
        if d == 0.0 {
            0.0
        } else if d > 0.0 {
            scaled_k0(s * d)
        } else {
            scaled_k0(-s * d) * (2.0 * s * d).exp()
        }
    };
    let mut integral = 0.0;
    // Upstream of x: ξ from −l to min(x, l); downstream: ξ from max(x, −l) to l.
    let pieces = [
        (-half_width, x.min(half_width)),
        (x.max(-half_width), half_width),
    ];
    for (a, b) in pieces {
        if b <= a {
            continue;
        }
        // The singular end is the one at ξ = x (if inside); ξ = e + (o − e)·u², u ∈ [0, 1].
        let (end, other) = if (x - b).abs() < (x - a).abs() {
            (b, a)
        } else {
            (a, b)
        };
        for (&r, &w) in rule.points.iter().zip(&rule.weights) {
            let u = 0.5 * (r + 1.0);
            let xi = end + (other - end) * u * u;
            let jacobian = 2.0 * (other - end).abs() * u * 0.5;
            integral += w * jacobian * kernel(x - xi);
        }
    }
    q / (std::f64::consts::PI * conductivity) * integral
}

/// The x positions (mm) of the mesh lines of the moving-band block, graded into the band
/// −5 ≤ x ≤ 5 and thinning downstream.
const BAND_LINES: [f64; 16] = [
    -30.0, -15.0, -8.0, -5.0, -3.0, -1.0, 1.0, 3.0, 5.0, 8.0, 12.0, 18.0, 26.0, 38.0, 52.0, 70.0,
];

/// The depths (mm) of the moving-band block's mesh lines, graded towards its top.
const BAND_DEPTHS: [f64; 10] = [25.0, 16.0, 8.0, 4.0, 2.0, 1.0, 0.5, 0.25, 0.1, 0.0];

/// The finite-element counterpart of [`moving_band_temperature`] (its check in the tests and
/// in `wearfem validate`): a steel block −30 ≤ x ≤ 70, −25 ≤ z ≤ 0 mm, 10 mm thick, at degree
/// `p`, its material flowing in +x at `speed` mm/s, held at 0 °C at its base and, if
/// `hold_inflow`, at its inflow edge (else the material enters there at 0 °C: Danckwerts'
/// condition), with a flux `q` (mW/mm²) on the band |x| ≤ 5 mm of its top. Returns the body
/// and its stationary temperature.
pub fn moving_band_case(
    p: usize,
    speed: f64,
    q: f64,
    hold_inflow: bool,
) -> Result<(ConductionBody, Vec<f64>), ConductionError> {
    let (left, right, depth) = (-30.0, 70.0, 25.0);
    let mesh = Mesh::build(vec![MeshBlock {
        block: Block::new(
            [[left, -depth], [right, -depth], [right, 0.0], [left, 0.0]],
            std::array::from_fn(|_| EdgeShape::Straight),
        )
        .expect("a rectangle is a valid block"),
        u_lines: BAND_LINES
            .iter()
            .map(|x| (x - left) / (right - left))
            .collect(),
        v_lines: BAND_DEPTHS.iter().map(|d| 1.0 - d / depth).collect(),
        material: 0,
        edge_names: [
            Some("bottom".into()),
            Some("right".into()),
            Some("top".into()),
            Some("left".into()),
        ],
    }])
    .expect("the band block's mesh lines are ordered");
    let pieces = |name: &str| EdgePiece::named(&mesh, name);
    let mut edges = Vec::new();
    let held: &[&str] = if hold_inflow {
        &["left", "bottom"]
    } else {
        &["bottom"]
    };
    for &name in held {
        edges.extend(
            pieces(name)
                .into_iter()
                .map(|piece| (piece, EdgeCondition::Temperature(0.0))),
        );
    }
    let spec = ConductionSpec {
        name: "moving band".into(),
        p,
        // The spaces of a run's heat ([`super::spaces`]): the tensor-product space where the
        // heat enters, the trunk space below.
        space: Space::Trunk,
        tensor_elements: pieces("top").iter().map(|piece| piece.element).collect(),
        thickness: 10.0,
        materials: vec![Some(ThermalMaterial::from_engineering(
            50.0, 460.0, 7800.0, 1.2e-5,
        ))],
        edges,
        faces: None,
        flow: Some(Flow::Translation([speed, 0.0])),
        inflow_temperature: 0.0,
    };
    let body = ConductionBody::new(&mesh, &spec)?;
    let mut load = vec![0.0; body.n_full()];
    for piece in pieces("top") {
        if mesh.point_on_edge(piece.element, piece.local, 0.0)[0].abs() < 5.0 {
            for (l, f) in load.iter_mut().zip(body.edge_flux_load(&piece, q)) {
                *l += f;
            }
        }
    }
    let field = body.stationary(&load)?;
    Ok((body, field))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bessel_k0_matches_tabulated_values() {
        // Abramowitz & Stegun Table 9.8: K₀(0.5) = 0.9244191, K₀(1) = 0.4210244,
        // K₀(2) = 0.1138939, K₀(5) = 3.691098e-3.
        for (x, k0) in [
            (0.5, 0.9244191),
            (1.0, 0.4210244),
            (2.0, 0.1138939),
            (5.0, 3.691098e-3),
        ] {
            let ours = scaled_k0(x) * (-x).exp();
            assert!((ours - k0).abs() < 3e-7 * k0, "{x}: {ours}");
        }
    }

    #[test]
    fn a_fast_band_heats_as_one_dimensional_penetration() {
        // At a high Péclet number L = V l/(2κ) heat has no time to spread sideways: a surface
        // point under the band has taken the flux q for t = (x + l)/V, so
        // T = (2q/k)·√(κt/π), the largest at the trailing edge x = l. The lateral flow the
        // 1D form neglects is of relative order 1/√L... here checked at L = 400 within 3 %.
        let (q, l, k, kappa) = (40.0, 5.0, 50.0, 13.9);
        let speed = 400.0 * 2.0 * kappa / l;
        for x in [-2.5, 0.0, 2.5, 5.0] {
            let ours = moving_band_temperature(x, q, l, speed, k, kappa);
            let penetration =
                2.0 * q / k * (kappa * (x + l) / (speed * std::f64::consts::PI)).sqrt();
            assert!(
                (ours - penetration).abs() < 0.03 * penetration,
                "{x}: {ours} vs {penetration}"
            );
        }
    }
}
