"""LCP batches through lcpbatch.solve and lcpbatch.Solver: small LCPs worked
by hand, random batches checked in NumPy, dtypes and memory layouts,
ragged batches, methods, warm start, chunks and the report."""

import numpy as np
import pytest

import lcpbatch
from lcpbatch import Status

from conftest import assert_lcp_solutions, random_pd_batch

SEED_002_M = np.array([[0.0, -1.0, 2.0], [2.0, 0.0, -2.0], [-1.0, 1.0, 0.0]])


@pytest.mark.parametrize("solver", ["auto", "enum", "lemke", "pgs"])
def test_seed_000_two_by_two(solver):
    # Two coupled contacts: M = [[2, 1], [1, 2]], q = (−5, −6). Both active:
    # 2 z1 + z2 = 5 and z1 + 2 z2 = 6 give z = (4/3, 7/3), w = 0.
    r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]),
                       method=solver, backend="cpu")
    tol = 1e-8 if solver == "pgs" else 1e-12
    assert r.status.tolist() == [Status.SOLVED]
    np.testing.assert_allclose(r.z[0], [4 / 3, 7 / 3], atol=tol)
    np.testing.assert_allclose(r.w[0], [0.0, 0.0], atol=tol)
    assert r.error[0] < 1e-8
    if solver != "pgs":
        assert r.basis.tolist() == [[True, True]] and r.has_basis.all()


@pytest.mark.parametrize("solver", ["auto", "enum", "lemke"])
def test_seed_002_lemke_walkthrough(solver):
    # A 3×3 walk-through of Lemke's method (Lemke 1965; src/tests/seeds.rs),
    # non-symmetric M with zero diagonal: q = (−3, 6, −1) gives z = (0, 1, 3):
    # w1 = −z2 + 2 z3 − 3 = 2, w2 = 2 z1 − 2 z3 + 6 = 0, w3 = −z1 + z2 − 1 = 0.
    # With the sign of q3 flipped, q = (−3, 6, 1) gives z = (1, 0, 1.5),
    # w = (0, 5, 0).
    M = np.stack([SEED_002_M, SEED_002_M])
    q = np.array([[-3.0, 6.0, -1.0], [-3.0, 6.0, 1.0]])
    r = lcpbatch.solve(M, q, method=solver, backend="cpu")
    assert r.status_names().tolist() == ["solved", "solved"]
    np.testing.assert_allclose(r.z, [[0, 1, 3], [1, 0, 1.5]], atol=1e-12)
    np.testing.assert_allclose(r.w, [[2, 0, 0], [0, 5, 0]], atol=1e-12)
    assert r.basis[0].tolist() == [False, True, True]
    if solver == "lemke":
        # Lemke's walk by hand: z0 in, z1 in, z3 in, w1 in, z2 in.
        assert r.pivots[0] == 5


def test_seed_002_with_all_solutions_is_unique():
    r = lcpbatch.solve(SEED_002_M[None], np.array([[-3.0, 6.0, -1.0]]), all_solutions=True, method="enum")
    assert r.status[0] == Status.SOLVED
    assert r.solution_set == ["isolated"] and r.solution_count.tolist() == [1]
    assert r.all_z[0].shape == (1, 3) and r.all_basis[0].tolist() == [[False, True, True]]
    np.testing.assert_allclose(r.all_z[0], [[0.0, 1.0, 3.0]], atol=1e-12)
    assert lcpbatch.solve(SEED_002_M[None], np.array([[-3.0, 6.0, -1.0]])).all_z is None


def test_all_solutions_of_a_degenerate_problem():
    # M = [[1, 1], [1, 1]], q = (−1, −1): every z ≥ 0 with z1 + z2 = 1 solves it
    # (a segment); the bases {1}, {2} give its ends (1, 0) and (0, 1).
    r = lcpbatch.solve(np.ones((1, 2, 2)), -np.ones((1, 2)), all_solutions=True, method="enum")
    assert r.solution_set == ["bounded_continuum"] and r.solution_count.tolist() == [-1]
    ends = sorted(map(tuple, np.round(r.all_z[0], 12).tolist()))
    assert (0.0, 1.0) in ends and (1.0, 0.0) in ends


