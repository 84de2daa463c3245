//! The same quantity written to several files must be the same number in each: the wear of a
//! recorded step is in snapshots.csv (`wear_mm`), summary.json (`snapshots[].wear`) and the
//! ParaView contact line (`wear`). With `wear.shape_zero_at` the wear is re-zeroed at x₀,
//! which the shape of a '+' step (mid cycle) is not, so a writer that took shape minus
//! initial gap would disagree with the others exactly there.

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;

/// The value of attribute `name` in the tag `tag` (text between its quotes).
fn attribute(tag: &str, name: &str) -> Option<String> {
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let end = start + tag[start..].find('"')?;
    Some(tag[start..end].to_string())
}

/// The point data array `name` of a .vtu file.
fn vtu_array(path: &Path, name: &str) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    let a = text
        .find(&format!("Name=\"{name}\""))
        .unwrap_or_else(|| panic!("{}: no array {name}", path.display()));
    let body = &text[a + text[a..].find('>').unwrap() + 1..];
    body[..body.find("</DataArray>").unwrap()]
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect()
}

/// Largest |a − b| over two profiles of the same length.
fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The wear at x₀, interpolated linearly between the contact points around it.
fn at(x: &[f64], v: &[f64], x0: f64) -> f64 {
    let i = (0..x.len() - 1)
        .find(|&i| (x[i] - x0) * (x[i + 1] - x0) <= 0.0 && x[i] != x[i + 1])
        .expect("x0 inside the contact points");
    let s = (x0 - x[i]) / (x[i + 1] - x[i]);
    (1.0 - s) * v[i] + s * v[i + 1]
}

#[test]
fn snapshot_wear_is_the_same_in_csv_summary_and_paraview_files_with_shape_zero_at() {
    // punch-b40 sets shape_zero_at = 1100; steps 1 and 3 are '+' steps (mid cycle), 2 and 4
    // end a cycle.
    let dir = std::env::temp_dir().join(format!("wearfem-consistency-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(["run", "punch-b40", "--steps", "4", "--vtk", "--quiet"])
        .args(["--set", "wear.record=[1, 2, 3, 4]", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let floats = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    let x = floats(&summary["final"]["x"]);

    // snapshots.csv: wear_mm and shape_mm per (step, point), in the order of x.
    let csv = std::fs::read_to_string(dir.join("snapshots.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (step_c, wear_c, shape_c) = (column("step"), column("wear_mm"), column("shape_mm"));
    let mut csv_wear: HashMap<u64, Vec<f64>> = HashMap::new();
    let mut csv_shape: HashMap<u64, Vec<f64>> = HashMap::new();
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let step: u64 = cells[step_c].parse().unwrap();
        csv_wear
            .entry(step)
            .or_default()
            .push(cells[wear_c].parse().unwrap());
        csv_shape
            .entry(step)
            .or_default()
            .push(cells[shape_c].parse().unwrap());
    }

    // results.pvd: the contact line's file at each time (half periods).
    let pvd = std::fs::read_to_string(dir.join(wearfem::vtk::PVD_NAME)).unwrap();
    let contact_files: HashMap<String, String> = pvd
        .split("<DataSet")
        .skip(1)
        .filter(|d| attribute(d, "part").as_deref() == Some("1"))
        .map(|d| {
            (
                attribute(d, "timestep").unwrap(),
                attribute(d, "file").unwrap(),
            )
        })
        .collect();

    // The initial gap, to show that the re-zeroing matters for the '+' steps of this run
    // (otherwise the test could not tell the writers apart).
    let problem = wearfem::problem::Problem::from_toml(
        wearfem::examples::example("punch-b40").unwrap(),
        "punch-b40",
    )
    .unwrap();
    let (contact, _, _) = wearfem::contact::CondensedContact::build(&problem).unwrap();
    let g0 = &contact.points.initial_gap;

    let snapshots = summary["snapshots"].as_array().unwrap();
    assert_eq!(snapshots.len(), 4);
    let mut plus_steps = 0;
    for s in snapshots {
        let step = s["step"].as_u64().unwrap();
        let wear = floats(&s["wear"]);
        let scale = wear.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        assert!(scale > 0.0, "step {step}: no wear");
        // Full-precision numbers in all three files: equal to round-off.
        let tolerance = 1e-12 * scale;
        let d = max_difference(&csv_wear[&step], &wear);
        assert!(
            d <= tolerance,
            "step {step}: snapshots.csv − summary.json = {d:e} mm"
        );
        let time = s["half_period"].as_u64().unwrap().to_string();
        let vtu = dir.join(&contact_files[&time]);
        let d = max_difference(&vtu_array(&vtu, "wear"), &wear);
        assert!(
            d <= tolerance,
            "step {step}: ParaView − summary.json = {d:e} mm"
        );
        // The wear is zero at shape_zero_at in every snapshot, '+' or '−' (its definition).
        assert!(at(&x, &csv_wear[&step], 1100.0).abs() <= tolerance);
        if s["direction"] == "+" {
            plus_steps += 1;
            // Mid cycle the shape is not re-zeroed: shape − g₀ is not the reported wear.
            let unshifted: Vec<f64> = csv_shape[&step]
                .iter()
                .zip(g0)
                .map(|(g, g0)| g - g0)
                .collect();
            assert!(
                max_difference(&unshifted, &wear) > 1e3 * tolerance,
                "step {step}: the shift is too small to test the writers"
            );
        }
    }
    assert_eq!(plus_steps, 2);
    let _ = std::fs::remove_dir_all(&dir);
}
