//! Tests of the override keys, values and the reading of problem files.

#[test]
fn value_at_reads_the_file_with_its_overrides() {
    use super::{parse_value, value_at, Override};
    let text = "[contact]\nfriction = 0.25\n[plate]\npin = [1100.0, 140.0]\n";
    let set = |k: &str, v: &str| Override::new(k, parse_value(v)).unwrap();
    let at = |overrides: &[Override], key| value_at(text, "t.toml", overrides, key).unwrap();
    assert_eq!(at(&[], "contact.friction"), Some(parse_value("0.25")));
    let moved = [set("plate.pin[1]", "150.0")];
    assert_eq!(
        at(&moved, "plate.pin"),
        Some(parse_value("[1100.0, 150.0]"))
    );
    assert_eq!(at(&moved, "plate.pin[0]"), Some(parse_value("1100.0")));
    // Not in the file: the schema's default applies, which the text does not hold.
    assert_eq!(at(&[], "contact.discretisation"), None);
    assert_eq!(at(&[], "plate.pin[5]"), None);
}

#[test]
fn value_text_is_short_and_reads_back_as_the_same_value() {
    use super::{parse_value, value_text};
    for (given, shown) in [
        ("1e200", "1e200"),
        ("1e-30", "1e-30"),
        ("0.25", "0.25"),
        ("1100.0", "1100.0"),
        ("-3.5e-7", "-3.5e-7"),
        ("[1100.0, 1e200]", "[1100.0, 1e200]"),
        ("[\"a\", 2]", "[\"a\", 2]"),
        ("\"exact\"", "exact"),
        ("7", "7"),
    ] {
        let value = parse_value(given);
        let text = value_text(&value);
        assert_eq!(text, shown, "{given}");
        if !matches!(value, toml::Value::String(_)) {
            // A label or cell read back (as a --set value) is the value it labels.
            assert_eq!(parse_value(&text), value, "{given}");
        }
    }
}

#[test]
fn a_wrong_type_in_the_file_names_its_dotted_key_and_line() {
    let text = "title = 1\n[analysis]\nkind = \"plane_stress\"\n[[bodies]]\nname = \"a\"\n[[bodies.blocks]]\nu = 1\n[[bodies.blocks]]\nu = 2\n[[bodies]]\nname = \"b\"\n[[bodies.blocks]]\nv = 3\n[contact]\nfriction = \"x\"\n";
    let key = |line| key_on_line(text, line);
    assert_eq!(key(1).as_deref(), Some("title"));
    assert_eq!(key(3).as_deref(), Some("analysis.kind"));
    assert_eq!(key(7).as_deref(), Some("bodies[0].blocks[0].u"));
    assert_eq!(key(9).as_deref(), Some("bodies[0].blocks[1].u"));
    // A second body restarts the count of its blocks.
    assert_eq!(key(13).as_deref(), Some("bodies[1].blocks[0].v"));
    assert_eq!(key(15).as_deref(), Some("contact.friction"));
    assert_eq!(key(14), None, "a header");
    let e = parse_spec(text, "t.toml", &[]).unwrap_err();
    assert_eq!(e.key, "title (line 1)");
    // An unknown or missing field is named in its table, wherever the reader points.
    let e = parse_spec(
        "[analysis]\nkind = \"plane_stress\"\nfoo = 1\n",
        "t.toml",
        &[],
    )
    .unwrap_err();
    assert!(e.key.starts_with("analysis."), "{}: {}", e.key, e.message);
    assert!(e.key.contains("(line "), "{}", e.key);
}

use super::*;

