"""Frictional contact problems (Siconos' FrictionContact3D form) as arrays:
the checks of ``solve_friction``'s arguments and :class:`FrictionResult`.

One problem of k contacts: W (3k, 3k), q (3k), μ (k), with contact i owning
entries 3i (normal) and 3i + 1, 3i + 2 (tangents), interleaved as in
Siconos' fc3d files. Find r (the reactions) with u = W r + q and, per
contact, Coulomb's law: r in the cone ‖r_T‖ ≤ μ r_N, and either sticking
(u_T = 0) or sliding (r_T opposite u_T on the cone's boundary), with the
normal part complementary to u_N + μ‖u_T‖ (De Saxcé's correction)."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from ._inputs import id_array, ragged_ids, real_array
from ._results import Report, Status, _split, fill_doc

__all__ = ["FrictionResult", "FRICTION_FIELDS_DOC", "dense", "ragged"]

#: The fields of :class:`FrictionResult` (in its docstring and ``solve_friction``'s).
FRICTION_FIELDS_DOC = """\
    - ``r``, ``u``: (B, 3k) float64 (lists for a ragged batch): reactions and
      velocities u = W r + q, interleaved per contact (normal, t1, t2);
    - ``status``: (B,) int8 :class:`Status` codes (``SOLVED`` when the
      Coulomb error, or for "jacobi", "pgs", "apgd" the cone error, is at
      most ``friction_tolerance``; ``NOT_CONVERGED`` at the iteration cap;
      ``NUMERICAL_FAILURE``); ``status_names()``: the same as str;
      ``ok``: (B,) bool, solved;
    - ``coulomb_error`` (also ``error``): (B,) Siconos' fc3d error with De
      Saxcé's correction, normalised by max(‖q‖, ‖r‖, ‖u‖);
      ``cone_error``: (B,) the residual ‖r − P_K(r − u)‖ of the convex
      cone complementarity problem;
    - ``iterations``: (B,) NSGS sweeps plus Newton steps (the projected
      methods: their iterations); ``warm_started``: (B,) bool, started from
      the reactions remembered by contact id;
    - ``ragged``: whether the batch was lists of problems of different k;
    - ``report``: :class:`Report` (``friction_statuses``,
      ``max_coulomb_error``; ``help(lcpbatch.Report)``).
