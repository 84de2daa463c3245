//! Hierarchical integrated-Legendre shape functions (Szabó & Babuška) on the
//! reference square [-1, 1]².
//!
//! 1D functions, indexed k = 0..=p:
//! `N_0(x) = (1-x)/2`, `N_1(x) = (1+x)/2`, and for k >= 2
//! `φ_k(x) = (P_k(x) - P_{k-2}(x)) / sqrt(2(2k-1)) = sqrt((2k-1)/2) ∫_{-1}^x P_{k-1}`,
//! with `φ_k'(x) = sqrt((2k-1)/2) P_{k-1}(x)`.
//! The bubbles satisfy `φ_k(±1) = 0` and `φ_k(-x) = (-1)^k φ_k(x)`, so
//! odd-degree edge modes flip sign when an edge is traversed backwards; the
//! global assembly must account for this when neighbouring elements disagree
//! on an edge's direction.

/// Values and derivatives of the 1D functions 0..=p at x ∈ [-1, 1], written
/// into `values[0..=p]` and `derivatives[0..=p]` (d/dx on the reference
/// interval). Index 0 is `N_0`, 1 is `N_1`, k >= 2 is the bubble `φ_k`.
///
/// # Panics
/// If either slice is shorter than `p + 1`.
pub fn shape_1d(p: usize, x: f64, values: &mut [f64], derivatives: &mut [f64]) {
    assert!(
        values.len() > p && derivatives.len() > p,
        "output slices too short"
    );
    values[0] = 0.5 * (1.0 - x);
    derivatives[0] = -0.5;
    if p == 0 {
        return;
    }
    values[1] = 0.5 * (1.0 + x);
    derivatives[1] = 0.5;
    // Run the Legendre recurrence once, keeping P_{k-2}, P_{k-1}, P_k, rather
    // than calling quadrature::legendre per k (which would be O(p²)).
    let mut p_km2 = 1.0; // P_0
    let mut p_km1 = x; // P_1
    for k in 2..=p {
        let kf = k as f64;
        let p_k = ((2.0 * kf - 1.0) * x * p_km1 - (kf - 1.0) * p_km2) / kf;
        values[k] = (p_k - p_km2) / (2.0 * (2.0 * kf - 1.0)).sqrt();
        derivatives[k] = ((2.0 * kf - 1.0) / 2.0).sqrt() * p_km1;
        p_km2 = p_km1;
        p_km1 = p_k;
    }
}

/// Polynomial space of an element.
///
/// `TensorProduct` is Q_p (all `x^a y^b` with a, b <= p); `Trunk` is the
/// trunk/serendipity space (all `x^a y^b` with a + b <= p plus `x^p y`,
/// `x y^p`), which has the same boundary modes but fewer internal ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Space {
    /// Full tensor-product space Q_p: (p+1)² modes.
    TensorProduct,
    /// Trunk space: 4p + (p-2)(p-3)/2 modes for p >= 2 (4 for p = 1).
    Trunk,
}

/// Which topological entity a 2D mode belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModeKind {
    /// Vertex mode of local vertex 0..4 (v0=(-1,-1), v1=(1,-1), v2=(1,1), v3=(-1,1)).
    Vertex(usize),
    /// Edge mode of local edge 0..4 with polynomial degree 2..=p along the edge.
    Edge {
        /// Local edge index 0..4.
        edge: usize,
        /// Degree k of the bubble φ_k along the edge.
        degree: usize,
    },
    /// Internal (bubble) mode, vanishing on the whole element boundary.
    Internal,
}

/// One 2D mode = `xi_fn(ξ) · eta_fn(η)`, both indices into the 1D functions
/// of [`shape_1d`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mode {
    /// Index of the 1D function in ξ.
    pub xi_fn: usize,
    /// Index of the 1D function in η.
    pub eta_fn: usize,
    /// Entity the mode belongs to.
    pub kind: ModeKind,
}

/// Local (start, end) vertex of each local edge; the edge parameter runs
/// from start to end along increasing ξ (edges 0, 2) or η (edges 1, 3).
const EDGE_ENDPOINTS: [(usize, usize); 4] = [(0, 1), (1, 2), (3, 2), (0, 3)];

/// Local (start, end) vertex of local edge `edge` (0..4):
/// edge 0 → (v0, v1), edge 1 → (v1, v2), edge 2 → (v3, v2), edge 3 → (v0, v3).
///
/// # Panics
/// If `edge >= 4`.
pub fn edge_endpoints(edge: usize) -> (usize, usize) {
    EDGE_ENDPOINTS[edge]
}

