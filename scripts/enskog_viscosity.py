#!/usr/bin/env python3
"""The shear viscosity of elastic hard spheres in Couette flow of the Enskog box, against Enskog theory.

usage: scripts/python3 scripts/enskog_viscosity.py RUN_DIR [RUN_DIR ...] [--from C] [--margin L] [--batches K]
       scripts/python3 scripts/enskog_viscosity.py --wave RUN_DIR [RUN_DIR ...] [--from C] [--to C]
       scripts/python3 scripts/enskog_viscosity.py --theory PHI [PHI ...]

RUN_DIR is a box run (run.equation = "enskog" or the Boltzmann equation) of one species of elastic
smooth hard spheres between two diffuse walls normal to y moving along x (cases/box_couette_enskog.toml),
with profiles.csv along y and walls.csv. Over the rows from C collisions per particle on (--from,
default 100), in K batches of consecutive rows (--batches, default 10):
  P_xy      the walls' momentum flux, the mean of walls.csv's y_lower.P_xy and y_upper.P_xy;
  du_x/dy   the least-squares slope of profiles.csv's u_x over the bulk, the slabs centred more than
            L diameters from either wall (--margin, default 4);
  eta       -P_xy/(du_x/dy), at the bulk's mean density n_b and temperature T_b;
  balance   the profiles' total P_xy (kinetic P_xy + collisional Pc_xy) of every slab against the
            walls': its bulk mean minus the walls' over |P_xy|, the same for the two slabs touching
            the walls, and the largest deviation of one of the other slabs (those within L of the
            walls included) over its error (batch means); and the largest relative deviation of a
            slab's total P_yy from the walls' P_yy.
Errors: the standard error of the batch means. Theory: Enskog's viscosity at phi_b = (pi/6) n_b
sigma^3 and Carnahan & Starling's chi, in units of eta_0 = (5/(16 sigma^2)) sqrt(m T_b/pi):
  first Sonine   eta_1/eta_0 = (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi,
  Chapman-Enskog eta_CE/eta_0 = 1.016034 (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi
(Chapman & Cowling 1970, section 16.41: the higher Sonine orders multiply the kinetic-type part by
the dilute gas's 1.016034 and leave the bulk-like collisional part). Prints one line per run:
phi_b, cells along y and their edge, grains per cell, eta/eta_0 with its error, both theories,
eta/eta_CE, the balance, and eta over eta_CE plus the DSMC's cell-size excess
16/(45 pi) (chi dy/lambda)^2 eta_0, lambda = 1/(sqrt(2) pi n sigma^2) (the Boltzmann cells' law of
Alexander, Garcia & Alder 1998 at the Enskog collision frequency; docs/validation.md, "The Enskog
equation in a box", measures it).

--wave: RUN_DIR is a periodic box with a transverse wave along x ([initial] mode = "transverse",
wave = [1, 0, 0]; cases/box_viscosity_wave.toml with run.equation = "enskog"): each replica's decay
rate of moments.csv's u_wave (replicas/moments_R.csv), least squares on its logarithm over the rows
from C (--from) to C (--to, default the run's end) collisions per particle, gives eta = rate n m/k^2
in units of eta_0 at the window's thermal temperature (T_tr less the wave's m u_wave^2/6); the error
is the replicas' scatter. Theory at the box's phi, the cell edge the one along x.

--theory PHI...: prints chi, eta_1/eta_0 and eta_CE/eta_0 at the given solid fractions.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header, replica_column  # noqa: E402

SONINE_FACTOR = 1.016034


def chi_cs(phi):
    """Carnahan & Starling's contact value (1 - phi/2)/(1 - phi)^3."""
    return (1 - phi / 2) / (1 - phi) ** 3


def enskog_eta(phi, converged):
    """Enskog's shear viscosity over eta_0: first Sonine, or with the kinetic part's 1.016034."""
    chi = chi_cs(phi)
    kinetic = (1 + 1.6 * phi * chi) ** 2 / chi
    return (SONINE_FACTOR if converged else 1.0) * kinetic + 768 / (25 * math.pi) * phi ** 2 * chi


def cell_law(phi, edge):
    """The DSMC's cell-size excess over eta_0 for cells of `edge` diameters along the gradient:
    16/(45 pi) (chi edge/lambda)^2, lambda = 1/(sqrt(2) pi n sigma^2) (Alexander, Garcia & Alder 1998,
    with the Enskog collision frequency)."""
    lam = 1 / (math.sqrt(2) * math.pi * 6 * phi / math.pi)
    return 16 / (45 * math.pi) * (chi_cs(phi) * edge / lam) ** 2


