"""Checks and conversions of the arguments of ``solve``: shapes and dtypes
here (a ``TypeError`` or ``ValueError`` naming the argument and the index),
finite entries in the extension (in the library, for a C-ordered batch
it reads in place).

Arrays of float64 reach the extension as they are (C order, Fortran order
or strided views, no copy); float32 and integer arrays are converted to
float64 once (the solver computes in f64)."""

from __future__ import annotations

from typing import Any, List, Optional, Sequence, Tuple, Union

import numpy as np

Dense = Tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]
Ragged = Tuple[List[np.ndarray], List[np.ndarray], Optional[List[np.ndarray]]]


def real_array(value: Any, name: str) -> np.ndarray:
    """``value`` as a float64 array; ``TypeError`` for complex, object,
    string or boolean data."""
    a = np.asarray(value)
    if a.dtype.kind not in "fiu":
        raise TypeError(
            f"{name}: dtype {a.dtype} is not a real number type "
            "(give float64 or float32; integers are converted)"
        )
    return a.astype(np.float64, copy=False)


def id_array(value: Any, name: str) -> np.ndarray:
    """Contact ids as uint64; ``TypeError`` for non-integers, ``ValueError``
    for negative ones."""
    a = np.asarray(value)
    if a.dtype.kind not in "iu":
        raise TypeError(f"{name}: dtype {a.dtype} is not an integer type (contact ids)")
    if a.dtype.kind == "i" and a.size and a.min() < 0:
        k = tuple(int(i) for i in np.unravel_index(int(np.argmin(a)), a.shape))
        where = ", ".join(map(str, k))
        raise ValueError(f"{name}[{where}] is {a[k]}: contact ids must be ≥ 0")
    return a.astype(np.uint64, copy=False)


def is_ragged(M: Any) -> bool:
    """A list or tuple of NumPy arrays (one (nᵢ, nᵢ) array per problem, or
    an empty list) is a ragged batch; anything else, nested lists of numbers
    included, is read by ``np.asarray`` as a dense (B, n, n) batch."""
    return isinstance(M, (list, tuple)) and all(isinstance(m, np.ndarray) for m in M)


def dense(M: Any, q: Any, ids: Any) -> Dense:
    """M (B, n, n) and q (B, n), ids (B, n) or None."""
    try:
        m = real_array(M, "M")
    except ValueError as e:  # nested lists of different lengths
        raise ValueError(
            f"M: not a (B, n, n) array ({e}); for problems of different sizes "
            "give a list of NumPy arrays, one (n, n) array per problem"
        ) from None
    qa = real_array(q, "q")
    if m.ndim != 3 or m.shape[1] != m.shape[2]:
        hint = " (for one problem pass M[None] and q[None])" if m.ndim == 2 else ""
        raise ValueError(f"M: expected shape (B, n, n), got {m.shape}{hint}")
    b, n = m.shape[0], m.shape[1]
    if qa.shape != (b, n):
        raise ValueError(f"q: expected shape {(b, n)} to match M {m.shape}, got {qa.shape}")
    if n == 0 and b > 0:
        raise ValueError("M: n = 0: every problem needs at least one row")
    idsa = None
    if ids is not None:
        idsa = id_array(ids, "ids")
        if idsa.shape != (b, n):
            raise ValueError(f"ids: expected shape {(b, n)} to match M {m.shape}, got {idsa.shape}")
    return m, qa, idsa


def ragged(M: Sequence[Any], q: Any, ids: Any) -> Ragged:
    """Lists of (nᵢ, nᵢ) and (nᵢ,) arrays, ids a list of (nᵢ,) or None."""
    if not isinstance(q, (list, tuple)) or len(q) != len(M):
        got = f"a {type(q).__name__} of length {len(q)}" if hasattr(q, "__len__") else type(q).__name__
        raise ValueError(f"q: M is a list of {len(M)} problems, so q must be a list of as many; got {got}")
    ms, qs = [], []
    for i, (mi, qi) in enumerate(zip(M, q)):
        m = real_array(mi, f"M[{i}]")
        qa = real_array(qi, f"q[{i}]")
        if m.ndim != 2 or m.shape[0] != m.shape[1] or m.shape[0] == 0:
            raise ValueError(f"M[{i}]: expected a square (n, n) array with n ≥ 1, got shape {m.shape}")
        if qa.shape != (m.shape[0],):
            raise ValueError(f"q[{i}]: expected shape {(m.shape[0],)} to match M[{i}] {m.shape}, got {qa.shape}")
        ms.append(m)
        qs.append(qa)
    return ms, qs, ragged_ids(ids, [x.shape for x in qs], "")


def ragged_ids(ids: Any, shapes: Sequence[Tuple[int, ...]], what: str) -> Optional[List[np.ndarray]]:
    """A list of id arrays, one of each shape in ``shapes`` (``what`` says
    what an id stands for in the error), or None."""
    if ids is None:
        return None
    if not isinstance(ids, (list, tuple)) or len(ids) != len(shapes):
        raise ValueError(f"ids: expected a list of {len(shapes)} arrays, one per problem")
    idl = []
    for i, (k, shape) in enumerate(zip(ids, shapes)):
        a = id_array(k, f"ids[{i}]")
        if a.shape != shape:
            raise ValueError(f"ids[{i}]: expected shape {shape}{what}, got {a.shape}")
        idl.append(a)
    return idl


def check_enumeration_size(sizes: Union[Sequence[int], np.ndarray], method: str, backend: str) -> None:
    """Enumeration on the CPU visits 2^n bases and stops at n = 20: say so
    before solving, naming the first problem too large."""
    if method not in ("enum", "enumeration") or backend != "cpu":
        return
    for i, n in enumerate(sizes):
        if n > 20:
            raise ValueError(
                f"M[{i}]: n = {n} is too large for enumeration on the CPU (n ≤ 20: "
                "it visits 2^n bases); use method='auto' or method='lemke'"
            )
