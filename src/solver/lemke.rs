//! Lemke's complementary pivoting method for the linear complementarity
//! problem LCP(q, M): find z ≥ 0 with w = M z + q ≥ 0 and zᵀw = 0.
//!
//! This is the fallback of the contact solver, so robustness beats speed:
//! the lexicographic ratio test keeps degenerate problems from cycling, the
//! data are normalised so that pivot tolerances are scale-free, and the final
//! basis is re-solved from the original data to shed pivoting round-off.

/// Why Lemke's method could not deliver a solution.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum LemkeError {
    /// The entering column has no positive entry, so the path is unbounded.
    #[error("Lemke's method ended on a secondary ray after {pivots} pivots: the LCP has no solution reachable from this start (M is not copositive-plus?)")]
    Ray {
        /// Pivots made before the ray.
        pivots: usize,
    },
    /// The pivot budget was exhausted.
    #[error("Lemke's method did not finish in {pivots} pivots")]
    MaxPivots {
        /// The pivot budget.
        pivots: usize,
    },
    /// `m.len()` is not `q.len()²`.
    #[error("LCP dimensions do not match: M has {m_len} entries, q has {n}")]
    Dimension {
        /// Entries of M.
        m_len: usize,
        /// Entries of q.
        n: usize,
    },
    /// NaN or infinity in `m` or `q`.
    #[error("LCP data contain a non-finite number")]
    NonFinite,
}