def analyse(run_dir, start, margin, batches):
    prof_path, walls_path = os.path.join(run_dir, "profiles.csv"), os.path.join(run_dir, "walls.csv")
    case = read_header(prof_path)["resolved"]
    species = case["species"][0]
    m, sigma = float(species.get("mass", 1.0)), 2 * float(species["radius"])
    domain = case["domain"]
    L, cells = float(domain["size"][1]), int(domain["cells"][1])
    grains = int(case["run"]["particles"])
    prof, walls = read_csv(prof_path), read_csv(walls_path)
    bins = int(prof["bin"].max()) + 1
    rows = len(walls["t"])
    if bins != cells or len(prof["t"]) != rows * bins:
        sys.exit(f"{run_dir}: profiles.csv does not hold {cells} slabs per row of walls.csv")
    cpp = walls["coll_per_particle"]
    inside = np.zeros(rows, bool)
    inside[1:] = cpp[:-1] >= start - 1e-9  # the interval since the previous row lies in the window
    idx = np.nonzero(inside)[0]
    y = prof["y"][:bins]
    field = {f: prof[f].reshape(rows, bins) for f in ("n", "u_x", "T_tr", "P_xy", "Pc_xy", "P_yy", "Pc_yy")}
    bulk = (y > margin * sigma) & (y < L - margin * sigma)
    per = []
    for block in np.array_split(idx, batches):
        wall = 0.5 * (walls["y_lower.P_xy"][block] + walls["y_upper.P_xy"][block]).mean()
        u = field["u_x"][block].mean(axis=0)
        slope = np.polyfit(y[bulk], u[bulk], 1)[0]
        nb, Tb = field["n"][block][:, bulk].mean(), field["T_tr"][block][:, bulk].mean()
        total = (field["P_xy"][block] + field["Pc_xy"][block]).mean(axis=0)
        eta0 = 5 / (16 * sigma ** 2) * math.sqrt(m * Tb / math.pi)
        edge = 0.5 * (total[0] + total[-1])
        per.append([-wall / slope / eta0, nb, Tb, wall, (total[bulk].mean() - wall) / abs(wall),
                    (edge - wall) / abs(wall)] + list(total))
    per = np.array(per)
    mean = per.mean(axis=0)
    err = per.std(axis=0, ddof=1) / math.sqrt(len(per))
    phi = math.pi / 6 * mean[1] * sigma ** 3
    total, total_err = mean[6:], err[6:]
    worst = np.max((np.abs(total - mean[3]) / np.hypot(total_err, err[3]))[1:-1])
    normal = (field["P_yy"][idx] + field["Pc_yy"][idx]).mean(axis=0)
    wall_yy = 0.5 * (walls["y_lower.P_yy"][idx] + walls["y_upper.P_yy"][idx]).mean()
    return {
        "phi": phi, "cells": cells, "dy": L / cells / sigma,
        "per_cell": grains / (cells * int(domain["cells"][0]) * int(domain["cells"][2])),
        "eta": mean[0], "eta_err": err[0], "T": mean[2], "P_xy": mean[3], "P_xy_err": err[3],
        "balance": mean[4], "balance_err": err[4], "worst": worst, "normal": np.max(np.abs(normal / wall_yy - 1)), "edge": mean[5], "edge_err": err[5],
        "eta_1": enskog_eta(phi, False), "eta_CE": enskog_eta(phi, True),
        "law": enskog_eta(phi, True) + cell_law(phi, L / cells / sigma),
    }