/// Hierarchical basis of polynomial order `p` on the reference square.
///
/// Mode order (a contract relied upon by assembly): the 4 vertex modes
/// (v0..v3), then edge modes of edge 0, 1, 2, 3 (degrees 2..=p each), then
/// internal modes `φ_i(ξ) φ_j(η)` with j outer, i inner.
#[derive(Clone, Debug)]
pub struct QuadBasis {
    /// Polynomial order (>= 1).
    pub p: usize,
    /// Polynomial space.
    pub space: Space,
    /// All modes in the contractual order.
    pub modes: Vec<Mode>,
}

impl QuadBasis {
    /// Build the basis of order `p` for `space`.
    ///
    /// # Panics
    /// If `p == 0`.
    pub fn new(p: usize, space: Space) -> Self {
        assert!(p >= 1, "polynomial order must be at least 1");
        let mut modes = Vec::new();
        let mut push = |xi_fn, eta_fn, kind| {
            modes.push(Mode {
                xi_fn,
                eta_fn,
                kind,
            })
        };
        // (xi_fn, eta_fn) of the vertex modes: N_0 ↔ coordinate -1, N_1 ↔ +1.
        for (v, &(a, b)) in [(0, 0), (1, 0), (1, 1), (0, 1)].iter().enumerate() {
            push(a, b, ModeKind::Vertex(v));
        }
        for edge in 0..4 {
            for k in 2..=p {
                let (a, b) = [(k, 0), (1, k), (k, 1), (0, k)][edge];
                push(a, b, ModeKind::Edge { edge, degree: k });
            }
        }
        for j in 2..=p {
            for i in 2..=p {
                if space == Space::TensorProduct || i + j <= p {
                    push(i, j, ModeKind::Internal);
                }
            }
        }
        Self { p, space, modes }
    }

    /// Total number of modes.
    pub fn n_modes(&self) -> usize {
        self.modes.len()
    }

    /// Number of vertex + edge modes, 4p; they come first in the mode order.
    pub fn n_boundary(&self) -> usize {
        4 * self.p
    }

    /// Number of internal modes: (p-1)² for TensorProduct, (p-2)(p-3)/2 for
    /// Trunk (p >= 2).
    pub fn n_internal(&self) -> usize {
        self.n_modes() - self.n_boundary()
    }

    /// Local indices of the p+1 modes that do not vanish on local edge `edge`,
    /// in the order: start vertex, end vertex (see [`edge_endpoints`]), then
    /// the edge modes of degree 2..=p.
    ///
    /// # Panics
    /// If `edge >= 4`.
    pub fn edge_trace(&self, edge: usize) -> Vec<usize> {
        let (start, end) = edge_endpoints(edge);
        let first = 4 + edge * (self.p - 1);
        let mut trace = vec![start, end];
        trace.extend(first..first + self.p - 1);
        trace
    }

    /// Tabulate all modes and their reference derivatives at the tensor grid
    /// `xi_pts × eta_pts`; see [`Tabulation`] for the layout.
    pub fn tabulate(&self, xi_pts: &[f64], eta_pts: &[f64]) -> Tabulation {
        let np1 = self.p + 1;
        // 1D tables first so each 2D entry is two products, not a recurrence.
        let table = |pts: &[f64]| {
            let mut v = vec![0.0; pts.len() * np1];
            let mut d = vec![0.0; pts.len() * np1];
            for (i, &x) in pts.iter().enumerate() {
                let r = i * np1..(i + 1) * np1;
                shape_1d(self.p, x, &mut v[r.clone()], &mut d[r]);
            }
            (v, d)
        };
        let (xv, xd) = table(xi_pts);
        let (ev, ed) = table(eta_pts);
        let n_points = xi_pts.len() * eta_pts.len();
        let size = self.n_modes() * n_points;
        let mut tab = Tabulation {
            n_points,
            values: vec![0.0; size],
            d_xi: vec![0.0; size],
            d_eta: vec![0.0; size],
        };
        for (m, mode) in self.modes.iter().enumerate() {
            for ie in 0..eta_pts.len() {
                let (fe, de) = (ev[ie * np1 + mode.eta_fn], ed[ie * np1 + mode.eta_fn]);
                for ix in 0..xi_pts.len() {
                    let (fx, dx) = (xv[ix * np1 + mode.xi_fn], xd[ix * np1 + mode.xi_fn]);
                    let idx = m * n_points + ie * xi_pts.len() + ix;
                    tab.values[idx] = fx * fe;
                    tab.d_xi[idx] = dx * fe;
                    tab.d_eta[idx] = fx * de;
                }
            }
        }
        tab
    }
}

/// Row-major tables of size `n_modes × n_points`: entry `m * n_points + q`
/// belongs to mode m at point `q = i_eta * xi_pts.len() + i_xi`.
/// Derivatives are with respect to the reference coordinates ξ, η.
#[derive(Clone, Debug)]
pub struct Tabulation {
    /// Number of grid points, `xi_pts.len() * eta_pts.len()`.
    pub n_points: usize,
    /// Mode values.
    pub values: Vec<f64>,
    /// ∂/∂ξ of each mode.
    pub d_xi: Vec<f64>,
    /// ∂/∂η of each mode.
    pub d_eta: Vec<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quadrature::gauss_legendre;

