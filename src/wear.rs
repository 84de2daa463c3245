//! Wear time integration (paper §4, eq. 24–30): the Archard-type rule ẇ = β̃ pᵇ vᵃ (eq. 1)
//! integrated half period by half period, with the pressure held at its end-of-half-period
//! value (implicit, iterated to criterion eq. 27), the extrapolation factor k (eq. 29–30), and
//! the friction direction alternating every half period.
//!
//! The wear of both bodies is measured along n_c and accumulated into the gap g of the contact
//! points (paper eq. 25–26): body 1's wear where it happens; body 2's at the substrate point
//! paired with each contact point (the pairs do not move, reference model), i.e. the substrate
//! segment under the punch, which is what the paper's segment M̃Ñ describes.

use crate::complementarity::{ContactSolution, ContactSolver, Direction, SolveInfo, Status};
use crate::contact::{CondensedContact, ContactPoints};
pub use crate::kinematics::ScheduleEntry;
use crate::kinematics::{factor, half_period_sliding, paper_schedule, partial_sliding};
use serde::{Deserialize, Serialize};

/// Wear law parameters of one body: ẇ = β̃ pᵇ vᵃ (mm/s with p in MPa and v in mm/s).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct WearLaw {
    /// β̃ = β μᵇ, mm^(1−a) s^(a−1) MPa^(−b); 0 switches wear of this body off.
    pub beta: f64,
    /// Velocity exponent a (> 0).
    #[serde(default = "one")]
    pub a: f64,
    /// Pressure exponent b (> 0).
    #[serde(default = "one")]
    pub b: f64,
}

fn one() -> f64 {
    1.0
}

/// `[wear]` section of a problem file.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct WearSpec {
    /// Wear of body 1 (the punch).
    pub body1: Option<WearLaw>,
    /// Wear of body 2 (the substrate).
    pub body2: Option<WearLaw>,
    /// "reciprocating" (u_τ = −u₀ cos ωτ) or "monotonic" (constant speed, '+' direction).
    #[serde(default = "reciprocating")]
    pub sliding: String,
    /// Reciprocating amplitude u₀, mm.
    #[serde(default)]
    pub amplitude: f64,
    /// Reciprocating angular frequency ω, rad/s.
    #[serde(default)]
    pub omega: f64,
    /// Monotonic sliding speed v, mm/s.
    #[serde(default)]
    pub speed: f64,
    /// Monotonic: time per step, s.
    #[serde(default)]
    pub step_time: f64,
    /// Number of steps n.
    pub steps: usize,
    /// Extrapolation schedule (default: the paper's k = 1, 5, 10 after steps 50, 100).
    pub extrapolation: Option<Vec<ScheduleEntry>>,
    /// Criterion eq. 27, percent (default 0.01).
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// "eq27" (default): the paper's integral criterion; "pointwise": the largest change of the
    /// wear increment at any point, relative to its largest value (percent).
    #[serde(default = "eq27")]
    pub criterion: String,
    /// Most implicit iterations per step (default 50).
    #[serde(default = "default_iterations")]
    pub max_iterations: usize,
    /// 0: the paper's half-period scheme; m > 0: plain explicit time stepping with m sub-steps
    /// per half period (for checking the scheme).
    #[serde(default)]
    pub substeps: usize,
    /// x (mm) of the point where the shape is shifted to zero after every full cycle, by a
    /// vertical rigid translation of body 1 (which leaves the pressures unchanged).
    pub shape_zero_at: Option<f64>,
    /// Steps at which whole pressure and shape profiles are recorded.
    #[serde(default)]
    pub record: Vec<usize>,
}

fn reciprocating() -> String {
    "reciprocating".into()
}
fn eq27() -> String {
    "eq27".into()
}
fn default_tolerance() -> f64 {
    0.01
}
fn default_iterations() -> usize {
    50
}

/// Pressure profiles and shape at one step.
#[derive(Clone, Debug, Serialize)]
pub struct Snapshot {
    /// Step number n.
    pub step: usize,
    /// Half periods done at the end of the step.
    pub half_period: usize,
    /// "+" or "-".
    pub direction: &'static str,
    /// Pressure at the end of the step, MPa.
    pub pressure: Vec<f64>,
    /// Shape (accumulated wear gap) at the end of the step, mm.
    pub shape: Vec<f64>,
}