def analyse_wave(run_dir, start, end):
    """A periodic box with a transverse wave along x ([initial] mode = "transverse", wave = [1, 0, 0]):
    each replica's decay rate of moments.csv's u_wave, least squares on its logarithm over the rows
    from `start` to `end` collisions per particle, over eta k^2/(n m) with eta the theory's at the
    box's phi and the thermal temperature's mean over the window (T_tr less the wave's m u^2/6)."""
    path = os.path.join(run_dir, "moments.csv")
    case = read_header(path)["resolved"]
    species = case["species"][0]
    m, sigma = float(species.get("mass", 1.0)), 2 * float(species["radius"])
    n = float(case["run"]["density"])
    Lx = float(case["domain"]["size"][0])
    k = 2 * math.pi / Lx
    d = read_csv(path)
    sel = (d["coll_per_particle"] >= start - 1e-9) & (d["coll_per_particle"] <= end + 1e-9)
    curves = replica_column(path, "u_wave", len(d["t"]))
    temps = replica_column(path, "T_tr", len(d["t"]))
    if curves is None:
        curves, temps = d["u_wave"][:, None], d["T_tr"][:, None]
    t = d["t"][sel]
    rates = []
    for r in range(curves.shape[1]):
        u, T = curves[sel, r], temps[sel, r]
        rate = -np.polyfit(t, np.log(u), 1)[0]
        Tw = np.mean(T - m * u ** 2 / 6)
        eta0 = 5 / (16 * sigma ** 2) * math.sqrt(m * Tw / math.pi)
        rates.append(rate * n * m / (k ** 2 * eta0))  # eta/eta_0 from the rate
    rates = np.array(rates)
    phi = math.pi / 6 * n * sigma ** 3
    err = rates.std(ddof=1) / math.sqrt(len(rates)) if len(rates) > 1 else float("nan")
    return {"phi": phi, "cells": int(case["domain"]["cells"][0]), "dx": Lx / int(case["domain"]["cells"][0]) / sigma,
            "per_cell": int(case["run"]["particles"]) / np.prod([int(c) for c in case["domain"]["cells"]]),
            "k_sigma": k * sigma, "eta": rates.mean(), "eta_err": err, "R": len(rates),
            "eta_1": enskog_eta(phi, False), "eta_CE": enskog_eta(phi, True),
            "law": enskog_eta(phi, True) + cell_law(phi, Lx / int(case["domain"]["cells"][0]) / sigma)}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir", nargs="*")
    parser.add_argument("--from", dest="start", type=float, default=100.0)
    parser.add_argument("--margin", type=float, default=4.0)
    parser.add_argument("--batches", type=int, default=10)
    parser.add_argument("--to", dest="end", type=float, default=1e300)
    parser.add_argument("--wave", action="store_true")
    parser.add_argument("--theory", type=float, nargs="+")
    args = parser.parse_args(argv[1:])
    if args.theory:
        for phi in args.theory:
            print(f"phi {phi:g}: chi {chi_cs(phi):.6f}, eta_1/eta_0 {enskog_eta(phi, False):.5f}, "
                  f"eta_CE/eta_0 {enskog_eta(phi, True):.5f}")
        return 0
    if not args.run_dir:
        parser.error("RUN_DIR is required (or --theory)")
    if args.wave:
        print("run | phi | cells along x (dx/sigma) | grains/cell | k sigma | replicas | eta/eta_0 | eta_1 | eta_CE | "
              "eta/eta_CE | eta_CE + cell law | eta/(eta_CE + cell law)")
        for run_dir in args.run_dir:
            r = analyse_wave(run_dir, args.start, args.end)
            print(f"{run_dir} | {r['phi']:.4f} | {r['cells']} ({r['dx']:.3g}) | {r['per_cell']:.0f} | "
                  f"{r['k_sigma']:.4f} | {r['R']} | {r['eta']:.4f} +- {r['eta_err']:.4f} | {r['eta_1']:.4f} | "
                  f"{r['eta_CE']:.4f} | {r['eta'] / r['eta_CE']:.4f} +- {r['eta_err'] / r['eta_CE']:.4f} | {r['law']:.4f} | "
                  f"{r['eta'] / r['law']:.4f} +- {r['eta_err'] / r['law']:.4f}")
        return 0
    print("run | phi_b | cells (dy/sigma) | grains/cell | T_b | eta/eta_0 | eta_1 | eta_CE | eta/eta_CE | "
          "(bulk - wall) P_xy/|P_xy| | (wall slabs - wall) P_xy/|P_xy| | max dev of another slab [errors] | "
          "max |P_yy/P_yy,walls - 1| | eta_CE + cell law | eta/(eta_CE + cell law)")
    for run_dir in args.run_dir:
        r = analyse(run_dir, args.start, args.margin, args.batches)
        print(f"{run_dir} | {r['phi']:.4f} | {r['cells']} ({r['dy']:.3g}) | {r['per_cell']:.0f} | {r['T']:.4f} | "
              f"{r['eta']:.4f} +- {r['eta_err']:.4f} | {r['eta_1']:.4f} | {r['eta_CE']:.4f} | "
              f"{r['eta'] / r['eta_CE']:.4f} +- {r['eta_err'] / r['eta_CE']:.4f} | "
              f"{r['balance']:+.4f} +- {r['balance_err']:.4f} | {r['edge']:+.4f} +- {r['edge_err']:.4f} | {r['worst']:.1f} | {r['normal']:.4f} | {r['law']:.4f} | "
              f"{r['eta'] / r['law']:.4f} +- {r['eta_err'] / r['law']:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
