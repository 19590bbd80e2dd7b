#!/usr/bin/env python3
"""Writes the built-in primitive meshes, data/primitives/*.obj.

Each primitive is a closed solid that exactly fills the unit box [0,1]^3
(z is up), written as one OBJ object with positions, texture coordinates and
per-face (flat) normals. Faces are convex polygons listed here with their
outward normal; the script orders each face's corners counter-clockwise as
seen from outside, so the winding cannot disagree with the normal.

    scripts/make_primitives.py            rewrite data/primitives/
    scripts/make_primitives.py --check    exit 1 if the files are out of date
    scripts/make_primitives.py --out DIR  write somewhere else

The output depends only on this file: same script, same bytes.
"""

import argparse
import math
import os
import sys

# ---------------------------------------------------------------- geometry


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(v):
    length = math.sqrt(dot(v, v))
    return (v[0] / length, v[1] / length, v[2] / length)


def face(points, outward):
    """A convex face: its corners sorted counter-clockwise about `outward`."""
    n = len(points)
    c = tuple(sum(p[i] for p in points) / n for i in range(3))
    # An in-plane basis (u, w) with u x w along the outward normal.
    u = unit(sub(points[0], c))
    w = cross(unit(outward), u)
    ordered = sorted(points, key=lambda p: math.atan2(dot(sub(p, c), w), dot(sub(p, c), u)))
    # The geometric normal must agree with the declared one: catches typos.
    normal = (0.0, 0.0, 0.0)
    for i in range(n):  # Newell's method
        a, b = ordered[i], ordered[(i + 1) % n]
        normal = (normal[0] + (a[1] - b[1]) * (a[2] + b[2]),
                  normal[1] + (a[2] - b[2]) * (a[0] + b[0]),
                  normal[2] + (a[0] - b[0]) * (a[1] + b[1]))
    normal = unit(normal)
    if dot(normal, unit(outward)) < 1 - 1e-9:
        sys.exit(f"make_primitives: face {points} is not planar or its normal is not {outward}")
    # Start at the lowest corner (z, then y, then x) so the text reads calmly.
    first = min(range(n), key=lambda i: (ordered[i][2], ordered[i][1], ordered[i][0]))
    return (ordered[first:] + ordered[:first], normal)


def box_faces(x0, x1, y0, y1, z0, z1):
    return [
        face([(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)], (0, 0, -1)),
        face([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], (0, 0, 1)),
        face([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], (0, -1, 0)),
        face([(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)], (0, 1, 0)),
        face([(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)], (-1, 0, 0)),
        face([(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)], (1, 0, 0)),
    ]


def base():
    return face([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], (0, 0, -1))


def outward_of(points, inside):
    """The normal of a planar face pointing away from a point inside the solid."""
    n = unit(cross(sub(points[1], points[0]), sub(points[2], points[0])))
    return n if dot(n, sub(points[0], inside)) > 0 else (-n[0], -n[1], -n[2])


# ---------------------------------------------------------------- shapes


def rect():
    return box_faces(0, 1, 0, 1, 0, 1)


def gable():
    """Ridge along x: cross-section (y,z) = (0,0), (1,0), (0.5,1)."""
    inside = (0.5, 0.5, 0.25)
    slope_front = [(0, 0, 0), (1, 0, 0), (1, 0.5, 1), (0, 0.5, 1)]
    slope_back = [(0, 1, 0), (1, 1, 0), (1, 0.5, 1), (0, 0.5, 1)]
    return [
        base(),
        face(slope_front, outward_of(slope_front, inside)),
        face(slope_back, outward_of(slope_back, inside)),
        face([(0, 0, 0), (0, 1, 0), (0, 0.5, 1)], (-1, 0, 0)),
        face([(1, 0, 0), (1, 1, 0), (1, 0.5, 1)], (1, 0, 0)),
    ]


def right_angle_triangle():
    """Half gable along y: cross-section (x,z) = (0,0), (1,0), (0,1)."""
    slope = [(1, 0, 0), (1, 1, 0), (0, 1, 1), (0, 0, 1)]
    return [
        base(),
        face([(0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)], (-1, 0, 0)),
        face(slope, outward_of(slope, (0.25, 0.5, 0.25))),
        face([(0, 0, 0), (1, 0, 0), (0, 0, 1)], (0, -1, 0)),
        face([(0, 1, 0), (1, 1, 0), (0, 1, 1)], (0, 1, 0)),
    ]


