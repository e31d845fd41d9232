#!/usr/bin/env python3
"""The shear viscosity of an elastic hard-sphere gas from a decaying transverse wave.

usage: scripts/python3 scripts/shear_viscosity.py RUN_DIR [--from C] [--to C] [--check-theory TOL] [--plot PNG]
       scripts/python3 scripts/shear_viscosity.py --self-check

RUN_DIR is a box run with a transverse wave along one axis ([initial] mode = "transverse", wave
[n, 0, 0], [0, n, 0] or [0, 0, n]) and [spectra] (modes.csv), of one species of elastic smooth hard
spheres (alpha = 1, beta = -1): cases/box_viscosity_wave.toml. The wave u = A e sin(k x) decays as
exp(-eta k^2 t/(n m)).

The amplitude is modes.csv's complex amplitude of the wave's mode and transverse component,
projected on its phase at t = 0 (the wave stands: its phase does not move; the projection keeps
the noise of one component, unbiased, where |u_k| would add the other's). The temperature is the
thermal one: moments.csv's T_tr is taken about the box's mean velocity and holds the wave's flow
energy, (m/2) <u^2> = m A^2/4 per grain, m A^2/6 of T_tr (A: moments.csv's u_wave); that share
decays with the wave, warming the gas. eta of hard spheres goes as sqrt(T), so the logarithm of the
amplitude is fitted against tau = the integral of sqrt(T(t)/T_w) dt, T_w the thermal temperature's
mean over the window: the slope is eta(T_w) k^2/(n m) however the gas warms.

The window, in collisions per particle: from C = 10 (--from; the shear stress builds up from the
Maxwellian start within a few collision times, ~10 leave e^-8 of the transient) to the last row
before the amplitude first falls below 10 times the sampling noise of one replica's amplitude,
sqrt(2 T/(m N)) (N grains per replica; there the logarithm's noise bias, (noise/amplitude)^2/2,
stays below 0.005), or the run's end; --to C sets the end. The fit is weighted: generalised least
squares with the covariance of the sampling noise, which is that of the mode's thermal
fluctuations: variance 2 T/(m N R) for the mean of R replicas, correlated in time as exp(-gamma
|dtau|) with the wave's own rate gamma (they decay as the wave does, Onsager's regression),
divided by the fitted amplitudes (the logarithm's noise bias, -(noise/amplitude)^2/2, is added
back). The error of eta is the scatter of the replicas' own slopes
(replicas/moments_R.csv's u_wave, fitted over the same window the same way) over sqrt(R) when
R >= 4, else the fit's; both are printed.

Theory: eta_0 = (5/(16 sigma^2)) sqrt(m T_w/pi), the Chapman-Enskog viscosity eta_CE = 1.016034
eta_0 (Chapman & Cowling 1970), times the DSMC's leading-order discretisation laws
1 + 16/(45 pi) (dx/lambda)^2 (the cell edge dx along the wave vector; Alexander, Garcia & Alder
1998) + 16/(75 pi) (c0 dt/lambda)^2 = (4/75) s^2 (steps of s = domain.time_step mean free times,
c0 = sqrt(2 T/m); Hadjiconstantinou 2000), lambda = 1/(sqrt(2) pi n sigma^2) (docs/validation.md
measures both laws). The table also gives eta/eta_CE with the window shifted by a quarter of its
length earlier and later: the fit-window sensitivity.

--from C, --to C: the window's ends in collisions per particle.
--check-theory TOL: exit 1 unless |eta/eta_CE,laws - 1| <= TOL + 4 standard errors.
--plot PNG: draw ln(amplitude) against collisions per particle with the fit and the window.
--self-check: check the fit on synthetic waves of known decay rate with the sampling noise's
statistics (no run directory); exit 1 on a failure.
Exit 2 for a run directory the method does not apply to (missing files, no transverse wave, not
one species of elastic smooth hard spheres, no rows in the window).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header  # noqa: E402
from transport_common import (ETA_CE_OVER_ETA0, VISCOSITY_LAWS, Refused, SelfCheck, check_theory,  # noqa: E402
                              elastic_smooth_species, eta_0, mean_free_path, run_cli)

CELL_LAW, STEP_LAW = VISCOSITY_LAWS
DEFAULT_FROM = 10.0  # collisions per particle
NOISE_FACTOR = 10.0  # the window ends before the amplitude falls below this many sampling noises
COMPONENTS = "xyz"


def transverse_direction(wave):
    """The axis (0, 1, 2) of a transverse wave's velocity, by roughgas's rule: y if k_y = 0, else z if
    k_z = 0, else along k x x (not a single axis: None)."""
    if wave[1] == 0:
        return 1
    if wave[2] == 0:
        return 2
    return None


def tau_of(t, temperature, t_ref):
    """tau(t) = integral of sqrt(T/T_ref) dt from the first row (trapezoids)."""
    w = np.sqrt(np.asarray(temperature) / t_ref)
    return np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])


def gls_decay(tau, amplitude, sigma, iterations=3):
    """Fits ln(amplitude) = a - gamma tau by generalised least squares, the amplitude's noise having
    the standard deviation `sigma` (per row) and the correlation exp(-gamma |tau_i - tau_j|). The
    logarithm's noise bias, -(sigma/u)^2/2 at the fitted amplitude u, is added back.
    Returns (gamma, its standard error, a)."""
    tau, amplitude = np.asarray(tau, float), np.asarray(amplitude, float)
    sigma = np.broadcast_to(np.asarray(sigma, float), tau.shape)
    if len(tau) < 3 or np.any(amplitude <= 0):
        raise Refused("fewer than 3 rows with a positive amplitude in the window")
    y = np.log(amplitude)
    x = np.column_stack([np.ones_like(tau), -tau])
    coef = np.linalg.lstsq(x, y, rcond=None)[0]
    cov = None
    for _ in range(iterations):
        gamma = max(coef[1], 1e-12)
        fitted = np.exp(coef[0] - gamma * tau)
        s = sigma / fitted
        c = np.outer(s, s) * np.exp(-gamma * np.abs(tau[:, None] - tau[None, :]))
        ci_x = np.linalg.solve(c, x)
        cov = np.linalg.inv(x.T @ ci_x)
        coef = cov @ (ci_x.T @ (y + 0.5 * s ** 2))
    return coef[1], math.sqrt(cov[1, 1]), coef[0]


def read_run(run_dir):
    """What the fit needs from RUN_DIR: the case's parameters, the wave's projected amplitude per row,
    the thermal temperature per row, and each replica's u_wave."""
    moments_path = os.path.join(run_dir, "moments.csv")
    modes_path = os.path.join(run_dir, "modes.csv")
    for p in (moments_path, modes_path):
        if not os.path.isfile(p):
            raise Refused(f"{p} does not exist (a box run with [spectra] and spectra.modes > 0 writes modes.csv)")
    case = read_header(moments_path)["resolved"]
    if not case:
        raise Refused(f"{moments_path} has no resolved case in its header")
    run, domain, initial = case.get("run", {}), case.get("domain"), case.get("initial", {})
    if domain is None or initial.get("mode") != "transverse":
        raise Refused("the run has no transverse wave ([initial] mode = \"transverse\" in a [domain] run)")
    species = elastic_smooth_species(case)
    wave = [int(w) for w in initial.get("wave", [1, 0, 0])]
    axes = [a for a in range(3) if wave[a] != 0]
    if len(axes) != 1:
        raise Refused(f"the wave {wave} is not along one axis (modes.csv holds the modes along the axes)")
    axis = axes[0]
    component = transverse_direction(wave)
    if any(b != "periodic" for b in domain.get("boundary", ["periodic"] * 3)):
        raise Refused("the box must be periodic")
    p = {
        "n": float(run["density"]), "N": int(run["particles"]), "R": int(run.get("replicas", 1)),
        "m": float(species["mass"]), "sigma": 2.0 * float(species["radius"]),
        "L": float(domain["size"][axis]), "cells": int(domain["cells"][axis]), "s": float(domain.get("time_step", 0.2)),
        "axis": axis, "component": component, "wave": abs(wave[axis]), "amplitude": float(initial.get("amplitude", 0.1)),
    }
    p["k"] = 2 * math.pi * p["wave"] / p["L"]
    p["dx"] = p["L"] / p["cells"]
    p["lambda"] = mean_free_path(p["n"], p["sigma"])

    modes = read_csv(modes_path)
    rows = (modes["axis"] == axis + 1) & (modes["n"] == p["wave"])
    if not np.any(rows):
        raise Refused(f"modes.csv has no mode n = {p['wave']} along {COMPONENTS[axis]} (spectra.modes >= {p['wave']})")
    name = "u_" + COMPONENTS[component]
    re, im = modes[name + "_re"][rows], modes[name + "_im"][rows]
    phase = math.atan2(im[0], re[0])
    amp = re * math.cos(phase) + im * math.sin(phase)
    moments = read_csv(moments_path)
    t, cpp = modes["t"][rows], modes["coll_per_particle"][rows]
    if len(moments["t"]) != len(t) or np.any(np.abs(moments["t"] - t) > 1e-9 * (1 + np.abs(t))):
        raise Refused("moments.csv and modes.csv do not have the same rows")
    flow = p["m"] * moments["u_wave"] ** 2 / 6.0  # the wave's share of T_tr
    thermal = moments["T_tr"] - flow
    replicas = []
    for r in range(p["R"] if p["R"] > 1 else 0):
        path = os.path.join(run_dir, "replicas", f"moments_{r}.csv")
        if not os.path.isfile(path):
            replicas = []
            break
        d = read_csv(path)
        if len(d["t"]) != len(t):
            replicas = []
            break
        sign = 1.0 if d["u_wave"][0] >= 0 else -1.0
        replicas.append((sign * d["u_wave"], d["T_tr"] - p["m"] * d["u_wave"] ** 2 / 6.0))
    return p, {"t": t, "cpp": cpp, "amp": amp, "T": thermal, "T_tr": moments["T_tr"], "flow": flow}, replicas


