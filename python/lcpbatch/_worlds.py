"""Worlds in time: :class:`World` (bodies under gravity, from the library's
JSON world format or a standard generator) with its state as arrays, and
:class:`StepResult`, what ``Solver.step_worlds`` / ``simulate`` return.

A step (the velocity-level time stepping of Stewart and Trinkle 1996 and
Anitescu and Potra 1997; README, "Simulating worlds"): collision (spheres,
boxes, planes), one batch of contact islands for every world (frictionless
islands as LCPs, islands with friction by the Coulomb solvers), the
velocities after the impulses, then the poses. Units: m, kg, s; gravity
default (0, −9.81, 0)."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _native
from ._results import Report, fill_doc

__all__ = ["World", "StepResult", "STEP_FIELDS_DOC", "concat_step_results"]

#: The fields of :class:`StepResult` (in its docstring and ``simulate``'s).
STEP_FIELDS_DOC = """\
    - ``kinetic``, ``potential``: (steps, W) energies (J) after each step;
      ``energy``: their sum;
    - ``max_penetration``: (steps, W) deepest penetration (m) before the step's correction;
    - ``contacts``, ``islands``, ``awake``: (steps, W) int64: contacts,
      contact islands and bodies awake (not sleeping);
    - ``impacts``, ``impacts_deferred``: (steps, W) int64: bounces resolved
      at their time of impact within the step, and those left to the step
      when its bound on impacts (16 per world) was reached;
    - ``max_error``: (steps, W) largest error of the world's islands (LCP
      error, or Coulomb error for frictional ones; 0 without islands);
    - ``unsolved``: (steps,) islands whose status is not a solution, over
      all worlds (each given exact frictionless impulses, else PGS's, else
      none: an unchecked answer never moves a body);
    - ``timings``: dict of (steps,) seconds: ``collision``, ``solve``, ``integrate``;
    - ``worlds``: the worlds (updated in place), and their final states
      ``positions``, ``orientations``, ``velocities``, ``angular_velocities``
      as lists of arrays, one per world;
    - ``report``: :class:`Report` of the last step's solve (None for 0 steps).
