#!/usr/bin/env python3
"""The thermal conductivity of an elastic hard-sphere gas from Fourier flow between two walls.

usage: scripts/python3 scripts/thermal_conductivity.py RUN_DIR [--from C] [--to C] [--margin L] [--check-theory TOL] [--plot PNG]
       scripts/python3 scripts/thermal_conductivity.py --self-check

RUN_DIR is a box run of one species of elastic smooth hard spheres (alpha = 1, beta = -1: a
monatomic gas, all its energy translational) between two diffuse walls at rest along y at
different temperatures, periodic along x and z, with its profiles along y (profiles.csv) and the
walls' fluxes (walls.csv): cases/box_conductivity_fourier.toml. Rough grains (beta > -1) exchange
translational and rotational energy at every collision and carry heat in their spins too: their
conductivity is not the one below, and such runs are refused. In the steady state the heat flux
q_y is uniform and equal to what the walls exchange.

The flux: the mean of the two walls' energy fluxes y_lower.q_y and y_upper.q_y (walls.csv), which
count every grain that crosses: the profiles' kinetic q_y leaves out the energy that collisions
carry between the grains of a cell, the DSMC's cell-size error. The mean of the two walls cancels
the flux that fills or empties the gas's energy (the channel's symmetric thermal modes).
The gradient, by the integral form of Fourier's law: kappa = kappa_1 sqrt(T) for hard spheres, so
-q_y = kappa_1 sqrt(T) dT/dy = (2/3) kappa_1 dT^(3/2)/dy, and integrated between any two points of
the bulk, (2/3) kappa_1 [T^(3/2)] = -q_y [y]: T^(3/2), not T, is linear across the channel. The
least-squares line through T^(3/2) of the bulk's slabs (the time-averaged T_tr of profiles.csv)
gives kappa_1 = -(3/2) q_y/(dT^(3/2)/dy): every slab counts, no derivative of a noisy profile is
taken, and the conductivity's dependence on T is exact (a line through T itself would put kappa
0.1 % low here). kappa is printed at T_b, the bulk slabs' mean temperature; kappa/kappa_0 is
kappa_1 over kappa_0's own sqrt(T) coefficient, the same at every T.
The bulk: the slabs whose centres are more than L = 3 mean free paths from each wall (--margin;
lambda at run.density). Within a few mean free paths of a diffuse wall the gas is not
Navier-Stokes: the Knudsen layer, which carries the temperature jump, bends the profile there (its
correction to T decays over a few lambda), and the two slabs touching the walls carry the
profiles' sampling error at the walls (docs/box_flows.md). Slabs inside it pull the slope, and
kappa, down: the table gives kappa with the margin 1 lambda narrower and wider.

The window, in collisions per particle: from 5 of the channel's slowest thermal relaxation times
(--from; its fundamental mode, tau_1 = nu L_eff^2/(pi^2 D_T) with D_T = kappa_CE/(n c_p), c_p = 5/2,
nu = 4 n sigma^2 sqrt(pi T/m) and L_eff = L_y + 4 lambda, the temperature jump of about two mean
free paths at each wall: 77 collisions per particle for walls 20 lambda apart; e^-5 of that mode is
left, and it cancels in the walls' mean flux, while the antisymmetric modes, which tilt the profile,
relax four times faster) to the run's end (--to). Where steady.csv's detector, which watches the
box's moments, finds the run steady is printed beside it: the moments settle sooner than the
profile's slowest mode. The error: batch means over time, as a jackknife
over 20 batches of consecutive rows (fewer when the window is shorter than 10 relaxation times:
each batch at least half of one, so that the batches are nearly independent). Batches in time, not
replicas: the replicas' own profiles are not written (replicas/ holds their moments only), and one
replica or many, the batches are independent once they outlast the relaxation. The estimate itself
is the whole window's mean flux over its mean profile's slope; the jackknife also gives the error of
each window variant's difference from it.

Theory (k_B = 1; lambda = 1/(sqrt(2) pi n sigma^2), the hard spheres' mean free path; cbar =
sqrt(8 T/(pi m)) and c0 = sqrt(2 T/m), the mean and the most probable speed; a step of s mean free
times is dt = s lambda/cbar): kappa_0 = (75/(64 sigma^2)) sqrt(T/(pi m)), the first Sonine value,
and the Chapman-Enskog conductivity kappa_CE = 1.025218 kappa_0 (Chapman & Cowling 1970), times the
DSMC's leading-order discretisation laws
  kappa_DSMC/kappa_CE = 1 + 32/(225 pi) (dy/lambda)^2 + 32/(225 pi) (c0 dt/lambda)^2
                      = 1 + 32/(225 pi) (dy/lambda)^2 + (8/225) s^2,
dy the cell edge along y (Alexander, Garcia & Alder 1998; 2/5 of the viscosity's 16/(45 pi)) and dt
the step (Garcia & Wagner 2000, Hadjiconstantinou 2000; (c0 dt/lambda)^2 = (pi/4) s^2), each averaged
over the bulk's slabs at their own density and collision frequency: lambda of the slab's n, and s =
domain.time_step times the slab's collision frequency over the densest slab's (the steps are set
by the densest slab, at the cold wall). The laws, not the lower coefficients docs/validation.md
measures in this channel (0.034 (dy/lambda)^2 and 0.019 s^2): they are derived, the measured cells
follow the law within their errors up to lambda/2, and at cells of lambda/4 and steps of 0.2 the two
differ by 0.1 % of kappa; the table prints the ratio with the measured coefficients too. The window
sensitivity: the ratio with the window shifted a quarter of its length earlier (into the start-up
when the window starts early) and later, and with the margin 1 lambda narrower and wider, each with
its difference from the nominal and that difference's jackknife error (the variants share most of
their rows).

--from C, --to C: the window's ends in collisions per particle.
--margin L: the bulk is the slabs whose centres are more than L mean free paths from each wall.
--check-theory TOL: exit 1 unless |kappa/kappa_CE,laws - 1| <= TOL + 4 standard errors.
--plot PNG: draw the bulk's fit on the T_tr profile and the batches' kappa against time.
--self-check: check the fit on synthetic profiles of known kappa (exact, and with noise correlated
in time, against the jackknife's error) and the reading and refusals on synthetic run directories
(no run directory); exit 1 on a failure.
Exit 2 for a run directory the method does not apply to (missing files, no diffuse walls at rest
along y at two temperatures, not one species of elastic smooth hard spheres, no profiles along y,
too few slabs in the bulk, a run too short to be steady over 5 batches).
"""
import argparse
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header  # noqa: E402
from transport_common import (CONDUCTIVITY_LAWS, KAPPA_CE_OVER_KAPPA0, Refused, SelfCheck, check_theory,  # noqa: E402
                              elastic_smooth_species, kappa_0, kappa_1, mean_free_path, run_cli)

