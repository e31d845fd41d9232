#!/usr/bin/env python3
"""Independent reference for the Navier-Stokes linear modes of the cooling state of rough grains.

Run:  scripts/python3 scripts/rough_linear_theory_reference.py [--n N --sigma S --m M --T T]
                                                              [--check-collision-integrals]

What it computes
----------------
The linear hydrodynamics of the homogeneous cooling state (HCS) of a dilute gas of ROUGH inelastic
hard spheres (d = 3, equal spheres of mass m and diameter sigma, constant normal restitution alpha,
tangential restitution beta in (-1, 1], reduced moment of inertia q = 4 I/(m sigma^2)), and prints,
in the layout of the C++ test arrays (ready to paste), the reference numbers hard-coded in

  tests/observables/longitudinal_modes_test.cpp
      RoughAgreesWithAnIndependentEvaluation
          {alpha, beta, q, theta, eta_b*, zeta_U, kappa*, mu*, L_par/lambda} and
          {alpha, beta, q, k lambda, heat, Re sound[0], Im sound[0], Re sound[1], Im sound[1]}
      RoughHeatModeGrowsInBoxesLongerThanTheCriticalLength
          L_par/lambda and L_c/lambda at alpha = 0.9, q = 2/5, beta = -0.5, 0, 0.5, 1
      ElasticPerfectlyRoughGasIsPidduckGas (the limits it states, q = 0.1, 0.4, 1)
  tests/observables/shear_mode_test.cpp
      RoughGrainsCoefficients  {alpha, beta, theta, eta*, growth at k -> 0, L_c/lambda}  (q = 2/5)
      RoughGrainsLimits        (alpha = beta = 1; beta -> -1 is discussed below)

Method (nothing is taken from the C++ sources)
----------------------------------------------
* Collision rule (docs/model.md section 3), equal spheres, R = sigma/2, I = q m R^2, u = R omega,
  n the unit normal from grain 2 to grain 1, approaching when (v1 - v2).n < 0:
      g_c = v1 - v2 - (u1 + u2) x n,   g_c^T = g_c - (g_c.n) n,
      a~ = (1 + alpha)/2,   b~ = q (1 + beta)/(2 (1 + q)),
      v1' - v1 = v2 - v2' = -a~ (g_c.n) n - b~ g_c^T,   u1' - u1 = u2' - u2 = -n x (v1' - v1)/q.
* Boltzmann collision integrals over the two-temperature Maxwellian
      f0 = n (m/2 pi T_tr)^(3/2) (I/2 pi T_rot)^(3/2) exp(-m c^2/2T_tr - I omega^2/2T_rot),
  (sigma^2/2) int dv1 dw1 dv2 dw2 f f int_{g.n < 0} dn |g.n| [psi(1') + psi(2') - psi(1) - psi(2)],
  and the linearised ones sigma^2 int f0(1) f0(2) phi(2) ... for a trial function f1 = f0 phi, by
  deterministic quadrature: the integrands used are rotation invariant scalars (tensor and vector
  moments are contracted with their trial functions), so n is put along z (factor 4 pi); in the
  variables G = (v1 + v2)/2, g = v1 - v2, W = u1 + u2, D = u1 - u2 (independent Gaussians) the only
  non-polynomial factor is |g_z| on g_z < 0, integrated by the Gauss rule of the weight
  s exp(-s^2/2) on (0, inf) (Stieltjes procedure); every other variable by Gauss-Hermite with enough
  nodes to be exact for the polynomial degree it carries (G: 3, D: 2, W_z: 2, W_x, W_y: 3,
  g_x, g_y: 4, s: 5 nodes; --check-collision-integrals adds one node everywhere and the results do
  not move beyond round-off).
* Cooling state (two-temperature Maxwellian; Huthmann & Zippelius 1997 for the approximation):
  Xi_tr = int (m c^2/2) J[f0, f0], Xi_rot = int (I omega^2/2) J[f0, f0];
  zeta_tr = -Xi_tr/((3/2) n T_tr) = zeta_rot = -Xi_rot/((3/2) n T_rot) fixes theta = T_rot/T_tr
  (found by bisection on the sign of zeta_tr - zeta_rot, no closed form used);
  T = (T_tr + T_rot)/2 (energy density 3 n T), zeta = -(Xi_tr + Xi_rot)/(3 n T).
* Chapman-Enskog to first order about it, each coefficient in the first Sonine approximation (the
  scheme of Kremer, Santos & Garzo 2014, PRE 90 022205, and Garzo, Santos & Kremer 2018, PRE 97
  052901), derived here from the moments of  (d_t^(0) + L) f1 = -(D_t^(1) + c.grad) f0,
  d_t^(0) = -zeta T d/dT at fixed theta (every coefficient ~ T^(1/2), mu ~ T^(3/2)):
  - shear viscosity: trial f1 ~ f0 (c c - c^2/3), Pi = -eta (grad u + grad u^T - (2/3) div u),
        eta = n T_tr/(nu_eta - zeta/2);
  - heat flux q = q_tr + q_rot = -kappa grad T - mu grad n: trial f1 = f0 c.[A (x_t - 5/2) +
    B (x_r - 3/2)], x_t = m c^2/2T_tr, x_r = I omega^2/2T_rot; the collision moments of
    (m c^2/2) c and (I omega^2/2) c give a 2x2 matrix N (int psi_a L f1 = N_ab q_b), the sources are
    -(5/2) n T_tr^2/(m T) grad T and -(3/2) n T_tr T_rot/(m T) grad T (none in grad n), so
        (N - 2 zeta) (kappa_tr, kappa_rot) = (5/2 n T_tr^2, 3/2 n T_tr T_rot)/(m T),
        (N - 3/2 zeta) (mu_tr, mu_rot) = zeta (T/n) (kappa_tr, kappa_rot);
  - bulk viscosity and first-order cooling: trial f1 = f0 [(x_t - 3/2)/T_tr - (x_r - 3/2)/T_rot]
    delta (T_tr -> T_tr + delta, T_rot -> T_rot - delta at fixed T), delta = -eta_b div u/n, so
    p = n T_tr - eta_b div u and zeta = zeta^(0) + zeta_U div u.  With D = d/dT_tr - d/dT_rot (the
    linearised collision integrals of that trial function), tau_t = 2/(1 + theta),
    tau_r = 2 theta/(1 + theta), the translational energy balance at first order gives
        n T_tr (tau_r/2) div u = [(tau_r/2) D Xi_tr - (tau_t/2) D Xi_rot + (3/4) n zeta] delta,
        zeta_U = eta_b D(Xi_tr + Xi_rot)/(3 n^2 T).
* Linearised Navier-Stokes equations about the HCS (see RoughGas.longitudinal_matrix), per unit
  time in dimensional units, divided by the collision frequency nu_c = n pi sigma^2 <|v1 - v2|>
  (also by quadrature), eigenvalues by numpy.linalg.eigvals; critical lengths by bisection.

Conventions (those of docs/model.md section 8, "Linear stability of the cooling state" and "Heat and
sound modes")
----------------------------------------------------------------------------------------------
* Everything is computed in dimensional units with arbitrary n, sigma, m, T (defaults 0.37, 1.3,
  2.1, 0.8; T is the total temperature (T_tr + T_rot)/2); the printed numbers are dimensionless and
  must not depend on them.
* Reduced units at T_tr: eta0 = (5/(16 sigma^2)) sqrt(m T_tr/pi), kappa0 = (15/4) eta0/m,
  nu0 = n T_tr/eta0; eta* = eta/eta0, eta_b* = eta_b/eta0, kappa* = kappa/kappa0,
  mu* = n mu/(T kappa0) (T the total temperature), zeta* = zeta/nu0; zeta_U is dimensionless.
* Rates per collision per particle: divided by nu_c (= 4 n sigma^2 sqrt(pi T_tr/m)); wave numbers in
  units of lambda = 1/(sqrt(2) pi n sigma^2), lengths L = 2 pi/k in units of lambda.
* Longitudinal fields of a standing wave: delta n/n = rho cos kx, delta T/T = tau cos kx,
  u_x/sqrt(T_tr(t)/m) = w sin kx (T_tr(t) of the cooling state); d(rho, tau, w)/dt = M (rho, tau, w),
  eigenvalues of M/nu_c.  Labels: if a conjugate pair exists, heat = the real eigenvalue, sound[0] =
  the one with Im > 0, sound[1] its conjugate; if all three are real, heat >= sound[0] >= sound[1].
* Transverse (shear) mode: u_y/sqrt(T_tr(t)/m) ~ sin kx grows at [zeta/2 - eta k^2/(n m)]/nu_c.
* beta = -1 (smooth grains) is outside this scheme: there the rotational degrees do not exchange
  energy, the cooling state has no finite theta, and the smooth theory (with its Sonine a2) applies;
  the script shows the limit beta -> -1 of the rough theory instead (zeta* -> 0).

Cross-checks printed (separate sections, compared, not used): the closed forms of docs/model.md for
theta, zeta*, eta*, N, kappa*, mu*, L_par/L_c; Pidduck's elastic perfectly rough gas (alpha = beta
= 1, Chapman & Cowling 1970: eta* = 6(1+q)^2/(6+13q), kappa* = 12(1+q)^2(37+151q+50q^2)/
(25(12+75q+101q^2+102q^3)), eta_b* = (1+q)^2/(10q), sound speed sqrt(4T/(3m))); the k -> 0
eigenvalues +zeta/(2 nu_c), 0, -zeta/(2 nu_c).

Runtime: about 5 s.  Optional check (--check-collision-integrals, about 25 s more): the collision rule itself (contact
velocity restitution and energy change), every collision integral with one more quadrature node in
every variable, and against a Monte Carlo quadrature of the collision rule over random normals on the
whole sphere (no n = z reduction), with its standard errors.
"""

