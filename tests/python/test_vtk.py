"""ParaView output read back by meshio (a real VTK XML reader) and checked against summary.json.

The binary (WEARFEM_BIN) is run on built-in examples into temporary directories; every file of
each results.pvd must be readable, and the values at known points must be those that
summary.json reports for the same state.
"""

import json
import os
import subprocess
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

BIN = os.environ.get("WEARFEM_BIN", "target/release/wearfem")


def run(tmp_path, *args):
    out = tmp_path / "out"
    subprocess.run([BIN, *args, "--vtk", "--out", str(out)], check=True, capture_output=True)
    summary = json.loads((out / "summary.json").read_text())
    return out, summary


def scalar(values):
    """A scalar array as a flat vector (meshio keeps NumberOfComponents = 1 as a column)."""
    return np.asarray(values).reshape(-1)


def cells(mesh, name):
    return scalar(np.concatenate(mesh.cell_data[name]))


def collection(out):
    """(time, part, mesh) of every data set in results.pvd, each read by meshio."""
    root = ET.parse(out / "results.pvd").getroot()
    sets = root.find("Collection").findall("DataSet")
    assert sets, "results.pvd lists no data sets"
    return [(float(d.get("timestep")), int(d.get("part")), meshio.read(out / d.get("file"))) for d in sets]


def check_bodies(mesh, bodies):
    """Sub-quads with both cell data, finite fields, von Mises ≥ 0."""
    assert mesh.points.shape[1] == 3 and np.all(mesh.points[:, 2] == 0.0)
    assert [c.type for c in mesh.cells] == ["quad"]
    assert sorted(set(cells(mesh, "body").tolist())) == bodies
    assert np.all(cells(mesh, "material") >= 0)
    for name in ["displacement", "stress_xx", "stress_zz", "stress_xz", "von_mises"]:
        assert np.all(np.isfinite(mesh.point_data[name])), name
    assert np.all(np.isfinite(mesh.points))
    assert mesh.point_data["displacement"].shape == (len(mesh.points), 3)
    assert np.all(scalar(mesh.point_data["von_mises"]) >= 0.0)


def contact_line(sets, time):
    meshes = [m for t, part, m in sets if part == 1 and t == time]
    assert len(meshes) == 1, f"one contact line at time {time}"
    return meshes[0]