def test_random_batches_are_solutions_checked_in_numpy():
    rng = np.random.default_rng(1)
    for n in (1, 3, 8):
        M, q = random_pd_batch(rng, 300, n)
        r = lcpbatch.Solver(backend="cpu").solve(M, q)
        assert r.ok.all(), r.report
        assert r.z.shape == r.w.shape == r.basis.shape == (300, n)
        assert r.status.shape == r.error.shape == (300,)
        assert_lcp_solutions(M, q, r.z, r.w, r.ok)
        # The basis is where z carries impulse (z_i > 0 only if basic).
        assert not np.any((r.z > 1e-12) & ~r.basis)


def test_general_matrices_every_answer_that_claims_a_solution_is_one():
    rng = np.random.default_rng(2)
    M = rng.standard_normal((500, 4, 4))
    q = rng.standard_normal((500, 4))
    r = lcpbatch.solve(M, q, backend="cpu", method="enum")
    assert set(r.status.tolist()) <= {Status.SOLVED, Status.NO_SOLUTION}
    assert r.ok.sum() > 100
    assert_lcp_solutions(M, q, r.z, r.w, r.ok)


def test_float32_input_is_solved_in_f64():
    rng = np.random.default_rng(3)
    M, q = random_pd_batch(rng, 50, 4, np.float32)
    r32 = lcpbatch.solve(M, q, backend="cpu")
    r64 = lcpbatch.solve(M.astype(np.float64), q.astype(np.float64), backend="cpu")
    assert r32.z.dtype == np.float64
    np.testing.assert_array_equal(r32.z, r64.z)
    assert_lcp_solutions(M, q, r32.z, r32.w, r32.ok)


def test_fortran_order_and_strided_views_give_the_same_answers():
    rng = np.random.default_rng(4)
    M, q = random_pd_batch(rng, 40, 5)
    ref = lcpbatch.solve(M, q, backend="cpu")
    fortran = lcpbatch.solve(np.asfortranarray(M), np.asfortranarray(q), backend="cpu")
    np.testing.assert_array_equal(fortran.z, ref.z)
    # Every other problem, through a strided view, and M given as its transpose's transpose.
    big_M = np.zeros((80, 5, 7))
    big_M[::2, :, 1:6] = M
    big_q = np.zeros((80, 10))
    big_q[::2, ::2] = q
    view = lcpbatch.solve(big_M[::2, :, 1:6], big_q[::2, ::2], backend="cpu")
    assert not big_M[::2, :, 1:6].flags.c_contiguous
    np.testing.assert_array_equal(view.z, ref.z)
    mt = np.ascontiguousarray(M.transpose(0, 2, 1)).transpose(0, 2, 1)
    np.testing.assert_array_equal(lcpbatch.solve(mt, q, backend="cpu").z, ref.z)
    # Integers and nested lists of numbers are read as NumPy reads them.
    for r in (lcpbatch.solve([[[2, 1], [1, 2]]], [[-5, -6]]),
              lcpbatch.solve(np.array([[[2, 1], [1, 2]]]), np.array([[-5, -6]]))):
        assert not r.ragged
        np.testing.assert_allclose(r.z, [[4 / 3, 7 / 3]])


def test_a_batch_read_in_place_gives_the_copied_batchs_full_result():
    # C order is read in place by the library; Fortran order is copied into
    # one problem each: every field of the result is the same bits.
    rng = np.random.default_rng(12)
    M, q = random_pd_batch(rng, 300, 6)
    M[::7] -= 3 * np.eye(6)  # some without a (unique) solution
    ids = np.arange(300 * 6, dtype=np.uint64).reshape(300, 6)
    a = lcpbatch.Solver(backend="cpu", warm_start=True)
    b = lcpbatch.Solver(backend="cpu", warm_start=True)
    for _ in range(2):
        c_order = a.solve(M, q, ids=ids)
        copied = b.solve(np.asfortranarray(M), np.asfortranarray(q), ids=np.asfortranarray(ids))
        for field in ("z", "w", "basis", "status", "path", "error", "pivots", "bases_visited"):
            np.testing.assert_array_equal(getattr(c_order, field), getattr(copied, field), err_msg=field)
        assert c_order.report.statuses == copied.report.statuses
    assert c_order.report.counts["warm_start"] > 0


