//! `wearfem._wearfem`: the compiled half of the Python package.
//!
//! A thin shell over the library: every figure comes from `wearfem::driver`,
//! `wearfem::output` or `wearfem::sweep`, as summary JSON text identical to what the command
//! line writes; the Python half (`python/wearfem/__init__.py`) turns it into numpy arrays.
//! Every computation runs with the GIL released.

use std::ops::ControlFlow;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// How often a wear run without a progress callback takes the GIL to let Python handle its
/// signals (Ctrl-C): often enough to stop at once for a person, rarely enough to cost nothing
/// (one GIL round trip per 50 ms of run).
const SIGNAL_INTERVAL: Duration = Duration::from_millis(50);

use pyo3::exceptions::PyValueError;

/// Rust allocations of the extension go to mimalloc, not glibc's malloc, whose behaviour
/// Dask's workers change (see Cargo.toml); Python's own allocations are unaffected.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use wearfem::driver::{self, JobError};
use wearfem::overrides::Override;
use wearfem::problem::{Problem, ProblemError};
use wearfem::sweep::{self, Job, Variant};

/// Raise `wearfem.WearfemError(file, key, message)` (defined in Python, a ValueError).
fn problem_error(py: Python<'_>, e: &ProblemError) -> PyErr {
    let raised = py
        .import("wearfem")
        .and_then(|m| m.getattr("WearfemError"))
        .and_then(|cls| cls.call1((&e.file, &e.key, &e.message)));
    match raised {
        Ok(value) => PyErr::from_value(value),
        Err(err) => err,
    }
}

fn job_error(py: Python<'_>, e: &JobError) -> PyErr {
    match e {
        JobError::Problem(p) => problem_error(py, p),
        // A computation that could not be carried out at all (a contact solve failed inside
        // one of the paper's §6 methods): nothing to return as a result.
        JobError::Compute(message) => pyo3::exceptions::PyRuntimeError::new_err(message.clone()),
    }
}

/// `wearfem.WearfemError("--set", key, message)`: an override value that cannot be written in a
/// problem file, named like the command line's `--set` errors.
fn set_error(py: Python<'_>, key: &str, message: String) -> PyErr {
    problem_error(
        py,
        &ProblemError {
            file: wearfem::overrides::SET.into(),
            key: key.into(),
            message,
        },
    )
}

/// A Python value (bool, int, float, str, list, tuple, dict, numpy scalar) as a TOML value;
/// anything else (None, a set, an integer beyond 64 bits) is a `WearfemError` naming `key`.
fn to_toml(value: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    let py = value.py();
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return value.extract().map(toml::Value::Integer).map_err(|_| {
            set_error(
                py,
                key,
                format!("the integer {value} does not fit in 64 bits"),
            )
        });
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(value.extract()?));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items: PyResult<Vec<_>> = value.try_iter()?.map(|v| to_toml(&v?, key)).collect();
        return Ok(toml::Value::Array(items?));
    }
    if let Ok(dict) = value.downcast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in dict.iter() {
            let k: String = k.extract().map_err(|_| {
                set_error(py, key, format!("table keys must be strings, got {k:?}"))
            })?;
            let inner = format!("{key}.{k}");
            table.insert(k, to_toml(&v, &inner)?);
        }
        return Ok(toml::Value::Table(table));
    }
    // numpy scalars and the like: integers first (`__index__`), then anything float-like.
    if let Ok(i) = value.extract::<i64>() {
        return Ok(toml::Value::Integer(i));
    }
    if let Ok(x) = value.extract::<f64>() {
        return Ok(toml::Value::Float(x));
    }
    Err(set_error(
        py,
        key,
        format!(
            "{} cannot be written in a problem file (type {})",
            value.repr()?,
            value.get_type().name()?
        ),
    ))
}

