//! Settings a study's job never reads. An axis over one of them gives rows that are the same
//! for every value, which a table of results presents as "no influence": almost certainly a
//! mistake (the key of another job, or of a sliding the problem does not have). A study
//! warns about each such axis (red-team review 10, F7).
//!
//! The list is here, in one place, for every front end (`wearfem sweep`, and Python's
//! `study`): [`unread`] says whether one axis key is read, [`warnings`] gives the lines of a
//! whole study. Keep it in step with what [`crate::driver::steady`], [`crate::driver::wear`]
//! and [`super::solve`] read: `tests/sweep_rows.rs` sweeps every entry and checks that the
//! rows' values are indeed the same.

use super::{Job, Variant};
use crate::problem::Problem;

/// Under which sliding an entry is unread.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sliding {
    /// Whatever the sliding.
    Any,
    /// When `wear.sliding = "reciprocating"`.
    Reciprocating,
    /// When `wear.sliding = "monotonic"`.
    Monotonic,
}

/// A setting a job does not read.
#[derive(Clone, Copy, Debug)]
pub struct Unread {
    /// The key (an axis on it or on anything under it is unread).
    pub key: &'static str,
    /// The jobs that do not read it.
    pub jobs: &'static [Job],
    /// Under which sliding they do not.
    pub sliding: Sliding,
    /// Why not, for the warning.
    pub why: &'static str,
}

const STEADY: &[Job] = &[Job::Steady];
const BOTH: &[Job] = &[Job::Steady, Job::Run];

/// Every setting a study's job does not read.
pub const UNREAD: &[Unread] = &[
    // The steady state is solved for directly: nothing of the time integration is used.
    Unread {
        key: "wear.scheme",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is how `run` solves a time step; the steady state is solved for directly",
    },
    Unread {
        key: "wear.tolerance",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the tolerance of a time step of `run`",
    },
    Unread {
        key: "wear.criterion",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the convergence test of a time step of `run`",
    },
    Unread {
        key: "wear.max_iterations",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it bounds the iterations of a time step of `run`",
    },
    Unread {
        key: "wear.substeps",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it divides a time step of `run`",
    },
    Unread {
        key: "wear.extrapolation",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the extrapolation schedule of `run`'s time steps",
    },
    Unread {
        key: "wear.adaptive",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the error-controlled schedule of `run`'s time steps",
    },
    Unread {
        key: "wear.steps",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the duration of `run`; the steady state is where a long run ends",
    },
    Unread {
        key: "wear.cycles",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the duration of `run`; the steady state is where a long run ends",
    },
    Unread {
        key: "wear.distance",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "it is the duration of `run`; the steady state is where a long run ends",
    },
    Unread {
        key: "wear.record",
        jobs: BOTH,
        sliding: Sliding::Any,
        why: "it chooses the steps `run` records as snapshots, and a study reports no snapshots",
    },
    Unread {
        key: "wear.shape_zero_at",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "`steady` gives the shape orthogonal to the plate's rigid modes and does not shift it to zero there (docs/problem-files.md)",
    },
    // `steady` solves exact contact whatever the method (it warns about a penalty method).
    Unread {
        key: "contact.method",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "the steady state is computed with exact contact whatever the method",
    },
    Unread {
        key: "contact.penalty",
        jobs: STEADY,
        sliding: Sliding::Any,
        why: "the steady state is computed with exact contact whatever the method",
    },
    // A periodic steady state has both half cycles: which comes first does not change it
    // (only the check of the first contact solve's plate motion, a warning, uses it).
    Unread {
        key: "contact.direction",
        jobs: STEADY,
        sliding: Sliding::Reciprocating,
        why: "the steady state of reciprocating sliding is periodic: which half cycle comes first does not change it",
    },
    // Each sliding has its own kinematic settings; the other's are not read.
    Unread {
        key: "wear.speed",
        jobs: BOTH,
        sliding: Sliding::Reciprocating,
        why: "reciprocating sliding is set by wear.amplitude and wear.omega",
    },
    Unread {
        key: "wear.step_time",
        jobs: BOTH,
        sliding: Sliding::Reciprocating,
        why: "reciprocating sliding is set by wear.amplitude and wear.omega",
    },
    Unread {
        key: "wear.amplitude",
        jobs: BOTH,
        sliding: Sliding::Monotonic,
        why: "monotonic sliding is set by wear.speed and wear.step_time",
    },
    Unread {
        key: "wear.omega",
        jobs: BOTH,
        sliding: Sliding::Monotonic,
        why: "monotonic sliding is set by wear.speed and wear.step_time",
    },
    Unread {
        key: "output.vtk",
        jobs: BOTH,
        sliding: Sliding::Any,
        why: "a study writes no ParaView files",
    },
];

