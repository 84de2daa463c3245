//! Numbers as JSON values for the summaries the jobs and checks build: non-finite values become null
//! (never NaN in a file), and named lists become objects.

use serde_json::{json, Value};

/// A finite number as JSON, `null` otherwise (JSON has no NaN; we never write one).
pub fn number(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// A vector of finite numbers as JSON.
pub fn numbers(x: &[f64]) -> Value {
    Value::Array(x.iter().map(|&v| number(v)).collect())
}

/// A JSON object {name: value} of named numbers (rigid-body unknowns and the like).
pub fn named(names: &[&str], values: &[f64]) -> Value {
    Value::Object(
        names
            .iter()
            .zip(values)
            .map(|(n, v)| (n.to_string(), number(*v)))
            .collect(),
    )
}