import argparse
import functools
import itertools
import math

import numpy as np
from numpy.polynomial.hermite_e import hermegauss
from numpy.polynomial.legendre import leggauss

# The smooth grains' reference's root finding and the labels of a mode matrix's eigenvalues (no
# physics: the matrix is this script's own).
from linear_theory_reference import LinearModes, add_gas_unit_arguments, bisect_sign, critical_length

PI = math.pi

LONGITUDINAL_CASES = [(0.9, 0.0, 0.4), (0.8, 0.5, 0.4), (0.9, 1.0, 0.4), (0.7, -0.5, 0.5)]
K_LAMBDAS = (0.02, 0.1, 0.3)
SHEAR_CASES = [(0.9, -0.5), (0.9, 0.0), (0.9, 1.0), (0.8, 0.5), (0.7, 0.9), (0.5, -0.5)]
ALPHA09_BETAS = (-0.5, 0.0, 0.5, 1.0)
PIDDUCK_QS = (0.1, 0.4, 1.0)

# Gauss nodes per variable: G (each component), D (each), W_z, W_x and W_y, g_x and g_y, s = |g_z|.
ORDERS = dict(G=3, D=2, Wz=2, Wt=3, gt=4, s=5)
ENERGY_ORDERS = dict(G=1, D=1, Wz=1, Wt=2, gt=2, s=3)  # Xi_tr, Xi_rot only: g_t, W_t, s enter