DEFAULT_MARGIN = 3.0  # mean free paths
RELAXATION_TIMES = 5.0  # the window starts after this many of the slowest relaxation times
JUMP = 2.0  # mean free paths: the temperature jump at each wall, in L_eff
BATCHES = 20
MIN_BATCHES = 5
C_P = 2.5  # heat capacity per grain at constant pressure (k_B = 1)
MEASURED = (0.034, 0.019)  # docs/validation.md: the fitted coefficients of (dy/lambda)^2 and s^2 in this channel


def relaxation_time(L, lam):
    """The slowest thermal relaxation time of a channel of width L, in collisions per particle:
    nu L_eff^2/(pi^2 D_T), D_T = kappa_CE/(n c_p), L_eff = L + 2 JUMP lambda (independent of T, n and
    m at a given L/lambda: nu/D_T = 4 n sigma^2 sqrt(pi T/m) n c_p/kappa_CE)."""
    n, sigma, T, m = 1.0 / (math.sqrt(2.0) * math.pi * lam), 1.0, 1.0, 1.0  # sigma = 1: n from lambda
    nu = 4 * n * sigma ** 2 * math.sqrt(math.pi * T / m)
    diffusivity = KAPPA_CE_OVER_KAPPA0 * kappa_0(m, T, sigma) / (n * C_P)
    return nu * (L + 2 * JUMP * lam) ** 2 / (math.pi ** 2 * diffusivity)


def y_walls(case):
    """The [wall_lower], [wall_upper] tables of the walls along y (an axis's own, else the shared ones)."""
    return [case.get(f"wall_{side}_y", case.get(f"wall_{side}")) for side in ("lower", "upper")]


def read_run(run_dir):
    """What the fit needs from RUN_DIR: the case's parameters and, per row, collisions per particle,
    the time since the previous row, the two walls' q_y, and the slabs' T_tr and n."""
    paths = {name: os.path.join(run_dir, name + ".csv") for name in ("profiles", "walls")}
    for name, path in paths.items():
        if not os.path.isfile(path):
            raise Refused(f"{path} does not exist (a box run writes profiles.csv, and walls.csv when it has walls)")
    case = read_header(paths["profiles"])["resolved"]
    if not case:
        raise Refused(f"{paths['profiles']} has no resolved case in its header")
    species = elastic_smooth_species(case)
    run, domain = case.get("run", {}), case.get("domain")
    if domain is None or domain.get("boundary") != ["periodic", "walls", "periodic"]:
        raise Refused("the method is for a channel: walls along y, periodic along x and z (domain.boundary = "
                      "[\"periodic\", \"walls\", \"periodic\"])")
    if domain.get("profile_axis", "y") != "y":
        raise Refused("profiles.csv is not along y (domain.profile_axis = \"y\")")
    if any(float(g) != 0.0 for g in domain.get("gravity", [0.0, 0.0, 0.0])):
        raise Refused("gravity: the pressure is not uniform (the method is for domain.gravity = [0, 0, 0])")
    walls = y_walls(case)
    if any(w is None or w.get("kind") != "diffuse" for w in walls):
        raise Refused("the walls along y must both be diffuse (kind = \"diffuse\")")
    if any(float(v) != 0.0 for w in walls for v in w.get("velocity", [0.0, 0.0, 0.0])):
        raise Refused("a wall moves: shear heats the gas (Couette flow), the heat flux is not uniform")
    t_walls = [float(w.get("temperature", 1.0)) for w in walls]
    if t_walls[0] == t_walls[1]:
        raise Refused(f"the walls are at the same temperature ({t_walls[0]:g}): no heat flux")
    p = {
        "n": float(run["density"]), "N": int(run["particles"]), "R": int(run.get("replicas", 1)),
        "m": float(species["mass"]), "sigma": 2.0 * float(species["radius"]), "L": float(domain["size"][1]),
        "cells": int(domain["cells"][1]), "s": float(domain.get("time_step", 0.2)), "T_walls": t_walls,
    }
    p["dy"] = p["L"] / p["cells"]
    p["lambda"] = mean_free_path(p["n"], p["sigma"])
    p["tau1"] = relaxation_time(p["L"], p["lambda"])

    prof, walls_csv = read_csv(paths["profiles"]), read_csv(paths["walls"])
    bins = int(prof["bin"].max()) + 1
    rows = len(walls_csv["t"])
    if bins != p["cells"] or len(prof["t"]) != rows * bins:
        raise Refused(f"profiles.csv does not hold {p['cells']} slabs for each of walls.csv's {rows} rows")
    t = prof["t"].reshape(rows, bins)[:, 0]
    if np.any(np.abs(t - walls_csv["t"]) > 1e-9 * (1 + np.abs(t))):
        raise Refused("profiles.csv and walls.csv do not have the same rows")
    data = {
        "t": t, "cpp": walls_csv["coll_per_particle"], "dt": np.concatenate([[0.0], np.diff(t)]),
        "q_lower": walls_csv["y_lower.q_y"], "q_upper": walls_csv["y_upper.q_y"],
        "y": prof["y"][:bins], "T": prof["T_tr"].reshape(rows, bins), "n_slab": prof["n"].reshape(rows, bins),
    }
    return p, data