def test_a_keyed_batch_of_several_chunks_is_checked_before_any_is_remembered():
    # n = 16: 128 problems a chunk (CHUNK_WORK), so 300 problems are 3 chunks.
    rng = np.random.default_rng(13)
    M, q = random_pd_batch(rng, 300, 16)
    ids = np.arange(300 * 16).reshape(300, 16)
    s = lcpbatch.Solver(backend="cpu", warm_start=True)
    bad = q.copy()
    bad[290, 3] = np.nan
    with pytest.raises(ValueError, match=r"q\[290, 3\] is NaN: every entry of q must be finite"):
        s.solve(M, bad, ids=ids)
    # Nothing of the first two chunks was remembered.
    assert s.solve(M, q, ids=ids).report.counts["warm_start"] == 0
    assert s.solve(M, q, ids=ids).report.counts["warm_start"] > 0


def test_ragged_batches_give_lists_in_order():
    rng = np.random.default_rng(5)
    ms, qs = [], []
    for n in (3, 1, 6, 2):
        M, q = random_pd_batch(rng, 1, n)
        ms.append(M[0])
        qs.append(q[0])
    r = lcpbatch.Solver(backend="cpu").solve(ms, qs)
    assert r.ragged and [len(z) for z in r.z] == [3, 1, 6, 2]
    for M, q, z, w in zip(ms, qs, r.z, r.w):
        assert_lcp_solutions(M[None], q[None], z[None], w[None], np.array([True]))
        single = lcpbatch.solve(M[None], q[None], backend="cpu")
        np.testing.assert_array_equal(single.z[0], z)


def test_empty_batches():
    r = lcpbatch.solve(np.zeros((0, 3, 3)), np.zeros((0, 3)))
    assert r.z.shape == (0, 3) and len(r) == 0 and r.report.statuses["solved"] == 0
    assert lcpbatch.solve([], []).z == []


def test_solver_reuse_keeps_one_device_and_warm_starts_by_ids():
    rng = np.random.default_rng(6)
    M, q = random_pd_batch(rng, 64, 4)
    # Singular M (rank 1): no predicted basis, so warm start is what settles it.
    s = lcpbatch.Solver(backend="cpu", method="enum", warm_start=True)
    ids = np.arange(64 * 4).reshape(64, 4)
    first = s.solve(M, q, ids=ids)
    second = s.solve(M, q, ids=ids)
    np.testing.assert_array_equal(first.z, second.z)
    assert (second.path == "warm_start").sum() >= (first.path == "warm_start").sum()
    assert second.report.counts["warm_start"] == (second.path == "warm_start").sum() > 0
    s.clear_warm_start()
    third = s.solve(M, q, ids=ids)
    assert third.report.counts["warm_start"] == 0
    # Different ids: nothing remembered for them.
    fresh = s.solve(M, q, ids=ids + 10_000)
    assert fresh.report.counts["warm_start"] == 0
    # The module function keeps its solver per settings: warm_start=ids works across calls.
    lcpbatch.solve(M, q, warm_start=ids + 20_000, backend="cpu", method="enum")
    again = lcpbatch.solve(M, q, warm_start=ids + 20_000, backend="cpu", method="enum")
    assert again.report.counts["warm_start"] > 0


