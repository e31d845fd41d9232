#!/usr/bin/env python3
"""The speed targets of issue 5, each with a confidence interval.

    scripts/python3 scripts/bench_targets.py [--build build] [--out out/targets] [--repetitions 12]
    scripts/python3 scripts/bench_targets.py --ceiling 6     (also: what two threads can reach here)
    scripts/python3 scripts/bench_targets.py --self-check   (the interval and verdicts on synthetic data)

bench_table.py measures every kernel in a call of its own, minutes apart, and reports medians of
3 repetitions: on a machine whose speed drifts by up to 30 % within minutes (a VM sharing its host),
a ratio of two such medians is not established by one table. This script measures only the
benchmarks the targets name, all in ONE Google Benchmark call whose repetitions are randomly
interleaved, so that a drift of the machine hits numerator and denominator alike, and it reports
every ratio with a 90 % bootstrap interval (the repetitions of each benchmark resampled
independently, 4000 times; the ratio of the medians). A target is
  met        when the interval lies above it,
  not met    when the interval lies below it,
  undecided  otherwise (more repetitions, or a quieter machine, would decide it).
The interval covers the repetitions of one process: a second call of the same binary can differ
by more (session 7, AMD EPYC: constant rough 8.36 and 9.00e6/s in two calls, smooth/rough 1.30 and
1.22), so a verdict near its target wants a second call before it is believed.
The benchmarks (tests/bench/dsmc_bench.cpp, BM_Case_*/N/T, wall-clock collisions per second):
constant rough, constant smooth and cached brilliantov at N = 1e6 on 1 and 2 threads, and elastic
smooth at N = 1e5 and 1e6 on one thread (against SPARTA's figures on this machine, from the issue).
Writes markdown to stdout and the raw JSON to --out.

--ceiling R adds, for the same three kernels at N = 1e6, R rounds of three calls in a random order:
one one-thread process alone, two one-thread processes at once (summed: they share nothing but the
machine's cores, caches and memory, so their sum is what two threads of one process can reach at
best), and one two-thread process. Each round's ratios (pair / alone, two threads / alone, two
threads / pair) are taken within the round, seconds apart; the table gives their median and a 90 %
bootstrap interval over the rounds. If even the pair's interval lies below 1.8, the two-thread
target is out of this machine's reach.
"""
import argparse
import datetime
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import (BENCH_ENV, benchmark_iterations, commit, cpu_times, loadavg, machine,  # noqa: E402
                          pair_rate, single_rate, stolen_since)

FILTER = ("^BM_Case_(RoughConstant|SmoothConstant|Brilliantov)/1000000/[12]/|"
          "^BM_Case_SmoothElastic/(100000|1000000)/1/")


def interval(num, den, rng, boots=4000):
    """Median ratio of num/den (den may be a constant) and its 90 % bootstrap interval."""
    num = np.asarray(num, dtype=float)
    den_arr = np.atleast_1d(np.asarray(den, dtype=float))
    est = np.median(num) / np.median(den_arr)
    bn = np.median(rng.choice(num, size=(boots, num.size)), axis=1)
    bd = np.median(rng.choice(den_arr, size=(boots, den_arr.size)), axis=1)
    lo, hi = np.percentile(bn / bd, [5, 95])
    return est, lo, hi


def verdict(lo, hi, target):
    return "met" if lo >= target else ("not met" if hi < target else "undecided")


