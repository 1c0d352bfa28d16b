"""``lcpbatch.jax.solve`` through the XLA FFI handlers (``lcpbatch_solve``,
``lcpbatch_vjp``): the same z, w, statuses and gradients as the
``pure_callback`` path, bit for bit (float64 and float32, eager, under
``jit`` and under ``vmap``), the same error messages, and every bad
argument a caller of ``jax.ffi.ffi_call`` can pass refused with a message
naming it. JAX (CPU) is installed in CI."""

import ctypes
import warnings

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import lcpbatch
from conftest import gpu_solver_or_skip, random_pd_batch

jax.config.update("jax_enable_x64", True)

import lcpbatch.jax as lj  # noqa: E402


def problems(dtype):
    """Random PD problems of n = 2, then one without a solution (M = −I,
    q = −1: w = −z − 1 < 0) and one with a weakly active contact."""
    M, q = random_pd_batch(np.random.default_rng(25), 40, 2)
    M = np.concatenate([M, [-np.eye(2), np.eye(2)]]).astype(dtype)
    q = np.concatenate([q, [[-1.0, -1.0], [-1.0, 0.0]]]).astype(dtype)
    return M, q


def solve_and_pull(M, q, c, d, transform=lambda f: f):
    """z, w and the gradients of c·z + d·w (NaN rows kept: jax.vjp with
    the cotangents directly)."""

    def run(M, q, c, d):
        (z, w), pull = jax.vjp(lambda M, q: lj.solve(M, q, backend="cpu"), M, q)
        return (z, w) + pull((c, d))

    return [np.asarray(x) for x in transform(run)(M, q, c, d)]


def both_paths(monkeypatch, *args, **kwargs):
    out = {}
    for ffi in (True, False):
        monkeypatch.setattr(lj, "_USE_FFI", ffi)
        out[ffi] = solve_and_pull(*args, **kwargs)
    return out[True], out[False]


def assert_bitwise_equal(got, want):
    for g, w in zip(got, want):
        assert g.dtype == w.dtype and g.shape == w.shape
        assert np.array_equal(g, w, equal_nan=True), np.abs(g - w).max()


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_ffi_path_equals_the_callback_path_bit_for_bit(monkeypatch, dtype):
    assert lj._ffi_ready()
    M, q = problems(dtype)
    rng = np.random.default_rng(26)
    c, d = (rng.standard_normal(q.shape).astype(dtype) for _ in range(2))
    ffi, callback = both_paths(monkeypatch, M, q, c, d)
    assert_bitwise_equal(ffi, callback)
    z, w, gM, gq = ffi
    assert np.isnan(z[-2]).all() and np.isnan(gM[-2]).all() and np.isfinite(z[:-2]).all()
    # Under jit, and under vmap over a leading axis (one call of the batch).
    assert_bitwise_equal(both_paths(monkeypatch, M, q, c, d, jax.jit)[0], callback)
    split = [x.reshape((2, -1) + x.shape[1:]) for x in (M, q, c, d)]
    mapped = both_paths(monkeypatch, *split, transform=lambda f: jax.jit(jax.vmap(f)))
    assert_bitwise_equal(mapped[0], mapped[1])
    assert_bitwise_equal([x.reshape(y.shape) for x, y in zip(mapped[0], callback)], callback)


def test_on_the_gpu_backend_the_ffi_path_equals_the_callbacks(monkeypatch):
    """The handler drives the solver's device as the callbacks do (lavapipe
    here): the same z and gradients, bit for bit."""
    settings = dict(backend="gpu", precision=gpu_solver_or_skip().settings["precision"])
    M, q = random_pd_batch(np.random.default_rng(27), 64, 4)
    out = {}
    for ffi in (True, False):
        monkeypatch.setattr(lj, "_USE_FFI", ffi)
        z = lj.solve(M, q, **settings)[0]
        g = jax.grad(lambda q: jnp.sum(lj.solve(M, q, **settings)[0]))(q)
        out[ffi] = [np.asarray(z), np.asarray(g)]
    assert_bitwise_equal(out[True], out[False])
    np.testing.assert_allclose(out[True][0], lcpbatch.solve(M, q, backend="cpu").z, atol=1e-9)


def test_device_trouble_warns_once_and_the_handler_solves_on_the_cpu():
    """A solver whose GPU is not there warns once (when it is made) and
    solves on the CPU; the handler's report of that fallback goes back to
    the same once-only warning (through the GIL) and raises nothing."""
    M, q = problems(np.float64)
    with pytest.warns(lcpbatch.DeviceWarning, match="solving on the CPU"):
        z = lj.solve(M, q, backend="gpu", adapter="no-such-adapter-anywhere")[0]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        z2 = jax.jit(lambda M, q: lj.solve(M, q, backend="gpu", adapter="no-such-adapter-anywhere")[0])(M, q)
    want = lcpbatch.solve(M, q, backend="cpu").z
    want[-2] = np.nan
    assert np.array_equal(np.asarray(z), want, equal_nan=True) and np.array_equal(np.asarray(z2), np.asarray(z),
                                                                                    equal_nan=True)


