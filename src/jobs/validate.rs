//! `wearfem validate`: every validation claim of docs/validation.md recomputed, compared with
//! its reference (a closed form or a number printed in the paper) and judged against a stated
//! bound, as one table.
//!
//! Every value in the "ours" column is computed when the report is made; only the references
//! (closed forms evaluated here, or the paper's printed numbers) and the bounds are fixed.
//! [`Options::perturb`] replaces one reference value so that a test can see a failing check
//! make the command fail.

use serde_json::{json, Value};
use std::time::Instant;

mod axisymmetric_cases;
mod cases;
mod fretting_cases;
pub mod half_plane;
mod heat_cases;
mod part_cases;
mod partial_slip_cases;
mod sliding_cases;
mod wear_cases;

/// How a check's difference is measured and bounded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// |ours − reference| / |reference| ≤ the value.
    Relative(f64),
    /// |ours − reference| ≤ the value, in the check's unit.
    Absolute(f64),
    /// ours ≥ reference.
    AtLeast,
}

/// One row of the validation table.
#[derive(Clone, Debug)]
pub struct Check {
    /// Stable identifier (used by [`Options::perturb`]), e.g. `lame.inner`.
    pub id: String,
    /// What is compared.
    pub quantity: String,
    /// Unit of `reference` and `ours` ("" if dimensionless).
    pub unit: &'static str,
    /// The reference value.
    pub reference: f64,
    /// Where the reference comes from.
    pub source: String,
    /// Our value.
    pub ours: f64,
    /// The bound.
    pub bound: Bound,
}

impl Check {
    /// The measured difference: relative, absolute or ours − reference, per [`Bound`].
    pub fn difference(&self) -> f64 {
        match self.bound {
            Bound::Relative(_) => (self.ours - self.reference).abs() / self.reference.abs(),
            Bound::Absolute(_) => (self.ours - self.reference).abs(),
            Bound::AtLeast => self.ours - self.reference,
        }
    }

    /// Whether the check passes (a NaN never does).
    pub fn passed(&self) -> bool {
        let d = self.difference();
        match self.bound {
            Bound::Relative(b) | Bound::Absolute(b) => d <= b,
            Bound::AtLeast => d >= 0.0,
        }
    }

    fn difference_text(&self) -> String {
        let d = self.difference();
        match self.bound {
            Bound::Relative(_) => percent(d),
            Bound::Absolute(_) => format!("{d:.2e} {}", self.unit).trim_end().to_string(),
            Bound::AtLeast => format!("{d:+.3}"),
        }
    }

    fn bound_text(&self) -> String {
        match self.bound {
            Bound::Relative(b) => percent(b),
            Bound::Absolute(b) => format!("{b:.1e} {}", self.unit).trim_end().to_string(),
            Bound::AtLeast => "≥ reference".into(),
        }
    }
}

fn percent(x: f64) -> String {
    if 100.0 * x >= 1e-3 {
        format!("{:.3} %", 100.0 * x)
    } else {
        format!("{:.1e} %", 100.0 * x)
    }
}

fn value_text(x: f64, unit: &str) -> String {
    let text = if x != 0.0 && (x.abs() < 1e-2 || x.abs() >= 1e5) {
        format!("{x:.6e}")
    } else {
        format!("{x:.6}")
    };
    format!("{text} {unit}").trim_end().to_string()
}

/// What to run.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Skip the long transient runs (the b = 0.8 law, load variant 3 to 5000 steps, the brake
    /// and the steady-versus-transient comparisons that need them).
    pub quick: bool,
    /// Replace the reference value of the check with this id (a test of the failure path).
    pub perturb: Option<(String, f64)>,
}

/// Errors that stop the validation before a table exists.
#[derive(Debug, thiserror::Error)]
pub enum ValidateError {
    /// A built-in problem could not be set up or solved (a defect, not a failed check).
    #[error("validation case {case}: {message}")]
    Setup {
        /// The case.
        case: String,
        /// What went wrong.
        message: String,
    },
    /// `perturb` names no check.
    #[error("--perturb: no check has the id \"{0}\"")]
    UnknownCheck(String),
}

