#!/usr/bin/env python3
"""Work-precision diagram of the DSMC (issue 5 item 4, first part): wall time against error.

    scripts/python3 scripts/bench_accuracy.py [--build build] [--out out/accuracy] [--quick]

Reference with a known answer: the inelastic rough Maxwell model (run.kernel = "maxwell"), whose
T_tr(t) and T_rot(t) obey closed linear ODEs exactly (README "The Maxwell kernel"); every
constant-restitution run writes that solution as its theory columns. Each point is one
`roughgas run` of a rough gas (alpha = 0.8, beta = 0.4, theta(0) = 0.1, 8 collisions per particle,
8 output rows) with some setting; its error is the rms over the rows and replicas of
T_tr/T_tr_theory - 1 and T_rot/T_rot_theory - 1, its cost the wall time of the run (the CLI's
own "collisions in ... s"). Curves: N (the statistical error falls as N^-1/2 at fixed collisions per
particle), threads 1 and 2, and groups (automatic against 1). The DSMC of the homogeneous gas has
no time-step error (exact majorant sampling; the step only refreshes bounds: tests/dsmc), so no
time-step curve here; the time step of uniform shear flow (shear.time_step) and the restitution
cache against the direct integrator are the next curves to add.

Writes DIR/accuracy.csv and DIR/accuracy.png and prints the load average with every point.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv  # noqa: E402

CASE = """[run]
particles = {n}
end = 8.0
output_every = 1.0
replicas = {replicas}
kernel = "maxwell"
groups = {groups}
[[species]]
mass = 1.0
radius = 0.5
temperature = 1.0
rotational_temperature = 0.1
[collision]
model = "constant"
alpha = 0.8
beta = 0.4
"""


def loadavg():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def point(roughgas, n, replicas, groups, threads):
    env = {**os.environ, "OMP_WAIT_POLICY": os.environ.get("OMP_WAIT_POLICY", "passive")}
    with tempfile.TemporaryDirectory() as d:
        case = os.path.join(d, "case.toml")
        with open(case, "w") as f:
            f.write(CASE.format(n=n, replicas=replicas, groups=groups))
        load0 = loadavg()
        r = subprocess.run([roughgas, "run", case, "--out", os.path.join(d, "o"), "--quiet", "--threads",
                            str(threads)], capture_output=True, text=True, env=env, check=True)
        load1 = loadavg()
        m = re.search(r"collisions in ([0-9.eE+-]+) s", r.stdout)
        seconds = float(m.group(1))
        c = read_csv(os.path.join(d, "o", "moments.csv"))
    rows = c["t"] > 0
    e2, k = 0.0, 0
    for col in ("T_tr", "T_rot"):
        rel = c[col][rows] / c[col + "_theory"][rows] - 1
        e2 += float((rel ** 2).sum())
        k += int(rows.sum())
    return seconds, (e2 / k) ** 0.5, load0, load1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/accuracy")
    ap.add_argument("--quick", action="store_true", help="N up to 1e5 (checks the script)")
    a = ap.parse_args()
    roughgas = os.path.join(a.build, "roughgas")
    os.makedirs(a.out, exist_ok=True)
    sizes = [2000, 10000, 100000] if a.quick else [2000, 10000, 100000, 1000000]
    curves = [("1 thread, groups auto", 0, 1), ("2 threads, groups auto", 0, 2), ("1 thread, 1 group", 1, 1)]
    rows = []
    for label, groups, threads in curves:
        for n in sizes:
            seconds, err, l0, l1 = point(roughgas, n, 2, groups, threads)
            print(f"{label:24s} N = {n:8d}: {seconds:8.3f} s, rms error {err:.2e} (load {l0:.2f} .. {l1:.2f})")
            rows.append({"curve": label, "N": n, "groups": groups, "threads": threads, "seconds": seconds,
                         "rms_error": err, "load_before": l0, "load_after": l1})
    with open(os.path.join(a.out, "accuracy.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for label, _, _ in curves:
        pts = [r for r in rows if r["curve"] == label]
        ax.loglog([p["seconds"] for p in pts], [p["rms_error"] for p in pts], "o-", label=label)
        for p in pts:
            ax.annotate(f"N={p['N']:.0e}", (p["seconds"], p["rms_error"]), fontsize=7)
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("rms relative error of T_tr, T_rot (Maxwell model, exact ODEs)")
    ax.set_title("work-precision, 8 collisions per particle, 2 replicas")
    ax.legend()
    fig.tight_layout()
    tmp = os.path.join(a.out, ".accuracy.png.tmp")
    fig.savefig(tmp, dpi=120, format="png")
    os.replace(tmp, os.path.join(a.out, "accuracy.png"))
    print(f"wrote {a.out}/accuracy.csv and accuracy.png")


if __name__ == "__main__":
    main()
