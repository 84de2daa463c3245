//! Files of an earlier command in the output directory. Every command overwrites only the
//! files it writes itself, and writes some of them only on success (final.csv after a full
//! cycle, nothing at all after a steady iteration that did not converge, fewer .vtu files
//! after a shorter run), so without a clean-up an earlier command's results would stay beside
//! or instead of this one's and could be read as its results. [`remove_earlier_outputs`]
//! removes them before a command starts; it removes only files that wearfem writes: by name
//! (and, under `vtk/`, by wearfem's naming pattern), and only when the file's content looks
//! like wearfem's (a JSON file with `wearfem_version`, a CSV file with one of wearfem's
//! headers, …), so a user's file of the same name is left alone.

use super::OutputError;
use std::fs;
use std::path::{Path, PathBuf};

/// The figures (each `NAME.svg` and `NAME.png`) any command writes into the directory.
const FIGURES: &[&str] = &[
    "pressure",
    "shape",
    "history",
    "pressure_plus",
    "pressure_minus",
    "shape_evolution",
    "dissipation",
    "delta_w",
    "wear",
    "temperature",
    "contact_temperature",
    "sweep",
];

/// How a file of each name is recognised as wearfem's: `Json(key)`, a JSON file holding
/// `"key":`; `Header(start)`, a text file whose first line starts with `start`.
enum Signature {
    Json(&'static str),
    Header(&'static str),
    SweepCsv,
}

/// The data files any command writes into the directory, and their signatures.
const DATA: &[(&str, Signature)] = &[
    ("summary.json", Signature::Json("wearfem_version")),
    ("sweep.json", Signature::Json("wearfem_version")),
    ("validation.json", Signature::Json("checks")),
    (
        "history.csv",
        Signature::Header("step,half_period,direction,k,"),
    ),
    ("final.csv", Signature::Header("x_mm,p_plus_MPa,")),
    ("steady.csv", Signature::Header("x_mm,p_plus_MPa,")),
    (
        "snapshots.csv",
        Signature::Header("step,half_period,direction,x_mm,"),
    ),
    (
        "contact.csv",
        Signature::Header("x_mm,z_mm,pressure_MPa,gap_mm"),
    ),
    (
        "iterations.csv",
        Signature::Header("iteration,i_delta_w_mm3,"),
    ),
    (
        "heat.csv",
        Signature::Header("x_mm,contact_temperature_body1_C,"),
    ),
    (
        "steady_heat.csv",
        Signature::Header("x_mm,thermal_gap_plus_mm,"),
    ),
    ("sweep.csv", Signature::SweepCsv),
    (
        "validation.md",
        Signature::Header("| id | quantity | reference |"),
    ),
    (
        crate::vtk::PVD_NAME,
        Signature::Header("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\""),
    ),
];

/// The first `n` bytes of a file (fewer if it is shorter); None if it cannot be read.
fn head(path: &Path, n: usize) -> Option<Vec<u8>> {
    use std::io::Read;
    let mut bytes = Vec::with_capacity(n);
    fs::File::open(path)
        .ok()?
        .take(n as u64)
        .read_to_end(&mut bytes)
        .ok()?;
    Some(bytes)
}

fn starts_with(path: &Path, start: &str) -> bool {
    head(path, start.len()).is_some_and(|b| b == start.as_bytes())
}

fn is_ours(path: &Path, signature: &Signature) -> bool {
    match signature {
        // serde_json writes the keys in alphabetical order, so the version may be anywhere.
        Signature::Json(key) => {
            let needle = format!("\"{key}\":");
            fs::read(path).is_ok_and(|b| {
                b.first() == Some(&b'{') && b.windows(needle.len()).any(|w| w == needle.as_bytes())
            })
        }
        Signature::Header(start) => starts_with(path, start),
        // The overridden keys come first; status and the time are always there.
        Signature::SweepCsv => head(path, 64 * 1024).is_some_and(|b| {
            let text = String::from_utf8_lossy(&b);
            let first = text.lines().next().unwrap_or_default();
            first.contains(",status,") && first.ends_with(",warnings,seconds")
        }),
    }
}

/// A figure of wearfem's: an SVG document (plotters writes `<svg width=…`) or a PNG image.
fn is_figure(path: &Path) -> bool {
    match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => starts_with(path, "<svg width=\""),
        Some("png") => head(path, 8).is_some_and(|b| b == b"\x89PNG\r\n\x1a\n"),
        _ => false,
    }
}

/// `bodies_NNNN.vtu` or `contact_NNNN.vtu` (at least four digits), the names of
/// [`crate::vtk`]'s files under `vtk/`.
fn is_vtu_name(name: &str) -> bool {
    let Some(stem) = name.strip_suffix(".vtu") else {
        return false;
    };
    let digits = stem
        .strip_prefix("bodies_")
        .or_else(|| stem.strip_prefix("contact_"));
    digits.is_some_and(|d| d.len() >= 4 && d.bytes().all(|c| c.is_ascii_digit()))
}

/// A regular file (not a directory, not a symbolic link, which wearfem never creates).
fn is_file(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok_and(|m| m.is_file())
}

/// Remove from `dir` the files that an earlier wearfem command wrote there (any command's:
/// after `run`, a `steady` into the same directory must not leave the run's history.csv
/// beside its summary.json), so that the directory holds only what the coming command
/// writes. Files of other names, and files of wearfem's names whose content is not
/// wearfem's, are kept; `vtk/` is removed once empty. A `dir` that does not exist or is not
/// a directory has nothing to remove (writing into it reports the error). Returns the
/// removed paths.
pub fn remove_earlier_outputs(dir: &Path) -> Result<Vec<PathBuf>, OutputError> {
    let mut removed = Vec::new();
    if !dir.is_dir() {
        return Ok(removed);
    }
    let mut remove = |path: PathBuf| {
        fs::remove_file(&path).map_err(|source| OutputError {
            path: format!("{} (an earlier output, to be removed)", path.display()),
            source,
        })?;
        removed.push(path);
        Ok::<(), OutputError>(())
    };
    for (name, signature) in DATA {
        let path = dir.join(name);
        if is_file(&path) && is_ours(&path, signature) {
            remove(path)?;
        }
    }
    for name in FIGURES {
        for ext in ["svg", "png"] {
            let path = dir.join(format!("{name}.{ext}"));
            if is_file(&path) && is_figure(&path) {
                remove(path)?;
            }
        }
    }
    let vtk = dir.join("vtk");
    if vtk.is_dir() && !fs::symlink_metadata(&vtk).is_ok_and(|m| m.is_symlink()) {
        let entries = fs::read_dir(&vtk).map_err(|source| OutputError {
            path: vtk.display().to_string(),
            source,
        })?;
        for entry in entries.flatten() {
            let path = entry.path();
            let name = entry.file_name();
            if is_vtu_name(&name.to_string_lossy())
                && is_file(&path)
                && starts_with(
                    &path,
                    "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"",
                )
            {
                remove(path)?;
            }
        }
        // Only if empty: a user's files under vtk/ keep it.
        let _ = fs::remove_dir(&vtk);
    }
    Ok(removed)
}

#[cfg(test)]
mod tests {
    use super::is_vtu_name;

    #[test]
    fn only_wearfems_vtu_names_match() {
        for name in ["bodies_0000.vtu", "contact_0012.vtu", "bodies_12345.vtu"] {
            assert!(is_vtu_name(name), "{name}");
        }
        for name in [
            "bodies_12.vtu",
            "bodies_00a0.vtu",
            "mesh_0000.vtu",
            "contact_0000.vtk",
            "bodies_.vtu",
        ] {
            assert!(!is_vtu_name(name), "{name}");
        }
    }
}
