//! The step loop of [`WearIntegrator::run`]: the paper's half-period scheme (implicit,
//! iterated to criterion eq. 27, with Aitken relaxation), plain explicit sub-stepping for
//! checks, the histories, and the shift of the shape to zero at a chosen point.

use super::{Snapshot, StepRecord, WearHistory, WearIntegrator};
use crate::complementarity::{ContactSolution, ContactSolver, Direction, SolveInfo, Status};
use crate::contact::{CondensedContact, ContactPoints};
use crate::kinematics::{factor, partial_sliding};

impl WearIntegrator {
    /// Run the integration from shape `initial` (mm), reporting probes at `probe_points`
    /// (indices into the contact points). `on_step` sees every record as it is made.
    pub fn run(
        &self,
        solver: &mut ContactSolver,
        contact: &CondensedContact,
        initial: &[f64],
        probe_points: &[usize],
        mut on_step: impl FnMut(&StepRecord),
    ) -> WearHistory {
        let points = &contact.points;
        let n = points.x.len();
        let mut ws = Workspace::new(n);
        ws.weight.copy_from_slice(&points.weight);
        ws.sliding = self.laws.iter().map(|l| self.sliding(l.a)).collect();
        let mut shape = initial.to_vec();
        ws.last_shape.copy_from_slice(&shape);
        let mut cycle_wear = vec![0.0; n];
        let mut hist = WearHistory {
            steps: Vec::with_capacity(self.spec.steps),
            snapshots: vec![],
            p_plus: vec![0.0; n],
            p_minus: vec![0.0; n],
            shape: vec![],
            solves: 0,
            unconverged_steps: 0,
            failed_solves: 0,
            stopped_at: None,
        };
        let monotonic = self.is_monotonic();
        let zero_at = self
            .spec
            .shape_zero_at
            .map(|x0| interpolation_weights(points, x0));
        let mut half_periods = 0;
        for step in 1..=self.spec.steps {
            // Odd steps slide in the first direction (contact.direction), even ones back.
            let first_half = monotonic || step % 2 == 1;
            let direction = if first_half {
                self.first_direction
            } else {
                self.first_direction.reversed()
            };
            let k = factor(&self.schedule, step);
            half_periods += k;
            let mut count = SolveCount::default();
            let (iterations, criterion) = if self.spec.substeps > 0 {
                let iterations =
                    self.explicit_step(solver, &mut shape, direction, k, &mut ws, &mut count);
                (iterations, 0.0)
            } else {
                let (iterations, criterion, converged) =
                    self.implicit_step(solver, &mut shape, direction, k, &mut ws, &mut count);
                hist.unconverged_steps += usize::from(!converged);
                (iterations, criterion)
            };
            hist.solves += count.solves;
            hist.failed_solves += count.failed;
            if !(shape.iter().all(|g| g.is_finite()) && ws.increment.iter().all(|w| w.is_finite()))
            {
                // Wear too large for the arithmetic (β̃ or the load far out of range): stop with
                // what was computed so far rather than write infinities.
                hist.stopped_at = Some(step);
                shape.copy_from_slice(&ws.last_shape);
                break;
            }
            ws.last_shape.copy_from_slice(&shape);
            let (pressure, increment) = (&ws.solution.pressure, &ws.increment);
            let dissipation: f64 = (0..n)
                .map(|i| pressure[i] * increment[i] * points.weight[i])
                .sum::<f64>()
                * contact.thickness;
            if direction == Direction::Plus || monotonic {
                hist.p_plus.copy_from_slice(pressure);
            } else {
                hist.p_minus.copy_from_slice(pressure);
            }
            let mut delta_w = 0.0;
            if first_half && !monotonic {
                cycle_wear.copy_from_slice(increment);
            } else {
                // A full cycle ends here (under monotonic sliding every step is one).
                for i in 0..n {
                    cycle_wear[i] = increment[i] + if monotonic { 0.0 } else { cycle_wear[i] };
                }
                let min = cycle_wear.iter().cloned().fold(f64::INFINITY, f64::min);
                delta_w = cycle_wear.iter().map(|w| w - min).fold(0.0, f64::max);
                if let Some(weights) = &zero_at {
                    shift_to_zero(&mut shape, weights, points);
                }
            }
            let record = StepRecord {
                step,
                half_period: half_periods,
                direction: direction.symbol(),
                k,
                iterations,
                solves: count.solves,
                criterion,
                dissipation,
                probes: probe_points.iter().map(|&i| pressure[i]).collect(),
                delta_w,
            };
            on_step(&record);
            hist.steps.push(record);
            if self.spec.record.contains(&step) {
                hist.snapshots.push(Snapshot {
                    step,
                    half_period: half_periods,
                    direction: direction.symbol(),
                    pressure: pressure.clone(),
                    shape: shape.clone(),
                });
            }
        }
        hist.shape = shape;
        hist
    }

