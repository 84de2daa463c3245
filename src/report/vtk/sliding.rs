//! ParaView files of a sliding-pairs run (`wearfem run --vtk`): the worn track of body 2 and
//! the worn contact edge of body 1 at every recorded step and at the end, as lines at rest
//! with the wear as data and as a vector to warp by.
//!
//! The bodies themselves are not written: at each position body 2 sits elsewhere under body
//! 1, and a state of the whole bodies would be one position's, re-solved. The track is what a
//! finite stroke adds: `wear_body2` (mm) along it, and `worn_surface` = −w n (mm, n the outward
//! normal), so that *Warp By Vector* (with a scale factor: the wear is micrometres) draws the
//! worn profile.

use super::jobs::VtkError;
use super::{write, write_pvd, Piece, PvdEntry, VTK_LINE};
use crate::jobs::sliding::SlidingRun;
use crate::output::OutputError;
use std::path::Path;

/// One state to write: half periods done, body 1's wear at its points, body 2's along the
/// track, and the pressure at the step's last position (MPa).
struct State<'a> {
    half_periods: usize,
    wear_body1: &'a [f64],
    wear_body2: &'a [f64],
    pressure: &'a [f64],
}

/// Write `vtk/track_NNNN.vtu` and `vtk/slider_NNNN.vtu` for every recorded step and the last
/// one, and the collection `results.pvd` (time: half periods, or turns).
pub fn write_sliding(dir: &Path, run: &SlidingRun) -> Result<(), VtkError> {
    let h = &run.history;
    let mut states: Vec<State> = h
        .snapshots
        .iter()
        .map(|s| State {
            half_periods: s.half_period,
            wear_body1: &s.wear_body1,
            wear_body2: &s.track,
            pressure: step_end(&s.pressures, s.step, run.settings.monotonic),
        })
        .collect();
    if let Some(last) = h.steps.last() {
        if states.last().map(|s| s.half_periods) != Some(last.half_period) {
            let direction = usize::from(!run.settings.monotonic && last.step % 2 == 0);
            states.push(State {
                half_periods: last.half_period,
                wear_body1: &h.wear_body1,
                wear_body2: &h.track.wear,
                pressure: step_end(&h.last_cycle[direction], last.step, run.settings.monotonic),
            });
        }
    }
    let mut entries = Vec::new();
    for (k, state) in states.iter().enumerate() {
        for (part, name) in [(0, "track"), (1, "slider")] {
            let file = format!("vtk/{name}_{k:04}.vtu");
            let path = dir.join(&file);
            let text = if part == 0 {
                track_piece(run, state)
            } else {
                slider_piece(run, state)
            };
            write(&path, &text).map_err(io(&path))?;
            entries.push(PvdEntry {
                time: state.half_periods as f64,
                part,
                file,
            });
        }
    }
    let path = dir.join(super::PVD_NAME);
    write_pvd(&path, &entries).map_err(io(&path))?;
    Ok(())
}

/// The pressure at the last position a step visited (`pressures` in the order of the
/// positions): the last on a '+' step, the first on a '−' one; empty if none was kept.
fn step_end(pressures: &[Vec<f64>], step: usize, monotonic: bool) -> &[f64] {
    let forward = monotonic || step % 2 == 1;
    let at = if forward {
        pressures.last()
    } else {
        pressures.first()
    };
    at.map_or(&[], Vec::as_slice)
}

fn track_piece(run: &SlidingRun, state: &State) -> String {
    let points: Vec<[f64; 2]> = run.track_surface.iter().map(|s| s.0).collect();
    let worn: Vec<[f64; 2]> = (run.track_surface.iter().zip(state.wear_body2))
        .map(|((_, n), w)| [-w * n[0], -w * n[1]])
        .collect();
    let n = points.len();
    let mut cells: Vec<Vec<usize>> = (1..n).map(|i| vec![i - 1, i]).collect();
    if run.history.track.period.is_some() && n > 2 {
        cells.push(vec![n - 1, 0]);
    }
    Piece {
        points: &points,
        cells,
        cell_type: VTK_LINE,
        point_vectors: vec![("worn_surface", &worn)],
        point_scalars: vec![("wear_body2", state.wear_body2.to_vec())],
        cell_ints: vec![],
    }
    .xml()
}

fn slider_piece(run: &SlidingRun, state: &State) -> String {
    let points = &run.contact.contacts[0].points;
    // n_c is body 1's outward normal: its worn surface is drawn back along it.
    let worn: Vec<[f64; 2]> = (points.normal.iter().zip(state.wear_body1))
        .map(|(n, w)| [-w * n[0], -w * n[1]])
        .collect();
    let n = points.x.len();
    let mut scalars = vec![("wear_body1", state.wear_body1.to_vec())];
    if state.pressure.len() == n {
        scalars.push(("pressure", state.pressure.to_vec()));
    }
    Piece {
        points: &points.x,
        cells: (1..n).map(|i| vec![i - 1, i]).collect(),
        cell_type: VTK_LINE,
        point_vectors: vec![("worn_surface", &worn)],
        point_scalars: scalars,
        cell_ints: vec![],
    }
    .xml()
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> VtkError + '_ {
    move |source| {
        VtkError::Output(OutputError {
            path: path.display().to_string(),
            source,
        })
    }
}
