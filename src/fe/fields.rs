//! Post-processing: displacement, strain and stress at any point of a solved body.

use crate::elasticity::{Displacement, ElasticBody};
use crate::geometry::Point;

/// Displacement, strain and stress at one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointValues {
    /// Displacement [u_x, u_z], mm.
    pub displacement: [f64; 2],
    /// Strain [ε_xx, ε_zz, γ_xz] (engineering shear strain), dimensionless.
    pub strain: [f64; 3],
    /// Stress [σ_xx, σ_zz, σ_xz], MPa.
    pub stress: [f64; 3],
    /// Axisymmetric bodies: the hoop strain ε_θθ = u_r/r and stress σ_θθ (MPa); zero in a
    /// plane analysis.
    pub hoop: [f64; 2],
}

impl ElasticBody {
    /// Field values at reference point (ξ, η) of `element`.
    pub fn values_at_reference(
        &self,
        u: &Displacement,
        element: usize,
        xi: f64,
        eta: f64,
    ) -> PointValues {
        let tab = self.basis.tabulate(&[xi], &[eta]);
        let (j, det) = self.mesh.jacobian(element, xi, eta);
        let (dxi_dx, dxi_dz) = (j[1][1] / det, -j[0][1] / det);
        let (deta_dx, deta_dz) = (-j[1][0] / det, j[0][0] / det);
        let coeff = &u.local[element];
        let mut disp = [0.0; 2];
        let mut grad = [[0.0; 2]; 2]; // grad[c][d] = ∂u_c/∂x_d
        for a in 0..self.basis.n_modes() {
            let dx = tab.d_xi[a] * dxi_dx + tab.d_eta[a] * deta_dx;
            let dz = tab.d_xi[a] * dxi_dz + tab.d_eta[a] * deta_dz;
            for c in 0..2 {
                let coef = coeff[2 * a + c];
                disp[c] += coef * tab.values[a];
                grad[c][0] += coef * dx;
                grad[c][1] += coef * dz;
            }
        }
        let strain = [grad[0][0], grad[1][1], grad[0][1] + grad[1][0]];
        let material = self.materials[self.mesh.elements[element].material];
        let d = material.constitutive(self.analysis);
        let mut stress = [0.0; 3];
        for (r, row) in d.iter().enumerate() {
            stress[r] = row.iter().zip(&strain).map(|(a, b)| a * b).sum();
        }
        let mut hoop = [0.0; 2];
        if self.analysis.is_axisymmetric() {
            let r = self.mesh.map(element, xi, eta)[0];
            let size = self
                .mesh
                .vertices
                .iter()
                .fold(0.0f64, |a, v| a.max(v[0].abs()));
            // On the axis u_r = 0 (held there), and u_r/r tends to ∂u_r/∂r.
            let hoop_strain = if !crate::material::on_axis(r, size) {
                disp[0] / r
            } else {
                grad[0][0]
            };
            let (lambda, modulus) = material.hoop_coupling();
            stress[0] += lambda * hoop_strain;
            stress[1] += lambda * hoop_strain;
            hoop = [
                hoop_strain,
                lambda * (strain[0] + strain[1]) + modulus * hoop_strain,
            ];
        }
        PointValues {
            displacement: disp,
            strain,
            stress,
            hoop,
        }
    }

    /// Field values at physical point `x` (mm); `None` if the point is outside the body.
    pub fn values_at(&self, u: &Displacement, x: Point) -> Option<PointValues> {
        let (element, xi, eta) = self.mesh.locate(x)?;
        Some(self.values_at_reference(u, element, xi, eta))
    }
}

/// Strain energy ½ fᵀu (N·mm) of a solution for load vector `load`; exact for zero-valued
/// supports, which are the only ones wearfem has.
pub fn strain_energy(load: &[f64], u: &Displacement) -> f64 {
    0.5 * load
        .iter()
        .zip(&u.boundary)
        .map(|(f, d)| f * d)
        .sum::<f64>()
}

/// A temperature field on an elastic body, for its thermal stress and for output: per
/// element the coefficients of T − T_ref on the element's modes (the elasticity's basis; the
/// heat stage's field on the same mesh, signs applied), K.
#[derive(Clone, Debug)]
pub struct TemperatureField {
    /// Per element, the rise's coefficients on its modes, K.
    pub rise: Vec<Vec<f64>>,
    /// The stress-free temperature, °C.
    pub reference: f64,
    /// The body's thermal load operators (and the materials' expansion).
    pub loads: std::sync::Arc<crate::elasticity::ThermalLoads>,
}

impl TemperatureField {
    /// T − T_ref (K) at reference point (ξ, η) of `element` of `body`.
    pub fn rise_at_reference(&self, body: &ElasticBody, element: usize, xi: f64, eta: f64) -> f64 {
        debug_assert_eq!(self.loads.temperature_basis(element).p, body.basis.p);
        let tab = self
            .loads
            .temperature_basis(element)
            .tabulate(&[xi], &[eta]);
        self.rise[element]
            .iter()
            .zip(&tab.values)
            .map(|(c, n)| c * n)
            .sum()
    }
}
