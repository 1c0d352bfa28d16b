"""``lcpbatch.torch.solve``: the exact LCP solve as a differentiable PyTorch
function (a ``torch.autograd.Function``), for ``loss.backward()`` and
``torch.autograd.grad``; and ``lcpbatch.torch.solve_scenes``, the same for
frictionless scenes (bodies and contacts as tensors), differentiable
through assembly.

The forward pass (the solve) and the backward pass (the library's VJP,
:func:`lcpbatch.lcp_vjp`) run in f64 on every CPU core with the GIL
released; tensors on another device are copied to the CPU and the results
back. The backward pass is not itself differentiable (no second
derivatives).

Imported on first use (``import lcpbatch`` does not import PyTorch);
without it, an ``ImportError`` says what to install (a CPU build is enough).
"""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _gradient

torch = _gradient.framework("torch", "PyTorch",
                            'pip install torch (a CPU build is enough; or pip install "lcpbatch[torch]")')

__all__ = ["solve", "solve_scenes"]


def _numpy(t: "torch.Tensor") -> Any:
    return t.detach().cpu().numpy()


def _tensor(a: Any, like: "torch.Tensor") -> "torch.Tensor":
    return torch.from_numpy(a).to(dtype=like.dtype, device=like.device)


class _LcpSolve(torch.autograd.Function):
    """z, w = solve(M, q) with its VJP; ``key`` holds the settings."""

    @staticmethod
    def forward(ctx: Any, M: "torch.Tensor", q: "torch.Tensor",
                key: Tuple[Any, ...]) -> Tuple["torch.Tensor", "torch.Tensor"]:
        z, w = _gradient.forward(_numpy(M), _numpy(q), dict(key[1]))
        z_t, w_t = _tensor(z, q), _tensor(w, q)
        ctx.save_for_backward(M, q, z_t)
        ctx.vjp_tolerance = key[0]
        # An output the loss does not use gets None in backward, not zeros.
        ctx.set_materialize_grads(False)
        return z_t, w_t

    @staticmethod
    @torch.autograd.function.once_differentiable
    def backward(ctx: Any, dz: Optional["torch.Tensor"],
                 dw: Optional["torch.Tensor"]) -> Tuple[Any, Any, None]:
        M, q, z = ctx.saved_tensors
        z_a = _numpy(z)
        dz_a = np.zeros(z_a.shape, dtype=z_a.dtype) if dz is None else _numpy(dz)
        dm, dq = _gradient.backward(_numpy(M), _numpy(q), z_a, dz_a, None if dw is None else _numpy(dw),
                                    ctx.vjp_tolerance)
        return _tensor(dm, M), _tensor(dq, q), None


def solve(M: "torch.Tensor", q: "torch.Tensor", *, vjp_tolerance: Optional[float] = None,
          **settings: Any) -> Tuple["torch.Tensor", "torch.Tensor"]:
    """Solves w = M z + q ≥ 0, z ≥ 0, zᵀw = 0 for a batch and returns
    ``(z, w)``, differentiable in ``M`` and ``q``.

    ``M`` (..., n, n) and ``q`` (..., n) floating-point tensors, any leading
    batch dimensions (none for one problem); z and w have q's shape, dtype
    and device (computed in f64 on the CPU). The gradient is the library's
    exact VJP at the solution's active set (see ``lcpbatch.jax.solve`` and
    ``lcpbatch.lcp_vjp`` for the degenerate cases; ``vjp_tolerance`` decides
    weak activity). A problem the solver finds no solution of gives NaN z,
    w and gradients. The other keyword arguments are the settings of
    :class:`lcpbatch.Solver` (not ``warm_start``).

    >>> import torch, lcpbatch.torch
    >>> M = torch.tensor([[[2.0, 1.0], [1.0, 2.0]]], dtype=torch.float64)
    >>> q = torch.tensor([[-5.0, -6.0]], dtype=torch.float64, requires_grad=True)
    >>> z, w = lcpbatch.torch.solve(M, q)
    >>> (g,) = torch.autograd.grad(z[0, 0], q)                      # −(M⁻ᵀ e₁)
    >>> (g * 3).round(decimals=9).tolist()
    [[-2.0, 1.0]]
    """
    if not (torch.is_tensor(M) and torch.is_tensor(q)):
        raise TypeError(f"M and q: expected torch tensors, got {type(M).__name__} and {type(q).__name__}")
    if not (M.is_floating_point() and q.is_floating_point()):
        raise TypeError(f"M and q: expected floating-point tensors, got {M.dtype} and {q.dtype}")
    if q.dim() < 1 or tuple(M.shape) != tuple(q.shape) + tuple(q.shape[-1:]):
        raise ValueError(f"M: expected shape {tuple(q.shape) + tuple(q.shape[-1:])} to match q "
                         f"{tuple(q.shape)} (M (..., n, n), q (..., n)), got {tuple(M.shape)}")
    dtype = torch.promote_types(M.dtype, q.dtype)
    return _LcpSolve.apply(M.to(dtype), q.to(dtype), _gradient.settings_of(vjp_tolerance, settings))


