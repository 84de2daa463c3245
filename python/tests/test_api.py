"""The Python API: errors, overrides, round trips, pickling."""

import math
import pickle

import numpy as np
import pytest

import wearfem


@pytest.fixture(scope="module")
def punch():
    return wearfem.Problem.builtin("punch-b40")


def test_bad_key_raises_with_key(punch):
    with pytest.raises(wearfem.WearfemError) as e:
        punch.with_overrides({"contact.frictoin": 0.3})
    assert e.value.key == "contact.frictoin"
    assert e.value.file == "built-in example punch-b40"
    assert isinstance(e.value, ValueError)
    assert str(e.value).startswith("built-in example punch-b40: contact.frictoin: ")


def test_a_misspelt_key_in_a_file_is_named_without_its_line():
    """Red team C: ``.key`` was ``"contact.frictoin (line 4)"``; the line is ``.line``, and
    ``str(error)`` stays the command line's message."""
    text = wearfem.Problem.builtin("punch-b40").to_toml().replace("friction = ", "frictoin = ")
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.from_toml(text, "misspelt.toml")
    line = next(i + 1 for i, l in enumerate(text.splitlines()) if l.startswith("frictoin"))
    assert e.value.key == "contact.frictoin" and e.value.line == line
    assert str(e.value).startswith(f"misspelt.toml: contact.frictoin (line {line}): ")
    import pickle

    again = pickle.loads(pickle.dumps(e.value))
    assert (again.key, again.line, str(again)) == (e.value.key, line, str(e.value))


def test_a_template_is_completed_by_the_overrides_it_is_read_with(punch, tmp_path):
    """A file that leaves ``analysis.p`` to its overrides, as ``--set`` may (red team: Python
    could not read such a file at all, and blamed a bad override on the missing key)."""
    text = wearfem.Problem.builtin("punch-b40").to_toml()
    template = _re_sub_line(text, "p = 8", "")
    path = tmp_path / "template.toml"
    path.write_text(template)
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.from_file(path)
    assert e.value.key == "analysis.p"
    completed = wearfem.Problem.from_file(path, overrides={"analysis.p": 8})
    assert completed.steady().p_plus.tolist() == punch.steady().p_plus.tolist()
    # Variants of it, as a study makes them.
    assert completed.with_overrides({"contact.friction": 0.1}).title == punch.title
    # A bad override is named, not the key it was meant to supply.
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.from_toml(template, "template.toml", overrides={"analysis.p": 8.5})
    assert e.value.key == "analysis.p" and e.value.line is None


def _re_sub_line(text, line, by):
    lines = text.splitlines()
    assert line in lines, line
    return "\n".join(by if l == line else l for l in lines) + "\n"


def test_bad_value_type_raises_with_key(punch):
    with pytest.raises(wearfem.ProblemError) as e:
        punch.with_overrides({"contact.friction": "lots"})
    assert e.value.key == "contact.friction"


def test_broken_file_names_key(tmp_path):
    text = wearfem.Problem.builtin("punch-b40").to_toml()
    bad = tmp_path / "bad.toml"
    # A negative Young's modulus: the schema reads it, validation must refuse it by key.
    p = wearfem.Problem.from_toml(text, str(bad))
    for key in ["materials.steel.young", "materials.punch.young"]:
        try:
            p.with_overrides({key: -1.0})
        except wearfem.WearfemError as e:
            assert e.key.startswith("materials.") and e.key.endswith("young"), e.key
            assert e.file == str(bad)
            break
    else:
        pytest.fail("no material named steel or punch in punch-b40")


def test_missing_file():
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.from_file("/nonexistent/x.toml")
    assert e.value.file == "/nonexistent/x.toml"


def test_unknown_builtin():
    with pytest.raises(wearfem.WearfemError, match="punch-b40"):
        wearfem.Problem.builtin("punch-b41")


def test_syntax_error_names_line():
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.from_toml("title = 'x'\n[contact\n", "broken.toml")
    assert e.value.file == "broken.toml"
    assert e.value.key.startswith("line ")
    assert e.value.line == int(e.value.key.split()[1])


def test_overrides_change_what_they_name(punch):
    base = punch.steady()
    low = punch.with_overrides({"contact.friction": 0.05}).steady()
    assert base.converged and low.converged
    # Friction tilts the punch: a different friction must change the pressure profile ...
    assert np.max(np.abs(base.p_plus - low.p_plus)) > 1e-3 * np.max(base.p_plus)
    # ... and the override is recorded where it was set, nothing else.
    assert punch.with_overrides({"contact.friction": 0.05}).overrides == [("contact.friction", "0.05")]
    assert "friction = 0.05" in punch.with_overrides({"contact.friction": 0.05}).to_toml()


