"""Generate exact mass-property reference data for closed polyhedral meshes.

Regenerate (from the repository root; standard library only):

    python3 tests/data/gen/inertia.py

Writes, relative to this script's location:

    ../polyhedra/NAME.obj          closed, manifold, outward-wound test meshes
    ../polyhedra_expected.csv      exact reference mass properties (one row per mesh)
    ../../../assets/t_handle.obj   demo mesh: T-handle (Dzhanibekov effect), metres
    ../../../assets/top.stl        demo mesh: spinning top, binary STL, metres
    ../../../assets/top_ascii.stl  the same top as ASCII STL
    ../../../assets/README.md      description of the assets and their mass properties

Conventions
-----------
* SI units.  Solid values at density 1 (mass = volume), shell values at
  surface density 1 (mass = area).
* Inertia tensor about the centre of mass,
  I_ab = integral of rho (r^2 delta_ab - r_a r_b) with r measured from the
  centre of mass; the CSV columns ixy, ixz, iyz are the tensor ELEMENTS
  (I_xy = -integral x y), not the products of inertia.
* Triangles are wound counter-clockwise seen from outside: the outward normal
  is (b - a) x (c - a).
* Every coordinate is first rounded to the precision of the file it is stored
  in (f64 for OBJ, written with repr(); f32 for STL), and the reference values
  are computed EXACTLY with fractions.Fraction from those stored binary values:
  solids by the divergence theorem as a sum of signed tetrahedra (0, a, b, c),
  thin shells by exact per-triangle integrals.  Shell columns are filled only
  when every triangle area is exactly rational (|cross|^2 is the square of a
  rational), otherwise they are left empty.
* Each exact value is rounded once to the nearest f64 (Fraction -> float is
  correctly rounded) and written with '%.17g', which round-trips that f64
  exactly.

The script is deterministic (no randomness, no dependence on dict/hash order
beyond insertion order) and checks itself with assertions: closed manifold
surfaces, positive volumes, closed forms for boxes, tetrahedron, octahedron,
rotated boxes (R diag R^T) and translation invariance.
"""

import math
import os
import struct
import sys
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.normpath(os.path.join(HERE, ".."))
POLY = os.path.join(DATA, "polyhedra")
ASSETS = os.path.normpath(os.path.join(HERE, "..", "..", "..", "assets"))

HEADER = ("name,triangles,volume,cx,cy,cz,ixx,iyy,izz,ixy,ixz,iyz,area,"
          "shell_cx,shell_cy,shell_cz,shell_ixx,shell_iyy,shell_izz,"
          "shell_ixy,shell_ixz,shell_iyz")


# ---------------------------------------------------------------------------
# Meshes
# ---------------------------------------------------------------------------

class Mesh:
    """Indexed triangle mesh; vertices are tuples of Python floats, welded by
    exact value."""

    def __init__(self, name):
        self.name = name
        self.vertices = []
        self.index = {}
        self.faces = []

    def vid(self, p):
        p = tuple(float(c) + 0.0 for c in p)  # + 0.0 turns -0.0 into 0.0
        i = self.index.get(p)
        if i is None:
            i = len(self.vertices)
            self.index[p] = i
            self.vertices.append(p)
        return i

    def tri(self, a, b, c):
        ia, ib, ic = self.vid(a), self.vid(b), self.vid(c)
        assert len({ia, ib, ic}) == 3, (self.name, a, b, c)
        self.faces.append((ia, ib, ic))

    def quad(self, a, b, c, d):
        """Planar quad a-b-c-d, counter-clockwise seen from outside."""
        self.tri(a, b, c)
        self.tri(a, c, d)

    def exact_vertices(self):
        return [tuple(F(c) for c in v) for v in self.vertices]


