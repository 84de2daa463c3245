//! The space of the heat problem's reduction ([`super::reduced`]): the rational Krylov
//! vectors, solved for two shifts at once, and made C-orthonormal block by block, with the
//! dense products shared among the threads.
//!
//! # The vectors
//!
//! The basis spans the `extra` vectors, then (K + σC)⁻¹ B for each shift σ and, at σ = 0,
//! the second moment K⁻¹ C K⁻¹ B. The shifts are independent of each other, so as many are
//! factorised and solved at once as there are threads, each with a factor of its own
//! (refilled for its next shift, so that its memory is allocated once); their blocks then
//! join the basis in the order of the shifts, so the basis does not depend on the number
//! of threads.
//!
//! # Orthonormalisation
//!
//! Block classical Gram–Schmidt in the capacity inner product, twice (one pass leaves the
//! new directions orthogonal only to the square root of round-off when they are nearly
//! dependent), then the block's own Gram matrix is diagonalised and its directions whose
//! squared norm left after projection is below [`DROP`] of what they had are dropped. C V
//! is kept beside V, so that a block's projection VᵀCW = (CV)ᵀW costs dense products only.
//!
//! A Gram-matrix form of the same algorithm was tried (2026-11-30): orthonormalise the
//! coefficients of all the vectors on G = WᵀCW, with WᵀKW from the Krylov relations
//! K w = b − σ C w, so that the only N-row products are G and the modes. It is cheaper by
//! a third, but it squares the vectors' condition: on punch-b40-heat the modes' capacity
//! Gram matrix was off the identity by 1.5e-5 and VᵀKV by 1.2e-4 (the interface's tie puts
//! rates of 3e7 1/s into the space beside those of 1e-2), and the thermal gap moved by 1e-4
//! of its size. The products are shared among the threads instead.
//!
//! The N-row products are split into a fixed number of row ranges (not one per thread),
//! whose partial sums are added in one order: the model is the same on any number of cores.

use super::blocks::BlockOperator;
use super::reduced::{HeatOperators, ReductionError};
use super::transient::{SparseFactor, SparseSymbolic};
use faer::linalg::matmul::matmul;
use faer::sparse::SparseColMatRef;
use faer::{Accum, Mat, MatMut, MatRef, Par, Side};
use rayon::prelude::*;
use std::ops::Range;

/// A new direction is kept when its squared C-norm after projection on the basis exceeds
/// DROP times its own (a residual of 1e-3 of its size): the blocks of nearby shifts are
/// nearly parallel, and what is left of them beyond that changes no output by more than the
/// reduction's own error (docs/convergence.md).
pub const DROP: f64 = 1e-6;

/// Row ranges of the N-row products: a fixed number, so that their partial sums are added
/// in the same order on any machine (more than the threads of a small machine, so that
/// both of its cores are busy to the end).
const ROW_RANGES: usize = 8;

/// Width of the column panels of a symmetric product's lower triangle.
const PANEL: usize = 48;

/// A basis kept C-orthonormal as blocks are added, with C times it.
pub struct Basis {
    /// The basis, column by column (N values each): reserved for every direction that may
    /// be added but filled only as directions are kept, so that memory is touched for the
    /// kept ones only (growing a matrix block by block zeroed 200 MB of fresh pages on
    /// punch-b40-heat; reserving it whole and zeroing it, most of a gigabyte at 32 contact
    /// elements).
    columns: Vec<f64>,
    /// C times the basis, the same way (N r values, as much as the basis).
    capacity_columns: Vec<f64>,
    rows: usize,
}

/// What a thread keeps between its shifts: K + σC's values and its factor.
struct Slot {
    values: Vec<f64>,
    factor: Option<SparseFactor>,
}

