//! Parameter studies: the Cartesian product of overrides ([`crate::overrides`]) of one problem,
//! each variant solved by a job of [`crate::driver`] (the steady state or a wear run), the
//! variants in parallel on a rayon pool. The CLI's `wearfem sweep` is a thin shell around
//! [`Sweep::prepare`], [`run`] and [`report::write`]; a Python layer can call the same three.
//!
//! Each variant is solved exactly as a single `wearfem steady --set …` (or `run --set …`) with
//! the same overrides would be: the same problem text, the same overrides in the same order,
//! the same job function, on one thread. Its figures are therefore identical to the single
//! run's, bit for bit.

use crate::driver::{self, JobError};
use crate::overrides::{Override, SET};
use crate::problem::{Problem, ProblemError};
use rayon::prelude::*;
use std::time::Instant;

pub mod report;
pub mod unread;

/// Which job each variant runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Job {
    /// The steady worn state, computed directly ([`driver::steady`]).
    Steady,
    /// The wear time integration over the problem's steps ([`driver::wear`]).
    Run,
}

/// The axes of a study: for each key, the values it takes.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// (key, values) in the order given; the first key varies slowest.
    pub axes: Vec<(String, Vec<toml::Value>)>,
}

impl Sweep {
    /// Read the axes from `--set` texts `KEY=[V1, V2, …]` (a TOML array of the values; a
    /// value that is not an array is one value).
    pub fn parse(sets: &[String]) -> Result<Sweep, ProblemError> {
        let mut axes = Vec::new();
        for text in sets {
            let (key, value) = crate::overrides::split(text)?;
            let values = match crate::overrides::parse_value(value) {
                toml::Value::Array(values) => values,
                single => vec![single],
            };
            if values.is_empty() {
                return Err(ProblemError {
                    file: SET.into(),
                    key: key.into(),
                    message: "the list of values is empty".into(),
                });
            }
            // Checks the key's syntax now, before any variant is built.
            Override::new(key, values[0].clone())?;
            axes.push((key.to_string(), values));
        }
        // A key given twice, or one inside a table another axis sets, would have its values
        // replaced in every variant while the table still listed them.
        let keys: Vec<&str> = axes.iter().map(|(k, _)| k.as_str()).collect();
        crate::overrides::check_axes(&keys)?;
        Ok(Sweep { axes })
    }

    /// The overrides of every variant: the Cartesian product of the axes, first key slowest.
    pub fn variants(&self) -> Result<Vec<Vec<Override>>, ProblemError> {
        let mut variants: Vec<Vec<Override>> = vec![vec![]];
        for (key, values) in &self.axes {
            let mut next = Vec::with_capacity(variants.len() * values.len());
            for v in &variants {
                for value in values {
                    let mut o = v.clone();
                    o.push(Override::new(key, value.clone())?);
                    next.push(o);
                }
            }
            variants = next;
        }
        Ok(variants)
    }

    /// Build and validate every variant's problem, with the settings `job` reads
    /// ([`check_settings`]), before any is solved, so that a bad key or value stops the study
    /// at once.
    pub fn prepare(&self, text: &str, file: &str, job: Job) -> Result<Vec<Variant>, ProblemError> {
        self.variants()?
            .into_iter()
            .map(|overrides| {
                let problem = Problem::with_overrides(text, file, &overrides)?;
                check_settings(&problem, job)?;
                Ok(Variant { overrides, problem })
            })
            .collect()
    }
}

/// What `job` reads from `problem`, checked without assembling or solving anything, so that a
/// study refuses a bad variant before it solves any: the contact and plate sections
/// ([`crate::contact::check_settings`]), the solver method and first direction, the probes'
/// body, and the wear section. Only the checks that need the contact points (a point without
/// a partner on body 2, a probe or `wear.shape_zero_at` off the contact edge) and a body whose
/// supports do not hold it (found when it is factorised) wait for the variant's solve.
pub fn check_settings(problem: &Problem, job: Job) -> Result<(), ProblemError> {
    if super::fretting::is_fretting(problem) {
        return Err(problem.error("fretting", "parameter studies of fretting problems are not built yet: run `wearfem run` or `wearfem steady` on each variant (--set)"));
    }
    crate::contact::check_settings(problem)?;
    driver::method(problem)?;
    driver::direction(problem)?;
    driver::check_probe_bodies(problem)?;
    let wear = problem
        .spec
        .wear
        .as_ref()
        .ok_or_else(|| problem.error("wear", "this problem has no [wear] section"))?;
    let integrator = crate::wear::WearIntegrator::new(wear)
        .map_err(|(key, message)| problem.error(key, message))?;
    match job {
        Job::Run => super::run::check_shape_zero_plate(problem)?,
        Job::Steady => {
            // What the steady state refuses before it iterates (`driver::steady` names the
            // same keys for these errors).
            use crate::steady::SteadyError;
            let plate_moves = problem
                .spec
                .plate
                .as_ref()
                .is_some_and(|p| p.motion != "fixed");
            if !plate_moves {
                let e = SteadyError::NoRigidMotion;
                return Err(problem.error("plate.motion", e.to_string()));
            }
            if integrator.half_period_wear().iter().all(|t| t.0 == 0.0) {
                return Err(problem.error("wear.body1.beta", SteadyError::NoWear.to_string()));
            }
        }
    }
    Ok(())
}