def check_closed(mesh):
    """Every directed edge appears exactly once and its reverse exactly once
    (closed, manifold, consistently wound); no degenerate triangles."""
    edges = {}
    for f in mesh.faces:
        for k in range(3):
            e = (f[k], f[(k + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    for (a, b), n in edges.items():
        assert n == 1, (mesh.name, "directed edge used %d times" % n, a, b)
        assert (b, a) in edges, (mesh.name, "open edge", a, b)
    used = {i for f in mesh.faces for i in f}
    assert used == set(range(len(mesh.vertices))), (mesh.name, "unused vertex")
    V = mesh.exact_vertices()
    for f in mesh.faces:
        n = cross(sub(V[f[1]], V[f[0]]), sub(V[f[2]], V[f[0]]))
        assert dot(n, n) > 0, (mesh.name, "degenerate triangle", f)
    # Euler characteristic of a sphere-like surface (all meshes here are genus 0).
    assert len(mesh.vertices) - len(edges) // 2 + len(mesh.faces) == 2, mesh.name


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


# ---------------------------------------------------------------------------
# Exact integrals
# ---------------------------------------------------------------------------

def solid_moments(verts, faces, origin=(F(0), F(0), F(0))):
    """Exact (V, S_i = int x_i, P_ij = int x_i x_j) of the closed solid, as a
    sum of signed tetrahedra (origin, a, b, c) with d = a . (b x c), s = a+b+c:
    V = d/6, int x_i = d/24 s_i, int x_i x_j = d/120 (s_i s_j + sum_k a_ki a_kj)
    (the tetrahedron's V/20 (sum over its 4 vertices of v_i v_j + s_i s_j)).  The result does not depend on
    `origin` (checked by the caller)."""
    V = F(0)
    S = [F(0)] * 3
    P = [[F(0)] * 3 for _ in range(3)]
    o = origin
    for f in faces:
        a, b, c = (sub(verts[i], o) for i in f)
        d = dot(a, cross(b, c))
        s = add(add(a, b), c)
        V += d / 6
        for i in range(3):
            S[i] += d / 24 * s[i]
            for j in range(i, 3):
                P[i][j] += d / 120 * (s[i] * s[j] + a[i] * a[j] + b[i] * b[j] + c[i] * c[j])
    # Shift from the apex `o` back to the coordinate origin.
    # int (y+o)_i (y+o)_j = P_ij + o_i S_j + o_j S_i + o_i o_j V, int (y+o) = S + o V
    P2 = [[F(0)] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            P2[i][j] = P[i][j] + o[i] * S[j] + o[j] * S[i] + o[i] * o[j] * V
            P2[j][i] = P2[i][j]
    S2 = [S[i] + o[i] * V for i in range(3)]
    return V, S2, P2


def rational_sqrt(q):
    """sqrt of a non-negative Fraction if it is rational, else None."""
    n, d = q.numerator, q.denominator
    rn, rd = math.isqrt(n), math.isqrt(d)
    if rn * rn == n and rd * rd == d:
        return F(rn, rd)
    return None


def shell_moments(verts, faces):
    """Exact (A, S, P) of the surface at unit surface density, or None if some
    triangle area is irrational."""
    A = F(0)
    S = [F(0)] * 3
    P = [[F(0)] * 3 for _ in range(3)]
    for f in faces:
        p = [verts[i] for i in f]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        r = rational_sqrt(dot(n, n))
        if r is None:
            return None
        a = r / 2
        s = add(add(p[0], p[1]), p[2])
        A += a
        for i in range(3):
            S[i] += a / 3 * s[i]
            for j in range(3):
                P[i][j] += a / 12 * (s[i] * s[j] + sum(pk[i] * pk[j] for pk in p))
    return A, S, P


def central(m, S, P):
    """(mass, centre, inertia tensor about the centre) from raw moments."""
    c = [S[i] / m for i in range(3)]
    C = [[P[i][j] - m * c[i] * c[j] for j in range(3)] for i in range(3)]
    tr = C[0][0] + C[1][1] + C[2][2]
    I = [[(tr if i == j else 0) - C[i][j] for j in range(3)] for i in range(3)]
    return m, c, I


def props(mesh):
    V = mesh.exact_vertices()
    solid = central(*solid_moments(V, mesh.faces))
    # Independent re-summation with a different apex: must agree exactly.
    alt = central(*solid_moments(V, mesh.faces, origin=V[0]))
    assert alt == solid, mesh.name
    assert solid[0] > 0, (mesh.name, "volume not positive")
    sh = shell_moments(V, mesh.faces)
    shell = central(*sh) if sh is not None else None
    return solid, shell


# ---------------------------------------------------------------------------
# Mesh builders
# ---------------------------------------------------------------------------

def box_faces(mesh, lo, hi, n=1, transform=None):
    """Axis-aligned box [lo, hi] (each face an n x n grid of quads)."""
    T = transform or (lambda p: p)
    for ax in range(3):
        u, v = (ax + 1) % 3, (ax + 2) % 3
        for side, val in ((-1, lo[ax]), (1, hi[ax])):
            us = [lo[u] + (hi[u] - lo[u]) * F(k, n) for k in range(n + 1)]
            vs = [lo[v] + (hi[v] - lo[v]) * F(k, n) for k in range(n + 1)]
            for i in range(n):
                for j in range(n):
                    def P(a, b):
                        p = [None] * 3
                        p[ax], p[u], p[v] = val, a, b
                        return T(tuple(p))
                    q = [P(us[i], vs[j]), P(us[i + 1], vs[j]),
                         P(us[i + 1], vs[j + 1]), P(us[i], vs[j + 1])]
                    if side < 0:
                        q.reverse()
                    mesh.quad(*q)


def make_box(name, lo, hi, n=1, transform=None):
    m = Mesh(name)
    box_faces(m, [F(c) for c in lo], [F(c) for c in hi], n, transform)
    return m


def box_union(name, boxes, scale=None):
    """Closed surface of a union of axis-aligned boxes (given as (lo, hi) in
    exact units), on the rectilinear grid of all box planes, so adjacent faces
    share whole edges (no T-junctions, no internal faces).  `scale` maps an
    exact grid coordinate to the stored float (default: exact float)."""
    scale = scale or float
    grid = [sorted({F(b[k][ax]) for b in boxes for k in (0, 1)}) for ax in range(3)]
    dims = [len(g) - 1 for g in grid]

    def inside(i, j, k):
        if not (0 <= i < dims[0] and 0 <= j < dims[1] and 0 <= k < dims[2]):
            return False
        c = [(grid[0][i] + grid[0][i + 1]) / 2, (grid[1][j] + grid[1][j + 1]) / 2,
             (grid[2][k] + grid[2][k + 1]) / 2]
        return any(all(F(lo[a]) < c[a] < F(hi[a]) for a in range(3)) for lo, hi in boxes)

    m = Mesh(name)
    for i in range(dims[0]):
        for j in range(dims[1]):
            for k in range(dims[2]):
                if not inside(i, j, k):
                    continue
                cell = (i, j, k)
                for ax in range(3):
                    u, v = (ax + 1) % 3, (ax + 2) % 3
                    for side in (-1, 1):
                        nb = list(cell)
                        nb[ax] += side
                        if inside(*nb):
                            continue
                        val = grid[ax][cell[ax] + (1 if side > 0 else 0)]
                        u0, u1 = grid[u][cell[u]], grid[u][cell[u] + 1]
                        v0, v1 = grid[v][cell[v]], grid[v][cell[v] + 1]

                        def P(a, b):
                            p = [None] * 3
                            p[ax], p[u], p[v] = val, a, b
                            return tuple(scale(c) for c in p)
                        q = [P(u0, v0), P(u1, v0), P(u1, v1), P(u0, v1)]
                        if side < 0:
                            q.reverse()
                        m.quad(*q)
    return m


def area2(poly):
    return sum(F(poly[i][0]) * F(poly[(i + 1) % len(poly)][1])
               - F(poly[(i + 1) % len(poly)][0]) * F(poly[i][1]) for i in range(len(poly)))


def ear_clip(poly):
    """Triangulate a simple counter-clockwise polygon (exact arithmetic)."""
    idx = list(range(len(poly)))
    P = [(F(x), F(y)) for x, y in poly]
    tris = []

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    while len(idx) > 3:
        for k in range(len(idx)):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            if orient(P[a], P[b], P[c]) <= 0:
                continue
            if any(orient(P[a], P[b], P[t]) >= 0 and orient(P[b], P[c], P[t]) >= 0
                   and orient(P[c], P[a], P[t]) >= 0 for t in idx if t not in (a, b, c)):
                continue
            tris.append((a, b, c))
            idx.pop(k)
            break
        else:
            raise AssertionError("ear clipping failed")
    tris.append(tuple(idx))
    return tris


def extrude(name, poly, z0, z1):
    """Prism over a simple CCW polygon (no repeated vertices), z in [z0, z1]."""
    assert area2(poly) > 0, (name, "polygon must be counter-clockwise")
    m = Mesh(name)
    n = len(poly)
    for a, b, c in ear_clip(poly):
        A, B, C = poly[a], poly[b], poly[c]
        m.tri((A[0], A[1], z1), (B[0], B[1], z1), (C[0], C[1], z1))  # top, +z
        m.tri((A[0], A[1], z0), (C[0], C[1], z0), (B[0], B[1], z0))  # bottom, -z
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        m.quad((p[0], p[1], z0), (q[0], q[1], z0), (q[0], q[1], z1), (p[0], p[1], z1))
    return m


def revolve(name, profile, segments, point):
    """Solid of revolution about z.  `profile` is a list of (r, z) from the
    bottom of the axis to the top (r = 0 only at both ends); `point(r, z, k)`
    returns the stored vertex for ring k."""
    m = Mesh(name)
    for i in range(len(profile) - 1):
        (r0, z0), (r1, z1) = profile[i], profile[i + 1]
        for k in range(segments):
            k1 = (k + 1) % segments
            A, B = point(r0, z0, k), point(r0, z0, k1)
            C, D = point(r1, z1, k1), point(r1, z1, k)
            if r0 == 0:
                m.tri(A, C, D)
            elif r1 == 0:
                m.tri(A, B, C)
            else:
                m.quad(A, B, C, D)
    return m


# ---------------------------------------------------------------------------
# Rotation
# ---------------------------------------------------------------------------

def quat_matrix(w, x, y, z):
    """Exact rotation matrix of the (unnormalised) integer quaternion."""
    n = w * w + x * x + y * y + z * z
    R = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]
    R = [[F(e, n) for e in row] for row in R]
    for i in range(3):
        for j in range(3):
            assert sum(R[i][k] * R[j][k] for k in range(3)) == (1 if i == j else 0)
    return R


def matvec(R, p):
    return tuple(sum(R[i][k] * p[k] for k in range(3)) for i in range(3))


def rdrt(R, d):
    return [[sum(R[i][k] * d[k] * R[j][k] for k in range(3)) for j in range(3)] for i in range(3)]


def box_closed_form(a, b, c):
    m = a * b * c
    return [[m / 12 * (b * b + c * c), 0, 0],
            [0, m / 12 * (a * a + c * c), 0],
            [0, 0, m / 12 * (a * a + b * b)]]


# ---------------------------------------------------------------------------
# Float32 helpers (STL)
# ---------------------------------------------------------------------------

def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def unit_circle(k, segments):
    """(cos, sin) of 2 pi k / segments with exact octant symmetry (segments a
    multiple of 8): mirror images and the x <-> y swap map the ring onto itself
    bit for bit."""
    assert segments % 8 == 0
    q4 = segments // 4
    quadrant, j = divmod(k % segments, q4)
    if 2 * j == q4:
        c = s = math.sqrt(0.5)
    elif 2 * j < q4:
        t = 2 * math.pi * j / segments
        c, s = math.cos(t), math.sin(t)
    else:
        t = 2 * math.pi * (q4 - j) / segments
        s, c = math.cos(t), math.sin(t)
    if j == 0:
        c, s = 1.0, 0.0
    return [(c, s), (-s, c), (-c, -s), (s, -c)][quadrant]


# ---------------------------------------------------------------------------
# Writers
# ---------------------------------------------------------------------------

def write_obj(mesh, path, comment, obj_name=None):
    lines = ["# " + c for c in comment]
    if obj_name:
        lines.append("o " + obj_name)
    for v in mesh.vertices:
        lines.append("v %s %s %s" % tuple(repr(c) for c in v))
    for f in mesh.faces:
        lines.append("f %d %d %d" % tuple(i + 1 for i in f))
    with open(path, "w", newline="\n") as fh:
        fh.write("\n".join(lines) + "\n")
    # Round-trip check: the file holds exactly the values the reference used.
    with open(path) as fh:
        vs = [tuple(float(t) for t in ln.split()[1:4]) for ln in fh if ln.startswith("v ")]
    assert vs == mesh.vertices, path


def facet_normal(mesh, f):
    p = [mesh.vertices[i] for i in f]
    n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
    ln = math.sqrt(dot(n, n))
    return tuple(f32(c / ln) for c in n)


def write_stl_binary(mesh, path, header):
    h = header.encode("ascii")
    assert len(h) <= 80 and not h.lower().startswith(b"solid")
    out = [h.ljust(80, b" "), struct.pack("<I", len(mesh.faces))]
    for f in mesh.faces:
        out.append(struct.pack("<3f", *facet_normal(mesh, f)))
        for i in f:
            out.append(struct.pack("<3f", *mesh.vertices[i]))
        out.append(struct.pack("<H", 0))
    data = b"".join(out)
    assert len(data) == 84 + 50 * len(mesh.faces)
    with open(path, "wb") as fh:
        fh.write(data)


def write_stl_ascii(mesh, path, solid_name):
    def g(x):
        # Shortest decimal of the float32 value held as a double: it parses
        # back to exactly that value whether a reader uses f32 or f64.
        s = repr(float(x))
        assert float(s) == x and f32(float(s)) == x, (x, s)
        return s
    lines = ["solid " + solid_name]
    for f in mesh.faces:
        lines.append("  facet normal %s %s %s" % tuple(g(c) for c in facet_normal(mesh, f)))
        lines.append("    outer loop")
        for i in f:
            lines.append("      vertex %s %s %s" % tuple(g(c) for c in mesh.vertices[i]))
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid " + solid_name)
    with open(path, "w", newline="\n") as fh:
        fh.write("\n".join(lines) + "\n")


def fmt(q):
    return "%.17g" % float(q)


def csv_row(name, ntri, solid, shell):
    m, c, I = solid
    row = [name, str(ntri), fmt(m)] + [fmt(x) for x in c]
    row += [fmt(I[0][0]), fmt(I[1][1]), fmt(I[2][2]), fmt(I[0][1]), fmt(I[0][2]), fmt(I[1][2])]
    if shell is None:
        row += [""] * 10
    else:
        a, sc, sI = shell
        row += [fmt(a)] + [fmt(x) for x in sc]
        row += [fmt(sI[0][0]), fmt(sI[1][1]), fmt(sI[2][2]),
                fmt(sI[0][1]), fmt(sI[0][2]), fmt(sI[1][2])]
    return ",".join(row)


# ---------------------------------------------------------------------------
# The meshes
# ---------------------------------------------------------------------------

def build_test_meshes():
    meshes = []

    # Tetrahedron (0,0,0),(1,0,0),(0,1,0),(0,0,1).
    t = Mesh("tetrahedron")
    O, X, Y, Z = (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)
    t.tri(O, Y, X)
    t.tri(O, X, Z)
    t.tri(O, Z, Y)
    t.tri(X, Y, Z)
    meshes.append(t)

    meshes.append(make_box("unit_cube", (0, 0, 0), (1, 1, 1)))
    meshes.append(make_box("box_1x2x3", (-0.5, -1, -1.5), (0.5, 1, 1.5)))
    meshes.append(make_box("box_1x2x3_far", (1e6 - 0.5, -2e6 - 1, 3e6 - 1.5),
                           (1e6 + 0.5, -2e6 + 1, 3e6 + 1.5)))

    # Rotated boxes: R from the integer quaternion (1, 2, 3, 4), |q|^2 = 30.
    R = quat_matrix(1, 2, 3, 4)
    shift = (F(1, 4), F(-1, 2), F(3, 4))
    # (a) box 1x2x3: the exact rotated vertices are not binary fractions, so
    # the stored floats are rounded; reference computed from the stored floats.
    meshes.append(make_box("box_rotated", (-0.5, -1, -1.5), (0.5, 1, 1.5),
                           transform=lambda p: add(matvec(R, p), shift)))
    # (b) box (15/16)(1, 2, 3): every rotated vertex is a multiple of 1/64, so
    # the stored mesh is exactly R * box + shift and I = R diag R^T exactly.
    meshes.append(make_box("box_rotated_exact", (F(-15, 32), F(-15, 16), F(-45, 32)),
                           (F(15, 32), F(15, 16), F(45, 32)),
                           transform=lambda p: add(matvec(R, p), shift)))

    # Octahedron with vertices +-(1,0,0), +-(0,2,0), +-(0,0,3).
    o = Mesh("octahedron")
    ax = [(1, 0, 0), (0, 2, 0), (0, 0, 3)]
    for sx in (1, -1):
        for sy in (1, -1):
            for sz in (1, -1):
                a = (sx * 1, 0, 0)
                b = (0, sy * 2, 0)
                c = (0, 0, sz * 3)
                if sx * sy * sz > 0:
                    o.tri(a, b, c)
                else:
                    o.tri(a, c, b)
    del ax
    meshes.append(o)

    # L: extruded non-convex hexagon (3 x 2 with a 2 x 1 notch), z in [0, 0.5].
    meshes.append(extrude("l_shape", [(0, 0), (3, 0), (3, 1), (1, 1), (1, 2), (0, 2)], 0, 0.5))

    # T: crossbar 4 x 1 x 1 on top of a stem 0.5 x 0.5 x 2 (different widths,
    # so it is not an extrusion), fused on the rectilinear grid.
    meshes.append(box_union("t_handle_exact", [
        ((-2, -0.5, 0), (2, 0.5, 1)),
        ((-0.25, -0.25, -2), (0.25, 0.25, 0)),
    ]))

    meshes.append(make_box("cube_fine", (0, 0, 0), (1, 1, 1), n=8))

    # Convex, non-regular hexagon whose edge vectors are Pythagorean
    # ((5,0),(3,4),(-5,12),(-8,-6),(-3,-4),(8,-6), scaled by 1/8), so all
    # side walls have rational area; z in [-0.75, 1.5].
    edges = [(5, 0), (3, 4), (-5, 12), (-8, -6), (-3, -4), (8, -6)]
    p = (F(-3, 8), F(-5, 4))
    hexa = []
    for e in edges:
        hexa.append((float(p[0]), float(p[1])))
        p = (p[0] + F(e[0], 8), p[1] + F(e[1], 8))
    assert p == (F(-3, 8), F(-5, 4))
    meshes.append(extrude("prism_hex", hexa, -0.75, 1.5))
    return meshes, R


def build_t_handle():
    """T-handle in metres: crossbar 80 mm along x with a 12 mm x 12 mm section,
    stem 50 mm along -z with a 10 mm x 10 mm section, fused.  Origin at the
    centre of the joint (bottom face of the crossbar)."""
    mm = lambda v: v / 1000.0  # noqa: E731  (exact mm integer -> nearest float metres)
    m = box_union("t_handle", [
        ((-40, -6, 0), (40, 6, 12)),
        ((-5, -5, -50), (5, 5, 0)),
    ], scale=lambda c: mm(float(c)))
    return m


TOP_PROFILE_MM = [
    (0, 0),     # tip (on the axis, at the origin)
    (24, 18),   # cone
    (30, 22),   # flare to the rim
    (30, 27),   # rim, 60 mm diameter
    (6, 30),    # shallow conical upper face
    (4, 30),    # shoulder
    (4, 50),    # spindle, 8 mm diameter
    (0, 50),    # top of the spindle
]
TOP_SEGMENTS = 64


def build_top():
    def point(r, z, k):
        c, s = unit_circle(k, TOP_SEGMENTS)
        rm = r / 1000.0
        return (f32(rm * c), f32(rm * s), f32(z / 1000.0))
    m = revolve("top", TOP_PROFILE_MM, TOP_SEGMENTS, point)
    # STL stores triangles without indices: distinct vertices must stay
    # distinct in float32 so that welding by position recovers this mesh.
    assert len(m.index) == len(m.vertices)
    return m


# ---------------------------------------------------------------------------
# Self-checks
# ---------------------------------------------------------------------------

def approx_equal(A, B, rel):
    scale = max(abs(x) for row in B for x in row)
    return all(abs(A[i][j] - B[i][j]) <= rel * scale for i in range(3) for j in range(3))


def self_checks(results, R):
    zero3 = [F(0)] * 3

    # Boxes: textbook closed forms.
    for name, (a, b, c), centre in [
            ("unit_cube", (1, 1, 1), [F(1, 2)] * 3),
            ("cube_fine", (1, 1, 1), [F(1, 2)] * 3),
            ("box_1x2x3", (1, 2, 3), zero3),
            ("box_1x2x3_far", (1, 2, 3), [F(10**6), F(-2 * 10**6), F(3 * 10**6)])]:
        (m, cc, I), shell = results[name]
        a, b, c = F(a), F(b), F(c)
        assert m == a * b * c, name
        assert cc == centre, name
        assert I == box_closed_form(a, b, c), name
        # Shell of a box: six plates, parallel-axis terms for the offset ones.
        A, sc, sI = shell
        assert A == 2 * (a * b + b * c + a * c) and sc == centre, name
        assert sI == box_shell_closed_form(a, b, c), name

    # Far box equals the centred box exactly (solid and shell, up to the centre).
    s0, h0 = results["box_1x2x3"]
    s1, h1 = results["box_1x2x3_far"]
    assert s0[0] == s1[0] and s0[2] == s1[2]
    assert h0[0] == h1[0] and h0[2] == h1[2]

    # Tetrahedron: moments of the unit simplex, int x^a y^b z^c = a! b! c! / (a+b+c+3)!
    def simplex(a, b, c):
        return F(math.factorial(a) * math.factorial(b) * math.factorial(c),
                 math.factorial(a + b + c + 3))
    V = simplex(0, 0, 0)
    S = [simplex(1, 0, 0)] * 3
    P = [[simplex(2, 0, 0) if i == j else simplex(1, 1, 0) for j in range(3)] for i in range(3)]
    closed = central(V, S, P)
    (m, c, I), shell = results["tetrahedron"]
    assert (m, c, I) == closed
    assert m == F(1, 6) and c == [F(1, 4)] * 3
    assert I[0][0] == F(1, 80) and I[0][1] == F(1, 480)
    assert shell is None  # the slanted face has area sqrt(3)/2

    # Octahedron |x/a| + |y/b| + |z/c| <= 1: V = 4abc/3, I_xx = V (b^2 + c^2) / 10.
    (m, c, I), shell = results["octahedron"]
    a, b, cc = F(1), F(2), F(3)
    assert m == 4 * a * b * cc / 3 and c == zero3
    assert I == [[m * (b * b + cc * cc) / 10, 0, 0], [0, m * (a * a + cc * cc) / 10, 0],
                 [0, 0, m * (a * a + b * b) / 10]]
    assert shell is not None and shell[0] == 8 * F(7, 2)  # |cross| = sqrt(36+9+4) = 7

    # Rotated boxes: I = R diag R^T.
    (m, c, I), _ = results["box_rotated_exact"]
    a, b, cc = F(15, 16), F(15, 8), F(45, 16)
    assert m == a * b * cc
    assert c == [F(1, 4), F(-1, 2), F(3, 4)]
    D = box_closed_form(a, b, cc)
    assert I == rdrt(R, [D[0][0], D[1][1], D[2][2]])
    assert all(I[i][j] != 0 for i in range(3) for j in range(3))
    Ds = box_shell_closed_form(a, b, cc)
    shell = results["box_rotated_exact"][1]
    assert shell[0] == 2 * (a * b + b * cc + a * cc) and shell[1] == c
    assert shell[2] == rdrt(R, [Ds[0][0], Ds[1][1], Ds[2][2]])
    # box_rotated: the exact rational mesh (before rounding to floats) gives
    # R diag R^T exactly; the stored-float mesh agrees to rounding level.
    exact = make_box("exact", (-0.5, -1, -1.5), (0.5, 1, 1.5))
    Vx = [add(matvec(R, p), (F(1, 4), F(-1, 2), F(3, 4))) for p in exact.exact_vertices()]
    me, ce, Ie = central(*solid_moments(Vx, exact.faces))
    D = box_closed_form(F(1), F(2), F(3))
    Dd = [D[0][0], D[1][1], D[2][2]]
    assert me == 6 and ce == [F(1, 4), F(-1, 2), F(3, 4)] and Ie == rdrt(R, Dd)
    (m, c, I), _ = results["box_rotated"]
    assert abs(m - 6) < F(1, 10**14) and approx_equal(I, Ie, F(1, 10**14))
    assert all(I[i][j] != 0 for i in range(3) for j in range(3))

    # L-shape: union of [0,3]x[0,1] and [0,1]x[1,2], thickness 1/2.
    (m, c, I), shell = results["l_shape"]
    assert m == 2 and c == [F(5, 4), F(3, 4), F(1, 4)], (m, c)
    assert shell is not None

    # T (exact): parallel-axis sum of the two boxes.
    (m, c, I), shell = results["t_handle_exact"]
    parts = [(F(4), F(1), F(1), (F(0), F(0), F(1, 2))),
             (F(1, 2), F(1, 2), F(2), (F(0), F(0), F(-1)))]
    assert I == compound_boxes(parts)[2] and m == compound_boxes(parts)[0]

    # prism_hex: shell rows exist (Pythagorean walls).
    assert results["prism_hex"][1] is not None


def box_shell_closed_form(a, b, c):
    """Thin-shell box a x b x c (unit surface density) about its centre."""
    e = (a, b, c)
    I = [[F(0)] * 3 for _ in range(3)]
    for ax in range(3):  # axis of the inertia component
        u, v = (ax + 1) % 3, (ax + 2) % 3
        # the two faces normal to ax: plates e_u x e_v
        I[ax][ax] += 2 * e[u] * e[v] * (e[u] ** 2 + e[v] ** 2) / 12
        # the two faces normal to u (spanning ax and v, offset e_u/2 along u)
        I[ax][ax] += 2 * e[ax] * e[v] * (e[v] ** 2 / 12 + e[u] ** 2 / 4)
        # the two faces normal to v (spanning ax and u, offset e_v/2 along v)
        I[ax][ax] += 2 * e[ax] * e[u] * (e[u] ** 2 / 12 + e[v] ** 2 / 4)
    return I


def compound_boxes(parts):
    """Exact (m, c, I) of disjoint boxes (a, b, c, centre) by parallel axes."""
    M = sum(a * b * c for a, b, c, _ in parts)
    C = [sum(a * b * c * p[i] for a, b, c, p in parts) / M for i in range(3)]
    I = [[F(0)] * 3 for _ in range(3)]
    for a, b, c, p in parts:
        m = a * b * c
        D = box_closed_form(a, b, c)
        d = [p[i] - C[i] for i in range(3)]
        dd = dot(d, d)
        for i in range(3):
            for j in range(3):
                I[i][j] += D[i][j] + m * ((dd if i == j else 0) - d[i] * d[j])
    return M, C, I


# ---------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------

def principal_diag(I):
    assert I[0][1] == I[0][2] == I[1][2] == 0
    return I[0][0], I[1][1], I[2][2]


def main():
    os.makedirs(POLY, exist_ok=True)
    os.makedirs(ASSETS, exist_ok=True)

    meshes, R = build_test_meshes()
    t_handle = build_t_handle()
    top = build_top()

    results = {}
    rows = []
    summary = []
    for mesh in meshes + [t_handle, top]:
        check_closed(mesh)
        results[mesh.name] = props(mesh)
    self_checks(results, R)

    gen = "tests/data/gen/inertia.py"
    for mesh in meshes:
        write_obj(mesh, os.path.join(POLY, mesh.name + ".obj"), [
            "%s: closed outward-wound triangle mesh, %d vertices, %d triangles"
            % (mesh.name, len(mesh.vertices), len(mesh.faces)),
            "generated by %s (python3 %s); reference in tests/data/polyhedra_expected.csv"
            % (gen, gen)])

    # Assets.
    (m, c, I), _ = results["t_handle"]
    write_obj(t_handle, os.path.join(ASSETS, "t_handle.obj"), [
        "T-handle (Dzhanibekov effect demo), units: metres",
        "crossbar 80 x 12 x 12 mm along x, stem 10 x 10 x 50 mm along -z; origin at the joint",
        "generated by %s (python3 %s)" % (gen, gen)], obj_name="t_handle")
    write_stl_binary(top, os.path.join(ASSETS, "top.stl"),
                     "kreisel spinning top, metres, %d segments, by %s" % (TOP_SEGMENTS, gen))
    write_stl_ascii(top, os.path.join(ASSETS, "top_ascii.stl"), "top")
    check_stl_files(top)

    ordered = [(mesh.name, mesh) for mesh in meshes] + [
        ("t_handle", t_handle), ("top", top), ("top_ascii", top)]
    for name, mesh in ordered:
        solid, shell = results[mesh.name]
        rows.append(csv_row(name, len(mesh.faces), solid, shell))
        summary.append("%-18s %5d tris  V=%-22s shell=%s" % (
            name, len(mesh.faces), fmt(solid[0]), "yes" if shell else "no"))

    comment = ("# generated by python3 tests/data/gen/inertia.py; exact (fractions.Fraction) "
               "mass properties of the stored vertex values, rounded to nearest f64, '%.17g'; "
               "SI, solid density 1 (mass = volume), shell surface density 1 (mass = area); "
               "centre of mass (cx..) and inertia tensor about it, I_ab = int(r^2 delta_ab - "
               "r_a r_b), ixy = I_xy = -int x y (tensor element, not product of inertia); "
               "shell columns empty unless all triangle areas are rational; meshes in "
               "tests/data/polyhedra/NAME.obj except t_handle = assets/t_handle.obj, "
               "top = assets/top.stl (binary), top_ascii = assets/top_ascii.stl")
    with open(os.path.join(DATA, "polyhedra_expected.csv"), "w", newline="\n") as fh:
        fh.write(comment + "\n" + HEADER + "\n" + "\n".join(rows) + "\n")

    readme = write_readme(results, t_handle, top)
    with open(os.path.join(ASSETS, "README.md"), "w", newline="\n") as fh:
        fh.write(readme)

    print("\n".join(summary))
    for name in ("t_handle", "top"):
        (m, c, I), _ = results[name]
        p = principal_diag(I)
        print("%s @ 1000 kg/m^3: mass %.6g kg, com (%s) m, principal moments (%s) kg m^2" % (
            name, 1000 * m, ", ".join("%.6g" % float(x) for x in c),
            ", ".join("%.6g" % float(1000 * x) for x in p)))
    print("wrote %d meshes + 3 asset files, %s, assets/README.md" % (
        len(meshes), "tests/data/polyhedra_expected.csv"))


def check_stl_files(top):
    """Re-read both STL files and check they hold exactly the mesh's triangles."""
    want = [tuple(top.vertices[i] for i in f) for f in top.faces]
    with open(os.path.join(ASSETS, "top.stl"), "rb") as fh:
        data = fh.read()
    n = struct.unpack_from("<I", data, 80)[0]
    assert n == len(top.faces) and len(data) == 84 + 50 * n
    got = []
    for t in range(n):
        vals = struct.unpack_from("<12fH", data, 84 + 50 * t)
        got.append((vals[3:6], vals[6:9], vals[9:12]))
    assert got == want
    got = []
    with open(os.path.join(ASSETS, "top_ascii.stl")) as fh:
        vs = [tuple(f32(float(x)) for x in ln.split()[1:4]) for ln in fh
              if ln.strip().startswith("vertex")]
    got = [tuple(vs[3 * t:3 * t + 3]) for t in range(len(vs) // 3)]
    assert got == want


def intermediate_axis(I):
    p = principal_diag(I)
    assert len(set(p)) == 3, "principal moments must be distinct"
    return "xyz"[sorted(range(3), key=lambda i: p[i])[1]]


def write_readme(results, t_handle, top):
    def block(name):
        (m, c, I), _ = results[name]
        p = principal_diag(I)
        rho = 1000
        lines = [
            "- mass %.6g kg (volume %.6g m³)" % (rho * m, m),
            "- centre of mass (%s) m" % ", ".join("%.6g" % float(x) for x in c),
            "- principal moments about the centre of mass (along x, y, z): %s kg·m²"
            % ", ".join("%.6g" % float(rho * x) for x in p),
        ]
        return "\n".join(lines)

    def steel(name, rho):
        (m, c, I), _ = results[name]
        p = principal_diag(I)
        return "%.4g kg, (%s) kg·m²" % (rho * m, ", ".join("%.4g" % float(rho * x) for x in p))

    return """# Demo meshes

Both meshes are generated (not hand-edited) by `tests/data/gen/inertia.py`;
regenerate them from the repository root with

    python3 tests/data/gen/inertia.py

which also rewrites the exact reference values (density 1, rows `t_handle`,
`top`, `top_ascii`) in `tests/data/polyhedra_expected.csv`. All units are
metres; every surface is closed, manifold and wound counter-clockwise seen from
outside. The mass properties below are at a density of 1000 kg/m³ (scale
linearly for other materials) and were computed exactly from the stored
coordinates.

## `t_handle.obj`

A T-handle like the wing nut of the Dzhanibekov (tennis-racket) effect
demonstrations: a crossbar 80 mm long (along x) with a 12 mm × 12 mm square
section, and a stem 50 mm long (along −z) with a 10 mm × 10 mm square section,
fused into one closed surface (%d vertices, %d triangles, object `o t_handle`).
The origin is at the centre of the joint (the middle of the crossbar's lower
face); the x, y and z axes are principal axes. Coordinates are the millimetre
values divided by 1000 (the nearest f64, written with `repr`). All three
principal moments differ, and the intermediate one (about %s) is the unstable
axis.

%s

In steel (7850 kg/m³): %s; in aluminium (2700 kg/m³): %s.

## `top.stl` and `top_ascii.stl`

A spinning top: a solid of revolution about the z axis with %d segments around,
made of a cone from the tip at the origin up to a 60 mm diameter, 5 mm high rim
at z = 22…27 mm, a shallow conical upper face, and a spindle of 8 mm diameter up
to z = 50 mm (%d vertices, %d triangles). Profile (radius, height) in mm:
%s. `top.stl` is binary STL (float32 coordinates; the generator rounds every
vertex to float32 first and computes the reference from those values);
`top_ascii.stl` is the same triangles as ASCII STL with coordinates written as
the shortest decimals of the float32 values (as doubles), which parse back
exactly whether read as float32 or float64. The ring vertices are
octant-symmetric bit for bit, so the products of inertia vanish exactly and the
two transverse moments are exactly equal (a symmetric top).

%s

In steel (7850 kg/m³): %s; in aluminium (2700 kg/m³): %s.
""" % (len(t_handle.vertices), len(t_handle.faces), intermediate_axis(results["t_handle"][0][2]),
       block("t_handle"),
       steel("t_handle", 7850), steel("t_handle", 2700),
       TOP_SEGMENTS, len(top.vertices), len(top.faces),
       ", ".join("(%g, %g)" % p for p in TOP_PROFILE_MM), block("top"),
       steel("top", 7850), steel("top", 2700))


if __name__ == "__main__":
    sys.exit(main())
