"""wearfem: steady sliding wear under periodic sliding, from Python.

A thin layer over the Rust library ``wearfem``: every figure is computed there (the same code
as the command line, with the GIL released) and handed over as the command line's
``summary.json``; this module only turns its lists into numpy arrays.

Units everywhere: mm, N, MPa (N/mm²), s; rigid wear per period: ``lambda_F`` in mm,
``lambda_M`` in rad.

    >>> import wearfem
    >>> p = wearfem.Problem.builtin("punch-b40").with_overrides({"contact.friction": 0.4})
    >>> s = p.steady()
    >>> s.status, s.p_plus.max()   # doctest: +SKIP
"""

from __future__ import annotations

import json
import re as _re
import warnings as _warnings
from typing import Any, Callable, Dict, List, Mapping, Optional

import operator as _operator

import numpy as np
import numpy.typing as _npt

from ._wearfem import Problem as _Problem
from ._wearfem import __version__
from ._wearfem import _NO_CYCLE

__all__ = [
    "Problem",
    "WearfemError",
    "WearfemWarning",
    "ProblemError",
    "ElasticResult",
    "ContactResult",
    "RunResult",
    "SteadyResult",
    "study",
    "examples",
    "FloatArray",
    "__version__",
]

#: The type of every profile: float64 numpy arrays (mm, MPa as each attribute says).
FloatArray = _npt.NDArray[np.float64]


class WearfemError(ValueError):
    """Bad input: ``file``, dotted ``key`` (``contact.friction``; ``line N`` for a TOML syntax
    error, which names no key), ``message``, and ``line`` (1-based line of the file, or None
    where the error has no line of its own).

    ``str(error)`` is the command line's message ``FILE: KEY (line N): message``; ``key`` is
    the key alone, as ``with_overrides`` takes it.
    """

    def __init__(self, file: str, key: str, message: str):
        super().__init__(f"{file}: {key}: {message}")
        self._located_key = key
        located = _re.fullmatch(r"(.*) \(line (\d+)\)", key)
        # A TOML syntax error names a line and no key: the CLI's "FILE: line N: message".
        syntax = _re.fullmatch(r"line (\d+)", key)
        self.file = file
        self.key = located.group(1) if located else key
        self.line = int(located.group(2)) if located else int(syntax.group(1)) if syntax else None
        self.message = message

    def __reduce__(self):
        return (type(self), (self.file, self._located_key, self.message))


#: Alias: the Rust library calls this error ``ProblemError``.
ProblemError = WearfemError


def _array(values) -> np.ndarray:
    """A float array from JSON numbers; JSON null (a non-finite value) becomes NaN."""
    return np.array([np.nan if v is None else v for v in values], dtype=float)


class WearfemWarning(UserWarning):
    """A result that may be wrong by more than its solver's tolerance: the command line's
    warning lines (a coarse mesh at a contact zone's end, a model assumption that does not
    hold, ...), issued with :func:`warnings.warn` when a result is made and kept in its
    ``warnings`` list. ``warnings.simplefilter("error", wearfem.WearfemWarning)`` turns them
    into exceptions."""


class _Result:
    """Common part of the results: the summary dict and attribute access to its scalars."""

    def __init__(self, summary: Dict[str, Any]):
        #: The command line's summary.json, as a dict (lists not converted).
        self.summary = summary
        #: The command line's warning lines for this result (summary.json ``warnings``).
        self.warnings = list(summary.get("warnings", []))
        for text in self.warnings:
            # Results are made inside Problem.steady()/run(): point at the caller's line.
            _warnings.warn(text, WearfemWarning, stacklevel=4)

    def __getitem__(self, key: str) -> Any:
        return self.summary[key]

    def __repr__(self) -> str:
        status = getattr(self, "status", None)
        return f"<{type(self).__name__} {self.summary.get('title', '')!r} status={status!r}>"


