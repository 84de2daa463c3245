//! Heat carried by the body's own motion: in the frame of body 1, body 2's material moves
//! through the contact (a strip sliding past, a disc turning), and its heat equation gains the
//! advection term ρc w·∇T:
//!
//! ρc (∂T/∂t + w·∇T) = ∇·(k ∇T) − (2 h_f / t)(T − T∞).
//!
//! Galerkin's form adds A_ab = t ∫ ρc N_a (w·∇N_b) dA to the conductivity (not symmetric).
//! There is no upwinding: on a mesh graded to the thermal layer under the contact the
//! p-version's Galerkin solution stays within 0.3 % of Jaeger's moving band up to a Péclet
//! number of 1800 with undershoots of 1e-3 of the peak, while streamline-upwind diffusion
//! (Brooks and Hughes, tried first) smeared the band's trailing edge by 2 % of the peak at
//! Péclet 360: its extra diffusion is not consistent for p > 1 unless the residual's second
//! derivatives are kept. The heat the motion carries out is 1ᵀ A T = ∮ ρc T w·n ds, the
//! enthalpy flux through the boundary (w divergence-free).
//!
//! Where the material enters the body (w·n < 0 on a boundary edge: the upstream end of a
//! strip, the cut of a ring segment) it brings the temperature it had outside, T_in (the
//! ambient). The condition is Danckwerts': the heat crossing the edge, advected and
//! conducted, is the enthalpy that enters, ρc (w·n) T − k ∂T/∂n = ρc (w·n) T_in, which in the
//! weak form is a convection with the film coefficient ρc |w·n|: t ∫ ρc |w·n| N_a N_b ds in K
//! and t ∫ ρc |w·n| T_in N_a ds in the load. A held temperature on that edge overrides it.

use super::blocks::Block;
use super::{piece_quadrature, ConductionSpec, EdgePiece, ElementSpaces};
use crate::basis::QuadBasis;
use crate::dofs::DofMap;
use crate::geometry::Point;
use crate::material::ThermalMaterial;
use crate::mesh::Mesh;
use crate::quadrature::gauss_legendre;
use faer::Mat;
use std::sync::Arc;

/// How a body's material moves through the frame its heat is solved in (mm/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Flow {
    /// A uniform velocity [w_x, w_z], mm/s: a strip sliding past.
    Translation([f64; 2]),
    /// A rotation about `center` at `rate` rad/s (counter-clockwise positive): a disc turning.
    Rotation {
        /// Centre [x, z], mm.
        center: Point,
        /// Angular speed, rad/s.
        rate: f64,
    },
}

impl Flow {
    /// The velocity (mm/s) at `x`.
    pub fn at(&self, x: Point) -> [f64; 2] {
        match *self {
            Flow::Translation(w) => w,
            Flow::Rotation { center, rate } => {
                [-rate * (x[1] - center[1]), rate * (x[0] - center[0])]
            }
        }
    }
}

/// The advection block of `element` (over its modes, in the basis's order; `unknowns` its
/// full unknowns with signs): A_ab = t ∫ ρc N_a (w·∇N_b) dA.
pub fn element_block(
    mesh: &Mesh,
    element: usize,
    basis: &QuadBasis,
    material: &ThermalMaterial,
    thickness: f64,
    flow: &Flow,
    unknowns: Vec<(usize, f64)>,
) -> Block {
    let p = basis.p;
    let nq = crate::elasticity::quadrature_points(mesh, element, p) + 1;
    let rule = gauss_legendre(nq);
    let tab = basis.tabulate(&rule.points, &rule.points);
    let n = basis.n_modes();
    let mut matrix = Mat::<f64>::zeros(n, n);
    let mut stream = vec![0.0; n];
    for iy in 0..nq {
        for ix in 0..nq {
            let q = iy * nq + ix;
            let (xi, eta) = (rule.points[ix], rule.points[iy]);
            let (j, det) = mesh.jacobian(element, xi, eta);
            let w = flow.at(mesh.map(element, xi, eta));
            let weight =
                rule.weights[ix] * rule.weights[iy] * det * thickness * material.heat_capacity;
            let (dxi_dx, dxi_dz) = (j[1][1] / det, -j[0][1] / det);
            let (deta_dx, deta_dz) = (-j[1][0] / det, j[0][0] / det);
            for (a, s) in stream.iter_mut().enumerate() {
                let idx = a * tab.n_points + q;
                let (nxi, neta) = (tab.d_xi[idx], tab.d_eta[idx]);
                let dx = nxi * dxi_dx + neta * deta_dx;
                let dz = nxi * dxi_dz + neta * deta_dz;
                *s = w[0] * dx + w[1] * dz;
            }
            for a in 0..n {
                let na = tab.values[a * tab.n_points + q];
                for b in 0..n {
                    matrix[(a, b)] += weight * na * stream[b];
                }
            }
        }
    }
    Block {
        unknowns,
        matrix: Arc::new(matrix),
    }
}

