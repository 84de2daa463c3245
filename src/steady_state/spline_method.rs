//! The spline method of the paper's §6.2 (eq. 41–48): the shape is a cubic spline
//! through 17 points along the contact (the paper's, x = 1070 … 1130 mm for Example 1, zero at
//! mid contact), started from the averaged monotonic shape; a polynomial iteration adds
//! Δ·m·|x − x_mid|^q/(L/2)^q (eq. 44, q = 9, m = 1 … 7; Δ = 0.0004 mm on Example 1 and in
//! proportion to the bodies' deflection elsewhere), and Newton steps on the 16 free ordinates
//! drive δw to zero at 16 zones (eq. 45–48). The sensitivities ∂δw/∂a_j are forward
//! differences (eq. 46, Δs = 2e-7 mm on Example 1, a hundredth of the paper's, and in
//! proportion elsewhere) or exact: at fixed active sets the contact forces are linear in the
//! gap, so one solve with the active-set matrix per half cycle gives all 16 columns. The paper does not name the spline's end conditions; not-a-knot ends follow
//! the steep steady shape at the punch corners (a natural spline, with zero curvature there,
//! left 8–9 % of the peak pressure at the corner points against 3–4 % with not-a-knot).
//! Those 3–4 % sit at x_cl and x_cr, where one half cycle's pressure rises steeply from zero
//! and the steady shape's curvature changes abruptly: the 17 points' resolution. `MethodSettings::spline_refinement`
//! bisects every interval between them (33 points: 0.03–0.05 %, docs/validation.md).

use crate::complementarity::Direction;
use crate::paper_steady::{Evaluator, IterationRecord, MethodError, MethodSettings, Sensitivities};
use faer::linalg::solvers::Solve;
use faer::Mat;

/// The paper's spline points (§6.2.1) as fractions of the contact length L = 60 mm: the
/// printed x = 1071.5 … 1130 mm, with the illegible point 7 and the unprinted points 1–2 taken
/// as the mirror images of points 11, 16 and 17. Point 9 (the middle) is held at zero.
pub const KNOTS: [f64; 17] = [
    0.0, 0.75, 1.5, 3.63, 5.75, 7.88, 10.0, 20.0, 30.0, 43.63, 50.0, 52.13, 54.25, 56.38, 58.5,
    59.25, 60.0,
];
/// eq. 44: exponent q and steps m = 1 … 7.
const POLY_Q: i32 = 9;
const POLY_STEPS: usize = 7;
/// eq. 44's step Δ = 0.0004 mm and eq. 46's Δs = 0.00002 mm are the paper's for Example 1
/// with the punch sliding vertically (`punch-a`, the case of its §6.2 and of our Fig. 19–22).
/// There the contact surfaces bend by this much (mm, range over the contact) under the mean
/// steady pressure p̄ = 16.666 MPa: with a uniform p_Σ that is also the rise of the averaged
/// start (eq. 39, mean reading) from the middle to the corners, for which the paper prints
/// 1.8280e-3 mm (docs/validation.md, "What the paper's printed ordinates are"). Both steps are
/// taken in proportion to the problem's own deflection (`deflection_scale`): a stiffer
/// body, another load or other units scale the steady shape, and fixed millimetres are then
/// far too large or too small (E × 1000 on `punch-b40`: Δ was 135 times the start's rise and
/// the method failed; a tenth of the load gave 8.6 % instead of 3.6 %).
pub const EXAMPLE_1_DEFLECTION: f64 = 0.001_973_0;
/// The paper's Δ of eq. 44 (mm) on Example 1.
const POLY_DELTA_EXAMPLE_1: f64 = 0.0004;
/// The paper's Δs of eq. 46 (mm) on Example 1.
pub const FD_STEP_EXAMPLE_1: f64 = 0.00002;
/// The share of the paper's Δs taken. At the paper's own (1 % of Example 1's deflection) the
/// forward differences were too inexact near the end: `punch-b40` with 33 spline points
/// stopped at 1.77 % of the peak from the exact state where the exact sensitivities reach
/// 0.05 %; at a tenth, punch-a with a 257-point contact and punch-b40 at p = 10 still ended
/// 2.4 and 3.2 % of the peak from where the exact sensitivities end (red team 28). With a
/// hundredth, all of the 18 shipped cases and red team 28's 30 (17, 33 and 65 spline points,
/// 65–257 contact points, p = 8–12) end where the exact sensitivities do, within 3e-6 of
/// the peak and mostly 1e-10; at a thousandth round-off begins to show (3e-9).
const FD_STEP_SHARE: f64 = 0.01;
/// Zones at which δw is driven to zero (eq. 48).
const ZONES: usize = 16;
/// Drive δw to zero in the least-squares sense at every contact point instead of at the 16
/// zone means: the zone means hide the corner points, where a spline shape leaves pressure
/// peaks (measured: zone residual 1e-9 of the wear with the corner at 4.8 p̃).
const POINTWISE: bool = true;
/// Newton steps at most.
const NEWTON_STEPS: usize = 20;

