//! The buffers of a run's step loop (sized once, so that the loop does not allocate) and the
//! small records a step returns.

use crate::complementarity::{ContactSolution, SolveInfo, Status};

/// Largest pointwise difference of two wear increments, relative to the largest of `new`.
pub(super) fn pointwise_change(new: &[f64], old: &[f64]) -> f64 {
    let largest = new.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let change = new
        .iter()
        .zip(old)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    change / largest.max(f64::MIN_POSITIVE)
}

/// Mean of the positive entries, if any.
pub(super) fn mean_positive(values: &[f64]) -> Option<f64> {
    let (sum, count) = values
        .iter()
        .filter(|&&v| v > 0.0)
        .fold((0.0, 0usize), |(s, c), v| (s + v, c + 1));
    (count > 0).then(|| sum / count as f64)
}

/// What one step did.
#[derive(Default)]
pub(super) struct StepOutcome {
    pub iterations: usize,
    /// Final criterion of the step's iteration, percent.
    pub criterion: f64,
    pub converged: bool,
    pub oscillating: bool,
    /// An implicit step that did not converge and whose error stopped falling in the second
    /// half of its iterations: more iterations would not help.
    pub stalled: bool,
}

/// Buffers of one run, sized once so that the step loop does not allocate.
#[derive(Clone)]
pub(super) struct Workspace {
    /// ∫|v|ᵃ dτ of one half period for each wear law.
    pub sliding: Vec<f64>,
    /// The wear law of one half period, W(p) = Σ c pᵇ, as (c, b) pairs ([`crate::wear::law`]).
    pub terms: super::WearTerms,
    /// Lobatto weight × edge Jacobian of each contact point (mm), for eq. 27's integral.
    pub weight: Vec<f64>,
    /// Contact area w_i t of each point, mm².
    pub area: Vec<f64>,
    /// Each point's own elastic flexibility: the normal approach per unit pressure at that
    /// point, A_nn(i, i) w_i t, mm/MPa.
    pub own_flexibility: Vec<f64>,
    /// Wear compliance of the implicit step, mm/N, and all zeros (no wear compliance).
    pub compliance: Vec<f64>,
    pub zero: Vec<f64>,
    /// Newton's linearisation of the wear: slope (mm/MPa), offset (mm) and pressure (MPa).
    pub slope: Vec<f64>,
    pub linear_wear: Vec<f64>,
    pub linearised_at: Vec<f64>,
    /// Points that Newton's step in the wear sent out of contact in this step: from then on
    /// linearised with the chord ([`crate::wear::law::chord_slope`]).
    pub chord: Vec<bool>,
    /// Wear of one half period of the last second half cycle, mm, and that wear times k: the
    /// look-ahead of the next first half cycle.
    pub second_half: Vec<f64>,
    pub ahead: Vec<f64>,
    /// Last pressure of each direction ('+', '−'), the start of Newton's method.
    pub last_pressure: [Vec<f64>; 2],
    pub trial: Vec<f64>,
    pub increment: Vec<f64>,
    pub new_increment: Vec<f64>,
    pub residual: Vec<f64>,
    /// The shape after the last step that was kept.
    pub last_shape: Vec<f64>,
    /// With heat: the thermal gap the next step is solved with (mm), and the one the last
    /// kept step was solved with; empty without heat.
    pub thermal: Vec<f64>,
    pub solved_thermal: Vec<f64>,
    /// With heat and the adaptive schedule: the last step's contact problem with the
    /// end-of-step thermal gap, for the split's error estimate.
    pub split_trial: Vec<f64>,
    pub split_solution: ContactSolution,
    /// With heat: the modal coordinates of the temperature the last kept step was solved
    /// with.
    pub solved_modal: Vec<f64>,
    pub solution: ContactSolution,
}

impl Workspace {
    pub fn new(n: usize) -> Workspace {
        Workspace {
            sliding: vec![],
            terms: Default::default(),
            weight: vec![0.0; n],
            area: vec![0.0; n],
            own_flexibility: vec![0.0; n],
            compliance: vec![0.0; n],
            zero: vec![0.0; n],
            slope: vec![0.0; n],
            linear_wear: vec![0.0; n],
            chord: vec![false; n],
            linearised_at: vec![0.0; n],
            last_pressure: [vec![0.0; n], vec![0.0; n]],
            second_half: vec![0.0; n],
            ahead: vec![0.0; n],
            trial: vec![0.0; n],
            increment: vec![0.0; n],
            new_increment: vec![0.0; n],
            residual: vec![0.0; n],
            last_shape: vec![0.0; n],
            thermal: Vec::new(),
            solved_thermal: Vec::new(),
            split_trial: vec![0.0; n],
            split_solution: ContactSolution::default(),
            solved_modal: Vec::new(),
            solution: ContactSolution::default(),
        }
    }
}

/// Contact solves of one step, how many of them failed, and the first failure.
#[derive(Default)]
pub(super) struct SolveCount {
    pub solves: usize,
    pub failed: usize,
    pub first_failure: Option<SolveInfo>,
}

impl SolveCount {
    pub fn track(&mut self, info: SolveInfo) {
        self.solves += 1;
        if info.status == Status::Failed {
            self.failed += 1;
            self.first_failure.get_or_insert(info);
        }
    }
}
