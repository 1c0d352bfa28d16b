"""Friction: scenes with ``mu`` per contact and batches of FrictionContact3D
problems (``solve_friction``), checked against friction-disc projections
worked by hand, Siconos' conformance problems and Coulomb's law evaluated in
NumPy."""

import json
import os
import pathlib

import numpy as np
import pytest

import lcpbatch

# The ground's normal (0, 1, 0) has the library's frame t1 = (1, 0, 0),
# t2 = n × t1 = (0, 0, −1) (src/friction/cone.rs).
T1, T2, N = np.array([1.0, 0, 0]), np.array([0, 0, -1.0]), np.array([0, 1.0, 0])


def point_mass_on_ground(v_t, gamma_n, mu, tangent=None):
    """One point mass (m = 1, no rotation: the contact is at its centre) hitting
    the ground with normal speed γ_n and tangential velocity v_t = (v·t1, v·t2):
    the Delassus matrix is W = I, so the normal impulse is γ_n (restitution 0)
    and the friction impulse is the projection of −v_t on the disc of radius
    μ γ_n (Coulomb's law with maximum dissipation)."""
    v = v_t[0] * T1 + v_t[1] * T2 - gamma_n * N
    bodies = dict(inv_mass=[1.0], inv_inertia=[[0.0, 0.0, 0.0]], position=[[0, 0.5, 0]], velocity=[v])
    contacts = dict(a=[0], point=[[0, 0.5, 0]], normal=[N], mu=mu)
    if tangent is not None:
        contacts["tangent"] = [tangent]
    return bodies, contacts


@pytest.mark.parametrize("mu, gamma_n, v_t, expected", [
    (0.5, 10.0, (3.0, -4.0), (-3.0, 4.0)),
    (0.6, 5.0, (4.0, 3.0), (-2.4, -1.8)),
])
def test_seed_001_projection_examples_through_solve_scenes(mu, gamma_n, v_t, expected):
    bodies, contacts = point_mass_on_ground(v_t, gamma_n, mu)
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    assert r.friction_status.tolist() == [lcpbatch.Status.SOLVED]
    assert r.friction_error[0] <= 1e-10
    np.testing.assert_allclose(r.impulses, [gamma_n], atol=1e-12)
    np.testing.assert_allclose(r.tangential[0], expected, atol=1e-12)
    world = gamma_n * N + expected[0] * T1 + expected[1] * T2
    np.testing.assert_allclose(r.impulse[0], world, atol=1e-12)
    # The LCP island arrays hold no frictional island; the report counts it.
    assert len(r.status) == 0 and r.report.friction_islands == 1
    assert r.report.friction_statuses["solved"] == 1
    assert r.report.max_coulomb_error == r.friction_error[0]


def test_a_caller_tangent_turns_only_the_frame():
    """With t1 = (0, 0, 1) (so t2 = n × t1 = (1, 0, 0)) the world impulse is
    the same, its parts are in the caller's frame."""
    bodies, contacts = point_mass_on_ground((4.0, 3.0), 5.0, 0.6)
    plain = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    t1 = np.array([0, 0, 1.0])
    bodies, contacts = point_mass_on_ground((4.0, 3.0), 5.0, 0.6, tangent=t1)
    turned = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    np.testing.assert_allclose(turned.impulse, plain.impulse, atol=1e-12)
    t2 = np.cross(N, t1)
    np.testing.assert_allclose(turned.tangential[0], [plain.impulse[0] @ t1, plain.impulse[0] @ t2], atol=1e-12)


def random_scenes(rng, count, mu):
    """Boxes' corners (4 contacts each) hitting the ground with random
    velocities, one body per scene."""
    bodies, contacts = [], []
    for _ in range(count):
        v = rng.standard_normal(3) + [0, -2.0, 0]
        w = rng.standard_normal(3)
        bodies.append(dict(inv_mass=[1.0], inv_inertia=[[6.0, 6.0, 6.0]], position=[[0, 0.5, 0]],
                           velocity=[v], angular_velocity=[w]))
        corners = np.array([[x, 0.0, z] for x in (-0.5, 0.5) for z in (-0.5, 0.5)])
        contacts.append(dict(a=[0] * 4, point=corners, normal=[N] * 4, mu=mu, restitution=0.2))
    return bodies, contacts