# ---------------------------------------------------------------------------------------------
# Quadrature rules
# ---------------------------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def half_range_rule(npts):
    """Gauss rule for int_0^inf F(s) s exp(-s^2/2) ds (total weight 1), by the Stieltjes procedure
    on a composite Gauss-Legendre discretisation of [0, 16] (16 panels of 32 nodes) and the
    Golub-Welsch eigenproblem."""
    t, wt = leggauss(32)
    x = np.concatenate([j + 0.5 * (t + 1) for j in range(16)])
    w = np.tile(0.5 * wt, 16) * x * np.exp(-x * x / 2)
    a, b = [], []
    p_prev, p, norm_prev = np.zeros_like(x), np.ones_like(x), 1.0
    for k in range(npts):
        norm = np.sum(w * p * p)
        a.append(np.sum(w * x * p * p) / norm)
        b.append(norm / norm_prev if k > 0 else 0.0)
        p_prev, p = p, (x - a[-1]) * p - (b[-1] * p_prev if k > 0 else 0.0)
        norm_prev = norm
    J = np.diag(a) + np.diag(np.sqrt(b[1:]), 1) + np.diag(np.sqrt(b[1:]), -1)
    nodes, vecs = np.linalg.eigh(J)
    return nodes, np.sum(w) * vecs[0] ** 2


def normal_rule(npts):
    """Gauss-Hermite for E[F(Z)], Z standard normal."""
    x, w = hermegauss(npts)
    return x, w / math.sqrt(2 * PI)


# ---------------------------------------------------------------------------------------------
# The collision rule (docs/model.md section 3, equal spheres), vectorised over pairs
# ---------------------------------------------------------------------------------------------
def dot(a, b):
    return np.einsum("...i,...i->...", a, b)


def collide(v1, v2, u1, u2, nrm, alpha, beta, q):
    """Post-collision (v1', v2', u1', u2'), u = R omega; nrm from grain 2 to grain 1."""
    at, bt = (1 + alpha) / 2, q * (1 + beta) / (2 * (1 + q))
    gc = v1 - v2 - np.cross(u1 + u2, nrm)
    gn = dot(gc, nrm)[..., None]
    dv = -at * gn * nrm - bt * (gc - gn * nrm)
    du = -np.cross(nrm, dv) / q
    return v1 + dv, v2 - dv, u1 + du, u2 + du


class Pair:
    """Pre- and post-collision velocities of a sample of pairs, with the gas constants."""

    def __init__(self, v1, v2, u1, u2, nrm, gas):
        self.c1, self.c2, self.u1, self.u2 = v1, v2, u1, u2
        self.p1, self.p2, self.pu1, self.pu2 = collide(v1, v2, u1, u2, nrm, gas.alpha, gas.beta, gas.q)
        self.m, self.q, self.T_tr, self.T_rot = gas.m, gas.q, gas.T_tr, gas.T_rot


def pair_integrals(gas, funcs, orders=ORDERS):
    """For each F: I[F] = int dG1 dG2 f0(1) f0(2) int_{g.n<0} dn |g.n| F, F a rotation invariant
    function of (pre, post) pair velocities (a Pair), f0 the two-temperature Maxwellian of gas.

    n = z (factor 4 pi); G ~ N(0, T_tr/2m), g ~ N(0, 2T_tr/m), W, D ~ N(0, 2T_rot/(q m)) per
    component; g_z = -s sqrt(2 T_tr/m) with the weight s exp(-s^2/2).  The s nodes and the x
    component of G are looped over, the rest is vectorised.
    """
    m, q, T_tr, T_rot = gas.m, gas.q, gas.T_tr, gas.T_rot
    sG, sg, sW = math.sqrt(T_tr / (2 * m)), math.sqrt(2 * T_tr / m), math.sqrt(2 * T_rot / (q * m))
    rG, rD, rWz, rWt, rgt = (normal_rule(orders[k]) for k in ("G", "D", "Wz", "Wt", "gt"))
    rs = half_range_rule(orders["s"])
    inner = [rG, rG, rD, rD, rD, rWz, rWt, rWt, rgt, rgt]
    grids = np.meshgrid(*[r[0] for r in inner], indexing="ij")
    wgrid = np.ones_like(grids[0])
    for k, r in enumerate(inner):
        shape = [1] * len(inner)
        shape[k] = len(r[1])
        wgrid = wgrid * r[1].reshape(shape)
    X = [gr.reshape(-1) for gr in grids]
    wflat = wgrid.reshape(-1)
    Gy, Gz = sG * X[0], sG * X[1]
    D = sW * np.stack([X[2], X[3], X[4]], -1)
    W = sW * np.stack([X[6], X[7], X[5]], -1)
    u1, u2 = (W + D) / 2, (W - D) / 2
    nrm = np.array([0.0, 0.0, 1.0])
    pref = gas.n ** 2 * 4 * PI * sg / math.sqrt(2 * PI)
    total = np.zeros(len(funcs))
    for (gx_node, gx_w), (s_node, s_w) in itertools.product(zip(*rG), zip(*rs)):
        G = np.stack([np.full_like(Gy, sG * gx_node), Gy, Gz], -1)
        g = np.stack([sg * X[8], sg * X[9], np.full_like(Gy, -sg * s_node)], -1)
        pair = Pair(G + g / 2, G - g / 2, u1, u2, nrm, gas)
        w = wflat * (gx_w * s_w)
        for j, f in enumerate(funcs):
            total[j] += np.sum(w * f(pair))
    return pref * total


