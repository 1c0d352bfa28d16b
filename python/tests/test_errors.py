"""Bad input raises ValueError or TypeError naming the argument, the index
and what is wrong; bad settings name the setting; no panic reaches Python."""

import numpy as np
import pytest

import lcpbatch

M2 = np.array([[[2.0, 1.0], [1.0, 2.0]]])
Q2 = np.array([[-5.0, -6.0]])


@pytest.mark.parametrize(
    "M, q, match",
    [
        (np.zeros((2, 3)), np.zeros((2,)), r"M: expected shape \(B, n, n\), got \(2, 3\)"),
        (np.zeros((1, 2, 3)), np.zeros((1, 2)), r"M: expected shape \(B, n, n\)"),
        (np.zeros((2, 2, 2)), np.zeros((2, 3)), r"q: expected shape \(2, 2\)"),
        (np.zeros((2, 2, 2)), np.zeros((3, 2)), r"q: expected shape \(2, 2\).*got \(3, 2\)"),
    ],
)
def test_shapes_are_named(M, q, match):
    with pytest.raises(ValueError, match=match):
        lcpbatch.solve(M, q)


def test_non_finite_entries_name_the_problem_and_entry():
    M = np.repeat(M2, 4, axis=0)
    q = np.repeat(Q2, 4, axis=0)
    M[2, 0, 1] = np.nan
    with pytest.raises(ValueError, match=r"M\[2, 0, 1\] is NaN: every entry of M must be finite"):
        lcpbatch.solve(M, q)
    M[2, 0, 1] = 1.0
    q[3, 1] = np.inf
    with pytest.raises(ValueError, match=r"q\[3, 1\] is inf"):
        lcpbatch.solve(M, q)
    with pytest.raises(ValueError, match=r"M\[1\]\[1, 0\] is NaN"):
        lcpbatch.solve([M2[0], np.array([[1.0, 0.0], [np.nan, 1.0]])], [Q2[0], Q2[0]])


def test_dtypes_are_type_errors():
    with pytest.raises(TypeError, match="M: dtype complex128 is not a real number type"):
        lcpbatch.solve(M2.astype(complex), Q2)
    with pytest.raises(TypeError, match="q: dtype <U1"):
        lcpbatch.solve(M2, np.array([["a", "b"]]))
    with pytest.raises(TypeError, match=r"M\[0\]: dtype bool"):
        lcpbatch.solve([np.eye(2, dtype=bool)], [np.zeros(2)])
    with pytest.raises(TypeError, match="ids: dtype float64 is not an integer type"):
        lcpbatch.Solver(warm_start=True).solve(M2, Q2, ids=np.zeros((1, 2)))


def test_nested_lists_of_different_sizes_point_to_the_ragged_form():
    with pytest.raises(ValueError, match="give a list of NumPy arrays"):
        lcpbatch.solve([[[1.0]], [[1.0, 0.0], [0.0, 1.0]]], [[1.0], [1.0, 1.0]])


def test_ragged_and_id_mismatches():
    with pytest.raises(ValueError, match=r"q\[1\]: expected shape \(1,\) to match M\[1\]"):
        lcpbatch.solve([np.eye(2), np.eye(1)], [np.zeros(2), np.zeros(2)])
    with pytest.raises(ValueError, match=r"M\[0\]: expected a square"):
        lcpbatch.solve([np.zeros((2, 3))], [np.zeros(2)])
    with pytest.raises(ValueError, match="q: M is a list of 2 problems"):
        lcpbatch.solve([np.eye(2), np.eye(1)], np.zeros(2))
    with pytest.raises(ValueError, match=r"ids: expected shape \(1, 2\)"):
        lcpbatch.Solver(warm_start=True).solve(M2, Q2, ids=np.zeros((1, 3), dtype=int))
    with pytest.raises(ValueError, match=r"ids\[0, 1\] is -4: contact ids must be ≥ 0"):
        lcpbatch.Solver(warm_start=True).solve(M2, Q2, ids=np.array([[1, -4]]))


def test_warm_start_takes_ids_not_a_flag():
    with pytest.raises(TypeError, match="warm_start: give the contact ids"):
        lcpbatch.solve(M2, Q2, warm_start=True)
    assert lcpbatch.solve(M2, Q2, warm_start=False).ok.all()


def test_n_too_large_for_enumeration_names_the_problem():
    big = np.eye(21)[None]
    with pytest.raises(ValueError, match=r"M\[1\]: n = 21 is too large for enumeration"):
        lcpbatch.solve([np.eye(2), big[0]], [np.zeros(2), -np.ones(21)], method="enum", backend="cpu")
    with pytest.raises(ValueError, match="too large for enumeration"):
        lcpbatch.solve(big, -np.ones((1, 21)), method="enum", backend="cpu")
    # The default solver takes it (Lemke above the enumeration's limit).
    r = lcpbatch.solve(big, -np.ones((1, 21)), backend="cpu")
    np.testing.assert_allclose(r.z, np.ones((1, 21)))


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(backend="tpu"), r"backend: 'tpu' is not one of"),
        (dict(method="simplex"), r"method: 'simplex' is not one of"),
        (dict(precision="f16"), r"precision: 'f16' is not one of"),
        (dict(api="cuda"), r"api: 'cuda' is not one of"),
        (dict(tolerance=2.0), r"tolerance.*2 is not in \(0, 1\)"),
        (dict(pgs_max_sweeps=0), "pgs_max_sweeps"),
        (dict(all_solutions=True, method="lemke"), "all_solutions"),
        (dict(backend="gpu", method="pgs"), "backend"),
        (dict(threads=-1), "threads: -1 is negative"),
        (dict(warm_start_calls=0), r"warm_start_calls: 0 is not an integer ≥ 1"),
        (dict(warm_start_calls=-3), r"warm_start_calls: -3 is not an integer ≥ 1"),
    ],
)
def test_bad_settings_name_the_setting(kwargs, match):
    with pytest.raises(ValueError, match=match):
        lcpbatch.Solver(**kwargs)


def test_wrong_types_of_settings_are_type_errors():
    with pytest.raises(TypeError):
        lcpbatch.Solver(threads="many")
    with pytest.raises(TypeError, match="warm_start_calls: expected an integer ≥ 1, got float"):
        lcpbatch.Solver(warm_start_calls=1.5)


def test_a_panic_becomes_a_runtime_error():
    with pytest.raises(RuntimeError, match="internal error.*deliberate panic"):
        lcpbatch._native._panic_for_test()
    # The module still works afterwards.
    assert lcpbatch.solve(M2, Q2).ok.all()
