//! Output: the summary JSON and CSV files that every command writes, assembled from the
//! results of the earlier stages. This is the only module that touches the file system.

use serde_json::{json, Value};
use std::fs;
use std::io::Write;
use std::path::Path;

/// Errors writing results.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {source}")]
pub struct OutputError {
    /// The file.
    pub path: String,
    /// Why.
    pub source: std::io::Error,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |source| OutputError {
        path: path.display().to_string(),
        source,
    }
}

/// Write `value` as pretty JSON to `dir/name`, creating `dir`.
pub fn write_json(dir: &Path, name: &str, value: &Value) -> Result<(), OutputError> {
    fs::create_dir_all(dir).map_err(io(dir))?;
    let path = dir.join(name);
    let text = serde_json::to_string_pretty(value).expect("JSON values always serialise");
    fs::write(&path, text + "\n").map_err(io(&path))
}

/// Write a CSV file with a header and rows of numbers or strings.
pub fn write_csv(
    dir: &Path,
    name: &str,
    header: &[&str],
    rows: &[Vec<Value>],
) -> Result<(), OutputError> {
    fs::create_dir_all(dir).map_err(io(dir))?;
    let path = dir.join(name);
    let mut file = std::io::BufWriter::new(fs::File::create(&path).map_err(io(&path))?);
    let mut text = header.join(",");
    text.push('\n');
    for row in rows {
        let cells: Vec<String> = row
            .iter()
            .map(|v| match v {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            })
            .collect();
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    file.write_all(text.as_bytes()).map_err(io(&path))
}

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
