#!/usr/bin/env python3
"""The driven two-temperature theory of equal rough spheres, evaluated independently of roughgas.

Integrates the Maxwellian equations (Huthmann & Zippelius 1997 in 3-D form, docs/model.md) with a
thermostat's sources by scipy's DOP853 and finds roots by brentq, with no closed form of
include/roughgas/observables/driven_steady_state.hpp: theta of the white-noise steady state at
several alpha (the long-time limit of the integration), the steady state in a Langevin bath, the
Mpemba crossing of docs/model.md "Maxwellian theory of the driven gas", and van Noije & Ernst's a2
from the moment equations. Prints the numbers tests/observables/*_test.cpp compare with.
"""
import argparse
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq


def coefficients(alpha, beta, q, m=1.0, sigma=1.0, n=1.0):
    eta = q * (1 + beta) / (2 * (1 + q))
    A = (1 - alpha**2) / 4 + eta * (1 - eta)
    B = eta**2 / q
    C = (eta / q) * (1 - eta / q)
    G = 16 / 3 * n * sigma**2 * math.sqrt(math.pi / m)
    return A, B, C, G


def rhs(alpha, beta, q, white=0.0, eps=0.0, bath=None, m=1.0):
    """dT_tr/dt, dT_rot/dt: collisions plus white noise (m xi^2 split by eps) or a bath (T_b, gamma, gamma_rot)."""
    A, B, C, G = coefficients(alpha, beta, q, m=m)

    def f(_t, y):
        T, R = max(y[0], 0.0), max(y[1], 0.0)
        s = math.sqrt(T)
        dT = G * (-A * T * s + B * s * R) + (1 - eps) * m * white
        dR = G * (B * T * s - C * s * R) + eps * m * white
        if bath is not None:
            Tb, g, gr = bath
            dT += 2 * g * (Tb - T)
            dR += 2 * gr * (Tb - R)
        return [dT, dR]

    return f


def integrate(f, y0, t1):
    return solve_ivp(f, (0, t1), y0, method="DOP853", rtol=1e-13, atol=1e-15, dense_output=True)


def main():
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    q = 0.4
    print("white noise, eps = 0: theta at t -> infinity (integrated) and q(1 + beta)/(1 + 2q - beta)")
    for beta in (-0.6, 0.0, 0.5):
        for alpha in (0.2, 0.6, 0.9):
            sol = integrate(rhs(alpha, beta, q, white=0.7), [1.0, 1.0], 400.0)
            T, R = sol.y[:, -1]
            print(f"  beta = {beta:5.2f} alpha = {alpha:4.2f}: theta = {R / T:.12f}   closed form {q * (1 + beta) / (1 + 2 * q - beta):.12f}")

    print("Langevin bath T_b = 1.5, gamma = 0.4, gamma_rot = 0.1 (alpha = 0.9, beta = 0.4): long-time T_tr, T_rot")
    sol = integrate(rhs(0.9, 0.4, q, bath=(1.5, 0.4, 0.1)), [1.0, 1.0], 400.0)
    print(f"  T_tr = {sol.y[0, -1]:.12f}  T_rot = {sol.y[1, -1]:.12f}")

    alpha, beta = 0.9, -0.3
    A, B, C, G = coefficients(alpha, beta, q)
    theta = q * (1 + beta) / (1 + 2 * q - beta)
    xi2 = G * (A - B * theta)  # steady T_tr = 1
    f = rhs(alpha, beta, q, white=xi2)
    a, b = integrate(f, [2.0, 0.2], 3.0), integrate(f, [1.5, 6.0], 3.0)
    gap = lambda t: a.sol(t)[0] - b.sol(t)[0]
    ts = np.linspace(1e-6, 3.0, 30001)
    d = gap(ts)
    i = int(np.nonzero(np.sign(d[1:]) != np.sign(d[:-1]))[0][0])
    tc = brentq(gap, ts[i], ts[i + 1], xtol=1e-15)
    nu = 4 * math.sqrt(math.pi)  # collisions per unit time at T = 1, n = sigma = m = 1
    late = np.linspace(tc, 3.0, 3001)
    widest = late[np.argmax(np.abs(gap(late)))]
    print(f"Mpemba: alpha = {alpha}, beta = {beta}, q = {q}, xi^2 = {xi2:.8f} (steady T_tr = 1), A (2, 0.2), B (1.5, 6)")
    print(f"  crossing t = {tc:.12f} = {tc * nu:.6f} collision times; B - A at most {-gap(widest):.6f} at {widest * nu:.3f}")

    print("van Noije & Ernst's a2 from mu_4 = (d + 2) mu_2, mu_2 ~ 1 + 3 a2/16, mu_4 ~ (d + 3/2 + alpha^2) + K a2")
    for d in (2, 3):
        for alpha in (0.5, 0.9):
            K = 3 / 32 * (10 * d + 39 + 10 * alpha**2) + (d - 1) / (1 - alpha)
            print(f"  d = {d} alpha = {alpha}: a2 = {(0.5 - alpha**2) / (K - 3 * (d + 2) / 16):.10f}")


if __name__ == "__main__":
    main()