/// The finished table.
#[derive(Clone, Debug)]
pub struct Report {
    /// The rows, in order.
    pub checks: Vec<Check>,
    /// Whether this was the quick subset.
    pub quick: bool,
    /// Wall time, s.
    pub seconds: f64,
}

impl Report {
    /// Whether every check passed.
    pub fn passed(&self) -> bool {
        self.checks.iter().all(Check::passed)
    }

    /// Number of failed checks.
    pub fn failures(&self) -> usize {
        self.checks.iter().filter(|c| !c.passed()).count()
    }

    /// The table as Markdown.
    pub fn markdown(&self) -> String {
        let mut out = String::from(
            "| id | quantity | reference | source | ours | difference | bound | result |\n|---|---|---|---|---|---|---|---|\n",
        );
        for c in &self.checks {
            out += &format!(
                "| `{}` | {} | {} | {} | {} | {} | {} | {} |\n",
                c.id,
                c.quantity,
                value_text(c.reference, c.unit),
                c.source,
                value_text(c.ours, c.unit),
                c.difference_text(),
                c.bound_text(),
                if c.passed() { "PASS" } else { "**FAIL**" }
            );
        }
        out += &format!(
            "\n{} checks{}, {} failed.\n",
            self.checks.len(),
            if self.quick { " (--quick)" } else { "" },
            self.failures()
        );
        out
    }

    /// The table as JSON: `checks` (id, quantity, unit, reference, source, ours, difference,
    /// bound {kind, value}, passed), `passed`, `quick`, `seconds`.
    pub fn json(&self) -> Value {
        let number = crate::report::json::number;
        let checks: Vec<Value> = self
            .checks
            .iter()
            .map(|c| {
                let (kind, value) = match c.bound {
                    Bound::Relative(b) => ("relative", number(b)),
                    Bound::Absolute(b) => ("absolute", number(b)),
                    Bound::AtLeast => ("at_least", Value::Null),
                };
                json!({
                    "id": c.id, "quantity": c.quantity, "unit": c.unit,
                    "reference": number(c.reference), "source": c.source,
                    "ours": number(c.ours), "difference": number(c.difference()),
                    "bound": { "kind": kind, "value": value }, "passed": c.passed(),
                })
            })
            .collect();
        json!({ "checks": checks, "passed": self.passed(), "quick": self.quick, "seconds": self.seconds })
    }
}

/// Half-width a (mm) of a Hertz line contact measured from a solution: the elliptic profile
/// p² = p0²(1 − x²/a²) is linear in x², fitted by least squares through the points above 30 %
/// of the peak pressure (away from the contact edges, where the square-root fall is not
/// resolved by a polynomial inside an element). The contact is assumed centred at x = 0.
pub fn hertz_half_width(
    contact: &crate::contact::CondensedContact,
    solution: &crate::complementarity::ContactSolution,
) -> f64 {
    let peak = solution.pressure.iter().cloned().fold(0.0, f64::max);
    let pts: Vec<(f64, f64)> = contact
        .points
        .x
        .iter()
        .zip(&solution.pressure)
        .filter(|(_, &p)| p > 0.3 * peak)
        .map(|(x, &p)| (x[0] * x[0], p * p))
        .collect();
    let n = pts.len() as f64;
    let sx: f64 = pts.iter().map(|p| p.0).sum();
    let sy: f64 = pts.iter().map(|p| p.1).sum();
    let sxx: f64 = pts.iter().map(|p| p.0 * p.0).sum();
    let sxy: f64 = pts.iter().map(|p| p.0 * p.1).sum();
    let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    let intercept = (sy - slope * sx) / n;
    (-intercept / slope).sqrt()
}

