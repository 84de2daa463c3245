//! The integrals of one element and one edge piece: the conductivity and capacity blocks, the
//! convection of an edge.

use super::blocks::Block;
use super::{EdgePiece, ElementSpaces};
use crate::basis::QuadBasis;
use crate::dofs::DofMap;
use crate::material::ThermalMaterial;
use crate::mesh::Mesh;
use crate::quadrature::gauss_legendre;
use faer::Mat;
use std::sync::Arc;

/// Element matrices of one element: conductivity (with the face sink), capacity, and the
/// face load per unit ambient temperature, over the element's modes.
pub(super) struct ElementMatrices {
    pub(super) conductivity: Arc<Mat<f64>>,
    pub(super) capacity: Arc<Mat<f64>>,
    /// ∫ N_a dA · t (mm³), for the face load and the stored heat.
    pub(super) volume: Vec<f64>,
}

pub(super) fn element_matrices(
    mesh: &Mesh,
    element: usize,
    basis: &QuadBasis,
    material: &ThermalMaterial,
    thickness: f64,
    face_coefficient: f64,
    nq: usize,
) -> ElementMatrices {
    let rule = gauss_legendre(nq);
    let tab = basis.tabulate(&rule.points, &rule.points);
    let n = basis.n_modes();
    let n_points = nq * nq;
    let mut gx = Mat::<f64>::zeros(n, n_points);
    let mut gz = Mat::<f64>::zeros(n, n_points);
    let mut nv = Mat::<f64>::zeros(n, n_points);
    let mut volume = vec![0.0; n];
    for iy in 0..nq {
        for ix in 0..nq {
            let q = iy * nq + ix;
            let (j, det) = mesh.jacobian(element, rule.points[ix], rule.points[iy]);
            let w = rule.weights[ix] * rule.weights[iy] * det;
            let scale = w.sqrt();
            let (dxi_dx, dxi_dz) = (j[1][1] / det, -j[0][1] / det);
            let (deta_dx, deta_dz) = (-j[1][0] / det, j[0][0] / det);
            for a in 0..n {
                let idx = a * n_points + q;
                let (nxi, neta) = (tab.d_xi[idx], tab.d_eta[idx]);
                gx[(a, q)] = (nxi * dxi_dx + neta * deta_dx) * scale;
                gz[(a, q)] = (nxi * dxi_dz + neta * deta_dz) * scale;
                nv[(a, q)] = tab.values[idx] * scale;
                volume[a] += tab.values[idx] * w * thickness;
            }
        }
    }
    let gradients = &gx * gx.transpose() + &gz * gz.transpose();
    let mass = &nv * nv.transpose();
    let conductivity = Mat::from_fn(n, n, |a, b| {
        thickness * material.conductivity * gradients[(a, b)]
            + 2.0 * face_coefficient * mass[(a, b)]
    });
    let capacity = Mat::from_fn(n, n, |a, b| {
        thickness * material.heat_capacity * mass[(a, b)]
    });
    ElementMatrices {
        conductivity: Arc::new(conductivity),
        capacity: Arc::new(capacity),
        volume,
    }
}

/// Gauss points (t, ds) on an edge piece: `n` points, ds the arc-length weight in mm.
pub fn piece_quadrature(mesh: &Mesh, piece: &EdgePiece, n: usize) -> Vec<(f64, f64)> {
    let rule = gauss_legendre(n);
    let half = 0.5 * (piece.t[1] - piece.t[0]);
    rule.points
        .iter()
        .zip(&rule.weights)
        .map(|(&r, &w)| {
            let t = piece.t[0] + half * (r + 1.0);
            let (tangent, _) = mesh.edge_frame(piece.element, piece.local, t);
            (t, w * half * tangent[0].hypot(tangent[1]))
        })
        .collect()
}

/// An edge piece's convection t h ∫ N_a N_b ds as a block of K, with t h T∞ ∫ N_a ds added
/// to `load`; `th` = t h (mW/(mm·K)).
pub(super) fn convection_block(
    mesh: &Mesh,
    dofs: &DofMap,
    spaces: &ElementSpaces,
    piece: &EdgePiece,
    th: f64,
    ambient: f64,
    load: &mut [f64],
) -> Block {
    let basis = spaces.basis(piece.element);
    let trace = basis.edge_trace(piece.local);
    let element = spaces.unknowns(mesh, dofs, piece.element);
    let n = trace.len();
    let mut matrix = Mat::<f64>::zeros(n, n);
    let mut vector = vec![0.0; n];
    for (tp, ds) in piece_quadrature(mesh, piece, basis.p + 2) {
        let (xi, eta) = Mesh::edge_reference_point(piece.local, tp);
        let tab = basis.tabulate(&[xi], &[eta]);
        for (a, &ma) in trace.iter().enumerate() {
            vector[a] += tab.values[ma] * ds;
            for (b, &mb) in trace.iter().enumerate() {
                matrix[(a, b)] += th * tab.values[ma] * tab.values[mb] * ds;
            }
        }
    }
    let unknowns: Vec<(usize, f64)> = trace.iter().map(|&m| element[m]).collect();
    for (a, &(g, s)) in unknowns.iter().enumerate() {
        load[g] += s * th * ambient * vector[a];
    }
    Block {
        unknowns,
        matrix: Arc::new(matrix),
    }
}
