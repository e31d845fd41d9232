"""roughgas.collide: the collision rule over arrays (docs/model.md §3): momentum is conserved, the
normal and tangential contact velocities come out as -alpha and -beta times what they were."""
import numpy as np
import pytest

import roughgas


def pairs(count, seed=2):
    rng = np.random.default_rng(seed)
    v_i, w_i, v_j, w_j = (rng.standard_normal((count, 3)) for _ in range(4))
    n = rng.standard_normal((count, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    return v_i, w_i, v_j, w_j, n


def contact_velocity(v_i, w_i, v_j, w_j, n, r_i, r_j):
    return v_i - v_j - np.cross(r_i * w_i + r_j * w_j, n)


def test_the_rule_over_arrays():
    count = 1000
    v_i, w_i, v_j, w_j, n = pairs(count)
    alpha = np.linspace(0.5, 1.0, count)
    beta = np.linspace(-1.0, 1.0, count)
    grain_i, grain_j = (1.0, 0.5, 0.4), (2.0, 0.7, 0.3)
    before = [a.copy() for a in (v_i, w_i, v_j, w_j, n)]
    vi, wi, vj, wj = roughgas.collide(v_i, w_i, v_j, w_j, n, alpha, beta, grain_i, grain_j)
    for a, b in zip(before, (v_i, w_i, v_j, w_j, n)):
        assert np.array_equal(a, b)  # the inputs are left as they were
    np.testing.assert_allclose(1.0 * vi + 2.0 * vj, 1.0 * v_i + 2.0 * v_j, atol=1e-12)
    g = contact_velocity(v_i, w_i, v_j, w_j, n, 0.5, 0.7)
    g2 = contact_velocity(vi, wi, vj, wj, n, 0.5, 0.7)
    gn, gn2 = np.sum(g * n, axis=1), np.sum(g2 * n, axis=1)
    np.testing.assert_allclose(gn2, -alpha * gn, atol=1e-12)
    gt, gt2 = g - gn[:, None] * n, g2 - gn2[:, None] * n
    np.testing.assert_allclose(gt2, -beta[:, None] * gt, atol=1e-12)


def test_scalar_coefficients_and_equal_grains():
    v_i, w_i, v_j, w_j, n = pairs(10)
    vi, _, vj, _ = roughgas.collide(v_i, w_i, v_j, w_j, n, 1.0, -1.0)  # elastic and smooth
    np.testing.assert_allclose(vi + vj, v_i + v_j, atol=1e-12)
    np.testing.assert_allclose(np.sum(vi**2 + vj**2, axis=1), np.sum(v_i**2 + v_j**2, axis=1), rtol=1e-12)


def test_bad_input_raises():
    v_i, w_i, v_j, w_j, n = pairs(4)
    with pytest.raises(ValueError, match="n\\[0\\]"):
        roughgas.collide(v_i, w_i, v_j, w_j, 2 * n, 0.9, 0.0)
    with pytest.raises(ValueError, match="alpha"):
        roughgas.collide(v_i, w_i, v_j, w_j, n, 1.5, 0.0)
    with pytest.raises(ValueError, match="beta"):
        roughgas.collide(v_i, w_i, v_j, w_j, n, 0.9, [0.0, 0.0, np.nan, 0.0])
    with pytest.raises(ValueError, match="w_j"):
        roughgas.collide(v_i, w_i, v_j, w_j[:3], n, 0.9, 0.0)
    with pytest.raises(ValueError, match="v_i"):
        roughgas.collide(v_i[:, :2], w_i, v_j, w_j, n, 0.9, 0.0)
    bad = v_i.copy()
    bad[1, 1] = np.inf
    with pytest.raises(ValueError, match="v_j"):
        roughgas.collide(v_i, w_i, bad, w_j, n, 0.9, 0.0)
    with pytest.raises(ValueError, match="grain_i"):
        roughgas.collide(v_i, w_i, v_j, w_j, n, 0.9, 0.0, grain_i=(1.0, -0.5, 0.4))
    with pytest.raises(TypeError):
        roughgas.collide("x", w_i, v_j, w_j, n, 0.9, 0.0)