def pair_integrals_monte_carlo(gas, funcs, samples, seed=12345, chunk=200000):
    """The same I[F] by Monte Carlo over Maxwellian pairs and normals uniform on the whole sphere,
    weight 4 pi |g.n| on g.n < 0; returns (estimates, standard errors)."""
    rng = np.random.default_rng(seed)
    m, q, T_tr, T_rot = gas.m, gas.q, gas.T_tr, gas.T_rot
    sv, su = math.sqrt(T_tr / m), math.sqrt(T_rot / (q * m))
    s1, s2, done = np.zeros(len(funcs)), np.zeros(len(funcs)), 0
    while done < samples:
        k = min(chunk, samples - done)
        v1, v2 = sv * rng.standard_normal((k, 3)), sv * rng.standard_normal((k, 3))
        u1, u2 = su * rng.standard_normal((k, 3)), su * rng.standard_normal((k, 3))
        nrm = rng.standard_normal((k, 3))
        nrm /= np.linalg.norm(nrm, axis=1)[:, None]
        gn = dot(v1 - v2, nrm)
        wt = 4 * PI * np.where(gn < 0, -gn, 0.0)
        pair = Pair(v1, v2, u1, u2, nrm, gas)
        for j, f in enumerate(funcs):
            y = wt * f(pair)
            s1[j] += np.sum(y)
            s2[j] += np.sum(y * y)
        done += k
    mean = s1 / samples
    err = np.sqrt(np.maximum(s2 / samples - mean ** 2, 0.0) / samples)
    return gas.n ** 2 * mean, gas.n ** 2 * err


# ---------------------------------------------------------------------------------------------
# Integrands (sums over both grains of psi(after) - psi(before), times a trial function of grain 2)
# ---------------------------------------------------------------------------------------------
def e_tr(P, c):
    return 0.5 * P.m * dot(c, c)


def e_rot(P, u):
    return 0.5 * P.q * P.m * dot(u, u)


def d_e_tr(P):
    return e_tr(P, P.p1) + e_tr(P, P.p2) - e_tr(P, P.c1) - e_tr(P, P.c2)


def d_e_rot(P):
    return e_rot(P, P.pu1) + e_rot(P, P.pu2) - e_rot(P, P.u1) - e_rot(P, P.u2)


def x_t(P, c):
    return 0.5 * P.m * dot(c, c) / P.T_tr


def x_r(P, u):
    return 0.5 * P.q * P.m * dot(u, u) / P.T_rot


def phi_exchange(P):
    """(x_t - 3/2)/T_tr - (x_r - 3/2)/T_rot of grain 2: d f0/dT_tr - d f0/dT_rot over f0."""
    return (x_t(P, P.c2) - 1.5) / P.T_tr - (x_r(P, P.u2) - 1.5) / P.T_rot


def d_pressure(P):
    """Sum over grains of the change of m (c c)°, contracted with (c c)° of grain 2
    ((a a)°:(b b)° = (a.b)^2 - a^2 b^2/3)."""
    b, b2 = P.c2, dot(P.c2, P.c2)
    contract = lambda a: dot(a, b) ** 2 - dot(a, a) * b2 / 3
    return P.m * (contract(P.p1) + contract(P.p2) - contract(P.c1) - contract(P.c2))


def flux_tr(P, c, u):
    return e_tr(P, c)[..., None] * c


def flux_rot(P, c, u):
    return e_rot(P, u)[..., None] * c


def heat(psi, trial):
    def f(P):
        d = psi(P, P.p1, P.pu1) + psi(P, P.p2, P.pu2) - psi(P, P.c1, P.u1) - psi(P, P.c2, P.u2)
        return trial(P) * dot(P.c2, d)
    return f


TRIAL_T = lambda P: x_t(P, P.c2) - 2.5
TRIAL_R = lambda P: x_r(P, P.u2) - 1.5

INTEGRANDS = [
    lambda P: np.ones_like(P.c1[..., 0]),            # 0: collisions
    d_e_tr,                                          # 1: 2 Xi_tr/sigma^2
    d_e_rot,                                         # 2: 2 Xi_rot/sigma^2
    lambda P: phi_exchange(P) * d_e_tr(P),           # 3: D Xi_tr/sigma^2
    lambda P: phi_exchange(P) * d_e_rot(P),          # 4: D Xi_rot/sigma^2
    d_pressure,                                      # 5: shear
    heat(flux_tr, TRIAL_T), heat(flux_tr, TRIAL_R),  # 6, 7: J_tt, J_tr
    heat(flux_rot, TRIAL_T), heat(flux_rot, TRIAL_R),  # 8, 9: J_rt, J_rr
]
INTEGRAND_NAMES = ["collisions", "Xi_tr", "Xi_rot", "D Xi_tr", "D Xi_rot", "shear (c c)°",
                   "heat tr<-tr", "heat tr<-rot", "heat rot<-tr", "heat rot<-rot"]


# ---------------------------------------------------------------------------------------------
# The gas: cooling state, transport coefficients, linear modes
# ---------------------------------------------------------------------------------------------
class _Temperatures:
    """Minimal stand-in carrying what pair_integrals needs at a trial theta."""

    def __init__(self, alpha, beta, q, n, m, T_tr, T_rot):
        self.alpha, self.beta, self.q, self.n, self.m = alpha, beta, q, n, m
        self.T_tr, self.T_rot = T_tr, T_rot