#[test]
fn a_name_that_is_not_a_bare_key_is_quoted_as_in_toml() {
    // A red team's material `[materials."st.eel ü"]` could not be overridden.
    let key = |k: &str| Override::new(k, toml::Value::Float(1.0)).map(|o| o.path);
    let name = |n: &str| Segment::Key(n.into());
    assert_eq!(
        key(r#"materials."st.eel ü".young"#).unwrap(),
        [name("materials"), name("st.eel ü"), name("young")]
    );
    assert_eq!(
        key(r#"bodies[1]."a \"b\""[0]"#).unwrap(),
        [
            name("bodies"),
            Segment::Index(1),
            name("a \"b\""),
            Segment::Index(0)
        ]
    );
    for bad in [
        r#"materials."steel.young"#,
        "plate..pin",
        "bodies[1]x",
        r#"a."\q""#,
    ] {
        assert!(key(bad).is_err(), "{bad}");
    }
    // Applied to a file whose material is named so.
    let text = crate::examples::example("lame")
        .unwrap()
        .replace("[materials.steel]", "[materials.\"st.eel ü\"]")
        .replace("\"steel\"", "\"st.eel ü\"");
    let set = Override::parse(r#"materials."st.eel ü".young=1.5e5"#).unwrap();
    let spec = parse_spec(&text, "lame", &[set]).unwrap();
    assert_eq!(spec.materials["st.eel ü"].young, 1.5e5);
}

fn punch() -> &'static str {
    crate::examples::example("punch-b40").unwrap()
}

fn with(sets: &[&str]) -> Result<ProblemSpec, ProblemError> {
    let o: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    parse_spec(punch(), "f.toml", &o)
}

#[test]
fn text_with_overrides_reads_as_the_overridden_spec() {
    let o = [
        Override::parse("contact.friction=0.4").unwrap(),
        Override::parse("plate.pin=[1100, 120]").unwrap(),
    ];
    let text = apply_to_text(punch(), "f.toml", &o).unwrap();
    let spec: ProblemSpec = toml::from_str(&text).unwrap();
    assert_eq!(spec.contact.unwrap().friction, 0.4);
    assert_eq!(spec.plate.unwrap().pin, Some([1100.0, 120.0]));
    let bad = [Override::parse("bodies[7].name=x").unwrap()];
    assert_eq!(
        apply_to_text(punch(), "f.toml", &bad).unwrap_err().key,
        "bodies[7].name"
    );
}

#[test]
fn values_reach_the_schema() {
    let spec = with(&[
        "plate.pin=[1100, 120]",
        "contact.friction=0.4",
        "wear.body1.b=1.2",
        "bodies[1].blocks[0].v=8",
        "contact.method=lemke",
    ])
    .unwrap();
    assert_eq!(spec.plate.unwrap().pin, Some([1100.0, 120.0]));
    let c = spec.contact.unwrap();
    assert_eq!((c.friction, c.method.as_str()), (0.4, "lemke"));
    assert_eq!(spec.wear.unwrap().body1.unwrap().b, 1.2);
    assert!(matches!(spec.bodies[1].blocks[0].v, LinesSpec::Count(8)));
}

use crate::schema::LinesSpec;

#[test]
fn bad_keys_and_values_name_the_key() {
    let cases = [
        ("plate.pinn=[1, 2]", "plate.pinn", "pinn"),
        (
            "contact.friction=\"high\"",
            "contact.friction",
            "invalid type",
        ),
        ("plate.pin=[1, 2, 3]", "plate.pin", "two numbers"),
        ("bodies[5].name=\"x\"", "bodies[5].name", "2 entries"),
        ("contact.friction.x=1", "contact.friction.x", "not a table"),
        ("wear.steps=1.5", "wear.steps", "invalid type"),
        // A table given whole: the key inside it that is wrong, as a file names it (red
        // team I: these named the table only).
        (
            "plate={edge=\"top\", motion=\"vertical\", pinn=1}",
            "plate.pinn",
            "pinn",
        ),
        (
            "wear.body1={beta=\"x\", a=1.0, b=1.0}",
            "wear.body1.beta",
            "invalid type",
        ),
    ];
    for (set, key, fragment) in cases {
        let e = with(&[set]).unwrap_err();
        assert_eq!(
            (e.file.as_str(), e.key.as_str()),
            ("f.toml", key),
            "{set}: {e}"
        );
        assert!(e.message.contains(fragment), "{set}: {e}");
        assert_eq!(e.to_string().lines().count(), 1);
    }
}

#[test]
fn malformed_set_text_is_rejected() {
    for text in [
        "contact.friction",
        "=1",
        "a..b=1",
        "bodies[x].name=1",
        "a[1=2",
    ] {
        let e = Override::parse(text).unwrap_err();
        assert_eq!(e.file, SET, "{text}: {e}");
    }
}

/// The overridden document is read from a TOML value, the plain file from text: both
/// readers must give the same schema for the same content, in every shipped example.
#[test]
fn a_no_op_override_changes_nothing() {
    for (name, text) in crate::examples::EXAMPLES {
        let plain = parse_spec(text, name, &[]).unwrap();
        let same = Override::parse("title=\"x\"").unwrap();
        let mut via_value = parse_spec(text, name, &[same]).unwrap();
        via_value.title = plain.title.clone();
        assert_eq!(format!("{plain:?}"), format!("{via_value:?}"), "{name}");
    }
}

#[test]
fn no_overrides_reads_the_file_unchanged() {
    let spec = with(&[]).unwrap();
    assert_eq!(spec.plate.unwrap().pin, Some([1100.0, 140.0]));
}

#[test]
fn overrides_may_supply_what_the_file_lacks() {
    // Red team 19: a file without analysis.p, completed by `--set analysis.p=8`, was refused
    // ("missing field `p`") because the file was read alone first.
    let text = punch().replace("p = 8\n", "");
    let set = |s: &str| Override::parse(s).unwrap();
    let spec = parse_spec(&text, "t.toml", &[set("analysis.p=8")]).unwrap();
    assert_eq!(spec.analysis.p, 8);
    // An override that does not supply it leaves the file's own error, with its line.
    let e = parse_spec(&text, "t.toml", &[set("contact.friction=0.3")]).unwrap_err();
    assert!(e.key.starts_with("analysis.p (line "), "{}", e.key);
    // One that supplies it wrongly is named.
    let e = parse_spec(&text, "t.toml", &[set("analysis.p=x")]).unwrap_err();
    assert_eq!(e.key, "analysis.p");
}

#[test]
fn an_index_into_a_key_the_file_lacks_asks_for_the_whole_array() {
    // `wear.extrapolation[1].k` on a file without a schedule was answered "the file is a
    // table, not an array" (the missing key had been made a table on the way).
    let e = with(&["wear.extrapolation[1].k=5"]).unwrap_err();
    assert_eq!(e.key, "wear.extrapolation[1].k");
    assert!(
        e.message.contains("wear.extrapolation is not in the file")
            && e.message.contains("--set 'wear.extrapolation=[…]'"),
        "{}",
        e.message
    );
    // A missing table is still made, as before.
    assert!(with(&["wear.adaptive.method=\"bdf2\""]).is_ok());
}

#[test]
fn lines_of_a_multi_line_value_are_not_headers() {
    // Red team 21: after a `corners` list written one point per line, a syntax error (which
    // the span reading cannot parse) was named `1000.0, 100.0.material`.
    let text = "[[bodies]]\nname = \"a\"\n[[bodies.blocks]]\ncorners = [\n  [0.0, 0.0],\n  [1.0, 0.0],\n]\ndescription = \"\"\"\n[not a header]\n\"\"\"\nmaterial = \n";
    assert_eq!(
        key_on_line(text, 11).as_deref(),
        Some("bodies[0].blocks[0].material")
    );
    let e = parse_spec(text, "t.toml", &[]).unwrap_err();
    assert!(
        e.key.starts_with("bodies[0].blocks[0].material (line 11)"),
        "{}",
        e.key
    );
}

#[test]
fn an_error_of_the_file_is_not_blamed_on_an_override() {
    // Red team 21: a file without `p` and with a typo in [contact], read with `--set
    // analysis.p=8`: the typo (the next error, once `p` is supplied) was charged to the
    // override.
    let text = punch()
        .replace("p = 8\n", "")
        .replace("friction = 0.25", "frction = 0.25");
    let e = parse_spec(&text, "t.toml", &[Override::parse("analysis.p=8").unwrap()]).unwrap_err();
    // With its line in the file, as without the override (a later red team: it was lost).
    let line = 1 + text.lines().position(|l| l.starts_with("frction")).unwrap();
    assert_eq!(e.key, format!("contact.frction (line {line})"));
    // A wrong type mended around the same way keeps its line too.
    let text = punch()
        .replace("p = 8\n", "")
        .replace("friction = 0.25", "friction = \"high\"");
    let e = parse_spec(&text, "t.toml", &[Override::parse("analysis.p=8").unwrap()]).unwrap_err();
    let line = 1 + text
        .lines()
        .position(|l| l.starts_with("friction"))
        .unwrap();
    assert_eq!(e.key, format!("contact.friction (line {line})"));
}
