//! Symmetric operators kept as sums of dense blocks (the element matrices, the convection of
//! an edge, the tie of a contact pair), and the sparse matrices assembled from them on one
//! pattern.
//!
//! A p-version element couples all its (p + 1)² modes: at p = 8 each element matrix is a
//! dense 81 × 81 block. Multiplying a basis of a few hundred vectors by the assembled sparse
//! matrix reads one row of the basis per nonzero, scattered over memory (2 GB of traffic for
//! 400 vectors on punch-b40's heat problem); block by block it is a gather, a dense product
//! and a scatter per element (50 MB, and the product runs at the speed of a matrix
//! multiplication). The sparse matrices are still needed for the factorisations: the
//! capacity and the conductivity are assembled on one pattern (their union), sorted once, so
//! that K + σC for any shift σ is a sum of two value arrays.

use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Mat, MatRef};
use std::sync::Arc;

/// A dense symmetric block: A += Pᵀ M P, P taking the unknowns (index, sign) of `unknowns`.
#[derive(Clone, Debug)]
pub struct Block {
    /// The block's unknowns and their signs, in the order of the matrix's rows.
    pub unknowns: Vec<(usize, f64)>,
    /// The matrix (shared between blocks of the same element type).
    pub matrix: Arc<Mat<f64>>,
}

/// A symmetric operator of `size` unknowns as a sum of blocks.
#[derive(Clone, Debug, Default)]
pub struct BlockOperator {
    /// Number of unknowns.
    pub size: usize,
    /// The blocks.
    pub blocks: Vec<Block>,
}

impl BlockOperator {
    /// A V for the columns of `v` (size × r).
    pub fn apply(&self, v: MatRef<'_, f64>) -> Mat<f64> {
        let r = v.ncols();
        let mut out = Mat::<f64>::zeros(self.size, r);
        let mut gathered = Mat::<f64>::zeros(0, r);
        for block in &self.blocks {
            let n = block.unknowns.len();
            gathered.resize_with(n, r, |_, _| 0.0);
            // Column by column: each column of V is contiguous, the block's rows a few
            // scattered entries of it (row by row, every entry was a cache miss).
            for c in 0..r {
                let column = v.col(c);
                for (a, &(g, s)) in block.unknowns.iter().enumerate() {
                    gathered[(a, c)] = s * column[g];
                }
            }
            let product = &*block.matrix * &gathered;
            for c in 0..r {
                let mut column = out.col_mut(c);
                for (a, &(g, s)) in block.unknowns.iter().enumerate() {
                    column[g] += s * product[(a, c)];
                }
            }
        }
        out
    }

    /// A x for one vector.
    pub fn apply_vector(&self, x: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; self.size];
        for block in &self.blocks {
            for (a, &(ga, sa)) in block.unknowns.iter().enumerate() {
                let mut acc = 0.0;
                for (b, &(gb, sb)) in block.unknowns.iter().enumerate() {
                    acc += block.matrix[(a, b)] * sb * x[gb];
                }
                y[ga] += sa * acc;
            }
        }
        y
    }
}

/// Two operators of one size assembled as sparse matrices (both triangles) on their common
/// pattern, and the pattern itself (for factorisations shared by K + σC).
#[derive(Clone, Debug)]
pub struct PairedMatrices {
    /// The first operator's matrix.
    pub first: SparseColMat<usize, f64>,
    /// The second operator's matrix, on the same pattern.
    pub second: SparseColMat<usize, f64>,
}

/// A block's unknowns with its matrix in the first and in the second operator (None: not in
/// that operator).
type PairedBlock<'a> = (
    &'a [(usize, f64)],
    Option<&'a Mat<f64>>,
    Option<&'a Mat<f64>>,
);