impl Basis {
    /// The C-orthonormal basis of `extra`, then (K + σC)⁻¹ `inputs` for each of `shifts`
    /// (1/s) and K⁻¹CK⁻¹ `inputs` at σ = 0. K + σC has one pattern for every σ (the union
    /// of K's and C's), so the symbolic factorisation is made once.
    pub fn krylov(
        operators: HeatOperators<'_>,
        inputs: MatRef<'_, f64>,
        shifts: &[f64],
        extra: &[Vec<f64>],
    ) -> Result<Basis, ReductionError> {
        let k = &operators.matrices.first;
        let n = k.nrows();
        let symbolic = SparseSymbolic::new(k, operators.symmetric)
            .ok_or(ReductionError::NotDefinite { shift: 0.0 })?;
        let most = extra.len()
            + inputs.ncols() * (shifts.len() + shifts.iter().filter(|&&s| s == 0.0).count());
        let mut basis = Basis {
            columns: Vec::with_capacity(n * most),
            capacity_columns: Vec::with_capacity(n * most),
            rows: n,
        };
        basis.add(
            operators.capacity,
            Mat::from_fn(n, extra.len(), |i, j| extra[j][i]),
        )?;
        let threads = rayon::current_num_threads().max(1);
        let mut slots: Vec<Slot> = (0..threads.min(shifts.len()))
            .map(|_| Slot {
                values: vec![0.0; k.val().len()],
                factor: None,
            })
            .collect();
        for group in shifts.chunks(threads) {
            let solved: Vec<Result<Vec<Mat<f64>>, ReductionError>> = group
                .par_iter()
                .zip(slots.par_iter_mut())
                .map(|(&shift, slot)| solve_shift(operators, &symbolic, inputs, shift, slot))
                .collect();
            for blocks in solved {
                for block in blocks? {
                    basis.add(operators.capacity, block)?;
                }
            }
        }
        Ok(basis)
    }

    /// Number of directions r.
    pub fn len(&self) -> usize {
        self.columns.len() / self.rows.max(1)
    }

    /// V (N × r).
    pub fn view(&self) -> MatRef<'_, f64> {
        MatRef::from_column_major_slice(&self.columns, self.rows, self.len())
    }

    fn capacity_view(&self) -> MatRef<'_, f64> {
        MatRef::from_column_major_slice(&self.capacity_columns, self.rows, self.len())
    }

    /// Add the directions of `w` (N × b) that the basis lacks (the module's documentation).
    fn add(&mut self, capacity: &BlockOperator, w: Mat<f64>) -> Result<(), ReductionError> {
        let mut w = w;
        let cw = capacity.apply_parallel(w.as_ref());
        // Unit C-norm columns, so that the drop is relative to each direction's own size.
        for c in 0..w.ncols() {
            let norm: f64 = (0..w.nrows())
                .map(|i| w[(i, c)] * cw[(i, c)])
                .sum::<f64>()
                .sqrt();
            let inverse = if norm > 0.0 && norm.is_finite() {
                1.0 / norm
            } else {
                0.0
            };
            for i in 0..w.nrows() {
                w[(i, c)] *= inverse;
            }
        }
        if self.len() > 0 {
            for _ in 0..2 {
                let h = transpose_product(self.capacity_view(), w.as_ref());
                subtract_product(w.as_mut(), self.view(), h.as_ref());
            }
        }
        let cw = capacity.apply_parallel(w.as_ref());
        let gram = transpose_product(w.as_ref(), cw.as_ref());
        let eigen = gram
            .self_adjoint_eigen(Side::Lower)
            .map_err(|_| ReductionError::Eigen)?;
        let s = eigen.S().column_vector();
        let kept: Vec<usize> = (0..s.nrows()).filter(|&i| s[i] > DROP).collect();
        if kept.is_empty() {
            return Ok(());
        }
        let u = eigen.U();
        let scale = Mat::from_fn(u.nrows(), kept.len(), |r, j| {
            u[(r, kept[j])] / s[kept[j]].sqrt()
        });
        let added = rows_product(w.as_ref(), scale.as_ref());
        let capacity_added = rows_product(cw.as_ref(), scale.as_ref());
        for c in 0..added.ncols() {
            self.columns.extend(added.col(c).iter());
            self.capacity_columns.extend(capacity_added.col(c).iter());
        }
        Ok(())
    }
}

/// (K + σC)⁻¹ B, and at σ = 0 also K⁻¹ C K⁻¹ B, with the slot's factor refilled.
fn solve_shift(
    operators: HeatOperators<'_>,
    symbolic: &SparseSymbolic,
    inputs: MatRef<'_, f64>,
    shift: f64,
    slot: &mut Slot,
) -> Result<Vec<Mat<f64>>, ReductionError> {
    let (k, c) = (&operators.matrices.first, &operators.matrices.second);
    for ((m, k), c) in slot.values.iter_mut().zip(k.val()).zip(c.val()) {
        *m = k + shift * c;
    }
    let matrix = SparseColMatRef::new(k.symbolic(), &slot.values);
    let factor = SparseFactor::refactorise(slot.factor.take(), symbolic, matrix)
        .ok_or(ReductionError::NotDefinite { shift })?;
    let mut first = inputs.to_owned();
    factor.solve_in_place(&mut first);
    let mut blocks = vec![first];
    if shift == 0.0 {
        let mut second = operators.capacity.apply(blocks[0].as_ref());
        factor.solve_in_place(&mut second);
        blocks.push(second);
    }
    slot.factor = Some(factor);
    if blocks
        .iter()
        .all(|b| b.col_iter().all(|c| c.iter().all(|x| x.is_finite())))
    {
        Ok(blocks)
    } else {
        Err(ReductionError::NotDefinite { shift })
    }
}