def self_check():
    """The interval on synthetic repetitions (lognormal scatter) whose true ratio is 1.5, over 200 trials
    of 12 repetitions each: with 10 % scatter the 90 % interval must cover 1.5 in 80-99 % of the trials
    (a bootstrap of medians from 12 values is not exact); with 5 % scatter every trial must call 1.3
    met and 1.7 not met; with 30 % scatter a target equal to the truth must stay undecided in at least
    80 % of them. Exits 1 on a failure (ctest: scripts_bench_targets)."""
    rng = np.random.default_rng(7)
    boot = np.random.default_rng(1)
    failures = []

    def trials(scatter, n=200):
        for _ in range(n):
            den = 4e6 * rng.lognormal(0, scatter, 12)
            num = 1.5 * 4e6 * rng.lognormal(0, scatter, 12)
            yield interval(num, den, boot, boots=1000)

    cover = np.mean([lo < 1.5 < hi for _, lo, hi in trials(0.10)])
    if not 0.80 <= cover <= 0.99:
        failures.append(f"10 % scatter: the interval covers the true ratio in {cover:.0%} of the trials")
    wrong = sum(verdict(lo, hi, 1.3) != "met" or verdict(lo, hi, 1.7) != "not met" for _, lo, hi in trials(0.05))
    if wrong:
        failures.append(f"5 % scatter: {wrong} of 200 trials do not decide 1.3 and 1.7")
    undecided = np.mean([verdict(lo, hi, 1.5) == "undecided" for _, lo, hi in trials(0.30)])
    if undecided < 0.80:
        failures.append(f"30 % scatter: the truth is undecided in only {undecided:.0%} of the trials")
    num = 4e6 * rng.lognormal(0, 0.05, 12)
    _, lo, hi = interval(num, 2e6, boot)  # against a constant (the SPARTA figures)
    if not lo < np.median(num) / 2e6 < hi:
        failures.append("a constant denominator: the interval misses the ratio of the medians")
    for f in failures:
        print("bench_targets.py --self-check:", f)
    print(f"bench_targets.py --self-check: coverage {cover:.0%} (10 % scatter), undecided {undecided:.0%} "
          f"(30 % scatter), {'FAILED' if failures else 'passed'}")
    sys.exit(1 if failures else 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/targets")
    ap.add_argument("--repetitions", type=int, default=12)
    ap.add_argument("--ceiling", type=int, default=0, metavar="R",
                    help="also R rounds of one alone / two at once / two threads (0: none)")
    ap.add_argument("--self-check", action="store_true", help="check the interval and verdicts, then exit")
    a = ap.parse_args()
    if a.self_check:
        self_check()
    dsmc = os.path.join(a.build, "tests", "bench", "dsmc_bench")
    if not os.path.exists(dsmc):
        sys.exit(f"bench_targets.py: {dsmc} missing: build with -DCMAKE_BUILD_TYPE=Release (benchmarks on)")
    if a.repetitions < 3:
        sys.exit("bench_targets.py: --repetitions must be at least 3")
    if a.ceiling and a.ceiling < 3:
        sys.exit("bench_targets.py: --ceiling must be 0 or at least 3")
    os.makedirs(a.out, exist_ok=True)
    out_json = os.path.join(a.out, "targets.json")
    l0, t0 = loadavg(), cpu_times()
    start = datetime.datetime.now(datetime.timezone.utc)
    runs = benchmark_iterations(dsmc, FILTER, a.repetitions, out_json)
    minutes = (datetime.datetime.now(datetime.timezone.utc) - start).total_seconds() / 60
    s = {name.removeprefix("BM_Case_"): np.array([b["items_per_second"] for b in bs]) for name, bs in runs.items()}
    rng = np.random.default_rng(1)

    print(f"Measured {start:%Y-%m-%d %H:%M} UTC ({minutes:.0f} min) on {machine()}; commit {commit()[:12]}; "
          f"{a.repetitions} randomly interleaved repetitions of each benchmark in one call; load (1 min) "
          f"{l0:.2f} before, {loadavg():.2f} after; CPU time stolen by the hypervisor {stolen_since(t0)}; "
          f"OMP_WAIT_POLICY={BENCH_ENV['OMP_WAIT_POLICY']}.\n")
    print("| benchmark | median 1e6 coll/s | min .. max |")
    print("|-----------|-------------------|------------|")
    for name in sorted(s):
        v = s[name] / 1e6
        print(f"| {name} | {np.median(v):.2f} | {v.min():.2f} .. {v.max():.2f} |")

    rows = [
        ("rough constant, N = 1e6, one thread (1e6/s)", s["RoughConstant/1000000/1"], 1e6, 3.0),
        ("elastic smooth / SPARTA at N = 1e5 (0.75e6/s)", s["SmoothElastic/100000/1"], 0.75e6, 5.0),
        ("elastic smooth / SPARTA at N = 1e6 (0.5e6/s)", s["SmoothElastic/1000000/1"], 0.5e6, 5.0),
        ("smooth / rough, one thread", s["SmoothConstant/1000000/1"], s["RoughConstant/1000000/1"], 1.3),
        ("smooth / rough, two threads", s["SmoothConstant/1000000/2"], s["RoughConstant/1000000/2"], 1.3),
        ("brilliantov / rough constant, one thread", s["Brilliantov/1000000/1"], s["RoughConstant/1000000/1"], 0.7),
        ("brilliantov / rough constant, two threads", s["Brilliantov/1000000/2"], s["RoughConstant/1000000/2"], 0.7),
        ("two threads / one, rough", s["RoughConstant/1000000/2"], s["RoughConstant/1000000/1"], 1.8),
        ("two threads / one, smooth", s["SmoothConstant/1000000/2"], s["SmoothConstant/1000000/1"], 1.8),
        ("two threads / one, brilliantov", s["Brilliantov/1000000/2"], s["Brilliantov/1000000/1"], 1.8),
    ]
    print("\n| target (issue 5) | goal | measured | 90 % interval | verdict |")
    print("|------------------|------|----------|---------------|---------|")
    for label, num, den, goal in rows:
        est, lo, hi = interval(num, den, rng)
        print(f"| {label} | >= {goal:g} | {est:.2f} | {lo:.2f} .. {hi:.2f} | {verdict(lo, hi, goal)} |")
    if a.ceiling:
        ceiling(dsmc, a.ceiling, os.path.join(a.out, "ceiling.json"), rng)


def ceiling(dsmc, rounds, out_json, rng):
    """The two-thread ceiling of this machine (module docstring, --ceiling)."""
    order = np.random.default_rng()
    kernels = ("RoughConstant", "SmoothConstant", "Brilliantov")
    data = {k: [] for k in kernels}
    l0, t0, start = loadavg(), cpu_times(), datetime.datetime.now(datetime.timezone.utc)
    for _ in range(rounds):
        for k in order.permutation(kernels):
            f1, f2 = f"^BM_Case_{k}/1000000/1/", f"^BM_Case_{k}/1000000/2/"
            calls = {"alone": lambda: single_rate(dsmc, f1), "pair": lambda: pair_rate(dsmc, f1),
                     "two_threads": lambda: single_rate(dsmc, f2)}
            r = {}
            for c in order.permutation(list(calls)):
                r[c] = calls[c]()
            data[k].append(r)
    with open(out_json, "w") as f:
        json.dump(data, f, indent=1)
    minutes = (datetime.datetime.now(datetime.timezone.utc) - start).total_seconds() / 60
    print(f"\nThe two-thread ceiling ({start:%H:%M} UTC, {minutes:.0f} min, {rounds} rounds of three calls in random "
          f"order; load {l0:.2f} before, {loadavg():.2f} after; CPU time stolen by the hypervisor {stolen_since(t0)}), "
          "N = 1e6, ratios within each round:\n")
    print("| kernel | two processes / one alone | two threads / one alone | two threads / two processes |")
    print("|--------|---------------------------|-------------------------|-----------------------------|")
    for k in kernels:
        cells = []
        for num, den in (("pair", "alone"), ("two_threads", "alone"), ("two_threads", "pair")):
            est, lo, hi = interval([r[num] / r[den] for r in data[k]], 1.0, rng)
            cells.append(f"{est:.2f} ({lo:.2f} .. {hi:.2f})")
        print(f"| {k} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
