#!/usr/bin/env python3
"""Cost of the spatially resolved solver per particle and step, on the DSMC reference deck.

    scripts/python3 scripts/bench_box.py [--build build] [--rounds 3] [--sizes 1e5,1e6] [--out out/bench_box]

The deck (the elastic hard-sphere gas of the usual DSMC benchmark): a periodic cube, cells of 0.42
mean free paths holding 20 grains on average, steps of half a mean free time
(domain.time_step = 0.5), 300 steps (150 collisions per particle), one output row at the end. For
each N: smooth grains on 1 thread, rough grains (alpha = 1, beta = 1: energy-conserving, with
spins) on 1 thread, smooth grains on 2 threads, smooth grains with nearest partners
(domain.partners) on 1 thread, and the ice grains of cases/hcs_brilliantov.toml (eps^N and eps^T
from cached tables, cooling: 120 steps, the case's 60 collisions per particle) on the same deck
on 1 thread. A round runs rough grains, smooth grains, 2 threads, nearest partners, smooth grains
again and ice grains, the order reversed every other round, for --rounds rounds: every ratio to
smooth grains on 1 thread takes the smooth run right before or after it, so that the two sides of
a ratio run within a minute of each other and a drift of the machine's speed hits both alike.
Reported per variant: the median and range of the wall time per particle and step (ns, smooth
grains over both of their runs per round), and of the ratios rough/smooth, 1 thread/2 threads,
nearest/random partners and brilliantov/smooth (one per round, its two sides adjacent), twice:
for whole runs (the process's start and the initial state included, which the ice deck's 120
steps share out less than the others' 300), and for the steps alone: each variant also runs its
first SHORT_STEPS steps right after its whole run, and the difference of the two runs' times is
the cost of the steps beyond them, the start cancelled. The machine, date, commit and load are
printed with the tables (docs/performance.md).
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import box_deck, cpu_times, loadavg, machine, measured_line, timed  # noqa: E402

STEPS = 300
TIME_STEP = 0.5
ICE_STEPS = 120
SHORT_STEPS = 10  # the short run that cancels the start in the steps-alone figures


def deck(n, rough, partners="random"):
    """The case text for n grains: cells of 0.42 mean free paths with 20 grains each."""
    return box_deck(n, STEPS * TIME_STEP, STEPS * TIME_STEP, TIME_STEP, 1.0 if rough else -1.0, partners)


def brilliantov_deck(n, cache_file):
    """cases/hcs_brilliantov.toml (ice grains, eps^N and eps^T from their tables) on the same deck:
    cells of 0.42 mean free paths at its density and diameter, 20 grains each, steps of half a mean
    free time of the cooling gas, but ICE_STEPS of them (the case's 60 collisions per particle: the
    gas cools by eight decades, and further on its slowest impacts would leave the tables' range for
    direct integration); the tables from `cache_file`."""
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cases", "hcs_brilliantov.toml")) as f:
        text = f.read()
    values = {"particles": str(n), "end": str(ICE_STEPS * TIME_STEP), "output_every": str(ICE_STEPS * TIME_STEP),
              "output_spacing": '"linear"', "cache_file": f'"{cache_file}"'}
    lines, section = [], ""
    for line in text.splitlines():
        if line.startswith("["):
            section = line.split("]")[0].strip("[")
        key = f"{section}.{line.split('=')[0].strip()}"
        values_key = key.split(".", 1)[1] if key.split(".", 1)[0] in ("run", "contact") else None
        replace = "=" in line and values_key in values and (values_key != "end" or section == "run")
        lines.append(f"{values_key} = {values[values_key]}" if replace else line)
    density, radius = 1000.0, 0.01  # the case's run.density and species radius
    lam = 1.0 / (2 ** 0.5 * 3.141592653589793 * density * (2 * radius) ** 2)
    cells = max(1, round((n / 20) ** (1 / 3)))
    side = cells * 0.42 * lam
    return ("\n".join(lines) + f"\n\n[domain]\nsize = [{side}, {side}, {side}]\n"
            f"cells = [{cells}, {cells}, {cells}]\ntime_step = {TIME_STEP}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--sizes", default="1e5,1e6", help="particle numbers, comma-separated")
    ap.add_argument("--out", default="out/bench_box")
    a = ap.parse_args()
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.makedirs(a.out, exist_ok=True)
    print(machine(), file=sys.stderr)
    load0, steal0 = loadavg(), cpu_times()
    rows, rows_steps = [], []
    for n in (int(float(x)) for x in a.sizes.split(",")):
        cases = {}
        for rough in (False, True):
            path = os.path.join(a.out, f"deck_{n}_{'rough' if rough else 'smooth'}.toml")
            with open(path, "w") as f:
                f.write(deck(n, rough))
            cases[rough] = path
        nearest = os.path.join(a.out, f"deck_{n}_nearest.toml")
        with open(nearest, "w") as f:
            f.write(deck(n, False, "nearest"))
        ice = os.path.join(a.out, f"deck_{n}_brilliantov.toml")
        with open(ice, "w") as f:
            f.write(brilliantov_deck(n, os.path.abspath(os.path.join(a.out, "ice_tables.bin"))))
        timed([roughgas, "run", ice, "--out", os.path.join(a.out, "run"), "--force", "--quiet", "--threads", "2",
               "--set", "run.particles=2000"], "bench_box")  # builds the tables' cache file: the timed runs load it
        # Each ratio's sides run next to each other: the smooth runs at positions 1 and 4 are the
        # partners of rough grains and 2 threads, and of nearest partners and ice grains.
        smooth = ("smooth, 1 thread", cases[False], "1")
        variants = [("rough, 1 thread", cases[True], "1"), smooth, ("smooth, 2 threads", cases[False], "2"),
                    ("smooth, nearest, 1 thread", nearest, "1"), smooth, ("brilliantov, 1 thread", ice, "1")]
        partner = {0: 1, 2: 1, 3: 4, 5: 4}  # a variant's position: its smooth run's
        times = {v[0]: [] for v in variants}
        steps_alone = {v[0]: [] for v in variants}
        ratios = {name: [] for name in RATIOS}
        ratios_steps = {name: [] for name in RATIOS}
        short = [f"run.end={SHORT_STEPS * TIME_STEP}", f"run.output_every={SHORT_STEPS * TIME_STEP}"]
        for r in range(a.rounds):
            order = list(range(len(variants))) if r % 2 == 0 else list(range(len(variants)))[::-1]
            whole, alone = {}, {}
            for k in order:
                name, case, threads = variants[k]
                run = [roughgas, "run", case, "--out", os.path.join(a.out, "run"), "--force", "--quiet",
                       "--threads", threads]
                steps = ICE_STEPS if case == ice else STEPS
                t = timed(run, "bench_box")
                t_short = timed(run + [arg for s in short for arg in ("--set", s)], "bench_box")
                whole[k] = t / (n * steps) * 1e9
                alone[k] = (t - t_short) / (n * (steps - SHORT_STEPS)) * 1e9
                times[name].append(whole[k])
                steps_alone[name].append(alone[k])
                print(f"  N = {n:.0e}, {name}, round {r + 1}: {whole[k]:.1f} ns, steps alone {alone[k]:.1f} ns",
                      file=sys.stderr)
            for k, k_smooth in partner.items():
                name = RATIO_OF[variants[k][0]]
                # 1 thread/2 threads is the smooth run over the 2-thread one; the others, the variant over smooth
                flip = variants[k][2] == "2"
                for store, ns in ((ratios, whole), (ratios_steps, alone)):
                    store[name].append(ns[k_smooth] / ns[k] if flip else ns[k] / ns[k_smooth])
        for table, ns, rs in ((rows, times, ratios), (rows_steps, steps_alone, ratios_steps)):
            table.append(row(n, ns, rs))
    print(measured_line(a.rounds, "wall ns per particle and step (whole runs: start, initial state, 300 "
                                  "steps, one row): median (min-max)", load0, steal0))
    for title, table in (("whole runs", rows), (f"the steps alone (whole runs less their first {SHORT_STEPS} "
                                                f"steps)", rows_steps)):
        print(f"\n{title}:\n")
        print("| N | smooth, 1 thread | rough, 1 thread | smooth, 2 threads | rough/smooth | 1 thread/2 threads "
              "| nearest/random partners | brilliantov, 1 thread | brilliantov/smooth |")
        print("|---|---|---|---|---|---|---|---|---|")
        for r in table:
            print(r)


RATIOS = ("rough/smooth", "1 thread/2 threads", "nearest/random partners", "brilliantov/smooth")
RATIO_OF = {"rough, 1 thread": "rough/smooth", "smooth, 2 threads": "1 thread/2 threads",
            "smooth, nearest, 1 thread": "nearest/random partners", "brilliantov, 1 thread": "brilliantov/smooth"}


def row(n, times, ratios):
    """A table row: the variants' ns per particle and step and their ratios, medians and ranges."""
    def fmt(x):
        return f"{statistics.median(x):.1f} ({min(x):.1f}-{max(x):.1f})"

    def ratio(name):
        rs = ratios[name]
        return f"{statistics.median(rs):.2f} ({min(rs):.2f}-{max(rs):.2f})"
    return (f"| {n:.0e} | {fmt(times['smooth, 1 thread'])} | {fmt(times['rough, 1 thread'])} | "
            f"{fmt(times['smooth, 2 threads'])} | {ratio('rough/smooth')} | {ratio('1 thread/2 threads')} | "
            f"{ratio('nearest/random partners')} | {fmt(times['brilliantov, 1 thread'])} | "
            f"{ratio('brilliantov/smooth')} |")


if __name__ == "__main__":
    main()