/// Assemble `first` and `second` (of the same size) on their union pattern. Blocks of the
/// two with the same unknowns (the elements' conductivity and capacity) are walked once.
/// The entries are bucketed by column (a counting sort, linear in their number) and each
/// column's few hundred rows sorted and merged: sorting all 1.4 million entries of
/// punch-b40's heat problem at once took a quarter of a second.
pub fn assemble_pair(first: &BlockOperator, second: &BlockOperator) -> PairedMatrices {
    let size = first.size;
    // (unknowns, first's matrix, second's matrix) of every block, shared ones paired.
    let mut blocks: Vec<PairedBlock> = Vec::new();
    let shared = first
        .blocks
        .iter()
        .zip(&second.blocks)
        .take_while(|(a, b)| a.unknowns == b.unknowns)
        .count();
    for (a, b) in first.blocks.iter().zip(&second.blocks).take(shared) {
        blocks.push((&a.unknowns, Some(&a.matrix), Some(&b.matrix)));
    }
    blocks.extend(
        first.blocks[shared..]
            .iter()
            .map(|a| (&a.unknowns[..], Some(&*a.matrix), None)),
    );
    blocks.extend(
        second.blocks[shared..]
            .iter()
            .map(|b| (&b.unknowns[..], None, Some(&*b.matrix))),
    );
    let mut count = vec![0usize; size + 1];
    for (unknowns, ..) in &blocks {
        for &(g, s) in unknowns.iter() {
            if s != 0.0 {
                count[g + 1] += unknowns.iter().filter(|u| u.1 != 0.0).count();
            }
        }
    }
    for j in 0..size {
        count[j + 1] += count[j];
    }
    let mut next = count.clone();
    let total = count[size];
    let mut rows = vec![0usize; total];
    let mut values = vec![(0.0f64, 0.0f64); total];
    for (unknowns, a, b) in &blocks {
        for (cb, &(gb, sb)) in unknowns.iter().enumerate() {
            if sb == 0.0 {
                continue;
            }
            for (ca, &(ga, sa)) in unknowns.iter().enumerate() {
                if sa == 0.0 {
                    continue;
                }
                let k = next[gb];
                next[gb] += 1;
                rows[k] = ga;
                let s = sa * sb;
                values[k] = (
                    a.map_or(0.0, |m| s * m[(ca, cb)]),
                    b.map_or(0.0, |m| s * m[(ca, cb)]),
                );
            }
        }
    }
    // Sort each column by row and merge duplicates.
    // Reserved for every entry (merging only shrinks them) and filled as merged: growing them
    // by doubling copied each into fresh pages, which the kernel zeroes first (fresh pages
    // were most of this function's time in a profile of punch-b40-heat's set-up).
    let mut col_ptr = Vec::with_capacity(size + 1);
    let mut row_idx = Vec::with_capacity(total);
    let (mut first_values, mut second_values) =
        (Vec::with_capacity(total), Vec::with_capacity(total));
    let mut order: Vec<usize> = Vec::new();
    col_ptr.push(0);
    for j in 0..size {
        order.clear();
        order.extend(count[j]..count[j + 1]);
        order.sort_unstable_by_key(|&k| rows[k]);
        for &k in &order {
            if row_idx.len() > col_ptr[j] && *row_idx.last().unwrap() == rows[k] {
                *first_values.last_mut().unwrap() += values[k].0;
                *second_values.last_mut().unwrap() += values[k].1;
            } else {
                row_idx.push(rows[k]);
                first_values.push(values[k].0);
                second_values.push(values[k].1);
            }
        }
        col_ptr.push(row_idx.len());
    }
    let symbolic = SymbolicSparseColMat::new_checked(size, size, col_ptr, None, row_idx);
    PairedMatrices {
        first: SparseColMat::new(symbolic.clone(), first_values),
        second: SparseColMat::new(symbolic, second_values),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_apply_as_their_assembled_matrix() {
        // Two overlapping blocks with a sign flip: the block product and the assembled
        // sparse matrix agree to round-off.
        let m1 = Arc::new(Mat::from_fn(3, 3, |i, j| 1.0 / (1.0 + i as f64 + j as f64)));
        let m2 = Arc::new(Mat::from_fn(2, 2, |i, j| if i == j { 2.0 } else { -0.5 }));
        let op = BlockOperator {
            size: 4,
            blocks: vec![
                Block {
                    unknowns: vec![(0, 1.0), (1, -1.0), (2, 1.0)],
                    matrix: m1,
                },
                Block {
                    unknowns: vec![(2, 1.0), (3, 1.0)],
                    matrix: m2,
                },
            ],
        };
        let none = BlockOperator {
            size: 4,
            blocks: vec![],
        };
        let pair = assemble_pair(&op, &none);
        let v = Mat::from_fn(4, 2, |i, j| (i + 3 * j) as f64 - 1.5);
        let by_blocks = op.apply(v.as_ref());
        for c in 0..2 {
            let x: Vec<f64> = (0..4).map(|i| v[(i, c)]).collect();
            let mut y = vec![0.0; 4];
            super::super::add_product(&pair.first, &x, &mut y);
            for i in 0..4 {
                assert!((y[i] - by_blocks[(i, c)]).abs() < 1e-14);
            }
        }
        assert_eq!(pair.second.val().len(), pair.first.val().len());
    }
}
