//! Supports beyond a zero displacement: a prescribed constant displacement on an edge or at a
//! vertex, and elastic supports (a bed of springs along an edge).
//!
//! **Prescribed displacement.** The held dofs take their values (a constant along an edge:
//! its vertex dofs take the value, its edge modes zero, so the trace is that constant
//! exactly), and the free dofs feel them through the stiffness: K_ff u_f = f_f − K_fp u_p. The
//! lift −K_fp u_p is made once, element by element from the condensed element matrices (the
//! assembled matrix has the held rows and columns replaced by the identity), and added to
//! every physical load; the solves of the contact's flexibility stay homogeneous.
//!
//! **Elastic support.** A Winkler bed along an edge pulls back with a traction
//! −(k_n (u·n) n + k_t (u·τ) τ) (MPa), k_n and k_t in N/mm³ (MPa per mm of displacement):
//! per unit length of edge that is k·t N/mm per mm. Its stiffness
//! t ∫ N_a N_b (k_n n nᵀ + k_t τ τᵀ) ds acts on the edge's trace dofs only, which are boundary
//! dofs, so it is added to the condensed matrix as it is, and the internal modes' condensation
//! does not change.

use crate::basis::QuadBasis;
use crate::dofs::{DofMap, Pattern};
use crate::loads::{edge_quadrature, trace_dofs};
use crate::mesh::Mesh;

/// A bed of springs on one element edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spring {
    /// Element index.
    pub element: usize,
    /// Local edge 0..4.
    pub local: usize,
    /// Normal modulus k_n, N/mm³ (traction in MPa per mm of normal displacement).
    pub normal: f64,
    /// Tangential modulus k_t, N/mm³.
    pub tangential: f64,
}

/// The stiffness of one spring bed over its edge's trace dofs.
pub struct SpringBlock {
    /// The global dofs (x and z of each trace mode) with the mode's sign.
    pub unknowns: Vec<(usize, f64)>,
    /// The dense stiffness over `unknowns` (N/mm).
    pub matrix: Vec<Vec<f64>>,
}

impl SpringBlock {
    /// The block of `spring` on `mesh`, for a body of the given analysis (its thickness, or
    /// 2πr).
    pub fn new(
        mesh: &Mesh,
        dofs: &DofMap,
        basis: &QuadBasis,
        analysis: crate::material::Analysis,
        spring: &Spring,
    ) -> Self {
        let p = dofs.p;
        let trace = trace_dofs(dofs, mesh, basis, spring.element, spring.local);
        let unknowns: Vec<(usize, f64)> = trace
            .iter()
            .flat_map(|&(g, sign)| [(g[0], sign), (g[1], sign)])
            .collect();
        let n = unknowns.len();
        let mut matrix = vec![vec![0.0; n]; n];
        let mut values = vec![0.0; p + 1];
        let mut derivatives = vec![0.0; p + 1];
        // The product of two trace modes has degree 2p: p + 2 Gauss points are exact on a
        // straight edge, and on a curved one the normal's variation needs a few more.
        for (t, ds) in edge_quadrature(mesh, spring.element, spring.local, None, p + 4) {
            let (_, normal) = mesh.edge_frame(spring.element, spring.local, t);
            let thickness = analysis.weight(mesh.point_on_edge(spring.element, spring.local, t));
            let tangent = [-normal[1], normal[0]];
            crate::basis::shape_1d(p, t, &mut values, &mut derivatives);
            // k_n n nᵀ + k_t τ τᵀ, per unit area.
            let bed = |c: usize, d: usize| {
                spring.normal * normal[c] * normal[d] + spring.tangential * tangent[c] * tangent[d]
            };
            for a in 0..=p {
                for b in 0..=p {
                    let w = values[a] * values[b] * ds * thickness;
                    for c in 0..2 {
                        for d in 0..2 {
                            matrix[2 * a + c][2 * b + d] += w * bed(c, d);
                        }
                    }
                }
            }
        }
        Self { unknowns, matrix }
    }

    /// Add the block into the lower triangle of `pattern`'s values.
    pub fn add_to(&self, pattern: &Pattern, values: &mut [f64]) {
        for (a, &(row, sign_row)) in self.unknowns.iter().enumerate() {
            for (b, &(col, sign_col)) in self.unknowns.iter().enumerate() {
                if row < col {
                    continue;
                }
                let range = pattern.col_ptr[col]..pattern.col_ptr[col + 1];
                let at = pattern.row_idx[range.clone()].binary_search(&row).expect(
                    "the dofs of one element edge share an element, so the pattern has them",
                );
                values[range.start + at] += sign_row * sign_col * self.matrix[a][b];
            }
        }
    }

    /// The bed's forces K u at global displacement `u` (N), added into `out` times `scale`.
    pub fn add_forces(&self, u: &[f64], scale: f64, out: &mut [f64]) {
        for (a, &(g, sign_row)) in self.unknowns.iter().enumerate() {
            let force: f64 = self
                .unknowns
                .iter()
                .enumerate()
                .map(|(b, &(h, sign_col))| self.matrix[a][b] * sign_col * u[h])
                .sum();
            out[g] += scale * sign_row * force;
        }
    }

    /// The bed's strain energy ½ uᵀKu at global displacement `u` (N·mm).
    pub fn energy(&self, u: &[f64]) -> f64 {
        let local: Vec<f64> = self.unknowns.iter().map(|&(g, s)| s * u[g]).collect();
        0.5 * (0..local.len())
            .map(|a| {
                (0..local.len())
                    .map(|b| local[a] * self.matrix[a][b] * local[b])
                    .sum::<f64>()
            })
            .sum::<f64>()
    }
}