def cooling_rates(alpha, beta, q, n, sigma, m, T, theta):
    """(zeta_tr, zeta_rot) of the two-temperature Maxwellian at theta, T = (T_tr + T_rot)/2."""
    T_tr, T_rot = 2 * T / (1 + theta), 2 * T * theta / (1 + theta)
    t = _Temperatures(alpha, beta, q, n, m, T_tr, T_rot)
    i_tr, i_rot = pair_integrals(t, [d_e_tr, d_e_rot], ENERGY_ORDERS)
    xi_tr, xi_rot = 0.5 * sigma ** 2 * i_tr, 0.5 * sigma ** 2 * i_rot
    return -xi_tr / (1.5 * n * T_tr), -xi_rot / (1.5 * n * T_rot)


def cooling_state_theta(alpha, beta, q, n, sigma, m, T):
    """theta with zeta_tr = zeta_rot, by bisection in ln theta on the sign of the difference."""
    f = lambda th: np.subtract(*cooling_rates(alpha, beta, q, n, sigma, m, T, th))
    lo, hi = 1e-8, 1e8
    if not (f(lo) > 0 > f(hi)):
        raise ValueError(f"no cooling state with finite theta at alpha={alpha}, beta={beta}, q={q}")
    return bisect_sign(f, lo, hi, lambda lo, hi: math.sqrt(lo * hi))


class RoughGas(LinearModes):
    """Dimensional HCS of rough inelastic hard spheres and its Navier-Stokes coefficients."""

    def __init__(self, alpha, beta, q, n, sigma, m, T, orders=ORDERS, theta=None):
        """theta: None for the cooling state's; a number only to evaluate the collision integrals
        of a two-temperature Maxwellian that is not the cooling state (the beta = -1 check)."""
        self.alpha, self.beta, self.q, self.n, self.sigma, self.m, self.T = alpha, beta, q, n, sigma, m, T
        th = cooling_state_theta(alpha, beta, q, n, sigma, m, T) if theta is None else theta
        self.theta = th
        self.T_tr, self.T_rot = 2 * T / (1 + th), 2 * T * th / (1 + th)
        T_tr, T_rot = self.T_tr, self.T_rot
        self.integrals = r = pair_integrals(self, INTEGRANDS, orders)
        s2 = sigma ** 2
        self.nu_c = s2 * r[0] / n
        xi_tr, xi_rot = 0.5 * s2 * r[1], 0.5 * s2 * r[2]
        self.zeta_tr, self.zeta_rot = -xi_tr / (1.5 * n * T_tr), -xi_rot / (1.5 * n * T_rot)
        self.zeta = -(xi_tr + xi_rot) / (3 * n * T)
        if abs(self.zeta) < 1e-12 * self.nu_c:  # alpha = beta = 1: zero up to round-off
            self.zeta = 0.0
        d_tr, d_rot = s2 * r[3], s2 * r[4]
        # shear viscosity: int m (cc)° L[f0 (cc)°] = (X/5) P, f1 = f0 (m/(2 n T_tr^2)) Pi:(cc)°
        nu_eta = -s2 * r[5] * m / (10 * n * T_tr ** 2)
        self.eta = n * T_tr / (nu_eta - self.zeta / 2)
        # heat flux: N_ab from int psi_a L[f0 c phi_b] = (J_ab/3) delta, f1 of unit q_t, q_r
        J = s2 * np.array([[r[6], r[7]], [r[8], r[9]]])
        norm = np.array([2.5 * n * T_tr ** 2 / m, 1.5 * n * T_tr * T_rot / m])
        self.N = -J / (3 * norm[None, :])
        z = self.zeta
        self.kappa_vec = np.linalg.solve(self.N - 2 * z * np.eye(2), norm / T)
        self.mu_vec = z * (T / n) * np.linalg.solve(self.N - 1.5 * z * np.eye(2), self.kappa_vec)
        self.kappa, self.mu = float(np.sum(self.kappa_vec)), float(np.sum(self.mu_vec))
        # bulk viscosity and zeta_U
        tau_t, tau_r = 2 / (1 + th), 2 * th / (1 + th)
        bracket = 0.5 * tau_r * d_tr - 0.5 * tau_t * d_rot + 0.75 * n * z
        delta_per_div_u = n * T_tr * 0.5 * tau_r / bracket
        self.eta_b = -n * delta_per_div_u
        self.zeta_u = self.eta_b * (d_tr + d_rot) / (3 * n ** 2 * T)
        self.nu_eta = nu_eta
        self.lam = 1 / (math.sqrt(2) * PI * n * sigma ** 2)
        self.eta0 = 5 / (16 * sigma ** 2) * math.sqrt(m * T_tr / PI)
        self.kappa0 = 15 / 4 * self.eta0 / m
        self.nu0 = n * T_tr / self.eta0

    # dimensionless coefficients, for printing
    eta_star = property(lambda s: s.eta / s.eta0)
    eta_b_star = property(lambda s: s.eta_b / s.eta0)
    kappa_star = property(lambda s: s.kappa / s.kappa0)
    mu_star = property(lambda s: s.n * s.mu / (s.T * s.kappa0))
    zeta_star = property(lambda s: s.zeta / s.nu0)
    N_star = property(lambda s: s.N / s.nu0)

    def longitudinal_matrix(self, k):
        """Real M: d/dt (rho, tau, w) for rho cos kx, tau cos kx, w sin kx (see the docstring).

        continuity  d(dn)/dt = -n du/dx                               -> drho/dt = -k v w,
                    u = v w, v = sqrt(T_tr/m), dv/dt = -(zeta/2) v
        momentum    m n du/dt = -d(n T_tr)/dx + ((4/3) eta + eta_b) d2u/dx2, T_tr = 2T/(1+theta)
                                                                      -> dw/dt = k v (rho + tau)
                                                   + (zeta/2 - ((4/3) eta + eta_b) k^2/(m n)) w
        energy      3 n dT/dt = -n T_tr du/dx + d/dx(kappa dT/dx + mu dn/dx) - 3 n T zeta,
                    zeta = zeta0 (n/n_h) (T/T_h)^(1/2) + zeta_U du/dx
                    -> dtau/dt = -(zeta + mu k^2/(3 T)) rho - (zeta/2 + kappa k^2/(3 n)) tau
                                 - (T_tr/(3 T) + zeta_U) k v w
        """
        n, m, T, z = self.n, self.m, self.T, self.zeta
        v = math.sqrt(self.T_tr / m)
        return np.array([
            [0.0, 0.0, -k * v],
            [-(z + self.mu * k ** 2 / (3 * T)), -(z / 2 + self.kappa * k ** 2 / (3 * n)),
             -(self.T_tr / (3 * T) + self.zeta_u) * k * v],
            [k * v, k * v, z / 2 - (4 * self.eta / 3 + self.eta_b) * k ** 2 / (m * n)],
        ])

    def longitudinal_matrix_complex(self, k):
        """The same equations for amplitudes of exp(ikx) (u_x = v w exp(ikx)); cross-check only."""
        M = self.longitudinal_matrix(k).astype(complex)
        M[0, 2] *= 1j
        M[1, 2] *= 1j
        M[2, 0] *= -1j
        M[2, 1] *= -1j
        return M


