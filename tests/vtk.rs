//! The ParaView files parse as VTK XML with consistent sizes (the Python test under
//! tests/python/ reads them with meshio and checks values against summary.json).

mod common;
use common::problem;
use std::path::Path;

/// The value of attribute `name` in the tag `tag` (text between its quotes).
fn attribute(tag: &str, name: &str) -> Option<String> {
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let end = start + tag[start..].find('"')?;
    Some(tag[start..end].to_string())
}

/// Check one .vtu: well-formed enough (every DataArray closed), every array as long as its
/// points or cells times its components; returns (points, cells).
fn check_vtu(path: &Path) -> (usize, usize) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.starts_with("<?xml") && text.trim_end().ends_with("</VTKFile>"));
    let piece = &text[text.find("<Piece").unwrap()..];
    let tag = &piece[..piece.find('>').unwrap()];
    let points: usize = attribute(tag, "NumberOfPoints").unwrap().parse().unwrap();
    let cells: usize = attribute(tag, "NumberOfCells").unwrap().parse().unwrap();
    assert!(points > 0 && cells > 0);
    let section = |name: &str| {
        let a = text.find(&format!("<{name}>")).unwrap();
        let b = text.find(&format!("</{name}>")).unwrap();
        &text[a..b]
    };
    let connectivity_len = {
        let cells_text = section("Cells");
        let a = cells_text.find("Name=\"offsets\"").unwrap();
        let body = &cells_text[cells_text[a..].find('>').unwrap() + a + 1..];
        let values: Vec<usize> = body[..body.find("</DataArray>").unwrap()]
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(values.len(), cells);
        *values.last().unwrap()
    };
    for (name, count) in [
        ("PointData", points),
        ("CellData", cells),
        ("Points", points),
        ("Cells", cells),
    ] {
        let s = section(name);
        for array in s.split("<DataArray").skip(1) {
            let (tag, rest) = array.split_at(array.find('>').unwrap());
            let components: usize = attribute(tag, "NumberOfComponents")
                .unwrap()
                .parse()
                .unwrap();
            let values: Vec<f64> = rest[1..rest.find("</DataArray>").unwrap()]
                .split_whitespace()
                .map(|v| v.parse().unwrap())
                .collect();
            assert!(values.iter().all(|v| v.is_finite()));
            let expected = if attribute(tag, "Name").as_deref() == Some("connectivity") {
                connectivity_len
            } else {
                count * components
            };
            assert_eq!(
                values.len(),
                expected,
                "{}: {name} array {:?}",
                path.display(),
                attribute(tag, "Name")
            );
        }
    }
    (points, cells)
}

