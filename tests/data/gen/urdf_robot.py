"""Generate the toy robot of the `kreisel inertia --urdf` tests and its exact
reference inertials.

Regenerate (from the repository root; needs mpmath, see requirements.txt):

    python3 tests/data/gen/urdf_robot.py

Writes, relative to this script's location:

    ../robot/toy_robot/urdf/toy.urdf     the robot description (hand-formatted,
                                         comments and mixed layouts on purpose)
    ../robot/toy_robot/meshes/*.stl|obj  closed polyhedra in millimetres
    ../robot/expected.json               every filled link's inertial

The robot
---------
* base_link: primitives only (a box and a cylinder), rotated and moved.
* arm: one binary STL mesh in mm (scale="0.001 0.001 0.001") through a
  package:// path, placed by a non-zero xyz and rpy; its old inertial has
  mass 0, so it gets the density.
* forearm: two meshes (an OBJ through a relative path, an STL through
  package://), each with its own origin; its positive mass 2.5 kg is kept.
* hand: an OBJ mesh with a mirroring, non-uniform scale and a sphere.
* tool_tip: no geometry and no inertial; sensor: an inertial, no geometry
  (both must be left untouched).
Visual elements differ from the collision ones; only collision counts.

Reference values
----------------
Mesh coordinates are integers in mm (exact in f32 STL and in OBJ).  Each
mesh's volume, first and second moments are computed EXACTLY with
fractions.Fraction (signed tetrahedra (0, a, b, c)) from the vertices times
the exact binary value of the URDF scale (float("0.001")); primitives by
their closed forms.  Placement (R = Rz(yaw) Ry(pitch) Rx(roll) from the exact
binary values of the rpy strings), the compound sum (parallel axis) and the
scaling to the link's mass or density 1000 kg/m^3 are done with mpmath at
50 significant digits.  Each value is rounded once to f64 and written with
repr().  Inertia: the tensor about the centre of mass in link axes, elements
ixx ixy ixz iyy iyz izz (I_xy = -integral x y).

The script is deterministic and checks itself: closed, consistently
oriented surfaces, positive volumes, and a closed form (the box mesh
equals the box primitive).
"""

import json
import os
import struct
from fractions import Fraction as F

import mpmath
from mpmath import mp, mpf

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
ROBOT = os.path.normpath(os.path.join(HERE, "..", "robot"))
PKG = os.path.join(ROBOT, "toy_robot")
DENSITY = 1000


# ---------------------------------------------------------------------------
# Meshes (integer millimetres, outward counter-clockwise triangles)
# ---------------------------------------------------------------------------

def prism(base, shift):
    """A prism over the counter-clockwise (seen from +z) polygon `base` in
    z = 0, its top `base + shift` (shift z > 0): vertices and triangles."""
    n = len(base)
    v = [(x, y, 0) for x, y in base] + [(x + shift[0], y + shift[1], shift[2]) for x, y in base]
    t = []
    for i in range(1, n - 1):
        t.append((0, i + 1, i))              # bottom, seen from below
        t.append((n, n + i, n + i + 1))      # top
    for i in range(n):
        j = (i + 1) % n
        t.append((i, j, n + j))
        t.append((i, n + j, n + i))
    return v, t


