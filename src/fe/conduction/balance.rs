//! The heat balance of a body: what it stores and what leaves it through convecting edges and
//! faces, held edges and, for a flowing body, with its material.

use super::blocks::BlockOperator;
use super::element::piece_quadrature;
use super::{ConductionBody, EdgeCondition, FaceConvection};
use crate::quadrature::gauss_legendre;

impl ConductionBody {
    /// The heat (mJ) stored per kelvin of each full unknown: C 1, so that the heat stored in
    /// a field T relative to a uniform T_ref is (C 1)·(T − T_ref 1).
    pub fn heat_content_weights(&self) -> Vec<f64> {
        self.full_capacity().apply_vector(&self.uniform(1.0))
    }

    fn full_capacity(&self) -> BlockOperator {
        BlockOperator {
            size: self.n_full(),
            blocks: self.capacity_blocks.clone(),
        }
    }

    /// The element's modes as (full unknown, sign) pairs, in the basis's mode order.
    pub fn element_unknowns(&self, element: usize) -> Vec<(usize, f64)> {
        self.spaces.unknowns(&self.mesh, &self.dofs, element)
    }

    /// Heat stored in `field` relative to the uniform temperature `reference` (mJ):
    /// t ∫ ρc (T − T_ref) dA.
    pub fn stored_heat(&self, field: &[f64], reference: f64) -> f64 {
        let uniform = self.uniform(reference);
        self.heat_content_weights()
            .iter()
            .zip(field.iter().zip(&uniform))
            .map(|(c, (t, r))| c * (t - r))
            .sum()
    }

    /// Heat flowing out of the body (mW) at temperature `field` (full, °C): through
    /// convecting edges and faces, and through held edges (the reaction at the held
    /// unknowns: the residual of K T − f there, plus C Ṫ for a transient, `rate` being dT/dt
    /// in K/s per full unknown). Frictional heat is not counted: it enters the free unknowns.
    pub fn heat_out(&self, field: &[f64], rate: Option<&[f64]>) -> HeatFlows {
        let mut convected = 0.0;
        for (piece, condition) in &self.edges {
            if let EdgeCondition::Convection {
                coefficient,
                ambient,
            } = *condition
            {
                for (tp, ds) in piece_quadrature(&self.mesh, piece, self.spaces.p() + 2) {
                    let t: f64 = self
                        .edge_trace(piece.element, piece.local, tp)
                        .iter()
                        .map(|&(g, c)| c * field[g])
                        .sum();
                    convected += coefficient * (t - ambient) * ds * self.thickness;
                }
            }
        }
        let faces = self.faces.map_or(0.0, |f| self.face_loss(field, f));
        let full_conductivity = BlockOperator {
            size: self.n_full(),
            blocks: self.conductivity_blocks.clone(),
        };
        let mut residual = full_conductivity.apply_vector(field);
        if let Some(rate) = rate {
            for (r, c) in residual
                .iter_mut()
                .zip(self.full_capacity().apply_vector(rate))
            {
                *r += c;
            }
        }
        let mut held_out = 0.0;
        for v in 0..self.mesh.vertices.len() {
            let d = self.dofs.vertex_dof(v, 0);
            if self.held[d].is_some() {
                // The reaction is the heat the held edge supplies; it leaves when negative.
                held_out -= residual[d] - self.full_load[d];
            }
        }
        let advected = if self.is_symmetric() {
            0.0
        } else {
            let motion = BlockOperator {
                size: self.n_full(),
                blocks: self.advection_blocks.clone(),
            };
            motion
                .apply_vector(field)
                .iter()
                .zip(self.uniform(1.0))
                .map(|(a, one)| a * one)
                .sum::<f64>()
                - self.inflow_enthalpy
        };
        HeatFlows {
            convected,
            faces,
            held: held_out,
            advected,
        }
    }

    /// Heat lost through both faces (mW): 2 h_f ∫ (T − T∞) dA.
    fn face_loss(&self, field: &[f64], faces: FaceConvection) -> f64 {
        let mut loss = 0.0;
        for element in 0..self.mesh.elements.len() {
            let nq = crate::elasticity::quadrature_points(&self.mesh, element, self.spaces.p());
            let rule = gauss_legendre(nq);
            let tab = self
                .spaces
                .basis(element)
                .tabulate(&rule.points, &rule.points);
            let unknowns = self.element_unknowns(element);
            for iy in 0..nq {
                for ix in 0..nq {
                    let q = iy * nq + ix;
                    let (_, det) = self
                        .mesh
                        .jacobian(element, rule.points[ix], rule.points[iy]);
                    let t: f64 = unknowns
                        .iter()
                        .enumerate()
                        .map(|(a, &(g, s))| s * tab.values[a * tab.n_points + q] * field[g])
                        .sum();
                    loss += 2.0
                        * faces.coefficient
                        * (t - faces.ambient)
                        * rule.weights[ix]
                        * rule.weights[iy]
                        * det;
                }
            }
        }
        loss
    }
}

/// Heat leaving a body, mW.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HeatFlows {
    /// Through convecting edges.
    pub convected: f64,
    /// Through the faces of a plane-stress plate.
    pub faces: f64,
    /// Through edges at a held temperature.
    pub held: f64,
    /// Carried out by the material's motion (the enthalpy ρc T w·n over the boundary).
    pub advected: f64,
}

impl HeatFlows {
    /// All the heat leaving, mW.
    pub fn total(&self) -> f64 {
        self.convected + self.faces + self.held + self.advected
    }
}