    /// One step of plain explicit stepping: `substeps` sub-steps per half period, each with the
    /// pressure of the shape at its start. Leaves in `ws.increment` the wear of one half period
    /// (the applied total over k) and in `ws.solution` the contact solution at the new shape.
    /// Returns the number of sub-steps.
    fn explicit_step(
        &self,
        solver: &mut ContactSolver,
        shape: &mut [f64],
        direction: Direction,
        k: usize,
        ws: &mut Workspace,
        count: &mut SolveCount,
    ) -> usize {
        let m = self.spec.substeps;
        let monotonic = self.is_monotonic();
        // `new_increment` sums what the sub-steps really wore.
        ws.new_increment.iter_mut().for_each(|w| *w = 0.0);
        for sub in 0..m {
            count.track(solver.solve_into(shape, direction, &mut ws.solution));
            let part: Vec<f64> = self
                .laws
                .iter()
                .map(|l| {
                    if monotonic {
                        self.sliding(l.a) / m as f64
                    } else {
                        let start = std::f64::consts::PI * sub as f64 / m as f64;
                        let end = std::f64::consts::PI * (sub + 1) as f64 / m as f64;
                        partial_sliding(self.spec.amplitude, self.spec.omega, l.a, [start, end])
                    }
                })
                .collect();
            self.wear_increment(&ws.solution.pressure, &part, k as f64, &mut ws.increment);
            for ((g, total), w) in shape
                .iter_mut()
                .zip(ws.new_increment.iter_mut())
                .zip(&ws.increment)
            {
                *g += w;
                *total += w;
            }
        }
        count.track(solver.solve_into(shape, direction, &mut ws.solution));
        for i in 0..shape.len() {
            ws.increment[i] = ws.new_increment[i] / k as f64;
        }
        m
    }

    /// One step of the paper's half-period scheme (eq. 24–30): the wear of k half periods at
    /// the pressure of the end of the step, iterated until the criterion holds. Leaves in
    /// `ws.increment` the wear of one half period and in `ws.solution` the contact solution
    /// it was computed from. Returns (iterations, last criterion in %, converged).
    fn implicit_step(
        &self,
        solver: &mut ContactSolver,
        shape: &mut [f64],
        direction: Direction,
        k: usize,
        ws: &mut Workspace,
        count: &mut SolveCount,
    ) -> (usize, f64, bool) {
        let n = shape.len();
        let sliding = &ws.sliding;
        count.track(solver.solve_into(shape, direction, &mut ws.solution));
        self.wear_increment(&ws.solution.pressure, sliding, k as f64, &mut ws.increment);
        let (mut iterations, mut criterion, mut converged) = (0, 0.0, false);
        // The fixed-point iteration is a contraction only while k·∂W/∂p times the contact
        // compliance stays below one, which large k or b > 1 break. Aitken's dynamic relaxation
        // (Irons–Tuck) picks the step from the last two residuals r = W(p(g + Δw)) − Δw; the
        // first step is the plain one.
        let mut relaxation = 1.0;
        for iteration in 0..self.spec.max_iterations {
            iterations += 1;
            for ((t, g), w) in ws.trial.iter_mut().zip(shape.iter()).zip(&ws.increment) {
                *t = g + w;
            }
            count.track(solver.solve_into(&ws.trial, direction, &mut ws.solution));
            self.wear_increment(
                &ws.solution.pressure,
                &ws.sliding,
                k as f64,
                &mut ws.new_increment,
            );
            criterion = self.criterion(shape, ws);
            if criterion <= self.spec.tolerance {
                converged = true;
                break;
            }
            let (mut dot, mut norm) = (0.0, 0.0);
            for i in 0..n {
                let r = ws.new_increment[i] - ws.increment[i];
                let dr = r - ws.residual[i];
                dot += ws.residual[i] * dr;
                norm += dr * dr;
                ws.residual[i] = r;
            }
            if iteration > 0 && norm > 0.0 {
                // Bounded so that a noisy estimate can neither stall nor overshoot.
                relaxation = (-relaxation * dot / norm).clamp(1e-3, 2.0);
            }
            for i in 0..n {
                ws.increment[i] += relaxation * ws.residual[i];
            }
        }
        // Keep the last evaluated wear (converged or not): a relaxed iterate was never checked
        // and, with a relaxation factor above one, could even be negative.
        std::mem::swap(&mut ws.increment, &mut ws.new_increment);
        for (g, w) in shape.iter_mut().zip(ws.increment.iter_mut()) {
            *g += *w;
            // Report one half period's wear, not k of them.
            *w /= k as f64;
        }
        (iterations, criterion, converged)
    }