def test_contact_job_matches_summary(tmp_path):
    out, summary = run(tmp_path, "contact", "punch-b40")
    sets = collection(out)
    assert len(sets) == 2
    check_bodies(next(m for _, part, m in sets if part == 0), [1, 2])
    line = contact_line(sets, 0.0)
    assert [c.type for c in line.cells] == ["line"]
    # Same solve as summary.json, written with 17 significant digits: round-off only.
    np.testing.assert_allclose(line.points[:, 0], summary["x"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(line.points[:, 1], summary["z"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(scalar(line.point_data["pressure"]), summary["pressure"], rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(scalar(line.point_data["gap"]), summary["gap"], rtol=1e-12, atol=1e-12)


def test_contact_line_displacement_is_the_bodies_displacement_there(tmp_path):
    out, _ = run(tmp_path, "contact", "punch-b40")
    sets = collection(out)
    bodies = next(m for _, part, m in sets if part == 0)
    line = contact_line(sets, 0.0)
    body = cells(bodies, "body")
    quads = bodies.cells[0].data
    punch_points = np.unique(quads[body == 1].ravel())
    for x, u in zip(line.points, line.point_data["displacement"]):
        d = np.linalg.norm(bodies.points[punch_points] - x, axis=1)
        near = punch_points[d < 1e-9]
        assert len(near) > 0, f"contact point {x} is not a sample point of the punch"
        # Continuous displacement: every element's sample there agrees to round-off.
        np.testing.assert_allclose(bodies.point_data["displacement"][near], np.tile(u, (len(near), 1)), atol=1e-12)


def test_elastic_job_matches_the_probes(tmp_path):
    out, summary = run(tmp_path, "elastic", "lame")
    sets = collection(out)
    assert len(sets) == 1
    mesh = sets[0][2]
    check_bodies(mesh, [1])
    probes = {"inner": [100.0, 0.0], "outer": [200.0, 0.0]}
    for name, at in probes.items():
        d = np.linalg.norm(mesh.points[:, :2] - at, axis=1)
        near = d < 1e-9
        assert near.any(), f"probe {name} is not a sample point"
        expected = summary["probes"][name]
        np.testing.assert_allclose(mesh.point_data["displacement"][near][:, :2],
                                   np.tile(expected["displacement"], (near.sum(), 1)), rtol=1e-9, atol=1e-15)
        stress = np.stack([scalar(mesh.point_data[k])[near] for k in ["stress_xx", "stress_zz", "stress_xz"]], axis=1)
        # Stress is evaluated per element; at p = 8 the Lamé field is continuous to ~1e-9.
        np.testing.assert_allclose(stress, np.tile(expected["stress"], (near.sum(), 1)), rtol=0, atol=1e-6 * 100.0)


def test_run_job_has_every_recorded_step(tmp_path):
    out, summary = run(tmp_path, "run", "punch-b40", "--steps", "103", "--set", "wear.record=[1,2,51,52,101,102]")
    sets = collection(out)
    assert {s["direction"] for s in summary["snapshots"]} == {"+", "\u2212"}
    times = sorted({t for t, _, _ in sets})
    recorded = [s["half_period"] for s in summary["snapshots"]]
    last = summary["steps"][-1]["half_period"]
    assert times == sorted({0.0, *map(float, recorded), float(last)})
    for t, part, mesh in sets:
        if part == 0:
            check_bodies(mesh, [1, 2])
    for snap in summary["snapshots"]:
        line = contact_line(sets, float(snap["half_period"]))
        np.testing.assert_allclose(scalar(line.point_data["pressure_recorded"]), snap["pressure"], rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(scalar(line.point_data["shape"]), snap["shape"], rtol=1e-12, atol=1e-15)
        # The state is solved again from the gap the run's pressure solved (after a '+' step
        # the shape plus the look-ahead); the implicit step with b = 1 solves that contact
        # problem exactly, so the two agree to the solver's round-off, 1e-6 of the peak
        # leaving room for the ASCII round trip. (With the recorded shape alone, '+' steps
        # were 0.2-0.4 % off: review of 2026-11-24.)
        peak = max(snap["pressure"])
        assert np.max(np.abs(scalar(line.point_data["pressure"]) - snap["pressure"])) < 1e-6 * peak
        assert np.all(scalar(line.point_data["gap"]) >= -1e-9)


def test_steady_job_reproduces_both_half_cycles(tmp_path):
    out, summary = run(tmp_path, "steady", "punch-b40")
    sets = collection(out)
    for time, key in [(0.0, "p_plus"), (1.0, "p_minus")]:
        line = contact_line(sets, time)
        np.testing.assert_allclose(scalar(line.point_data["pressure_recorded"]), summary[key], rtol=1e-12, atol=1e-9)
        # The steady shape reproduces its pressures in the contact solver to 1e-8 of the peak
        # (tests/steady.rs); 1e-6 leaves room for the ASCII round trip.
        peak = max(summary[key])
        np.testing.assert_allclose(scalar(line.point_data["pressure"]), summary[key], rtol=0, atol=1e-6 * peak)


def test_plate_edge_moves_with_the_plate(tmp_path):
    """Body 1 is clamped to the rigid plate along its top edge (z = 200): there the displacement
    is the plate's motion λ_F (0, −1) + λ_M (z − 140, −(x − 1100)) about the pin (1100, 140)."""
    out, summary = run(tmp_path, "contact", "punch-b40")
    bodies = next(m for _, part, m in collection(out) if part == 0)
    lam_f, lam_m = summary["rigid"]["lambda_F"], summary["rigid"]["lambda_M"]
    top = np.abs(bodies.points[:, 1] - 200.0) < 1e-9
    assert top.sum() > 0
    x, z = bodies.points[top, 0], bodies.points[top, 1]
    expected = np.stack([lam_m * (z - 140.0), -lam_f - lam_m * (x - 1100.0)], axis=1)
    np.testing.assert_allclose(bodies.point_data["displacement"][top][:, :2], expected, rtol=0, atol=1e-12)
    # The plate really moves: λ_F is the punch's descent under 10 kN, micrometres, not zero.
    assert lam_f > 1e-4


@pytest.mark.parametrize("example", ["punch-b40", "brake"])
def test_sub_cells_are_counter_clockwise(tmp_path, example):
    """Every sub-quadrilateral, straight or on an arc, has positive area in VTK's node order."""
    out, _ = run(tmp_path, "contact", example)
    bodies = next(m for _, part, m in collection(out) if part == 0)
    p = bodies.points[bodies.cells[0].data][:, :, :2]
    area = 0.5 * np.sum(p[:, :, 0] * np.roll(p[:, :, 1], -1, axis=1) - np.roll(p[:, :, 0], -1, axis=1) * p[:, :, 1], axis=1)
    assert np.all(area > 0)
