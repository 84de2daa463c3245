//! The flexibility of both bodies at the contact points, projected onto the normals and
//! tangents the condensed problem needs.

use super::{ContactPoints, Trace};
use crate::elasticity::{ElasticBody, Row};
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

/// Each trace's displacement along its point's direction, as a row of dofs.
fn projected(traces: &[Trace], directions: &[Point]) -> Vec<Row> {
    traces
        .iter()
        .zip(directions)
        .map(|(tr, v)| {
            tr.iter()
                .flat_map(|&(g, coef)| [(g[0], coef * v[0]), (g[1], coef * v[1])])
                .collect()
        })
        .collect()
}

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
    let project = |directions: &[Point]| projected(traces, directions);
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

/// A body's flexibility on a set of its dofs, G = K⁻¹ restricted to them (mm/N), made once:
/// sliding pairs meet body 2 at every position of the stroke through other traces of the
/// same dofs (those of its track), and each position's part of A_nn and A_nt is then two
/// products with G instead of a factorisation and a Schur complement of its own.
#[derive(Clone, Debug)]
pub struct DofFlexibility {
    /// Index of each global dof in `g` (usize::MAX: not among them; fixed dofs stay out,
    /// as they do not move).
    index: Vec<usize>,
    /// G, symmetric, column-major.
    g: faer::Mat<f64>,
}

impl DofFlexibility {
    /// G on `dofs` of `body` (global dof numbers).
    pub fn new(
        problem: &Problem,
        body: &ElasticBody,
        dofs: &[usize],
    ) -> Result<DofFlexibility, ProblemError> {
        let rows: Vec<Row> = dofs.iter().map(|&d| vec![(d, 1.0)]).collect();
        let g = body
            .row_flexibility(&rows, &rows)
            .map_err(|e| problem.error("contact", e.to_string()))?;
        let mut index = vec![usize::MAX; body.dofs.n_dofs()];
        for (k, &d) in dofs.iter().enumerate() {
            index[d] = k;
        }
        Ok(DofFlexibility { index, g })
    }

    /// Add the body's part to A_nn and A_nt as [`add_flexibility`] does, from G; false
    /// (nothing added) if a trace touches a dof outside G.
    pub(super) fn add_to(
        &self,
        traces: &[Trace],
        points: &ContactPoints,
        a_nn: &mut [f64],
        a_nt: &mut [f64],
    ) -> bool {
        // The projected rows with G's indices for the dofs.
        let project = |directions: &[Point]| -> Option<Vec<Vec<(usize, f64)>>> {
            projected(traces, directions)
                .into_iter()
                .map(|row| {
                    row.into_iter()
                        .filter(|e| e.1 != 0.0)
                        .map(|(d, coef)| match self.index[d] {
                            usize::MAX => None,
                            k => Some((k, coef)),
                        })
                        .collect()
                })
                .collect()
        };
        let (Some(normal), Some(tangent)) = (project(&points.normal), project(&points.tangent))
        else {
            return false;
        };
        let n = points.x.len();
        // Only the rows of G that this position's traces touch are needed (a few hundred of
        // the track's thousands).
        let mut touched: Vec<usize> = normal
            .iter()
            .chain(&tangent)
            .flatten()
            .map(|e| e.0)
            .collect();
        touched.sort_unstable();
        touched.dedup();
        let mut column = vec![0.0; self.g.nrows()];
        for i in 0..n {
            // G n_iᵀ at the touched rows, from G's columns (G is symmetric).
            for &k in &touched {
                column[k] = 0.0;
            }
            for &(k, coef) in &normal[i] {
                let source = self.g.col(k).try_as_col_major().expect("contiguous");
                let source = source.as_slice();
                for &r in &touched {
                    column[r] += coef * source[r];
                }
            }
            let dot = |row: &[(usize, f64)]| row.iter().map(|&(k, c)| c * column[k]).sum::<f64>();
            for j in 0..n {
                a_nn[i * n + j] += dot(&normal[j]);
                a_nt[i * n + j] += dot(&tangent[j]);
            }
        }
        true
    }
}

/// One body's tangential flexibility at the contact points, added to A_tt (row-major N × N):
/// τ_iᵀ G_ij τ_j with G = C K⁻¹ Cᵀ ([`ElasticBody::row_flexibility`]), `tangents` being the
/// body's own frame at its traces. Only the stick problem needs it (full slip and the normal
/// problem do not), so it is made on demand, not with the contact.
pub(super) fn add_tangential_flexibility(
    problem: &Problem,
    body: &ElasticBody,
    traces: &[Trace],
    tangents: &[Point],
    a_tt: &mut [f64],
) -> Result<(), ProblemError> {
    let rows = projected(traces, tangents);
    let product = body
        .row_flexibility(&rows, &rows)
        .map_err(|e| problem.error("contact", e.to_string()))?;
    let n = tangents.len();
    for i in 0..n {
        let column = product.col(i);
        for j in 0..n {
            a_tt[i * n + j] += column[j];
        }
    }
    Ok(())
}
