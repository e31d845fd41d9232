#!/usr/bin/env python3
"""Draws slices of a box run's cell fields ([fields]) to PNG, and checks the files ParaView reads.

usage: scripts/python3 scripts/plot_fields.py RUN_DIR [--replica R] [--times N] [--axis {x,y,z}]
                                              [--index I] [--out PNG] [--check]

Reads the XDMF sidecar RUN_DIR/fields/replica_R.xmf (default R = 0) and the HDF5 files it names.
For N snapshots spread over the series (default 3: the first, the middle and the last) it draws
the slice of cells I (default: the middle one) normal to --axis (default z: for a slab of one cell
along z, the whole slab) in two rows:
  - the density n over its mean over the box (clusters: dense, cold regions);
  - the vorticity's component along --axis, (curl u)_axis, from the cells' flow u by central
    differences (one-sided at the ends of an axis; empty cells count with u = 0): vortices.
Writes PNG (default: RUN_DIR/fields_replica_R.png) atomically.
--check: also verify what ParaView's XDMF reader will read: every HDF5 file the sidecar names
exists, holds the dataset, and the dataset's shape is the sidecar's Dimensions (cells along z, y, x,
then the components); each file's row and t are its grid's; exit 1 on any mismatch or if no
panel was drawn.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

AXES = "xyz"


def read_sidecar(path):
    """The sidecar's snapshots: [(name, time, {attribute: (file, dataset, dimensions)})]."""
    root = ET.parse(path).getroot()
    series = root.find("Domain/Grid")
    snapshots = []
    for grid in series.findall("Grid"):
        time = float(grid.find("Time").get("Value"))
        nodes = [int(d) for d in grid.find("Topology").get("Dimensions").split()]
        items = {}
        for attribute in grid.findall("Attribute"):
            item = attribute.find("DataItem")
            file, dataset = item.text.strip().rsplit(":", 1)
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            items[attribute.get("Name")] = (file, dataset, dims, attribute.get("AttributeType"))
        snapshots.append((grid.get("Name"), time, nodes, items))
    return snapshots


def check(snapshots):
    """Problems ParaView would meet, as text (empty: none)."""
    problems = []
    for name, time, nodes, items in snapshots:
        for attr, (file, dataset, dims, kind) in items.items():
            if not os.path.isabs(file):
                problems.append(f"{name}/{attr}: {file} is not an absolute path")
            if not os.path.exists(file):
                problems.append(f"{name}/{attr}: {file} does not exist")
                continue
            with h5py.File(file, "r") as h:
                if dataset.lstrip("/") not in h:
                    problems.append(f"{name}/{attr}: {file} has no dataset {dataset}")
                    continue
                shape = h[dataset].shape
                if shape != dims:
                    problems.append(f"{name}/{attr}: {file}:{dataset} has shape {shape}, the sidecar says {dims}")
                if tuple(d - 1 for d in nodes) != dims[:3]:
                    problems.append(f"{name}/{attr}: the topology's {nodes} nodes do not bound {dims[:3]} cells")
                components = {"Scalar": 3, "Vector": 4, "Tensor6": 4}.get(kind)
                if components != len(dims):
                    problems.append(f"{name}/{attr}: {kind} with dimensions {dims}")
                if float(h.attrs["t"]) != time or f"row {int(h.attrs['row'])}" != name:
                    problems.append(f"{name}/{attr}: {file} holds row {int(h.attrs['row'])} at t = {h.attrs['t']}")
    return problems


def curl_component(u, axis, spacing):
    """(curl u) along `axis` of u[z, y, x, 3] on cells of `spacing` (x, y, z)."""
    u = np.nan_to_num(u)
    a, b = [c for c in range(3) if c != axis]  # the plane's axes, curl_axis = d_a u_b - d_b u_a

    def d(f, c):  # derivative along axis c (array axis 2 - c: the arrays run z, y, x)
        if f.shape[2 - c] < 2:
            return np.zeros_like(f)
        return np.gradient(f, spacing[c], axis=2 - c)

    return d(u[..., b], a) - d(u[..., a], b)