/// Values at `xs` of the not-a-knot cubic spline through (`xk`, `yk`): the third derivative is
/// continuous across the second and the last-but-one knot, so the end intervals keep the
/// curvature the data have there (a natural spline forces it to zero).
pub fn not_a_knot_spline(xk: &[f64], yk: &[f64], xs: &[f64]) -> Vec<f64> {
    let n = xk.len();
    let h: Vec<f64> = (0..n - 1).map(|i| xk[i + 1] - xk[i]).collect();
    let mut a = Mat::<f64>::zeros(n, n);
    let mut r = Mat::<f64>::zeros(n, 1);
    for i in 1..n - 1 {
        a[(i, i - 1)] = h[i - 1];
        a[(i, i)] = 2.0 * (h[i - 1] + h[i]);
        a[(i, i + 1)] = h[i];
        r[(i, 0)] = 6.0 * ((yk[i + 1] - yk[i]) / h[i] - (yk[i] - yk[i - 1]) / h[i - 1]);
    }
    // (M₁ − M₀)/h₀ = (M₂ − M₁)/h₁ and the same at the right end.
    a[(0, 0)] = -1.0 / h[0];
    a[(0, 1)] = 1.0 / h[0] + 1.0 / h[1];
    a[(0, 2)] = -1.0 / h[1];
    a[(n - 1, n - 3)] = -1.0 / h[n - 3];
    a[(n - 1, n - 2)] = 1.0 / h[n - 3] + 1.0 / h[n - 2];
    a[(n - 1, n - 1)] = -1.0 / h[n - 2];
    let m = a.partial_piv_lu().solve(&r);
    xs.iter()
        .map(|&x| {
            let k = (0..n - 1).find(|&k| x <= xk[k + 1]).unwrap_or(n - 2);
            let (p, q) = (xk[k + 1] - x, x - xk[k]);
            m[(k, 0)] * p.powi(3) / (6.0 * h[k])
                + m[(k + 1, 0)] * q.powi(3) / (6.0 * h[k])
                + (yk[k] / h[k] - m[(k, 0)] * h[k] / 6.0) * p
                + (yk[k + 1] / h[k] - m[(k + 1, 0)] * h[k] / 6.0) * q
        })
        .collect()
}

/// Value at `x` of the profile `v` at the points `xs` (rising): Lagrange through the 6 nearest.
pub fn interpolate(xs: &[f64], v: &[f64], x: f64) -> f64 {
    let mut idx: Vec<usize> = (0..xs.len()).collect();
    idx.sort_by(|&a, &b| (xs[a] - x).abs().total_cmp(&(xs[b] - x).abs()));
    let near = &idx[..6.min(xs.len())];
    near.iter()
        .map(|&i| {
            let l: f64 = near
                .iter()
                .filter(|&&j| j != i)
                .map(|&j| (x - xs[j]) / (xs[i] - xs[j]))
                .product();
            l * v[i]
        })
        .sum()
}

/// What [`spline`] returns: the final shape at the contact points, the history, whether it
/// ended (see [`spline`]) and the shape after every polynomial and Newton step.
pub(crate) struct SplineRun {
    pub shape: Vec<f64>,
    pub history: Vec<IterationRecord>,
    pub converged: bool,
    pub iterates: Vec<(usize, Vec<f64>)>,
}

/// The spline's geometry on one contact: knot x, the basis (contact point i, free ordinate j)
/// and the zone of each contact point.
struct Spline {
    knots: Vec<f64>,
    /// n × (knots − 1): shape_i = Σ_j basis[i][j] a_j over the free ordinates.
    basis: Vec<Vec<f64>>,
    zone: Vec<usize>,
}

