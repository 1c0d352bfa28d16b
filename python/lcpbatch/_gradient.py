"""Gradients of the exact LCP solve in NumPy: :func:`lcp_vjp` (the library's
vector–Jacobian product, ``lcpbatch::gradient::lcp_vjp_batch``) and the two
host functions :mod:`lcpbatch.jax` and :mod:`lcpbatch.torch` call, the
solve (:func:`forward`) and its VJP (:func:`backward`), on batches with any
leading dimensions (``M`` (..., n, n), ``q`` (..., n)).

Nothing here imports JAX or PyTorch."""

from __future__ import annotations

import importlib
import types
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _inputs, _native

__all__ = ["LcpGradient", "lcp_vjp", "SceneGradient", "scene_vjp", "DERIVATIVE_NAMES", "DEFAULT_VJP_TOLERANCE"]

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


class SceneGradient:
    """∂L/∂ the arrays of one frictionless scene (the keys of ``solve_scenes``).

    - ``bodies``: dict of ``inv_mass`` (N,), ``inv_inertia`` (N, 3, 3), each
      entry a separate variable), ``position``, ``velocity``,
      ``angular_velocity`` (N, 3); a static body's ``inv_mass`` and
      ``inv_inertia`` entries are 0 (not differentiated: making it dynamic
      would join islands);
    - ``contacts``: dict of ``point``, ``normal`` (C, 3, the normal as
      given, not renormalised) and ``restitution`` (C,);
    - ``islands``: (I,) str, the derivative kind of each island of the
      scene ("exact", "one_sided", "undefined", as :class:`LcpGradient`);
      ``derivative``: the worst of them ("exact" without contacts). An
      undefined island passes nothing through its LCP.
    """

    def __init__(self, d: Dict[str, Any]):
        self.bodies: Dict[str, np.ndarray] = {k: d[k] for k in ("inv_mass", "inv_inertia", "position",
                                                                 "velocity", "angular_velocity")}
        self.contacts: Dict[str, np.ndarray] = {k: d[k] for k in ("point", "normal", "restitution")}
        self.islands: np.ndarray = _DERIVATIVES[d["islands"]] if len(d["islands"]) else np.array([], dtype=str)
        self.derivative: str = DERIVATIVE_NAMES[d["derivative"]]

    def __repr__(self) -> str:
        return (f"<lcpbatch.SceneGradient: {len(self.bodies['inv_mass'])} bodies, "
                f"{len(self.contacts['restitution'])} contacts; {self.derivative}>")


def scene_vjp(bodies: Union[Mapping[str, Any], Sequence[Mapping[str, Any]]],
              contacts: Union[Mapping[str, Any], Sequence[Mapping[str, Any]]],
              impulses: Any, d_impulses: Any = None, d_velocity: Any = None,
              d_angular_velocity: Any = None, *,
              tolerance: Optional[float] = None) -> Union[SceneGradient, List[SceneGradient]]:
    """The vector–Jacobian product of ``solve_scenes`` through assembly
    (K, the LCP's M and q, Newton's restitution), for frictionless scenes:
    at the solved ``impulses`` (``solve_scenes(...).impulses``), given
    ∂L/∂impulses (``d_impulses``, (C,)) and/or ∂L/∂(velocities after)
    (``d_velocity``, ``d_angular_velocity``, (N, 3); None: 0), ∂L/∂ every
    body's and contact's array (:class:`SceneGradient`).

    One scene (two dicts, arrays per argument) or a batch (two lists of
    dicts, and a list per argument); scenes one after the other, GIL
    released. A contact with ``mu`` > 0 is a ``ValueError`` naming the
    scene, the contact and ``friction``: Coulomb friction is not
    differentiated. ``tolerance``: as :func:`lcp_vjp`.

    >>> import lcpbatch
    >>> ball = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
    ...             velocity=[[0, -1.0, 0]])
    >>> ground = dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=[0.5])
    >>> r = lcpbatch.solve_scenes(ball, ground)             # impulse (1 + e) · 1 = 1.5
    >>> g = lcpbatch.scene_vjp(ball, ground, r.impulses, d_impulses=[1.0])
    >>> float(g.contacts["restitution"][0]), g.bodies["velocity"][0].tolist(), g.derivative
    (1.0, [0.0, -1.5, 0.0], 'exact')
    """
    from ._scenes import scene_arrays

    single = isinstance(bodies, Mapping)
    if single != isinstance(contacts, Mapping):
        raise TypeError("bodies and contacts: give two dicts (one scene) or two lists of dicts (a batch)")
    bl, cl = ([bodies], [contacts]) if single else (list(bodies), list(contacts))
    if len(bl) != len(cl):
        raise ValueError(f"contacts: {len(cl)} scenes, but bodies has {len(bl)}")
    arrays = [scene_arrays(b, c, i) for i, (b, c) in enumerate(zip(bl, cl))]

    def per_scene(value: Any, name: str, ndim: int) -> Optional[List[np.ndarray]]:
        if value is None:
            return None
        values = [value] if single else list(value)
        if len(values) != len(arrays):
            raise ValueError(f"{name}: expected one array per scene ({len(arrays)}), got {len(values)}")
        out = []
        for i, v in enumerate(values):
            a = _inputs.real_array(v, f"{name}[{i}]")
            if a.ndim != ndim:
                raise ValueError(f"{name}[{i}]: expected {ndim} dimension(s), got shape {a.shape}")
            out.append(a)
        return out

    d = _native.scene_vjp_batch(arrays, per_scene(impulses, "impulses", 1), per_scene(d_impulses, "d_impulses", 1),
                                per_scene(d_velocity, "d_velocity", 2),
                                per_scene(d_angular_velocity, "d_angular_velocity", 2), tolerance)
    out = [SceneGradient(g) for g in d]
    return out[0] if single else out


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
    z, w, ok = _cached(**settings)._solve_zw(m, qa)
    if not ok.all():  # z and w are this call's own arrays
        z[~ok] = np.nan
        w[~ok] = np.nan
    return z.reshape(shape), w.reshape(shape)