class ElasticResult(_Result):
    """Static elastic solve (``wearfem elastic``).

    Attributes: ``dofs``, ``condensed_dofs``, ``strain_energy`` (N·mm), ``probes``
    ({name: {"displacement" (mm), "stress" (MPa), "strain"}}), ``seconds`` (s).
    """

    def __init__(self, summary):
        super().__init__(summary)
        self.dofs: int = summary["dofs"]
        self.condensed_dofs: int = summary["condensed_dofs"]
        self.strain_energy: float = summary["strain_energy"]
        self.probes: Dict[str, Any] = summary["probes"]
        self.seconds: float = summary["seconds"]
        self.status = "solved"


class ContactResult(_Result):
    """One contact solve of the initial configuration (``wearfem contact``).

    Arrays, one entry per contact point in edge order: ``x``, ``z`` (mm), ``pressure`` (MPa),
    ``gap`` (mm). Scalars: ``status`` ("solved" or "failed": a failed solve is returned, not
    raised, with its residuals and None for pressure, gap, rigid and probes), ``iterations``,
    ``rigid`` (plate unknowns: mm, rad), ``probes`` (MPa), residuals.
    """

    def __init__(self, summary):
        super().__init__(summary)
        self.x = _array(summary["x"])
        self.z = _array(summary["z"])
        # A failed solve carries no values (None), only its status and residuals.
        self.pressure = _array(summary["pressure"]) if summary["pressure"] is not None else None
        self.gap = _array(summary["gap"]) if summary["gap"] is not None else None
        self.rigid: Optional[Dict[str, float]] = summary["rigid"]
        self.probes: Optional[Dict[str, float]] = summary["probes"]
        self.iterations: int = summary["iterations"]
        self.status: str = summary["solve"]["status"]
        self.converged: bool = self.status == "solved"


class SteadyResult(_Result):
    """Steady worn state computed directly (``wearfem steady``).

    Arrays, one entry per contact point: ``x`` (mm), ``p_plus``, ``p_minus``, ``p_sum``
    (MPa; ``p_minus`` and ``p_sum`` are None for monotonic sliding), ``shape`` (worn shape,
    mm). Scalars: ``status`` ("Solved" or why not), ``converged``, ``iterations``,
    ``wear_residual`` (relative), ``rigid_wear_per_period`` ({"lambda_F": mm, "lambda_M":
    rad}), ``probes`` (p⁺ at the contact point nearest to each probe, MPa), ``seconds`` (s,
    set-up included).

    A solve that did not converge is returned, not raised, with its ``status``,
    ``iterations`` and ``wear_residual``; its values (``p_plus``, ``p_minus``, ``p_sum``,
    ``shape``, ``rigid_wear_per_period``, ``probes``) are None: nothing of the last iterate is
    a result (the command line writes nothing and exits 1).
    """

    def __init__(self, summary):
        points = summary.pop("probe_points", [])
        super().__init__(summary)
        self.status: str = summary["status"]
        self.converged: bool = self.status == "Solved"
        self.x = _array(summary["x"])

        def profile(key):
            value = summary.get(key)
            return _array(value) if value is not None else None

        self.p_plus = profile("p_plus")
        self.p_minus = profile("p_minus")
        self.p_sum = profile("p_sum")
        self.shape = profile("shape")
        self.sliding: str = summary["sliding"]
        self.iterations: int = summary["iterations"]
        self.wear_residual: float = summary["wear_residual"]
        self.rigid_wear_per_period: Optional[Dict[str, float]] = summary["rigid_wear_per_period"]
        self.seconds: float = summary["seconds"]
        self.probes: Optional[Dict[str, float]] = (
            {name: float(self.p_plus[i]) for name, i in points}
            if self.p_plus is not None
            else None
        )


