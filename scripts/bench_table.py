#!/usr/bin/env python3
"""The performance tables of docs/performance.md, regenerated from the benchmark binaries.

    scripts/python3 scripts/bench_table.py [--build build] [--out out/bench] [--repetitions 3] [--quick]

Runs (Release build with benchmarks, ROUGHGAS_BUILD_BENCHMARKS=ON):
  0. tests/bench/machine_bench: what a random access and a cache line between the two cores cost on
     this machine (the latencies behind the tables below);
  1. tests/bench/dsmc_bench BM_Case_*/N/T: collisions per second (wall clock) of the constant
     rough, constant smooth, elastic smooth, coulomb, viscoelastic (smooth and rough) and brilliantov
     kernels for N = 1e4 .. 1e7 on 1 and 2 threads (groups as `roughgas run` chooses them);
  2. dsmc_bench BM_Skip_* / BM_Threads_* / BM_Layout_*: what each compile-time skip and the groups are worth;
     BM_StepStart_*: the step start alone (time per step start and per grain);
  3. tests/bench/restitution_bench BM_*TableBuild: building the restitution tables;
  4. `roughgas run` of a constant rough case for each N under /usr/bin/time: peak memory (max RSS);
  5. the ceiling of two threads: two one-thread benchmark processes at once (nothing shared but the
     machine), against one alone, interleaved; and the speed targets computed from the tables.
Repetitions are randomly interleaved (Google Benchmark --benchmark_enable_random_interleaving), the
median is reported, and every number comes with the load average (/proc/loadavg, 1 min) read
before and after its benchmark: numbers taken on a loaded machine say so. Writes markdown to
stdout and the raw JSON and CSV files to --out.
"""
import argparse
import csv
import datetime
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import BENCH_ENV, benchmark_iterations, loadavg, machine, pair_rate, rough_case, single_rate  # noqa: E402

CASES = [
    ("SmoothConstant", "constant, smooth (alpha 0.9)"),
    ("SmoothElastic", "constant, smooth, elastic"),
    ("RoughConstant", "constant, rough (alpha 0.9, beta 0.5)"),
    ("Coulomb", "coulomb"),
    ("ViscoelasticSmooth", "viscoelastic, smooth (ice)"),
    ("Viscoelastic", "viscoelastic, beta 0.5 (ice)"),
    ("Brilliantov", "brilliantov, cached (ice)"),
]


def run_bench(binary, flt, reps, out_json):
    """Runs one Google Benchmark filter; returns ({name: (median items/s, median real ms)}, load before, after)."""
    before = loadavg()
    runs = benchmark_iterations(binary, flt, reps, out_json)
    after = loadavg()
    samples = {name: [(b.get("items_per_second", 0.0), b["real_time"], b) for b in bs] for name, bs in runs.items()}
    result = {}
    for name, s in samples.items():
        result[name] = (statistics.median(x[0] for x in s), statistics.median(x[1] for x in s), s[-1][2])
    return result, before, after


def concurrent_pair(binary, flt, reps, out_prefix):
    """Two processes of the same one-thread benchmark at once, `reps` times, alternating with one alone
    (so that a drift of the machine hits both). Returns the medians of (one alone, the pair's sum)
    in items/s, and the load before and after."""
    before = loadavg()
    alone, pair = [], []
    for k in range(reps):
        alone.append(single_rate(binary, flt))
        pair.append(pair_rate(binary, flt))
        with open(f"{out_prefix}_{k}.json", "w") as f:
            json.dump({"alone": alone[-1], "pair": pair[-1]}, f)
    return statistics.median(alone), statistics.median(pair), before, loadavg()


def fmt_rate(x):
    return f"{x / 1e6:.2f}" if x else "-"


def peak_memory(roughgas, n, threads):
    """Max RSS of `roughgas run` of a rough constant case with n particles, 0.5 collisions per particle."""
    case = rough_case(n, 0.5, 0.5)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "case.toml")
        with open(path, "w") as f:
            f.write(case)
        r = subprocess.run(["/usr/bin/time", "-f", "%M", roughgas, "run", path, "--out", os.path.join(d, "out"),
                            "--quiet", "--threads", str(threads)], capture_output=True, text=True, check=True,
                           env=BENCH_ENV)
        kib = int(r.stderr.strip().splitlines()[-1])
    return kib * 1024


