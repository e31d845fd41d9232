#!/usr/bin/env python3
"""Draws the moments.csv of `roughgas run` to PNG.

usage: scripts/python3 scripts/plot.py RUN_DIR|moments.csv [--out PNG] [--x t|coll] [--logx|--linx] [--check]

Three panels against the time t or the collisions per particle (--x coll, the default):
  temperatures T_tr and T_rot (log scale; mixtures also per species),
  theta = T_rot/T_tr (mixtures also per species),
  the cumulants a20, a02, a11 and the alignment A_cw.
Theory columns (*_theory: Maxwellian approximation, Haff's law) are drawn dashed; with replicas
the X_err columns (standard error of the mean) are drawn as error bars. The x axis is logarithmic
for log-spaced outputs spanning more than two decades (override with --logx / --linx).
Writes PNG (default: next to the CSV, moments.png) atomically: a temporary file, then os.replace.
--check: exit 1 unless the picture was written and every curve the CSV supports was drawn.
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

CUMULANTS = ["a20", "a02", "a11", "A_cw"]


def draw(ax, x, d, name, logy, drawn, label=None, **style):
    """One curve with error bars from NAME_err where present; non-finite (and, on a log axis,
    non-positive) values are left out."""
    if name not in d:
        return None
    y = d[name]
    err = d.get(name + "_err")
    ok = np.isfinite(x) & np.isfinite(y)
    if logy:
        ok &= y > 0
    if not ok.any():
        return None
    label = label or name
    if err is not None:
        e = np.where(np.isfinite(err), err, 0.0)
        line = ax.errorbar(x[ok], y[ok], yerr=e[ok], label=label, capsize=2, elinewidth=0.8, **style)
    else:
        (line,) = ax.plot(x[ok], y[ok], label=label, **style)
    drawn.append(name)
    return line


def theory(ax, x, d, name, logy, drawn, color, label):
    if name not in d:
        return
    y = d[name]
    ok = np.isfinite(x) & np.isfinite(y)
    if logy:
        ok &= y > 0
    if ok.any():
        ax.plot(x[ok], y[ok], "--", color=color, lw=1.5, label=label)
        drawn.append(name)


def plot(csv_path, out_path, x_col="coll", logx=None):
    d = read_csv(csv_path)
    x_name = "coll_per_particle" if x_col == "coll" else "t"
    x = d[x_name]
    positive = x[np.isfinite(x) & (x > 0)]
    if logx is None:  # log-spaced outputs spanning more than two decades
        steps = np.diff(np.sort(positive))
        logx = len(steps) > 1 and positive.max() / positive.min() > 100 and steps[-1] > 10 * steps[0]
    xlabel = "collisions per particle" if x_col == "coll" else "t"
    species = species_names(d)
    drawn = []

    fig, axes = plt.subplots(3, 1, figsize=(7, 10), sharex=True)
    ax_t, ax_th, ax_c = axes

    # temperatures
    for q, color in (("T_tr", "C0"), ("T_rot", "C3")):
        draw(ax_t, x, d, q, True, drawn, color=color, marker=".", ms=3, lw=1)
        theory(ax_t, x, d, q + "_theory", True, drawn, color, q + " theory")
    for k, s in enumerate(species):
        for q, color in (("T_tr", f"C{2 * k + 4}"), ("T_rot", f"C{2 * k + 5}")):
            draw(ax_t, x, d, f"{q}.{s}", True, drawn, color=color, lw=0.8, alpha=0.8)
            theory(ax_t, x, d, f"{q}_theory.{s}", True, drawn, color, None)
    ax_t.set_yscale("log")
    ax_t.set_ylabel("temperature [energy]")
    ax_t.legend(fontsize=7, ncol=2)

    # theta
    th = d.get("theta")
    log_theta = th is not None and np.isfinite(th).any() and np.nanmin(th) > 0 and np.nanmax(th) / np.nanmin(th) > 30
    draw(ax_th, x, d, "theta", log_theta, drawn, color="C1", marker=".", ms=3, lw=1)
    theory(ax_th, x, d, "theta_theory", log_theta, drawn, "C1", "theta theory")
    for k, s in enumerate(species):
        color = f"C{k + 6}"
        draw(ax_th, x, d, f"theta.{s}", log_theta, drawn, color=color, lw=0.8)
        theory(ax_th, x, d, f"theta_theory.{s}", log_theta, drawn, color, None)
    if log_theta:
        ax_th.set_yscale("log")
    ax_th.set_ylabel(r"$\theta = T_{rot}/T_{tr}$")
    ax_th.legend(fontsize=7, ncol=2)

    # cumulants
    for k, q in enumerate(CUMULANTS):
        draw(ax_c, x, d, q, False, drawn, color=f"C{k}", marker=".", ms=3, lw=1)
    ax_c.axhline(0.0, color="k", lw=0.5)
    ax_c.set_ylabel("cumulants")
    ax_c.legend(fontsize=7, ncol=4)
    ax_c.set_xlabel(xlabel)

    for ax in axes:
        if logx:
            ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(os.path.basename(os.path.dirname(os.path.abspath(csv_path))) + "/" + os.path.basename(csv_path))
    fig.tight_layout()
    save_figure(fig, out_path)
    plt.close(fig)
    return d, drawn


def main(argv):
    args, opts = [], {}
    it = iter(argv[1:])
    for a in it:
        if a in ("--out", "--x"):
            opts[a] = next(it, None)
        elif a.startswith("--"):
            opts[a] = True
        else:
            args.append(a)
    if "--help" in opts or "-h" in args:
        print(__doc__)
        return 0
    if len(args) != 1 or opts.get("--x") not in (None, "t", "coll"):
        print(__doc__, file=sys.stderr)
        return 2
    csv_path = args[0]
    if os.path.isdir(csv_path):
        csv_path = os.path.join(csv_path, "moments.csv")
    if not os.path.exists(csv_path):
        print(f"plot.py: {csv_path}: no such file", file=sys.stderr)
        return 1
    out = opts.get("--out") or os.path.join(os.path.dirname(os.path.abspath(csv_path)), "moments.png")
    logx = True if "--logx" in opts else False if "--linx" in opts else None
    d, drawn = plot(csv_path, out, opts.get("--x") or "coll", logx)
    print(f"plot.py: wrote {out}")
    if "--check" in opts:
        expected = [c for c in ["T_tr", "T_rot", "theta", "T_tr_theory", "T_rot_theory", "theta_theory"] + CUMULANTS
                    if c in d and np.isfinite(d[c]).any()]
        missing = [c for c in expected if c not in drawn]
        if missing or not os.path.getsize(out) > 0:
            print(f"plot.py: --check: not drawn: {missing}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
