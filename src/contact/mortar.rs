//! Mortar (segment-to-segment) traces of body 2 at body 1's contact points, with dual
//! Lagrange multipliers (Wohlmuth), so that the two bodies may be meshed independently.
//!
//! # The discretisation
//!
//! On each element of body 1's contact edge, parametrised by s ∈ [−1, 1] in the order of the
//! contact points, N_a(s) (a = 0..p) are the Lagrange polynomials at the p + 1 Gauss–Lobatto
//! points s_a; they span the trace of body 1's displacement there, since the hierarchical trace
//! is a polynomial of degree p in s. The contact pressure is the field λ = Σ_i p_i ψ_i with the
//! dual basis ψ_a = Σ_b A_ab N_b, A = D M⁻¹, built element by element from
//!
//! M_ab = ∫ N_a N_b ds,  D_aa = ∫ N_a ds  (ds the arc length on body 1),
//!
//! so that ∫ ψ_a N_b ds = δ_ab D_aa (biorthogonality) and Σ_a ψ_a = 1. A node shared by two
//! elements has ψ_i made of both elements' pieces and D_ii = the sum of both shares. The gap of
//! constraint i is the ψ_i-weighted mean of the gap field,
//!
//! d_i = (1/D_ii) ∫ ψ_i [ (u⁽²⁾(π(x)) − u⁽¹⁾(x))·n_i + g₀(x) ] ds,
//!
//! where π(x) is the point of body 2's edge on the line x + σ n(x) and g₀(x) = σ plus any
//! initial shape. The geometric part is then taken at the point itself, g₀(x_i) (in
//! `CondensedContact::build`): the mean equals it whenever body 1's element polynomials
//! interpolate g₀, as they do the wear, and ψ_i's negative lobes made the mean of a step or
//! groove of body 2's surface inside one of body 1's elements a false interference. Biorthogonality turns body 1's part into the point value u⁽¹⁾(x_i)·n_i, the
//! same trace as collocation, and makes a wear w = Σ_j w_j N_j change d_i by w_i alone. The
//! virtual work t ∫ λ d ds = Σ_i P_i d_i with P_i = p_i D_ii t: P_i/(D_ii t) is the weighted
//! mean pressure at point i (for a uniform pressure, exactly that pressure), and the contact
//! area of point i is D_ii t. On a straight edge D_ii is the Lobatto weight times the edge
//! Jacobian, the collocation weight.
//!
//! Body 2's part is a trace of the same form as a point's: Σ coef · u(dof) with
//! coef = (1/D_ii) ∫ ψ_i(x) N⁽²⁾_k(π(x)) ds, so the flexibility and everything after it are
//! unchanged.
//!
//! # The overlap
//!
//! Body 2's field is only piecewise smooth: its element ends are kinks. Each end y is projected
//! onto each element of body 1 (the parameter s where (y − x(s))·τ(s) = 0, found by bisection),
//! which splits the element into pieces where π(x) stays inside one element of body 2. Each
//! piece is integrated with p + 3 Gauss points: on straight edges π is affine, the integrand is
//! a polynomial of degree 2p (exact with p + 1 points), and the margin covers the smooth
//! non-polynomial map of arcs. On curved edges the normal n(x) turns along the element: the
//! projection follows n(x), the gap is measured along n(x), and the displacement component is
//! taken along n_i, the normal at the constraint's own point, as collocation does.

use super::Trace;
use crate::basis::shape_1d;
use crate::elasticity::ElasticBody;
use crate::loads::trace_dofs;
use crate::quadrature::{gauss_legendre, gauss_lobatto};

/// One element of body 1's contact chain: (element, local edge, traversed with t decreasing),
/// and the index of its first contact point.
pub(super) struct ChainElement {
    pub element: usize,
    pub local: usize,
    pub reversed: bool,
    pub first_point: usize,
}

/// Body 2's part of every constraint and the constraint weights.
pub(super) struct MortarTraces {
    /// Body 2's trace of each constraint (Σ coef · u(dof) per component).
    pub traces: Vec<Trace>,
    /// (1/D_ii) ∫ ψ_i g₀ ds, mm (g₀ the geometric gap along n(x) plus the initial shape).
    pub gap: Vec<f64>,
    /// D_ii = ∫ N_i ds, mm.
    pub weight: Vec<f64>,
}

/// Lagrange polynomials at `nodes` evaluated at s.
fn lagrange(nodes: &[f64], s: f64, out: &mut [f64]) {
    for (a, &sa) in nodes.iter().enumerate() {
        out[a] = nodes
            .iter()
            .enumerate()
            .filter(|&(b, _)| b != a)
            .map(|(_, &sb)| (s - sb) / (sa - sb))
            .product();
    }
}