def pyramid():
    v = [(0, 0, 0), (30, 0, 0), (30, 20, 0), (0, 20, 0), (7, 12, 18)]
    t = [(0, 2, 1), (0, 3, 2), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
    return v, t


def octahedron():
    # +x, -x, +y, -y, +z, -z corners, unevenly far out and off-axis.
    v = [(20, 1, 2), (-12, -1, 3), (2, 15, -1), (-1, -9, 1), (3, 2, 22), (4, -3, -14)]
    px, nx, py, ny, pz, nz = range(6)
    t = [(px, py, pz), (py, nx, pz), (nx, ny, pz), (ny, px, pz),
         (py, px, nz), (nx, py, nz), (ny, nx, nz), (px, ny, nz)]
    return v, t


def box_mesh(a, b, c):
    return prism([(0, 0), (a, 0), (a, b), (0, b)], (0, 0, c))


MESHES = {
    "wedge": prism([(0, 0), (40, 0), (10, 30)], (5, 3, 25)),
    "pyramid": pyramid(),
    "octa": octahedron(),
}


def check_closed(name, v, t):
    edges = {}
    for tri in t:
        for k in range(3):
            e = (tri[k], tri[(k + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    for (a, b), n in edges.items():
        assert n == 1 and edges.get((b, a)) == 1, (name, a, b)


def moments(v, t, scale):
    """Exact (volume, first moments, second moments S_ij = integral x_i x_j)
    of the mesh with vertices scaled per axis by the exact `scale`."""
    s = [F(x) for x in scale]
    flip = s[0] * s[1] * s[2] < 0
    p = [tuple(F(c) * s[k] for k, c in enumerate(x)) for x in v]
    vol = F(0)
    first = [F(0)] * 3
    second = [[F(0)] * 3 for _ in range(3)]
    for tri in t:
        a, b, c = (p[i] for i in (tri if not flip else (tri[0], tri[2], tri[1])))
        det = (a[0] * (b[1] * c[2] - b[2] * c[1])
               - a[1] * (b[0] * c[2] - b[2] * c[0])
               + a[2] * (b[0] * c[1] - b[1] * c[0]))
        vol += det / 6
        for i in range(3):
            first[i] += det / 24 * (a[i] + b[i] + c[i])
            for j in range(3):
                sq = a[i] * a[j] + b[i] * b[j] + c[i] * c[j]
                sm = (a[i] + b[i] + c[i]) * (a[j] + b[j] + c[j])
                second[i][j] += det / 120 * (sq + sm)
    assert vol > 0
    return vol, first, second


def mp_of(x):
    return mpf(x.numerator) / x.denominator if isinstance(x, F) else mpf(x)


def part_from_moments(vol, first, second):
    """Unit-density (mass, com, inertia about com) in mpmath from exact moments."""
    m = vol
    c = [f / vol for f in first]
    tr = second[0][0] + second[1][1] + second[2][2]
    inertia = [[(tr if i == j else 0) - second[i][j] - m * ((sum(x * x for x in c) if i == j else 0) - c[i] * c[j])
                for j in range(3)] for i in range(3)]
    return mp_of(m), [mp_of(x) for x in c], mpmath.matrix([[mp_of(x) for x in r] for r in inertia])


def box(size):
    a, b, c = (mpf(x) for x in size)
    m = a * b * c
    return m, [mpf(0)] * 3, mpmath.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])


def cylinder(r, h):
    r, h = mpf(r), mpf(h)
    m = mpmath.pi * r * r * h
    side = m * (3 * r * r + h * h) / 12
    return m, [mpf(0)] * 3, mpmath.diag([side, side, m * r * r / 2])


def sphere(r):
    r = mpf(r)
    m = 4 * mpmath.pi * r ** 3 / 3
    return m, [mpf(0)] * 3, mpmath.diag([2 * m * r * r / 5] * 3)


def rotation(rpy):
    r, p, y = (mpf(float(x)) for x in rpy)
    rx = mpmath.matrix([[1, 0, 0], [0, mpmath.cos(r), -mpmath.sin(r)], [0, mpmath.sin(r), mpmath.cos(r)]])
    ry = mpmath.matrix([[mpmath.cos(p), 0, mpmath.sin(p)], [0, 1, 0], [-mpmath.sin(p), 0, mpmath.cos(p)]])
    rz = mpmath.matrix([[mpmath.cos(y), -mpmath.sin(y), 0], [mpmath.sin(y), mpmath.cos(y), 0], [0, 0, 1]])
    return rz * ry * rx


def placed(part, xyz, rpy):
    m, c, i = part
    rot = rotation(rpy)
    cc = rot * mpmath.matrix(c)
    c2 = [cc[k] + mpf(float(xyz[k])) for k in range(3)]
    return m, c2, rot * i * rot.T


def compound(parts):
    m = sum(p[0] for p in parts)
    c = [sum(p[0] * p[1][k] for p in parts) / m for k in range(3)]
    total = mpmath.zeros(3, 3)
    for pm, pc, pi in parts:
        d = [pc[k] - c[k] for k in range(3)]
        d2 = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                total[i, j] += pi[i, j] + pm * ((d2 if i == j else 0) - d[i] * d[j])
    return m, c, total


# ---------------------------------------------------------------------------
# Files
# ---------------------------------------------------------------------------

def write_stl(path, name, v, t):
    with open(path, "wb") as f:
        f.write(("kreisel toy robot: " + name).ljust(80).encode()[:80])
        f.write(struct.pack("<I", len(t)))
        for tri in t:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))
            for i in tri:
                f.write(struct.pack("<3f", *v[i]))
            f.write(b"\0\0")


