#!/usr/bin/env python3
"""The instability of the homogeneous cooling state over (alpha, beta): the measured growth rates of
a transverse wave and the critical lengths, against Navier-Stokes.

    scripts/python3 scripts/instability_map.py [--build build] [--alphas 0.9,0.8]
        [--betas=-1,-0.5,0,0.5,1] [--factors 0.8,1.25,2] [--seeds 4] [--particles 100000]
        [--jobs 2] [--out out/instability_map] [--plot docs/instability_map.png]

For each (alpha, beta) (constant restitution, one species, q = 2/5; beta = -1: smooth) `roughgas
check` gives the Navier-Stokes critical length L_c of the shear mode and, for rough grains, theta of
the cooling state in the Maxwellian approximation (docs/model.md §8). A gas (n = 0.02, sigma = 1:
mean free path lambda = 11.254) started at that theta, with a transverse wave
u_y = 0.1 sqrt(T/m) sin(2 pi x/L), cools in periodic boxes of L = f L_c for each factor f, 2 lambda
across (cells of lambda/4 along x, lambda/2 across; steps of 0.2 mean free times): --seeds runs of
--particles grains each (seeds 1, 2, ...; --jobs of them at a time, one thread each), rows every
half collision per particle. A run's growth rate gamma of u_wave/sqrt(T/m) per collision per
particle (T = T_tr - u_wave^2/6, the temperature about the flow) is the least-squares slope of its
logarithm over the rows from 3 collisions per particle (after the start's transient) while the
wave lies between 0.03 and 0.4 of the thermal speed (above the sampling noise sqrt(2/N) and in the
linear regime); a box's gamma is the mean over its runs, with their standard error. Per (alpha,
beta) the boxes' rates are fitted, weighted by their errors, by gamma = G - D (k lambda)^2, which
gives the measured critical length 2 pi sqrt(D/G) lambda and its error.

The theory beside them: modes.csv's gamma_perp_theory at each box's k (the gas's viscosity), and
the same with the DSMC's viscosity for these cells and steps, the damping raised by
16/(45 pi) (1/4)^2 + 16/(75 pi) (0.1 sqrt(pi))^2 = 0.92 % (docs/validation.md). Prints a markdown
table per box and one per (alpha, beta) (docs/validation.md keeps them) and writes
OUT/instability_boxes.csv and OUT/instability_map.csv; --plot draws gamma/G against (k/k_c)^2, on
which every theory is the line 1 - (k/k_c)^2, and the critical lengths against beta per alpha,
with the theory's curves (the gas's L_c; the DSMC's is 0.46 % longer). A run of 10^5 grains takes
a few seconds: the defaults (10 points, 3 boxes, 4 seeds: 120 runs) about four minutes on two
cores, --seeds 8 (docs/validation.md) eight.
"""
import argparse
import concurrent.futures
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roughgas_csv import read_csv  # noqa: E402
from atomic_output import save_figure, write_text  # noqa: E402

DENSITY = 0.02
LAMBDA = 1.0 / (math.sqrt(2.0) * math.pi * DENSITY)
INERTIA = 0.4
AMPLITUDE = 0.1
# The DSMC's viscosity over the gas's for cells of lambda/4 along the wave and steps of 0.2 mean
# free times (the leading-order cell-size and step laws).
LAWS = 16 / (45 * math.pi) / 16 + 16 / (75 * math.pi) * (0.2 * math.sqrt(math.pi) / 2) ** 2
FIT_FROM, WAVE_LOW, WAVE_HIGH, MIN_ROWS = 3.0, 0.03, 0.4, 6


def case_text(alpha, beta, theta, length, particles, end, seed):
    """A cooling box of length `length` lambda along x with the transverse wave."""
    cells_x = max(4, round(4 * length))
    rot = f"rotational_temperature = {theta!r}\n" if beta > -1 else ""
    return (f"[run]\nparticles = {particles}\nend = {float(end)!r}\noutput_every = 0.5\n"
            f"density = {DENSITY}\nseed = {seed}\n\n"
            f"[[species]]\nmass = 1.0\nradius = 0.5\ninertia = {INERTIA}\n{rot}\n"
            f"[collision]\nmodel = \"constant\"\nalpha = {alpha!r}\nbeta = {beta!r}\n\n"
            f"[domain]\nsize = [{length * LAMBDA!r}, {2 * LAMBDA!r}, {2 * LAMBDA!r}]\ncells = [{cells_x}, 4, 4]\n\n"
            f"[initial]\nmode = \"transverse\"\namplitude = {AMPLITUDE}\nwave = [1, 0, 0]\n\n"
            "[spectra]\nmodes = 1\n")