    const SPACES: [Space; 2] = [Space::TensorProduct, Space::Trunk];

    /// Deterministic, irregularly spaced points in (-1, 1) (no external crates);
    /// the fractional parts of a fast-growing sine argument scatter well enough.
    fn random_points(n: usize, seed: u64) -> Vec<f64> {
        (0..n)
            .map(|i| (((i as u64 + 7 * seed) as f64 * 12.9898).sin() * 43758.55).sin())
            .collect()
    }

    fn eval(basis: &QuadBasis, x: f64, y: f64) -> Tabulation {
        basis.tabulate(&[x], &[y])
    }

    // Values are O(1) sums of a handful of O(1) products: 1e-14 is ~50 ulps.
    const TOL: f64 = 1e-14;

    #[test]
    fn mode_counts() {
        for p in 1..=12 {
            let tp = QuadBasis::new(p, Space::TensorProduct);
            assert_eq!(tp.n_modes(), (p + 1) * (p + 1));
            assert_eq!(tp.n_internal(), (p - 1) * (p - 1));
            let tr = QuadBasis::new(p, Space::Trunk);
            let internal = if p < 4 { 0 } else { (p - 2) * (p - 3) / 2 };
            assert_eq!(tr.n_internal(), internal);
            assert_eq!(tr.n_modes(), 4 * p + internal);
            for b in [&tp, &tr] {
                assert_eq!(b.n_boundary(), 4 * p);
                let internal = b.modes.iter().filter(|m| m.kind == ModeKind::Internal);
                assert_eq!(internal.count(), b.n_internal());
            }
        }
    }

    #[test]
    fn vertex_modes_partition_unity_and_others_vanish_at_corners() {
        let b = QuadBasis::new(7, Space::TensorProduct);
        let pts = random_points(20, 1);
        let t = b.tabulate(&pts, &pts);
        for q in 0..t.n_points {
            let s: f64 = (0..4).map(|m| t.values[m * t.n_points + q]).sum();
            let sx: f64 = (0..4).map(|m| t.d_xi[m * t.n_points + q]).sum();
            let sy: f64 = (0..4).map(|m| t.d_eta[m * t.n_points + q]).sum();
            assert!((s - 1.0).abs() < TOL && sx.abs() < TOL && sy.abs() < TOL);
        }
        // Grid layout: ξ varies fastest, so point q = 1 of a 2×1 grid is (1, -1) = v1.
        let t = b.tabulate(&[-1.0, 1.0], &[-1.0]);
        assert_eq!((t.n_points, t.values[2 + 1], t.values[2]), (2, 1.0, 0.0));
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        for (c, &(x, y)) in corners.iter().enumerate() {
            let t = eval(&b, x, y);
            for m in 0..b.n_modes() {
                let expected = if m == c { 1.0 } else { 0.0 };
                assert!((t.values[m] - expected).abs() < TOL, "mode {m} corner {c}");
            }
        }
    }

