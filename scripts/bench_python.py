#!/usr/bin/env python3
"""What the Python module costs against the command line (docs/performance.md, "Python module").

    scripts/python3 scripts/bench_python.py [--build DIR] [--rounds 5] [--particles 1000000] [--end 20]

Two measurements:
  run    the rough gas of the run-level benchmarks (bench_common.rough_case: alpha 0.9, beta 0.5;
         --particles grains to --end collisions per particle, a row every collision per particle,
         1 thread), each round run once by `roughgas run` and once by a Python process doing
         `import roughgas; roughgas.run(...)`, alternating which goes first: the wall time of each
         whole process (interpreter start and import included) and the ratio Python/CLI per round;
         the seconds of the call roughgas.run(...) within its process; and, in each round, a Python
         process that only imports roughgas (the fixed cost);
  eps_n  roughgas.eps_n over 10^6 log-spaced speeds of the ice case from its table (tabulated=True,
         after the tables are built once), in one process: the seconds of each of --rounds calls.
Prints the medians and ranges, with the machine, the commit and the load.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import cpu_times, loadavg, measured_line, rough_case, timed  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

EPS_N = """
import sys, time
import numpy as np
import roughgas
case = roughgas.Case(sys.argv[1])
g = np.geomspace(1e-3, 5.0, 1000000)
roughgas.eps_n(g[:10], case, tabulated=True)  # builds the tables once
for _ in range(int(sys.argv[2])):
    t0 = time.perf_counter()
    roughgas.eps_n(g, case, tabulated=True)
    print(time.perf_counter() - t0)
"""


def summary(values, fmt="{:.3f}"):
    return f"{fmt.format(statistics.median(values))} ({fmt.format(min(values))} – {fmt.format(max(values))})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--particles", type=int, default=1000000)
    ap.add_argument("--end", type=float, default=20)
    args = ap.parse_args()
    binary = os.path.join(args.build, "roughgas")
    env = dict(os.environ, PYTHONPATH=os.path.join(args.build, "python"), OMP_WAIT_POLICY="passive")
    os.environ["OMP_WAIT_POLICY"] = "passive"
    load0, steal0 = loadavg(), cpu_times()
    with tempfile.TemporaryDirectory(prefix="bench_python_") as work:
        case = os.path.join(work, "case.toml")
        with open(case, "w") as f:
            f.write(rough_case(args.particles, args.end, 1))
        cli = [binary, "run", case, "--out", os.path.join(work, "cli"), "--force", "--quiet", "--threads", "1"]
        # The process prints the seconds roughgas.run took in it, last.
        py = ["/usr/bin/python3", "-c",
              f"import time, roughgas; t0 = time.perf_counter(); roughgas.run({case!r}, "
              f"out={os.path.join(work, 'py')!r}, threads=1, progress=False, force=True); "
              "print(time.perf_counter() - t0)"]
        imports = ["/usr/bin/python3", "-c", "import roughgas"]
        cli_s, py_s, ratio, import_s, call_s = [], [], [], [], []
        for r in range(args.rounds):
            first_cli = r % 2 == 0
            order = [("cli", cli), ("py", py)] if first_cli else [("py", py), ("cli", cli)]
            times = {}
            for name, cmd in order + [("import", imports)]:
                if name == "cli":
                    times[name] = timed(cmd, "bench_python.py")
                else:
                    t0 = time.perf_counter()
                    done = subprocess.run(cmd, check=True, env=env, capture_output=True, text=True)
                    times[name] = time.perf_counter() - t0
                    if name == "py":
                        call_s.append(float(done.stdout.split()[-1]))
            cli_s.append(times["cli"])
            py_s.append(times["py"])
            import_s.append(times["import"])
            ratio.append(times["py"] / times["cli"])
        eps = subprocess.run(["/usr/bin/python3", "-c", EPS_N, os.path.join(ROOT, "cases", "ice.toml"),
                              str(args.rounds)], check=True, env=env, capture_output=True, text=True)
        eps_s = [float(x) for x in eps.stdout.split()]
    print(measured_line(args.rounds, "wall seconds, median (range)", load0, steal0))
    print(f"| what | CLI | Python | Python/CLI |\n|---|---|---|---|")
    print(f"| run: {args.particles} grains to {args.end:g} collisions per particle, 1 thread | {summary(cli_s)} | "
          f"{summary(py_s)} | {summary(ratio, '{:.4f}')} |")
    print(f"| the call roughgas.run(...) within its process | | {summary(call_s)} | "
          f"{summary([c / t for c, t in zip(call_s, cli_s)], '{:.4f}')} |")
    print(f"| a Python process that only imports roughgas | | {summary(import_s)} | |")
    print(f"| eps_n over 10^6 speeds from its table ({os.cpu_count()} threads) | | {summary(eps_s, '{:.4f}')} | |")


if __name__ == "__main__":
    main()