/// One variant of a study: its overrides and the problem they give.
#[derive(Clone, Debug)]
pub struct Variant {
    /// The overrides, one per axis, in axis order.
    pub overrides: Vec<Override>,
    /// The validated problem.
    pub problem: Problem,
}

/// The figures of one solved variant.
///
/// A variant that did not converge has no figures: `values` is `None`, so that nothing from a
/// failed or non-converged solve can be written or returned as a result (its row keeps the
/// overrides, `status` and `seconds`, its value cells are empty). A wear run that converged
/// but completed no full cycle has no figures either: there is no last cycle to report.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// "solved", or what went wrong ("not converged (…)", "failed solves …, stopped at step …");
    /// for a converged run also "stopped at step N: the steady state was reached" (adaptive
    /// schedule) or [`NO_CYCLE`], as `wearfem run` and Python's `RunResult.status` say.
    pub status: String,
    /// Whether the computation converged, as the single command's exit code 0 says; `values`
    /// is `Some` when it did, except for a run that completed no full cycle.
    pub converged: bool,
    /// x of the contact points, mm (the geometry, known whether or not the solve converged).
    pub x: Vec<f64>,
    /// Whether the sliding is reciprocating (a '−' half cycle exists), from the problem.
    pub reciprocating: bool,
    /// Probe names and their contact point indices.
    pub probes: Vec<(String, usize)>,
    /// Names of the plate unknowns whose rigid wear per period a steady variant reports
    /// (`lambda_F`, `lambda_M`); empty for a wear run.
    pub rigid_names: Vec<String>,
    /// The figures; `None` when the variant did not converge.
    pub values: Option<Values>,
    /// Wall-clock seconds of this variant (set-up included).
    pub seconds: f64,
    /// The warning lines `wearfem steady` or `wearfem run` would print for this variant
    /// (none for one that did not converge, whose values are not results anyway).
    pub warnings: Vec<String>,
}

/// The figures of a converged variant.
#[derive(Clone, Debug)]
pub struct Values {
    /// '+' half-cycle pressure (monotonic: the pressure), MPa, one per contact point.
    pub p_plus: Vec<f64>,
    /// '−' half-cycle pressure, MPa; `None` for monotonic sliding.
    pub p_minus: Option<Vec<f64>>,
    /// Worn shape (wear gap), mm.
    pub shape: Vec<f64>,
    /// Rigid wear per period by plate unknown, in the order of `Outcome::rigid_names`
    /// (`lambda_F` mm, `lambda_M` rad); steady only.
    pub rigid_wear_per_period: Option<Vec<f64>>,
    /// Run only: how far the last cycle's pressures are from the steady state of the same
    /// problem, relative to its peak (`steady_distance.pressure` of `wearfem run`; `None`
    /// without a steady state to compare with), and whether the run counts as at the steady
    /// state (`steady_reached`). A converged run can still be far from it: a study of runs
    /// says which.
    pub steady: Option<(Option<f64>, bool)>,
}

impl Outcome {
    /// Largest '+' pressure, MPa; `None` without values.
    pub fn peak_p_plus(&self) -> Option<f64> {
        self.values.as_ref().map(|v| peak(&v.p_plus))
    }

    /// Largest '−' pressure, MPa (reciprocating only); `None` without values.
    pub fn peak_p_minus(&self) -> Option<f64> {
        self.values.as_ref()?.p_minus.as_deref().map(peak)
    }

