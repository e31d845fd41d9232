#!/usr/bin/env python3
"""Draws uniform shear flow results of roughgas to PNG.

usage: scripts/python3 scripts/plot_shear.py RUN_DIR|moments.csv [--out PNG] [--check]
       scripts/python3 scripts/plot_shear.py --sweep SWEEP_DIR|sweep.csv [--out PNG] [--check]

Run (`roughgas run` of a kind = "shear" case): the approach to the steady state against the
collisions per particle: T_tr and T_rot (log scale when they span more than a decade; mixtures
also per species), a mixture's temperature ratios T_tr.A/T_tr.B and T_rot.A/T_rot.B, theta (mixtures
also per species), the reduced pressure tensor P*_xx, P*_yy, P*_zz, P*_xy, and a*, eta*. With
replicas the X_err columns (standard error of the mean) are shaded bands, mean +- X_err. When
steady.csv sits next to the CSV, the start of the steady window is a vertical line and the steady
averages are dotted horizontal lines.
Sweep (`roughgas sweep`): the steady (or scaled) state against the swept key (the first column of
sweep.csv), with the batch-means errors as error bars and a shaded band; points whose steady state
was not reached are drawn hollow. The panels are those of the headline quantities sweep.csv has:
P*_ij with the normal stress differences N1*, N2*; theta (mixtures also per species); a mixture's
temperature ratios; a* and eta*; for a cooling case's sweep (no a* column) the reduced cooling rate
zeta_star and the cumulants a20, a02, a11, A_cw; theory columns (*_theory) dashed.
Both: a panel or curve is drawn only when its column carries information (as in plot.py: not
all-NaN or all-zero, a measured column not constant to round-off, no theta or T_rot when the spins
never change); the title gives the case's key parameters from the CSV's header (a sweep's swept key
left out), and the temperature axis its unit from the header's "# units:" line (see plot.py).
Writes PNG (default: moments_shear.png or sweep.png next to the CSV) atomically.
--check: exit 1 unless the picture was written, every quantity the CSV supports (as above) was
drawn and no other curve was.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header, species_names, column_unit, label_with_unit, case_summary  # noqa: E402
from atomic_output import save_figure  # noqa: E402
from plot import omitted, band, dashed, theory_name  # noqa: E402

STRESS = ["P_xx_star", "P_yy_star", "P_zz_star", "P_xy_star"]
SP_COLORS = ["C2", "C4", "C9", "C6", "C8", "C5"]


def panels_of(d, sweep):
    """(key, y label, [(column, color)]) of every panel a run (sweep: a sweep) can have, in order."""
    species = species_names(d)
    temps = [("T_tr", "C0"), ("T_rot", "C3")]
    thetas = [("theta", "C1")]
    for k, s in enumerate(species):
        temps += [(f"T_tr.{s}", SP_COLORS[(2 * k) % 6]), (f"T_rot.{s}", SP_COLORS[(2 * k + 1) % 6])]
        thetas.append((f"theta.{s}", SP_COLORS[(2 * k) % 6]))
    ratios = [c for c in d if "/" in c and not c.endswith("_err") and not c.endswith("_theory")]
    ratios = [(c, ("C0" if c.startswith("T_tr.") else "C3") if len(ratios) <= 2 else f"C{k % 10}")
              for k, c in enumerate(ratios)]
    stress = [(q, f"C{k}") for k, q in enumerate(STRESS + (["N1_star", "N2_star"] if sweep else []))]
    panels = [] if sweep else [("temperatures", "temperature", temps)]
    if sweep:
        panels.append(("stress", "P*_ij, N1*, N2*", stress))
    panels += [("ratios", "temperature ratio", ratios), ("theta", r"$\theta = T_{rot}/T_{tr}$", thetas)]
    if not sweep:
        panels.append(("stress", "P*_ij = P_ij/(n T_tr)", stress))
    panels.append(("rheology", "a*, eta*", [("a_star", "C0"), ("eta_star", "C1")]))
    if sweep and "a_star" not in d:  # a cooling case's sweep: the scaled state
        panels += [("zeta", r"$\zeta^*$ (decay of T_tr per collision per particle)", [("zeta_star", "C5")]),
                   ("cumulants", "cumulants", [(q, f"C{k}") for k, q in enumerate(["a20", "a02", "a11", "A_cw"])])]
    return panels


def kept_panels(d, why, sweep):
    out = []
    for key, ylabel, curves in panels_of(d, sweep):
        keep = [(c, color) for c, color in curves if c in d and c not in why]
        if keep:
            out.append((key, ylabel, keep))
    return out


def expected(d, why, sweep):
    """Every curve the CSV supports, found from its column names (not from the panels, which this
    checks): the quantities the docstring lists, with their theory, less those that carry no
    information."""
    species = species_names(d)
    names = ["theta"] + [f"theta.{s}" for s in species] + STRESS + ["a_star", "eta_star"]
    names += [c for c in d if "/" in c and not c.endswith("_err") and not c.endswith("_theory")]
    if sweep:
        names += ["N1_star", "N2_star"]
        if "a_star" not in d:
            names += ["zeta_star", "a20", "a02", "a11", "A_cw"]
    else:
        names += ["T_tr", "T_rot"] + [f"{q}.{s}" for s in species for q in ("T_tr", "T_rot")]
    return [n for c in names for n in (c, theory_name(c)) if n in d and n not in why]


def figure(d, h, why, sweep, skip=()):
    panels = kept_panels(d, why, sweep)
    title = case_summary(h, skip)
    notes = []
    left_out = {}
    for _, _, curves in panels_of(d, sweep):
        for c, _ in curves:
            if c in d and c in why:
                left_out.setdefault(why[c], []).append(c)
    notes += ["not drawn (%s): %s" % (reason, ", ".join(cs)) for reason, cs in left_out.items()]
    return panels, title, notes


def layout(n, title, notes, extra_title=0):
    foot = 0.17 * len(notes) + 0.05  # inches of the notes under the panels
    height = 2.3 * n + 0.6 + foot + 0.17 * (len(title) + extra_title)
    fig, axes = plt.subplots(max(n, 1), 1, figsize=(7.5, height), sharex=True, squeeze=False)
    return fig, axes[:, 0], foot, height


def finish(fig, axes, title, notes, foot, height, out):
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=3)
    fig.suptitle("\n".join(title), fontsize=9, y=1 - 0.05 / height, va="top")
    for k, line in enumerate(notes):
        fig.text(0.01, (foot - 0.17 * k - 0.17) / height, line, fontsize=7, ha="left", va="bottom")
    fig.tight_layout(rect=(0, foot / height, 1, 1))
    save_figure(fig, out)
    plt.close(fig)


def check(d, why, sweep, drawn):
    want = expected(d, why, sweep)
    return [c for c in want if c not in drawn] + [c + " (no data to support it)" for c in drawn if c not in want]


def plot_run(csv_path, out):
    d = read_csv(csv_path)
    h = read_header(csv_path)
    why = omitted(d, species_names(d))
    x = d["coll_per_particle"]
    steady_path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "steady.csv")
    st = read_csv(steady_path) if os.path.exists(steady_path) else None
    panels, title, notes = figure(d, h, why, False)
    if any(c.endswith("_err") and c not in ("t_err", "coll_per_particle_err") for c in d):
        notes.insert(0, "shaded: mean \u00b1 standard error over the replicas")
    if st is not None:
        reached = st["steady"][0] == 1
        notes.insert(0, "steady window from %.3g collisions per particle%s (vertical line); dotted: its averages" %
                     (st["steady_from"][0], "" if reached else ", NOT reached"))
    fig, axes, foot, height = layout(len(panels), title, notes)
    drawn = []
    for ax, (key, ylabel, curves) in zip(axes, panels):
        logy = False
        if key == "temperatures":  # log scale when the temperatures span decades
            v = np.concatenate([d[c][np.isfinite(d[c])] for c, _ in curves])
            logy = v.size > 0 and v.min() > 0 and v.max() / v.min() > 10
            ylabel = label_with_unit(ylabel, column_unit(h, "T_tr"))
        for c, color in curves:
            if band(ax, x, d[c], d.get(c + "_err"), logy, c, color, marker=".", ms=3, lw=1):
                drawn.append(c)
            t = theory_name(c)
            if t in d and t not in why and dashed(ax, x, d[t], logy, None, color):
                drawn.append(t)
            if st is not None and c in st and np.isfinite(st[c][0]):
                ax.axhline(st[c][0], color=color, lw=0.7, ls=":")
        if key == "ratios":
            ax.axhline(1.0, color="k", lw=0.6, ls=":", label="equipartition")
        if logy:
            ax.set_yscale("log")
        ax.set_ylabel(ylabel)
        if st is not None:
            ax.axvline(st["steady_from"][0], color="k", lw=0.8, ls="--" if st["steady"][0] == 1 else ":")
    axes[-1].set_xlabel("collisions per particle")
    finish(fig, axes, title, notes, foot, height, out)
    return check(d, why, False, drawn)


def plot_sweep(csv_path, out):
    d = read_csv(csv_path)
    h = read_header(csv_path)
    key = h["columns"][0]
    why = omitted(d, species_names(d))
    x = d[key]
    ok = d["steady"] == 1
    order = np.argsort(x)
    panels, title, notes = figure(d, h, why, True, skip=(key,))
    sweep_note = next((n for n in h["notes"] if n.startswith("sweep of")), "")
    state = "steady state" if "a_star" in d else "scaled state"  # shear, cooling
    title.insert(0, (sweep_note.split(";")[0] if sweep_note else "sweep of " + key) + f": {state}s")
    notes.insert(0, f"error bars and shaded: batch-means errors; hollow: {state} not reached"
                 + ("; dashed: Maxwellian theory" if any("_theory" in c for c in d) else ""))
    fig, axes, foot, height = layout(len(panels), title, notes)
    drawn = []

    def pts(ax, name, color, marker):
        y = d[name]
        err = d.get(name + "_err")
        for sel, face in ((ok, color), (~ok, "none")):
            if sel.any():
                ax.errorbar(x[sel], y[sel], yerr=None if err is None else err[sel], fmt=marker, capsize=2,
                            color=color, mfc=face, label=name if face == color or not ok.any() else None)
        band(ax, x[order], y[order], None if err is None else err[order], False, None, color, lw=0.6, alpha=0.6)
        drawn.append(name)

    for ax, (pkey, ylabel, curves) in zip(axes, panels):
        for k, (c, color) in enumerate(curves):
            pts(ax, c, color, "osD^vx"[k % 6])
            t = theory_name(c)
            if t in d and t not in why and dashed(ax, x[order], d[t][order], False, None, color):
                drawn.append(t)
        if pkey == "ratios":
            ax.axhline(1.0, color="k", lw=0.6, ls=":", label="equipartition")
        ax.set_ylabel(ylabel)
    axes[-1].set_xlabel(label_with_unit(key, column_unit(h, key)))  # the swept key's unit, from sweep.csv
    finish(fig, axes, title, notes, foot, height, out)
    return check(d, why, True, drawn)


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
    problems = plot_sweep(path, out) if sweep else plot_run(path, out)
    print(f"plot_shear.py: wrote {out}")
    if "--check" in opts and (problems or not os.path.getsize(out) > 0):
        print(f"plot_shear.py: --check: not drawn, or drawn without data: {problems}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
