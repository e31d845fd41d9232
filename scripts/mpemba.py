#!/usr/bin/env python3
"""Measures the Mpemba crossing of two driven runs and draws it beside the Maxwellian theory's.

usage: scripts/python3 scripts/mpemba.py HOT_RUN COLD_RUN [--labels HOT COLD] [--out PNG]
           [--bootstrap K] [--seed S] [--check]

HOT_RUN and COLD_RUN are run directories (or their moments.csv) of the same gas under the same
thermostat, started from two states with T_tr,hot(0) > T_tr,cold(0) (cases/mpemba_hot.toml and
cases/mpemba_cold.toml, from the states that cases/mpemba_prepare_*.toml save) and clocked by
run.end_time with the same output times, so that their rows coincide in t (within 1e-9 relative).

The crossing. D(t) = T_tr,hot(t) - T_tr,cold(t) (the replicas' means) changes sign at the first row
where its sign differs from the sign at t = 0; the crossing time t_c is where the straight line
through that row and the one before is zero. Its error is the standard deviation of t_c over K
bootstrap resamples of the replicas (--bootstrap, default 1000; each run's replicas drawn with
replacement from DIR/replicas/moments_R.csv, the crossing found as above in each resample), which
carries the correlation of each replica's rows in time; a resample whose D does not change sign is
counted and left out. Without per-replica files (one replica, or a run whose replicas/ directory is
gone) the error is that of the line's zero from the X_err columns: sqrt(e_hot^2 + e_cold^2) at the
crossing over |dD/dt|.

The theory. The Maxwellian two-temperature equations of equal rough spheres (observables/theory.hpp,
docs/model.md), with the thermostat of HOT_RUN's resolved case (white noise of strength xi0^2 and
rotational share eps, or a Langevin bath; constant or by schedule):
  dT_tr/dt  = G [-A T_tr^{3/2} + B T_tr^{1/2} T_rot] + (1 - eps) m xi0^2   (+ 2 gamma (T_b - T_tr))
  dT_rot/dt = G [ B T_tr^{3/2} - C T_tr^{1/2} T_rot] + eps m xi0^2         (+ 2 gamma_rot (T_b - T_rot))
  A = (1 - alpha^2)/4 + eta (1 - eta), B = eta^2/q, C = (eta/q)(1 - eta/q), eta = q(1 + beta)/(2(1 + q)),
  G = (16/3) n sigma^2 sqrt(pi/m),
integrated (scipy DOP853, relative tolerance 1e-10) from each run's first row, T_tr(0) and T_rot(0)
as measured (the prepared states, not the cases' species temperatures), and the crossing of the two
theoretical T_tr found by brentq. One species, constant alpha and beta.

The picture: T_tr of both runs with their error bands (replicas' mean +- X_err) and the theory's
trajectories dashed, the crossings marked; theta = T_rot/T_tr; D(t) with its band. Written
atomically (default mpemba.png in the working directory).

Prints the two crossing times, their ratio and, with the error, how many errors apart they are.
--check: exit 1 unless the picture was written and both the runs and the theory cross. Exit 2 for
bad usage: a missing moments.csv, rows that do not coincide in t, fewer than three rows, equal
T_tr at t = 0, runs under different thermostats or of different gases, a case the theory does not
cover (several species, a restitution other than constant).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.optimize import brentq  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv, read_header, replica_column, species_names  # noqa: E402
from atomic_output import save_figure  # noqa: E402

COINCIDE = 1e-9  # relative distance within which two rows' t are the same time


class UsageError(Exception):
    pass


def moments_path(arg):
    return os.path.join(arg, "moments.csv") if os.path.isdir(arg) else arg


def gas_of(resolved, path):
    """(alpha, beta, q, m, sigma, n, thermostat table) of a resolved case the theory covers."""
    species = resolved.get("species", [])
    coll = resolved.get("collision", {})
    if len(species) != 1:
        raise UsageError(f"{path}: {len(species)} species; the theory here is that of one species")
    if coll.get("model") != "constant":
        raise UsageError(f"{path}: collision.model = {coll.get('model')!r}; the theory needs constant alpha, beta")
    if "thermostat" not in resolved:
        raise UsageError(f"{path}: no [thermostat]: a Mpemba crossing needs two driven runs")
    s = species[0]
    return (coll["alpha"], coll["beta"], s["inertia"], s["mass"], 2 * s["radius"], resolved["run"]["density"],
            resolved["thermostat"])


def drive(th):
    """The thermostat's drive as [(t_k, x_k)]: strength (white noise) or bath temperature (Langevin)."""
    if "schedule" in th:
        return [(float(t), float(x)) for t, x in th["schedule"]]
    return [(0.0, float(th["strength"] if th.get("kind", "white_noise") == "white_noise" else th["bath_temperature"]))]


