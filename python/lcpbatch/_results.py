"""What a solve returns: :class:`Status`, :class:`Report`, :class:`LcpResult`
and :class:`ScenesResult`. Plain Python objects holding NumPy arrays, so they
pickle (for :mod:`lcpbatch.distributed`) and print readably."""

from __future__ import annotations

import enum
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _native

__all__ = ["Status", "Report", "LcpResult", "ScenesResult", "PATH_NAMES"]


def fill_doc(obj: Any, **parts: str) -> None:
    """Puts each part in ``obj``'s docstring in place of its line
    ``<name>``, so that one text (the settings, a result's fields) is
    written once and shown by ``help()`` of every function that has it."""
    for name, text in parts.items():
        marker = f"    <{name}>\n"
        if marker not in (obj.__doc__ or ""):
            raise AssertionError(f"{obj.__qualname__}: no <{name}> in its docstring")
        obj.__doc__ = obj.__doc__.replace(marker, text.rstrip("\n") + "\n")


class Status(enum.IntEnum):
    """What a solve found for one problem (the codes of ``result.status``).

    ``result.status`` is an ``int8`` array of these codes, so NumPy
    comparisons work directly:

    >>> import numpy as np, lcpbatch
    >>> r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))
    >>> bool((r.status == lcpbatch.Status.SOLVED).all())
    True
    >>> lcpbatch.Status(int(r.status[0])).name
    'SOLVED'
    """

    #: A solution was found (unique when every basis was visited).
    SOLVED = 0
    #: Exhaustive enumeration (``all_solutions=True``) found several.
    MULTIPLE_SOLUTIONS = 1
    #: Every complementary basis was visited and none is feasible.
    NO_SOLUTION = 2
    #: Lemke ended on a secondary ray (no solution for copositive-plus M).
    RAY_TERMINATION = 3
    #: PGS or Lemke's pivot cap stopped before the tolerance; z is the last iterate.
    NOT_CONVERGED = 4
    #: The problem could not be posed (e.g. PGS with a zero diagonal entry).
    INVALID_INPUT = 5
    #: z, w or the error is not finite, or the error is above ``tolerance``.
    NUMERICAL_FAILURE = 6

    @property
    def is_solution(self) -> bool:
        """True for ``SOLVED`` and ``MULTIPLE_SOLUTIONS``."""
        return self in (Status.SOLVED, Status.MULTIPLE_SOLUTIONS)


# The Rust side numbers statuses in this order; a mismatch is a build error.
if [s.name.lower() for s in Status] != list(_native.status_names()):  # pragma: no cover
    raise ImportError("lcpbatch: Status codes differ from the extension's; rebuild it")

#: Names of the solve paths, indexed by the codes the extension returns.
PATH_NAMES: List[str] = list(_native.path_names())
_PATHS = np.array(PATH_NAMES)

#: The fields of :class:`LcpResult` (in its docstring and ``solve``'s).
LCP_FIELDS_DOC = """\
    Attributes (B problems; for a ragged batch, a list of B arrays where the
    dense form has a (B, n) array):

    - ``z``, ``w``: (B, n) float64, with w = M z + q recomputed in f64;
    - ``status``: (B,) int8 codes of :class:`Status` (SOLVED,
      MULTIPLE_SOLUTIONS, NO_SOLUTION, RAY_TERMINATION, NOT_CONVERGED,
      INVALID_INPUT, NUMERICAL_FAILURE); ``status_names()``: the same as
      (B,) str ("solved", …); ``ok``: (B,) bool, a solution;
    - ``error``: (B,) float64, the Siconos measure ‖z − max(0, z − w)‖ / ‖q‖;
    - ``basis``: (B, n) bool, z_i basic; ``has_basis``: (B,) bool, whether the
      solver reported a basis (PGS does not: its rows are all False);
    - ``pivots`` (Lemke), ``iterations`` (PGS sweeps), ``bases_visited``
      (enumeration): (B,) uint64;
    - ``path``: (B,) str, how each problem was settled, one of
      ``PATH_NAMES``: "separating", "single_contact", "warm_start",
      "predicted_basis", "enumerated_gpu", "lemke_gpu", "repaired",
      "enumerated_cpu", "lemke", "pgs", "invalid" (see :class:`Report`'s ``counts``);
    - ``solution_count``: (B,) int64, distinct solutions with
      ``all_solutions=True`` (−1 where unknown); ``solution_set``: list of
      "empty", "isolated", "bounded_continuum", "unbounded_continuum" or None;
    - ``all_z``, ``all_basis``: with ``all_solutions=True``, per problem a
      (k, n) array of the z (and the basis) of every valid complementary
      basis found; None otherwise;
    - ``ragged``: whether the batch was a list of problems of different sizes;
    - ``report``: :class:`Report`, the batch's figures (``help(lcpbatch.Report)``).
"""


