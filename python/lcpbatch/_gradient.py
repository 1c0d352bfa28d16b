"""Gradients of the exact LCP solve in NumPy: :func:`lcp_vjp` (the library's
vector–Jacobian product, ``lcpbatch::gradient::lcp_vjp_batch``) and the two
host functions :mod:`lcpbatch.jax` and :mod:`lcpbatch.torch` call, the
solve (:func:`forward`) and its VJP (:func:`backward`), on batches with any
leading dimensions (``M`` (..., n, n), ``q`` (..., n)).

Nothing here imports JAX or PyTorch."""

from __future__ import annotations

import importlib
import types
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _inputs, _native

__all__ = ["LcpGradient", "lcp_vjp", "DERIVATIVE_NAMES", "DEFAULT_VJP_TOLERANCE"]

#: Names of the per-island derivative kinds, indexed by the extension's codes.
DERIVATIVE_NAMES = list(_native.derivative_names())
_DERIVATIVES = np.array(DERIVATIVE_NAMES)

#: The default ``tolerance`` of :func:`lcp_vjp` (the solver's default
#: ``tolerance``): relative to the island's scale, τ_w = t · max(‖q‖∞,
#: max|M| ‖z‖∞) and τ_z = τ_w / max|M|; a contact with z_i ≤ τ_z and
#: w_i ≤ τ_w is weakly active.
DEFAULT_VJP_TOLERANCE: float = _native.DEFAULT_VJP_TOLERANCE


class LcpGradient:
    """∂L/∂M and ∂L/∂q of a batch, and how far to trust each island's.

    - ``M``: (B, n, n) float64, ∂L/∂M;
    - ``q``: (B, n) float64, ∂L/∂q;
    - ``derivative``: (B,) str, per island "exact" (every contact strictly
      active, z_i > 0, or strictly inactive, w_i > 0, and M_αα nonsingular:
      the solution map is differentiable there), "one_sided" (a weakly
      active contact, z_i = w_i = 0 within the tolerance's scale, is treated
      as inactive: the derivative along perturbations that keep it off) or
      "undefined" (M_αα singular, so z_α is not locally unique, or z is not
      a solution within the tolerance): then both gradients are zero.
    """

    def __init__(self, dm: np.ndarray, dq: np.ndarray, codes: np.ndarray):
        self.M: np.ndarray = dm
        self.q: np.ndarray = dq
        self.derivative: np.ndarray = _DERIVATIVES[codes] if len(codes) else np.array([], dtype=str)

    def __repr__(self) -> str:
        kinds, counts = np.unique(self.derivative, return_counts=True)
        summary = ", ".join(f"{k} {c}" for k, c in zip(kinds, counts)) or "none"
        return f"<lcpbatch.LcpGradient: {len(self.q)} islands; {summary}>"


def _f64(value: Any, name: str, shape: Tuple[int, ...]) -> np.ndarray:
    a = _inputs.real_array(value, name)
    if a.shape != shape:
        raise ValueError(f"{name}: expected shape {shape} to match q, got {a.shape}")
    return a


def lcp_vjp(M: Any, q: Any, z: Any, dz: Any, dw: Optional[Any] = None, *,
            tolerance: Optional[float] = None) -> LcpGradient:
    """The vector–Jacobian product of the solve z(M, q) of a batch of LCPs
    (w = M z + q ≥ 0, z ≥ 0, zᵀw = 0) at its solution ``z``: given ∂L/∂z
    (``dz``) and optionally ∂L/∂w (``dw``), returns ∂L/∂M and ∂L/∂q.

    ``M`` (B, n, n), ``q``, ``z``, ``dz``, ``dw`` (B, n) (float64 or float32,
    computed in f64); ``z`` the solution (``lcpbatch.solve(M, q).z``).
    With α the active set (z_i > 0) and u solving M_ααᵀ u = ∂L/∂z_α:
    ∂L/∂q_α = −u and ∂L/∂M_αβ = −u z_βᵀ; inactive rows carry ∂L/∂w. Runs on
    every core with the GIL released; ``tolerance`` (in [0, 1), default
    ``DEFAULT_VJP_TOLERANCE``, 1e-8) decides weak activity. Returns an
    :class:`LcpGradient` (``M``, ``q``, ``derivative`` per island).

    A bad value (not finite, a wrong shape) raises ``ValueError`` naming the
    argument and the index.

    >>> import numpy as np, lcpbatch
    >>> M, q = np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]])
    >>> z = lcpbatch.solve(M, q).z                 # both active: z = −M⁻¹ q
    >>> g = lcpbatch.lcp_vjp(M, q, z, np.array([[1.0, 0.0]]))
    >>> (g.q * 3).round(12).tolist(), g.derivative.tolist()   # −M⁻ᵀ e₁
    ([[-2.0, 1.0]], ['exact'])
    """
    m, qa, _ = _inputs.dense(M, q, None)
    shape = qa.shape
    za = _f64(z, "z", shape)
    dza = _f64(dz, "dz", shape)
    dwa = None if dw is None else _f64(dw, "dw", shape)
    tol = DEFAULT_VJP_TOLERANCE if tolerance is None else float(tolerance)
    dm, dq, codes = _native.lcp_vjp(m, qa, za, dza, dwa, tol)
    return LcpGradient(dm, dq, codes)