def solver_of(M, q):
    """The id of the solver that lcpbatch.jax.solve(M, q, backend="cpu")
    registers for the handler."""
    lj.solve(M, q, backend="cpu")
    return lj._FFI_SOLVERS[(("backend", "cpu"),)][1]


def test_without_jax_ffi_the_callbacks_solve(monkeypatch):
    """A JAX without ``jax.ffi`` (or a GPU default backend) takes the
    ``pure_callback`` path: no custom call in the program, the same z."""
    M, q = problems(np.float64)
    want = lcpbatch.solve(M, q, backend="cpu").z
    want[-2] = np.nan  # no solution: NaN from the adapters
    monkeypatch.setattr(lj, "_jax_ffi", None)
    assert not lj._ffi_ready()
    f = jax.jit(lambda M, q: lj.solve(M, q, backend="cpu")[0])
    assert "lcpbatch_solve" not in f.lower(M, q).as_text()
    assert np.array_equal(np.asarray(f(M, q)), want, equal_nan=True)


def raw_solve(M, q, solver_id, out=None):
    """The handler called directly, as any jax.ffi.ffi_call may call it."""
    q = jnp.asarray(q)
    out = out or (jax.ShapeDtypeStruct(q.shape, q.dtype),) * 2 + (jax.ShapeDtypeStruct(q.shape[:-1], np.int8),)
    return jax.ffi.ffi_call("lcpbatch_solve", out)(M, q, solver=np.int64(solver_id))


def test_the_handlers_status_is_the_solves():
    M, q = problems(np.float64)
    z, w, status = raw_solve(M, q, solver_of(M, q))
    r = lcpbatch.solve(M, q, backend="cpu")
    assert np.array_equal(np.asarray(status), r.status)
    assert r.status[-2] == lcpbatch.Status.NO_SOLUTION and np.isnan(np.asarray(z)[-2]).all()
    assert np.array_equal(np.asarray(z)[:-2], r.z[:-2]) and np.array_equal(np.asarray(w)[:-2], r.w[:-2])


def test_bad_arguments_are_refused_naming_them():
    M, q = problems(np.float64)
    solver_id = solver_of(M, q)
    f64 = lambda *shape: jax.ShapeDtypeStruct(shape, np.float64)  # noqa: E731
    cases = [
        (dict(M=M.astype(np.int32)), r"M: expected float32 or float64, got int32"),
        (dict(q=q.astype(np.float32)), r"q: expected float64 of shape \(42, 2\) .*got float32 of shape \(42, 2\)"),
        (dict(q=q[:, :1]), r"q: expected float64 of shape \(42, 2\) .*got float64 of shape \(42, 1\)"),
        (dict(M=M[:, :1]), r"M: expected shape \(\.\.\., n, n\), got \(42, 1, 2\)"),
        (dict(out=(f64(42, 3), f64(42, 2), jax.ShapeDtypeStruct((42,), np.int8))), r"z: expected float64 of shape"),
        (dict(out=(f64(42, 2), f64(42, 2), f64(42))), r"status: expected int8 of shape \(42,\)"),
        (dict(out=(f64(42, 2), f64(42, 2))), r"results: expected 3 \(z, w, status\), got 2"),
        (dict(solver_id=10_000), r"solver: no solver registered as 10000"),
        (dict(M=np.zeros((2, 0, 0)), q=np.zeros((2, 0))), r"M: n = 0: every problem needs at least one row"),
    ]
    for change, message in cases:
        args = {"M": M, "q": q, "solver_id": solver_id, **change}
        with pytest.raises(Exception, match=message):
            np.asarray(raw_solve(**args)[0])
    q_ = jnp.asarray(q)
    out = (jax.ShapeDtypeStruct(q.shape, q.dtype),) * 2 + (jax.ShapeDtypeStruct(q.shape[:-1], np.int8),)
    with pytest.raises(Exception, match=r"solver: missing attribute"):
        np.asarray(jax.ffi.ffi_call("lcpbatch_solve", out)(M, q_)[0])
    with pytest.raises(Exception, match=r"solver: expected a int64 scalar attribute"):
        np.asarray(jax.ffi.ffi_call("lcpbatch_solve", out)(M, q_, solver=np.float64(0.5))[0])
    # The VJP's handler: a ∂L/∂z of another dtype, a tolerance of the wrong type.
    z = q_
    grads = (jax.ShapeDtypeStruct(M.shape, M.dtype), jax.ShapeDtypeStruct(q.shape, q.dtype))
    vjp = jax.ffi.ffi_call("lcpbatch_vjp", grads)
    with pytest.raises(Exception, match=r"dz: expected float64 of shape \(42, 2\) .*got float32"):
        np.asarray(vjp(M, q_, z, z.astype(np.float32), z, tolerance=1e-8)[0])
    with pytest.raises(Exception, match=r"tolerance: expected a float64 scalar attribute"):
        np.asarray(vjp(M, q_, z, z, z, tolerance=np.int64(1))[0])
    with pytest.raises(Exception, match=r"arguments: expected 5 \(M, q, z, dz, dw\), got 4"):
        np.asarray(vjp(M, q_, z, z, tolerance=1e-8)[0])