/// Overrides from a Python mapping {key: value}, in its order.
fn overrides_from(py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<Vec<Override>> {
    values
        .iter()
        .map(|(k, v)| {
            let key: String = k
                .extract()
                .map_err(|_| set_error(py, &format!("{k}"), "keys must be strings".into()))?;
            let value = to_toml(&v, &key)?;
            Override::new(&key, value).map_err(|e| problem_error(py, &e))
        })
        .collect()
}

/// A validated problem: the file text, its overrides and the model built from them.
#[pyclass(name = "Problem", module = "wearfem._wearfem", frozen)]
struct PyProblem {
    text: String,
    file: String,
    overrides: Vec<Override>,
    /// Built on creation, except for a problem restored from a pickle: there it is built on
    /// first use, because Dask's scheduler unpickles every task argument without using it,
    /// and building (parsing, validating, meshing) costs about a millisecond of the
    /// scheduler's time per variant (docs/performance.md).
    problem: OnceLock<Problem>,
}

impl PyProblem {
    fn build(
        py: Python<'_>,
        text: String,
        file: String,
        overrides: Vec<Override>,
    ) -> PyResult<Self> {
        let problem = py
            .allow_threads(|| Problem::with_overrides(&text, &file, &overrides))
            .map_err(|e| problem_error(py, &e))?;
        Ok(PyProblem {
            text,
            file,
            overrides,
            problem: OnceLock::from(problem),
        })
    }

    /// The model, built now if this problem came from a pickle. A pickle is only made of a
    /// validated problem, so this fails only for a pickle read by another version of wearfem,
    /// with the same error as building it.
    fn model(&self, py: Python<'_>) -> PyResult<&Problem> {
        if let Some(problem) = self.problem.get() {
            return Ok(problem);
        }
        let built = py
            .allow_threads(|| Problem::with_overrides(&self.text, &self.file, &self.overrides))
            .map_err(|e| problem_error(py, &e))?;
        // Two threads may build it at once; both models are the same, the first is kept.
        Ok(self.problem.get_or_init(|| built))
    }
}

#[pymethods]
impl PyProblem {
    /// Parse problem-file text, apply `overrides` ({dotted key: value}, as `--set`) and
    /// validate the result; `file` names it in error messages. The file alone need not be
    /// complete: a template may leave to the overrides what they set.
    #[staticmethod]
    #[pyo3(signature = (text, file = "<string>".to_string(), overrides = None))]
    fn from_toml(
        py: Python<'_>,
        text: String,
        file: String,
        overrides: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let overrides = match overrides {
            Some(values) => overrides_from(py, values)?,
            None => Vec::new(),
        };
        wearfem::overrides::check_together(&overrides).map_err(|e| problem_error(py, &e))?;
        PyProblem::build(py, text, file, overrides)
    }

    /// Restore from (text, file, [(key, TOML value text)]): unpickling, for process pools and
    /// Dask. The model is built on first use (see `PyProblem::problem`).
    #[staticmethod]
    fn _restore(
        py: Python<'_>,
        text: String,
        file: String,
        sets: Vec<(String, String)>,
    ) -> PyResult<Self> {
        let overrides = sets
            .iter()
            .map(|(k, v)| Override::new(k, wearfem::overrides::parse_value(v)))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| problem_error(py, &e))?;
        Ok(PyProblem {
            text,
            file,
            overrides,
            problem: OnceLock::new(),
        })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, PyObject)> {
        let py = slf.py();
        let me = slf.get();
        let sets: Vec<(String, String)> = me
            .overrides
            .iter()
            .map(|o| (o.key.clone(), o.value.to_string()))
            .collect();
        let restore = slf.get_type().getattr("_restore")?;
        let args = (me.text.clone(), me.file.clone(), sets).into_pyobject(py)?;
        Ok((restore, args.into_any().unbind()))
    }

    /// The text of built-in example `name` (None if there is none).
    #[staticmethod]
    fn _example_text(name: &str) -> Option<&'static str> {
        wearfem::examples::example(name)
    }

    /// Names of the built-in examples.
    #[staticmethod]
    fn _example_names() -> Vec<&'static str> {
        wearfem::examples::EXAMPLES.iter().map(|e| e.0).collect()
    }

    /// A new problem with `values` ({dotted key: value}) applied after this one's overrides.
    fn with_overrides(&self, py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<Self> {
        let mut overrides = self.overrides.clone();
        let new = overrides_from(py, values)?;
        // Keys of one dict must not replace one another (`contact` after `contact.friction`);
        // a later call may replace what an earlier one set.
        wearfem::overrides::check_together(&new).map_err(|e| problem_error(py, &e))?;
        overrides.extend(new);
        PyProblem::build(py, self.text.clone(), self.file.clone(), overrides)
    }

    /// The problem file with its overrides applied, as TOML text.
    fn to_toml(&self, py: Python<'_>) -> PyResult<String> {
        wearfem::overrides::apply_to_text(&self.text, &self.file, &self.overrides)
            .map_err(|e| problem_error(py, &e))
    }

    /// File name (or "built-in example NAME"), as in error messages.
    #[getter]
    fn file(&self) -> String {
        self.file.clone()
    }

    /// Title of the problem.
    #[getter]
    fn title(&self, py: Python<'_>) -> PyResult<String> {
        Ok(self.model(py)?.spec.title.clone())
    }

    /// The overrides applied, as [(key, TOML value text)].
    #[getter]
    fn overrides(&self) -> Vec<(String, String)> {
        self.overrides
            .iter()
            .map(|o| (o.key.clone(), o.value.to_string()))
            .collect()
    }

    /// Static elastic solve: summary JSON text.
    fn _elastic(&self, py: Python<'_>) -> PyResult<String> {
        let p = self.model(py)?;
        let out = py.allow_threads(|| driver::elastic(p));
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// One contact solve: summary JSON text.
    fn _contact(&self, py: Python<'_>) -> PyResult<String> {
        let p = self.model(py)?;
        let out = py.allow_threads(|| driver::contact(p).map(|r| r.0));
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// A run of sliding pairs (`contact.pairs = "sliding"`): summary JSON text. A run that
    /// stopped (a failed solve) is raised with its reason, nothing of it returned, as the
    /// command line exits 1.
    fn _run_sliding(&self, py: Python<'_>, steps: Option<usize>) -> PyResult<String> {
        let p = self.model(py)?;
        let out = py.allow_threads(|| {
            let run = wearfem::jobs::sliding::wear(p, steps)?;
            if let Some((step, reason)) = &run.history.stopped {
                return Err(JobError::Compute(format!("step {step}: {reason}")));
            }
            Ok(run.summary(p))
        });
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// A fretting problem's jobs (`[fretting]`): `job` is "contact", "run" or "steady";
    /// summary JSON text. A run that stopped (a failed solve) is raised with its reason.
    fn _fretting(&self, py: Python<'_>, job: &str, cycles: Option<f64>) -> PyResult<String> {
        let p = self.model(py)?;
        let out = py.allow_threads(|| match job {
            "contact" => wearfem::jobs::fretting::contact(p).map(|r| r.summary(p)),
            "run" => {
                let run = wearfem::jobs::fretting::run(p, cycles, |_| {})?;
                if let Some((step, reason)) = &run.history.stopped {
                    return Err(JobError::Compute(format!("step {step}: {reason}")));
                }
                Ok(run.summary(p))
            }
            _ => wearfem::jobs::fretting::steady(p).map(|r| r.summary(p)),
        });
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// Steady state: summary JSON text, with "probes" (name → contact point index) added.
    fn _steady(&self, py: Python<'_>) -> PyResult<String> {
        let p = self.model(py)?;
        if wearfem::jobs::sliding::is_sliding(p) {
            // A ring turning under body 1 (a reciprocating stroke is refused with the reason).
            let out = py.allow_threads(|| {
                let steady = wearfem::jobs::sliding_steady::steady(p)?;
                if steady.state.status != wearfem::steady::SteadyStatus::Solved {
                    return Err(JobError::Compute(format!("the steady-state iteration did not converge ({:?}, wear residual {:.3e})", steady.state.status, steady.state.wear_residual)));
                }
                let mut summary = steady.summary(p);
                summary["probe_points"] = serde_json::json!(steady.setup.probes);
                Ok(summary)
            });
            return out.map(|v| v.to_string()).map_err(|e| job_error(py, &e));
        }
        let out = py.allow_threads(|| {
            driver::steady(p).map(|(state, contact, seconds)| {
                let warnings = if state.status == wearfem::steady::SteadyStatus::Solved {
                    driver::steady_warnings(p, &contact, &state)
                } else {
                    Vec::new()
                };
                let mut summary =
                    wearfem::output::steady_summary(p, &contact, &state, seconds, &warnings);
                summary["probe_points"] = serde_json::json!(driver::contact_probes(p, &contact));
                if state.status != wearfem::steady::SteadyStatus::Solved {
                    // The command line writes nothing for an iteration that did not converge;
                    // here the status, iterations and residual are returned, but none of the
                    // last iterate's values (as for a failed contact solve).
                    for key in [
                        "p_plus",
                        "p_minus",
                        "p_sum",
                        "shape",
                        "rigid_wear_per_period",
                    ] {
                        if summary.get(key).is_some() {
                            summary[key] = serde_json::Value::Null;
                        }
                    }
                    summary["edge_ends_in_contact"] = serde_json::json!([]);
                    summary["coarse_partner_zones"] = serde_json::json!([]);
                }
                summary
            })
        });
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// Wear run: summary JSON text. `progress(step, half_period)` is called after each step.
    ///
    /// The run holds the GIL only to call `progress` and, at least every
    /// [`SIGNAL_INTERVAL`], to let Python handle its signals: Ctrl-C (KeyboardInterrupt) or an
    /// exception of `progress` stops the run after the current step, and is raised (red team
    /// 24: a notebook could only kill its kernel to stop a long run).
    #[pyo3(signature = (steps = None, progress = None))]
    fn _run(
        &self,
        py: Python<'_>,
        steps: Option<usize>,
        progress: Option<PyObject>,
    ) -> PyResult<String> {
        let p = self.model(py)?;
        let mut stopped_by: Option<PyErr> = None;
        let mut last_check = Instant::now();
        let out = py.allow_threads(|| {
            driver::wear_checked(p, steps, |s| {
                if progress.is_none() && last_check.elapsed() < SIGNAL_INTERVAL {
                    return ControlFlow::Continue(());
                }
                last_check = Instant::now();
                Python::with_gil(|py| {
                    let called = match &progress {
                        Some(f) => f.call1(py, (s.step, s.half_period)).map(drop),
                        None => Ok(()),
                    };
                    match called.and_then(|()| py.check_signals()) {
                        Ok(()) => ControlFlow::Continue(()),
                        Err(e) => {
                            stopped_by = Some(e);
                            ControlFlow::Break(())
                        }
                    }
                })
            })
            .map(|run| run.summary(p))
        });
        if let Some(e) = stopped_by {
            return Err(e);
        }
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }

    /// The settings `job` ("steady" or "run") reads, checked without solving anything: a
    /// study checks every variant so before it solves any (`wearfem::sweep::check_settings`).
    fn _check(&self, py: Python<'_>, job: &str) -> PyResult<()> {
        let job = study_job(job)?;
        let problem = self.model(py)?;
        py.allow_threads(|| sweep::check_settings(problem, job))
            .map_err(|e| problem_error(py, &e))
    }

    /// The value at dotted `key` in the file with this problem's overrides applied, as JSON
    /// text, or None where the file does not set it (the schema's default applies): a study
    /// given as a list of dicts fills a variant's cell of a key it does not override with it.
    fn _value_at(&self, py: Python<'_>, key: &str) -> PyResult<Option<String>> {
        let value = wearfem::overrides::value_at(&self.text, &self.file, &self.overrides, key)
            .map_err(|e| problem_error(py, &e))?;
        Ok(value.map(|v| serde_json::to_string(&v).expect("a TOML value is JSON")))
    }

    /// One variant of a study (`job`: "steady" or "run"): its row of `wearfem sweep`'s
    /// sweep.json as JSON text.
    fn _study_row(&self, py: Python<'_>, job: &str) -> PyResult<String> {
        let job = study_job(job)?;
        let problem = self.model(py)?;
        let out = py.allow_threads(|| {
            sweep::solve(problem, job).map(|outcome| {
                let variant = Variant {
                    overrides: self.overrides.clone(),
                    problem: problem.clone(),
                };
                let s = sweep::report::summary("", job, 1, &[variant], &[outcome], 0.0);
                s["variants"][0].clone()
            })
        });
        out.map(|v| v.to_string()).map_err(|e| job_error(py, &e))
    }
}

fn study_job(job: &str) -> PyResult<Job> {
    match job {
        "steady" => Ok(Job::Steady),
        "run" => Ok(Job::Run),
        other => Err(PyValueError::new_err(format!(
            "job must be \"steady\" or \"run\", got \"{other}\""
        ))),
    }
}

/// The keys of a study's axes checked as `wearfem sweep` checks its `--set` axes: none twice,
/// none inside a table another sets (`wearfem::overrides::check_axes`).
#[pyfunction]
fn _check_axes(py: Python<'_>, keys: Vec<String>) -> PyResult<()> {
    let keys: Vec<&str> = keys.iter().map(String::as_str).collect();
    wearfem::overrides::check_axes(&keys).map_err(|e| problem_error(py, &e))
}

/// The warning lines `wearfem sweep` prints for a study's axes that `job` does not read
/// (`wearfem::sweep::unread::warnings`): `problems` are the variants, each with the study's
/// `axes` overrides last.
#[pyfunction]
fn _study_warnings(
    py: Python<'_>,
    problems: Vec<PyRef<'_, PyProblem>>,
    job: &str,
    axes: usize,
) -> PyResult<Vec<String>> {
    let job = study_job(job)?;
    let variants = problems
        .iter()
        .map(|p| {
            let first_axis = p.overrides.len().saturating_sub(axes);
            Ok(Variant {
                overrides: p.overrides[first_axis..].to_vec(),
                problem: p.model(py)?.clone(),
            })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let file = problems.first().map(|p| p.file.clone()).unwrap_or_default();
    Ok(sweep::unread::warnings(&file, job, &variants))
}

/// The compiled module.
#[pymodule]
fn _wearfem(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyProblem>()?;
    m.add_function(wrap_pyfunction!(_check_axes, m)?)?;
    m.add_function(wrap_pyfunction!(_study_warnings, m)?)?;
    // The library's build stamp (crate version + git commit), as summary.json's
    // `wearfem_version`: a wheel out of step with the command line shows it.
    m.add("__version__", wearfem::VERSION)?;
    // A run's status when it completed no full cycle, as a study row says it.
    m.add("_NO_CYCLE", sweep::NO_CYCLE)?;
    Ok(())
}
