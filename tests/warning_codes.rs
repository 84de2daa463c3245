//! Warning codes (issue 28, item 8): every warning is one line, `warning[CODE]: FILE: what`,
//! with a code that `wearfem explain` knows; every code the program can give is explained in
//! docs/warnings.md, and every code explained there is one the program gives.

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

/// The codes the source gives: the first argument of every `warning("CODE", …)` call.
fn codes_in_source() -> BTreeSet<String> {
    fn walk(dir: &Path, found: &mut BTreeSet<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                for (i, _) in text.match_indices("warning(") {
                    let rest = text[i + "warning(".len()..].trim_start();
                    if let Some(quoted) = rest.strip_prefix('"') {
                        let code = quoted.split('"').next().unwrap();
                        if !code.is_empty() && !code.contains(' ') && code != "CODE" {
                            found.insert(code.to_string());
                        }
                    }
                }
            }
        }
    }
    let mut found = BTreeSet::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut found,
    );
    found
}

#[test]
fn every_code_given_is_explained_and_every_explained_code_is_given() {
    let given = codes_in_source();
    let explained: BTreeSet<String> = wearfem::codes::codes()
        .into_iter()
        .map(String::from)
        .collect();
    assert!(given.len() >= 30, "{given:?}");
    let unexplained: Vec<_> = given.difference(&explained).collect();
    let unused: Vec<_> = explained.difference(&given).collect();
    assert!(
        unexplained.is_empty(),
        "codes without a section in docs/warnings.md: {unexplained:?}"
    );
    assert!(
        unused.is_empty(),
        "sections of docs/warnings.md no warning gives: {unused:?}"
    );
}

#[test]
fn wearfem_explain_prints_every_code_s_explanation() {
    let bin = env!("CARGO_BIN_EXE_wearfem");
    for code in wearfem::codes::codes() {
        let out = Command::new(bin).args(["explain", code]).output().unwrap();
        assert!(out.status.success(), "{code}");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.starts_with(code) && text.len() > 80, "{code}: {text}");
    }
    let out = Command::new(bin)
        .args(["explain", "no-such-code"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("p-check"));
}

#[test]
fn the_warnings_of_real_runs_are_coded_lines() {
    // Problems that draw many different warnings (stroke, depth, p-check, body 2 wearing, a
    // zone end in a coarse element, …): each warning is one line with a known code.
    let known = wearfem::codes::codes();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/problems");
    let mut seen = BTreeSet::new();
    for name in [
        "cylinder-wears-its-flat.toml",
        "crowned-pad-long-stroke.toml",
        "rigid-punch-deep-layers.toml",
        "thin-strip-worn.toml",
        "pad-worn-through.toml",
    ] {
        let path = dir.join(name);
        let text = std::fs::read_to_string(&path).unwrap();
        let file = path.display().to_string();
        let problem = wearfem::problem::Problem::from_toml(&text, &file).unwrap();
        let warnings: Vec<String> = if problem.spec.wear.is_some() {
            let run = wearfem::driver::wear(&problem, Some(40), |_| {}).unwrap();
            run.warnings(&problem).to_vec()
        } else {
            let (summary, ..) = wearfem::driver::contact(&problem).unwrap();
            summary["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .map(|w| w.as_str().unwrap().to_string())
                .collect()
        };
        for w in warnings {
            assert!(!w.contains('\n'), "{name}: {w}");
            let code =
                wearfem::codes::code_of(&w).unwrap_or_else(|| panic!("{name}: no code: {w}"));
            assert!(known.contains(&code), "{name}: unknown code {code}");
            assert!(w.contains(&file), "{name}: {w}");
            // One line, short enough to read: the explanation is in docs/warnings.md.
            assert!(w.len() < 450, "{name}: {} characters: {w}", w.len());
            seen.insert(code.to_string());
        }
    }
    assert!(seen.len() >= 3, "{seen:?}");
}
