#!/usr/bin/env python3
"""Draws uniform shear flow results of roughgas to PNG.

usage: scripts/python3 scripts/plot_shear.py RUN_DIR|moments.csv [--out PNG] [--check]
       scripts/python3 scripts/plot_shear.py --sweep SWEEP_DIR|sweep.csv [--out PNG] [--check]

Run (`roughgas run` of a kind = "shear" case): the approach to the steady state against the
collisions per particle, four panels: T_tr and T_rot (log scale; mixtures also per species),
theta, the reduced pressure tensor P*_xx, P*_yy, P*_zz, P*_xy, and a*, eta*. Error bars from the
X_err columns (replicas). When steady.csv sits next to the CSV, the start of the steady window is
a vertical line and the steady averages are dotted horizontal lines.
Sweep (`roughgas sweep`): the rheology against the swept key (the first column of sweep.csv):
P*_ij, the normal stress differences N1*, N2*, theta, a* and eta*, with their batch-means errors;
points whose steady state was not reached are drawn hollow.
Writes PNG (default: moments_shear.png or sweep.png next to the CSV) atomically.
--check: exit 1 unless the picture was written and every quantity the CSV has was drawn.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, species_names  # noqa: E402
from atomic_output import save_figure  # noqa: E402

STRESS = ["P_xx_star", "P_yy_star", "P_zz_star", "P_xy_star"]


def curve(ax, x, d, name, drawn, logy=False, label=None, **style):
    if name not in d:
        return
    y = d[name]
    ok = np.isfinite(y) & np.isfinite(x)
    if logy:
        ok &= y > 0
    if not ok.any():
        return
    err = d.get(name + "_err")
    ax.errorbar(x[ok], y[ok], yerr=None if err is None else err[ok], label=label or name, capsize=2, lw=1, **style)
    drawn.add(name)


def save(fig, out):
    fig.tight_layout()
    save_figure(fig, out)
    plt.close(fig)


def plot_run(csv_path, out):
    d = read_csv(csv_path)
    x = d["coll_per_particle"]
    steady_path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "steady.csv")
    st = read_csv(steady_path) if os.path.exists(steady_path) else None
    fig, axes = plt.subplots(4, 1, figsize=(7, 11), sharex=True)
    drawn = set()
    ax = axes[0]
    curve(ax, x, d, "T_tr", drawn, logy=True)
    curve(ax, x, d, "T_rot", drawn, logy=True)
    for s in species_names(d):
        curve(ax, x, d, "T_tr." + s, drawn, logy=True, ls="--")
        curve(ax, x, d, "T_rot." + s, drawn, logy=True, ls=":")
    ax.set_yscale("log")
    ax.set_ylabel("temperature")
    curve(axes[1], x, d, "theta", drawn)
    for s in species_names(d):
        curve(axes[1], x, d, "theta." + s, drawn, ls="--")
    axes[1].set_ylabel("theta = T_rot/T_tr")
    for q in STRESS:
        curve(axes[2], x, d, q, drawn)
    axes[2].set_ylabel("P*_ij = P_ij/(n T_tr)")
    curve(axes[3], x, d, "a_star", drawn)
    curve(axes[3], x, d, "eta_star", drawn)
    axes[3].set_ylabel("a*, eta*")
    axes[3].set_xlabel("collisions per particle")
    if st is not None:
        reached = st["steady"][0] == 1
        for ax, names in zip(axes, [["T_tr", "T_rot"], ["theta"], STRESS, ["a_star", "eta_star"]]):
            ax.axvline(st["steady_from"][0], color="k", lw=0.8, ls="--" if reached else ":")
            for n in names:
                if n in st and np.isfinite(st[n][0]):
                    ax.axhline(st[n][0], color="gray", lw=0.6, ls=":")
        axes[0].set_title("steady from %.3g collisions per particle%s" %
                          (st["steady_from"][0], "" if reached else " (NOT reached)"), fontsize=9)
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=3)
    fig.suptitle(os.path.basename(os.path.dirname(os.path.abspath(csv_path))) + "/" + os.path.basename(csv_path))
    save(fig, out)
    expected = [c for c in ["T_tr", "T_rot", "theta", "a_star", "eta_star"] + STRESS if c in d and np.isfinite(d[c]).any()
                and (not c.startswith("T_") or (d[c][np.isfinite(d[c])] > 0).any())]
    return [c for c in expected if c not in drawn]


def plot_sweep(csv_path, out):
    d = read_csv(csv_path)
    with open(csv_path) as f:
        key = next(line for line in f if not line.startswith("#")).split(",")[0].strip()
    x = d[key]
    ok = d["steady"] == 1
    fig, axes = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
    drawn = set()

    def pts(ax, name, marker):
        if name not in d or not np.isfinite(d[name]).any():
            return
        err = d.get(name + "_err")
        color = "C%d" % (len(ax.lines) % 10)
        for sel, face in ((ok, color), (~ok, "none")):
            if sel.any():
                ax.errorbar(x[sel], d[name][sel], yerr=None if err is None else err[sel], fmt=marker, capsize=2,
                            color=color, mfc=face, label=name if face == color or not ok.any() else None)
        ax.plot(x, d[name], lw=0.6, color=color, alpha=0.5)
        drawn.add(name)

    for q, m in zip(STRESS + ["N1_star", "N2_star"], "osD^vx"):
        pts(axes[0], q, m)
    axes[0].set_ylabel("P*_ij, N1*, N2*")
    pts(axes[1], "theta", "o")
    axes[1].set_ylabel("theta")
    pts(axes[2], "a_star", "o")
    pts(axes[2], "eta_star", "s")
    axes[2].set_ylabel("a*, eta*")
    axes[2].set_xlabel(key)
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=3)
    fig.suptitle("steady states against " + key + " (hollow: not steady)")
    save(fig, out)
    expected = [c for c in STRESS + ["N1_star", "N2_star", "theta", "a_star", "eta_star"]
                if c in d and np.isfinite(d[c]).any()]
    return [c for c in expected if c not in drawn]


def main(argv):
    args, opts = [], {}
    it = iter(argv[1:])
    for a in it:
        if a == "--out":
            opts[a] = next(it, None)
        elif a.startswith("--"):
            opts[a] = True
        else:
            args.append(a)
    if "--help" in opts or "-h" in args:
        print(__doc__)
        return 0
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    sweep = "--sweep" in opts
    path = args[0]
    if os.path.isdir(path):
        path = os.path.join(path, "sweep.csv" if sweep else "moments.csv")
    if not os.path.exists(path):
        print(f"plot_shear.py: {path}: no such file", file=sys.stderr)
        return 1
    out = opts.get("--out") or os.path.join(os.path.dirname(os.path.abspath(path)),
                                            "sweep.png" if sweep else "moments_shear.png")
    missing = plot_sweep(path, out) if sweep else plot_run(path, out)
    print(f"plot_shear.py: wrote {out}")
    if "--check" in opts and (missing or not os.path.getsize(out) > 0):
        print(f"plot_shear.py: --check: not drawn: {missing}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