/// One row of the step history.
#[derive(Clone, Debug, Serialize)]
pub struct StepRecord {
    /// Step number n (1-based).
    pub step: usize,
    /// Half periods done at the end of the step (paper eq. 30).
    pub half_period: usize,
    /// "+" or "-".
    pub direction: &'static str,
    /// Extrapolation factor k.
    pub k: usize,
    /// Implicit iterations j.
    pub iterations: usize,
    /// Contact solves in this step.
    pub solves: usize,
    /// Final criterion eq. 27, percent.
    pub criterion: f64,
    /// Wear dissipation of one half period, t∫ p Δwₙ dS (N·mm) (paper eq. 9, 13).
    pub dissipation: f64,
    /// Pressure at each probe (nearest contact point), MPa, in probe order.
    pub probes: Vec<f64>,
    /// Largest δw = Δw − min Δw over the cycle ending here (paper eq. 40), mm; 0 after '+' steps.
    pub delta_w: f64,
}

/// Result of a wear run.
#[derive(Clone, Debug, Serialize)]
pub struct WearHistory {
    /// One record per step.
    pub steps: Vec<StepRecord>,
    /// Snapshots at the requested steps.
    pub snapshots: Vec<Snapshot>,
    /// Pressure of the last '+' step (of the last step for monotonic sliding), MPa.
    pub p_plus: Vec<f64>,
    /// Pressure of the last '−' step, MPa.
    pub p_minus: Vec<f64>,
    /// Shape at the end, mm.
    pub shape: Vec<f64>,
    /// Total contact solves.
    pub solves: usize,
    /// Steps whose implicit iteration did not meet the criterion.
    pub unconverged_steps: usize,
    /// Contact solves that failed (the last iterate was kept).
    pub failed_solves: usize,
    /// The step at which the wear stopped being finite, if it did; the run ended before it.
    pub stopped_at: Option<usize>,
}

/// Most steps a run may have (each keeps a record of about 100 bytes).
pub const MAX_STEPS: usize = 1_000_000;
/// Largest extrapolation factor k.
pub const MAX_FACTOR: usize = 1_000_000;

/// The integrator: wear laws, kinematics and schedule, validated.
#[derive(Clone, Debug)]
pub struct WearIntegrator {
    /// The validated specification.
    pub spec: WearSpec,
    schedule: Vec<ScheduleEntry>,
    laws: Vec<WearLaw>,
    /// Sliding direction of the first (odd) steps; default '+'.
    pub first_direction: Direction,
}

