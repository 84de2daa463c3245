"""Parameter studies: chunks of variants as tasks on any ``concurrent.futures``-style executor.

Each variant is solved by the library's ``sweep::solve`` (the function behind
``wearfem sweep``), so a row here equals the row of ``wearfem sweep`` with the same overrides,
bit for bit, whichever executor ran it.
"""

from __future__ import annotations

import itertools
import json
import random
from typing import Any, Dict, List, Mapping, Sequence, Union

import numpy as np

from ._wearfem import _check_axes, _study_warnings

Grid = Union[Mapping[str, Sequence[Any]], Sequence[Mapping[str, Any]]]


def variants(grid: Grid) -> List[Dict[str, Any]]:
    """The override dicts of a study: the Cartesian product of a dict of lists (first key
    slowest, as ``wearfem sweep``), or a list of override dicts taken as given."""
    if isinstance(grid, Mapping):
        axes: Dict[str, list] = {}
        for k, values in grid.items():
            if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
                raise TypeError(f"grid[{k!r}] must be a list of values")
            axes[k] = list(values)
            if not axes[k]:
                # As `wearfem sweep`: an empty axis would make an empty study without a word.
                from . import WearfemError

                raise WearfemError("--set", str(k), "the list of values is empty")
        # As `wearfem sweep`: no key inside a table another axis sets (its column would list
        # values that were not used).
        _check_axes([str(k) for k in axes])
        return [dict(zip(axes, values)) for values in itertools.product(*axes.values())]
    return [dict(v) for v in grid]


def solve_variant(problem, job: str = "steady") -> Dict[str, Any]:
    """One variant's row: status, converged, peak_p_plus, peak_p_minus (MPa), p_plus_<probe>,
    p_minus_<probe> (MPa), rigid wear per period (lambda_F mm, lambda_M rad; steady only),
    shape_range (mm), for runs steady_distance (the last cycle's pressures from the steady
    state, relative to its peak) and steady_reached, seconds (s, this variant's own wall
    time), warnings (the command line's warning lines for the variant, a list). Runs with the
    GIL released.

    A variant that did not converge (``converged`` False) has NaN for every value: nothing of
    a failed or non-converged solve is a result (``wearfem sweep`` leaves those cells empty)."""
    from . import WearfemError  # the package imports this module

    try:
        row = json.loads(problem._inner._study_row(job))
    except WearfemError as e:
        # A check that needs the contact itself (a probe on the contact edge) comes only
        # now: say which variant of the study it refused (red team 24).
        variant = ", ".join(f"{k}={v}" for k, v in problem.overrides)
        raise WearfemError(e.file, e.key, f"{e.message} (in the study's variant {variant})") from None
    out: Dict[str, Any] = {
        "status": row["status"],
        "converged": row["converged"],
        "peak_p_plus": _float(row.get("peak_p_plus")),
        "peak_p_minus": _float(row.get("peak_p_minus")),
    }
    for name, value in row.get("probes_p_plus", {}).items():
        out[f"p_plus_{name}"] = _float(value)
    for name, value in row.get("probes_p_minus", {}).items():
        out[f"p_minus_{name}"] = _float(value)
    for name, value in row.get("rigid_wear_per_period", {}).items():
        out[f"{name}_per_period"] = _float(value)
    out["shape_range"] = _float(row.get("shape_range"))
    if job == "run":
        # How far the run ended from the steady state (relative to its peak), as `wearfem
        # run` says it: a converged run can still be far from it.
        out["steady_distance"] = _float(row.get("steady_distance"))
        out["steady_reached"] = row.get("steady_reached")
    # The warning lines `wearfem steady`/`run` would print for this variant (a list).
    out["warnings"] = list(row.get("warnings", []))
    out["seconds"] = row["seconds"]
    return out


def _float(v) -> float:
    return np.nan if v is None else float(v)


def solve_variants(problems, job: str = "steady") -> List[Dict[str, Any]]:
    """The rows of several variants, in order: one executor task for a chunk of a study."""
    return [solve_variant(p, job) for p in problems]


