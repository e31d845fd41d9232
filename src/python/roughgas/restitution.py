"""eps_n and eps_t: a case's restitution over NumPy arrays, for the pair `roughgas restitution`
tabulates. tabulated=True evaluates the tables a run of the case uses (built once per case, or
loaded from its contact.cache_file); False integrates every contact directly. The compiled code
releases the GIL and spreads the points over OpenMP's threads."""
import numpy as np

from . import _roughgas
from .case import Case


def _functions(case, tabulated, material, contact):
    if material or contact:  # a copy of the case with [material] and [contact] keys set
        case = Case(case)
        for table, keys in (("material", material), ("contact", contact)):
            for key, value in (keys or {}).items():
                case.set(f"{table}.{key}", value)
    elif not isinstance(case, Case):
        case = Case(case)
    # Kept with the case: its tables are built once (Case.set drops them).
    cache = case.__dict__.setdefault("_contact", {})
    if bool(tabulated) not in cache:
        cache[bool(tabulated)] = _roughgas.ContactFunctions(case._source, bool(tabulated))
    return cache[bool(tabulated)]


def _speeds(name, a):
    try:
        a = np.asarray(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: an array of speeds (m/s) expected ({e})") from None
    return a


def eps_n(g_n, case, tabulated=False, material=None, contact=None):
    """eps_N at the normal impact speeds g_n (m/s, > 0), an array of g_n's shape. material, contact:
    {key: value} of those tables, set on a copy of the case (e.g. material={"dissipation": 1e-7})."""
    g = _speeds("g_n", g_n)
    return _functions(case, tabulated, material, contact).eps_n(g.ravel()).reshape(g.shape)


def eps_t(g_n, g_t, case, tabulated=False, material=None, contact=None):
    """eps_T at the impact speeds (g_n > 0, g_t >= 0 in m/s, broadcast together)."""
    gn, gt = np.broadcast_arrays(_speeds("g_n", g_n), _speeds("g_t", g_t))
    return _functions(case, tabulated, material, contact).eps_t(gn.ravel(), gt.ravel()).reshape(gn.shape)
