//! The flexibility of both bodies at the contact points, projected onto the normals and
//! tangents the condensed problem needs.

use super::{ContactPoints, Trace};
use crate::elasticity::{ElasticBody, Row};
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

/// Add one body's flexibility at the contact points, projected, to A_nn and A_nt (row-major
/// N × N): n_iᵀ G_ij n_j and n_iᵀ G_ij τ_j with G = C K⁻¹ Cᵀ by the Schur complement onto the
/// trace dofs ([`ElasticBody::row_flexibility`]). It gives what 2N solves with the body's
/// factorisation give, to round-off (tested in `elasticity::schur`), and costs less at every
/// size measured: 16 against 27 ms at the 65 points of punch-b40, the same at 129, 3 times
/// less at 513 (docs/performance.md). The traces are projected first, so that the product
/// has the N × 2N entries needed and not the 2N × 2N of G.
pub(super) fn add_flexibility(
    problem: &Problem,
    body: &ElasticBody,
    traces: &[Trace],
    points: &ContactPoints,
    a_nn: &mut [f64],
    a_nt: &mut [f64],
) -> Result<(), ProblemError> {
    let project = |directions: &[Point]| -> Vec<Row> {
        traces
            .iter()
            .zip(directions)
            .map(|(tr, v)| {
                tr.iter()
                    .flat_map(|&(g, coef)| [(g[0], coef * v[0]), (g[1], coef * v[1])])
                    .collect()
            })
            .collect()
    };
    let normal = project(&points.normal);
    let both: Vec<Row> = normal
        .iter()
        .cloned()
        .chain(project(&points.tangent))
        .collect();
    // Column i of [C_n; C_t] K⁻¹ C_nᵀ is row i of [A_nn | A_nt] (K is symmetric).
    let product = body
        .row_flexibility(&both, &normal)
        .map_err(|e| problem.error("contact", e.to_string()))?;
    let n = points.x.len();
    for i in 0..n {
        let column = product.col(i);
        for j in 0..n {
            a_nn[i * n + j] += column[j];
            a_nt[i * n + j] += column[n + j];
        }
    }
    Ok(())
}
