"""``lcpbatch.jax.solve``: the exact LCP solve as a differentiable JAX
function (``jax.custom_vjp``), for ``jax.grad``, ``jit`` and ``vmap``; and
``lcpbatch.jax.solve_scenes``, the same for frictionless scenes (bodies and
contacts as arrays), differentiable through assembly.

``solve``'s forward pass (the solve) and backward pass (the library's VJP,
:func:`lcpbatch.lcp_vjp`) are XLA FFI calls (``jax.ffi.ffi_call``) of two
handlers the extension exports (``lcpbatch_solve``, ``lcpbatch_vjp``):
XLA hands them its own buffers, so nothing is copied into Python and the
GIL is not taken; they run on every CPU core. That is when JAX's default
backend is the CPU; otherwise (a GPU jaxlib), and for ``solve_scenes``,
the two passes run through ``jax.pure_callback``, which copies the arrays
to the host and back. Either way, inside ``jit`` they are two host calls
per step, whatever the batch size, and under ``vmap`` (``vmap_method=
"broadcast_all"``) the mapped axis is prepended to every argument and the
whole mapped batch is one call (not one per element). Both paths give the
same numbers, bit for bit. Ctrl-C is not seen during an FFI call.

Imported on first use (``import lcpbatch`` does not import JAX); without
JAX, an ``ImportError`` says what to install: ``pip install "jax[cpu]"``.
"""

from __future__ import annotations

import functools
from typing import Any, Callable, Dict, List, Optional, Tuple

import numpy as np

from . import _gradient, _inputs, _native

jax = _gradient.framework("jax", "JAX", 'pip install "jax[cpu]" (or pip install "lcpbatch[jax]")')
jnp = jax.numpy
try:  # XLA's FFI from Python (`jax.ffi`, in newer JAX); without it, the callbacks.
    from jax import ffi as _jax_ffi
except ImportError:
    _jax_ffi = None

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
    key = _gradient.settings_of(vjp_tolerance, settings)
    # An empty batch or n = 0: nothing to solve, the callbacks' empty arrays.
    function = _ffi_function(key) if q.size and _ffi_ready() else _function(key)
    return function(M.astype(dtype), q.astype(dtype))


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


#: Whether ``solve`` may use the FFI handlers (tests turn it off to compare
#: with the ``pure_callback`` path).
_USE_FFI = True


def _ffi_ready() -> bool:
    """Whether ``solve`` calls the FFI handlers: ``jax.ffi`` exists and
    JAX's default backend is the CPU (the handlers are registered for the
    CPU platform; on first use). The choice follows the default backend,
    not the platform a call is lowered for: with a CPU default and arrays
    placed on an accelerator, the FFI call has no handler there and
    lowering fails; ``_USE_FFI = False`` keeps the callbacks."""
    if not _USE_FFI or _jax_ffi is None or jax.default_backend() != "cpu":
        return False
    _register_ffi_targets()
    return True


@functools.lru_cache(maxsize=1)
def _register_ffi_targets() -> None:
    for name, capsule in _native.ffi_targets().items():
        _jax_ffi.register_ffi_target(name, capsule, platform="cpu", api_version=1)


#: The solver id (``_native.ffi_register``) of each set of settings the FFI
#: path has used. Never dropped: a compiled program holds only the id, and
#: the extension keeps the solver for the process's life.
_FFI_SOLVERS: Dict[Tuple[Any, ...], Tuple[Any, int]] = {}


@functools.lru_cache(maxsize=32)
def _ffi_function(key: Tuple[Any, ...]) -> Callable[[Any, Any], Tuple[Any, Any]]:
    """The custom_vjp function of one set of settings through the FFI
    handlers (see the module docs): the same solve and VJP as
    :func:`_function`'s callbacks, bit for bit."""
    from ._solver import _cached

    vjp_tolerance, items = key
    if items not in _FFI_SOLVERS:
        solver = _cached(**dict(items))
        _FFI_SOLVERS[items] = (solver, _native.ffi_register(solver))
    solver, solver_id = _FFI_SOLVERS[items]

    def forward(M: Any, q: Any) -> Tuple[Any, Any, Any]:
        batch, n = q.shape[:-1], q.shape[-1]
        _inputs.check_enumeration_size([n], solver.settings["method"], solver.settings["backend"])
        out = (jax.ShapeDtypeStruct(q.shape, q.dtype),) * 2 + (jax.ShapeDtypeStruct(batch, np.int8),)
        return _jax_ffi.ffi_call("lcpbatch_solve", out, vmap_method="broadcast_all")(
            M, q, solver=np.int64(solver_id))

    @jax.custom_vjp
    def f(M: Any, q: Any) -> Tuple[Any, Any]:
        return forward(M, q)[:2]

    def f_fwd(M: Any, q: Any) -> Tuple[Tuple[Any, Any], Tuple[Any, ...]]:
        z, w, _ = forward(M, q)
        return (z, w), (M, q, z)

    def f_bwd(res: Tuple[Any, ...], g: Tuple[Any, Any]) -> Tuple[Any, Any]:
        M, q, z = res
        tolerance = _gradient._tolerance_for(vjp_tolerance, np.zeros(0, z.dtype))
        out = (jax.ShapeDtypeStruct(M.shape, M.dtype), jax.ShapeDtypeStruct(q.shape, q.dtype))
        return tuple(_jax_ffi.ffi_call("lcpbatch_vjp", out, vmap_method="broadcast_all")(
            M, q, z, *g, tolerance=np.float64(tolerance)))

    f.defvjp(f_fwd, f_bwd)
    return f


@functools.lru_cache(maxsize=32)
def _function(key: Tuple[Any, ...]) -> Callable[[Any, Any], Tuple[Any, Any]]:
    """The custom_vjp function of one set of settings through
    ``pure_callback`` (cached, so that jit sees the same function on every
    call): the path without the FFI handlers."""
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