/// The blocks a flow adds to a body's conductivity: the advection block of every element and
/// the inflow condition of every boundary edge where the material enters; the inflow's
/// T_in part is added to `load`. Returns the blocks and the enthalpy the inflow brings at
/// T_in per second, mW (what the outflow takes away beyond it is the heat the motion removes).
pub(super) fn flow_blocks(
    mesh: &Mesh,
    dofs: &DofMap,
    spaces: &ElementSpaces,
    spec: &ConductionSpec,
    flow: &Flow,
    load: &mut [f64],
) -> (Vec<Block>, f64) {
    let material_of = |element: usize| {
        spec.materials[mesh.elements[element].material]
            .expect("the element blocks checked every material")
    };
    let mut blocks: Vec<Block> = (0..mesh.elements.len())
        .map(|element| {
            element_block(
                mesh,
                element,
                spaces.basis(element),
                &material_of(element),
                spec.thickness,
                flow,
                spaces.unknowns(mesh, dofs, element),
            )
        })
        .collect();
    let mut entering = 0.0;
    for edge in mesh.edges.iter().filter(|e| e.elements.len() == 1) {
        let (element, local) = edge.elements[0];
        let piece = EdgePiece::whole(element, local);
        let heat_capacity = material_of(element).heat_capacity;
        let basis = spaces.basis(element);
        let trace = basis.edge_trace(local);
        let unknowns = spaces.unknowns(mesh, dofs, element);
        let n = trace.len();
        let mut matrix = Mat::<f64>::zeros(n, n);
        let mut vector = vec![0.0; n];
        // More points than the mass term needs: |w·n| may change slope along a curved edge.
        for (tp, ds) in piece_quadrature(mesh, &piece, basis.p + 4) {
            let (_, normal) = mesh.edge_frame(element, local, tp);
            let w = flow.at(mesh.point_on_edge(element, local, tp));
            let inflow = -(w[0] * normal[0] + w[1] * normal[1]);
            if inflow <= 0.0 {
                continue;
            }
            let film = spec.thickness * heat_capacity * inflow * ds;
            let (xi, eta) = Mesh::edge_reference_point(local, tp);
            let tab = basis.tabulate(&[xi], &[eta]);
            for (a, &ma) in trace.iter().enumerate() {
                vector[a] += film * tab.values[ma];
                for (b, &mb) in trace.iter().enumerate() {
                    matrix[(a, b)] += film * tab.values[ma] * tab.values[mb];
                }
            }
        }
        if vector.iter().all(|&v| v == 0.0) {
            continue;
        }
        let unknowns: Vec<(usize, f64)> = trace.iter().map(|&m| unknowns[m]).collect();
        for (a, &(g, sign)) in unknowns.iter().enumerate() {
            load[g] += sign * spec.inflow_temperature * vector[a];
        }
        // ∫ N_a summed with the vertex modes' partition of unity: the edge's ∫ ρc|w·n| ds t.
        entering += spec.inflow_temperature * vector[..2].iter().sum::<f64>();
        blocks.push(Block {
            unknowns,
            matrix: Arc::new(matrix),
        });
    }
    (blocks, entering)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_turns_counter_clockwise() {
        let rotation = Flow::Rotation {
            center: [1.0, 2.0],
            rate: 3.0,
        };
        assert_eq!(rotation.at([1.0, 3.0]), [-3.0, 0.0]);
        assert_eq!(rotation.at([2.0, 2.0]), [0.0, 3.0]);
    }
}