class Report:
    """Batch figures of one call: where it ran and why, islands per path,
    per status, the largest error, seconds per phase and any GPU fallback.

    ``print(report)`` gives the library's summary (``text``); every figure
    is also an attribute:

    - ``device``: the device in words (adapter, wgpu backend, precision);
      ``device_kind``: "cpu", "hardware_gpu" or "software_gpu";
      ``precision``: "f64" or "f32" (the GPU shaders'; "f64" on the CPU);
    - ``choice``: why this device (the backend asked for; with
      backend "auto" and a GPU open, the cost model's CPU and GPU
      estimates); ``fallback``: why the CPU took over from the GPU (None:
      no device trouble);
    - ``counts``: islands per path: "separating" (q ≥ 0, no impulse),
      "single_contact" (closed form), "warm_start" (last call's basis),
      "predicted_basis" (the approaching contacts' basis, M positive
      definite), "enumerated_gpu" (enumerated on the GPU, confirmed in f64),
      "lemke_gpu" (Lemke's path on the GPU, its basis checked in f64: method
      "auto" or "lemke" on the GPU),
      "accepted" (GPU answers whose own z passed the f64 check),
      "polished" (GPU answers whose basis, re-solved in f64, held), "repaired" (GPU
      answers re-solved on the CPU), "enumerated_cpu", "lemke",
      "cpu_fallback" (handed by the GPU to Lemke on the CPU: n > 16, or
      the GPU's Lemke kernel could not settle them),
      "pgs", "invalid" (failed their checks);
    - ``statuses``: islands per :class:`Status` name ("solved", …);
    - ``max_error``, ``max_error_index``: the largest error measure over
      the islands with a solution, and which island (None: none);
    - ``timings``: seconds: "build" (checks, islands, assembly),
      "prediction", "gpu" (upload, dispatch, readback), "validation"
      (checking the GPU's answers in f64), "solve" (CPU solves), "impulses"
      (velocities after the impulses), "total" (the whole call);
    - ``gpu``: None on the CPU, else "chunks" (parts under the device's
      limits), "dispatches", "rounds" (enumeration rounds),
      "tree_decided", "tree_undecided" (islands the tree kernel decided or
      left to elimination), "max_gpu_error" (the GPU's own error before
      the f64 polish), "max_velocity_deviation" (scenes: the GPU's impulse
      stage against its f64 twin), and the seconds of the "gpu" timing's
      parts as the host sees them: "pack_seconds" (planning the chunks:
      sorting by size, the tree kernel's routes), "upload_seconds" (writing
      M and q into the device's buffers), "kernel_seconds" (submission to
      the end of the last round, waits included), "readback_seconds"
      (reading the answers back), "check_seconds" (the f64 check of the
      GPU's answers), "repair_seconds" (answers the check rejected, solved
      again on the CPU), "report_seconds" (the batch's report),
      "overlapped_seconds" (host seconds spent while a part was on the
      device), "kernel_device_seconds" (the kernels as GPU timestamps
      measure them; None where the adapter has no TIMESTAMP_QUERY);
    - ``chunks``: parts the call was solved in (Ctrl-C is seen between them);
    - ``friction_islands``: frictional islands (or problems of
      ``solve_friction``); ``friction_statuses``: their statuses;
      ``max_coulomb_error``, ``max_coulomb_error_index``: the largest
      Coulomb error over the solved ones and which (None: none);
    - ``text``: the summary ``print`` shows; ``to_dict()``: all of it.

    >>> import numpy as np, lcpbatch
    >>> r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]), backend="cpu")
    >>> r.report.statuses["solved"], r.report.device_kind, r.report.fallback
    (1, 'cpu', None)
    >>> "islands" in str(r.report)
    True
    """

    #: The attributes, in the order of ``repr``.
    FIELDS = (
        "device", "device_kind", "precision", "choice", "fallback", "counts",
        "statuses", "max_error", "max_error_index", "timings", "gpu", "chunks",
        "friction_islands", "friction_statuses", "max_coulomb_error", "max_coulomb_error_index",
    )

    def __init__(self, d: Dict[str, Any]):
        self.text: str = d["text"]
        self.device: str = d["device"]
        self.device_kind: str = d["device_kind"]
        self.precision: str = d["precision"]
        self.choice: str = d["choice"]
        self.fallback: Optional[str] = d["fallback"]
        self.counts: Dict[str, int] = dict(d["counts"])
        self.statuses: Dict[str, int] = dict(d["statuses"])
        self.max_error: Optional[float] = d["max_error"]
        self.max_error_index: Optional[int] = d["max_error_index"]
        self.timings: Dict[str, float] = dict(d["timings"])
        self.gpu: Optional[Dict[str, float]] = d["gpu"]
        self.chunks: int = d["chunks"]
        #: Frictional islands (or problems of ``solve_friction``), their
        #: statuses, and the largest Coulomb error over the solved ones with
        #: its index (None when there is none).
        self.friction_islands: int = d.get("friction_islands", 0)
        self.friction_statuses: Dict[str, int] = dict(d.get("friction_statuses") or {})
        self.max_coulomb_error: Optional[float] = d.get("max_coulomb_error")
        self.max_coulomb_error_index: Optional[int] = d.get("max_coulomb_error_index")

    def to_dict(self) -> Dict[str, Any]:
        """The figures as a plain dict (JSON-friendly)."""
        d = {k: getattr(self, k) for k in self.FIELDS}
        d["text"] = self.text
        return d

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        body = "\n  ".join(self.text.splitlines())
        return f"<lcpbatch.Report\n  {body}>"


