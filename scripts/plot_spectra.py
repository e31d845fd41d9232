#!/usr/bin/env python3
"""Draws the Fourier spectra of a periodic box run ([spectra]) to PNG.

usage: scripts/python3 scripts/plot_spectra.py RUN_DIR [--out PNG] [--times N] [--check]

Reads RUN_DIR/spectra.csv and, for the temperature T, RUN_DIR/moments.csv's T_tr (taken about the
box's mean velocity: where a flow has grown, T holds its energy too). Two panels:
  - against collisions per particle, at the smallest wave number of the shells and along each axis
    with more than two cells: E_perp / T (the transverse current, whose growth is the shear mode
    leaving the homogeneous state: vortices) and S (the structure factor, whose growth at small k
    is clustering); a uniform gas has 1 for both (E_perp / T: for one species, or species at one
    temperature);
  - the shell spectra S(k) and E_perp(k) / T at N times spread over the run (default 4), k in units
    of the smallest shell's.
With replicas the values are the replicas' means (spectra.csv's X_err columns are not drawn).
Writes PNG (default: RUN_DIR/spectra.png) atomically.
--check: exit 1 unless both panels were drawn.
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


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="PNG file (default: RUN_DIR/spectra.png)")
    parser.add_argument("--times", type=int, default=4, help="shell spectra at this many times (default 4)")
    parser.add_argument("--check", action="store_true", help="exit 1 unless both panels were drawn")
    args = parser.parse_args(argv[1:])
    path = os.path.join(args.run_dir, "spectra.csv")
    if not os.path.exists(path):
        print(f"plot_spectra: {path} does not exist (a box run with [spectra] writes it)", file=sys.stderr)
        return 2
    s = read_csv(path)
    m = read_csv(os.path.join(args.run_dir, "moments.csv"))
    # spectra.csv has one block per moments.csv row, in order: the block's temperature is the row's.
    rows = len(m["t"])
    block = len(s["t"]) // rows
    T = np.repeat(m["T_tr"], block)
    cpp = s["coll_per_particle"]
    fig, ax = plt.subplots(2, 1, figsize=(7, 9))
    drawn = set()
    shells = s["axis"] == 0
    first = s["n"][shells].min() if shells.any() else 1
    for axis, n, label in ((0, first, f"shell {first:.0f}"), (1, 1, "along x, n = 1"), (2, 1, "along y, n = 1"),
                           (3, 1, "along z, n = 1")):
        sel = (s["axis"] == axis) & (s["n"] == n)
        if not sel.any() or not np.isfinite(T[sel]).all() or not (T[sel] > 0).all():
            continue
        k = s["k"][sel][0]
        ax[0].semilogy(cpp[sel], s["E_perp"][sel] / T[sel], "-", lw=1.2, label=f"E_perp/T, {label} (k = {k:.3g})")
        ax[0].semilogy(cpp[sel], s["S"][sel], "--", lw=1.2, label=f"S, {label}")
        drawn.add(0)
    ax[0].axhline(1.0, color="k", lw=0.6)
    ax[0].set_xlabel("collisions per particle")
    ax[0].set_ylabel("E_perp / T,  S  (ideal gas: 1)")
    if shells.any():
        blocks = np.unique(cpp[shells])
        k1 = s["k"][shells & (s["n"] == first)][0]
        picks = np.unique(np.linspace(0, len(blocks) - 1, max(1, args.times)).round().astype(int))
        for j, c in enumerate(blocks[picks]):
            sel = shells & (cpp == c)
            colour = plt.cm.viridis(j / max(1, len(picks) - 1))
            ax[1].loglog(s["k"][sel] / k1, s["S"][sel], "--", color=colour, lw=1.2, label=f"S at {c:.3g}")
            ok = T[sel] > 0
            ax[1].loglog(s["k"][sel][ok] / k1, s["E_perp"][sel][ok] / T[sel][ok], "-", color=colour, lw=1.2,
                         label=f"E_perp/T at {c:.3g}")
            drawn.add(1)
        ax[1].axhline(1.0, color="k", lw=0.6)
        ax[1].set_xlabel("k / k_1 (k_1: the smallest shell's k)")
        ax[1].set_ylabel("shell spectra")
    for a in ax:
        a.grid(alpha=0.3, which="both")
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize=7)
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.run_dir))}: Fourier spectra (spectra.csv)", fontsize=9)
    out = args.out or os.path.join(args.run_dir, "spectra.png")
    fig.tight_layout()
    save_figure(fig, out)
    plt.close(fig)
    print(f"plot_spectra: wrote {out}")
    if args.check and len(drawn) < 2:
        print(f"plot_spectra: only {len(drawn)} of 2 panels drawn", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
