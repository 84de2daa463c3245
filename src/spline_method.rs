//! The spline method of the paper's §6.2 (eq. 41–48).

use crate::paper_steady::{IterationRecord, MethodError, MethodSettings, Problem};

/// Placeholder until the method is written.
pub(crate) fn spline(
    _problem: &mut Problem,
    _averaged: &[f64],
    _settings: MethodSettings,
) -> Result<(Vec<f64>, Vec<IterationRecord>, bool), MethodError> {
    Err(MethodError::Unsupported("spline: not written yet".into()))
}