def test_numpy_values_are_taken_as_python_ones(punch):
    """A study's values often come from numpy (linspace, arrays): the same override as with
    plain Python values, key for key."""
    plain = punch.with_overrides({"plate.pin": [1100.0, 40.0], "contact.friction": 0.3, "bodies[1].blocks[0].v": [0.0, 0.5, 1.0]})
    numpy = punch.with_overrides(
        {"plate.pin": np.array([1100.0, 40.0]), "contact.friction": np.float64(0.3), "bodies[1].blocks[0].v": np.linspace(0.0, 1.0, 3)}
    )
    assert numpy.overrides == plain.overrides


def test_failed_contact_solve_has_no_values(punch):
    """μ = 5 tips the pinned plate: the result says so and carries no values of the solve."""
    r = punch.with_overrides({"contact.friction": 5.0}).contact()
    assert r.status == "failed" and not r.converged
    assert r.pressure is None and r.gap is None and r.rigid is None


def test_steady_that_did_not_converge_has_no_values(punch):
    """Red-team review 4, F2: μ = 0.9 on punch-b40 has no steady state of one rigid wear per
    period (the friction moment separates the half cycles' zones); the iteration stops at its
    limit. The result carries the status and residual and None for every value (the command
    line writes nothing and exits 1), not the last iterate's pressures and shape."""
    s = punch.with_overrides({"contact.friction": 0.9}).steady()
    assert s.status == "MaxIterations" and not s.converged
    assert s.wear_residual > 0.1
    for name in ["p_plus", "p_minus", "p_sum", "shape", "rigid_wear_per_period", "probes"]:
        assert getattr(s, name) is None, name
    assert s.summary["p_plus"] is None and s.summary["edge_ends_in_contact"] == []
    # A converged one still has all of them.
    ok = punch.with_overrides({"contact.friction": 0.1}).steady()
    assert ok.converged and ok.p_plus is not None and ok.probes is not None


def test_override_load_scales_pressure(punch):
    """The paper's eq. 23a: in the periodic steady state p⁺ + p⁻ = 2 p̃ at every contact
    point, p̃ = the normal traction on the punch top (punch and top are equally wide). Set
    the traction through an override and the summed pressure must follow it. Tolerance: the
    steady Newton iteration stops at a relative wear residual near 1e-10; 1e-7 of p̃ leaves a
    wide margin while any load that did not reach the model would miss by 100 %."""
    for traction in [16.666, 40.0]:
        s = punch.with_overrides({"bodies[0].tractions[0].normal": traction}).steady()
        assert s.converged, s.status
        np.testing.assert_allclose(s.p_sum, 2 * traction, rtol=1e-7)


def test_to_toml_round_trip(punch):
    p = punch.with_overrides({"contact.friction": 0.35})
    q = wearfem.Problem.from_toml(p.to_toml(), "round-trip.toml")
    np.testing.assert_array_equal(p.steady().p_plus, q.steady().p_plus)


def test_from_dict_equals_text():
    tomllib = pytest.importorskip("tomllib", reason="tomllib is in the standard library from Python 3.11")

    text = wearfem.Problem.builtin("punch-b40").to_toml()
    d = tomllib.loads(text)
    a = wearfem.Problem.from_dict(d).steady()
    b = wearfem.Problem.builtin("punch-b40").steady()
    np.testing.assert_array_equal(a.p_plus, b.p_plus)
    np.testing.assert_array_equal(a.shape, b.shape)


def test_from_dict_errors_name_the_key():
    # Red team 19: a wrong value in a dict named only "line 5" of a text the caller never saw.
    tomllib = pytest.importorskip("tomllib", reason="tomllib is in the standard library from Python 3.11")

    d = tomllib.loads(wearfem.Problem.builtin("punch-b40").to_toml())
    cases = [
        ({**d, "contact": {**d["contact"], "friction": "x"}}, "contact.friction"),
        ({**d, "wear": {**d["wear"], "body1": {**d["wear"]["body1"], "bta": 2}}}, "wear.body1.bta"),
        ({**d, "probes": {"M": {"body": "punch"}}}, "probes.M.at"),
    ]
    for broken, key in cases:
        with pytest.raises(wearfem.WearfemError) as e:
            wearfem.Problem.from_dict(broken)
        assert e.value.key == key
        assert e.value.file == "<dict>"


def test_pickle_keeps_overrides(punch):
    p = punch.with_overrides({"contact.friction": 0.1})
    q = pickle.loads(pickle.dumps(p))
    assert q.overrides == p.overrides
    np.testing.assert_array_equal(p.steady().p_plus, q.steady().p_plus)


