"""roughgas.collide: the collision rule of docs/model.md §3 over arrays of pre-collision states."""
import numpy as np

from . import _roughgas


def collide(v_i, w_i, v_j, w_j, n, alpha, beta, grain_i=(1.0, 0.5, 0.4), grain_j=None):
    """The post-collision (v_i, w_i, v_j, w_j) of N pairs of rough grains.

    v_i, w_i, v_j, w_j: velocities and spins, arrays of shape (N, 3); n: the unit normals from j to
    i, (N, 3); alpha in [0, 1], beta in [-1, 1]: scalars or one per pair (e.g. eps_n(g_n, case) and
    -eps_t(g_n, g_t, case)); grain_i, grain_j: (mass, radius, inertia q = J/(m R^2)) of the two
    grains (grain_j None: the same as grain_i). The inputs are left as they were.
    """
    arrays = []
    for name, a in (("v_i", v_i), ("w_i", w_i), ("v_j", v_j), ("w_j", w_j), ("n", n)):
        try:
            arrays.append(np.asarray(a, dtype=np.float64))
        except (TypeError, ValueError) as e:
            raise TypeError(f"{name}: an array of shape (N, 3) expected ({e})") from None
    count = arrays[0].shape[0] if arrays[0].ndim == 2 else 0
    coefficients = []
    for name, c in (("alpha", alpha), ("beta", beta)):
        c = np.asarray(c, dtype=np.float64)
        coefficients.append(np.broadcast_to(c, (count,)) if c.ndim == 0 else c)
    grains = [tuple(float(x) for x in grain_i), tuple(float(x) for x in (grain_j if grain_j is not None else grain_i))]
    return _roughgas.collide(*arrays, *coefficients, *grains)
