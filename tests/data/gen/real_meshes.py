"""Compare `kreisel inertia` with trimesh and MuJoCo on real robot meshes.

Not part of `cargo test`.  Every STL and OBJ file under pybullet's bundled
data (or the directories given) is integrated three ways, side by side:

* kreisel: `kreisel inertia FILE --density 1 --format json` (release build);
* trimesh: `trimesh.load(FILE, force="mesh")` (merges vertices to 1e-8, but
  keeps an OBJ's vertices apart along texture and normal seams, so that
  many closed OBJ meshes are not `is_watertight`), then also
  `merge_vertices(merge_tex=True, merge_norm=True)` (positions only, the
  geometric surface); `is_watertight`, `is_volume` and, for the merged
  mesh, `mass_properties` at density 1;
* MuJoCo (if importable): the mesh as the only geom of a free body with
  `<mesh inertia="exact"/>` and density 1; `body_mass`, `body_ipos` and the
  principal moments `body_inertia`. MuJoCo reads only the first object of
  an OBJ file, so it is compared only where kreisel finds one body.

Setup (a venv outside the repository):

    python3 -m venv /tmp/meshvenv
    /tmp/meshvenv/bin/pip install pybullet trimesh mujoco
    cargo build --release -p kreisel-cli
    /tmp/meshvenv/bin/python tests/data/gen/real_meshes.py [--kreisel target/release/kreisel] [DIR ...]

Prints the acceptance of each tool, why kreisel refuses the meshes trimesh
integrates (`is_volume`), and the largest relative disagreement of mass,
centre of mass (relative to the bounding-box diagonal) and inertia
(principal moments relative to the largest) where both accept.
"""

import argparse
import collections
import json
import os
import re
import subprocess
import sys

import numpy as np
import trimesh

try:
    import mujoco
except ImportError:  # MuJoCo is optional.
    mujoco = None


def mesh_files(dirs):
    for d in dirs:
        for root, _, files in os.walk(d):
            for f in sorted(files):
                if f.lower().endswith((".stl", ".obj")):
                    yield os.path.join(root, f)


def run_kreisel(exe, path):
    try:
        p = subprocess.run(
            [exe, "inertia", path, "--density", "1", "--format", "json"],
            capture_output=True,
            text=True,
            timeout=120,
        )
    except subprocess.TimeoutExpired:
        return None, "timeout"
    if p.returncode != 0:
        return None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "exit %d" % p.returncode
    out = json.loads(p.stdout)
    return {
        "mass": out["mass"],
        "com": np.array(out["center_of_mass"]),
        "inertia": np.array(out["inertia"]),
        "principal": np.array(out["principal_moments"]),
        "warnings": out["warnings"],
        "bodies": len(out["bodies"]),
    }, None


def run_trimesh(path):
    try:
        m = trimesh.load(path, force="mesh")
    except Exception as e:  # noqa: BLE001 (any loader failure is a refusal)
        return None, "load: %s" % e
    if not isinstance(m, trimesh.Trimesh) or len(m.faces) == 0:
        return None, "no triangles"
    result = {
        "watertight_default": bool(m.is_watertight),
        "volume_default": bool(m.is_volume),
    }
    m.merge_vertices(merge_tex=True, merge_norm=True)
    result.update({
        "watertight": bool(m.is_watertight),
        "volume_ok": bool(m.is_volume),
        "diag": float(np.linalg.norm(m.extents)) if len(m.vertices) else 0.0,
    })
    if m.is_volume:
        mp = m.mass_properties
        result["mass"] = float(mp["mass"])
        result["com"] = np.array(mp["center_mass"])
        result["inertia"] = np.array(mp["inertia"])
        result["principal"] = np.sort(np.linalg.eigvalsh(result["inertia"]))
    return result, None


def raw_signed_volume(path):
    """The divergence-theorem volume of the file's triangles as stored (no
    merging, no repair): an independent check where trimesh declines. OBJ
    is read here (`v` and fan-triangulated `f` lines), STL by trimesh."""
    if path.lower().endswith(".obj"):
        vs, total = [], 0.0
        with open(path, errors="replace") as f:
            for line in f:
                w = line.split()
                if not w:
                    continue
                if w[0] == "v":
                    vs.append(np.array([float(x) for x in w[1:4]]))
                elif w[0] == "f" and len(w) >= 4:
                    idx = [int(c.split("/")[0]) for c in w[1:]]
                    idx = [i - 1 if i > 0 else len(vs) + i for i in idx]
                    for j in range(1, len(idx) - 1):
                        a, b, c = vs[idx[0]], vs[idx[j]], vs[idx[j + 1]]
                        total += float(np.dot(a, np.cross(b, c)))
        return total / 6.0
    m = trimesh.load(path, force="mesh", process=False)
    v, f = m.vertices, m.faces
    return float(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6.0)


