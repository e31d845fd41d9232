#!/usr/bin/env python3
"""Reference data with their own error bars, and the check of the solver against them.

    scripts/python3 scripts/make_reference.py hcs [--build build] [--threads 1]   # ~2 min CPU
    scripts/python3 scripts/make_reference.py usf [--build build] [--threads 1]   # ~12 min CPU
    scripts/python3 scripts/make_reference.py check [--build build] [--set KEY=VALUE]... [--expect-fail]

hcs   Runs tests/data/hcs_rough_reference.toml (rough hard spheres, constant alpha = 0.8, beta = 0.4,
      theta(0) = 0.1, to 32 collisions per particle) with 100x the statistics of its own [run] keys:
      10x the particles, 10x the replicas, seed 1000 (the check uses seed 1: independent streams).
      Writes tests/data/hcs_rough_reference.csv: '# reference:' lines saying how it was made
      (command, seed, N, replicas, commit, date, machine, load average, time) and how far it is
      from the Maxwellian theory columns (information, not a tolerance), then the run's moments.csv
      as `roughgas run` wrote it (its own provenance lines and every column X with X_err, the
      standard error of the mean over the replicas).
usf   Runs tests/data/usf_rough_reference.toml (uniform shear flow, alpha = 0.9, beta = 0, a = 1,
      started at the steady temperatures) at the Strang steps h of USF_STEPS and writes
      tests/data/usf_rough_reference.csv: per h the steady averages of P*_xy, eta*, a*, theta (rows
      from STEADY_FROM collisions per particle on; batch means over 10 batches), and in its header the
      Richardson extrapolation P*_xy(h) = P0 + c2 h^2 + c4 h^4 (a weighted least-squares fit, even
      powers only: Strang splitting is symmetric) that bench_accuracy.py measures the time-step
      error against.
check The ctest `hcs_reference`: runs tests/data/hcs_rough_reference.toml as it is (1/100 of the
      reference's statistics) and compares t, T_tr (= T_tr(t)/T_tr(0), T_tr(0) = 1), T_rot and theta
      at every output row but t = 0 with the reference: |x - x_ref| <= K sqrt(err^2 + err_ref^2).
      The resolved case must be the reference's but for the statistics ([run] particles, replicas,
      seed) and the keys given with --set. Exit 0 when every row agrees (with --expect-fail: when some
      row does not, the ctest `hcs_reference_power` that shows the check can fail), 1 otherwise.
"""
import argparse
import datetime
import os
import subprocess
import sys
import tempfile
import tomllib

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import commit, loadavg, machine, run_roughgas  # noqa: E402
from roughgas_csv import read_csv  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HCS_CASE = os.path.join(ROOT, "tests", "data", "hcs_rough_reference.toml")
HCS_REFERENCE = os.path.join(ROOT, "tests", "data", "hcs_rough_reference.csv")
USF_CASE = os.path.join(ROOT, "tests", "data", "usf_rough_reference.toml")
USF_REFERENCE = os.path.join(ROOT, "tests", "data", "usf_rough_reference.csv")

# The reference has STATS_FACTOR x the particles and x the replicas of the case's [run] keys.
STATS_FACTOR = 10
REFERENCE_SEED = 1000
QUANTITIES = ("t", "T_tr", "T_rot", "theta")
# K = 4: the check makes 32 comparisons (8 rows x 4 quantities); the test's errors come from 40
# replicas, so z follows a t distribution with 39 degrees of freedom, P(|z| > 4) = 2.7e-4, and a
# correct solver fails with probability < 32 x 2.7e-4 < 1% (union bound; the comparisons are
# correlated, which only lowers it). The reference's errors are 1/10 of the test's (100x the
# statistics): they widen the tolerance by 0.5%. Measured power (same seed): alpha 0.125% off gives
# |z| = 4.8, 0.25% off 13, 1% off 38 (hcs_reference_power); beta 1% off 7.2.
K = 4.0

# Strang steps up to half the output interval (run.output_every = 1 collision per particle): longer
# ones are cut at the rows (dsmc/shear.hpp), so their h is not the one asked for.
USF_STEPS = (0.5, 0.35, 0.25, 0.177, 0.125, 0.0625)
# Collisions per particle left out before the steady averages. The runs start at the steady
# temperatures but with a Maxwellian (P_xy = 0): until the shear stress builds up the gas cools, then
# heats back. Measured (N = 1e6, 4 replicas, h = 0.25, the step rule before commit d0d1bd3): P*_xy
# above its steady value by 1.7% over the first 5 collisions per particle, 0.7% over 5-10, 0.13%
# over 10-15, 0.07% over 15-25, and within the errors (2-3e-4) from 25 on; leaving out 10 made
# 40-row averages 3-5e-4 too large.
STEADY_FROM = 30.0
BATCHES = 10


