#!/usr/bin/env python3
"""Independent reference for the Navier-Stokes linear modes of the homogeneous cooling state.

Run:  scripts/python3 scripts/linear_theory_reference.py [--n N --sigma S --m M --T T]
                                                        [--check-collision-integrals]

What it computes
----------------
The linear hydrodynamics of the homogeneous cooling state (HCS) of a dilute gas of SMOOTH inelastic
hard spheres (d = 3, constant normal restitution alpha), and prints, in the layout of the C++ test
arrays (ready to paste), the reference numbers hard-coded in

  tests/observables/longitudinal_modes_test.cpp  LongitudinalModes.AgreesWithAnIndependentEvaluation
      {alpha, kappa*, mu*, L_par/lambda} and
      {alpha, k lambda, heat, Re sound[0], Im sound[0], Re sound[1], Im sound[1]}
  tests/observables/shear_mode_test.cpp          ShearMode.CoefficientsOfTheFirstSonineTheory
      {alpha, a2, eta*, growth at k -> 0, L_c/lambda}

Smooth spheres only: the rough-sphere tables of those files (Rough*, theta, eta_b, zeta_U, ...)
are NOT covered by this script.

References (formulas taken from the literature, not from the C++ sources)
-------------------------------------------------------------------------
* a2 of the HCS in the first Sonine approximation, linear in a2: T. P. C. van Noije & M. H. Ernst,
  Granular Matter 1, 57 (1998):  a2 = 16 (1-a)(1-2a^2)/(81 - 17a + 30a^2(1-a)).
* Navier-Stokes hydrodynamics and transport coefficients of the dilute gas, standard first Sonine
  approximation (Maxwellian weight, linear in a2): J. J. Brey, J. W. Dufty, C. S. Kim & A. Santos,
  Phys. Rev. E 58, 4638 (1998); V. Garzo & J. W. Dufty, Phys. Rev. E 59, 5895 (1999) (low-density
  limit).  Used from there: the collision frequencies of the Sonine trial functions
      nu_eta*   = (3-a)(1+a)(1 - a2/32)/4,
      nu_kappa* = (1+a)/3 [1 + 33(1-a)/16 + (19-3a) a2/512]   (both over nu0 = n T/eta0).
  Not the "modified Sonine" variant (Garzo, Santos & Montanero, Physica A 376, 94 (2007)).
* Derived here (so that they are not copied): the cooling rate zeta and the collision frequency
  nu_c of the first Sonine HCS distribution f0 = f_M [1 + a2 S2(c^2)], from Gaussian moments of the
  relative speed (<g> -> (1 - a2/16) <g>_M, <g^3> -> (1 + 3a2/16) <g^3>_M); and the Chapman-Enskog
  moment algebra that turns nu_eta, nu_kappa into eta, kappa, mu:
      eta   = n T / (nu_eta - zeta/2),
      kappa = (5 n T/(2m)) (1 + 2 a2) / (nu_kappa - 2 zeta),
      mu    = [(5/2) T^2 a2/m + zeta T kappa/n] / (nu_kappa - 3 zeta/2)
  (q = -kappa grad T - mu grad n;  the -2 zeta and -3/2 zeta come from -zeta T d/dT acting on the
  T^(3/2) heat-flux moments, plus -zeta/2 resp. -zeta A from d_t grad ln T = -grad zeta,
  zeta ~ n T^(1/2)).

Conventions (those of docs/model.md section 8 and docs/reference.md, modes.csv theory columns)
----------------------------------------------------------------------------------------------
* Everything is computed in dimensional units with arbitrary n, sigma, m, T (defaults 0.37, 1.3,
  2.1, 0.8); the printed numbers are dimensionless and must not depend on them.
* eta0 = (5/(16 sigma^2)) sqrt(m T/pi), kappa0 = (15/4) eta0/m, nu0 = n T/eta0;
  eta* = eta/eta0, kappa* = kappa/kappa0, mu* = n mu/(T kappa0), zeta* = zeta/nu0.
* Rates are per collision per particle: divided by nu_c = n pi sigma^2 <g>, the true collision
  frequency of the first Sonine HCS (= nu_M (1 - a2/16), nu_M = 4 n sigma^2 sqrt(pi T/m)).
* Wave numbers in units of the mean free path lambda = 1/(sqrt(2) pi n sigma^2); lengths L = 2 pi/k
  in units of lambda.
* Longitudinal fields of a standing wave: delta n/n = rho cos kx, delta T/T = theta cos kx,
  u_x/sqrt(T(t)/m) = w sin kx (T(t) the cooling reference temperature), a real 3x3 system
  d(rho, theta, w)/dt = M (rho, theta, w) per unit time; eigenvalues of M/nu_c by
  numpy.linalg.eigvals (cross-checked against the complex exp(ikx) form).  Labels: if a conjugate
  pair exists, heat = the real eigenvalue, sound[0] = the one with Im > 0, sound[1] its conjugate;
  if all three are real, heat >= sound[0] >= sound[1] (heat -> +zeta/(2 nu_c) as k -> 0).
* Transverse (shear) mode: u_y/sqrt(T(t)/m) ~ sin kx grows at [zeta/2 - eta k^2/(n m)]/nu_c.
* Critical lengths: L_par = 2 pi/k_par with k_par the zero of the largest real part of the
  longitudinal eigenvalues, and L_c = 2 pi/k_c with k_c the zero of the shear rate, both found by
  bisection on the sign (no closed form used).

Optional check (--check-collision-integrals, about 10 s per alpha): re-derives the literature
inputs -- a2 (from the steady c^4/c^2 moment balance, linearised in a2 as van Noije & Ernst do), the
Sonine factors of zeta and nu_c, and nu_eta*, nu_kappa* with their a2 terms -- by deterministic
quadrature of the inelastic collision integrals over Maxwellian pairs (Gauss-Hermite in the centre
of mass velocity, Gauss-Legendre in |g| and cos(theta), a uniform grid in phi), and prints them next
to the closed forms used above (they agree to ~1e-15).
"""