    #[test]
    fn edge_modes_live_on_their_edge_only() {
        let p = 8;
        let b = QuadBasis::new(p, Space::Trunk);
        let s = random_points(10, 2);
        // Points on edge e as (ξ, η), parameter s along the edge.
        let on_edge = |e: usize, s: f64| match e {
            0 => (s, -1.0),
            1 => (1.0, s),
            2 => (s, 1.0),
            _ => (-1.0, s),
        };
        for e in 0..4 {
            let trace = b.edge_trace(e);
            assert_eq!(trace.len(), p + 1);
            let (v0, v1) = edge_endpoints(e);
            assert_eq!((trace[0], trace[1]), (v0, v1));
            for (k, &m) in trace[2..].iter().enumerate() {
                let expected = ModeKind::Edge {
                    edge: e,
                    degree: k + 2,
                };
                assert_eq!(b.modes[m].kind, expected);
            }
            for f in 0..4 {
                for &si in &s {
                    let (x, y) = on_edge(f, si);
                    let t = eval(&b, x, y);
                    for m in (0..b.n_modes()).filter(|m| !b.edge_trace(f).contains(m)) {
                        assert!(t.values[m].abs() < TOL, "mode {m} on edge {f}");
                    }
                    if f == e {
                        // Along its own edge the trace is the 1D function of s,
                        // with no sign flip: start vertex ~ N_0(s), end ~ N_1(s).
                        let (mut v, mut d) = ([0.0; 9], [0.0; 9]);
                        shape_1d(p, si, &mut v, &mut d);
                        for (k, &m) in trace.iter().enumerate() {
                            assert!((t.values[m] - v[k]).abs() < TOL);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        // Central differences with h = 1e-6: truncation h²/6·|f'''| <~ 1e-9 for
        // p = 10 and cancellation ~eps/h ~ 1e-10, so 1e-7 is a safe bound.
        let h = 1e-6;
        for space in SPACES {
            let b = QuadBasis::new(10, space);
            let xs = random_points(15, 3);
            let ys = random_points(15, 4);
            for (&x, &y) in xs.iter().zip(&ys) {
                let (x, y) = (x * 0.999, y * 0.999); // keep x ± h inside [-1, 1]
                let t = eval(&b, x, y);
                let (xp, xm) = (eval(&b, x + h, y), eval(&b, x - h, y));
                let (yp, ym) = (eval(&b, x, y + h), eval(&b, x, y - h));
                for m in 0..b.n_modes() {
                    let fd_x = (xp.values[m] - xm.values[m]) / (2.0 * h);
                    let fd_y = (yp.values[m] - ym.values[m]) / (2.0 * h);
                    assert!((fd_x - t.d_xi[m]).abs() < 1e-7, "d_xi mode {m}");
                    assert!((fd_y - t.d_eta[m]).abs() < 1e-7, "d_eta mode {m}");
                }
            }
        }
    }

    #[test]
    fn parity_of_bubbles() {
        let p = 12;
        let [mut v, mut d, mut vm, mut dm] = [[0.0; 13]; 4];
        for &x in &random_points(20, 5) {
            shape_1d(p, x, &mut v, &mut d);
            shape_1d(p, -x, &mut vm, &mut dm);
            for k in 2..=p {
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                assert!((vm[k] - sign * v[k]).abs() < TOL);
                assert!((dm[k] + sign * d[k]).abs() < 1e-13); // |φ_k'| ~ sqrt(k)
            }
        }
    }

    /// Least-squares residual (max abs) of fitting `f` by the basis on the grid,
    /// via Householder QR of the n_points × n_modes collocation matrix.
    fn ls_residual(b: &QuadBasis, pts: &[f64], f: impl Fn(f64, f64) -> f64) -> f64 {
        let t = b.tabulate(pts, pts);
        let (rows, cols) = (t.n_points, b.n_modes());
        let n = pts.len();
        let rhs: Vec<f64> = (0..rows).map(|q| f(pts[q % n], pts[q / n])).collect();
        // Tabulation rows are modes, i.e. the columns of A: column-major [A | f].
        let mut a = [t.values.as_slice(), &rhs].concat();
        for c in 0..cols {
            let mut v = a[c * rows + c..(c + 1) * rows].to_vec();
            let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            v[0] += norm.copysign(v[0]); // sign choice avoids cancellation
            let vv: f64 = v.iter().map(|x| x * x).sum();
            for col in a.chunks_mut(rows).skip(c) {
                let tail = &mut col[c..];
                let dot: f64 = v.iter().zip(tail.iter()).map(|(x, y)| x * y).sum();
                tail.iter_mut()
                    .zip(&v)
                    .for_each(|(y, x)| *y -= 2.0 * dot / vv * x);
            }
        }
        let mut coef = vec![0.0; cols];
        for c in (0..cols).rev() {
            let s: f64 = (c + 1..cols).map(|k| a[k * rows + c] * coef[k]).sum();
            coef[c] = (a[cols * rows + c] - s) / a[c * rows + c];
        }
        let fit = |q: usize| {
            (0..cols)
                .map(|m| t.values[m * rows + q] * coef[m])
                .sum::<f64>()
        };
        (0..rows).fold(0.0, |acc: f64, q| acc.max((fit(q) - rhs[q]).abs()))
    }

    #[test]
    fn span_reproduces_monomials() {
        // The monomials are O(1) on the square and the integrated-Legendre
        // basis is well conditioned for these p, so an exact representation
        // leaves only round-off (~1e-14); 1e-12 is the required bound.
        for p in 1..=8 {
            let pts = gauss_legendre(p + 2).points;
            for space in SPACES {
                let b = QuadBasis::new(p, space);
                for a_deg in 0..=p {
                    for b_deg in 0..=p {
                        if space == Space::Trunk && a_deg + b_deg > p {
                            continue;
                        }
                        let f = |x: f64, y: f64| x.powi(a_deg as i32) * y.powi(b_deg as i32);
                        let r = ls_residual(&b, &pts, f);
                        assert!(r < 1e-12, "p={p} {space:?} x^{a_deg} y^{b_deg}: {r}");
                    }
                }
            }
        }
        // Sanity check that the fit can fail: Q_p cannot represent x^{p+1}.
        let b = QuadBasis::new(3, Space::TensorProduct);
        assert!(ls_residual(&b, &gauss_legendre(6).points, |x, _| x.powi(4)) > 1e-3);
    }
}
