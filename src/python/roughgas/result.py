"""roughgas.load and Result: a run directory's CSVs as NumPy arrays keyed by their column names.

Each file's numbers come in one buffer that the compiled module moves into NumPy (no copy); each
column is a view of it, and its values are the doubles the run wrote (the CSVs hold shortest
round-trip decimals)."""
import glob
import os
import re

from . import _roughgas

try:
    import pandas
except ImportError:  # pandas is optional: without it the tables are dicts of arrays
    pandas = None


def read_csv(path):
    """(header, {column: array}) of a CSV that roughgas wrote; header: its '#' lines."""
    comments, names, values = _roughgas.read_csv(os.fspath(path))
    return comments, {name: values[i] for i, name in enumerate(names)}


def load_csv(path):
    """Any CSV that roughgas wrote (moments.csv, normal.csv, ...) as {column: array}."""
    return read_csv(path)[1]


class FieldsSnapshot:
    """One snapshot of a box run's cell fields (DIR/fields/replica_R/row_NNNNNN.h5): t,
    coll_per_particle, row, replica, box, cells from the file's attributes; snapshot["n"] (any
    quantity of fields.quantities) reads that dataset when asked, cell (i, j, l) at [l, j, i]."""

    quantities = ("n", "u", "T_tr", "T_rot", "theta", "omega", "P", "q")  # what fields.quantities may name

    def __init__(self, path):
        self.path = path
        self.__dict__.update(_roughgas.read_fields_header(path))
        self.units = {}
        self._read = {}

    def __getitem__(self, name):
        if name not in self._read:
            self._read[name], self.units[name] = _roughgas.read_fields(self.path, name)
        return self._read[name]

    def read_all(self):
        """Reads every quantity the file has now (roughgas.run does, before removing a temporary directory)."""
        for name in self.quantities:
            try:
                self[name]
            except RuntimeError:  # not among this run's fields.quantities
                pass

    def __repr__(self):
        return f"<roughgas.FieldsSnapshot row {self.row}, t = {self.t}: {self.path}>"


class Result:
    """What a run wrote. Tables are {column: array} (pandas DataFrames when pandas is importable),
    None where the run has no such file:

    moments          moments.csv (one row per output time; X_err with replicas)
    summary          the one row of steady.csv (driven or sheared) or scaled.csv (freely cooling), as
                     {column: float}, errors in X_err; summary_kind: "steady", "scaled" or None
    profiles, steady_profiles, spectra, modes, walls, histograms   the box's and histograms' CSVs
    replicas         each replica's moments (replicas/moments_R.csv), in order ([] for one replica)
    fields           box runs with [fields]: {replica: [FieldsSnapshot, ...]} in row order ({} without)
    header           moments.csv's '#' lines (case, --set, seed, resolved case, units)
    arrays(name)     any of these files as {column: array}, whatever pandas
    """

    _tables = {"moments": "moments.csv", "profiles": "profiles.csv", "steady_profiles": "steady_profiles.csv",
               "spectra": "spectra.csv", "modes": "modes.csv", "walls": "walls.csv",
               "histograms": "histograms.csv"}

    def __init__(self, directory):
        self.dir = os.fspath(directory)
        self._arrays = {}
        self.header = []
        for attr, file in self._tables.items():
            path = os.path.join(self.dir, file)
            if os.path.exists(path):
                comments, columns = read_csv(path)
                self._arrays[file] = columns
                if attr == "moments":
                    self.header = comments
            setattr(self, attr, self._frame(self._arrays.get(file)))
        self.summary, self.summary_kind = None, None
        for kind in ("steady", "scaled"):
            path = os.path.join(self.dir, kind + ".csv")
            if os.path.exists(path):
                _, columns = read_csv(path)
                self._arrays[kind + ".csv"] = columns
                self.summary = {k: float(v[-1]) for k, v in columns.items() if len(v)}
                self.summary_kind = kind
        files = glob.glob(os.path.join(self.dir, "replicas", "moments_*.csv"))
        files.sort(key=lambda f: int(re.sub(r"\D", "", os.path.basename(f)) or 0))
        self.replicas = [self._frame(read_csv(f)[1]) for f in files]
        self.fields = {}
        for sidecar in glob.glob(os.path.join(self.dir, "fields", "replica_*")):
            if os.path.isdir(sidecar):
                replica = int(os.path.basename(sidecar)[len("replica_"):])
                self.fields[replica] = [FieldsSnapshot(f) for f in sorted(glob.glob(os.path.join(sidecar, "row_*.h5")))]
        if "moments.csv" not in self._arrays:
            raise FileNotFoundError(f"{os.path.join(self.dir, 'moments.csv')}: not a run directory")

    def arrays(self, name):
        """A file of the run ("moments", "profiles", ..., "steady", "scaled") as {column: array}."""
        file = name if name.endswith(".csv") else name + ".csv"
        if file not in self._arrays:
            raise KeyError(f"{name}: not written by this run (it wrote {', '.join(sorted(self._arrays))})")
        return self._arrays[file]

    @staticmethod
    def _frame(columns):
        if columns is None or pandas is None:
            return columns
        return pandas.DataFrame(columns, copy=False)

    def __repr__(self):
        return f"<roughgas.Result {self.dir}: {', '.join(sorted(self._arrays))}>"


def load(dir):
    """A run directory that `roughgas run` (or roughgas.run) wrote, as a Result."""
    if not os.path.isdir(dir):
        raise FileNotFoundError(f"{dir}: no such directory")
    return Result(dir)