def test_every_impulse_is_in_its_cone_and_mu_zero_is_the_frictionless_answer():
    rng = np.random.default_rng(7)
    bodies, contacts = random_scenes(rng, 40, 0.4)
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    assert (r.friction_status == lcpbatch.Status.SOLVED).all() and r.scene_ok.all()
    assert r.friction_error.max() <= 1e-8
    for n_part, t_part in zip(r.impulses, r.tangential):
        assert (n_part >= -1e-12).all()
        assert (np.hypot(t_part[:, 0], t_part[:, 1]) <= 0.4 * n_part + 1e-10).all()
    # μ = 0: no frictional island, the impulse vector is z n, the LCP answer.
    frictionless = lcpbatch.solve_scenes(bodies, [dict(c, mu=0.0) for c in contacts], backend="cpu")
    plain = lcpbatch.solve_scenes(bodies, [{k: v for k, v in c.items() if k != "mu"} for c in contacts],
                                  backend="cpu")
    assert len(frictionless.friction_status) == 0 and frictionless.report.friction_islands == 0
    for a, b in zip(frictionless.impulses, plain.impulses):
        np.testing.assert_array_equal(a, b)
    for imp, z in zip(frictionless.impulse, frictionless.impulses):
        np.testing.assert_allclose(imp, z[:, None] * N, atol=0)
    # A tiny μ gives (nearly) the frictionless impulses through the friction path.
    tiny = lcpbatch.solve_scenes(bodies, [dict(c, mu=1e-12) for c in contacts], backend="cpu")
    assert len(tiny.friction_status) == 40
    for a, b in zip(tiny.impulses, plain.impulses):
        np.testing.assert_allclose(a.sum(), b.sum(), rtol=1e-6, atol=1e-9)


def test_a_mixed_batch_keeps_scene_indices_across_chunks(monkeypatch):
    """Frictional and frictionless scenes in one batch, solved in chunks:
    the report's friction parts are merged with shifted scene indices."""
    rng = np.random.default_rng(3)
    bodies, contacts = random_scenes(rng, 6, 0.5)
    for k in (1, 4):
        contacts[k] = dict(contacts[k], mu=0.0)
    whole = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    assert whole.friction_scene.tolist() == [0, 2, 3, 5]
    assert whole.report.chunks == 1
    # One scene per chunk: CHUNK_CONTACTS is read by the extension, so cut
    # the batch by hand and compare the merged result of lcpbatch.distributed's helper.
    from lcpbatch._results import concat_scenes_results
    parts = [lcpbatch.solve_scenes(bodies[i:i + 2], contacts[i:i + 2], backend="cpu") for i in (0, 2, 4)]
    merged = concat_scenes_results(parts)
    assert merged.friction_scene.tolist() == [0, 2, 3, 5]
    np.testing.assert_array_equal(np.concatenate(merged.impulse), np.concatenate(whole.impulse))
    assert merged.report.friction_islands == 4
    assert merged.report.max_coulomb_error == whole.report.max_coulomb_error
    assert merged.report.max_coulomb_error_index == whole.report.max_coulomb_error_index


def coulomb_error(W, q, mu, r):
    """The README's error (Siconos fc3d with De Saxcé's correction), in NumPy."""
    u = W @ r + q
    nat = []
    for i, m in enumerate(mu):
        ri, ui = r[3 * i:3 * i + 3], u[3 * i:3 * i + 3]
        x = ri - ui - np.array([m * np.hypot(ui[1], ui[2]), 0, 0])
        t = np.hypot(x[1], x[2])
        if m * t <= -x[0]:
            p = np.zeros(3)
        elif t <= m * x[0]:
            p = x
        else:
            pn = (m * t + x[0]) / (m * m + 1)
            p = np.array([pn, m * pn * x[1] / t, m * pn * x[2] / t])
        nat.append(ri - p)
    scale = max(np.linalg.norm(q), np.linalg.norm(r), np.linalg.norm(u))
    return np.linalg.norm(np.concatenate(nat)) / (scale if scale > 2.22e-16 else 1.0)


def read_dense_fc3d(path):
    """A FrictionContact3D .dat file with dense W (README of siconos-fc3d)."""
    tok = path.read_text().split()
    d, nc, storage, n0, n1 = (int(t) for t in tok[:5])
    assert d == 3 and storage == 0 and n0 == n1 == 3 * nc
    assert int(tok[5]) == n0 and int(tok[6]) == n1
    at = 7
    W = np.array(tok[at:at + n0 * n1], dtype=float).reshape(n1, n0).T   # column-major
    at += n0 * n1
    q = np.array(tok[at:at + n0], dtype=float)
    mu = np.array(tok[at + n0:at + n0 + nc], dtype=float)
    return W, q, mu


def conformance_dir():
    env = os.environ.get("LCPBATCH_CONFORMANCE")
    root = pathlib.Path(env) if env else pathlib.Path(__file__).resolve().parents[2] / ".." / "shared" / "conformance"
    d = root / "siconos-fc3d"
    if not d.is_dir():
        pytest.skip(f"{d} not found (set LCPBATCH_CONFORMANCE)")
    return d


