"""Type stubs of wearfem. Units: mm, N, MPa, s; rigid wear λ_F in mm, λ_M in rad."""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from ._wearfem import Problem as _Problem

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

__version__: str

FloatArray = npt.NDArray[np.float64]

class WearfemError(ValueError):
    """Bad input: the file, the dotted key and what is wrong."""

    file: str
    key: str
    line: Optional[int]
    message: str
    def __init__(self, file: str, key: str, message: str) -> None: ...

ProblemError = WearfemError

class WearfemWarning(UserWarning):
    """A result that may be wrong by more than its solver's tolerance (the command line's
    warning lines), issued when a steady or run result is made."""

class ElasticResult:
    summary: Dict[str, Any]
    def __init__(self, summary: Dict[str, Any]) -> None: ...
    status: str
    dofs: int
    condensed_dofs: int
    strain_energy: float  # N·mm
    probes: Dict[str, Any]  # displacement mm, stress MPa, strain
    seconds: float
    def __getitem__(self, key: str) -> Any: ...

class ContactResult:
    summary: Dict[str, Any]
    def __init__(self, summary: Dict[str, Any]) -> None: ...
    warnings: List[str]  # the command line's warning lines
    x: FloatArray  # mm
    z: FloatArray  # mm
    pressure: Optional[FloatArray]  # MPa; None for a failed solve
    gap: Optional[FloatArray]  # mm; None for a failed solve
    rigid: Optional[Dict[str, float]]  # mm, rad; None for a failed solve
    probes: Optional[Dict[str, float]]  # MPa; None for a failed solve
    iterations: int
    status: str  # "solved" or "failed"
    converged: bool
    def __getitem__(self, key: str) -> Any: ...

class SteadyResult:
    summary: Dict[str, Any]
    def __init__(self, summary: Dict[str, Any]) -> None: ...
    warnings: List[str]  # the command line's warning lines
    x: FloatArray  # mm
    # The values are None when the solve did not converge (converged False): nothing of the
    # last iterate is a result.
    p_plus: Optional[FloatArray]  # MPa
    p_minus: Optional[FloatArray]  # MPa, None for monotonic sliding
    p_sum: Optional[FloatArray]  # MPa, None for monotonic sliding
    shape: Optional[FloatArray]  # mm
    status: str  # "Solved", or why not
    converged: bool
    sliding: str
    iterations: int
    wear_residual: float
    rigid_wear_per_period: Optional[Dict[str, float]]  # lambda_F mm, lambda_M rad
    probes: Optional[Dict[str, float]]  # p⁺ at the probes, MPa
    seconds: float
    def __getitem__(self, key: str) -> Any: ...

class RunResult:
    summary: Dict[str, Any]
    def __init__(self, summary: Dict[str, Any]) -> None: ...
    warnings: List[str]  # the command line's warning lines
    history: Dict[str, np.ndarray]  # one entry per step
    x: Optional[FloatArray]  # mm
    p_plus: Optional[FloatArray]  # MPa
    p_minus: Optional[FloatArray]  # MPa
    p_sum: Optional[FloatArray]  # MPa
    shape: Optional[FloatArray]  # mm, initial gap plus wear
    wear: Optional[FloatArray]  # mm, the wear alone
    wear_body1: Optional[FloatArray]  # mm, the depth worn off body 1
    wear_body2: Optional[FloatArray]  # mm, the depth worn off body 2 (at the partner points)
    status: str
    converged: bool
    steady_reached: Optional[bool]
    steady_distance: Optional[Dict[str, Any]]  # pressure, wear, delta_w, summed_pressure (None when meaningless), summed_pressure_note
    solves: int
    failed_solves: int
    unconverged_steps: int
    oscillating_steps: int
    worn_depth: List[float]
    worn_volume: List[float]  # mm³, body 1 and body 2
    sliding_distance_m: Optional[float]  # m
    setup_seconds: float
    run_seconds: float
    def __getitem__(self, key: str) -> Any: ...

class Problem:
    def __init__(self, inner: _Problem) -> None: ...
    def __dask_tokenize__(self) -> Tuple[str, str, str, Tuple[Tuple[str, str], ...]]: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    @classmethod
    def from_toml(
        cls, text: str, file: str = "<string>", overrides: Optional[Mapping[str, Any]] = None
    ) -> Problem: ...
    @classmethod
    def from_file(
        cls, path: Union[str, "os.PathLike[str]"], overrides: Optional[Mapping[str, Any]] = None
    ) -> Problem: ...
    @classmethod
    def from_dict(cls, d: Mapping[str, Any], file: str = "<dict>") -> Problem: ...
    @classmethod
    def builtin(cls, name: str) -> Problem: ...
    def with_overrides(self, values: Mapping[str, Any]) -> Problem: ...
    def to_toml(self) -> str: ...
    @property
    def file(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def overrides(self) -> List[Tuple[str, str]]: ...
    def elastic(self) -> ElasticResult: ...
    def contact(self) -> ContactResult: ...
    def run(
        self,
        steps: Optional[int] = None,
        progress: Optional[Callable[[int, int], Any]] = None,
    ) -> RunResult: ...
    def run_sliding(self, steps: Optional[int] = None) -> dict: ...
    def fretting_contact(self) -> dict: ...
    def fretting_run(self, cycles: Optional[float] = None) -> dict: ...
    def fretting_steady(self) -> dict: ...
    def steady(self, method: str = "exact") -> SteadyResult: ...

def examples() -> List[str]: ...
def study(
    problem: Problem,
    grid: Union[Mapping[str, Sequence[Any]], Sequence[Mapping[str, Any]]],
    executor: Optional[Any] = None,
    job: str = "steady",
    chunksize: Optional[int] = None,
) -> Any: ...

