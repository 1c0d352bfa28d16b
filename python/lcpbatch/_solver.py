"""``Solver`` (the library's solver kept between calls), and the functions
``solve`` and ``solve_scenes`` that use a cached one per set of settings."""

from __future__ import annotations

import threading
import warnings
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _inputs, _native
from ._results import LcpResult, ScenesResult
from ._scenes import scene_arrays

__all__ = ["Solver", "solve", "solve_scenes", "DeviceWarning", "adapters"]

ArrayLike = Any
SceneArrays = Mapping[str, ArrayLike]


class DeviceWarning(RuntimeWarning):
    """The GPU could not be used (no adapter, no f64, a lost device): the
    batch, and every later one of this solver, is solved on the CPU in f64.
    The reason is also in ``result.report.fallback``.

    >>> import warnings, lcpbatch
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     s = lcpbatch.Solver(backend="gpu", adapter="no-such-adapter")
    >>> caught[0].category.__name__, s.device_kind
    ('DeviceWarning', 'cpu')
    """


def adapters(api: str = "auto") -> List[Dict[str, Any]]:
    """Every GPU adapter wgpu finds on ``api`` ("auto", "vulkan", "gl",
    "metal", "dx12"): dicts with name, backend, device_type, driver,
    software and f64. Empty when there is none.

    >>> import lcpbatch
    >>> isinstance(lcpbatch.adapters(), list)
    True
    """
    return list(_native.adapters(api))


