//! Graded block meshes (`u = { n = 20, ratio = 1.15 }`): the lines a problem file asks for,
//! on straight edges and arcs alike, give the same answers as any other mesh of the exact
//! geometry, and wrong tables are named.

use wearfem::driver;
use wearfem::problem::Problem;

/// The lamé example with its mesh lines replaced.
fn lame(u: &str, v: &str) -> Problem {
    let text = wearfem::examples::example("lame")
        .unwrap()
        .replace("u = 2 ", &format!("u = {u} "))
        .replace("v = 2 ", &format!("v = {v} "));
    Problem::from_toml(&text, "lame-graded").unwrap()
}

#[test]
fn a_graded_arc_is_graded_in_angle() {
    // v runs along the quarter arcs: its lines are block parameters, and on a circular arc the
    // parameter runs with the angle. Graded by 2 over 3 divisions: angles in the ratio 1 : 2 : 4
    // of 90°.
    let problem = lame("1", "{ n = 3, ratio = 2.0 }");
    let body = problem.elastic_body(0, &[]).unwrap();
    let mut angles: Vec<f64> = body
        .mesh
        .vertices
        .iter()
        .filter(|x| (x[0].hypot(x[1]) - 100.0).abs() < 1e-9)
        .map(|x| x[1].atan2(x[0]).to_degrees())
        .collect();
    angles.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let expected = [0.0, 90.0 / 7.0, 270.0 / 7.0, 90.0];
    assert_eq!(angles.len(), 4, "{angles:?}");
    for (a, e) in angles.iter().zip(expected) {
        assert!((a - e).abs() < 1e-9, "{angles:?}");
    }
}

#[test]
fn lame_on_graded_meshes_is_the_closed_form() {
    // Lamé's u_r at the inner and outer radius (the closed form of tests/elastic.rs) on meshes
    // graded radially towards the bore (where the stress is largest) and around the arc
    // towards both ends: exact geometry and p = 8 keep the 1e-7 of the lamé example.
    let (a, b, p, e, nu) = (100.0f64, 200.0f64, 100.0f64, 2.0e5f64, 0.3f64);
    let radial = |r: f64| {
        let aa = p * a * a / (b * b - a * a);
        let bb = p * a * a * b * b / (b * b - a * a);
        (1.0 + nu) / e * ((1.0 - 2.0 * nu) * aa * r + bb / r)
    };
    for (u, v) in [
        (
            "{ n = 3, ratio = 1.6 }",
            "{ n = 4, ratio = 1.3, both_ends = true }",
        ),
        ("{ n = 2, ratio = 0.5 }", "{ n = 3, ratio = 1.2 }"),
    ] {
        let summary = driver::elastic(&lame(u, v)).unwrap();
        for (name, r) in [("inner", 100.0), ("outer", 200.0)] {
            let ur = summary["probes"][name]["displacement"][0].as_f64().unwrap();
            let rel = (ur - radial(r)).abs() / radial(r);
            assert!(rel < 1e-7, "u = {u}, v = {v}, {name}: {rel:.2e}");
        }
    }
}

#[test]
fn a_wrong_grading_is_named() {
    // Exit 2 and the key, for a ratio that is not positive, no divisions, an unknown key, and
    // a grading so steep that an element falls below 1e-6 of the body (the mesh's own check).
    let dir = std::env::temp_dir().join(format!("wearfem-graded-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (k, (lines, key)) in [
        ("{ n = 4, ratio = -1.0 }", "bodies[0].blocks[0].u.ratio"),
        ("{ n = 0, ratio = 1.2 }", "bodies[0].blocks[0].u.n"),
        (
            "{ n = 4, ratio = 1.2, bothends = true }",
            "bodies[0].blocks[0].u",
        ),
        ("{ n = 20, ratio = 3.0 }", "bodies[0].blocks[0].u"),
    ]
    .iter()
    .enumerate()
    {
        let text = wearfem::examples::example("lame")
            .unwrap()
            .replace("u = 2 ", &format!("u = {lines} "));
        let file = dir.join(format!("g{k}.toml"));
        std::fs::write(&file, text).unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearfem"))
            .arg("elastic")
            .arg(&file)
            .arg("--out")
            .arg(dir.join("out"))
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{lines}: {err}");
        assert!(err.contains(key), "{lines}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{lines}: {err}");
    }
}