def test_methods_and_counters():
    rng = np.random.default_rng(7)
    M, q = random_pd_batch(rng, 20, 6)
    lemke = lcpbatch.solve(M, q, method="lemke", backend="cpu")
    pgs = lcpbatch.solve(M, q, method="pgs", backend="cpu", pgs_max_sweeps=100_000)
    enum = lcpbatch.solve(M, q, method="enum", backend="cpu", predict=False)
    assert (lemke.path == "lemke").all() and (lemke.pivots > 0).any()
    assert (pgs.path == "pgs").all() and (pgs.iterations > 0).any() and not pgs.has_basis.any()
    assert (enum.path == "enumerated_cpu").all() and (enum.bases_visited > 0).all()
    np.testing.assert_allclose(lemke.z, enum.z, atol=1e-10)
    np.testing.assert_allclose(pgs.z[pgs.ok], enum.z[pgs.ok], atol=1e-6)


def test_chunks_cover_a_large_batch_in_order():
    # 70,000 problems of n = 1 exceed CHUNK_PROBLEMS: two library calls, one report.
    q = -np.arange(1, 70_001, dtype=np.float64)[:, None]
    M = np.full((70_000, 1, 1), 2.0)
    r = lcpbatch.solve(M, q, backend="cpu")
    assert r.report.chunks == 2 and lcpbatch.CHUNK_PROBLEMS == 65_536
    np.testing.assert_allclose(r.z[:, 0], np.arange(1, 70_001) / 2.0)
    assert r.report.statuses["solved"] == 70_000 == r.report.counts["single_contact"]
    assert r.report.max_error_index is not None and 0 <= r.report.max_error_index < 70_000
    # Work per chunk: 2^n per problem, at most CHUNK_WORK.
    n = 12
    per_chunk = lcpbatch.CHUNK_WORK // 2**n
    M = np.broadcast_to(np.eye(n), (per_chunk + 1, n, n))
    r = lcpbatch.solve(M, np.ones((per_chunk + 1, n)), backend="cpu")
    assert r.report.chunks == 2 and (r.path == "separating").all()


def test_warm_start_covers_every_chunk_and_forgets_after_warm_start_calls():
    # M = [[1, 1], [1, 1]], q = (−1, −1) (rank one: no predicted basis, only
    # the warm start settles it), 140,000 times: three chunks of at most
    # CHUNK_PROBLEMS, one library call each, counted as one call of memory.
    b = 140_000
    M = np.broadcast_to(np.ones((2, 2)), (b, 2, 2))
    q = np.full((b, 2), -1.0)
    x = np.arange(2 * b).reshape(b, 2)
    y, z = x + 2 * b, x + 4 * b

    def warm(s, ids):
        r = s.solve(M, q, ids=ids)
        assert r.report.chunks == 3 and r.ok.all()
        return r.path == "warm_start"

    s = lcpbatch.Solver(backend="cpu", method="enum", warm_start=True)
    assert not warm(s, x).any()
    assert warm(s, x).all()  # every chunk, the first one included
    assert not warm(s, y).any() and not warm(s, x).any()  # default: the last call only
    two = lcpbatch.Solver(backend="cpu", method="enum", warm_start=True, warm_start_calls=2)
    assert two.settings["warm_start_calls"] == 2
    assert not warm(two, x).any() and not warm(two, y).any()
    assert warm(two, x).all()  # seen two calls ago: kept
    assert not warm(two, z).any() and warm(two, z).all()
    assert not warm(two, x).any()  # seen three calls ago: forgotten


def test_report_reads_well():
    r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]), backend="cpu")
    text = repr(r.report)
    assert "device: cpu" in text and "statuses: solved 1" in text and "time: total" in text
    assert r.report.device_kind == "cpu" and r.report.fallback is None
    assert set(r.report.timings) >= {"total", "solve"} and r.report.counts["predicted_basis"] == 1
    assert "1 problems" in repr(r) and "solved 1" in repr(r)
    assert r.report.to_dict()["statuses"]["solved"] == 1


def test_results_pickle():
    import pickle

    r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))
    back = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(back.z, r.z)
    assert str(back.report) == str(r.report)
    s = pickle.loads(pickle.dumps(lcpbatch.Solver(backend="cpu", method="lemke")))
    assert s.settings["method"] == "lemke"
