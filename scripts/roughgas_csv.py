"""Reading roughgas CSV files: '#' lines are metadata, the first other line names the columns."""
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
