#!/usr/bin/env python3
"""Draws slices of a box run's cell fields ([fields]) to PNG, and checks the files ParaView reads.

usage: scripts/python3 scripts/plot_fields.py RUN_DIR [--replica R] [--times N] [--from C]
                                              [--axis {x,y,z}] [--index I] [--block B] [--linear]
                                              [--out PNG] [--check]

Reads the XDMF sidecar RUN_DIR/fields/replica_R.xmf (default R = 0) and the HDF5 files it names.
The cells are first coarse-grained in blocks of B cells along every axis (fewer along an axis of
fewer cells; the last block of an axis holds the remainder): a block's density is the mean of its
cells' n, its flow the number-weighted mean of their u (empty cells left out). The default B is
the smallest whose blocks hold 100 grains on average; --block 1 draws the cells themselves.
Grains are the simulated ones, the run's particles over its cells (run.particles of the resolved
case in RUN_DIR/moments.csv's header); without moments.csv, n x cell volume (the grains they
stand for).
For N snapshots spread over the series (default 3: the first, the middle and the last; with
--from C, over the snapshots at C or more collisions per particle) it draws the slice of blocks
that holds cell I (default: the middle one) along --axis (default z: for a slab of one cell along
z, the whole slab) in two rows:
  - the density n over its mean over the box, on a logarithmic colour scale (--linear: a linear
    one) from one grain per block (or the slice's smallest nonzero density, if larger) to the
    slice's largest; empty blocks take the lowest colour. Clusters: dense, cold regions;
  - the vorticity's component along --axis, (curl u)_axis, from the blocks' flow by central
    differences with the blocks' spacing, wrapped around periodic axes and one-sided at the ends
    of the others; blank (grey) next to an empty block. The colour scale is symmetric, up to the
    99th percentile of |curl u| in the slice. Vortices.
Which axes are periodic comes from the header of RUN_DIR/moments.csv (domain.boundary; with
run.kind = shear the Lees-Edwards axis y counts as not periodic). The field files do not record
it: without moments.csv every axis counts as bounded, with one-sided differences at its ends.
Each column's title gives t, collisions per particle, the block in cells and its mean grains.
Writes PNG (default: RUN_DIR/fields_replica_R.png) atomically.
--check: also verify what ParaView's XDMF reader will read: every HDF5 file the sidecar names
(relative to the sidecar's folder, or absolute) exists, holds the dataset, and the dataset's
shape is the sidecar's Dimensions (cells along z, y, x, then the components); each file's row and
t are its grid's; exit 1 on any mismatch or if no panel was drawn.
"""
import argparse
import os
import sys
import tomllib
import xml.etree.ElementTree as ET

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as mticker  # noqa: E402
import numpy as np  # noqa: E402
from atomic_output import save_figure  # noqa: E402

AXES = "xyz"
GRAINS_PER_BLOCK = 100  # the default block holds at least this many grains on average


def read_sidecar(path):
    """The sidecar's snapshots: [(name, time, {attribute: (file, dataset, dimensions)})], each file
    resolved against the sidecar's folder, as ParaView's reader resolves it (an absolute name stays)."""
    folder = os.path.dirname(os.path.abspath(path))
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
            file = os.path.join(folder, file)
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            items[attribute.get("Name")] = (file, dataset, dims, attribute.get("AttributeType"))
        snapshots.append((grid.get("Name"), time, nodes, items))
    return snapshots


def check(snapshots):
    """Problems ParaView would meet, as text (empty: none)."""
    problems = []
    for name, time, nodes, items in snapshots:
        for attr, (file, dataset, dims, kind) in items.items():
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


def resolved_case(run_dir):
    """The resolved case of RUN_DIR/moments.csv's '#' header as a dict, or None without one."""
    path = os.path.join(run_dir, "moments.csv")
    if not os.path.exists(path):
        return None
    lines, inside = [], False
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            text = line[1:].removeprefix(" ").rstrip("\n")
            if text.startswith("resolved case"):
                inside = True
            elif inside and text.startswith("units:"):
                break
            elif inside:
                lines.append(text)
    try:
        return tomllib.loads("\n".join(lines)) if lines else None
    except tomllib.TOMLDecodeError:
        return None


def periodic_axes(case):
    """Per axis x, y, z whether the fields wrap around it (all False when unknown)."""
    try:
        periodic = [b == "periodic" for b in case["domain"]["boundary"]]
        if case["run"].get("kind") == "shear":
            periodic[1] = False  # Lees-Edwards: the images above and below slide along x
        return periodic if len(periodic) == 3 else [False] * 3
    except (KeyError, TypeError, AttributeError):
        return [False] * 3


def starts(cells, block):
    """The first cell of each block of `block` cells along an axis of `cells` cells."""
    return np.arange(0, cells, block)


