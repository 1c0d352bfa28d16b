"""Shared helpers: the GPU solver (skipped without an adapter, failing
instead under LCPBATCH_REQUIRE_GPU=1 as the Rust tests do) and the NumPy
check of an LCP answer."""

import os
import warnings

import numpy as np
import pytest

import lcpbatch


def require_gpu() -> bool:
    return os.environ.get("LCPBATCH_REQUIRE_GPU") == "1"


def gpu_solver_or_skip(**settings) -> lcpbatch.Solver:
    """A solver on the GPU (lavapipe in CI) at f64 where the adapter has it;
    skips with the reason when there is no adapter, fails under
    LCPBATCH_REQUIRE_GPU=1."""
    found = lcpbatch.adapters()
    if not found:
        why = f"no GPU adapter (install one: {lcpbatch._native.__name__} found none)"
        if require_gpu():
            pytest.fail(f"LCPBATCH_REQUIRE_GPU=1 but {why}")
        pytest.skip(why)
    precision = "f64" if any(a["f64"] for a in found) else "auto"
    with warnings.catch_warnings():
        warnings.simplefilter("error", lcpbatch.DeviceWarning)
        s = lcpbatch.Solver(backend="gpu", precision=precision, **settings)
    assert s.device_kind != "cpu", s.device
    return s


def assert_lcp_solutions(M, q, z, w, ok, tol=1e-9):
    """Where ok: z ≥ 0, w ≥ 0, zᵀw ≈ 0 and w = M z + q, scaled by the data."""
    M, q, z, w = (np.asarray(a, dtype=np.float64) for a in (M, q, z, w))
    scale = 1.0 + np.abs(q).max(axis=-1) + np.abs(M).max(axis=(-1, -2)) * np.abs(z).max(axis=-1)
    Mz = np.einsum("bij,bj->bi", M, z)
    assert np.all(np.abs(w - (Mz + q)).max(axis=-1)[ok] <= tol * scale[ok])
    assert np.all(z.min(axis=-1)[ok] >= -tol * scale[ok])
    assert np.all(w.min(axis=-1)[ok] >= -tol * scale[ok])
    assert np.all(np.abs(np.einsum("bi,bi->b", z, w))[ok] <= tol * scale[ok] ** 2)


def random_pd_batch(rng, b, n, dtype=np.float64):
    """b problems of size n with M = A Aᵀ + I (positive definite: one solution)."""
    A = rng.standard_normal((b, n, n))
    M = A @ A.transpose(0, 2, 1) + np.eye(n)
    q = rng.standard_normal((b, n)) * 3
    return M.astype(dtype), q.astype(dtype)
