//! The flexibility of a body at a few points (the contact points) by a Schur complement,
//! instead of one full solve per unit load.
//!
//! The displacements at the points depend only on the dofs of the elements they lie on (the
//! trace dofs E): u = C u_E. Ordering the unknowns so that E comes last (the rest I by nested
//! dissection of the mesh, [`super::dissection`]), the Cholesky factor's trailing block L_EE is
//! the factor of the Schur complement S = K_EE − K_EI K_II⁻¹ K_IE, and (K⁻¹)_EE = S⁻¹. So
//!
//!   G = C K⁻¹ Cᵀ = C (L_EE L_EEᵀ)⁻¹ Cᵀ = Yᵀ Y,  Y = L_EE⁻¹ Cᵀ:
//!
//! one sparse factorisation with a constrained ordering and the inverse of its trailing block,
//! in place of 2N sparse solves of the whole body. The factorisation does the elimination of
//! I once for all columns. What is left is S⁻¹ = L_EE⁻ᵀ L_EE⁻¹ (2|E|³/3 operations by faer's
//! blocked triangular kernels) and G = C S⁻¹ Cᵀ, cheap because each row of C has only the
//! modes of one element edge (p + 1 entries): forming Yᵀ Y with Y = L_EE⁻¹ Cᵀ densely instead
//! would cost 3|E|³ for 2N ≈ |E| columns.

use super::{ElasticBody, ElasticityError, Factor};
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::{Mat, Par};

/// One point's displacement as a combination of global dofs: (x dof, z dof, coefficient).
pub type Trace = Vec<([usize; 2], f64)>;

impl ElasticBody {
    /// Flexibility G (mm/N, 2N × 2N, row 2i + c = component c of point i) of this body at the
    /// points whose displacements are `traces`: G = C K⁻¹ Cᵀ by the Schur complement onto the
    /// trace dofs (module docs). Fixed dofs do not move and are left out.
    pub fn trace_flexibility(&self, traces: &[Trace]) -> Result<Mat<f64>, ElasticityError> {
        let n = self.dofs.n_dofs();
        let rows = 2 * traces.len();
        // Position of each trace dof in E (usize::MAX: not a trace dof).
        let mut position = vec![usize::MAX; n];
        let mut trace_dofs = Vec::new();
        for tr in traces {
            for &(g, _) in tr {
                for &d in &g {
                    if !self.fixed[d] && position[d] == usize::MAX {
                        position[d] = trace_dofs.len();
                        trace_dofs.push(d);
                    }
                }
            }
        }
        let ne = trace_dofs.len();
        if ne == 0 {
            return Ok(Mat::zeros(rows, rows));
        }
        let forward = self.constrained_order(&position, &trace_dofs);
        let mut inverse = vec![0usize; n];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        let singular = || ElasticityError::Singular {
            body: self.name.clone(),
        };
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let perm = PermRef::new_checked(&forward, &inverse, n);
        let whole = Factor::new(&self.matrix, SymmetricOrdering::Custom(perm), params)
            .ok_or_else(singular)?;
        let SymbolicCholeskyRaw::Supernodal(supernodal) = whole.symbolic.raw() else {
            return Err(singular());
        };
        let factor = SupernodalLltRef::new(supernodal, &whole.values);
        let first = n - ne;
        let mut l_ee = Mat::<f64>::zeros(ne, ne);
        for s in 0..supernodal.n_supernodes() {
            let node = factor.supernode(s);
            let (start, block) = (node.start(), node.val());
            let ncols = block.ncols();
            if start + ncols <= first {
                continue;
            }
            let pattern = node.pattern();
            for c in 0..ncols {
                let col = start + c;
                if col < first {
                    continue;
                }
                for r in c..block.nrows() {
                    let row = if r < ncols {
                        start + r
                    } else {
                        pattern[r - ncols]
                    };
                    l_ee[(row - first, col - first)] = block[(r, c)];
                }
            }
        }
        // The factorisation serves the body's later solves too (one factorisation, not two).
        self.keep_factor(whole);
        Ok(trace_product(&schur_inverse(l_ee), traces, |d| {
            (position[d] != usize::MAX).then(|| inverse[d] - first)
        }))
    }
}

/// S⁻¹ from the Cholesky factor L of S, both triangles filled.
fn schur_inverse(l: Mat<f64>) -> Mat<f64> {
    let n = l.nrows();
    let mut inverse = Mat::<f64>::zeros(n, n);
    let mut buffer =
        MemBuffer::new(faer::linalg::cholesky::llt::inverse::inverse_scratch::<f64>(n, Par::Seq));
    faer::linalg::cholesky::llt::inverse::inverse(
        inverse.as_mut(),
        l.as_ref(),
        Par::Seq,
        MemStack::new(&mut buffer),
    );
    // Only the lower triangle is written.
    for j in 0..n {
        for i in 0..j {
            inverse[(i, j)] = inverse[(j, i)];
        }
    }
    inverse
}