def coarse(field, weight, blocks):
    """Sums of field[z, y, x, ...] * weight over the blocks (blocks: cells per block along x, y, z)."""
    out = np.where(weight > 0, field * weight, 0.0) if weight is not None else field
    for c in range(3):
        out = np.add.reduceat(out, starts(field.shape[2 - c], blocks[c]), axis=2 - c)
    return out


def block_fields(n, u, blocks):
    """The blocks' mean density n[z, y, x] and number-weighted flow u[z, y, x, 3] (NaN where empty)."""
    count = coarse(np.ones_like(n), None, blocks)
    nb = coarse(n, None, blocks) / count
    if u is None:
        return nb, None
    mass = coarse(n, None, blocks)
    momentum = coarse(np.nan_to_num(u), n[..., None], blocks)
    with np.errstate(invalid="ignore", divide="ignore"):
        ub = np.where(mass[..., None] > 0, momentum / mass[..., None], np.nan)
    return nb, ub


def centres(cells, block, spacing):
    """The block centres along an axis (the last block may be shorter)."""
    s = starts(cells, block)
    e = np.append(s[1:], cells)
    return 0.5 * (s + e) * spacing


def edges(cells, block, spacing):
    return np.append(starts(cells, block), cells) * spacing


def derivative(f, c, x, length, periodic):
    """d f / d x_c of f[z, y, x] on block centres x: central differences, wrapped when periodic."""
    a = 2 - c  # the arrays run z, y, x
    m = f.shape[a]
    if m < 2:
        return np.zeros_like(f)
    if not periodic:
        return np.gradient(f, x, axis=a)  # one-sided at the ends
    padded = np.take(f, np.r_[m - 1, np.arange(m), 0], axis=a)
    xp = np.r_[x[-1] - length, x, x[0] + length]
    return np.take(np.gradient(padded, xp, axis=a), np.arange(1, m + 1), axis=a)


def curl_component(u, axis, coords, box, periodic):
    """(curl u) along `axis` of u[z, y, x, 3] on block centres coords (x, y, z)."""
    a, b = [c for c in range(3) if c != axis]  # the plane's axes, curl_axis = d_a u_b - d_b u_a
    return (derivative(u[..., b], a, coords[a], box[a], periodic[a])
            - derivative(u[..., a], b, coords[b], box[b], periodic[b]))


def plane(field, axis, index):
    """The slice of field[z, y, x] at `index` normal to `axis`, as [row, column] for pcolormesh."""
    if axis == 2:
        return field[index, :, :]  # rows y, columns x
    if axis == 1:
        return field[:, index, :]  # rows z, columns x
    return field[:, :, index]  # rows z, columns y