def window_rows(cpp, start, end):
    """Rows whose interval since the previous row lies within [start, end] (walls.csv's fluxes cover
    that interval, profiles.csv's slabs are sampled at its end)."""
    inside = np.zeros(len(cpp), bool)
    inside[1:] = (cpp[:-1] >= start - 1e-9) & (cpp[1:] <= end + 1e-9)
    return inside


def bulk_slabs(y, L, margin):
    return (y > margin) & (y < L - margin)


def estimate(data, rows, bulk):
    """(kappa_1, q, dT^(3/2)/dy, the walls' imbalance) over the rows (mask) and bulk slabs (mask):
    the time-weighted mean of the walls' mean flux over the slope of the mean profile's T^(3/2)."""
    w = data["dt"][rows]
    q_lower = np.sum(w * data["q_lower"][rows]) / np.sum(w)
    q_upper = np.sum(w * data["q_upper"][rows]) / np.sum(w)
    q = 0.5 * (q_lower + q_upper)
    profile = np.sum(w[:, None] * data["T"][rows], axis=0) / np.sum(w)
    slope = np.polyfit(data["y"][bulk], profile[bulk] ** 1.5, 1)[0]
    return np.array([kappa_1(data["y"][bulk], profile[bulk], q), q, slope, (q_lower - q_upper) / abs(q)])


def jackknife(data, variants, batches):
    """estimate() for each (rows, bulk) of `variants`, with jackknife standard errors over `batches`
    consecutive blocks of the union of their rows: (values [variant, quantity], errors alike, the
    errors of each variant's values minus the first's)."""
    union = np.nonzero(np.logical_or.reduce([r for r, _ in variants]))[0]
    full = np.array([estimate(data, r, b) for r, b in variants])
    leave = []
    for block in np.array_split(union, batches):
        keep = np.ones(len(data["t"]), bool)
        keep[block] = False
        leave.append([estimate(data, r & keep, b) for r, b in variants])
    leave = np.array(leave)  # [batch, variant, quantity]

    def spread(x):
        return np.sqrt((batches - 1) / batches * np.sum((x - x.mean(axis=0)) ** 2, axis=0))

    return full, spread(leave), spread(leave - leave[:, :1, :])


def laws(p, data, rows, bulk):
    """The cell and step terms (coefficient-free): the bulk slabs' mean (dy/lambda)^2 at their own
    density and mean s^2 at their own collision frequency (steps set by the densest slab's)."""
    w = data["dt"][rows]
    n = np.sum(w[:, None] * data["n_slab"][rows], axis=0) / np.sum(w)
    T = np.sum(w[:, None] * data["T"][rows], axis=0) / np.sum(w)
    cells = (p["dy"] / mean_free_path(1.0, p["sigma"]) * n) ** 2  # lambda = lambda(n = 1)/n
    nu = n * np.sqrt(T)
    steps = (p["s"] * nu / nu.max()) ** 2
    return float(np.mean(cells[bulk])), float(np.mean(steps[bulk])), float(np.mean(T[bulk]))


