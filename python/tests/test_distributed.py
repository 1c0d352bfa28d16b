"""lcpbatch.distributed on a local Dask cluster of 2 worker processes:
results identical to a single-process solve, one solver per worker built
once, per-worker timings."""

import logging

import numpy as np
import pytest

import lcpbatch

distributed = pytest.importorskip("distributed", reason="the 'distributed' extra is not installed")
import lcpbatch.distributed as ld  # noqa: E402

from conftest import random_pd_batch  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=":0", silence_logs=logging.ERROR)
    c = distributed.Client(cluster)
    c.wait_for_workers(2, timeout=60)
    yield c
    c.close()
    cluster.close()


def test_lcp_batches_match_a_single_process_solve(client):
    rng = np.random.default_rng(11)
    M, q = random_pd_batch(rng, 1000, 6)
    single = lcpbatch.Solver(backend="cpu", threads=1).solve(M, q)
    dist = ld.DistributedSolver(client, backend="cpu", threads=1)
    r = dist.solve(M, q, shards=4)
    for attr in ("z", "w", "basis", "status", "error", "path", "pivots"):
        np.testing.assert_array_equal(getattr(r, attr), getattr(single, attr), err_msg=attr)
    assert r.report.statuses == single.report.statuses
    assert sum(w["items"] for w in r.workers.values()) == 1000
    assert sum(w["shards"] for w in r.workers.values()) == 4
    assert len(r.workers) == 2, r.workers  # scattered shards spread over both workers
    assert all(w["seconds"] >= w["solve_seconds"] > 0 for w in r.workers.values())
    assert "2 part(s)" not in str(r.report) and "4 part(s)" in str(r.report)

    # The solvers were built once: the same objects serve a second call.
    before = client.run(lambda dask_worker, name=dist.name: id(dask_worker.plugins[name].solver))
    again = dist.solve(M, q)
    after = client.run(lambda dask_worker, name=dist.name: id(dask_worker.plugins[name].solver))
    assert before == after and len(before) == 2
    np.testing.assert_array_equal(again.z, single.z)


def test_ragged_batches_and_scenes_match_too(client):
    rng = np.random.default_rng(12)
    ms, qs = [], []
    for k in range(30):
        M, q = random_pd_batch(rng, 1, 1 + k % 5)
        ms.append(M[0])
        qs.append(q[0])
    single = lcpbatch.Solver(backend="cpu").solve(ms, qs)
    r = ld.solve(client, ms, qs, backend="cpu", shards=3)
    assert all(np.array_equal(a, b) for a, b in zip(r.z, single.z)) and len(r.z) == 30

    bodies = [dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
                   velocity=[[0.1 * k, -1.0 - k, 0]]) for k in range(10)]
    contacts = [dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=0.5)] * 10
    one = lcpbatch.Solver(backend="cpu").solve_scenes(bodies, contacts)
    many = ld.solve_scenes(client, bodies, contacts, backend="cpu", shards=4)
    assert all(np.array_equal(a, b) for a, b in zip(many.impulses, one.impulses))
    assert all(np.array_equal(a, b) for a, b in zip(many.velocity, one.velocity))
    np.testing.assert_array_equal(many.island_scene, one.island_scene)
    assert sum(w["items"] for w in many.workers.values()) == 10


def test_worlds_stepped_on_the_cluster_match_a_single_process(client):
    worlds = [lcpbatch.World.generate(k, None, seed=s) for s, k in enumerate(["rain", "slide", "stack", "spheres", "incline"])]
    copies = [w.copy() for w in worlds]
    single = lcpbatch.Solver(backend="cpu").step_worlds(copies, dt=0.01, steps=30)
    r = ld.simulate(client, worlds, dt=0.01, steps=30, backend="cpu", shards=3)
    for name in ("kinetic", "potential", "max_penetration", "max_error", "contacts", "islands"):
        np.testing.assert_array_equal(getattr(r, name), getattr(single, name), err_msg=name)
    np.testing.assert_array_equal(r.unsolved, single.unsolved)
    for mine, ref in zip(worlds, copies):                       # updated in place
        for x, y in zip(mine.state(), ref.state()):
            np.testing.assert_array_equal(x, y)
    assert sum(w["items"] for w in r.workers.values()) == 5
    # The slide and the incline have friction; the merged last-step report counts their islands.
    assert r.report is not None and r.report.friction_islands >= 2
