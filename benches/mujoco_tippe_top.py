#!/usr/bin/env python3
"""The tippe top in MuJoCo under several solver settings, side by side with
kreisel's converged answer (BENCHMARKS.md, "Tops on a table (issue #17)").

    python3 -m venv /tmp/mjt && /tmp/mjt/bin/pip install mujoco numpy
    cargo build --release --example tippe_top_timing
    /tmp/mjt/bin/python benches/mujoco_tippe_top.py            # markdown tables
    /tmp/mjt/bin/python benches/mujoco_tippe_top.py --quick    # fewer settings

Two tops:

* Leine & Glocker's (Eur. J. Mech. A/Solids 22 (2003) 193), the one
  crates/dynamics/tests/contact_sphere.rs checks kreisel on: one sphere geom R = 15 mm whose
  centre is a = 3 mm from the centre of mass towards the stem, mass and
  inertia given explicitly (<inertial>, m = 6 g, I1 = 8e-7, I3 = 7e-7 kg m^2),
  a free joint, sliding friction mu = 0.3 on both geoms (MuJoCo combines
  them by max; condim 3, so no torsional or rolling friction), tilted by
  0.1 rad about x, spinning at 180 rad/s about its axis, centre of mass at
  rest, the ball touching z = 0.
* MuJoCo's own tutorial tippe top (the tutorial notebook's MJCF, reproduced
  below as test data: a 2 cm ball, a stem, an invisible ballast box, default
  friction 1), started from its "spinning" keyframe.

For each setting: the first time the symmetry axis passes the horizontal
going down (linear interpolation between steps; "never" within 15 s), the
tilt theta of the axis and E/E0 at 15 s, Jellett's lambda at 15 s over its
start value (conserved by the exact dynamics for any force at the contact
point), and the wall time: of the C stepping alone (one mj_step call with
nstep = the steps to the answer, or to 15 s), measured in a second run from
the same start. kreisel's rows come from its release example
(`--kreisel-bin`), run in the same session.
"""

import argparse
import math
import subprocess
import sys
import time

import mujoco
import numpy as np

DURATION = 15.0

LEINE_GLOCKER = """
<mujoco model="Leine-Glocker tippe top">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 .01" friction="0.3 0 0"/>
    <body name="top">
      <freejoint/>
      <inertial pos="0 0 0" mass="0.006" diaginertia="8e-7 8e-7 7e-7"/>
      <geom name="ball" type="sphere" size="0.015" pos="0 0 0.003" friction="0.3 0 0"/>
    </body>
  </worldbody>
</mujoco>
"""

# MuJoCo's tutorial notebook (google-deepmind/mujoco, python/tutorial.ipynb),
# "tippe top" (test data); its texture, material, light and camera left out.
TUTORIAL = """
<mujoco model="tippe top">
  <option integrator="RK4"/>
  <worldbody>
    <geom size=".2 .2 .01" type="plane"/>
    <body name="top" pos="0 0 .02">
      <freejoint/>
      <geom name="ball" type="sphere" size=".02" />
      <geom name="stem" type="cylinder" pos="0 0 .02" size="0.004 .008"/>
      <geom name="ballast" type="box" size=".023 .023 0.005"  pos="0 0 -.015"
       contype="0" conaffinity="0" group="3"/>
    </body>
  </worldbody>
  <keyframe>
    <key name="spinning" qpos="0 0 0.02 1 0 0 0" qvel="0 0 0 0 1 200" />
  </keyframe>
</mujoco>
"""

INTEGRATORS = {
    "Euler": mujoco.mjtIntegrator.mjINT_EULER,
    "RK4": mujoco.mjtIntegrator.mjINT_RK4,
    "implicitfast": mujoco.mjtIntegrator.mjINT_IMPLICITFAST,
}
CONES = {
    "pyramidal": mujoco.mjtCone.mjCONE_PYRAMIDAL,
    "elliptic": mujoco.mjtCone.mjCONE_ELLIPTIC,
}


def setting(dt, integrator="RK4", cone="pyramidal", impratio=1.0, noslip=0, solref=None):
    return dict(dt=dt, integrator=integrator, cone=cone, impratio=impratio,
                noslip=noslip, solref=solref)


def describe(s):
    text = f"{s['integrator']}, dt {s['dt']:g}, {s['cone']}, impratio {s['impratio']:g}"
    if s["noslip"]:
        text += f", noslip {s['noslip']}"
    if s["solref"]:
        text += f", solref {s['solref'][0]:g} {s['solref'][1]:g}"
    return text