def analyse(p, data, start, end, margin):
    """The measurement: a dict of the nominal result and its window variants."""
    cpp, lam, y = data["cpp"], p["lambda"], data["y"]
    if cpp[-1] < start:
        raise Refused(f"the run ends at {cpp[-1]:g} collisions per particle, before the window's start at {start:.4g}: "
                      f"too short to be steady (the flow is steady from {RELAXATION_TIMES:g} of the channel's slowest "
                      f"relaxation times, tau_1 = {p['tau1']:.3g} collisions per particle); run it longer")
    rows = window_rows(cpp, start, end)
    idx = np.nonzero(rows)[0]
    length = cpp[idx[-1]] - cpp[idx[0] - 1] if len(idx) else 0.0
    batches = min(BATCHES, len(idx), int(length / (0.5 * p["tau1"]) + 1e-9))
    if batches < MIN_BATCHES:
        raise Refused(f"the window from {start:.4g} to {min(end, cpp[-1]):.4g} collisions per particle ({len(idx)} rows) "
                      f"is too short to be steady over {MIN_BATCHES} batches of half a relaxation time "
                      f"(tau_1 = {p['tau1']:.3g} collisions per particle): run it longer")
    bulk = bulk_slabs(y, p["L"], margin * lam)
    if np.sum(bulk) < 3:
        raise Refused(f"fewer than 3 slabs more than {margin:g} mean free paths from both walls (the channel is "
                      f"{p['L'] / lam:.3g} lambda wide; --margin)")
    variants = [("nominal", rows, bulk)]
    quarter = length / 4
    first, last = cpp[idx[0] - 1], cpp[idx[-1]]
    for shift in (-quarter, quarter):
        lo, hi = max(first + shift, cpp[0]), min(last + shift, cpp[-1])
        r = window_rows(cpp, lo, hi)
        if np.sum(r) >= 3:
            variants.append((f"window {'earlier' if shift < 0 else 'later'} by {quarter:.3g} ({lo:.3g} to {hi:.3g}"
                             f"{', into the start-up' if lo < RELAXATION_TIMES * p['tau1'] - 1e-9 else ''})", r, bulk))
    for delta in (-1.0, 1.0):
        b = bulk_slabs(y, p["L"], (margin + delta) * lam)
        if margin + delta >= 0 and np.sum(b) >= 3:
            variants.append((f"margin {margin + delta:g} lambda ({np.sum(b)} slabs)", rows, b))
    values, errors, diff_errors = jackknife(data, [(r, b) for _, r, b in variants], batches)
    cells, steps, t_bulk = laws(p, data, rows, bulk)
    law = 1 + CONDUCTIVITY_LAWS[0] * cells + CONDUCTIVITY_LAWS[1] * steps
    measured = 1 + MEASURED[0] * (p["dy"] / lam) ** 2 + MEASURED[1] * p["s"] ** 2
    k01 = kappa_0(p["m"], 1.0, p["sigma"])  # kappa_0 / sqrt(T)
    out = {"rows": rows, "bulk": bulk, "margin": margin, "batches": batches, "first": first, "last": last, "T_b": t_bulk,
           "cells": cells, "steps": steps, "laws": law, "measured_laws": measured, "kappa0_1": k01,
           "variants": []}
    for k, (name, r, b) in enumerate(variants):
        ratio = values[k, 0] / (KAPPA_CE_OVER_KAPPA0 * k01 * law)
        out["variants"].append({
            "name": name, "rows": r, "bulk": b, "kappa_1": values[k, 0], "kappa_1_err": errors[k, 0],
            "q": values[k, 1], "q_err": errors[k, 1], "slope": values[k, 2], "slope_err": errors[k, 2],
            "imbalance": values[k, 3], "imbalance_err": errors[k, 3], "ratio": ratio,
            "ratio_err": ratio * errors[k, 0] / values[k, 0],
            "diff": ratio - values[0, 0] / (KAPPA_CE_OVER_KAPPA0 * k01 * law),
            "diff_err": diff_errors[k, 0] / (KAPPA_CE_OVER_KAPPA0 * k01 * law)})
    return out


def batch_series(p, data, out):
    """kappa/kappa_CE,laws of each batch of rows over the whole run (for the plot)."""
    cpp = data["cpp"]
    length = (out["last"] - out["first"]) / out["batches"]
    edges = np.arange(cpp[0], cpp[-1] + length, length)
    points = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        r = window_rows(cpp, lo, hi)
        if np.sum(r) >= 1:
            k1 = estimate(data, r, out["bulk"])[0]
            points.append((0.5 * (lo + hi), k1 / (KAPPA_CE_OVER_KAPPA0 * out["kappa0_1"] * out["laws"])))
    return np.array(points)


def draw(path, p, data, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from atomic_output import save_figure
    nominal = out["variants"][0]
    rows, bulk, lam = out["rows"], out["bulk"], p["lambda"]
    y = data["y"] / lam
    profile = np.mean(data["T"][rows], axis=0)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    left.plot(y[~bulk], profile[~bulk], "o", ms=4, mfc="none", color="0.5", label="T_tr, Knudsen layers (left out)")
    left.plot(y[bulk], profile[bulk], "o", ms=4, color="C0", label="T_tr, bulk")
    intercept = np.mean(profile[bulk] ** 1.5) - nominal["slope"] * np.mean(data["y"][bulk])
    yy = np.linspace(0, p["L"], 200)
    left.plot(yy / lam, np.clip(intercept + nominal["slope"] * yy, 0, None) ** (2 / 3), "-", color="C3", lw=1,
              label="fit: T^(3/2) linear over the bulk")
    left.plot([0, p["L"] / lam], p["T_walls"], "s", color="k", label="walls")
    left.axvspan(0, out["margin"], color="0.85", alpha=0.5)
    left.axvspan(p["L"] / lam - out["margin"], p["L"] / lam, color="0.85", alpha=0.5)
    left.set_xlabel("y / \u03bb")
    left.set_ylabel("T_tr")
    left.set_title(f"window {out['first']:.4g} to {out['last']:.4g} collisions per particle")
    left.legend(fontsize=8)
    series = batch_series(p, data, out)
    right.plot(series[:, 0], series[:, 1], "o", ms=3, color="C0", label="batches")
    right.axvspan(out["first"], out["last"], color="C3", alpha=0.08, label="window")
    right.axhline(1.0, color="k", lw=0.8, ls="--")
    right.axhline(nominal["ratio"], color="C3", lw=1,
                  label=f"\u03ba/\u03ba_CE,laws = {nominal['ratio']:.4f} \u00b1 {nominal['ratio_err']:.4f}")
    right.set_xlabel("collisions per particle")
    right.set_ylabel("\u03ba / \u03ba_CE,laws")
    right.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)


