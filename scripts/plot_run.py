#!/usr/bin/env python3
"""Draws what a roughgas run directory holds, with the plot scripts that fit its kind of run.

usage: scripts/python3 scripts/plot_run.py RUN_DIR [--check]

The kind is read from the files the run wrote:
  a cooling run (scaled.csv)          plot.py: temperatures, theta, zeta*, cumulants, the cooling
                                      state's theory dashed;
  uniform shear flow (a_star column)  plot_shear.py: temperatures, stresses, rheology, the steady window;
  a box (profiles.csv)                plot_profiles.py: the profiles across the box, the walls' values;
                                      with spectra.csv plot_spectra.py, with fields/ plot_fields.py.
A box whose walls drive it (steady.csv without a_star: Couette, Fourier, a heated bed) gets its
profiles only: the cooling panels and their theory line do not describe a driven gas. Each script
writes its PNG into RUN_DIR; a line per script on stdout says which ran.
--check: passed on to every script (each exits 1 unless it drew all it should); exit 1 if any did.
"""
import argparse
import glob
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def columns(csv_path):
    """The column names of a roughgas CSV (its first line that is not a '#' comment)."""
    with open(csv_path) as f:
        for line in f:
            if not line.startswith("#"):
                return line.strip().split(",")
    return []


def plots_for(run_dir):
    """The plot scripts (name, extra arguments) that draw RUN_DIR, in order."""
    has = lambda name: os.path.exists(os.path.join(run_dir, name))  # noqa: E731
    if not has("moments.csv"):
        raise SystemExit(f"plot_run.py: {run_dir}: no moments.csv (not a roughgas run directory)")
    shear = "a_star" in columns(os.path.join(run_dir, "moments.csv"))
    plots = []
    if has("scaled.csv"):
        plots.append(("plot.py", []))
    elif shear:
        plots.append(("plot_shear.py", []))
    if has("profiles.csv"):
        plots.append(("plot_profiles.py", []))
        if has("spectra.csv"):
            plots.append(("plot_spectra.py", []))
        if glob.glob(os.path.join(run_dir, "fields", "*.xmf")):
            plots.append(("plot_fields.py", []))
    return plots


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--check", action="store_true", help="exit 1 unless every script drew all it should")
    a = parser.parse_args(argv)
    failed = []
    for script, extra in plots_for(a.run_dir):
        print(f"plot_run.py: {script} {a.run_dir}", flush=True)
        cmd = [sys.executable, os.path.join(HERE, script), a.run_dir] + extra + (["--check"] if a.check else [])
        if subprocess.run(cmd).returncode != 0:
            failed.append(script)
    if failed:
        print(f"plot_run.py: {', '.join(failed)} failed on {a.run_dir}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