def case_run_keys(case):
    with open(case, "rb") as f:
        return tomllib.load(f)["run"]


def resolved_case(csv_path):
    """The '# resolved case' block of a roughgas CSV as {"section.key": value}; [[species]] tables are
    "species.0", "species.1", ..."""
    keys, section, counts, inside = {}, "", {}, False
    with open(csv_path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            text = line[1:].strip()
            if text.startswith("resolved case"):
                inside = True
            elif inside and text.startswith("units:"):
                break
            elif inside and text.startswith("[["):
                name = text.strip("[]")
                section = f"{name}.{counts.get(name, 0)}"
                counts[name] = counts.get(name, 0) + 1
            elif inside and text.startswith("["):
                section = text.strip("[]")
            elif inside and "=" in text:
                k, _, v = text.partition("=")
                keys[f"{section}.{k.strip()}"] = v.strip()
    return keys


def key_defaults(roughgas):
    """{section.key: default} from `roughgas keys` (its markdown table's Default column)."""
    out = subprocess.run([roughgas, "keys"], check=True, capture_output=True, text=True).stdout
    defaults = {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 5 and cells[1].startswith("`") and "." in cells[1]:
            defaults[cells[1].strip("`")] = cells[4]
    return defaults


def reference_header(csv_path):
    with open(csv_path) as f:
        return [line.rstrip("\n") for line in f if line.startswith("# reference:")]


def check(a):
    roughgas = os.path.join(a.build, "roughgas")
    ref = read_csv(HCS_REFERENCE)
    with tempfile.TemporaryDirectory() as d:
        r = run_roughgas(roughgas, HCS_CASE, os.path.join(d, "o"), a.set, a.threads)
        test = read_csv(os.path.join(d, "o", "moments.csv"))
        test_case = resolved_case(os.path.join(d, "o", "moments.csv"))
    ref_case = resolved_case(HCS_REFERENCE)
    allowed = {"run.particles", "run.replicas", "run.seed"} | {s.partition("=")[0] for s in a.set}
    # A key the reference's case lacks (added to roughgas after it was made) at its default leaves
    # the case what it was.
    defaults = key_defaults(roughgas)
    differ = sorted(k for k in set(test_case) | set(ref_case)
                    if k not in allowed and test_case.get(k) != ref_case.get(k)
                    and not (k not in ref_case and test_case.get(k) == defaults.get(k)))
    if differ:
        sys.exit("make_reference.py check: the case is not the reference's (regenerate it with "
                 f"`make_reference.py hcs`): {', '.join(f'{k} = {test_case.get(k)} vs {ref_case.get(k)}' for k in differ)}")
    if not np.array_equal(test["coll_per_particle"], ref["coll_per_particle"]):
        sys.exit("make_reference.py check: the output rows differ from the reference's")
    print(f"check of {os.path.relpath(HCS_CASE, ROOT)} (sets: {' '.join(a.set) or 'none'}) against "
          f"{os.path.relpath(HCS_REFERENCE, ROOT)}: {r['seconds']:.2f} s of collisions, tolerance {K:g} combined "
          "standard errors")
    print("coll/particle | quantity | test | reference | z")
    worst = 0.0
    for i in np.nonzero(ref["coll_per_particle"] > 0)[0]:
        for q in QUANTITIES:
            x, e, xr, er = test[q][i], test[q + "_err"][i], ref[q][i], ref[q + "_err"][i]
            z = (x - xr) / np.hypot(e, er)
            worst = max(worst, abs(z))
            flag = "  <-- outside" if abs(z) > K else ""
            print(f"{ref['coll_per_particle'][i]:6g} | {q:5s} | {x:.6g} +- {e:.2g} | {xr:.6g} +- {er:.2g} | "
                  f"{z:+6.2f}{flag}")
    failed = worst > K
    print(f"largest |z| = {worst:.2f}: {'FAILS' if failed else 'passes'} (tolerance {K:g})")
    if a.expect_fail:
        print("expected to fail:", "it does" if failed else "it does NOT")
        return 0 if failed else 1
    return 1 if failed else 0


def theory_deviation_lines(d):
    """The reference against its Maxwellian theory columns, one line per output row."""
    lines = ["coll/particle, theta/theta_theory - 1, T_tr/T_tr_theory - 1, T_rot/T_rot_theory - 1, a20, a02, a11 "
             "(each +- its standard error)"]
    for i in np.nonzero(d["coll_per_particle"] > 0)[0]:
        cells = [f"{d['coll_per_particle'][i]:g}"]
        for q in ("theta", "T_tr", "T_rot"):
            cells.append(f"{d[q][i] / d[q + '_theory'][i] - 1:+.4f} +- {d[q + '_err'][i] / d[q + '_theory'][i]:.4f}")
        for q in ("a20", "a02", "a11"):
            cells.append(f"{d[q][i]:+.4f} +- {d[q + '_err'][i]:.4f}")
        lines.append(", ".join(cells))
    return lines


def provenance(command, revision, seconds, extra):
    return [f"command: {command}",
            f"commit: {revision}",
            f"date: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC",
            f"machine: {machine()}",
            f"time: {seconds['process_seconds']:.0f} s wall, {seconds['cpu_seconds']:.0f} s CPU; load average "
            f"{seconds['load_before']:.2f} before, {seconds['load_after']:.2f} after"] + extra


def write_with_header(path, header, body_path):
    tmp = path + ".tmp"
    with open(tmp, "w") as out, open(body_path) as body:
        for line in header:
            out.write(f"# reference: {line}\n")
        out.write(body.read())
    os.replace(tmp, path)


def make_hcs(a):
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.chdir(ROOT)  # the run's provenance lines name the case relative to the checkout
    run = case_run_keys(HCS_CASE)
    n, k = run["particles"] * STATS_FACTOR, run["replicas"] * STATS_FACTOR
    sets = [f"run.particles={n}", f"run.replicas={k}", f"run.seed={REFERENCE_SEED}"]
    command = (f"roughgas run {os.path.relpath(HCS_CASE, ROOT)} {' '.join('--set ' + s for s in sets)} "
               f"--threads {a.threads} (scripts/make_reference.py hcs)")
    print(f"{command}: {n * k * run['end'] / 2:.3g} collisions, load {loadavg():.2f}", flush=True)
    revision = commit()
    with tempfile.TemporaryDirectory() as d:
        r = run_roughgas(roughgas, os.path.relpath(HCS_CASE), os.path.join(d, "o"), sets, a.threads)
        body = os.path.join(d, "o", "moments.csv")
        dev = theory_deviation_lines(read_csv(body))
        header = provenance(command, revision, r, [
            f"statistics: {k} replicas of N = {n} (seed {REFERENCE_SEED}), {STATS_FACTOR * STATS_FACTOR}x the "
            f"{run['replicas']} replicas of N = {run['particles']} (seed {run['seed']}) of the check; X_err = "
            "standard error of the mean over the replicas",
            "T_tr(0) = 1 (the case's initial temperature), so T_tr is T_tr(t)/T_tr(0); rows at fixed collisions "
            "per particle, t their mean time",
            "against the Maxwellian theory columns (information: the cooling state is not Maxwellian):"] + dev)
        write_with_header(HCS_REFERENCE, header, body)
    print("\n".join(header))
    print(f"wrote {HCS_REFERENCE}")


def batch_mean(x, batches=BATCHES):
    """Mean of a correlated series and its error from `batches` batch means."""
    m = len(x) // batches
    b = np.array([x[j * m:(j + 1) * m].mean() for j in range(batches)])
    return float(x.mean()), float(b.std(ddof=1) / np.sqrt(batches))


def steady(d, column, start=STEADY_FROM):
    return batch_mean(d[column][d["coll_per_particle"] >= start])


def richardson(h, p, err):
    """Weighted least squares P(h) = P0 + c2 h^2 + c4 h^4; returns (coefficients, their errors, chi^2, dof)."""
    h, p, err = map(np.asarray, (h, p, err))
    design = np.stack([np.ones_like(h), h ** 2, h ** 4], axis=1) / err[:, None]
    coef, *_ = np.linalg.lstsq(design, p / err, rcond=None)
    cov = np.linalg.inv(design.T @ design)
    chi2 = float((((design @ coef) - p / err) ** 2).sum())
    return coef, np.sqrt(np.diag(cov)), chi2, len(h) - 3


def read_usf_reference(path=USF_REFERENCE):
    """The Richardson fit over the rows of the shear reference: P0, its error, c2, c4; and s, the
    statistical error of a long steady average of P*_xy over N particles and L collisions per particle
    being s/sqrt(N L) (relative; s pooled over the rows' batch-means errors)."""
    d = read_csv(path)
    coef, err, _, _ = richardson(d["time_step"], d["P_xy_star"], d["P_xy_star_err"])
    run = case_run_keys(USF_CASE)
    n_l = run["particles"] * run["replicas"] * (run["end"] - STEADY_FROM)
    s = float(np.sqrt(np.mean((d["P_xy_star_err"] / d["P_xy_star"]) ** 2) * n_l))
    return {"P0": coef[0], "P0_err": err[0], "c2": coef[1], "c4": coef[2], "s": s}


def make_usf(a):
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    run = case_run_keys(USF_CASE)
    rows, total = [], {"process_seconds": 0, "cpu_seconds": 0, "load_before": loadavg()}
    revision = commit()
    with tempfile.TemporaryDirectory() as d:
        for h in USF_STEPS:
            r = run_roughgas(roughgas, USF_CASE, os.path.join(d, "o"), [f"shear.time_step={h}"], a.threads)
            m = read_csv(os.path.join(d, "o", "moments.csv"))
            row = {"time_step": h}
            for q in ("P_xy_star", "eta_star", "a_star", "theta", "T_tr"):
                row[q], row[q + "_err"] = steady(m, q)
            row.update({"seconds": r["seconds"], "cpu_seconds": r["cpu_seconds"]})
            rows.append(row)
            for key in ("process_seconds", "cpu_seconds"):
                total[key] += r[key]
            print(f"h = {h:5g}: P*_xy = {row['P_xy_star']:.5f} +- {row['P_xy_star_err']:.5f}, {r['seconds']:.1f} s "
                  f"(load {r['load_before']:.2f} .. {r['load_after']:.2f})", flush=True)
    total["load_after"] = loadavg()
    coef, err, chi2, dof = richardson([r["time_step"] for r in rows], [r["P_xy_star"] for r in rows],
                                      [r["P_xy_star_err"] for r in rows])
    command = (f"roughgas run {os.path.relpath(USF_CASE, ROOT)} --set shear.time_step=H --threads {a.threads}, "
               f"H = {', '.join(f'{h:g}' for h in USF_STEPS)} (scripts/make_reference.py usf)")
    header = provenance(command, revision, total, [
        f"statistics: {run['replicas']} replicas of N = {run['particles']} (seed {run['seed']}) per time step, "
        f"steady averages over the rows from {STEADY_FROM:g} to {run['end']:g} collisions per particle, errors "
        f"from {BATCHES} batch means",
        f"Richardson fit P*_xy(h) = P0 + c2 h^2 + c4 h^4 over these rows (chi^2 = {chi2:.2f} for {dof} degrees "
        f"of freedom): P0 = {coef[0]:.6f} +- {err[0]:.6f}, c2 = {coef[1]:.5f} +- {err[1]:.5f}, "
        f"c4 = {coef[2]:.5f} +- {err[2]:.5f}"])
    with tempfile.TemporaryDirectory() as d:
        body = os.path.join(d, "rows.csv")
        with open(body, "w") as f:
            f.write(",".join(rows[0]) + "\n")
            for row in rows:
                f.write(",".join(f"{v:.10g}" for v in row.values()) + "\n")
        write_with_header(USF_REFERENCE, header, body)
    print("\n".join(header))
    print(f"wrote {USF_REFERENCE}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["hcs", "usf", "check"])
    ap.add_argument("--build", default="build")
    ap.add_argument("--threads", type=int, default=1, help="threads of roughgas run (default 1: a shared machine)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="check: passed to roughgas run")
    ap.add_argument("--expect-fail", action="store_true", help="check: succeed only if the comparison fails")
    a = ap.parse_args()
    if a.what == "check":
        return check(a)
    if a.set or a.expect_fail:
        ap.error("--set and --expect-fail go with check")
    (make_hcs if a.what == "hcs" else make_usf)(a)
    return 0


if __name__ == "__main__":
    sys.exit(main())