def steady_detector(run_dir, first):
    """What roughgas's steady-state detector (steady.csv: on the box's moments) says, beside the window."""
    path = os.path.join(run_dir, "steady.csv")
    if not os.path.isfile(path):
        return "no steady.csv"
    row = read_csv(path)
    if row["steady"][0] != 1:
        return "steady.csv: the run's steady-state criterion never held (its moments drift)"
    start = row["steady_from"][0]
    return (f"steady.csv: the moments are steady from {start:.4g} collisions per particle"
            + (", after the window's start" if start > first + 1e-9 else ""))


def report(run_dir, args):
    p, data = read_run(run_dir)
    start = RELAXATION_TIMES * p["tau1"] if args.start is None else args.start
    end = math.inf if args.end is None else args.end
    out = analyse(p, data, start, end, args.margin)
    nominal, lam = out["variants"][0], p["lambda"]
    y, bulk = data["y"], out["bulk"]
    print(f"thermal_conductivity: {run_dir}: Fourier flow along y between diffuse walls at T = {p['T_walls'][0]:g} and "
          f"{p['T_walls'][1]:g}, {p['L'] / lam:.4g} lambda apart; {p['R']} replica{'s' if p['R'] != 1 else ''} of "
          f"{p['N']} grains; cells of {p['dy'] / lam:.3g} lambda along y, steps of {p['s']:g} mean free times")
    batch = (out["last"] - out["first"]) / out["batches"]
    print(f"window: {out['first']:.4g} to {out['last']:.4g} collisions per particle ({int(np.sum(out['rows']))} rows, "
          f"{out['batches']} batches of {batch:.3g}): from "
          + (f"{RELAXATION_TIMES:g} of the channel's slowest relaxation times (tau_1 = {p['tau1']:.3g} collisions per "
             f"particle)" if args.start is None else "--from") + "; to " + ("the run's end" if args.end is None else "--to"))
    print(f"bulk: {int(np.sum(bulk))} of {len(y)} slabs, centres more than {args.margin:g} lambda from each wall "
          f"(y = {y[bulk][0]:.4g} to {y[bulk][-1]:.4g}); T_b = {out['T_b']:.5g} (their mean T_tr)")
    print(f"steady: the walls' fluxes differ by (q_lower - q_upper)/|q| = {nominal['imbalance']:+.4f} "
          f"\u00b1 {nominal['imbalance_err']:.4f} over the window (0 when the gas's energy is steady); "
          + steady_detector(run_dir, out["first"]))
    intercept = np.mean(np.mean(data["T"][out["rows"]], axis=0)[bulk] ** 1.5) - nominal["slope"] * np.mean(y[bulk])
    jumps = []
    for wall, at in zip(p["T_walls"], (0.0, p["L"])):
        t_gas = max(intercept + nominal["slope"] * at, 0.0) ** (2 / 3)
        gradient = (2 / 3) * nominal["slope"] / math.sqrt(t_gas)  # dT/dy of the fitted line at the wall
        jumps.append((t_gas, abs(t_gas - wall) / abs(gradient) / lam))
    print(f"jumps: the bulk's fit meets the walls at T = {jumps[0][0]:.4g} and {jumps[1][0]:.4g}, jumps of "
          f"{jumps[0][1]:.3g} and {jumps[1][1]:.3g} lambda times the gradient")
    print(f"laws: 1 + 32/(225 pi) (dy/lambda)^2 + (8/225) s^2 = 1 + 32/(225 pi) {out['cells']:.4g} + (8/225) "
          f"{out['steps']:.4g} = {out['laws']:.5f}, over the bulk's slabs at their own lambda and steps (at run.density "
          f"and the nominal step: {(p['dy'] / lam) ** 2:.4g} and {p['s'] ** 2:.4g}; cells: Alexander, Garcia & Alder "
          f"1998; steps: Garcia & Wagner 2000, Hadjiconstantinou 2000); kappa_CE = 1.025218 kappa_0 (Chapman & Cowling 1970)")
    k0 = out["kappa0_1"] * math.sqrt(out["T_b"])
    to_kappa = math.sqrt(out["T_b"])
    measured = nominal["kappa_1"] / (KAPPA_CE_OVER_KAPPA0 * out["kappa0_1"] * out["measured_laws"])
    print()
    print("| quantity | value | error | minus the nominal |")
    print("|---|---|---|---|")
    print(f"| q_y, the walls' mean (case units) | {nominal['q']:.6g} | {nominal['q_err']:.3g} | - |")
    print(f"| dT^(3/2)/dy over the bulk (case units) | {nominal['slope']:.6g} | {nominal['slope_err']:.3g} | - |")
    print(f"| kappa_1 = kappa/sqrt(T) (case units) | {nominal['kappa_1']:.6g} | {nominal['kappa_1_err']:.3g} | - |")
    print(f"| kappa at T_b (case units) | {nominal['kappa_1'] * to_kappa:.6g} | "
          f"{nominal['kappa_1_err'] * to_kappa:.3g} | - |")
    print(f"| kappa_0 = (75/64) sqrt(T_b/(pi m))/sigma^2 | {k0:.6g} | - | - |")
    print(f"| kappa/kappa_0 | {nominal['kappa_1'] / out['kappa0_1']:.5f} | "
          f"{nominal['kappa_1_err'] / out['kappa0_1']:.5f} | - |")
    ce = KAPPA_CE_OVER_KAPPA0 * out["kappa0_1"]
    print(f"| kappa/kappa_CE | {nominal['kappa_1'] / ce:.5f} | {nominal['kappa_1_err'] / ce:.5f} | - |")
    print(f"| kappa/kappa_CE,laws | {nominal['ratio']:.5f} | {nominal['ratio_err']:.5f} | - |")
    print(f"| kappa/kappa_CE with the measured coefficients, 1 + {MEASURED[0]} (dy/lambda)^2 + {MEASURED[1]} s^2 = "
          f"{out['measured_laws']:.5f} | {measured:.5f} | {measured * nominal['ratio_err'] / nominal['ratio']:.5f} | "
          f"{measured - nominal['ratio']:+.5f} |")
    for v in out["variants"][1:]:
        print(f"| kappa/kappa_CE,laws, {v['name']} | {v['ratio']:.5f} | {v['ratio_err']:.5f} | "
              f"{v['diff']:+.5f} \u00b1 {v['diff_err']:.5f} |")
    print()
    moves = {kind: [v for v in out["variants"][1:] if v["name"].startswith(kind)] for kind in ("window", "margin")}
    parts = []
    for kind, vs in moves.items():
        if vs:
            v = max(vs, key=lambda x: abs(x["diff"]))
            parts.append(f"{kind} {abs(v['diff']):.4f} ({abs(v['diff']) / v['diff_err']:.1f} standard errors of the "
                         f"difference)" if v["diff_err"] > 0 else f"{kind} {abs(v['diff']):.4f}")
    print(f"error from batch means (a jackknife over {out['batches']} batches of consecutive rows); the window "
          f"sensitivity, the largest move of kappa/kappa_CE,laws: " + ("; ".join(parts) if parts else "-"))
    if args.plot:
        draw(args.plot, p, data, out)
        print(f"thermal_conductivity: wrote {args.plot}")
    if args.check_theory is not None:
        return check_theory("kappa/kappa_CE,laws", nominal["ratio"], nominal["ratio_err"], args.check_theory)
    return 0 if math.isfinite(nominal["kappa_1"]) else 1