def machine_table(probe, reps, out):
    """The latencies of tests/bench/machine_bench: median and range over `reps` interleaved repetitions."""
    l0 = loadavg()
    runs = benchmark_iterations(probe, ".", reps, os.path.join(out, "machine.json"))
    l1 = loadavg()
    print(f"Latencies of this machine (tests/bench/machine_bench, {reps} interleaved repetitions; "
          f"load {l0:.2f} .. {l1:.2f}); ns per dependent load or per one-way line transfer:\n")
    print("| probe | median ns | min .. max |")
    print("|-------|-----------|------------|")
    def order(name):  # by probe, then by its size argument
        probe_name, _, arg = name.partition("/")
        return probe_name, int(arg) if arg.isdigit() else 0

    for name, bs in sorted(runs.items(), key=lambda kv: order(kv[0])):
        ns = [b.get("ns_per_load", b.get("ns_one_way")) for b in bs]
        ns = [x * 1e9 for x in ns if x is not None]
        if not ns:  # skipped (BM_Machine_LineTransfer on one CPU)
            print(f"| {name} | {bs[0].get('error_message', 'skipped')} | |")
            continue
        print(f"| {name} | {statistics.median(ns):.1f} | {min(ns):.1f} .. {max(ns):.1f} |")
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/bench")
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="N up to 1e5, one repetition (checks the script)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    dsmc = os.path.join(a.build, "tests", "bench", "dsmc_bench")
    rest = os.path.join(a.build, "tests", "bench", "restitution_bench")
    probe = os.path.join(a.build, "tests", "bench", "machine_bench")
    roughgas = os.path.join(a.build, "roughgas")
    for b in (dsmc, rest, probe, roughgas):
        if not os.path.exists(b):
            sys.exit(f"bench_table.py: {b} missing: build with -DCMAKE_BUILD_TYPE=Release (benchmarks on)")
    reps = 1 if a.quick else a.repetitions
    sizes = [10000, 100000] if a.quick else [10000, 100000, 1000000, 10000000]
    size_re = "|".join(str(n) for n in sizes)

    print(f"Measured {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC on {machine()}; "
          f"median of {reps} randomly interleaved repetitions; wall-clock collisions per second in 1e6/s; "
          f"OMP_WAIT_POLICY={BENCH_ENV['OMP_WAIT_POLICY']}.\n")

    machine_table(probe, max(reps, 5), a.out)

    rows = []
    print("| kernel | N | 1 thread | 2 threads | 2T/1T | load (1 min) before, after |")
    print("|--------|---|----------|-----------|-------|-----------------------------|")
    for key, label in CASES:
        res, l0, l1 = run_bench(dsmc, f"^BM_Case_{key}/({size_re})/", reps, os.path.join(a.out, f"case_{key}.json"))
        for n in sizes:
            r1 = res.get(f"BM_Case_{key}/{n}/1", (0, 0, {}))[0]
            r2 = res.get(f"BM_Case_{key}/{n}/2", (0, 0, {}))[0]
            ratio = f"{r2 / r1:.2f}" if r1 and r2 else "-"
            print(f"| {label} | {n:.0e} | {fmt_rate(r1)} | {fmt_rate(r2)} | {ratio} | {l0:.2f}, {l1:.2f} |")
            rows.append({"kernel": key, "N": n, "coll_per_s_1T": r1, "coll_per_s_2T": r2, "load_before": l0,
                         "load_after": l1})
    with open(os.path.join(a.out, "cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    # The speed targets, from the table above (N = 1e6, or the largest N of a --quick run).
    n_t = 1000000 if 1000000 in sizes else sizes[-1]
    rate = {(r["kernel"], r["N"]): r for r in rows}
    r1 = lambda k: rate[(k, n_t)]["coll_per_s_1T"]  # noqa: E731
    r2 = lambda k: rate[(k, n_t)]["coll_per_s_2T"]  # noqa: E731
    elastic_100k = rate[("SmoothElastic", 100000)]["coll_per_s_1T"]
    print(f"\nSpeed targets, from the table (N = {n_t:.0e}):\n")
    print("| target | measured |")
    print("|--------|----------|")
    print(f"| rough constant, one thread >= 3e6/s | {fmt_rate(r1('RoughConstant'))}e6/s |")
    print(f"| elastic smooth >= 5x SPARTA (0.75e6 at 1e5, 0.5e6 at 1e6 per CPU-second) | "
          f"{elastic_100k / 0.75e6:.1f}x at 1e5, {r1('SmoothElastic') / 0.5e6:.1f}x at {n_t:.0e} |")
    print(f"| smooth >= 1.3x rough | {r1('SmoothConstant') / r1('RoughConstant'):.2f}x (one thread), "
          f"{r2('SmoothConstant') / r2('RoughConstant'):.2f}x (two) |")
    print(f"| brilliantov (cached) >= 0.7x constant | {r1('Brilliantov') / r1('RoughConstant'):.2f}x (one thread), "
          f"{r2('Brilliantov') / r2('RoughConstant'):.2f}x (two) |")
    print(f"| two threads >= 1.8x one | rough {r2('RoughConstant') / r1('RoughConstant'):.2f}x, "
          f"smooth {r2('SmoothConstant') / r1('SmoothConstant'):.2f}x |")

    print(f"\nThe ceiling of two threads on this machine: two one-thread processes at once, N = {n_t:.0e} "
          "(nothing shared but the cores' caches and memory; alone and pair interleaved):\n")
    print("| kernel | one process alone | two at once, summed | ratio | load before, after |")
    print("|--------|-------------------|---------------------|-------|--------------------|")
    for key in ("RoughConstant", "SmoothConstant"):
        one, two, l0, l1 = concurrent_pair(dsmc, f"^BM_Case_{key}/{n_t}/1/", reps,
                                           os.path.join(a.out, f"pair_{key}"))
        print(f"| {key} | {fmt_rate(one)} | {fmt_rate(two)} | {two / one:.2f} | {l0:.2f}, {l1:.2f} |")

    n_skip = "100000" if a.quick else "1000000"
    # One call for the variants and their references, so that their repetitions are interleaved.
    res, l0, l1 = run_bench(dsmc, f"^BM_(Skip|Layout)_.*/{n_skip}|^BM_Case_(RoughConstant|SmoothConstant|Brilliantov)/{n_skip}/1/",
                            reps, os.path.join(a.out, "skips.json"))
    print(f"\nCompile-time skips and layouts against the kernels roughgas run uses, interleaved, N = {n_skip}, "
          f"one thread (load {l0:.2f} .. {l1:.2f}):\n")
    print("| variant | 1e6 coll/s | bytes (store, total) |")
    print("|---------|------------|----------------------|")
    for name, (rate, _, b) in sorted(res.items()):
        print(f"| {name} | {fmt_rate(rate)} | {b.get('bytes', 0):.0f}, {b.get('bytes_total', 0):.0f} |")

    res, l0, l1 = run_bench(dsmc, f"^BM_Threads_.*/{n_skip}/", reps, os.path.join(a.out, "threads.json"))
    print(f"\nGroups G and threads T, N = {n_skip} (load {l0:.2f} .. {l1:.2f}):\n")
    print("| benchmark (N/G/T) | 1e6 coll/s |")
    print("|-------------------|------------|")
    for name, (rate, _, _) in sorted(res.items()):
        print(f"| {name} | {fmt_rate(rate)} |")

    step_sizes = "100000" if a.quick else "100000|1000000|10000000"
    res, l0, l1 = run_bench(dsmc, f"^BM_StepStart_.*/({step_sizes})/", reps, os.path.join(a.out, "step_start.json"))
    print(f"\nThe step start alone (partition, counting sort, bounds; load {l0:.2f} .. {l1:.2f}):\n")
    print("| benchmark (N/T) | time per step start | per grain |")
    print("|-----------------|---------------------|-----------|")
    for name, (_, ms, _) in sorted(res.items()):
        n = int(name.split("/")[1])
        print(f"| {name.split('/min_time')[0]} | {ms:.2f} ms | {ms * 1e6 / n:.1f} ns |")

    res, l0, l1 = run_bench(rest, "TableBuild", 1, os.path.join(a.out, "tables.json"))
    print(f"\nRestitution table builds (load {l0:.2f} .. {l1:.2f}):\n")
    print("| table | build time |")
    print("|-------|------------|")
    for name, (_, ms, _) in sorted(res.items()):
        print(f"| {name} | {ms / 1000:.2f} s |")

    print("\nPeak memory of `roughgas run` (rough constant case, 0.5 collisions per particle, 2 threads):\n")
    print("| N | max RSS | per particle |")
    print("|---|---------|--------------|")
    for n in sizes:
        rss = peak_memory(roughgas, n, 2)
        print(f"| {n:.0e} | {rss / 2**20:.1f} MiB | {rss / n:.0f} B |")


if __name__ == "__main__":
    main()