/// The paper's spline points (mm from the left end of its 60 mm contact; scaled to the actual
/// contact length by the method) with every interval bisected `refinement` times: 17, 33, 65, …
/// points, the middle one (held at zero) staying the middle.
pub fn knot_positions(refinement: u32) -> Vec<f64> {
    let mut k = KNOTS.to_vec();
    for _ in 0..refinement {
        let mut finer = Vec::with_capacity(2 * k.len() - 1);
        for w in k.windows(2) {
            finer.push(w[0]);
            finer.push(0.5 * (w[0] + w[1]));
        }
        finer.push(k[k.len() - 1]);
        k = finer;
    }
    k
}

impl Spline {
    fn new(xs: &[f64], refinement: u32) -> Spline {
        let (lo, hi) = (xs[0], xs[xs.len() - 1]);
        let fractions = knot_positions(refinement);
        let knots: Vec<f64> = fractions
            .iter()
            .map(|f| lo + (hi - lo) * f / 60.0)
            .collect();
        let mid = knots.len() / 2;
        let free: Vec<usize> = (0..knots.len()).filter(|&k| k != mid).collect();
        let columns: Vec<Vec<f64>> = free
            .iter()
            .map(|&k| {
                let mut unit = vec![0.0; knots.len()];
                unit[k] = 1.0;
                not_a_knot_spline(&knots, &unit, xs)
            })
            .collect();
        let basis = (0..xs.len())
            .map(|i| columns.iter().map(|c| c[i]).collect())
            .collect();
        let zone = xs
            .iter()
            .map(|x| (((x - lo) / (hi - lo) * ZONES as f64) as usize).min(ZONES - 1))
            .collect();
        Spline { knots, basis, zone }
    }
    fn shape(&self, a: &[f64]) -> Vec<f64> {
        self.basis
            .iter()
            .map(|row| row.iter().zip(a).map(|(b, x)| b * x).sum())
            .collect()
    }
    /// Area-weighted mean of `v` over each zone, or, with `pointwise`, √area_i · v_i at every
    /// contact point (the least-squares form of eq. 48 over all points).
    fn zones(&self, v: &[f64], area: &[f64]) -> Vec<f64> {
        if POINTWISE {
            return v.iter().zip(area).map(|(x, a)| x * a.sqrt()).collect();
        }
        let (mut sum, mut weight) = (vec![0.0; ZONES], vec![0.0; ZONES]);
        for i in 0..v.len() {
            sum[self.zone[i]] += area[i] * v[i];
            weight[self.zone[i]] += area[i];
        }
        sum.iter()
            .zip(&weight)
            .map(|(s, w)| if *w > 0.0 { s / w } else { 0.0 })
            .collect()
    }
}

/// δw of eq. 40 before its minimum is taken off (the period's wear less its rigid part) at
/// the 16 zones, and the record, at ordinates `a`.
fn zone_residual(
    problem: &mut Evaluator,
    spline: &Spline,
    a: &[f64],
    iteration: usize,
) -> Result<(Vec<f64>, IterationRecord), MethodError> {
    let h = problem.halves(&spline.shape(a))?;
    let r = problem.without_rigid(&problem.period_wear(&h));
    Ok((
        spline.zones(&r, &problem.area),
        problem.record(iteration, &h),
    ))
}

/// The largest `MethodSettings::spline_refinement` r that `points` contact points determine:
/// no more spline points (16 · 2^r + 1) than contact points, and r ≤ 16 in any case (memory);
/// 0 when even the paper's 17 points are more (the paper's spline is used regardless).
pub fn max_refinement(points: usize) -> u32 {
    (0..=16u32)
        .rev()
        .find(|&r| (16usize << r) < points)
        .unwrap_or(0)
}