# The synthetic channel of the self-check: the shipped case's, rows every 4 collisions per particle.
SYNTHETIC_L, SYNTHETIC_BINS = 225.0, 80
SYNTHETIC_CASE = """[run]
kind = "cooling"
particles = 40000
density = 0.02
replicas = 1
kernel = "hard_sphere"

[[species]]
name = "grain"
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 1.0
beta = {beta}

[domain]
size = [11.25, 225.0, 11.25]
cells = [3, 80, 3]
boundary = {boundary}
gravity = [0.0, 0.0, 0.0]
profile_axis = "y"
time_step = 0.2

[wall_lower]
kind = "diffuse"
temperature = 0.8
velocity = [{velocity}, 0.0, 0.0]

[wall_upper]
kind = "diffuse"
temperature = {t_upper}
velocity = [0.0, 0.0, 0.0]
"""


def synthetic(kappa1, rows, rng=None, t_noise=0.0, rho=0.0, q_noise=0.0, layer=0.0):
    """A steady channel of known kappa_1: the shipped case's slabs, T^(3/2) linear from 0.83 to 1.17 across
    the bulk (n = 0.02/T), q = -(2/3) kappa_1 dT^(3/2)/dy at both walls, rows every 4 collisions per particle;
    `layer`: a Knudsen-layer bump of that size in the slabs within 2.5 lambda of each wall; noise: each
    slab's T with relative standard deviation t_noise, correlated as rho^k over k rows, each wall's q
    with relative standard deviation q_noise."""
    L, bins, lam = SYNTHETIC_L, SYNTHETIC_BINS, mean_free_path(0.02, 1.0)
    y = (np.arange(bins) + 0.5) * L / bins
    a, b = 0.83 ** 1.5, (1.17 ** 1.5 - 0.83 ** 1.5) / L
    T = (a + b * y) ** (2 / 3)
    near = np.minimum(y, L - y)
    T = T + layer * np.where(near < 2.5 * lam, 1 - near / (2.5 * lam), 0.0) * np.sign(y - L / 2)
    q = -(2 / 3) * kappa1 * b
    T_rows = np.tile(T, (rows, 1))
    q_lower, q_upper = np.full(rows, q), np.full(rows, q)
    if rng is not None:
        xi = np.empty((rows, bins))
        xi[0] = rng.standard_normal(bins)
        for k in range(1, rows):
            xi[k] = rho * xi[k - 1] + math.sqrt(1 - rho ** 2) * rng.standard_normal(bins)
        T_rows = T_rows * (1 + t_noise * xi)
        q_lower = q * (1 + q_noise * rng.standard_normal(rows))
        q_upper = q * (1 + q_noise * rng.standard_normal(rows))
    cpp = 4.0 * np.arange(rows)
    q_lower[0] = q_upper[0] = math.nan  # the first row has no interval
    return {"t": 7.05 * cpp, "cpp": cpp, "dt": np.concatenate([[0.0], np.full(rows - 1, 7.05 * 4)]),
            "q_lower": q_lower, "q_upper": q_upper, "y": y, "T": T_rows, "n_slab": 0.02 / T_rows}


