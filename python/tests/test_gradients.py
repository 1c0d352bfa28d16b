"""Gradients of the solve: ``lcpbatch.lcp_vjp`` (the library's VJP),
``lcpbatch.scene_vjp`` (through assembly, against solve_scenes),
``lcpbatch.jax.solve`` and ``lcpbatch.torch.solve``. The VJP equals central
finite differences of the solve on seeded batches at points whose active
set is stable within the step; the adapters give the VJP's numbers, under
``jit`` and ``vmap`` too; degenerate islands are flagged; importing
lcpbatch imports neither JAX nor PyTorch. JAX (CPU) is installed in CI;
the PyTorch tests run where torch is installed."""

import doctest
import importlib.util
import subprocess
import sys
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import lcpbatch

from conftest import random_pd_batch

# JAX is not skipped: CI installs it (jax[cpu]); f64 for the comparisons.
jax.config.update("jax_enable_x64", True)

import lcpbatch.jax  # noqa: E402

STEP = 1e-6


def stable_batch(rng, b, n, margin=1e-3):
    """Seeded PD problems whose rows are all strictly active (z_i > margin)
    or strictly inactive (w_i > margin), so that a step of 1e-6 in any
    entry of M or q keeps the active set."""
    M, q = random_pd_batch(rng, 4 * b, n)
    r = lcpbatch.solve(M, q, backend="cpu")
    keep = r.ok & (np.maximum(r.z, r.w).min(axis=1) > margin)
    assert keep.sum() >= b, (n, keep.sum())
    return M[keep][:b], q[keep][:b]


def losses(M, q, c, d):
    """L = c·z + d·w per problem, solved in f64."""
    r = lcpbatch.solve(M, q, backend="cpu")
    assert r.ok.all()
    return np.einsum("bi,bi->b", c, r.z) + np.einsum("bi,bi->b", d, r.w)


