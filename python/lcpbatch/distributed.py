"""Shard a batch of LCPs, scenes or worlds over an existing Dask cluster.

Dask does the scheduling; this module only cuts the batch into consecutive
shards, scatters them to the workers, solves each shard with the worker's
own :class:`lcpbatch.Solver` (built once per worker by a worker plugin, so
the device and pipelines are opened once), and gathers the results in the
batch's order, with per-worker timings.

Needs the ``distributed`` extra: ``pip install 'lcpbatch[distributed]'``
(``./python[distributed]`` from a checkout), on the client and on every
worker (the workers import ``lcpbatch`` too).

Pointing it at a real cluster: start a scheduler and workers as Dask
documents (``dask scheduler`` on one machine, ``dask worker tcp://HOST:8786
--nthreads 1`` on each, or a ``dask_jobqueue``/``dask_kubernetes`` cluster)
with ``lcpbatch`` installed in every worker's environment, then pass
``Client("tcp://HOST:8786")``. One thread per worker is best: each worker's
solver uses every core of its machine (``threads=0``), or give
``threads=k`` and ``--nthreads`` to match.

>>> from dask.distributed import Client, LocalCluster      # doctest: +SKIP
>>> import numpy as np, lcpbatch, lcpbatch.distributed as ld  # doctest: +SKIP
>>> client = Client(LocalCluster(n_workers=2, threads_per_worker=1))  # doctest: +SKIP
>>> M = np.tile(np.eye(3), (1000, 1, 1)); q = -np.ones((1000, 3))      # doctest: +SKIP
>>> r = ld.solve(client, M, q, backend="cpu")              # doctest: +SKIP
>>> r.z.shape, sorted(r.workers)                           # doctest: +SKIP
((1000, 3), ['tcp://127.0.0.1:…', 'tcp://127.0.0.1:…'])
>>> worlds = [lcpbatch.World.generate("rain", 32, seed=s) for s in range(64)]  # doctest: +SKIP
>>> out = ld.simulate(client, worlds, dt=0.01, steps=100, backend="cpu")     # doctest: +SKIP
>>> out.kinetic.shape                                      # doctest: +SKIP
(100, 64)
"""

from __future__ import annotations

import hashlib
import json
import time
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

try:
    from distributed import Client, WorkerPlugin, get_worker
except ImportError as e:  # pragma: no cover - exercised without the extra
    raise ImportError(
        "lcpbatch.distributed needs Dask's distributed scheduler: "
        "pip install 'lcpbatch[distributed]' (the 'distributed' extra: dask and distributed)"
    ) from e

from . import _inputs
from ._results import LcpResult, ScenesResult, concat_lcp_results, concat_scenes_results
from ._solver import Solver, _method
from ._worlds import StepResult, World, concat_step_results

__all__ = ["DistributedSolver", "solve", "solve_scenes", "simulate"]


class SolverPlugin(WorkerPlugin):
    """Builds one :class:`lcpbatch.Solver` on each worker when registered
    (and on workers that join later); tasks find it by the plugin's name."""

    def __init__(self, settings: Dict[str, Any]):
        self.settings = dict(settings)
        digest = hashlib.sha1(json.dumps(self.settings, sort_keys=True).encode()).hexdigest()[:12]
        self.name = f"lcpbatch-solver-{digest}"
        self.solver: Optional[Solver] = None
        self.created = 0.0

    def setup(self, worker: Any) -> None:
        self.solver = Solver(**self.settings)
        self.created = time.time()

    def teardown(self, worker: Any) -> None:
        self.solver = None


def _worker_solver(name: str) -> Tuple[Solver, str]:
    """The solver the plugin `name` built on this worker, and its address."""
    worker = get_worker()
    plugin = worker.plugins[name]
    assert isinstance(plugin, SolverPlugin) and plugin.solver is not None, name
    return plugin.solver, worker.address


