//! What a wear run says about itself in words: the lines the command line prints after a run,
//! made here so that the command line only prints them.
//!
//! Reciprocating runs speak of half periods, periods and the last '+' half cycle; monotonic
//! runs of steps, step units of `wear.step_time`, time and sliding distance, and of their last
//! step. A run whose contact zone still grows gets no advice to run longer or to compare
//! with the steady state ([`SteadyCheck::Growing`]).

use super::WearRun;
use crate::checks::steady_check::SteadyCheck;
use crate::problem::Problem;

impl WearRun {
    /// The first line after a run: steps, their time, the solves, the probes' pressures in
    /// the last step of the first direction, and where the files went (`out`).
    pub fn console_summary(&self, problem: &Problem, out: &str) -> String {
        let h = &self.history;
        let units = h.steps.last().map_or(0, |s| s.half_period);
        let distance = units as f64 * self.sliding_per_half_period / 1000.0;
        let first = h.steps.first().map_or("+", |s| s.direction);
        let last_first = h.steps.iter().rev().find(|s| s.direction == first);
        let probes: Vec<String> = match last_first {
            Some(step) if !self.probes.is_empty() => self
                .probes
                .iter()
                .zip(&step.probes)
                .map(|((n, _), value)| format!("p({n}) = {value:.4} MPa"))
                .collect(),
            Some(_) => vec!["no probes".to_string()],
            None => vec!["no steps".to_string()],
        };
        let (duration, last) = if let Some(words) = self.turn_words(units) {
            let last = if self.monotonic {
                "last step".to_string()
            } else {
                format!("last '{first}' half cycle")
            };
            (format!("{units} {}: {words}", self.time_axis()), last)
        } else if self.monotonic {
            let step_time = problem.spec.wear.as_ref().map_or(0.0, |w| w.step_time);
            (
                format!(
                    "{units} step units of {step_time} s: {:.6} s, {distance:.6} m of sliding",
                    units as f64 * step_time
                ),
                "last step".to_string(),
            )
        } else {
            (
                format!("{units} half periods, {distance:.6} m of sliding"),
                format!("last '{first}' half cycle"),
            )
        };
        format!(
            "{}: {} steps ({duration}), {} contact solves in {:.3} s (+{:.3} s set-up); {last}: {} → {out}",
            problem.file,
            h.steps.len(),
            h.solves,
            self.run_seconds,
            self.setup_seconds,
            probes.join(", "),
        )
    }

    /// The line on the last cycle (the last step, under monotonic sliding): against the
    /// steady state, the run's own measures, and the verdict. None when no cycle completed.
    pub fn console_cycle(&self, penalty: bool) -> Option<String> {
        let h = &self.history;
        let d = h.steady_distance?;
        let settled = d.unsettled() <= crate::wear::STEADY_REPORT_LIMIT;
        let verdict = match &self.steady_check {
            check if check.reached(h) => "at the steady state",
            SteadyCheck::Growing { .. } => "running in",
            SteadyCheck::SeparateZones { .. } => {
                "NOT a steady state of one rigid wear per period, and none exists to reach (run longer only to see whether the pressures still change)"
            }
            SteadyCheck::Unavailable(_) if self.contact.rigid_modes.is_empty() => {
                "no steady state with wear exists while the plate is held: the wear only relieves the contact, towards no pressure"
            }
            SteadyCheck::Unavailable(why) if why.starts_with(crate::checks::steady_check::NONE_EXISTS) => {
                "no steady state exists to reach"
            }
            // `wearfem steady` cannot help where there is none to compare with.
            SteadyCheck::Unavailable(_) => {
                "NOT at a steady state by its last cycle's own wear: run longer to see whether it settles"
            }
            _ if penalty => {
                "NOT at the steady state of exact contact, which `wearfem steady` computes whatever `contact.method` says: the penalty method's own steady state lies beside it by the penalty's overlap (see the c_n warning; raise contact.penalty)"
            }
            _ if settled => {
                "NOT at the steady state, though one cycle changes little: a slow approach (run longer) or a schedule that settles beside it (explicit `substeps`, very large k); `wearfem steady` gives the steady state directly"
            }
            _ => "NOT yet at the steady state: run longer, or use `wearfem steady`",
        };
        let against = match &self.steady_check {
            SteadyCheck::NoCycle => String::new(),
            check => check.to_string(),
        };
        let (cycle, per) = if self.monotonic {
            ("last step", "its wear")
        } else {
            ("last cycle", "wear per period")
        };
        // δw compares the two half cycles of a period: none under monotonic sliding.
        let delta_w = if self.monotonic {
            String::new()
        } else {
            format!(", δw = {:.3e} mm", d.delta_w)
        };
        // Said by the check itself when it finds the zone growing.
        let growing = matches!(self.steady_check, SteadyCheck::Growing { .. });
        let closing = if d.closing > crate::wear::STEADY_REPORT_LIMIT && !growing {
            format!(
                ", closing the gaps beside the contact zone at {:.2e} of the largest wear (the zone still grows)",
                d.closing
            )
        } else {
            String::new()
        };
        Some(format!(
            "{cycle}: {against}; {per} rigid to {:.2e} (relative){closing}{delta_w}: {verdict}",
            d.wear
        ))
    }
}