def test_an_unpickled_problem_is_built_when_first_used(punch):
    # Unpickling keeps the text and overrides and builds the model on first use (Dask's
    # scheduler unpickles every task argument it never uses). A pickle that no longer builds
    # (one written by another version of wearfem, imitated here) must then raise the same
    # error as building it, naming the key, not fail silently or crash.
    restore, (text, file, sets) = punch.with_overrides({"contact.friction": 0.1})._inner.__reduce__()
    broken = restore(text, file, [("analysis.thickness", "-1.0")])
    q = wearfem.Problem(broken)
    with pytest.raises(wearfem.WearfemError, match="analysis.thickness"):
        q.steady()
    with pytest.raises(wearfem.WearfemError, match="analysis.thickness"):
        q.title


def test_progress_exception_stops_the_run_at_once(punch):
    """An exception of the callback stops the run after its step (red team 24: all 400 000
    steps ran first), and is raised."""
    seen = []

    def boom(step, half_period):
        seen.append(step)
        if step == 10:
            raise RuntimeError("stop")

    with pytest.raises(RuntimeError, match="stop"):
        punch.run(steps=100_000, progress=boom)
    assert seen == list(range(1, 11))


def test_ctrl_c_stops_a_run(punch):
    """SIGINT stops a run without a progress callback too: the run lets Python handle its
    signals every 50 ms. 10⁶ steps of punch-b40 take tens of seconds; the signal comes from
    a timer 0.3 s in, and the run must end with KeyboardInterrupt rather than finish."""
    import os
    import signal
    import threading

    if not hasattr(signal, "SIGINT") or threading.current_thread() is not threading.main_thread():
        pytest.skip("needs SIGINT in the main thread")
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            punch.run(steps=1_000_000)
    finally:
        timer.cancel()


def test_run_arguments_are_checked_before_running(punch):
    with pytest.raises(ValueError, match="steps"):
        punch.run(steps=-1)
    with pytest.raises(TypeError, match="progress"):
        punch.run(steps=3, progress=5)


def test_steady_result_fields(punch):
    s = punch.steady()
    assert s.x.shape == s.p_plus.shape == s.shape.shape
    np.testing.assert_array_equal(s.p_sum, s.p_plus + s.p_minus)
    assert set(s.rigid_wear_per_period) >= {"lambda_F"}
    assert all(np.isfinite(v) for v in s.probes.values())


def test_non_converged_steady_is_a_result_not_an_exception(punch, cli):
    """μ = 0.4 with the pin 60 mm up: the friction moment separates the two half cycles'
    contact zones and no steady state with one rigid wear per period exists (README,
    Limitations). The command line exits 1 and says so; Python returns the status."""
    sets = {"contact.friction": 0.4, "plate.pin": [1100, 160]}
    s = punch.with_overrides(sets).steady()
    assert not s.converged and s.status != "Solved"
    proc, out = cli("steady", "punch-b40", "--set", "contact.friction=0.4", "--set", "plate.pin=[1100, 160]")
    assert proc.returncode == 1 and "did not converge" in proc.stderr


def test_version_stamp_matches_the_command_line(punch, wearfem_bin):
    """Red-team review 4, N1: a stale wheel went unnoticed. ``wearfem.__version__`` is the
    library's build stamp (crate version + git commit), the ``wearfem_version`` of every
    summary and what ``wearfem --version`` prints for a binary built from the same source."""
    import subprocess

    v = wearfem.__version__
    assert v.startswith("0.") and v == punch.contact().summary["wearfem_version"]
    assert punch.steady().summary["wearfem_version"] == v
    cli = subprocess.run([str(wearfem_bin), "--version"], capture_output=True, text=True).stdout.split()
    assert cli == ["wearfem", v], (
        f"{wearfem_bin} was built from another commit than this wheel: rebuild it (cargo build --release)"
    )