def _solve_shard(name: str, kind: str, shard: Tuple[Any, ...]) -> Tuple[Any, str, float, int]:
    """Runs on a worker: one shard through the worker's solver."""
    solver, address = _worker_solver(name)
    start = time.perf_counter()
    result: Union[LcpResult, ScenesResult]
    if kind == "lcp":
        result = solver.solve(*shard)
        size = len(result)
    elif kind == "worlds":
        result = solver.step_worlds(*shard)
        size = len(result.worlds)
    else:
        result = solver.solve_scenes(*shard)
        size = len(result.scene_ok)
    return result, address, time.perf_counter() - start, size


def _bounds(count: int, shards: int) -> List[Tuple[int, int]]:
    """Consecutive [start, end) of `shards` near-equal parts of `count` items."""
    shards = max(1, min(shards, count))
    edges = np.linspace(0, count, shards + 1).round().astype(int)
    return [(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:]) if b > a]


class DistributedSolver:
    """One :class:`lcpbatch.Solver` per worker of a Dask ``client``, built
    once (worker plugin) with the keyword arguments of ``Solver``.

    ``solve`` and ``solve_scenes`` take what ``Solver``'s do, plus
    ``shards`` (default: twice the number of workers); they return the
    result a single ``Solver`` would, with ``workers``: per worker address,
    the shards and problems (or scenes) it solved, the seconds its tasks
    took and the seconds inside the library (``solve_seconds``), and
    ``wall_seconds`` for the whole call.
    """

    def __init__(self, client: Client, **settings: Any):
        self.client = client
        if "solver" in settings:
            # Warned here once, not on every worker.
            settings["method"] = _method(settings.get("method", "auto"), settings.pop("solver"), stacklevel=1)
        self.settings = settings
        self.plugin = SolverPlugin(settings)
        # register_plugin since distributed 2023.9; register_worker_plugin before.
        register = getattr(client, "register_plugin", None) or getattr(client, "register_worker_plugin")
        register(self.plugin, name=self.plugin.name)

    @property
    def name(self) -> str:
        """The worker plugin's name (the key of each worker's solver)."""
        return self.plugin.name

    def _run(self, kind: str, shards: List[Tuple[Any, ...]]) -> Tuple[List[Any], Dict[str, Dict[str, Any]], float]:
        start = time.perf_counter()
        # hash=False: unique keys. With content hashes a batch scattered again
        # right after the last call reuses keys the scheduler is still
        # releasing, and Dask reports the data lost.
        data = self.client.scatter(shards, hash=False)
        futures = [self.client.submit(_solve_shard, self.name, kind, d, pure=False) for d in data]
        done = self.client.gather(futures)
        wall = time.perf_counter() - start
        workers: Dict[str, Dict[str, Any]] = {}
        for result, address, seconds, size in done:
            report = result.report
            w = workers.setdefault(address, dict(shards=0, items=0, seconds=0.0, solve_seconds=0.0,
                                                 device=report.device if report else None))
            w["shards"] += 1
            w["items"] += size
            w["seconds"] += seconds
            # Worlds: the seconds of every step's solve; batches: the library's total.
            w["solve_seconds"] += (float(result.timings["solve"].sum()) if kind == "worlds"
                                   else report.timings["total"])
        return [d[0] for d in done], workers, wall

    def solve(self, M: Any, q: Any, ids: Any = None, *, shards: Optional[int] = None) -> LcpResult:
        """A batch of LCPs (dense arrays or ragged lists, as :meth:`Solver.solve`),
        cut into ``shards`` consecutive parts solved on the workers."""
        ragged = _inputs.is_ragged(M)
        if not ragged:
            M, q = np.asarray(M), np.asarray(q)
            ids = None if ids is None else np.asarray(ids)
        count = len(M)
        if count == 0:
            return Solver(**self.settings).solve(M, q, ids)
        parts = []
        for a, b in _bounds(count, shards or 2 * self._workers()):
            k = None if ids is None else ids[a:b]
            parts.append((list(M[a:b]) if ragged else M[a:b], list(q[a:b]) if ragged else q[a:b], k))
        results, workers, wall = self._run("lcp", parts)
        out = concat_lcp_results(results)
        out.workers, out.wall_seconds = workers, wall  # type: ignore[attr-defined]
        return out

    def solve_scenes(self, bodies: Union[Sequence[Mapping[str, Any]], Mapping[str, Any]],
                     contacts: Union[Sequence[Mapping[str, Any]], Mapping[str, Any]],
                     *, shards: Optional[int] = None) -> ScenesResult:
        """A batch of scenes (two lists of dicts, as :meth:`Solver.solve_scenes`),
        cut into ``shards`` consecutive parts solved on the workers (the
        result is in the batch form: lists, one entry per scene)."""
        bodies = [bodies] if isinstance(bodies, Mapping) else list(bodies)
        contacts = [contacts] if isinstance(contacts, Mapping) else list(contacts)
        if len(bodies) != len(contacts):
            raise ValueError(f"contacts: {len(contacts)} scenes of contacts for {len(bodies)} scenes of bodies")
        bounds = _bounds(len(bodies), shards or 2 * self._workers())
        parts = [(list(bodies[a:b]), list(contacts[a:b])) for a, b in bounds]
        results, workers, wall = self._run("scenes", parts)
        out = concat_scenes_results(results)
        out.workers, out.wall_seconds = workers, wall  # type: ignore[attr-defined]
        return out

    def step_worlds(self, worlds: Union[World, Sequence[World]], dt: float, steps: int = 1,
                    *, shards: Optional[int] = None) -> StepResult:
        """Steps a batch of worlds (as :meth:`Solver.step_worlds`), cut into
        ``shards`` consecutive parts each stepped ``steps`` times on a
        worker. The caller's worlds are updated in place; on the CPU each
        world's trajectory is the one a single process gives, bit for bit."""
        ws = [worlds] if isinstance(worlds, World) else list(worlds)
        for i, w in enumerate(ws):
            if not isinstance(w, World):
                raise TypeError(f"worlds[{i}]: expected an lcpbatch.World, got {type(w).__name__}")
        if not ws:
            return Solver(**self.settings).step_worlds(ws, dt, steps)
        bounds = _bounds(len(ws), shards or 2 * self._workers())
        results, workers, wall = self._run("worlds", [(ws[a:b], dt, steps) for a, b in bounds])
        stepped = [w for r in results for w in r.worlds]
        for mine, theirs in zip(ws, stepped):
            mine._w = theirs._w
        out = concat_step_results(results, ws)
        out.workers, out.wall_seconds = workers, wall  # type: ignore[attr-defined]
        return out

    def _workers(self) -> int:
        return max(1, len(self.client.scheduler_info().get("workers", {})))

    def close(self) -> None:
        """Removes the solvers from the workers."""
        self.client.unregister_worker_plugin(self.name)


