#!/usr/bin/env python3
"""Draws the moments.csv of `roughgas run` to PNG.

usage: scripts/python3 scripts/plot.py RUN_DIR|moments.csv [--out PNG] [--x t|coll] [--logx|--linx] [--check]

Panels against the time t or the collisions per particle (--x coll, the default), each drawn only
when the CSV has data for it:
  temperatures T_tr and T_rot (log scale when they span more than a decade; mixtures also per
  species),
  mixtures: the temperature ratios T_tr.A/T_tr.B and T_rot.A/T_rot.B (1: equipartition),
  theta = T_rot/T_tr (mixtures also per species),
  the reduced cooling rate zeta_star (the decay of T_tr per collision per particle),
  the cumulants a20, a02, a11 and the alignment A_cw.
Theory columns (*_theory: Maxwellian approximation, Haff's law) are drawn dashed, the first Sonine
approximation of the scaled cooling state (*_sonine: theta, zeta_star, a20, a02, a11 of one species,
constant) dash-dotted, each in the color of its measured curve; with replicas
the X_err columns (standard error of the mean) are drawn as shaded bands, mean +- X_err (error
bars at points without finite neighbours, e.g. a curve of one point). The panels named
(temperatures, ratios, theta, zeta, cumulants) are printed with the output path. Curves
that carry no information are left out, and a note under the panels says which: all-NaN or
all-zero columns, measured columns constant to round-off (1e-12 relative), and, when T_rot (of the
gas or of a species) is constant so (smooth grains: the spins never change), its T_rot, theta,
T_rot ratios and, for the whole gas, a02, a11 and A_cw. When T_rot changes by less than 10 % while
T_tr falls tenfold or more (nearly smooth contacts, e.g. ice's small friction), a note says so and
why theta grows. The title gives the case's key parameters
from the CSV's header (case name, kind, N, replicas, restitution per pair, a mixture's species,
the contact model's material); the axes carry the columns' units from the header's "# units:"
line, in the symbols of its "unit system:" note when it has one (else the base names time,
energy, ... that the header uses). The x axis is logarithmic for log-spaced outputs spanning more
than two decades (override with --logx / --linx).
Writes PNG (default: next to the CSV, moments.png) atomically: a temporary file, then os.replace.
--check: exit 1 unless the picture was written, every curve the CSV supports (as above) was drawn
and no other curve was.
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

CUMULANTS = ["a20", "a02", "a11", "A_cw"]
# Mixture-wide quantities that describe the spins: meaningless while the spins never change.
SPIN_CUMULANTS = ["a02", "a11", "A_cw"]
ROUND_OFF = 1e-12  # relative spread below which a measured column is constant by construction


def informative(y):
    """Some finite value, and not all of them exactly zero."""
    v = y[np.isfinite(y)]
    return v.size > 0 and bool(np.any(v != 0))


def constant(y):
    """At least two finite values, equal to round-off."""
    v = y[np.isfinite(y)]
    return v.size >= 2 and float(np.ptp(v)) <= ROUND_OFF * float(np.max(np.abs(v)))


def measured_of(name):
    """The measured column a theory column belongs to (T_tr_theory.small -> T_tr.small,
    T_tr.a/T_tr.b_theory -> T_tr.a/T_tr.b, theta_sonine -> theta); None for a measured column."""
    if name.endswith("_sonine"):
        return name.removesuffix("_sonine")
    return name.replace("_theory", "") if "_theory" in name else None


def omitted(d, species):
    """{column: why it is not drawn} for the columns of the panels that carry no information."""
    why = {}
    frozen = [s for s in [""] + ["." + s for s in species] if "T_rot" + s in d and constant(d["T_rot" + s])]
    for s in frozen:  # the spins never change (smooth grains): rotational quantities say nothing
        note = "T_rot%s constant: the spins never change" % s
        for c in ("T_rot" + s, "theta" + s, "T_rot_theory" + s, "theta_theory" + s):
            why[c] = note
        if s == "":
            for c in SPIN_CUMULANTS + ["theta_sonine"] + [q + "_sonine" for q in SPIN_CUMULANTS]:
                why[c] = note
        for c in d:
            if s and c.startswith("T_rot.") and "/" in c and not c.endswith("_err"):
                a, b = c.removesuffix("_theory").split("/", 1)
                if s[1:] in (a[len("T_rot."):], b[len("T_rot."):]):
                    why[c] = note
    for c, y in d.items():
        if c in why or c.endswith("_err"):
            continue
        if not informative(y):
            why[c] = "no data (NaN or 0)"
        elif measured_of(c) is None and constant(y):
            why[c] = "constant"
    for c in d:  # a theory curve goes with its measured curve
        m = measured_of(c)
        if m is not None and c not in why and m in why:
            why[c] = why[m]
    return why


def band(ax, x, y, err, logy, label, color, **style):
    """A measured curve: the mean as a line with markers, with the standard error (replicas) as a
    shaded band mean +- err. Non-finite values (and on a log axis non-positive ones) are left out.
    True when something was drawn."""
    ok = np.isfinite(x) & np.isfinite(y)
    if logy:
        ok &= y > 0
    if not ok.any():
        return False
    ax.plot(x[ok], y[ok], label=label, color=color, **style)
    if err is not None:
        e = np.where(np.isfinite(err), err, 0.0)[ok]
        lo, hi = y[ok] - e, y[ok] + e
        if logy:
            lo = np.where(lo > 0, lo, np.nan)
        ax.fill_between(x[ok], lo, hi, color=color, alpha=0.25, lw=0)
        # a band has no width at a point without finite neighbours: an error bar there
        alone = ok & ~np.r_[False, ok[:-1]] & ~np.r_[ok[1:], False]
        if alone.any():
            ax.errorbar(x[alone], y[alone], yerr=np.where(np.isfinite(err), err, 0.0)[alone], fmt="none",
                        ecolor=color, capsize=2, elinewidth=0.8)
    return True


def dashed(ax, x, y, logy, label, color, style="--"):
    ok = np.isfinite(x) & np.isfinite(y)
    if logy:
        ok &= y > 0
    if not ok.any():
        return False
    ax.plot(x[ok], y[ok], style, color=color, lw=1.5, label=label)
    return True


def spins_note(d, why):
    """Why T_rot stays flat while T_tr falls, when it does: the rate at which collisions change the
    spins' energy vanishes with 1 + beta (the tangential restitution near -1: nearly smooth
    contacts), so a T_rot that changes by less than 10 % while T_tr falls tenfold or more means the
    contacts hardly grip, and theta = T_rot/T_tr grows as T_tr falls. The note's lines; none otherwise
    (nor for smooth grains, whose T_rot never changes: omitted() names them)."""
    if "T_tr" not in d or "T_rot" not in d or "T_rot" in why:
        return []
    tr, rot = d["T_tr"], d["T_rot"]
    ok = np.isfinite(tr) & np.isfinite(rot) & (tr > 0) & (rot > 0)
    if ok.sum() < 2:
        return []
    tr, rot = tr[ok], rot[ok]
    fall = tr[0] / tr[-1]
    change = abs(rot[-1] / rot[0] - 1)
    if fall < 10 or change > 0.1:
        return []
    return ["T_rot changes by %.2g %% while T_tr falls %.2g-fold: the contacts hardly grip the spins" % (100 * change, fall),
            "(tangential restitution near \u22121: nearly smooth), so \u03b8 = T_rot/T_tr grows as T_tr falls"]


def panels_of(d, species):
    """The panels and their curves: (key, [(column, color, label or None)]); the theory of a
    column, NAME_theory, is drawn dashed in its color."""
    sp_colors = [("C2", "C4"), ("C9", "C6"), ("C8", "C5"), ("C7", "C1")]
    temps = [("T_tr", "C0", "T_tr"), ("T_rot", "C3", "T_rot")]
    thetas = [("theta", "C1", "theta")]
    for k, s in enumerate(species):
        tr, rot = sp_colors[k % len(sp_colors)]
        temps += [(f"T_tr.{s}", tr, None), (f"T_rot.{s}", rot, None)]
        thetas.append((f"theta.{s}", tr, None))
    ratios = [c for c in d if "/" in c and not c.endswith("_err") and not c.endswith("_theory")]
    ratios = [(c, "C0" if c.startswith("T_tr.") else "C3", None) for c in ratios]
    if len(ratios) > 2:  # more than two species: a color per pair
        ratios = [(c, f"C{k % 10}", lab) for k, (c, _, lab) in enumerate(ratios)]
    return [
        ("temperatures", temps),
        ("ratios", ratios),
        ("theta", thetas),
        ("zeta", [("zeta_star", "C5", "zeta_star")]),
        ("cumulants", [(q, f"C{k}", q) for k, q in enumerate(CUMULANTS)]),
    ]


def theory_name(c):
    """NAME_theory for NAME (T_tr.small -> T_tr_theory.small; ratios and plain names: + _theory)."""
    if "/" in c or "." not in c:
        return c + "_theory"
    base, s = c.split(".", 1)
    return f"{base}_theory.{s}"


def log_spaced(x):
    """Log-spaced outputs spanning more than two decades: what a logarithmic x axis is for."""
    positive = x[np.isfinite(x) & (x > 0)]
    steps = np.diff(np.sort(positive))
    return bool(len(steps) > 1 and positive.max() / positive.min() > 100 and steps.max() > 10 * steps[0])


def plot(csv_path, out_path, x_col="coll", logx=None):
    d = read_csv(csv_path)
    h = read_header(csv_path)
    x_name = "coll_per_particle" if x_col == "coll" else "t"
    x = d[x_name]
    if logx is None:
        logx = log_spaced(x)
    if logx:
        x = np.where(x > 0, x, np.nan)
    xlabel = "collisions per particle" if x_col == "coll" else label_with_unit("t", column_unit(h, "t"))
    species = species_names(d)
    why = omitted(d, species)
    replicas = any(c.endswith("_err") and c != "t_err" and c != "coll_per_particle_err" for c in d)

    panels = []
    for key, curves in panels_of(d, species):
        keep = [(c, color, lab) for c, color, lab in curves if c in d and c not in why]
        if keep:
            panels.append((key, keep))
    n = max(len(panels), 1)
    title = case_summary(h) or [os.path.basename(os.path.dirname(os.path.abspath(csv_path))) + "/" +
                                os.path.basename(csv_path)]
    notes = []
    if replicas:
        notes.append("shaded: mean \u00b1 standard error over the replicas")
    if any(c.endswith("_theory") or "_theory." in c for c in d):
        notes.append("dashed: Maxwellian theory")
    if any(c.endswith("_sonine") for c in d):
        notes.append("dash-dotted: first Sonine approximation of the scaled cooling state")
    left_out = {}
    for _, curves in panels_of(d, species):
        for c, _, _ in curves:
            if c in d and c in why:
                left_out.setdefault(why[c], []).append(c)
    notes += ["not drawn (%s): %s" % (reason, ", ".join(cs)) for reason, cs in left_out.items()]
    notes += spins_note(d, why)
    foot = 0.17 * len(notes)  # inches of the notes under the panels and of the title above them
    head = 0.17 * len(title) + 0.1
    height = 2.5 * n + 0.6 + foot + head
    fig, axes = plt.subplots(n, 1, figsize=(7.5, height), sharex=True, squeeze=False)
    axes = axes[:, 0]
    drawn = {}

    for ax, (key, curves) in zip(axes, panels):
        logy = False
        if key in ("temperatures", "theta"):  # log scale when the values span decades
            v = np.concatenate([d[c][np.isfinite(d[c])] for c, _, _ in curves])
            logy = v.size > 0 and v.min() > 0 and v.max() / v.min() > (10 if key == "temperatures" else 30)
        names = drawn.setdefault(key, [])
        for c, color, lab in curves:
            if band(ax, x, d[c], d.get(c + "_err"), logy, lab or c, color, marker=".", ms=3, lw=1):
                names.append(c)
            t = theory_name(c)
            if t in d and t not in why and dashed(ax, x, d[t], logy, None, color):
                names.append(t)
            t = c + "_sonine"
            if t in d and t not in why and dashed(ax, x, d[t], logy, None, color, "-."):
                names.append(t)
        if logy:
            ax.set_yscale("log")
        if key == "temperatures":
            unit = column_unit(h, "T_tr")
            ax.set_ylabel(label_with_unit("temperature", unit))
        elif key == "ratios":
            ax.axhline(1.0, color="k", lw=0.6, ls=":", label="equipartition")
            ax.set_ylabel("temperature ratio")
        elif key == "theta":
            ax.set_ylabel(r"$\theta = T_{rot}/T_{tr}$")
        elif key == "zeta":
            ax.set_ylabel(r"$\zeta^* = -\Delta \ln T_{tr}\,/\,\Delta$(coll./particle)", fontsize=9)
        else:
            ax.axhline(0.0, color="k", lw=0.5)
            ax.set_ylabel("cumulants")
        ax.legend(fontsize=7, ncol=2 if key != "cumulants" else 4)
    if not panels:
        axes[0].text(0.5, 0.5, "no column of this CSV varies", ha="center", va="center", transform=axes[0].transAxes)
    finish_figure(fig, axes, xlabel, logx, title, notes, foot, height, out_path)
    return d, drawn, why


def finish_figure(fig, axes, xlabel, logx, title, notes, foot, height, out_path):
    """The panels' shared x axis and grid, the title above them and the notes under them (foot
    inches, 0.17 per line, of a figure `height` inches tall), written to out_path atomically."""
    axes[-1].set_xlabel(xlabel)
    for ax in axes:
        if logx:
            ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("\n".join(title), fontsize=9, y=1 - 0.05 / height, va="top")
    for k, line in enumerate(notes):
        fig.text(0.01, (foot - 0.17 * k - 0.12) / height, line, fontsize=7, ha="left", va="bottom")
    fig.tight_layout(rect=(0, (foot + 0.05) / height, 1, 1))  # tight_layout makes room for the title
    save_figure(fig, out_path)
    plt.close(fig)


def expected_curves(d, why):
    """Every curve the CSV supports, found from its column names (not from the panels, which this
    checks): the quantities the docstring lists, per species and as ratios, with their theory,
    less those that carry no information."""
    names = ["T_tr", "T_rot", "theta", "zeta_star"] + CUMULANTS
    names += [f"{q}.{s}" for s in species_names(d) for q in ("T_tr", "T_rot", "theta")]
    names += [c for c in d if "/" in c and not c.endswith("_err") and not c.endswith("_theory")]
    return [n for c in names for n in (c, theory_name(c), c + "_sonine") if n in d and n not in why]


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
    d, drawn, why = plot(csv_path, out, opts.get("--x") or "coll", logx)
    print(f"plot.py: wrote {out} (panels: {', '.join(drawn) or 'none'})")
    if "--check" in opts:
        expected = expected_curves(d, why)
        got = [c for names in drawn.values() for c in names]
        missing = [c for c in expected if c not in got]
        # a panel whose every curve is constant, or a curve the CSV does not support, is a defect too
        extra = [c for c in got if c not in expected]
        empty = [k for k, names in drawn.items() if all(measured_of(c) is None and constant(d[c]) for c in names)]
        if missing or extra or empty or not os.path.getsize(out) > 0:
            print(f"plot.py: --check: not drawn: {missing}; drawn without data to support them: {extra}; "
                  f"panels of constant curves only: {empty}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
