//! What a row of `wearfem sweep` says, against the single command with the same overrides
//! (red-team review 10): probe columns when an axis changes the probes (F4), runs that
//! complete no cycle or stop at the steady state (F6), axes the job never reads (F7), a
//! thread count above the number of variants (F8), and string values in sweep.csv (F9).

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn wearfem(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wearfem-rows-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `wearfem sweep punch-b40 ARGS --quiet --out DIR`: exit code, stderr, sweep.json, and the
/// CSV as a header and rows of cells.
fn sweep(dir: &Path, args: &[&str]) -> (i32, String, Value, Vec<String>, Vec<Vec<String>>) {
    let mut all = vec!["sweep", "punch-b40"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--quiet", "--out", dir.to_str().unwrap()]);
    let (code, _, err) = wearfem(&all);
    assert!(code == 0 || code == 1, "{args:?}: {err}");
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let mut lines = csv.lines().map(csv_cells);
    let header = lines.next().unwrap();
    (
        code,
        err,
        json(&dir.join("sweep.json")),
        header,
        lines.collect(),
    )
}

/// The cells of one CSV row, split at commas outside quotes (no line breaks in these cells).
fn csv_cells(line: &str) -> Vec<String> {
    let (mut cells, mut cell, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => cells.push(std::mem::take(&mut cell)),
            _ => cell.push(c),
        }
    }
    cells.push(cell);
    cells
}

fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

const M: &str = "M={body=\"punch\",at=[1070.0,100.0]}";
const Q: &str = "Q={body=\"punch\",at=[1100.0,100.0]}";

/// F4: an axis over `probes` gives each variant its own probe. Every probe gets its columns;
/// a solved row fills its own probe's cells with the single command's pressure there (the
/// contact point nearest the probe) and leaves only the other probe's empty.
#[test]
fn every_variant_s_probe_has_its_columns() {
    let dir = scratch("probes");
    let (code, err, summary, header, rows) =
        sweep(&dir, &["--set", &format!("probes=[{{{M}}},{{{Q}}}]")]);
    assert_eq!(code, 0, "{err}");
    let single = dir.join("single");
    let (code1, _, err1) = wearfem(&[
        "steady",
        "punch-b40",
        "--quiet",
        "--out",
        single.to_str().unwrap(),
    ]);
    assert_eq!(code1, 0, "{err1}");
    let s = json(&single.join("summary.json"));
    let floats = |v: &Value| -> Vec<f64> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    let (x, p_plus, p_minus) = (floats(&s["x"]), floats(&s["p_plus"]), floats(&s["p_minus"]));
    let nearest = |at: f64| {
        (0..x.len())
            .min_by(|&a, &b| (x[a] - at).abs().total_cmp(&(x[b] - at).abs()))
            .unwrap()
    };
    let variants = summary["variants"].as_array().unwrap();
    for (k, (own, other, at)) in [("M", "Q", 1070.0), ("Q", "M", 1100.0)]
        .into_iter()
        .enumerate()
    {
        assert_eq!(rows[k][column(&header, "status")], "solved");
        let i = nearest(at);
        for (half, expected) in [("plus", p_plus[i]), ("minus", p_minus[i])] {
            let cell = &rows[k][column(&header, &format!("p_{half}_{own}_MPa"))];
            let value: f64 = cell.parse().unwrap_or_else(|_| panic!("{own}: {cell:?}"));
            assert!(
                (value - expected).abs() <= 1e-12 * expected.abs().max(1.0),
                "{own} {half}: {value} vs {expected}"
            );
            assert_eq!(
                rows[k][column(&header, &format!("p_{half}_{other}_MPa"))],
                ""
            );
            // sweep.json agrees: the variant's own probe only, with the same value.
            let probes = variants[k][format!("probes_p_{half}")].as_object().unwrap();
            assert_eq!(probes.keys().collect::<Vec<_>>(), [own]);
            assert_eq!(probes[own].as_f64().unwrap(), value);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// F6: a run too short for one cycle exits 0 from `wearfem run` (no final profiles): its
/// study row is converged with empty value cells, and the study exits 0 as well; an adaptive
/// run that stops at the steady state has the status Python's `RunResult` gives it, built
/// from summary.json's `stopped_at_step` and `stop_reason`.
#[test]
fn a_run_row_says_what_the_single_run_says() {
    let dir = scratch("runs");
    let (code, err, summary, header, rows) = sweep(
        &dir,
        &[
            "--set",
            "wear.steps=[1,3]",
            "--set",
            "wear.record=[[1]]",
            "--run",
        ],
    );
    let variants = summary["variants"].as_array().unwrap();
    for (k, steps) in ["1", "3"].into_iter().enumerate() {
        let single = dir.join(format!("single-{steps}"));
        let (code1, _, err1) = wearfem(&[
            "run",
            "punch-b40",
            "--steps",
            steps,
            "--set",
            "wear.record=[1]",
            "--quiet",
            "--out",
            single.to_str().unwrap(),
        ]);
        assert_eq!(variants[k]["converged"], code1 == 0, "{steps}: {err1}");
        let s = json(&single.join("summary.json"));
        let has_cycle = s.get("final").is_some_and(|f| !f.is_null());
        assert_eq!(!variants[k]["p_plus"].is_null(), has_cycle, "{steps}");
        let peak = &rows[k][column(&header, "peak_p_plus_MPa")];
        assert_eq!(peak.is_empty(), !has_cycle, "{steps}: {peak:?}");
        if !has_cycle {
            assert!(
                variants[k]["status"]
                    .as_str()
                    .unwrap()
                    .contains("no full cycle"),
                "{}",
                variants[k]["status"]
            );
        }
    }
    // Both single runs exit 0, so the study does.
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("completed no full cycle") && err.contains("wear.steps=1 "),
        "{err}"
    );

    let adaptive = dir.join("adaptive");
    let (code, err, summary, _, _) = sweep(&adaptive, &["--set", "wear.adaptive=[{}]", "--run"]);
    let single = dir.join("single-adaptive");
    let (code1, _, err1) = wearfem(&[
        "run",
        "punch-b40",
        "--set",
        "wear.adaptive={}",
        "--quiet",
        "--out",
        single.to_str().unwrap(),
    ]);
    assert_eq!(code, code1, "{err} / {err1}");
    let s = json(&single.join("summary.json"));
    let row = &summary["variants"][0];
    let expected = format!(
        "stopped at step {}: {}",
        s["stopped_at_step"],
        s["stop_reason"].as_str().unwrap()
    );
    assert!(expected.contains("steady state"), "{expected}");
    assert_eq!(row["status"], expected.as_str());
    assert_eq!(row["converged"], true);
    assert_eq!(row["p_plus"], s["final"]["p_plus"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The result fields of a sweep.json row (everything but the overrides, times and warnings).
fn results(row: &Value) -> Value {
    let mut row = row.clone();
    for key in ["overrides", "seconds", "warnings"] {
        row.as_object_mut().unwrap().remove(key);
    }
    row
}

/// F7: an axis over a key the job does not read warns once, on stderr and in sweep.json, and
/// its rows' results are indeed the same (which also checks the list
/// `wearfem::sweep::unread::UNREAD` against the code); an axis the job reads, or one with a
/// single value, does not warn.
#[test]
fn an_axis_the_job_does_not_read_is_named() {
    let monotonic = [
        "--set",
        "wear.sliding=\"monotonic\"",
        "--set",
        "wear.speed=1.0",
        "--set",
        "wear.step_time=1.0",
    ];
    let run = [
        "--run",
        "--set",
        "wear.steps=20",
        "--set",
        "wear.record=[[]]",
    ];
    let cases: Vec<(&str, &str, &[&str])> = vec![
        ("wear.scheme", "[\"implicit\",\"fixed_point\"]", &[]),
        ("wear.tolerance", "[0.01,0.5]", &[]),
        (
            "wear.criterion",
            "[\"eq27\",\"pointwise\"]",
            &["--set", "wear.scheme=\"fixed_point\""],
        ),
        ("wear.max_iterations", "[50,5]", &[]),
        ("wear.substeps", "[0,4]", &[]),
        (
            "wear.extrapolation",
            "[[{k=1}],[{until=10,k=1},{k=5}]]",
            &[],
        ),
        ("wear.adaptive", "[{tolerance=1e-3},{tolerance=1e-2}]", &[]),
        ("wear.steps", "[10,1700]", &["--set", "wear.record=[[]]"]),
        ("wear.record", "[[1],[2,3]]", &[]),
        ("wear.shape_zero_at", "[1100.0,1080.0]", &[]),
        ("contact.method", "[\"active_set\",\"lemke\"]", &[]),
        ("contact.penalty", "[1e6,1e7]", &[]),
        ("contact.direction", "[\"+\",\"-\"]", &[]),
        ("wear.speed", "[1.0,2.0]", &[]),
        ("wear.step_time", "[1.0,2.0]", &[]),
        ("output.vtk", "[false,true]", &[]),
        ("wear.amplitude", "[1.5,3.0]", &monotonic),
        ("wear.omega", "[10.0,20.0]", &monotonic),
        (
            "wear.record",
            "[[1],[2,3]]",
            &["--run", "--set", "wear.steps=20"],
        ),
        ("wear.speed", "[1.0,2.0]", &run),
        ("output.vtk", "[false,true]", &run),
    ];
    for (k, (key, values, extra)) in cases.into_iter().enumerate() {
        let dir = scratch(&format!("unread{k}"));
        let mut args = vec!["--set".to_string(), format!("{key}={values}")];
        args.extend(extra.iter().map(|s| s.to_string()));
        let args: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
        let (code, err, summary, _, _) = sweep(&dir, &args);
        assert_eq!(code, 0, "{key} {extra:?}: {err}");
        let job = if extra.contains(&"--run") {
            "run"
        } else {
            "steady"
        };
        let line = format!("--set {key}: a {job} study does not read {key}");
        assert_eq!(err.matches(&line).count(), 1, "{key} {extra:?}: {err}");
        let warnings = summary["warnings"].as_array().unwrap();
        assert_eq!(warnings.len(), 1, "{key}: {warnings:?}");
        assert!(warnings[0].as_str().unwrap().contains(&line));
        let rows = summary["variants"].as_array().unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0]["converged"], true, "{key}: {}", rows[0]["status"]);
        assert_eq!(results(&rows[0]), results(&rows[1]), "{key} {extra:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }
    // Read: friction; the direction of monotonic sliding; a single value of an unread key.
    let monotonic_direction: Vec<&str> = ["--set", "contact.direction=[\"+\",\"-\"]"]
        .into_iter()
        .chain(monotonic)
        .collect();
    for args in [
        &["--set", "contact.friction=[0.1,0.25]"][..],
        &monotonic_direction[..],
        &["--set", "wear.scheme=[\"fixed_point\"]"][..],
    ] {
        let dir = scratch("read");
        let (code, err, summary, _, _) = sweep(&dir, args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(!err.contains("does not read"), "{args:?}: {err}");
        assert_eq!(summary["warnings"], serde_json::json!([]), "{args:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// F8: far more threads than variants: the study uses one per variant, finishes, and gives
/// the rows of a study on one thread.
#[test]
fn more_threads_than_variants_are_not_started() {
    let set = ["--set", "contact.friction=[0.1,0.25]"];
    let (one, many) = (scratch("j1"), scratch("jmany"));
    let (_, _, on_one, _, _) = sweep(&one, &[set[0], set[1], "-j", "1"]);
    let (code, err, on_many, _, _) = sweep(&many, &[set[0], set[1], "-j", "100000"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(on_many["threads"], 2);
    assert_eq!(on_one["threads"], 1);
    let rows = |s: &Value| -> Vec<Value> {
        s["variants"]
            .as_array()
            .unwrap()
            .iter()
            .map(results)
            .collect()
    };
    assert_eq!(rows(&on_many), rows(&on_one));
    let _ = std::fs::remove_dir_all(&one);
    let _ = std::fs::remove_dir_all(&many);
}

/// F9: an override cell holds a string as its text (quoted as CSV quotes, RFC 4180, when it
/// holds a comma or a quote) and any other value as TOML, as docs/problem-files.md says;
/// sweep.json keeps the types.
#[test]
fn override_cells_are_written_as_documented() {
    let dir = scratch("cells");
    let (code, err, summary, header, rows) = sweep(
        &dir,
        &[
            "--set",
            "title=[\"a,b\",\"say \\\"hi\\\"\",\"plain\"]",
            "--set",
            "plate.pin=[[1100,140]]",
        ],
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(header[..2], ["title", "plate.pin"]);
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert!(
        lines[1].starts_with("\"a,b\",\"[1100, 140]\","),
        "{}",
        lines[1]
    );
    assert!(lines[2].starts_with("\"say \"\"hi\"\"\","), "{}", lines[2]);
    assert_eq!(rows[2][..2], ["plain", "[1100, 140]"]);
    let variants = summary["variants"].as_array().unwrap();
    assert_eq!(variants[1]["overrides"]["title"], "say \"hi\"");
    assert_eq!(
        variants[0]["overrides"]["plate.pin"],
        serde_json::json!([1100, 140])
    );
    let _ = std::fs::remove_dir_all(&dir);
}