impl WearIntegrator {
    /// Validate `spec`; the error names the key.
    pub fn new(spec: &WearSpec) -> Result<WearIntegrator, (String, String)> {
        let bad = |k: &str, m: String| Err((format!("wear.{k}"), m));
        let mut laws = Vec::new();
        for (name, law) in [("body1", spec.body1), ("body2", spec.body2)] {
            if let Some(l) = law {
                if !(l.beta.is_finite() && l.beta >= 0.0) {
                    return bad(
                        &format!("{name}.beta"),
                        format!("must be ≥ 0, got {}", l.beta),
                    );
                }
                // Measured exponents lie between about 0.3 and 4; beyond 10 only overflow waits.
                if !(l.a > 0.0 && l.a <= 10.0 && l.b > 0.0 && l.b <= 10.0) {
                    return bad(
                        name,
                        format!(
                            "exponents a and b must lie in (0, 10], got a = {}, b = {}",
                            l.a, l.b
                        ),
                    );
                }
                if l.beta > 0.0 {
                    laws.push(l);
                }
            }
        }
        match spec.sliding.as_str() {
            "reciprocating" => {
                if !(spec.amplitude > 0.0 && spec.amplitude.is_finite()) {
                    return bad(
                        "amplitude",
                        format!(
                            "reciprocating sliding needs u₀ > 0 (mm), got {}",
                            spec.amplitude
                        ),
                    );
                }
                if !(spec.omega > 0.0 && spec.omega.is_finite()) {
                    return bad(
                        "omega",
                        format!(
                            "reciprocating sliding needs ω > 0 (rad/s), got {}",
                            spec.omega
                        ),
                    );
                }
            }
            "monotonic" => {
                if !(spec.speed > 0.0
                    && spec.step_time > 0.0
                    && spec.speed.is_finite()
                    && spec.step_time.is_finite())
                {
                    return bad("speed", format!("monotonic sliding needs speed > 0 (mm/s) and step_time > 0 (s), got {} and {}", spec.speed, spec.step_time));
                }
            }
            other => {
                return bad(
                    "sliding",
                    format!("must be \"reciprocating\" or \"monotonic\", got \"{other}\""),
                )
            }
        }
        if !(spec.tolerance.is_finite() && spec.tolerance > 0.0) {
            return bad(
                "tolerance",
                format!("must be positive (percent), got {}", spec.tolerance),
            );
        }
        if spec.criterion != "eq27" && spec.criterion != "pointwise" {
            return bad(
                "criterion",
                format!(
                    "must be \"eq27\" or \"pointwise\", got \"{}\"",
                    spec.criterion
                ),
            );
        }
        // Upper limits far beyond any use, so that a typo cannot exhaust memory (one record per
        // step), run for days, or overflow the half-period counter.
        if !(1..=MAX_STEPS).contains(&spec.steps) {
            return bad(
                "steps",
                format!("must be 1 … {MAX_STEPS}, got {}", spec.steps),
            );
        }
        if !(1..=10_000).contains(&spec.max_iterations) {
            return bad(
                "max_iterations",
                format!("must be 1 … 10000, got {}", spec.max_iterations),
            );
        }
        if spec.substeps > 10_000 {
            return bad(
                "substeps",
                format!("must be 0 … 10000, got {}", spec.substeps),
            );
        }
        let schedule = spec.extrapolation.clone().unwrap_or_else(paper_schedule);
        if schedule.is_empty() || schedule.iter().any(|e| !(1..=MAX_FACTOR).contains(&e.k)) {
            return bad(
                "extrapolation",
                format!("needs entries with 1 ≤ k ≤ {MAX_FACTOR}"),
            );
        }
        let bounds: Vec<usize> = schedule.iter().filter_map(|e| e.until).collect();
        if bounds.first() == Some(&0)
            || bounds.windows(2).any(|w| w[1] <= w[0])
            || schedule[..schedule.len() - 1]
                .iter()
                .any(|e| e.until.is_none())
        {
            return bad(
                "extrapolation",
                "`until` (the last step of an entry) must be at least 1 and rise from entry to entry; only the last entry may omit it".into(),
            );
        }
        if spec.shape_zero_at.is_some_and(|x| !x.is_finite()) {
            return bad("shape_zero_at", "must be a finite x coordinate (mm)".into());
        }
        let integrator = WearIntegrator {
            spec: spec.clone(),
            schedule,
            laws,
            first_direction: Direction::Plus,
        };
        for (name, law) in [("body1", spec.body1), ("body2", spec.body2)] {
            if let Some(l) = law {
                let per_half_period = l.beta * integrator.sliding(l.a);
                if !per_half_period.is_finite() {
                    return bad(
                        &format!("{name}.beta"),
                        format!("β̃ ∫|v|ᵃ dτ overflows ({per_half_period}): β̃, a or the sliding amplitude/speed is out of range"),
                    );
                }
            }
        }
        Ok(integrator)
    }

    /// The wear of one half period (one monotonic step) as terms (c, b): Δw = Σ c pᵇ, with
    /// c = β̃ ∫|v|ᵃ dτ (mm MPa⁻ᵇ), one term per wearing body.
    pub fn half_period_wear(&self) -> Vec<(f64, f64)> {
        self.laws
            .iter()
            .map(|l| (l.beta * self.sliding(l.a), l.b))
            .collect()
    }

    /// Whether the sliding is monotonic (one direction) rather than reciprocating.
    pub fn is_monotonic(&self) -> bool {
        self.spec.sliding == "monotonic"
    }

    /// Sliding integral ∫|v|ᵃ dτ of one half period (or one monotonic step).
    fn sliding(&self, a: f64) -> f64 {
        if self.spec.sliding == "monotonic" {
            self.spec.speed.powf(a) * self.spec.step_time
        } else {
            half_period_sliding(self.spec.amplitude, self.spec.omega, a)
        }
    }

    /// Wear gap increment of one half period at pressures `p` (mm), scaled by `scale`.
    fn wear_increment(&self, p: &[f64], sliding: &[f64], scale: f64, out: &mut [f64]) {
        out.iter_mut().for_each(|w| *w = 0.0);
        for (law, s) in self.laws.iter().zip(sliding) {
            for (w, &pi) in out.iter_mut().zip(p) {
                *w += scale * law.beta * pi.max(0.0).powf(law.b) * s;
            }
        }
    }

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