class RunResult(_Result):
    """Wear time integration (``wearfem run``).

    ``history``: a dict of arrays, one entry per step, ready for ``pandas.DataFrame``: step,
    half_period, direction ("+"/"−"), k, iterations, solves (contact solves of the step),
    criterion (%), dissipation (N·mm),
    delta_w (mm, reciprocating only), torque (N·mm, bodies of revolution turning about their
    axis only: ∫ μ p r dA) and ``p_<probe>`` (MPa). Final profiles (None when the
    run did not complete a cycle): ``x`` (mm), ``p_plus``, ``p_minus``, ``p_sum`` (MPa),
    ``shape`` (mm, the gap's profile: initial gap plus wear), ``wear`` (mm, the wear
    alone, positive where material was removed) and ``wear_body1``, ``wear_body2`` (mm, the
    depth worn off each body, body 2's at the partner points; they add up to ``wear`` unless
    ``wear.shape_zero_at`` shifts it). Scalars: ``status`` ("solved", or what went wrong), ``converged``,
    ``steady_reached`` (the last cycle's pressures within 1 % of the peak of the steady
    state of the same problem, or, where none exists, its wear rigid to 1 %),
    ``steady_distance`` (a dict: ``pressure``, that distance relative to the peak, None
    without a steady state; ``wear``, ``delta_w`` mm, ``summed_pressure``; ``delta_w`` is None
    for monotonic sliding and ``summed_pressure`` None, with ``summed_pressure_note`` saying
    why, when fewer than two points carry pressure in both half cycles), ``solves``,
    ``failed_solves``, ``unconverged_steps``, ``oscillating_steps`` (``converged`` is False
    when any of these three is non-zero or the run stopped early for another reason than the
    steady state; the profiles and steps are then only those of the completed steps),
    ``sliding_distance_m`` (m; None for a turn about the axis), ``turn`` (a dict, bodies of
    revolution turning about their axis only: ``angle_rad``, ``revolutions``, ``torque_Nmm``,
    ``power_W``), ``worn_depth`` ([body 1, body 2]: the largest depth worn off
    each body at a contact point, mm), ``worn_volume`` ([body 1, body 2], mm³),
    ``setup_seconds``, ``run_seconds`` (s).
    """

    def __init__(self, summary):
        super().__init__(summary)
        steps = summary["steps"]
        history: Dict[str, np.ndarray] = {}
        for name in ["step", "half_period", "k", "iterations", "solves"]:
            if not steps or name in steps[0]:
                history[name] = np.array([s[name] for s in steps], dtype=int)
        history["direction"] = np.array([s["direction"] for s in steps], dtype=str)
        for name in ["criterion", "dissipation", "delta_w", "torque"]:
            if steps and name in steps[0]:
                history[name] = _array([s[name] for s in steps])
        for probe in steps[0]["probes"] if steps else []:
            history[f"p_{probe}"] = _array([s["probes"][probe] for s in steps])
        self.history = history
        final = summary.get("final")
        self.x = _array(final["x"]) if final else None
        self.p_plus = _array(final["p_plus"]) if final else None
        self.p_minus = _array(final["p_minus"]) if final and "p_minus" in final else None
        self.p_sum = _array(final["p_sum"]) if final and "p_sum" in final else None
        self.shape = _array(final["shape"]) if final else None
        self.wear = _array(final["wear"]) if final else None
        self.wear_body1 = _array(final["wear_body1"]) if final else None
        self.wear_body2 = _array(final["wear_body2"]) if final else None
        self.solves: int = summary["solves"]
        self.failed_solves: int = summary["failed_solves"]
        self.unconverged_steps: int = summary["unconverged_steps"]
        self.oscillating_steps: int = summary.get("oscillating_steps", 0)
        # [body 1, body 2]: the largest depth worn off each body at a contact point, mm.
        self.worn_depth: List[float] = list(summary["worn_depth"])
        # [body 1, body 2]: the volume worn off each body, mm³.
        self.worn_volume: List[float] = list(summary["worn_volume"])
        self.steady_reached: Optional[bool] = summary.get("steady_reached")
        self.steady_distance: Optional[Dict[str, Optional[float]]] = summary.get("steady_distance")
        self.sliding_distance_m: Optional[float] = summary["sliding_distance_m"]
        # Bodies of revolution turning about their axis: angle, revolutions, torque (N·mm),
        # power (W); None otherwise (docs/problem-files.md, summary.json's `turn`).
        self.turn: Optional[Dict[str, object]] = summary.get("turn")
        self.setup_seconds: float = summary["setup_seconds"]
        self.run_seconds: float = summary["run_seconds"]
        problems = []
        if self.failed_solves:
            problems.append(f"failed solves {self.failed_solves}")
        if self.unconverged_steps:
            problems.append(f"unconverged steps {self.unconverged_steps}")
        if self.oscillating_steps:
            problems.append(f"oscillating steps {self.oscillating_steps}")
        if "stop_reason" in summary:
            problems.append(
                f"stopped at step {summary['stopped_at_step']}: {summary['stop_reason']}"
            )
        if not problems and final is None:
            # A converged run too short for one full cycle: no profiles (as a study row).
            problems.append(_NO_CYCLE)
        self.status: str = ", ".join(problems) if problems else "solved"
        # As the command line's exit code: any failed, unconverged or oscillating step.
        stopped_early = summary.get("stop_reason", "the steady state was reached") != (
            "the steady state was reached"
        )
        self.converged: bool = not (
            self.failed_solves or self.unconverged_steps or self.oscillating_steps or stopped_early
        )