# ---------------------------------------------------------------------------------------------
# Cross-check only: the closed forms stated in docs/model.md (not used above)
# ---------------------------------------------------------------------------------------------
def closed_forms(alpha, beta, q):
    at, bt = (1 + alpha) / 2, q * (1 + beta) / (2 * (1 + q))
    e = bt
    A = (1 - alpha ** 2) / 4 + e * (1 - e)
    B = e ** 2 / q
    C = (e / q) * (1 - e / q)
    th = (A - C + math.sqrt((A - C) ** 2 + 4 * B ** 2)) / (2 * B)
    zeta = 5 / 12 * (1 - alpha ** 2 + 4 * bt * (1 - bt) - 4 * bt ** 2 * th / q)
    eta = 1 / ((at + bt) * (2 - at - bt) + bt ** 2 * th / (6 * q) - zeta / 2)
    N = np.array([
        [(41 * (at + bt) - 33 * (at ** 2 + bt ** 2) - 16 * at * bt - 7 * bt ** 2 * th / q) / 12,
         -25 / 18 * bt ** 2 / q],
        [-5 / 12 * (bt / q) * (bt * th / q + 3 * bt - th),
         5 / 18 * (3 * (at + bt) - (bt / q) * (4 * at + 6 * bt - 7) - 3 * bt ** 2 / q ** 2)],
    ])
    kv = 8 / (15 * (1 + th)) * np.linalg.solve(N - 2 * zeta * np.eye(2), np.array([2.5, 1.5 * th]))
    kappa = float(np.sum(kv))
    mu = zeta * float(np.sum(np.linalg.solve(N - 1.5 * zeta * np.eye(2), kv)))
    L_c = 5 * PI ** 1.5 / 4 * math.sqrt(eta / zeta) if zeta > 0 else math.inf
    L_par = L_c * math.sqrt(5 * (kappa - mu) / (4 * eta))
    return dict(theta=th, zeta=zeta, eta=eta, N=N, kappa=kappa, mu=mu, L_c=L_c, L_par=L_par)


def pidduck(q):
    return dict(eta=6 * (1 + q) ** 2 / (6 + 13 * q),
                kappa=12 * (1 + q) ** 2 * (37 + 151 * q + 50 * q ** 2)
                / (25 * (12 + 75 * q + 101 * q ** 2 + 102 * q ** 3)),
                eta_b=(1 + q) ** 2 / (10 * q))


def rel(a, b):
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(b), 1e-300)


# ---------------------------------------------------------------------------------------------
# Optional checks of the collision integrals
# ---------------------------------------------------------------------------------------------
def check_collision_rule(alpha, beta, q, samples=1000, seed=7):
    rng = np.random.default_rng(seed)
    v1, v2, u1, u2 = (rng.standard_normal((samples, 3)) for _ in range(4))
    nrm = rng.standard_normal((samples, 3))
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    p1, p2, pu1, pu2 = collide(v1, v2, u1, u2, nrm, alpha, beta, q)
    gc = v1 - v2 - np.cross(u1 + u2, nrm)
    pgc = p1 - p2 - np.cross(pu1 + pu2, nrm)
    gn, pgn = dot(gc, nrm), dot(pgc, nrm)
    gT, pgT = gc - gn[:, None] * nrm, pgc - pgn[:, None] * nrm
    E = lambda a, b, c, d: 0.5 * (dot(a, a) + dot(b, b)) + 0.5 * q * (dot(c, c) + dot(d, d))  # m = 1
    dE = E(p1, p2, pu1, pu2) - E(v1, v2, u1, u2)
    kappa_eff = q / (1 + q)
    dE_rule = 0.25 * (alpha ** 2 - 1) * gn ** 2 + 0.25 * kappa_eff * (beta ** 2 - 1) * dot(gT, gT)
    # angular momentum about the contact point, m = 1, R = 1: L = I w + r x v, r = +-n
    Lc = lambda a, b, c, d: q * (c + d) + np.cross(nrm, a) - np.cross(nrm, b)
    return (np.max(np.abs(pgn + alpha * gn)), np.max(np.abs(pgT + beta * gT)), np.max(np.abs(dE - dE_rule)),
            np.max(np.abs(p1 + p2 - v1 - v2)),
            np.max(np.abs(Lc(p1, p2, pu1, pu2) - Lc(v1, v2, u1, u2))))


