#!/usr/bin/python3
# Copyright (c) 2026 CGAL Global Shape Analysis contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Renders a point cloud segmented by `shape_analysis points recognize` (or `points segment`) as
a PNG figure of the manual, headless, with matplotlib's Agg backend (Debian: python3-matplotlib;
run it with /usr/bin/python3).

Every object (the PLY's `object` property, >= 0) gets its own colour; the points left out as
ground (`ground` = 1) are light grey, the other points (buildings, trees, isolated points) a darker
grey. The view is an orthographic projection from the given azimuth and elevation, the points drawn
from the farthest to the nearest.

The figure of the Point_set_object_recognition manual (doc/Point_set_object_recognition/fig/
recognized_street.png and its small version) was made with:

    shape_analysis points generate --seed 1 --points 250000 --length 100 \\
        --output street.ply --truth street.json
    shape_analysis points recognize street.ply --output street_objects.ply \\
        --locations street_locations.csv --report street_report.json
    doc/render_point_cloud_figure.py street_objects.ply \\
        doc/Point_set_object_recognition/fig/recognized_street.png \\
        --small doc/Point_set_object_recognition/fig/recognized_street_small.png \\
        --elevation 50 --near-limit 9.5 --point-size 2 --x-range 20 75 --background-fraction 0.8

The figure coloured by class (recognized_classes.png) was made the same way from the same street,
recognized with a model trained on two other streets:

    shape_analysis points generate --seed 2 --points 4000000 --length 800 --output t2.ply --truth t2.json
    shape_analysis points generate --seed 3 --points 4000000 --length 800 --output t3.ply --truth t3.json
    shape_analysis points train t2.ply t3.ply --labels t2.json t3.json --min-points 20 --output model.json
    shape_analysis points recognize street.ply --model model.json --output street_classes.ply
    doc/render_point_cloud_figure.py street_classes.ply \\
        doc/Point_set_object_recognition/fig/recognized_classes.png --by-class \\
        --elevation 50 --near-limit 9.5 --point-size 2 --x-range 20 75 --background-fraction 0.8

(the street runs along x; its facades stand at y = -10 and y = 10 m, and --near-limit leaves out
the one between the viewer and the street).
"""

import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
             "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
             "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
             "float64": "f8"}


def read_ply_vertices(path):
    """The vertex element of a PLY file (ascii or binary) as a numpy structured array."""
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline()
            if not line:
                sys.exit(path + ": no end_header")
            line = line.decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        fmt = header[1].split()[1]
        elements = []
        for line in header:
            words = line.split()
            if words[:1] == ["element"]:
                elements.append((words[1], int(words[2]), []))
            elif words[:1] == ["property"]:
                if words[1] == "list":
                    sys.exit(path + ": list properties before the vertices are not supported")
                elements[-1][2].append((words[2], PLY_TYPES[words[1]]))
        name, count, properties = elements[0]
        if name != "vertex":
            sys.exit(path + ": the first element is not 'vertex'")
        if fmt == "ascii":
            data = np.loadtxt(f, max_rows=count)
            result = np.zeros(count, dtype=[(n, t) for n, t in properties])
            for i, (n, _) in enumerate(properties):
                result[n] = data[:, i]
            return result
        order = "<" if fmt == "binary_little_endian" else ">"
        dtype = np.dtype([(n, order + t) for n, t in properties])
        return np.frombuffer(f.read(dtype.itemsize * count), dtype=dtype, count=count)


def palette(n):
    """n distinct, saturated colours in a fixed order (no greys: those mark the background)."""
    base = [plt.get_cmap("tab10")(i) for i in (0, 1, 2, 3, 4, 5, 6, 8, 9)]
    base += [plt.get_cmap("Dark2")(i) for i in range(7)]
    return [base[i % len(base)] for i in range(n)]


def class_names(path):
    """The class names of the header comment 'label: 0 car, 1 pedestrian, ...' of a PLY file."""
    names = {}
    with open(path, "rb") as f:
        for raw in f:
            line = raw.decode("latin-1").strip()
            if line == "end_header":
                break
            if line.startswith("comment label:"):
                body = line[len("comment label:"):].split(" (-1")[0]
                for item in body.split(","):
                    number, _, name = item.strip().partition(" ")
                    names[int(number)] = name
    return names


def save(fig, path, colours):
    """Saves the figure as a PNG file with a palette of `colours` colours."""
    from io import BytesIO

    from PIL import Image
    buffer = BytesIO()
    fig.savefig(buffer, format="png", dpi=100)
    image = Image.open(buffer).convert("RGB")
    image.convert("P", palette=Image.Palette.ADAPTIVE, colors=colours).save(path, optimize=True)


def main():
    parser = argparse.ArgumentParser(description="Renders a segmented point cloud to a PNG file.")
    parser.add_argument("ply")
    parser.add_argument("output")
    parser.add_argument("--small", help="also write a 120 x 90 picture for the package overview")
    parser.add_argument("--azimuth", type=float, default=90.0,
                        help="the direction the viewer looks, around z from the x axis, in degrees "
                             "(90: towards +y)")
    parser.add_argument("--elevation", type=float, default=35.0, help="in degrees above the horizon")
    parser.add_argument("--width", type=float, default=10.0, help="inches, at 100 dpi")
    parser.add_argument("--point-size", type=float, default=0.6)
    parser.add_argument("--background-fraction", type=float, default=0.5,
                        help="the fraction of the background points drawn")
    parser.add_argument("--x-range", type=float, nargs=2, default=None, metavar=("MIN", "MAX"),
                        help="draw only the points whose x lies in this range")
    parser.add_argument("--colours", type=int, default=256,
                        help="the PNG is written with a palette of this many colours (smaller)")
    parser.add_argument("--by-class", action="store_true",
                        help="colour the objects by their class (the PLY's 'label' property of "
                             "'points recognize --model', its names in the header comment), with "
                             "a legend; objects of the class 'background' stay grey")
    parser.add_argument("--near-limit", type=float, default=None,
                        help="leave out the points nearer to the viewer than this distance from the "
                             "centre (for instance the facade between the viewer and the street)")
    args = parser.parse_args()

    v = read_ply_vertices(args.ply)
    x, y, z = (v[c].astype(float) for c in ("x", "y", "z"))
    obj = v["object"].astype(int) if "object" in v.dtype.names else np.full(len(v), -1)
    ground = v["ground"].astype(bool) if "ground" in v.dtype.names else np.zeros(len(v), bool)

    a, e = np.radians(args.azimuth), np.radians(args.elevation)
    # Camera: looking along `forward` (azimuth a around z from the x axis, elevation e downwards);
    # `right` and `up` are the image's axes.
    forward = np.array([np.cos(a) * np.cos(e), np.sin(a) * np.cos(e), -np.sin(e)])
    right = np.array([np.sin(a), -np.cos(a), 0.0])
    up = np.cross(right, forward)
    p = np.stack([x - x.mean(), y - y.mean(), z - z.min()], axis=1)
    u, w, depth = p @ right, p @ up, p @ forward

    rng = np.random.default_rng(1)
    is_object = obj >= 0
    keep = is_object | (rng.random(len(v)) < args.background_fraction)
    if args.x_range is not None:
        keep &= (x >= args.x_range[0]) & (x <= args.x_range[1])
    if args.near_limit is not None:
        horizontal = np.array([np.cos(a), np.sin(a), 0.0])
        keep &= p @ horizontal > -args.near_limit
    ids = np.unique(obj[is_object])
    colours = np.zeros((len(v), 4))
    colours[:] = (0.45, 0.45, 0.45, 1.0)
    colours[ground] = (0.78, 0.78, 0.78, 1.0)
    legend = []
    if args.by_class:
        names = class_names(args.ply)
        label = v["label"].astype(int)
        shown = [c for c in np.unique(label[is_object & keep]) if names.get(c, "background") != "background"]
        for c, colour in zip(shown, palette(len(shown))):
            colours[is_object & (label == c)] = colour
            legend.append((names.get(c, str(c)), colour))
    else:
        lookup = dict(zip(ids, palette(len(ids))))
        for i in ids:
            colours[obj == i] = lookup[i]

    u, w, depth = u[keep], w[keep], depth[keep]
    colours = colours[keep]
    sel = np.argsort(-depth, kind="stable")  # farthest first
    aspect = (w.max() - w.min()) / (u.max() - u.min())
    fig = plt.figure(figsize=(args.width, max(2.0, args.width * aspect)), dpi=100)
    ax = fig.add_axes([0, 0, 1, 1])
    # Square markers without antialiasing: every pixel takes one of the few colours, so that the
    # palette of the PNG file keeps them exactly.
    sizes = np.where(is_object[keep], 2.0 * args.point_size, args.point_size)
    ax.scatter(u[sel], w[sel], s=sizes[sel], c=colours[sel], marker="s", linewidths=0,
               antialiased=False, rasterized=True)
    ax.set_xlim(u.min(), u.max())
    ax.set_ylim(w.min(), w.max())
    ax.set_aspect("equal")
    ax.axis("off")
    if legend:
        handles = [plt.Line2D([], [], marker="s", linestyle="", color=c, label=n) for n, c in legend]
        ax.legend(handles=handles, loc="upper left", ncol=min(len(handles), 5), fontsize=8, frameon=False)
    save(fig, args.output, args.colours)
    print("%s: %d points drawn, %d objects" % (args.output, len(sel), len(ids)))

    if args.small:
        fig.set_size_inches(1.2, 0.9)
        ax.set_aspect("auto")
        cx = 0.5 * (u.min() + u.max())
        half = 0.5 * (w.max() - w.min()) * 1.2 / 0.9
        ax.set_xlim(cx - half, cx + half)
        for c in ax.collections:
            c.set_sizes([args.point_size * 0.5])
        save(fig, args.small, args.colours)
    return 0


if __name__ == "__main__":
    sys.exit(main())
