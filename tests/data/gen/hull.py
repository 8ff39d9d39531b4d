"""Convex-hull reference volumes for thin and degenerate point sets, from
scipy.spatial.ConvexHull (Qhull), and exact volumes where the hull is known.

Regenerate (from the repository root):

    pip install numpy scipy
    python3 tests/data/gen/hull.py

Writes, relative to this script:

    ../hull/NAME.csv        one point per line, x,y,z (repr: exact f64)
    ../hull_expected.csv    name,points,qhull_volume,qhull_vertices,exact_volume

exact_volume is filled where the hull is known in closed form (a box whose
corners are in the set, an octahedron), computed with fractions from the
stored coordinates. Qhull runs with its default options ("Qt"), in the
frame given; for the 1000:1 sets it is also run after rescaling to a round
set and the two volumes are checked to agree (the script asserts it).
"""

import math
import os
from fractions import Fraction as F

import numpy as np
from scipy.spatial import ConvexHull

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.normpath(os.path.join(HERE, ".."))
OUT = os.path.join(DATA, "hull")

rng = np.random.default_rng(20261123)


def fibonacci(n, s):
    g = math.pi * (3 - math.sqrt(5))
    pts = []
    for i in range(n):
        z = 1 - 2 * (i + 0.5) / n
        r = math.sqrt(1 - z * z)
        t = g * i
        pts.append((r * math.cos(t) * s[0], r * math.sin(t) * s[1], z * s[2]))
    return np.array(pts)


def rotation(seed):
    q = np.random.default_rng(seed).normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def box_cloud(size, n):
    """The 8 corners of a box, points on its faces and inside it."""
    corners = [(i * size[0], j * size[1], k * size[2])
               for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    inside = rng.random((n, 3)) * size
    faces = rng.random((n, 3)) * size
    axis = rng.integers(0, 3, n)
    faces[np.arange(n), axis] = np.array(size)[axis] * rng.integers(0, 2, n)
    return np.vstack([corners, inside, faces])


def octahedron_cloud(n):
    """An octahedron |x|+|y|+|z| <= 1 with many points on its faces and edges."""
    corners = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    # Points on faces: barycentric combinations with dyadic weights (exact).
    pts = list(corners)
    for _ in range(n):
        a, b = rng.integers(0, 64, 2)
        if a + b > 64:
            a, b = 64 - a, 64 - b
        c = 64 - a - b
        sx, sy, sz = rng.choice([-1, 1], 3)
        pts.append((sx * a / 64, sy * b / 64, sz * c / 64))
    return np.array(pts, dtype=float)


SETS = {
    # The case: 1 m x 1 mm flat ellipsoid, 500 points.
    "flat_ellipsoid_500": (fibonacci(500, (0.5, 0.5, 0.0005)), None),
    "flat_ellipsoid_tilted_2000": (
        fibonacci(2000, (0.5, 0.0005, 0.5)) @ rotation(1).T + np.array([3.0, -2.0, 1.0]), None),
    "needle_1000": (fibonacci(1000, (0.5, 0.0005, 0.0005)), None),
    "flat_box_cloud": (box_cloud((1.0, 1.0, 0.001), 1000), "box"),
    "octahedron_coplanar": (octahedron_cloud(1500), "octahedron"),
    "ball_2000": (rng.normal(size=(2000, 3)), None),
}


def exact(kind, pts):
    if kind == "box":
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        v = F(1)
        for a, b in zip(lo, hi):
            v *= F(float(b)) - F(float(a))
        return float(v)
    if kind == "octahedron":
        return float(F(4, 3))
    return None


def main():
    os.makedirs(OUT, exist_ok=True)
    rows = ["name,points,qhull_volume,qhull_vertices,exact_volume"]
    for name, (pts, kind) in SETS.items():
        with open(os.path.join(OUT, name + ".csv"), "w") as f:
            for p in pts:
                f.write("%r,%r,%r\n" % tuple(float(c) for c in p))
        hull = ConvexHull(pts)
        # Cross-check Qhull on the rescaled (round) set: volume scales by the determinant.
        scale = pts.max(axis=0) - pts.min(axis=0)
        centred = pts - pts.mean(axis=0)
        u, s, vt = np.linalg.svd(centred, full_matrices=False)
        round_pts = centred @ vt.T / s
        round_volume = ConvexHull(round_pts).volume * np.prod(s)
        assert abs(round_volume / hull.volume - 1) < 1e-9, (name, round_volume, hull.volume)
        e = exact(kind, pts)
        if e is not None:
            assert abs(hull.volume / e - 1) < 1e-9, (name, hull.volume, e)
        rows.append("%s,%d,%.17g,%d,%s" % (name, len(pts), hull.volume, len(hull.vertices),
                                          "" if e is None else "%.17g" % e))
        del scale
    with open(os.path.join(DATA, "hull_expected.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