def check_collision_integrals(args, samples):
    print("// collision rule: max |(g.n)' + alpha g.n|, |g_T' + beta g_T|, |dE - model.md dE|,"
          " |d momentum|, |d angular momentum about the contact| (1000 random collisions)")
    for a, b, q in [(0.9, 0.0, 0.4), (0.7, -0.5, 0.5), (0.9, 1.0, 0.4)]:
        errs = check_collision_rule(a, b, q)
        print(f"//   {a}, {b}, {q}: " + ", ".join(f"{e:.1e}" for e in errs))
    x, w = half_range_rule(ORDERS["s"])
    worst = max(abs(np.sum(w * x ** k) / (2 ** (k / 2) * math.gamma(k / 2 + 1)) - 1) for k in range(10))
    print(f"// half-range Gauss rule ({ORDERS['s']} nodes): moments 0..9 of s exp(-s^2/2), worst relative error {worst:.1e}")
    finer = {k: v + 1 for k, v in ORDERS.items()}
    print(f"// collision integrals at the cooling state: Gauss nodes {ORDERS} against one more node"
          f" everywhere, and Monte Carlo ({samples} pairs, normals on the whole sphere)")
    for a, b, q in [(0.9, 0.0, 0.4), (0.7, -0.5, 0.5)]:
        g = RoughGas(a, b, q, args.n, args.sigma, args.m, args.T)
        fine = pair_integrals(g, INTEGRANDS, finer)
        mc, err = pair_integrals_monte_carlo(g, INTEGRANDS, samples, seed=12345 + int(1000 * (a + b + q)))
        print(f"//   alpha = {a}, beta = {b}, q = {q} (theta = {g.theta:.15g}):")
        for name, x0, x1, xm, em in zip(INTEGRAND_NAMES, g.integrals, fine, mc, err):
            print(f"//     {name:14s} {x0:+.15e}  finer rel {rel(x1, x0):.1e}  Monte Carlo {xm:+.6e} +- {em:.1e}"
                  f" ({(xm - x0) / em:+.2f} s.e.)")


