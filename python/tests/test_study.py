"""Studies: serial, thread pool and Dask give the same rows, equal to `wearfem sweep`."""

import concurrent.futures
import json

import numpy as np
import pytest

import wearfem
from wearfem._study import variants

RESULTS = ["status", "converged", "peak_p_plus", "peak_p_minus", "shape_range", "lambda_F_per_period"]


@pytest.fixture(scope="module")
def punch():
    return wearfem.Problem.builtin("punch-b40")


GRID = {"contact.friction": [0.1, 0.2, 0.25, 0.3], "plate.pin": [[1100, 120], [1100, 140]]}


def test_variants_product_first_key_slowest():
    v = variants({"a": [1, 2], "b": [3, 4, 5]})
    assert v == [{"a": a, "b": b} for a in [1, 2] for b in [3, 4, 5]]
    assert variants([{"a": 1}, {"b": 2}]) == [{"a": 1}, {"b": 2}]


def test_study_rows_equal_single_solves(punch):
    table = wearfem.study(punch, {"contact.friction": [0.1, 0.3]})
    assert list(table["contact.friction"]) == [0.1, 0.3]
    for i, mu in enumerate([0.1, 0.3]):
        s = punch.with_overrides({"contact.friction": mu}).steady()
        assert table["peak_p_plus"][i] == s.p_plus.max()
        assert table["peak_p_minus"][i] == s.p_minus.max()
        assert table["shape_range"][i] == s.shape.max() - s.shape.min()
        assert table["lambda_F_per_period"][i] == s.rigid_wear_per_period["lambda_F"]
        assert table["p_plus_M"][i] == s.probes["M"] if "M" in s.probes else True


def test_a_list_study_fills_keys_a_variant_does_not_override_from_the_file(punch):
    """A red team's list study left None where a variant kept the file's value: a friction of
    "None" for a solve at the file's 0.25 (examples/punch-b40.toml)."""
    table = wearfem.study(punch, [{"contact.friction": 0.1}, {"plate.pin": [1100.0, 120.0]}])
    assert list(table["contact.friction"]) == [0.1, 0.25]
    assert [list(p) for p in table["plate.pin"]] == [[1100.0, 140.0], [1100.0, 120.0]]
    # The second row is the file's friction solved: equal to the same variant set explicitly.
    same = wearfem.study(punch, [{"contact.friction": 0.25, "plate.pin": [1100.0, 120.0]}])
    assert table["peak_p_plus"][1] == same["peak_p_plus"][0]
    # A key the file leaves to its default stays None (the file does not hold the value).
    table = wearfem.study(punch, [{"contact.align_target_mesh": True}, {"contact.friction": 0.1}])
    assert table["contact.align_target_mesh"][1] is None


def test_study_equals_cli_sweep(punch, cli):
    proc, out = cli("sweep", "punch-b40", "--set", "contact.friction=[0.1, 0.3]", "--set", "plate.pin=[[1100, 120], [1100, 140]]")
    assert proc.returncode == 0, proc.stderr
    rows = json.loads((out / "sweep.json").read_text())["variants"]
    table = wearfem.study(punch, {"contact.friction": [0.1, 0.3], "plate.pin": [[1100, 120], [1100, 140]]})
    assert len(rows) == len(table["status"]) == 4
    for i, row in enumerate(rows):
        assert table["peak_p_plus"][i] == row["peak_p_plus"]
        assert table["shape_range"][i] == row["shape_range"]


@pytest.mark.parametrize("job", ["steady", "run"])
def test_a_variant_that_did_not_converge_has_nan_values(punch, job):
    """Red-team review 4, F1: a variant that did not converge (μ = 0.9: no steady state of
    this form; the run's first contact solve fails) has NaN in every value column, not the
    numbers of its failed solve (nor 0.0 for a run that made no step)."""
    grid = {"contact.friction": [0.1, 0.9], "wear.steps": [20], "wear.record": [[20]]}
    table = wearfem.study(punch, grid, job=job)
    assert list(table["converged"]) == [True, False]
    values = [c for c in table if c.startswith(("peak_", "p_plus_", "p_minus_", "lambda_")) or c == "shape_range"]
    assert "peak_p_plus" in values and "shape_range" in values
    for c in values:
        assert np.isfinite(table[c][0]), c
        assert np.isnan(table[c][1]), (c, table[c][1])
    assert table["seconds"][1] > 0


def test_bad_variant_raises_before_solving(punch):
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(punch, {"contact.friction": [0.2, "x"]})
    assert e.value.key == "contact.friction"