def check(roughgas, case):
    """(L_c / lambda, theta, gamma at the box's k) from `roughgas check`'s shear-mode line."""
    p = subprocess.run([roughgas, "check", case], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"instability_map: roughgas check {case} failed ({p.returncode}):\n{p.stderr}")
    text = p.stdout + p.stderr
    lc = re.search(r"critical length ([0-9.eE+-]+) mean free paths", text)
    rate = re.search(r"(grows|decays) against the thermal speed by ([0-9.eE+-]+) per collision", text)
    theta = re.search(r"cooling state theta = ([0-9.eE+-]+)", text)
    if not lc or not rate:
        sys.exit(f"instability_map: no critical length in roughgas check {case}:\n{text}")
    gamma = float(rate.group(2)) * (1 if rate.group(1) == "grows" else -1)
    return float(lc.group(1)), float(theta.group(1)) if theta else 0.0, gamma


def growth_rate(run_dir):
    """The run's gamma (slope of ln(u_wave/sqrt(T)) over the window) and the window's ends."""
    m = read_csv(os.path.join(run_dir, "moments.csv"))
    s, u = m["coll_per_particle"], m["u_wave"]
    ratio = u / np.sqrt(m["T_tr"] - u * u / 6)
    keep = []
    for k in np.nonzero(s >= FIT_FROM)[0]:
        if not WAVE_LOW < ratio[k] < WAVE_HIGH:
            break
        keep.append(k)
    if len(keep) < MIN_ROWS:
        return float("nan"), float("nan"), float("nan")
    slope = np.polyfit(s[keep], np.log(ratio[keep]), 1)[0]
    return float(slope), float(s[keep[0]]), float(s[keep[-1]])


def theory_rate(run_dir):
    """gamma_perp_theory of the imposed mode (axis 1, n = 1) in modes.csv."""
    m = read_csv(os.path.join(run_dir, "modes.csv"))
    rows = (m["axis"] == 1) & (m["n"] == 1)
    return float(m["gamma_perp_theory"][rows][0])


