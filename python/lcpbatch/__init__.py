"""lcpbatch: batches of rigid-body contact problems (LCPs) from NumPy.

Thousands of small independent contact islands solved at once, on the GPU
(wgpu) or on every CPU core in f64, every GPU answer checked in f64.

>>> import numpy as np, lcpbatch
>>> M = np.array([[[2.0, 1.0], [1.0, 2.0]]])   # (B, n, n)
>>> q = np.array([[-5.0, -6.0]])               # (B, n)
>>> r = lcpbatch.solve(M, q)
>>> r.z.round(6).tolist(), bool((r.status == lcpbatch.Status.SOLVED).all())
([[1.333333, 2.333333]], True)

Entry points: :func:`solve` (LCP batches), :func:`solve_scenes` (bodies and
contacts as arrays, friction ``mu`` per contact), :func:`solve_friction`
(Siconos FrictionContact3D problems), :class:`World` and :func:`simulate`
(worlds in time), :class:`Solver` (keeps the device between calls),
:mod:`lcpbatch.distributed` (shards over a Dask cluster). ``help()`` of each
lists every setting with the values it accepts, and the result's fields.

Gradients: :func:`lcp_vjp` (∂L/∂M, ∂L/∂q of a solved batch, NumPy),
:func:`scene_vjp` (∂L/∂ the bodies' and contacts' arrays of frictionless scenes),
:mod:`lcpbatch.jax` and :mod:`lcpbatch.torch` (``solve`` differentiable in
M and q). Those two are imported on first use (``lcpbatch.jax.solve``), so
``import lcpbatch`` imports neither JAX nor PyTorch.
"""

import os as _os
import tempfile as _tempfile

# Where XDG_RUNTIME_DIR is not set (a headless machine, root, a container),
# Mesa's Wayland probe prints "error: XDG_RUNTIME_DIR is invalid or not set
# in the environment." at every adapter enumeration; as the command-line tool
# does, point it at the temporary folder for this process, which only quiets
# that probe (no Wayland display is found there either).
if "XDG_RUNTIME_DIR" not in _os.environ:
    _os.environ["XDG_RUNTIME_DIR"] = _tempfile.gettempdir()

from . import _native  # noqa: E402
from ._friction import FrictionResult  # noqa: E402
from ._gradient import LcpGradient, SceneGradient, lcp_vjp, scene_vjp  # noqa: E402
from ._results import PATH_NAMES, LcpResult, Report, ScenesResult, Status  # noqa: E402
from ._solver import DeviceWarning, Solver, adapters, simulate, solve, solve_friction, solve_scenes  # noqa: E402
from ._worlds import StepResult, World  # noqa: E402

#: At most this many problems per chunk (Ctrl-C is checked between chunks).
CHUNK_PROBLEMS: int = _native.CHUNK_PROBLEMS
#: At most this much work per chunk, counting 2^n per problem of size n.
CHUNK_WORK: int = _native.CHUNK_WORK
#: At most this many contacts per chunk of scenes (a scene is never split).
CHUNK_CONTACTS: int = _native.CHUNK_CONTACTS
#: At most this much work per chunk of frictional problems, counting (3k)².
CHUNK_FRICTION_WORK: int = _native.CHUNK_FRICTION_WORK

__version__ = "0.1.0"

__all__ = [
    "solve",
    "solve_scenes",
    "solve_friction",
    "simulate",
    "World",
    "StepResult",
    "FrictionResult",
    "Solver",
    "Status",
    "LcpResult",
    "ScenesResult",
    "Report",
    "DeviceWarning",
    "adapters",
    "PATH_NAMES",
    "CHUNK_PROBLEMS",
    "CHUNK_WORK",
    "CHUNK_CONTACTS",
    "CHUNK_FRICTION_WORK",
    "lcp_vjp",
    "LcpGradient",
    "scene_vjp",
    "SceneGradient",
]


def __getattr__(name: str):
    # lcpbatch.jax and lcpbatch.torch on first use: importing lcpbatch must
    # not import JAX or PyTorch (each takes seconds, and may be missing).
    if name in ("jax", "torch"):
        import importlib

        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
