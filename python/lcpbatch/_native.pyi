"""Type stubs of the Rust extension ``lcpbatch._native`` (python/src/)."""

from typing import Any, Dict, List, Optional

import numpy as np
import numpy.typing as npt

CHUNK_PROBLEMS: int
CHUNK_WORK: int
CHUNK_CONTACTS: int

def adapters(api: str = "auto") -> List[Dict[str, Any]]: ...
def status_names() -> List[str]: ...
def path_names() -> List[str]: ...
def _panic_for_test() -> None: ...

class NativeSolver:
    def __init__(
        self,
        backend: str = "auto",
        solver: str = "auto",
        precision: str = "auto",
        all_solutions: bool = False,
        warm_start: bool = False,
        tolerance: Optional[float] = None,
        threads: int = 0,
        adapter: Optional[str] = None,
        api: str = "auto",
        predict: bool = True,
        lemke_max_pivots: Optional[int] = None,
        pgs_max_sweeps: Optional[int] = None,
        pgs_tolerance: Optional[float] = None,
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
    def solve_ragged(
        self,
        m: List[npt.NDArray[np.float64]],
        q: List[npt.NDArray[np.float64]],
        ids: Optional[List[npt.NDArray[np.uint64]]] = None,
    ) -> Dict[str, Any]: ...
    def solve_scenes(self, scenes: List[Dict[str, Any]]) -> Dict[str, Any]: ...
    def time_solve_lcps(
        self, m: npt.NDArray[np.float64], q: npt.NDArray[np.float64], repeats: int
    ) -> List[float]: ...
