"""``Solver`` (the library's solver kept between calls), and the functions
``solve``, ``solve_scenes``, ``solve_friction`` and ``simulate`` that use a
cached one per set of settings."""

from __future__ import annotations

import threading
import warnings
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _friction, _inputs, _native
from ._friction import FRICTION_FIELDS_DOC, FrictionResult
from ._results import LCP_FIELDS_DOC, SCENES_FIELDS_DOC, LcpResult, ScenesResult, Status, fill_doc
from ._scenes import scene_arrays
from ._worlds import STEP_FIELDS_DOC, StepResult, World

__all__ = ["Solver", "solve", "solve_scenes", "solve_friction", "simulate", "DeviceWarning", "adapters"]

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


#: The settings of :class:`Solver`, which every solve function takes too
#: (shown by ``help()`` of each).
_SETTINGS_DOC = """\
    Settings: keyword arguments, each optional (defaults are the library's
    ``Settings``), with every value each accepts:

    - ``backend``: where islands are solved.

      - ``"auto"`` (default): the CPU unless a GPU is worth opening. With
        ``method`` "lemke" or "pgs" (CPU-only methods): the CPU. With an
        ``adapter`` named: that adapter, even a software one. Else a
        hardware adapter if wgpu finds one; an unnamed software adapter
        (lavapipe, llvmpipe) is never opened, being slower than the CPU on
        every batch measured (BENCHMARKS.md). With a GPU open, each batch
        goes where a cost model of this machine (seconds per island by
        size on each path, measured once and cached per device) estimates
        it faster; frictional islands stay on the CPU. ``choice`` and
        ``report.choice`` say why, with both estimates.
      - ``"cpu"``: the f64 path over every core.
      - ``"gpu"``: the GPU for every batch, software adapters included,
        every answer checked on the CPU in f64 (method "auto" or "enum";
        "lemke" and "pgs" are a ``ValueError`` there).

      Device trouble (no adapter, a named adapter not found, f64 asked of
      an adapter without it, a device lost) solves on the CPU instead, with
      one :class:`DeviceWarning` and the reason in ``fallback``.
    - ``method``: the algorithm of frictionless islands and LCPs.

      - ``"auto"`` (default): the fastest exact path: prediction (separating,
        single contact, warm start, predicted basis), then Lemke, its basis
        re-solved and checked in f64, enumeration where the check fails; on
        the GPU, enumeration.
      - ``"enum"`` (also ``"enumeration"``): enumeration of the
        complementary bases, fewest active contacts first (CPU n ≤ 20, GPU
        n ≤ 16); the only method the GPU runs.
      - ``"lemke"``: Lemke's complementary pivoting (CPU, any n).
      - ``"pgs"``: projected Gauss–Seidel from z = 0 (CPU, iterative).
    - ``solver``: the old name of ``method``; deprecated (a
      ``DeprecationWarning``), same values.
    - ``precision``: GPU shader precision, ``"auto"`` (default: f64 where the
      adapter has SHADER_F64, else f32), ``"f32"`` or ``"f64"`` (f64 on an
      adapter without it is device trouble, never silently f32). Answers
      are checked in f64 on the CPU whatever it is.
    - ``all_solutions`` (default False): enumerate every basis and report
      the solution set (``all_z``, ``all_basis``, ``solution_count``,
      ``solution_set``); method "auto" or "enum".
    - ``warm_start`` (default False): remember each problem's basis (and
      each frictional contact's reaction) by its contact ``ids`` and start
      the next call from it.
    - ``warm_start_calls`` (default 1, at least 1): calls a contact id is
      remembered without being seen again; 1 keeps the last call's ids
      only. A call counts once however many chunks it is solved in; in
      ``step_worlds`` each step is a call.
    - ``tolerance``: the largest error measure reported as solved (default
      1e-8, in (0, 1)).
    - ``threads``: CPU threads (default 0: every core).
    - ``adapter``: part of a GPU adapter's name (case-insensitive; default
      None: the best adapter, hardware before software).
    - ``api``: the wgpu backend to look on, ``"auto"`` (default: all, Vulkan
      before GL), ``"vulkan"``, ``"gl"``, ``"metal"`` or ``"dx12"``.
    - ``predict`` (default True): settle the islands that need no
      enumeration first (same answers).
    - ``lemke_max_pivots``: Lemke's pivot cap (default 10,000);
      ``pgs_max_sweeps``: PGS's sweep cap (default 1000); ``pgs_tolerance``:
      PGS stops at this error (default 1e-10).
    - ``friction_method``: the algorithm of islands and problems with
      friction.

      - ``"auto"`` (default): NSGS sweeps, then Alart–Curnier semismooth
        Newton, each stopping when the Coulomb error (Siconos' fc3d error
        with De Saxcé's correction) is at most ``friction_tolerance``.
      - ``"nsgs"``: non-smooth block Gauss–Seidel, each contact solved exactly.
      - ``"newton"``: Alart–Curnier Newton with line search alone.
      - ``"prox"``: the proximal-point iteration (Newton on W + αI around
        the last iterate), for large islands where Newton alone stalls.
      - ``"jacobi"``, ``"pgs"``, ``"apgd"``: projected Jacobi sweeps,
        projected Gauss–Seidel sweeps, accelerated projected gradient on
        the cone complementarity model of Anitescu–Tasora (on the GPU with
        backend "gpu"), judged by that model's residual ``cone_error``.

      The exact methods ("auto", "nsgs", "newton", "prox") run on the CPU in f64.
    - ``friction_tolerance``: the largest Coulomb error (projected methods:
      cone error) reported as solved (default 1e-8, in (0, 1));
      ``friction_max_iterations``: cap on NSGS sweeps plus Newton steps, or
      on the projected methods' iterations (default 1000).

    A bad value raises ``ValueError`` naming the argument and the values it
    accepts.
"""


