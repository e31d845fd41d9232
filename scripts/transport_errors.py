#!/usr/bin/env python3
"""The DSMC's discretisation errors of the viscosity and the conductivity, measured in Couette and Fourier flow.

    scripts/python3 scripts/transport_errors.py [--flow couette|fourier] [--build build] [--threads 2]
        [--collisions 1000] [--out out/transport_errors_FLOW] [--plot docs/transport_errors.png] [--no-run]

An elastic hard-sphere gas (run.density = 0.02, sigma = 1: mean free path lambda = 11.254) between
diffuse walls at T_w = 1 moving at -0.5 and +0.5 along x, 20 mean free paths apart. The viscosity
-P_xy/(du_x/dy) comes from the walls' momentum flux (walls.csv) and the slope of u_x over the
bulk slabs (profiles.csv, slabs centred more than 2 lambda from the walls), as batch means over
the rows after the first 100 collisions per particle (rows every 10), at the bulk's temperature,
in units of the Chapman-Enskog value 1.016034 eta_0, eta_0 = (5/16) sqrt(m T/pi)/sigma^2.

Three series:
  cells   random partners, cells of 0.25 to 2 lambda along y (one cell across the 1 x 1 lambda
          section), steps of 0.2 mean free times; the leading-order law
          1 + 16/(45 pi) (dy/lambda)^2 (Alexander, Garcia & Alder 1998);
  nearest nearest partners (domain.partners = "nearest"), cubic cells of 0.5 to 2 lambda holding
          20 grains, steps of 0.2;
  steps   random partners, cells of 0.25 lambda, steps of 0.1 to 1 mean free time (for the
          conductivity, whose step law is the weaker, also 0.1 and 1 with four times the grains in
          a section of 2 x 2 lambda)
          (domain.time_step); the law 1 + 16/(75 pi) (c_0 dt/lambda)^2, c_0 = sqrt(2 T/m)
          (Hadjiconstantinou 2000), that is 1 + (4/75) s^2 for steps of s mean free times
          lambda/cbar.
--flow fourier measures the conductivity instead: the same channel between diffuse walls at rest
at T_w = 0.8 and 1.2, kappa = -q_y/(dT/dy) from the walls' energy flux and the bulk's T_tr (as
kappa = kappa_1 sqrt(T), the slope of T_tr^(3/2) gives kappa_1 = -(3/2) q_y/(dT^(3/2)/dy)), in units
of the Chapman-Enskog value 1.025218 kappa_0, kappa_0 = (75/64) sqrt(T/(m pi))/sigma^2; the cells and steps series only, against the laws 1 + 32/(225 pi) (dy/lambda)^2 (the
Green-Kubo self term of the energy that a collision carries between grains a cell apart, the
route by which Alexander, Garcia & Alder 1998 find the viscosity's; 2/5 of it, as kappa_0 is
15/(4m) eta_0 and the transfers' ratio 3/(2m)) and 1 + 32/(225 pi) (c_0 dt/lambda)^2 = 1 + (8/225) s^2
(Hadjiconstantinou 2000).
Prints a table (docs/validation.md) and least-squares fits of the cells and steps series to
a + b x^2; --plot draws the ratio against (dy/lambda)^2 and s^2 with the laws.
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure  # noqa: E402
from transport_common import (CONDUCTIVITY_LAWS, ETA_CE_OVER_ETA0, KAPPA_CE_OVER_KAPPA0, VISCOSITY_LAWS,  # noqa: E402
                              eta_0, kappa_0, kappa_1, mean_free_path)

DENSITY = 0.02
LAMBDA = mean_free_path(DENSITY, 1.0)
WIDTH = 20  # mean free paths between the walls
# The leading-order laws' coefficients of (dy/lambda)^2 and s^2 per flow (see the docstring).
LAWS = {"couette": VISCOSITY_LAWS, "fourier": CONDUCTIVITY_LAWS}
WALLS = {"couette": ((1.0, -0.5), (1.0, 0.5)), "fourier": ((0.8, 0.0), (1.2, 0.0))}


def case_text(flow, particles, section, cells, partners, time_step, collisions):
    """A channel case: section [L_x, L_z] and cells [n_x, n_y, n_z] in mean free paths and counts."""
    (t_lower, u_lower), (t_upper, u_upper) = WALLS[flow]
    size = [section[0] * LAMBDA, WIDTH * LAMBDA, section[1] * LAMBDA]
    return (f"[run]\nparticles = {particles}\nend = {float(collisions)}\noutput_every = 10.0\n"
            f"density = {DENSITY}\nseed = 1\n\n[[species]]\nmass = 1.0\nradius = 0.5\n\n"
            "[collision]\nmodel = \"constant\"\nalpha = 1.0\nbeta = -1.0\n\n"
            f"[domain]\nsize = [{size[0]!r}, {size[1]!r}, {size[2]!r}]\ncells = {list(cells)}\n"
            "boundary = [\"periodic\", \"walls\", \"periodic\"]\n"
            f"time_step = {time_step}\nallow_coarse = true\npartners = \"{partners}\"\n\n"
            f"[wall_lower]\nkind = \"diffuse\"\ntemperature = {t_lower}\nvelocity = [{u_lower}, 0.0, 0.0]\n\n"
            f"[wall_upper]\nkind = \"diffuse\"\ntemperature = {t_upper}\nvelocity = [{u_upper}, 0.0, 0.0]\n")


def runs(flow):
    """(series, dy/lambda, steps in mean free times, partners, particles, section, cells)."""
    out = []
    for dy in (0.25, 0.5, 1.0, 1.5, 2.0):
        ny = round(WIDTH / dy)
        out.append(("cells", WIDTH / ny, 0.2, "random", 40000, (1.0, 1.0), (1, ny, 1)))
    for dy, m in ((0.5, 8), (1.0, 10), (2.0, 10)) if flow == "couette" else ():
        ny = round(WIDTH / dy)
        out.append(("nearest", dy, 0.2, "nearest", 20 * m * m * ny, (m * dy, m * dy), (m, ny, m)))
    for s in (0.1, 0.35, 0.5, 0.75, 1.0):
        out.append(("steps", 0.25, s, "random", 40000, (1.0, 1.0), (1, 80, 1)))
    for s in (0.1, 1.0) if flow == "fourier" else ():
        out.append(("steps", 0.25, s, "random", 160000, (2.0, 2.0), (1, 80, 1)))
    return out


def transport(flow, directory):
    """eta/eta_CE (couette) or kappa/kappa_CE (fourier) and its standard error from batch means of
    10 rows after the first 100 collisions per particle."""
    prof = read_csv(os.path.join(directory, "profiles.csv"))
    walls = read_csv(os.path.join(directory, "walls.csv"))
    times = walls["coll_per_particle"]
    flux, field = ("P_xy", "u_x") if flow == "couette" else ("q_y", "T_tr")
    wall_flux = 0.5 * (walls["y_lower." + flux] + walls["y_upper." + flux])
    keep = [k for k, t in enumerate(times) if t > 100.5]
    batches = [keep[i:i + 10] for i in range(0, len(keep) - 9, 10)]
    ratios = []
    for batch in batches:
        ys, us, ts, p = None, None, [], 0.0
        for k in batch:
            rows = prof["coll_per_particle"] == times[k]
            y, u, T = prof["y"][rows], prof[field][rows], prof["T_tr"][rows]
            bulk = (y > 2 * LAMBDA) & (y < (WIDTH - 2) * LAMBDA)
            ys = y[bulk]
            us = u[bulk] / len(batch) if us is None else us + u[bulk] / len(batch)
            ts.append(T[bulk].mean())
            p += wall_flux[k] / len(batch)
        if flow == "couette":
            slope = np.polyfit(ys, us, 1)[0]
            ratios.append(-p / slope / (ETA_CE_OVER_ETA0 * eta_0(1.0, float(np.mean(ts)), 1.0)))
        else:
            ratios.append(kappa_1(ys, us, p) / (KAPPA_CE_OVER_KAPPA0 * kappa_0(1.0, 1.0, 1.0)))
    r = np.array(ratios)
    return r.mean(), r.std(ddof=1) / math.sqrt(len(r))


def fit(x, y, e):
    """Weighted least squares y = a + b x; returns (a, b, sigma_a, sigma_b)."""
    w = 1 / np.asarray(e) ** 2
    A = np.vstack([np.ones_like(x), x]).T
    cov = np.linalg.inv(A.T @ (A * w[:, None]))
    a, b = cov @ (A.T @ (w * np.asarray(y)))
    return a, b, math.sqrt(cov[0, 0]), math.sqrt(cov[1, 1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--flow", choices=("couette", "fourier"), default="couette",
                    help="couette: the viscosity; fourier: the conductivity")
    ap.add_argument("--build", default="build", help="build directory with the roughgas binary")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--collisions", type=int, default=1000, help="collisions per particle of each run")
    ap.add_argument("--out", default=None, help="directory for the cases and runs (out/transport_errors_FLOW)")
    ap.add_argument("--plot", default=None, help="PNG to draw (e.g. docs/transport_errors.png)")
    ap.add_argument("--no-run", action="store_true", help="analyse the runs already in the output directory")
    a = ap.parse_args()
    out = a.out or os.path.join("out", "transport_errors_" + a.flow)
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.makedirs(out, exist_ok=True)
    cell_law, step_law = LAWS[a.flow]
    what = "eta / eta_CE" if a.flow == "couette" else "kappa / kappa_CE"
    results = []
    for k, (series, dy, s, partners, n, section, cells) in enumerate(runs(a.flow)):
        name = f"{series}_{k}"
        case = os.path.join(out, name + ".toml")
        if not a.no_run:
            with open(case, "w") as f:
                f.write(case_text(a.flow, n, section, cells, partners, s, a.collisions))
            p = subprocess.run([roughgas, "run", case, "--out", os.path.join(out, name), "--force", "--quiet",
                                "--threads", str(a.threads)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               text=True)
            if p.returncode != 0:
                sys.exit(f"transport_errors: {case} failed ({p.returncode}):\n{p.stderr}")
        ratio, err = transport(a.flow, os.path.join(out, name))
        per_cell = n / (cells[0] * cells[1] * cells[2])
        law = 1 + cell_law * dy ** 2 + step_law * s ** 2 if partners == "random" else float("nan")
        results.append((series, dy, s, partners, per_cell, ratio, err, law))
        print(f"{series:8s} dy = {dy:.3g} lambda, step {s} mean free times, {partners} partners, "
              f"{per_cell:.0f} per cell: {what} = {ratio:.4f} +- {err:.4f} (law {law:.4f})", flush=True)

    print("\n| series | cell edge along y [lambda] | step [mean free times] | partners | grains per cell "
          f"| {what.replace('eta', 'η').replace('kappa', 'κ')} | leading-order laws |")
    print("|---|---|---|---|---|---|---|")
    for series, dy, s, partners, per_cell, ratio, err, law in results:
        law_text = "-" if math.isnan(law) else f"{law:.4f}"
        print(f"| {series} | {dy:.3g} | {s} | {partners} | {per_cell:.0f} | {ratio:.4f} ± {err:.4f} | {law_text} |")
    for series, var, coefficient, label in (("cells", 1, cell_law, "(dy/lambda)^2"), ("steps", 2, step_law, "s^2")):
        rows = [r for r in results if r[0] == series]
        x = np.array([r[var] ** 2 for r in rows])
        a0, b, sa, sb = fit(x, [r[5] for r in rows], [r[6] for r in rows])
        print(f"{series}: {what} = {a0:.4f} (+- {sa:.4f}) + {b:.4f} (+- {sb:.4f}) {label}; "
              f"leading-order coefficient {coefficient:.4f}")
        if series == "cells":
            fine = [r for r in rows if r[1] <= 1.0]
            a0, b, sa, sb = fit(np.array([r[1] ** 2 for r in fine]), [r[5] for r in fine], [r[6] for r in fine])
            print(f"cells up to lambda: {what} = {a0:.4f} (+- {sa:.4f}) + {b:.4f} (+- {sb:.4f}) {label}")
    if a.plot:
        draw(a.flow, results, a.plot)


def draw(flow, results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cell_law, step_law = LAWS[flow]
    symbol = "η / η_CE" if flow == "couette" else "κ / κ_CE"
    cell_text = "16/(45π)" if flow == "couette" else "32/(225π)"
    step_text = "(4/75) s²" if flow == "couette" else "(8/225) s²"
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for series, style, label in (("cells", "o", "random partners"), ("nearest", "s", "nearest partners")):
        rows = [r for r in results if r[0] == series]
        if rows:
            left.errorbar([r[1] ** 2 for r in rows], [r[5] for r in rows], [r[6] for r in rows], fmt=style,
                          label=label, capsize=3)
    x = np.linspace(0, 4.2, 50)
    left.plot(x, 1 + cell_law * x + step_law * 0.04, "k--", lw=1, label=f"1 + {cell_text} (Δy/λ)²")
    left.set_xlabel("(Δy/λ)²: squared cell edge along the gradient")
    left.set_ylabel(symbol)
    left.set_title("cells (steps of 0.2 mean free times)")
    left.legend()
    for wide, style, label in ((False, "o", "random partners, Δy = λ/4"), (True, "s", "the same, 4 × the grains")):
        rows = [r for r in results if r[0] == "steps" and (r[4] > 1000) == wide]
        if rows:
            right.errorbar([r[2] ** 2 for r in rows], [r[5] for r in rows], [r[6] for r in rows], fmt=style,
                           label=label, capsize=3)
    x = np.linspace(0, 1.05, 50)
    right.plot(x, 1 + cell_law / 16 + step_law * x, "k--", lw=1, label=f"1 + {step_text}")
    right.set_xlabel("s²: squared step in mean free times")
    right.set_title("steps (cells of λ/4)")
    right.legend()
    if flow == "couette":
        fig.suptitle("Couette flow of elastic hard spheres, walls 20 λ apart: the DSMC's viscosity")
    else:
        fig.suptitle("Fourier flow of elastic hard spheres, walls 20 λ apart: the DSMC's conductivity")
    fig.tight_layout()
    save_figure(fig, path)


if __name__ == "__main__":
    main()
