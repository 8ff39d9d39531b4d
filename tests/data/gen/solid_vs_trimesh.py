"""kreisel's whole-file solid against trimesh on real multi-body files.

kreisel: `kreisel inertia --format json FILE`, the assembly that
kreisel-inertia's `load_solid` computes (every body a solid of 1000 kg/m^3,
compounded). Reference: the OBJ split here by hand into its objects/groups,
each a trimesh solid, compounded with numpy (parallel-axis theorem).
Files: pybullet_data's convex decompositions (V-HACD) and random_urdfs.

    pip install trimesh scipy pybullet
    cargo build -p kreisel-cli
    python tests/data/gen/solid_vs_trimesh.py [path/to/kreisel]

Nothing is written: it prints the worst relative differences.
"""
import json, subprocess, sys, glob
import numpy as np
import trimesh

import os
import pybullet_data

KREISEL = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.environ.get("CARGO_TARGET_DIR", "target"), "debug", "kreisel")
D = pybullet_data.getDataPath()
files = sorted(glob.glob(D + "/**/*vhacd*.obj", recursive=True) + glob.glob(D + "/random_urdfs/*/*.obj"))
worst = [0, 0, 0]; n = 0; skipped = 0; reasons = {}
for f in files:
    out = subprocess.run([KREISEL, "inertia", "--format", "json", f], capture_output=True, text=True)
    if out.returncode != 0:
        reasons["kreisel error"] = reasons.get("kreisel error", 0) + 1; skipped += 1; continue
    k = json.loads(out.stdout)
    # The OBJ split by hand into its objects/groups (faces fan-triangulated).
    verts = []; groups = {}; order = []; current = None
    for line in open(f, errors="replace"):
        w = line.split()
        if not w: continue
        if w[0] == "v": verts.append([float(x) for x in w[1:4]])
        elif w[0] in ("o", "g"): current = " ".join(w[1:]) or current
        elif w[0] == "f":
            idx = [int(t.split("/")[0]) for t in w[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            if current not in groups: groups[current] = []; order.append(current)
            groups[current] += [[idx[0], idx[j], idx[j + 1]] for j in range(1, len(idx) - 1)]
    V = np.array(verts)
    parts = []; meshes = []
    for name in order:
        g = trimesh.Trimesh(V, np.array(groups[name]), process=True)  # merge duplicate vertices
        g.remove_unreferenced_vertices()
        g.density = 1000.0
        meshes.append(g)
        parts.append((g.mass, g.center_mass, g.moment_inertia))
    if len(parts) != len(k["bodies"]) or len(parts) < 2:
        r = "one body" if len(k["bodies"]) < 2 else f"count differs"
        reasons[r] = reasons.get(r, 0) + 1; skipped += 1; continue
    m = sum(p[0] for p in parts)
    c = sum(p[0] * p[1] for p in parts) / m
    I = sum(Ik + mk * ((ck - c) @ (ck - c) * np.eye(3) - np.outer(ck - c, ck - c)) for mk, ck, Ik in parts)
    size = np.ptp(np.vstack([g.vertices for g in meshes]), axis=0).max()
    e = [abs(k["mass"] - m) / m,
         np.abs(np.array(k["center_of_mass"]) - c).max() / size,
         np.abs(np.array(k["inertia"]) - I).max() / np.abs(I).max()]
    worst = [max(a, b) for a, b in zip(worst, e)]
    n += 1
print(f"{n} multi-body files compared, {skipped} skipped; worst relative difference: "
      f"mass {worst[0]:.1e}, centre {worst[1]:.1e} (of size), inertia {worst[2]:.1e}")
print("skipped:", reasons)
