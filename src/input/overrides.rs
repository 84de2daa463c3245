//! Overrides: `KEY=VALUE` changes to a problem file, as given by `--set` on the command line
//! or by a parameter study ([`crate::sweep`]).
//!
//! An override is applied to the parsed TOML document *before* it is read into the schema, so
//! an overridden value passes exactly the checks of a value written in the file: a key that
//! the schema does not know, or a value of the wrong type, is an error naming the key.
//!
//! **Key syntax.** A dotted path of TOML bare keys, with `[i]` (from 0, file order) to pick
//! an entry of an array of tables: `plate.pin`, `contact.friction`, `wear.body1.b`,
//! `materials.steel.young`, `bodies[1].blocks[0].u`, `bodies[0].tractions[0].normal`.
//! Missing tables on the way are created (`wear.body2.beta` adds a `body2` table), so a key
//! the file omits but the schema allows can be set; the finished table must then still be
//! complete (`missing field …` otherwise).
//!
//! **Value syntax.** A TOML value as it would be written after `=` in the file: `0.3`,
//! `[1100, 140]`, `"lemke"`, `{ beta = 1e-8, b = 1.2 }`. A bare word that is not TOML
//! (`lemke`) is taken as a string, to spare the shell quoting.

use crate::problem::ProblemError;
use crate::schema::ProblemSpec;
use line_keys::{error_key, key_on_line, named_field_key};

/// One override: a dotted key path and the TOML value to put there.
#[derive(Clone, Debug, PartialEq)]
pub struct Override {
    /// The key as written (`bodies[1].blocks[0].u`), for messages and output columns.
    pub key: String,
    /// The value.
    pub value: toml::Value,
    path: Vec<Segment>,
}

#[derive(Clone, Debug, PartialEq)]
enum Segment {
    Key(String),
    Index(usize),
}

/// Where override errors that concern the command line itself (not a file) are reported.
pub const SET: &str = "--set";

fn set_error(key: &str, message: impl Into<String>) -> ProblemError {
    ProblemError {
        file: SET.into(),
        key: key.into(),
        message: message.into(),
    }
}

impl Override {
    /// An override of `key` with `value`; the key's syntax is checked here, its existence in
    /// the schema when it is applied.
    pub fn new(key: &str, value: toml::Value) -> Result<Override, ProblemError> {
        Ok(Override {
            key: key.to_string(),
            value,
            path: parse_key(key)?,
        })
    }

    /// Parse `KEY=VALUE` (the text of one `--set`).
    pub fn parse(text: &str) -> Result<Override, ProblemError> {
        let (key, value) = split(text)?;
        Override::new(key, parse_value(value))
    }

    /// The value as TOML text (`[1100, 140]`, `0.25`), for output columns.
    pub fn value_text(&self) -> String {
        value_text(&self.value)
    }

    /// Whether applying `self` after `earlier` replaces `earlier`'s value: `self` names the
    /// same key, or a table that holds it (`contact` after `contact.friction`).
    pub fn replaces(&self, earlier: &Override) -> bool {
        earlier.path.starts_with(&self.path)
    }
}

/// Overrides given together (the `--set`s of one command, one Python dict) are applied in
/// order, so one that replaces an earlier one ([`Override::replaces`]) would drop its value
/// without a word; refused, naming the later key. (Overrides added later to a problem that
/// already has some, as Python's chained `with_overrides`, replace on purpose.)
pub fn check_together(overrides: &[Override]) -> Result<(), ProblemError> {
    for (j, later) in overrides.iter().enumerate() {
        if let Some(earlier) = overrides[..j].iter().find(|e| later.replaces(e)) {
            let message = if earlier.key == later.key {
                "is given twice; give it once".to_string()
            } else {
                format!(
                    "sets a table that holds {0}, given before it, and would replace its value; give one or the other, or {0} after it",
                    earlier.key
                )
            };
            return Err(set_error(&later.key, message));
        }
    }
    Ok(())
}

