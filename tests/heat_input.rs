//! Broken `[heat]` sections and thermal properties: from the valid punch-b40-heat, one break
//! at a time; each gives one message naming the file and the key, and exit code 2. A problem
//! whose heat cannot leave: `steady` refuses it, `run` warns.

use std::process::Command;

fn baseline() -> String {
    wearfem::examples::example("punch-b40-heat")
        .unwrap()
        .to_string()
}

/// Write `text` to `<tag>.toml` in a fresh directory and run `wearfem <command> FILE <extra>`;
/// returns (exit code, stdout, stderr, output directory).
fn run_cli(
    command: &str,
    extra: &[&str],
    text: &str,
    tag: &str,
) -> (i32, String, String, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!("wearfem-heat-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{tag}.toml"));
    std::fs::write(&file, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .arg(command)
        .arg(&file)
        .args(extra)
        .arg("--out")
        .arg(dir.join("out"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
        dir.join("out"),
    )
}

#[test]
fn broken_heat_sections_name_their_key() {
    let base = baseline();
    let cases = [
        // A material of a contact body without one of its thermal properties.
        (
            "conductivity = 50.0    # W/(m·K)\n",
            "",
            "materials.steel.conductivity",
        ),
        ("density = 846.0", "densty = 846.0", "densty"),
        (
            "conductivity = 50.0 ",
            "conductivity = 0.0 ",
            "materials.steel.conductivity",
        ),
        (
            "conductivity = 2.0 ",
            "conductivity = -2.0 ",
            "materials.composite.conductivity",
        ),
        (
            "specific_heat = 460.0",
            "specific_heat = nan",
            "materials.steel.specific_heat",
        ),
        (
            "expansion = 1.2e-5",
            "expansion = 12.0",
            "materials.steel.expansion",
        ),
        (
            "other_edges = { convection = 25.0, ambient = 20.0 }",
            "other_edges = { convection = -25.0, ambient = 20.0 }",
            "heat.other_edges.convection",
        ),
        (
            "faces = { convection = 25.0, ambient = 20.0 }",
            "faces = { temperature = 20.0 }",
            "heat.faces",
        ),
        (
            "edge = \"base\"\ntemperature",
            "edge = \"bse\"\ntemperature",
            "heat.edges[0].edge",
        ),
        (
            "body = \"strip\"\nedge = \"base\"",
            "body = \"plate\"\nedge = \"base\"",
            "heat.edges[0].body",
        ),
        (
            "temperature = 20.0             # °C, held",
            "temperature = 20.0\nconvection = 5.0",
            "heat.edges[0]",
        ),
        (
            "temperature = 20.0             # °C, held",
            "temperature = -300.0",
            "heat.edges[0].temperature",
        ),
        (
            "partition = \"perfect\"",
            "partition = 1.5",
            "heat.partition",
        ),
        (
            "partition = \"perfect\"",
            "partition = \"ideal\"",
            "heat.partition",
        ),
        (
            "reference_temperature = 20.0",
            "reference_temperatur = 20.0",
            "reference_temperatur",
        ),
        (
            "reference_temperature = 20.0",
            "reference_temperature = 20.0\nspace = \"serendipity\"",
            "heat.space",
        ),
        (
            "kind = \"plane_stress\"",
            "kind = \"plane_strain\"",
            "heat.faces",
        ),
        // Body 1's contact edge exchanges heat with body 2: it takes no condition.
        (
            "body = \"strip\"\nedge = \"base\"",
            "body = \"punch\"\nedge = \"contact\"",
            "heat.edges[0].edge",
        ),
    ];
    for (k, (from, to, key)) in cases.iter().enumerate() {
        assert!(base.contains(from), "baseline lacks '{from}'");
        let tag = format!("heat{k}");
        let (code, _, err, _) =
            run_cli("run", &["--steps", "2"], &base.replacen(from, to, 1), &tag);
        assert_eq!(code, 2, "{key}: exit {code}: {err}");
        assert!(
            err.contains(key) && err.contains(&format!("{tag}.toml")),
            "{key}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{key}: one line: {err}");
    }
}

/// Every edge insulated and the faces closed: the heat cannot leave.
fn sealed() -> String {
    baseline()
        .replace("other_edges = { convection = 25.0, ambient = 20.0 }   # W/(m²·K), °C: every outer edge not named\n", "")
        .replace("faces = { convection = 25.0, ambient = 20.0 }         # both faces of the 10 mm plate\n", "")
        .replace("[[heat.edges]]\nbody = \"strip\"\nedge = \"base\"\ntemperature = 20.0             # °C, held\n", "")
}

#[test]
fn heat_that_cannot_leave_has_no_steady_state() {
    let text = sealed();
    assert!(!text.contains("other_edges") && !text.contains("[[heat.edges]]"));
    let (code, _, err, out) = run_cli("steady", &[], &text, "sealed_steady");
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("heat") && err.contains("cannot lose it"),
        "{err}"
    );
    assert!(!out.join("summary.json").exists(), "nothing is written");
    // A run integrates the transient all the same, and says what it is.
    let (code, _, err, out) = run_cli("run", &["--steps", "4"], &text, "sealed_run");
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("cannot lose it"), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["heat"]["heat_can_leave"], false);
}

