//! The adaptive schedule's two integrators of the worn shape between recorded cycles
//! ([`super::adaptive`] derives both): step doubling with Richardson extrapolation, and
//! variable-step BDF2 with Milne's error estimate.

use super::workspace::Workspace;

/// The state of the adaptive schedule's step doubling ([`super::adaptive`]).
pub(super) struct StepDoubling {
    /// Fine cycles done in the current macro step (0 or 1).
    pub(super) fine_cycles: usize,
    /// Whether the next macro step starts from the Richardson extrapolation 2 g_f − g_c.
    pub(super) extrapolate: bool,
    /// The coarse cycle's shape (mm) and pressures of its two half cycles (MPa): '+' then
    /// '−' (the one direction under monotonic sliding first), whichever ran first.
    pub(super) shape: Vec<f64>,
    pub(super) pressure: [Vec<f64>; 2],
    /// The last macro step's pressures of the two half cycles (MPa).
    pub(super) previous: [Vec<f64>; 2],
    /// The coarse cycle's copy of the run's buffers.
    pub(super) ws: Workspace,
}

impl StepDoubling {
    pub(super) fn new(ws: &Workspace) -> StepDoubling {
        let n = ws.trial.len();
        StepDoubling {
            fine_cycles: 0,
            extrapolate: false,
            shape: vec![0.0; n],
            pressure: [vec![0.0; n], vec![0.0; n]],
            previous: [vec![0.0; n], vec![0.0; n]],
            ws: ws.clone(),
        }
    }

    /// At the end of a macro step with the fine pressures `plus` and `minus` (empty under
    /// monotonic sliding): the local error estimate max |p_f − p_c|, the change
    /// max |p − p_previous| since the last macro step and the peak max p, all MPa.
    pub(super) fn compare(&mut self, plus: &[f64], minus: &[f64]) -> (f64, f64, f64) {
        let (mut local, mut change, mut peak) = (0.0f64, 0.0f64, 0.0f64);
        for (half, fine) in [plus, minus].into_iter().enumerate() {
            for (i, &p) in fine.iter().enumerate() {
                local = local.max((p - self.pressure[half][i]).abs());
                change = change.max((p - self.previous[half][i]).abs());
                peak = peak.max(p);
                self.previous[half][i] = p;
            }
        }
        (local, change, peak)
    }
}

/// The state of the adaptive schedule's BDF2 ([`super::adaptive`]). A cycle (both half
/// periods; one step under monotonic sliding) is one BDF2 step of k cycles, in the
/// fixed-leading-coefficient form: the wear term always has the weight (2/3) k, and the
/// shape one step back is interpolated from the stored ones when k has just changed.
pub(super) struct Bdf2 {
    /// Time (cycles of factor 1 done) at the start of the current cycle.
    pub(super) time: f64,
    /// The (at most two) cycle-end shapes before the current cycle's start shape, newest
    /// first, with their times (mm).
    pub(super) shapes: Vec<(f64, Vec<f64>)>,
    /// A buffer for the next stored shape.
    pub(super) spare: Vec<f64>,
    /// Weight of the wear term in the current cycle: k for the first cycle (backward
    /// Euler), (2/3) k after.
    pub(super) weight: f64,
    /// The last three cycles, newest first: k and the pressures of both half cycles (MPa).
    pub(super) history: Vec<(usize, [Vec<f64>; 2])>,
    /// Under monotonic sliding a cycle has one half.
    pub(super) monotonic: bool,
}

impl Bdf2 {
    pub(super) fn new(monotonic: bool) -> Bdf2 {
        Bdf2 {
            time: 0.0,
            shapes: Vec::with_capacity(3),
            spare: Vec::new(),
            weight: 0.0,
            history: Vec::with_capacity(4),
            monotonic,
        }
    }

