"""Big convex-hull inputs for `kreisel inertia --hull` (not committed: tens of MB).

    python3 tests/data/gen/hull_sphere.py OUT_DIR [--scipy]

Writes OUT_DIR/uv_sphere.stl (a UV sphere of radius 1, 1600 longitudes x 800
latitude bands: 2,556,800 triangles, 1,278,402 distinct points, every one a
hull vertex) and OUT_DIR/bumpy_sphere.stl (the same grid, radius
1 + 0.05 sin(5 theta) sin(7 phi): 1.28 M points, a few per cent on the hull),
as binary STL in f32. Prints for each file the point count and, for the UV
sphere, the exact volume of its hull, a stack of prismatoids between
regular 1600-gons (V = h/6 (A1 + 4 Am + A2), Am the 1600-gon of the mean
radius; f32 rounding of the written points moves the true hull by ~1e-8),
and for both the volume of the written mesh (its f32 quads are not exactly
planar, so the hull differs from it by ~1e-8 too); with --scipy also
scipy.spatial.ConvexHull's (Qhull's) volume and vertex count and its time.
"""

import sys
import time

import numpy as np

NLON, NLAT = 1600, 800


def grid(radius):
    theta = np.pi * np.arange(1, NLAT) / NLAT  # polar angle of the rings
    phi = 2 * np.pi * np.arange(NLON) / NLON
    t, p = np.meshgrid(theta, phi, indexing="ij")
    r = radius(t, p)
    ring = np.stack([r * np.sin(t) * np.cos(p), r * np.sin(t) * np.sin(p), r * np.cos(t)], -1)
    north = np.array([[0.0, 0.0, radius(0.0, 0.0)]])
    south = np.array([[0.0, 0.0, -radius(np.pi, 0.0)]])
    pts = np.vstack([north, ring.reshape(-1, 3), south]).astype(np.float32)
    idx = lambda i, j: 1 + i * NLON + (j % NLON)  # noqa: E731
    tris = []
    j = np.arange(NLON)
    tris.append(np.stack([np.zeros(NLON, int), idx(0, j), idx(0, j + 1)], -1))
    for i in range(NLAT - 2):
        a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
        tris.append(np.stack([a, b, c], -1))
        tris.append(np.stack([a, c, d], -1))
    s = len(pts) - 1
    tris.append(np.stack([idx(NLAT - 2, j), np.full(NLON, s), idx(NLAT - 2, j + 1)], -1))
    return pts, np.vstack(tris)


def write_stl(path, pts, tris):
    rec = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = pts[tris]
    with open(path, "wb") as f:
        f.write(b"\0" * 80)
        f.write(np.uint32(len(tris)).tobytes())
        f.write(rec.tobytes())


def uv_hull_volume(pts):
    """The UV polyhedron's volume from its ring heights and radii (the f32
    rounding of the written points moves it by ~1e-8 relative)."""
    p = pts.astype(np.float64)
    zs = [p[0, 2]] + [p[1 + i * NLON, 2] for i in range(NLAT - 1)] + [p[-1, 2]]
    rs = [0.0] + [np.hypot(p[1 + i * NLON, 0], p[1 + i * NLON, 1]) for i in range(NLAT - 1)] + [0.0]
    k = NLON / 2 * np.sin(2 * np.pi / NLON)
    v = 0.0
    for a in range(len(zs) - 1):
        h = zs[a] - zs[a + 1]
        r1, r2 = rs[a], rs[a + 1]
        v += h / 6 * k * (r1 * r1 + (r1 + r2) ** 2 + r2 * r2)
    return v


def main():
    out = sys.argv[1]
    for name, radius in [
        ("uv_sphere", lambda t, p: np.ones_like(np.asarray(t, float))),
        ("bumpy_sphere", lambda t, p: 1 + 0.05 * np.sin(5 * np.asarray(t)) * np.sin(7 * np.asarray(p))),
    ]:
        pts, tris = grid(radius)
        write_stl(f"{out}/{name}.stl", pts, tris)
        print(f"{name}: {len(tris)} triangles, {len(pts)} points")
        p = pts.astype(np.float64)[tris]
        mesh = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6
        print(f"  mesh volume (divergence theorem, f64) {mesh!r}")
        if name == "uv_sphere":
            print(f"  UV polyhedron volume (prismatoids, f64 grid) {uv_hull_volume(pts)!r}")
        if "--scipy" in sys.argv:
            from scipy.spatial import ConvexHull

            t0 = time.perf_counter()
            h = ConvexHull(pts.astype(np.float64))
            dt = time.perf_counter() - t0
            print(f"  scipy ConvexHull volume {h.volume!r}, {len(h.vertices)} vertices, {dt:.1f} s")


if __name__ == "__main__":
    main()