def _tolerance_for(tolerance: Optional[float], z: Any) -> float:
    """The VJP's tolerance: as given, else ``DEFAULT_VJP_TOLERANCE`` or 100
    units in the last place of z's dtype where that is more (see
    :func:`backward`)."""
    if tolerance is not None:
        return tolerance
    return max(DEFAULT_VJP_TOLERANCE, 100 * float(np.finfo(np.asarray(z).dtype).eps))


def backward(M: np.ndarray, q: np.ndarray, z: np.ndarray, dz: np.ndarray, dw: Optional[np.ndarray],
             tolerance: Optional[float]) -> Tuple[np.ndarray, np.ndarray]:
    """∂L/∂M (..., n, n) and ∂L/∂q (..., n) from :func:`lcp_vjp`; NaN for
    the problems :func:`forward` gave NaN (no solution found).

    ``tolerance`` None: ``DEFAULT_VJP_TOLERANCE``, or 100 units in the last
    place of z's dtype where that is more: a float32 z is the solution
    rounded (relative 6e-8), so w = M z + q recomputed from it is off by
    about as much, and 1e-8 would call its active rows not a solution."""
    tolerance = _tolerance_for(tolerance, z)
    m, qa, shape = _flat(M, q)
    n = shape[-1]
    za = np.asarray(z, dtype=np.float64).reshape(-1, n)
    dza = np.asarray(dz, dtype=np.float64).reshape(-1, n)
    # A zero ∂L/∂w (JAX and PyTorch pass zeros for an unused w) adds nothing.
    dwa = None if dw is None or not np.any(dw) else np.asarray(dw, dtype=np.float64).reshape(-1, n)
    # The extension's product straight on the float64 arrays (their shapes
    # are the batch's here): no checks or derivative names it does not need.
    # One sum finds whether the forward gave any NaN row (a sum that
    # overflows goes row by row too, to the same numbers).
    if np.isfinite(za.sum()):
        dm, dq, _ = _native.lcp_vjp(m, qa, za, dza, dwa, tolerance)
    else:
        ok = np.isfinite(za).all(axis=1)
        dm = np.full(m.shape, np.nan)
        dq = np.full(qa.shape, np.nan)
        dm[ok], dq[ok], _ = _native.lcp_vjp(m[ok], qa[ok], za[ok], dza[ok], None if dwa is None else dwa[ok],
                                            tolerance)
    return dm.reshape(shape + (n,)), dq.reshape(shape)


#: The arrays of a scene that the scene adapters differentiate, bodies'
#: first: inv_mass (..., N), inv_inertia (..., N, 3, 3), position, velocity,
#: angular_velocity (..., N, 3), then the contacts' point, normal (..., C, 3)
#: and restitution (..., C).
SCENE_FLOATS = ("inv_mass", "inv_inertia", "position", "velocity", "angular_velocity",
                "point", "normal", "restitution")


