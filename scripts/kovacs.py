#!/usr/bin/env python3
"""Measures the Kovacs hump of a driven run and draws it beside the Maxwellian theory's.

usage: scripts/python3 scripts/kovacs.py RUN_DIR|moments.csv [--out PNG] [--window W]
           [--bootstrap K] [--seed S] [--check]

RUN_DIR is a run driven by a thermostat whose schedule ends with the switch of the Kovacs protocol
(cases/kovacs_rough.toml): at t_w, the schedule's last time, the drive becomes the one whose steady
state has the T_tr the gas has at t_w, so that T_tr starts at its final value; the spins (theta not
at its steady value) make it leave that value and come back: the hump.

Measured after t_w, on the replicas' mean T_tr:
  T_tr(t_w)   the row at t_w (or the line between the rows around it);
  T_tr(inf)   the mean of the rows in the last quarter of the run after t_w, with its standard
              error from the replicas (the X_err columns' rows averaged, treated as one error: the
              rows of one replica are correlated);
  the hump    the extremum of the parabola fitted by least squares to the rows within +-W/2 of the
              rows' extremum after t_w (--window W, default a twelfth of the time after t_w): its
              height over T_tr(inf) and its time after t_w.
The errors of the hump's height and time are standard deviations over K bootstrap resamples of the
replicas (--bootstrap, default 1000; DIR/replicas/moments_R.csv, each resample's mean curve measured
as above), which carry the correlation of each replica's rows in time; without per-replica files
none is given. The Maxwellian theory's hump is measured the same way on the T_tr_theory column (the
driven equations through the schedule from the case's temperatures; docs/reference.md), the same
estimator on exact rows.

The picture: T_tr and T_rot with their error bands and the theory dashed, the switch at t_w and
the hump marked; theta; written atomically (default kovacs.png in the working directory).
--check: exit 1 unless the picture was written and the measured hump has the theory's sign and
stands out of its error (height > 2 errors). Exit 2 for bad usage: a missing moments.csv, a run
without a thermostat schedule, fewer than ten rows after t_w, no T_tr_theory column.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header, replica_column  # noqa: E402
from atomic_output import save_figure  # noqa: E402


def moments_path(arg):
    return os.path.join(arg, "moments.csv") if os.path.isdir(arg) else arg


def measure(t, T, tw, window, fit=True):
    """(T_tr(t_w), T_tr(inf), hump height over T_tr(inf), hump time after t_w) of one curve."""
    T_w = float(np.interp(tw, t, T))
    after = t >= tw
    ta, Ta = t[after], T[after]
    late = ta >= tw + 0.75 * (ta[-1] - tw)
    T_inf = float(Ta[late].mean())
    sign = 1.0 if np.max(Ta - T_inf) >= -np.min(Ta - T_inf) else -1.0
    k = int(np.argmax(sign * (Ta - T_inf)))
    if not fit:
        return T_w, T_inf, float(Ta[k] - T_inf), float(ta[k] - tw)
    near = np.abs(ta - ta[k]) <= window / 2
    if near.sum() < 3:
        return T_w, T_inf, float(Ta[k] - T_inf), float(ta[k] - tw)
    c2, c1, c0 = np.polyfit(ta[near] - ta[k], Ta[near], 2)
    x = -c1 / (2 * c2) if c2 != 0 else 0.0
    x = min(max(x, -window / 2), window / 2)
    return T_w, T_inf, float(c0 + c1 * x + c2 * x * x - T_inf), float(ta[k] + x - tw)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="the run directory (or its moments.csv)")
    parser.add_argument("--out", default="kovacs.png", help="PNG to write (default kovacs.png)")
    parser.add_argument("--window", type=float, help="width of the parabola's fit around the hump (time; "
                        "default a twelfth of the time after t_w)")
    parser.add_argument("--bootstrap", type=int, default=1000, metavar="K",
                        help="bootstrap resamples of the replicas for the errors (default 1000)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the bootstrap's resampling (default 1)")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless the hump has the theory's sign and exceeds two errors")
    a = parser.parse_args(argv[1:])
    path = moments_path(a.run)
    if not os.path.exists(path):
        print(f"kovacs.py: {path}: no such file", file=sys.stderr)
        return 2
    d = read_csv(path)
    sched = read_header(path)["resolved"].get("thermostat", {}).get("schedule")
    if not sched or len(sched) < 2:
        print(f"kovacs.py: {path}: no thermostat schedule with a switch (the Kovacs protocol's t_w is its last "
              "time)", file=sys.stderr)
        return 2
    if "T_tr_theory" not in d:
        print(f"kovacs.py: {path}: no column T_tr_theory", file=sys.stderr)
        return 2
    tw = float(sched[-1][0])
    t, T = d["t"], d["T_tr"]
    if (t >= tw).sum() < 10:
        print(f"kovacs.py: {path}: fewer than ten rows after t_w = {tw:.6g}", file=sys.stderr)
        return 2
    window = a.window if a.window else (t[-1] - tw) / 12
    T_w, T_inf, h, th = measure(t, T, tw, window)
    Tw_th, Tinf_th, h_th, th_th = measure(t, d["T_tr_theory"], tw, window)
    late = (t >= tw) & (t >= tw + 0.75 * (t[-1] - tw))
    T_inf_err = float(d["T_tr_err"][late].mean()) if "T_tr_err" in d else None
    h_err = th_err = None
    reps = replica_column(path, "T_tr", len(t))
    if reps is not None and a.bootstrap > 1:
        rng = np.random.default_rng(a.seed)
        res = np.array([measure(t, reps[:, rng.integers(0, reps.shape[1], reps.shape[1])].mean(axis=1), tw, window)
                        for _ in range(a.bootstrap)])
        h_err, th_err = float(np.std(res[:, 2], ddof=1)), float(np.std(res[:, 3], ddof=1))

    fig, axes = plt.subplots(2, 1, figsize=(7.5, 7), sharex=True)
    for name, col in (("T_tr", "tab:red"), ("T_rot", "tab:blue")):
        y, e = d[name], d.get(name + "_err", np.zeros_like(d[name]))
        axes[0].plot(t, y, color=col, label=f"{name}: DSMC")
        axes[0].fill_between(t, y - e, y + e, color=col, alpha=0.3, lw=0)
        if name + "_theory" in d:
            axes[0].plot(t, d[name + "_theory"], "--", color=col, lw=1, label=f"{name}: Maxwellian theory")
    y, e = d["theta"], d.get("theta_err", np.zeros_like(d["theta"]))
    axes[1].plot(t, y, color="k", label="DSMC")
    axes[1].fill_between(t, y - e, y + e, color="k", alpha=0.25, lw=0)
    if "theta_theory" in d:
        axes[1].plot(t, d["theta_theory"], "--", color="k", lw=1, label="Maxwellian theory")
    for ax in axes:
        ax.axvline(tw, color="0.5", lw=0.8, ls=":")
    axes[0].axhline(T_inf, color="tab:red", lw=0.6, ls=":")
    axes[0].plot([tw + th], [T_inf + h], "o", color="tab:red", ms=4)
    axes[0].set_yscale("log")
    axes[0].set_ylabel("temperature")
    axes[1].set_ylabel("theta = T_rot/T_tr")
    axes[1].set_xlabel("t")
    axes[0].legend(fontsize=8)
    axes[1].legend(fontsize=8)
    pm = f" ± {h_err:.2g}" if h_err is not None else ""
    axes[0].set_title(f"switch at t_w = {tw:.6g}: hump {h:+.4f}{pm} over T_tr(inf) = {T_inf:.4f} "
                      f"(theory {h_th:+.4f})", fontsize=9)
    # an inset of T_tr after t_w, where the hump is a few per cent
    ins = axes[0].inset_axes([0.55, 0.45, 0.42, 0.3])
    after = t >= tw
    ins.plot(t[after], T[after], color="tab:red", lw=1)
    ins.fill_between(t[after], (T - d.get("T_tr_err", 0 * T))[after], (T + d.get("T_tr_err", 0 * T))[after],
                     color="tab:red", alpha=0.3, lw=0)
    ins.plot(t[after], d["T_tr_theory"][after], "--", color="tab:red", lw=1)
    ins.axhline(T_inf, color="tab:red", lw=0.6, ls=":")
    ins.axvline(tw, color="0.5", lw=0.8, ls=":")
    ins.tick_params(labelsize=7)
    fig.tight_layout()
    save_figure(fig, a.out)
    plt.close(fig)

    err = lambda x: f" +- {x:.2g}" if x is not None else ""  # noqa: E731
    print(f"kovacs.py: wrote {a.out}")
    print(f"  t_w = {tw:.6g}: T_tr(t_w) = {T_w:.5g} (theory {Tw_th:.5g}); T_tr(inf) = {T_inf:.5g}{err(T_inf_err)} "
          f"(theory {Tinf_th:.5g})")
    print(f"  hump: {h:+.5f}{err(h_err)} = {h / T_inf:+.4f} T_tr(inf) at t - t_w = {th:.4g}{err(th_err)}; "
          f"theory {h_th:+.5f} = {h_th / Tinf_th:+.4f} T_tr(inf) at t - t_w = {th_th:.4g}")
    if a.check:
        ok = os.path.getsize(a.out) > 0 and np.sign(h) == np.sign(h_th) and (h_err is None or abs(h) > 2 * h_err)
        if not ok:
            print("kovacs.py: --check: the hump does not have the theory's sign or does not exceed two errors",
                  file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