def run_mujoco(path):
    if mujoco is None:
        return None, "not installed"
    xml = """<mujoco><compiler boundmass="0" boundinertia="0"/>
<asset><mesh name="m" file="%s" inertia="exact"/></asset>
<worldbody><body><freejoint/><geom type="mesh" mesh="m" density="1"/></body></worldbody>
</mujoco>""" % os.path.abspath(path)
    try:
        model = mujoco.MjModel.from_xml_string(xml)
    except Exception as e:  # noqa: BLE001
        return None, str(e).splitlines()[0]
    return {
        "mass": float(model.body_mass[1]),
        "com": np.array(model.body_ipos[1]),
        "principal": np.sort(np.array(model.body_inertia[1])),
    }, None


def refusal_class(reason):
    for pattern, name in [
        (r"--merge", "closed only with --merge"),
        (r"--weld", "open, cracks (advice: --weld)"),
        (r"mesh is open", "open (holes)"),
        (r"not closed", "non-manifold, windings do not cancel"),
        (r"not orientable", "not orientable"),
        (r"zero volume", "zero volume"),
        (r"invalid", "parse error"),
        (r"non-finite", "non-finite coordinate (NaN in the file)"),
    ]:
        if re.search(pattern, reason):
            return name
    return reason[:80]


def rel(a, b, scale):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / scale) if scale > 0 else float("inf")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kreisel", default="target/release/kreisel")
    ap.add_argument("--show", type=int, default=8, help="examples listed per refusal class")
    ap.add_argument("dirs", nargs="*")
    args = ap.parse_args()
    dirs = args.dirs
    if not dirs:
        import pybullet_data

        dirs = [pybullet_data.getDataPath()]
    files = list(mesh_files(dirs))
    n = len(files)
    k_ok = t_water = t_vol = t_water_default = t_vol_default = mj_ok = 0
    refused_vol = collections.Counter()
    examples = collections.defaultdict(list)
    worst = {"mass": (0, ""), "com": (0, ""), "inertia": (0, ""),
             "mj_mass": (0, ""), "mj_com": (0, ""), "mj_inertia": (0, "")}
    both = 0
    warn_classes = collections.Counter()
    refused_all = collections.Counter()
    refused_others = collections.Counter()
    only_kreisel = only_kreisel_mj = 0
    only_raw = []  # kreisel vs the raw signed volume where trimesh declines
    mj_cmp = []  # (mass, com, inertia) relative differences, one body only
    for path in files:
        k, k_err = run_kreisel(args.kreisel, path)
        t, _ = run_trimesh(path)
        mj, _ = run_mujoco(path)
        k_ok += k is not None
        mj_ok += mj is not None
        t_volume = t is not None and t["volume_ok"]
        if t is not None:
            t_water += t["watertight"]
            t_vol += t["volume_ok"]
            t_water_default += t["watertight_default"]
            t_vol_default += t["volume_default"]
        if k is None:
            c = refusal_class(k_err)
            refused_all[c] += 1
            if len(examples["all " + c]) < 3:
                examples["all " + c].append("%s: %s" % (os.path.relpath(path, dirs[0]), k_err))
            if t_volume or mj is not None:
                refused_others["%s; %s" % (c, "trimesh is_volume (merged)" if t_volume else "MuJoCo compiles")] += 1
        else:
            for w in k["warnings"]:
                for key in ["welded", "degenerate", "shared by more than two", "inconsistent",
                            "inside-out", "implausible", "fewer than 3"]:
                    if key in w:
                        warn_classes[key] += 1
        if t_volume:
            if k is None:
                c = refusal_class(k_err)
                refused_vol[c] += 1
                if len(examples[c]) < args.show:
                    examples[c].append("%s: %s" % (os.path.relpath(path, dirs[0]), k_err))
            else:
                both += 1
                mscale = abs(t["mass"])
                diag = t["diag"]
                for key, val in [
                    ("mass", abs(k["mass"] - t["mass"]) / mscale),
                    ("com", rel(k["com"], t["com"], diag)),
                    ("inertia", rel(k["inertia"], t["inertia"], np.max(np.abs(t["principal"])))),
                ]:
                    if val > worst[key][0]:
                        worst[key] = (val, path)
        elif k is not None:
            only_kreisel += 1
            d = abs(k["mass"] - abs(raw_signed_volume(path))) / k["mass"]
            d = float("inf") if d != d else d
            only_raw.append((d, path, [w for w in k["warnings"] if "implausible" not in w]))
        if k is not None and mj is not None and k["bodies"] == 1 and t is not None:
            only_kreisel_mj += not t_volume
            diffs = (
                abs(k["mass"] - mj["mass"]) / abs(k["mass"]),
                rel(k["com"], mj["com"], t["diag"]),
                rel(np.sort(k["principal"]), mj["principal"], np.max(np.abs(k["principal"]))),
            )
            mj_cmp.append((diffs, path, t_volume))
            for key, val in zip(["mj_mass", "mj_com", "mj_inertia"], diffs):
                if val > worst[key][0]:
                    worst[key] = (val, path)
    print("meshes: %d (STL/OBJ under %s)" % (n, ", ".join(dirs)))
    print("kreisel accepts:          %d (%.1f %%)" % (k_ok, 100.0 * k_ok / n))
    print("trimesh is_watertight:    %d (%.1f %%) as loaded, %d (%.1f %%) merged across seams"
          % (t_water_default, 100.0 * t_water_default / n, t_water, 100.0 * t_water / n))
    print("trimesh is_volume:        %d (%.1f %%) as loaded, %d (%.1f %%) merged across seams"
          % (t_vol_default, 100.0 * t_vol_default / n, t_vol, 100.0 * t_vol / n))
    if mujoco is not None:
        print("MuJoCo compiles (exact):  %d (%.1f %%)" % (mj_ok, 100.0 * mj_ok / n))
    print("trimesh is_volume (merged) but kreisel refuses: %d" % sum(refused_vol.values()))
    for c, count in refused_vol.most_common():
        print("  %4d  %s" % (count, c))
        for e in examples[c]:
            print("          %s" % e)
    print("kreisel warnings on accepted meshes: %s" % dict(warn_classes))
    print("both kreisel and trimesh (merged, is_volume): %d; largest relative differences:" % both)
    for key in ["mass", "com", "inertia"]:
        v, p = worst[key]
        print("  %-8s %.3g  %s" % (key, v, os.path.relpath(p, dirs[0]) if p else ""))
    print("kreisel accepts, trimesh (merged) not is_volume: %d" % only_kreisel)
    if only_raw:
        kinds = collections.Counter(
            "non-manifold" if any("shared by more" in w for w in ws) else
            "welded" if any("welded" in w for w in ws) else
            "degenerate" if any("degenerate" in w for w in ws) else
            "repaired winding" if any("flipped" in w or "inside-out" in w for w in ws) else "none"
            for _, _, ws in only_raw)
        print("  kreisel's warning on them: %s" % dict(kinds))
        off = sorted(only_raw, key=lambda x: -x[0])
        print("  mass vs the raw signed volume of the file's triangles: max %.3g, > 1e-6 on %d"
              % (off[0][0], sum(d > 1e-6 for d, _, _ in off)))
        for d, p, ws in off[: args.show]:
            if d > 1e-6:
                print("    %s %.3g %s" % (os.path.relpath(p, dirs[0]), d, "; ".join(w[:90] for w in ws)))
    print("kreisel refusals by cause (all %d):" % sum(refused_all.values()))
    for c, count in refused_all.most_common():
        print("  %4d  %s" % (count, c))
        for e in examples["all " + c]:
            print("          %s" % e[:300])
    print("  of which trimesh or MuJoCo integrate: %s" % dict(refused_others))
    if mujoco is not None:
        big = [(d, p, tv) for d, p, tv in mj_cmp if max(d) > 1e-6]
        print("kreisel vs MuJoCo (one body, both accept): %d meshes, %d of them not is_volume for trimesh"
              % (len(mj_cmp), only_kreisel_mj))
        for key in ["mj_mass", "mj_com", "mj_inertia"]:
            v, p = worst[key]
            print("  %-10s %.3g  %s" % (key, v, os.path.relpath(p, dirs[0]) if p else ""))
        print("  differences > 1e-6: %d" % len(big))
        for d, p, tv in sorted(big, key=lambda x: -max(x[0]))[: args.show]:
            print("    %s mass %.3g com %.3g inertia %.3g (trimesh is_volume: %s)"
                  % (os.path.relpath(p, dirs[0]), d[0], d[1], d[2], tv))
    return 0


if __name__ == "__main__":
    sys.exit(main())
