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
use faer::linalg::matmul::triangular::{matmul, BlockStructure};
use faer::linalg::triangular_inverse::invert_lower_triangular;
use faer::linalg::triangular_solve::solve_upper_triangular_in_place;
use faer::perm::PermRef;
use faer::reborrow::{Reborrow, ReborrowMut};
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::{Accum, Mat, MatMut, MatRef, Par};

/// One point's displacement as a combination of global dofs: (x dof, z dof, coefficient).
pub type Trace = Vec<([usize; 2], f64)>;

/// One row of a constraint matrix: a displacement as a combination of global dofs
/// (dof, coefficient).
pub type Row = Vec<(usize, f64)>;

impl ElasticBody {
    /// Flexibility G (mm/N, 2N × 2N, row 2i + c = component c of point i) of this body at the
    /// points whose displacements are `traces`: G = C K⁻¹ Cᵀ by the Schur complement onto the
    /// trace dofs (module docs). Fixed dofs do not move and are left out.
    pub fn trace_flexibility(&self, traces: &[Trace]) -> Result<Mat<f64>, ElasticityError> {
        let rows: Vec<Row> = (0..2 * traces.len())
            .map(|r| traces[r / 2].iter().map(|&(g, c)| (g[r % 2], c)).collect())
            .collect();
        self.row_flexibility(&rows, &rows)
    }