class Solver:
    """A contact solver built once and used for many batches: it keeps the
    device, its compiled pipelines and the warm-start memory between calls.

    Keyword arguments (defaults are the library's):

    - ``backend``: "auto" (a hardware GPU if there is one, else the CPU),
      "cpu" or "gpu" (software adapters too; device trouble falls back to
      the CPU with a :class:`DeviceWarning`);
    - ``solver``: "auto" (the fastest exact path), "enum" (enumeration of
      complementary bases), "lemke" or "pgs";
    - ``precision``: GPU shader precision "auto", "f32" or "f64" (answers are
      checked in f64 on the CPU whatever it is);
    - ``all_solutions``: enumerate every basis and report the solution set
      (``all_z``, ``all_basis``; where it runs: the library's ``Settings``);
    - ``warm_start``: remember each problem's basis by its contact ``ids``;
    - ``tolerance``: the largest error measure reported as solved (default 1e-8);
    - ``threads``: CPU threads (0: every core); ``adapter``: part of a GPU
      adapter's name; ``api``: "auto", "vulkan", "gl", "metal", "dx12";
      ``predict``: settle easy problems before enumerating (default True);
      ``lemke_max_pivots``, ``pgs_max_sweeps``, ``pgs_tolerance``.

    A bad value raises ``ValueError`` naming the argument.

    >>> import numpy as np, lcpbatch
    >>> s = lcpbatch.Solver(backend="cpu", warm_start=True)
    >>> M, q = np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]])
    >>> ids = np.array([[10, 11]])
    >>> s.solve(M, q, ids=ids).path.tolist(), s.solve(M, q, ids=ids).path.tolist()
    (['predicted_basis'], ['warm_start'])
    """

    def __init__(
        self,
        *,
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
    ):
        self.settings: Dict[str, Any] = dict(
            backend=backend, solver=solver, precision=precision, all_solutions=all_solutions,
            warm_start=warm_start, tolerance=tolerance, threads=threads, adapter=adapter,
            api=api, predict=predict, lemke_max_pivots=lemke_max_pivots,
            pgs_max_sweeps=pgs_max_sweeps, pgs_tolerance=pgs_tolerance,
        )
        if threads < 0:
            raise ValueError(f"threads: {threads} is negative (0 means every core)")
        self._native = _native.NativeSolver(**self.settings)
        self._warned = False
        self._warn_fallback(self._native.fallback())

    def __reduce__(self) -> Tuple[Any, ...]:
        # A pickled solver is rebuilt from its settings (a new device on the
        # other side); the warm-start memory does not travel.
        return (_rebuild, (self.settings,))

    @property
    def device(self) -> str:
        """Where the next batch will be solved, in words."""
        return self._native.device()

    @property
    def device_kind(self) -> str:
        """"cpu", "hardware_gpu" or "software_gpu"."""
        return self._native.device_kind()

    @property
    def choice(self) -> str:
        """Why this device: the backend asked for and what was found."""
        return self._native.choice()

    @property
    def fallback(self) -> Optional[str]:
        """Why the CPU took over from the GPU (None: no device trouble)."""
        return self._native.fallback()

    def clear_warm_start(self) -> None:
        """Forgets the bases remembered for warm start.

        >>> import numpy as np, lcpbatch
        >>> s = lcpbatch.Solver(backend="cpu", warm_start=True)
        >>> M, q, ids = np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]), np.array([[1, 2]])
        >>> _ = s.solve(M, q, ids=ids); s.clear_warm_start()
        >>> s.solve(M, q, ids=ids).path.tolist()
        ['predicted_basis']
        """
        self._native.clear_warm_start()

    def _warn_fallback(self, why: Optional[str]) -> None:
        if why is not None and not self._warned:
            self._warned = True
            warnings.warn(f"GPU: {why}; solving on the CPU (f64, exact)", DeviceWarning, stacklevel=3)

    def solve(self, M: Union[ArrayLike, Sequence[ArrayLike]], q: Union[ArrayLike, Sequence[ArrayLike]],
              ids: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None) -> LcpResult:
        """Solves the LCPs w = M z + q ≥ 0, z ≥ 0, zᵀw = 0 of a batch.

        ``M`` (B, n, n) and ``q`` (B, n), float64 or float32 (computed in
        f64), any memory order, or nested lists NumPy reads as such; or a
        list of NumPy arrays, one (nᵢ, nᵢ) per problem, with a list of (nᵢ,)
        for q, for problems of different sizes (the result's z, w, basis are
        then lists). ``ids`` (same shape as q, integers ≥ 0): contact ids, with
        ``warm_start=True`` each problem starts from the basis its contacts
        had in the last call. The GIL is released while solving; the batch
        is solved in chunks (``CHUNK_PROBLEMS`` problems, at most
        ``CHUNK_WORK`` / 2^n of size n) and Ctrl-C between chunks raises
        ``KeyboardInterrupt``.

        >>> import numpy as np, lcpbatch
        >>> s = lcpbatch.Solver(backend="cpu")
        >>> r = s.solve([np.array([[2.0, 1.0], [1.0, 2.0]]), np.array([[1.0]])],
        ...             [np.array([-5.0, -6.0]), np.array([3.0])])
        >>> [z.round(6).tolist() for z in r.z], r.status_names().tolist()
        ([[1.333333, 2.333333], [0.0]], ['solved', 'solved'])
        """
        backend = self.settings["backend"]
        if _inputs.is_ragged(M):
            ms, qs, idl = _inputs.ragged(M, q, ids)
            _inputs.check_enumeration_size([len(x) for x in qs], self.settings["solver"], backend)
            d = self._native.solve_ragged(ms, qs, idl)
            result = LcpResult(d, ragged=True, n=None)
        else:
            m, qa, idsa = _inputs.dense(M, q, ids)
            if len(m):
                _inputs.check_enumeration_size([m.shape[1]], self.settings["solver"], backend)
            d = self._native.solve_dense(m, qa, idsa)
            result = LcpResult(d, ragged=False, n=m.shape[1])
        self._warn_fallback(result.report.fallback)
        return result

    def solve_scenes(self, bodies: Union[SceneArrays, Sequence[SceneArrays]],
                     contacts: Union[SceneArrays, Sequence[SceneArrays]]) -> ScenesResult:
        """Solves the impact of one scene (``bodies`` and ``contacts`` dicts of
        arrays) or of a batch (two lists of dicts, one per scene): the normal
        impulse of every contact and the bodies' velocities after it. See
        ``lcpbatch._scenes`` for the layout (``b = -1``: the static world).

        >>> import lcpbatch
        >>> s = lcpbatch.Solver(backend="cpu")
        >>> ball = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
        ...             velocity=[[0, -1.0, 0]])
        >>> ground = dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=0.5)
        >>> r = s.solve_scenes([ball, ball], [ground, ground])
        >>> [float(i[0]) for i in r.impulses]
        [1.5, 1.5]
        """
        single = isinstance(bodies, Mapping)
        if single != isinstance(contacts, Mapping):
            raise TypeError("bodies and contacts: give two dicts (one scene) or two lists of dicts (a batch)")
        bl: List[SceneArrays] = [bodies] if isinstance(bodies, Mapping) else list(bodies)
        cl: List[SceneArrays] = [contacts] if isinstance(contacts, Mapping) else list(contacts)
        if len(bl) != len(cl):
            raise ValueError(f"contacts: {len(cl)} scenes of contacts for {len(bl)} scenes of bodies")
        arrays = [scene_arrays(b, c, i) for i, (b, c) in enumerate(zip(bl, cl))]
        result = ScenesResult(self._native.solve_scenes(arrays), single)
        self._warn_fallback(result.report.fallback)
        return result

    def __repr__(self) -> str:
        return f"<lcpbatch.Solver on {self.device}; {self.choice}>"