def scene_inputs(bodies: Mapping[str, Any], contacts: Mapping[str, Any], caller: str,
                 asarray: Callable[[Any], Any], zeros: Callable[[Tuple[int, ...]], Any],
                 diag: Callable[[Any], Any]) -> Tuple[np.ndarray, np.ndarray, List[Any]]:
    """The layout (``a``, ``b`` as int64 arrays) and the :data:`SCENE_FLOATS`
    arrays of a batch of scenes given to an adapter's ``solve_scenes``
    (``caller``), as the framework's arrays (``asarray``; ``zeros`` for the
    velocities and restitution left out, ``diag`` to make (..., N, 3)
    inverse inertias (..., N, 3, 3)); ``ValueError`` naming a key that is
    unknown, missing or of the wrong shape."""
    for name, d, known, needed in (
            ("bodies", bodies, SCENE_FLOATS[:5], ("inv_mass", "inv_inertia", "position")),
            ("contacts", contacts, ("a", "b") + SCENE_FLOATS[5:], ("a", "point", "normal"))):
        unknown, missing = sorted(set(d) - set(known)), [k for k in needed if k not in d]
        if unknown or missing:
            raise ValueError(f"{name}: {f'unknown key(s) {unknown}' if unknown else f'missing key(s) {missing}'}; "
                             f"{caller} takes {list(known)} (frictionless scenes)")
    a = np.asarray(contacts["a"], dtype=np.int64)
    b = np.asarray(contacts.get("b", np.full(a.shape, -1)), dtype=np.int64)
    inv_mass = asarray(bodies["inv_mass"])
    lead, count = tuple(inv_mass.shape[:-1]), inv_mass.shape[-1]
    inertia = asarray(bodies["inv_inertia"])
    if tuple(inertia.shape) == lead + (count, 3):
        inertia = diag(inertia)
    arrays = [inv_mass, inertia, bodies["position"], bodies.get("velocity", zeros(lead + (count, 3))),
              bodies.get("angular_velocity", zeros(lead + (count, 3))), contacts["point"], contacts["normal"],
              contacts.get("restitution", zeros(lead + a.shape))]
    arrays = [asarray(x) for x in arrays]
    for key, x, want in zip(SCENE_FLOATS, arrays,
                            [(count,), (count, 3, 3)] + [(count, 3)] * 3 + [a.shape + (3,)] * 2 + [a.shape]):
        if tuple(x.shape) != lead + want:
            raise ValueError(f"{key}: expected shape {lead + want} (leading dimensions {lead} of inv_mass), "
                             f"got {tuple(x.shape)}")
    return a, b, arrays


def _scene_dicts(arrays: Sequence[np.ndarray], a: np.ndarray,
                 b: np.ndarray) -> Tuple[List[Dict[str, Any]], List[Dict[str, Any]], Tuple[int, ...]]:
    """The per-scene dicts of a batch given as :data:`SCENE_FLOATS` arrays
    with leading dimensions (those of inv_mass less its last), and the
    leading shape."""
    lead = np.shape(arrays[0])[:-1]
    flat = [np.asarray(x, dtype=np.float64).reshape((-1,) + np.shape(x)[len(lead):]) for x in arrays]
    count = int(np.prod(lead, dtype=np.int64))
    bodies = [{k: x[s] for k, x in zip(SCENE_FLOATS[:5], flat[:5])} for s in range(count)]
    contacts = [dict({k: x[s] for k, x in zip(SCENE_FLOATS[5:], flat[5:])}, a=a, b=b) for s in range(count)]
    return bodies, contacts, lead


def scene_forward(arrays: Sequence[np.ndarray], a: np.ndarray, b: np.ndarray,
                  settings: Dict[str, Any]) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Impulses (..., C), velocities and angular velocities after (..., N, 3)
    of a batch of frictionless scenes of one layout (contacts between bodies
    ``a`` and ``b``), solved by the cached solver of ``settings``; NaN for a
    scene with an island the solver found no solution of."""
    from ._solver import _cached

    bodies, contacts, lead = _scene_dicts(arrays, a, b)
    n, c = np.shape(arrays[0])[-1], len(a)
    if not bodies:
        return np.zeros(lead + (c,)), np.zeros(lead + (n, 3)), np.zeros(lead + (n, 3))
    r = _cached(**settings).solve_scenes(bodies, contacts)
    out = [np.stack(r.impulses), np.stack(r.velocity), np.stack(r.angular_velocity)]
    for x in out:
        x[~r.scene_ok] = np.nan
    return out[0].reshape(lead + (c,)), out[1].reshape(lead + (n, 3)), out[2].reshape(lead + (n, 3))


def scene_backward(arrays: Sequence[np.ndarray], a: np.ndarray, b: np.ndarray, impulses: np.ndarray,
                   d_impulses: np.ndarray, d_velocity: np.ndarray, d_angular_velocity: np.ndarray,
                   tolerance: Optional[float]) -> List[np.ndarray]:
    """∂L/∂ each of the :data:`SCENE_FLOATS` arrays (their shapes) from
    :func:`scene_vjp`; NaN for the scenes :func:`scene_forward` gave NaN.
    ``tolerance`` None: as :func:`backward`."""
    bodies, contacts, lead = _scene_dicts(arrays, a, b)
    count = len(bodies)
    flat = [np.asarray(x, dtype=np.float64).reshape((count,) + np.shape(x)[len(lead):])
            for x in (impulses, d_impulses, d_velocity, d_angular_velocity)]
    grads = [np.full((count,) + np.shape(x)[len(lead):], np.nan) for x in arrays]
    ok = [s for s in range(count) if np.isfinite(flat[0][s]).all()]
    if ok:
        pick = [[x[s] for s in ok] for x in flat]
        gs = scene_vjp([bodies[s] for s in ok], [contacts[s] for s in ok], *pick,
                       tolerance=_tolerance_for(tolerance, impulses))
        for k, key in enumerate(SCENE_FLOATS):
            grads[k][ok] = [g.bodies[key] if k < 5 else g.contacts[key] for g in gs]
    return [g.reshape(np.shape(x)) for g, x in zip(grads, arrays)]


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