    /// A K⁻¹ Bᵀ (mm/N, `a.len()` × `b.len()`) for constraint rows A and B, by the Schur
    /// complement onto the dofs they touch (module docs). Fixed dofs do not move and are left
    /// out. Each product is one row of one matrix: projecting the traces onto the directions
    /// needed first (normals, tangents) saves the 2N × 2N flexibility and its products.
    pub fn row_flexibility(&self, a: &[Row], b: &[Row]) -> Result<Mat<f64>, ElasticityError> {
        let n = self.dofs.n_dofs();
        // Position of each trace dof in E (usize::MAX: not a trace dof). The dofs of B come
        // last (E₂), the others of A before them (E₁): only S⁻¹'s columns E₂ are needed.
        let mut position = vec![usize::MAX; n];
        let touched = |rows: &[Row]| -> Vec<usize> {
            let mut dofs: Vec<usize> = rows
                .iter()
                .flatten()
                .filter(|&&(d, coef)| coef != 0.0 && !self.fixed[d])
                .map(|&(d, _)| d)
                .collect();
            dofs.sort_unstable();
            dofs.dedup();
            dofs
        };
        let last = touched(b);
        let mut trace_dofs: Vec<usize> = touched(a)
            .into_iter()
            .filter(|d| last.binary_search(d).is_err())
            .collect();
        let h1 = trace_dofs.len();
        trace_dofs.extend(&last);
        for (e, &d) in trace_dofs.iter().enumerate() {
            position[d] = e;
        }
        let ne = trace_dofs.len();
        if last.is_empty() {
            return Ok(Mat::zeros(a.len(), b.len()));
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
        let columns = schur_inverse_columns(&whole, ne, h1).ok_or_else(singular)?;
        // The factorisation serves the body's later solves too (one factorisation, not two).
        self.keep_factor(whole);
        let first = n - ne;
        let column = |d: usize| (position[d] != usize::MAX).then(|| inverse[d] - first);
        Ok(row_product(columns, a, b, column))
    }
}

/// Columns E₂ = `h1..ne` of S⁻¹ (ne × (ne − h1)) from the trailing ne × ne block of the
/// factor, the Cholesky factor L of S; None if the factor is not supernodal.
fn schur_inverse_columns(whole: &Factor, ne: usize, h1: usize) -> Option<Mat<f64>> {
    let SymbolicCholeskyRaw::Supernodal(supernodal) = whole.symbolic.raw() else {
        return None;
    };
    let factor = SupernodalLltRef::new(supernodal, &whole.values);
    let first = supernodal.nrows() - ne;
    let last = factor.supernode(supernodal.n_supernodes() - 1);
    if last.start() == first && last.val().ncols() == ne {
        // The trace block is one supernode (dense, as it is once the interior is eliminated):
        // use it where it is instead of copying it out.
        Some(inverse_columns(last.val().subrows(0, ne), h1))
    } else {
        let l_ee = trailing_block(&factor, supernodal.n_supernodes(), first, ne);
        Some(inverse_columns(l_ee.as_ref(), h1))
    }
}

/// X = S⁻¹ [0; I] for S = L Lᵀ, the identity in rows h1.. (L read in its lower triangle):
/// with L = [L₁₁ 0; L₂₁ L₂₂] and M = L₂₂⁻¹, X₂ = Mᵀ M and X₁ = −L₁₁⁻ᵀ L₂₁ᵀ X₂. With
/// h1 = ne/2 (a flat contact: normals along z, tangents along x) this is 11/24 of the work of
/// the whole inverse, and a third of the memory.
fn inverse_columns(l: MatRef<'_, f64>, h1: usize) -> Mat<f64> {
    let ne = l.nrows();
    let h2 = ne - h1;
    let mut x = Mat::<f64>::zeros(ne, h2);
    let (l11, l21, l22) = (
        l.submatrix(0, 0, h1, h1),
        l.submatrix(h1, 0, h2, h1),
        l.submatrix(h1, h1, h2, h2),
    );
    {
        let mut m = Mat::<f64>::zeros(h2, h2);
        invert_lower_triangular(m.as_mut(), l22, Par::Seq);
        matmul(
            x.as_mut().subrows_mut(h1, h2),
            BlockStructure::TriangularLower,
            Accum::Replace,
            m.transpose(),
            BlockStructure::TriangularUpper,
            m.as_ref(),
            BlockStructure::TriangularLower,
            1.0,
            Par::Seq,
        );
    }
    let (mut top, mut bottom) = x.as_mut().split_at_row_mut(h1);
    mirror_lower(bottom.rb_mut());
    if h1 > 0 {
        faer::linalg::matmul::matmul(
            top.rb_mut(),
            Accum::Replace,
            l21.transpose(),
            bottom.rb(),
            -1.0,
            Par::Seq,
        );
        solve_upper_triangular_in_place(l11.transpose(), top, Par::Seq);
    }
    x
}

/// The block of rows and columns `first..first + ne` of the factor, copied out.
fn trailing_block(
    factor: &SupernodalLltRef<'_, usize, f64>,
    supernodes: usize,
    first: usize,
    ne: usize,
) -> Mat<f64> {
    let mut l_ee = Mat::<f64>::zeros(ne, ne);
    for s in 0..supernodes {
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
    l_ee
}

/// Copy the lower triangle of a square matrix onto its upper one, in tiles that stay in
/// the cache (element by element, every write of a column-major transpose misses).
fn mirror_lower(mut m: MatMut<'_, f64>) {
    const TILE: usize = 32;
    let n = m.nrows();
    for jb in (0..n).step_by(TILE) {
        for ib in (0..jb + 1).step_by(TILE) {
            for j in jb..(jb + TILE).min(n) {
                for i in ib..(ib + TILE).min(j) {
                    m[(i, j)] = m[(j, i)];
                }
            }
        }
    }
}

/// A S⁻¹ Bᵀ for the rows A and B from `columns` = S⁻¹'s columns E₂, the last ones, which are
/// all B touches; `column(d)` is the position of global dof d among S's unknowns, None for a
/// dof left out (fixed).
fn row_product(
    columns: Mat<f64>,
    a: &[Row],
    b: &[Row],
    column: impl Fn(usize) -> Option<usize>,
) -> Mat<f64> {
    let restrict = |rows: &[Row]| -> Vec<Vec<(usize, f64)>> {
        rows.iter()
            .map(|row| {
                row.iter()
                    .filter(|e| e.1 != 0.0)
                    .filter_map(|&(d, coef)| column(d).map(|e| (e, coef)))
                    .collect()
            })
            .collect()
    };
    let (a, b) = (restrict(a), restrict(b));
    // T = S⁻¹ Bᵀ, column by column (S⁻¹ is symmetric: its column e is its row e).
    let ne = columns.nrows();
    let h1 = ne - columns.ncols();
    let mut t = Mat::<f64>::zeros(ne, b.len());
    for (r, entries) in b.iter().enumerate() {
        let target = t.col_mut(r).try_as_col_major_mut().expect("contiguous");
        let target = target.as_slice_mut();
        for &(e, coef) in entries {
            let source = column_slice(columns.as_ref(), e - h1);
            for (x, s) in target.iter_mut().zip(source) {
                *x += coef * s;
            }
        }
    }
    drop(columns);
    Mat::from_fn(a.len(), b.len(), |r, s| {
        let col = column_slice(t.as_ref(), s);
        a[r].iter().map(|&(e, coef)| coef * col[e]).sum()
    })
}

/// Column `j` of a column-major matrix as a slice.
fn column_slice(m: MatRef<'_, f64>, j: usize) -> &[f64] {
    m.col(j)
        .try_as_col_major()
        .expect("an owned matrix has contiguous columns")
        .as_slice()
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
        // Only the z rows on the right: S⁻¹'s columns for them alone (the x dofs eliminated
        // first, E₁), and the same entries.
        let rows: Vec<super::Row> = (0..2 * n)
            .map(|r| traces[r / 2].iter().map(|&(g, c)| (g[r % 2], c)).collect())
            .collect();
        let z_rows: Vec<super::Row> = rows.iter().skip(1).step_by(2).cloned().collect();
        let partial = body.row_flexibility(&rows, &z_rows).unwrap();
        for r in 0..2 * n {
            for i in 0..n {
                let (got, want) = (partial[(r, i)], schur[(r, 2 * i + 1)]);
                assert!(
                    (got - want).abs() < 1e-10 * largest,
                    "({r}, {i}): {got} vs {want}"
                );
            }
        }
    }
}