def plane(field, axis, index):
    """The slice of field[z, y, x] at `index` normal to `axis`, as [row, column] for imshow."""
    if axis == 2:
        return field[index, :, :]  # rows y, columns x
    if axis == 1:
        return field[:, index, :]  # rows z, columns x
    return field[:, :, index]  # rows z, columns y


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--replica", type=int, default=0, help="the replica's fields (default 0)")
    parser.add_argument("--times", type=int, default=3, help="snapshots drawn, spread over the series (default 3)")
    parser.add_argument("--axis", choices=list(AXES), default="z", help="the slice's normal (default z)")
    parser.add_argument("--index", type=int, help="the slice's cell along --axis (default: the middle one)")
    parser.add_argument("--out", help="PNG file (default: RUN_DIR/fields_replica_R.png)")
    parser.add_argument("--check", action="store_true",
                        help="verify the sidecar's files, datasets and shapes; exit 1 on a mismatch or no panel")
    args = parser.parse_args(argv[1:])
    sidecar = os.path.join(args.run_dir, "fields", f"replica_{args.replica}.xmf")
    if not os.path.exists(sidecar):
        print(f"plot_fields: {sidecar} does not exist (a box run with [fields] writes it)", file=sys.stderr)
        return 2
    snapshots = read_sidecar(sidecar)
    if args.check:
        problems = check(snapshots)
        for p in problems:
            print(f"plot_fields: {p}", file=sys.stderr)
        if problems:
            return 1
        print(f"plot_fields: {sidecar}: {len(snapshots)} snapshots, every dataset where the sidecar says")
    axis = AXES.index(args.axis)
    picks = sorted(set(np.linspace(0, len(snapshots) - 1, max(1, args.times)).round().astype(int))) if snapshots else []
    fig, ax = plt.subplots(2, max(1, len(picks)), figsize=(3.6 * max(1, len(picks)), 6.6), squeeze=False)
    drawn = 0
    for j, k in enumerate(picks):
        name, time, nodes, items = snapshots[k]
        with h5py.File(items[next(iter(items))][0], "r") as h:
            box, cells, cpp = h.attrs["box"], h.attrs["cells"], float(h.attrs["coll_per_particle"])
        index = args.index if args.index is not None else int(cells[axis]) // 2
        index = min(max(index, 0), int(cells[axis]) - 1)
        plane_axes = [c for c in range(3) if c != axis]
        extent = [0, box[plane_axes[0]], 0, box[plane_axes[1]]]
        title = f"t = {time:.4g} ({cpp:.3g} coll./particle)"
        if "n" in items:
            with h5py.File(items["n"][0], "r") as h:
                n = h[items["n"][1]][...]
            im = ax[0][j].imshow(plane(n / n.mean(), axis, index), origin="lower", extent=extent, cmap="magma",
                                 aspect="equal")
            fig.colorbar(im, ax=ax[0][j], shrink=0.8, label="n / <n>")
            ax[0][j].set_title(title, fontsize=8)
            drawn += 1
        if "u" in items:
            with h5py.File(items["u"][0], "r") as h:
                u = h[items["u"][1]][...]
            spacing = [box[c] / cells[c] for c in range(3)]
            w = plane(curl_component(u, axis, spacing), axis, index)
            scale = np.abs(w).max() or 1.0
            im = ax[1][j].imshow(w, origin="lower", extent=extent, cmap="RdBu_r", vmin=-scale, vmax=scale,
                                 aspect="equal")
            fig.colorbar(im, ax=ax[1][j], shrink=0.8, label=f"(curl u)_{args.axis}")
            drawn += 1
        for r in range(2):
            ax[r][j].set_xlabel(AXES[plane_axes[0]])
            ax[r][j].set_ylabel(AXES[plane_axes[1]])
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.run_dir))}, replica {args.replica}: density and "
                 f"vorticity, cells {args.axis} = {args.index if args.index is not None else 'middle'}", fontsize=9)
    out = args.out or os.path.join(args.run_dir, f"fields_replica_{args.replica}.png")
    fig.tight_layout()
    tmp = out + ".tmp"
    fig.savefig(tmp, dpi=110, format="png")
    os.replace(tmp, out)  # never leave a half-written picture
    plt.close(fig)
    print(f"plot_fields: wrote {out}")
    if args.check and drawn == 0:
        print("plot_fields: no panel drawn (the fields hold neither n nor u)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