def build(xml, s):
    model = mujoco.MjModel.from_xml_string(xml)
    model.opt.timestep = s["dt"]
    model.opt.integrator = INTEGRATORS[s["integrator"]]
    model.opt.cone = CONES[s["cone"]]
    model.opt.impratio = s["impratio"]
    model.opt.noslip_iterations = s["noslip"]
    model.opt.enableflags |= mujoco.mjtEnableBit.mjENBL_ENERGY
    if s["solref"]:
        model.geom_solref[:] = s["solref"]
    return model


def start_leine_glocker(model, data):
    mujoco.mj_resetData(model, data)
    theta0, a, radius = 0.1, 0.003, 0.015
    data.qpos[:3] = [0.0, 0.0, radius - a * math.cos(theta0)]
    data.qpos[3:7] = [math.cos(theta0 / 2), math.sin(theta0 / 2), 0.0, 0.0]
    data.qvel[:] = [0.0, 0.0, 0.0, 0.0, 0.0, 180.0]  # angular: body axes
    mujoco.mj_forward(model, data)


def start_tutorial(model, data):
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)


def jellett(model, data, body, ball):
    """lambda = L_G . (R z - (ball centre - G))."""
    omega_world = data.xmat[body].reshape(3, 3) @ data.qvel[3:6]
    ri = data.ximat[body].reshape(3, 3)
    l_world = ri @ (model.body_inertia[body] * (ri.T @ omega_world))
    radius = model.geom_size[ball][0]
    return l_world @ (np.array([0.0, 0.0, radius]) - (data.geom_xpos[ball] - data.xipos[body]))


def run(xml, start, s):
    model = build(xml, s)
    data = mujoco.MjData(model)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "top")
    ball = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "ball")
    start(model, data)
    e0, lam0 = data.energy.sum(), jellett(model, data, body, ball)
    steps = int(round(DURATION / s["dt"]))
    z_prev, crossed, crossed_step, bad = data.xmat[body][8], None, None, False
    for n in range(steps):
        mujoco.mj_step(model, data)
        z = data.xmat[body][8]
        if not np.isfinite(z):
            bad = True
            break
        if crossed is None and z_prev > 0.0 >= z:
            crossed = data.time - s["dt"] * z / (z - z_prev)
            crossed_step = n + 1
        z_prev = z
    mujoco.mj_forward(model, data)
    theta = math.degrees(math.acos(max(-1.0, min(1.0, data.xmat[body][8]))))
    e_ratio = data.energy.sum() / e0
    lam_ratio = jellett(model, data, body, ball) / lam0
    # The C stepping alone, to the answer (or to 15 s), from the same start.
    n_timed = crossed_step if crossed_step else steps
    start(model, data)
    clock = time.perf_counter()
    mujoco.mj_step(model, data, nstep=n_timed)
    wall = time.perf_counter() - clock
    return dict(setting=describe(s), horizontal=crossed, theta=theta, e=e_ratio,
                lam=lam_ratio, wall=wall, steps=n_timed, bad=bad)


