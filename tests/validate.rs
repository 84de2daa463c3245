//! `wearfem validate`: the quick table passes, and a broken reference makes it fail with exit
//! code 1 and a FAIL row (the hidden `--perturb ID=VALUE` replaces one reference value).

use std::process::Command;

fn validate(extra: &[&str], out: &std::path::Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(["validate", "--quick", "--out"])
        .arg(out)
        .args(extra)
        .output()
        .expect("run wearfem")
}

fn temp(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("wearfem-validate-{name}-{}", std::process::id()))
}

#[test]
fn quick_validation_passes_and_writes_markdown_and_json() {
    let out = temp("pass");
    let result = validate(&[], &out);
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(
        result.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&result.stderr)
    );
    assert!(stdout.contains("| `lame.inner` |") && !stdout.contains("FAIL"));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("validation.json")).unwrap())
            .unwrap();
    assert_eq!(json["passed"], true);
    assert!(json["checks"].as_array().unwrap().len() > 20);
    let markdown = std::fs::read_to_string(out.join("validation.md")).unwrap();
    assert!(markdown.starts_with("| id | quantity |"));
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn a_broken_reference_fails_with_exit_code_1() {
    let out = temp("fail");
    // The Lamé displacement at r = 100 mm is 0.0953 mm; 0.1 mm is 5 % off, far beyond 1e-7.
    let result = validate(&["--perturb", "lame.inner=0.1"], &out);
    assert_eq!(result.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&result.stdout);
    let row = stdout.lines().find(|l| l.contains("`lame.inner`")).unwrap();
    assert!(row.ends_with("| **FAIL** |"), "{row}");
    assert_eq!(
        stdout.matches("FAIL").count(),
        1,
        "only the broken check fails"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("validation.json")).unwrap())
            .unwrap();
    assert_eq!(json["passed"], false);
    assert!(String::from_utf8_lossy(&result.stderr).contains("1 of"));
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn an_unknown_check_id_is_bad_input() {
    let out = temp("unknown");
    let result = validate(&["--perturb", "no.such.check=1"], &out);
    assert_eq!(result.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&result.stderr).contains("no.such.check"));
    assert!(!out.exists(), "nothing is written");
}