def run_one(roughgas, case, out):
    p = subprocess.run([roughgas, "run", case, "--out", out, "--force", "--quiet", "--threads", "1"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"instability_map: roughgas run {case} failed ({p.returncode}):\n{p.stderr}")
    return out


def fit_line(x, y, e):
    """Weighted least squares y = G - D x: (G, D, their covariance matrix)."""
    w = 1 / np.asarray(e) ** 2
    A = np.vstack([np.ones_like(x), -np.asarray(x)]).T
    cov = np.linalg.inv(A.T @ (A * w[:, None]))
    G, D = cov @ (A.T @ (w * np.asarray(y)))
    return G, D, cov


def critical_length(G, D, cov):
    """2 pi sqrt(D/G) and its error by propagation (nan when G or D is not positive)."""
    if G <= 0 or D <= 0:
        return float("nan"), float("nan")
    L = 2 * math.pi * math.sqrt(D / G)
    var_log = 0.25 * (cov[1, 1] / D ** 2 + cov[0, 0] / G ** 2 - 2 * cov[0, 1] / (G * D))
    return L, L * math.sqrt(max(var_log, 0.0))


def values(text):
    return [float(v) for v in text.split(",")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="build directory with the roughgas binary")
    ap.add_argument("--alphas", default="0.9,0.8", help="normal restitution coefficients (comma-separated)")
    ap.add_argument("--betas", default="-1,-0.5,0,0.5,1",
                    help="tangential ones, -1 smooth (comma-separated; write --betas=-1,0 when the list starts with -)")
    ap.add_argument("--factors", default="0.8,1.25,2", help="box lengths in units of the theory's L_c")
    ap.add_argument("--seeds", type=int, default=4, help="runs per box")
    ap.add_argument("--particles", type=int, default=100000, help="grains per run")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (one thread each)")
    ap.add_argument("--out", default="out/instability_map", help="directory for the cases, runs and CSVs")
    ap.add_argument("--plot", default=None, help="PNG to draw (e.g. docs/instability_map.png)")
    a = ap.parse_args()
    roughgas = os.path.abspath(os.path.join(a.build, "roughgas"))
    os.makedirs(a.out, exist_ok=True)
    points = [(al, be) for al in values(a.alphas) for be in values(a.betas)]
    factors = values(a.factors)

    # Plan every run first (the theory from roughgas check), then run them all.
    boxes, jobs = [], []
    for alpha, beta in points:
        probe = os.path.join(a.out, f"a{alpha}_b{beta}_probe.toml")
        with open(probe, "w") as f:
            f.write(case_text(alpha, beta, 0.0, 10.0, 1000, 1, 1))
        lc, theta, _ = check(roughgas, probe)
        for factor in factors:
            length = factor * lc
            name = f"a{alpha}_b{beta}_f{factor}"
            case = os.path.join(a.out, name + ".toml")
            with open(case, "w") as f:
                f.write(case_text(alpha, beta, theta, length, 1000, 1, 1))
            _, _, gamma = check(roughgas, case)
            # Long enough for the wave to cross the fit window: to 0.4 when it grows, to 0.03 when
            # it decays (at least 12, at most 40 collisions per particle).
            span = math.log(WAVE_HIGH / AMPLITUDE) if gamma > 0 else math.log(AMPLITUDE / WAVE_LOW)
            end = min(40.0, max(12.0, math.ceil(FIT_FROM + 1.3 * span / max(abs(gamma), 1e-9))))
            runs = []
            for seed in range(1, a.seeds + 1):
                case_s = os.path.join(a.out, f"{name}_s{seed}.toml")
                with open(case_s, "w") as f:
                    f.write(case_text(alpha, beta, theta, length, a.particles, end, seed))
                runs.append(os.path.join(a.out, f"{name}_s{seed}"))
                jobs.append((case_s, runs[-1]))
            boxes.append(dict(alpha=alpha, beta=beta, theta=theta, lc=lc, factor=factor, length=length,
                              end=end, runs=runs))
    print(f"instability_map: {len(jobs)} runs of {a.particles} grains, {a.jobs} at a time", flush=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for k, done in enumerate(pool.map(lambda j: run_one(roughgas, *j), jobs)):
            if (k + 1) % 10 == 0:
                print(f"instability_map: {k + 1} of {len(jobs)} runs done", flush=True)

    for b in boxes:
        rates = [growth_rate(r) for r in b["runs"]]
        g = np.array([r[0] for r in rates])
        b["gamma"] = float(np.mean(g))
        b["gamma_err"] = float(np.std(g, ddof=1) / math.sqrt(len(g))) if len(g) > 1 else float("nan")
        b["window"] = (min(r[1] for r in rates), max(r[2] for r in rates))
        b["theory"] = theory_rate(b["runs"][0])
        b["k_lambda"] = 2 * math.pi / b["length"]

    print("\n| α | β | L / L_c | kλ | fit window [coll./particle] | γ measured | γ Navier–Stokes (DSMC viscosity) |")
    print("|---|---|---|---|---|---|---|")
    summary = []
    for alpha, beta in points:
        mine = [b for b in boxes if b["alpha"] == alpha and b["beta"] == beta]
        x = np.array([b["k_lambda"] ** 2 for b in mine])
        th = np.array([b["theory"] for b in mine])
        # The theory's G and D from its (exactly linear) rates; the DSMC's damping is (1 + LAWS) D.
        G_th, D_th, _ = fit_line(x, th, np.ones_like(x))
        for b in mine:
            b["theory_dsmc"] = G_th - (1 + LAWS) * D_th * b["k_lambda"] ** 2
            print(f"| {alpha} | {beta} | {b['factor']} | {b['k_lambda']:.3f} | {b['window'][0]:.1f}–{b['window'][1]:.1f} "
                  f"| {b['gamma']:+.4f} ± {b['gamma_err']:.4f} | {b['theory_dsmc']:+.4f} |")
        ok = [b for b in mine if math.isfinite(b["gamma"]) and b["gamma_err"] > 0]
        G = D = float("nan")
        L = Le = float("nan")
        if len(ok) >= 2:
            G, D, cov = fit_line(np.array([b["k_lambda"] ** 2 for b in ok]), [b["gamma"] for b in ok],
                                 [b["gamma_err"] for b in ok])
            L, Le = critical_length(G, D, cov)
        summary.append(dict(alpha=alpha, beta=beta, theta=mine[0]["theta"], lc=mine[0]["lc"],
                            lc_dsmc=mine[0]["lc"] * math.sqrt(1 + LAWS), G=G, D=D, G_th=G_th,
                            D_th=(1 + LAWS) * D_th, L=L, L_err=Le))

    print("\n| α | β | θ (theory) | L_c / λ Navier–Stokes | L_c / λ with the DSMC's viscosity | L_c / λ measured "
          "| G measured / theory | D measured / DSMC theory |")
    print("|---|---|---|---|---|---|---|---|")
    for s in summary:
        print(f"| {s['alpha']} | {s['beta']} | {s['theta']:.4f} | {s['lc']:.2f} | {s['lc_dsmc']:.2f} "
              f"| {s['L']:.2f} ± {s['L_err']:.2f} | {s['G'] / s['G_th']:.3f} | {s['D'] / s['D_th']:.3f} |")

    write_csv(os.path.join(a.out, "instability_boxes.csv"),
              ["alpha", "beta", "L_over_Lc", "k_lambda", "gamma", "gamma_err", "gamma_theory", "gamma_theory_dsmc"],
              [[b["alpha"], b["beta"], b["factor"], b["k_lambda"], b["gamma"], b["gamma_err"], b["theory"],
                b["theory_dsmc"]] for b in boxes])
    write_csv(os.path.join(a.out, "instability_map.csv"),
              ["alpha", "beta", "theta_theory", "Lc_theory", "Lc_theory_dsmc", "Lc", "Lc_err", "G", "G_theory",
               "D", "D_theory_dsmc"],
              [[s["alpha"], s["beta"], s["theta"], s["lc"], s["lc_dsmc"], s["L"], s["L_err"], s["G"], s["G_th"],
                s["D"], s["D_th"]] for s in summary])
    if a.plot:
        draw(roughgas, a.out, boxes, summary, a.plot)


def write_csv(path, names, rows):
    lines = [",".join(names)] + [",".join(repr(float(v)) for v in r) for r in rows]
    write_text(path, "\n".join(lines) + "\n")


def draw(roughgas, out, boxes, summary, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    alphas = sorted({s["alpha"] for s in summary}, reverse=True)
    markers = "osD^v<>"
    for s in summary:
        mine = [b for b in boxes if b["alpha"] == s["alpha"] and b["beta"] == s["beta"]]
        # In units of the DSMC theory's growth term and critical wave number, every theory is 1 - x.
        kc2 = s["G_th"] / s["D_th"]
        left.errorbar([b["k_lambda"] ** 2 / kc2 for b in mine], [b["gamma"] / s["G_th"] for b in mine],
                      [b["gamma_err"] / s["G_th"] for b in mine], fmt=markers[alphas.index(s["alpha"]) % 7],
                      ms=4, capsize=2, label=f"α = {s['alpha']}, β = {s['beta']}")
    x = np.linspace(0, max(b["k_lambda"] ** 2 / (s["G_th"] / s["D_th"]) for b in boxes for s in summary
                           if b["alpha"] == s["alpha"] and b["beta"] == s["beta"]) * 1.05, 50)
    left.plot(x, 1 - x, "k--", lw=1, label="Navier–Stokes")
    left.axhline(0, color="0.7", lw=0.5)
    left.set_xlabel("(k / k_c)²")
    left.set_ylabel("γ / G (G: the theory's growth term)")
    left.set_title("transverse wave in boxes of 0.8 to 2 L_c")
    left.legend(fontsize=6, ncol=2)
    betas_fine = np.linspace(-0.95, 1.0, 40)
    for alpha in alphas:
        mine = [s for s in summary if s["alpha"] == alpha]
        curve = []
        for beta in betas_fine:
            probe = os.path.join(out, "curve_probe.toml")
            with open(probe, "w") as f:
                f.write(case_text(alpha, float(beta), 0.0, 10.0, 1000, 1, 1))
            curve.append(check(roughgas, probe)[0])
        line = right.plot(betas_fine, curve, "-", lw=1, label=f"Navier–Stokes, α = {alpha}")[0]
        smooth = [s for s in mine if s["beta"] == -1]
        if smooth:
            right.axhline(smooth[0]["lc"], color=line.get_color(), ls=":", lw=1)
        right.errorbar([s["beta"] for s in mine], [s["L"] for s in mine], [s["L_err"] for s in mine],
                       fmt=markers[alphas.index(alpha) % 7], color=line.get_color(), capsize=3,
                       label=f"measured, α = {alpha}")
    right.set_ylim(0, 50)
    right.set_xlabel("β (−1: smooth; dotted: the smooth grains' L_c)")
    right.set_ylabel("critical length L_c / λ")
    right.set_title("critical length of the shear mode, q = 2/5")
    right.legend(fontsize=7)
    fig.suptitle("Instability of the homogeneous cooling state: DSMC against Navier–Stokes")
    fig.tight_layout()
    save_figure(fig, path, dpi=100)


if __name__ == "__main__":
    main()
