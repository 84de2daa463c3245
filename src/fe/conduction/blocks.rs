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
//! capacity and the conductivity are assembled on one pattern (their union), column by
//! column, so that K + σC for any shift σ is a sum of two value arrays.

use faer::linalg::matmul::matmul;
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Accum, Mat, MatMut, MatRef, Par};
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
        let mut out = Mat::<f64>::zeros(self.size, v.ncols());
        self.add_applied(v, out.as_mut());
        out
    }

    /// A V with the columns shared out among the threads: the same numbers as
    /// [`Self::apply`] on any number of threads (the columns are split into a fixed number of
    /// ranges), for the few hundred columns of the heat problem's reduction.
    pub fn apply_parallel(&self, v: MatRef<'_, f64>) -> Mat<f64> {
        let mut out = Mat::<f64>::zeros(self.size, v.ncols());
        for_column_ranges(out.as_mut(), |range, part| {
            self.add_applied(v.subcols(range.start, range.len()), part)
        });
        out
    }

    /// out += A V.
    fn add_applied(&self, v: MatRef<'_, f64>, mut out: MatMut<'_, f64>) {
        let r = v.ncols();
        let (mut gathered, mut product) = (Mat::<f64>::zeros(0, r), Mat::<f64>::zeros(0, r));
        for block in &self.blocks {
            let n = block.unknowns.len();
            gathered.resize_with(n, r, |_, _| 0.0);
            product.resize_with(n, r, |_, _| 0.0);
            // Column by column: each column of V is contiguous, the block's rows a few
            // scattered entries of it (row by row, every entry was a cache miss).
            for c in 0..r {
                let column = v.col(c);
                for (a, &(g, s)) in block.unknowns.iter().enumerate() {
                    gathered[(a, c)] = s * column[g];
                }
            }
            matmul(
                product.as_mut(),
                Accum::Replace,
                block.matrix.as_ref(),
                gathered.as_ref(),
                1.0,
                Par::Seq,
            );
            for c in 0..r {
                let mut column = out.as_mut().col_mut(c);
                for (a, &(g, s)) in block.unknowns.iter().enumerate() {
                    column[g] += s * product[(a, c)];
                }
            }
        }
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

/// Column ranges of a product split among the threads: a fixed number, so that the split,
/// and with it every number, is the same on any machine.
const COLUMN_RANGES: usize = 8;

/// Call `work` on ranges of `out`'s columns (a fixed number of them), on all threads.
pub fn for_column_ranges<F>(out: MatMut<'_, f64>, work: F)
where
    F: Fn(std::ops::Range<usize>, MatMut<'_, f64>) + Sync,
{
    use rayon::prelude::*;
    let width = out.ncols().div_ceil(COLUMN_RANGES).max(1);
    let mut parts = Vec::new();
    let mut rest = out;
    let mut start = 0;
    while rest.ncols() > 0 {
        let take = width.min(rest.ncols());
        let (head, tail) = rest.split_at_col_mut(take);
        parts.push((start..start + take, head));
        start += take;
        rest = tail;
    }
    parts
        .into_par_iter()
        .for_each(|(range, part)| work(range, part));
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
///
/// Column by column: each column's blocks (an incidence list, one entry per block and
/// unknown) add their column into a dense accumulator of the matrix's size, whose touched
/// rows are then sorted and copied out. No list of all 1.4 million contributions of
/// punch-b40's heat problem is made: writing it, bucketing and sorting it took three times
/// as long, most of it the kernel zeroing the 35 MB of fresh pages it filled.
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
    // The blocks of each unknown: (block, its row in the block), grouped by unknown.
    let mut start = vec![0usize; size + 1];
    let mut total = 0;
    for (unknowns, ..) in &blocks {
        let active = unknowns.iter().filter(|u| u.1 != 0.0).count();
        total += active * active;
        for &(g, s) in unknowns.iter() {
            if s != 0.0 {
                start[g + 1] += 1;
            }
        }
    }
    for j in 0..size {
        start[j + 1] += start[j];
    }
    let mut next = start.clone();
    let mut incidence = vec![(0usize, 0usize); start[size]];
    for (b, (unknowns, ..)) in blocks.iter().enumerate() {
        for (c, &(g, s)) in unknowns.iter().enumerate() {
            if s != 0.0 {
                incidence[next[g]] = (b, c);
                next[g] += 1;
            }
        }
    }
    // `total` bounds the merged entries; reserving it touches no memory, and the arrays
    // never grow by copying (fresh pages, which the kernel zeroes first).
    let mut col_ptr = Vec::with_capacity(size + 1);
    let mut row_idx = Vec::with_capacity(total);
    let (mut first_values, mut second_values) =
        (Vec::with_capacity(total), Vec::with_capacity(total));
    // The column being assembled: its values by row, and which rows it has (marked with the
    // column's number, so that the marks need no clearing).
    let mut accumulated = vec![(0.0f64, 0.0f64); size];
    let mut mark = vec![usize::MAX; size];
    let mut touched: Vec<usize> = Vec::new();
    col_ptr.push(0);
    for j in 0..size {
        touched.clear();
        for &(b, cb) in &incidence[start[j]..start[j + 1]] {
            let (unknowns, a, m) = blocks[b];
            let sb = unknowns[cb].1;
            // The block's column cb, contiguous (the element matrices are column-major).
            let (a, m) = (column_of(a, cb), column_of(m, cb));
            for (ca, &(ga, sa)) in unknowns.iter().enumerate() {
                if sa == 0.0 {
                    continue;
                }
                if mark[ga] != j {
                    mark[ga] = j;
                    accumulated[ga] = (0.0, 0.0);
                    touched.push(ga);
                }
                let s = sa * sb;
                let entry = &mut accumulated[ga];
                if let Some(a) = a {
                    entry.0 += s * a[ca];
                }
                if let Some(m) = m {
                    entry.1 += s * m[ca];
                }
            }
        }
        touched.sort_unstable();
        for &i in &touched {
            row_idx.push(i);
            first_values.push(accumulated[i].0);
            second_values.push(accumulated[i].1);
        }
        col_ptr.push(row_idx.len());
    }
    let symbolic = SymbolicSparseColMat::new_checked(size, size, col_ptr, None, row_idx);
    PairedMatrices {
        first: SparseColMat::new(symbolic.clone(), first_values),
        second: SparseColMat::new(symbolic, second_values),
    }
}

/// Column `c` of a block's matrix as a slice (an owned matrix's columns are contiguous).
fn column_of(matrix: Option<&Mat<f64>>, c: usize) -> Option<&[f64]> {
    matrix.map(|x| x.col(c).try_as_col_major().unwrap().as_slice())
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
