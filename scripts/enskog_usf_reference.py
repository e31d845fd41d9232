#!/usr/bin/env python3
"""Independent evaluation of the steady uniform shear flow of the Enskog equation for inelastic
smooth hard spheres in Grad's approximation (the theory of observables/enskog_usf_theory.hpp).

Where the C++ function reduces the collision integrals to one-dimensional Gaussian integrals in
closed form (erfc) and integrates over the contact direction n by quadrature, this script samples
the collisions themselves: pairs of Maxwellian velocities V_i, V_j and directions n uniform on the
sphere (randomly scrambled Sobol points), the relative velocity g = V_i - V_j + a sigma n_y x, the
impulse of the collision rule applied literally (V_i' = V_i + Delta, Delta = -(1 + alpha)/2 (g.n) n)
and the moments taken as they are defined:

  Lambda_ij = chi sigma^2 n^2 int dn < Theta(-g.n) |g.n| m (V_i' V_i' - V_i V_i)_ij  Grad >
            (evaluated as the mean of the changes of i and of j, an exact identity),
  P^c_ij    = (1/2) chi sigma^3 n^2 int dn < Theta(-g.n) |g.n| sigma n_i m Delta_j  Grad >,

with Grad = 1 + (m/2T) c:(V_i V_i + V_j V_j) (the pair's product f(V_i) f(V_j) linearized in c, as in
the C++ function; --full-product keeps the c c term as well, to show what the linearization costs).
Units m = T = sigma = 1, n = 6 phi/pi, nu = (16/5) n sqrt(pi), a* = a/nu. The steady state solves
Lambda_yy = Lambda_zz = 0, Lambda_xy = a P^k_yy, Lambda_xx = 2 a P^k_xy. The spread over independent
scramblings gives the Monte Carlo error (printed as +- one standard error of the mean).

Usage: scripts/enskog_usf_reference.py [--samples-log2 K] [--scramblings R] [--full-product]
"""
import argparse
import math
import sys

import numpy as np
from scipy import optimize, special, stats

# (alpha, phi, chi): chi = None means Carnahan-Starling's (1 - phi/2)/(1 - phi)^3.
STATES = [(0.9, 0.0, 1.0), (0.7, 0.0, 1.0), (0.5, 0.0, 1.0),
          (0.9, 0.1, None), (0.9, 0.25, None), (0.7, 0.1, None), (0.7, 0.25, None), (0.5, 0.25, None)]

# Traceless USF tensors: E_xx = diag(1, 0, -1), E_yy = diag(0, 1, -1), E_xy = xy + yx.
BASIS = [np.diag([1.0, 0.0, -1.0]), np.diag([0.0, 1.0, -1.0]),
         np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])]
COMPONENTS = [(0, 0), (1, 1), (2, 2), (0, 1)]  # xx, yy, zz, xy


def carnahan_starling(phi):
    return (1 - phi / 2) / (1 - phi) ** 3


class Samples:
    """One scrambled Sobol set of (V_i, V_j, n), with the Grad weights' pieces."""

    def __init__(self, log2n, seed):
        u = stats.qmc.Sobol(d=8, scramble=True, seed=seed).random_base2(log2n)
        u = np.clip(u, 1e-15, 1 - 1e-15)
        g = special.ndtri(u[:, :6])  # unit-variance Gaussians: T/m = 1
        self.v1, self.v2 = g[:, :3], g[:, 3:6]
        z = 2 * u[:, 6] - 1
        ph = 2 * math.pi * u[:, 7]
        s = np.sqrt(1 - z * z)
        self.n = np.stack([s * np.cos(ph), s * np.sin(ph), z], axis=1)
        q1 = [np.einsum('ni,ij,nj->n', self.v1, E, self.v1) for E in BASIS]
        q2 = [np.einsum('ni,ij,nj->n', self.v2, E, self.v2) for E in BASIS]
        # d Grad/d c_k = (1/2) E_k:(V_i V_i + V_j V_j); the c_k c_l term of the product is
        # (1/4)(E_k:V_i V_i)(E_l:V_j V_j), symmetrized in k, l.
        self.lin = np.stack([0.5 * (q1[k] + q2[k]) for k in range(3)])
        self.quad = np.stack([0.125 * (q1[k] * q2[l] + q1[l] * q2[k]) for k in range(3) for l in range(3)])

    def moments(self, alpha, phi, chi, a_star):
        """Lambda/(n T nu) and P^c/(n T) as (value at c = 0, linear coefficients, quadratic coefficients)."""
        A = a_star * 96 / 5 * phi / math.sqrt(math.pi)  # a sigma sqrt(m/T) = a* nu sigma
        g = self.v1 - self.v2
        g[:, 0] += A * self.n[:, 1]
        gn = np.einsum('ni,ni->n', g, self.n)
        h = np.where(gn < 0, -gn, 0.0)  # the rate's |g.n| Theta(-g.n)
        delta = (0.5 * (1 + alpha) * h)[:, None] * self.n  # the velocity change of i
        v1, v2 = self.v1, self.v2
        v1p, v2p = v1 + delta, v2 - delta
        # Lambda counts the change of particle i over ordered pairs; relabelling i <-> j (n -> -n, g -> -g,
        # an equally likely sample with the same weight) makes it the mean of both particles' changes,
        # which cancels the centre-of-mass velocity's noise.
        prod = np.stack([0.5 * h * (v1p[:, i] * v1p[:, j] - v1[:, i] * v1[:, j] + v2p[:, i] * v2p[:, j]
                                    - v2[:, i] * v2[:, j]) for i, j in COMPONENTS])
        flux = np.stack([h * self.n[:, i] * delta[:, j] for i, j in COMPONENTS])
        N = h.size
        # 4 pi (solid angle) chi n^2 <...>/(n nu) and (1/2) 4 pi chi n^2 <...>/n, sigma = 1.
        sp = 5 * math.sqrt(math.pi) * chi / 4
        sc = 12 * phi * chi
        weights = np.vstack([np.ones((1, N)), self.lin, self.quad])
        L = sp * (prod @ weights.T) / N
        P = sc * (flux @ weights.T) / N
        return L, P


