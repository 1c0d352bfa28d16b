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
:mod:`lcpbatch.distributed` (shards over a Dask cluster).
"""

from . import _native
from ._friction import FrictionResult
from ._results import PATH_NAMES, LcpResult, Report, ScenesResult, Status
from ._solver import DeviceWarning, Solver, adapters, simulate, solve, solve_friction, solve_scenes
from ._worlds import StepResult, World

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
]