/// The dual basis coefficients A = D M⁻¹ ((p+1)², row-major) and D of one element of body 1.
fn dual_basis(body: &ElasticBody, c: &ChainElement, nodes: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = nodes.len();
    // ds/ds is not polynomial on arcs: 2n points integrate M (degree 2p) exactly on straight
    // edges with room for the smooth Jacobian of an arc.
    let rule = gauss_legendre(2 * n);
    let (mut m, mut d) = (vec![0.0; n * n], vec![0.0; n]);
    let mut values = vec![0.0; n];
    for (&s, &w) in rule.points.iter().zip(&rule.weights) {
        let t = if c.reversed { -s } else { s };
        let (tangent, _) = body.mesh.edge_frame(c.element, c.local, t);
        let ds = w * tangent[0].hypot(tangent[1]);
        lagrange(nodes, s, &mut values);
        for a in 0..n {
            d[a] += values[a] * ds;
            for b in 0..n {
                m[a * n + b] += values[a] * values[b] * ds;
            }
        }
    }
    let inverse = invert(&m, n);
    let mut a = vec![0.0; n * n];
    for r in 0..n {
        for col in 0..n {
            a[r * n + col] = d[r] * inverse[r * n + col];
        }
    }
    (a, d)
}

/// Inverse of a small symmetric positive definite matrix (Gauss–Jordan with partial pivoting).
fn invert(m: &[f64], n: usize) -> Vec<f64> {
    let mut a = m.to_vec();
    let mut inv: Vec<f64> = (0..n * n)
        .map(|k| if k / n == k % n { 1.0 } else { 0.0 })
        .collect();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        for k in 0..n {
            a.swap(col * n + k, pivot * n + k);
            inv.swap(col * n + k, pivot * n + k);
        }
        let diag = a[col * n + col];
        for k in 0..n {
            a[col * n + k] /= diag;
            inv[col * n + k] /= diag;
        }
        for r in (0..n).filter(|&r| r != col) {
            let f = a[r * n + col];
            if f != 0.0 {
                for k in 0..n {
                    a[r * n + k] -= f * a[col * n + k];
                    inv[r * n + k] -= f * inv[col * n + k];
                }
            }
        }
    }
    inv
}

/// Parameters s ∈ (−1, 1) of body 1's element where the normal line passes through one of
/// body 2's element ends: the kinks of the integrand.
pub(super) fn break_points(
    body1: &ElasticBody,
    c: &ChainElement,
    body2: &ElasticBody,
    edges2: &[(usize, usize)],
) -> Vec<f64> {
    let ends = edges2
        .iter()
        .flat_map(|&(e, l)| [-1.0, 1.0].map(|t2| body2.mesh.point_on_edge(e, l, t2)));
    breaks_at(body1, c, ends)
}

/// Parameters s ∈ (−1, 1) of body 1's element where the normal line passes through one of
/// `points`, with −1 and 1, sorted.
fn breaks_at(
    body1: &ElasticBody,
    c: &ChainElement,
    points: impl Iterator<Item = crate::geometry::Point>,
) -> Vec<f64> {
    let point = |s: f64| {
        let t = if c.reversed { -s } else { s };
        let (tangent, _) = body1.mesh.edge_frame(c.element, c.local, t);
        (body1.mesh.point_on_edge(c.element, c.local, t), tangent)
    };
    let mut breaks = vec![-1.0, 1.0];
    for y in points {
        let side = |s: f64| {
            let (x, tan) = point(s);
            (y[0] - x[0]) * tan[0] + (y[1] - x[1]) * tan[1]
        };
        let (fa, fb) = (side(-1.0), side(1.0));
        if fa * fb >= 0.0 {
            continue;
        }
        breaks.push(crate::geometry::bisect(side, -1.0, 1.0, 60));
    }
    breaks.sort_by(f64::total_cmp);
    // Ends shared by neighbouring elements of body 2 project twice; a piece of length ~0 adds
    // nothing but cost.
    breaks.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    breaks
}