def write_run(directory, data, **case):
    """A run directory of the synthetic channel: profiles.csv and walls.csv with a resolved case."""
    keys = {"beta": "-1.0", "boundary": '["periodic", "walls", "periodic"]', "velocity": "0.0", "t_upper": "1.2"}
    keys.update(case)
    header = "# roughgas (synthetic)\n# resolved case (every default filled in):\n" + "".join(
        f"# {line}\n" for line in SYNTHETIC_CASE.format(**keys).splitlines())
    rows, bins = data["T"].shape
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "profiles.csv"), "w") as f:
        f.write(header + "t,coll_per_particle,bin,y,n,T_tr\n")
        for k in range(rows):
            for i in range(bins):
                f.write(f"{data['t'][k]!r},{data['cpp'][k]!r},{i},{data['y'][i]!r},{data['n_slab'][k, i]!r},"
                        f"{data['T'][k, i]!r}\n")
    with open(os.path.join(directory, "walls.csv"), "w") as f:
        f.write(header + "t,coll_per_particle,y_lower.q_y,y_upper.q_y\n")
        for k in range(rows):
            f.write(f"{data['t'][k]!r},{data['cpp'][k]!r},{data['q_lower'][k]!r},{data['q_upper'][k]!r}\n")


def self_check():
    """The fit on synthetic channels: exact profiles, noise correlated in time, run directories."""
    check = SelfCheck()
    k01 = kappa_0(1.0, 1.0, 1.0)
    lam = mean_free_path(0.02, 1.0)

    kappa1 = 1.0123 * k01
    data = synthetic(kappa1, 300, layer=0.03)
    rows, y = window_rows(data["cpp"], 0.0, math.inf), data["y"]
    got = estimate(data, rows, bulk_slabs(y, SYNTHETIC_L, DEFAULT_MARGIN * lam))[0]
    check.expect(abs(got / kappa1 - 1) < 1e-10, f"an exact profile, Knudsen layers within the margin: kappa_1 "
                                                f"{got:.10g} against {kappa1:.10g}")
    got = estimate(data, rows, bulk_slabs(y, SYNTHETIC_L, (DEFAULT_MARGIN - 1) * lam))[0]
    check.expect(abs(got / kappa1 - 1) > 1e-3,
                 f"the layers inside a margin of {DEFAULT_MARGIN - 1:g} lambda move it: {got / kappa1:.5f}")
    bulk = bulk_slabs(y, SYNTHETIC_L, DEFAULT_MARGIN * lam)
    linear_t = -data["q_lower"][1] / np.polyfit(y[bulk], data["T"][1][bulk], 1)[0] / math.sqrt(np.mean(data["T"][1][bulk]))
    check.expect(abs(linear_t / kappa1 - 1) > 3e-4, f"a line through T instead of T^(3/2) would be off: "
                                                    f"{linear_t / kappa1:.5f}")

    # Noise: each slab's T correlated over rows, the walls' q white; the jackknife's error against the scatter.
    rng = np.random.default_rng(11)
    trials, values, errors = 200, [], []
    for _ in range(trials):
        d = synthetic(kappa1, 500, rng, t_noise=0.01, rho=0.3, q_noise=0.1)
        r = window_rows(d["cpp"], 100.0, math.inf)
        b = bulk_slabs(d["y"], SYNTHETIC_L, DEFAULT_MARGIN * lam)
        full, err, _ = jackknife(d, [(r, b)], BATCHES)
        values.append(full[0, 0])
        errors.append(err[0, 0])
    values, errors = np.array(values), np.array(errors)
    sem = values.std(ddof=1) / math.sqrt(trials)
    check.expect(abs(values.mean() - kappa1) < 4 * sem, f"noisy channels: mean kappa_1 {values.mean():.6g} against "
                                                        f"{kappa1:.6g} (4 standard errors {4 * sem:.2g})")
    # The scatter of a standard deviation from 200 samples is 5 %, the jackknife's own 16 % over 20 batches
    # averages to ~1 %: 20 % is 4 of the first.
    ratio = values.std(ddof=1) / errors.mean()
    check.expect(abs(ratio - 1) < 0.2, f"the jackknife's error against the scatter of kappa_1: {ratio:.3f}")

    # The laws and the relaxation time.
    s = 0.3
    c0_dt_over_lambda = s * math.sqrt(2.0) / math.sqrt(8.0 / math.pi)
    check.expect(abs(CONDUCTIVITY_LAWS[0] * c0_dt_over_lambda ** 2 - CONDUCTIVITY_LAWS[1] * s ** 2) < 1e-15,
                 "the step law (8/225) s^2 = 32/(225 pi) (c0 dt/lambda)^2")
    closed = 64.0 / (15.0 * KAPPA_CE_OVER_KAPPA0 * math.pi ** 3) * (10.0 + 2 * JUMP) ** 2
    check.expect(abs(relaxation_time(10 * lam, lam) / closed - 1) < 1e-12
                 and abs(relaxation_time(100.0, 10.0) / closed - 1) < 1e-12,
                 f"tau_1 = 64 (L/lambda + 4)^2/(15 pi^3 1.025218) = {closed:.4g} collisions per particle at L = 10 lambda")
    uniform = synthetic(kappa1, 10)
    uniform["T"][:] = 1.0
    uniform["n_slab"][:] = 0.02
    p = {"dy": SYNTHETIC_L / SYNTHETIC_BINS, "sigma": 1.0, "s": 0.2}
    cells, steps, _ = laws(p, uniform, window_rows(uniform["cpp"], 0, math.inf), np.ones(SYNTHETIC_BINS, bool))
    check.expect(abs(cells - (SYNTHETIC_L / SYNTHETIC_BINS / lam) ** 2) < 1e-12 and abs(steps - 0.04) < 1e-12,
                 f"the laws' terms in a uniform gas: (dy/lambda)^2 = {cells:.6g}, s^2 = {steps:.6g}")

    # Run directories: read, measured, refused.
    with tempfile.TemporaryDirectory() as tmp:
        good = os.path.join(tmp, "good")
        data = synthetic(kappa1, 300, layer=0.03)
        write_run(good, data)
        p, read = read_run(good)
        out = analyse(p, read, RELAXATION_TIMES * p["tau1"], math.inf, DEFAULT_MARGIN)
        v = out["variants"][0]
        windows = [w for w in out["variants"] if w["name"].startswith("window")]
        margins = [w for w in out["variants"] if w["name"].startswith("margin")]
        check.expect(abs(v["kappa_1"] / kappa1 - 1) < 1e-9 and v["kappa_1_err"] < 1e-9 * kappa1
                     and len(windows) == 2 and all(abs(w["diff"]) < 1e-9 for w in windows)
                     and len(margins) == 2 and abs(margins[0]["diff"]) > 1e-3 and abs(margins[1]["diff"]) < 1e-9,
                     f"a run directory: kappa_1 {v['kappa_1']:.10g}, error {v['kappa_1_err']:.2g}; the windows "
                     f"shifted equal, the margin of {DEFAULT_MARGIN - 1:g} lambda in the layers {margins[0]['diff'] if margins else 0:+.4f}")
        exact = os.path.join(tmp, "exact")
        write_run(exact, synthetic(KAPPA_CE_OVER_KAPPA0 * k01 * out["laws"], 300, layer=0.03))
        off = os.path.join(tmp, "off")
        write_run(off, synthetic(1.02 * KAPPA_CE_OVER_KAPPA0 * k01 * out["laws"], 300, layer=0.03))
        quiet = argparse.Namespace(start=None, end=None, margin=DEFAULT_MARGIN, plot=None, check_theory=0.01)
        with open(os.devnull, "w") as devnull:
            stdout, sys.stdout = sys.stdout, devnull
            try:
                verdicts = (report(exact, quiet), report(off, quiet))
            finally:
                sys.stdout = stdout
        check.expect(verdicts == (0, 1), f"--check-theory 0.01 passes kappa_CE,laws and fails 1.02 times it: "
                                         f"exits {verdicts}")
        refusals = {
            "rough grains": ({"beta": "0.0"}, None, "elastic smooth"),
            "a moving wall": ({"velocity": "0.5"}, None, "moves"),
            "walls at one temperature": ({"t_upper": "0.8"}, None, "same temperature"),
            "walls along x too": ({"boundary": '["walls", "walls", "periodic"]'}, None, "channel"),
            "no profiles": ({}, "profiles.csv", "does not exist"),
            "too short to be steady": ({}, 30, "too short"),
        }
        for name, (keys, change, message) in refusals.items():
            directory = os.path.join(tmp, name.replace(" ", "_"))
            write_run(directory, synthetic(kappa1, change if isinstance(change, int) else 300), **keys)
            if isinstance(change, str):
                os.remove(os.path.join(directory, change))
            try:
                p, read = read_run(directory)
                analyse(p, read, RELAXATION_TIMES * p["tau1"], math.inf, DEFAULT_MARGIN)
                check.expect(False, f"{name}: not refused")
            except Refused as e:
                check.expect(message in str(e), f"{name}: refused ({e})")
        try:
            p, read = read_run(good)
            analyse(p, read, RELAXATION_TIMES * p["tau1"], math.inf, 9.8)
            check.expect(False, "a margin of 9.8 lambda: not refused")
        except Refused as e:
            check.expect("fewer than 3 slabs" in str(e), f"a margin of 9.8 lambda: refused ({e})")
    return check.status()


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir", nargs="?", help="a box run of Fourier flow along y with profiles.csv and walls.csv")
    parser.add_argument("--from", dest="start", type=float, default=None,
                        help="the window's start, collisions per particle (default: 5 of the channel's slowest "
                             "thermal relaxation times)")
    parser.add_argument("--to", dest="end", type=float, default=None,
                        help="the window's end, collisions per particle (default: the run's end)")
    parser.add_argument("--margin", type=float, default=DEFAULT_MARGIN, metavar="L",
                        help="the bulk: slabs more than L mean free paths from each wall (default 3)")
    parser.add_argument("--check-theory", type=float, default=None, metavar="TOL",
                        help="exit 1 unless |kappa/kappa_CE,laws - 1| <= TOL + 4 standard errors")
    parser.add_argument("--plot", default=None, metavar="PNG", help="draw the fit and the batches")
    parser.add_argument("--self-check", action="store_true", help="check the fit on synthetic channels")
    return run_cli("thermal_conductivity", parser, argv, report, self_check)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
