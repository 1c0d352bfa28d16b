#!/usr/bin/env python3
"""MuJoCo beside `lcpbatch simulate` on its standard frictional worlds
(src/world/generate.rs), stepped with mujoco.rollout, default Newton
solver, dt = 0.01 s, printing world-steps/s (wall clock and per CPU-second
of this process).

  stack:N    N unit boxes (half extents 0.5 m, 1,000 kg/m^3) resting on
             each other on the ground, mu = 0.5 (lcpbatch: sqrt(0.5 * 0.5));
  pyramid:N  a 2-D wall of unit boxes, N on the bottom row, mu = 0.5;
  rain:N     N spheres (radius 0.2-0.5 m) and boxes (half extents
             0.15-0.45 m), 500-2,000 kg/m^3, random orientations and
             velocities (|v_i| <= 0.5 m/s per axis), in a cube of cells
             1.6988 m apart from 1 m up, falling on the ground, mu = 0.4.
             lcpbatch's restitution (0-0.3) has no MuJoCo counterpart and
             is left out; the seeds differ (numpy's generator), the
             distributions are lcpbatch's.

lcpbatch's y is up; here z is up. Not a test and no test depends on it;
it needs `pip install mujoco` (written against mujoco 4.0.0):

    python3 benches/mujoco_worlds.py --world stack:4 --worlds 1000 --steps 200 --threads 2
"""

import argparse
import math
import time

import mujoco
import numpy as np
from mujoco import rollout


def box(name, pos, half, density, quat=(1, 0, 0, 0), vel=None):
    h = " ".join(f"{x:.6f}" for x in half)
    q = " ".join(f"{x:.9f}" for x in quat)
    p = " ".join(f"{x:.6f}" for x in pos)
    return (f'<body name="{name}" pos="{p}" quat="{q}"><freejoint/>'
            f'<geom type="box" size="{h}" density="{density:.3f}"/></body>')


def sphere(name, pos, radius, density):
    p = " ".join(f"{x:.6f}" for x in pos)
    return (f'<body name="{name}" pos="{p}"><freejoint/>'
            f'<geom type="sphere" size="{radius:.6f}" density="{density:.3f}"/></body>')


def world_xml(kind: str, size: int, dt: float, seed: int):
    """(MJCF, initial linear velocities per body or None) of the world."""
    vels = None
    if kind == "stack":
        mu = 0.5
        bodies = [box(f"b{k}", (0, 0, 0.5 + k), (0.5,) * 3, 1000) for k in range(size)]
    elif kind == "pyramid":
        mu = 0.5
        bodies = []
        for row in range(size):
            for k in range(size - row):
                x = k + 0.5 * row - 0.5 * (size - 1)
                bodies.append(box(f"b{row}_{k}", (x, 0, 0.5 + row), (0.5,) * 3, 1000))
    elif kind == "rain":
        mu = 0.4
        rng = np.random.default_rng(seed)
        reach = max(0.5, 0.45 * math.sqrt(3))
        pitch = 2 * (reach + 0.05) + 0.04
        side = max(1, math.ceil(size ** (1 / 3) - 1e-12))
        bodies, vels = [], []
        for k in range(size):
            # lcpbatch's cell (x, y up, z) as (x, z, y up) here.
            cx, cup, cz = k % side, k // (side * side), (k // side) % side
            p = np.array([cx, cz, cup]) * pitch + np.array([0, 0, 1.0])
            p += rng.uniform(-0.05, 0.05, 3)
            density = rng.uniform(500, 2000)
            if rng.uniform() < 0.5:
                bodies.append(sphere(f"b{k}", p, rng.uniform(0.2, 0.5), density))
            else:
                axis = rng.normal(size=3)
                axis /= np.linalg.norm(axis)
                a = rng.uniform(0, 2 * math.pi)
                quat = (math.cos(a / 2), *(math.sin(a / 2) * axis))
                half = rng.uniform(0.15, 0.45, 3)
                bodies.append(box(f"b{k}", p, half, density, quat))
            vels.append(rng.uniform(-0.5, 0.5, 3))
    else:
        raise SystemExit(f"unknown world kind {kind}")
    xml = f"""
<mujoco>
  <option timestep="{dt}" solver="Newton" gravity="0 0 -9.81"/>
  <default><geom friction="{mu} 0.005 0.0001" condim="3"/></default>
  <worldbody>
    <geom type="plane" size="50 50 0.1"/>
    {chr(10).join(bodies)}
  </worldbody>
</mujoco>"""
    return xml, vels


def many_worlds(model, initial, steps: int, threads: int):
    """World-steps/s of `initial` (one state per world) stepped through
    rollout on `threads` threads, by wall and by CPU time (warm-up untimed).
    """
    data = [mujoco.MjData(model) for _ in range(threads)]
    rollout.rollout(model, data, initial, nstep=2)  # warm-up (threads, memory)
    start, cpu = time.perf_counter(), time.process_time()
    rollout.rollout(model, data, initial, nstep=steps)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    n = initial.shape[0]
    return n * steps / wall, n * steps / cpu


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--world", default="stack:4", help="stack:N, pyramid:N or rain:N")
    p.add_argument("--dt", type=float, default=0.01)
    p.add_argument("--worlds", type=int, default=1000)
    p.add_argument("--steps", type=int, default=200)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
    kind, _, size = a.world.partition(":")
    size = int(size) if size else {"stack": 4, "pyramid": 4, "rain": 32}[kind]
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    states = []
    # Stacks and pyramids are the same in every world; each rain world
    # has its own seed (one model per world would defeat rollout's batch,
    # so the rain's worlds share the seed's shapes and differ in velocities).
    xml, vels = world_xml(kind, size, a.dt, a.seed)
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    rng = np.random.default_rng(a.seed + 1)
    for w in range(a.worlds):
        mujoco.mj_resetData(model, data)
        if vels is not None:
            for k in range(len(vels)):
                v = vels[k] if w == 0 else rng.uniform(-0.5, 0.5, 3)
                data.qvel[6 * k:6 * k + 3] = v
        mujoco.mj_forward(model, data)
        s = np.zeros(mujoco.mj_stateSize(model, spec))
        mujoco.mj_getState(model, data, s, spec)
        states.append(s)
    initial = np.array(states)
    wall, cpu = many_worlds(model, initial, a.steps, a.threads)
    # Contacts and penetration of world 0 stepped alone, for reading speed
    # beside what the soft contacts do.
    mujoco.mj_setState(model, data, initial[0], spec)
    deepest, contacts = 0.0, 0
    for _ in range(a.steps):
        mujoco.mj_step(model, data)
        contacts += data.ncon
        deepest = max(deepest, max((-data.contact[i].dist for i in range(data.ncon)), default=0.0))
    print(f"mujoco {mujoco.__version__} {a.world}: {a.worlds} worlds x {a.steps} steps, "
          f"dt {a.dt}, Newton, rollout on {a.threads} thread(s): "
          f"{wall:,.0f} world-steps/s wall, {cpu:,.0f} per CPU-second; "
          f"world 0: {contacts / a.steps:.1f} contacts/step, deepest penetration {deepest * 1e3:.2f} mm")


if __name__ == "__main__":
    main()