"""


def _mu_rows(mu: Any, b: int, k: int) -> np.ndarray:
    """mu as (B, k) float64: a (B, k) array, or a scalar for every contact."""
    m = real_array(mu, "mu")
    if m.ndim == 0:
        m = np.full((b, k), float(m))
    if m.shape != (b, k):
        raise ValueError(f"mu: expected shape {(b, k)} (one coefficient per contact) or a scalar, "
                         f"got {m.shape}")
    return m


def dense(W: Any, q: Any, mu: Any, ids: Any) -> Tuple[np.ndarray, np.ndarray, np.ndarray, Optional[np.ndarray]]:
    """W (B, 3k, 3k), q (B, 3k), mu (B, k) or a scalar, ids (B, k) or None."""
    try:
        w = real_array(W, "W")
    except ValueError as e:  # nested lists of different lengths
        raise ValueError(f"W: not a (B, 3k, 3k) array ({e}); for problems of different sizes "
                         "give lists of NumPy arrays") from None
    if w.ndim != 3 or w.shape[1] != w.shape[2]:
        hint = " (for one problem pass W[None], q[None], mu[None])" if w.ndim == 2 else ""
        raise ValueError(f"W: expected shape (B, 3k, 3k), got {w.shape}{hint}")
    b, n = w.shape[0], w.shape[1]
    if n % 3 or (n == 0 and b > 0):
        raise ValueError(f"W: its size {n} is not 3k for k ≥ 1 contacts (3 rows per contact)")
    qa = real_array(q, "q")
    if qa.shape != (b, n):
        raise ValueError(f"q: expected shape {(b, n)} to match W {w.shape}, got {qa.shape}")
    m = _mu_rows(mu, b, n // 3)
    idsa = None
    if ids is not None:
        idsa = id_array(ids, "ids")
        if idsa.shape != (b, n // 3):
            raise ValueError(f"ids: expected shape {(b, n // 3)} (one id per contact), got {idsa.shape}")
    return w, qa, m, idsa


def _scalar(v: Any) -> bool:
    """A number (one μ for every contact), not a list of arrays."""
    return isinstance(v, (int, float, np.number)) or (isinstance(v, np.ndarray) and v.ndim == 0)


def ragged(W: Sequence[Any], q: Any, mu: Any, ids: Any) -> Tuple[List[np.ndarray], ...]:
    """Lists of (3kᵢ, 3kᵢ), (3kᵢ,) and (kᵢ,) arrays (mu may be a scalar), ids a list or None."""
    for name, v in (("q", q), ("mu", mu)):
        if name == "mu" and _scalar(mu):
            continue
        if not isinstance(v, (list, tuple)) or len(v) != len(W):
            raise ValueError(f"{name}: W is a list of {len(W)} problems, so {name} must be a list of as many")
    ws, qs, ms = [], [], []
    for i, wi in enumerate(W):
        w = real_array(wi, f"W[{i}]")
        n = w.shape[0] if w.ndim == 2 else -1
        if w.ndim != 2 or w.shape[0] != w.shape[1] or n == 0 or n % 3:
            raise ValueError(f"W[{i}]: expected a square (3k, 3k) array with k ≥ 1, got shape {w.shape}")
        qa = real_array(q[i], f"q[{i}]")
        if qa.shape != (n,):
            raise ValueError(f"q[{i}]: expected shape {(n,)} to match W[{i}] {w.shape}, got {qa.shape}")
        m = real_array(mu if _scalar(mu) else mu[i], f"mu[{i}]")
        m = np.full(n // 3, float(m)) if m.ndim == 0 else m
        if m.shape != (n // 3,):
            raise ValueError(f"mu[{i}]: expected shape {(n // 3,)} (one per contact), got {m.shape}")
        ws.append(w)
        qs.append(qa)
        ms.append(m)
    return ws, qs, ms, ragged_ids(ids, [m.shape for m in ms], " (one per contact)")


class FrictionResult:
    """The answers of a batch of frictional problems, one row per problem.

    <fields>

    >>> import numpy as np, lcpbatch
    >>> W = np.eye(3)[None]; q = np.array([[-1.0, 3.0, 0.0]]); mu = np.array([[0.5]])
    >>> r = lcpbatch.solve_friction(W, q, mu)          # slides: r_T on the cone
    >>> (r.r.round(6) + 0.0).tolist(), r.status_names().tolist()
    ([[1.0, -0.5, 0.0]], ['solved'])
    """

    def __init__(self, d: Dict[str, Any], ragged: bool, n: Optional[int]):
        offsets = d["offsets"]
        self.ragged = ragged
        if ragged:
            self.r: Union[np.ndarray, List[np.ndarray]] = _split(d["r"], offsets)
            self.u: Union[np.ndarray, List[np.ndarray]] = _split(d["u"], offsets)
        else:
            shape = (len(offsets) - 1, n or 0)
            self.r = d["r"].reshape(shape)
            self.u = d["u"].reshape(shape)
        self.status: np.ndarray = d["status"]
        self.coulomb_error: np.ndarray = d["coulomb_error"]
        self.cone_error: np.ndarray = d["cone_error"]
        self.iterations: np.ndarray = d["iterations"]
        self.warm_started: np.ndarray = d["warm_started"]
        self.report = Report(d["report"])

    @property
    def error(self) -> np.ndarray:
        """(B,): the Coulomb error (``coulomb_error``), the measure ``status`` is judged by."""
        return self.coulomb_error

    @property
    def ok(self) -> np.ndarray:
        """(B,) bool: the status is a solution."""
        return self.status <= Status.MULTIPLE_SOLUTIONS

    def status_names(self) -> np.ndarray:
        """(B,) str: each problem's status by name."""
        names = np.array([s.name.lower() for s in Status])
        return names[self.status] if len(self.status) else np.array([], dtype=str)

    def __len__(self) -> int:
        return len(self.status)

    def __repr__(self) -> str:
        counts = ", ".join(f"{k} {v}" for k, v in self.report.friction_statuses.items() if v)
        err = self.report.max_coulomb_error
        return (
            f"<lcpbatch.FrictionResult: {len(self)} problems; {counts or 'none'}; max Coulomb error "
            f"{'none' if err is None else f'{err:.3e}'}; on {self.report.device}>"
        )


fill_doc(FrictionResult, fields=FRICTION_FIELDS_DOC)
