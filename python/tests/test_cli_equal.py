"""Every built-in example from Python equals the command line's summary.json to round-off.

Both sides run the same library code on the same problem text, so the profiles agree to the
last bit in practice; the tolerance 1e-12 relative (a few hundred ulps) only allows for a
different instruction order between two builds (the binary and the wheel are compiled
separately). Timings (`seconds`) are the only fields left out.
"""

import json

import numpy as np
import pytest

import wearfem

STEADY = [
    "punch-a",
    "punch-b20",
    "punch-b40",
    "punch-b40-b1.2",
    "punch-b40-b0.8",
    "punch-b40-variant2",
    "punch-b40-variant3",
    "punch-b20-variant2",
    "brake",
]
RTOL = 1e-12


def close(a, b, path="summary"):
    """Recursive equality of two JSON values, numbers to RTOL, timings and build stamp skipped."""
    if isinstance(a, dict):
        assert set(a) == set(b), f"{path}: keys {sorted(a)} != {sorted(b)}"
        for k in a:
            # wearfem_version differs when the binary and the wheel were built at different
            # commits; test_api.py::test_version_stamp_matches_the_command_line says so once.
            if "seconds" in k or k == "wearfem_version":
                continue
            close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), f"{path}: lengths {len(a)} != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{path}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert a is not None and b is not None, f"{path}: {a} != {b}"
        scale = max(abs(a), abs(b), 1e-300)
        assert abs(a - b) <= RTOL * scale, f"{path}: {a!r} != {b!r}"
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"


def test_examples_listed():
    # Every example tested here is built in (newer ones, e.g. the mortar examples, are
    # compared by the Rust tests).
    assert set(STEADY) | {"lame"} <= set(wearfem.examples())


@pytest.mark.parametrize("name", STEADY)
def test_steady_equals_cli(name, cli):
    proc, out = cli("steady", name)
    s = wearfem.Problem.builtin(name).steady()
    if proc.returncode == 1:
        # The CLI says the iteration did not converge: Python returns it with its status.
        assert not s.converged
    else:
        assert proc.returncode == 0, proc.stderr
    expected = json.loads((out / "summary.json").read_text())
    close(expected, s.summary)
    np.testing.assert_array_equal(s.p_plus, np.array(expected["p_plus"], dtype=float))
    np.testing.assert_array_equal(s.x, np.array(expected["x"], dtype=float))


def test_elastic_equals_cli(cli):
    proc, out = cli("elastic", "lame")
    assert proc.returncode == 0, proc.stderr
    close(json.loads((out / "summary.json").read_text()), wearfem.Problem.builtin("lame").elastic().summary)


@pytest.mark.parametrize("name", ["punch-b40", "brake"])
def test_contact_equals_cli(name, cli):
    proc, out = cli("contact", name)
    assert proc.returncode == 0, proc.stderr
    c = wearfem.Problem.builtin(name).contact()
    close(json.loads((out / "summary.json").read_text()), c.summary)
    assert c.status == "solved"


@pytest.mark.parametrize("name,steps", [("punch-b40", 12), ("punch-a", 6)])
def test_run_shortened_equals_cli(name, steps, cli):
    proc, out = cli("run", name, "--steps", str(steps))
    assert proc.returncode == 0, proc.stderr
    seen = []
    r = wearfem.Problem.builtin(name).run(steps=steps, progress=lambda step, hp: seen.append(step))
    close(json.loads((out / "summary.json").read_text()), r.summary)
    assert seen == list(range(1, steps + 1))
    assert list(r.history["step"]) == seen
    # Ready for pandas: every column as long as the history.
    assert {len(v) for v in r.history.values()} == {steps}


def test_overrides_equal_cli_set(cli):
    proc, out = cli("steady", "punch-b40", "--set", "contact.friction=0.2", "--set", "plate.pin=[1000, 120]")
    assert proc.returncode == 0, proc.stderr
    p = wearfem.Problem.builtin("punch-b40").with_overrides({"contact.friction": 0.2, "plate.pin": [1000, 120]})
    close(json.loads((out / "summary.json").read_text()), p.steady().summary)


@pytest.mark.parametrize("job", ["contact", "steady"])
def test_fretting_equals_cli(job, cli):
    proc, out = cli(job, "fretting-cylinder")
    assert proc.returncode == 0, proc.stderr
    problem = wearfem.Problem.builtin("fretting-cylinder")
    ours = problem.fretting_contact() if job == "contact" else problem.fretting_steady()
    close(json.loads((out / "summary.json").read_text()), ours)


def test_fretting_run_equals_cli(cli):
    proc, out = cli("run", "fretting-cylinder", "--set", "wear.cycles=1000", "--set", "wear.record_cycles=[]")
    assert proc.returncode == 0, proc.stderr
    ours = wearfem.Problem.builtin("fretting-cylinder").with_overrides({"wear.record_cycles": []}).fretting_run(cycles=1000)
    close(json.loads((out / "summary.json").read_text()), ours)
    # Nothing wears where the points stick through the cycle.
    final = ours["final"]
    assert all(w == 0.0 for w, s in zip(final["worn_depth"], final["sticks"]) if s)


def test_fretting_problem_refuses_the_full_slip_jobs():
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.builtin("fretting-cylinder").contact()
    assert "fretting" in str(e.value)