def _workers(executor) -> int:
    """How many tasks `executor` runs at once, if it says (a Dask client, a
    concurrent.futures pool); 1 otherwise."""
    nthreads = getattr(executor, "nthreads", None)
    if callable(nthreads):
        try:
            return max(1, sum(nthreads().values()))
        except Exception:  # not a Dask client after all
            return 1
    return max(1, int(getattr(executor, "_max_workers", 1) or 1))


def study(problem, grid: Grid, executor=None, job: str = "steady", chunksize=None):
    """Solve every variant of ``grid`` and tabulate the overrides and key results.

    ``grid``: {key: [values]} (Cartesian product, first key slowest) or [{key: value}, …],
    with the command line's ``--set`` keys. ``executor``: None (serial, in this thread) or
    anything with ``submit(fn, *args)`` returning futures with ``.result()``:
    ``concurrent.futures.ThreadPoolExecutor`` (the GIL is released while solving),
    ``ProcessPoolExecutor``, or a ``dask.distributed.Client`` (one task per chunk of variants, see ``chunksize``).
    ``job``: "steady" (default) or "run" (the wear time integration).
    ``chunksize``: variants per task. By default the tasks shrink as the study goes (guided
    self-scheduling over the workers the executor reports: a Dask client's threads, a pool's
    ``max_workers``), so that the scheduler's cost per task is spread over several variants
    (on 2 Dask workers, 64 variants of punch-b40 ran 1.3 times the serial rate one per task
    and 1.6 times in chunks of 8, docs/performance.md) and the workers still end together.

    Every variant is validated (``wearfem sweep``'s checks): a bad key or value raises
    :class:`wearfem.WearfemError` naming the first bad variant in grid order, and the study
    returns nothing. With an executor the variants are built while the first tasks solve, and
    on an error the tasks already submitted are cancelled (at most the time it took to build
    the variants is spent on them). The checks that need the contact itself (a probe's
    position on the contact edge) come when the variant is solved: such a variant raises
    then, and the tasks not yet started are cancelled, as on Ctrl-C. A variant that does not
    converge is a row with its ``status``, ``converged = False`` and NaN for every value.

    Returns a pandas DataFrame (one row per variant, in grid order) when pandas is installed,
    else a dict of numpy arrays with the same columns: the override keys, then the columns of
    :func:`solve_variant`. In a study given as a list, a variant that does not override a key
    another does has the file's value in that column (None where the file does not set it and
    the default applies).
    """
    if job not in ("steady", "run"):
        raise ValueError(f'job must be "steady" or "run", got {job!r}')
    if executor is not None and chunksize is not None:
        whole = isinstance(chunksize, (int, np.integer)) and not isinstance(chunksize, bool)
        if not (whole and chunksize >= 1):
            raise ValueError(f"chunksize must be a positive integer, got {chunksize!r}")
        chunksize = int(chunksize)  # numpy integers too
    sets = variants(grid)
    if executor is None:
        problems = _build(problem, sets, job)
        _warn_axes(grid, sets, problems, job)
        rows = [solve_variant(p, job) for p in problems]
    else:
        sizes = _chunk_sizes(len(sets), _workers(executor), chunksize)
        problems, futures = _submit_chunks(executor, problem, sets, job, sizes)
        _warn_axes(grid, sets, problems, job)
        rows = _collect(futures, len(sets))
    warned = [s for s, r in zip(sets, rows) if r.get("warnings")]
    if warned:
        # One line for the study; each variant's lines are in its `warnings` cell.
        _warn_all(
            [
                f"{len(warned)} of {len(sets)} variants have warnings (the `warnings` column), "
                f"first {warned[0]}"
            ]
        )
    return _table(sets, rows, problems)


def _warn_all(lines: List[str]) -> None:
    import warnings

    from . import WearfemWarning

    for line in lines:
        warnings.warn(line, WearfemWarning, stacklevel=3)