def theory_rhs(gas, x):
    """The right-hand side of the two-temperature equations with the drive at x."""
    alpha, beta, q, m, sigma, n, th = gas
    eta = q * (1 + beta) / (2 * (1 + q))
    A = (1 - alpha**2) / 4 + eta * (1 - eta)
    B = eta**2 / q
    C = (eta / q) * (1 - eta / q)
    G = 16 / 3 * n * sigma**2 * math.sqrt(math.pi / m)
    white = th.get("kind", "white_noise") == "white_noise"
    eps = th.get("rotational_share", 0.0)
    g, gr = th.get("friction", 0.0), th.get("rotational_friction", 0.0)

    def f(_t, y):
        T, R = max(y[0], 0.0), max(y[1], 0.0)
        s = math.sqrt(T)
        dT = G * (-A * T * s + B * s * R)
        dR = G * (B * T * s - C * s * R)
        if white:
            dT += (1 - eps) * m * x
            dR += eps * m * x
        else:
            dT += 2 * g * (x - T)
            dR += 2 * gr * (x - R)
        return [dT, dR]

    return f


def theory(gas, y0, t_end):
    """The theory's trajectory from y0 = (T_tr, T_rot) over [0, t_end]: a callable t -> (T_tr, T_rot)."""
    pieces, y = [], list(y0)
    sched = drive(gas[6])
    for k, (t0, x) in enumerate(sched):
        t1 = sched[k + 1][0] if k + 1 < len(sched) else t_end
        t1 = min(t1, t_end)
        if t1 <= t0:
            continue
        sol = solve_ivp(theory_rhs(gas, x), (t0, t1), y, method="DOP853", rtol=1e-10, atol=1e-14,
                        dense_output=True)
        pieces.append((t0, t1, sol.sol))
        y = list(sol.y[:, -1])

    def at(t):
        for t0, t1, s in pieces:
            if t <= t1:
                return s(t)
        return pieces[-1][2](pieces[-1][1])

    return at


def first_crossing(t, d):
    """The zero of the line through the first row where d's sign differs from d[0]'s and the row
    before, with its index; (None, None) without a change of sign."""
    flip = np.nonzero(np.sign(d) != np.sign(d[0]))[0]
    if len(flip) == 0:
        return None, None
    k = flip[0]
    return t[k - 1] + d[k - 1] * (t[k] - t[k - 1]) / (d[k - 1] - d[k]), k


def bootstrap(t, hot, cold, K, seed):
    """t_c over K resamples of the replicas: (crossing times, resamples without a crossing)."""
    rng = np.random.default_rng(seed)
    tcs, missed = [], 0
    for _ in range(K):
        h = hot[:, rng.integers(0, hot.shape[1], hot.shape[1])].mean(axis=1)
        c = cold[:, rng.integers(0, cold.shape[1], cold.shape[1])].mean(axis=1)
        tc, _ = first_crossing(t, h - c)
        if tc is None:
            missed += 1
        else:
            tcs.append(tc)
    return np.array(tcs), missed