#[test]
fn contact_job_files_parse_and_have_consistent_sizes() {
    let dir = std::env::temp_dir().join(format!("wearfem-vtk-{}", std::process::id()));
    let p = problem("punch-b40", &[]);
    wearfem::vtk::write_contact_job(&dir, &p).unwrap();
    let pvd = std::fs::read_to_string(dir.join(wearfem::vtk::PVD_NAME)).unwrap();
    let files: Vec<String> = pvd
        .split("<DataSet")
        .skip(1)
        .map(|d| attribute(d, "file").unwrap())
        .collect();
    assert_eq!(files.len(), 2);
    let (points, cells) = check_vtu(&dir.join(&files[0]));
    // 8 × (3 + 4) punch and 12 × 4 strip elements, p = 8: 8 × 8 sub-quads and 9 × 9 points
    // each.
    let elements = 8 * 7 + 12 * 4;
    assert_eq!((points, cells), (81 * elements, 64 * elements));
    let (points, cells) = check_vtu(&dir.join(&files[1]));
    assert_eq!(
        (points, cells),
        (65, 64),
        "65 contact points joined by 64 segments"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn output_section_is_read_strictly() {
    let text = wearfem::examples::example("punch-b40").unwrap().to_string();
    let ok = wearfem::problem::Problem::from_toml(
        &format!("{text}\n[output]\nvtk = true\n"),
        "out.toml",
    )
    .unwrap();
    assert!(ok.spec.output.unwrap().vtk);
    for (extra, expected) in [
        ("[output]\npvd = true\n", "pvd"),
        ("[output]\nvtk = \"yes\"\n", "boolean"),
    ] {
        let err = wearfem::problem::Problem::from_toml(&format!("{text}\n{extra}"), "out.toml")
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with("out.toml: ") && err.contains(expected) && !err.contains('\n'),
            "{err}"
        );
    }
}

#[test]
fn run_with_output_vtk_key_writes_every_state_through_the_binary() {
    // `[output] vtk = true` in the problem file asks for the files as `--vtk` does; 4 steps
    // with the recorded steps 1 and 2 give the states 0, 1, 2 and the last step, 4.
    let dir = std::env::temp_dir().join(format!("wearfem-vtk-run-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("p.toml");
    let text = wearfem::examples::example("punch-b40").unwrap();
    std::fs::write(&file, format!("{text}\n[output]\nvtk = true\n")).unwrap();
    let out = dir.join("out");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .arg("run")
        .arg(&file)
        .args(["--steps", "4", "--out"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let pvd = std::fs::read_to_string(out.join(wearfem::vtk::PVD_NAME)).unwrap();
    let sets: Vec<(String, String)> = pvd
        .split("<DataSet")
        .skip(1)
        .map(|d| {
            (
                attribute(d, "timestep").unwrap(),
                attribute(d, "file").unwrap(),
            )
        })
        .collect();
    let times: Vec<&str> = sets.iter().map(|s| s.0.as_str()).step_by(2).collect();
    // Half periods: step 1 = 1, step 2 = 2, step 4 = 4 (k = 1 for n ≤ 50).
    assert_eq!(times, ["0", "1", "2", "4"]);
    for (_, file) in &sets {
        check_vtu(&out.join(file));
    }
    for name in [
        "pressure_plus.png",
        "pressure_minus.png",
        "shape_evolution.png",
        "delta_w.png",
    ] {
        let bytes = std::fs::read(out.join(name)).unwrap();
        assert_eq!(&bytes[1..4], b"PNG", "{name}");
        // IHDR: width and height, big-endian, at bytes 16..24.
        let size = |k: usize| u32::from_be_bytes(bytes[k..k + 4].try_into().unwrap());
        assert_eq!((size(16), size(20)), wearfem::plot::SIZE, "{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Check the files of one job's output folder: summary.json parses and has `keys`; every CSV
/// is rectangular with finite numbers (or a direction symbol); every PNG has the figure size;
/// every state of results.pvd is a consistent .vtu. Returns the number of files checked.
fn check_output_folder(out: &Path, keys: &[&str]) -> usize {
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
            .unwrap_or_else(|e| panic!("{}: summary.json: {e}", out.display()));
    for key in keys {
        assert!(
            summary.get(key).is_some(),
            "{}: no key {key}",
            out.display()
        );
    }
    let mut checked = 1;
    for entry in std::fs::read_dir(out).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        match path.extension().and_then(|e| e.to_str()) {
            Some("csv") => {
                let text = std::fs::read_to_string(&path).unwrap();
                let mut lines = text.lines();
                let columns = lines.next().unwrap().split(',').count();
                let mut rows = 0;
                for line in lines {
                    let cells: Vec<&str> = line.split(',').collect();
                    assert_eq!(cells.len(), columns, "{name}: {line}");
                    for c in cells {
                        let number = c.parse::<f64>().map(f64::is_finite).unwrap_or(false);
                        assert!(number || c == "+" || c == "−", "{name}: '{c}' in {line}");
                    }
                    rows += 1;
                }
                assert!(rows > 0, "{name} has no rows");
            }
            Some("png") => {
                let bytes = std::fs::read(&path).unwrap();
                assert_eq!(&bytes[1..4], b"PNG", "{name}");
                // IHDR: width and height, big-endian, at bytes 16..24.
                let size = |k: usize| u32::from_be_bytes(bytes[k..k + 4].try_into().unwrap());
                assert_eq!((size(16), size(20)), wearfem::plot::SIZE, "{name}");
            }
            Some("pvd") => {
                let pvd = std::fs::read_to_string(&path).unwrap();
                for set in pvd.split("<DataSet").skip(1) {
                    check_vtu(&out.join(attribute(set, "file").unwrap()));
                    checked += 1;
                }
            }
            _ => continue,
        }
        checked += 1;
    }
    checked
}

#[test]
fn every_builtin_example_writes_readable_files_through_the_binary() {
    // Issue 11: every built-in example through the binary, each job it supports, with the
    // ParaView files; wear runs shortened to 4 steps (their files have the same form).
    let dir = std::env::temp_dir().join(format!("wearfem-builtins-{}", std::process::id()));
    let contact_keys = [
        "x",
        "pressure",
        "gap",
        "rigid",
        "residuals",
        "solve",
        "coarse_partner_zones",
    ];
    let run_keys = [
        "steps",
        "final",
        "snapshots",
        "steady_distance",
        "solves",
        "coarse_partner_zones",
    ];
    let steady_keys = [
        "x",
        "p_plus",
        "p_minus",
        "p_sum",
        "shape",
        "status",
        "coarse_partner_zones",
    ];
    // Monotonic sliding has one pressure (docs/problem-files.md, `steady`).
    let monotonic_steady_keys = ["x", "p_plus", "shape", "status", "coarse_partner_zones"];
    for (name, text) in wearfem::examples::EXAMPLES {
        if text.contains("[fretting]") {
            // Fretting writes no ParaView files yet (--vtk is refused); its files are checked
            // in tests/fretting.rs.
            continue;
        }
        if text.contains("pairs = \"sliding\"") {
            // Sliding pairs write no ParaView files yet and have no steady job; their run's
            // files are checked in tests/sliding.rs.
            continue;
        }
        let steady_keys: &[&str] = if text.contains("sliding = \"monotonic\"") {
            &monotonic_steady_keys
        } else {
            &steady_keys
        };
        let jobs: Vec<(&str, &[&str], &[&str])> = if !text.contains("[contact]") {
            vec![("elastic", &[], &["dofs", "strain_energy", "probes"])]
        } else if !text.contains("[wear]") {
            vec![("contact", &[], &contact_keys)]
        } else {
            vec![
                ("contact", &[], &contact_keys),
                ("run", &["--steps", "4"], &run_keys),
                ("steady", &[], steady_keys),
            ]
        };
        for (job, args, keys) in jobs {
            let out = dir.join(format!("{name}-{job}"));
            let result = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
                .args(["--quiet", job, name])
                .args(args)
                .arg("--vtk")
                .arg("--out")
                .arg(&out)
                .output()
                .unwrap();
            assert!(
                result.status.success(),
                "{name} {job}: {}",
                String::from_utf8_lossy(&result.stderr)
            );
            let files = check_output_folder(&out, keys);
            assert!(files >= 3, "{name} {job}: only {files} files");
            // The shipped examples mesh body 2 finely enough where their zones end.
            if job != "elastic" {
                let text = std::fs::read_to_string(out.join("summary.json")).unwrap();
                let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
                assert_eq!(
                    summary["coarse_partner_zones"],
                    serde_json::json!([]),
                    "{name} {job}"
                );
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
