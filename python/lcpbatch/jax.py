"""``lcpbatch.jax.solve``: the exact LCP solve as a differentiable JAX
function (``jax.custom_vjp``), for ``jax.grad``, ``jit`` and ``vmap``; and
``lcpbatch.jax.solve_scenes``, the same for frictionless scenes (bodies and
contacts as arrays), differentiable through assembly.

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
from typing import Any, Callable, Dict, List, Optional, Tuple

import numpy as np

from . import _gradient

jax = _gradient.framework("jax", "JAX", 'pip install "jax[cpu]" (or pip install "lcpbatch[jax]")')
jnp = jax.numpy

__all__ = ["solve", "solve_scenes"]


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


def solve_scenes(bodies: Dict[str, Any], contacts: Dict[str, Any], *, vjp_tolerance: Optional[float] = None,
                 **settings: Any) -> Tuple[Any, Any, Any]:
    """Solves the impacts of a batch of frictionless scenes of one layout and
    returns ``(impulses, velocity, angular_velocity)``: the contacts' normal
    impulses (..., C) and the bodies' velocities after (..., N, 3),
    differentiable in every float array of the scenes.

    ``bodies``: dict of ``inv_mass`` (..., N), ``inv_inertia`` (..., N, 3, 3)
    or its diagonal (..., N, 3), ``position``, ``velocity``,
    ``angular_velocity`` (..., N, 3); ``contacts``: dict of ``a``, ``b``
    (C,) body indices (integers, static: one layout for the whole batch;
    ``b`` −1, the default, for the static world), ``point``, ``normal``
    (..., C, 3) and ``restitution`` (..., C) (default 0). The leading
    dimensions "..." are the batch (none for one scene); the layout is
    that of :func:`lcpbatch.solve_scenes`. The gradient is
    :func:`lcpbatch.scene_vjp`'s (through assembly and each island's LCP;
    ``vjp_tolerance`` as for :func:`solve`); friction (``mu``) is not
    differentiated and not accepted here. A scene with an island the solver
    finds no solution of gives NaN. The other keyword arguments are the
    settings of :class:`lcpbatch.Solver`.

    >>> import jax, jax.numpy as jnp, lcpbatch.jax
    >>> ball = dict(inv_mass=jnp.array([1.0]), inv_inertia=jnp.array([[2.5, 2.5, 2.5]]),
    ...             position=jnp.array([[0, 0.5, 0]]), velocity=jnp.array([[0, -1.0, 0]]))
    >>> ground = dict(a=[0], point=jnp.zeros((1, 3)), normal=jnp.array([[0, 1.0, 0]]))
    >>> def bounce(e):                                  # the ball's vertical velocity after
    ...     return lcpbatch.jax.solve_scenes(ball, dict(ground, restitution=jnp.array([e])))[1][0, 1]
    >>> float(bounce(0.5)), float(jax.grad(bounce)(0.5))   # v⁺ = e · 1
    (0.5, 1.0)
    """
    a, b, arrays = _gradient.scene_inputs(bodies, contacts, "lcpbatch.jax.solve_scenes", jnp.asarray, jnp.zeros,
                                          lambda d: d[..., None] * jnp.eye(3))
    dtype = jnp.result_type(*[x.dtype for x in arrays], jnp.float32)
    key = (_gradient.settings_of(vjp_tolerance, settings), a.tobytes(), b.tobytes())
    return _scene_function(key)(*[x.astype(dtype) for x in arrays])


def _differentiable(host_forward: Callable[..., Tuple[np.ndarray, ...]], host_backward: Callable[..., Any],
                    outputs: Callable[..., Tuple[Any, ...]]) -> Callable[..., Tuple[Any, ...]]:
    """A ``jax.custom_vjp`` function of arrays computed on the host:
    ``host_forward(*xs)`` gives the outputs (shapes and dtypes
    ``outputs(*xs)``), ``host_backward(xs, outs, cotangents)`` the
    gradients of ``xs`` (``outs``: the first output only, the forward's
    own, the one both adapters' products start from: the others are not
    kept or passed); both through ``pure_callback``, one host call under
    ``vmap`` (``broadcast_all``)."""

    def forward(*xs: Any) -> Tuple[Any, ...]:
        return jax.pure_callback(host_forward, outputs(*xs), *xs, vmap_method="broadcast_all")

    @jax.custom_vjp
    def f(*xs: Any) -> Tuple[Any, ...]:
        return forward(*xs)

    def f_fwd(*xs: Any) -> Tuple[Tuple[Any, ...], Tuple[Any, ...]]:
        outs = forward(*xs)
        return outs, (xs, outs[:1])

    def f_bwd(res: Tuple[Any, ...], g: Tuple[Any, ...]) -> Tuple[Any, ...]:
        xs, outs = res
        k, m = len(xs), len(outs)

        def host(*args: np.ndarray) -> Tuple[np.ndarray, ...]:
            grads = host_backward(args[:k], args[k:k + m], args[k + m:])
            return tuple(np.asarray(d).astype(x.dtype, copy=False) for d, x in zip(grads, args[:k]))

        shapes = tuple(jax.ShapeDtypeStruct(x.shape, x.dtype) for x in xs)
        return tuple(jax.pure_callback(host, shapes, *xs, *outs, *g, vmap_method="broadcast_all"))

    f.defvjp(f_fwd, f_bwd)
    return f


@functools.lru_cache(maxsize=32)
def _function(key: Tuple[Any, ...]) -> Callable[[Any, Any], Tuple[Any, Any]]:
    """The custom_vjp function of one set of settings (cached, so that jit
    sees the same function on every call)."""
    vjp_tolerance, items = key
    settings = dict(items)

    def host_forward(M: np.ndarray, q: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
        z, w = _gradient.forward(M, q, settings)
        return z.astype(q.dtype, copy=False), w.astype(q.dtype, copy=False)

    def host_backward(xs: Tuple[np.ndarray, ...], outs: Tuple[np.ndarray, ...],
                      g: Tuple[np.ndarray, ...]) -> Tuple[np.ndarray, np.ndarray]:
        return _gradient.backward(xs[0], xs[1], outs[0], g[0], g[1], vjp_tolerance)

    def outputs(M: Any, q: Any) -> Tuple[Any, Any]:
        return (jax.ShapeDtypeStruct(q.shape, q.dtype),) * 2

    return _differentiable(host_forward, host_backward, outputs)


@functools.lru_cache(maxsize=32)
def _scene_function(key: Tuple[Any, ...]) -> Callable[..., Tuple[Any, Any, Any]]:
    """The custom_vjp function of one set of settings and one layout (the
    contacts' bodies a and b, as bytes)."""
    (vjp_tolerance, items), a, b = key
    settings = dict(items)
    a, b = np.frombuffer(a, dtype=np.int64), np.frombuffer(b, dtype=np.int64)

    def host_forward(*xs: np.ndarray) -> Tuple[np.ndarray, ...]:
        return tuple(o.astype(xs[0].dtype, copy=False) for o in _gradient.scene_forward(xs, a, b, settings))

    def host_backward(xs: Tuple[np.ndarray, ...], outs: Tuple[np.ndarray, ...],
                      g: Tuple[np.ndarray, ...]) -> List[np.ndarray]:
        return _gradient.scene_backward(xs, a, b, outs[0], *g, vjp_tolerance)

    def outputs(*xs: Any) -> Tuple[Any, Any, Any]:
        lead, n = xs[0].shape[:-1], xs[0].shape[-1]
        return (jax.ShapeDtypeStruct(lead + (len(a),), xs[0].dtype),
                jax.ShapeDtypeStruct(lead + (n, 3), xs[0].dtype),
                jax.ShapeDtypeStruct(lead + (n, 3), xs[0].dtype))

    return _differentiable(host_forward, host_backward, outputs)
