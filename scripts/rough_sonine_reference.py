#!/usr/bin/env python3
"""Independent reference for the homogeneous cooling state of rough spheres in the first Sonine approximation.

Run:  scripts/python3 scripts/rough_sonine_reference.py [--n N --sigma S --m M --T T] [--monte-carlo K]
                                                       [--print-closed-forms]

What it computes
----------------
A dilute gas of equal ROUGH inelastic hard spheres (d = 3, constant normal restitution alpha,
tangential restitution beta, reduced moment of inertia q = 4 I/(m sigma^2), docs/model.md sections
1-3) with the first Sonine distribution (Santos, Kremer & dos Santos, Phys. Fluids 23, 030604 (2011))

    f = f_M(c) f_M(w) [1 + a20 S2(c^2) + a02 S2(w^2) + a11 S1(c^2) S1(w^2)],
    c = v/sqrt(2 T_tr/m),  w = omega/sqrt(2 T_rot/I),  S1(x) = 3/2 - x,  S2(x) = 15/8 - 5x/2 + x^2/2,

so that a20 = (4/15)<c^4> - 1, a02 = (4/15)<w^4> - 1, a11 = (4/9)<c^2 w^2> - 1 (docs/model.md section
5). It prints, in the layout of the C++ test arrays, the numbers hard-coded in
tests/observables/sonine_theory_test.cpp:

  SonineTheory.RatesAgreeWithQuadrature
      {alpha, beta, q, theta, then for psi = c^2, w^2, c^4, w^4, c^2 w^2 the four coefficients
       (1, a20, a02, a11) of the reduced production rate R_psi}
  SonineTheory.CoolingStateAgreesWithAnIndependentEvaluation
      {alpha, beta, q, theta, a20, a02, a11, zeta*}
  SonineTheory.QuasiSmoothLimit
      {alpha, q, y = lim b~^2 theta/q, a20, a02} as beta -> -1 (a11 -> 0, theta -> infinity)

Reduced production rates. For a one-particle function psi(c, w),
    R_psi = -(d<psi>/dt)_coll / nu_M,   nu_M = 4 n sigma^2 sqrt(pi T_tr/m)
(the Maxwellian collision frequency per particle), taken at fixed T_tr and T_rot, linear in the
cumulants: R_psi = R_psi^0 + R_psi^20 a20 + R_psi^02 a02 + R_psi^11 a11. The collision frequency of
the Sonine distribution is nu_M (1 - a20/16) (printed as the check "collisions").

Two independent evaluations of the R coefficients (nothing is taken from the C++ sources):
* closed forms, derived here with sympy: with n along z, G = (c1 + c2)/2, g = c1 - c2, W = w1 + w2,
  D = w1 - w2 (independent Gaussians in the reduced variables) and the collision rule of
  docs/model.md section 3, every integrand is a polynomial times |g_z| on g_z < 0; each monomial is
  replaced by its Gaussian (resp. half-range) moment. --print-closed-forms prints them.
* deterministic quadrature of the same collision integrals in dimensional units with the collision
  rule of scripts/rough_linear_theory_reference.py (pair_integrals: Gauss-Hermite per variable,
  the Gauss rule of s exp(-s^2/2) for |g_z|), with node counts exact for the polynomial degree of
  each weight (5 nodes where the weight is of degree 4 in that variable, 4 for a11, 3 otherwise):
  it agrees with the closed forms to round-off (printed). --monte-carlo K adds a Monte Carlo
  quadrature over K pairs with normals on the whole sphere, with standard errors.

The cooling state. In the scaled homogeneous cooling state theta and the cumulants are constant:
    R_c2 = R_w2 (theta constant: the two temperatures decay at one rate),
    R_c4 = 5 R_c2 (1 + a20),  R_w4 = 5 R_w2 (1 + a02),  R_c2w2 = (3/2)(R_c2 + R_w2)(1 + a11)
(d<c^4>/dt = 0 etc. in the variables scaled by the decaying thermal speeds). Linearisation in the
cumulants: the products of two cumulants in the last three equations are
dropped, so at fixed theta the cumulants solve a 3 x 3 linear system; theta itself is NOT expanded
about the Maxwellian value: it is the root of R_c2 - R_w2 (with those cumulants) on the branch
continued from the Maxwellian theta (the root closest to it in ln theta with no pole of the linear
system in between), found by bisection. zeta* = (2/3) R_c2/(1 - a20/16): the decay rate of T_tr
per collision per particle of the Sonine distribution (zeta_star of moments.csv).
For the DSMC cases of docs/validation.md it also prints the state with the products of cumulants
kept (the four equations solved by Newton's method): how much the linearisation matters there.
Checks printed: at beta = -1 (smooth) the a20 equation is van Noije & Ernst's (1998)
a2 = 16(1-alpha)(1-2 alpha^2)/(81 - 17 alpha + 30 alpha^2 (1-alpha)); as beta -> -1 the rough
cooling state does not tend to it (a singular limit, Santos, Kremer & dos Santos 2011): with
y = b~^2 theta/q fixed, b~ = q(1+beta)/(2(1+q)) -> 0, the leading orders of the four equations give
a11 = 0 and three equations for y, a20, a02 (derived here, solved by Newton's method).

Runtime: a minute or two of CPU (the quadrature); --monte-carlo 2000000 about a minute more.
"""

