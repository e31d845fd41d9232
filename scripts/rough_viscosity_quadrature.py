#!/usr/bin/env python3
"""Monte Carlo quadratures of the collision rule of elastic perfectly rough spheres (alpha = beta = 1,
q = 2/5) behind observables/rough_enskog_viscosity.hpp and docs/validation.md ("Perfectly rough
grains in shear").

usage: scripts/python3 scripts/rough_viscosity_quadrature.py [--seed S] [--chunks K]   (~1 min)

1. The dilute gas: a Galerkin solution of the linearized Boltzmann equation for the shear stress with
   the trial functions C_xC_y, C_xC_y(C^2 - 7), C_xC_y(J w^2 - 3), J w_x w_y, C_x (C x w)_y + C_y (C x w)_x
   (m = T = sigma = 1): eta over Pidduck's first approximation as they are added. The matrix is
   M_ab = < |g.n| Theta(-g.n) Dphi_a Dphi_b > over Maxwellian pairs, Dphi the change of phi_i + phi_j.
2. The Enskog gas: the moments linear in the Grad coefficients of C_xC_y and J w_x w_y and in the
   shear shift a sigma (finite differences at +-a with common samples; the mean spin at -a/2):
   rows: production of V_xV_y, of J w_x w_y, and the collisional transfer sigma n_y J_x; columns: per
   unit Grad coefficient of each, per unit a. Then eta* with one and with both moments at phi = 0,
   0.1, 0.25 (Carnahan & Starling chi).
"""
import argparse
import math

import numpy as np

Q = 0.4
I = Q / 4
KAPPA = Q / (1 + Q)


def sample(rng, N):
    Vi, Vj = rng.normal(size=(N, 3)), rng.normal(size=(N, 3))
    si, sj = rng.normal(size=(N, 3)) / math.sqrt(I), rng.normal(size=(N, 3)) / math.sqrt(I)
    n = rng.normal(size=(N, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    return Vi, Vj, si, sj, n


def collide(Vi, Vj, si, sj, n, a):
    """Spins si, sj about the mean spin -a/2 z; the partner shifted by a n_y x. Returns the weight
    max(0, -g_c.n), the impulse J on i and the spin change (the same for both)."""
    Om = np.array([0.0, 0.0, -a / 2])
    g = Vi - Vj
    g[:, 0] += a * n[:, 1]
    gc = g - 0.5 * np.cross(si + sj + 2 * Om, n)
    w = np.sum(gc * n, 1)
    J = -(w[:, None] * n + KAPPA * (gc - w[:, None] * n))
    return np.maximum(0, -w), J, -np.cross(n, J) / (2 * I)


def basis(V, s):
    b = V[:, 0] * V[:, 1]
    V2, W2 = np.sum(V * V, 1), I * np.sum(s * s, 1)
    X = np.cross(V, s)
    return np.stack([b, b * (V2 - 7), b * (W2 - 3), I * s[:, 0] * s[:, 1], V[:, 0] * X[:, 1] + V[:, 1] * X[:, 0]], 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=1, help="seed of numpy's generator (default: 1)")
    ap.add_argument("--chunks", type=int, default=10,
                    help="chunks of samples; the errors are their scatter (default: 10)")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    N = 1_000_000
    M = np.zeros((5, 5))
    acc = np.zeros((3, 3))
    a = 0.1
    for _ in range(args.chunks):
        Vi, Vj, si, sj, n = sample(rng, N)
        wt, J, dw = collide(Vi, Vj, si, sj, n, 0.0)
        d = basis(Vi + J, si + dw) + basis(Vj - J, sj + dw) - basis(Vi, si) - basis(Vj, sj)
        M += (d * wt[:, None]).T @ d / N
        F = [d[:, 0] * 0 + Vi[:, 0] * Vi[:, 1] + Vj[:, 0] * Vj[:, 1], I * (si[:, 0] * si[:, 1] + sj[:, 0] * sj[:, 1])]
        rows = [0.5 * d[:, 0], 0.5 * d[:, 3], 0.5 * n[:, 1] * J[:, 0]]
        for r, x in enumerate(rows):
            for c in range(2):
                acc[r, c] += np.mean(wt * x * F[c])
        for sign in (1, -1):
            wt2, J2, dw2 = collide(Vi, Vj, si, sj, n, sign * a)
            d2 = basis(Vi + J2, si + dw2) + basis(Vj - J2, sj + dw2) - basis(Vi, si) - basis(Vj, sj)
            x2 = [0.5 * d2[:, 0], 0.5 * d2[:, 3], 0.5 * n[:, 1] * J2[:, 0]]
            for r in range(3):
                acc[r, 2] += sign * np.mean(wt2 * x2[r]) / (2 * a)
    acc *= 4 * math.pi / args.chunks
    eta_p = 6 * (1 + Q) ** 2 / (6 + 13 * Q)
    print("1. dilute gas: eta over Pidduck's first approximation (%.4f) with the first k trial functions" % eta_p)
    for k in range(1, 6):
        print("   k = %d: %.5f" % (k, M[0, 0] * np.linalg.inv(M[:k, :k])[0, 0]))
    np.set_printoptions(precision=5, suppress=True)
    print("2. Enskog moments (n = chi = 1): rows VxVy production, J wx wy production, transfer; columns x1, x2, a")
    print(acc)
    L, S, T, B = acc[:2, :2], acc[:2, 2], acc[2, :2], acc[2, 2]
    eta0 = 5 / (16 * math.sqrt(math.pi))
    for phi in (0.0, 0.1, 0.25):
        dense = phi > 0
        n = 6 * phi / math.pi if dense else 1.0
        chi = (1 - phi / 2) / (1 - phi) ** 3
        out = []
        for m in (1, 2):
            # steady: chi n (L x + S a) = (a, 0) at a = 1; the shift only in the Enskog gas
            rhs = np.array([1 / (chi * n), 0.0]) - (S if dense else 0)
            x = np.append(np.linalg.solve(L[:m, :m], rhs[:m]), [0.0] * (2 - m))
            Pk = n * x[0]
            Pc = chi * n * n * (T @ x + B) if dense else 0.0
            out.append(-(Pk + Pc) / eta0)
        print("   phi = %.2f: eta* with C_xC_y %.4f, with J w_x w_y too %.4f" % (phi, out[0], out[1]))


if __name__ == "__main__":
    main()