def _chunk_sizes(count: int, workers: int, chunksize=None) -> List[int]:
    """How many variants each task takes. A given ``chunksize`` for all (the last takes the
    rest); by default guided self-scheduling: each task a quarter of what is left per worker,
    at least 2, so the first tasks are large (the executor's cost per task spread over many
    variants) and the last ones small (whichever worker is free takes them, and the workers
    end together; on 2 Dask workers with equal chunks one ended 60-120 ms after the other in a
    0.75 s study, docs/performance.md)."""
    if chunksize is not None:
        return [min(chunksize, count - start) for start in range(0, count, chunksize)]
    sizes, left = [], count
    while left > 0:
        size = min(left, max(2, -(-left // (2 * workers))))
        sizes.append(size)
        left -= size
    return sizes


def _warn_axes(grid: Grid, sets, problems, job: str) -> None:
    if isinstance(grid, Mapping) and problems:
        # As `wearfem sweep`: an axis the job does not read gives equal rows, said once here.
        _warn_all(_study_warnings([p._inner for p in problems], job, len(sets[0])))


def _checked(problem, overrides: Dict[str, Any], job: str):
    """One variant built and its settings for ``job`` checked (``wearfem sweep``'s checks)."""
    variant = problem.with_overrides(overrides)
    variant._inner._check(job)
    return variant


def _build(problem, sets: List[Dict[str, Any]], job: str) -> list:
    """Every variant built and checked, in grid order: the first bad one raises."""
    return [_checked(problem, s, job) for s in sets]


def _submit_chunks(executor, problem, sets, job: str, sizes: List[int]):
    """Every variant built and checked, each task submitted as soon as its variants are:
    the workers start on the first task while the client builds the rest (building and
    checking is about 1 ms per variant of punch-b40, 5 % of its solve; on 2 Dask workers the
    second one waited 30-60 ms for all 64 to be built, docs/performance.md). On a bad
    variant the submitted tasks are cancelled and the first bad one in grid order raises.

    The variants go to the tasks in a fixed shuffled order, not as neighbours: a variant's cost
    follows the grid's axes (friction changes the contact iterations), so a task of
    neighbours could hold the costliest row of the grid. The order changes no result (each
    variant is solved on its own), and it is the same on every run."""
    order = list(range(len(sets)))
    random.Random(len(sets)).shuffle(order)
    problems: list = [None] * len(sets)
    futures: list = []
    start = 0
    for size in sizes:
        chunk = order[start : start + size]
        start += size
        try:
            for i in chunk:
                problems[i] = _checked(problem, sets[i], job)
        except Exception:
            for _, future in futures:
                future.cancel()
            # The first bad variant in grid order, as a serial study names it.
            _build(problem, sets, job)
            raise
        futures.append((chunk, executor.submit(solve_variants, [problems[i] for i in chunk], job)))
    return problems, futures


def _collect(futures, count: int) -> List[Dict[str, Any]]:
    """The rows of every variant in grid order from the tasks' results. On an error or
    Ctrl-C the tasks not yet started are cancelled, so that the executor is free for the next
    study at once (red team 24: a thread pool's next task waited 11 s behind the abandoned
    variants; tasks already running finish)."""
    rows: List[Dict[str, Any]] = [{}] * count
    try:
        for chunk, future in futures:
            for i, row in zip(chunk, future.result()):
                rows[i] = row
    except BaseException:
        for _, future in futures:
            future.cancel()
        raise
    return rows


def _table(sets: List[Dict[str, Any]], rows: List[Dict[str, Any]], problems: list):
    columns: Dict[str, list] = {}
    keys = list(dict.fromkeys(k for s in sets for k in s))
    for k in keys:
        # A study given as a list of dicts: a variant that does not override a key another
        # does has the file's value there (None only where the file leaves it to its default).
        columns[k] = [s[k] if k in s else _value_at(p, k) for s, p in zip(sets, problems)]
    result_keys = list(dict.fromkeys(k for r in rows for k in r))
    for k in result_keys:
        columns[k] = [r.get(k, np.nan) for r in rows]
    try:
        import pandas as pd
    except ImportError:
        return {k: _column(v) for k, v in columns.items()}
    return pd.DataFrame(columns)


def _value_at(problem, key: str):
    text = problem._inner._value_at(key)
    return None if text is None else json.loads(text)


def _column(values: list) -> np.ndarray:
    try:
        return np.array(values)
    except ValueError:
        # Ragged values (lists of different lengths): one object per row.
        out = np.empty(len(values), dtype=object)
        out[:] = values
        return out