def _flat(M: np.ndarray, q: np.ndarray) -> Tuple[np.ndarray, np.ndarray, Tuple[int, ...]]:
    """(…, n, n) and (…, n) as (B, n, n) and (B, n) (views where possible)."""
    q = np.asarray(q, dtype=np.float64)
    n = q.shape[-1]
    M = np.asarray(M, dtype=np.float64)
    return M.reshape(-1, n, n), q.reshape(-1, n), q.shape


def forward(M: np.ndarray, q: np.ndarray, settings: Dict[str, Any]) -> Tuple[np.ndarray, np.ndarray]:
    """z and w of every problem of M (..., n, n), q (..., n), solved by the
    cached solver of ``settings``; NaN rows where a problem has no solution
    the solver found (its status is not SOLVED or MULTIPLE_SOLUTIONS)."""
    from ._solver import _cached

    m, qa, shape = _flat(M, q)
    r = _cached(**settings).solve(m, qa)
    z, w = r.z, r.w
    bad = ~r.ok
    if bad.any():
        z, w = z.copy(), w.copy()
        z[bad] = np.nan
        w[bad] = np.nan
    return z.reshape(shape), w.reshape(shape)


def backward(M: np.ndarray, q: np.ndarray, z: np.ndarray, dz: np.ndarray, dw: Optional[np.ndarray],
             tolerance: Optional[float]) -> Tuple[np.ndarray, np.ndarray]:
    """∂L/∂M (..., n, n) and ∂L/∂q (..., n) from :func:`lcp_vjp`; NaN for
    the problems :func:`forward` gave NaN (no solution found).

    ``tolerance`` None: ``DEFAULT_VJP_TOLERANCE``, or 100 units in the last
    place of z's dtype where that is more: a float32 z is the solution
    rounded (relative 6e-8), so w = M z + q recomputed from it is off by
    about as much, and 1e-8 would call its active rows not a solution."""
    if tolerance is None:
        tolerance = max(DEFAULT_VJP_TOLERANCE, 100 * float(np.finfo(np.asarray(z).dtype).eps))
    m, qa, shape = _flat(M, q)
    n = shape[-1]
    za = np.asarray(z, dtype=np.float64).reshape(-1, n)
    dza = np.asarray(dz, dtype=np.float64).reshape(-1, n)
    # A zero ∂L/∂w (JAX and PyTorch pass zeros for an unused w) adds nothing.
    dwa = None if dw is None or not np.any(dw) else np.asarray(dw, dtype=np.float64).reshape(-1, n)
    ok = np.isfinite(za).all(axis=1)
    if ok.all():
        g = lcp_vjp(m, qa, za, dza, dwa, tolerance=tolerance)
        dm, dq = g.M, g.q
    else:
        dm = np.full(m.shape, np.nan)
        dq = np.full(qa.shape, np.nan)
        g = lcp_vjp(m[ok], qa[ok], za[ok], dza[ok], None if dwa is None else dwa[ok], tolerance=tolerance)
        dm[ok], dq[ok] = g.M, g.q
    return dm.reshape(shape + (n,)), dq.reshape(shape)


def framework(name: str, label: str, install: str) -> types.ModuleType:
    """The module ``name`` (JAX or PyTorch) for the adapter ``lcpbatch.<name>``;
    ``ImportError`` saying what to install when it is missing."""
    try:
        return importlib.import_module(name)
    except ImportError as e:
        raise ImportError(f"lcpbatch.{name} needs {label}, which is not installed: {install}") from e


def settings_of(vjp_tolerance: Optional[float], settings: Dict[str, Any]) -> Tuple[Any, ...]:
    """A hashable key of an adapter's settings (the solver's and the VJP's)."""
    if "warm_start" in settings:
        raise TypeError("warm_start: the differentiable solve takes no contact ids; "
                        "use lcpbatch.Solver(warm_start=True) for warm starts")
    return (vjp_tolerance, tuple(sorted(settings.items())))
