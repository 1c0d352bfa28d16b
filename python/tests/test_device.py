"""The GPU (lavapipe in CI) against the CPU, and device trouble as a
warning with the CPU's answers. GPU tests skip without an adapter and fail
instead under LCPBATCH_REQUIRE_GPU=1."""

import warnings

import numpy as np
import pytest

import lcpbatch

from conftest import assert_lcp_solutions, gpu_solver_or_skip, random_pd_batch


@pytest.fixture(scope="module")
def gpu():
    return gpu_solver_or_skip()


def test_cpu_and_gpu_give_the_same_statuses_and_answers(gpu):
    rng = np.random.default_rng(9)
    # Positive definite batches (one solution each) and general ones (some
    # without a solution): the statuses must agree problem by problem.
    M, q = random_pd_batch(rng, 200, 5)
    G = rng.standard_normal((200, 4, 4))
    g = rng.standard_normal((200, 4))
    for M_, q_ in ((M, q), (G, g)):
        # Method "auto" on both: the GPU's Lemke kernel is the CPU Auto's twin.
        cpu = lcpbatch.Solver(backend="cpu").solve(M_, q_)
        on_gpu = gpu.solve(M_, q_)
        assert on_gpu.report.device_kind != "cpu" and on_gpu.report.gpu is not None
        # The GPU phase's parts, in seconds, within the call's total.
        g = on_gpu.report.gpu
        parts = [g[k] for k in ("pack_seconds", "upload_seconds", "kernel_seconds", "readback_seconds")]
        assert all(np.isfinite(t) and t >= 0 for t in parts), g
        assert sum(parts) <= on_gpu.report.timings["total"], (g, on_gpu.report.timings)
        host = [g[k] for k in ("check_seconds", "repair_seconds", "report_seconds", "overlapped_seconds")]
        assert all(np.isfinite(t) and t >= 0 for t in host), g
        device = g["kernel_device_seconds"]
        assert device is None or (np.isfinite(device) and device >= 0), g
        counts = on_gpu.report.counts
        if counts["enumerated_gpu"] + counts["lemke_gpu"] > 0:
            assert g["kernel_seconds"] > 0 and g["dispatches"] > 0, g
        np.testing.assert_array_equal(on_gpu.status, cpu.status)
        ok = cpu.ok
        np.testing.assert_allclose(on_gpu.z[ok], cpu.z[ok], atol=1e-9)
        assert_lcp_solutions(M_, q_, on_gpu.z, on_gpu.w, on_gpu.ok)


def test_scenes_on_the_gpu_match_the_cpu(gpu):
    bodies = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
                  velocity=[[0.3, -1.0, 0]])
    contacts = dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=0.5)
    on_gpu = gpu.solve_scenes([bodies] * 3, [contacts] * 3)
    cpu = lcpbatch.Solver(backend="cpu").solve_scenes([bodies] * 3, [contacts] * 3)
    assert on_gpu.report.device_kind != "cpu"
    for a, b in zip(on_gpu.velocity, cpu.velocity):
        np.testing.assert_allclose(a, b, atol=1e-9)


def test_device_trouble_warns_and_solves_on_the_cpu():
    # An adapter that does not exist is device trouble, not an error.
    with pytest.warns(lcpbatch.DeviceWarning, match="solving on the CPU"):
        s = lcpbatch.Solver(backend="gpu", adapter="no-such-adapter-anywhere")
    assert s.device_kind == "cpu" and s.fallback
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # warned once, not on every call
        r = s.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))
    assert r.report.fallback == s.fallback and "GPU trouble" in str(r.report)
    np.testing.assert_allclose(r.z, [[4 / 3, 7 / 3]])