/// Body 2's mortar traces, gaps and weights for the points of body 1's `chain` (N points).
/// `shape(x)` is the initial shape added to the gap. Err(x) names a point of body 1 with no
/// partner on body 2.
pub(super) fn mortar_traces(
    body1: &ElasticBody,
    chain: &[ChainElement],
    body2: &ElasticBody,
    edges2: &[(usize, usize)],
    n_points: usize,
    shape: impl Fn(crate::geometry::Point) -> f64,
) -> Result<MortarTraces, crate::geometry::Point> {
    let p1 = body1.dofs.p;
    let p2 = body2.dofs.p;
    let nodes = gauss_lobatto(p1 + 1).points;
    let rule = gauss_legendre(p1.max(p2) + 3);
    let mut raw: Vec<Trace> = vec![Vec::new(); n_points];
    let mut gap = vec![0.0; n_points];
    let mut weight = vec![0.0; n_points];
    let (mut lag, mut psi) = (vec![0.0; p1 + 1], vec![0.0; p1 + 1]);
    let (mut values, mut derivs) = (vec![0.0; p2 + 1], vec![0.0; p2 + 1]);
    for c in chain {
        let (a, d) = dual_basis(body1, c, &nodes);
        for (k, dk) in d.iter().enumerate() {
            weight[c.first_point + k] += dk;
        }
        let breaks = break_points(body1, c, body2, edges2);
        for piece in breaks.windows(2) {
            let half = 0.5 * (piece[1] - piece[0]);
            for (&r, &w) in rule.points.iter().zip(&rule.weights) {
                let s = piece[0] + half * (r + 1.0);
                let t = if c.reversed { -s } else { s };
                let x = body1.mesh.point_on_edge(c.element, c.local, t);
                let (tangent, normal) = body1.mesh.edge_frame(c.element, c.local, t);
                let ds = w * half * tangent[0].hypot(tangent[1]);
                let (sigma, element2, local2, t2) =
                    super::locate_on_body2(body2, edges2, x, normal).ok_or(x)?;
                let g0 = sigma + shape(x);
                lagrange(&nodes, s, &mut lag);
                for (row, value) in psi.iter_mut().enumerate() {
                    *value = (0..=p1).map(|b| a[row * (p1 + 1) + b] * lag[b]).sum();
                }
                shape_1d(p2, t2, &mut values, &mut derivs);
                let dofs2 = trace_dofs(&body2.dofs, &body2.mesh, &body2.basis, element2, local2);
                for (k, &psi_k) in psi.iter().enumerate() {
                    let i = c.first_point + k;
                    gap[i] += psi_k * g0 * ds;
                    for (&(g, sign), &v) in dofs2.iter().zip(&values) {
                        if v != 0.0 {
                            raw[i].push((g, psi_k * sign * v * ds));
                        }
                    }
                }
            }
        }
    }
    let traces = raw
        .into_iter()
        .zip(&weight)
        .map(|(mut tr, &w)| {
            tr.sort_by_key(|e| e.0);
            let mut merged: Trace = Vec::new();
            for (g, coef) in tr {
                match merged.last_mut() {
                    Some(last) if last.0 == g => last.1 += coef / w,
                    _ => merged.push((g, coef / w)),
                }
            }
            merged
        })
        .collect();
    for (g, w) in gap.iter_mut().zip(&weight) {
        *g /= w;
    }
    Ok(MortarTraces {
        traces,
        gap,
        weight,
    })
}

/// Where body 2's surface departs most, on one of body 1's contact elements, from the
/// surface its contact points see (the polynomial through their gaps).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceMisfit {
    /// Where on body 1's edge [x, z], mm.
    pub x: crate::geometry::Point,
    /// g₀ there minus the polynomial through the points' gaps, mm: negative where body 2
    /// rises above what the points see (a ridge), positive where it falls away (a groove).
    pub misfit: f64,
    /// The geometric gap g₀ there, mm.
    pub gap: f64,
    /// The chord of body 1's element, mm.
    pub element_length: f64,
    /// The contact points of body 1's element (first, last).
    pub points: [usize; 2],
}