/// The row ranges of an N-row product.
fn row_ranges(rows: usize) -> Vec<Range<usize>> {
    let step = rows.div_ceil(ROW_RANGES).max(1);
    (0..rows)
        .step_by(step)
        .map(|start| start..(start + step).min(rows))
        .collect()
}

/// aᵀ b for a symmetric result (b = C a): its lower triangle in column panels, summed over
/// the row ranges (on all threads) in a fixed order, then mirrored.
pub fn symmetric_product(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> Mat<f64> {
    let m = a.ncols();
    let parts: Vec<Mat<f64>> = row_ranges(a.nrows())
        .into_par_iter()
        .map(|rows| {
            let (a, b) = (
                a.subrows(rows.start, rows.len()),
                b.subrows(rows.start, rows.len()),
            );
            let mut part = Mat::<f64>::zeros(m, m);
            for start in (0..m).step_by(PANEL) {
                let width = PANEL.min(m - start);
                matmul(
                    part.as_mut().submatrix_mut(start, start, m - start, width),
                    Accum::Replace,
                    a.subcols(start, m - start).transpose(),
                    b.subcols(start, width),
                    1.0,
                    Par::Seq,
                );
            }
            part
        })
        .collect();
    let mut sum = Mat::<f64>::zeros(m, m);
    for part in &parts {
        sum += part;
    }
    for j in 0..m {
        for i in 0..j {
            sum[(i, j)] = sum[(j, i)];
        }
    }
    sum
}

/// aᵀ b (a: N × m, b: N × k), summed over the row ranges in a fixed order.
pub fn transpose_product(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> Mat<f64> {
    let parts: Vec<Mat<f64>> = row_ranges(a.nrows())
        .into_par_iter()
        .map(|rows| {
            a.subrows(rows.start, rows.len()).transpose() * b.subrows(rows.start, rows.len())
        })
        .collect();
    let mut sum = Mat::<f64>::zeros(a.ncols(), b.ncols());
    for part in &parts {
        sum += part;
    }
    sum
}

/// out = α a t (`Accum::Replace`) or out += α a t (`Accum::Add`), with a: N × m, t: m × k,
/// each row range on its own.
fn rows_product_into(
    out: MatMut<'_, f64>,
    accum: Accum,
    a: MatRef<'_, f64>,
    t: MatRef<'_, f64>,
    alpha: f64,
) {
    let mut tasks = Vec::new();
    let mut rest = out;
    for rows in row_ranges(a.nrows()) {
        let (head, tail) = rest.split_at_row_mut(rows.len());
        tasks.push((rows, head));
        rest = tail;
    }
    tasks.into_par_iter().for_each(|(rows, part)| {
        matmul(
            part,
            accum,
            a.subrows(rows.start, rows.len()),
            t,
            alpha,
            Par::Seq,
        );
    });
}

/// w −= v h (w: N × b, v: N × r, h: r × b).
fn subtract_product(w: MatMut<'_, f64>, v: MatRef<'_, f64>, h: MatRef<'_, f64>) {
    rows_product_into(w, Accum::Add, v, h, -1.0);
}

/// a t (a: N × m, t: m × k), each row range on its own.
pub fn rows_product(a: MatRef<'_, f64>, t: MatRef<'_, f64>) -> Mat<f64> {
    let mut out = Mat::<f64>::zeros(a.nrows(), t.ncols());
    rows_product_into(out.as_mut(), Accum::Replace, a, t, 1.0);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_split_by_rows_are_the_products() {
        let a = Mat::from_fn(37, 9, |i, j| ((i * 7 + j * 3) % 11) as f64 - 5.0);
        let b = Mat::from_fn(37, 4, |i, j| ((i + 2 * j) % 5) as f64 * 0.5);
        let t = Mat::from_fn(9, 3, |i, j| (i as f64 - j as f64) * 0.25);
        let square = a.transpose() * &a;
        let symmetric = symmetric_product(a.as_ref(), a.as_ref());
        let general = transpose_product(a.as_ref(), b.as_ref());
        let expected = a.transpose() * &b;
        let rows = rows_product(a.as_ref(), t.as_ref());
        let expected_rows = &a * &t;
        // Integers and halves: every product is exact in floating point.
        assert_eq!(symmetric, square);
        assert_eq!(general, expected);
        assert_eq!(rows, expected_rows);
    }
}