def choose_window(p, rows, start, end):
    """(first index, last index, the reason for the end) of the rows in the window."""
    cpp, amp = rows["cpp"], rows["amp"]
    noise = np.sqrt(2 * rows["T"] / (p["m"] * p["N"]))
    inside = cpp >= start - 1e-9
    if end is not None:
        inside &= cpp <= end + 1e-9
        reason = "--to"
    else:
        below = np.nonzero(inside & (amp < NOISE_FACTOR * noise))[0]
        if len(below):
            inside &= np.arange(len(cpp)) < below[0]
            reason = (f"the amplitude falls below {NOISE_FACTOR:g} times one replica's sampling noise "
                      f"sqrt(2T/(mN)) at {cpp[below[0]]:.4g}")
        else:
            reason = f"the run's end (the amplitude stays above {NOISE_FACTOR:g} times one replica's sampling noise)"
    idx = np.nonzero(inside)[0]
    if len(idx) < 3:
        raise Refused(f"fewer than 3 rows in the window from {start:g} to "
                      f"{'the noise limit' if end is None else end} collisions per particle (the run has rows at "
                      f"{', '.join(f'{c:g}' for c in cpp[:8])}{' ...' if len(cpp) > 8 else ''})")
    return idx[0], idx[-1], reason


def measure(p, rows, replicas, first, last):
    """The viscosity over rows first..last: a dict of the fit's results."""
    sl = slice(first, last + 1)
    t_w = float(np.mean(rows["T"][sl]))
    tau = tau_of(rows["t"], rows["T"], t_w)[sl]
    noise = np.sqrt(2 * rows["T"][sl] / (p["m"] * p["N"] * p["R"]))
    gamma, gamma_fit_err, _ = gls_decay(tau, rows["amp"][sl], noise)
    slopes = []
    for u, temp in replicas:
        tau_r = tau_of(rows["t"], temp, t_w)[sl]
        slopes.append(gls_decay(tau_r, u[sl], np.sqrt(2 * temp[sl] / (p["m"] * p["N"])))[0])
    scatter_err = float(np.std(slopes, ddof=1) / math.sqrt(len(slopes))) if len(slopes) >= 2 else float("nan")
    gamma_err = scatter_err if len(slopes) >= 4 else gamma_fit_err
    to_eta = p["n"] * p["m"] / p["k"] ** 2
    eta0 = eta_0(p["m"], t_w, p["sigma"])
    laws = 1 + CELL_LAW * (p["dx"] / p["lambda"]) ** 2 + STEP_LAW * p["s"] ** 2
    eta = gamma * to_eta
    return {"gamma": gamma, "gamma_fit_err": gamma_fit_err, "gamma_scatter_err": scatter_err,
            "replica_slopes": slopes, "eta": eta, "eta_err": gamma_err * to_eta, "eta0": eta0, "T": t_w,
            "laws": laws, "ratio": eta / (ETA_CE_OVER_ETA0 * eta0 * laws),
            "ratio_err": gamma_err * to_eta / (ETA_CE_OVER_ETA0 * eta0 * laws),
            "error_from": "the replicas' scatter" if len(slopes) >= 4 else "the fit"}