    /// The implicit criterion in percent between the trial increment `ws.increment` and the
    /// wear `ws.new_increment` it produced: eq. 27 (the integral of the trial gap) or the
    /// largest pointwise change.
    fn criterion(&self, shape: &[f64], ws: &Workspace) -> f64 {
        if self.spec.criterion == "pointwise" {
            let largest = ws.new_increment.iter().fold(0.0f64, |m, w| m.max(w.abs()));
            let change = ws
                .new_increment
                .iter()
                .zip(&ws.increment)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            100.0 * change / largest.max(f64::MIN_POSITIVE)
        } else {
            let integral = |g: &[f64]| g.iter().zip(&ws.weight).map(|(a, w)| a * w).sum::<f64>();
            let before = integral(&ws.trial);
            let after = integral(shape) + integral(&ws.new_increment);
            100.0 * (after - before).abs() / before.abs().max(f64::MIN_POSITIVE)
        }
    }
}

/// Buffers of one run, sized once so that the step loop does not allocate.
struct Workspace {
    /// ∫|v|ᵃ dτ of one half period for each wear law.
    sliding: Vec<f64>,
    /// Lobatto weight × edge Jacobian of each contact point (mm), for eq. 27's integral.
    weight: Vec<f64>,
    trial: Vec<f64>,
    increment: Vec<f64>,
    new_increment: Vec<f64>,
    residual: Vec<f64>,
    /// The shape after the last step whose wear was finite.
    last_shape: Vec<f64>,
    solution: ContactSolution,
}

impl Workspace {
    fn new(n: usize) -> Workspace {
        Workspace {
            sliding: vec![],
            weight: vec![0.0; n],
            trial: vec![0.0; n],
            increment: vec![0.0; n],
            new_increment: vec![0.0; n],
            residual: vec![0.0; n],
            last_shape: vec![0.0; n],
            solution: ContactSolution::default(),
        }
    }
}

/// Contact solves of one step, and how many of them failed.
#[derive(Default)]
struct SolveCount {
    solves: usize,
    failed: usize,
}

impl SolveCount {
    fn track(&mut self, info: SolveInfo) {
        self.solves += 1;
        self.failed += usize::from(info.status == Status::Failed);
    }
}

/// Shift `shape` to zero at the interpolation point `weights` by a vertical rigid translation
/// of body 1. It changes the gap by n_c·(−e_z) at each point (1 under a flat punch, cos α on
/// an arc) and so leaves every pressure unchanged: the plate's λ_F takes it up.
fn shift_to_zero(shape: &mut [f64], weights: &[(usize, f64)], points: &ContactPoints) {
    let mode = |i: usize| -points.normal[i][1];
    let at_ref: f64 = weights.iter().map(|&(i, w)| w * mode(i)).sum();
    if at_ref.abs() > 1e-12 {
        let offset = weights.iter().map(|&(i, w)| w * shape[i]).sum::<f64>() / at_ref;
        for (i, g) in shape.iter_mut().enumerate() {
            *g -= offset * mode(i);
        }
    }
}

/// Linear interpolation weights of the contact points at x = `x0` (nearest pair along x).
fn interpolation_weights(points: &ContactPoints, x0: f64) -> Vec<(usize, f64)> {
    let xs: Vec<f64> = points.x.iter().map(|p| p[0]).collect();
    for i in 0..xs.len().saturating_sub(1) {
        let (a, b) = (xs[i], xs[i + 1]);
        if (a - x0) * (b - x0) <= 0.0 && a != b {
            let s = (x0 - a) / (b - a);
            return vec![(i, 1.0 - s), (i + 1, s)];
        }
    }
    let nearest = (0..xs.len())
        .min_by(|&i, &j| (xs[i] - x0).abs().total_cmp(&(xs[j] - x0).abs()))
        .unwrap_or(0);
    vec![(nearest, 1.0)]
}