def test_siconos_fc3d_conformance_problems_reach_1e_10():
    d = conformance_dir()
    reference = json.loads((d / "reference.json").read_text())["problems"]
    names = sorted(k for k, v in reference.items() if v["W_storage_in_file"] == "dense")
    assert len(names) >= 5, names
    problems = [read_dense_fc3d(d / n) for n in names]
    r = lcpbatch.solve_friction([p[0] for p in problems], [p[1] for p in problems],
                                [p[2] for p in problems], tolerance=1e-10, backend="cpu")
    assert r.status_names().tolist() == ["solved"] * len(names), list(zip(names, r.coulomb_error))
    for (W, q, mu), ri, ui, e, name in zip(problems, r.r, r.u, r.coulomb_error, names):
        assert e <= 1e-10, name
        assert coulomb_error(W, q, mu, ri) <= 1e-10, name      # our NumPy error, not the reported one
        np.testing.assert_allclose(ui, W @ ri + q, atol=1e-12 * (1 + np.abs(q).max()))
        assert reference[name]["contacts"] == len(mu)
    assert r.report.friction_statuses["solved"] == len(names)


def test_solve_friction_dense_float32_fortran_and_mu_zero():
    rng = np.random.default_rng(11)
    b, k = 64, 3
    A = rng.standard_normal((b, 3 * k, 3 * k))
    W = A @ A.transpose(0, 2, 1) + np.eye(3 * k)
    q = rng.standard_normal((b, 3 * k))
    mu = rng.uniform(0.1, 1.0, (b, k))
    r = lcpbatch.solve_friction(W, q, mu, backend="cpu")
    assert r.r.shape == r.u.shape == (b, 3 * k) and r.ok.all()
    for i in range(b):
        assert coulomb_error(W[i], q[i], mu[i], r.r[i]) <= 1e-8
        rn, rt = r.r[i, 0::3], np.hypot(r.r[i, 1::3], r.r[i, 2::3])
        assert (rn >= -1e-12).all() and (rt <= mu[i] * rn + 1e-9).all()
    # Any layout, float32 (computed in f64): the same answers as the f64 copy.
    W32, q32 = W.astype(np.float32), q.astype(np.float32)
    r32 = lcpbatch.solve_friction(np.asfortranarray(W32), q32[:, ::1], mu, backend="cpu")
    ref = lcpbatch.solve_friction(W32.astype(np.float64), q32.astype(np.float64), mu, backend="cpu")
    np.testing.assert_array_equal(r32.r, ref.r)
    # μ = 0: the normal parts are the LCP answer of the normal rows, no tangential force.
    r0 = lcpbatch.solve_friction(W, q, 0.0, backend="cpu", tolerance=1e-12)
    rows = np.arange(0, 3 * k, 3)
    lcp = lcpbatch.solve(W[:, rows][:, :, rows], q[:, rows], backend="cpu")
    np.testing.assert_allclose(r0.r[:, rows], lcp.z, atol=1e-9)
    np.testing.assert_allclose(r0.r[:, 1::3], 0, atol=1e-12)


def test_solver_friction_settings_and_warm_start():
    W, q = np.eye(3)[None], np.array([[-1.0, 3.0, -4.0]])
    s = lcpbatch.Solver(backend="cpu", warm_start=True, friction_method="nsgs", friction_tolerance=1e-12)
    first = s.solve_friction(W, q, [[0.5]], ids=[[7]])
    second = s.solve_friction(W, q, [[0.5]], ids=[[7]])
    assert not first.warm_started[0] and second.warm_started[0]
    np.testing.assert_allclose(second.r, [[1.0, -0.3, 0.4]], atol=1e-12)
    capped = lcpbatch.solve_friction(np.eye(6)[None] + 0.9 * np.ones((6, 6)), np.array([[-1, 2, 1, -1, -2, 3.0]]),
                                     [[0.8, 0.8]], method="nsgs", max_iterations=1, tolerance=1e-14,
                                     backend="cpu")
    assert capped.status_names().tolist() == ["not_converged"] and capped.iterations[0] == 1


def test_friction_warm_start_covers_every_chunk():
    # 8,000 problems of four decoupled contacts (W = I): (3k)² = 144 of
    # work each, three chunks under CHUNK_FRICTION_WORK, one call of memory.
    b, k = 8_000, 4
    W = np.broadcast_to(np.eye(3 * k), (b, 3 * k, 3 * k))
    q = np.tile([-1.0, 3.0, -4.0], (b, k))
    ids = np.arange(b * k).reshape(b, k)
    assert b * 9 * k * k > 2 * lcpbatch.CHUNK_FRICTION_WORK
    s = lcpbatch.Solver(backend="cpu", warm_start=True, friction_method="nsgs")
    first = s.solve_friction(W, q, 0.5, ids=ids)
    second = s.solve_friction(W, q, 0.5, ids=ids)
    assert first.report.chunks == second.report.chunks == 3
    assert not first.warm_started.any() and second.warm_started.all()
    np.testing.assert_allclose(second.r, np.tile([1.0, -0.3, 0.4], (b, k)), atol=1e-9)
    s.solve_friction(W, q, 0.5, ids=ids + b * k)
    assert not s.solve_friction(W, q, 0.5, ids=ids).warm_started.any()


