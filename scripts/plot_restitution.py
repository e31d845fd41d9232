#!/usr/bin/env python3
"""Draws the output of `roughgas restitution` to PNG: the project's versions of Brilliantov et al.
(1996) Figs. 1 and 2.

usage: scripts/python3 scripts/plot_restitution.py OUT_DIR [--bridges]
  OUT_DIR/normal.csv      -> OUT_DIR/normal.png      eps^N against g_N (cm/s), with the measured ice law
                                                     eps = (v/v_c)^-0.234, v_c = 0.0077 cm/s (Bridges et al. 1984)
                                                     drawn dashed over 0.05-5 cm/s when --bridges is given
  OUT_DIR/tangential.csv  -> OUT_DIR/tangential.png  eps^T over the (g_N, g_T) plane, with the line eps^T = 0
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure  # noqa: E402




def bridges(v_cm_s):
    return (v_cm_s / 0.0077) ** -0.234


def plot_normal(out_dir, with_bridges):
    d = read_csv(os.path.join(out_dir, "normal.csv"))
    g_cm = d["g_N"] * 100.0
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.semilogx(g_cm, d["eps_N"], "-", lw=2, label="viscoelastic contact (this model)")
    if with_bridges:
        v = np.logspace(np.log10(0.05), np.log10(5.0), 100)
        ax.semilogx(v, bridges(v), "k--", label=r"ice, Bridges et al.: $(v/v_c)^{-0.234}$")
    ax.set_xlabel(r"$g^N$ [cm/s]")
    ax.set_ylabel(r"$\epsilon^N$")
    ax.set_ylim(0, 1.02)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="lower left")
    ax.set_title("Normal restitution (Brilliantov et al. 1996, Fig. 1)")
    fig.tight_layout()
    path = os.path.join(out_dir, "normal.png")
    save_figure(fig, path, dpi=120)
    plt.close(fig)
    return path


def plot_tangential(out_dir):
    d = read_csv(os.path.join(out_dir, "tangential.csv"))
    gn, gt = np.unique(d["g_N"]), np.unique(d["g_T"])
    eps = np.full((len(gt), len(gn)), np.nan)
    i = np.searchsorted(gn, d["g_N"])
    j = np.searchsorted(gt, d["g_T"])
    eps[j, i] = d["eps_T"]
    fig, ax = plt.subplots(figsize=(6, 4.8))
    mesh = ax.pcolormesh(gn * 100, gt * 100, eps, cmap="RdBu_r", vmin=-1, vmax=1, shading="nearest")
    if len(gn) > 1 and len(gt) > 1:
        ax.contour(gn * 100, gt * 100, eps, levels=[0.0], colors="k", linewidths=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"$g^N$ [cm/s]")
    ax.set_ylabel(r"$g^T$ [cm/s]")
    fig.colorbar(mesh, ax=ax, label=r"$\epsilon^T$ ($\beta = -\epsilon^T$)")
    ax.set_title(r"Tangential restitution (Brilliantov et al. 1996, Fig. 2); black: $\epsilon^T = 0$")
    fig.tight_layout()
    path = os.path.join(out_dir, "tangential.png")
    save_figure(fig, path, dpi=120)
    plt.close(fig)
    return path


def main(argv):
    if "-h" in argv[1:] or "--help" in argv[1:]:
        print(__doc__)
        return 0
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = args[0]
    written = []
    if os.path.exists(os.path.join(out_dir, "normal.csv")):
        written.append(plot_normal(out_dir, "--bridges" in argv))
    if os.path.exists(os.path.join(out_dir, "tangential.csv")):
        written.append(plot_tangential(out_dir))
    if not written:
        print(f"plot_restitution: no normal.csv or tangential.csv in {out_dir}", file=sys.stderr)
        return 1
    for w in written:
        print(f"plot_restitution: wrote {w}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
