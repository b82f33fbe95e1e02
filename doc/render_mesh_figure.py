#!/usr/bin/python3
# Copyright (c) 2026 CGAL Global Shape Analysis contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Renders triangle meshes (OFF files) side by side as one PNG figure of the manual, headless, with
matplotlib's Agg backend (Debian: python3-matplotlib; run it with /usr/bin/python3).

Every mesh is a panel with its own title, all seen in the same orthographic view (azimuth and
elevation around the --up axis). The faces are drawn from the farthest to the nearest (painter's
algorithm), flat shaded by a light fixed to the viewer, with thin dark edges so that the
triangulation shows.

A panel is either plain (light grey) or mirror-coloured: with the mirror plane given by --plane
(unit normal n and offset d of the plane n.x = d), every face is reflected across the plane, the
face having the reflected vertices is looked up (vertices matched by position, to 1e-6 of the
bounding box diagonal by default), and the two faces get the same colour, taken from a palette by a
hash of the smaller of their two indices (a face that is its own mirror keeps its own colour). The
faces whose mirror is not found are bright red, and their number is printed for every panel: on a
mesh with a mirror-symmetric connectivity it is 0, and the colours repeat mirrored across the plane.

The panels are given as positional arguments PATH[:STYLE[:TITLE]], STYLE being `plain` (the
default), `mirror` (about the plane of --plane) or `mirror=PLANE` (about PLANE, for this panel
only), TITLE the panel's title (the file name by default; it may contain colons). A plane is
written nx,ny,nz,d or given as a JSON report of shape_analysis (its key "plane").

The figure of the Surface_mesh_symmetrization manual (doc/Surface_mesh_symmetrization/fig/
symmetric_remeshing.png) shows CGAL's cow (5,804 triangles), its symmetrization, its symmetric
remeshing (`symmetry remesh` symmetrizes the cow first, then remeshes it) and that remeshing
decimated to a fifth of its faces. It was made in a scratch directory, REPO being the repository
and REPO/build its build directory, with:

    cp $REPO/build/data/cow.off input.off
    $REPO/build/examples/symmetrize    # writes the symmetrized cow to cow_symmetric.off
    mv cow_symmetric.off symmetrized.off
    S=$REPO/build/src/shape_analysis
    $S symmetry remesh input.off --output remeshed.off --report remeshed.json
    $S symmetry decimate remeshed.off --faces 1160 --output fifth.off --report fifth.json
    /usr/bin/python3 $REPO/doc/render_mesh_figure.py input.off:plain:"input (5,804 faces)" \\
        symmetrized.off:plain:"symmetrized (5,804 faces)" \\
        remeshed.off:mirror:"remeshed (5,804 faces)" \\
        fifth.off:mirror:"decimated to a fifth (1,160 faces)" \\
        --plane remeshed.json --azimuth 90 --elevation 60 \\
        --output $REPO/doc/Surface_mesh_symmetrization/fig/symmetric_remeshing.png

