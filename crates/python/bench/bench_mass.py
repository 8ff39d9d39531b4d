"""kreisel.mass_properties against trimesh on large meshes, in one run.

For every mesh file: `kreisel.mass_properties(path, density=RHO)` (load,
weld, check, integrate, the report dict) against `trimesh.load(path,
force="mesh")` + `mesh.mass_properties` (with the same density); and, for
trimesh users whose mesh is already loaded, `kreisel.mass_properties_from_arrays
(mesh.vertices, mesh.faces)` against `mesh.mass_properties` alone. Wall and
CPU time (`time.perf_counter`, `time.process_time`), best of --repeat runs,
and the relative difference of the masses. Prints a Markdown table.

The meshes (closed tori, 10^6 triangles in binary STL, ASCII STL, OBJ, ASCII
and binary PLY) are written by the committed generator:

    python examples/end_to_end/mesh_end_to_end.py --kreisel target/release/kreisel \\
        --dir /tmp/kreisel_e2e --sizes 1e6 --repeat 1

Run (after `maturin develop --release` in crates/python):

    python crates/python/bench/bench_mass.py --dir /tmp/kreisel_e2e --size 1e06
"""

import argparse
import gc
import pathlib
import sys
import time

import numpy as np


def timed(f, repeat):
    """(best wall s, best CPU s, last result) of `repeat` calls of f."""
    best_wall = best_cpu = float("inf")
    result = None
    for _ in range(repeat):
        gc.collect()
        w0, c0 = time.perf_counter(), time.process_time()
        result = f()
        w1, c1 = time.perf_counter(), time.process_time()
        best_wall, best_cpu = min(best_wall, w1 - w0), min(best_cpu, c1 - c0)
    return best_wall, best_cpu, result


FORMATS = [
    ("binary STL", "stl.stl"),
    ("binary STL, shuffled", "stls.stl"),
    ("ASCII STL", "stla.stl"),
    ("OBJ", "obj.obj"),
    ("ASCII PLY", "ply.ply"),
    ("binary PLY", "plyb.ply"),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dir", default="/tmp/kreisel_e2e", type=pathlib.Path)
    parser.add_argument("--size", default="1e06", help="the size in the file names (torus_SIZE_*)")
    parser.add_argument("--repeat", default=2, type=int)
    parser.add_argument("--density", default=2700.0, type=float)
    args = parser.parse_args()

    import kreisel
    import trimesh

    print(f"kreisel {kreisel.__version__}, trimesh {trimesh.__version__}, numpy {np.__version__}, "
          f"python {sys.version.split()[0]}; best of {args.repeat}; density {args.density}")  # fmt: skip
    print()
    print("| input | triangles | kreisel wall s | kreisel CPU s | trimesh wall s | trimesh CPU s "
          "| wall trimesh/kreisel | CPU trimesh/kreisel | mass rel. diff. |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|---|")
    rho = args.density
    for name, suffix in FORMATS:
        path = args.dir / f"torus_{args.size}_{suffix}"
        if not path.exists():
            print(f"| {name} | (missing: {path}) |")
            continue
        kw, kc, k = timed(lambda: kreisel.mass_properties(path, density=rho), args.repeat)

        def with_trimesh():
            mesh = trimesh.load(str(path), force="mesh")
            mesh.density = rho
            return mesh, mesh.mass_properties

        tw, tc, (mesh, t) = timed(with_trimesh, args.repeat)
        diff = abs(k["mass"] - t["mass"]) / abs(k["mass"])
        print(f"| {name}, file | {k['triangles']:,} | {kw:.3f} | {kc:.3f} | {tw:.3f} | {tc:.3f} "
              f"| {tw / kw:.1f} | {tc / kc:.1f} | {diff:.1e} |")  # fmt: skip
        if suffix in ("stl.stl", "obj.obj"):
            v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
            aw, ac, a = timed(lambda: kreisel.mass_properties_from_arrays(v, f, density=rho), args.repeat)

            def trimesh_only():
                fresh = trimesh.Trimesh(vertices=v, faces=f, process=False)
                fresh.density = rho
                return fresh.mass_properties

            ow, oc, o = timed(trimesh_only, args.repeat)
            diff = abs(a["mass"] - o["mass"]) / abs(a["mass"])
            print(f"| {name}, arrays (no load) | {a['triangles']:,} | {aw:.3f} | {ac:.3f} | {ow:.3f} "
                  f"| {oc:.3f} | {ow / aw:.1f} | {oc / ac:.1f} | {diff:.1e} |")  # fmt: skip
        del mesh
        sys.stdout.flush()


if __name__ == "__main__":
    main()