def _rebuild(settings: Dict[str, Any]) -> Solver:
    return Solver(**settings)


_CACHE: Dict[Tuple[Any, ...], Solver] = {}
_CACHE_LOCK = threading.Lock()
_CACHE_SIZE = 8


def _cached(**settings: Any) -> Solver:
    """One solver per distinct settings, kept for later calls (the device
    and its pipelines are opened once); at most 8 are kept."""
    key = tuple(sorted(settings.items()))
    with _CACHE_LOCK:
        s = _CACHE.get(key)
        if s is None:
            if len(_CACHE) >= _CACHE_SIZE:
                _CACHE.pop(next(iter(_CACHE)))
            s = _CACHE[key] = Solver(**settings)
        return s


def solve(M: Union[ArrayLike, Sequence[ArrayLike]], q: Union[ArrayLike, Sequence[ArrayLike]], *,
          solver: str = "auto", backend: str = "auto", precision: str = "auto",
          all_solutions: bool = False, warm_start: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None,
          tolerance: Optional[float] = None, **settings: Any) -> LcpResult:
    """Solves a batch of LCPs: find z with w = M z + q ≥ 0, z ≥ 0, zᵀw = 0.

    ``M`` (B, n, n) and ``q`` (B, n) arrays (float64 or float32, any
    memory order), or a list of NumPy arrays, one (nᵢ, nᵢ) per problem, and
    a list of (nᵢ,) for problems of different sizes. ``warm_start``: contact ids shaped like q; each problem
    then starts from the basis its contacts had in the last call with the
    same settings (the solver behind this function is cached per settings).
    Other keyword arguments are those of :class:`Solver`. Returns an
    :class:`LcpResult`.

    >>> import numpy as np, lcpbatch
    >>> M = np.array([[[2.0, 1.0], [1.0, 2.0]]])      # seed 000's example
    >>> q = np.array([[-5.0, -6.0]])
    >>> r = lcpbatch.solve(M, q)
    >>> r.z.round(6).tolist(), r.status_names().tolist(), bool(r.error[0] < 1e-12)
    ([[1.333333, 2.333333]], ['solved'], True)
    """
    if isinstance(warm_start, (bool, np.bool_)):
        if warm_start:
            raise TypeError("warm_start: give the contact ids (integers shaped like q), not True; "
                            "or keep a Solver(warm_start=True) and pass ids to its solve")
        warm_start = None
    s = _cached(solver=solver, backend=backend, precision=precision, all_solutions=all_solutions,
                warm_start=warm_start is not None, tolerance=tolerance, **settings)
    return s.solve(M, q, ids=warm_start)


def solve_scenes(bodies: Union[SceneArrays, Sequence[SceneArrays]],
                 contacts: Union[SceneArrays, Sequence[SceneArrays]], **settings: Any) -> ScenesResult:
    """Solves the impact of one scene or a batch of scenes given as arrays
    (see :meth:`Solver.solve_scenes`); keyword arguments are those of
    :class:`Solver`.

    >>> import lcpbatch
    >>> ball = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
    ...             velocity=[[0, -1.0, 0]])
    >>> ground = dict(a=[0], b=[-1], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=[0.5])
    >>> r = lcpbatch.solve_scenes(ball, ground, backend="cpu")
    >>> r.velocity.tolist()
    [[0.0, 0.5, 0.0]]
    """
    return _cached(**settings).solve_scenes(bodies, contacts)