def kreisel_rows(binary):
    try:
        out = subprocess.run([binary, "--csv"], check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as err:
        print(f"kreisel example not run ({err}); build it with "
              "`cargo build --release --example tippe_top_timing`", file=sys.stderr)
        return [], []
    rows, notes = [], []
    for line in out.splitlines():
        if line.startswith("#"):
            notes.append(line[2:])
        elif line and not line.startswith("case,"):
            case, dt, t, wall, steps = line.split(",")
            rows.append(dict(case=case, dt=float(dt), t=None if t == "never" else float(t),
                             wall=float(wall), steps=int(steps)))
    return rows, notes


def table(title, results, reference):
    """A markdown table; `reference` = (kreisel's answer, its wall time)."""
    t_ref, wall_ref, dt_ref = reference if reference else (None, None, None)
    print(f"\n### {title}\n")
    print("| MuJoCo setting | axis horizontal at (s) | θ at 15 s (°) | E/E₀ at 15 s "
          "| λ/λ₀ at 15 s | wall to answer (s) | steps | wall / kreisel's |")
    print("|---|---|---|---|---|---|---|---|")
    for r in results:
        t = "never" if r["horizontal"] is None else f"{r['horizontal']:.3f}"
        if r["bad"]:
            t += " (diverged)"
        ratio = f"{r['wall'] / wall_ref:.1f}" if wall_ref else "–"
        print(f"| {r['setting']} | {t} | {r['theta']:.1f} | {r['e']:.3f} | {r['lam']:.4f} "
              f"| {r['wall']:.3f} | {r['steps']} | {ratio} |")
    if t_ref is not None:
        print(f"\nkreisel's converged answer (within 1e-6 relative of its finest step from "
              f"dt = {dt_ref:g} s): {t_ref:.6f} s in {wall_ref:.3f} s wall.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kreisel-bin", default="target/release/examples/tippe_top_timing")
    parser.add_argument("--quick", action="store_true", help="fewer MuJoCo settings")
    args = parser.parse_args()
    print(f"MuJoCo {mujoco.__version__}, numpy {np.__version__}")

    rows, notes = kreisel_rows(args.kreisel_bin)
    if rows:
        print("\n### kreisel (fixed-step RK4, regularised Coulomb / viscous)\n")
        print("| case | dt (s) | axis horizontal at (s) | wall to answer (s) | steps |")
        print("|---|---|---|---|---|")
        for r in rows:
            t = "never" if r["t"] is None else f"{r['t']:.9f}"
            print(f"| {r['case']} | {r['dt']:g} | {t} | {r['wall']:.3f} | {r['steps']} |")
        print()
        for n in notes:
            print(f"- {n}")

    def reference(case):
        """kreisel's answer and wall time at the largest step whose answer is
        within 1e-6 relative of the finest step's (the converged answer)."""
        runs = [r for r in rows if r["case"] == case]
        if not runs or any(r["t"] is None for r in runs):
            return None
        finest = min(runs, key=lambda r: r["dt"])["t"]
        ok = [r for r in runs if abs(r["t"] - finest) <= 1e-6 * finest]
        best = max(ok, key=lambda r: r["dt"])
        return best["t"], best["wall"], best["dt"]

    model = mujoco.MjModel.from_xml_string(TUTORIAL)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "top")
    print(f"\nMuJoCo's tutorial top as compiled: m = {model.body_mass[body]:.9e} kg, "
          f"centre of mass {model.body_ipos[body]} m from the ball's centre, "
          f"principal inertia {model.body_inertia[body]} kg m², iquat {model.body_iquat[body]}")

    lg = [
        setting(2e-3, "Euler"),
        setting(2e-3, "RK4"),
        setting(1e-3, "RK4", "pyramidal", 1),
        setting(1e-3, "RK4", "elliptic", 1),
        setting(1e-3, "RK4", "pyramidal", 10),
        setting(1e-3, "RK4", "elliptic", 10),
        setting(1e-3, "RK4", "pyramidal", 100),
        setting(1e-3, "RK4", "elliptic", 100),
        setting(1e-3, "RK4", "pyramidal", 1, noslip=10),
        setting(1e-3, "RK4", "elliptic", 1, noslip=10),
        setting(1e-4, "RK4", "pyramidal", 1),
        setting(1e-4, "RK4", "elliptic", 1),
        setting(1e-4, "RK4", "pyramidal", 100),
        setting(1e-4, "RK4", "elliptic", 100),
        setting(1e-4, "RK4", "elliptic", 1, solref=(0.002, 1.0)),
        setting(1e-4, "implicitfast", "elliptic", 1),
    ]
    tutorial = [
        setting(2e-3, "RK4", "pyramidal", 1),
        setting(2e-3, "RK4", "elliptic", 1),
        setting(2e-3, "RK4", "pyramidal", 100),
        setting(2e-3, "RK4", "elliptic", 100),
        setting(1e-4, "RK4", "pyramidal", 1),
        setting(1e-4, "RK4", "elliptic", 1),
    ]
    if args.quick:
        lg = lg[:4]
        tutorial = tutorial[:3]
    table("Leine & Glocker's top in MuJoCo (μ = 0.3); kreisel: sliding, ε = 1 mm/s",
          [run(LEINE_GLOCKER, start_leine_glocker, s) for s in lg],
          reference("lg-sliding-eps1mm"))
    table("MuJoCo's tutorial top (μ = 1); kreisel: the ball only, sliding, ε = 1 mm/s",
          [run(TUTORIAL, start_tutorial, s) for s in tutorial],
          reference("tutorial-sliding-eps1mm"))


if __name__ == "__main__":
    main()