class _SceneSolve(torch.autograd.Function):
    """impulses, velocity, angular_velocity = solve_scenes(*xs) (the
    :data:`lcpbatch._gradient.SCENE_FLOATS` tensors) with its VJP; ``key``
    holds the settings and the layout."""

    @staticmethod
    def forward(ctx: Any, key: Tuple[Any, ...], *xs: "torch.Tensor") -> Tuple["torch.Tensor", ...]:
        (vjp_tolerance, items), a, b = key
        outs = _gradient.scene_forward([_numpy(x) for x in xs], a, b, dict(items))
        outs_t = tuple(_tensor(o, xs[0]) for o in outs)
        ctx.save_for_backward(*xs, outs_t[0])
        ctx.key = key
        return outs_t

    @staticmethod
    @torch.autograd.function.once_differentiable
    def backward(ctx: Any, *g: "torch.Tensor") -> Tuple[Any, ...]:
        (vjp_tolerance, _), a, b = ctx.key
        *xs, impulses = ctx.saved_tensors
        grads = _gradient.scene_backward([_numpy(x) for x in xs], a, b, _numpy(impulses),
                                         *[_numpy(d) for d in g], vjp_tolerance)
        return (None,) + tuple(_tensor(d, x) for d, x in zip(grads, xs))


def solve_scenes(bodies: Dict[str, Any], contacts: Dict[str, Any], *, vjp_tolerance: Optional[float] = None,
                 **settings: Any) -> Tuple["torch.Tensor", "torch.Tensor", "torch.Tensor"]:
    """Solves the impacts of a batch of frictionless scenes of one layout and
    returns ``(impulses, velocity, angular_velocity)``: the contacts' normal
    impulses (..., C) and the bodies' velocities after (..., N, 3),
    differentiable in every float tensor of the scenes.

    The arguments are those of :func:`lcpbatch.jax.solve_scenes`, as
    tensors (or arrays, read with ``torch.as_tensor``): ``bodies`` dict of
    ``inv_mass`` (..., N), ``inv_inertia`` (..., N, 3, 3) or its diagonal
    (..., N, 3), ``position``, ``velocity``, ``angular_velocity``
    (..., N, 3); ``contacts`` dict of ``a``, ``b`` (C,) body indices (one
    layout for the batch; ``b`` −1, the default, for the static world),
    ``point``, ``normal`` (..., C, 3) and ``restitution`` (..., C). The
    outputs have the inputs' promoted floating dtype (computed in f64 on
    the CPU). The gradient is :func:`lcpbatch.scene_vjp`'s; friction is not
    differentiated and not accepted here; a scene with an island the solver
    finds no solution of gives NaN.

    >>> import torch, lcpbatch.torch
    >>> ball = dict(inv_mass=torch.tensor([1.0]), inv_inertia=torch.tensor([[2.5, 2.5, 2.5]]),
    ...             position=torch.tensor([[0, 0.5, 0]]), velocity=torch.tensor([[0, -1.0, 0]]))
    >>> e = torch.tensor([0.5], requires_grad=True)
    >>> ground = dict(a=[0], point=torch.zeros(1, 3), normal=torch.tensor([[0, 1.0, 0]]), restitution=e)
    >>> v_up = lcpbatch.torch.solve_scenes(ball, ground)[1][0, 1]   # v⁺ = e · 1
    >>> v_up.item(), torch.autograd.grad(v_up, e)[0].tolist()
    (0.5, [1.0])
    """
    a, b, arrays = _gradient.scene_inputs(bodies, contacts, "lcpbatch.torch.solve_scenes", torch.as_tensor,
                                          torch.zeros, torch.diag_embed)
    dtype = torch.float32
    for x in arrays:
        dtype = torch.promote_types(dtype, x.dtype)
    key = (_gradient.settings_of(vjp_tolerance, settings), a, b)
    return _SceneSolve.apply(key, *[x.to(dtype) for x in arrays])