def solve_linear(L, a_star):
    """c on the basis from the yy, zz, xy balances; the xx balance's residual."""
    M = np.array([L[1, 1:4], L[2, 1:4], L[3, 1:4]])
    M[2, 1] -= a_star
    rhs = -np.array([L[1, 0], L[2, 0], L[3, 0] - a_star])
    c = np.linalg.solve(M, rhs)
    return c, L[0, 0] + L[0, 1:4] @ c - 2 * a_star * c[2]


def full_residuals(L, a_star, c):
    cc = np.array([c[k] * c[l] for k in range(3) for l in range(3)])
    lam = L[:, 0] + L[:, 1:4] @ c + L[:, 4:] @ cc
    return np.array([lam[1], lam[2], lam[3] - a_star * (1 + c[1]), lam[0] - 2 * a_star * c[2]])


def steady(samples, alpha, phi, chi, full_product):
    def residual(a):
        return solve_linear(samples.moments(alpha, phi, chi, a)[0], a)[1]

    lo, hi = 1e-6, 0.25
    while residual(hi) <= 0:
        lo, hi = hi, 2 * hi
    a_star = optimize.brentq(residual, lo, hi, xtol=1e-12, rtol=1e-12)
    L, P = samples.moments(alpha, phi, chi, a_star)
    c, _ = solve_linear(L, a_star)
    if full_product:
        def f(x):
            return full_residuals(samples.moments(alpha, phi, chi, x[3])[0], x[3], x[:3])
        x = optimize.fsolve(f, np.append(c, a_star), xtol=1e-12)
        c, a_star = x[:3], x[3]
        L, P = samples.moments(alpha, phi, chi, a_star)
    cc = np.array([c[k] * c[l] for k in range(3) for l in range(3)])
    pc = P[:, 0] + P[:, 1:4] @ c + (P[:, 4:] @ cc if full_product else 0)
    kin = np.array([1 + c[0], 1 + c[1], 1 - c[0] - c[1], c[2]])
    tot = kin + pc
    return {
        'a*': a_star, 'eta*': -tot[3] / a_star,
        'Pxx': tot[0], 'Pyy': tot[1], 'Pzz': tot[2], 'Pxy': tot[3],
        'N1': tot[0] - tot[1], 'N2': tot[1] - tot[2],
        'Pk_xx': kin[0], 'Pk_yy': kin[1], 'Pk_zz': kin[2], 'Pk_xy': kin[3],
        'Pc_xx': pc[0], 'Pc_yy': pc[1], 'Pc_zz': pc[2], 'Pc_xy': pc[3],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--samples-log2', type=int, default=21)
    ap.add_argument('--scramblings', type=int, default=8)
    ap.add_argument('--full-product', action='store_true')
    args = ap.parse_args()
    print(f'# Enskog USF, Grad, {"full" if args.full_product else "linearized"} product; '
          f'{args.scramblings} scramblings x 2^{args.samples_log2} samples; mean +- standard error')
    states = [(alpha, phi, carnahan_starling(phi) if chi is None else chi) for alpha, phi, chi in STATES]
    runs = [[] for _ in states]
    for seed in range(args.scramblings):  # one sample set in memory at a time
        samples = Samples(args.samples_log2, seed)
        for k, (alpha, phi, chi) in enumerate(states):
            runs[k].append(steady(samples, alpha, phi, chi, args.full_product))
    for (alpha, phi, chi), run in zip(states, runs):
        print(f'alpha = {alpha}, phi = {phi}, chi = {chi:.10g}')
        for key in run[0]:
            v = np.array([r[key] for r in run])
            print(f'  {key:6s} {v.mean(): .5f} +- {v.std(ddof=1) / math.sqrt(len(v)):.1e}')
        if phi == 0:
            zeta = 5 / 12 * (1 - alpha ** 2)
            beta = (1 + alpha) * (3 - alpha) / 4
            print(f'  closed form (Boltzmann Grad): a* = {chi * math.sqrt(1.5 * zeta / (beta - zeta)) * beta:.6f}, '
                  f'eta* = {(beta - zeta) / (chi * beta ** 2):.6f}, P*_yy = P*_zz = {1 - zeta / beta:.6f}')
        sys.stdout.flush()


if __name__ == '__main__':
    main()