import argparse
import math

import numpy as np

PI = math.pi

LONGITUDINAL_ALPHAS = [0.95, 0.9, 0.8, 0.7, 0.5]
LONGITUDINAL_ROWS = [(a, x) for a in LONGITUDINAL_ALPHAS for x in (0.1, 0.3)]
SHEAR_ALPHAS = [0.95, 0.90, 0.80, 0.70, 0.60, 0.50]


# ---------------------------------------------------------------------------------------------
# Cooling state: a2 (literature) and the Sonine corrections of <g^p> (derived)
# ---------------------------------------------------------------------------------------------
def sonine_a2(alpha):
    """van Noije & Ernst (1998), first Sonine approximation, linear in a2, d = 3."""
    return 16 * (1 - alpha) * (1 - 2 * alpha ** 2) / (81 - 17 * alpha + 30 * alpha ** 2 * (1 - alpha))


def unit_maxwell_moment(p):
    """<|Z|^p> for a 3D standard normal vector Z."""
    return 2 ** (p / 2) * math.gamma((p + 3) / 2) / math.gamma(1.5)


def sonine_factor(p, a2):
    """<g^p> over f0 f0 divided by its Maxwellian value, to first order in a2.

    Reduced velocities c = V/sqrt(2T/m), f0 ~ exp(-c^2)[1 + a2 S2(c^2)], S2(x) = x^2/2 - 5x/2 + 15/8.
    For a Maxwellian pair, G = (c1 + c2)/2 (variance 1/4 per component) is independent of
    g = c1 - c2 (variance 1), and with u = g^2/4:
        E[c1^2 | g] = 3/4 + u,   E[c1^4 | g] = 15/16 + (5/2) u + u^2,
        E[S2(c1^2) | g] = u^2/2 - (5/4) u + 15/32.
    Both grains contribute alike: factor 1 + 2 a2 <g^p E[S2|g]>/<g^p>.
    """
    mp = unit_maxwell_moment
    corr = (mp(p + 4) / 32 - 5 * mp(p + 2) / 16 + 15 * mp(p) / 32) / mp(p)
    return 1 + 2 * a2 * corr