"""


class World:
    """One simulation instance: rigid bodies (spheres, boxes, static planes)
    under gravity. Build it from the library's strict JSON world format
    (:meth:`from_json`, the CLI's ``--worlds`` files) or a standard
    generator (:meth:`generate`: ``World.kinds()``); step it with
    :meth:`Solver.step_worlds` or :func:`lcpbatch.simulate`, which update it
    in place.

    The state as arrays (N bodies, static ones included): ``positions``
    (N, 3) centres of mass, ``orientations`` (N, 4) unit quaternions
    [x, y, z, w] body to world, ``velocities`` and ``angular_velocities``
    (N, 3, world frame). Assign an array to change it (checked: a non-unit
    quaternion or a NaN is a ``ValueError`` naming the body and the field).

    >>> import lcpbatch
    >>> w = lcpbatch.World.generate("spheres", 2, seed=1)
    >>> w.shapes, w.positions.shape, w.orientations.shape
    (['plane', 'sphere', 'sphere'], (3, 3), (3, 4))
    >>> w2 = lcpbatch.World.from_json(w.to_json())[0]
    >>> bool((w2.positions == w.positions).all())
    True
    """

    def __init__(self, native: "_native.NativeWorld"):
        self._w = native

    @staticmethod
    def kinds() -> List[str]:
        """Names of the standard generators: "spheres" (falling spheres),
        "stack" (boxes resting on each other), "pyramid" (boxes, ``size`` on
        the bottom row), "slide" (a box sliding at 2 m/s, μ = 0.5),
        "incline" (a box on a 20° incline, μ = 0.5: it sticks), "rain"
        (spheres and boxes of mixed sizes from random poses)."""
        return list(_native.NativeWorld.kinds())

    @classmethod
    def generate(cls, kind: str, size: Optional[int] = None, seed: int = 0) -> "World":
        """The standard world ``kind`` with ``size`` bodies (or boxes in a
        stack, or the bottom row of a pyramid; None: the kind's default) from
        ``seed``: the same arguments give the same world on every platform.

        >>> import lcpbatch
        >>> len(lcpbatch.World.generate("stack", 3).shapes)   # the ground and 3 boxes
        4
        """
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ValueError(f"seed: {seed!r} is not an integer ≥ 0")
        return cls(_native.NativeWorld.generate(kind, size, int(seed)))

    @classmethod
    def from_json(cls, text: str) -> List["World"]:
        """Every world of a world file's text (``{"worlds": [...]}``); the
        format is strict (an unknown key or a key twice is a ``ValueError``
        naming the world, the body and the field).

        >>> import lcpbatch
        >>> text = '{"worlds": [{"bodies": [{"shape": {"sphere": {"radius": 0.5}}, "position": [0, 1, 0], "mass": 1}]}]}'
        >>> lcpbatch.World.from_json(text)[0].positions.tolist()
        [[0.0, 1.0, 0.0]]
        """
        return [cls(w) for w in _native.NativeWorld.from_json(text)]

    def to_json(self) -> str:
        """The world in the library's JSON world format (readable by :meth:`from_json`)."""
        return self._w.to_json()

    def copy(self) -> "World":
        """An independent copy, bit for bit."""
        return World(self._w.copy())

    def __copy__(self) -> "World":
        return self.copy()

    def __reduce__(self) -> Tuple[Any, ...]:
        # The JSON text, then the state arrays, so that the state travels bit
        # for bit whatever the text's decimal form.
        return (_restore, (self.to_json(), self.state()))

    @property
    def shapes(self) -> List[str]:
        """Per body: "sphere", "box" or "plane"."""
        return list(self._w.shapes())

    @property
    def fixed(self) -> np.ndarray:
        """(N,) bool: static bodies."""
        return np.array(self._w.fixed(), dtype=bool)

    @property
    def asleep(self) -> np.ndarray:
        """(N,) bool: sleeping bodies."""
        return np.array(self._w.asleep(), dtype=bool)

    def state(self) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(positions, orientations, velocities, angular_velocities), fresh arrays."""
        return self._w.state()

    def set_state(self, positions: Any = None, orientations: Any = None, velocities: Any = None,
                  angular_velocities: Any = None) -> None:
        """Replaces the parts given (None keeps a part); checked as a whole."""
        def arr(v: Any) -> Optional[np.ndarray]:
            return None if v is None else np.ascontiguousarray(np.asarray(v, dtype=np.float64))
        self._w.set_state(arr(positions), arr(orientations), arr(velocities), arr(angular_velocities))

    positions = property(lambda self: self.state()[0],
                         lambda self, v: self.set_state(positions=v), doc="(N, 3) centres of mass (m).")
    orientations = property(lambda self: self.state()[1],
                            lambda self, v: self.set_state(orientations=v),
                            doc="(N, 4) unit quaternions [x, y, z, w].")
    velocities = property(lambda self: self.state()[2],
                          lambda self, v: self.set_state(velocities=v), doc="(N, 3) m/s.")
    angular_velocities = property(lambda self: self.state()[3],
                                  lambda self, v: self.set_state(angular_velocities=v),
                                  doc="(N, 3) rad/s, world frame.")

    @property
    def kinetic_energy(self) -> float:
        """Kinetic energy (J)."""
        return self._w.kinetic_energy()

    @property
    def potential_energy(self) -> float:
        """Potential energy −Σ m g·x (J)."""
        return self._w.potential_energy()

    def __len__(self) -> int:
        return self._w.bodies()

    def __repr__(self) -> str:
        counts = {s: self.shapes.count(s) for s in ("sphere", "box", "plane")}
        parts = ", ".join(f"{n} {s}(s)" for s, n in counts.items() if n)
        return f"<lcpbatch.World: {parts or 'no bodies'}>"


def _restore(text: str, state: Tuple[np.ndarray, ...]) -> World:
    w = World.from_json(text)[0]
    w.set_state(*state)
    return w


class StepResult:
    """What ``steps`` steps of a batch of W worlds found, per step and world:

    <fields>

    >>> import lcpbatch
    >>> w = lcpbatch.World.generate("spheres", 1, seed=0)
    >>> out = lcpbatch.simulate([w], dt=0.01, steps=3, backend="cpu")
    >>> out.kinetic.shape, len(out.positions)
    ((3, 1), 1)
    """

    def __init__(self, d: Dict[str, Any], worlds: Sequence[World]):
        self.kinetic: np.ndarray = d["kinetic"]
        self.potential: np.ndarray = d["potential"]
        self.max_penetration: np.ndarray = d["max_penetration"]
        self.max_error: np.ndarray = d["max_error"]
        self.contacts: np.ndarray = d["contacts"]
        self.islands: np.ndarray = d["islands"]
        self.awake: np.ndarray = d["awake"]
        self.impacts: np.ndarray = d["impacts"]
        self.impacts_deferred: np.ndarray = d["impacts_deferred"]
        self.unsolved: np.ndarray = d["unsolved"]
        self.timings: Dict[str, np.ndarray] = {k: d[k] for k in ("collision", "solve", "integrate")}
        self.report: Optional[Report] = None if d["report"] is None else Report(d["report"])
        self.worlds: List[World] = list(worlds)
        states = [w.state() for w in self.worlds]
        self.positions: List[np.ndarray] = [s[0] for s in states]
        self.orientations: List[np.ndarray] = [s[1] for s in states]
        self.velocities: List[np.ndarray] = [s[2] for s in states]
        self.angular_velocities: List[np.ndarray] = [s[3] for s in states]

    @property
    def energy(self) -> np.ndarray:
        """(steps, W) total mechanical energy, kinetic + potential (J)."""
        return self.kinetic + self.potential

    def __repr__(self) -> str:
        steps, worlds = self.kinetic.shape
        return (f"<lcpbatch.StepResult: {steps} step(s) of {worlds} world(s); "
                f"{int(self.unsolved.sum())} unsolved island(s)>")


fill_doc(StepResult, fields=STEP_FIELDS_DOC)


def concat_step_results(parts: Sequence[StepResult], worlds: Sequence[World]) -> StepResult:
    """The result of a batch of worlds stepped in consecutive parts (the
    same steps each): per-world arrays side by side, ``unsolved`` and the
    seconds per step summed, the parts' last reports merged."""
    from ._results import merge_reports

    out = object.__new__(StepResult)
    for attr in ("kinetic", "potential", "max_penetration", "max_error", "contacts", "islands", "awake",
                 "impacts", "impacts_deferred"):
        setattr(out, attr, np.concatenate([getattr(p, attr) for p in parts], axis=1))
    out.unsolved = np.sum([p.unsolved for p in parts], axis=0)
    out.timings = {k: np.sum([p.timings[k] for p in parts], axis=0) for k in parts[0].timings}
    reports = [p.report for p in parts if p.report is not None]
    out.report = merge_reports(reports) if reports else None
    out.worlds = list(worlds)
    for attr in ("positions", "orientations", "velocities", "angular_velocities"):
        setattr(out, attr, [x for p in parts for x in getattr(p, attr)])
    return out