/// G = C S⁻¹ Cᵀ (2N × 2N) for the traces' rows of C; `column(d)` is the position of global
/// dof d among S's unknowns, None for a dof left out (fixed).
fn trace_product(
    s_inverse: &Mat<f64>,
    traces: &[Trace],
    column: impl Fn(usize) -> Option<usize>,
) -> Mat<f64> {
    let rows = 2 * traces.len();
    let c_rows: Vec<Vec<(usize, f64)>> = (0..rows)
        .map(|r| {
            traces[r / 2]
                .iter()
                .filter_map(|&(g, coef)| column(g[r % 2]).map(|e| (e, coef)))
                .collect()
        })
        .collect();
    // T = S⁻¹ Cᵀ, column by column (S⁻¹ is symmetric: its column e is its row e).
    let ne = s_inverse.nrows();
    let mut t = Mat::<f64>::zeros(ne, rows);
    for (r, entries) in c_rows.iter().enumerate() {
        let mut target = t.col_mut(r);
        for &(e, coef) in entries {
            let source = s_inverse.col(e);
            for i in 0..ne {
                target[i] += coef * source[i];
            }
        }
    }
    Mat::from_fn(rows, rows, |r, s| {
        c_rows[r].iter().map(|&(e, coef)| coef * t[(e, s)]).sum()
    })
}

impl ElasticBody {
    /// The elimination order: the dofs outside E by nested dissection of the mesh entities
    /// they belong to ([`super::dissection`]), then E (in `trace_dofs` order). Approximate
    /// minimum degree of the interior alone, the earlier choice, left 1.2–1.7 times the fill
    /// (punch-b40 at 64 elements under the punch: 5.9 and 5.4 million factor entries for punch
    /// and strip, against 4.8 and 3.1) and took 2–3 times as long to factorise.
    fn constrained_order(&self, position: &[usize], trace_dofs: &[usize]) -> Vec<usize> {
        let offsets = &self.dofs.entity_offset;
        let interior_dofs =
            |e: usize| (offsets[e]..offsets[e + 1]).filter(|&d| position[d] == usize::MAX);
        super::dissection::entity_order(&self.mesh, |e| interior_dofs(e).next().is_some())
            .into_iter()
            .flat_map(interior_dofs)
            .chain(trace_dofs.iter().copied())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::problem::Problem;

    #[test]
    fn schur_flexibility_equals_the_full_solves() {
        // The strip of Example 1 with traces at a few surface dofs, one trace mixing two dofs:
        // both ways compute C K⁻¹ Cᵀ exactly, so they agree to round-off (1e-10 of the
        // largest entry leaves room for the conditioning of K, about 1e6 here).
        let problem =
            Problem::from_toml(crate::examples::example("punch-b40").unwrap(), "b40").unwrap();
        let body = problem.elastic_body(1, &[]).unwrap();
        let mesh_dofs = body.dofs.n_dofs();
        let traces: Vec<super::Trace> = (0..6)
            .map(|i| {
                let d = (37 * i + 11) % (mesh_dofs / 2) * 2;
                vec![
                    ([d, d + 1], 0.7),
                    ([(d + 2) % mesh_dofs, (d + 3) % mesh_dofs], 0.3),
                ]
            })
            .collect();
        let schur = body.trace_flexibility(&traces).unwrap();
        let n = traces.len();
        let mut rhs = faer::Mat::<f64>::zeros(mesh_dofs, 2 * n);
        for (i, tr) in traces.iter().enumerate() {
            for &(g, coef) in tr {
                for c in 0..2 {
                    rhs[(g[c], 2 * i + c)] += coef;
                }
            }
        }
        body.solve_in_place(&mut rhs).unwrap();
        let largest = (0..2 * n)
            .flat_map(|r| (0..2 * n).map(move |c| (r, c)))
            .map(|(r, c)| schur[(r, c)].abs())
            .fold(0.0, f64::max);
        for r in 0..2 * n {
            let (i, c) = (r / 2, r % 2);
            for col in 0..2 * n {
                let full: f64 = traces[i]
                    .iter()
                    .filter(|(g, _)| !body.is_fixed(g[c]))
                    .map(|&(g, coef)| coef * rhs[(g[c], col)])
                    .sum();
                assert!(
                    (full - schur[(r, col)]).abs() < 1e-10 * largest,
                    "({r}, {col}): {full} vs {}",
                    schur[(r, col)]
                );
            }
        }
    }
}