class Problem:
    """A validated problem file (TOML, see docs/problem-files.md), possibly with overrides.

    Build with :meth:`from_file`, :meth:`from_toml`, :meth:`from_dict` or :meth:`builtin`;
    bad input raises :class:`WearfemError` naming the file and the key. A problem is
    immutable; :meth:`with_overrides` returns a new one. Problems pickle (for process pools
    and Dask workers).
    """

    __slots__ = ("_inner",)

    def __init__(self, inner: _Problem):
        self._inner = inner

    def __getstate__(self):
        return self._inner

    def __setstate__(self, inner):
        self._inner = inner

    def __dask_tokenize__(self):
        """Dask's key for a task argument: the problem text, file name and overrides.

        Without it Dask tokenises an object by pickling and unpickling it twice, and each
        unpickling rebuilds the problem (0.6 ms): for a 256-variant study that was 0.57 s of
        the client's CPU, taken from the two workers on a 2-core machine
        (docs/performance.md)."""
        text, file, sets = self._inner.__reduce__()[1]
        return ("wearfem.Problem", text, file, tuple(map(tuple, sets)))

    def __eq__(self, other: object) -> bool:
        """Equal problems have the same text, file name and overrides (so a problem equals
        its own pickle, and ``functools.lru_cache`` of a solve hits)."""
        if not isinstance(other, Problem):
            return NotImplemented
        return self.__dask_tokenize__() == other.__dask_tokenize__()

    def __hash__(self) -> int:
        return hash(self.__dask_tokenize__())

    def __repr__(self) -> str:
        sets = ", ".join(f"{k}={v}" for k, v in self.overrides)
        return f"<wearfem.Problem {self.file!r}{' with ' + sets if sets else ''}>"

    @classmethod
    def from_toml(
        cls, text: str, file: str = "<string>", overrides: Optional[Mapping[str, Any]] = None
    ) -> "Problem":
        """Parse and validate problem-file text; ``file`` names it in error messages.

        ``overrides`` ({dotted key: value}, as :meth:`with_overrides`) are applied before the
        problem is validated, as ``--set`` on the command line: a template file that leaves
        keys to them (``analysis.p``, say) is complete only with them, and cannot be read
        without."""
        values = None if overrides is None else {k: _plain(v) for k, v in dict(overrides).items()}
        return cls(_Problem.from_toml(text, file, values))

    @classmethod
    def from_file(cls, path, overrides: Optional[Mapping[str, Any]] = None) -> "Problem":
        """Read and validate the problem file at ``path``, with ``overrides`` applied first
        (see :meth:`from_toml`)."""
        path = str(path)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise WearfemError(path, "(file)", f"cannot read: {e.strerror}") from None
        except UnicodeDecodeError as e:
            raise WearfemError(path, "(file)", f"cannot read: not UTF-8 text (byte {e.start})") from None
        return cls.from_toml(text, path, overrides)

    @classmethod
    def from_dict(cls, d: Mapping[str, Any], file: str = "<dict>") -> "Problem":
        """Validate a problem given as nested dicts and lists (the TOML file's structure).
        An error names the dotted key (``wear.body1.beta``, ``probes.M.at``)."""
        try:
            return cls.from_toml(_toml_text(d, file), file)
        except WearfemError as e:
            # Its line number is of the TOML text made from the dict, which the caller never sees.
            raise WearfemError(e.file, e.key, e.message) from None

    @classmethod
    def builtin(cls, name: str) -> "Problem":
        """Built-in example ``name`` (see :func:`examples`), as ``wearfem run NAME`` uses."""
        text = _Problem._example_text(name)
        if text is None:
            raise WearfemError(
                name,
                "(name)",
                "no built-in example of that name (examples: "
                + ", ".join(_Problem._example_names())
                + ")",
            )
        return cls.from_toml(text, f"built-in example {name}")

    def with_overrides(self, values: Mapping[str, Any]) -> "Problem":
        """A new problem with ``values`` ({dotted key: value}, the command line's ``--set``
        keys: ``contact.friction``, ``plate.pin``, ``bodies[1].blocks[0].u``) applied, in
        order, after this problem's own overrides. A key the schema does not know, or a
        value of the wrong type, raises :class:`WearfemError` naming the key. numpy scalars
        and arrays are taken as the Python numbers and lists they hold."""
        return Problem(self._inner.with_overrides({k: _plain(v) for k, v in dict(values).items()}))

    def to_toml(self) -> str:
        """The problem file with its overrides applied, as TOML text."""
        return self._inner.to_toml()

    @property
    def file(self) -> str:
        """File name (or "built-in example NAME"), as error messages give it."""
        return self._inner.file

    @property
    def title(self) -> str:
        """Title of the problem."""
        return self._inner.title

    @property
    def overrides(self) -> list:
        """The overrides applied: [(key, value as TOML text)]."""
        return self._inner.overrides

    def elastic(self) -> ElasticResult:
        """Static elastic solve of every body (``wearfem elastic``)."""
        return ElasticResult(json.loads(self._inner._elastic()))

    def contact(self) -> ContactResult:
        """One contact solve of the initial configuration (``wearfem contact``)."""
        return ContactResult(json.loads(self._inner._contact()))

    def run(
        self,
        steps: Optional[int] = None,
        progress: Optional[Callable[[int, int], Any]] = None,
    ) -> RunResult:
        """Wear time integration (``wearfem run``), ``steps`` replacing the file's duration.

        ``progress(step, half_period)`` is called after every step (with the GIL held only
        for the call). An exception it raises, or Ctrl-C (KeyboardInterrupt, also without a
        ``progress``: the run lets Python handle its signals every 50 ms), stops the run after
        the current step and is raised; nothing of the run is returned.
        """
        if steps is not None:
            steps = _operator.index(steps)
            if steps < 1:
                raise ValueError(f"steps must be a positive integer, got {steps}")
        if progress is not None and not callable(progress):
            raise TypeError(f"progress must be callable as progress(step, half_period), got {progress!r}")
        return RunResult(json.loads(self._inner._run(steps, progress)))

    def run_sliding(self, steps: Optional[int] = None) -> dict:
        """Wear time integration of sliding pairs (``contact.pairs = "sliding"``; ``wearfem
        run`` on such a problem), ``steps`` replacing the file's duration: summary.json as a
        dict (docs/sliding.md: ``track``, ``final``, ``worn_volume``, ``history``, …). A run
        that stops on a failed solve raises RuntimeError with its reason.
        """
        if steps is not None:
            steps = _operator.index(steps)
            if steps < 1:
                raise ValueError(f"steps must be a positive integer, got {steps}")
        return json.loads(self._inner._run_sliding(steps))

    def fretting_contact(self) -> dict:
        """A fretting problem's (``[fretting]``) normal load and one periodic cycle
        (``wearfem contact`` on it): summary.json as a dict (docs/fretting.md: ``fretting``
        with the loop's figures and the stick zone; profiles ``x``, ``pressure``,
        ``shear_at_peak``, ``sticks``, ``slip_amplitude``)."""
        return json.loads(self._inner._fretting("contact", None))

    def fretting_run(self, cycles: Optional[float] = None) -> dict:
        """A fretting problem's wear by the local slip (``wearfem run`` on it), ``cycles``
        replacing ``wear.cycles``: summary.json as a dict (``final`` holds the profiles). A run
        that stops on a failed solve raises RuntimeError with its reason."""
        if cycles is not None and not (cycles >= 1):
            raise ValueError(f"cycles must be at least 1, got {cycles}")
        return json.loads(self._inner._fretting("run", None if cycles is None else float(cycles)))

    def fretting_steady(self) -> dict:
        """A fretting problem's final state of partial slip (``wearfem steady`` on it):
        summary.json as a dict (``pressure``, ``worn_depth``, ``in_final_stick_set``)."""
        return json.loads(self._inner._fretting("steady", None))

    def steady(self, method: str = "exact") -> SteadyResult:
        """Steady worn state computed directly (``wearfem steady``).

        ``method``: "exact" (Newton on the steady-state conditions) is the only one so far.
        A solve that does not converge is returned with its ``status``, not raised.

        Sliding pairs (``contact.pairs = "sliding"``): a ring turning under body 1 has a
        steady state, and ``result["track"]`` gives its even wear (``body2_depth_per_turn``,
        ``body2_depth_per_metre``, mm) and ``position_spread``; one that does not converge
        raises RuntimeError. A reciprocating stroke has none: WearfemError, key
        ``contact.pairs`` (docs/sliding.md).
        """
        if method != "exact":
            raise ValueError(f'method must be "exact", got {method!r}')
        return SteadyResult(json.loads(self._inner._steady()))