def pyramid():
    apex = (0.5, 0.5, 1)
    inside = (0.5, 0.5, 0.25)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    faces = [base()]
    for i in range(4):
        tri = [corners[i], corners[(i + 1) % 4], apex]
        faces.append(face(tri, outward_of(tri, inside)))
    return faces


def hip():
    """Ridge along x from (0.25,0.5,1) to (0.75,0.5,1)."""
    r0, r1 = (0.25, 0.5, 1), (0.75, 0.5, 1)
    inside = (0.5, 0.5, 0.25)
    sides = [
        [(0, 0, 0), (1, 0, 0), r1, r0],
        [(1, 1, 0), (0, 1, 0), r0, r1],
        [(0, 1, 0), (0, 0, 0), r0],
        [(1, 0, 0), (1, 1, 0), r1],
    ]
    return [base()] + [face(s, outward_of(s, inside)) for s in sides]


def corner():
    """Hip corner: the surface z = min(x, y), apex over (1,1)."""
    apex = (1, 1, 1)
    inside = (0.75, 0.75, 0.25)
    slope_y = [(0, 0, 0), (1, 0, 0), apex]
    slope_x = [(0, 0, 0), apex, (0, 1, 0)]
    return [
        base(),
        face(slope_y, outward_of(slope_y, inside)),
        face(slope_x, outward_of(slope_x, inside)),
        face([(1, 0, 0), (1, 1, 0), apex], (1, 0, 0)),
        face([(1, 1, 0), (0, 1, 0), apex], (0, 1, 0)),
    ]


def trough():
    """Valley piece: the surface z = max(x, y)."""
    slope_x = [(0, 0, 0), (1, 0, 1), (1, 1, 1)]  # z = x where x >= y
    slope_y = [(0, 0, 0), (1, 1, 1), (0, 1, 1)]  # z = y where y >= x
    return [
        base(),
        face(slope_x, outward_of(slope_x, (0.9, 0.5, 0.1))),
        face(slope_y, outward_of(slope_y, (0.5, 0.9, 0.1))),
        face([(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)], (1, 0, 0)),
        face([(1, 1, 0), (0, 1, 0), (0, 1, 1), (1, 1, 1)], (0, 1, 0)),
        face([(0, 0, 0), (0, 1, 0), (0, 1, 1)], (-1, 0, 0)),
        face([(0, 0, 0), (1, 0, 0), (1, 0, 1)], (0, -1, 0)),
    ]


BAR = 0.1  # frame bar width, as a fraction of the unit