/// Where body 2's surface departs from what the constraints see: on each of body 1's
/// contact elements the largest |g₀(x) − Σ_b N_b(x) g_b| over the Gauss points of the pieces
/// between body 2's element ends (so that every feature made of body 2's elements is
/// sampled), g_b the constraints' point gaps `point_gap` (mm), g₀ including `shape` (mm) with
/// its kinks at `shape_kinks`. A ridge or groove of body 2
/// narrower than the spacing of body 1's contact points falls between them, and the
/// constraints see none of it (red team D: a ridge 1 µm high and 0.2 mm wide between two
/// points carried 16 % of a flat punch's load in a mesh that resolves it, and nothing in one
/// that does not). Elements with no misfit above 1e-12 mm are left out.
pub(super) fn surface_misfits(
    body1: &ElasticBody,
    chain: &[ChainElement],
    body2: &ElasticBody,
    edges2: &[(usize, usize)],
    point_gap: &[f64],
    (shape, shape_kinks): (
        impl Fn(crate::geometry::Point) -> f64,
        &[crate::geometry::Point],
    ),
) -> Vec<SurfaceMisfit> {
    let p1 = body1.dofs.p;
    let nodes = gauss_lobatto(p1 + 1).points;
    let rule = gauss_legendre(p1.max(body2.dofs.p) + 3);
    let mut lag = vec![0.0; p1 + 1];
    let mut misfits = Vec::new();
    for c in chain {
        let ends = [-1.0, 1.0].map(|t| body1.mesh.point_on_edge(c.element, c.local, t));
        // The worst rise and the worst fall: which one matters depends on where the bodies
        // touch, so neither may hide the other (red team H: a fall beside the zone hid a rise
        // inside it).
        let none = SurfaceMisfit {
            x: [0.0, 0.0],
            misfit: 0.0,
            gap: 0.0,
            element_length: (ends[1][0] - ends[0][0]).hypot(ends[1][1] - ends[0][1]),
            points: [c.first_point, c.first_point + p1],
        };
        let mut worst = [none, none];
        let gap_at = |s: f64| {
            let t = if c.reversed { -s } else { s };
            let x = body1.mesh.point_on_edge(c.element, c.local, t);
            let (_, normal) = body1.mesh.edge_frame(c.element, c.local, t);
            super::locate_on_body2(body2, edges2, x, normal)
                .map(|(sigma, ..)| (x, sigma + shape(x)))
        };
        // The element's own limits at its ends: a step of body 2 under a shared end point (a
        // mesh line of body 1 at the step, as advised) has one gap on each side, and the
        // point's gap is one of them; the element is judged by its own side's (1e-6 of the
        // element inside, beyond the 1e-10 within which an edge's end counts as crossed).
        let mut seen_at_nodes: Vec<f64> = point_gap[c.first_point..=c.first_point + p1].to_vec();
        for (b, s) in [(0, -1.0 + 1e-6), (p1, 1.0 - 1e-6)] {
            if let Some((_, g)) = gap_at(s) {
                seen_at_nodes[b] = g;
            }
        }
        // Body 2's element ends and the initial shape's own kinks (a crown narrower than the
        // points' spacing, red team H) split the element into smooth pieces.
        let mut breaks = break_points(body1, c, body2, edges2);
        breaks.extend(breaks_at(body1, c, shape_kinks.iter().copied()));
        breaks.sort_by(f64::total_cmp);
        breaks.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
        for piece in breaks.windows(2) {
            let half = 0.5 * (piece[1] - piece[0]);
            for &r in &rule.points {
                let s = piece[0] + half * (r + 1.0);
                let Some((x, g0)) = gap_at(s) else {
                    continue;
                };
                lagrange(&nodes, s, &mut lag);
                let seen: f64 = (0..=p1).map(|b| lag[b] * seen_at_nodes[b]).sum();
                let misfit = g0 - seen;
                let w = &mut worst[usize::from(misfit > 0.0)];
                if misfit.abs() > w.misfit.abs() {
                    w.misfit = misfit;
                    w.gap = g0;
                    w.x = x;
                }
            }
        }
        misfits.extend(worst.into_iter().filter(|w| w.misfit.abs() > 1e-12));
    }
    misfits
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lagrange_is_a_partition_of_unity_and_interpolates() {
        let nodes = gauss_lobatto(7).points;
        let mut v = vec![0.0; 7];
        for (a, &s) in nodes.iter().enumerate() {
            lagrange(&nodes, s, &mut v);
            for (b, vb) in v.iter().enumerate() {
                assert!((vb - if a == b { 1.0 } else { 0.0 }).abs() < 1e-13);
            }
        }
        lagrange(&nodes, 0.123, &mut v);
        assert!((v.iter().sum::<f64>() - 1.0).abs() < 1e-13);
    }

    #[test]
    fn inverse_of_a_mass_matrix_times_itself_is_the_identity() {
        let n = 5;
        let m: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                1.0 / (1.0 + i as f64 + j as f64) + if i == j { 1.0 } else { 0.0 }
            })
            .collect();
        let inv = invert(&m, n);
        for i in 0..n {
            for j in 0..n {
                let s: f64 = (0..n).map(|k| m[i * n + k] * inv[k * n + j]).sum();
                // Condition number < 10: round-off of a few ε.
                assert!((s - if i == j { 1.0 } else { 0.0 }).abs() < 1e-13);
            }
        }
    }
}