def _split(flat: np.ndarray, offsets: np.ndarray) -> List[np.ndarray]:
    """Views of ``flat`` between consecutive offsets."""
    return [flat[offsets[i]: offsets[i + 1]] for i in range(len(offsets) - 1)]


class LcpResult:
    """The answers of an LCP batch, one row per problem.

    <fields>

    >>> import numpy as np, lcpbatch
    >>> r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))
    >>> np.round(r.z * 3, 12).tolist(), r.basis.tolist()
    ([[4.0, 7.0]], [[True, True]])
    """

    def __init__(self, d: Dict[str, Any], ragged: bool, n: Optional[int]):
        offsets = d["offsets"]
        self.ragged = ragged
        if ragged:
            self.z: Union[np.ndarray, List[np.ndarray]] = _split(d["z"], offsets)
            self.w: Union[np.ndarray, List[np.ndarray]] = _split(d["w"], offsets)
            self.basis: Union[np.ndarray, List[np.ndarray]] = _split(d["basis"], offsets)
        else:
            shape = (len(offsets) - 1, n or 0)
            self.z = d["z"].reshape(shape)
            self.w = d["w"].reshape(shape)
            self.basis = d["basis"].reshape(shape)
        self.status: np.ndarray = d["status"]
        self.error: np.ndarray = d["error"]
        self.has_basis: np.ndarray = d["has_basis"]
        self.pivots: np.ndarray = d["pivots"]
        self.iterations: np.ndarray = d["iterations"]
        self.bases_visited: np.ndarray = d["bases_visited"]
        self.path: np.ndarray = _PATHS[d["path"]] if len(d["path"]) else np.array([], dtype=str)
        self.solution_count: np.ndarray = d["solution_count"]
        self.solution_set: List[Optional[str]] = list(d["solution_set"])
        found = d.get("all_bases")
        self.all_z: Optional[List[np.ndarray]] = None if found is None else [z for z, _ in found]
        self.all_basis: Optional[List[np.ndarray]] = None if found is None else [b for _, b in found]
        self.report = Report(d["report"])

    @property
    def ok(self) -> np.ndarray:
        """(B,) bool: the status is SOLVED or MULTIPLE_SOLUTIONS.

        >>> import numpy as np, lcpbatch
        >>> M = np.array([[[1.0]], [[-1.0]]])         # the second has no solution
        >>> lcpbatch.solve(M, np.array([[-1.0], [-1.0]]), method="enum").ok.tolist()
        [True, False]
        """
        return self.status <= Status.MULTIPLE_SOLUTIONS

    def status_names(self) -> np.ndarray:
        """(B,) str: the status of each problem by name ("solved", …).

        >>> import numpy as np, lcpbatch
        >>> M = np.array([[[1.0]], [[-1.0]]])
        >>> lcpbatch.solve(M, np.array([[-1.0], [-1.0]]), method="enum").status_names().tolist()
        ['solved', 'no_solution']
        """
        names = np.array([s.name.lower() for s in Status])
        return names[self.status] if len(self.status) else np.array([], dtype=str)

    def __len__(self) -> int:
        return len(self.status)

    def __repr__(self) -> str:
        counts = ", ".join(f"{k} {v}" for k, v in self.report.statuses.items() if v)
        err = self.report.max_error
        kind = "ragged" if self.ragged else "dense"
        return (
            f"<lcpbatch.LcpResult: {len(self)} problems ({kind}); {counts or 'none'}; "
            f"max error {'none' if err is None else f'{err:.3e}'}; on {self.report.device}>"
        )


