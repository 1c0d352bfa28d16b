"""Scenes from arrays: impulses and velocities, batches, warm start by
contact ids, and the checks of the layout."""

import numpy as np
import pytest

import lcpbatch
from lcpbatch import Status


def ball(vy=-1.0):
    # 1 kg ball of radius 0.5 (I⁻¹ = 2.5 for a solid sphere: 1 / (2/5 m r²)).
    return dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0.0, 0.5, 0.0]],
                velocity=[[0.0, vy, 0.0]])


GROUND = dict(a=[0], b=[-1], point=[[0.0, 0.0, 0.0]], normal=[[0.0, 1.0, 0.0]], restitution=[0.5])


def test_a_ball_on_the_ground_bounces_with_its_restitution():
    # v_rel = −1, q = v_rel + ε min(v_rel, 0) = −1.5, M = 1/m = 1: z = 1.5 = (1 + ε) m v.
    r = lcpbatch.solve_scenes(ball(), GROUND, backend="cpu")
    np.testing.assert_allclose(r.impulses, [1.5], atol=1e-12)
    np.testing.assert_allclose(r.velocity, [[0.0, 0.5, 0.0]], atol=1e-12)
    np.testing.assert_allclose(r.angular_velocity, [[0.0, 0.0, 0.0]], atol=1e-12)
    assert r.status.tolist() == [Status.SOLVED] and r.scene_ok.tolist() == [True]
    assert r.island_scene.tolist() == [0] and r.island_contacts[0].tolist() == [0]


def test_two_balls_colliding_head_on_exchange_momentum():
    # Equal masses, elastic (ε = 1): the velocities swap. Normal from b (1) to a (0).
    bodies = dict(inv_mass=[1.0, 1.0], inv_inertia=np.full((2, 3), 2.5),
                  position=[[0.0, 0, 0], [1.0, 0, 0]], velocity=[[1.0, 0, 0], [-1.0, 0, 0]])
    contacts = dict(a=[0], b=[1], point=[[0.5, 0, 0]], normal=[[-1.0, 0, 0]], restitution=[1.0])
    r = lcpbatch.solve_scenes(bodies, contacts, backend="cpu")
    np.testing.assert_allclose(r.impulses, [2.0], atol=1e-12)
    np.testing.assert_allclose(r.velocity, [[-1.0, 0, 0], [1.0, 0, 0]], atol=1e-12)


def test_a_batch_of_scenes_gives_lists_in_order_and_matches_single_solves():
    rng = np.random.default_rng(8)
    bodies, contacts = [], []
    for k in range(6):
        n = 1 + k % 3
        bodies.append(dict(inv_mass=np.ones(n), inv_inertia=np.full((n, 3), 2.5),
                           position=np.c_[np.arange(n) * 1.0, np.full(n, 0.5), np.zeros(n)],
                           velocity=np.c_[np.zeros(n), -rng.uniform(0.5, 2, n), np.zeros(n)],
                           angular_velocity=rng.standard_normal((n, 3)) * 0.1))
        contacts.append(dict(a=np.arange(n), b=-np.ones(n, dtype=int),
                             point=np.c_[np.arange(n) * 1.0, np.zeros(n), np.zeros(n)],
                             normal=np.tile([0.0, 1.0, 0.0], (n, 1)), restitution=0.3))
    s = lcpbatch.Solver(backend="cpu")
    r = s.solve_scenes(bodies, contacts)
    assert [len(i) for i in r.impulses] == [1, 2, 3, 1, 2, 3]
    assert r.scene_ok.all() and len(r.velocity) == 6
    for k in range(6):
        one = s.solve_scenes(bodies[k], contacts[k])
        np.testing.assert_array_equal(one.impulses, r.impulses[k])
        np.testing.assert_array_equal(one.velocity, r.velocity[k])
        # After the impact nothing approaches the ground: v_y ≥ 0 at each contact point
        # (the points lie below the centres, so ω adds no normal velocity there).
        assert (one.velocity[:, 1] >= -1e-12).all()


def test_warm_start_by_contact_ids_in_scenes():
    # A box on 4 coplanar contacts: M singular, so nothing predicts its basis.
    h = 0.5
    corners = np.array([[x, 0.0, z] for x in (-h, h) for z in (-h, h)])
    box = dict(inv_mass=[1.0], inv_inertia=[[6.0, 6.0, 6.0]], position=[[0.0, h, 0.0]],
               velocity=[[0.0, -1.0, 0.0]])
    contacts = dict(a=np.zeros(4, dtype=int), point=corners, normal=np.tile([0.0, 1, 0], (4, 1)),
                    restitution=0.0, id=[7, 8, 9, 10])
    s = lcpbatch.Solver(backend="cpu", method="enum", warm_start=True)
    cold = s.solve_scenes(box, contacts)
    hot = s.solve_scenes(box, contacts)
    np.testing.assert_array_equal(cold.impulses, hot.impulses)
    assert hot.path.tolist() == ["warm_start"] and cold.path.tolist() != ["warm_start"]
    np.testing.assert_allclose(hot.velocity, [[0.0, 0.0, 0.0]], atol=1e-12)


def test_a_scene_without_contacts_keeps_its_velocities():
    none = dict(a=[], point=[], normal=[], restitution=[])
    r = lcpbatch.solve_scenes([ball(), ball()], [none, GROUND], backend="cpu")
    assert r.impulses[0].shape == (0,) and r.island_scene.tolist() == [1]
    np.testing.assert_array_equal(r.velocity[0], [[0.0, -1.0, 0.0]])
    np.testing.assert_allclose(r.velocity[1], [[0.0, 0.5, 0.0]], atol=1e-12)


def test_scene_errors_name_the_scene_the_item_and_the_field():
    with pytest.raises(ValueError, match=r"scene 0, contact 0: field `normal`: not a unit vector"):
        lcpbatch.solve_scenes(ball(), dict(GROUND, normal=[[0.0, 2.0, 0.0]]), backend="cpu")
    with pytest.raises(ValueError, match=r"scene 1, contact 0: field `b`: body index 3 out of range"):
        lcpbatch.solve_scenes([ball(), ball()], [GROUND, dict(GROUND, b=[3])], backend="cpu")
    with pytest.raises(ValueError, match=r"contacts\[0\]\['b'\]\[0\] is -2"):
        lcpbatch.solve_scenes(ball(), dict(GROUND, b=[-2]), backend="cpu")
    with pytest.raises(ValueError, match=r"bodies\[0\]\['position'\]: expected shape \(1, 3\)"):
        lcpbatch.solve_scenes(dict(ball(), position=[0.0, 0.5, 0.0]), GROUND, backend="cpu")
    with pytest.raises(ValueError, match=r"unknown key\(s\) \['friction'\] \(the friction coefficient is 'mu'\)"):
        lcpbatch.solve_scenes(ball(), dict(GROUND, friction=[0.5]), backend="cpu")
    with pytest.raises(ValueError, match=r"bodies\[0\]: missing key 'position'"):
        b = ball()
        del b["position"]
        lcpbatch.solve_scenes(b, GROUND, backend="cpu")
    with pytest.raises(ValueError, match=r"scene 0, body 0: field `velocity\[1\]`: not a finite number"):
        lcpbatch.solve_scenes(ball(vy=np.nan), GROUND, backend="cpu")
    with pytest.raises(TypeError, match="two dicts"):
        lcpbatch.solve_scenes(ball(), [GROUND], backend="cpu")
    with pytest.raises(TypeError, match=r"contacts\[0\]\['a'\]: dtype float64"):
        lcpbatch.solve_scenes(ball(), dict(GROUND, a=[0.0]), backend="cpu")