class LinearModes:
    """The modes of a gas's Navier-Stokes matrix, per collision per particle, and their labels:
    needs longitudinal_matrix(k) (per unit time), lam, nu_c, zeta, eta, n and m."""

    def longitudinal_rates(self, x):
        """(heat, sound0, sound1) per collision per particle at k lambda = x."""
        k = x / self.lam
        ev = np.linalg.eigvals(self.longitudinal_matrix(k) / self.nu_c)
        real = [e for e in ev if e.imag == 0.0]
        if len(real) == 3:
            heat, s0, s1 = sorted((e.real for e in ev), reverse=True)
            return complex(heat), complex(s0), complex(s1)
        assert len(real) == 1, ev
        pair = [e for e in ev if e.imag != 0.0]
        s0 = pair[0] if pair[0].imag > 0 else pair[1]
        s1 = pair[1] if pair[0].imag > 0 else pair[0]
        return complex(real[0].real), complex(s0), complex(s1)

    def longitudinal_max_rate(self, x):
        return max(np.linalg.eigvals(self.longitudinal_matrix(x / self.lam) / self.nu_c).real)

    def shear_rate(self, x):
        """Transverse wave u_y/sqrt(T_tr/m) (T_tr = T for smooth grains): [zeta/2 - eta k^2/(n m)]/nu_c at k lambda = x."""
        k = x / self.lam
        return (self.zeta / 2 - self.eta * k ** 2 / (self.n * self.m)) / self.nu_c


class Gas(LinearModes):
    """Dimensional HCS of smooth inelastic hard spheres and its Navier-Stokes coefficients."""

    def __init__(self, alpha, n, sigma, m, T):
        self.alpha, self.n, self.sigma, self.m, self.T = alpha, n, sigma, m, T
        a2 = sonine_a2(alpha)
        self.a2 = a2
        gscale = math.sqrt(2 * T / m)  # relative velocity: variance 2T/m per component
        g1 = gscale * unit_maxwell_moment(1) * sonine_factor(1, a2)
        g3 = gscale ** 3 * unit_maxwell_moment(3) * sonine_factor(3, a2)
        # collisions per particle and unit time
        self.nu_c = n * PI * sigma ** 2 * g1
        # energy lost per collision (m/4)(1 - alpha^2)(g.s)^2, rate n^2 sigma^2/2 int (g.s)^3 ...,
        # hemisphere int (ghat.s)^3 ds = pi/2;  (3/2) n zeta T = that rate
        loss = 0.5 * n ** 2 * sigma ** 2 * (m / 4) * (1 - alpha ** 2) * (PI / 2) * g3
        self.zeta = loss / (1.5 * n * T)
        self.lam = 1 / (math.sqrt(2) * PI * n * sigma ** 2)
        # elastic first Sonine references
        self.eta0 = 5 / (16 * sigma ** 2) * math.sqrt(m * T / PI)
        self.kappa0 = 15 / 4 * self.eta0 / m
        self.nu0 = n * T / self.eta0
        # Sonine collision frequencies (Brey et al. 1998), dimensional
        nu_eta = (3 - alpha) * (1 + alpha) * (1 - a2 / 32) / 4 * self.nu0
        nu_kappa = (1 + alpha) / 3 * (1 + 33 * (1 - alpha) / 16 + (19 - 3 * alpha) * a2 / 512) * self.nu0
        z = self.zeta
        self.eta = n * T / (nu_eta - z / 2)
        self.kappa = 5 * n * T / (2 * m) * (1 + 2 * a2) / (nu_kappa - 2 * z)
        self.mu = (2.5 * T ** 2 * a2 / m + z * T * self.kappa / n) / (nu_kappa - 1.5 * z)

    # dimensionless coefficients, for printing
    @property
    def eta_star(self):
        return self.eta / self.eta0

    @property
    def kappa_star(self):
        return self.kappa / self.kappa0

    @property
    def mu_star(self):
        return self.n * self.mu / (self.T * self.kappa0)

    @property
    def zeta_star(self):
        return self.zeta / self.nu0

    # ------------------------------------------------------------------------------------------
    # Linearised Navier-Stokes equations about the HCS, per unit time
    # ------------------------------------------------------------------------------------------
    def longitudinal_matrix(self, k):
        """Real M: d/dt (rho, theta, w) for rho cos kx, theta cos kx, w sin kx (see docstring).

        continuity  d(dn)/dt = -n du/dx                         -> drho/dt = -k v w
        momentum    m n du/dt = -d(n T)/dx + (4/3) eta d2u/dx2,  u = v w, v = sqrt(T/m),
                    dv/dt = -(zeta/2) v                          -> dw/dt = k v (rho + theta)
                                                                   + (zeta/2 - 4 eta k^2/(3 m n)) w
        energy      (3/2) n dT/dt + n T du/dx - d/dx(kappa dT/dx + mu dn/dx) = -(3/2) n zeta T,
                    zeta T ~ n T^(3/2), T = T_h (1 + theta cos kx), dT_h/dt = -zeta T_h
                    -> dtheta/dt = -(zeta + 2 mu k^2/(3 T)) rho - (zeta/2 + 2 kappa k^2/(3 n)) theta
                                   - (2/3) k v w
        """
        n, m, T, z = self.n, self.m, self.T, self.zeta
        v = math.sqrt(T / m)
        return np.array([
            [0.0, 0.0, -k * v],
            [-(z + 2 * self.mu * k ** 2 / (3 * T)), -(z / 2 + 2 * self.kappa * k ** 2 / (3 * n)), -2.0 / 3.0 * k * v],
            [k * v, k * v, z / 2 - 4 * self.eta * k ** 2 / (3 * m * n)],
        ])

    def longitudinal_matrix_complex(self, k):
        """The same equations for amplitudes of exp(ikx) (u_x = v w exp(ikx)); cross-check only."""
        n, m, T, z = self.n, self.m, self.T, self.zeta
        v = math.sqrt(T / m)
        return np.array([
            [0.0, 0.0, -1j * k * v],
            [-(z + 2 * self.mu * k ** 2 / (3 * T)), -(z / 2 + 2 * self.kappa * k ** 2 / (3 * n)), -2j / 3 * k * v],
            [-1j * k * v, -1j * k * v, z / 2 - 4 * self.eta * k ** 2 / (3 * m * n)],
        ], dtype=complex)


