//! Progress bars of the command line (not part of the library, which never prints): drawn on
//! stderr by indicatif, only when stderr is a terminal, never with `--quiet`, and only once a
//! job has run for a second (shorter jobs would just flash a bar).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::time::{Duration, Instant};
use wearfem::problem::Problem;
use wearfem::wear::StepRecord;

/// How long a job runs before its bar appears.
const DELAY: Duration = Duration::from_secs(1);

fn hidden_bar(len: usize, template: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::hidden());
    if let Ok(style) = ProgressStyle::with_template(template) {
        let rate = |state: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
            let _ = write!(w, "{:.0}/s", state.per_sec());
        };
        bar.set_style(style.progress_chars("=> ").with_key("rate", rate));
    }
    bar
}

/// The bar of a wear run: step, half period, pressure at the first probe, steps per second
/// and time left.
pub struct StepBar {
    bar: ProgressBar,
    probe: Option<String>,
    start: Instant,
    quiet: bool,
}

impl StepBar {
    /// A bar for the run of `problem` (with `steps` replacing `wear.steps` when given).
    pub fn new(problem: &Problem, steps: Option<usize>, quiet: bool) -> StepBar {
        let resolved = problem
            .spec
            .wear
            .as_ref()
            .and_then(|w| wearfem::wear_units::resolve_duration(w).ok());
        let total = steps.or(resolved.map(|w| w.steps)).unwrap_or(0);
        // The step records carry the probes on the contact body, in name order.
        let body = problem.spec.contact.as_ref().map(|c| c.body.as_str());
        let probe = problem
            .spec
            .probes
            .iter()
            .find(|(_, p)| Some(p.body.as_str()) == body)
            .map(|(n, _)| n.clone());
        StepBar {
            bar: hidden_bar(
                total,
                "[{bar:30}] step {pos}/{len}, {msg}, {rate} (ETA {eta})",
            ),
            probe,
            start: Instant::now(),
            quiet,
        }
    }

    /// Show step `s`.
    pub fn step(&self, s: &StepRecord) {
        if !self.quiet && self.bar.is_hidden() && self.start.elapsed() > DELAY {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
        }
        self.bar.set_position(s.step as u64);
        let probe = match (&self.probe, s.probes.first()) {
            (Some(name), Some(p)) => format!(", p({name}) = {p:.3} MPa"),
            _ => String::new(),
        };
        self.bar
            .set_message(format!("half period {}{probe}", s.half_period));
    }

    /// Remove the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// A bar counting `len` finished items (variants of a study), shown at once unless quiet.
pub fn count_bar(len: usize, what: &str, quiet: bool) -> ProgressBar {
    let bar = hidden_bar(
        len,
        &format!("[{{bar:30}}] {{pos}}/{{len}} {what} ({{elapsed}}, ETA {{eta}})"),
    );
    if !quiet {
        bar.set_draw_target(ProgressDrawTarget::stderr());
    }
    bar
}
