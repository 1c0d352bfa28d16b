"""Type stubs of the Rust extension ``lcpbatch._native`` (python/src/)."""

from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

CHUNK_PROBLEMS: int
CHUNK_WORK: int
CHUNK_CONTACTS: int
CHUNK_FRICTION_WORK: int
DEFAULT_VJP_TOLERANCE: float

def adapters(api: str = "auto") -> List[Dict[str, Any]]: ...
def status_names() -> List[str]: ...
def path_names() -> List[str]: ...
def _panic_for_test() -> None: ...
def derivative_names() -> List[str]: ...
def lcp_vjp(
    m: npt.NDArray[np.float64],
    q: npt.NDArray[np.float64],
    z: npt.NDArray[np.float64],
    dz: npt.NDArray[np.float64],
    dw: Optional[npt.NDArray[np.float64]] = None,
    tolerance: Optional[float] = None,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.int8]]: ...
def scene_vjp_batch(
    scenes: List[Dict[str, Any]],
    impulses: List[npt.NDArray[np.float64]],
    d_impulses: Optional[List[npt.NDArray[np.float64]]] = None,
    d_velocity: Optional[List[npt.NDArray[np.float64]]] = None,
    d_angular_velocity: Optional[List[npt.NDArray[np.float64]]] = None,
    tolerance: Optional[float] = None,
) -> List[Dict[str, Any]]: ...
def ffi_targets() -> Dict[str, Any]: ...
def ffi_register(solver: Any) -> int: ...
def time_lcp_vjp(
    m: npt.NDArray[np.float64],
    q: npt.NDArray[np.float64],
    z: npt.NDArray[np.float64],
    dz: npt.NDArray[np.float64],
    repeats: int,
    dense: bool = False,
) -> List[float]: ...

class NativeSolver:
    def __init__(
        self,
        backend: str = "auto",
        method: str = "auto",
        precision: str = "auto",
        all_solutions: bool = False,
        warm_start: bool = False,
        warm_start_calls: int = 1,
        tolerance: Optional[float] = None,
        threads: int = 0,
        adapter: Optional[str] = None,
        api: str = "auto",
        predict: bool = True,
        lemke_max_pivots: Optional[int] = None,
        pgs_max_sweeps: Optional[int] = None,
        pgs_tolerance: Optional[float] = None,
        friction_method: str = "auto",
        friction_tolerance: Optional[float] = None,
        friction_max_iterations: Optional[int] = None,
    ) -> None: ...
    def device(self) -> str: ...
    def device_kind(self) -> str: ...
    def choice(self) -> str: ...
    def fallback(self) -> Optional[str]: ...
    def clear_warm_start(self) -> None: ...
    def solve_dense(
        self,
        m: npt.NDArray[np.float64],
        q: npt.NDArray[np.float64],
        ids: Optional[npt.NDArray[np.uint64]] = None,
    ) -> Dict[str, Any]: ...
    def solve_dense_zw(
        self, m: npt.NDArray[np.float64], q: npt.NDArray[np.float64]
    ) -> Tuple[Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.int8]], Optional[str]]: ...
    def solve_ragged(
        self,
        m: List[npt.NDArray[np.float64]],
        q: List[npt.NDArray[np.float64]],
        ids: Optional[List[npt.NDArray[np.uint64]]] = None,
    ) -> Dict[str, Any]: ...
    def solve_scenes(self, scenes: List[Dict[str, Any]]) -> Dict[str, Any]: ...
    def solve_friction_dense(
        self,
        w: npt.NDArray[np.float64],
        q: npt.NDArray[np.float64],
        mu: npt.NDArray[np.float64],
        ids: Optional[npt.NDArray[np.uint64]] = None,
    ) -> Dict[str, Any]: ...
    def solve_friction_ragged(
        self,
        w: List[npt.NDArray[np.float64]],
        q: List[npt.NDArray[np.float64]],
        mu: List[npt.NDArray[np.float64]],
        ids: Optional[List[npt.NDArray[np.uint64]]] = None,
    ) -> Dict[str, Any]: ...
    def step_worlds(self, worlds: List["NativeWorld"], dt: float, steps: int) -> Dict[str, Any]: ...
    def time_solve_lcps(
        self, m: npt.NDArray[np.float64], q: npt.NDArray[np.float64], repeats: int, dense: bool = False
    ) -> List[float]: ...

_F64 = npt.NDArray[np.float64]

class NativeWorld:
    @staticmethod
    def from_json(text: str) -> List["NativeWorld"]: ...
    @staticmethod
    def generate(kind: str, size: Optional[int] = None, seed: int = 0) -> "NativeWorld": ...
    @staticmethod
    def kinds() -> List[str]: ...
    def copy(self) -> "NativeWorld": ...
    def to_json(self) -> str: ...
    def bodies(self) -> int: ...
    def shapes(self) -> List[str]: ...
    def fixed(self) -> List[bool]: ...
    def asleep(self) -> List[bool]: ...
    def state(self) -> Tuple[_F64, _F64, _F64, _F64]: ...
    def set_state(
        self,
        positions: Optional[_F64] = None,
        orientations: Optional[_F64] = None,
        velocities: Optional[_F64] = None,
        angular_velocities: Optional[_F64] = None,
    ) -> None: ...
    def kinetic_energy(self) -> float: ...
    def potential_energy(self) -> float: ...
