//! Output files of the new input forms: monotonic runs write no '−', summed or δw columns;
//! a wear law given as Archard's k, and a duration given in cycles, give the run of the
//! equivalent β̃ and steps.

use std::process::Command;
use wearfem::driver;
use wearfem::overrides::Override;
use wearfem::problem::Problem;

fn punch(sets: &[&str]) -> Problem {
    let o: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
    Problem::with_overrides(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
        &o,
    )
    .unwrap()
}

#[test]
fn monotonic_runs_write_no_minus_columns() {
    let dir = std::env::temp_dir().join(format!("wearfem-mono-{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(["run", "punch-b40", "--steps", "20", "--quiet", "--out"])
        .arg(&dir)
        .args(["--set", "wear.sliding=monotonic", "--set", "wear.speed=10"])
        .args(["--set", "wear.step_time=0.3"])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let header = |name: &str| {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        text.lines().next().unwrap().to_string()
    };
    assert_eq!(
        header("final.csv"),
        "x_mm,p_plus_MPa,shape_mm,wear_mm,wear_body1_mm,wear_body2_mm"
    );
    assert!(!header("history.csv").contains("delta_w"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert!(summary["final"].get("p_minus").is_none());
    assert!(summary["final"].get("p_sum").is_none());
    assert!(summary["steps"][0].get("delta_w").is_none());
    // 20 steps of the paper's schedule slide 20 step units of v · step_time = 3 mm: 0.06 m.
    let d = summary["sliding_distance_m"].as_f64().unwrap();
    assert!((d - 0.06).abs() < 1e-15, "{d}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn archard_k_and_cycles_give_the_equivalent_run() {
    // β̃ = 1.25π·10⁻⁸ MPa⁻¹ is k = 1000 β̃ mm³/(N·m) (docs/problem-files.md).
    let beta = punch(&["wear.steps=120", "wear.record=[]"]);
    let k = punch(&[
        "wear.steps=0",
        // 455 half periods: 50 + 5·50 + 10·14 = 440 after step 114; the 15 left are 8 '+'
        // and 7 '−' (steps 115 and 116), so that 228 slide '+' and 227 '−'.
        "wear.cycles=227.5",
        "wear.record=[]",
        "wear.body1={ k = 3.9269908169872414e-5 }",
    ]);
    let a = driver::wear(&beta, Some(114), |_| {}).unwrap();
    let b = driver::wear(&k, None, |_| {}).unwrap();
    let (ha, hb) = (&a.history, &b.history);
    assert_eq!(hb.steps.len(), 116);
    assert_eq!(hb.steps.last().unwrap().half_period, 455);
    assert_eq!((hb.steps[114].k, hb.steps[115].k), (8, 7));
    // The first 114 steps are the same run: k / 1000 differs from the β̃ literal by at most
    // one rounding (relative 1e-16), amplified by the 114 steps' contact solves; 1e-10
    // relative is far below any physical difference and far above that round-off.
    for (x, y) in ha.steps.iter().zip(&hb.steps) {
        for (p, q) in x.probes.iter().zip(&y.probes) {
            assert!(
                (p - q).abs() <= 1e-10 * p.abs(),
                "step {}: {p} vs {q}",
                x.step
            );
        }
    }
}

/// The progress bar is for a person at a terminal: with stderr piped (as here) a run that
/// lasts well over the bar's one-second delay must print nothing on stderr.
#[test]
fn no_progress_bar_when_stderr_is_not_a_terminal() {
    let dir = std::env::temp_dir().join(format!("wearfem-bar-{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args([
            "run",
            "brake",
            "--steps",
            "60000",
            "--set",
            "wear.record=[]",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `shape` is the gap's profile (initial gap plus wear), `wear` the wear alone. On a crowned
/// punch (contact.initial_shape, R = 20 m about x = 1100) the corner x = 1070 never carries
/// pressure in a short run: its wear is 0 and its shape the crown's height there,
/// R − √(R² − 30²) = 22.5 µm. (Only the ParaView `wear` field said so before: the review of
/// 2026-11-24 took `shape_mm` for the worn depth.)
#[test]
fn shape_is_the_initial_gap_plus_the_wear_and_wear_is_the_wear() {
    let dir = std::env::temp_dir().join(format!("wearfem-crown-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Without the shift to zero at x = 1100, which would move the wear by its depth there.
    let text = wearfem::examples::example("punch-a")
        .unwrap()
        .replace("shape_zero_at = 1100.0", "");
    let file = dir.join("crowned.toml");
    std::fs::write(&file, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .arg("run")
        .arg(&file)
        .args(["--steps", "4", "--quiet", "--out"])
        .arg(&dir)
        .args([
            "--set",
            "contact.initial_shape={radius=20000.0, center_x=1100.0}",
        ])
        .args([
            "--set",
            "wear.extrapolation=[{k=1}]",
            "--set",
            "wear.record=[3]",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("final.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "x_mm,p_plus_MPa,p_minus_MPa,p_sum_MPa,shape_mm,wear_mm,wear_body1_mm,wear_body2_mm"
    );
    let first: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(first[0], 1070.0);
    assert_eq!(first[3], 0.0, "the corner carries pressure");
    let crown = 20000.0 - (20000.0f64 * 20000.0 - 30.0 * 30.0).sqrt();
    // The crown enters the gap as given (plus the bodies' geometric gap, 0 on flat faces).
    assert!(
        (first[4] - crown).abs() < 1e-9,
        "shape {} against crown {crown}",
        first[4]
    );
    assert_eq!(first[5], 0.0, "wear where nothing was worn");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let wear = summary["final"]["wear"].as_array().unwrap();
    let snapshot_wear = summary["snapshots"][0]["wear"].as_array().unwrap();
    assert_eq!(wear[0].as_f64(), Some(0.0));
    assert_eq!(snapshot_wear[0].as_f64(), Some(0.0));
    // In the middle the punch wore: wear > 0, and shape = crown (0 at x = 1100) + wear.
    let mid = wear.len() / 2;
    let shape_mid = summary["final"]["shape"][mid].as_f64().unwrap();
    assert!(wear[mid].as_f64().unwrap() > 0.0);
    assert!((shape_mid - wear[mid].as_f64().unwrap()).abs() < 1e-12);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `wear.shape_zero_at` on a curved body (the pin): the shift is a vertical rigid translation
/// of body 1, which the plate's λ_F takes up, so the pressures do not change. Along the pin's
/// normals a vertical translation c changes the gap by c·m(x), m = −n_z; the reported wear
/// must be the unshifted run's wear w minus the translation that makes it zero at x₀,
/// w − (w(x₀)/m(x₀))·m (x₀ interpolated between the neighbouring points as the shift
/// interpolates). A review found it offset by −g₀(x₀), the pin's initial gap at x₀ (12.5 µm
/// at x₀ = 10 mm, as large as the whole wear range), so negative everywhere.
#[test]
fn wear_relative_to_shape_zero_at_is_zero_there_on_a_curved_body() {
    let text = wearfem::examples::example("pin").unwrap();
    let run = |sets: &[&str]| {
        let sets: Vec<Override> = sets.iter().map(|s| Override::parse(s).unwrap()).collect();
        let p = Problem::with_overrides(text, "pin", &sets).unwrap();
        driver::wear(&p, Some(60), |_| {}).unwrap()
    };
    let plain = run(&["wear.record=[59]"]);
    let shifted = run(&["wear.shape_zero_at=10.0", "wear.record=[59]"]);
    let x: Vec<f64> = plain.contact.points.x.iter().map(|p| p[0]).collect();
    let i = x.iter().position(|&v| v > 10.0).unwrap();
    let s = (10.0 - x[i - 1]) / (x[i] - x[i - 1]);
    for (a, b) in [
        (&plain.history.shape, &shifted.history.shape),
        (
            &plain.history.snapshots[0].shape,
            &shifted.history.snapshots[0].shape,
        ),
    ] {
        let (wa, wb) = (plain.wear_of(a), shifted.wear_of(b));
        let m: Vec<f64> = plain.contact.points.normal.iter().map(|n| -n[1]).collect();
        let interpolate = |v: &[f64]| (1.0 - s) * v[i - 1] + s * v[i];
        let c = interpolate(&wa) / interpolate(&m);
        let range = wa.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - wa.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(range > 1e-4, "the pin wore {range} mm");
        // The two runs differ by the rigid shift alone, integrated in floating point over 60
        // steps: 1e-9 of the range covers that round-off.
        for (k, (u, v)) in wa.iter().zip(&wb).enumerate() {
            assert!(
                (u - c * m[k] - v).abs() < 1e-9 * range,
                "point {k}: shifted wear {v}, unshifted {u} minus {c} × {}",
                m[k]
            );
        }
        let zero = (1.0 - s) * wb[i - 1] + s * wb[i];
        assert!(zero.abs() < 1e-9 * range, "wear at x0 {zero}");
    }
}

#[test]
fn every_summary_says_which_build_wrote_it() {
    // Red-team review 4, N1: a stale Python wheel gave other results than the binary, and
    // nothing told them apart. Every summary.json (and sweep.json) now carries
    // `wearfem_version`, the crate version plus the git commit when built from a checkout,
    // the same string as `wearfem --version`.
    let problem = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/small-punch.toml"
    );
    let version = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .arg("--version")
        .output()
        .unwrap();
    let version = String::from_utf8_lossy(&version.stdout).trim().to_string();
    assert_eq!(version, format!("wearfem {}", wearfem::VERSION));
    assert!(wearfem::VERSION.starts_with(env!("CARGO_PKG_VERSION")));
    // The tests run from a git checkout (CI clones the repository): the commit is there.
    if std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.git")).exists() {
        assert!(wearfem::VERSION.contains("+g"), "{}", wearfem::VERSION);
    }
    let dir = std::env::temp_dir().join(format!("wearfem-version-{}", std::process::id()));
    for (args, file) in [
        (&["elastic", "lame"][..], "summary.json"),
        (&["contact", problem][..], "summary.json"),
        (&["run", problem, "--steps", "2"][..], "summary.json"),
        (&["steady", problem][..], "summary.json"),
        (
            &["steady", problem, "--method", "penalty"][..],
            "summary.json",
        ),
        (
            &["sweep", problem, "--set", "contact.friction=[0.1]"][..],
            "sweep.json",
        ),
    ] {
        let _ = std::fs::remove_dir_all(&dir);
        let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .args(args)
            .args(["--quiet", "--out"])
            .arg(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join(file)).unwrap()).unwrap();
        assert_eq!(v["wearfem_version"], wearfem::VERSION, "{args:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Run `wearfem run` on the small punch with `sets`; returns summary.json and history.csv.
fn small_punch_run(sets: &[&str], tag: &str) -> (serde_json::Value, String) {
    let problem = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/small-punch.toml"
    );
    let dir = std::env::temp_dir().join(format!("wearfem-f6-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_wearfem"));
    cmd.args(["run", problem, "--quiet", "--out"]).arg(&dir);
    for s in sets {
        cmd.args(["--set", s]);
    }
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{tag}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let history = std::fs::read_to_string(dir.join("history.csv")).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    (summary, history)
}

#[test]
fn steady_distance_has_no_meaningless_numbers_and_history_counts_solves() {
    // Red-team review 4, F6b: under monotonic sliding summed_pressure was 0.999 at the steady
    // state and delta_w the whole wear of a step; both compare two half cycles.
    let (s, _) = small_punch_run(
        &[
            "wear.sliding=monotonic",
            "wear.speed=10",
            "wear.step_time=1",
            "wear.record=[1]",
        ],
        "monotonic",
    );
    let d = &s["steady_distance"];
    assert!(
        d["summed_pressure"].is_null() && d["delta_w"].is_null(),
        "{d}"
    );
    assert!(d["summed_pressure_note"]
        .as_str()
        .unwrap()
        .contains("monotonic"));
    assert!(d["wear"].as_f64().unwrap() < 0.01, "{d}");
    // F6c: a load on a 2 mm window near one end, far from steady (wear rigid to only 0.84):
    // no point carries pressure in both half cycles, and summed_pressure was 0.0, the value
    // of the steady state. Now null with the reason.
    let (s, _) = small_punch_run(
        &[
            "bodies[0].tractions[0].normal=300",
            "bodies[0].tractions[0].window={x=[18,20]}",
            "wear.adaptive={}",
            "wear.steps=100000",
            "wear.body1.beta=4e-7",
            "wear.record=[1]",
        ],
        "window",
    );
    let d = &s["steady_distance"];
    assert!(d["wear"].as_f64().unwrap() > 0.5, "{d}");
    assert!(d["summed_pressure"].is_null(), "{d}");
    assert!(d["summed_pressure_note"]
        .as_str()
        .unwrap()
        .contains("both half cycles"));
    // A reciprocating run with a proper two-sided zone keeps its number.
    let (s, _) = small_punch_run(&["wear.record=[1]"], "reciprocating");
    assert!(
        s["steady_distance"]["summed_pressure"].is_f64(),
        "{}",
        s["steady_distance"]
    );
    assert!(s["steady_distance"].get("summed_pressure_note").is_none());
    // F6d: history.csv and steps[] have the per-step `solves` the docs promise; with step
    // doubling the coarse cycles' solves are in the step after them, so the column sums to
    // the run's total, which exceeds the number of steps.
    let (s, history) = small_punch_run(
        &[
            "wear.adaptive={method=\"step_doubling\"}",
            "wear.steps=20000",
            "wear.body1.beta=4e-7",
            "wear.record=[1]",
        ],
        "doubling",
    );
    let mut lines = history.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "solves")
        .expect("solves column");
    let total: u64 = lines
        .map(|l| l.split(',').nth(col).unwrap().parse::<u64>().unwrap())
        .sum();
    let steps = s["steps"].as_array().unwrap();
    assert_eq!(total, s["solves"].as_u64().unwrap());
    assert_eq!(
        total,
        steps
            .iter()
            .map(|r| r["solves"].as_u64().unwrap())
            .sum::<u64>()
    );
    assert!(
        total > steps.len() as u64,
        "{total} solves in {} steps",
        steps.len()
    );
}

#[test]
fn a_caller_can_stop_a_run_after_any_step() {
    // What the Python layer does on Ctrl-C: `wear_until`'s callback breaks after step 7 of
    // 1700; the run ends there, with that step kept, named as interrupted, and no snapshot
    // past it.
    let problem = punch(&[]);
    let run = wearfem::driver::wear_until(&problem, None, |record| {
        if record.step == 7 {
            std::ops::ControlFlow::Break(())
        } else {
            std::ops::ControlFlow::Continue(())
        }
    })
    .unwrap();
    let history = &run.history;
    assert_eq!(history.steps.len(), 7);
    assert_eq!(history.steps.last().map(|s| s.step), Some(7));
    assert_eq!(
        history.stopped,
        Some((7, wearfem::wear::StopReason::Interrupted))
    );
    assert!(history.snapshots.iter().all(|s| s.step <= 7));
}
