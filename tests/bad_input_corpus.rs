//! The corpus of broken problem files in `tests/bad-input/`: each file says in its first
//! lines which command to run (`# command: …`) and the message it must produce
//! (`# expect: …`). Every one must exit with code 2, print exactly one line on stderr naming
//! the file and containing the message, never panic, and write nothing.

use std::path::Path;
use std::process::Command;

fn header<'a>(text: &'a str, field: &str) -> Option<&'a str> {
    text.lines()
        .take_while(|l| l.starts_with('#'))
        .find_map(|l| l.strip_prefix(&format!("# {field}: ")))
}

#[test]
fn every_broken_file_gives_its_message() {
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad-input");
    let mut files: Vec<_> = std::fs::read_dir(&corpus)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(
        files.len() >= 25,
        "only {} files in the corpus",
        files.len()
    );
    let scratch = std::env::temp_dir().join(format!("wearfem-corpus-{}", std::process::id()));
    let mut failures = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let (Some(command), Some(expect)) = (header(&text, "command"), header(&text, "expect"))
        else {
            failures.push(format!("{name}: no '# command:' or '# expect:' line"));
            continue;
        };
        let out_dir = scratch.join(&name);
        let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .args([command, file.to_str().unwrap(), "--quiet", "--out"])
            .arg(&out_dir)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        let code = out.status.code().unwrap_or(-1);
        let problems = [
            (code != 2, format!("exit code {code}")),
            (err.contains("panicked"), "panicked".into()),
            (err.trim().lines().count() != 1, "not one line".into()),
            (!err.contains(&name), "does not name the file".into()),
            (!err.contains(expect), format!("lacks '{expect}'")),
            (out_dir.exists(), "wrote output".into()),
        ];
        for (bad, what) in problems {
            if bad {
                failures.push(format!("{name} ({command}): {what}: {}", err.trim()));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&scratch);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