_SOLVERS: Dict[Tuple[int, str], DistributedSolver] = {}


def _cached(client: Client, settings: Dict[str, Any]) -> DistributedSolver:
    key = (id(client), json.dumps(settings, sort_keys=True))
    if key not in _SOLVERS:
        _SOLVERS[key] = DistributedSolver(client, **settings)
    return _SOLVERS[key]


def solve(client: Client, M: Any, q: Any, ids: Any = None, *, shards: Optional[int] = None,
          **settings: Any) -> LcpResult:
    """:meth:`DistributedSolver.solve` with a solver per worker kept for
    later calls with the same client and settings."""
    return _cached(client, settings).solve(M, q, ids, shards=shards)


def solve_scenes(client: Client, bodies: Union[Sequence[Mapping[str, Any]], Mapping[str, Any]],
                 contacts: Union[Sequence[Mapping[str, Any]], Mapping[str, Any]], *,
                 shards: Optional[int] = None, **settings: Any) -> ScenesResult:
    """:meth:`DistributedSolver.solve_scenes` with a solver per worker kept
    for later calls with the same client and settings."""
    return _cached(client, settings).solve_scenes(bodies, contacts, shards=shards)


def simulate(client: Client, worlds: Union[World, Sequence[World]], dt: float, steps: int = 1, *,
             shards: Optional[int] = None, **settings: Any) -> StepResult:
    """:meth:`DistributedSolver.step_worlds` with a solver per worker kept
    for later calls with the same client and settings."""
    return _cached(client, settings).step_worlds(worlds, dt, steps, shards=shards)
