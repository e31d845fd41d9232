"""Reading roughgas CSV files: '#' lines are metadata, the first other line names the columns.

As a command, prints columns of one row with their standard errors (the X_err columns of a run
with replicas), e.g. the late-time temperature ratio of a mixture:

    scripts/python3 scripts/roughgas_csv.py out/mix/moments.csv 'T_tr.small/T_tr.large' theta [--row -1]

--row: the row's index (default -1, the last; 0 is the first). Prints one line per column,
"NAME = VALUE +- ERROR" (no error without replicas), after the row's coll_per_particle.

As a module: read_csv (the columns), replica_column (one column of every replica of a run), species_names, read_header (the '#' lines: case file, notes,
resolved case, column units), column_unit (a column's unit in the case's unit system when the header
states one) and case_summary (the case's key parameters, for a figure's title).
"""
import argparse
import glob
import os
import re
import sys
import tomllib

import numpy as np


def read_csv(path):
    """Returns {column name: numpy array} for a CSV written by roughgas."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    names = [n.strip() for n in lines[0].split(",")]
    data = np.array([[float(v) for v in line.split(",")] for line in lines[1:] if line.strip()], ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def replica_column(path, column, n_rows):
    """`column` of each replica of the run whose moments.csv is `path`, as an array of n_rows rows x
    replicas, from DIR/replicas/moments_R.csv; None without two such files or when one has another
    number of rows."""
    files = glob.glob(os.path.join(os.path.dirname(os.path.abspath(path)), "replicas", "moments_*.csv"))
    curves = []
    for f in sorted(files, key=lambda f: int(re.sub(r"\D", "", os.path.basename(f)) or 0)):
        d = read_csv(f)
        if column not in d or len(d[column]) != n_rows:
            return None
        curves.append(d[column])
    return np.array(curves).T if len(curves) >= 2 else None


def species_names(d):
    """Species of a mixture, from the columns T_tr.NAME (not the ratios T_tr.A/T_tr.B)."""
    return [c[len("T_tr."):] for c in d if c.startswith("T_tr.") and "/" not in c and not c.endswith("_err")]


def read_header(path):
    """The '#' lines of a CSV written by roughgas, as a dict:
    "case": the case file as named ("" when absent), "sets": the --set arguments, "notes": the other
    lines before the resolved case, "resolved": the resolved case as a dict ({} when absent or
    unreadable), "units": {column: unit} from the "# units:" line ({} when absent or not one unit per
    column), "columns": the column names."""
    comments, columns = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].rstrip("\n").removeprefix(" "))
            else:
                columns = [n.strip() for n in line.split(",")]
                break
    h = {"case": "", "sets": [], "notes": [], "resolved": {}, "units": {}, "columns": columns}
    toml_lines, in_case = [], False
    for c in comments:
        if c.startswith("units: "):
            units = [u.strip() for u in c[len("units: "):].split(",")]
            if len(units) == len(columns):
                h["units"] = dict(zip(columns, units))
            in_case = False
        elif in_case:
            toml_lines.append(c)
        elif c.startswith("resolved case"):
            in_case = True
        elif c.startswith("case: "):
            h["case"] = c[len("case: "):]
        elif c.startswith("set: "):
            h["sets"].append(c[len("set: "):])
        else:
            h["notes"].append(c)
    try:
        h["resolved"] = tomllib.loads("\n".join(toml_lines))
    except (tomllib.TOMLDecodeError, ValueError):
        pass
    return h


# The base units a "# units:" entry is written in (energy/(volume*time), 1/time, ...).
BASE_UNITS = ("time", "length", "mass", "energy", "volume")
SI_UNITS = {"time": "s", "length": "m", "mass": "kg", "energy": "J", "volume": "m^3"}


def unit_system(header):
    """{base unit: symbol} from a note "unit system: NAME (time SYMBOL, energy SYMBOL, ...)" (entries
    also as "time = SYMBOL"; NAME "SI" alone gives s, m, kg, J, m^3); {} when the header states none,
    and the columns keep the base units' names."""
    for note in header.get("notes", []):
        if not note.lower().startswith("unit system:"):
            continue
        text = note[len("unit system:"):].strip()
        units = dict(SI_UNITS) if re.match(r"SI\b", text) else {}
        inner = re.search(r"\((.*)\)", text)
        for item in (inner.group(1) if inner else "").replace(";", ",").split(","):
            m = re.match(r"\s*(%s)\s*[=:]?\s*(\S.*?)\s*$" % "|".join(BASE_UNITS), item)
            if m:
                units[m.group(1)] = m.group(2)
        return units
    return {}


def column_unit(header, column):
    """The unit of a column for an axis label: "" when dimensionless ("-"), None when the header
    does not give it; base units replaced by the symbols of the header's unit system."""
    unit = header.get("units", {}).get(column)
    if unit is None:
        return None
    if unit in ("-", ""):
        return ""
    system = unit_system(header)
    if unit in system:
        return system[unit]

    def symbol(m):  # a compound symbol (sigma/sqrt(T0/m)) inside a compound unit keeps its parentheses
        sym = system.get(m.group(1), m.group(1))
        return f"({sym})" if re.search(r"[/* ]", sym) else sym

    return re.sub(r"\b(%s)\b" % "|".join(BASE_UNITS), symbol, unit)