/// The spline method from the averaged shape; returns the shape at the contact points, the
/// history (m = 1 … 7 of the polynomial iteration, then the Newton steps) and whether it
/// ended: the eq. 49 residual at the tolerance, or a stationary point of the least squares
/// (the best shape the spline can represent).
pub(crate) fn spline(
    problem: &mut Evaluator,
    averaged: &[f64],
    settings: MethodSettings,
) -> Result<SplineRun, MethodError> {
    let xs: Vec<f64> = problem.contact.points.x.iter().map(|p| p[0]).collect();
    // More spline points than contact points cannot be determined by δw at the points (and a
    // large refinement would exhaust memory): cap the refinement at the contact's resolution.
    let refinement = settings.spline_refinement.min(max_refinement(xs.len()));
    let sp = Spline::new(&xs, refinement);
    let (last, mid_knot) = (sp.knots.len() - 1, sp.knots.len() / 2);
    let free: Vec<usize> = (0..sp.knots.len()).filter(|&k| k != mid_knot).collect();
    let start: Vec<f64> = free
        .iter()
        .map(|&k| interpolate(&xs, averaged, sp.knots[k]))
        .collect();
    let (mid, half) = (sp.knots[mid_knot], 0.5 * (sp.knots[last] - sp.knots[0]));
    let scale = deflection_scale(problem);
    let poly_delta = POLY_DELTA_EXAMPLE_1 * scale;
    let fd_step = settings
        .fd_step
        .unwrap_or(FD_STEP_EXAMPLE_1 * FD_STEP_SHARE * scale);
    // Polynomial iteration (eq. 44): keep the m with the smallest I_δw · max δw, the start
    // (m = 0) included. Without friction the averaged start is the steady state itself, and
    // every m ≥ 1 lifted the corners off, beyond Newton's reach (red team 28: 1.09 % off on
    // punch-a, refused on a rigid punch on deep layers).
    let mut history = Vec::new();
    let mut iterates = vec![(0, sp.shape(&start))];
    let (_, record) = zone_residual(problem, &sp, &start, 0)?;
    let mut best = (record.i_delta_w * record.max_delta_w, start.clone());
    for m in 1..=POLY_STEPS {
        let a: Vec<f64> = free
            .iter()
            .zip(&start)
            .map(|(&k, s)| {
                s + poly_delta * m as f64 * ((sp.knots[k] - mid).abs() / half).powi(POLY_Q)
            })
            .collect();
        let (_, record) = zone_residual(problem, &sp, &a, m)?;
        history.push(record);
        iterates.push((m, sp.shape(&a)));
        let objective = record.i_delta_w * record.max_delta_w;
        if objective < best.0 {
            best = (objective, a);
        }
    }
    let mut a = best.1;
    let (mut r, mut record) = zone_residual(problem, &sp, &a, POLY_STEPS + 1)?;
    history.push(record);
    let norm = |r: &[f64]| r.iter().map(|v| v * v).sum::<f64>();
    let mut damping = None;
    let mut converged = record.residual <= settings.tolerance;
    let mut step = 1;
    while !converged && step <= NEWTON_STEPS.min(settings.max_iterations) {
        let jac = match settings.sensitivities {
            Sensitivities::FiniteDifference => fd_jacobian(problem, &sp, &a, &r, fd_step)?,
            Sensitivities::Exact => exact_jacobian(problem, &sp, &a)?,
        };
        // Levenberg–Marquardt on eq. 48: the full Newton step of the paper leaves the region
        // where the active sets of the linearisation hold (near-singular zone Jacobian); the
        // damping is cut after a success and raised after a failure.
        let trace: f64 = jac.iter().flatten().map(|v| v * v).sum();
        let mut lambda: f64 = damping.unwrap_or(1e-8 * trace);
        let mut accepted = false;
        let mut stalled = false;
        for _ in 0..30 {
            let delta = least_squares(&jac, &r, lambda);
            let trial: Vec<f64> = a.iter().zip(&delta).map(|(x, d)| x + d).collect();
            let (r_trial, rec_trial) = zone_residual(problem, &sp, &trial, POLY_STEPS + 1 + step)?;
            if norm(&r_trial) < norm(&r) {
                // A step that gains less than 1e-6 of the objective is round-off at the
                // stationary point: take it and stop.
                stalled = norm(&r_trial) > (1.0 - 1e-6) * norm(&r);
                (a, r, record) = (trial, r_trial, rec_trial);
                damping = Some(lambda / 3.0);
                accepted = true;
                break;
            }
            lambda *= 4.0;
        }
        if !accepted {
            // No damped step lowers the objective: a stationary point of the least-squares
            // problem (41) within the spline's 16 ordinates, the method's own end. Its eq. 49
            // residual is the spline's representation limit, not a tolerance met.
            converged = true;
            break;
        }
        history.push(record);
        iterates.push((record.iteration, sp.shape(&a)));
        converged = stalled || record.residual <= settings.tolerance;
        step += 1;
    }
    Ok(SplineRun {
        shape: sp.shape(&a),
        history,
        converged,
        iterates,
    })
}