# ---------------------------------------------------------------------------------------------
# Optional: the literature inputs re-derived by quadrature of the collision integrals
# ---------------------------------------------------------------------------------------------
def pair_integrals(alpha, funcs, nG=8, ng=48, gmax=11.0, nmu=12, nphi=16):
    """For each F: int dc1 dc2 pi^-3 exp(-c1^2 - c2^2) int_{g.s > 0} ds (g.s) F(c1, c2, c1', c2').

    Reduced units c = v/sqrt(2T/m), sigma = n = 1; c1' = c1 - (1+alpha)/2 (g.s) s, c2' = c2 + ...
    c1, c2 = G +- g/2 (Jacobian 1); the integrands used are rotation invariant, so g is put along z
    (4 pi g^2 dg); G ~ normal with variance 1/4 per component.
    """
    from numpy.polynomial.hermite_e import hermegauss
    from numpy.polynomial.legendre import leggauss
    x, wx = hermegauss(nG)
    wx = wx / math.sqrt(2 * PI)
    G = np.stack(np.meshgrid(x / 2, x / 2, x / 2, indexing="ij"), -1).reshape(-1, 3)
    wG = np.einsum("i,j,k->ijk", wx, wx, wx).reshape(-1)
    mu, wmu = leggauss(nmu)
    mu, wmu = 0.5 * (mu + 1), 0.5 * wmu
    phi = 2 * PI * np.arange(nphi) / nphi
    MU, PHI = np.meshgrid(mu, phi, indexing="ij")
    st = np.sqrt(1 - MU ** 2)
    S = np.stack([st * np.cos(PHI), st * np.sin(PHI), MU], -1).reshape(-1, 3)
    wS = np.outer(wmu, np.full(nphi, 2 * PI / nphi)).reshape(-1)
    gr, wg = leggauss(ng)
    gr, wg = 0.5 * gmax * (gr + 1), 0.5 * gmax * wg
    pref = PI ** -3 * (PI / 2) ** 1.5 * 4 * PI
    ones = np.ones((1, len(S), 1))
    total = np.zeros(len(funcs))
    for gi, wgi in zip(gr, wg):
        gv = np.array([0.0, 0.0, gi])
        c1, c2 = (G[:, None, :] + gv / 2) * ones, (G[:, None, :] - gv / 2) * ones
        gs = gi * S[None, :, 2]
        d = ((1 + alpha) / 2 * gs)[..., None] * S[None, :, :]
        p1, p2 = c1 - d, c2 + d
        w = wG[:, None] * wS[None, :] * gs * (wgi * gi * gi * math.exp(-gi * gi / 2)) * pref
        for j, f in enumerate(funcs):
            total[j] += np.sum(w * f(c1, c2, p1, p2))
    return total