    /// Start a cycle with factor `k` from `shape` (g_n, the last cycle's end): replace it by
    /// the known part (4 g_n − g_v)/3 of the BDF2 formula, g_v being the shape k cycles
    /// back, and return the weight (2/3) k of the wear term. The first cycle is backward
    /// Euler (weight k, shape unchanged).
    pub(super) fn begin_cycle(&mut self, shape: &mut [f64], k: usize) -> f64 {
        let kf = k as f64;
        let mut current = std::mem::take(&mut self.spare);
        current.clear();
        current.extend_from_slice(shape);
        self.weight = if self.shapes.is_empty() {
            kf
        } else {
            // g_v by Lagrange interpolation through g_n and the stored shapes at t_n − k:
            // exactly a stored shape unless k was just halved (the controller doubles k
            // only after two cycles with the same k).
            let times: Vec<f64> = std::iter::once(self.time)
                .chain(self.shapes.iter().map(|(t, _)| *t))
                .collect();
            let target = self.time - kf;
            let w = lagrange(&times, target);
            for (i, g) in shape.iter_mut().enumerate() {
                let back = w[0] * current[i]
                    + self
                        .shapes
                        .iter()
                        .zip(&w[1..])
                        .map(|((_, stored), wj)| wj * stored[i])
                        .sum::<f64>();
                *g = (4.0 * current[i] - back) / 3.0;
            }
            2.0 / 3.0 * kf
        };
        self.shapes.insert(0, (self.time, current));
        if self.shapes.len() > 2 {
            self.spare = self.shapes.pop().map(|(_, s)| s).unwrap_or_default();
        }
        self.time += kf;
        self.weight
    }

    /// The shape after the first half cycle of the current cycle (factor `k`, that half
    /// period's wear `increment`), as the other schemes report it: g_n + k ΔW⁺, written into
    /// `out`. (The working shape (4 g_n − g_v)/3 + (2/3) k ΔW⁺ is only the BDF2 formula's
    /// intermediate: its volume is k/3 half periods ahead.)
    pub(super) fn mid_cycle_shape(&self, k: usize, increment: &[f64], out: &mut [f64]) {
        let start = &self.shapes[0].1;
        for ((o, g), w) in out.iter_mut().zip(start).zip(increment) {
            *o = g + k as f64 * w;
        }
    }

    /// At the end of a cycle with factor `k` and pressures `plus` and `minus` (empty under
    /// monotonic sliding): the local error estimate (NaN until three cycles are known), the
    /// change max |p − p_previous| since the last cycle and the peak max p, all MPa.
    pub(super) fn end_cycle(&mut self, k: usize, plus: &[f64], minus: &[f64]) -> (f64, f64, f64) {
        let halves: [&[f64]; 2] = [plus, if self.monotonic { &[] } else { minus }];
        let (mut local, mut change, mut peak) = (f64::NAN, 0.0f64, 0.0f64);
        if self.history.len() == 3 {
            // Milne's device: the quadratic extrapolation of the last three cycles'
            // pressures to this cycle's end (the predictor, error −C_p p‴ with
            // C_p = h₀(h₀ + h₁)(h₀ + h₁ + h₂)/6) against the corrector (error C_c p‴,
            // C_c = (2/9) h₀³): the corrector's share of their difference.
            let h = [k as f64, self.history[0].0 as f64, self.history[1].0 as f64];
            let w = lagrange(&[-h[0], -h[0] - h[1], -h[0] - h[1] - h[2]], 0.0);
            let corrector = 2.0 / 9.0 * h[0].powi(3);
            let predictor = h[0] * (h[0] + h[1]) * (h[0] + h[1] + h[2]) / 6.0;
            let share = corrector / (corrector + predictor);
            let mut worst = 0.0f64;
            for (half, now) in halves.iter().enumerate() {
                for (i, &p) in now.iter().enumerate() {
                    let predicted: f64 = (0..3).map(|j| w[j] * self.history[j].1[half][i]).sum();
                    worst = worst.max((p - predicted).abs());
                }
            }
            local = share * worst;
        }
        for (half, now) in halves.iter().enumerate() {
            for (i, &p) in now.iter().enumerate() {
                if let Some(last) = self.history.first() {
                    change = change.max((p - last.1[half][i]).abs());
                }
                peak = peak.max(p);
            }
        }
        let mut entry = if self.history.len() == 3 {
            self.history.pop().unwrap_or_default()
        } else {
            (0, [Vec::new(), Vec::new()])
        };
        entry.0 = k;
        for (half, now) in halves.iter().enumerate() {
            entry.1[half].clear();
            entry.1[half].extend_from_slice(now);
        }
        self.history.insert(0, entry);
        (local, change, peak)
    }
}

/// Lagrange weights of the polynomial through the nodes `times` evaluated at `at`.
fn lagrange(times: &[f64], at: f64) -> Vec<f64> {
    (0..times.len())
        .map(|j| {
            (0..times.len())
                .filter(|&m| m != j)
                .map(|m| (at - times[m]) / (times[j] - times[m]))
                .product::<f64>()
        })
        .collect()
}
