"""``lcpbatch.jax.solve``: the exact LCP solve as a differentiable JAX
function (``jax.custom_vjp``), for ``jax.grad``, ``jit`` and ``vmap``.

The forward pass (the solve) and the backward pass (the library's VJP,
:func:`lcpbatch.lcp_vjp`) run on the host through ``jax.pure_callback``,
on every CPU core with the GIL released: inside ``jit`` they are two host
calls per step, whatever the batch size. Under ``vmap`` the callbacks use
``vmap_method="broadcast_all"``: the mapped axis is prepended to every
argument and the whole mapped batch is one host call (not one per element).

Imported on first use (``import lcpbatch`` does not import JAX); without
JAX, an ``ImportError`` says what to install: ``pip install "jax[cpu]"``.
"""

from __future__ import annotations

import functools
from typing import Any, Callable, Optional, Tuple

import numpy as np

from . import _gradient

jax = _gradient.framework("jax", "JAX", 'pip install "jax[cpu]" (or pip install "lcpbatch[jax]")')
jnp = jax.numpy

__all__ = ["solve"]


def solve(M: Any, q: Any, *, vjp_tolerance: Optional[float] = None, **settings: Any) -> Tuple[Any, Any]:
    """Solves w = M z + q ≥ 0, z ≥ 0, zᵀw = 0 for a batch and returns
    ``(z, w)``, differentiable in ``M`` and ``q``.

    ``M`` (..., n, n) and ``q`` (..., n), any leading batch dimensions (none
    for one problem); z and w have q's shape and the dtype of the inputs
    (float32 unless ``jax_enable_x64``; the solve and its gradient are
    computed in f64 either way). The gradient is the exact derivative of the
    solution map at the solution's active set (``lcpbatch.lcp_vjp``): exact
    where the active set is strict, the one-sided derivative that treats
    weakly active contacts (z_i = w_i = 0 within ``vjp_tolerance``, a
    relative number: default 1e-8 for float64, 100 units in the last place
    for float32) as inactive, and zero where M_αα is singular (several
    solutions nearby); ``lcpbatch.lcp_vjp(M, q, z, dz).derivative`` tells
    which, per island. A problem the solver finds no solution of gives NaN
    z, w and gradients.

    The other keyword arguments are the settings of :class:`lcpbatch.Solver`
    (``backend``, ``method``, ``tolerance``, ``threads``, …; not
    ``warm_start``); they must be hashable (they key a cached function).

    >>> import jax, jax.numpy as jnp, lcpbatch.jax
    >>> M, q = jnp.array([[[2.0, 1.0], [1.0, 2.0]]]), jnp.array([[-5.0, -6.0]])
    >>> z, w = lcpbatch.jax.solve(M, q)
    >>> [round(float(v), 5) for v in z[0]]
    [1.33333, 2.33333]
    >>> g = jax.grad(lambda q: lcpbatch.jax.solve(M, q)[0][0, 0])(q)   # −(M⁻ᵀ e₁)
    >>> [round(float(v) * 3, 5) for v in g[0]]
    [-2.0, 1.0]
    """
    M, q = jnp.asarray(M), jnp.asarray(q)
    dtype = jnp.result_type(M.dtype, q.dtype, jnp.float32)
    if q.ndim < 1 or M.shape != q.shape + q.shape[-1:]:
        raise ValueError(f"M: expected shape {q.shape + q.shape[-1:]} to match q {q.shape} "
                         f"(M (..., n, n), q (..., n)), got {M.shape}")
    return _function(_gradient.settings_of(vjp_tolerance, settings))(M.astype(dtype), q.astype(dtype))


@functools.lru_cache(maxsize=32)
def _function(key: Tuple[Any, ...]) -> Callable[[Any, Any], Tuple[Any, Any]]:
    """The custom_vjp function of one set of settings (cached, so that jit
    sees the same function on every call)."""
    vjp_tolerance, items = key
    settings = dict(items)

    def host_forward(M: np.ndarray, q: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
        z, w = _gradient.forward(M, q, settings)
        return z.astype(q.dtype, copy=False), w.astype(q.dtype, copy=False)

    def host_backward(M: np.ndarray, q: np.ndarray, z: np.ndarray, dz: np.ndarray,
                      dw: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
        dm, dq = _gradient.backward(M, q, z, dz, dw, vjp_tolerance)
        return dm.astype(M.dtype, copy=False), dq.astype(q.dtype, copy=False)

    def forward(M: Any, q: Any) -> Tuple[Any, Any]:
        out = jax.ShapeDtypeStruct(q.shape, q.dtype)
        return jax.pure_callback(host_forward, (out, out), M, q, vmap_method="broadcast_all")

    @jax.custom_vjp
    def lcp(M: Any, q: Any) -> Tuple[Any, Any]:
        return forward(M, q)

    def lcp_fwd(M: Any, q: Any) -> Tuple[Tuple[Any, Any], Tuple[Any, Any, Any]]:
        z, w = forward(M, q)
        return (z, w), (M, q, z)

    def lcp_bwd(res: Tuple[Any, Any, Any], g: Tuple[Any, Any]) -> Tuple[Any, Any]:
        M, q, z = res
        dz, dw = g
        out = (jax.ShapeDtypeStruct(M.shape, M.dtype), jax.ShapeDtypeStruct(q.shape, q.dtype))
        return tuple(jax.pure_callback(host_backward, out, M, q, z, dz, dw, vmap_method="broadcast_all"))

    lcp.defvjp(lcp_fwd, lcp_bwd)
    return lcp