The cow's length runs along x, its head towards +x, its up axis is y and its mirror plane is
z = 0: the view from behind and above (azimuth 90, elevation 60) sees the plane edge-on, as the
vertical line through the middle of every panel. `symmetry decimate` detects the plane of
remeshed.off again: its vertices are exact mirror pairs, so the detected plane is fitted to them
and equals the plane of remeshed.json to rounding (fifth.json has it too).
"""

import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

PLAIN_COLOUR = (0.85, 0.85, 0.85)
MISSING_COLOUR = (1.0, 0.0, 0.0)
EDGE_COLOUR = (0.2, 0.2, 0.2)


def read_off(path):
    """The vertices (n x 3 floats) and triangles (m x 3 ints) of an OFF file."""
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            words.extend(line.split())
    if not words or words[0] != "OFF":
        sys.exit(path + ": not an OFF file (no 'OFF' header)")
    n_vertices, n_faces = int(words[1]), int(words[2])
    at = 4
    vertices = np.array(words[at:at + 3 * n_vertices], dtype=float).reshape(n_vertices, 3)
    at += 3 * n_vertices
    faces = np.empty((n_faces, 3), dtype=np.int64)
    for i in range(n_faces):
        if words[at] != "3":
            sys.exit("%s: face %d is not a triangle" % (path, i))
        faces[i] = [int(w) for w in words[at + 1:at + 4]]
        at += 4
    if len(faces) and (faces.min() < 0 or faces.max() >= n_vertices):
        sys.exit(path + ": a face refers to a vertex that does not exist")
    return vertices, faces


def palette():
    """Distinct colours for the face pairs: tab20 without its greys and reds (red marks the faces
    without a mirror, grey the plain panels)."""
    cmap = plt.get_cmap("tab20")
    return np.array([cmap(i)[:3] for i in range(20) if i not in (6, 7, 14, 15)])


def pair_colour_index(face, count):
    """A palette index spread by a multiplicative hash of the face index, so that neighbouring
    faces (which often have close indices) seldom share a colour."""
    return ((int(face) + 1) * 2654435761 % (1 << 32) >> 12) % count


def match_vertices(points, targets, tolerance):
    """For every point, the index of the target vertex nearest to it if it lies within
    `tolerance`, else -1; and the largest distance of a matched point. The targets are hashed in a
    grid of cells of side `tolerance`, and every point looks in its cell and the 26 around it."""
    cells = {}
    keys = np.floor(targets / tolerance).astype(np.int64)
    for i, key in enumerate(map(tuple, keys)):
        cells.setdefault(key, []).append(i)
    around = [(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)]
    result = np.full(len(points), -1, dtype=np.int64)
    worst = 0.0
    for i, (p, key) in enumerate(zip(points, np.floor(points / tolerance).astype(np.int64))):
        best, best_distance = -1, tolerance
        for a, b, c in around:
            for j in cells.get((key[0] + a, key[1] + b, key[2] + c), ()):
                distance = float(np.linalg.norm(targets[j] - p))
                if distance <= best_distance:
                    best, best_distance = j, distance
        result[i] = best
        if best >= 0:
            worst = max(worst, best_distance)
    return result, worst


def mirror_faces(vertices, faces, normal, offset, tolerance):
    """For every face the index of its mirror face across the plane normal.x = offset, or -1; and
    the largest distance between a reflected vertex and the vertex matched to it."""
    reflected = vertices - 2.0 * np.outer(vertices @ normal - offset, normal)
    image, worst = match_vertices(reflected, vertices, tolerance)
    by_vertices = {tuple(sorted(f)): i for i, f in enumerate(faces.tolist())}
    mirror = np.full(len(faces), -1, dtype=np.int64)
    for i, f in enumerate(faces.tolist()):
        corners = image[f]
        if (corners >= 0).all():
            mirror[i] = by_vertices.get(tuple(sorted(corners.tolist())), -1)
    return mirror, worst


def camera(azimuth, elevation, up_axis):
    """The image's right and up vectors and the viewing direction, in world coordinates. The
    azimuth turns around the up axis, from the first horizontal axis (z for up = y, x for up = z,
    y for up = x) towards the second one; the elevation is the angle above the horizon the viewer
    looks down from."""
    up = "xyz".index(up_axis)
    h1, h2 = (up + 1) % 3, (up + 2) % 3
    a, e = np.radians(azimuth), np.radians(elevation)

    def world(c1, c2, c3):
        v = np.zeros(3)
        v[h1], v[h2], v[up] = c1, c2, c3
        return v

    forward = world(np.cos(a) * np.cos(e), np.sin(a) * np.cos(e), -np.sin(e))
    right = world(np.sin(a), -np.cos(a), 0.0)
    return right, np.cross(right, forward), forward


def parse_plane(text):
    """A plane (unit normal, offset) from 'nx,ny,nz,d' or from the key "plane" ("normal" and
    "offset") of a JSON report of shape_analysis."""
    if text.endswith(".json"):
        with open(text) as f:
            plane = json.load(f)["plane"]
        values = list(plane["normal"]) + [plane["offset"]]
    else:
        values = [float(v) for v in text.split(",")]
    if len(values) != 4:
        sys.exit("%s: a plane is four numbers nx,ny,nz,d or a JSON file" % text)
    normal = np.array(values[:3], dtype=float)
    length = np.linalg.norm(normal)
    return normal / length, float(values[3]) / length


def parse_panel(spec, default_plane):
    """(path, plane or None, title) of a panel PATH[:STYLE[:TITLE]]."""
    path, _, rest = spec.partition(":")
    style, _, title = rest.partition(":")
    style, _, plane = (style or "plain").partition("=")
    if style not in ("plain", "mirror"):
        sys.exit("%s: the style is 'plain' or 'mirror', not '%s'" % (spec, style))
    if style == "mirror":
        plane = parse_plane(plane) if plane else default_plane
        if plane is None:
            sys.exit("%s: a mirror panel needs a plane (--plane or mirror=PLANE)" % spec)
    else:
        plane = None
    return path, plane, title or os.path.basename(path)


def main():
    parser = argparse.ArgumentParser(
        description="Renders triangle meshes (OFF) side by side to a PNG file.",
        epilog="A panel is PATH[:STYLE[:TITLE]], STYLE 'plain', 'mirror' or 'mirror=PLANE'.")
    parser.add_argument("panels", nargs="+", metavar="PATH[:STYLE[:TITLE]]",
                        help="STYLE: plain, mirror (the plane of --plane) or mirror=PLANE (a "
                        "plane nx,ny,nz,d or a JSON report, for this panel)")
    parser.add_argument("--output", "-o", required=True, help="the PNG file written")
    parser.add_argument("--plane", help="the mirror plane n.x = d of the mirror panels: "
                        "nx,ny,nz,d (write --plane=..., the value may begin with a minus sign) "
                        "or a JSON report of shape_analysis, its key 'plane'")
    parser.add_argument("--tolerance", type=float, default=1e-6,
                        help="the distance, relative to the bounding box diagonal, within which a "
                        "reflected vertex matches a vertex")
    parser.add_argument("--up", choices="xyz", default="y", help="the world's up axis")
    parser.add_argument("--azimuth", type=float, default=0.0,
                        help="in degrees around the up axis (see camera() for the axes)")
    parser.add_argument("--elevation", type=float, default=30.0,
                        help="in degrees above the horizon (90: from above)")
    parser.add_argument("--roll", type=float, default=0.0,
                        help="turns the picture in its plane, in degrees, counterclockwise")
    parser.add_argument("--ambient", type=float, default=0.6,
                        help="the part of the brightness that does not depend on the light")
    parser.add_argument("--light", default="-0.3,0.5,1.0",
                        help="the light direction in the viewer's frame (right, up, towards the "
                        "viewer)")
    parser.add_argument("--size", type=int, nargs=2, default=(1600, 450), metavar=("W", "H"),
                        help="the size of the picture in pixels")
    parser.add_argument("--dpi", type=float, default=100.0)
    parser.add_argument("--linewidth", type=float, default=0.15, help="of the edges, in points")
    parser.add_argument("--title-size", type=float, default=11.0)
    parser.add_argument("--colours", type=int, default=0,
                        help="if > 0, the PNG is written with a palette of this many colours "
                        "(smaller file)")
    args = parser.parse_args()

    if args.tolerance <= 0:
        sys.exit("--tolerance must be positive")
    default_plane = parse_plane(args.plane) if args.plane else None
    panels = [parse_panel(s, default_plane) for s in args.panels]

    right, up, forward = camera(args.azimuth, args.elevation, args.up)
    r = np.radians(args.roll)
    right, up = np.cos(r) * right + np.sin(r) * up, -np.sin(r) * right + np.cos(r) * up
    light = np.array([float(v) for v in args.light.split(",")])
    light /= np.linalg.norm(light)
    colours_of_pairs = palette()

    drawn = []
    for path, plane, title in panels:
        vertices, faces = read_off(path)
        diagonal = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))
        if plane is not None:
            mirror, worst = mirror_faces(vertices, faces, plane[0], plane[1],
                                         args.tolerance * diagonal)
            missing = int((mirror < 0).sum())
            base = np.empty((len(faces), 3))
            for i, m in enumerate(mirror):
                base[i] = MISSING_COLOUR if m < 0 else \
                    colours_of_pairs[pair_colour_index(min(i, m), len(colours_of_pairs))]
            print("%s: %d faces, %d without a mirror face, %d their own mirror; largest distance "
                  "of a reflected vertex to its match %.3g (%.3g of the diagonal)"
                  % (path, len(faces), missing, int((mirror == np.arange(len(faces))).sum()),
                     worst, worst / diagonal))
        else:
            base = np.tile(PLAIN_COLOUR, (len(faces), 1))
            print("%s: %d faces" % (path, len(faces)))
        # Viewer's frame: u to the right, w up, depth towards the viewer.
        view = np.stack([vertices @ right, vertices @ up, -(vertices @ forward)], axis=1)
        corners = view[faces]
        normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        lengths = np.linalg.norm(normals, axis=1)
        lengths[lengths == 0] = 1.0
        # Two-sided lighting: the orientation of the faces does not matter.
        lambert = np.abs(normals @ light) / lengths
        shade = (args.ambient + (1.0 - args.ambient) * lambert)[:, None]
        order = np.argsort(corners[:, :, 2].mean(axis=1), kind="stable")  # farthest first
        drawn.append((title, corners[order][:, :, :2], np.clip(base[order] * shade, 0, 1)))

    # The same scale and extent for all the panels.
    lows = np.min([c.reshape(-1, 2).min(axis=0) for _, c, _ in drawn], axis=0)
    highs = np.max([c.reshape(-1, 2).max(axis=0) for _, c, _ in drawn], axis=0)
    centre, extent = 0.5 * (lows + highs), (highs - lows) * 1.03
    width, height = args.size
    fig = plt.figure(figsize=(width / args.dpi, height / args.dpi), dpi=args.dpi)
    fig.patch.set_facecolor("white")
    title_band = 2.2 * args.title_size / 72.0 * args.dpi / height
    panel_width = 1.0 / len(drawn)
    for k, (title, polygons, colours) in enumerate(drawn):
        ax = fig.add_axes([k * panel_width, 0.0, panel_width, 1.0 - title_band])
        ax.add_collection(PolyCollection(polygons, facecolors=colours, edgecolors=EDGE_COLOUR,
                                         linewidths=args.linewidth))
        # Keep the aspect ratio: widen the extent in whichever direction the axes box is longer.
        box_ratio = (panel_width * width) / ((1.0 - title_band) * height)
        half = 0.5 * np.array([max(extent[0], extent[1] * box_ratio),
                               max(extent[1], extent[0] / box_ratio)])
        ax.set_xlim(centre[0] - half[0], centre[0] + half[0])
        ax.set_ylim(centre[1] - half[1], centre[1] + half[1])
        ax.set_aspect("equal")
        ax.axis("off")
        fig.text((k + 0.5) * panel_width, 1.0 - 0.5 * title_band, title, ha="center",
                 va="center", fontsize=args.title_size)

    if args.colours > 0:
        from io import BytesIO

        from PIL import Image
        buffer = BytesIO()
        fig.savefig(buffer, format="png", dpi=args.dpi, facecolor="white")
        image = Image.open(buffer).convert("RGB")
        image.convert("P", palette=Image.Palette.ADAPTIVE, colors=args.colours).save(
            args.output, optimize=True)
    else:
        fig.savefig(args.output, dpi=args.dpi, facecolor="white",
                    pil_kwargs={"optimize": True})
    print("%s written, %d x %d pixels" % (args.output, width, height))
    return 0


if __name__ == "__main__":
    sys.exit(main())
