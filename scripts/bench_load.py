#!/usr/bin/env python3
"""Wall times of `roughgas run` on a shared machine: threads against one thread, idle and under load.

    scripts/python3 scripts/bench_load.py [--build build] [--rounds 5] [--out out/bench_load]
                                          [--only idle,dense,busy,two,mpi]

Each comparison runs its two sides alternately (A B, then B A in the next round, so that a drift of
the machine's speed hits both alike) and reports, per side, the median and the range of the wall
times over the rounds, and the median of the per-round ratios. The cases (a rough gas, alpha 0.9,
beta 0.5) are written to --out:

  idle (idle, N = 1e6)    --threads 2 against --threads 1: the speed-up (t1/t2)
  dense (N = 1e5)         the same with a row per collision per particle (100 rows)
  busy (beside a core)    the default thread count against --threads 1 while another process
                          keeps one core busy (a shell loop): t_default/t1
  two (runs at once)      two default runs started together against two --threads 1 runs started
                          together: the slower run's time, t_default/t1
  mpi (mpirun -np 2, 8 replicas)  (when mpirun and a roughgas built with MPI exist) one rank against two
                          ranks with one thread each: t_np1/t_np2

The machine, date, commit and load average are printed with the table (docs/performance.md).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import cpu_times, loadavg, machine, measured_line, rough_case  # noqa: E402


def write_case(out, name, n, end, every, replicas=1):
    path = os.path.join(out, name + ".toml")
    with open(path, "w") as f:
        f.write(rough_case(n, end, every, replicas))
    return path


def timed(cmds, env=None):
    """Starts every command at once; returns the wall time until the last one ends."""
    t0 = time.perf_counter()
    procs = [subprocess.Popen(c, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env) for c in cmds]
    for p, c in zip(procs, cmds):
        _, err = p.communicate()
        if p.returncode != 0:
            sys.exit(f"bench_load: {' '.join(c)} failed ({p.returncode}):\n{err.decode()}")
    return time.perf_counter() - t0


def compare(name, side_a, side_b, rounds, ratio_text):
    """side_a, side_b: () -> seconds. Alternates them; returns a table row."""
    ta, tb, ratios = [], [], []
    for r in range(rounds):
        if r % 2 == 0:
            a = side_a()
            b = side_b()
        else:
            b = side_b()
            a = side_a()
        ta.append(a)
        tb.append(b)
        ratios.append(a / b)
        print(f"  {name}, round {r + 1}: {a:.2f} s, {b:.2f} s", file=sys.stderr)
    def fmt(ts):
        return f"{statistics.median(ts):.2f} ({min(ts):.2f}-{max(ts):.2f})"
    return f"| {name} | {fmt(ta)} | {fmt(tb)} | {ratio_text} {statistics.median(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f}) |"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out", default="out/bench_load")
    ap.add_argument("--only", default="idle,dense,busy,two,mpi",
                    help="the comparisons to run, comma-separated (default: all)")
    a = ap.parse_args()
    only = set(a.only.split(","))
    unknown = only - {"idle", "dense", "busy", "two", "mpi"}
    if unknown:
        sys.exit(f"bench_load: --only {a.only}: unknown {', '.join(sorted(unknown))} "
                 "(choose from idle, dense, busy, two, mpi)")
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.makedirs(a.out, exist_ok=True)
    big = write_case(a.out, "n1e6", 1000000, 20.0, 5.0)
    dense = write_case(a.out, "n1e5_dense", 100000, 100.0, 1.0)
    ens = write_case(a.out, "n1e5_8replicas", 100000, 100.0, 5.0, replicas=8)

    def run(case, tag, *extra):
        return [roughgas, "run", case, "--out", os.path.join(a.out, tag), "--force", "--quiet", *extra]

    rows = []
    print(machine(), file=sys.stderr)
    load0, steal0 = loadavg(), cpu_times()
    if "idle" in only:
        rows.append(compare("idle, N = 1e6, 2 threads vs 1",
                            lambda: timed([run(big, "a", "--threads", "1")]),
                            lambda: timed([run(big, "b", "--threads", "2")]), a.rounds, "t1/t2"))
    if "dense" in only:
        rows.append(compare("idle, N = 1e5, a row per collision per particle, 2 threads vs 1",
                            lambda: timed([run(dense, "a", "--threads", "1")]),
                            lambda: timed([run(dense, "b", "--threads", "2")]), a.rounds, "t1/t2"))
    busy = subprocess.Popen(["sh", "-c", "while :; do :; done"]) if "busy" in only else None
    try:
        if busy:
            time.sleep(0.5)
            rows.append(compare("beside a busy core, N = 1e5 dense: default threads vs 1",
                                lambda: timed([run(dense, "a")]),
                                lambda: timed([run(dense, "b", "--threads", "1")]), a.rounds, "t_default/t1"))
    finally:
        if busy:
            busy.kill()
            busy.wait()
    if "two" in only:
        rows.append(compare("two runs at once, N = 1e5 dense: default threads vs 1 each",
                            lambda: timed([run(dense, "a1"), run(dense, "a2")]),
                            lambda: timed([run(dense, "b1", "--threads", "1"), run(dense, "b2", "--threads", "1")]),
                            a.rounds, "t_default/t1"))
    mpirun = shutil.which("mpirun")
    if "mpi" in only and mpirun and subprocess.run([roughgas, "--version"], capture_output=True, text=True).stdout.find("MPI") >= 0:
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        def mpi(np, tag):
            return [mpirun, "--oversubscribe", "--bind-to", "none", "-np", str(np), *run(ens, tag, "--threads", "1")]
        rows.append(compare("8 replicas of N = 1e5: mpirun -np 1 vs -np 2, one thread per rank",
                            lambda: timed([mpi(1, "a")], env), lambda: timed([mpi(2, "b")], env),
                            a.rounds, "t_np1/t_np2"))
    print(measured_line(a.rounds, "wall seconds: median (min-max)", load0, steal0))
    print("| comparison | side A | side B | ratio |")
    print("|------------|--------|--------|-------|")
    for r in rows:
        print(r)


if __name__ == "__main__":
    main()
