"""Scenes as arrays: the layout of ``bodies`` and ``contacts`` and its checks.

One scene is a pair of mappings (dicts) of arrays:

``bodies`` (N bodies)
    ``inv_mass`` (N,): 1/m, 0 for a body that cannot translate;
    ``inv_inertia`` (N, 3, 3) world-frame inverse inertia, or (N, 3) its diagonal;
    ``position`` (N, 3): centre of mass;
    ``velocity``, ``angular_velocity`` (N, 3), before the impact (default 0).

``contacts`` (C contacts)
    ``a`` (C,) int: body a, the normal points towards it;
    ``b`` (C,) int: body b, −1 for the static world (default −1);
    ``point`` (C, 3): contact point; ``normal`` (C, 3): unit normal from b to a;
    ``restitution`` (C,) or a scalar in [0, 1] (default 0);
    ``id`` (C,) int ≥ 0, optional: contact ids for warm start;
    ``mu`` (C,) or a scalar ≥ 0: Coulomb friction coefficient (default 0,
    frictionless); an island with any μ > 0 is solved by the exact Coulomb
    solvers (CPU, f64);
    ``tangent`` (C, 3), optional: the first tangent t1 of each contact's
    friction frame (unit, orthogonal to the normal; t2 = n × t1), default
    the library's deterministic basis of the normal. Only the frame of the
    reported tangential parts depends on it.

Conventions (those of the scene format, README "Formats"): r = point −
centre of mass, v_rel = (ṗ_a − ṗ_b)·n, impulse +z n on a and −z n on b.
Unknown keys are an error (a misspelt ``restitution`` is never silently 0)."""

from __future__ import annotations

from typing import Any, Dict, Mapping, Optional

import numpy as np

from ._inputs import id_array, real_array

BODY_KEYS = ("inv_mass", "inv_inertia", "position", "velocity", "angular_velocity")
CONTACT_KEYS = ("a", "b", "point", "normal", "restitution", "id", "mu", "tangent")


def _unknown(given: Mapping[str, Any], known: tuple, name: str) -> None:
    extra = sorted(set(given) - set(known))
    if extra:
        hint = " (the friction coefficient is 'mu')" if "friction" in extra else ""
        raise ValueError(f"{name}: unknown key(s) {extra}{hint}; known keys: {list(known)}")


def _rows(d: Mapping[str, Any], key: str, name: str, shape: tuple, default: Optional[float] = None) -> np.ndarray:
    """d[key] as float64 of `shape`; a missing key takes `default` (error if None)."""
    if key not in d:
        if default is None:
            raise ValueError(f"{name}: missing key '{key}'")
        return np.full(shape, default, dtype=np.float64)
    a = real_array(d[key], f"{name}['{key}']")
    if a.ndim == 0 and len(shape) == 1:
        a = np.full(shape, float(a))
    if a.size == 0 and 0 in shape:  # [] for a scene without contacts
        a = a.reshape(shape)
    if a.shape != shape:
        raise ValueError(f"{name}['{key}']: expected shape {shape}, got {a.shape}")
    return a


def _ints(d: Mapping[str, Any], key: str, name: str, c: int, default: Optional[int]) -> np.ndarray:
    if key not in d:
        if default is None:
            raise ValueError(f"{name}: missing key '{key}'")
        return np.full(c, default, dtype=np.int64)
    a = np.asarray(d[key])
    if a.size == 0:  # [] reads as float64
        a = a.astype(np.int64)
    if a.dtype.kind not in "iu":
        raise TypeError(f"{name}['{key}']: dtype {a.dtype} is not an integer type (body indices)")
    if a.shape != (c,):
        raise ValueError(f"{name}['{key}']: expected shape {(c,)}, got {a.shape}")
    return a.astype(np.int64, copy=False)


def scene_arrays(bodies: Mapping[str, Any], contacts: Mapping[str, Any], index: int) -> Dict[str, Any]:
    """The flat dict of arrays the extension reads, for scene `index`."""
    bn, cn = f"bodies[{index}]", f"contacts[{index}]"
    if not isinstance(bodies, Mapping):
        raise TypeError(f"{bn}: expected a dict of arrays, got {type(bodies).__name__}")
    if not isinstance(contacts, Mapping):
        raise TypeError(f"{cn}: expected a dict of arrays, got {type(contacts).__name__}")
    _unknown(bodies, BODY_KEYS, bn)
    _unknown(contacts, CONTACT_KEYS, cn)
    if "inv_mass" not in bodies:
        raise ValueError(f"{bn}: missing key 'inv_mass'")
    inv_mass = real_array(bodies["inv_mass"], f"{bn}['inv_mass']")
    if inv_mass.ndim != 1:
        raise ValueError(f"{bn}['inv_mass']: expected shape (N,), got {inv_mass.shape}")
    n = inv_mass.shape[0]
    if "inv_inertia" not in bodies:
        raise ValueError(f"{bn}: missing key 'inv_inertia'")
    inertia = real_array(bodies["inv_inertia"], f"{bn}['inv_inertia']")
    if inertia.shape == (n, 3):
        inertia = inertia[:, :, None] * np.eye(3)
    if inertia.shape != (n, 3, 3):
        raise ValueError(f"{bn}['inv_inertia']: expected shape {(n, 3, 3)} or {(n, 3)}, got {inertia.shape}")
    if "a" not in contacts:
        raise ValueError(f"{cn}: missing key 'a'")
    c = np.shape(contacts["a"])[0] if np.ndim(contacts["a"]) == 1 else -1
    if c < 0:
        raise ValueError(f"{cn}['a']: expected shape (C,), got {np.shape(contacts['a'])}")
    ids = None
    if contacts.get("id") is not None:
        ids = id_array(contacts["id"], f"{cn}['id']")
        if ids.shape != (c,):
            raise ValueError(f"{cn}['id']: expected shape {(c,)}, got {ids.shape}")
    return {
        "inv_mass": inv_mass,
        "inv_inertia": inertia,
        "position": _rows(bodies, "position", bn, (n, 3)),
        "velocity": _rows(bodies, "velocity", bn, (n, 3), 0.0),
        "angular_velocity": _rows(bodies, "angular_velocity", bn, (n, 3), 0.0),
        "a": _ints(contacts, "a", cn, c, None),
        "b": _ints(contacts, "b", cn, c, -1),
        "point": _rows(contacts, "point", cn, (c, 3)),
        "normal": _rows(contacts, "normal", cn, (c, 3)),
        "restitution": _rows(contacts, "restitution", cn, (c,), 0.0),
        "mu": _rows(contacts, "mu", cn, (c,), 0.0),
        "tangent": None if contacts.get("tangent") is None else _rows(contacts, "tangent", cn, (c, 3)),
        "id": ids,
    }