def central_differences(M, q, c, d, h=STEP):
    """∂L/∂M and ∂L/∂q by central differences, every perturbed problem of
    the batch solved in one call."""
    b, n = q.shape
    k = n * n + n
    Ms = np.repeat(M[:, None], 2 * k, axis=1)
    qs = np.repeat(q[:, None], 2 * k, axis=1)
    for e in range(k):
        for s, sign in ((2 * e, 1.0), (2 * e + 1, -1.0)):
            if e < n * n:
                Ms[:, s, e // n, e % n] += sign * h
            else:
                qs[:, s, e - n * n] += sign * h
    L = losses(Ms.reshape(-1, n, n), qs.reshape(-1, n), np.repeat(c, 2 * k, axis=0),
               np.repeat(d, 2 * k, axis=0)).reshape(b, k, 2)
    g = (L[:, :, 0] - L[:, :, 1]) / (2 * h)
    return g[:, : n * n].reshape(b, n, n), g[:, n * n:]


def assert_close_relative(got, want, rtol=1e-5):
    """Per problem: max |got − want| ≤ rtol · max(1, max |want|)."""
    b = len(want)
    err = np.abs(got - want).reshape(b, -1).max(axis=1)
    scale = np.maximum(1.0, np.abs(want).reshape(b, -1).max(axis=1))
    assert (err <= rtol * scale).all(), (err / scale).max()


@pytest.mark.parametrize("n", range(1, 9))
def test_lcp_vjp_equals_central_differences(n):
    rng = np.random.default_rng(100 + n)
    M, q = stable_batch(rng, 12, n)
    c, d = rng.standard_normal(q.shape), rng.standard_normal(q.shape)
    z = lcpbatch.solve(M, q, backend="cpu").z
    g = lcpbatch.lcp_vjp(M, q, z, c, d)
    assert g.M.shape == M.shape and g.q.shape == q.shape
    assert g.derivative.tolist() == ["exact"] * len(q)
    fd_m, fd_q = central_differences(M, q, c, d)
    assert_close_relative(g.q, fd_q)
    assert_close_relative(g.M, fd_m)
    # Without dw, w carries nothing back: the gradient of c·z alone.
    g0 = lcpbatch.lcp_vjp(M, q, z, c)
    fd_m0, fd_q0 = central_differences(M, q, c, np.zeros_like(d))
    assert_close_relative(g0.q, fd_q0)
    assert_close_relative(g0.M, fd_m0)


def jax_loss(c, d, **settings):
    def loss(M, q):
        z, w = lcpbatch.jax.solve(M, q, **settings)
        return jnp.sum(c * z) + jnp.sum(d * w)
    return loss


@pytest.mark.parametrize("n", [1, 3, 8])
def test_jax_grad_is_the_rust_vjp_and_central_differences(n):
    rng = np.random.default_rng(200 + n)
    M, q = stable_batch(rng, 10, n)
    c, d = rng.standard_normal(q.shape), rng.standard_normal(q.shape)
    gM, gq = jax.grad(jax_loss(c, d, backend="cpu"), argnums=(0, 1))(jnp.asarray(M), jnp.asarray(q))
    z = lcpbatch.solve(M, q, backend="cpu").z
    g = lcpbatch.lcp_vjp(M, q, z, c, d)
    np.testing.assert_allclose(np.asarray(gM), g.M, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(np.asarray(gq), g.q, rtol=1e-13, atol=1e-13)
    fd_m, fd_q = central_differences(M, q, c, d)
    assert_close_relative(np.asarray(gM), fd_m)
    assert_close_relative(np.asarray(gq), fd_q)


def test_jax_forward_is_the_solve_and_jit_gives_the_same():
    rng = np.random.default_rng(3)
    M, q = random_pd_batch(rng, 50, 4)
    r = lcpbatch.solve(M, q, backend="cpu")
    z, w = lcpbatch.jax.solve(M, q, backend="cpu")
    np.testing.assert_array_equal(np.asarray(z), r.z)
    np.testing.assert_array_equal(np.asarray(w), r.w)
    zj, wj = jax.jit(lambda M, q: lcpbatch.jax.solve(M, q, backend="cpu"))(M, q)
    np.testing.assert_array_equal(np.asarray(zj), r.z)
    c = rng.standard_normal(q.shape)
    loss = jax_loss(c, np.zeros_like(c), backend="cpu")
    g = jax.grad(loss, argnums=(0, 1))(M, q)
    gj = jax.jit(jax.grad(loss, argnums=(0, 1)))(M, q)
    for a, b in zip(g, gj):
        np.testing.assert_allclose(np.asarray(a), np.asarray(b), rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("ffi", [True, False])
def test_jax_vmap_is_one_host_call_and_matches_the_batch(monkeypatch, ffi):
    monkeypatch.setattr(lcpbatch.jax, "_USE_FFI", ffi)
    rng = np.random.default_rng(4)
    M, q = stable_batch(rng, 6, 3)
    c = rng.standard_normal(q.shape)
    calls = []
    forward = lcpbatch._gradient.forward

    def counting(*args):
        calls.append(np.shape(args[1]))
        return forward(*args)

    monkeypatch.setattr(lcpbatch._gradient, "forward", counting)

    def one(M1, q1, c1):  # one problem: M (n, n), q (n,)
        z, _ = lcpbatch.jax.solve(M1, q1, backend="cpu")
        return jnp.sum(c1 * z)

    step = jax.jit(jax.vmap(jax.grad(one, argnums=(0, 1))))
    per_problem = step(M, q, c)
    if ffi:  # one FFI call each of the whole mapped batch (no loop around it)
        hlo = step.lower(M, q, c).as_text()
        assert calls == [] and "while" not in hlo
        for target, m_shape in (("lcpbatch_solve", "6x3x3"), ("lcpbatch_vjp", "6x3x3")):
            lines = [x for x in hlo.splitlines() if f"custom_call @{target}(" in x]
            assert len(lines) == 1 and f": (tensor<{m_shape}xf64>, tensor<6x3xf64>" in lines[0], lines
    else:
        assert calls == [(6, 3)], calls  # broadcast_all: the mapped axis, one call
    batched = jax.grad(jax_loss(c, np.zeros_like(c), backend="cpu"), argnums=(0, 1))(M, q)
    for a, b in zip(per_problem, batched):
        np.testing.assert_allclose(np.asarray(a), np.asarray(b), rtol=1e-13, atol=1e-13)
    # vmap over a batch of batches: (2, 3, n, n), with q mapped and M shared.
    z2, _ = jax.vmap(lambda qq: lcpbatch.jax.solve(M[:3], qq, backend="cpu"))(q.reshape(2, 3, 3))
    want = lcpbatch.solve(np.concatenate([M[:3], M[:3]]), q, backend="cpu").z
    np.testing.assert_array_equal(np.asarray(z2).reshape(6, 3), want)


def test_jax_float32_inputs_give_float32_and_f64_numbers():
    M = np.array([[[2.0, 1.0], [1.0, 2.0]]])
    q = np.array([[-5.0, -6.0]])
    z, w = lcpbatch.jax.solve(jnp.asarray(M, jnp.float32), jnp.asarray(q, jnp.float32))
    assert z.dtype == w.dtype == jnp.float32
    np.testing.assert_allclose(np.asarray(z), [[4 / 3, 7 / 3]], rtol=1e-7)
    g = jax.grad(lambda q: lcpbatch.jax.solve(jnp.asarray(M, jnp.float32), q)[0][0, 0])(jnp.asarray(q, jnp.float32))
    assert g.dtype == jnp.float32
    np.testing.assert_allclose(np.asarray(g), [[-2 / 3, 1 / 3]], rtol=1e-7)


def test_degenerate_islands_are_flagged():
    # 0: strict (exact). 1: M = I, q = (−1, 0): z = (1, 0), w = (0, 0), the
    # second contact touches without pushing (one-sided: kept inactive).
    # 2: M = [[1, 1], [1, 1]] at z = (½, ½), both active, M_αα singular
    # (undefined: zero gradient). 3: z is not a solution (undefined).
    M = np.array([[[2.0, 1.0], [1.0, 2.0]], np.eye(2), np.ones((2, 2)), np.eye(2)])
    q = np.array([[-5.0, -6.0], [-1.0, 0.0], [-1.0, -1.0], [-1.0, -1.0]])
    z = np.array([[4 / 3, 7 / 3], [1.0, 0.0], [0.5, 0.5], [2.0, 0.0]])
    dz = np.ones((4, 2))
    g = lcpbatch.lcp_vjp(M, q, z, dz)
    assert g.derivative.tolist() == ["exact", "one_sided", "undefined", "undefined"]
    assert not g.M[2:].any() and not g.q[2:].any()
    # The one-sided derivative of z₂ = max(0, −q₂) is that of the side that
    # keeps the contact inactive (q₂ growing): 0; z₁ = −q₁ gives −1.
    np.testing.assert_array_equal(g.q[1], [-1.0, 0.0])
    right = lcpbatch.solve(M[1:2], q[1:2] + [0.0, STEP]).z
    assert right[0, 1] == 0.0
    # The adapter gives the same numbers as the VJP at the degenerate island.
    gq = jax.grad(lambda qq: jnp.sum(lcpbatch.jax.solve(M[1:2], qq)[0]))(jnp.asarray(q[1:2]))
    np.testing.assert_array_equal(np.asarray(gq), g.q[1:2])
    assert "one_sided 1" in repr(g) and "undefined 2" in repr(g)


def test_an_island_without_solution_gives_nan_and_leaves_the_others():
    # M = [[−1]], q = [−1] has no solution (w = −z − 1 < 0 for every z ≥ 0).
    M = np.array([[[-1.0]], [[2.0]]])
    q = np.array([[-1.0], [-4.0]])
    z, w = lcpbatch.jax.solve(M, q, backend="cpu")
    assert np.isnan(np.asarray(z)[0]).all() and np.isnan(np.asarray(w)[0]).all()
    assert float(z[1, 0]) == 2.0
    gq = jax.grad(lambda qq: jnp.sum(lcpbatch.jax.solve(M, qq, backend="cpu")[0]))(jnp.asarray(q))
    assert np.isnan(np.asarray(gq)[0]).all()
    assert float(gq[1, 0]) == -0.5


def test_memory_order_does_not_change_the_vjp():
    """Each argument in Fortran order, or strided, gives the C-ordered
    call's numbers (NumPy's flat view of a Fortran array is not the
    batch's order: the in-place path must not take it)."""
    rng = np.random.default_rng(77)
    M, q = stable_batch(rng, 6, 3)
    z = lcpbatch.solve(M, q, backend="cpu").z
    dz, dw = rng.standard_normal(q.shape), rng.standard_normal(q.shape)
    want = lcpbatch.lcp_vjp(M, q, z, dz, dw)
    for k in range(5):
        for change in (np.asfortranarray, lambda a: np.repeat(a, 2, axis=0)[::2]):
            args = [M, q, z, dz, dw]
            args[k] = change(args[k])
            got = lcpbatch.lcp_vjp(*args)
            assert np.array_equal(got.M, want.M) and np.array_equal(got.q, want.q), k


def test_bad_input_names_the_argument_and_the_island():
    M = np.array([[[2.0, 1.0], [1.0, 2.0]]] * 3)
    q = np.array([[-5.0, -6.0]] * 3)
    z = lcpbatch.solve(M, q).z
    dz = np.ones_like(z)
    with pytest.raises(ValueError, match=r"z: expected shape \(3, 2\) to match q, got \(3, 3\)"):
        lcpbatch.lcp_vjp(M, q, np.ones((3, 3)), dz)
    bad = dz.copy()
    bad[1, 0] = np.nan
    with pytest.raises(ValueError, match=r"island 1.*dz\[0\].*not a finite number"):
        lcpbatch.lcp_vjp(M, q, z, bad)
    Mb = M.copy()
    Mb[2, 1, 0] = np.inf
    with pytest.raises(ValueError, match=r"M\[2, 1, 0\] is inf"):
        lcpbatch.lcp_vjp(Mb, q, z, dz)
    with pytest.raises(ValueError, match=r"tolerance.*not in \[0, 1\)"):
        lcpbatch.lcp_vjp(M, q, z, dz, tolerance=2.0)
    with pytest.raises(ValueError, match=r"M: expected shape \(3, 2, 2\) to match q \(3, 2\)"):
        lcpbatch.jax.solve(M[:, :1], q)
    with pytest.raises(TypeError, match="warm_start"):
        lcpbatch.jax.solve(M, q, warm_start=True)


def stacked_balls():
    """Two balls falling onto the ground, the upper one onto the lower,
    with off-centre contact points (so rotation couples the contacts) and
    restitution: both contacts push (a stable active set)."""
    bodies = dict(inv_mass=np.array([1.0, 0.5]), inv_inertia=np.array([[2.5, 2.0, 2.5], [5.0, 4.0, 4.5]]),
                  position=np.array([[0.0, 0.5, 0.0], [0.1, 1.5, 0.0]]),
                  velocity=np.array([[0.2, -1.0, 0.1], [0.0, -2.0, -0.3]]),
                  angular_velocity=np.array([[0.0, 0.3, 0.5], [-0.4, 0.0, 0.2]]))
    contacts = dict(a=np.array([0, 1]), b=np.array([-1, 0]), point=np.array([[0.05, 0.0, 0.02], [0.08, 1.0, -0.03]]),
                    normal=np.array([[0.0, 1.0, 0.0], [0.0, 1.0, 0.0]]), restitution=np.array([0.3, 0.5]))
    return bodies, contacts


def test_scene_vjp_equals_central_differences_of_solve_scenes():
    bodies, contacts = stacked_balls()
    rng = np.random.default_rng(7)
    gz, gv, gw = rng.standard_normal(2), rng.standard_normal((2, 3)), rng.standard_normal((2, 3))

    def loss(b, c):
        r = lcpbatch.solve_scenes(b, c, backend="cpu")
        assert (r.impulses > 1e-3).all(), r.impulses  # both contacts push
        return gz @ r.impulses + np.sum(gv * r.velocity) + np.sum(gw * r.angular_velocity)

    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    g = lcpbatch.scene_vjp(bodies, contacts, r.impulses, gz, gv, gw)
    assert g.derivative == "exact" and g.islands.tolist() == ["exact"]
    checked = 0
    for part, given, grads, keys in ((bodies, "bodies", g.bodies, ("inv_mass", "position", "velocity",
                                                                       "angular_velocity", "inv_inertia")),
                                     (contacts, "contacts", g.contacts, ("point", "restitution"))):
        for key in keys:
            for ix in np.ndindex(np.shape(part[key])):
                def at(h):
                    moved = {k: np.array(v, dtype=float) if k not in ("a", "b") else v for k, v in part.items()}
                    moved[key][ix] += h
                    return loss(moved, contacts) if given == "bodies" else loss(bodies, moved)
                fd = (at(STEP) - at(-STEP)) / (2 * STEP)
                want = grads[key][ix + (ix[-1],)] if key == "inv_inertia" else grads[key][ix]
                assert abs(fd - want) <= 1e-5 * max(1.0, abs(fd)), (given, key, ix, fd, want)
                checked += 1
    assert checked == 34  # 26 entries of the bodies, 8 of the contacts
    # The normal, moved along x (a tangent: unit to first order).
    for i in range(2):
        def at(h):
            moved = dict(contacts, normal=contacts["normal"].copy())
            moved["normal"][i, 0] += h
            return loss(bodies, moved)
        fd = (at(STEP) - at(-STEP)) / (2 * STEP)
        assert abs(fd - g.contacts["normal"][i, 0]) <= 1e-5 * max(1.0, abs(fd))


def test_scene_vjp_batches_and_names_bad_input():
    bodies, contacts = stacked_balls()
    r = lcpbatch.solve_scenes([bodies, bodies], [contacts, contacts], backend="cpu")
    gs = lcpbatch.scene_vjp([bodies, bodies], [contacts, contacts], r.impulses, d_impulses=[np.ones(2), np.ones(2)])
    one = lcpbatch.scene_vjp(bodies, contacts, r.impulses[0], d_impulses=np.ones(2))
    assert len(gs) == 2 and "exact" in repr(gs[1])
    for k in one.bodies:
        np.testing.assert_array_equal(gs[1].bodies[k], one.bodies[k])
    with pytest.raises(ValueError, match=r"scene 1, contact 0.*friction"):
        lcpbatch.scene_vjp([bodies, bodies], [contacts, dict(contacts, mu=0.5)], r.impulses)
    with pytest.raises(ValueError, match=r"scene 1.*d_impulses"):
        lcpbatch.scene_vjp([bodies, bodies], [contacts, contacts], r.impulses, d_impulses=[np.ones(2), np.ones(3)])
    with pytest.raises(ValueError, match=r"d_velocity\[0\]: expected shape \(2, 3\)"):
        lcpbatch.scene_vjp(bodies, contacts, r.impulses[0], d_velocity=np.ones((3, 3)))
    with pytest.raises(ValueError, match=r"impulses: expected one array per scene \(2\), got 1"):
        lcpbatch.scene_vjp([bodies, bodies], [contacts, contacts], r.impulses[:1])


def test_jax_solve_scenes_is_scene_vjp_under_jit_and_vmap():
    bodies, contacts = stacked_balls()
    rng = np.random.default_rng(8)
    gz, gv, gw = rng.standard_normal(2), rng.standard_normal((2, 3)), rng.standard_normal((2, 3))
    layout = dict(a=contacts["a"], b=contacts["b"])

    def loss(inv_mass, velocity, point, restitution):
        imp, vel, ang = lcpbatch.jax.solve_scenes(
            dict(bodies, inv_mass=inv_mass, velocity=velocity),
            dict(layout, point=point, normal=contacts["normal"], restitution=restitution), backend="cpu")
        return jnp.sum(gz * imp) + jnp.sum(gv * vel) + jnp.sum(gw * ang)

    args = (bodies["inv_mass"], bodies["velocity"], contacts["point"], contacts["restitution"])
    got = jax.jit(jax.grad(loss, argnums=(0, 1, 2, 3)))(*args)
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    g = lcpbatch.scene_vjp(bodies, contacts, r.impulses, gz, gv, gw)
    want = (g.bodies["inv_mass"], g.bodies["velocity"], g.contacts["point"], g.contacts["restitution"])
    for x, y in zip(got, want):
        np.testing.assert_allclose(np.asarray(x), y, rtol=1e-13, atol=1e-13)
    # A batch of 3 scenes by vmap over the restitution: each its own solve.
    es = jnp.array([[0.0, 0.0], [0.3, 0.5], [1.0, 1.0]])
    imp = jax.vmap(lambda e: lcpbatch.jax.solve_scenes(bodies, dict(contacts, restitution=e))[0])(es)
    for k in range(3):
        want = lcpbatch.solve_scenes(bodies, dict(contacts, restitution=np.asarray(es[k])), backend="cpu").impulses
        np.testing.assert_allclose(np.asarray(imp[k]), want, rtol=1e-13)
    with pytest.raises(ValueError, match=r"contacts: unknown key\(s\) \['mu'\]"):
        lcpbatch.jax.solve_scenes(bodies, dict(contacts, mu=0.5))
    with pytest.raises(ValueError, match=r"point: expected shape \(2, 3\)"):
        lcpbatch.jax.solve_scenes(bodies, dict(contacts, point=np.zeros((3, 3))))


def run_python(code):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)


def test_import_lcpbatch_imports_neither_jax_nor_torch():
    out = run_python("import sys, lcpbatch; print('jax' in sys.modules, 'torch' in sys.modules)")
    assert out.stdout.split() == ["False", "False"], out.stdout + out.stderr
    # lcpbatch.jax on first use, through the attribute alone.
    out = run_python("import sys, lcpbatch; lcpbatch.jax.solve; print('jax' in sys.modules)")
    assert out.stdout.split() == ["True"], out.stdout + out.stderr


@pytest.mark.parametrize("module, hint", [("jax", 'pip install "jax[cpu]"'), ("torch", "pip install torch")])
def test_a_missing_framework_is_named_with_what_to_install(module, hint):
    code = (
        f"import sys; sys.modules[{module!r}] = None\n"
        "import lcpbatch\n"
        f"try:\n    lcpbatch.{module}.solve\nexcept ImportError as e:\n    print(e)\n"
    )
    out = run_python(code)
    assert hint in out.stdout and f"lcpbatch.{module} needs" in out.stdout, out.stdout + out.stderr


@pytest.mark.parametrize("module", ["lcpbatch._gradient", "lcpbatch.jax"])
def test_docstring_examples_run(module):
    result = doctest.testmod(importlib.import_module(module), verbose=False)
    assert result.attempted > 0 and result.failed == 0, result


def test_the_example_fits_restitution_in_a_few_dozen_steps():
    path = Path(__file__).resolve().parents[1] / "examples" / "fit_restitution.py"
    spec = importlib.util.spec_from_file_location("fit_restitution", path)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    h = example.fit(rods_count=64, steps=30)
    assert abs(h["e"][0] - 0.1) < 1e-12
    assert abs(h["e"][-1] - 0.6) < 5e-3, h["e"]
    assert h["loss"][-1] < 1e-3 * h["loss"][0]


# PyTorch: only where it is installed (CI installs JAX, not torch).


@pytest.fixture
def torch():
    return pytest.importorskip("torch")


@pytest.mark.parametrize("n", [1, 4, 8])
def test_torch_grad_is_the_rust_vjp_and_central_differences(torch, n):
    import lcpbatch.torch

    rng = np.random.default_rng(300 + n)
    M, q = stable_batch(rng, 10, n)
    c, d = rng.standard_normal(q.shape), rng.standard_normal(q.shape)
    Mt = torch.tensor(M, requires_grad=True)
    qt = torch.tensor(q, requires_grad=True)
    z, w = lcpbatch.torch.solve(Mt, qt, backend="cpu")
    loss = (torch.tensor(c) * z).sum() + (torch.tensor(d) * w).sum()
    gM, gq = torch.autograd.grad(loss, (Mt, qt))
    g = lcpbatch.lcp_vjp(M, q, lcpbatch.solve(M, q, backend="cpu").z, c, d)
    np.testing.assert_allclose(gM.numpy(), g.M, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(gq.numpy(), g.q, rtol=1e-13, atol=1e-13)
    fd_m, fd_q = central_differences(M, q, c, d)
    assert_close_relative(gM.numpy(), fd_m)
    assert_close_relative(gq.numpy(), fd_q)


def test_torch_shapes_dtypes_and_docstring(torch):
    import lcpbatch.torch

    M = torch.tensor([[2.0, 1.0], [1.0, 2.0]])          # one problem, float32
    q = torch.tensor([-5.0, -6.0], requires_grad=True)
    z, w = lcpbatch.torch.solve(M, q)
    assert z.shape == (2,) and z.dtype == torch.float32
    z[0].backward()
    np.testing.assert_allclose(q.grad.numpy(), [-2 / 3, 1 / 3], rtol=1e-6)
    with pytest.raises(ValueError, match=r"M: expected shape \(2, 2\)"):
        lcpbatch.torch.solve(M[:1], q)
    result = doctest.testmod(lcpbatch.torch, verbose=False)
    assert result.attempted > 0 and result.failed == 0, result


def test_torch_one_output_and_any_memory_order_give_the_rust_vjp(torch):
    """A loss of z alone or of w alone (backward gets None for the other),
    with M and q as C-ordered or transposed (Fortran-ordered) tensors,
    gives lcp_vjp's numbers."""
    import lcpbatch.torch

    rng = np.random.default_rng(404)
    M, q = stable_batch(rng, 6, 3)
    c = rng.standard_normal(q.shape)
    z = lcpbatch.solve(M, q, backend="cpu").z
    for uses_w in (False, True):
        want = lcpbatch.lcp_vjp(M, q, z, np.zeros_like(c) if uses_w else c, c if uses_w else None)
        for fortran in (False, True):
            if fortran:
                Mt = torch.tensor(np.ascontiguousarray(M.transpose(2, 1, 0)), requires_grad=True).permute(2, 1, 0)
                qt = torch.tensor(np.ascontiguousarray(q.T), requires_grad=True).t()
                assert not Mt.is_contiguous() and not qt.is_contiguous()
            else:
                Mt, qt = torch.tensor(M, requires_grad=True), torch.tensor(q, requires_grad=True)
            zt, wt = lcpbatch.torch.solve(Mt, qt, backend="cpu")
            assert np.array_equal(zt.detach().numpy(), z)
            gM, gq = torch.autograd.grad((torch.tensor(c) * (wt if uses_w else zt)).sum(), (Mt, qt))
            assert np.array_equal(gM.numpy(), want.M) and np.array_equal(gq.numpy(), want.q), (uses_w, fortran)


def test_torch_solve_scenes_is_scene_vjp_and_batches(torch):
    """lcpbatch.torch.solve_scenes: torch.autograd.grad gives scene_vjp's
    numbers (the diagonal inverse inertia's through its expansion), a
    leading batch dimension solves each scene, and friction is refused."""
    import lcpbatch.torch

    bodies, contacts = stacked_balls()
    rng = np.random.default_rng(9)
    gz, gv, gw = rng.standard_normal(2), rng.standard_normal((2, 3)), rng.standard_normal((2, 3))
    tb = {k: torch.tensor(v, requires_grad=True) for k, v in bodies.items()}
    tc = dict(contacts, **{k: torch.tensor(contacts[k], requires_grad=True) for k in ("point", "normal", "restitution")})
    imp, vel, ang = lcpbatch.torch.solve_scenes(tb, tc, backend="cpu")
    loss = (torch.tensor(gz) * imp).sum() + (torch.tensor(gv) * vel).sum() + (torch.tensor(gw) * ang).sum()
    keys = list(tb) + ["point", "normal", "restitution"]
    got = torch.autograd.grad(loss, [tb[k] for k in keys[:5]] + [tc[k] for k in keys[5:]])
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    np.testing.assert_allclose(imp.detach().numpy(), r.impulses, rtol=1e-13)
    g = lcpbatch.scene_vjp(bodies, contacts, r.impulses, gz, gv, gw)
    want = {**g.bodies, **g.contacts}
    want["inv_inertia"] = np.diagonal(want["inv_inertia"], axis1=-2, axis2=-1)   # given as its diagonal
    for k, x in zip(keys, got):
        np.testing.assert_allclose(x.numpy(), want[k], rtol=1e-13, atol=1e-13, err_msg=k)
    # A batch of 3 scenes (a leading dimension on every float array).
    es = torch.tensor([[0.0, 0.0], [0.3, 0.5], [1.0, 1.0]])
    stack = {k: torch.tensor(np.stack([v] * 3)) for k, v in bodies.items()}
    layout = dict(a=contacts["a"], b=contacts["b"], point=torch.tensor(np.stack([contacts["point"]] * 3)),
                  normal=torch.tensor(np.stack([contacts["normal"]] * 3)), restitution=es)
    imp = lcpbatch.torch.solve_scenes(stack, layout, backend="cpu")[0]
    assert imp.shape == (3, 2) and imp.dtype == torch.float64
    for k in range(3):
        want = lcpbatch.solve_scenes(bodies, dict(contacts, restitution=es[k].numpy()), backend="cpu").impulses
        np.testing.assert_allclose(imp[k].numpy(), want, rtol=1e-13)
    with pytest.raises(ValueError, match=r"contacts: unknown key\(s\) \['mu'\]"):
        lcpbatch.torch.solve_scenes(tb, dict(tc, mu=0.5))
    with pytest.raises(ValueError, match=r"point: expected shape \(2, 3\)"):
        lcpbatch.torch.solve_scenes(tb, dict(tc, point=torch.zeros(3, 3)))