/// The keys of a study's axes must set disjoint parts of the file: an axis whose key names a
/// table holding another axis's key (`contact` and `contact.friction`) would replace or
/// rewrite that axis's value in every variant, and its column would list values that were not
/// the ones used. Refused, naming the later key.
pub fn check_axes(keys: &[&str]) -> Result<(), ProblemError> {
    let paths = keys
        .iter()
        .map(|k| parse_key(k))
        .collect::<Result<Vec<_>, _>>()?;
    for j in 1..paths.len() {
        for i in 0..j {
            let (a, b) = (&paths[i], &paths[j]);
            if a == b {
                return Err(set_error(
                    keys[j],
                    "is given twice; give all its values in one list",
                ));
            }
            if a.starts_with(b) || b.starts_with(a) {
                return Err(set_error(
                    keys[j],
                    format!(
                        "overlaps the axis {}: one sets a table that holds the other, so a row would list a value that was not the one used; vary only one of them",
                        keys[i]
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// Split `KEY=VALUE` at the first `=`.
pub fn split(text: &str) -> Result<(&str, &str), ProblemError> {
    match text.split_once('=') {
        Some((key, value)) if !key.trim().is_empty() && !value.trim().is_empty() => {
            Ok((key.trim(), value.trim()))
        }
        _ => Err(set_error(
            text,
            "expected KEY=VALUE, for example contact.friction=0.3",
        )),
    }
}

/// A TOML value from its text; a bare word that is not TOML becomes a string.
pub fn parse_value(text: &str) -> toml::Value {
    match toml::from_str::<toml::Table>(&format!("value = {text}")) {
        Ok(mut table) => table
            .remove("value")
            .unwrap_or(toml::Value::String(text.into())),
        Err(_) => toml::Value::String(text.into()),
    }
}

/// A TOML value as inline text, for labels and table cells. A finite float is written as the
/// shortest text that reads back as the same number, with an exponent where that is shorter
/// (`1e200`, `1e-30`, `0.25`): TOML's own text writes every digit (201 of them for 1e200).
pub fn value_text(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => s.clone(),
        other => inline_text(other),
    }
}

/// `value` as TOML inline text (strings quoted), floats as in [`value_text`].
fn inline_text(value: &toml::Value) -> String {
    match value {
        toml::Value::Float(f) if f.is_finite() => format!("{f:?}"),
        toml::Value::Array(items) => {
            let items: Vec<String> = items.iter().map(inline_text).collect();
            format!("[{}]", items.join(", "))
        }
        other => other.to_string(),
    }
}

fn parse_key(key: &str) -> Result<Vec<Segment>, ProblemError> {
    let bad = |why: &str| {
        set_error(
            key,
            format!("{why}; a key is a dotted path such as plate.pin or bodies[1].blocks[0].u"),
        )
    };
    let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
    let mut path = Vec::new();
    let mut rest = key;
    loop {
        // A name: bare (`steel`) or quoted as in TOML (`"st.eel 2"`, for names that are not
        // bare keys; `\"` and `\\` inside).
        let name;
        if let Some(quoted) = rest.strip_prefix('"') {
            let mut text = String::new();
            let mut chars = quoted.char_indices();
            let mut end = None;
            while let Some((i, c)) = chars.next() {
                match c {
                    '"' => {
                        end = Some(i);
                        break;
                    }
                    '\\' => match chars.next() {
                        Some((_, e @ ('"' | '\\'))) => text.push(e),
                        _ => return Err(bad("only \\\" and \\\\ may follow \\ in a quoted name")),
                    },
                    c => text.push(c),
                }
            }
            let end = end.ok_or_else(|| bad("unclosed \""))?;
            name = text;
            rest = &quoted[end + 1..];
        } else {
            let len = rest.find(['.', '[']).unwrap_or(rest.len());
            let part = &rest[..len];
            if part.is_empty() || !part.chars().all(bare) {
                let shown = rest.split('.').next().unwrap_or(rest);
                return Err(bad(&format!("\"{shown}\" is not a key name")));
            }
            name = part.to_string();
            rest = &rest[len..];
        }
        path.push(Segment::Key(name));
        while let Some(inside) = rest.strip_prefix('[') {
            let close = inside.find(']').ok_or_else(|| bad("unclosed ["))?;
            let index = inside[..close]
                .trim()
                .parse::<usize>()
                .map_err(|_| bad(&format!("\"[{}]\" is not an index", &inside[..close])))?;
            path.push(Segment::Index(index));
            rest = &inside[close + 1..];
        }
        match rest.strip_prefix('.') {
            Some(next) => rest = next,
            None if rest.is_empty() => return Ok(path),
            None => return Err(bad(&format!("unexpected \"{rest}\" after an index"))),
        }
    }
}

/// Put `o.value` at `o`'s path in `table`; the error says why the path cannot be followed.
fn apply(table: &mut toml::Table, o: &Override) -> Result<(), String> {
    let Some((last, inner)) = o.path.split_last() else {
        return Err("empty key".into());
    };
    let mut here = TableOrValue::Table(table);
    let mut walked = String::new();
    for (j, segment) in inner.iter().enumerate() {
        // A missing key is made a table, unless an index follows: an array cannot be made
        // entry by entry (`wear.extrapolation[1].k` on a file without the schedule was
        // answered "is a table, not an array").
        let before_index = matches!(o.path.get(j + 1), Some(Segment::Index(_)));
        here = here.step(segment, &mut walked, !before_index)?;
    }
    here.set(last, o.value.clone(), &walked)
}

enum TableOrValue<'a> {
    Table(&'a mut toml::Table),
    Value(&'a mut toml::Value),
}

impl<'a> TableOrValue<'a> {
    fn step(
        self,
        segment: &Segment,
        walked: &mut String,
        create: bool,
    ) -> Result<TableOrValue<'a>, String> {
        let name = walked.clone();
        let missing = |k: &str| {
            let key = if name.is_empty() {
                k.to_string()
            } else {
                format!("{name}.{k}")
            };
            format!("{key} is not in the file, so it has no entries to index: give the whole array (--set '{key}=[…]')")
        };
        let next = match (self, segment) {
            (TableOrValue::Table(t), Segment::Key(k))
            | (TableOrValue::Value(toml::Value::Table(t)), Segment::Key(k)) => {
                if !t.contains_key(k) {
                    if !create {
                        return Err(missing(k));
                    }
                    t.insert(k.clone(), toml::Value::Table(Default::default()));
                }
                t.get_mut(k).expect("present or just inserted")
            }
            (TableOrValue::Value(toml::Value::Array(a)), Segment::Index(i)) => {
                let n = a.len();
                a.get_mut(*i).ok_or_else(|| {
                    format!(
                        "{name} has {n} entries (indices 0 … {}), so [{i}] does not exist",
                        n.max(1) - 1
                    )
                })?
            }
            (TableOrValue::Value(v), Segment::Index(i)) => {
                return Err(format!(
                    "{name} is {}, not an array, so [{i}] does not exist",
                    kind(v)
                ))
            }
            (TableOrValue::Value(v), Segment::Key(k)) => {
                return Err(format!(
                    "{name} is {}, not a table, so it has no key \"{k}\"",
                    kind(v)
                ))
            }
            (TableOrValue::Table(_), Segment::Index(i)) => {
                return Err(format!("the file is a table, not an array: [{i}]"))
            }
        };
        match segment {
            Segment::Key(k) if walked.is_empty() => walked.push_str(k),
            Segment::Key(k) => {
                walked.push('.');
                walked.push_str(k)
            }
            Segment::Index(i) => walked.push_str(&format!("[{i}]")),
        }
        Ok(TableOrValue::Value(next))
    }

    fn set(self, segment: &Segment, value: toml::Value, walked: &str) -> Result<(), String> {
        match (self, segment) {
            (TableOrValue::Table(t), Segment::Key(k))
            | (TableOrValue::Value(toml::Value::Table(t)), Segment::Key(k)) => {
                t.insert(k.clone(), value);
                Ok(())
            }
            (here, segment) => {
                let mut walked = walked.to_string();
                match here.step(segment, &mut walked, false)? {
                    TableOrValue::Value(slot) => {
                        *slot = value;
                        Ok(())
                    }
                    TableOrValue::Table(_) => unreachable!("step always returns a value"),
                }
            }
        }
    }
}

fn kind(v: &toml::Value) -> &'static str {
    match v {
        toml::Value::String(_) => "a string",
        toml::Value::Integer(_) | toml::Value::Float(_) => "a number",
        toml::Value::Boolean(_) => "a boolean",
        toml::Value::Datetime(_) => "a date",
        toml::Value::Array(_) => "an array",
        toml::Value::Table(_) => "a table",
    }
}

/// One line from a TOML reader message, whatever its layout.
pub(crate) fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Read a problem file's text into the schema, with `overrides` applied in order.
///
/// Errors in the file itself name its line (as without overrides); an override that names a
/// key the schema does not know, follows a path that does not exist, or gives a value of the
/// wrong type is reported as `FILE: KEY: message` with the override's key.
pub fn parse_spec(
    text: &str,
    file: &str,
    overrides: &[Override],
) -> Result<ProblemSpec, ProblemError> {
    let file_error = |e: toml::de::Error| {
        let key = match e.span() {
            Some(span) => {
                let start = span.start.min(text.len());
                let line = text[..start].matches('\n').count() + 1;
                let key = error_key(text, start, e.message())
                    .or_else(|| named_field_key(text, line, e.message()))
                    .or_else(|| key_on_line(text, line));
                match key {
                    Some(key) => format!("{key} (line {line})"),
                    None => format!("line {line}"),
                }
            }
            None => "(file)".into(),
        };
        ProblemError {
            file: file.into(),
            key,
            message: one_line(e.message()),
        }
    };
    if overrides.is_empty() {
        return toml::from_str::<ProblemSpec>(text).map_err(file_error);
    }
    let mut table: toml::Table = toml::from_str(text).map_err(file_error)?;
    for o in overrides {
        apply(&mut table, o).map_err(|message| ProblemError {
            file: file.into(),
            key: o.key.clone(),
            message,
        })?;
    }
    // Read once with every override applied; only a failed reading is worth the work of
    // finding whom to charge (a study builds hundreds of variants, each read once).
    match toml::Value::Table(table).try_into::<ProblemSpec>() {
        Ok(spec) => Ok(spec),
        Err(_) => Err(charge_failure(text, file, overrides, file_error)),
    }
}

/// The error of a file whose reading with `overrides` applied fails: charged to the file, or
/// to the override after which the reading failed for good.
fn charge_failure(
    text: &str,
    file: &str,
    overrides: &[Override],
    file_error: impl Fn(toml::de::Error) -> ProblemError,
) -> ProblemError {
    // The file is read on its own first, so that its own errors keep their line numbers.
    let alone = toml::from_str::<ProblemSpec>(text);
    let mut table: toml::Table = match toml::from_str(text) {
        Ok(table) => table,
        Err(e) => return file_error(e),
    };
    // A file may lack what its overrides supply (a template completed by `--set`), so a
    // failed reading is charged to the file until an override changes it, then to that
    // override: the reading is repeated after each, and the last one fails (else the
    // caller would not be here).
    let mut failure: Option<(Option<&Override>, toml::de::Error)> = alone.err().map(|e| (None, e));
    for o in overrides {
        if apply(&mut table, o).is_err() {
            // Not reached: the caller applied every override without error.
            return ProblemError {
                file: file.into(),
                key: o.key.clone(),
                message: "could not be applied".into(),
            };
        }
        match toml::Value::Table(table.clone()).try_into::<ProblemSpec>() {
            Ok(_) => failure = None,
            Err(e) => {
                let same = failure
                    .as_ref()
                    .is_some_and(|(_, f)| f.message() == e.message());
                if !same {
                    failure = Some((Some(o), e));
                }
            }
        }
    }
    match failure {
        Some((Some(o), e)) => ProblemError {
            file: file.into(),
            // The reader stops at its first error, so an override that mends one error of the
            // file shows the next: charge the override only if the error is at its key
            // (red team 21: a typo in [contact] was blamed on `--set analysis.p=8`).
            key: match key_in(&table, e.message()) {
                // An error of the file itself, with its line when the file writes the key
                // (red team: the line was lost when an override mended another error); not
                // where another override wrote the key, whose value is then not the file's
                // (review M: `--set contact.friction="high"` was given the file's line).
                Some(key) if !concerns(&key, &o.key) => {
                    let written = overrides.iter().any(|other| concerns(&key, &other.key));
                    match located::line_of(text, &key).filter(|_| !written) {
                        Some(line) => format!("{key} (line {line})"),
                        None => key,
                    }
                }
                // Inside a table the override gives (`plate={…, pinn=1}`): the key in it.
                Some(key) if key.len() > o.key.len() && concerns(&key, &o.key) => key,
                _ => o.key.clone(),
            },
            message: one_line(e.message()),
        },
        Some((None, e)) => file_error(e),
        // Not reached: the last reading failed.
        None => ProblemError {
            file: file.into(),
            key: "(file)".into(),
            message: "could not be read".into(),
        },
    }
}

/// The `title` of a problem file's text ("" where it has none or cannot be read), without
/// reading the rest into the schema: the title of a template whose other keys come from
/// overrides.
pub fn file_title(text: &str) -> String {
    toml::from_str::<toml::Table>(text)
        .ok()
        .and_then(|t| t.get("title")?.as_str().map(str::to_string))
        .unwrap_or_default()
}

/// The dotted key of the reading error `message` in `table` (the file with its overrides),
/// found by reading the table written out as text, whose spans the error then has.
fn key_in(table: &toml::Table, message: &str) -> Option<String> {
    let text = toml::to_string(table).ok()?;
    let error = toml::from_str::<ProblemSpec>(&text).err()?;
    if error.message() != message {
        return None;
    }
    error_key(&text, error.span()?.start.min(text.len()), message)
}

/// Whether an error at `key` concerns the override of `set`: the same key, one inside it, or
/// a table that holds it.
fn concerns(key: &str, set: &str) -> bool {
    let within = |inner: &str, outer: &str| {
        inner == outer
            || inner.starts_with(&format!("{outer}."))
            || inner.starts_with(&format!("{outer}["))
    };
    within(key, set) || within(set, key)
}

/// A problem file's text with `overrides` applied, as TOML text (for `Problem.to_toml` in
/// Python, and to save the variant of a study). Only the reading is checked here; validate the
/// result with [`crate::problem::Problem::from_toml`].
pub fn apply_to_text(
    text: &str,
    file: &str,
    overrides: &[Override],
) -> Result<String, ProblemError> {
    let table = applied_table(text, file, overrides)?;
    toml::to_string(&table).map_err(|e| ProblemError {
        file: file.into(),
        key: "(file)".into(),
        message: one_line(&e.to_string()),
    })
}

/// A problem file's text read as a TOML table, with `overrides` applied.
fn applied_table(
    text: &str,
    file: &str,
    overrides: &[Override],
) -> Result<toml::Table, ProblemError> {
    let error = |key: &str, message: String| ProblemError {
        file: file.into(),
        key: key.into(),
        message,
    };
    let mut table: toml::Table =
        toml::from_str(text).map_err(|e| error("(file)", one_line(e.message())))?;
    for o in overrides {
        apply(&mut table, o).map_err(|m| error(&o.key, m))?;
    }
    Ok(table)
}

/// The value at `key` in a problem file's text with `overrides` applied: what a variant of a
/// study has at a key that other variants override (None where the file does not set it and
/// the schema's default applies).
pub fn value_at(
    text: &str,
    file: &str,
    overrides: &[Override],
    key: &str,
) -> Result<Option<toml::Value>, ProblemError> {
    let table = applied_table(text, file, overrides)?;
    let mut here = None::<&toml::Value>;
    for segment in parse_key(key)? {
        let next = match (here, &segment) {
            (None, Segment::Key(k)) => table.get(k),
            (Some(toml::Value::Table(t)), Segment::Key(k)) => t.get(k),
            (Some(toml::Value::Array(a)), Segment::Index(i)) => a.get(*i),
            _ => None,
        };
        match next {
            Some(value) => here = Some(value),
            None => return Ok(None),
        }
    }
    Ok(here.cloned())
}

mod line_keys;
mod located;
#[cfg(test)]
mod tests;
