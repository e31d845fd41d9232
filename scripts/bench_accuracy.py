#!/usr/bin/env python3
"""Work-precision diagram of the DSMC: wall time against error.

    scripts/python3 scripts/bench_accuracy.py [--build build] [--out out/accuracy] [--quick]
                                              [--panels maxwell,hcs,restitution,shear]

Each point is one `roughgas run` (shear: several, with other seeds); its cost is the wall time of
its collisions (the CLI's own "collisions in ... s"; the CSV has the process's CPU time too), its
error the deviation from a reference with a known answer. Every N has its own seed, so the points
of a curve are independent (the thread and group curves share them: same seed, same trajectory
but for the groups). One panel per reference:

maxwell      the inelastic rough Maxwell model (run.kernel = "maxwell"), whose T_tr(t), T_rot(t) obey
             closed linear ODEs exactly (docs/model.md, the Maxwell kernel; the theory columns): a rough
             gas (alpha = 0.8, beta = 0.4, theta(0) = 0.1) over 8 collisions per particle, 4
             replicas; error = rms over the rows of T_tr/T_tr_theory - 1 and T_rot/T_rot_theory - 1
             of the replica mean. Curves: N, threads 1 and 2, groups automatic against 1.
hcs          the same gas with hard spheres (tests/data/hcs_rough_reference.toml, to 32 collisions
             per particle), 4 replicas, against tests/data/hcs_rough_reference.csv (make_reference.py
             hcs: 400 replicas of N = 1e5, its own error ~2e-4); error = rms over the rows of
             T_tr/T_tr_ref - 1 and T_rot/T_rot_ref - 1. Curves: N on 1 and 2 threads.
             Both panels also draw each run's own standard error (rms of X_err/X over the rows): a
             deviation that tracks it is statistics, one above it a bias.
restitution  viscoelastic ice (cases/hcs_viscoelastic_ice.toml, smooth) and, without --quick,
             brilliantov ice (cases/hcs_brilliantov.toml) over 4 collisions per particle, 2 replicas:
             the cached tables against the direct integrator (contact.cache = false). Error = rms of
             T_tr, T_rot against a cached run with 8x the statistics of the largest point (another
             seed). Open markers: the tables' own share, the rms of cached/direct - 1 of the same seed
             (the same random numbers). The tables are built once (contact.cache_file); their build
             time is printed, not added to the points.
shear        uniform shear flow (tests/data/usf_rough_reference.toml: alpha = 0.9, beta = 0, a = 1,
             started steady) for shear.time_step h and N, R runs each averaging SHEAR_WINDOW rows after
             SHEAR_START collisions per particle; error = rms over the runs of P*_xy/P0 - 1, P0 the Richardson
             extrapolation h -> 0 of tests/data/usf_rough_reference.csv. Prints the bias c2 h^2, the
             statistical error s/sqrt(N L), where they cross, and the time step that minimises the
             error at a given cost; draws the bias (dotted) and the model sqrt(bias^2 + s^2/(N L)) (x).

The homogeneous DSMC has no time-step error (exact majorant sampling; run.step only refreshes
bounds: tests/dsmc), so only the shear panel has a time-step curve.

Writes DIR/accuracy.csv and DIR/accuracy.png and prints the machine and the load average with
every point.
"""
import argparse
import csv
import datetime
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import loadavg, machine, run_roughgas  # noqa: E402
from make_reference import HCS_CASE, HCS_REFERENCE, ROOT, USF_CASE, read_usf_reference, steady  # noqa: E402
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure  # noqa: E402