def write_obj(path, name, v, t):
    with open(path, "w", newline="\n") as f:
        f.write("# kreisel toy robot: %s, millimetres\no %s\n" % (name, name))
        for x in v:
            f.write("v %d %d %d\n" % x)
        for tri in t:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in tri))


URDF = """<?xml version="1.0"?>
<!-- The toy robot of the tests of kreisel inertia with a URDF: generated by
     tests/data/gen/urdf_robot.py; meshes in millimetres. -->
<robot name="toy">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>

  <link name="base_link">
    <!-- primitives only -->
    <visual>
      <geometry><box size="0.31 0.2 0.1"/></geometry>
      <material name="grey"/>
    </visual>
    <collision>
      <origin xyz="0.01 -0.02 0.03" rpy="0.1 -0.2 0.3"/>
      <geometry>
        <box size="0.3 0.2 0.1"/>
      </geometry>
    </collision>
    <collision>
      <origin xyz="0 0 0.1" rpy="1.5707963267948966 0 0"/>
      <geometry><cylinder radius="0.04" length="0.12"/></geometry>
    </collision>
  </link>

  <joint name="shoulder" type="revolute">
    <parent link="base_link"/><child link="arm"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>

  <link name="arm">
    <inertial>
      <!-- a placeholder: mass 0, so the density applies -->
      <mass value="0"/>
      <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/>
    </inertial>
    <visual>
      <geometry><mesh filename="package://toy_robot/meshes/octa.stl" scale="0.001 0.001 0.001"/></geometry>
    </visual>
    <collision>
      <origin xyz="0.05 0.01 -0.02" rpy="0.4 0.5 -0.6"/>
      <geometry><mesh filename="package://toy_robot/meshes/wedge.stl" scale="0.001 0.001 0.001"/></geometry>
    </collision>
  </link>

  <joint name="elbow" type="revolute">
    <parent link="arm"/><child link="forearm"/>
    <origin xyz="0.1 0 0" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>

  <link name="forearm">
\t<collision>
\t\t<origin xyz="0 0 0.02" rpy="0 0.3 0"/>
\t\t<geometry><mesh filename="../meshes/pyramid.obj" scale="0.001 0.001 0.001"/></geometry>
\t</collision>
\t<inertial>
\t\t<origin xyz="0.1 0 0" rpy="0.1 0.2 0.3"/>
\t\t<mass value="2.5"/>
\t\t<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>
\t</inertial>
\t<collision>
\t\t<origin xyz="-0.03 0.04 0" rpy="-0.7 0.2 1.1"/>
\t\t<geometry><mesh filename="package://toy_robot/meshes/octa.stl" scale="0.001 0.001 0.001"/></geometry>
\t</collision>
  </link>

  <joint name="wrist" type="fixed">
    <parent link="forearm"/><child link="hand"/>
  </joint>

  <link name="hand"><collision>
      <origin xyz="0.002 0.003 0.004" rpy="0.25 -0.35 0.45"/>
      <geometry><mesh filename="../meshes/pyramid.obj" scale="0.001 -0.002 0.0015"/></geometry>
    </collision>
    <collision>
      <origin xyz="0.01 0.02 -0.05"/>
      <geometry><sphere radius="0.02"/></geometry>
    </collision>
  </link>

  <joint name="tip" type="fixed">
    <parent link="hand"/><child link="tool_tip"/>
  </joint>
  <link name="tool_tip"/>

  <joint name="sensor_mount" type="fixed">
    <parent link="hand"/><child link="sensor"/>
  </joint>
  <link name="sensor">
    <inertial>
      <mass value="0.01"/>
      <inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/>
    </inertial>
  </link>
</robot>
"""

MM = ("0.001", "0.001", "0.001")

