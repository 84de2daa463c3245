//! Where an error of the TOML reader lies in a problem file, as the dotted key `--set`
//! writes (`bodies[1].blocks[0].u`): the table of the last header above a line, with the
//! index of each array-of-tables entry, and the key on that line or named in the message.

/// The dotted key (`--set` syntax) of the `key = value` on line `line` (1-based) of a problem
/// file: its table from the last header above it, counting `[[…]]` entries (`bodies[1].blocks[0]`),
/// then the key. None for a header, a line without `=`, or a multi-line value's inner line.
pub(super) fn key_on_line(text: &str, line: usize) -> Option<String> {
    let lines: Vec<&str> = text.lines().collect();
    let here = lines.get(line.checked_sub(1)?)?.trim();
    if here.starts_with('[') || here.starts_with('#') {
        return None;
    }
    let key = here.split_once('=')?.0.trim();
    let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-' || c == '.';
    if key.is_empty() || !key.chars().all(bare) {
        return None;
    }
    let table = table_above(&lines, line - 1);
    Some(if table.is_empty() {
        key.to_string()
    } else {
        format!("{table}.{key}")
    })
}

/// The dotted key of a field the TOML reader names in `message` ("unknown field `foo`, …",
/// "missing field `bar`"), in the table that line `line` (1-based; its header or a key of it)
/// belongs to: the line itself holds no key of that name.
pub(super) fn named_field_key(text: &str, line: usize, message: &str) -> Option<String> {
    let field = ["unknown field `", "missing field `"]
        .iter()
        .find_map(|p| message.strip_prefix(p))?
        .split('`')
        .next()?;
    let lines: Vec<&str> = text.lines().collect();
    let table = table_above(&lines, line);
    Some(if table.is_empty() {
        field.to_string()
    } else {
        format!("{table}.{field}")
    })
}

/// The dotted key of a reader error at byte `at` of `text`: the key or value there
/// ([`located::key_at`]), with the field the message names ("unknown field `foo`", "missing
/// field `bar`") appended when the place is its table. None where no key or value holds `at`.
pub(super) fn error_key(text: &str, at: usize, message: &str) -> Option<String> {
    let place = super::located::key_at(text, at)?;
    let field = ["unknown field `", "missing field `"]
        .iter()
        .find_map(|p| message.strip_prefix(p))
        .and_then(|rest| rest.split('`').next());
    let Some(field) = field else {
        return Some(place);
    };
    // The reader points at the unknown key itself, or at the header of an unknown array of
    // tables (`[[bodiez]]`: the place is `bodiez[0]`), or at the table missing the field.
    let entry = place.trim_end_matches(|c: char| c.is_ascii_digit() || c == '[' || c == ']');
    Some(if entry == field || entry.ends_with(&format!(".{field}")) {
        entry.to_string()
    } else {
        format!("{place}.{field}")
    })
}

/// The table (as `--set` writes it: `bodies[1].blocks[0]`) that the last header among the
/// first `end` lines opens, counting `[[…]]` entries; "" before any header.
fn table_above(lines: &[&str], end: usize) -> String {
    let mut counts: std::collections::HashMap<String, usize> = Default::default();
    let mut table = String::new();
    // Lines inside a value written over several lines (an array of corners, a long string)
    // are not headers, whatever they start with (red team 21: `[1000.0, 100.0],` was one).
    let mut depth = 0i64;
    let mut in_long_string = false;
    for l in &lines[..end.min(lines.len())] {
        let l = l.trim();
        let inside = depth > 0 || in_long_string;
        (depth, in_long_string) = nesting_after(l, depth, in_long_string);
        if inside {
            continue;
        }
        if l.starts_with('[') {
            // A header: its own brackets do not open a value.
            depth = 0;
        }
        if let Some(name) = l.strip_prefix("[[").and_then(|r| r.split("]]").next()) {
            let name = name.trim().to_string();
            // A new entry of a parent restarts the counts of its children.
            counts.retain(|k, _| !k.starts_with(&format!("{name}.")));
            *counts.entry(name.clone()).or_insert(0) += 1;
            table = indexed(&name, &counts);
        } else if let Some(name) = l.strip_prefix('[').and_then(|r| r.split(']').next()) {
            table = indexed(name.trim(), &counts);
        }
    }
    table
}

/// The bracket depth of values and whether a triple-quoted string is open after `line`,
/// from those before it; quotes and comments are skipped (roughly: enough to tell the lines
/// of a value written over several lines from headers).
fn nesting_after(line: &str, mut depth: i64, mut in_long_string: bool) -> (i64, bool) {
    let mut rest = line;
    while !rest.is_empty() {
        if in_long_string {
            match rest.find("\"\"\"").or_else(|| rest.find("'''")) {
                Some(i) => {
                    in_long_string = false;
                    rest = &rest[i + 3..];
                }
                None => return (depth, true),
            }
            continue;
        }
        if rest.starts_with("\"\"\"") || rest.starts_with("'''") {
            in_long_string = true;
            rest = &rest[3..];
            continue;
        }
        let mut chars = rest.chars();
        let c = chars.next().unwrap_or(' ');
        match c {
            '#' => break,
            '"' | '\'' => {
                // A one-line string: skip to its closing quote.
                let body = &rest[1..];
                let close = body.find(c).map_or(body.len(), |i| i + 1);
                rest = &body[close.min(body.len())..];
                continue;
            }
            '[' | '{' => depth += 1,
            ']' | '}' => depth -= 1,
            _ => {}
        }
        rest = chars.as_str();
    }
    (depth.max(0), in_long_string)
}

/// `a.b.c` with each prefix that is an array of tables given its current index (count − 1).
fn indexed(name: &str, counts: &std::collections::HashMap<String, usize>) -> String {
    let mut out = String::new();
    let mut prefix = String::new();
    for part in name.split('.') {
        if !prefix.is_empty() {
            prefix.push('.');
            out.push('.');
        }
        prefix.push_str(part);
        out.push_str(part);
        if let Some(n) = counts.get(&prefix) {
            out.push_str(&format!("[{}]", n - 1));
        }
    }
    out
}