/// Markers around the generated table in docs/validation.md.
pub const DOC_BEGIN: &str = "<!-- wearfem validate: begin -->";
/// End marker, see [`DOC_BEGIN`].
pub const DOC_END: &str = "<!-- wearfem validate: end -->";

/// `doc` with the text between [`DOC_BEGIN`] and [`DOC_END`] replaced by `table`; `None` if
/// the markers are missing.
pub fn splice(doc: &str, table: &str) -> Option<String> {
    let start = doc.find(DOC_BEGIN)? + DOC_BEGIN.len();
    let end = start + doc[start..].find(DOC_END)?;
    Some(format!(
        "{}\n\n{}\n{}",
        &doc[..start],
        table.trim_end(),
        &doc[end..]
    ))
}

/// Run every check (or the quick subset).
pub fn run(options: &Options) -> Result<Report, ValidateError> {
    let start = Instant::now();
    let mut checks = Vec::new();
    cases::elastic(&mut checks)?;
    cases::hertz(&mut checks)?;
    cases::first_solve(&mut checks)?;
    wear_cases::table2(&mut checks)?;
    wear_cases::power_laws(&mut checks, options.quick)?;
    wear_cases::load_variants(&mut checks)?;
    wear_cases::steady(&mut checks, options.quick)?;
    wear_cases::beyond(&mut checks)?;
    if !options.quick {
        wear_cases::brake(&mut checks)?;
    }
    heat_cases::conduction(&mut checks)?;
    heat_cases::thermal_strain(&mut checks)?;
    heat_cases::punch(&mut checks)?;
    part_cases::supports(&mut checks)?;
    part_cases::body_volumes(&mut checks)?;
    sliding_cases::trough(&mut checks)?;
    sliding_cases::ring(&mut checks)?;
    sliding_cases::ring_steady(&mut checks)?;
    sliding_cases::tribometer_volumes(&mut checks)?;
    axisymmetric_cases::tube(&mut checks)?;
    axisymmetric_cases::sphere(&mut checks)?;
    axisymmetric_cases::ball(&mut checks)?;
    axisymmetric_cases::punch(&mut checks)?;
    axisymmetric_cases::washer(&mut checks)?;
    partial_slip_cases::cattaneo(&mut checks)?;
    fretting_cases::cycle_energy(&mut checks)?;
    fretting_cases::final_state(&mut checks)?;
    fretting_cases::dissimilar_stick_zone(&mut checks)?;
    if let Some((id, value)) = &options.perturb {
        let check = checks
            .iter_mut()
            .find(|c| &c.id == id)
            .ok_or_else(|| ValidateError::UnknownCheck(id.clone()))?;
        check.reference = *value;
    }
    Ok(Report {
        checks,
        quick: options.quick,
        seconds: start.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(ours: f64, bound: Bound) -> Check {
        Check {
            id: "x".into(),
            quantity: "q".into(),
            unit: "MPa",
            reference: 10.0,
            source: "s".into(),
            ours,
            bound,
        }
    }

    #[test]
    fn bounds_judge_as_documented() {
        assert!(check(10.05, Bound::Relative(0.01)).passed());
        assert!(!check(10.2, Bound::Relative(0.01)).passed());
        assert!(check(10.2, Bound::Absolute(0.25)).passed());
        assert!(!check(9.7, Bound::Absolute(0.25)).passed());
        assert!(check(12.0, Bound::AtLeast).passed());
        assert!(!check(9.0, Bound::AtLeast).passed());
        assert!(!check(f64::NAN, Bound::Relative(0.01)).passed());
    }

    #[test]
    fn splice_replaces_only_the_marked_table() {
        let doc = format!("head\n{DOC_BEGIN}\nold\n{DOC_END}\ntail\n");
        let new = splice(&doc, "| new |").unwrap();
        assert_eq!(
            new,
            format!("head\n{DOC_BEGIN}\n\n| new |\n{DOC_END}\ntail\n")
        );
        assert!(splice("no markers", "x").is_none());
    }
}