def label_with_unit(text, unit):
    """An axis label "TEXT [UNIT]"; TEXT alone when the unit is "" or unknown (None)."""
    return f"{text} [{unit}]" if unit else text


def _g(x):
    return f"{x:.4g}" if isinstance(x, float) else str(x)


def _restitution(table, prefix, skip):
    """"alpha = 0.9, beta = 0.5"-style phrase of a [collision] or [[pair]] table (keys in `skip`,
    e.g. a sweep's key, left out)."""
    parts = []
    model = table.get("model")
    if model and model != "constant":
        parts.append(str(model))
    for key, sym in (("alpha", "\u03b1"), ("beta", "\u03b2")):
        if key in table and prefix + key not in skip:
            parts.append(f"{sym} = {_g(table[key])}" + (" (smooth)" if key == "beta" and table[key] == -1 else ""))
    return ", ".join(parts)


def case_summary(header, skip=()):
    """The key parameters of the case a CSV's header describes, as short lines for a figure title:
    the case's name, kind, N and replicas (shear: the rate), the restitution (per pair in a
    mixture), and a mixture's species (mass, radius, fraction; the mass ratio). Whatever the header
    lacks is left out; `skip`: case keys not to show (a sweep's swept key)."""
    r = header.get("resolved") or {}
    lines = []
    try:
        run = r.get("run", {})
        head = [os.path.splitext(os.path.basename(header.get("case", "")))[0]]
        first = [str(run["kind"])] if "kind" in run else []
        if "particles" in run and "run.particles" not in skip:
            first.append(f"N = {run['particles']}")
        if "replicas" in run and "run.replicas" not in skip:
            first.append(f"{run['replicas']} replica" + ("s" if run["replicas"] != 1 else ""))
        shear = r.get("shear", {})
        if run.get("kind") == "shear" and "rate" in shear and "shear.rate" not in skip:
            rate_unit = unit_system(header).get("time")
            first.append(f"a = {_g(shear['rate'])}" + (f" 1/{rate_unit}" if rate_unit else ""))
        line = ": ".join(x for x in [head[0], ", ".join(first)] if x)
        if line:
            lines.append(line)
    except (AttributeError, TypeError):
        pass
    try:
        species = [s.get("name", f"species {i}") for i, s in enumerate(r.get("species", []))]
        coll = r.get("collision", {})
        pairs = r.get("pair", [])
        if len(species) < 2:
            text = _restitution(coll, "collision.", skip)
            if text:
                lines.append(("constant restitution: " if coll.get("model") == "constant" else "restitution: ") + text)
        else:
            phrases = []
            for i, a in enumerate(species):
                for b in species[i:]:
                    k, table, prefix = next(((k, p, f"pair.{k}.") for k, p in enumerate(pairs)
                                             if sorted(p.get("species", [])) == sorted([a, b])),
                                            (None, coll, "collision."))
                    phrases.append(f"{a}-{b}: " + _restitution({**coll, **table}, prefix, skip))
            models = {p.get("model", coll.get("model")) for p in pairs} | {coll.get("model")}
            lines.append(("constant restitution " if models == {"constant"} else "") + "; ".join(phrases))
    except (AttributeError, TypeError, StopIteration):
        pass
    try:
        sp = r.get("species", [])
        if len(sp) >= 2:
            parts = []
            for i, s in enumerate(sp):
                kv = [f"{sym} = {_g(s[key])}" for key, sym in (("mass", "m"), ("radius", "R"), ("fraction", "x"))
                      if key in s and f"species.{i}.{key}" not in skip]
                parts.append(f"{s.get('name', i)} ({', '.join(kv)})")
            masses = [s.get("mass") for s in sp]
            text = "species " + ", ".join(parts)
            if len(sp) == 2 and all(isinstance(m, (int, float)) and m > 0 for m in masses):
                ratio = _g(float(masses[1]) / float(masses[0]))
                text += f"; m_{sp[1].get('name', 1)}/m_{sp[0].get('name', 0)} = {ratio}"
            lines.append(text)
    except (AttributeError, TypeError, ValueError):
        pass
    try:  # the contact model's material (its keys are SI whatever the case's units)
        mat = r.get("material", {})
        kv = [f"{sym} = {_g(mat[key])}{unit}" for key, sym, unit in
              (("young_modulus", "Y", " Pa"), ("poisson_ratio", "\u03bd", ""), ("dissipation", "A", " s"),
               ("friction", "\u03bc", ""), ("asperity", "\u03b6\u2080", " m"))
              if key in mat and f"material.{key}" not in skip]
        if kv:
            lines.append("material: " + ", ".join(kv))
    except (AttributeError, TypeError):
        pass
    return lines


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