def block_size(cells, grains_per_cell, requested):
    """Cells per block along x, y, z: `requested` (capped by the cells), or the smallest B whose
    blocks hold GRAINS_PER_BLOCK grains on average."""
    if requested is not None:
        return [min(requested, int(g)) for g in cells]
    if grains_per_cell is None:  # no density to count grains by: the cells themselves
        return [1, 1, 1]
    for b in range(1, int(max(cells)) + 1):
        blocks = [min(b, int(g)) for g in cells]
        if np.prod(blocks) * grains_per_cell >= GRAINS_PER_BLOCK:
            return blocks
    return [int(g) for g in cells]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--replica", type=int, default=0, help="the replica's fields (default 0)")
    parser.add_argument("--times", type=int, default=3, help="snapshots drawn, spread over the series (default 3)")
    parser.add_argument("--from", dest="from_", type=float, metavar="C",
                        help="only the snapshots at C or more collisions per particle")
    parser.add_argument("--axis", choices=list(AXES), default="z", help="the slice's normal (default z)")
    parser.add_argument("--index", type=int, help="the slice's cell along --axis (default: the middle one)")
    parser.add_argument("--block", type=int, metavar="B",
                        help=f"cells per block along each axis (default: the smallest B giving {GRAINS_PER_BLOCK} "
                             "grains per block; 1: no coarse-graining)")
    parser.add_argument("--linear", action="store_true", help="the density on a linear colour scale")
    parser.add_argument("--out", help="PNG file (default: RUN_DIR/fields_replica_R.png)")
    parser.add_argument("--check", action="store_true",
                        help="verify the sidecar's files, datasets and shapes; exit 1 on a mismatch or no panel")
    args = parser.parse_args(argv[1:])
    if args.block is not None and args.block < 1:
        parser.error("--block must be at least 1")
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
    if args.from_ is not None:
        def cpp_of(snapshot):
            with h5py.File(next(iter(snapshot[3].values()))[0], "r") as h:
                return float(h.attrs["coll_per_particle"])
        snapshots = [s for s in snapshots if s[3] and cpp_of(s) >= args.from_]
        if not snapshots:
            print(f"plot_fields: {sidecar}: no snapshot at {args.from_:g} or more collisions per particle",
                  file=sys.stderr)
            return 1
    case = resolved_case(args.run_dir)
    periodic = periodic_axes(case)
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
        spacing = [box[c] / cells[c] for c in range(3)]
        n = u = None
        if "n" in items:
            with h5py.File(items["n"][0], "r") as h:
                n = h[items["n"][1]][...]
        if "u" in items:
            with h5py.File(items["u"][0], "r") as h:
                u = h[items["u"][1]][...]
        if n is None:  # the flow alone: every cell weighs the same
            n_weight = np.where(np.isnan(u[..., 0]), 0.0, 1.0) if u is not None else None
        else:
            n_weight = n
        mean_n = n.mean() if n is not None else None
        grains_per_cell = None  # on average: the simulated grains, else the grains n stands for
        if n is not None:
            try:
                grains_per_cell = int(case["run"]["particles"]) / int(np.prod(cells))
            except (KeyError, TypeError, ValueError):
                grains_per_cell = mean_n * float(np.prod(spacing))
        blocks = block_size(cells, grains_per_cell, args.block)
        if n_weight is None:
            continue
        nb, ub = block_fields(n_weight, u, blocks)
        coords = [centres(int(cells[c]), blocks[c], spacing[c]) for c in range(3)]
        xe, ye = (edges(int(cells[c]), blocks[c], spacing[c]) for c in plane_axes)
        slice_index = index // blocks[axis]
        block_text = " x ".join(str(blocks[c]) for c in range(3) if cells[c] > 1)
        title = f"t = {time:.4g}, {cpp:.4g} coll./particle\n" + (
            f"blocks of {block_text} cells" if np.prod(blocks) > 1 else "single cells")
        if grains_per_cell is not None:
            block_grains = grains_per_cell * np.prod(blocks)
            title += f", {block_grains:.0f} grains" if block_grains >= 10 else f", {block_grains:.2g} grains"
        if n is not None:
            rel = plane(nb / mean_n, axis, slice_index)
            if args.linear:
                norm, extend = mcolors.Normalize(vmin=0.0, vmax=max(float(rel.max()), 1e-300)), "neither"
                cmap = plt.get_cmap("magma")
            else:
                positive = rel[rel > 0]
                low = max(1.0 / block_grains, float(positive.min()) if positive.size else 1.0)
                high = max(float(rel.max()), low * 1.0001)
                norm = mcolors.LogNorm(vmin=low, vmax=high)
                extend = "min" if (rel < low).any() else "neither"
                base = plt.get_cmap("magma")
                cmap = base.with_extremes(under=base(0.0))
            im = ax[0][j].pcolormesh(xe, ye, rel, cmap=cmap, norm=norm, shading="flat")
            bar = fig.colorbar(im, ax=ax[0][j], shrink=0.8, label="n/<n>", extend=extend)
            if not args.linear:  # plain numbers; 1, 2, 5 per decade over up to two decades, 1 to 9 within 3x
                plain = mticker.FuncFormatter(lambda v, _: f"{v:g}")
                span = norm.vmax / norm.vmin
                if span < 300:
                    bar.ax.yaxis.set_major_locator(mticker.LogLocator(subs=(1, 2, 5) if span >= 3 else "all"))
                bar.ax.yaxis.set_major_formatter(plain)
                bar.ax.yaxis.set_minor_formatter(mticker.NullFormatter())
            drawn += 1
        ax[0][j].set_title(title, fontsize=8)
        if u is not None:
            w = plane(curl_component(ub, axis, coords, box, periodic), axis, slice_index)
            finite = np.abs(w[np.isfinite(w)])
            scale = float(np.percentile(finite, 99)) if finite.size else 0.0
            scale = scale or 1.0
            cmap = plt.get_cmap("RdBu_r").with_extremes(bad="0.75")
            im = ax[1][j].pcolormesh(xe, ye, np.ma.masked_invalid(w), cmap=cmap, vmin=-scale, vmax=scale,
                                     shading="flat")
            fig.colorbar(im, ax=ax[1][j], shrink=0.8, label=f"(curl u)_{args.axis}", extend="both")
            drawn += 1
        for r in range(2):
            ax[r][j].set_aspect("equal")
            ax[r][j].set_xlabel(AXES[plane_axes[0]])
            ax[r][j].set_ylabel(AXES[plane_axes[1]])
    scale_name = "linear" if args.linear else "log"
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.run_dir))}, replica {args.replica}: density ({scale_name}) "
                 f"and vorticity, cells {args.axis} = {args.index if args.index is not None else 'middle'}", fontsize=9)
    out = args.out or os.path.join(args.run_dir, f"fields_replica_{args.replica}.png")
    fig.tight_layout()
    save_figure(fig, out)
    plt.close(fig)
    print(f"plot_fields: wrote {out}")
    if args.check and drawn == 0:
        print("plot_fields: no panel drawn (the fields hold neither n nor u)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