    /// max − min of the shape over the contact points, mm; `None` without values.
    pub fn shape_range(&self) -> Option<f64> {
        let v = self.values.as_ref()?;
        let (lo, hi) = v
            .shape
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &s| {
                (a.min(s), b.max(s))
            });
        Some(hi - lo)
    }

    /// '+' pressure at probe `name`, MPa; `None` without values or without that probe.
    pub fn probe_p_plus(&self, name: &str) -> Option<f64> {
        let i = self.probes.iter().find(|p| p.0 == name)?.1;
        Some(self.values.as_ref()?.p_plus[i])
    }

    /// '−' pressure at probe `name`, MPa; `None` without values, probe or '−' half cycle.
    pub fn probe_p_minus(&self, name: &str) -> Option<f64> {
        let i = self.probes.iter().find(|p| p.0 == name)?.1;
        Some(self.values.as_ref()?.p_minus.as_ref()?[i])
    }

    /// Run only: the last cycle's distance from the steady state, relative to its peak;
    /// `None` without values, for a steady variant, or without a steady state to compare.
    pub fn steady_distance(&self) -> Option<f64> {
        self.values.as_ref()?.steady?.0
    }

    /// Run only: whether the run ended at the steady state; `None` without values or for a
    /// steady variant.
    pub fn steady_reached(&self) -> Option<bool> {
        Some(self.values.as_ref()?.steady?.1)
    }

    /// Rigid wear per period of plate unknown `name` (mm or rad); `None` without values.
    pub fn rigid_wear(&self, name: &str) -> Option<f64> {
        let k = self.rigid_names.iter().position(|n| n == name)?;
        Some(self.values.as_ref()?.rigid_wear_per_period.as_ref()?[k])
    }
}

/// The status of a converged wear run too short for one full cycle: it has no last-cycle
/// profiles, so its row has no values (what `wearfem run` prints for it, and exit code 0).
pub const NO_CYCLE: &str = "no full cycle completed: no final profiles";

fn peak(p: &[f64]) -> f64 {
    p.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
}

/// Solve one variant with `job`.
///
/// Only a converged variant carries figures ([`Outcome::values`]). A steady variant whose
/// iteration did not converge keeps nothing of its last iterate. A wear run converges when
/// `wearfem run` with the same overrides would exit with 0: every step solved and met its
/// tolerance, and it did not stop early but at the steady state of an adaptive schedule;
/// otherwise its row has no figures at all, not even those of the steps before a failure (a
/// profile of an earlier cycle is not the result of the run asked for), and `status` says
/// what went wrong and at which step the run stopped. A converged run that completed no full
/// cycle has no figures either (no final profiles, as `wearfem run`), and its status says so.
pub fn solve(problem: &Problem, job: Job) -> Result<Outcome, JobError> {
    let start = Instant::now();
    let outcome = match job {
        Job::Steady => {
            let (state, contact, _) = driver::steady(problem)?;
            let converged = state.status == crate::steady::SteadyStatus::Solved;
            let warnings = if converged {
                driver::study_steady_warnings(problem, &contact, &state)
            } else {
                Vec::new()
            };
            let reciprocating = state.sliding == crate::steady::SteadySliding::Reciprocating;
            Outcome {
                status: if converged {
                    "solved".into()
                } else {
                    format!(
                        "not converged ({:?}, wear residual {:.3e})",
                        state.status, state.wear_residual
                    )
                },
                converged,
                x: contact.points.x.iter().map(|p| p[0]).collect(),
                reciprocating,
                probes: driver::contact_probes(problem, &contact),
                rigid_names: contact.rigid_names.iter().map(|n| n.to_string()).collect(),
                values: converged.then(|| Values {
                    p_minus: reciprocating.then(|| state.p_minus.clone()),
                    p_plus: state.p_plus,
                    shape: state.shape,
                    rigid_wear_per_period: Some(state.rigid_wear),
                    steady: None,
                }),
                seconds: 0.0,
                warnings,
            }
        }
        Job::Run => {
            let run = driver::wear(problem, None, |_| {})?;
            let h = &run.history;
            // Converged exactly when `wearfem run` exits with 0 (and Python's
            // `RunResult.converged` is true): every step solved and met its tolerance, and the
            // run did not stop early for another reason than the steady state. A run too short
            // for one full cycle converged all the same (it did what was asked); it only has
            // no last-cycle profiles, so its row has no values (`wearfem run` writes no final
            // profiles either) and its status says why.
            let stopped_early = h
                .stopped
                .as_ref()
                .is_some_and(|(_, reason)| *reason != crate::wear::StopReason::SteadyState);
            let converged = h.failed_solves == 0
                && h.unconverged_steps == 0
                && h.oscillating_steps == 0
                && !stopped_early;
            let no_cycle = h.steady_distance.is_none();
            let reciprocating = problem
                .spec
                .wear
                .as_ref()
                .is_some_and(|w| w.sliding != "monotonic");
            // The status of Python's `RunResult` for the same run (built from summary.json's
            // counts and `stopped_at_step`/`stop_reason`), so that an adaptive run that
            // stopped at the steady state says so here too.
            let mut problems = Vec::new();
            if h.failed_solves > 0 {
                problems.push(format!("failed solves {}", h.failed_solves));
            }
            if h.unconverged_steps > 0 {
                problems.push(format!("unconverged steps {}", h.unconverged_steps));
            }
            if h.oscillating_steps > 0 {
                problems.push(format!("oscillating steps {}", h.oscillating_steps));
            }
            if let Some((s, reason)) = &h.stopped {
                problems.push(format!("stopped at step {s}: {reason}"));
            }
            if converged && no_cycle {
                // What `wearfem run` prints for it.
                problems.push(NO_CYCLE.into());
            }
            let converged_with_values = converged && !no_cycle;
            Outcome {
                status: if problems.is_empty() {
                    "solved".into()
                } else {
                    problems.join(", ")
                },
                converged,
                x: run.contact.points.x.iter().map(|p| p[0]).collect(),
                reciprocating,
                probes: run.probes.clone(),
                rigid_names: Vec::new(),
                values: converged_with_values.then(|| Values {
                    p_plus: h.p_plus.clone(),
                    p_minus: reciprocating.then(|| h.p_minus.clone()),
                    shape: h.shape.clone(),
                    rigid_wear_per_period: None,
                    steady: Some((
                        match run.steady_check {
                            crate::checks::steady_check::SteadyCheck::Compared {
                                pressure, ..
                            } => Some(pressure),
                            _ => None,
                        },
                        run.steady_check.reached(h),
                    )),
                }),
                seconds: 0.0,
                warnings: if converged {
                    run.study_warnings(problem)
                } else {
                    Vec::new()
                },
            }
        }
    };
    Ok(Outcome {
        seconds: start.elapsed().as_secs_f64(),
        ..outcome
    })
}