import argparse
import math

import numpy as np
import sympy as sp

from linear_theory_reference import add_gas_unit_arguments
from rough_linear_theory_reference import pair_integrals, pair_integrals_monte_carlo, rel, x_r, x_t

PSI_NAMES = ("c2", "w2", "c4", "w4", "c2w2")
WEIGHT_NAMES = ("1", "a20", "a02", "a11")
RATE_POINTS = [(0.9, 0.0, 0.4, 0.55), (0.7, -0.5, 0.5, 3.0), (0.5, 1.0, 0.3, 1.5)]
HCS_CASES = [(a, b, 0.4) for a in (0.9, 0.5) for b in (-0.5, 0.0, 0.5, 1.0)] + [(0.8, 0.3, 0.25), (1.0, 0.0, 0.4)]
QUASI_SMOOTH = [(0.9, 0.4), (0.5, 0.4), (0.7, 0.2)]
# The DSMC runs of tests/io/run_cli_test.cpp (ThetaDeviationFromMaxwellianIsTheSonineCorrection), q = 2/5.
VALIDATION_CASES = [(0.9, 0.5), (0.9, 0.0), (0.9, -0.5), (0.7, 0.5), (0.5, 1.0)]


# ---------------------------------------------------------------------------------------------
# Closed forms (sympy)
# ---------------------------------------------------------------------------------------------
def derive_closed_forms():
    """{(psi, weight): expression in at, bt, q, theta} of the reduced rate coefficients."""
    from sympy.polys.rings import ring

    names = "Gx Gy Gz gx gy s Wx Wy Wz Dx Dy Dz at bt lam il qi"
    R, *X = ring(names.replace(" ", ","), sp.QQ)
    Gx, Gy, Gz, gx, gy, s, Wx, Wy, Wz, Dx, Dy, Dz, at, bt, lam, il, qi = X
    h = sp.QQ(1, 2)
    c1, c2 = [Gx + gx * h, Gy + gy * h, Gz - s * h], [Gx - gx * h, Gy - gy * h, Gz + s * h]
    w1, w2 = [(Wx + Dx) * h, (Wy + Dy) * h, (Wz + Dz) * h], [(Wx - Dx) * h, (Wy - Dy) * h, (Wz - Dz) * h]
    # n = z, g_z = -s (s > 0, approaching); contact velocity in units of the thermal speed; lam = sqrt(theta/q)
    # is the ratio of the thermal speeds of R omega and v; il = 1/lam, qi = 1/q.
    gcx, gcy = gx - lam * Wy, gy + lam * Wx
    dc = [-bt * gcx, -bt * gcy, at * s]            # c1' - c1 = c2 - c2'
    dw = [dc[1] * qi * il, -dc[0] * qi * il, R(0)]  # w1' - w1 = w2' - w2 = -n x dc/(q lam)
    c1p, c2p = [a + b for a, b in zip(c1, dc)], [a - b for a, b in zip(c2, dc)]
    w1p, w2p = [a + b for a, b in zip(w1, dw)], [a + b for a, b in zip(w2, dw)]
    sq = lambda v: v[0] ** 2 + v[1] ** 2 + v[2] ** 2
    C1, C2, W1, W2, C1p, C2p, W1p, W2p = map(sq, (c1, c2, w1, w2, c1p, c2p, w1p, w2p))
    S1 = lambda x: sp.QQ(3, 2) - x
    S2 = lambda x: sp.QQ(15, 8) - sp.QQ(5, 2) * x + h * x ** 2
    psis = dict(c2=C1p + C2p - C1 - C2, w2=W1p + W2p - W1 - W2, c4=C1p ** 2 + C2p ** 2 - C1 ** 2 - C2 ** 2,
                w4=W1p ** 2 + W2p ** 2 - W1 ** 2 - W2 ** 2, c2w2=C1p * W1p + C2p * W2p - C1 * W1 - C2 * W2,
                collisions=R(1))
    weights = {"1": R(1), "a20": S2(C1) + S2(C2), "a02": S2(W1) + S2(W2),
               "a11": S1(C1) * S1(W1) + S1(C2) * S1(W2)}
    variances = [sp.QQ(1, 4)] * 3 + [sp.QQ(1)] * 2 + [None] + [sp.QQ(1)] * 6  # G, g_x, g_y, (s), W, D

    def gauss(v, k):
        if k % 2:
            return sp.QQ(0)
        return sp.QQ(int(sp.factorial2(k - 1))) * v ** (k // 2)

    def half_range(k):  # int_0^inf s^(k+1) e^(-s^2/2) ds, in units of the k = 0 value
        return sp.Integer(2) ** sp.Rational(k, 2) * sp.gamma(sp.Rational(k, 2) + 1)

    sa, sb, sl, sil, sqi = sp.symbols("at bt lam il qi")
    q, theta = sp.symbols("q theta", positive=True)

    def integrate(p):
        acc = {}
        for mon, coef in p.terms():
            m = coef
            for i in range(12):
                if i != 5 and mon[i]:
                    m *= gauss(variances[i], mon[i])
            if m:
                key = (mon[5],) + mon[12:]
                acc[key] = acc.get(key, 0) + m
        return sum(sp.Rational(m.numerator, m.denominator) * half_range(k[0]) * sa ** k[1] * sb ** k[2]
                   * sl ** k[3] * sil ** k[4] * sqi ** k[5] for k, m in acc.items())

    raw = {(p, w): integrate(P * W) for p, P in psis.items() for w, W in weights.items()}
    norm = raw[("collisions", "1")]  # 2 sum over both grains: R = -I/(2 I_0); collisions: I/I_0
    out = {}
    for key, v in raw.items():
        e = v / norm if key[0] == "collisions" else -v / (2 * norm)
        e = e.subs(sil, 1 / sl).subs(sqi, 1 / q).subs(sl, sp.sqrt(theta / q))
        out[key] = sp.factor(sp.expand(e.subs({sa: sp.Symbol("at"), sb: sp.Symbol("bt")})))
    return out


# ---------------------------------------------------------------------------------------------
# Quadrature (the collision rule and integrator of rough_linear_theory_reference.py)
# ---------------------------------------------------------------------------------------------
class _Gas:
    def __init__(self, alpha, beta, q, n, m, T_tr, T_rot):
        self.alpha, self.beta, self.q, self.n, self.m, self.T_tr, self.T_rot = alpha, beta, q, n, m, T_tr, T_rot


def s2(x):
    return 15 / 8 - 2.5 * x + 0.5 * x * x


def psi_change(name):
    def one(P, c, u):
        xt, xr = x_t(P, c), x_r(P, u)
        return dict(c2=xt, w2=xr, c4=xt * xt, w4=xr * xr, c2w2=xt * xr)[name]
    return lambda P: one(P, P.p1, P.pu1) + one(P, P.p2, P.pu2) - one(P, P.c1, P.u1) - one(P, P.c2, P.u2)


WEIGHTS = {
    "1": lambda P: 1.0,
    "a20": lambda P: s2(x_t(P, P.c1)) + s2(x_t(P, P.c2)),
    "a02": lambda P: s2(x_r(P, P.u1)) + s2(x_r(P, P.u2)),
    "a11": lambda P: (1.5 - x_t(P, P.c1)) * (1.5 - x_r(P, P.u1)) + (1.5 - x_t(P, P.c2)) * (1.5 - x_r(P, P.u2)),
}
# Gauss nodes per variable, exact for each weight's degree (psi: degree 4 in every variable).
WEIGHT_ORDERS = {
    "1": dict(G=3, D=3, Wz=3, Wt=3, gt=3, s=3),
    "a20": dict(G=5, D=3, Wz=3, Wt=3, gt=5, s=5),
    "a02": dict(G=3, D=5, Wz=5, Wt=5, gt=3, s=3),
    "a11": dict(G=4, D=4, Wz=4, Wt=4, gt=4, s=4),
}


def integrand(psi, weight):
    d = (lambda P: np.ones_like(P.c1[..., 0])) if psi == "collisions" else psi_change(psi)
    w = WEIGHTS[weight]
    return lambda P: w(P) * d(P)


def rates_by_quadrature(alpha, beta, q, theta, args):
    """{(psi, weight): R coefficient}, and the collisions' coefficients, by quadrature."""
    gas = _Gas(alpha, beta, q, args.n, args.m, args.T, args.T * theta)
    out = {}
    norm = None
    for w in WEIGHT_NAMES:
        names = ("collisions",) + PSI_NAMES
        vals = pair_integrals(gas, [integrand(p, w) for p in names], WEIGHT_ORDERS[w])
        if w == "1":
            norm = vals[0]
        for p, v in zip(names, vals):
            out[(p, w)] = v / norm if p == "collisions" else -v / (2 * norm)
    return out


def rates_by_monte_carlo(alpha, beta, q, theta, args, samples):
    gas = _Gas(alpha, beta, q, args.n, args.m, args.T, args.T * theta)
    funcs = [integrand(p, w) for w in WEIGHT_NAMES for p in ("collisions",) + PSI_NAMES]
    mean, err = pair_integrals_monte_carlo(gas, funcs, samples)
    norm = mean[0]
    out = {}
    k = 0
    for w in WEIGHT_NAMES:
        for p in ("collisions",) + PSI_NAMES:
            f = 1.0 if p == "collisions" else -0.5
            out[(p, w)] = (f * mean[k] / norm, abs(f) * err[k] / norm)
            k += 1
    return out


# ---------------------------------------------------------------------------------------------
# The cooling state
# ---------------------------------------------------------------------------------------------
class SonineHcs:
    def __init__(self, forms):
        at, bt, q, th = sp.symbols("at bt q theta", positive=True)
        at_, bt_ = sp.Symbol("at"), sp.Symbol("bt")
        args = (at_, bt_, sp.Symbol("q", positive=True), sp.Symbol("theta", positive=True))
        self.f = {k: sp.lambdify(args, v) for k, v in forms.items()}

    def coefficients(self, alpha, beta, q, theta):
        at, bt = (1 + alpha) / 2, q * (1 + beta) / (2 * (1 + q))
        return {k: float(f(at, bt, q, theta)) for k, f in self.f.items()}

    def linear_system(self, alpha, beta, q, theta):
        """M a = b: the linearised a20, a02, a11 equations at fixed theta; and the R coefficients."""
        r = self.coefficients(alpha, beta, q, theta)
        R = {p: np.array([r[(p, w)] for w in WEIGHT_NAMES]) for p in PSI_NAMES}
        e = np.eye(4)
        rows = [R["c4"] - 5 * R["c2"] - 5 * R["c2"][0] * e[1],
                R["w4"] - 5 * R["w2"] - 5 * R["w2"][0] * e[2],
                R["c2w2"] - 1.5 * (R["c2"] + R["w2"]) - 1.5 * (R["c2"][0] + R["w2"][0]) * e[3]]
        M = np.array([row[1:] for row in rows])
        b = -np.array([row[0] for row in rows])
        return M, b, R

    def theta_condition(self, alpha, beta, q, theta):
        """(R_c2 - R_w2 at the cumulants of the linear system, det M)."""
        M, b, R = self.linear_system(alpha, beta, q, theta)
        a = np.linalg.solve(M, b)
        d = R["c2"] - R["w2"]
        return d[0] + d[1:] @ a, np.linalg.det(M)

    def solve(self, alpha, beta, q, theta_maxwell):
        """(theta, a20, a02, a11, zeta*) on the branch of the Maxwellian theta (None if none)."""
        x0, h = math.log(theta_maxwell), 0.01
        F = lambda x: self.theta_condition(alpha, beta, q, math.exp(x))
        f0, d0 = F(x0)
        best = None
        for side in (-1, 1):
            xa, fa, da = x0, f0, d0
            for k in range(1, 601):
                xb = x0 + side * k * h
                fb, db = F(xb)
                if np.sign(db) != np.sign(da):
                    break  # a pole of the linear system: the branch ends
                if fa == 0 or np.sign(fb) != np.sign(fa):
                    # the bracket in increasing x (xb < xa on the side of smaller theta)
                    lo, hi, flo = (min(xa, xb), max(xa, xb), fa if xa < xb else fb) if fa != 0 else (xa, xa, fa)
                    while hi - lo > 1e-15 * max(1.0, abs(lo)):
                        mid = 0.5 * (lo + hi)
                        fm = F(mid)[0]
                        if np.sign(fm) == np.sign(flo):
                            lo, flo = mid, fm
                        else:
                            hi = mid
                    x = 0.5 * (lo + hi)
                    if best is None or abs(x - x0) < abs(best - x0):
                        best = x
                    break
                xa, fa, da = xb, fb, db
        if best is None:
            return None
        theta = math.exp(best)
        M, b, R = self.linear_system(alpha, beta, q, theta)
        a = np.linalg.solve(M, b)
        zeta = (2 / 3) * (R["c2"][0] + R["c2"][1:] @ a) / (1 - a[0] / 16)
        return theta, a[0], a[1], a[2], zeta


def not_linearised(hcs, alpha, beta, q, start):
    """(theta, a20, a02, a11) of the four cooling-state equations with the products of two cumulants
    kept, by Newton's method (central-difference Jacobian) from the linearised state `start`."""
    def G(v):
        r = hcs.coefficients(alpha, beta, q, math.exp(v[0]))
        R = {p: r[(p, "1")] + sum(r[(p, w)] * x for w, x in zip(WEIGHT_NAMES[1:], v[1:])) for p in PSI_NAMES}
        return np.array([R["c2"] - R["w2"], R["c4"] - 5 * R["c2"] * (1 + v[1]), R["w4"] - 5 * R["w2"] * (1 + v[2]),
                         R["c2w2"] - 1.5 * (R["c2"] + R["w2"]) * (1 + v[3])])
    v = np.array([math.log(start[0]), *start[1:4]])
    for _ in range(50):
        J = np.empty((4, 4))
        for j in range(4):
            e = np.zeros(4)
            e[j] = 1e-7
            J[:, j] = (G(v + e) - G(v - e)) / 2e-7
        dv = np.linalg.solve(J, -G(v))
        v += dv
        if np.max(np.abs(dv)) < 1e-13:
            break
    return (math.exp(v[0]), *v[1:])


def maxwellian_theta(alpha, beta, q):
    """The Maxwellian cooling state's theta (Huthmann & Zippelius 1997), for the bracket and the table."""
    e = q * (1 + beta) / (2 * (1 + q))
    A, B, C = (1 - alpha ** 2) / 4 + e * (1 - e), e * e / q, (e / q) * (1 - e / q)
    return (A - C + math.sqrt((A - C) ** 2 + 4 * B * B)) / (2 * B)


def quasi_smooth_equations(forms):
    """Leading orders in b~ -> 0 of the four cooling-state equations at y = b~^2 theta/q fixed."""
    at, bt, a20, a02, a11 = sp.symbols("at bt a20 a02 a11")
    q, th, y, eps = sp.Symbol("q", positive=True), sp.Symbol("theta", positive=True), *sp.symbols("y eps",
                                                                                                  positive=True)
    lin = {p: forms[(p, "1")] + forms[(p, "a20")] * a20 + forms[(p, "a02")] * a02 + forms[(p, "a11")] * a11
           for p in PSI_NAMES}
    A = (a20, a02, a11)

    def linearise(e):
        e = sp.expand(e)
        z = {x: 0 for x in A}
        return e.subs(z) + sum(sp.diff(e, x).subs(z) * x for x in A)

    eqs = [lin["c2"] - lin["w2"], linearise(lin["c4"] - 5 * lin["c2"] * (1 + a20)),
           linearise(lin["w4"] - 5 * lin["w2"] * (1 + a02)),
           linearise(lin["c2w2"] - sp.Rational(3, 2) * (lin["c2"] + lin["w2"]) * (1 + a11))]
    lead = []
    for e in eqs:
        e = sp.expand(sp.expand(e.subs(th, q * y / bt ** 2)).subs(bt, eps))
        p = sp.Poly(sp.expand(sp.series(e, eps, 0, 3).removeO() * eps ** 8), eps)
        lead.append(sp.factor(sorted(p.terms(), key=lambda t: t[0][0])[0][1]))
    return lead, (at, q, y, a20, a02, a11)


def quasi_smooth_limit(lead, symbols, alpha, q, guess):
    at, qs, y, a20, a02, a11 = symbols
    sub = {at: (1 + alpha) / 2, qs: q}
    eqs = [e.subs(sub) for e in lead]
    sol = sp.nsolve(eqs, (y, a20, a02, a11), guess, tol=1e-30, prec=40)
    return [float(v) for v in sol]


# ---------------------------------------------------------------------------------------------
def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_gas_unit_arguments(ap)
    ap.add_argument("--monte-carlo", type=int, default=0, metavar="K",
                    help="also compare the rate coefficients at the first rate point with a Monte Carlo"
                         " quadrature over K pairs (normals on the whole sphere), with standard errors")
    ap.add_argument("--print-closed-forms", action="store_true",
                    help="print the closed forms of the rate coefficients (sympy)")
    args = ap.parse_args()

    forms = derive_closed_forms()
    if args.print_closed_forms:
        print("// closed forms, at = (1 + alpha)/2, bt = q (1 + beta)/(2 (1 + q)):")
        for (p, w), e in forms.items():
            print(f"//   R[{p}, {w}] = {e}")
    hcs = SonineHcs(forms)

    print(f"// rough spheres, first Sonine approximation; dimensional units n = {args.n}, m = {args.m},"
          f" T_tr = {args.T}")
    print("// collision frequency of the Sonine distribution over nu_M: coefficients (1, a20, a02, a11) ="
          f" ({', '.join(str(forms[('collisions', w)]) for w in WEIGHT_NAMES)})")
    print("// sonine_theory_test.cpp, RatesAgreeWithQuadrature: {alpha, beta, q, theta,"
          " R_c2[1, a20, a02, a11], R_w2[..], R_c4[..], R_w4[..], R_c2w2[..]} (quadrature)")
    worst = 0.0
    for a, b, q, th in RATE_POINTS:
        quad = rates_by_quadrature(a, b, q, th, args)
        closed = hcs.coefficients(a, b, q, th)
        for k, v in quad.items():
            worst = max(worst, abs(v - closed[k]) / max(1.0, abs(closed[k])))
        vals = ", ".join(f"{quad[(p, w)]:.15e}" for p in PSI_NAMES for w in WEIGHT_NAMES)
        print(f"        {{{a}, {b}, {q}, {th}, {vals}}},")
    print(f"// quadrature against the closed forms: largest difference {worst:.1e} (relative to max(1, |R|))")

    if args.monte_carlo:
        a, b, q, th = RATE_POINTS[0]
        mc = rates_by_monte_carlo(a, b, q, th, args, args.monte_carlo)
        closed = hcs.coefficients(a, b, q, th)
        print(f"// Monte Carlo ({args.monte_carlo} pairs) at alpha = {a}, beta = {b}, q = {q}, theta = {th}:"
              " closed form, Monte Carlo +- s.e. (deviation in s.e.)")
        for p in ("collisions",) + PSI_NAMES:
            for w in WEIGHT_NAMES:
                m, e = mc[(p, w)]
                x = closed[(p, w)]
                dev = (m - x) / e if e > 0 else 0.0
                print(f"//   R[{p}, {w}] {x:+.10f}  {m:+.6f} +- {e:.1e} ({dev:+.2f})")

    print("// sonine_theory_test.cpp, CoolingStateAgreesWithAnIndependentEvaluation:"
          " {alpha, beta, q, theta, a20, a02, a11, zeta_star}")
    table = []
    for a, b, q in HCS_CASES:
        tm = maxwellian_theta(a, b, q)
        s = hcs.solve(a, b, q, tm)
        table.append((a, b, q, tm, s))
        print(f"        {{{a}, {b}, {q}, " + ", ".join(f"{v:.15g}" for v in s) + "},")
    print("// beside the Maxwellian theta (relative difference of the Sonine theta):")
    for a, b, q, tm, s in table:
        print(f"//   {a}, {b}, {q}: Maxwellian theta {tm:.6f}, Sonine {s[0]:.6f} ({s[0] / tm - 1:+.2%})")

    print("// the DSMC cases of docs/validation.md (q = 0.4): Maxwellian theta; Sonine theta, a20, a02, a11;"
          " the same without linearising in the cumulants")
    for a, b in VALIDATION_CASES:
        tm = maxwellian_theta(a, b, 0.4)
        s = hcs.solve(a, b, 0.4, tm)
        n = not_linearised(hcs, a, b, 0.4, s)
        print(f"//   {a}, {b}: {tm:.4f}; {s[0]:.4f}, {s[1]:+.4f}, {s[2]:+.4f}, {s[3]:+.4f};"
              f" {n[0]:.4f}, {n[1]:+.4f}, {n[2]:+.4f}, {n[3]:+.4f}")
    print("// beta = -1 (smooth): a20 of the linearised a20 equation against van Noije & Ernst (1998)")
    for a in (0.9, 0.5, 0.2):
        M, bvec, R = hcs.linear_system(a, -1.0, 0.4, 1.0)
        a2 = bvec[0] / M[0, 0]
        vne = 16 * (1 - a) * (1 - 2 * a * a) / (81 - 17 * a + 30 * a * a * (1 - a))
        print(f"//   alpha = {a}: {a2:.15g}, van Noije & Ernst {vne:.15g} (rel {rel(a2, vne):.1e})")

    lead, symbols = quasi_smooth_equations(forms)
    print("// quasi-smooth limit beta -> -1 (leading orders at y = b~^2 theta/q fixed):")
    for e in lead:
        print(f"//   0 = {e}")
    print("// sonine_theory_test.cpp, QuasiSmoothLimit: {alpha, q, y, a20, a02} (a11 -> 0)")
    for a, q in QUASI_SMOOTH:
        y, a20, a02, a11 = quasi_smooth_limit(lead, symbols, a, q, (0.1, 0.0, -0.3, 0.0))
        print(f"        {{{a}, {q}, {y:.15g}, {a20:.15g}, {a02:.15g}}},  // a11 = {a11:.1e}")
    print("//   approach at alpha = 0.9, q = 0.4: beta, theta b~^2/q, a20, a02, a11")
    for b in (-0.99, -0.999, -0.9999):
        q = 0.4
        s = hcs.solve(0.9, b, q, maxwellian_theta(0.9, b, q))
        bt = q * (1 + b) / (2 * (1 + q))
        print(f"//   {b}: " + ("no cooling state" if s is None else
                              f"{s[0] * bt * bt / q:.10f}, {s[1]:.10f}, {s[2]:.10f}, {s[3]:.3e}"))
    print("// small roughness: the branch of the Maxwellian theta (alpha = 0.9, q = 0.4)")
    for b in (-0.6, -0.7, -0.8, -0.9, -0.95):
        s = hcs.solve(0.9, b, 0.4, maxwellian_theta(0.9, b, 0.4))
        print(f"//   beta = {b}: " + ("no root of the theta condition before a pole of the linear system"
                                       if s is None else ", ".join(f"{v:.6g}" for v in s)))


if __name__ == "__main__":
    main()