/// How far the contact surfaces bend under the mean steady pressure, as a multiple of
/// Example 1's ([`EXAMPLE_1_DEFLECTION`]): the factor on the paper's Δ and Δs. The range over
/// the contact of A_nn · (p̄ area), p̄ = mean of p_Σ/2: it scales with the load and 1/E
/// exactly, converges with the mesh, and is the same for every load distribution of the
/// same total on the same bodies (Example 1's variants keep the paper's millimetres). Where
/// the bodies do not bend under a uniform pressure, only compress (a range at round-off of
/// the deflection itself: a strip as wide as the punch with ν = 0, red team 28), only
/// friction shapes the steady state, and the bending under the same pressure with its
/// friction in one half cycle is taken instead; without either, the paper's millimetres.
fn deflection_scale(problem: &Evaluator) -> f64 {
    let n = problem.area.len();
    let total_area: f64 = problem.area.iter().sum();
    let force: f64 = problem
        .p_sigma
        .iter()
        .zip(&problem.area)
        .map(|(p, a)| p * a)
        .sum();
    let mean = 0.5 * force / total_area;
    let range_under = |flexibility: &[f64]| {
        let deflection: Vec<f64> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| flexibility[i * n + j] * mean * problem.area[j])
                    .sum()
            })
            .collect();
        let (lo, hi) = deflection
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &d| {
                (l.min(d), h.max(d))
            });
        let (range, size) = (hi - lo, hi.abs().max(lo.abs()));
        (range > 1e-6 * size && range.is_finite()).then_some(range)
    };
    range_under(&problem.contact.a_nn)
        .or_else(|| range_under(&problem.contact.gap_matrix(1.0)))
        .map_or(1.0, |range| range / EXAMPLE_1_DEFLECTION)
}

/// ∂(zone δw)/∂a_j by forward differences (eq. 46): 16 × 16, row-major.
fn fd_jacobian(
    problem: &mut Evaluator,
    sp: &Spline,
    a: &[f64],
    r: &[f64],
    step: f64,
) -> Result<Vec<Vec<f64>>, MethodError> {
    let mut jac = vec![vec![0.0; a.len()]; r.len()];
    for j in 0..a.len() {
        let mut shifted = a.to_vec();
        shifted[j] += step;
        let (rj, _) = zone_residual(problem, sp, &shifted, 0)?;
        for z in 0..r.len() {
            jac[z][j] = (rj[z] - r[z]) / step;
        }
    }
    Ok(jac)
}

/// ∂(zone δw)/∂a_j exactly at the current active sets: per half cycle, the forces on the
/// active points and the plate motion solve [A_aa R_a; E_a 0] [P; λ] = [−g_a; −L], so
/// ∂P/∂a = −(first block of the inverse) · basis_a.
fn exact_jacobian(
    problem: &mut Evaluator,
    sp: &Spline,
    a: &[f64],
) -> Result<Vec<Vec<f64>>, MethodError> {
    let contact = problem.contact;
    let (n, m, free) = (contact.len(), contact.rigid_modes.len(), a.len());
    let shape = sp.shape(a);
    let mut dwear = vec![vec![0.0; free]; n];
    let c: f64 = problem.terms.iter().map(|t| t.0).sum();
    for direction in [Direction::Plus, Direction::Minus] {
        let (p, _) = problem.half(&shape, direction)?;
        let peak = p.iter().cloned().fold(0.0, f64::max);
        let active: Vec<usize> = (0..n).filter(|&i| p[i] > 1e-12 * peak).collect();
        let na = active.len();
        let s = direction.sign();
        let gap = contact.gap_matrix(s);
        let eq = contact.equilibrium_matrix(s);
        let mat = Mat::<f64>::from_fn(na + m, na + m, |r, col| match (r < na, col < na) {
            (true, true) => gap[active[r] * n + active[col]],
            (true, false) => problem.rigid[active[r] * m + (col - na)],
            (false, true) => eq[(r - na) * n + active[col]],
            (false, false) => 0.0,
        });
        let rhs = Mat::<f64>::from_fn(na + m, free, |r, j| {
            if r < na {
                -sp.basis[active[r]][j]
            } else {
                0.0
            }
        });
        let x = mat.partial_piv_lu().solve(&rhs);
        for (r, &i) in active.iter().enumerate() {
            for j in 0..free {
                dwear[i][j] += c * x[(r, j)] / problem.area[i];
            }
        }
    }
    let rows = if POINTWISE { n } else { ZONES };
    let mut jac = vec![vec![0.0; free]; rows];
    for j in 0..free {
        let column: Vec<f64> = (0..n).map(|i| dwear[i][j]).collect();
        let z = sp.zones(&problem.without_rigid(&column), &problem.area);
        for (zone, v) in z.iter().enumerate() {
            jac[zone][j] = *v;
        }
    }
    Ok(jac)
}