# ---------------------------------------------------------------------------------------------
def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_gas_unit_arguments(ap)
    ap.add_argument("--check-collision-integrals", action="store_true",
                    help="also check the collision rule and the quadrature of every collision integral"
                         " (one more node in every variable, and Monte Carlo over the whole sphere; slow)")
    ap.add_argument("--samples", type=int, default=4000000,
                    help="Monte Carlo pairs for --check-collision-integrals (default 4e6)")
    args = ap.parse_args()
    cache = {}

    def gas(alpha, beta, q):
        key = (alpha, beta, q)
        if key not in cache:
            cache[key] = RoughGas(alpha, beta, q, args.n, args.sigma, args.m, args.T)
        return cache[key]

    print(f"// rough spheres, dimensional units n = {args.n}, sigma = {args.sigma}, m = {args.m}, T = {args.T}")
    print("// longitudinal_modes_test.cpp, RoughAgreesWithAnIndependentEvaluation:"
          " {alpha, beta, q, theta, bulk, zeta_u, kappa_star, mu_star, critical_length}")
    for a, b, q in LONGITUDINAL_CASES:
        g = gas(a, b, q)
        L = critical_length(g.longitudinal_max_rate, g.zeta)
        print(f"        {{{a}, {b}, {q}, {g.theta:.15g}, {g.eta_b_star:.15g}, {g.zeta_u:.15g},"
              f" {g.kappa_star:.15g}, {g.mu_star:.15g}, {L:.15g}}},")
    print("// {alpha, beta, q, k_lambda, heat, re0, im0, re1, im1}")
    worst = 0.0
    for a, b, q in LONGITUDINAL_CASES:
        g = gas(a, b, q)
        for x in K_LAMBDAS:
            h, s0, s1 = g.longitudinal_rates(x)
            ev_c = np.linalg.eigvals(g.longitudinal_matrix_complex(x / g.lam) / g.nu_c)
            for e in (h, s0, s1):
                worst = max(worst, min(abs(ev_c - e)))
            vals = [h.real, s0.real, s0.imag, s1.real, s1.imag]
            txt = ", ".join(f"{v:.15e}" for v in vals)
            print(f"        {{{a}, {b}, {q}, {x}, {txt}}},")
    print(f"// complex exp(ikx) form: largest distance to the real form's eigenvalues {worst:.1e}")

    print("// shear_mode_test.cpp, RoughGrainsCoefficients (q = 0.4):"
          " {alpha, beta, theta, eta_star, growth, critical_length}")
    for a, b in SHEAR_CASES:
        g = gas(a, b, 0.4)
        L = critical_length(g.shear_rate, g.zeta)
        print(f"        {{{a}, {b}, {g.theta:.15g}, {g.eta_star:.15g}, {g.shear_rate(0.0):.15g}, {L:.15g}}},")

    print("// longitudinal_modes_test.cpp, RoughHeatModeGrowsInBoxesLongerThanTheCriticalLength"
          " (alpha = 0.9, q = 0.4): {beta, L_par, L_c, L_par/L_c, sqrt(5 (kappa* - mu*)/(4 eta*))}")
    for b in ALPHA09_BETAS:
        g = gas(0.9, b, 0.4)
        Lp, Lc = critical_length(g.longitudinal_max_rate, g.zeta), critical_length(g.shear_rate, g.zeta)
        ratio = math.sqrt(1.25 * (g.kappa_star - g.mu_star) / g.eta_star)
        print(f"//   {{{b}, {Lp:.15g}, {Lc:.15g}, {Lp / Lc:.15g}, {ratio:.15g}}}")

    print("// k -> 0 (x = 1e-7): heat, sound0, sound1 against +zeta/(2 nu_c), 0, -zeta/(2 nu_c)")
    for a, b, q in LONGITUDINAL_CASES:
        g = gas(a, b, q)
        h, s0, s1 = g.longitudinal_rates(1e-7)
        hz = g.zeta / (2 * g.nu_c)
        print(f"//   {a}, {b}, {q}: {h.real:+.15e} {s0.real:+.3e} {s1.real:+.15e}  zeta/(2 nu_c) = {hz:.15e}"
              f"  (= (2/5) zeta*: {0.4 * g.zeta_star:.15e})")

    print("// Pidduck's gas, alpha = beta = 1: theta, zeta*, zeta_U, mu*, L_par;"
          " eta*, kappa*, eta_b* (quadrature / Chapman & Cowling); sound speed/sqrt(T/m) at k lambda = 1e-6")
    for q in PIDDUCK_QS:
        g = gas(1.0, 1.0, q)
        p = pidduck(q)
        L = critical_length(g.longitudinal_max_rate, g.zeta)
        x = 1e-6
        _, s0, _ = g.longitudinal_rates(x)
        speed = s0.imag * g.nu_c / (x / g.lam) / math.sqrt(g.T / g.m)  # omega/k over sqrt(T/m)
        print(f"//   q = {q}: theta {g.theta:.15g}, zeta* {g.zeta_star:.1e}, zeta_U {g.zeta_u:.1e}, mu* {g.mu_star:.1e},"
              f" L_par {L}")
        print(f"//     eta* {g.eta_star:.15g} / {p['eta']:.15g} ({rel(g.eta_star, p['eta']):.1e}),"
              f" kappa* {g.kappa_star:.15g} / {p['kappa']:.15g} ({rel(g.kappa_star, p['kappa']):.1e}),"
              f" eta_b* {g.eta_b_star:.15g} / {p['eta_b']:.15g} ({rel(g.eta_b_star, p['eta_b']):.1e}),"
              f" sound {speed:.12g} / sqrt(4/3) = {math.sqrt(4 / 3):.12g}")

    print("// beta -> -1 (alpha = 0.9, q = 0.4): the rough theory does not tend to the smooth one;"
          " theta grows as 1/(1 + beta)^2, the spins hold the energy, zeta* -> 0, L_c -> inf")
    a = 0.9
    for b in (-0.9, -0.99, -0.999):
        g = gas(a, b, 0.4)
        print(f"//   beta = {b}: theta {g.theta:.6g}, zeta* {g.zeta_star:.6g}, eta* {g.eta_star:.6g},"
              f" L_c {critical_length(g.shear_rate, g.zeta):.6g}, L_par {critical_length(g.longitudinal_max_rate, g.zeta):.6g},"
              f" N*_tt {g.N_star[0, 0]:.6g}")
    print("// beta = -1 exactly, collision integrals of a two-temperature Maxwellian at theta = 1 (no cooling state):"
          " the translational part is the smooth gas's (Maxwellian, a2 = 0; Brey, Dufty, Kim & Santos 1998)")
    for a in (0.9, 0.5):
        g = RoughGas(a, -1.0, 0.4, args.n, args.sigma, args.m, args.T, theta=1.0)
        smooth = [("zeta_tr*", g.zeta_tr / g.nu0, 5 / 12 * (1 - a * a)), ("zeta_rot*", g.zeta_rot / g.nu0, 0.0),
                  ("nu_eta*", g.nu_eta / g.nu0, (3 - a) * (1 + a) / 4),
                  ("N*_tt", g.N_star[0, 0], (1 + a) / 3 * (1 + 33 * (1 - a) / 16)), ("N*_tr", g.N_star[0, 1], 0.0)]
        print(f"//   alpha = {a}: " + ", ".join(f"{nm} {x:+.15f} ({y:+.15f})" for nm, x, y in smooth))

    print("// cross-check against the closed forms of docs/model.md (not used above): relative differences"
          " (N: largest absolute difference in units of nu0; zeta*, mu* absolute where they vanish)")
    for key in sorted(cache):
        a, b, q = key
        g, c = cache[key], closed_forms(a, b, q)
        d = [("theta", rel(g.theta, c["theta"])), ("eta*", rel(g.eta_star, c["eta"])),
             ("N*", float(np.max(np.abs(g.N_star - c["N"])))), ("kappa*", rel(g.kappa_star, c["kappa"]))]
        if g.zeta == 0.0:
            d += [("zeta*", abs(c["zeta"])), ("mu*", abs(c["mu"]))]
        else:
            d += [("zeta*", rel(g.zeta_star, c["zeta"])), ("mu*", rel(g.mu_star, c["mu"])),
                  ("L_c", rel(critical_length(g.shear_rate, g.zeta), c["L_c"])),
                  ("L_par", rel(critical_length(g.longitudinal_max_rate, g.zeta), c["L_par"]))]
        print(f"//   {a}, {b}, {q}: " + ", ".join(f"{nm} {v:.1e}" for nm, v in d))

    if args.check_collision_integrals:
        check_collision_integrals(args, args.samples)


if __name__ == "__main__":
    main()