def test_run_gives_the_wear_apart_from_the_shape():
    # A crowned punch (contact.initial_shape, R = 20 m about x = 1100, no shift to zero):
    # shape is the gap's profile (crown plus wear), wear the wear alone; the corner x = 1070,
    # never in contact in 4 half periods, has no wear and the crown's 22.5 µm of shape.
    text = wearfem.Problem.builtin("punch-a").to_toml().replace("shape_zero_at = 1100.0", "")
    problem = wearfem.Problem.from_toml(text).with_overrides(
        {"contact.initial_shape": {"radius": 20000.0, "center_x": 1100.0},
         "wear.extrapolation": [{"k": 1}]}
    )
    r = problem.run(steps=4)
    crown = 20000.0 - np.sqrt(20000.0**2 - 30.0**2)
    assert r.x[0] == 1070.0 and r.p_plus[0] == 0.0 and r.p_minus[0] == 0.0
    assert r.wear[0] == 0.0
    assert abs(r.shape[0] - crown) < 1e-9
    # Elsewhere the two differ by the crown alone (to round-off of the gap's sum).
    crowns = 20000.0 - np.sqrt(20000.0**2 - (r.x - 1100.0) ** 2)
    np.testing.assert_allclose(r.shape - r.wear, crowns, rtol=0, atol=1e-12)


def test_each_body_s_wear_and_volume():
    # Both bodies wear, a = b = 1: each body's worn volume is β̃ᵢ F s (F = 16.666 MPa × 60 mm
    # × 10 mm, s the sliding distance), and without a shift to zero the two profiles add up
    # to the wear (round-off).
    text = wearfem.Problem.builtin("punch-a").to_toml().replace("shape_zero_at = 1100.0", "")
    beta1 = 3.9269908169872414e-8
    problem = wearfem.Problem.from_toml(text).with_overrides(
        {"wear.body2": {"beta": 0.5 * beta1, "a": 1.0, "b": 1.0}}
    )
    r = problem.run(steps=20)
    force, s = 16.666 * 60.0 * 10.0, r.sliding_distance_m * 1000.0
    np.testing.assert_allclose(r.worn_volume, [beta1 * force * s, 0.5 * beta1 * force * s], rtol=1e-9)
    np.testing.assert_allclose(r.wear_body1 + r.wear_body2, r.wear, rtol=0, atol=1e-15)
    np.testing.assert_allclose(r.wear_body2, 0.5 * r.wear_body1, rtol=0, atol=1e-15)
    assert r.worn_depth == [r.wear_body1.max(), r.wear_body2.max()]


def test_warnings_reach_python():
    # punch-b40 with β̃ × 1000: one half period's wear moves the pressure by 60 % of its
    # peak, outside the half-period scheme (docs/validation.md); the command line warns, and
    # so does Python, through warnings.warn and the result's list.
    import warnings

    problem = wearfem.Problem.builtin("punch-b40").with_overrides(
        {"wear.body1.beta": 3.9269908169872414e-5}
    )
    with pytest.warns(wearfem.WearfemWarning, match="one half period's wear changes"):
        steady = problem.steady()
    assert any("one half period" in w for w in steady.warnings)
    assert steady.summary["warnings"] == steady.warnings
    # The shipped example has none: no false alarm.
    with warnings.catch_warnings():
        warnings.simplefilter("error", wearfem.WearfemWarning)
        quiet = wearfem.Problem.builtin("punch-b40").steady()
        run = wearfem.Problem.builtin("punch-b40").run(steps=100)
    assert quiet.warnings == [] and run.warnings == []


def test_contact_warnings_reach_python():
    # Hertz with body 2 at p = 1 under body 1 at p = 8: the peak is 9 % above the closed form
    # and the zone is reported as unresolved by body 2 (tests/mortar.rs); so in Python too.
    problem = wearfem.Problem.builtin("hertz").with_overrides({"bodies[1].p": 1})
    with pytest.warns(wearfem.WearfemWarning, match="ends inside an element of body 2"):
        c = problem.contact()
    assert c.warnings and c.summary["warnings"] == c.warnings


def test_a_run_without_a_full_cycle_says_so_as_a_study_row(punch):
    # One half period: converged (nothing failed) but no final profiles; the status says why,
    # the same words as the study's row for the same overrides.
    run = punch.run(steps=1)
    assert run.converged and run.p_plus is None
    table = wearfem.study(punch, [{"wear.steps": 1, "wear.record": []}], job="run")
    assert run.status == table["status"][0] != "solved"


def test_from_dict_keys_are_plain_strings_and_numpy_bools_are_bools():
    """Red team 24: np.bool_ was refused; a non-string key and a dotted key came out garbled
    ('5.5', '"contact.friction".contact.friction')."""
    tomllib = pytest.importorskip("tomllib")  # Python 3.11+
    d = tomllib.loads(wearfem.Problem.builtin("punch-b40").to_toml())
    d["analysis"]["p_check"] = np.bool_(False)
    wearfem.Problem.from_dict(d)
    with pytest.raises(wearfem.WearfemError) as bad:
        wearfem.Problem.from_dict({**d, 5: 1})
    assert bad.value.key == "5" and "strings" in bad.value.message
    with pytest.raises(wearfem.WearfemError) as dotted:
        wearfem.Problem.from_dict({**d, "contact.friction": 0.1})
    assert dotted.value.key == "contact.friction" and "nest" in dotted.value.message


