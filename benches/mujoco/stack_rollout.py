#!/usr/bin/env python3
"""MuJoCo side by side with `lcpbatch simulate` / benches/world.rs: a stack of
unit boxes (half extents 0.5 m) on the ground, dt = 0.01 s, Newton solver,
friction mu = 0.5 (or frictionless with --friction 0: condim 1), stepped

  * one world on one thread with mujoco.mj_step (steps/s), and
  * --worlds copies through mujoco.rollout on 1 and 2 threads
    (world-steps/s = worlds x steps / wall seconds).

It also prints what the soft contacts do to the stack (the deepest
penetration at the end and how far the top box sank), so that speed is
read beside accuracy. Not a test and no test depends on it; it needs
`pip install mujoco` (written against mujoco 4.0.0).

    python3 benches/mujoco/stack_rollout.py --boxes 4 --worlds 1000 --steps 200
"""

import argparse
import time

import mujoco
import numpy as np
from mujoco import rollout


def stack_xml(boxes: int, friction: float, dt: float) -> str:
    """MJCF of `boxes` unit boxes resting on each other on a plane (z up)."""
    condim = 3 if friction > 0 else 1
    bodies = "\n".join(
        f'<body name="box{k}" pos="0 0 {0.5 + k}"><freejoint/>'
        f'<geom type="box" size="0.5 0.5 0.5" mass="1"/></body>'
        for k in range(boxes)
    )
    return f"""
<mujoco>
  <option timestep="{dt}" solver="Newton" gravity="0 0 -9.81"/>
  <default><geom friction="{friction} 0.005 0.0001" condim="{condim}"/></default>
  <worldbody>
    <geom type="plane" size="10 10 0.1"/>
    {bodies}
  </worldbody>
</mujoco>"""


def one_world(model, steps: int):
    """Steps one world on this thread; returns (steps/s by wall time, steps/s
    by this process's CPU time, mean contacts, data)."""
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    contacts = 0
    start, cpu = time.perf_counter(), time.process_time()
    for _ in range(steps):
        mujoco.mj_step(model, data)
        contacts += data.ncon
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    return steps / wall, steps / cpu, contacts / steps, data


def many_worlds(model, worlds: int, steps: int, threads: int):
    """Steps `worlds` copies through mujoco.rollout on `threads` threads;
    returns world-steps/s by wall time and by the process's CPU time (all
    threads; equal to wall on one idle core) (the first, warm-up call is
    not timed)."""
    data = [mujoco.MjData(model) for _ in range(threads)]
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    state0 = np.zeros(mujoco.mj_stateSize(model, spec))
    mujoco.mj_getState(model, data[0], state0, spec)
    initial = np.tile(state0, (worlds, 1))
    rollout.rollout(model, data, initial, nstep=2)  # warm-up (threads, memory)
    start, cpu = time.perf_counter(), time.process_time()
    rollout.rollout(model, data, initial, nstep=steps)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    return worlds * steps / wall, worlds * steps / cpu


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--boxes", type=int, default=4)
    p.add_argument("--friction", type=float, default=0.5)
    p.add_argument("--dt", type=float, default=0.01)
    p.add_argument("--worlds", type=int, default=1000)
    p.add_argument("--steps", type=int, default=200)
    p.add_argument("--single-steps", type=int, default=20000)
    p.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_string(stack_xml(a.boxes, a.friction, a.dt))
    print(f"mujoco {mujoco.__version__}: {a.boxes}-box stack, mu = {a.friction}, dt = {a.dt}, Newton")
    rate, rate_cpu, contacts, data = one_world(model, a.single_steps)
    print(
        f"one world, one thread (mj_step): {rate:,.0f} steps/s wall, "
        f"{rate_cpu:,.0f} by CPU time, {contacts:.1f} contacts/step"
    )
    top_z = data.qpos[7 * (a.boxes - 1) + 2]
    sink = (0.5 + (a.boxes - 1)) - top_z
    depth = max((-data.contact[i].dist for i in range(data.ncon)), default=0.0)
    print(f"after {a.single_steps * a.dt:.0f} s: deepest penetration {depth * 1e3:.3f} mm, top box sank {sink * 1e3:.3f} mm")
    for t in a.threads:
        rate, rate_cpu = many_worlds(model, a.worlds, a.steps, t)
        print(
            f"{a.worlds} worlds x {a.steps} steps, rollout on {t} thread(s): "
            f"{rate:,.0f} world-steps/s wall, {rate_cpu:,.0f} per CPU-second"
        )


if __name__ == "__main__":
    main()