def test_errors_are_the_callback_paths(monkeypatch):
    M, q = problems(np.float64)
    bad = M.copy()
    bad[1, 0, 1] = np.nan
    dz = np.ones(q.shape)
    dz[3, 0] = np.inf
    for ffi in (True, False):
        monkeypatch.setattr(lj, "_USE_FFI", ffi)
        with pytest.raises(Exception, match=r"M\[1, 0, 1\] is NaN: every entry of M must be finite"):
            np.asarray(lj.solve(bad, q, backend="cpu")[0])
        # Problem by problem, M[b] before q[b]: q[0] is named before M[1].
        bad_q = q.copy()
        bad_q[0, 1] = np.nan
        with pytest.raises(Exception, match=r"q\[0, 1\] is NaN: every entry of q must be finite"):
            np.asarray(lj.solve(bad, bad_q, backend="cpu")[0])
        _, pull = jax.vjp(lambda q: lj.solve(M[:40], q, backend="cpu")[0], jnp.asarray(q[:40]))
        with pytest.raises(Exception, match=r"island 3.*dz\[0\].*not a finite number"):
            np.asarray(pull(jnp.asarray(dz[:40]))[0])
        # Nothing to solve (an empty batch, n = 0): empty arrays, no error.
        for b, n in ((0, 3), (2, 0)):
            z, w = lj.solve(np.zeros((b, n, n)), np.zeros((b, n)), backend="cpu")
            assert z.shape == w.shape == (b, n)


class _ExtensionBase(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("kind", ctypes.c_int), ("next", ctypes.c_void_p)]


class _ApiVersion(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("extension_start", ctypes.c_void_p),
                ("major", ctypes.c_int), ("minor", ctypes.c_int)]


class _Metadata(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("api_version", _ApiVersion), ("traits", ctypes.c_uint32),
                ("state_type_id", ctypes.c_int64)]


class _MetadataExtension(ctypes.Structure):
    _fields_ = [("base", _ExtensionBase), ("metadata", ctypes.POINTER(_Metadata))]


class _List(ctypes.Structure):  # XLA_FFI_Args, XLA_FFI_Rets and (one more pointer) XLA_FFI_Attrs
    _fields_ = [("struct_size", ctypes.c_size_t), ("extension_start", ctypes.c_void_p), ("size", ctypes.c_int64),
                ("types", ctypes.c_void_p), ("items", ctypes.c_void_p)]


class _Attrs(ctypes.Structure):
    _fields_ = _List._fields_ + [("attrs", ctypes.c_void_p)]


class _CallFrame(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("extension_start", ctypes.c_void_p), ("api", ctypes.c_void_p),
                ("ctx", ctypes.c_void_p), ("stage", ctypes.c_int), ("args", _List), ("rets", _List),
                ("attrs", _Attrs), ("future", ctypes.c_void_p)]


def _handler(name):
    """The handler's function pointer out of its capsule, callable from ctypes."""
    get = ctypes.pythonapi.PyCapsule_GetPointer
    get.restype, get.argtypes = ctypes.c_void_p, (ctypes.py_object, ctypes.c_char_p)
    pointer = get(lcpbatch._native.ffi_targets()[name], None)
    return ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.POINTER(_CallFrame))(pointer)


@pytest.mark.parametrize("name", ["lcpbatch_solve", "lcpbatch_vjp"])
def test_the_handlers_answer_xlas_metadata_query_and_skip_stages_before_execute(name):
    """Called as XLA calls them (c_api.h's structs, by ctypes): the metadata
    extension gets the API version 0.3, no traits, no state; a stage before
    `execute` does nothing and reads no argument (none are given)."""
    handler = _handler(name)
    header_size = _CallFrame.future.offset  # XLA_FFI_CallFrame_STRUCT_SIZE: up to `attrs`
    metadata = _Metadata(struct_size=ctypes.sizeof(_Metadata), traits=99, state_type_id=7)
    ext = _MetadataExtension(base=_ExtensionBase(ctypes.sizeof(_MetadataExtension), 1, None),
                             metadata=ctypes.pointer(metadata))
    frame = _CallFrame(struct_size=header_size, extension_start=ctypes.addressof(ext), stage=3)
    assert handler(ctypes.byref(frame)) is None  # no error
    v = metadata.api_version
    assert (v.struct_size, v.major, v.minor) == (ctypes.sizeof(_ApiVersion), 0, 3)
    assert (metadata.traits, metadata.state_type_id) == (0, 0)
    for stage in (0, 1, 2):  # instantiate, prepare, initialize
        assert handler(ctypes.byref(_CallFrame(struct_size=header_size, stage=stage))) is None