def test_friction_errors_name_the_argument_index_and_fault():
    W, q, mu = np.eye(3)[None], np.array([[-1.0, 0, 0]]), np.array([[0.5]])
    cases = [
        (ValueError, r"W: expected shape \(B, 3k, 3k\)", (np.eye(3), q, mu)),
        (ValueError, r"W: its size 4 is not 3k", (np.eye(4)[None], np.zeros((1, 4)), mu)),
        (ValueError, r"q: expected shape \(1, 3\)", (W, np.zeros((1, 4)), mu)),
        (ValueError, r"mu: expected shape \(1, 1\)", (W, q, [[0.5, 0.5]])),
        (ValueError, r"mu\[0, 0\] is -0.5: a friction coefficient must be finite and ≥ 0", (W, q, -mu)),
        (ValueError, r"W\[0, 1, 2\] is NaN: every entry of W must be finite", (np.where(np.arange(9).reshape(1, 3, 3) == 5, np.nan, W), q, mu)),
        (ValueError, r"q\[0, 2\] is inf", (W, np.array([[-1.0, 0, np.inf]]), mu)),
        (TypeError, r"W: dtype complex128", (W.astype(complex), q, mu)),
        (ValueError, r"W\[1\]: expected a square \(3k, 3k\)", ([W[0], np.eye(2)], [q[0], q[0]], [mu[0], mu[0]])),
        (ValueError, r"mu\[1\]\[0\] is NaN", ([W[0], W[0]], [q[0], q[0]], [mu[0], [np.nan]])),
    ]
    for exc, pattern, args in cases:
        with pytest.raises(exc, match=pattern):
            lcpbatch.solve_friction(*args, backend="cpu")
    with pytest.raises(ValueError, match=r"ids: expected shape \(1, 1\)"):
        lcpbatch.solve_friction(W, q, mu, ids=[[1, 2]], backend="cpu")
    with pytest.raises(ValueError, match=r"ids\[0\]: expected shape \(1,\) \(one per contact\), got \(2,\)"):
        lcpbatch.solve_friction([W[0]], [q[0]], [mu[0]], ids=[np.array([1, 2])], backend="cpu")
    with pytest.raises(ValueError, match=r"friction_method: 'fast' is not one of"):
        lcpbatch.Solver(friction_method="fast")
    with pytest.raises(ValueError, match=r"friction_tolerance"):
        lcpbatch.Solver(friction_tolerance=2.0)
    bodies, contacts = point_mass_on_ground((1.0, 0.0), 1.0, -0.5)
    with pytest.raises(ValueError, match=r"scene 0, contact 0: field `friction`"):
        lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    bodies, contacts = point_mass_on_ground((1.0, 0.0), 1.0, 0.5, tangent=[0, 1.0, 0])
    with pytest.raises(ValueError, match=r"scene 0, contact 0: field `tangent`"):
        lcpbatch.solve_scenes(bodies, contacts, backend="cpu")


def test_the_extensions_chunks_merge_the_friction_parts():
    """More contacts than CHUNK_CONTACTS: two library calls, one report. Every
    other scene has friction; the frictional islands keep their scene index
    in the whole batch and the largest Coulomb error its island index."""
    count = lcpbatch.CHUNK_CONTACTS + 2
    rng = np.random.default_rng(5)
    vt = rng.standard_normal((count, 2))
    bodies, contacts = [], []
    for i in range(count):
        b, c = point_mass_on_ground(vt[i], 1.0 + i % 3, 0.5 if i % 2 == 0 else 0.0)
        bodies.append(b)
        contacts.append(c)
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    assert r.report.chunks == 2
    np.testing.assert_array_equal(r.friction_scene, np.arange(0, count, 2))
    assert r.report.friction_islands == len(r.friction_status) == (count + 1) // 2
    assert r.report.friction_statuses["solved"] == (count + 1) // 2
    assert r.report.max_coulomb_error == r.friction_error.max()
    assert r.friction_error[r.report.max_coulomb_error_index] == r.friction_error.max()
    assert r.report.statuses["solved"] == count // 2          # the frictionless islands
    # Each frictional answer is −v_t projected on the disc of radius μ γ_n (W = I per scene).
    gamma_n = 1.0 + np.arange(0, count, 2) % 3
    expected = -vt[::2] * np.minimum(1.0, 0.5 * gamma_n / np.hypot(vt[::2, 0], vt[::2, 1]))[:, None]
    np.testing.assert_allclose(np.array([t[0] for t in r.tangential[::2]]), expected, atol=1e-12)
