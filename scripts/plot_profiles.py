#!/usr/bin/env python3
"""Draws the profiles of a spatially resolved roughgas run to PNG.

usage: scripts/python3 scripts/plot_profiles.py RUN_DIR [--out PNG] [--from C] [--check]

Reads RUN_DIR/steady_profiles.csv when the run has one (a driven steady state: the profiles
averaged over the steady window, with batch-means error bars), else averages the blocks of
RUN_DIR/profiles.csv from C collisions per particle on (default: the second half of the run; error
bars from the scatter of the blocks, which are correlated: a lower bound). Four panels against the
profile axis: the density n, the flow velocity u (its components that are not zero within their
errors), the temperatures T_tr and T_rot, and the fluxes along the axis (the pressure tensor's
column P_xa, P_ya, P_za, kinetic plus collisional, and the heat flux q_a). With walls, the walls'
values from walls.csv (averaged over the same rows) are drawn as markers at the walls.
Writes PNG (default: RUN_DIR/profiles.png) atomically.
--check: exit 1 unless the picture was written with all four panels drawn.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure  # noqa: E402


def header_notes(path):
    """The '#' lines that describe the box (the first one naming it)."""
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            if "box" in line and "mean free paths" in line:
                return line[1:].strip()
    return ""


def averaged_blocks(path, start):
    """{field: (mean, err)} per bin from profiles.csv's blocks from `start` collisions per particle."""
    d = read_csv(path)
    bins = int(d["bin"].max()) + 1
    cpp = d["coll_per_particle"].reshape(-1, bins)[:, 0]
    if start is None:
        start = 0.5 * cpp[-1]
    keep = cpp >= start
    out = {}
    for name, col in d.items():
        blocks = col.reshape(-1, bins)[keep]
        k = max(1, blocks.shape[0])
        out[name] = (np.nanmean(blocks, axis=0), np.nanstd(blocks, axis=0) / np.sqrt(k))
    return out, start, cpp[keep]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="PNG file (default: RUN_DIR/profiles.png)")
    parser.add_argument("--from", dest="start", type=float, help="average the blocks from this coll_per_particle on")
    parser.add_argument("--check", action="store_true", help="exit 1 unless every panel was drawn")
    args = parser.parse_args(argv[1:])
    steady = os.path.join(args.run_dir, "steady_profiles.csv")
    blocks = os.path.join(args.run_dir, "profiles.csv")
    if not os.path.exists(blocks):
        print(f"plot_profiles: {blocks} does not exist (a run with [domain] writes it)", file=sys.stderr)
        return 2
    if os.path.exists(steady) and args.start is None:
        d = read_csv(steady)
        f = {n: (d[n], d.get(n + "_err", np.zeros_like(d[n]))) for n in d if not n.endswith("_err")}
        what = "steady window (steady_profiles.csv)"
        rows = None
    else:
        f, start, rows = averaged_blocks(blocks, args.start)
        what = f"mean of {len(rows)} blocks from {start:.4g} collisions per particle"
    axis = next(a for a in "xyz" if a in f)
    x = f[axis][0]
    fig, ax = plt.subplots(4, 1, figsize=(7, 11), sharex=True)
    drawn = set()

    def curve(a, name, label=None, **style):
        if name not in f:
            return
        y, e = f[name]
        ok = np.isfinite(y)
        if not ok.any():
            return
        a.errorbar(x[ok], y[ok], yerr=e[ok], capsize=2, lw=1, label=label or name, **style)
        drawn.add(a)

    curve(ax[0], "n")
    ax[0].set_ylabel("n [1/volume]")
    for c in "xyz":
        y, e = f["u_" + c]
        if np.any(np.abs(y) > 3 * np.maximum(e, 1e-300)):
            curve(ax[1], "u_" + c)
    if ax[1] not in drawn:  # no flow: draw u along the axis, all zero within errors
        curve(ax[1], "u_" + axis)
    ax[1].set_ylabel("u [length/time]")
    curve(ax[2], "T_tr")
    curve(ax[2], "T_rot")
    ax[2].set_ylabel("T [energy]")
    for c in "xyz":
        name = f"P_{c}{axis}"
        if name not in f and f"P_{axis}{c}" in f:
            name = f"P_{axis}{c}"
        y, e = f[name]
        pc = "Pc_" + name[2:]
        total = y + f[pc][0] if pc in f else y
        ok = np.isfinite(total)
        if c != axis and ok.any():
            ax[3].errorbar(x[ok], total[ok], yerr=e[ok], capsize=2, lw=1, label=f"P_{c}{axis} (kinetic + collisional)")
            drawn.add(ax[3])
    curve(ax[3], "q_" + axis, label=f"q_{axis}")
    ax[3].set_ylabel("fluxes along " + axis)
    ax[3].set_xlabel(axis + " [length]")
    walls = os.path.join(args.run_dir, "walls.csv")
    if os.path.exists(walls):
        w = read_csv(walls)
        sel = np.isfinite(w["coll_per_particle"]) & (w["coll_per_particle"] > 0)
        if rows is not None:
            sel &= np.isin(w["coll_per_particle"], rows)
        L = x[-1] + (x[1] - x[0]) / 2 if len(x) > 1 else 2 * x[0]
        for side, pos in (("lower", 0.0), ("upper", L)):
            for c in "xyz":
                col = f"{axis}_{side}.P_{c}{axis}"
                if c != axis and col in w and sel.any():
                    ax[3].plot([pos], [np.mean(w[col][sel])], "k^")
            col = f"{axis}_{side}.q_{axis}"
            if col in w and sel.any():
                ax[3].plot([pos], [np.mean(w[col][sel])], "ks")
        ax[3].plot([], [], "k^", label="walls: P (walls.csv)")
        ax[3].plot([], [], "ks", label="walls: q (walls.csv)")
    for a in ax:
        a.grid(alpha=0.3)
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize=8)
    note = header_notes(blocks)
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.run_dir))}: {what}\n{note[:110]}", fontsize=8)
    out = args.out or os.path.join(args.run_dir, "profiles.png")
    fig.tight_layout()
    save_figure(fig, out)
    plt.close(fig)
    print(f"plot_profiles: wrote {out}")
    if args.check and len(drawn) < 4:
        print(f"plot_profiles: only {len(drawn)} of 4 panels drawn", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