/// Δa minimising |J Δa + r|² + λ|Δa|²: the zone residuals carry the rigid wear's constraint
/// (their weighted sum vanishes), so J is rank-deficient and needs λ > 0.
fn least_squares(jac: &[Vec<f64>], r: &[f64], lambda: f64) -> Vec<f64> {
    let cols = jac[0].len();
    let jtj = Mat::<f64>::from_fn(cols, cols, |i, j| {
        jac.iter().map(|row| row[i] * row[j]).sum()
    });
    let reg = Mat::<f64>::from_fn(cols, cols, |i, j| {
        jtj[(i, j)] + if i == j { lambda } else { 0.0 }
    });
    let rhs = Mat::<f64>::from_fn(cols, 1, |i, _| {
        -jac.iter().zip(r).map(|(row, v)| row[i] * v).sum::<f64>()
    });
    let x = reg.partial_piv_lu().solve(&rhs);
    (0..cols).map(|i| x[(i, 0)]).collect()
}

#[cfg(test)]
mod tests {
    use super::{deflection_scale, not_a_knot_spline};
    use crate::contact::CondensedContact;
    use crate::paper_steady::Evaluator;
    use crate::problem::Problem;

    #[test]
    fn the_papers_steps_are_kept_on_example_1_and_its_load_variants() {
        // The reference deflection is punch-a's, so the scale there is 1 up to the 5 digits
        // of the constant; the pinned punch and the eccentric loads of the same 10 kN on the
        // same bodies bend alike (p̄ is the same), so they keep the paper's millimetres too.
        for name in ["punch-a", "punch-b40", "punch-b40-variant3"] {
            let text = crate::examples::example(name).unwrap();
            let problem = Problem::from_toml(text, name).unwrap();
            let (contact, _, _) = CondensedContact::build(&problem).unwrap();
            let terms = crate::wear::WearIntegrator::new(problem.spec.wear.as_ref().unwrap())
                .unwrap()
                .half_period_wear();
            let evaluator = Evaluator::new(&contact, &terms).unwrap();
            let scale = deflection_scale(&evaluator);
            assert!((scale - 1.0).abs() < 1e-4, "{name}: {scale}");
        }
    }

    #[test]
    fn not_a_knot_spline_reproduces_cubics_and_interpolates() {
        // A not-a-knot spline is exact for any cubic (the end conditions hold for it), on
        // uneven knots too; round-off of a 5 × 5 solve.
        let xk = [0.0, 0.7, 2.0, 3.5, 5.0];
        let cubic = |x: f64| 3.0 - 2.0 * x + 0.5 * x * x - 0.25 * x * x * x;
        let y: Vec<f64> = xk.iter().map(|&x| cubic(x)).collect();
        let xs = [0.1, 1.3, 2.9, 4.99];
        for (x, v) in xs.iter().zip(not_a_knot_spline(&xk, &y, &xs)) {
            assert!((v - cubic(*x)).abs() < 1e-12, "{x}: {v}");
        }
        let y = [1.0, -2.0, 0.5, 4.0, 3.0];
        for (k, v) in not_a_knot_spline(&xk, &y, &xk).iter().enumerate() {
            assert!((v - y[k]).abs() < 1e-12);
        }
    }
}