/// Whether `key` is `entry` or a key under it (`wear.adaptive.tolerance`,
/// `wear.extrapolation[0].k`).
fn under(key: &str, entry: &str) -> bool {
    key.strip_prefix(entry)
        .is_some_and(|rest| rest.is_empty() || rest.starts_with(['.', '[']))
}

/// The entry saying that `job` does not read `key` in any of `problems` (the study's
/// variants), if there is one. A conditional entry counts only when its sliding holds in
/// every variant: where another axis makes some variants read the key, its values matter.
pub fn unread<'a>(
    key: &str,
    job: Job,
    problems: impl IntoIterator<Item = &'a Problem>,
) -> Option<&'static Unread> {
    let entry = UNREAD
        .iter()
        .find(|u| u.jobs.contains(&job) && under(key, u.key))?;
    let holds = |p: &Problem| {
        let monotonic = p
            .spec
            .wear
            .as_ref()
            .is_some_and(|w| w.sliding == "monotonic");
        match entry.sliding {
            Sliding::Any => true,
            Sliding::Reciprocating => !monotonic,
            Sliding::Monotonic => monotonic,
        }
    };
    problems.into_iter().all(holds).then_some(entry)
}

/// One warning line per axis of the study (`variants`, all with the same axes, of the problem
/// file `file`) that `job` does not read and that takes more than one value. An axis of one
/// value only sets the key for every variant (`--set wear.record=[[]]`): no row is compared
/// with another there.
pub fn warnings(file: &str, job: Job, variants: &[Variant]) -> Vec<String> {
    let Some(first) = variants.first() else {
        return Vec::new();
    };
    let name = match job {
        Job::Steady => "steady",
        Job::Run => "run",
    };
    first
        .overrides
        .iter()
        .enumerate()
        .filter_map(|(axis, o)| {
            let values_differ = variants
                .iter()
                .any(|v| v.overrides.get(axis).is_some_and(|w| w.value != o.value));
            if !values_differ {
                return None;
            }
            let entry = unread(&o.key, job, variants.iter().map(|v| &v.problem))?;
            Some(crate::checks::codes::warning(
                "study-unread",
                file,
                format!(
                    "--set {key}: a {name} study does not read {key} ({why}): its rows are the same for every value",
                    key = o.key,
                    why = entry.why
                ),
            ))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_key_under_an_entry_is_unread_and_a_longer_name_is_not() {
        assert!(under("wear.adaptive", "wear.adaptive"));
        assert!(under("wear.adaptive.tolerance", "wear.adaptive"));
        assert!(under("wear.extrapolation[0].k", "wear.extrapolation"));
        assert!(!under("wear.steps_extra", "wear.steps"));
        assert!(!under("wear", "wear.steps"));
    }

    #[test]
    fn every_entry_is_a_key_of_the_problem_file() {
        // An entry with a misspelt key would never match an axis (a study refuses unknown
        // keys before it gets here).
        let text = crate::examples::example("punch-b40").unwrap();
        for u in UNREAD {
            let value = match u.key {
                "wear.scheme" => "\"implicit\"",
                "wear.criterion" => "\"eq27\"",
                "contact.method" => "\"active_set\"",
                "contact.direction" => "\"+\"",
                "wear.extrapolation" => "[{ k = 1 }]",
                "wear.adaptive" => "{}",
                "wear.record" => "[1]",
                "output.vtk" => "false",
                "wear.steps" | "wear.max_iterations" | "wear.substeps" => "2",
                _ => "1.0",
            };
            let o = crate::overrides::Override::parse(&format!("{}={value}", u.key)).unwrap();
            let parsed = crate::problem::Problem::with_overrides(text, "punch-b40", &[o]);
            // A value may be refused for its own sake (a duration given twice), never its key.
            if let Err(e) = parsed {
                assert!(!e.message.contains("unknown"), "{}: {e}", u.key);
            }
        }
    }
}
