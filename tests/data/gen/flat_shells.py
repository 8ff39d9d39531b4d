"""40 tilted flat sheets (regression data for MJCF/URDF/SDF output), and a
check that MuJoCo loads what `kreisel inertia --shell --format mjcf` prints.

A flat body has principal moments with A + B = C exactly, so rounding alone
can put its tensor on the wrong side of MuJoCo's check "inertia must satisfy
A + B >= C" (before the fix: 10 of these 40 sheets were refused).

Regenerate the sheets (standard library only; deterministic):

    python3 tests/data/gen/flat_shells.py

Check them with MuJoCo (pip install mujoco; CI has no MuJoCo, so the Rust
test crates/cli/tests/xml_output.rs asserts the inequality on the printed
numbers instead):

    cargo build -p kreisel-cli
    python3 tests/data/gen/flat_shells.py --check target/debug/kreisel

Writes ../flat_shells/sheet_NN.obj: a 0.3 m x 0.2 m rectangle of 2 x 3
quads, turned by a rotation from a fixed-seed generator and moved off the
origin.
"""

import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "flat_shells"))
COUNT = 40


def rotation(rng):
    """A uniformly random rotation matrix (Shoemake's quaternion method)."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    w, x, y, z = (a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
                  b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3))
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def sheet(rng):
    r = rotation(rng)
    shift = [rng.uniform(-1, 1) for _ in range(3)]
    nx, ny, sx, sy = 2, 3, 0.3, 0.2
    lines = ["# flat sheet %g m x %g m, tilted (tests/data/gen/flat_shells.py)" % (sx, sy)]
    for j in range(ny + 1):
        for i in range(nx + 1):
            p = (sx * i / nx, sy * j / ny, 0.0)
            q = [sum(r[k][m] * p[m] for m in range(3)) + shift[k] for k in range(3)]
            lines.append("v %r %r %r" % tuple(q))
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i + 1
            b, c, d = a + 1, a + nx + 2, a + nx + 1
            lines.append("f %d %d %d" % (a, b, c))
            lines.append("f %d %d %d" % (a, c, d))
    return "\n".join(lines) + "\n"


def generate():
    os.makedirs(OUT, exist_ok=True)
    rng = random.Random(20261123)
    for k in range(COUNT):
        with open(os.path.join(OUT, "sheet_%02d.obj" % k), "w") as f:
            f.write(sheet(rng))


def check(kreisel):
    import mujoco  # noqa: F401  (only needed for the check)
    refused = []
    for k in range(COUNT):
        path = os.path.join(OUT, "sheet_%02d.obj" % k)
        out = subprocess.run([kreisel, "inertia", path, "--shell", "--format", "mjcf"],
                             capture_output=True, text=True, check=True).stdout
        inertial = next(l for l in out.splitlines() if l.startswith("<inertial"))
        xml = ("<mujoco><worldbody><body><freejoint/>%s</body></worldbody></mujoco>"
               % inertial)
        try:
            mujoco.MjModel.from_xml_string(xml)
        except ValueError as e:
            refused.append((path, str(e).splitlines()[0]))
    print("MuJoCo %s loaded %d of %d tilted flat sheets"
          % (mujoco.__version__, COUNT - len(refused), COUNT))
    for path, why in refused:
        print("  refused %s: %s" % (os.path.basename(path), why))
    return not refused


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        sys.exit(0 if check(sys.argv[2]) else 1)
    generate()
