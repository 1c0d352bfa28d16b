"""Worlds in time from Python: World from JSON or a generator, states as
arrays, Solver.step_worlds / simulate."""

import json
import pickle
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import lcpbatch


def dropped_sphere(height=2.0, restitution=0.3, friction=0.0):
    text = json.dumps({"worlds": [{"bodies": [
        {"shape": {"plane": {"normal": [0, 1, 0]}}, "fixed": True, "position": [0, 0, 0],
         "friction": friction, "restitution": restitution},
        {"shape": {"sphere": {"radius": 0.5}}, "position": [0, height, 0], "mass": 2.0,
         "friction": friction, "restitution": restitution},
    ]}]})
    return lcpbatch.World.from_json(text)[0]


def test_a_dropped_sphere_comes_to_rest_on_the_ground():
    w = dropped_sphere()
    out = lcpbatch.simulate(w, dt=1 / 120, steps=600, backend="cpu")
    assert out.kinetic.shape == (600, 1) and out.unsolved.sum() == 0
    y, v = w.positions[1, 1], w.velocities[1]
    assert abs(y - 0.5) < 5e-3, y                       # resting on the plane (radius 0.5)
    assert np.abs(v).max() < 1e-3, v
    assert out.contacts[-1, 0] == 1 and out.max_penetration[-1, 0] < 5e-3
    # The first bounce (ε > 0, μ = 0) is met at its time of impact.
    assert out.impacts.shape == out.impacts_deferred.shape == (600, 1)
    assert out.impacts[:, 0].sum() >= 1 and out.impacts_deferred.sum() == 0
    # It loses energy at the bounces and never gains any (a small tolerance
    # for the integrator's rounding).
    e = out.energy[:, 0]
    assert (np.diff(e) <= 1e-6 * abs(e[0]) + 1e-9).all()
    assert e[-1] < e[0] - 0.9 * 2.0 * 9.81 * 1.5       # about m g Δh lost
    np.testing.assert_array_equal(out.positions[0], w.positions)


def test_two_steps_in_one_call_equal_two_calls_and_a_batch_equals_alone():
    a = lcpbatch.World.generate("rain", 12, seed=5)
    b, c = a.copy(), a.copy()
    s = lcpbatch.Solver(backend="cpu")
    for _ in range(2):
        s.step_worlds(a, dt=0.01, steps=40)
    s2 = lcpbatch.Solver(backend="cpu")
    s2.step_worlds([b], dt=0.01, steps=80)
    other = lcpbatch.World.generate("stack", 4)
    s3 = lcpbatch.Solver(backend="cpu")
    s3.step_worlds([other, c], dt=0.01, steps=80)
    for x, y in zip(a.state(), b.state()):
        np.testing.assert_array_equal(x, y)
    for x, y in zip(a.state(), c.state()):
        np.testing.assert_array_equal(x, y)
    assert not np.array_equal(a.positions, lcpbatch.World.generate("rain", 12, seed=5).positions)


def test_friction_stops_a_sliding_box_and_the_incline_holds():
    slide = lcpbatch.World.generate("slide")
    incline = lcpbatch.World.generate("incline")
    start = incline.positions.copy()
    out = lcpbatch.simulate([slide, incline], dt=0.01, steps=100, backend="cpu")
    assert out.unsolved.sum() == 0 and out.max_error.max() <= 1e-8
    # μ g = 4.9 m/s²: from 2 m/s it stops within about 0.41 s, after 2²/(2 μ g) ≈ 0.41 m.
    dynamic = ~slide.fixed
    assert np.abs(slide.velocities[dynamic]).max() < 1e-3
    assert 0.3 < slide.positions[dynamic][0, 0] < 0.5
    # tan 20° < 0.5: the box sticks on the incline.
    assert np.abs(incline.positions - start).max() < 1e-2
    assert out.report is not None and out.report.friction_islands >= 1


def test_world_state_arrays_round_trip_and_pickle():
    w = lcpbatch.World.generate("spheres", 3, seed=2)
    p = w.positions
    p[1] += [0.0, 1.0, 0.0]
    w.positions = p
    np.testing.assert_array_equal(w.positions, p)
    w.velocities = np.ones((4, 3))
    assert w.velocities[1].tolist() == [1.0, 1.0, 1.0]
    back = pickle.loads(pickle.dumps(w))
    for x, y in zip(back.state(), w.state()):
        np.testing.assert_array_equal(x, y)
    # The JSON text gives back the same bits (serde_json's float_roundtrip).
    rain = lcpbatch.World.generate("rain", 8, seed=9)
    lcpbatch.simulate(rain, dt=0.01, steps=20, backend="cpu")
    for x, y in zip(lcpbatch.World.from_json(rain.to_json())[0].state(), rain.state()):
        np.testing.assert_array_equal(x, y)
    assert len(w) == 4 and w.shapes == ["plane", "sphere", "sphere", "sphere"]
    assert "rain" in lcpbatch.World.kinds()


def test_world_errors_raise_the_right_exception():
    w = lcpbatch.World.generate("spheres", 2, seed=1)
    with pytest.raises(ValueError, match=r"orientations: expected shape \(3, 4\)"):
        w.orientations = np.zeros((3, 3))
    q = w.orientations
    q[1] = [0, 0, 0, 2.0]
    with pytest.raises(ValueError, match=r"body 1.*orientation"):
        w.orientations = q
    assert w.orientations[1].tolist() == [0, 0, 0, 1.0]          # left unchanged
    with pytest.raises(ValueError, match=r"dt: -0.1 is not a positive number"):
        lcpbatch.simulate(w, dt=-0.1, steps=1, backend="cpu")
    with pytest.raises(ValueError, match=r"steps"):
        lcpbatch.simulate(w, dt=0.01, steps=-1, backend="cpu")
    with pytest.raises(TypeError, match=r"worlds\[1\]: expected an lcpbatch.World"):
        lcpbatch.simulate([w, "stack"], dt=0.01, backend="cpu")
    with pytest.raises(ValueError, match=r"kind.*not a world kind"):
        lcpbatch.World.generate("tower")
    with pytest.raises(ValueError, match=r"bodies"):
        lcpbatch.World.from_json('{"worlds": [{"bodies": [], "bodies": []}]}')
    with pytest.raises(ValueError, match=r"unknown field"):
        lcpbatch.World.from_json('{"worlds": [{"bodies": [], "gravty": [0, 0, 0]}]}')


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT to a child process")
def test_ctrl_c_stops_stepping_and_keeps_the_last_finished_step():
    code = textwrap.dedent(
        """
        import time, lcpbatch
        worlds = [lcpbatch.World.generate("rain", 32, seed=s) for s in range(4)]
        s = lcpbatch.Solver(backend="cpu")
        print("stepping", flush=True)
        try:
            s.step_worlds(worlds, dt=0.01, steps=100000)
            print("finished", flush=True)
        except KeyboardInterrupt:
            moved = worlds[0].positions[1, 1] != lcpbatch.World.generate("rain", 32, seed=0).positions[1, 1]
            print("interrupted", moved, flush=True)
        """
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "stepping"
    time.sleep(1.5)
    sent = time.perf_counter()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    assert out.strip() == "interrupted True", out
    assert time.perf_counter() - sent < 10