def _plain(v: Any) -> Any:
    """numpy scalars and arrays as Python numbers and lists (recursively in lists, tuples and
    dicts), which the problem file's types are made of; everything else as it is."""
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, Mapping):
        return {k: _plain(x) for k, x in v.items()}
    return v


def _toml_value(v: Any, key: str, file: str) -> str:
    """One value as inline TOML; ``key`` names it in the error for a type TOML lacks."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        x = float(v)
        return repr(x) if np.isfinite(x) else ("nan" if np.isnan(x) else ("inf" if x > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k, key, file)} = {_toml_value(x, f'{key}.{k}', file)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(x, f"{key}[{i}]", file) for i, x in enumerate(v)) + "]"
    raise WearfemError(file, key, f"cannot be written in a problem file (type {type(v).__name__})")


def _toml_key(k: Any, parent: Optional[str], file: str) -> str:
    """A dict key as a TOML key: a string without dots (a dotted key would name a key the
    schema does not have, garbled in the error: nest dicts instead)."""
    where = f"{parent}.{k}" if parent else str(k)
    if not isinstance(k, str):
        raise WearfemError(file, where, f"keys of a problem dict are strings, got {type(k).__name__}")
    if "." in k:
        raise WearfemError(file, where, "a key of a problem dict has no dots: nest dicts instead ({'contact': {'friction': 0.3}})")
    return json.dumps(k)


def _toml_text(d: Mapping[str, Any], file: str) -> str:
    """TOML text of nested dicts (inline tables serve every section of the schema)."""
    return "".join(f"{_toml_key(k, None, file)} = {_toml_value(v, str(k), file)}\n" for k, v in d.items())


def examples() -> list:
    """Names of the built-in examples."""
    return list(_Problem._example_names())


from ._study import study  # noqa: E402