def check_collision_integrals(alpha):
    dot = lambda a, b: np.einsum("...i,...i->...", a, b)
    sq = lambda a: dot(a, a)
    s2 = lambda c: 0.5 * sq(c) ** 2 - 2.5 * sq(c) + 15 / 8
    pair_s2 = lambda c1, c2: s2(c1) + s2(c2)  # both grains' Sonine corrections, first order
    tl = lambda c: c[..., :, None] * c[..., None, :] - np.eye(3) * sq(c)[..., None, None] / 3
    d2 = lambda c1, c2, p1, p2: sq(p1) + sq(p2) - sq(c1) - sq(c2)
    d4 = lambda c1, c2, p1, p2: sq(p1) ** 2 + sq(p2) ** 2 - sq(c1) ** 2 - sq(c2) ** 2

    def l_eta(c1, c2, p1, p2):  # psi = traceless c c, X = f_M (traceless c c) at grain 2
        return -np.einsum("...ij,...ij->...", tl(c2), tl(p1) + tl(p2) - tl(c1) - tl(c2))

    def l_kappa(c1, c2, p1, p2):  # psi = c^2 c, X = f_M c (c^2 - 5/2) at grain 2
        dpsi = sq(p1)[..., None] * p1 + sq(p2)[..., None] * p2 - sq(c1)[..., None] * c1 - sq(c2)[..., None] * c2
        return -(sq(c2) - 2.5) * dot(c2, dpsi)

    f = [
        lambda c1, c2, p1, p2: np.ones_like(c1[..., 0]),                      # collisions
        lambda c1, c2, p1, p2: pair_s2(c1, c2),
        lambda c1, c2, p1, p2: 0.5 * d2(c1, c2, p1, p2),                      # int c^2 J[f,f]
        lambda c1, c2, p1, p2: 0.5 * pair_s2(c1, c2) * d2(c1, c2, p1, p2),
        lambda c1, c2, p1, p2: 0.5 * d4(c1, c2, p1, p2),                      # int c^4 J[f,f]
        lambda c1, c2, p1, p2: 0.5 * pair_s2(c1, c2) * d4(c1, c2, p1, p2),
        l_eta, lambda c1, c2, p1, p2: s2(c1) * l_eta(c1, c2, p1, p2),         # f0 = f_M(1 + a2 S2)
        l_kappa, lambda c1, c2, p1, p2: s2(c1) * l_kappa(c1, c2, p1, p2),     # at grain 1
    ]
    r = pair_integrals(alpha, f)
    a = alpha
    nu0 = 1.6 * math.sqrt(2 * PI)  # n T/eta0 at n = sigma = m = 1, T = 1/2
    # steady scaled moments: int c^p J = -(p zeta/2) <c^p>, so int c^4 J/int c^2 J = 5 (1 + a2)
    a2 = (r[4] - 5 * r[2]) / (5 * r[2] + 5 * r[3] - r[5])
    rows = [
        ("a2 (vNE)", a2, sonine_a2(a)),
        ("nu_c/nu_M - 1 per a2", r[1] / r[0], -1 / 16),
        ("zeta*_M", -(2 / 3) * r[2] / nu0, 5 / 12 * (1 - a * a)),
        ("zeta/zeta_M - 1 per a2", r[3] / r[2], 3 / 16),
        ("nu_eta* (a2^0)", r[6] / 2.5 / nu0, (3 - a) * (1 + a) / 4),
        ("nu_eta* (a2^1)", r[7] / 2.5 / nu0, -(3 - a) * (1 + a) / 128),
        ("nu_kappa* (a2^0)", r[8] / 3.75 / nu0, (1 + a) / 3 * (1 + 33 * (1 - a) / 16)),
        ("nu_kappa* (a2^1)", r[9] / 3.75 / nu0, (1 + a) * (19 - 3 * a) / 1536),
    ]
    for name, q, lit in rows:
        print(f"//   alpha = {a}: {name:24s} quadrature {q:+.15e}  formula {lit:+.15e}  diff {q - lit:+.1e}")


def bisect_sign(f, lo, hi, middle=lambda lo, hi: 0.5 * (lo + hi)):
    """The point where f changes from > 0 (at lo) to <= 0 (at hi), bisected until the middle
    (arithmetic, or any other) no longer lies strictly between the bounds."""
    while True:
        mid = middle(lo, hi)
        if mid <= lo or mid >= hi:
            return middle(lo, hi)
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid


