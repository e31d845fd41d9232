#!/usr/bin/env python3
"""Collisions per second of the Enskog equation against the Boltzmann equation, homogeneous gas or box.

    scripts/python3 scripts/bench_enskog.py [--build build] [--rounds 5] [--particles 1000000] [--out out/bench_enskog]
    scripts/python3 scripts/bench_enskog.py --box [--cell-edge 0.42] [--rounds 3] [--particles 1000000]

The gas: rough grains (alpha = 0.9, beta = 0.5) of unit diameter at the solid fraction phi = 0.25
(run.density = 0.4775), N particles, 10 collisions per particle, one thread, run with
`run.equation = "boltzmann"` and with `"enskog"` (Carnahan & Starling's chi = 2.07) alternately,
the order reversed every other round, so that the two sides of each round's ratio run within
seconds of each other and a drift of the machine's speed hits both alike. Reported: the median
and range of each equation's collisions per second (from the run's own "collisions in ... s") and
of the ratio Enskog/Boltzmann within a round, with the machine, date, commit and load
(docs/performance.md).

With --box: the box deck of bench_box.py at the solid fraction phi = 0.2 (run.density = 0.382,
sigma = 1): elastic smooth spheres in a periodic cube, cells of --cell-edge mean free paths
1/(sqrt(2) pi n sigma^2) holding 20 grains each (0.42: edges of 0.25 sigma, so that a partner a
diameter away is four cells off), steps of half a mean free time, 10 collisions per particle; the
same ratio per collision (the Enskog gas collides chi = 1.758 times as often per unit time, and its
steps are as many mean free times).
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import cpu_times, loadavg, measured_line, rough_case, run_roughgas  # noqa: E402

END = 10.0
DENSITY = 0.4775  # phi = 0.25 at sigma = 1
BOX_DENSITY = 0.3819718634  # phi = 0.2 at sigma = 1


def box_case(n, cell_edge):
    """The box deck at phi = 0.2: n grains, 20 per cell, cells of `cell_edge` mean free paths."""
    lam = 1.0 / (2 ** 0.5 * 3.141592653589793 * BOX_DENSITY)
    cells = max(1, round((n / 20) ** (1 / 3)))
    side = cells * cell_edge * lam
    return (f"[run]\nparticles = {n}\nend = {END}\noutput_every = {END}\ndensity = {BOX_DENSITY}\nseed = 1\n\n"
            f"[[species]]\nmass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\nalpha = 1.0\nbeta = -1.0\n\n"
            f"[domain]\nsize = [{side}, {side}, {side}]\ncells = [{cells}, {cells}, {cells}]\ntime_step = 0.5\n"
            f"allow_coarse = true\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default="build", help="build directory holding the roughgas binary (default: build)")
    p.add_argument("--rounds", type=int, default=5, help="rounds, each one run per equation (default: 5)")
    p.add_argument("--particles", type=float, default=1e6, help="particles per run (default: 1e6)")
    p.add_argument("--out", default="out/bench_enskog", help="scratch directory for the cases and runs")
    p.add_argument("--box", action="store_true", help="the box deck at phi = 0.2 instead of the homogeneous gas")
    p.add_argument("--cell-edge", type=float, default=0.42,
                   help="with --box: the cells' edge in mean free paths (default: 0.42, as bench_box.py)")
    a = p.parse_args()
    roughgas = os.path.join(a.build, "roughgas")
    n = int(a.particles)
    os.makedirs(a.out, exist_ok=True)
    case = os.path.join(a.out, "case.toml")
    with open(case, "w") as f:
        f.write(box_case(n, a.cell_edge) if a.box else rough_case(n, END, END))
    density = BOX_DENSITY if a.box else DENSITY
    collisions = n * END / 2
    load0, steal0 = loadavg(), cpu_times()
    rate = {"boltzmann": [], "enskog": []}
    ratio = []
    for r in range(a.rounds):
        order = ["boltzmann", "enskog"] if r % 2 == 0 else ["enskog", "boltzmann"]
        got = {}
        for eq in order:
            res = run_roughgas(roughgas, case, os.path.join(a.out, eq),
                               sets=[f"run.density={density}", f'run.equation="{eq}"'])
            got[eq] = collisions / res["seconds"]
            rate[eq].append(got[eq])
        ratio.append(got["enskog"] / got["boltzmann"])
    what = (f"N = {n:g}, 1 thread, box of elastic smooth spheres, phi = 0.2, cells of {a.cell_edge} mean free paths "
            f"holding 20 grains" if a.box else f"N = {n:g}, 1 thread, rough alpha = 0.9, beta = 0.5, phi = 0.25")
    print(measured_line(a.rounds, what, load0, steal0))
    print("| equation | collisions per second, median (range) | Enskog/Boltzmann within a round, median (range) |")
    print("|----------|----------------------------------------|---------------------------------------------------|")
    for eq in ("boltzmann", "enskog"):
        x = rate[eq]
        line = f"| {eq} | {statistics.median(x):.3g} ({min(x):.3g}–{max(x):.3g}) |"
        line += f" **{statistics.median(ratio):.3f}** ({min(ratio):.3f}–{max(ratio):.3f}) |" if eq == "enskog" else " |"
        print(line)


if __name__ == "__main__":
    main()