@pytest.mark.parametrize(
    "key, values",
    [
        ("contact.friction", [0.2, -1.0]),
        ("plate.motion", ["vertical_rotation", "sideways"]),
        ("wear.amplitude", [1.5, -1.0]),
        ("contact.target_edge", ["surface", "nowhere"]),
    ],
)
def test_a_bad_setting_raises_before_any_variant_is_solved(punch, monkeypatch, key, values):
    # These values make a well-formed file that only the contact, plate or wear stage refuses;
    # a serial study must refuse it before it solves the good variant in front of it.
    from wearfem import _study

    solved = []
    monkeypatch.setattr(_study, "solve_variant", lambda p, job="steady": solved.append(p))
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(punch, {key: values})
    assert e.value.key == key
    assert solved == []


def test_a_parallel_study_with_a_bad_variant_names_the_first_and_cancels_its_tasks(punch, monkeypatch):
    # A parallel study submits each task as soon as its variants are built, in a shuffled
    # order: the error must still name the first bad variant in grid order (friction -1 at the
    # start, not -2 further on, which the present order builds first, after one task has been
    # submitted), and every task submitted before must be cancelled.
    from wearfem import _study

    class Recording(concurrent.futures.Executor):
        def __init__(self):
            self.futures = []

        def submit(self, fn, *args):
            future = concurrent.futures.Future()  # never run: pending, so cancel() succeeds
            self.futures.append(future)
            return future

    frictions = [0.1 + 0.002 * i for i in range(40)]
    frictions[0], frictions[30] = -1.0, -2.0
    monkeypatch.setattr(_study, "_workers", lambda executor: 2)
    executor = Recording()
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(punch, {"contact.friction": frictions}, executor=executor)
    assert e.value.key == "contact.friction"
    assert "-1" in str(e.value) and "-2" not in str(e.value), str(e.value)
    assert executor.futures and all(f.cancelled() for f in executor.futures)


def test_thread_pool_equals_serial(punch):
    serial = wearfem.study(punch, GRID)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        threaded = wearfem.study(punch, GRID, executor=pool)
    for k in RESULTS:
        assert list(serial[k]) == list(threaded[k]), k


@pytest.mark.parametrize("chunksize", [1, 2, 3, None, 100])
def test_chunks_keep_the_grid_order(punch, chunksize):
    """Any chunk size, even ones that do not divide the variants, gives the serial table."""
    serial = wearfem.study(punch, GRID)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        chunked = wearfem.study(punch, GRID, executor=pool, chunksize=chunksize)
    for k in RESULTS + list(GRID):
        assert list(serial[k]) == list(chunked[k]), k


@pytest.mark.parametrize("count", [1, 2, 3, 7, 64, 65, 1000])
@pytest.mark.parametrize("workers", [1, 2, 3, 16])
def test_guided_chunks_cover_every_variant_once(count, workers):
    from wearfem._study import _chunk_sizes

    sizes = _chunk_sizes(count, workers)
    assert sum(sizes) == count and min(sizes) >= 1
    # Guided: never growing, so the last tasks are the small ones that balance the workers.
    assert all(a >= b for a, b in zip(sizes, sizes[1:]))


@pytest.mark.parametrize("chunksize", [0, -1, 2.5, "4"])
def test_a_bad_chunksize_is_refused(punch, chunksize):
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        with pytest.raises(ValueError, match="chunksize"):
            wearfem.study(punch, GRID, executor=pool, chunksize=chunksize)


def test_dask_local_cluster_equals_serial(punch):
    """32 variants of punch-b40 on two worker processes: exactly the serial results."""
    distributed = pytest.importorskip("distributed")
    grid = {"contact.friction": list(np.linspace(0.05, 0.4, 8)), "plate.pin": [[1100, z] for z in (110, 125, 140, 160)]}
    serial = wearfem.study(punch, grid)
    assert len(serial["status"]) == 32
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            on_dask = wearfem.study(punch, grid, executor=client)
    for k in RESULTS + ["contact.friction"]:
        a, b = list(serial[k]), list(on_dask[k])
        # Exactly: the same library code on the same input, one thread per task.
        assert a == b or all((x != x and y != y) or x == y for x, y in zip(a, b)), k


