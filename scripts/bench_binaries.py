#!/usr/bin/env python3
"""Wall time of two roughgas binaries on the same runs, alternating: is a change free of slowdown?

    scripts/python3 scripts/bench_binaries.py --old OLD_BINARY --new NEW_BINARY [--rounds 5] [--out DIR]

Three decks, each run by both binaries in every round (OLD then NEW, the order reversed every other
round, so that a drift of the machine's speed hits both sides of a ratio alike):
  homogeneous  a rough gas (alpha 0.9, beta 0.5) of 10^6 grains cooling to 20 collisions per
               particle, rows every collision per particle, 1 thread;
  replicas     the same gas, 4 replicas of 2.5 * 10^5 grains on 2 threads, rows every 0.2 collisions
               per particle (the rows, their combination and the files' rewrites weigh most here);
  box          the DSMC reference deck of bench_box.py (an elastic smooth gas, cells of 0.42 mean
               free paths holding 20 grains) with 10^6 grains, 100 steps of half a mean free time,
               a row every 10 steps, 1 thread.
Reported per deck: the median and range of each binary's wall time (the whole process) and of the
ratio NEW/OLD, one per round. The machine, date, commit and load are printed with the table
(docs/performance.md).
"""
import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import box_deck, cpu_times, loadavg, measured_line, rough_case, timed  # noqa: E402

DECKS = {
    "homogeneous": (lambda: rough_case(1000000, 20, 1), 1),
    "replicas": (lambda: rough_case(250000, 20, 0.2, replicas=4), 2),
    "box": (lambda: box_deck(1000000, 50.0, 5.0, 0.5), 1),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--old", required=True, help="the binary before the change")
    ap.add_argument("--new", required=True, help="the binary after the change")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--decks", default=",".join(DECKS), help="comma-separated: " + ", ".join(DECKS))
    ap.add_argument("--out", default=None, help="scratch directory (default: a temporary one)")
    a = ap.parse_args()
    decks = [d for d in a.decks.split(",") if d]
    for d in decks:
        if d not in DECKS:
            ap.error(f"--decks: unknown deck {d!r} (one of {', '.join(DECKS)})")
    for b in (a.old, a.new):
        if not os.access(b, os.X_OK):
            ap.error(f"{b}: not an executable")
    out = a.out or tempfile.mkdtemp(prefix="bench_binaries.")
    os.makedirs(out, exist_ok=True)
    load0, steal0 = loadavg(), cpu_times()
    times = {d: {"old": [], "new": []} for d in decks}
    for r in range(a.rounds):
        for d in decks:
            text, threads = DECKS[d]
            case = os.path.join(out, f"{d}.toml")
            with open(case, "w") as f:
                f.write(text())
            order = ("old", "new") if r % 2 == 0 else ("new", "old")
            for side in order:
                binary = a.old if side == "old" else a.new
                cmd = [binary, "run", case, "--out", os.path.join(out, f"{d}_{side}"), "--force", "--quiet",
                       "--threads", str(threads)]
                times[d][side].append(timed(cmd, "bench_binaries.py"))
        print(f"round {r + 1} of {a.rounds} done", file=sys.stderr)
    print(measured_line(a.rounds, f"old {a.old}, new {a.new}", load0, steal0))
    print()
    print("| deck | old (s) | new (s) | new/old |")
    print("|---|---|---|---|")
    for d in decks:
        old, new = times[d]["old"], times[d]["new"]
        ratios = [n / o for n, o in zip(new, old)]

        def cell(x, digits):
            return f"{statistics.median(x):.{digits}f} ({min(x):.{digits}f}–{max(x):.{digits}f})"
        print(f"| {d} | {cell(old, 2)} | {cell(new, 2)} | {cell(ratios, 3)} |")


if __name__ == "__main__":
    main()
