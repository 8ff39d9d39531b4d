"""Side by side in MuJoCo: `kreisel inertia --digits N` against the same
tensor rounded naively (every number to N significant digits), and the
principal form (`--principal`) against `fullinertia`. Measures; writes
nothing.

    pip install mujoco numpy
    cargo build -p kreisel-cli
    python3 tests/data/gen/digits_mujoco.py [path/to/kreisel]

Bodies: 40 tilted 0.3 x 0.2 sheets (--shell; A + B = C exactly, so any
rounding puts them on either side of MuJoCo's check), a 1 m x 0.1 mm x
0.1 mm rod tilted by --transform (A/C ~ 2e-8, far below the rounding of the
products), and a 2 x 1 x 3 box under five --transform tilts (one at pitch
pi/2, one 1e-9 rad from the identity).
"""

import math
import os
import re
import subprocess
import sys
import tempfile

import mujoco
import numpy as np

KREISEL = sys.argv[1] if len(sys.argv) > 1 else "target/debug/kreisel"
CUBE_FACES = [[1, 3, 2], [1, 4, 3], [5, 6, 7], [5, 7, 8], [1, 2, 6], [1, 6, 5],
              [4, 8, 7], [4, 7, 3], [1, 5, 8], [1, 8, 4], [2, 3, 7], [2, 7, 6]]


def rot(yaw, pitch, roll):
    cy, sy, cp, sp, cr, sr = (math.cos(yaw), math.sin(yaw), math.cos(pitch),
                              math.sin(pitch), math.cos(roll), math.sin(roll))
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


def write_sheet(path, k):
    r = rot(0.37 * k, 0.21 * k - 1.0, 0.1 * k)
    with open(path, "w") as f:
        for x, y in [(0, 0), (0.3, 0), (0.3, 0.2), (0, 0.2)]:
            p = r @ np.array([x - 0.09, y - 0.12, 0.0])
            f.write("v %r %r %r\n" % tuple(float(c) for c in p))
        f.write("f 1 2 3\nf 1 3 4\n")


def write_box(path, a, b, c):
    with open(path, "w") as f:
        for z in (0, c):
            for x, y in [(0, 0), (a, 0), (a, b), (0, b)]:
                f.write(f"v {x!r} {y!r} {z!r}\n")
        for i, j, k in CUBE_FACES:
            f.write(f"f {i} {j} {k}\n")


def mjcf(path, *args):
    out = subprocess.run([KREISEL, "inertia", path, "--format", "mjcf", *args],
                         capture_output=True, text=True, check=True).stdout
    return next(line for line in out.splitlines() if line.startswith("<inertial"))


def model(inertial):
    return mujoco.MjModel.from_xml_string(
        f"<mujoco><worldbody><body>{inertial}<freejoint/></body></worldbody></mujoco>")


def loads(inertial):
    try:
        model(inertial)
        return True
    except ValueError:
        return False


def naive(inertial, n):
    def round_all(m):
        values = " ".join("%.*e" % (n - 1, float(v)) for v in m.group(2).split())
        return f'{m.group(1)}="{values}"'
    return re.sub(r'(fullinertia|mass|pos)="([^"]*)"', round_all, inertial)


def count(path, extra, n):
    full = mjcf(path, *extra)
    return (loads(naive(full, n)),
            loads(mjcf(path, *extra, "--digits", str(n))),
            loads(mjcf(path, *extra, "--digits", str(n), "--principal")))


def tensor(inertial):
    m = model(inertial)
    r = np.zeros(9)
    mujoco.mju_quat2Mat(r, m.body_iquat[1])
    r = r.reshape(3, 3)
    return r @ np.diag(m.body_inertia[1]) @ r.T


def main():
    tmp = tempfile.mkdtemp()
    print(f"MuJoCo {mujoco.__version__}: how many load (naive rounding, --digits, --digits --principal)")
    sheets = []
    for k in range(40):
        sheets.append(os.path.join(tmp, f"sheet_{k}.obj"))
        write_sheet(sheets[-1], k)
    for n in [2, 3, 5, 8]:
        results = [count(p, ["--shell"], n) for p in sheets]
        print(f"  {len(sheets)} tilted sheets, digits {n}:", [sum(r[i] for r in results) for i in range(3)])
    rod = os.path.join(tmp, "rod.obj")
    write_box(rod, 1.0, 1e-4, 1e-4)
    tilts = ["0.3 -0.4 1.1", "0 0.7 0.2", "1 1 1", "2 -1 0.5", "-0.3 0.2 -2"]
    for n in [3, 4, 6]:
        results = [count(rod, ["--transform", "rpy=" + t], n) for t in tilts]
        print(f"  {len(tilts)} tilted thin rods, digits {n}:", [sum(r[i] for r in results) for i in range(3)])
    box = os.path.join(tmp, "box.obj")
    write_box(box, 2.0, 1.0, 3.0)
    worst = 0.0
    for t in ["0 0 0", "1e-9 0 0", "0.3 -0.4 1.1", "2.5 1.5707963267948966 -0.7", "0.1 1.2 -2.9"]:
        a = tensor(mjcf(box, "--transform", "rpy=" + t))
        b = tensor(mjcf(box, "--transform", "rpy=" + t, "--principal"))
        worst = max(worst, np.abs(a - b).max() / np.abs(a).max())
    print(f"box 2x1x3, 5 tilts: MuJoCo's tensor from fullinertia vs from --principal: max rel. difference {worst:.1e}")


if __name__ == "__main__":
    main()
