#!/usr/bin/env python3
"""End to end, file to mass properties: kreisel's CLI against trimesh.

Generates closed tori of about 1e5, 1e6 and 1e7 triangles as binary STL
(in surface order, and shuffled), ASCII STL, OBJ, ASCII PLY and binary PLY (into a scratch directory; nothing
is committed), then, for every file, in one run:

- kreisel: ``kreisel inertia FILE --format json`` (the release binary),
  the whole process (read, weld, check, integrate, JSON) under
  ``/usr/bin/time -v``: wall clock, CPU time (user + system) and peak RSS;
- trimesh: ``trimesh.load(FILE)`` + ``mesh.mass_properties`` in a fresh
  Python process, wall clock and CPU time (``time.process_time``) around
  those two calls (interpreter and import start-up excluded), peak RSS of
  the whole process (Python and numpy included, about 60 MiB).

The per-triangle figures use CPU time: on a shared VM the wall clock also
counts waiting for a core. Each tool's figure is the best of ``--repeat``
runs (one run from 2e6 triangles on). The two masses are compared
(density 1000 kg/m^3 for both) so a fast wrong answer cannot hide. Prints a
Markdown table.

    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install trimesh numpy
    cargo build --release -p kreisel-cli
    /tmp/venv/bin/python examples/end_to_end/mesh_end_to_end.py \
        --kreisel target/release/kreisel --dir /tmp/meshes

Options: ``--sizes 1e5,1e6,1e7``, ``--formats stl,stls,stla,obj,ply,plyb``,
``--repeat 3``, ``--no-trimesh``, ``--only-generate``.
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

FORMATS = {
    "stl": ("binary STL", ".stl"),
    "stls": ("binary STL, shuffled", ".stl"),
    "stla": ("ASCII STL", ".stl"),
    "obj": ("OBJ", ".obj"),
    "ply": ("ASCII PLY", ".ply"),
    "plyb": ("binary PLY", ".ply"),
}

DENSITY = 1000.0


def torus(triangles):
    """A closed, outward-wound torus (R = 1, r = 0.35) of about `triangles`.

    Returns (vertices float64 (n, 3), faces int64 (m, 3)); m = 2 nu nv.
    """
    nu = max(3, int(round(math.sqrt(triangles))))
    nv = max(3, int(round(triangles / (2 * nu))))
    u = np.arange(nu) * (2 * math.pi / nu)
    v = np.arange(nv) * (2 * math.pi / nv)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    ring = 1.0 + 0.35 * np.cos(vv)
    vertices = np.stack(
        [ring * np.cos(uu), ring * np.sin(uu), 0.35 * np.sin(vv)], axis=-1
    ).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    i, j = i.ravel(), j.ravel()
    ip, jp = (i + 1) % nu, (j + 1) % nv
    a, b, c, d = i * nv + j, ip * nv + j, ip * nv + jp, i * nv + jp
    # d(u) x d(v) points outwards for this parametrisation. The two
    # triangles of each quad follow each other, quads row by row (as
    # exporters write a surface).
    faces = np.stack([a, b, c, a, c, d], axis=1).reshape(-1, 3)
    return vertices, faces


def write_text(path, header, rows, template, chunk=200_000):
    """Writes `header`, then `template % row` for each row of a 2-D array."""
    with open(path, "w") as f:
        f.write(header)
        for start in range(0, len(rows), chunk):
            block = rows[start : start + chunk]
            f.write((template * len(block)) % tuple(block.ravel().tolist()))


def generate(path, fmt, vertices, faces):
    if fmt in ("stl", "stls"):
        if fmt == "stls":
            # Triangles in random order: no locality for vertex merging.
            faces = faces[np.random.default_rng(12).permutation(len(faces))]
        records = np.zeros(
            len(faces),
            dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")],
        )
        records["v"] = vertices[faces].astype(np.float32)
        with open(path, "wb") as f:
            f.write(b"binary torus".ljust(80, b" "))
            f.write(np.uint32(len(faces)).tobytes())
            records.tofile(f)
    elif fmt == "stla":
        corners = vertices[faces].reshape(len(faces), 9)
        facet = (
            "facet normal 0 0 0\n outer loop\n"
            + "  vertex %.17g %.17g %.17g\n" * 3
            + " endloop\nendfacet\n"
        )
        write_text(path, "solid torus\n", corners, facet)
        with open(path, "a") as f:
            f.write("endsolid torus\n")
    elif fmt == "obj":
        write_text(path, "o torus\n", vertices, "v %.17g %.17g %.17g\n")
        write_text(path + ".faces", "", faces + 1, "f %d %d %d\n")
        append(path, path + ".faces")
    elif fmt == "ply":
        header = (
            "ply\nformat ascii 1.0\n"
            f"element vertex {len(vertices)}\n"
            "property double x\nproperty double y\nproperty double z\n"
            f"element face {len(faces)}\n"
            "property list uchar int vertex_indices\nend_header\n"
        )
        write_text(path, header, vertices, "%.17g %.17g %.17g\n")
        write_text(path + ".faces", "", faces, "3 %d %d %d\n")
        append(path, path + ".faces")
    elif fmt == "plyb":
        header = (
            "ply\nformat binary_little_endian 1.0\n"
            f"element vertex {len(vertices)}\n"
            "property double x\nproperty double y\nproperty double z\n"
            f"element face {len(faces)}\n"
            "property list uchar int vertex_indices\nend_header\n"
        )
        face_rows = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        face_rows["n"] = 3
        face_rows["i"] = faces
        with open(path, "wb") as f:
            f.write(header.encode())
            vertices.astype("<f8").tofile(f)
            face_rows.tofile(f)
    else:
        raise ValueError(fmt)


def append(path, part):
    with open(path, "ab") as out, open(part, "rb") as src:
        while block := src.read(1 << 24):
            out.write(block)
    os.remove(part)


def timed(cmd):
    """Runs `cmd` under /usr/bin/time -v.

    Returns (stdout, wall s, CPU s = user + system, peak RSS bytes).
    """
    proc = subprocess.run(
        ["/usr/bin/time", "-v", *cmd], capture_output=True, text=True
    )
    if proc.returncode != 0:
        raise RuntimeError(f"{cmd} failed: {proc.stderr[-2000:]}")
    err = proc.stderr
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", err)
    h, m, s = wall.groups()
    elapsed = int(h or 0) * 3600 + int(m) * 60 + float(s)
    cpu = sum(float(re.search(rf"{k} time \(seconds\): ([\d.]+)", err)[1])
              for k in ("User", "System"))
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", err)[1])
    return proc.stdout, elapsed, cpu, rss * 1024


TRIMESH_RUN = """
import json, sys, time
import trimesh
path = sys.argv[1]
w0, c0 = time.perf_counter(), time.process_time()
mesh = trimesh.load(path)
mesh.density = %r
mp = mesh.mass_properties
mass = float(mp["mass"])
w1, c1 = time.perf_counter(), time.process_time()
print(json.dumps({"wall": w1 - w0, "cpu": c1 - c0, "mass": mass,
                  "triangles": len(mesh.faces)}))
