#!/usr/bin/env python3
"""Collisions per second of the Enskog equation against the Boltzmann equation, homogeneous gas.

    scripts/python3 scripts/bench_enskog.py [--build build] [--rounds 5] [--particles 1000000] [--out out/bench_enskog]

The gas: rough grains (alpha = 0.9, beta = 0.5) of unit diameter at the solid fraction phi = 0.25
(run.density = 0.4775), N particles, 10 collisions per particle, one thread, run with
`run.equation = "boltzmann"` and with `"enskog"` (Carnahan & Starling's chi = 2.07) alternately,
the order reversed every other round, so that the two sides of each round's ratio run within
seconds of each other and a drift of the machine's speed hits both alike. Reported: the median
and range of each equation's collisions per second (from the run's own "collisions in ... s") and
of the ratio Enskog/Boltzmann within a round, with the machine, date, commit and load
(docs/performance.md).
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import cpu_times, loadavg, measured_line, rough_case, run_roughgas  # noqa: E402

END = 10.0
DENSITY = 0.4775  # phi = 0.25 at sigma = 1


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default="build", help="build directory holding the roughgas binary (default: build)")
    p.add_argument("--rounds", type=int, default=5, help="rounds, each one run per equation (default: 5)")
    p.add_argument("--particles", type=float, default=1e6, help="particles per run (default: 1e6)")
    p.add_argument("--out", default="out/bench_enskog", help="scratch directory for the cases and runs")
    a = p.parse_args()
    roughgas = os.path.join(a.build, "roughgas")
    n = int(a.particles)
    os.makedirs(a.out, exist_ok=True)
    case = os.path.join(a.out, "case.toml")
    with open(case, "w") as f:
        f.write(rough_case(n, END, END))
    collisions = n * END / 2
    load0, steal0 = loadavg(), cpu_times()
    rate = {"boltzmann": [], "enskog": []}
    ratio = []
    for r in range(a.rounds):
        order = ["boltzmann", "enskog"] if r % 2 == 0 else ["enskog", "boltzmann"]
        got = {}
        for eq in order:
            res = run_roughgas(roughgas, case, os.path.join(a.out, eq),
                               sets=[f"run.density={DENSITY}", f'run.equation="{eq}"'])
            got[eq] = collisions / res["seconds"]
            rate[eq].append(got[eq])
        ratio.append(got["enskog"] / got["boltzmann"])
    print(measured_line(a.rounds, f"N = {n:g}, 1 thread, rough alpha = 0.9, beta = 0.5, phi = 0.25", load0, steal0))
    print("| equation | collisions per second, median (range) | Enskog/Boltzmann within a round, median (range) |")
    print("|----------|----------------------------------------|---------------------------------------------------|")
    for eq in ("boltzmann", "enskog"):
        x = rate[eq]
        line = f"| {eq} | {statistics.median(x):.3g} ({min(x):.3g}–{max(x):.3g}) |"
        line += f" **{statistics.median(ratio):.3f}** ({min(ratio):.3f}–{max(ratio):.3f}) |" if eq == "enskog" else " |"
        print(line)


if __name__ == "__main__":
    main()