MAXWELL_CASE = """[run]
particles = 1000
end = 8.0
output_every = 1.0
replicas = 4
kernel = "maxwell"
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
# Each shear run leaves out SHEAR_START collisions per particle, then averages SHEAR_WINDOW rows. The
# start-up transient is still ~2-3e-4 in 20-row windows from 30 to 70 (measured at h = 0.125 and
# 0.25, N = 1e6: at the resolution of those runs), which the long reference dilutes below 1e-5 and
# these windows would not: they start later.
SHEAR_START = 50.0
SHEAR_WINDOW = 40.0
COLUMNS = ["panel", "curve", "N", "replicas", "threads", "groups", "time_step", "runs", "seconds", "cpu_seconds",
           "rms_error", "bias", "stat_error", "load_before", "load_after"]


def rms_relative(d, ref, columns):
    """rms over the rows t > 0 and the columns of d[c]/ref[c] - 1."""
    rows = d["coll_per_particle"] > 0
    rel = np.concatenate([d[c][rows] / ref[c][rows] - 1 for c in columns])
    return float(np.sqrt((rel ** 2).mean()))


def own_error(d):
    """A run's own statistical error: rms over the rows t > 0 of T_tr_err/T_tr and T_rot_err/T_rot (the
    standard errors of the replica mean)."""
    rows = d["coll_per_particle"] > 0
    return float(np.sqrt(np.mean([(d[c + "_err"][rows] / d[c][rows]) ** 2 for c in ("T_tr", "T_rot")])))


class Runner:
    """Runs points, prints each with the load average, and collects the CSV rows."""

    def __init__(self, build, scratch):
        self.roughgas = os.path.join(build, "roughgas")
        self.scratch = scratch
        self.rows = []

    def run(self, case, sets, threads=1):
        r = run_roughgas(self.roughgas, case, os.path.join(self.scratch, "o"), sets, threads)
        return read_csv(os.path.join(self.scratch, "o", "moments.csv")), r

    def add(self, panel, curve, timing, rms_error, **extra):
        row = {k: "" for k in COLUMNS}
        row.update(panel=panel, curve=curve, rms_error=rms_error, **extra)
        for k in ("seconds", "cpu_seconds", "load_before", "load_after"):
            row[k] = timing[k]
        self.rows.append(row)
        print(f"{panel:11s} {curve:34s} N = {row['N']:8d}: {row['seconds']:8.3f} s ({row['cpu_seconds']:7.2f} s CPU), "
              f"rms error {rms_error:.2e} (load {row['load_before']:.2f} .. {row['load_after']:.2f})", flush=True)
        return row


def maxwell_panel(run, quick):
    case = os.path.join(run.scratch, "maxwell.toml")
    with open(case, "w") as f:
        f.write(MAXWELL_CASE)
    sizes = [2000, 10000, 100000] if quick else [2000, 10000, 100000, 1000000]
    for label, groups, threads in [("1 thread, groups auto", 0, 1), ("2 threads, groups auto", 0, 2),
                                   ("1 thread, 1 group", 1, 1)]:
        for n in sizes:
            d, r = run.run(case, [f"run.particles={n}", f"run.groups={groups}", f"run.seed={n + 7}"], threads)
            theory = {c: d[c + "_theory"] for c in ("T_tr", "T_rot")} | {"coll_per_particle": d["coll_per_particle"]}
            run.add("maxwell", label, r, rms_relative(d, theory, ("T_tr", "T_rot")), N=n, replicas=4,
                    threads=threads, groups=groups, stat_error=own_error(d))


def hcs_panel(run, quick):
    ref = read_csv(HCS_REFERENCE)
    sizes = [2000, 10000, 100000] if quick else [2000, 10000, 100000, 1000000]
    for threads in (1, 2):
        for n in sizes:
            d, r = run.run(HCS_CASE, [f"run.particles={n}", "run.replicas=4", f"run.seed={n + 7}"], threads)
            run.add("hcs", f"{threads} thread{'s' if threads > 1 else ''}", r, rms_relative(d, ref, ("T_tr", "T_rot")),
                    N=n, replicas=4, threads=threads, stat_error=own_error(d))
    own = own_error(ref)
    print(f"hcs reference's own rms relative error: {own:.2e}")
    return own


RESTITUTION_MODELS = [("viscoelastic", "cases/hcs_viscoelastic_ice.toml"), ("brilliantov", "cases/hcs_brilliantov.toml")]


def restitution_panel(run, quick):
    models = RESTITUTION_MODELS[:1] if quick else RESTITUTION_MODELS
    cached_sizes = [1000, 4000] if quick else [1000, 4000, 16000, 64000, 256000]
    direct_sizes = [1000] if quick else [1000, 4000, 16000]
    ref_n = 8 * cached_sizes[-1] // 4  # 4 replicas: 8x the statistics of the largest point
    for model, case in models:
        case = os.path.join(ROOT, case)
        tables = f"contact.cache_file={os.path.join(run.scratch, model + '.tables')}"
        build = run.run(case, [tables, "run.particles=1000", "run.end=0.01", "run.output_every=0.01"])[1]
        common = [tables, "run.end=4", "run.output_every=1", "run.output_spacing=linear"]
        print(f"restitution {model}: tables built in {build['process_seconds'] - build['seconds']:.1f} s wall, "
              f"{build['cpu_seconds']:.1f} s CPU (once: contact.cache_file)")
        ref, _ = run.run(case, common + [f"run.particles={ref_n}", "run.replicas=4", "run.seed=99"])
        cached = {}
        for n in cached_sizes:
            cached[n], r = run.run(case, common + [f"run.particles={n}", "run.replicas=2", f"run.seed={n + 1}"])
            run.add("restitution", f"{model}, cached", r, rms_relative(cached[n], ref, ("T_tr", "T_rot")), N=n,
                    replicas=2, threads=1)
        for n in direct_sizes:
            d, r = run.run(case, common + [f"run.particles={n}", "run.replicas=2", f"run.seed={n + 1}",
                                           "contact.cache=false"])
            run.add("restitution", f"{model}, direct", r, rms_relative(d, ref, ("T_tr", "T_rot")), N=n, replicas=2,
                    threads=1)
            run.add("restitution", f"{model}, cached/direct - 1, same seed", r,
                    rms_relative(cached[n], d, ("T_tr", "T_rot")), N=n, replicas=2, threads=1)


def shear_panel(run, quick):
    ref = read_usf_reference()
    print(f"shear reference: P0 = {ref['P0']:.6f} +- {ref['P0_err']:.6f}, c2 = {ref['c2']:.5f}, c4 = {ref['c4']:.5f}")
    steps = [0.5, 0.125] if quick else [0.5, 0.35, 0.25, 0.125, 0.0625]  # within the reference's fit
    sizes = [2000, 10000] if quick else [10000, 100000, 1000000]
    window = 20.0 if quick else SHEAR_WINDOW
    for h in steps:
        for n in sizes:
            runs = 2 if quick else 3 if n >= 1000000 else 4
            p, timing = [], []
            for seed in range(n + 1, n + runs + 1):  # other seeds for every N: independent points
                d, r = run.run(USF_CASE, [f"run.particles={n}", "run.replicas=1", f"run.seed={seed}",
                                          f"run.end={SHEAR_START + window}", f"shear.time_step={h}"])
                p.append(steady(d, "P_xy_star", SHEAR_START)[0])
                timing.append(r)
            rel = np.array(p) / ref["P0"] - 1
            mean_timing = {k: float(np.mean([t[k] for t in timing])) for k in ("seconds", "cpu_seconds")}
            mean_timing.update(load_before=timing[0]["load_before"], load_after=timing[-1]["load_after"])
            # per point: the rms error of one run, the mean deviation (bias), and the statistical error
            # of one run from the spread of the runs (independent seeds)
            run.add("shear", f"h = {h:g}", mean_timing, float(np.sqrt((rel ** 2).mean())), N=n, replicas=1,
                    threads=1, time_step=h, runs=runs, bias=float(rel.mean()), stat_error=float(rel.std(ddof=1)))
    return crossover(run.rows, ref, window)


def crossover(rows, ref, window):
    """The time-step bias against the statistical error: where they cross, and the time step that
    minimises the error at a given CPU time (printed; returned for the plot)."""
    pts = [r for r in rows if r["panel"] == "shear"]

    def bias(x):
        return abs((ref["c2"] * x ** 2 + ref["c4"] * x ** 4) / ref["P0"])

    # statistical error of a steady average over N particles and L collisions per particle: s/sqrt(N L);
    # s pooled over the points' run-to-run variances (windows of `window` rows), and s of long runs
    # (the reference's batch means)
    n_l = np.array([r["N"] * window for r in pts], dtype=float)
    s_window = float(np.sqrt(np.mean(np.array([r["stat_error"] for r in pts]) ** 2 * n_l)))
    s = ref["s"]
    # CPU time per collision = a + b/h (the run's collisions: N (SHEAR_START + window)/2), from N >= 1e5
    h = np.array([r["time_step"] for r in pts])
    per = np.array([r["cpu_seconds"] / (r["N"] * (SHEAR_START + window) / 2) for r in pts])
    big = np.array([r["N"] >= 100000 for r in pts])
    if not big.any():
        big[:] = True
    (a, b), *_ = np.linalg.lstsq(np.stack([np.ones(big.sum()), 1 / h[big]], axis=1), per[big], rcond=None)
    print(f"\nshear: time-step bias |c2 h^2 + c4 h^4|/|P0| = {abs(ref['c2'] / ref['P0']):.4f} h^2: "
          + ", ".join(f"{bias(x):.1e} at h = {x:g}" for x in (1, 0.5, 0.25, 0.2, 0.125, 0.1, 0.0625, 0.05)))
    print(f"statistical error s/sqrt(N L): s = {s:.2f} (long runs: the reference's batch means), {s_window:.2f} "
          f"(the {window:g}-row windows here: run-to-run spread); CPU per collision {a * 1e9:.0f} ns + "
          f"{b * 1e9:.1f} ns/h")
    print("N L (particles x collisions per particle averaged) | statistical error | h where bias = statistical "
          "error | CPU s at h = 0.2 | h minimising the error at that CPU time | error there, at h = 0.1, at "
          "h = 0.2")
    grid = np.linspace(0.01, 1.0, 991)
    for nl in (1e6, 1e7, 1e8, 1e9):
        sig = s / np.sqrt(nl)
        h_x = grid[np.argmin(abs(bias(grid) - sig))]
        cpu = nl / 2 * (a + b / 0.2)  # the CPU time of N L at h = 0.2; the same spent at every h
        err = np.sqrt(s ** 2 * (a + b / grid) / (2 * cpu) + bias(grid) ** 2)
        at = {x: err[np.argmin(abs(grid - x))] for x in (0.1, 0.2)}
        print(f"{nl:.0e} | {sig:.1e} | {h_x:.3f} | {cpu:.3g} | {grid[np.argmin(err)]:.3f} | {err.min():.1e}, "
              f"{at[0.1]:.1e}, {at[0.2]:.1e}")
    return {"s": s, "s_window": s_window, "window": window, "a": a, "b": b, "bias": bias}


def markdown(rows):
    """The points as docs/accuracy.md's tables: one per panel, a row per curve, a column per N; each cell
    "rms error (wall s)"."""
    out = []
    for panel in dict.fromkeys(r["panel"] for r in rows):
        pts = [r for r in rows if r["panel"] == panel]
        sizes = sorted({r["N"] for r in pts})
        out += [f"| {panel} | " + " | ".join(f"N = {n:.2g}" for n in sizes) + " |",
                "|---" * (len(sizes) + 1) + "|"]
        for curve in dict.fromkeys(r["curve"] for r in pts):
            cells = {r["N"]: f"{r['rms_error']:.1e} ({r['seconds']:.3g} s)" for r in pts if r["curve"] == curve}
            out.append(f"| {curve} | " + " | ".join(cells.get(n, "") for n in sizes) + " |")
        out.append("")
    return "\n".join(out)


def plot(rows, out, hcs_own, shear_model, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [p for p in ("maxwell", "hcs", "restitution", "shear") if any(r["panel"] == p for r in rows)]
    titles = {"maxwell": "Maxwell kernel vs exact ODEs (8 coll./particle)",
              "hcs": "hard spheres vs tests/data reference (32 coll./particle)",
              "restitution": "restitution tables vs direct integrator (4 coll./particle)",
              "shear": "shear flow: steady P*_xy vs Richardson h -> 0"}
    ylabels = {"maxwell": "rms rel. error of T_tr, T_rot", "hcs": "rms rel. error of T_tr, T_rot",
               "restitution": "rms rel. error of T_tr, T_rot", "shear": "rms rel. error of P*_xy"}
    cols = 2 if len(panels) > 1 else 1
    nrows = (len(panels) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(6 * cols, 4.6 * nrows), squeeze=False)
    for ax, panel in zip(axes.flat, panels):
        pts = [r for r in rows if r["panel"] == panel]
        for i, curve in enumerate(dict.fromkeys(r["curve"] for r in pts)):
            c = [r for r in pts if r["curve"] == curve]
            paired = "same seed" in curve
            x = [r["seconds"] for r in c]
            ax.loglog(x, [r["rms_error"] for r in c], "s--" if paired else "o-", color=f"C{i}",
                      mfc="none" if paired else None, label=curve)
            for r in c:
                ax.annotate(f"{r['N']:.2g}", (r["seconds"], r["rms_error"]), fontsize=6)
            if panel in ("maxwell", "hcs"):
                ax.loglog(x, [r["stat_error"] for r in c], ":", color=f"C{i}", lw=1,
                          label="its own standard error" if i == 0 else None)
            if panel == "shear" and shear_model:
                h = c[0]["time_step"]
                ax.axhline(shear_model["bias"](h), color=f"C{i}", ls=":", lw=0.8)
                ax.loglog(x, [np.hypot(shear_model["bias"](h), shear_model["s_window"] / np.sqrt(r["N"] * shear_model["window"]))
                              for r in c], "x", color=f"C{i}", label="bias + statistics (model)" if i == 0 else None)
        if panel == "hcs" and hcs_own:
            ax.axhline(hcs_own, color="gray", ls="-.", lw=0.8, label="reference's own error")
        ax.set_xlabel("wall time of the collisions [s]")
        ax.set_ylabel(ylabels[panel])
        ax.set_title(titles[panel], fontsize=9)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle(title, fontsize=8)
    fig.tight_layout()
    save_figure(fig, os.path.join(out, "accuracy.png"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/accuracy")
    ap.add_argument("--quick", action="store_true", help="small N only (checks the script; ~20 s)")
    ap.add_argument("--panels", default="maxwell,hcs,restitution,shear")
    a = ap.parse_args()
    panels = a.panels.split(",")
    os.makedirs(a.out, exist_ok=True)
    title = (f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, {machine()}, "
             f"load {loadavg():.2f} at the start{', --quick' if a.quick else ''}")
    print(title, flush=True)
    hcs_own, shear_model = None, None
    with tempfile.TemporaryDirectory() as scratch:
        run = Runner(a.build, scratch)
        if "maxwell" in panels:
            maxwell_panel(run, a.quick)
        if "hcs" in panels:
            hcs_own = hcs_panel(run, a.quick)
        if "restitution" in panels:
            restitution_panel(run, a.quick)
        if "shear" in panels:
            shear_model = shear_panel(run, a.quick)
    with open(os.path.join(a.out, "accuracy.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(run.rows)
    plot(run.rows, a.out, hcs_own, shear_model, title)
    print("\n" + markdown(run.rows) + "\n")
    print(f"wrote {a.out}/accuracy.csv and accuracy.png")


if __name__ == "__main__":
    main()