/// Solution of an LCP.
#[derive(Debug, Clone)]
pub struct LcpSolution {
    /// The unknown z ≥ 0.
    pub z: Vec<f64>,
    /// The slack w = M z + q ≥ 0, recomputed from the polished z.
    pub w: Vec<f64>,
    /// Number of pivots performed, including the initial z₀ pivot.
    pub pivots: usize,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Var {
    W(usize),
    Z(usize),
    Z0,
}

/// Solve LCP(q, M); `m` is row-major n×n. `Ok` means the pivoting ended with z₀ out of the
/// basis, not that the result is accurate: on an ill-conditioned tableau it may not be, so a
/// caller checks [`complementarity_residual`] of `z` and `w` (the contact solver does).
/// `max_pivots` bounds the work (a sensible caller value: 50·n).
pub fn lemke(m: &[f64], q: &[f64], max_pivots: usize) -> Result<LcpSolution, LemkeError> {
    let n = q.len();
    if m.len() != n * n {
        return Err(LemkeError::Dimension { m_len: m.len(), n });
    }
    if m.iter().chain(q).any(|x| !x.is_finite()) {
        return Err(LemkeError::NonFinite);
    }
    if q.iter().all(|&x| x >= 0.0) {
        return Ok(LcpSolution {
            z: vec![0.0; n],
            w: q.to_vec(),
            pivots: 0,
        });
    }
    // Solving LCP(βq, αM) gives z' = (β/α) z, so normalising both to unit
    // size lets the pivot tolerances below be absolute numbers.
    let alpha = 1.0 / m.iter().fold(f64::MIN_POSITIVE, |a, x| a.max(x.abs()));
    let beta = 1.0 / q.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    // Stored transposed so that B⁻¹·M_j runs over contiguous memory.
    let mt: Vec<f64> = (0..n * n).map(|k| m[(k % n) * n + k / n] * alpha).collect();

    // Revised form: keep only B⁻¹ and B⁻¹q; the tableau columns of the
    // initial w-basis are the identity, so B⁻¹ doubles as the lexicographic key.
    let mut binv: Vec<f64> = (0..n * n)
        .map(|k| f64::from(u8::from(k % (n + 1) == 0)))
        .collect();
    let mut b: Vec<f64> = q.iter().map(|x| x * beta).collect();
    let mut basis: Vec<Var> = (0..n).map(Var::W).collect();
    if max_pivots == 0 {
        return Err(LemkeError::MaxPivots { pivots: 0 });
    }
    // z₀ leaves every row at -1; the lexicographically smallest (q_r, e_rᵀ)
    // keeps all rows lex-positive, i.e. the minimum q with ties to the last index.
    let r = (0..n).fold(0, |r, i| if b[i] <= b[r] { i } else { r });
    let mut col = vec![-1.0; n];
    pivot(&mut binv, &mut b, &col, r);
    let mut leaving = std::mem::replace(&mut basis[r], Var::Z0);
    let mut pivots = 1;
    loop {
        let entering = match leaving {
            Var::W(i) => Var::Z(i),
            Var::Z(i) => Var::W(i),
            Var::Z0 => break,
        };
        if pivots >= max_pivots {
            return Err(LemkeError::MaxPivots { pivots });
        }
        entering_column(&binv, &mt, entering, &mut col);
        let r = ratio_test(&binv, &b, &col, &basis).ok_or(LemkeError::Ray { pivots })?;
        pivot(&mut binv, &mut b, &col, r);
        leaving = std::mem::replace(&mut basis[r], entering);
        pivots += 1;
    }

    let mut z = vec![0.0; n];
    if !polish(m, q, &basis, &mut z) {
        // The basis matrix proved numerically singular: the tableau values
        // are the best we have.
        z.iter_mut().for_each(|x| *x = 0.0);
        for (i, v) in basis.iter().enumerate() {
            if let Var::Z(j) = *v {
                z[j] = b[i] * alpha / beta;
            }
        }
    }
    let zscale = z.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    z.iter_mut()
        .filter(|x| **x < 0.0 && x.abs() < 1e-12 * zscale)
        .for_each(|x| *x = 0.0);
    let mut w = vec![0.0; n];
    for i in 0..n {
        let row = &m[i * n..(i + 1) * n];
        let wi = dot(row, &z) + q[i];
        // Round-off of this sum is bounded by ~n·ε times the absolute sum.
        let wscale = q[i].abs() + row.iter().zip(&z).map(|(a, x)| (a * x).abs()).sum::<f64>();
        let nonbasic = !basis.contains(&Var::W(i));
        w[i] = if wi.abs() < 1e-12 * wscale && (wi < 0.0 || nonbasic) {
            0.0
        } else {
            wi
        };
    }
    Ok(LcpSolution { z, w, pivots })
}

/// max over i of |min(z_i, w_i)| — the complementarity residual of a candidate solution (0 for an exact solution).
///
/// It also measures infeasibility, since a negative z_i or w_i makes the
/// minimum negative. Extra entries of the longer slice are ignored.
pub fn complementarity_residual(z: &[f64], w: &[f64]) -> f64 {
    z.iter()
        .zip(w)
        .fold(0.0, |a, (zi, wi)| a.max(zi.min(*wi).abs()))
}

/// B⁻¹ times the column of A = [I, -M, -e] that belongs to `var` (`mt` is Mᵀ).
fn entering_column(binv: &[f64], mt: &[f64], var: Var, col: &mut [f64]) {
    let n = col.len();
    for (i, c) in col.iter_mut().enumerate() {
        let row = &binv[i * n..(i + 1) * n];
        *c = match var {
            Var::W(j) => row[j],
            Var::Z(j) => -dot(row, &mt[j * n..(j + 1) * n]),
            Var::Z0 => -row.iter().sum::<f64>(),
        };
    }
}

/// Gauss–Jordan update of B⁻¹ and B⁻¹q for pivot row `r` of column `col`.
fn pivot(binv: &mut [f64], b: &mut [f64], col: &[f64], r: usize) {
    let n = b.len();
    let p = col[r];
    binv[r * n..(r + 1) * n].iter_mut().for_each(|x| *x /= p);
    b[r] /= p;
    let pivot_row = binv[r * n..(r + 1) * n].to_vec();
    for i in (0..n).filter(|&i| i != r && col[i] != 0.0) {
        let f = col[i];
        for (x, y) in binv[i * n..(i + 1) * n].iter_mut().zip(&pivot_row) {
            *x -= f * y;
        }
        b[i] -= f * b[r];
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Lexicographic minimum-ratio test; `None` means the column is a ray.
fn ratio_test(binv: &[f64], b: &[f64], col: &[f64], basis: &[Var]) -> Option<usize> {
    let n = b.len();
    let dmax = col.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    // Data are normalised, so entries this far below the column's largest
    // are elimination noise, not genuine blocking coefficients.
    let tol = (1e-11 * dmax).max(1e-14);
    let cand: Vec<usize> = (0..n).filter(|&i| col[i] > tol).collect();
    let min = cand
        .iter()
        .map(|&i| b[i] / col[i])
        .fold(f64::INFINITY, f64::min);
    let near = |v: f64, min: f64| v <= min + 1e-12 * min.abs().max(1.0);
    // z₀ (of order 1 at the start, q being normalised) would be left at round-off by this
    // step: it leaves now. Otherwise the path passes the solution with z₀ at 1e-14 and may
    // go on to a secondary ray: a frictional punch-b40 case did, after 63 pivots, with z₀
    // at 3e-14 on pivot 34 (tests/contact_properties.rs). The z this gives is polished
    // and its residuals are checked by the caller.
    if let Some(r0) = (0..n).find(|&i| basis[i] == Var::Z0) {
        if col[r0] > tol && min.is_finite() && b[r0] - col[r0] * min <= 1e-12 {
            return Some(r0);
        }
    }
    let mut ties: Vec<usize> = cand
        .into_iter()
        .filter(|&i| near(b[i] / col[i], min))
        .collect();
    // Letting z₀ leave whenever it may ends the path at once; it only breaks
    // a tie, so termination is unaffected.
    if let Some(&i) = ties.iter().find(|&&i| basis[i] == Var::Z0) {
        return Some(i);
    }
    for k in 0..n {
        if ties.len() <= 1 {
            break;
        }
        let key = |i: usize| binv[i * n + k] / col[i];
        let min = ties.iter().map(|&i| key(i)).fold(f64::INFINITY, f64::min);
        ties.retain(|&i| near(key(i), min));
    }
    ties.first().copied()
}

/// Recompute the basic z from the original data by one LU solve of B x = q.
/// Returns false if B is singular or the result is non-finite.
fn polish(m: &[f64], q: &[f64], basis: &[Var], z: &mut [f64]) -> bool {
    let n = q.len();
    let mut a = vec![0.0; n * n];
    for (c, v) in basis.iter().enumerate() {
        match *v {
            Var::W(i) => a[i * n + c] = 1.0,
            Var::Z(j) => (0..n).for_each(|i| a[i * n + c] = -m[i * n + j]),
            Var::Z0 => return false,
        }
    }
    let mut x = q.to_vec();
    if !lu_solve(&mut a, &mut x) {
        return false;
    }
    for (v, xi) in basis.iter().zip(&x) {
        if let Var::Z(j) = *v {
            z[j] = *xi;
        }
    }
    z.iter().all(|v| v.is_finite())
}

/// Solve A x = b in place by LU with partial pivoting (A row-major, overwritten).
fn lu_solve(a: &mut [f64], x: &mut [f64]) -> bool {
    let n = x.len();
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i * n + k].abs().total_cmp(&a[j * n + k].abs()));
        let p = p.unwrap_or(k);
        if a[p * n + k] == 0.0 {
            return false;
        }
        if p != k {
            for j in 0..n {
                a.swap(k * n + j, p * n + j);
            }
            x.swap(k, p);
        }
        for i in k + 1..n {
            let f = a[i * n + k] / a[k * n + k];
            if f != 0.0 {
                for j in k..n {
                    a[i * n + j] -= f * a[k * n + j];
                }
                x[i] -= f * x[k];
            }
        }
    }
    for k in (0..n).rev() {
        let s: f64 = (k + 1..n).map(|j| a[k * n + j] * x[j]).sum();
        x[k] = (x[k] - s) / a[k * n + k];
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    struct XorShift(u64);
    impl XorShift {
        /// Uniform in [-1, 1).
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    /// M = AᵀA + I (+ K − Kᵀ if `skew`): the skew part leaves xᵀMx unchanged,
    /// so M stays positive definite and the LCP has a unique solution.
    fn random_pd(n: usize, skew: bool, rng: &mut XorShift) -> Vec<f64> {
        let a: Vec<f64> = (0..n * n).map(|_| rng.next()).collect();
        let k: Vec<f64> = (0..n * n).map(|_| rng.next()).collect();
        let skew = f64::from(u8::from(skew));
        (0..n * n)
            .map(|idx| {
                let (i, j) = (idx / n, idx % n);
                let ata: f64 = (0..n).map(|l| a[l * n + i] * a[l * n + j]).sum();
                ata + f64::from(u8::from(i == j)) + skew * (k[idx] - k[j * n + i])
            })
            .collect()
    }

    /// Checks a solution against the LCP conditions. The bounds are 1e-10
    /// relative to the size of M z + q: for the well-conditioned (condition
    /// number ≲ 1e3 here) test matrices, the LU polish leaves errors near
    /// n·ε·cond ≈ 1e-11 at n = 80, so this has margin yet catches real bugs.
    fn check(m: &[f64], q: &[f64], sol: &LcpSolution) {
        let n = q.len();
        let amax = |v: &[f64]| v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
        let scale = amax(q).max(amax(m) * amax(&sol.z)).max(1.0);
        assert!(sol.z.iter().all(|&x| x >= -1e-12), "z {:?}", sol.z);
        assert!(sol.w.iter().all(|&x| x >= -1e-10 * scale), "w {:?}", sol.w);
        assert!(complementarity_residual(&sol.z, &sol.w) <= 1e-10 * scale);
        for i in 0..n {
            let wi: f64 = (0..n).map(|j| m[i * n + j] * sol.z[j]).sum::<f64>() + q[i];
            assert!((wi - sol.w[i]).abs() <= 1e-10 * scale, "w mismatch at {i}");
        }
    }

    #[test]
    fn nonnegative_q_gives_zero() {
        let sol = lemke(&[1.0, 2.0, 3.0, 4.0], &[0.0, 1.0], 100).unwrap();
        assert_eq!(sol.z, vec![0.0, 0.0]);
        assert_eq!(sol.w, vec![0.0, 1.0]);
        assert_eq!(sol.pivots, 0);
    }

    #[test]
    fn hand_solved_2x2() {
        // 2a + b = 5, a + 2b = 6 gives a = 4/3, b = 7/3 with w = 0.
        let sol = lemke(&[2.0, 1.0, 1.0, 2.0], &[-5.0, -6.0], 100).unwrap();
        // Polish solves the basis directly, so only a few ulps remain.
        assert!((sol.z[0] - 4.0 / 3.0).abs() < 1e-14 && (sol.z[1] - 7.0 / 3.0).abs() < 1e-14);
        assert_eq!(sol.w, vec![0.0, 0.0]);
    }

    #[test]
    fn hand_solved_3x3() {
        // z = (1/2, 0, 1/2) gives w = (0, 3, 0).
        let m = [2.0, 1.0, 0.0, 1.0, 2.0, 1.0, 0.0, 1.0, 2.0];
        let sol = lemke(&m, &[-1.0, 2.0, -1.0], 100).unwrap();
        let (z, w) = ([0.5, 0.0, 0.5], [0.0, 3.0, 0.0]);
        for i in 0..3 {
            assert!((sol.z[i] - z[i]).abs() < 1e-14 && (sol.w[i] - w[i]).abs() < 1e-14);
        }
    }

    #[test]
    fn random_spd_and_nonsymmetric() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
        for &n in &[5, 20, 80] {
            for skew in [false, true] {
                for _ in 0..3 {
                    let m = random_pd(n, skew, &mut rng);
                    let q: Vec<f64> = (0..n).map(|_| 10.0 * rng.next()).collect();
                    let sol = lemke(&m, &q, 50 * n).unwrap();
                    check(&m, &q, &sol);
                }
            }
        }
    }

    #[test]
    fn brute_force_agrees_for_p_matrix() {
        let n = 4;
        let mut rng = XorShift(12345);
        for _ in 0..20 {
            let m = random_pd(n, true, &mut rng);
            let q: Vec<f64> = (0..n).map(|_| rng.next()).collect();
            let sol = lemke(&m, &q, 200).unwrap();
            check(&m, &q, &sol);
            let mut found = 0;
            for mask in 0..1usize << n {
                // Basis columns of [I, -M]: z_c if bit c is set, else w_c.
                let zb = |c: usize| mask >> c & 1 == 1;
                let eye = |k: usize| f64::from(u8::from(k / n == k % n));
                let mut a: Vec<f64> = (0..n * n)
                    .map(|k| if zb(k % n) { -m[k] } else { eye(k) })
                    .collect();
                let mut x = q.clone();
                assert!(lu_solve(&mut a, &mut x));
                if x.iter().all(|&v| v >= -1e-12) {
                    found += 1;
                    // P-matrix: the solution is unique, and both answers come
                    // from LU solves of the same well-conditioned 4×4 basis
                    // (agreeing to ~1e-15), so 1e-10 only absorbs degenerate zeros.
                    for (i, (xi, si)) in x.iter().zip(&sol.z).enumerate() {
                        let zi = if zb(i) { *xi } else { 0.0 };
                        assert!((zi - si).abs() < 1e-10, "{zi} vs {si}");
                    }
                }
            }
            assert!(found >= 1);
        }
    }

    #[test]
    fn degenerate_cases_terminate() {
        let id = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
        let sol = lemke(&id, &[-1.0, -1.0, -1.0], 100).unwrap();
        assert_eq!(sol.z, vec![1.0, 1.0, 1.0]);
        // M = I + 𝟙𝟙ᵀ, q = -1: z = 1/4 each, every ratio test ties.
        let mut m = [1.0; 9];
        (0..3).for_each(|i| m[i * 4] = 2.0);
        let sol = lemke(&m, &[-1.0, -1.0, -1.0], 100).unwrap();
        check(&m, &[-1.0, -1.0, -1.0], &sol);
        assert!(sol.z.iter().all(|&x| (x - 0.25).abs() < 1e-14));
        // Zeros in q give degenerate (zero-ratio) pivots.
        let mut m = vec![1.0; 16];
        (0..4).for_each(|i| m[i * 5] = 3.0);
        let q = [0.0, -1.0, 0.0, -1.0];
        let sol = lemke(&m, &q, 100).unwrap();
        check(&m, &q, &sol);
        // Rank-one PSD M with all ties: copositive-plus, so Lemke must finish.
        let m = vec![1.0; 9];
        let q = [-1.0, -1.0, -1.0];
        let sol = lemke(&m, &q, 100).unwrap();
        check(&m, &q, &sol);
    }

    #[test]
    fn infeasible_returns_ray() {
        assert!(matches!(
            lemke(&[-1.0], &[-1.0], 10),
            Err(LemkeError::Ray { .. })
        ));
    }

    #[test]
    fn bad_input_is_rejected() {
        let err = lemke(&[1.0, 2.0, 3.0], &[-1.0, 1.0], 10).unwrap_err();
        assert_eq!(err, LemkeError::Dimension { m_len: 3, n: 2 });
        assert_eq!(
            lemke(&[f64::NAN], &[-1.0], 10).unwrap_err(),
            LemkeError::NonFinite
        );
        let err = lemke(&[2.0, 1.0, 1.0, 2.0], &[-5.0, -6.0], 1).unwrap_err();
        assert_eq!(err, LemkeError::MaxPivots { pivots: 1 });
    }
}
