#!/usr/bin/env python3
"""What spectra.csv, modes.csv and the cell fields cost a box run, at an output row per collision per
particle.

    scripts/python3 scripts/bench_spectra.py [--build build] [--rounds 5] [--sizes 1e5,1e6] [--out out/bench_spectra]

The deck: an elastic hard-sphere gas in a periodic cube, cells of 0.42 mean free paths holding 20
grains (the DSMC reference deck of bench_box.py), steps of 0.2 mean free times (the default), 30
collisions per particle with a row after each (150 steps, 31 rows), one thread. The same case is
run without either, with [spectra] (spectra.modes = 3), with [spectra] and [fields] at their
defaults (every quantity of every cell at every row, an HDF5 file per row), and with [spectra] and
the fields n, u, T_tr at every fifth row (as cases/box_cooling_slab.toml writes them), in turn for
--rounds rounds (the order rotated every round, so that a drift of the machine's speed hits all alike).
Reported: the median and range of the wall time per particle and step of each, and of the ratios
to the run without, of the wall times and of the processes' CPU times (the fields are written on a
thread of their own, behind the run: the wall time shows what the user waits for, the CPU time
what the writing costs a machine whose cores are all busy) (docs/performance.md). The machine,
date, commit and load are printed with the table.
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import box_deck, cpu_times, loadavg, machine, measured_line, run_roughgas  # noqa: E402

END = 30.0              # collisions per particle, a row after each
TIME_STEP = 0.2
STEPS = round(END / TIME_STEP)


SPECTRA = "\n[spectra]\nmodes = 3\n"
VARIANTS = {"plain": "", "spectra": SPECTRA, "fields": SPECTRA + "\n[fields]\n",
            "some_fields": SPECTRA + "\n[fields]\nquantities = [\"n\", \"u\", \"T_tr\"]\nevery = 5\n"}


def deck(n, variant):
    """The case text for n grains: cells of 0.42 mean free paths with 20 grains each."""
    return box_deck(n, END, 1.0, TIME_STEP, extra=VARIANTS[variant])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--sizes", default="1e5,1e6", help="particle numbers, comma-separated")
    ap.add_argument("--out", default="out/bench_spectra")
    a = ap.parse_args()
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.makedirs(a.out, exist_ok=True)
    print(machine(), file=sys.stderr)
    load0, steal0 = loadavg(), cpu_times()
    rows = []
    for n in (int(float(x)) for x in a.sizes.split(",")):
        cases = {}
        for variant in VARIANTS:
            path = os.path.join(a.out, f"deck_{n}_{variant}.toml")
            with open(path, "w") as f:
                f.write(deck(n, variant))
            cases[variant] = path
        names = list(VARIANTS)
        times = {v: [] for v in names}
        cpu = {v: [] for v in names}
        for r in range(a.rounds):
            for variant in names[r % len(names):] + names[:r % len(names)]:
                try:
                    res = run_roughgas(roughgas, cases[variant], os.path.join(a.out, "run"))
                except RuntimeError as e:
                    sys.exit(f"bench_spectra: {e}")
                times[variant].append(res["process_seconds"] / (n * STEPS) * 1e9)
                cpu[variant].append(res["cpu_seconds"] / (n * STEPS) * 1e9)
                print(f"  N = {n:.0e}, {variant}, round {r + 1}: {times[variant][-1]:.1f} ns wall, "
                      f"{cpu[variant][-1]:.1f} ns CPU", file=sys.stderr)

        def fmt(x, digits=1):
            return f"{statistics.median(x):.{digits}f} ({min(x):.{digits}f}-{max(x):.{digits}f})"
        cells = max(1, round((n / 20) ** (1 / 3)))
        ratios = {v: [y / x for x, y in zip(times["plain"], times[v])] for v in names[1:]}
        cpu_ratios = {v: [y / x for x, y in zip(cpu["plain"], cpu[v])] for v in names[1:]}
        rows.append(f"| {n:.0e} | {cells}^3 | " + " | ".join(fmt(times[v]) for v in names) + " | " +
                    " | ".join(fmt(ratios[v], 3) for v in names[1:]) + " | " +
                    " | ".join(fmt(cpu_ratios[v], 3) for v in names[1:]) + " |")
    print(measured_line(a.rounds, f"wall ns per particle and step (whole runs: start, initial state, {STEPS} "
                                  f"steps, {round(END) + 1} rows), one thread: median (min-max)", load0, steal0))
    print("| N | cells | without | spectra | spectra, fields | spectra, n u T_tr every 5th row | spectra/without "
          "| spectra, fields/without | spectra, n u T_tr every 5th row/without | CPU: spectra/without "
          "| CPU: spectra, fields/without | CPU: spectra, n u T_tr every 5th row/without |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(r)


if __name__ == "__main__":
    main()