def err_of(d, name):
    return d.get(name + "_err", np.zeros_like(d[name]))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("hot", help="the run started hotter (run directory or its moments.csv)")
    parser.add_argument("cold", help="the run started colder (run directory or its moments.csv)")
    parser.add_argument("--labels", nargs=2, metavar=("HOT", "COLD"), default=["hot", "cold"],
                        help="the two runs' labels (default: hot cold)")
    parser.add_argument("--out", default="mpemba.png", help="PNG to write (default mpemba.png)")
    parser.add_argument("--bootstrap", type=int, default=1000, metavar="K",
                        help="bootstrap resamples of the replicas for the crossing's error (default 1000)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the bootstrap's resampling (default 1)")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless the picture was written and both the runs and the theory cross")
    a = parser.parse_args(argv[1:])
    try:
        paths = [moments_path(a.hot), moments_path(a.cold)]
        for p in paths:
            if not os.path.exists(p):
                raise UsageError(f"{p}: no such file")
        runs = [read_csv(p) for p in paths]
        for p, d in zip(paths, runs):
            if "t" not in d or len(d["t"]) < 3:
                raise UsageError(f"{p}: fewer than three rows, or no column t")
            if species_names(d):
                raise UsageError(f"{p}: a mixture; the theory here is that of one species")
        gases = [gas_of(read_header(p)["resolved"], p) for p in paths]
        if gases[0] != gases[1]:
            raise UsageError("the two runs are not the same gas under the same thermostat "
                             "(restitution, species, density or [thermostat] differ)")
        t = runs[0]["t"]
        tb = runs[1]["t"]
        if len(t) != len(tb) or np.any(np.abs(t - tb) > COINCIDE * np.maximum(np.abs(t), 1e-300)):
            raise UsageError("the runs' rows are not at the same times: clock both by run.end_time with the "
                             "same run.output_every_time")
        hot, cold = runs
        d = hot["T_tr"] - cold["T_tr"]
        if d[0] <= 0:
            raise UsageError(f"T_tr of {paths[0]} at t = 0 ({hot['T_tr'][0]:.6g}) is not above that of "
                             f"{paths[1]} ({cold['T_tr'][0]:.6g}): give the hotter run first")
    except UsageError as e:
        print(f"mpemba.py: {e}", file=sys.stderr)
        return 2

    gas = gases[0]
    e = np.sqrt(err_of(hot, "T_tr") ** 2 + err_of(cold, "T_tr") ** 2)
    tc, k = first_crossing(t, d)
    tc_err, how = None, ""
    if tc is not None:
        reps = [replica_column(p, "T_tr", len(t)) for p in paths]
        if reps[0] is not None and reps[1] is not None and a.bootstrap > 1:
            tcs, missed = bootstrap(t, reps[0], reps[1], a.bootstrap, a.seed)
            tc_err = float(np.std(tcs, ddof=1)) if len(tcs) > 1 else None
            how = (f"bootstrap over {reps[0].shape[1]} + {reps[1].shape[1]} replicas, {a.bootstrap} resamples"
                   + (f", {missed} without a crossing" if missed else ""))
        else:
            slope = (d[k] - d[k - 1]) / (t[k] - t[k - 1])
            w = (tc - t[k - 1]) / (t[k] - t[k - 1])
            tc_err = float(((1 - w) * e[k - 1] + w * e[k]) / abs(slope)) if slope != 0 else None
            how = "the X_err columns at the crossing over the slope of T_tr,hot - T_tr,cold"

    y0 = [(r["T_tr"][0], r["T_rot"][0]) for r in runs]
    th = [theory(gas, y, t[-1]) for y in y0]
    grid = np.linspace(0, t[-1], 2001)
    th_curves = [np.array([f(s) for s in grid]) for f in th]
    gap = th_curves[0][:, 0] - th_curves[1][:, 0]
    tc_th = None
    flip = np.nonzero(np.sign(gap) != np.sign(gap[0]))[0]
    if len(flip):
        j = flip[0]
        tc_th = brentq(lambda s: th[0](s)[0] - th[1](s)[0], grid[j - 1], grid[j], xtol=1e-12)

    fig, axes = plt.subplots(3, 1, figsize=(7.5, 9.5), sharex=True)
    colors = ["tab:red", "tab:blue"]
    for r, lab, col, cur in zip(runs, a.labels, colors, th_curves):
        for ax, name in ((axes[0], "T_tr"), (axes[1], "theta")):
            y, ey = r[name], err_of(r, name)
            ax.plot(t, y, color=col, label=f"{lab}: DSMC" if name == "T_tr" else None)
            ax.fill_between(t, y - ey, y + ey, color=col, alpha=0.3, lw=0)
        axes[0].plot(grid, cur[:, 0], "--", color=col, lw=1, label=f"{lab}: Maxwellian theory")
        axes[1].plot(grid, cur[:, 1] / cur[:, 0], "--", color=col, lw=1)
    axes[2].plot(t, d, color="k", label="DSMC")
    axes[2].fill_between(t, d - e, d + e, color="k", alpha=0.25, lw=0)
    axes[2].plot(grid, gap, "--", color="k", lw=1, label="Maxwellian theory")
    axes[2].axhline(0, color="0.5", lw=0.6)
    for ax in axes:
        if tc is not None:
            ax.axvline(tc, color="k", lw=0.8, ls=":")
        if tc_th is not None:
            ax.axvline(tc_th, color="tab:green", lw=0.8, ls=":")
    axes[0].set_ylabel("T_tr")
    axes[1].set_ylabel("theta = T_rot/T_tr")
    axes[1].set_yscale("log")
    axes[2].set_ylabel(f"T_tr,{a.labels[0]} - T_tr,{a.labels[1]}")
    axes[2].set_xlabel("t")
    axes[0].legend(fontsize=8)
    axes[2].legend(fontsize=8)
    alpha, beta, q, m, sigma, n, _ = gas
    dsmc_txt = (f"DSMC crossing t = {tc:.4g} ± {tc_err:.2g}" if tc is not None and tc_err is not None
                else f"DSMC crossing t = {tc:.4g}" if tc is not None else "DSMC: no crossing")
    th_txt = f"theory t = {tc_th:.4g}" if tc_th is not None else "theory: no crossing"
    axes[0].set_title(f"alpha = {alpha}, beta = {beta}, q = {q:.3g}, n = {n:g}: {dsmc_txt} (dotted black), "
                      f"{th_txt} (dotted green)", fontsize=8)
    fig.tight_layout()
    save_figure(fig, a.out)
    plt.close(fig)

    print(f"mpemba.py: wrote {a.out}")
    print(f"  start: {a.labels[0]} T_tr = {y0[0][0]:.5g}, T_rot = {y0[0][1]:.5g}; "
          f"{a.labels[1]} T_tr = {y0[1][0]:.5g}, T_rot = {y0[1][1]:.5g}")
    if tc is None:
        print(f"  DSMC: T_tr,{a.labels[0]} - T_tr,{a.labels[1]} does not change sign by t = {t[-1]:.6g}")
    else:
        err_txt = f" +- {tc_err:.3g} ({how})" if tc_err is not None else ""
        print(f"  DSMC crossing: t = {tc:.5g}{err_txt}")
    if tc_th is None:
        print(f"  theory: no crossing by t = {t[-1]:.6g}")
    else:
        print(f"  Maxwellian theory's crossing from the first rows: t = {tc_th:.5g}")
    if tc is not None and tc_th is not None:
        rel = f" +- {tc_err / tc_th:.3f}" if tc_err else ""
        sig = f", {abs(tc - tc_th) / tc_err:.1f} errors apart" if tc_err else ""
        print(f"  DSMC/theory = {tc / tc_th:.4f}{rel}{sig}")
    if a.check and (tc is None or tc_th is None or not os.path.getsize(a.out) > 0):
        print("mpemba.py: --check: " + ("the runs do not cross" if tc is None else "the theory does not cross"),
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