class ScenesResult:
    """The answers of a batch of scenes.

    <fields>

    >>> import numpy as np, lcpbatch
    >>> bodies = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]],
    ...               position=[[0, 0.5, 0]], velocity=[[0, -1.0, 0]])
    >>> contacts = dict(a=[0], b=[-1], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=[0.5])
    >>> r = lcpbatch.solve_scenes(bodies, contacts)
    >>> float(r.impulses[0]), float(r.velocity[0, 1])
    (1.5, 0.5)
    """

    def __init__(self, d: Dict[str, Any], single: bool):
        impulses = _split(d["impulses"], d["contact_offsets"])
        velocity = _split(d["velocity"], d["body_offsets"])
        angular = _split(d["angular_velocity"], d["body_offsets"])
        self.single = single
        impulse = _split(d["impulse"], d["contact_offsets"])
        tangential = _split(d["tangential"], d["contact_offsets"])
        if single:
            self.impulse: Union[np.ndarray, List[np.ndarray]] = impulse[0]
            self.tangential: Union[np.ndarray, List[np.ndarray]] = tangential[0]
            self.impulses: Union[np.ndarray, List[np.ndarray]] = impulses[0]
            self.velocity: Union[np.ndarray, List[np.ndarray]] = velocity[0]
            self.angular_velocity: Union[np.ndarray, List[np.ndarray]] = angular[0]
        else:
            self.impulses, self.velocity, self.angular_velocity = impulses, velocity, angular
            self.impulse, self.tangential = impulse, tangential
        islands = LcpResult(d, ragged=True, n=None)
        self.island_scene: np.ndarray = d["island_scene"]
        self.island_contacts: List[np.ndarray] = _split(d["island_contacts"], d["offsets"])
        self.status = islands.status
        self.error = islands.error
        self.path = islands.path
        self.z: Union[np.ndarray, List[np.ndarray]] = islands.z
        self.w: Union[np.ndarray, List[np.ndarray]] = islands.w
        self.report = islands.report
        self.friction_scene: np.ndarray = d["friction_scene"]
        self.friction_contacts: List[np.ndarray] = _split(d["friction_contacts"], d["friction_offsets"])
        self.friction_status: np.ndarray = d["friction_status"]
        self.friction_error: np.ndarray = d["friction_error"]
        self.friction_cone_error: np.ndarray = d["friction_cone_error"]
        self.friction_iterations: np.ndarray = d["friction_iterations"]
        scenes = len(d["contact_offsets"]) - 1
        bad = np.concatenate([self.island_scene[~islands.ok],
                              self.friction_scene[self.friction_status > Status.MULTIPLE_SOLUTIONS]])
        self.scene_ok: np.ndarray = ~np.isin(np.arange(scenes), bad)

    def __repr__(self) -> str:
        counts = ", ".join(f"{k} {v}" for k, v in self.report.statuses.items() if v)
        friction = f", {len(self.friction_status)} frictional" if len(self.friction_status) else ""
        return (
            f"<lcpbatch.ScenesResult: {len(self.scene_ok)} scene(s), {len(self.status)} "
            f"island(s){friction}; {counts or 'none'}; on {self.report.device}>"
        )


