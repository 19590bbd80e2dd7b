#!/usr/bin/env python3
"""Examples from the CMP Facade Database (Tylecek and Sara 2013).

The database's base set annotates 378 rectified facade photographs with
labelled rectangles (facade, window, door, sill, blind, balcony, cornice,
molding, pillar, shop, deco, background), one XML file per facade, the
coordinates as fractions of the image (<x> down its height from the top,
<y> across its width: a door's <x> is near 1). This writes each facade as an OBJ
example: every rectangle a thin box labelled by its class, the facade
`--width` metres wide (default 15), as tall as the photograph's aspect
says (read from the JPEG beside the XML, when there is one), `--depth`
metres deep (default 0.2), z up.

The dataset is not part of the project: point this at a folder holding its
XML files (and JPEGs), for example the `base/` folder of a copy of it.

  scripts/cmp_facades.py DATASET_FOLDER OUT_FOLDER [--labels window,door]
                         [--count N] [--width 15] [--depth 0.2] [--drop-overlapping]

--labels keeps only the rectangles of those classes (the form `windows and
doors`); without it every rectangle is written, overlaps and all, as
annotated. --drop-overlapping leaves out a rectangle that overlaps one
written before it (a window annotated twice, as a few are). --count takes the first N facades (by file name).
Each output is OUT_FOLDER/<name>.obj; an existing file is replaced only
through a temporary file renamed into place.
"""

import argparse
import os
import struct
import sys
import tempfile
import xml.etree.ElementTree as ET


def jpeg_size(path):
    """(width, height) from a JPEG's first frame header, or None."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    if data[:2] != b"\xff\xd8":
        return None
    at = 2
    while at + 4 <= len(data):
        if data[at] != 0xFF:
            return None
        marker = data[at + 1]
        length = struct.unpack(">H", data[at + 2:at + 4])[0]
        # Start-of-frame markers (baseline, progressive, ...) hold the size.
        if marker in (0xC0, 0xC1, 0xC2, 0xC3, 0xC5, 0xC6, 0xC7, 0xC9, 0xCA, 0xCB, 0xCD, 0xCE, 0xCF):
            height, width = struct.unpack(">HH", data[at + 5:at + 9])
            return width, height
        at += 2 + length
    return None


def rectangles(xml_path):
    """The facade's rectangles: (label, x0, x1, y0, y1), fractions of the image, x across, y downwards."""
    text = open(xml_path, encoding="utf-8").read()
    # The files hold a sequence of <object> elements without one root.
    root = ET.fromstring("<annotation>" + text + "</annotation>")
    out = []
    for obj in root.iter("object"):
        name = obj.findtext("labelname")
        points = obj.find("points")
        if name is None or points is None:
            raise ValueError(f"{xml_path}: an object without a labelname or points")
        xs = [float(x.text) for x in points.findall("x")]
        ys = [float(y.text) for y in points.findall("y")]
        if len(xs) != 2 or len(ys) != 2:
            raise ValueError(f"{xml_path}: an object '{name}' without two x and two y")
        # The set's <x> values run down the image's rows and its <y> values
        # across its columns (a door's <x> is near 1, its bottom, as the
        # label maps beside the XML files show): x here is across.
        out.append((name.strip(), min(ys), max(ys), min(xs), max(xs)))
    return out


def box_lines(index, lo, hi):
    """The 8 vertices and 6 quads of an axis-aligned box, vertex numbers from index + 1."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    corners = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
               (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    lines = ["v %.6f %.6f %.6f" % c for c in corners]
    faces = [(1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)]
    lines += ["f " + " ".join(str(index + k) for k in face) for face in faces]
    return lines


def without_overlaps(rects):
    """The rectangles, each left out that overlaps (with some area) one kept before it."""
    kept = []
    for r in rects:
        _, x0, x1, y0, y1 = r
        if all(min(x1, k[2]) <= max(x0, k[1]) or min(y1, k[4]) <= max(y0, k[3]) for k in kept):
            kept.append(r)
    return kept


def facade_obj(rects, width, height, depth, name):
    # One group: a facade is one example, even where a background
    # rectangle stands apart from it (infer --buildings apart would
    # otherwise read parts standing apart on the ground as buildings).
    lines = ["# up z", "# a CMP facade: one thin box per annotated rectangle", "g " + name]
    used = {}
    vertices = 0
    for label, x0, x1, y0, y1 in rects:
        if x1 <= x0 or y1 <= y0:
            continue  # an empty rectangle (the set has one) is no part
        used[label] = used.get(label, 0) + 1
        lines.append("o %s.%03d" % (label, used[label]))
        lo = (x0 * width, 0.0, (1.0 - y1) * height)
        hi = (x1 * width, depth, (1.0 - y0) * height)
        lines += box_lines(vertices, lo, hi)
        vertices += 8
    return "\n".join(lines) + "\n"


def write_atomically(path, text):
    folder = os.path.dirname(os.path.abspath(path))
    fd, temp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(temp, path)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dataset")
    parser.add_argument("out")
    parser.add_argument("--labels", default="", help="comma-separated classes to keep (default: all)")
    parser.add_argument("--count", type=int, default=0, help="the first N facades (default: all)")
    parser.add_argument("--width", type=float, default=15.0)
    parser.add_argument("--depth", type=float, default=0.2)
    parser.add_argument("--drop-overlapping", action="store_true", help="leave out a rectangle overlapping one before it")
    args = parser.parse_args()
    if not os.path.isdir(args.dataset):
        sys.exit(f"cmp_facades: {args.dataset}: not a folder\n  hint: give the folder of the dataset's XML files (its base/)")
    if not os.path.isdir(args.out):
        sys.exit(f"cmp_facades: {args.out}: not an existing folder\n  hint: create it first")
    keep = {s.strip() for s in args.labels.split(",") if s.strip()}
    names = sorted(n for n in os.listdir(args.dataset) if n.endswith(".xml"))
    if args.count > 0:
        names = names[:args.count]
    if not names:
        sys.exit(f"cmp_facades: {args.dataset}: no .xml files\n  hint: give the folder of the dataset's XML files (its base/)")
    for name in names:
        stem = name[:-4]
        rects = rectangles(os.path.join(args.dataset, name))
        if keep:
            rects = [r for r in rects if r[0] in keep]
        if args.drop_overlapping:
            rects = without_overlaps(rects)
        size = jpeg_size(os.path.join(args.dataset, stem + ".jpg"))
        height = args.width * size[1] / size[0] if size else args.width
        write_atomically(os.path.join(args.out, stem + ".obj"), facade_obj(rects, args.width, height, args.depth, stem))
    print(f"cmp_facades: {len(names)} facades -> {args.out}")


if __name__ == "__main__":
    main()