def zero_by_bisection(f, x_hi_start=1e-3):
    """Zero of f with f > 0 below it and f < 0 above; returns inf if f stays positive up to
    k lambda = 1e6 and 0 if it is not positive at small x (no finite crossing)."""
    lo = 1e-9
    if not f(lo) > 0:
        return 0.0
    hi = x_hi_start
    while f(hi) > 0:
        lo = hi
        hi *= 2
        if hi > 1e6:
            return math.inf
    return bisect_sign(f, lo, hi)


def critical_length(f, zeta):
    """2 pi/x0 (in units of lambda) for the zero x0 of f; inf without cooling (alpha = 1) or if
    f is not positive at small k, 0 if f stays positive at every k (unstable in any box)."""
    if zeta == 0.0:
        return math.inf
    x = zero_by_bisection(f)
    if x == 0.0:
        return math.inf  # no growing long wave
    return 2 * PI / x  # x = inf (f > 0 up to k lambda = 1e6) gives 0


def add_gas_unit_arguments(ap):
    """--n, --sigma, --m, --T: the dimensional units the reference scripts work in (arbitrary: the
    reduced results do not depend on them)."""
    ap.add_argument("--n", type=float, default=0.37)
    ap.add_argument("--sigma", type=float, default=1.3)
    ap.add_argument("--m", type=float, default=2.1)
    ap.add_argument("--T", type=float, default=0.8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_gas_unit_arguments(ap)
    ap.add_argument("--check-collision-integrals", action="store_true",
                    help="also re-derive a2, zeta, nu_c, nu_eta*, nu_kappa* by quadrature (slow)")
    args = ap.parse_args()
    gas = lambda alpha: Gas(alpha, args.n, args.sigma, args.m, args.T)

    print(f"// smooth spheres, dimensional units n = {args.n}, sigma = {args.sigma}, m = {args.m}, T = {args.T}")
    print("// longitudinal_modes_test.cpp, AgreesWithAnIndependentEvaluation: {alpha, kappa_star, mu_star, critical_length}")
    for a in LONGITUDINAL_ALPHAS:
        g = gas(a)
        L = critical_length(g.longitudinal_max_rate, g.zeta)
        print(f"        {{{a}, {g.kappa_star:.15g}, {g.mu_star:.15g}, {L:.15g}}},")

    print("// {alpha, k_lambda, heat, re0, im0, re1, im1}")
    worst = 0.0
    for a, x in LONGITUDINAL_ROWS:
        g = gas(a)
        h, s0, s1 = g.longitudinal_rates(x)
        ev_c = np.linalg.eigvals(g.longitudinal_matrix_complex(x / g.lam) / g.nu_c)
        for e in (h, s0, s1):
            worst = max(worst, min(abs(ev_c - e)))
        vals = [h.real, s0.real, s0.imag, s1.real, s1.imag]
        txt = ", ".join("0.0" if v == 0.0 else f"{v:.15e}" for v in vals)
        print(f"        {{{a}, {x}, {txt}}},")
    print(f"// complex exp(ikx) form: largest distance to the real form's eigenvalues {worst:.1e}")

    print("// shear_mode_test.cpp, CoefficientsOfTheFirstSonineTheory: {alpha, a2, eta_star, growth, critical_length}")
    for a in SHEAR_ALPHAS:
        g = gas(a)
        L = critical_length(g.shear_rate, g.zeta)
        print(f"        {{{a:.2f}, {g.a2:+.15g}, {g.eta_star:.15g}, {g.shear_rate(0.0):.15g}, {L:.15g}}},")

    print("// context: zeta* and L_c/lambda, L_par/lambda at alpha = 0.9 (ShearModeGoesUnstableFirst)")
    g = gas(0.9)
    print(f"//   zeta* = {g.zeta_star:.15g}, L_c = {critical_length(g.shear_rate, g.zeta):.15g},"
          f" L_par = {critical_length(g.longitudinal_max_rate, g.zeta):.15g}")

    if args.check_collision_integrals:
        print("// literature inputs against quadrature of the collision integrals")
        for a in (0.9, 0.5):
            check_collision_integrals(a)


if __name__ == "__main__":
    main()