#: The fields of :class:`ScenesResult` (in its docstring and ``solve_scenes``').
SCENES_FIELDS_DOC = """\
    For one scene (``solve_scenes(bodies=dict, contacts=dict)``; ``single``
    is True) per contact and body of the scene, for a batch (lists of
    dicts) lists of those, one per scene:

    - ``impulses``: (C,) the normal impulse of each contact;
    - ``impulse``: (C, 3) each contact's impulse vector on body a in the
      world frame (normal plus tangential part; z n without friction);
    - ``tangential``: (C, 2) its tangential parts (r_t1, r_t2) in the
      contact's frame (t1, t2 = n × t1; zero without friction);
    - ``velocity``, ``angular_velocity``: (N, 3) the bodies' velocities
      after the impulses.

    Per frictionless island, all scenes in order (I islands):
    ``island_scene`` (I,) its scene; ``island_contacts`` (list) the scene's
    contact indices in the order of the island's LCP rows; ``status`` (I,)
    :class:`Status` codes; ``error`` (I,); ``path`` (I,) str (as in
    :class:`LcpResult`); ``z``, ``w`` (lists).

    Per frictional island (one with any μ > 0; F islands, not in the
    arrays above): ``friction_scene`` (F,); ``friction_contacts`` (list);
    ``friction_status`` (F,) :class:`Status` codes; ``friction_error`` (F,)
    the Coulomb error (Siconos' fc3d error with De Saxcé's correction);
    ``friction_cone_error`` (F,) the cone complementarity residual;
    ``friction_iterations`` (F,).

    ``scene_ok``: (S,) bool, every island of the scene (the frictional ones
    included) has a solution. ``report``: :class:`Report`, the batch's
    figures (``help(lcpbatch.Report)``).
"""

fill_doc(LcpResult, fields=LCP_FIELDS_DOC)
fill_doc(ScenesResult, fields=SCENES_FIELDS_DOC)


