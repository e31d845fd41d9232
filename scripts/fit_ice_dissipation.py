#!/usr/bin/env python3
"""Least-squares fit of the dissipative constant A (Brilliantov et al. (1996) eq. 23) to the
measured ice law that the paper's Fig. 1 draws dashed: eps(v) = (v/v_c)^-0.234, v_c = 0.0077 cm/s
(Bridges et al. 1984), over 0.05-5 cm/s.

usage: scripts/python3 scripts/fit_ice_dissipation.py [CASE.toml] [--write | --check] [--roughgas PATH]
  default CASE: cases/ice.toml. Prints the fitted A and the residuals.
  --write  puts the fitted value into the case's `dissipation = ...` line (atomically).
  --check  exits 1 unless the case's dissipation equals the fit to 1e-3 relative (used by ctest).

Method: eps^N depends on g_N only through w = g_N rho^2 tau^5 with tau = (3/2) A (eq. 24) or A (eq. 25)
(docs/model.md §6), so w = g_N c_ref (A/A_ref)^5. One `roughgas restitution` run at the case's A gives
the master curve eps^N(w) (column w of normal.csv); the fit is then a 1-D minimisation over ln A
of sum_v (eps^N(v c(A)) - eps_Bridges(v))^2 on 60 log-spaced speeds, by golden-section search after
a coarse scan.
"""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from roughgas_csv import read_csv

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
V_C = 0.0077e-2  # m/s
EXPONENT = -0.234
V_FIT = np.logspace(np.log10(0.05e-2), np.log10(5e-2), 60)  # 0.05-5 cm/s in m/s


def bridges(v):
    return (v / V_C) ** EXPONENT




def case_dissipation(case_path):
    with open(case_path) as f:
        text = f.read()
    m = re.search(r"^\s*dissipation\s*=\s*([0-9.eE+-]+)", text, re.M)
    if not m:
        sys.exit(f"{case_path}: no `dissipation = ...` line in [material]")
    return float(m.group(1)), text


def master_curve(roughgas, case_path, a_ref):
    """eps^N against w from one direct tabulation over 16 decades of g_N around the fit range."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out")
        cmd = [roughgas, "restitution", case_path, "--out", out,
               "--set", f"material.dissipation={a_ref!r}", "--set", "contact.cache=false",
               "--set", "restitution.g_n_min=1e-12", "--set", "restitution.g_n_max=1e4",
               "--set", "restitution.g_n_points=801", "--set", "restitution.spacing=\"log\"",
               "--set", "restitution.g_t_min=1e-3", "--set", "restitution.g_t_max=1e-3",
               "--set", "restitution.g_t_points=1"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        d = read_csv(os.path.join(out, "normal.csv"))
    c_ref = d["w"][0] / d["g_N"][0]
    return np.log(d["w"]), d["eps_N"], c_ref


def fit(log_w, eps, c_ref, a_ref):
    def cost(ln_a):
        w = V_FIT * c_ref * np.exp(5 * (ln_a - np.log(a_ref)))
        if np.log(w[0]) < log_w[0] or np.log(w[-1]) > log_w[-1]:
            return np.inf  # outside the master curve: refuse rather than extrapolate
        return np.sum((np.interp(np.log(w), log_w, eps) - bridges(V_FIT)) ** 2)

    grid = np.log(a_ref) + np.linspace(-6, 6, 241)
    costs = np.array([cost(g) for g in grid])
    k = int(np.argmin(costs))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    phi = (np.sqrt(5) - 1) / 2
    for _ in range(200):  # golden section to |d ln A| < 1e-12
        a, b = hi - phi * (hi - lo), lo + phi * (hi - lo)
        if cost(a) < cost(b):
            hi = b
        else:
            lo = a
        if hi - lo < 1e-12:
            break
    ln_a = 0.5 * (lo + hi)
    return float(np.exp(ln_a)), cost(ln_a)


def main(argv):
    if "-h" in argv[1:] or "--help" in argv[1:]:
        print(__doc__)
        return 0
    args = [a for a in argv[1:] if not a.startswith("--")]
    roughgas = os.environ.get("ROUGHGAS", os.path.join(ROOT, "build", "roughgas"))
    if "--roughgas" in argv:
        roughgas = argv[argv.index("--roughgas") + 1]
        args.remove(roughgas)
    case_path = args[0] if args else os.path.join(ROOT, "cases", "ice.toml")
    a_case, text = case_dissipation(case_path)
    a_fit, c = a_case, None
    for _ in range(3):  # re-centre the master curve on the fit: the interpolation error shrinks
        log_w, eps, c_ref = master_curve(roughgas, case_path, a_fit)
        a_fit, c = fit(log_w, eps, c_ref, a_fit)
    log_w, eps, c_ref = master_curve(roughgas, case_path, a_fit)
    model = np.interp(np.log(V_FIT * c_ref), log_w, eps)
    resid = model - bridges(V_FIT)
    print(f"fitted A = {a_fit:.6e} s  (case has {a_case:.6e} s)")
    print(f"rms residual {np.sqrt(np.mean(resid ** 2)):.4f}, max |residual| {np.max(np.abs(resid)):.4f} "
          f"over {V_FIT[0] * 100:.2f}-{V_FIT[-1] * 100:.1f} cm/s")
    if "--write" in argv:
        new = re.sub(r"^(\s*dissipation\s*=\s*)([0-9.eE+-]+)", lambda m: m.group(1) + f"{a_fit:.6e}", text,
                     count=1, flags=re.M)
        tmp = case_path + ".tmp"
        with open(tmp, "w") as f:
            f.write(new)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, case_path)
        print(f"wrote dissipation = {a_fit:.6e} into {case_path}")
    if "--check" in argv and abs(a_fit / a_case - 1) > 1e-3:
        print(f"FAIL: {case_path} has dissipation = {a_case:.6e}, the fit gives {a_fit:.6e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