def _method(method: str, solver: Optional[str], stacklevel: int) -> str:
    """The algorithm from ``method=``, or from ``solver=`` (its old name), with
    a ``DeprecationWarning`` that points ``stacklevel`` frames above the
    function calling this one (the user's line)."""
    if solver is None:
        return method
    warnings.warn("lcpbatch: the keyword solver= is deprecated; use method= (the same values)",
                  DeprecationWarning, stacklevel=stacklevel + 2)
    if method not in ("auto", solver):
        raise TypeError(f"method={method!r} and solver={solver!r}: give method= only "
                        "(solver= is its deprecated old name)")
    return solver


class Solver:
    """A contact solver built once and used for many batches: it keeps the
    device, its compiled pipelines and the warm-start memory between calls.

    <settings>

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
        solver: Optional[str] = None,
    ):
        method = _method(method, solver, stacklevel=1)
        self.settings: Dict[str, Any] = dict(
            backend=backend, method=method, precision=precision, all_solutions=all_solutions,
            warm_start=warm_start, warm_start_calls=warm_start_calls, tolerance=tolerance,
            threads=threads, adapter=adapter,
            api=api, predict=predict, lemke_max_pivots=lemke_max_pivots,
            pgs_max_sweeps=pgs_max_sweeps, pgs_tolerance=pgs_tolerance,
            friction_method=friction_method, friction_tolerance=friction_tolerance,
            friction_max_iterations=friction_max_iterations,
        )
        if threads < 0:
            raise ValueError(f"threads: {threads} is negative (0 means every core)")
        if isinstance(warm_start_calls, (bool, np.bool_)) or not isinstance(warm_start_calls, (int, np.integer)):
            raise TypeError(f"warm_start_calls: expected an integer ≥ 1, got {type(warm_start_calls).__name__}")
        if warm_start_calls < 1:
            raise ValueError(f"warm_start_calls: {warm_start_calls} is not an integer ≥ 1 "
                             "(calls a contact id is remembered)")
        self.settings["warm_start_calls"] = int(warm_start_calls)
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
            _inputs.check_enumeration_size([len(x) for x in qs], self.settings["method"], backend)
            d = self._native.solve_ragged(ms, qs, idl)
            result = LcpResult(d, ragged=True, n=None)
        else:
            m, qa, idsa = _inputs.dense(M, q, ids)
            if len(m):
                _inputs.check_enumeration_size([m.shape[1]], self.settings["method"], backend)
            d = self._native.solve_dense(m, qa, idsa)
            result = LcpResult(d, ragged=False, n=m.shape[1])
        self._warn_fallback(result.report.fallback)
        return result

    def _solve_zw(self, M: ArrayLike, q: ArrayLike) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """For the differentiable adapters: z and w (B, n) and ``ok`` (B,) of
        a dense batch, solved (checked, warned about) as :meth:`solve` solves
        it, without the rest of its result (the extension builds only these
        arrays; a C-ordered float64 batch is read in place)."""
        m, qa, _ = _inputs.dense(M, q, None)
        if len(m):
            _inputs.check_enumeration_size([m.shape[1]], self.settings["method"], self.settings["backend"])
        (z, w, status), fallback = self._native.solve_dense_zw(m, qa)
        self._warn_fallback(fallback)
        return z, w, status <= Status.MULTIPLE_SOLUTIONS

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

    def solve_friction(self, W: Union[ArrayLike, Sequence[ArrayLike]], q: Union[ArrayLike, Sequence[ArrayLike]],
                       mu: Union[ArrayLike, Sequence[ArrayLike]],
                       ids: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None) -> FrictionResult:
        """Solves a batch of frictional contact problems (Siconos'
        FrictionContact3D): u = W r + q with Coulomb's law per contact (see
        ``lcpbatch._friction``), with ``friction_method``: on the CPU in f64
        over every core (the projected methods on the GPU with backend "gpu").

        ``W`` (B, 3k, 3k), ``q`` (B, 3k), ``mu`` (B, k) or a scalar, float64
        or float32, any memory order; contact i owns entries 3i (normal),
        3i + 1, 3i + 2 (tangents). Or lists of NumPy arrays for problems of
        different k (results are then lists). ``ids`` (B, k) integers ≥ 0:
        contact ids; with ``warm_start=True`` each contact starts from its
        reaction of the last call. GIL released; chunks of at most
        ``CHUNK_FRICTION_WORK`` (3k)² with a Ctrl-C check between them.

        >>> import numpy as np, lcpbatch
        >>> s = lcpbatch.Solver(backend="cpu")
        >>> W = np.eye(3)[None]; q = np.array([[-1.0, 0.1, 0.0]])
        >>> r = s.solve_friction(W, q, 0.5)        # sticks: u_T = 0
        >>> (r.r.round(6) + 0.0).tolist(), (r.u.round(6) + 0.0).tolist()
        ([[1.0, -0.1, 0.0]], [[0.0, 0.0, 0.0]])
        """
        if _inputs.is_ragged(W):
            ws, qs, ms, idl = _friction.ragged(W, q, mu, ids)
            d = self._native.solve_friction_ragged(ws, qs, ms, idl)
            result = FrictionResult(d, ragged=True, n=None)
        else:
            w, qa, ma, idsa = _friction.dense(W, q, mu, ids)
            d = self._native.solve_friction_dense(w, qa, ma, idsa)
            result = FrictionResult(d, ragged=False, n=w.shape[1])
        self._warn_fallback(result.report.fallback)
        return result

    def step_worlds(self, worlds: Union[World, Sequence[World]], dt: float, steps: int = 1) -> StepResult:
        """Advances every world by ``steps`` steps of ``dt`` seconds, in
        place, through the library's ``step_worlds_for`` in calls of 1, 2,
        4, ... steps (doubled after a call under half a second) with the GIL
        released and a Ctrl-C check between calls (after
        ``KeyboardInterrupt`` the worlds hold the last call's last step); on
        the resident GPU path the states stay on the device within a call,
        per step only a small record per world comes back. A world gives the same trajectory alone or in a
        batch, and ``steps=2`` equals two calls of ``steps=1``.

        >>> import lcpbatch
        >>> s = lcpbatch.Solver(backend="cpu")
        >>> w = lcpbatch.World.generate("slide")           # a box sliding at 2 m/s, μ = 0.5
        >>> out = s.step_worlds([w], dt=0.01, steps=50)
        >>> bool(out.velocities[0][1, 0] < 2.0), int(out.unsolved.sum())
        (True, 0)
        """
        ws = [worlds] if isinstance(worlds, World) else list(worlds)
        for i, w in enumerate(ws):
            if not isinstance(w, World):
                raise TypeError(f"worlds[{i}]: expected an lcpbatch.World, got {type(w).__name__}")
        if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 0:
            raise ValueError(f"steps: {steps!r} is not an integer ≥ 0")
        dt = float(dt)
        if not np.isfinite(dt) or dt <= 0:
            raise ValueError(f"dt: {dt} is not a positive number of seconds")
        d = self._native.step_worlds([w._w for w in ws], dt, int(steps))
        result = StepResult(d, ws)
        if result.report is not None:
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
    if "solver" in settings:
        # Two frames up: the caller of solve, solve_scenes, solve_friction or simulate.
        settings["method"] = _method(settings.get("method", "auto"), settings.pop("solver"), stacklevel=2)
    key = tuple(sorted(settings.items()))
    with _CACHE_LOCK:
        s = _CACHE.get(key)
        if s is None:
            if len(_CACHE) >= _CACHE_SIZE:
                _CACHE.pop(next(iter(_CACHE)))
            s = _CACHE[key] = Solver(**settings)
        return s


def solve(M: Union[ArrayLike, Sequence[ArrayLike]], q: Union[ArrayLike, Sequence[ArrayLike]], *,
          method: str = "auto", backend: str = "auto", precision: str = "auto",
          all_solutions: bool = False, warm_start: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None,
          tolerance: Optional[float] = None, **settings: Any) -> LcpResult:
    """Solves a batch of LCPs: find z with w = M z + q ≥ 0, z ≥ 0, zᵀw = 0.

    ``M`` (B, n, n) and ``q`` (B, n) arrays (float64 or float32, any
    memory order), or a list of NumPy arrays, one (nᵢ, nᵢ) per problem, and
    a list of (nᵢ,) for problems of different sizes. ``warm_start``: contact
    ids shaped like q; each problem then starts from the basis its contacts
    had in the last call with the same settings (the solver behind this
    function is cached per settings). The other keyword arguments are the
    settings of :class:`Solver`:

    <settings>

    Returns an :class:`LcpResult`:

    <fields>

    >>> import numpy as np, lcpbatch
    >>> M = np.array([[[2.0, 1.0], [1.0, 2.0]]])      # two contacts, both active
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
    s = _cached(method=method, backend=backend, precision=precision, all_solutions=all_solutions,
                warm_start=warm_start is not None, tolerance=tolerance, **settings)
    return s.solve(M, q, ids=warm_start)


def solve_scenes(bodies: Union[SceneArrays, Sequence[SceneArrays]],
                 contacts: Union[SceneArrays, Sequence[SceneArrays]], **settings: Any) -> ScenesResult:
    """Solves the impact of one scene or a batch of scenes given as arrays
    (see :meth:`Solver.solve_scenes` and ``lcpbatch._scenes`` for the
    layout); the keyword arguments are the settings of :class:`Solver`:

    <settings>

    Returns a :class:`ScenesResult`:

    <fields>

    >>> import lcpbatch
    >>> ball = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
    ...             velocity=[[0, -1.0, 0]])
    >>> ground = dict(a=[0], b=[-1], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=[0.5])
    >>> r = lcpbatch.solve_scenes(ball, ground, backend="cpu")
    >>> r.velocity.tolist()
    [[0.0, 0.5, 0.0]]
    """
    return _cached(**settings).solve_scenes(bodies, contacts)


def solve_friction(W: Union[ArrayLike, Sequence[ArrayLike]], q: Union[ArrayLike, Sequence[ArrayLike]],
                   mu: Union[ArrayLike, Sequence[ArrayLike]], *, method: str = "auto",
                   tolerance: Optional[float] = None, max_iterations: Optional[int] = None,
                   ids: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None, **settings: Any) -> FrictionResult:
    """Solves a batch of frictional contact problems (Siconos'
    FrictionContact3D form; see :meth:`Solver.solve_friction`).

    ``method``: the friction method (``friction_method`` of
    :class:`Solver`): "auto" (default), "nsgs", "newton", "prox", "jacobi", "pgs" or
    "apgd"; ``tolerance``: the largest error reported as solved (default
    1e-8); ``max_iterations``: cap on NSGS sweeps plus Newton steps, or on
    the projected methods' iterations (default 1000); ``ids``: contact ids
    (B, k) for warm start from the last call with the same settings. The
    other keyword arguments are the settings of :class:`Solver`:

    <settings>

    Returns a :class:`FrictionResult`:

    <fields>

    A contact with W = I, free velocity q = (−1, 3, −4) (approaching,
    sliding with v_T = (3, −4)) and μ = 0.5 slides: r_N = 1 and r_T is the
    projection of −v_T on the disc of radius μ r_N (Coulomb's maximum
    dissipation), −μ r_N v_T/‖v_T‖ = (−0.3, 0.4):

    >>> import numpy as np, lcpbatch
    >>> r = lcpbatch.solve_friction(np.eye(3)[None], np.array([[-1.0, 3.0, -4.0]]), np.array([[0.5]]))
    >>> r.r.round(9).tolist(), bool(r.coulomb_error[0] < 1e-10)
    ([[1.0, -0.3, 0.4]], True)
    """
    s = _cached(friction_method=method, friction_tolerance=tolerance,
                friction_max_iterations=max_iterations, warm_start=ids is not None, **settings)
    return s.solve_friction(W, q, mu, ids=ids)


def simulate(worlds: Union[World, Sequence[World]], dt: float, steps: int = 1, **settings: Any) -> StepResult:
    """Steps a batch of worlds ``steps`` times by ``dt`` seconds, in place
    (see :meth:`Solver.step_worlds`; with ``backend="gpu"`` the batch stays
    on the device and the states come back into the worlds' arrays at the
    end; with ``backend="auto"`` and a GPU open, a hardware adapter or one
    named by ``adapter``, the library steps it there where its cost model
    estimates that faster than the CPU, else on the CPU, and the report's
    ``choice`` says which, with both estimates). ``friction_tolerance`` defaults to
    1e-12 here, as in ``lcpbatch simulate``: the Coulomb error is relative to
    an island's largest impulse, and the solver's 1e-8 leaves heavy resting
    boxes with velocities near 1e-6 m/s. The keyword arguments are the
    settings of :class:`Solver` (``warm_start=True`` carries contact
    impulses from step to step by contact id):

    <settings>

    Returns a :class:`StepResult`:

    <fields>

    >>> import lcpbatch
    >>> w = lcpbatch.World.generate("spheres", 1, seed=3)
    >>> out = lcpbatch.simulate(w, dt=1 / 60, steps=240, backend="cpu")
    >>> float(out.velocities[0][1:].max()) < 1e-3    # dropped, it came to rest
    True
    """
    settings.setdefault("friction_tolerance", 1e-12)
    return _cached(**settings).step_worlds(worlds, dt, steps)


fill_doc(Solver, settings=_SETTINGS_DOC)
fill_doc(solve, settings=_SETTINGS_DOC, fields=LCP_FIELDS_DOC)
fill_doc(solve_scenes, settings=_SETTINGS_DOC, fields=SCENES_FIELDS_DOC)
fill_doc(solve_friction, settings=_SETTINGS_DOC, fields=FRICTION_FIELDS_DOC)
fill_doc(simulate, settings=_SETTINGS_DOC, fields=STEP_FIELDS_DOC)