/// The threads a study of `variants` variants runs on when `requested` are asked for (0: one
/// per core): never more than the variants. A thread beyond them would have nothing to do,
/// and each costs its stack and start-up: `-j 10000` on two variants ran for over a minute
/// in 0.9 GB before this bound (red-team review 10, F8).
pub fn threads(requested: usize, variants: usize) -> usize {
    let requested = if requested == 0 {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    } else {
        requested
    };
    requested.min(variants).max(1)
}

/// Solve every variant with `job` on `jobs` threads (0: one per core; at most one per
/// variant, [`threads`]), calling `on_done` (from any thread) as each finishes. The outcomes
/// are in variant order; a variant whose input is bad gives its error in place.
pub fn run(
    variants: &[Variant],
    job: Job,
    jobs: usize,
    on_done: &(dyn Fn(&Result<Outcome, JobError>) + Sync),
) -> Vec<Result<Outcome, JobError>> {
    let work = || {
        variants
            .par_iter()
            .map(|v| {
                let outcome = solve(&v.problem, job);
                on_done(&outcome);
                outcome
            })
            .collect()
    };
    let jobs = threads(jobs, variants.len());
    match rayon::ThreadPoolBuilder::new().num_threads(jobs).build() {
        Ok(pool) => pool.install(work),
        // Only the speed depends on the pool: without one, rayon's global pool does the work.
        Err(_) => work(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_key_given_twice_is_an_error() {
        let sets = vec![
            "contact.friction=[0.1, 0.2]".to_string(),
            "contact.friction=[0.3]".to_string(),
        ];
        let e = Sweep::parse(&sets).unwrap_err();
        assert_eq!(e.key, "contact.friction");
        assert!(e.message.contains("given twice"), "{}", e.message);
    }

    #[test]
    fn variants_are_the_cartesian_product_first_key_slowest() {
        let sweep = Sweep::parse(&[
            "plate.pin=[[1100,120],[1100,140]]".into(),
            "contact.friction=[0.1,0.25,0.4]".into(),
            "wear.body1.b=1.2".into(),
        ])
        .unwrap();
        let v = sweep.variants().unwrap();
        assert_eq!(v.len(), 2 * 3);
        let text = |i: usize| -> Vec<String> { v[i].iter().map(|o| o.value_text()).collect() };
        assert_eq!(text(0), ["[1100, 120]", "0.1", "1.2"]);
        assert_eq!(text(1), ["[1100, 120]", "0.25", "1.2"]);
        assert_eq!(text(5), ["[1100, 140]", "0.4", "1.2"]);
    }

    #[test]
    fn no_more_threads_than_variants() {
        assert_eq!(threads(10_000, 2), 2);
        assert_eq!(threads(3, 10), 3);
        assert_eq!(threads(5, 0), 1);
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        assert_eq!(threads(0, 1000), cores.min(1000));
        assert_eq!(threads(0, 1), 1);
    }

    #[test]
    fn an_empty_list_is_an_error() {
        let e = Sweep::parse(&["contact.friction=[]".into()]).unwrap_err();
        assert_eq!(e.key, "contact.friction");
    }
}
