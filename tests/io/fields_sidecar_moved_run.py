#!/usr/bin/env python3
"""A box run's cell fields open from a copy of its run directory, the original deleted (a run
directory copied from a cluster to a laptop).

usage: /usr/bin/python3 tests/io/fields_sidecar_moved_run.py ROUGHGAS

Runs a small box case with [fields] on two replicas into a scratch directory, copies the run
directory elsewhere and deletes the original. Then, for each replica's XDMF sidecar in the copy,
parsed as XML: every HDF5 file it names, resolved against the sidecar's folder as ParaView's
reader resolves it, exists and is in the copy, holds the dataset named, of the shape of the
sidecar's Dimensions; the sidecar lists every snapshot file of the replica. Last,
scripts/plot_fields.py --check accepts a sidecar naming its files by absolute path (XDMF allows
either). Exit 1 on any problem.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPLICAS = 2
CASE = f"""[run]
particles = 2000
replicas = {REPLICAS}
end = 2.0
output_every = 1.0
density = 0.02
seed = 3

[[species]]
mass = 1.0
radius = 0.5

[collision]
model = "constant"
alpha = 0.9
beta = 0.5

[domain]
size = [30.0, 30.0, 30.0]
cells = [4, 3, 2]
allow_coarse = true

[fields]
quantities = ["n", "u", "P"]
replicas = {REPLICAS}
"""


def sidecar_items(sidecar):
    """[(grid name, file as written, file resolved, dataset, dimensions)] of every DataItem in HDF."""
    folder = os.path.dirname(sidecar)
    items = []
    for grid in ET.parse(sidecar).getroot().iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        for item in grid.iter("DataItem"):
            if item.get("Format") != "HDF":
                continue
            name, dataset = item.text.strip().rsplit(":", 1)
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            items.append((grid.get("Name"), name, os.path.join(folder, name), dataset, dims))
    return items


def check_replica(run_dir, replica):
    problems = []
    sidecar = os.path.join(run_dir, "fields", f"replica_{replica}.xmf")
    items = sidecar_items(sidecar)
    if not items:
        return [f"{sidecar}: names no HDF5 file"]
    for grid, name, path, dataset, dims in items:
        where = f"{sidecar} ({grid}): {name}"
        if not os.path.exists(path):
            problems.append(f"{where}: no such file relative to the sidecar's folder")
            continue
        if os.path.commonpath([os.path.realpath(path), os.path.realpath(run_dir)]) != os.path.realpath(run_dir):
            problems.append(f"{where}: outside the copied run directory")
        with h5py.File(path, "r") as h:
            if dataset.lstrip("/") not in h:
                problems.append(f"{where}: no dataset {dataset}")
            elif h[dataset].shape != dims:
                problems.append(f"{where}:{dataset} has shape {h[dataset].shape}, the sidecar says {dims}")
    listed = {os.path.realpath(path) for _, _, path, _, _ in items}
    replica_dir = os.path.join(run_dir, "fields", f"replica_{replica}")
    on_disk = {os.path.realpath(os.path.join(replica_dir, f)) for f in os.listdir(replica_dir) if f.endswith(".h5")}
    if listed != on_disk:
        problems.append(f"{sidecar} lists {sorted(listed)}, the replica's directory holds {sorted(on_disk)}")
    return problems


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    roughgas = os.path.abspath(argv[1])
    with tempfile.TemporaryDirectory(prefix="roughgas_fields_moved_") as scratch:
        cluster, laptop = os.path.join(scratch, "cluster"), os.path.join(scratch, "laptop")
        os.makedirs(cluster)
        case = os.path.join(cluster, "box.toml")
        with open(case, "w") as f:
            f.write(CASE)
        run = subprocess.run([roughgas, "run", case, "--out", os.path.join(cluster, "run"), "--quiet"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f"roughgas run failed ({run.returncode}):\n{run.stderr}", file=sys.stderr)
            return 1
        moved = os.path.join(laptop, "run")
        shutil.copytree(os.path.join(cluster, "run"), moved)
        shutil.rmtree(cluster)
        problems = []
        for replica in range(REPLICAS):
            problems += check_replica(moved, replica)
        if not problems:
            # A sidecar naming its files by absolute path: plot_fields resolves those as they are.
            sidecar = os.path.join(moved, "fields", "replica_0.xmf")
            tree = ET.parse(sidecar)
            for item in tree.getroot().iter("DataItem"):
                if item.get("Format") == "HDF":
                    item.text = os.path.join(os.path.dirname(os.path.abspath(sidecar)), item.text.strip())
            tree.write(sidecar)
            check = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "plot_fields.py"), moved,
                                    "--check", "--out", os.path.join(scratch, "fields.png")],
                                   capture_output=True, text=True)
            if check.returncode != 0:
                problems.append(f"plot_fields.py --check of a sidecar of absolute names failed "
                                f"({check.returncode}):\n{check.stderr}")
        for p in problems:
            print(f"fields_sidecar_moved_run: {p}", file=sys.stderr)
        if problems:
            return 1
        print(f"fields_sidecar_moved_run: {REPLICAS} sidecars open from a copy of the run directory")
        return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