def test_without_pandas_a_dict_of_arrays(punch, monkeypatch):
    import builtins

    real = builtins.__import__

    def no_pandas(name, *args, **kwargs):
        if name == "pandas":
            raise ImportError("no pandas here")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    table = wearfem.study(punch, {"contact.friction": [0.1, 0.2]})
    assert isinstance(table, dict)
    assert isinstance(table["peak_p_plus"], np.ndarray) and table["peak_p_plus"].shape == (2,)


def test_dask_token_names_the_problem_without_rebuilding_it(punch):
    # Dask's default token pickles and unpickles an argument twice, rebuilding the problem;
    # ours is built from the text, file and overrides, and tells variants apart.
    tokenize = pytest.importorskip("dask.base").tokenize
    a = punch.with_overrides({"contact.friction": 0.1})
    assert tokenize(a) == tokenize(punch.with_overrides({"contact.friction": 0.1}))
    assert tokenize(a) != tokenize(punch.with_overrides({"contact.friction": 0.2}))
    assert tokenize(a) != tokenize(punch)


def test_run_rows_say_how_far_they_are_from_the_steady_state(punch):
    # 150 steps of punch-b40 are far from the steady state, 1700 within 1 % (as wearfem run
    # reports it); both rows converge as steps.
    table = wearfem.study(punch, {"wear.steps": [150, 1700], "wear.record": [[]]}, job="run")
    steady_reached = list(table["steady_reached"])
    distance = list(table["steady_distance"])
    assert list(table["converged"]) == [True, True]
    assert steady_reached == [False, True]
    assert distance[0] > 0.1 and distance[1] < 0.01


def test_a_variant_with_warnings_says_so(punch):
    # β̃ = 1e-3 on punch-b40: one half period's wear moves the pressure by far more than 2 %
    # (the quasi-static half period fails), which `wearfem steady` warns about; a study row
    # must not hide it.
    with pytest.warns(wearfem.WearfemWarning, match="1 of 2 variants have warnings"):
        table = wearfem.study(punch, {"wear.body1.beta": [3.9e-8, 1e-3]})
    counts = [len(w) for w in table["warnings"]]
    assert counts[0] == 0 and counts[1] >= 1
    assert "one half period" in list(table["warnings"])[1][0]


CONTACT = {"body": "punch", "edge": "contact", "target_body": "strip", "target_edge": "surface"}


def test_axes_that_overlap_are_refused(punch):
    # `contact` would replace every variant's friction while the friction column still listed
    # its values (a red team's finding, as for `wearfem sweep`).
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(punch, {"contact.friction": [0.1, 0.4], "contact": [CONTACT]})
    assert e.value.key == "contact" and "overlaps" in e.value.message


def test_an_empty_axis_is_refused(punch):
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(punch, {"contact.friction": []})
    assert e.value.key == "contact.friction"


def test_one_dict_s_overrides_may_not_replace_each_other(punch):
    with pytest.raises(wearfem.WearfemError) as e:
        punch.with_overrides({"contact.friction": 0.4, "contact": CONTACT})
    assert e.value.key == "contact"
    # A later call replaces on purpose, and the friction set inside the new table is used.
    p = punch.with_overrides({"contact.friction": 0.4}).with_overrides({"contact": CONTACT})
    assert p.with_overrides({"contact.friction": 0.4}).to_toml() != p.to_toml()


@pytest.mark.parametrize("value", [None, {1, 2}, 2**70, object()])
def test_a_value_a_problem_file_cannot_hold_names_the_key(punch, value):
    with pytest.raises(wearfem.WearfemError) as e:
        punch.with_overrides({"wear.steps": value})
    assert e.value.key == "wear.steps" and e.value.file == "--set"


def test_an_axis_the_job_does_not_read_is_warned_about(punch):
    # A steady state does not read the time-stepping scheme: equal rows, said once (as
    # `wearfem sweep` says it).
    with pytest.warns(wearfem.WearfemWarning, match="does not read wear.scheme"):
        table = wearfem.study(punch, {"wear.scheme": ["implicit", "fixed_point"]})
    assert list(table["peak_p_plus"])[0] == list(table["peak_p_plus"])[1]


def test_a_variant_refused_when_solved_is_named():
    """A check that needs the contact (a probe on the contact edge) comes when the variant is
    solved; the error names the variant (red team 24: it named only the key)."""
    p = wearfem.Problem.builtin("punch-b40")
    with pytest.raises(wearfem.WearfemError) as e:
        wearfem.study(p, {"probes.M.at": [[1070.0, 100.0], [1100.0, 50.0]]})
    assert e.value.key == "probes.M.at"
    assert "in the study's variant probes.M.at=[1100" in e.value.message, e.value.message
