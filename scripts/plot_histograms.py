#!/usr/bin/env python3
"""Draws the histograms.csv of `roughgas run` (run.histogram_every > 0) to PNG.

usage: scripts/python3 scripts/plot_histograms.py RUN_DIR|histograms.csv [--out PNG] [--check]

Three panels: the reduced speed |c*|, the reduced spin |w*| and c*.w* (observables/histograms.hpp),
one curve per histogram time (colour from early to late; mixtures: one line style per species),
the Maxwellian reference dashed, on a log axis so that the tails show. With replicas the f_X_err
columns are drawn as error bars. Writes PNG (default: histograms.png next to the CSV) atomically.
--check: exit 1 unless the picture was written and every histogram of the CSV was drawn.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure  # noqa: E402

PANELS = [("c_star", "f_c", r"$|c^*|$"), ("w_star", "f_w", r"$|w^*|$"), ("cw_star", "f_cw", r"$c^*\cdot w^*$")]
STYLES = ["-", "--", ":", "-."]


def main(argv):
    if "-h" in argv or "--help" in argv:
        print(__doc__)
        return 0
    args = [a for a in argv if not a.startswith("--")]
    check = "--check" in argv
    out = None
    if "--out" in argv:
        out = argv[argv.index("--out") + 1]
        args.remove(out)
    if len(args) != 1:
        sys.exit(__doc__)
    path = args[0]
    if os.path.isdir(path):
        path = os.path.join(path, "histograms.csv")
    out = out or os.path.join(os.path.dirname(path), "histograms.png")
    d = read_csv(path)
    times = np.unique(d["coll_per_particle"])
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(times)))
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    drawn = 0
    expected = 0
    for ax, (x_name, f_name, label) in zip(axes, PANELS):
        stems = sorted(c for c in d if (c == f_name or c.startswith(f_name + ".")) and not c.endswith("_err"))
        for k, t in enumerate(times):
            rows = d["coll_per_particle"] == t
            x = d[x_name][rows]
            for s, stem in enumerate(stems):
                expected += 1
                y = d[stem][rows]
                if not np.any(np.isfinite(y) & (y > 0)):
                    continue  # no rotation: undefined
                err = d.get(stem + "_err")
                species = stem[len(f_name) + 1:] if "." in stem else ""
                labelled = k % max(1, len(times) // 5) == 0 or k == len(times) - 1
                name = f"{t:g} coll/particle" + (f" {species}" if species else "") if labelled else None
                y = np.where(y > 0, y, np.nan)
                ax.plot(x, y, ls=STYLES[s % len(STYLES)], color=colours[k], lw=1, label=name)
                if err is not None:  # one standard error, clipped to the log axis
                    lo = y - err[rows]
                    ax.fill_between(x, np.where(lo > 0, lo, y / 10), y + err[rows], color=colours[k], alpha=0.2,
                                    lw=0)
                drawn += 1
        ref = d[f_name + "_maxwell"][d["coll_per_particle"] == times[0]]
        ax.plot(d[x_name][d["coll_per_particle"] == times[0]], ref, "k--", lw=1, label="Maxwellian")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("probability density")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(os.path.relpath(path))
    fig.tight_layout()
    save_figure(fig, out, dpi=100)
    print(f"plot_histograms.py: wrote {out}")
    if check and (not os.path.exists(out) or drawn == 0):
        sys.exit("plot_histograms.py --check: nothing drawn")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
