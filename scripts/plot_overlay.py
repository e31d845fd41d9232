#!/usr/bin/env python3
"""Draws several runs' moments.csv on shared axes, to compare them at the same time t.

usage: scripts/python3 scripts/plot_overlay.py RUN_DIR|moments.csv RUN_DIR|moments.csv [...]
           [--x t|coll] [--labels LABEL ...] [--compare ratio|difference] [--out PNG] [--logx|--linx] [--check]

Panels, each run in its own colour, against the time t (--x t, the default) or the collisions per
particle (--x coll):
  temperatures T_tr (solid) and T_rot (dashed) (log scale when they span more than a decade),
  theta = T_rot/T_tr,
  the cumulants a20 (solid), a02 (dashed) and a11 (dotted),
each quantity drawn where every run has the column and some run has information in it (as
scripts/plot.py decides: smooth grains' T_rot, theta and spin cumulants, all-NaN columns, ... are left
out and named under the panels); with replicas the X_err columns are shaded bands, mean +- X_err, as
plot.py draws them.
The last panel compares each run with the first at the rows where their x coincide (within 1e-9
relative): T_tr and T_rot of the run over the first's (--compare ratio, the default; 1 where they
agree) or less the first's (--compare difference; 0 where they agree), with the errors of both
combined (sqrt(e1^2 + e2^2) for the difference, the relative errors so for the ratio). Rows of runs
clocked by run.end_time at the same output times coincide in t; runs clocked by run.end coincide
in coll_per_particle, not in t (a hotter gas collides more often per unit time). Without two
coinciding rows the panel is left out and a note says why.
--labels: one label per run (default: the run directories' names). The title gives the first run's
case parameters (scripts/roughgas_csv.py case_summary). Writes PNG (default overlay.png in the
working directory) atomically.
--check: exit 1 unless the picture was written, every quantity the runs share (as above) was drawn
for every run that has information in it, and the comparison panel was drawn when rows coincide.
Exit 2 for bad usage (fewer than two runs, a label count that does not match, a missing moments.csv,
a run without the --x column).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header, column_unit, label_with_unit, case_summary, species_names  # noqa: E402
from plot import band, finish_figure, omitted, log_spaced  # noqa: E402

# (panel, [(column, line style)]): the quantities every run of a homogeneous or box case has.
PANELS = [
    ("temperatures", [("T_tr", "-"), ("T_rot", "--")]),
    ("theta", [("theta", "-")]),
    ("cumulants", [("a20", "-"), ("a02", "--"), ("a11", ":")]),
]
COINCIDE = 1e-9  # relative distance within which two rows' x are the same time


def moments_path(arg):
    return os.path.join(arg, "moments.csv") if os.path.isdir(arg) else arg


def coinciding(xa, xb):
    """Index pairs (i, j) with xa[i] and xb[j] the same to COINCIDE (relative; exact at 0)."""
    pairs = []
    if not np.isfinite(xb).any():
        return pairs
    for i, x in enumerate(xa):
        if not np.isfinite(x):
            continue
        # NaN (t = 0 on a log axis) is never the nearest: np.argmin would pick it first.
        j = int(np.argmin(np.where(np.isfinite(xb), np.abs(xb - x), np.inf)))
        if abs(xb[j] - x) <= COINCIDE * max(abs(x), abs(xb[j])):
            pairs.append((i, j))
    return pairs


def compare(a, b, ea, eb, how):
    """a over b (or a less b) with the combined standard error (None without errors)."""
    if how == "difference":
        value = a - b
        err = None if ea is None and eb is None else np.hypot(0 if ea is None else ea, 0 if eb is None else eb)
        return value, err
    with np.errstate(divide="ignore", invalid="ignore"):
        value = a / b
        if ea is None and eb is None:
            return value, None
        rel = np.hypot(0 if ea is None else ea / a, 0 if eb is None else eb / b)
        return value, np.abs(value) * rel


def shared_curves(runs):
    """{column: [run indices with information in it]} for the PANELS' columns every run has, and
    {reason: [columns]} of those no run has information in."""
    whys = [omitted(d, species_names(d)) for d, _ in runs]
    curves, left_out = {}, {}
    for _, columns in PANELS:
        for c, _ in columns:
            if not all(c in d for d, _ in runs):
                continue
            have = [k for k, why in enumerate(whys) if c not in why]
            if have:
                curves[c] = have
            else:
                left_out.setdefault(whys[0][c], []).append(c)
    return curves, left_out


def plot(paths, labels, out_path, x_col="t", logx=None, how="ratio"):
    runs = [(read_csv(p), read_header(p)) for p in paths]
    x_name = "t" if x_col == "t" else "coll_per_particle"
    xs = [d[x_name] for d, _ in runs]
    if logx is None:
        logx = any(log_spaced(x) for x in xs)
    if logx:
        xs = [np.where(x > 0, x, np.nan) for x in xs]
    curves, left_out = shared_curves(runs)
    matches = [coinciding(xs[0], xs[k]) for k in range(len(runs))]
    comparable = [k for k in range(1, len(runs)) if len(matches[k]) >= 2]
    compared = [c for c in ("T_tr", "T_rot") if c in curves and 0 in curves[c]]
    panels = [(key, [(c, ls) for c, ls in cols if c in curves]) for key, cols in PANELS]
    panels = [(key, cols) for key, cols in panels if cols]
    if comparable and compared:
        panels.append(("compare", [(c, "-" if c == "T_tr" else "--") for c in compared]))
    notes = []
    if any(c.endswith("_err") and c not in ("t_err", "coll_per_particle_err") for d, _ in runs for c in d):
        notes.append("shaded: mean \u00b1 standard error over the replicas")
    notes += ["not drawn (%s): %s" % (why, ", ".join(cs)) for why, cs in left_out.items()]
    missing = [labels[k] for k in range(1, len(runs)) if k not in comparable]
    compare_note = None
    if missing:
        compare_note = "not compared with %s (fewer than two rows at the same %s): %s" % (
            labels[0], x_name, ", ".join(missing))
        notes.append(compare_note)
    title = (case_summary(runs[0][1]) or [])[:2] + ["runs: " + ", ".join(labels)]
    foot, head = 0.17 * len(notes), 0.17 * len(title) + 0.1
    n = max(len(panels), 1)
    height = 2.5 * n + 0.6 + foot + head
    fig, axes = plt.subplots(n, 1, figsize=(7.5, height), sharex=True, squeeze=False)
    axes = axes[:, 0]
    drawn = {}
    unit_t = column_unit(runs[0][1], "t")
    for ax, (key, cols) in zip(axes, panels):
        names = drawn.setdefault(key, [])
        if key == "compare":
            for c, ls in cols:
                for k in comparable:
                    d0, dk = runs[0][0], runs[k][0]
                    i = np.array([p[0] for p in matches[k]])
                    j = np.array([p[1] for p in matches[k]])
                    e0, ek = d0.get(c + "_err"), dk.get(c + "_err")
                    y, err = compare(dk[c][j], d0[c][i], None if ek is None else ek[j],
                                     None if e0 is None else e0[i], how)
                    if band(ax, xs[0][i], y, err, False, f"{c}: {labels[k]} {'/' if how == 'ratio' else '-'} "
                            f"{labels[0]}", f"C{k % 10}", ls=ls, marker=".", ms=3, lw=1):
                        names.append(f"{c}.{k}")
            ax.axhline(1.0 if how == "ratio" else 0.0, color="k", lw=0.6, ls=":")
            ax.set_ylabel(f"{'ratio' if how == 'ratio' else 'difference'} at the same {x_name}")
        else:
            logy = False
            if key in ("temperatures", "theta"):
                v = np.concatenate([runs[k][0][c][np.isfinite(runs[k][0][c])] for c, _ in cols for k in curves[c]])
                logy = v.size > 0 and v.min() > 0 and v.max() / v.min() > (10 if key == "temperatures" else 30)
            for c, ls in cols:
                for k in curves[c]:
                    d = runs[k][0]
                    if band(ax, xs[k], d[c], d.get(c + "_err"), logy, f"{c}: {labels[k]}", f"C{k % 10}",
                            ls=ls, marker=".", ms=3, lw=1):
                        names.append(f"{c}.{k}")
            if logy:
                ax.set_yscale("log")
            if key == "temperatures":
                ax.set_ylabel(label_with_unit("temperature", column_unit(runs[0][1], "T_tr")))
            elif key == "theta":
                ax.set_ylabel(r"$\theta = T_{rot}/T_{tr}$")
            else:
                ax.axhline(0.0, color="k", lw=0.5)
                ax.set_ylabel("cumulants")
        ax.legend(fontsize=7, ncol=2)
    if not panels:
        axes[0].text(0.5, 0.5, "no quantity the runs share varies", ha="center", va="center",
                     transform=axes[0].transAxes)
    xlabel = label_with_unit("t", unit_t) if x_col == "t" else "collisions per particle"
    finish_figure(fig, axes, xlabel, logx, title, notes, foot, height, out_path)
    if compare_note:  # on stdout too
        print(f"plot_overlay.py: {compare_note}")
    expected = [f"{c}.{k}" for c, ks in curves.items() for k in ks]
    if comparable:
        expected += [f"{c}.{k}" for c in compared for k in comparable]
    return drawn, expected


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run directories (or their moments.csv), two or more")
    parser.add_argument("--x", choices=("t", "coll"), default="t",
                        help="x axis: the time t (default) or the collisions per particle")
    parser.add_argument("--labels", nargs="+", help="one label per run (default: the directories' names)")
    parser.add_argument("--compare", choices=("ratio", "difference"), default="ratio",
                        help="the last panel: each run's T_tr, T_rot over (ratio) or less (difference) the first's")
    parser.add_argument("--out", default="overlay.png", help="PNG to write (default overlay.png)")
    scale = parser.add_mutually_exclusive_group()
    scale.add_argument("--logx", action="store_true", help="logarithmic x axis")
    scale.add_argument("--linx", action="store_true", help="linear x axis (default: log for log-spaced rows)")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless every shared quantity and the comparison were drawn")
    a = parser.parse_args(argv[1:])
    paths = [moments_path(r) for r in a.runs]
    labels = a.labels or [os.path.basename(os.path.dirname(os.path.abspath(p))) for p in paths]
    if len(paths) < 2:
        print("plot_overlay.py: two or more runs needed", file=sys.stderr)
        return 2
    if len(labels) != len(paths):
        print(f"plot_overlay.py: --labels: {len(labels)} labels for {len(paths)} runs", file=sys.stderr)
        return 2
    for p in paths:
        if not os.path.exists(p):
            print(f"plot_overlay.py: {p}: no such file", file=sys.stderr)
            return 2
        x_name = "t" if a.x == "t" else "coll_per_particle"
        if x_name not in read_header(p)["columns"]:
            print(f"plot_overlay.py: {p}: no column {x_name}", file=sys.stderr)
            return 2
    logx = True if a.logx else False if a.linx else None
    drawn, expected = plot(paths, labels, a.out, a.x, logx, a.compare)
    print(f"plot_overlay.py: wrote {a.out} (panels: {', '.join(drawn) or 'none'})")
    if a.check:
        got = [c for names in drawn.values() for c in names]
        missing = [c for c in expected if c not in got]
        if missing or not os.path.getsize(a.out) > 0:
            print(f"plot_overlay.py: --check: not drawn (column.run): {missing}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
