"""Reading roughgas CSV files: '#' lines are metadata, the first other line names the columns.

As a command, prints columns of one row with their standard errors (the X_err columns of a run
with replicas), e.g. the late-time temperature ratio of a mixture:

    scripts/python3 scripts/roughgas_csv.py out/mix/moments.csv 'T_tr.small/T_tr.large' theta [--row -1]

--row: the row's index (default -1, the last; 0 is the first). Prints one line per column,
"NAME = VALUE +- ERROR" (no error without replicas), after the row's coll_per_particle.
"""
import argparse
import sys

import numpy as np


def read_csv(path):
    """Returns {column name: numpy array} for a CSV written by roughgas."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    names = [n.strip() for n in lines[0].split(",")]
    data = np.array([[float(v) for v in line.split(",")] for line in lines[1:] if line.strip()], ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def species_names(d):
    """Species of a mixture, from the columns T_tr.NAME (not the ratios T_tr.A/T_tr.B)."""
    return [c[len("T_tr."):] for c in d if c.startswith("T_tr.") and "/" not in c and not c.endswith("_err")]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", help="a CSV written by roughgas (moments.csv, steady.csv, sweep.csv, ...)")
    parser.add_argument("columns", nargs="+", help="column names")
    parser.add_argument("--row", type=int, default=-1, help="row index (default -1: the last)")
    args = parser.parse_args(argv[1:])
    d = read_csv(args.csv)
    missing = [c for c in args.columns if c not in d]
    if missing:
        print(f"roughgas_csv: {args.csv} has no column {', '.join(missing)}; it has: {', '.join(d)}", file=sys.stderr)
        return 2
    rows = len(next(iter(d.values())))
    if not -rows <= args.row < rows:
        print(f"roughgas_csv: --row {args.row}: {args.csv} has {rows} rows", file=sys.stderr)
        return 2
    if "coll_per_particle" in d:
        print(f"at coll_per_particle = {d['coll_per_particle'][args.row]:.6g}:")
    for c in args.columns:
        value = d[c][args.row]
        err = d.get(c + "_err")
        print(f"{c} = {value:.8g}" + (f" +- {err[args.row]:.2g}" if err is not None else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
