"""Reading roughgas CSV files: '#' lines are metadata, the first other line names the columns."""
import numpy as np


def read_csv(path):
    """Returns {column name: numpy array} for a CSV written by roughgas."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    names = [n.strip() for n in lines[0].split(",")]
    data = np.array([[float(v) for v in line.split(",")] for line in lines[1:] if line.strip()], ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}