/// Temperatures the model cannot be trusted with are said, by `steady` as by `run`: above
/// 300 °C (the properties held constant) and below what the problem imposes (20 °C here:
/// frictional heat cannot cool anything, so an undershoot is the elements' oscillation in a
/// thermal layer they do not resolve).
#[test]
fn hot_and_unresolved_temperatures_are_warned_by_both_jobs() {
    // Sliding ten times faster: the contact passes 300 °C (steady: 324 °C), resolved.
    let fast = baseline().replace("omega = 10.0", "omega = 100.0");
    assert_ne!(fast, baseline());
    for job in ["run", "steady"] {
        let (code, _, err, _) = run_cli(job, &[], &fast, &format!("hot_{job}"));
        assert_eq!(code, 0, "{err}");
        assert!(err.contains("warning[heat-hot]"), "{job}: {err}");
        assert!(!err.contains("heat-undershoot"), "{job}: {err}");
    }
    // Conductivities a hundred times lower: a thermal layer of a few µm under elements of
    // 5 mm, and temperatures far below 20 °C beside the peak.
    let poor = baseline()
        .replace("conductivity = 2.0 ", "conductivity = 0.01 ")
        .replace("conductivity = 50.0 ", "conductivity = 0.05 ");
    assert_ne!(poor, baseline());
    for job in ["run", "steady"] {
        let (code, _, err, _) = run_cli(job, &[], &poor, &format!("cold_{job}"));
        assert_eq!(code, 0, "{err}");
        assert!(err.contains("warning[heat-undershoot]"), "{job}: {err}");
    }
    // The shipped example says neither.
    let (code, _, err, _) = run_cli("steady", &[], &baseline(), "shipped_steady");
    assert_eq!(code, 0, "{err}");
    assert!(
        !err.contains("heat-hot") && !err.contains("heat-undershoot"),
        "{err}"
    );
}

/// A probe given a hair outside body 1's contact edge (a coordinate rounded below the edge,
/// as a point on a brake shoe's arc rounded to four decimals is) has its temperature taken at
/// the contact point its pressure is read at, not refused: the same temperature, to the
/// field's smoothness over 0.1 µm, as a probe on the edge.
#[test]
fn a_probe_a_hair_off_the_contact_edge_reads_the_edge() {
    let on = baseline().replace(
        "M = { body = \"punch\", at = [1070.0, 100.0] }",
        "M = { body = \"punch\", at = [1100.0, 100.0] }",
    );
    let off = on.replace("at = [1100.0, 100.0]", "at = [1100.0, 99.9999]");
    assert_ne!(on, off);
    let temperature = |text: &str, tag: &str| {
        let (code, _, err, out) = run_cli("run", &["--steps", "20"], text, tag);
        assert_eq!(code, 0, "{err}");
        let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
        let header: Vec<&str> = history.lines().next().unwrap().split(',').collect();
        let column = header.iter().position(|h| *h == "T_M_C").unwrap();
        let last = history
            .lines()
            .last()
            .unwrap()
            .split(',')
            .nth(column)
            .unwrap();
        last.parse::<f64>().unwrap()
    };
    let (t_on, t_off) = (temperature(&on, "probe_on"), temperature(&off, "probe_off"));
    assert!(t_on > 20.5, "the contact has warmed: {t_on}");
    // The same contact point, the same trace: equal to round-off.
    assert!((t_on - t_off).abs() < 1e-9 * t_on, "{t_on} against {t_off}");
}

/// A body that cannot lose heat but is given none of it (a share of 0 for the punch, whose
/// edges and faces are then all insulated; the strip's base is held) has a steady state: the
/// punch keeps its start, 20 °C, and the strip's periodic temperature is the run's. `steady`
/// failed on it ("Singular", blaming friction): its constant mode, of rate 0, was divided by
/// the zero of its period's decay.
#[test]
fn a_sealed_body_given_no_heat_has_a_steady_state() {
    let text = baseline()
        .replace(
            "partition = \"perfect\"          # equal temperatures at partner points; the share follows\n",
            "partition = 0.0\n",
        )
        .replace("other_edges = { convection = 25.0, ambient = 20.0 }   # W/(m²·K), °C: every outer edge not named\n", "")
        .replace("faces = { convection = 25.0, ambient = 20.0 }         # both faces of the 10 mm plate\n", "");
    assert!(text.contains("partition = 0.0") && !text.contains("other_edges"));
    let read = |out: &std::path::Path| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
    };
    let (code, _, err, out) = run_cli("steady", &[], &text, "sealed_share0_steady");
    assert_eq!(code, 0, "{err}");
    let steady = read(&out);
    let (code, _, err, out) = run_cli("run", &[], &text, "sealed_share0_run");
    assert_eq!(code, 0, "{err}");
    let run = read(&out);
    let values = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    // The punch receives nothing: it stays at its start to round-off of the reduction.
    for t in values(&steady["heat"]["contact_temperature_plus"]["body1"]) {
        assert!((t - 20.0).abs() < 1e-6, "{t}");
    }
    // The strip's periodic temperature: the run's last step (a '−' end, the '+' start) within
    // 0.05 K of its 30–40 K rise, as the run reaches the steady state (its pressures 0.01 %).
    let strip_steady = values(&steady["heat"]["contact_temperature_plus"]["body2"]);
    let strip_run = values(&run["final"]["contact_temperature"]["body2"]);
    let peak = strip_steady.iter().cloned().fold(0.0, f64::max);
    assert!(peak > 40.0, "the strip warms: {peak}");
    for (a, b) in strip_steady.iter().zip(&strip_run) {
        assert!((a - b).abs() < 0.05, "{a} against {b}");
    }
}
