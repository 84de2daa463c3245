//! An output directory holds only the files of the last command run into it: a command that
//! fails, is refused or writes fewer files leaves none of an earlier command's results to be
//! mistaken for its own, and files wearfem did not write survive (review 10, F3).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn wearfem(args: &[&str], out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_wearfem"))
        .args(args)
        .arg("--quiet")
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn code(o: &Output) -> Option<i32> {
    o.status.code()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wearfem-stale-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Every file under `dir`, relative, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut list = vec![];
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let path = e.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let rel = path.strip_prefix(dir).unwrap();
                list.push(rel.to_string_lossy().replace('\\', "/"));
            }
        }
    }
    list.sort();
    list
}

/// Files of the user's in the output directory: other names, a wearfem name with other
/// content, and a file under vtk/. None of them may be removed.
const USER_FILES: &[(&str, &str)] = &[
    ("notes.txt", "my notes\n"),
    ("history.csv", "date,what\n2026-01-01,my own history\n"),
    ("pressure.svg", "<?xml version=\"1.0\"?><svg></svg>\n"),
    ("vtk/mesh.vtu", "<VTKFile/>\n"),
];

fn add_user_files(dir: &Path) {
    for (name, text) in USER_FILES {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
}

fn assert_user_files_kept(dir: &Path) {
    for (name, text) in USER_FILES {
        let kept = std::fs::read_to_string(dir.join(name)).unwrap_or_default();
        assert_eq!(&kept, text, "{name} was removed or changed");
    }
}

#[test]
fn a_failed_steady_after_a_solved_one_leaves_no_results() {
    let dir = scratch("steady");
    let solved = wearfem(&["steady", "punch-b40"], &dir);
    assert_eq!(code(&solved), Some(0));
    assert!(dir.join("summary.json").exists() && dir.join("steady.csv").exists());
    let _ = std::fs::remove_file(dir.join("pressure.svg"));
    add_user_files(&dir);
    // μ = 0.4 with the pin 140 mm up separates the two half cycles' contact zones: no steady
    // state (exit 1, "nothing was written").
    let failed = wearfem(
        &[
            "steady",
            "punch-b40",
            "--set",
            "plate.pin=[1100, 140]",
            "--set",
            "contact.friction=0.4",
        ],
        &dir,
    );
    assert_eq!(code(&failed), Some(1));
    let mut expected: Vec<String> = USER_FILES.iter().map(|(n, _)| n.to_string()).collect();
    expected.sort();
    assert_eq!(files(&dir), expected, "only the user's files are left");
    assert_user_files_kept(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_refused_command_after_a_run_leaves_no_results() {
    let dir = scratch("refused");
    let run = wearfem(&["run", "punch-b40", "--steps", "4", "--vtk"], &dir);
    assert_eq!(code(&run), Some(0));
    assert!(dir.join("history.csv").exists() && dir.join("vtk").is_dir());
    std::fs::write(dir.join("notes.txt"), "my notes\n").unwrap();
    let refused = wearfem(
        &["sweep", "punch-b40", "--set", "contact.frction=[0.1, 0.2]"],
        &dir,
    );
    assert_eq!(code(&refused), Some(2));
    assert_eq!(files(&dir), ["notes.txt"]);
    assert!(!dir.join("vtk").exists(), "the emptied vtk/ is removed");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_steady_after_a_run_leaves_none_of_the_runs_files() {
    let dir = scratch("after-run");
    assert_eq!(
        code(&wearfem(&["run", "punch-b40", "--steps", "4"], &dir)),
        Some(0)
    );
    assert!(dir.join("snapshots.csv").exists());
    assert_eq!(code(&wearfem(&["steady", "punch-b40"], &dir)), Some(0));
    // What `steady` writes, and nothing else (README, "writes into DIR").
    assert_eq!(
        files(&dir),
        [
            "pressure.png",
            "pressure.svg",
            "shape.png",
            "shape.svg",
            "steady.csv",
            "summary.json"
        ]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The `file` attributes of a .pvd collection.
fn pvd_files(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut list: Vec<String> = text
        .split(" file=\"")
        .skip(1)
        .map(|s| s[..s.find('"').unwrap()].to_string())
        .collect();
    list.sort();
    list
}

#[test]
fn a_shorter_vtk_rerun_leaves_only_the_files_of_its_collection() {
    let dir = scratch("vtk");
    // 10 steps recording 1…8: states 0, 1…8 and the last step, 10 states of 2 files.
    let long = wearfem(
        &[
            "run",
            "punch-b40",
            "--steps",
            "10",
            "--vtk",
            "--set",
            "wear.record=[1, 2, 3, 4, 5, 6, 7, 8]",
        ],
        &dir,
    );
    assert_eq!(code(&long), Some(0));
    assert_eq!(pvd_files(&dir.join("results.pvd")).len(), 20);
    std::fs::write(dir.join("vtk/mesh.vtu"), "<VTKFile/>\n").unwrap();
    // 2 steps recording 1: states 0, 1 and the last step, 2.
    let short = wearfem(
        &[
            "run",
            "punch-b40",
            "--steps",
            "2",
            "--vtk",
            "--set",
            "wear.record=[1]",
        ],
        &dir,
    );
    assert_eq!(code(&short), Some(0));
    let listed = pvd_files(&dir.join("results.pvd"));
    assert_eq!(listed.len(), 6);
    let mut on_disk: Vec<String> = files(&dir)
        .into_iter()
        .filter(|f| f.starts_with("vtk/") && f != "vtk/mesh.vtu")
        .collect();
    on_disk.sort();
    assert_eq!(on_disk, listed, "vtk/ holds exactly the collection's files");
    assert!(dir.join("vtk/mesh.vtu").exists(), "the user's file is kept");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_run_without_heat_after_one_with_heat_leaves_no_temperatures() {
    // heat.csv and the temperature figures were missing from the clean-up's list: a run of
    // the same directory without heat left the earlier run's temperatures beside its own
    // results.
    let dir = scratch("after-heat");
    let heat = wearfem(&["run", "punch-b40-heat", "--steps", "4"], &dir);
    assert_eq!(code(&heat), Some(0));
    assert!(dir.join("heat.csv").exists() && dir.join("temperature.png").exists());
    assert_eq!(
        code(&wearfem(&["run", "punch-b40", "--steps", "4"], &dir)),
        Some(0)
    );
    let left = files(&dir);
    for stale in [
        "heat.csv",
        "temperature.png",
        "temperature.svg",
        "contact_temperature.png",
    ] {
        assert!(!left.contains(&stale.to_string()), "{stale} left: {left:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