def shifted(p, rows, replicas, first, last):
    """eta/eta_CE,laws with the window shifted a quarter of its length earlier and later (clipped to
    the rows; None where fewer than 3 rows remain)."""
    cpp = rows["cpp"]
    quarter = (cpp[last] - cpp[first]) / 4
    out = []
    for shift in (-quarter, quarter):
        lo, hi = max(cpp[first] + shift, cpp[0]), min(cpp[last] + shift, cpp[-1])
        idx = np.nonzero((cpp >= lo - 1e-9) & (cpp <= hi + 1e-9))[0]
        try:
            r = measure(p, rows, replicas, idx[0], idx[-1]) if len(idx) >= 3 else None
        except Refused:
            r = None
        out.append((shift, lo, hi, r))
    return out


def draw(path, p, rows, first, last, result):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from atomic_output import save_figure
    cpp, amp = rows["cpp"], rows["amp"]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ok = amp > 0
    ax.plot(cpp[ok], np.log(amp[ok]), "o", ms=3, color="C0", label="ln u_k (modes.csv, projected on its phase)")
    noise = np.sqrt(2 * rows["T"] / (p["m"] * p["N"]))
    ax.plot(cpp, np.log(NOISE_FACTOR * noise), ":", color="0.5", label=f"ln({NOISE_FACTOR:g} sqrt(2T/(mN)))")
    sl = slice(first, last + 1)
    tau = tau_of(rows["t"], rows["T"], result["T"])
    a = np.mean(np.log(amp[sl]) + result["gamma"] * tau[sl])
    ax.plot(cpp[sl], a - result["gamma"] * tau[sl], "-", color="C3",
            label=f"fit: \u03b7/\u03b7_CE,laws = {result['ratio']:.4f} \u00b1 {result['ratio_err']:.4f}")
    ax.axvspan(cpp[first], cpp[last], color="C3", alpha=0.08)
    ax.set_xlabel("collisions per particle")
    ax.set_ylabel("ln(amplitude)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)


def report(run_dir, args):
    p, rows, replicas = read_run(run_dir)
    first, last, reason = choose_window(p, rows, args.start, args.end)
    r = measure(p, rows, replicas, first, last)
    sens = shifted(p, rows, replicas, first, last)
    cpp = rows["cpp"]
    print(f"shear_viscosity: {run_dir}: transverse wave u_{COMPONENTS[p['component']]} along "
          f"{COMPONENTS[p['axis']]}, n = {p['wave']}, k lambda = {p['k'] * p['lambda']:.4g}; "
          f"{p['R']} replica{'s' if p['R'] != 1 else ''} of {p['N']} grains")
    print(f"window: {cpp[first]:.4g} to {cpp[last]:.4g} collisions per particle ({last - first + 1} rows): from "
          + ("--from" if args.start != DEFAULT_FROM else f"{DEFAULT_FROM:g}, once the shear stress has built up")
          + f"; to {reason}")
    print(f"temperature: thermal T = {r['T']:.6g} (window mean of moments.csv's T_tr less the wave's flow energy "
          f"m u_wave^2/6: {rows['flow'][first]:.3g} to {rows['flow'][last]:.3g}); eta scaled to it by sqrt(T)")
    slopes = r["replica_slopes"]
    if slopes:
        print(f"replicas' own slopes (u_wave): mean {np.mean(slopes):.6g}, scatter/sqrt(R) "
              f"{r['gamma_scatter_err']:.3g}; the fit's error {r['gamma_fit_err']:.3g} (1/time)")
    print(f"laws: 1 + 16/(45 pi) (dx/lambda)^2 + (4/75) s^2 = 1 + 16/(45 pi) ({p['dx'] / p['lambda']:.4g})^2 + "
          f"(4/75) {p['s']:g}^2 = {r['laws']:.5f} (cells: Alexander, Garcia & Alder 1998; steps: "
          f"Hadjiconstantinou 2000); eta_CE = 1.016034 eta_0 (Chapman & Cowling 1970)")
    print()
    print("| quantity | value | error |")
    print("|---|---|---|")
    print(f"| decay rate (1/time, at T) | {r['gamma']:.6g} | {r['eta_err'] / (p['n'] * p['m'] / p['k'] ** 2):.3g} |")
    print(f"| eta (case units) | {r['eta']:.6g} | {r['eta_err']:.3g} |")
    print(f"| eta_0 = (5/(16 sigma^2)) sqrt(m T/pi) | {r['eta0']:.6g} | - |")
    print(f"| eta/eta_0 | {r['eta'] / r['eta0']:.5f} | {r['eta_err'] / r['eta0']:.5f} |")
    print(f"| eta/eta_CE | {r['eta'] / (ETA_CE_OVER_ETA0 * r['eta0']):.5f} | "
          f"{r['eta_err'] / (ETA_CE_OVER_ETA0 * r['eta0']):.5f} |")
    print(f"| eta/eta_CE,laws | {r['ratio']:.5f} | {r['ratio_err']:.5f} |")
    for shift, lo, hi, s in sens:
        what = (f"eta/eta_CE,laws, window {'earlier' if shift < 0 else 'later'} by {abs(shift):.3g} ({lo:.3g} to "
                f"{hi:.3g}{', into the stress build-up' if lo < DEFAULT_FROM - 1e-9 else ''})")
        if s is None:
            print(f"| {what} | - | - |")
        else:
            print(f"| {what} | {s['ratio']:.5f} | {s['ratio_err']:.5f} |")
    moved = [abs(s["ratio"] - r["ratio"]) for _, _, _, s in sens if s is not None]
    print()
    print(f"error from {r['error_from']}; the window sensitivity (largest move of eta/eta_CE,laws under a shift "
          f"of a quarter of the window): " + (f"{max(moved):.4f}" if moved else "-"))
    if args.plot:
        draw(args.plot, p, rows, first, last, r)
        print(f"shear_viscosity: wrote {args.plot}")
    if args.check_theory is not None:
        return check_theory("eta/eta_CE,laws", r["ratio"], r["ratio_err"], args.check_theory)
    return 0 if math.isfinite(r["eta"]) else 1


def self_check():
    """The fit on synthetic waves: exact exponentials, the noise's statistics, a warming gas."""
    rng = np.random.default_rng(7)
    check = SelfCheck()
    expect = check.expect

    t = np.arange(0.0, 200.0, 2.0)
    gamma = 0.0123
    g, _, a = gls_decay(t, 0.5 * np.exp(-gamma * t), 1e-7)
    expect(abs(g / gamma - 1) < 1e-10 and abs(a - math.log(0.5)) < 1e-10, f"an exact exponential: rate {g:.10g}")

    # Noise as the mode's thermal fluctuations: Ornstein-Uhlenbeck of variance sigma^2, rate gamma.
    sigma, trials, rates, errs = 0.01, 400, [], []
    decay = np.exp(-gamma * np.diff(t))
    for _ in range(trials):
        xi = np.empty_like(t)
        xi[0] = sigma * rng.standard_normal()
        for i in range(1, len(t)):
            xi[i] = xi[i - 1] * decay[i - 1] + sigma * math.sqrt(1 - decay[i - 1] ** 2) * rng.standard_normal()
        u = 0.5 * np.exp(-gamma * t) + xi
        keep = (t >= 10) & (t <= 150)
        g, e, _ = gls_decay(t[keep], u[keep], sigma)
        rates.append(g)
        errs.append(e)
    rates, errs = np.array(rates), np.array(errs)
    mean_err = rates.std(ddof=1) / math.sqrt(trials)
    expect(abs(rates.mean() - gamma) < 4 * mean_err,
           f"noisy waves: mean rate {rates.mean():.6g} against {gamma} (4 standard errors {4 * mean_err:.2g})")
    # The scatter of a standard deviation from 400 samples is 3.5 %: 15 % is more than 4 of it.
    ratio = rates.std(ddof=1) / np.mean(errs)
    expect(abs(ratio - 1) < 0.15, f"the fit's stated error against the rates' scatter: {ratio:.3f}")

    # A warming gas: the rate goes as sqrt(T); fitted against tau it is the rate at T_w.
    temp = 1.0 + 0.03 * (1 - np.exp(-2 * gamma * t))
    t_w = float(np.mean(temp))
    tau = tau_of(t, temp, t_w)
    rate = gamma * np.sqrt(temp / t_w)
    u = 0.5 * np.exp(-np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(t))]))
    g, _, _ = gls_decay(tau, u, 1e-7)
    expect(abs(g / gamma - 1) < 1e-9, f"a warming gas: rate at T_w {g:.10g} against {gamma}")

    # The step law: 16/(75 pi) (c0 dt/lambda)^2 with c0 = sqrt(2T/m), dt = s lambda/cbar.
    s = 0.3
    c0_dt_over_lambda = s * math.sqrt(2.0) / math.sqrt(8.0 / math.pi)
    expect(abs(16 / (75 * math.pi) * c0_dt_over_lambda ** 2 - STEP_LAW * s ** 2) < 1e-15, "the step law (4/75) s^2")
    expect(transverse_direction([1, 0, 0]) == 1 and transverse_direction([0, 1, 0]) == 2
           and transverse_direction([0, 0, 1]) == 1, "the transverse direction of waves along x, y, z")
    return check.status()


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir", nargs="?", help="a box run with a transverse wave and modes.csv")
    parser.add_argument("--from", dest="start", type=float, default=DEFAULT_FROM,
                        help="the window's start, collisions per particle (default 10)")
    parser.add_argument("--to", dest="end", type=float, default=None,
                        help="the window's end, collisions per particle (default: before the amplitude falls below "
                             "10 sampling noises, or the run's end)")
    parser.add_argument("--check-theory", type=float, default=None, metavar="TOL",
                        help="exit 1 unless |eta/eta_CE,laws - 1| <= TOL + 4 standard errors")
    parser.add_argument("--plot", default=None, metavar="PNG", help="draw the fit")
    parser.add_argument("--self-check", action="store_true", help="check the fit on synthetic waves")
    return run_cli("shear_viscosity", parser, argv, report, self_check)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
