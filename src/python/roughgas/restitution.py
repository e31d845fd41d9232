"""eps_n and eps_t: a case's restitution over NumPy arrays, for the pair `roughgas restitution`
tabulates. tabulated=True evaluates the tables a run of the case uses (built once per case, or
loaded from its contact.cache_file); False integrates every contact directly. The compiled code
releases the GIL and spreads the points over OpenMP's threads."""
import numpy as np

from . import _roughgas
from .case import Case


def _grain_case(material, contact, grain):
    """The case eps_n and eps_t evaluate without a case file: one species of `grain` ({"radius": R,
    "mass": m} or {"radius": R, "density": rho}, SI) colliding by the contact model of `material` (the
    [material] keys; with an asperity or a friction the tangential contact too: model "brilliantov",
    else "viscoelastic") with the [contact] keys of `contact`."""
    if not isinstance(material, dict) or not isinstance(grain, dict):
        raise TypeError("eps_n, eps_t: give a case, or material={...} (the [material] keys) and "
                        "grain={\"radius\": R, \"mass\": m} (or \"density\" instead of \"mass\")")
    model = "brilliantov" if "asperity" in material or "friction" in material else "viscoelastic"
    return Case({"run": {"particles": 2, "end": 1.0}, "species": [dict(grain)], "collision": {"model": model},
                 "material": dict(material), "contact": dict(contact or {})})


def _functions(case, tabulated, material, contact, grain=None):
    if case is None:
        case = _grain_case(material, contact, grain)
    elif material or contact:  # a copy of the case with [material] and [contact] keys set
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


def eps_n(g_n, case=None, tabulated=False, material=None, contact=None, grain=None):
    """eps_N at the normal impact speeds g_n (m/s, > 0), an array of g_n's shape. material, contact:
    {key: value} of those tables, set on a copy of the case (e.g. material={"dissipation": 1e-7});
    without a case, the whole [material] and the grain: eps_n(g, material={...}, grain={"radius": R,
    "mass": m})."""
    g = _speeds("g_n", g_n)
    return _functions(case, tabulated, material, contact, grain).eps_n(g.ravel()).reshape(g.shape)


def eps_t(g_n, g_t, case=None, tabulated=False, material=None, contact=None, grain=None):
    """eps_T at the impact speeds (g_n > 0, g_t >= 0 in m/s, broadcast together); case, material,
    contact and grain as for eps_n (the material with its asperity and friction)."""
    gn, gt = np.broadcast_arrays(_speeds("g_n", g_n), _speeds("g_t", g_t))
    return _functions(case, tabulated, material, contact, grain).eps_t(gn.ravel(), gt.ravel()).reshape(gn.shape)