# Each filled link: its collision parts as (kind, args, xyz, rpy), and the
# kept mass (None: density).
LINKS = {
    "base_link": ([("box", (0.3, 0.2, 0.1), ("0.01", "-0.02", "0.03"), ("0.1", "-0.2", "0.3")),
                   ("cylinder", (0.04, 0.12), ("0", "0", "0.1"), ("1.5707963267948966", "0", "0"))], None),
    "arm": ([("mesh", ("wedge", MM), ("0.05", "0.01", "-0.02"), ("0.4", "0.5", "-0.6"))], None),
    "forearm": ([("mesh", ("pyramid", MM), ("0", "0", "0.02"), ("0", "0.3", "0")),
                 ("mesh", ("octa", MM), ("-0.03", "0.04", "0"), ("-0.7", "0.2", "1.1"))], "2.5"),
    "hand": ([("mesh", ("pyramid", ("0.001", "-0.002", "0.0015")), ("0.002", "0.003", "0.004"), ("0.25", "-0.35", "0.45")),
              ("sphere", (0.02,), ("0.01", "0.02", "-0.05"), ("0", "0", "0"))], None),
}


# The same for --from visual (forearm, hand: no visual geometry).
LINKS_VISUAL = {
    "base_link": ([("box", (0.31, 0.2, 0.1), ("0", "0", "0"), ("0", "0", "0"))], None),
    "arm": ([("mesh", ("octa", MM), ("0", "0", "0"), ("0", "0", "0"))], None),
}


def part(kind, args):
    if kind == "box":
        return box(args)
    if kind == "cylinder":
        return cylinder(*args)
    if kind == "sphere":
        return sphere(*args)
    name, scale = args
    v, t = MESHES[name]
    return part_from_moments(*moments(v, t, [float(s) for s in scale]))


def f64(x):
    return float(mpmath.nstr(x, 40, strip_zeros=False)) if x != 0 else 0.0


def main():
    os.makedirs(os.path.join(PKG, "urdf"), exist_ok=True)
    os.makedirs(os.path.join(PKG, "meshes"), exist_ok=True)
    for name, (v, t) in MESHES.items():
        check_closed(name, v, t)
    check_closed("box", *box_mesh(3, 2, 1))
    # Self-check: the exact box mesh equals the box primitive.
    bm = part_from_moments(*moments(*box_mesh(3, 2, 1), [1.0, 1.0, 1.0]))
    bp = box((3, 2, 1))
    assert abs(bm[0] - bp[0]) == 0 and mpmath.norm(bm[2] - bp[2]) == 0
    assert all(abs(bm[1][k] - (mpf(3), mpf(2), mpf(1))[k] / 2) == 0 for k in range(3))
    write_stl(os.path.join(PKG, "meshes", "wedge.stl"), "wedge", *MESHES["wedge"])
    write_stl(os.path.join(PKG, "meshes", "octa.stl"), "octa", *MESHES["octa"])
    write_obj(os.path.join(PKG, "meshes", "pyramid.obj"), "pyramid", *MESHES["pyramid"])
    with open(os.path.join(PKG, "urdf", "toy.urdf"), "w", newline="\n") as f:
        f.write(URDF.replace("\\t", "\t"))
    out = {
        "about": "Exact inertials of tests/data/robot/toy_robot/urdf/toy.urdf (collision geometry, "
                 "density 1000 kg/m^3 unless the mass is kept; under 'visual': --from visual); "
                 "from tests/data/gen/urdf_robot.py. "
                 "inertia: ixx ixy ixz iyy iyz izz about the centre of mass, link axes.",
        "mpmath": mpmath.__version__,
        "untouched": ["tool_tip", "sensor"],
        "links": filled(LINKS),
        "visual": filled(LINKS_VISUAL),
    }
    with open(os.path.join(ROBOT, "expected.json"), "w", newline="\n") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


def filled(links):
    """The reference inertial of every link in `links`."""
    expected = {}
    for link, (parts, kept) in links.items():
        unit = compound([placed(part(kind, args), xyz, rpy) for kind, args, xyz, rpy in parts])
        volume = unit[0]
        mass = mpf(float(kept)) if kept else DENSITY * volume
        k = mass / volume
        m, c, i = unit[0] * k, unit[1], unit[2] * k
        expected[link] = {
            "mass": f64(m),
            "mass_source": "kept" if kept else "density",
            "density": f64(mass / volume),
            "com": [f64(x) for x in c],
            "inertia": [f64(i[0, 0]), f64(i[0, 1]), f64(i[0, 2]), f64(i[1, 1]), f64(i[1, 2]), f64(i[2, 2])],
        }
    return expected


if __name__ == "__main__":
    main()