def test_a_file_that_is_not_utf8_names_the_file(tmp_path):
    path = tmp_path / "latin1.toml"
    path.write_bytes("title = \"Reibung \xb5\"\n".encode("latin-1"))
    with pytest.raises(wearfem.WearfemError, match="UTF-8") as e:
        wearfem.Problem.from_file(path)
    assert e.value.file == str(path)


def test_float_array_is_importable():
    from wearfem import FloatArray  # noqa: F401  (the stubs declare it)


def test_problems_with_the_same_text_and_overrides_are_equal(punch):
    """Red team 24: a problem and its own pickle compared unequal."""
    variant = punch.with_overrides({"contact.friction": 0.1})
    assert pickle.loads(pickle.dumps(variant)) == variant
    assert hash(pickle.loads(pickle.dumps(variant))) == hash(variant)
    assert variant != punch
    assert punch.with_overrides({"contact.friction": 0.1}) == variant


def test_the_type_stubs_match_the_module(tmp_path):
    """mypy's stubtest compares __init__.pyi and _wearfem.pyi with what the installed module
    has at run time (red team 24: `FloatArray` was in the stubs only, the compiled module had
    no stub, constructors and `__all__` differed)."""
    pytest.importorskip("mypy")
    import subprocess
    import sys

    config = tmp_path / "mypy.ini"
    config.write_text("[mypy]\nignore_missing_imports = True\n")  # pandas has no stubs here
    proc = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "wearfem", "--mypy-config-file", str(config)],
        capture_output=True,
        text=True,
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_sliding_pairs_run_from_python_with_archards_volumes():
    """Issue 29: the tribometer's sliding pairs, 6 half periods of a 4 mm stroke under 500 N:
    each body's worn volume is k F s (Archard, a = b = 1) to 1e-6; the fixed pairs' run
    refuses sliding pairs by name."""
    tribometer = wearfem.Problem.builtin("tribometer")
    summary = tribometer.run_sliding(steps=6)
    s = 6 * 4.0 / 1000.0  # m
    for body, k in [(0, 5.0e-7), (1, 1.0e-6)]:
        assert summary["worn_volume"][body] == pytest.approx(k * 500.0 * s, rel=1e-6)
    assert len(summary["track"]["x"]) == len(summary["track"]["wear_body2"])
    with pytest.raises(wearfem.WearfemError) as e:
        tribometer.run(steps=2)
    assert e.value.key == "contact.pairs"


def test_a_turning_rings_steady_state_from_python():
    """Issue 29: the block on a ring turning under it has a steady state. The block's face is
    flat and its plate does not tilt, so the steady pressure is uniform, F/(L t), and the ring
    wears evenly by k₂ F/(2πR t) per metre (closed forms; 1e-9: the Newton solve's round-off).
    The tribometer's reciprocating stroke has none, and says so by key."""
    ring = wearfem.Problem.builtin("block-on-ring")
    steady = ring.steady()
    assert steady.converged
    # The load is the top traction (1.3338332917 MPa, 133.4 N to 8 digits) times L t.
    traction = 1.3338332917
    assert steady.p_plus == pytest.approx(traction, rel=1e-9)
    per_metre = 1.0e-8 * traction * 6.35 / (2.0 * math.pi * 17.5)
    assert steady["track"]["body2_depth_per_metre"] == pytest.approx(per_metre, rel=1e-9)
    assert steady["track"]["position_spread"] < 1e-6
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.Problem.builtin("tribometer").steady()
    assert e.value.key == "contact.pairs"
    assert "no periodic steady state" in str(e.value)


def test_a_turning_washer_reports_its_torque():
    """Bodies of revolution turning about their axis (`thrust-washer`): the history has the
    friction torque, which tends to the uniform-wear law's μF(r_o + r_i)/2 = 9000 N·mm (1 %:
    the issue's bound; the run is at its steady state to 1e-10 after 300 steps), and the
    summary's `turn` has the power ω T; the sliding distance, which depends on the radius,
    is None."""
    r = wearfem.Problem.builtin("thrust-washer").run()
    assert r.converged, r.status
    torque = r.history["torque"]
    assert len(torque) == len(r.history["step"])
    assert abs(torque[-1] - 9000.0) < 0.01 * 9000.0
    assert abs(r.turn["power_W"] - 10.0 * torque[-1] / 1000.0) < 1e-9 * r.turn["power_W"]
    assert r.sliding_distance_m is None