"""


def run_kreisel(binary, path, repeat):
    """Best (by CPU time) of `repeat` runs: (wall, cpu, rss, JSON report)."""
    best = None
    for _ in range(repeat):
        out, wall, cpu, rss = timed([binary, "inertia", path, "--format", "json"])
        if best is None or cpu < best[1]:
            best = (wall, cpu, rss, json.loads(out))
    return best


def run_trimesh(path, repeat):
    """Best (by CPU time) of `repeat` runs: (wall, cpu, rss, mass)."""
    best = None
    for _ in range(repeat):
        out, _, _, rss = timed([sys.executable, "-c", TRIMESH_RUN % DENSITY, path])
        r = json.loads(out)
        if best is None or r["cpu"] < best[1]:
            best = (r["wall"], r["cpu"], rss, r["mass"])
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--kreisel", default="target/release/kreisel")
    ap.add_argument("--dir", default=os.path.join(tempfile.gettempdir(), "kreisel_e2e"))
    ap.add_argument("--sizes", default="1e5,1e6,1e7")
    ap.add_argument("--formats", default=",".join(FORMATS))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-trimesh", action="store_true")
    ap.add_argument("--only-generate", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    sizes = [int(float(s)) for s in args.sizes.split(",")]
    formats = args.formats.split(",")

    rows = []
    for size in sizes:
        vertices, faces = torus(size)
        for fmt in formats:
            label, ext = FORMATS[fmt]
            path = os.path.join(args.dir, f"torus_{size:.0e}_{fmt}{ext}".replace("+", ""))
            if not os.path.exists(path):
                generate(path + ".part", fmt, vertices, faces)
                os.replace(path + ".part", path)
            if args.only_generate:
                continue
            n = len(faces)
            mb = os.path.getsize(path) / 1e6
            # Warm the page cache so both tools read from memory.
            with open(path, "rb") as f:
                while f.read(1 << 24):
                    pass
            repeat = args.repeat if n <= 2_000_000 else 1
            k_wall, k_cpu, k_rss, report = run_kreisel(args.kreisel, path, repeat)
            row = [label, f"{n:,}", f"{mb:.0f}", f"{k_wall:.2f}", f"{k_cpu / n * 1e9:.0f}",
                   f"{k_rss / 2**20:.0f}", f"{k_rss / n:.0f}"]
            if not args.no_trimesh:
                t_wall, t_cpu, t_rss, t_mass = run_trimesh(path, repeat)
                rel = abs(t_mass - report["mass"]) / abs(t_mass)
                row += [f"{t_wall:.2f}", f"{t_cpu / n * 1e9:.0f}", f"{t_rss / 2**20:.0f}",
                        f"{t_rss / n:.0f}", f"{t_cpu / k_cpu:.1f}", f"{rel:.1e}"]
            rows.append(row)
            print("|", " | ".join(row), "|", file=sys.stderr, flush=True)

    if args.only_generate:
        return
    head = ["format", "triangles", "file MB", "kreisel wall s", "kreisel CPU ns/tri",
            "kreisel peak RSS MiB", "kreisel B/tri"]
    if not args.no_trimesh:
        head += ["trimesh wall s", "trimesh CPU ns/tri", "trimesh peak RSS MiB",
                 "trimesh B/tri", "CPU trimesh/kreisel", "mass rel. diff."]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for row in rows:
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