def merge_reports(reports: Sequence[Report]) -> Report:
    """One report for consecutive parts of a batch (shards solved apart):
    counts, statuses, timings and chunks summed, the largest error with its
    index in the whole batch, the devices and fallbacks of every part."""

    def total(key: str) -> Dict[str, Any]:
        out: Dict[str, Any] = {}
        for r in reports:
            for k, v in getattr(r, key).items():
                out[k] = out.get(k, 0) + v
        return out

    islands = [sum(r.statuses.values()) for r in reports]
    starts = np.concatenate([[0], np.cumsum(islands)[:-1]]).astype(int)
    worst = [(r.max_error, int(s) + r.max_error_index) for r, s in zip(reports, starts)
             if r.max_error is not None and r.max_error_index is not None]
    max_error, max_index = max(worst, key=lambda e: (np.isnan(e[0]), e[0])) if worst else (None, None)
    fstarts = np.cumsum([0] + [r.friction_islands for r in reports[:-1]]).astype(int)
    fworst = [(r.max_coulomb_error, int(s) + r.max_coulomb_error_index) for r, s in zip(reports, fstarts)
              if r.max_coulomb_error is not None and r.max_coulomb_error_index is not None]
    max_coulomb, coulomb_index = (max(fworst, key=lambda e: (np.isnan(e[0]), e[0]))
                                  if fworst else (None, None))
    devices = sorted({r.device for r in reports})
    fallbacks = sorted({r.fallback for r in reports if r.fallback})
    gpus = [r.gpu for r in reports if r.gpu]
    d: Dict[str, Any] = dict(
        device="; ".join(devices), device_kind=reports[0].device_kind if reports else "cpu",
        precision=reports[0].precision if reports else "f64",
        choice="; ".join(sorted({r.choice for r in reports})),
        fallback="; ".join(fallbacks) or None, counts=total("counts"), statuses=total("statuses"),
        max_error=max_error, max_error_index=max_index, timings=total("timings"),
        gpu={k: (max if k.startswith("max_") else sum)(g[k] for g in gpus) for k in gpus[0]}
        if gpus
        else None,
        chunks=sum(r.chunks for r in reports),
        friction_islands=sum(r.friction_islands for r in reports),
        friction_statuses=total("friction_statuses"), max_coulomb_error=max_coulomb,
        max_coulomb_error_index=coulomb_index,
    )
    paths = ", ".join(f"{k} {v}" for k, v in d["counts"].items() if v)
    statuses = ", ".join(f"{k} {v}" for k, v in d["statuses"].items() if v)
    err = "none" if max_error is None else f"{max_error:.3e} (island {max_index})"
    t = d["timings"]
    d["text"] = "\n".join([
        f"device: {d['device']} ({len(reports)} part(s))",
        *([f"GPU trouble, solved on the CPU: {d['fallback']}"] if d["fallback"] else []),
        f"{sum(islands)} islands: {paths}",
        f"statuses: {statuses}",
        f"max error: {err}",
        *([f"{d['friction_islands']} frictional islands, max Coulomb error {max_coulomb:.3e} "
           f"(island {coulomb_index})"] if max_coulomb is not None else []),
        f"time (summed over parts): total {t.get('total', 0):.3f} s (solve {t.get('solve', 0):.3f}, "
        f"gpu {t.get('gpu', 0):.3f}, validation {t.get('validation', 0):.3f})",
    ])
    return Report(d)


def _concat(parts: Sequence[Any], attr: str) -> Any:
    values = [getattr(p, attr) for p in parts]
    if isinstance(values[0], list):
        return [v for vs in values for v in vs]
    return np.concatenate(values)


def concat_lcp_results(parts: Sequence[LcpResult]) -> LcpResult:
    """The result of a batch solved in consecutive parts (all dense or all ragged)."""
    out = object.__new__(LcpResult)
    out.ragged = parts[0].ragged
    for attr in ("z", "w", "basis", "status", "error", "has_basis", "pivots", "iterations",
                 "bases_visited", "path", "solution_count", "solution_set"):
        setattr(out, attr, _concat(parts, attr))
    for attr in ("all_z", "all_basis"):
        values = [getattr(p, attr) for p in parts]
        setattr(out, attr, None if any(v is None for v in values) else [x for v in values for x in v])
    out.report = merge_reports([p.report for p in parts])
    return out


def concat_scenes_results(parts: Sequence[ScenesResult]) -> ScenesResult:
    """The result of a batch of scenes solved in consecutive parts (lists)."""
    out = object.__new__(ScenesResult)
    out.single = False
    for attr in ("impulses", "impulse", "tangential", "velocity", "angular_velocity",
                 "island_contacts", "status", "error", "path", "z", "w", "scene_ok",
                 "friction_contacts", "friction_status", "friction_error", "friction_cone_error",
                 "friction_iterations"):
        setattr(out, attr, _concat(parts, attr))
    starts = np.cumsum([0] + [len(p.scene_ok) for p in parts[:-1]])
    out.island_scene = np.concatenate([p.island_scene + s for p, s in zip(parts, starts)])
    out.friction_scene = np.concatenate([p.friction_scene + s for p, s in zip(parts, starts)])
    out.report = merge_reports([p.report for p in parts])
    return out