def framed(opening_z0, recess_y0, recess_y1):
    """A frame around an opening x in [BAR, 1-BAR], z in [opening_z0, 1-BAR]
    in the xz plane, filled by a slab recessed to y in [recess_y0, recess_y1].

    The solid is the frame plus the slab: one closed surface. The frame's
    front and back faces are mitred trapezoids; the reveals (the opening's
    sides) run from each face of the frame to the slab.
    """
    x0, x1, z1 = BAR, 1 - BAR, 1 - BAR
    z0 = opening_z0
    faces = []
    for y, out in ((0, -1), (1, 1)):  # front and back of the frame
        outer = [(0, y, 0), (1, y, 0), (1, y, 1), (0, y, 1)]
        inner = [(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)]
        for i in range(4):
            if z0 == 0 and i == 0:
                continue  # a door has no sill: the bottom bar is missing
            quad = [outer[i], outer[(i + 1) % 4], inner[(i + 1) % 4], inner[i]]
            faces.append(face(quad, (0, out, 0)))
    # outer sides
    faces.append(face([(0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)], (-1, 0, 0)))
    faces.append(face([(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)], (1, 0, 0)))
    faces.append(face([(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], (0, 0, 1)))
    if z0 == 0:
        faces.append(face([(0, 0, 0), (x0, 0, 0), (x0, 1, 0), (0, 1, 0)], (0, 0, -1)))
        faces.append(face([(x1, 0, 0), (1, 0, 0), (1, 1, 0), (x1, 1, 0)], (0, 0, -1)))
        faces.append(face([(x0, recess_y0, 0), (x1, recess_y0, 0), (x1, recess_y1, 0), (x0, recess_y1, 0)],
                          (0, 0, -1)))
    else:
        faces.append(face([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], (0, 0, -1)))
    # reveals: the opening's sides in front of and behind the slab
    for ya, yb in ((0, recess_y0), (recess_y1, 1)):
        faces.append(face([(x0, ya, z0), (x0, yb, z0), (x0, yb, z1), (x0, ya, z1)], (1, 0, 0)))
        faces.append(face([(x1, ya, z0), (x1, yb, z0), (x1, yb, z1), (x1, ya, z1)], (-1, 0, 0)))
        faces.append(face([(x0, ya, z1), (x1, ya, z1), (x1, yb, z1), (x0, yb, z1)], (0, 0, -1)))
        if z0 > 0:
            faces.append(face([(x0, ya, z0), (x1, ya, z0), (x1, yb, z0), (x0, yb, z0)], (0, 0, 1)))
    # the slab's faces
    faces.append(face([(x0, recess_y0, z0), (x1, recess_y0, z0), (x1, recess_y0, z1), (x0, recess_y0, z1)],
                      (0, -1, 0)))
    faces.append(face([(x0, recess_y1, z0), (x1, recess_y1, z0), (x1, recess_y1, z1), (x0, recess_y1, z1)],
                      (0, 1, 0)))
    return faces


def window():
    return framed(BAR, 0.45, 0.55)


def door():
    return framed(0, 0.4, 0.6)


PRIMITIVES = {
    "rect": rect,
    "triangle": gable,
    "roof": gable,
    "right_angle_triangle": right_angle_triangle,
    "pyramid": pyramid,
    "hip": hip,
    "corner": corner,
    "trough": trough,
    "window": window,
    "door": door,
}

# ---------------------------------------------------------------- OBJ text


def number(v):
    """Shortest text that reads back to the same double; integers bare."""
    if v == 0:
        return "0"  # also folds -0
    if v == int(v):
        return str(int(v))
    return repr(float(v))


def texcoord(p, normal):
    """Planar projection onto the face's dominant plane, unmirrored as seen
    from outside the face."""
    axis = max(range(3), key=lambda i: abs(normal[i]))
    s = 1 if normal[axis] > 0 else -1
    x, y, z = p
    if axis == 0:
        return (y if s > 0 else 1 - y, z)
    if axis == 1:
        return (x if s < 0 else 1 - x, z)
    return (x, y if s > 0 else 1 - y)


def obj_text(name, faces):
    positions, uvs, normals, normal_of = {}, {}, {}, {}
    lines_f = []

    def index(table, key):
        if key not in table:
            table[key] = len(table) + 1
        return table[key]

    for points, normal in faces:
        # Equal normals computed from different faces may differ in the last
        # bit: the first one found stands for all.
        key = tuple(round(c, 12) + 0.0 for c in normal)
        normal_of.setdefault(key, normal)
        n = index(normals, key)
        corners = []
        for p in points:
            v = index(positions, tuple(float(c) for c in p))
            t = index(uvs, tuple(round(c, 12) + 0.0 for c in texcoord(p, normal)))
            corners.append(f"{v}/{t}/{n}")
        lines_f.append("f " + " ".join(corners))

    out = [f"# Vernacular built-in primitive '{name}': a closed solid filling the unit box, z up.",
           "# Generated by scripts/make_primitives.py; edit that script, not this file.",
           f"o {name}"]
    out += ["v " + " ".join(number(c) for c in p) for p in positions]
    out += ["vt " + " ".join(number(c) for c in t) for t in uvs]
    out += ["vn " + " ".join(number(c) for c in normal_of[n]) for n in normals]
    out += lines_f
    return "\n".join(out) + "\n"


def check_bounds(name, faces):
    for axis in range(3):
        values = [p[axis] for points, _ in faces for p in points]
        if min(values) != 0 or max(values) != 1:
            sys.exit(f"make_primitives: {name} does not fill the unit box on axis {axis}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(here, "..", "data", "primitives"))
    parser.add_argument("--check", action="store_true", help="compare instead of writing")
    args = parser.parse_args()

    stale = []
    for name, make in PRIMITIVES.items():
        faces = make()
        check_bounds(name, faces)
        text = obj_text(name, faces)
        path = os.path.join(args.out, name + ".obj")
        if args.check:
            try:
                with open(path, encoding="utf-8", newline="") as f:
                    if f.read() != text:
                        stale.append(path)
            except FileNotFoundError:
                stale.append(path)
            continue
        os.makedirs(args.out, exist_ok=True)
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    if stale:
        print("make_primitives: out of date (run scripts/make_primitives.py):", *stale, sep="\n  ")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
