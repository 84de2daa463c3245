//! The dotted key (`--set` syntax) of the place in a problem file's text that a TOML reader
//! error points at. The document is parsed with its spans, so keys inside inline tables
//! (`wear.body1.beta`, `probes.M.at`), entries of inline arrays of tables
//! (`bodies[0].supports[1].edge`) and values written over several lines are named as the user
//! would write them in `--set` (red team 19: a line-by-line reading took each line of a
//! multi-line `corners` list for a table header and skipped inline tables' names).

use toml_edit::{ImDocument, Item, Table, Value};

/// The path of the innermost key or value whose text contains byte `at` of `text`, with the
/// `[i]` of array entries; None if `text` is not TOML or `at` lies outside every key and value
/// (a comment, a blank line).
pub(super) fn key_at(text: &str, at: usize) -> Option<String> {
    let document = ImDocument::parse(text).ok()?;
    in_table(document.as_table(), at, "")
}

/// The line (1-based) where `key` (`--set` syntax: `contact.friction`, `probes.M.at`,
/// `bodies[0].blocks[1].u`) is written in `text`: its key's line, or an array entry's own.
/// None where the text does not hold it.
pub(super) fn line_of(text: &str, key: &str) -> Option<usize> {
    use super::Segment;
    /// Where the walk along the key is: a table's entry, an array-of-tables entry, or a value
    /// inside an inline table or array.
    enum Node<'a> {
        Item(&'a Item),
        Table(&'a Table),
        Value(&'a Value),
    }
    let document = ImDocument::parse(text).ok()?;
    let mut node = Node::Table(document.as_table());
    let mut span = None;
    for segment in super::parse_key(key).ok()? {
        node = match (node, segment) {
            (Node::Item(item), Segment::Key(name)) => {
                let (k, next) = item.as_table_like()?.get_key_value(&name)?;
                span = k.span().or(span);
                Node::Item(next)
            }
            (Node::Table(table), Segment::Key(name)) => {
                let (k, next) = table.get_key_value(&name)?;
                span = k.span().or(span);
                Node::Item(next)
            }
            (Node::Value(value), Segment::Key(name)) => {
                let (k, next) = value.as_inline_table()?.get_key_value(&name)?;
                span = k.span().or(span);
                Node::Item(next)
            }
            (Node::Item(Item::ArrayOfTables(array)), Segment::Index(i)) => {
                let entry = array.get(i)?;
                span = entry.span().or(span);
                Node::Table(entry)
            }
            (Node::Item(item), Segment::Index(i)) => {
                let element = item.as_array()?.get(i)?;
                span = element.span().or(span);
                Node::Value(element)
            }
            (Node::Value(value), Segment::Index(i)) => {
                let element = value.as_array()?.get(i)?;
                span = element.span().or(span);
                Node::Value(element)
            }
            (Node::Table(_), Segment::Index(_)) => return None,
        };
    }
    span.map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1)
}

/// `segment` appended to `prefix` as in `--set` keys: bare when it can be, else quoted.
fn join(prefix: &str, segment: &str) -> String {
    let bare = !segment.is_empty()
        && segment
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    let segment = if bare {
        segment.to_string()
    } else {
        format!("\"{}\"", segment.replace('\\', "\\\\").replace('"', "\\\""))
    };
    if prefix.is_empty() {
        segment
    } else {
        format!("{prefix}.{segment}")
    }
}

fn contains(span: Option<std::ops::Range<usize>>, at: usize) -> bool {
    span.is_some_and(|s| s.start <= at && at < s.end.max(s.start + 1))
}

/// A standard table: its header, or one of its entries (tables declared by their own headers
/// lie elsewhere in the text, so every entry is searched).
fn in_table(table: &Table, at: usize, path: &str) -> Option<String> {
    for (key, item) in table.iter() {
        let here = join(path, key);
        let key_span = table.key(key).and_then(|k| k.span());
        let found = match item {
            Item::Value(value) => in_value(value, at, &here)
                .or_else(|| contains(key_span.clone(), at).then(|| here.clone())),
            Item::Table(inner) => in_table(inner, at, &here)
                .or_else(|| contains(inner.span(), at).then(|| here.clone())),
            Item::ArrayOfTables(array) => array.iter().enumerate().find_map(|(i, entry)| {
                let entry_path = format!("{here}[{i}]");
                in_table(entry, at, &entry_path)
                    .or_else(|| contains(entry.span(), at).then_some(entry_path))
            }),
            Item::None => None,
        };
        if found.is_some() {
            return found;
        }
    }
    None
}

/// A value: an inline table's entry, an array's element, or the value itself.
fn in_value(value: &Value, at: usize, path: &str) -> Option<String> {
    if !contains(value.span(), at) {
        return None;
    }
    let inner = match value {
        Value::InlineTable(table) => table.iter().find_map(|(key, entry)| {
            let here = join(path, key);
            in_value(entry, at, &here).or_else(|| {
                let key_span = table.key(key).and_then(|k| k.span());
                contains(key_span, at).then_some(here)
            })
        }),
        Value::Array(array) => array
            .iter()
            .enumerate()
            .find_map(|(i, element)| in_value(element, at, &format!("{path}[{i}]"))),
        _ => None,
    };
    Some(inner.unwrap_or_else(|| path.to_string()))
}

#[cfg(test)]
mod tests {
    use super::key_at;

    fn key_of(text: &str, needle: &str) -> Option<String> {
        key_at(text, text.find(needle).expect("needle in text"))
    }

    #[test]
    fn a_key_s_line_is_where_it_is_written() {
        let text = "title = \"t\"\n[[bodies]]\nname = \"a\"\n[[bodies.blocks]]\ncorners = [\n  [0.0, 0.0],\n  [1.0, 0.0],\n]\nmaterial = 3\n[[bodies.blocks]]\nu = 4\n[wear]\nbody1 = { beta = 1e-8, a = 2 }\n[probes]\nM = { body = \"a\", at = [1.0, 2.0] }\n";
        let line = |key: &str| super::line_of(text, key);
        assert_eq!(line("title"), Some(1));
        assert_eq!(line("bodies[0].name"), Some(3));
        assert_eq!(line("bodies[0].blocks[0].corners"), Some(5));
        assert_eq!(line("bodies[0].blocks[0].corners[1]"), Some(7));
        assert_eq!(line("bodies[0].blocks[0].material"), Some(9));
        assert_eq!(line("bodies[0].blocks[1].u"), Some(11));
        assert_eq!(line("wear.body1.a"), Some(13));
        assert_eq!(line("probes.M.at"), Some(15));
        assert_eq!(line("bodies[0].blocks[2].u"), None);
        assert_eq!(line("wear.body2"), None);
        assert_eq!(line("contact.friction"), None);
    }

    #[test]
    fn keys_in_inline_tables_arrays_and_multi_line_values() {
        let text = "title = \"t\"\n[[bodies]]\nname = \"a\"\n[[bodies.blocks]]\ncorners = [\n  [0.0, 0.0],\n  [1.0, 0.0],\n]\nmaterial = 3\nsupports = [{ edge = \"base\" }, { edge = false }]\n[[bodies]]\nname = \"b\"\n[wear]\nbody1 = { beta = 1e-8, bta = 2 }\n[probes]\nM = { body = \"a\", at = [1.0, 2.0] }\n[materials.\"st eel\"]\nyoung = true\n";
        assert_eq!(
            key_of(text, "3\n").as_deref(),
            Some("bodies[0].blocks[0].material")
        );
        assert_eq!(
            key_of(text, "[1.0, 0.0]").as_deref(),
            Some("bodies[0].blocks[0].corners[1]")
        );
        assert_eq!(
            key_of(text, "false").as_deref(),
            Some("bodies[0].blocks[0].supports[1].edge")
        );
        assert_eq!(key_of(text, "\"b\"").as_deref(), Some("bodies[1].name"));
        assert_eq!(key_of(text, "bta").as_deref(), Some("wear.body1.bta"));
        assert_eq!(key_of(text, "{ body").as_deref(), Some("probes.M"));
        assert_eq!(key_of(text, "2.0]").as_deref(), Some("probes.M.at[1]"));
        assert_eq!(
            key_of(text, "true").as_deref(),
            Some("materials.\"st eel\".young")
        );
        assert_eq!(key_of(text, "[wear]").as_deref(), Some("wear"));
    }
}
