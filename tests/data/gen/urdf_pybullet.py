"""`kreisel inertia --urdf` on the robots bundled with pybullet: what
`--check` finds, and the filled inertials side by side with trimesh.

Run (from the repository root, after `cargo build -p kreisel-cli`):

    python3 -m venv /tmp/uv && /tmp/uv/bin/pip install pybullet trimesh scipy numpy
    /tmp/uv/bin/python tests/data/gen/urdf_pybullet.py [path/to/kreisel]

Writes nothing; prints
* for every URDF under pybullet_data (not random_urdfs/): the check's exit
  status and the failing links, with the solid model and with --hull;
  then how often each reason occurs;
* for a few robots: each link's filled centre of mass and inertia per unit
  mass against trimesh's (its mesh loaded with the URDF's scale, placed by the
  collision origin with trimesh's static-xyz Euler matrix, the convex hull
  with --hull), relative to the link's size and largest moment.
"""

import collections
import glob
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pybullet_data
import trimesh
from trimesh.transformations import euler_matrix

HERE = os.path.dirname(os.path.abspath(__file__))
KREISEL = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "..", "target", "debug", "kreisel")
DATA = pybullet_data.getDataPath()


def kreisel(*args):
    return subprocess.run([KREISEL, "inertia", *args], capture_output=True, text=True, timeout=600)


def survey():
    files = sorted(f for f in glob.glob(DATA + "/**/*.urdf", recursive=True) if "/random_urdfs/" not in f)
    for mode, extra in (("solid", []), ("hull", ["--hull"])):
        reasons = collections.Counter()
        links = failing = 0
        print("== --check, %s model, %d URDF files" % (mode, len(files)))
        for f in files:
            run = kreisel("--urdf", f, "--check", *extra)
            lines = run.stderr.strip().splitlines()
            rel = os.path.relpath(f, DATA)
            if run.returncode != 0 and len(lines) == 1:
                print("  %-45s error: %s" % (rel, lines[0].split(": ", 2)[-1][:110]))
                continue
            rows = [l for l in lines[1:] if not l.startswith(("/", "kreisel:"))]
            links += len(rows)
            bad = [r.split()[0] for r in rows if " FAIL " in r]
            failing += len(bad)
            print("  %-45s %2d links, %2d fail %s" % (rel, len(rows), len(bad), " ".join(bad)[:90]))
            for r in rows:
                if " FAIL " in r:
                    for why in r.split(" FAIL ", 1)[1].split(";"):
                        reasons[re.sub(r"-?[0-9][-+0-9.e]*%?|\([^)]*\)", "#", why.strip())[:70]] += 1
        print("  %d links, %d fail; reasons:" % (links, failing))
        for why, n in reasons.most_common():
            print("    %4d  %s" % (n, why))


def peers(urdf, hull):
    """Worst relative differences (com, I/m) of kreisel's filled links vs trimesh."""
    extra = ["--hull"] if hull else []
    filled = ET.fromstring(kreisel("--urdf", urdf, *extra).stdout)
    base = os.path.dirname(urdf)
    worst = [0.0, 0.0]
    for link in ET.parse(urdf).getroot().iter("link"):
        parts = []
        for c in link.findall("collision"):
            g = c.find("geometry")[0]
            if g.tag != "mesh":
                parts = []
                break
            m = trimesh.load(os.path.join(base, g.get("filename").replace("package://", "")), force="mesh")
            m.apply_scale([float(x) for x in (g.get("scale") or "1 1 1").split()])
            m = m.convex_hull if hull else m
            if not m.is_volume:
                parts = []
                break
            o = c.find("origin")
            xyz = [float(x) for x in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]
            rpy = [float(x) for x in (o.get("rpy", "0 0 0") if o is not None else "0 0 0").split()]
            t = euler_matrix(*rpy, "sxyz")
            t[:3, 3] = xyz
            m.apply_transform(t)
            parts.append(m)
        mine = [l for l in filled.iter("link") if l.get("name") == link.get("name")][0].find("inertial")
        if not parts or mine is None:
            continue
        mesh = trimesh.util.concatenate(parts) if len(parts) > 1 else parts[0]
        mass = float(mine.find("mass").get("value"))
        c = np.array([float(x) for x in mine.find("origin").get("xyz").split()])
        e = mine.find("inertia")
        g = lambda k: float(e.get(k))
        per_mass = np.array([[g("ixx"), g("ixy"), g("ixz")], [g("ixy"), g("iyy"), g("iyz")],
                             [g("ixz"), g("iyz"), g("izz")]]) / mass
        theirs = mesh.moment_inertia / mesh.mass
        worst[0] = max(worst[0], np.linalg.norm(c - mesh.center_mass) / np.linalg.norm(mesh.extents))
        worst[1] = max(worst[1], np.abs(per_mass - theirs).max() / np.abs(theirs).max())
    return worst


def main():
    survey()
    print("== filled inertials vs trimesh (worst relative difference: com, inertia per mass)")
    for rel, hull in (("kuka_iiwa/model.urdf", True), ("franka_panda/panda.urdf", True),
                      ("xarm/xarm6_robot.urdf", False), ("laikago/laikago.urdf", False)):
        com, inertia = peers(os.path.join(DATA, rel), hull)
        print("  %-28s %-6s com %.1e  inertia %.1e" % (rel, "hull" if hull else "solid", com, inertia))


if __name__ == "__main__":
    main()
