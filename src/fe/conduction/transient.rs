//! A full-order time integrator of C Ṫ + K T = f(t), kept as the reference that the run's
//! reduced model ([`super::reduced`]) is checked against, and the sparse solves both use.
//!
//! The method is Alexander's two-stage SDIRK (γ = 1 − 1/√2): second order, L-stable (the
//! stiff modes of fine meshes are damped in one step, as by backward Euler, and never left
//! ringing as by Crank–Nicolson), and stiffly accurate; both stages use the one matrix
//! C + γ h K, factorised once per step length.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky,
    SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMat, SparseColMatRef, Triplet};
use faer::{Conj, Mat, MatMut, Par, Side};
use std::sync::Arc;

use super::add_product;

/// The symbolic part of a sparse Cholesky factorisation, shared by every matrix of one
/// pattern (K + σC for every σ). Supernodal: the solves have tens of right-hand sides, for
/// which the supernodal kernels are several times faster than column-by-column ones.
#[derive(Clone)]
pub struct SpdSymbolic {
    symbolic: Arc<SymbolicCholesky<usize>>,
}

impl SpdSymbolic {
    /// The symbolic factorisation of `a`'s pattern (lower triangle read); None if it fails.
    pub fn new(a: &SparseColMat<usize, f64>) -> Option<SpdSymbolic> {
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic =
            factorize_symbolic_cholesky(a.symbolic(), Side::Lower, SymmetricOrdering::Amd, params)
                .ok()?;
        Some(SpdSymbolic {
            symbolic: Arc::new(symbolic),
        })
    }
}

/// A sparse Cholesky factorisation of a symmetric positive definite matrix.
pub struct SpdFactor {
    symbolic: Arc<SymbolicCholesky<usize>>,
    values: Vec<f64>,
    /// The numeric factorisation's scratch (the matrix permuted, the supernodes' updates),
    /// kept with the factor so that refactorising the same pattern ([`SpdFactor::refactorise`],
    /// once per shift of the heat problem's reduction) allocates nothing: fresh memory is
    /// zeroed by the kernel page by page before it is used.
    scratch: MemBuffer,
}

impl SpdFactor {
    /// Factorise `a` (both triangles stored; the lower one is read); None if it is not
    /// positive definite.
    pub fn new(a: &SparseColMat<usize, f64>) -> Option<SpdFactor> {
        Self::with_symbolic(&SpdSymbolic::new(a)?, a.as_ref())
    }

    /// Factorise `a`, whose pattern is the one `symbolic` was made for.
    pub fn with_symbolic(
        symbolic: &SpdSymbolic,
        a: SparseColMatRef<'_, usize, f64>,
    ) -> Option<SpdFactor> {
        let symbolic = Arc::clone(&symbolic.symbolic);
        let scratch = MemBuffer::new(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        );
        let mut factor = SpdFactor {
            values: vec![0.0; symbolic.len_val()],
            symbolic,
            scratch,
        };
        factor.refactorise(a).then_some(factor)
    }

    /// Factorise `a`, of the pattern this factor was made for, into this factor's storage;
    /// false if it is not positive definite (the factor is then unusable). The supernodal
    /// factorisation (forced by [`SpdSymbolic::new`]) clears the values it writes first.
    pub fn refactorise(&mut self, a: SparseColMatRef<'_, usize, f64>) -> bool {
        self.symbolic
            .factorize_numeric_llt(
                &mut self.values,
                a,
                Side::Lower,
                LltRegularization::default(),
                Par::Seq,
                MemStack::new(&mut self.scratch),
                Default::default(),
            )
            .is_ok()
    }

    /// Solve in place for every column of `rhs`.
    pub fn solve_in_place(&self, rhs: &mut Mat<f64>) {
        self.solve_columns(rhs.as_mut());
    }

    /// Solve in place for every column of `rhs`, a view.
    pub fn solve_columns(&self, rhs: MatMut<'_, f64>) {
        let mut buffer = MemBuffer::new(
            self.symbolic
                .solve_in_place_scratch::<f64>(rhs.ncols(), Par::Seq),
        );
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            rhs,
            Par::Seq,
            MemStack::new(&mut buffer),
        );
    }

    /// Solve for one right-hand side.
    pub fn solve(&self, rhs: &[f64]) -> Vec<f64> {
        let mut m = Mat::from_fn(rhs.len(), 1, |i, _| rhs[i]);
        self.solve_in_place(&mut m);
        (0..rhs.len()).map(|i| m[(i, 0)]).collect()
    }
}

/// Solve A x = b for a symmetric positive definite sparse A; None if A is not.
pub fn solve_spd(a: &SparseColMat<usize, f64>, b: &[f64]) -> Option<Vec<f64>> {
    let x = SpdFactor::new(a)?.solve(b);
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Solve A x = b for a sparse A with no symmetry (an advection term), by LU; None if it is
/// singular.
pub fn solve_general(a: &SparseColMat<usize, f64>, b: &[f64]) -> Option<Vec<f64>> {
    let x = SparseFactor::new(a, false)?.solve(b);
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The symbolic factorisation of one pattern: Cholesky's for symmetric matrices, LU's for the
/// conductivity of a body whose material flows (advection makes it non-symmetric).
#[derive(Clone)]
pub enum SparseSymbolic {
    /// Symmetric positive definite: Cholesky.
    Spd(SpdSymbolic),
    /// General: LU with partial pivoting.
    General(faer::sparse::linalg::solvers::SymbolicLu<usize>),
}

impl SparseSymbolic {
    /// The symbolic factorisation of `a`'s pattern for a matrix that is `symmetric` or not.
    pub fn new(a: &SparseColMat<usize, f64>, symmetric: bool) -> Option<SparseSymbolic> {
        if symmetric {
            SpdSymbolic::new(a).map(SparseSymbolic::Spd)
        } else {
            faer::sparse::linalg::solvers::SymbolicLu::try_new(a.symbolic())
                .ok()
                .map(SparseSymbolic::General)
        }
    }
}

/// A sparse factorisation: Cholesky (symmetric positive definite) or LU (general).
pub enum SparseFactor {
    /// Cholesky.
    Spd(SpdFactor),
    /// LU (boxed: it is several times the size of the Cholesky handle).
    General(Box<faer::sparse::linalg::solvers::Lu<usize, f64>>),
}

impl SparseFactor {
    /// Factorise `a`, `symmetric` or not; None if it fails (not positive definite, singular).
    pub fn new(a: &SparseColMat<usize, f64>, symmetric: bool) -> Option<SparseFactor> {
        Self::with_symbolic(&SparseSymbolic::new(a, symmetric)?, a.as_ref())
    }

    /// Factorise `a`, whose pattern is the one `symbolic` was made for.
    pub fn with_symbolic(
        symbolic: &SparseSymbolic,
        a: SparseColMatRef<'_, usize, f64>,
    ) -> Option<SparseFactor> {
        match symbolic {
            SparseSymbolic::Spd(s) => SpdFactor::with_symbolic(s, a).map(SparseFactor::Spd),
            SparseSymbolic::General(s) => {
                faer::sparse::linalg::solvers::Lu::try_new_with_symbolic(s.clone(), a)
                    .ok()
                    .map(|lu| SparseFactor::General(Box::new(lu)))
            }
        }
    }

    /// Factorise `a`, whose pattern is the one `symbolic` was made for, in the storage of
    /// `previous` (a factor of the same pattern) when it is a Cholesky factor: a sequence of
    /// shifts K + σC then allocates the factor and its scratch once.
    pub fn refactorise(
        previous: Option<SparseFactor>,
        symbolic: &SparseSymbolic,
        a: SparseColMatRef<'_, usize, f64>,
    ) -> Option<SparseFactor> {
        match previous {
            Some(SparseFactor::Spd(mut factor)) => {
                factor.refactorise(a).then_some(SparseFactor::Spd(factor))
            }
            _ => Self::with_symbolic(symbolic, a),
        }
    }

    /// Solve in place for every column of `rhs`.
    pub fn solve_in_place(&self, rhs: &mut Mat<f64>) {
        self.solve_columns(rhs.as_mut());
    }

    /// Solve in place for every column of `rhs`, a view.
    pub fn solve_columns(&self, rhs: MatMut<'_, f64>) {
        use faer::linalg::solvers::Solve;
        match self {
            SparseFactor::Spd(f) => f.solve_columns(rhs),
            SparseFactor::General(lu) => lu.solve_in_place(rhs),
        }
    }

    /// Solve for one right-hand side.
    pub fn solve(&self, rhs: &[f64]) -> Vec<f64> {
        let mut m = Mat::from_fn(rhs.len(), 1, |i, _| rhs[i]);
        self.solve_in_place(&mut m);
        (0..rhs.len()).map(|i| m[(i, 0)]).collect()
    }
}

/// α A + β B for two sparse matrices (of the same size; patterns merged).
pub fn combine(
    alpha: f64,
    a: &SparseColMat<usize, f64>,
    beta: f64,
    b: &SparseColMat<usize, f64>,
) -> SparseColMat<usize, f64> {
    let mut triplets = Vec::with_capacity(a.val().len() + b.val().len());
    for (scale, m) in [(alpha, a), (beta, b)] {
        let col_ptr = m.symbolic().col_ptr();
        let row_idx = m.symbolic().row_idx();
        for j in 0..m.ncols() {
            let range = col_ptr[j]..col_ptr[j + 1];
            for (&i, &v) in row_idx[range.clone()].iter().zip(&m.val()[range]) {
                triplets.push(Triplet::new(i, j, scale * v));
            }
        }
    }
    SparseColMat::try_new_from_triplets(a.nrows(), a.ncols(), &triplets)
        .expect("indices of two matrices of the same size")
}

/// The SDIRK2 stepper for C Ṫ + K T = f(t) with one step length h (s).
pub struct Sdirk2 {
    conductivity: SparseColMat<usize, f64>,
    capacity: SparseColMat<usize, f64>,
    factor: SparseFactor,
    step: f64,
}

/// γ = 1 − 1/√2 of Alexander's L-stable two-stage SDIRK.
const GAMMA: f64 = 1.0 - std::f64::consts::FRAC_1_SQRT_2;

impl Sdirk2 {
    /// The stepper of step length `step` (s) for a symmetric conductivity; None if
    /// C + γ h K is not positive definite.
    pub fn new(
        conductivity: &SparseColMat<usize, f64>,
        capacity: &SparseColMat<usize, f64>,
        step: f64,
    ) -> Option<Sdirk2> {
        Self::with_symmetry(conductivity, capacity, step, true)
    }

    /// The stepper of step length `step` (s) for a conductivity that is `symmetric` or not
    /// (advection); None if C + γ h K cannot be factorised.
    pub fn with_symmetry(
        conductivity: &SparseColMat<usize, f64>,
        capacity: &SparseColMat<usize, f64>,
        step: f64,
        symmetric: bool,
    ) -> Option<Sdirk2> {
        let matrix = combine(1.0, capacity, GAMMA * step, conductivity);
        Some(Sdirk2 {
            conductivity: conductivity.clone(),
            capacity: capacity.clone(),
            factor: SparseFactor::new(&matrix, symmetric)?,
            step,
        })
    }

    /// Advance `t` (free unknowns, °C) by one step from time `time`, the sources being
    /// `source(τ)` (mW per free unknown) at time τ.
    pub fn advance(&self, t: &mut [f64], time: f64, source: impl Fn(f64) -> Vec<f64>) {
        let n = t.len();
        let h = self.step;
        let mut c_t = vec![0.0; n];
        add_product(&self.capacity, t, &mut c_t);
        // Stage 1: (C + γhK) Y1 = C Tₙ + γh f(t + γh).
        let f1 = source(time + GAMMA * h);
        let rhs: Vec<f64> = (0..n).map(|i| c_t[i] + GAMMA * h * f1[i]).collect();
        let y1 = self.factor.solve(&rhs);
        // Stage 2: (C + γhK) Y2 = C Tₙ + (1 − γ)h (f(t + γh) − K Y1) + γh f(t + h).
        let mut k_y1 = vec![0.0; n];
        add_product(&self.conductivity, &y1, &mut k_y1);
        let f2 = source(time + h);
        let rhs: Vec<f64> = (0..n)
            .map(|i| c_t[i] + (1.0 - GAMMA) * h * (f1[i] - k_y1[i]) + GAMMA * h * f2[i])
            .collect();
        t.copy_from_slice(&self.factor.solve(&rhs));
    }
}
