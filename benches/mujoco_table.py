#!/usr/bin/env python3
"""Bodies on a table in MuJoCo (issue #26's peer side): the tippe top with its
stem, a ball dropped with restitution, a spinning superball and Euler's disk,
each under MuJoCo's defaults and a few solver settings, with the answer the
rigid nonsmooth model gives where one is known in closed form.

    python3 -m venv /tmp/mjt && /tmp/mjt/bin/pip install mujoco numpy
    /tmp/mjt/bin/python benches/mujoco_table.py                  # markdown tables
    /tmp/mjt/bin/python benches/mujoco_table.py --quick          # fewer settings
    /tmp/mjt/bin/python benches/mujoco_table.py --json out.json  # and the rows as JSON

(MuJoCo's and numpy's versions are printed at the top of the output.)

Scenes (SI units, gravity 9.81 m/s^2, MuJoCo's value):

1. Leine & Glocker's tippe top with its stem (Eur. J. Mech. A/Solids 22
   (2003) 193): m = 6 g, I1 = I2 = 8e-7, I3 = 7e-7 kg m^2 about the centre of
   mass G; a sphere R1 = 15 mm whose centre is a1 = 3 mm from G towards the
   stem (G below the ball's centre when the stem points up); a stem sphere
   R2 = 5 mm whose centre is a2 = 16 mm from G towards the stem; mu = 0.3,
   e = 0 (MuJoCo's default solref is critically damped: no bounce); the
   geometry is that of tests/data/gen/tippe_top_stem_reference.py (the
   cardillo reference, branch refs). Coulomb-Contensou friction over a
   contact disc of radius r = 0.5 mm in Moeller, Leine & Glocker's
   ellipsoidal approximation, F_t1^2 + F_t2^2 + (T_n / Rbar)^2 <= (mu N)^2
   with Rbar = (3 pi / 16) r (Hertzian pressure; uniform would give 2/3 r),
   is MuJoCo's elliptic cone (f_t / mu)^2 + (tau / mu_tor)^2 <= N^2 with the
   torsional coefficient mu_tor = mu Rbar = 8.84e-5 m, used where condim >= 4
   (with the pyramidal cone MuJoCo linearises that set); condim 6 adds
   rolling friction, set to MuJoCo's smallest coefficient (1e-5 m).
   Start: axis tilted 0.1 rad about x, the ball touching the table, spinning
   180 rad/s about the axis, G at rest. Measured: the time the axis first
   passes the horizontal, the time the stem sphere first touches (its lowest
   point crosses z = 0; interpolated between steps), the largest tilt, the
   time spent with the stem alone in contact and when it last left it,
   which spheres are in contact at 8 s, the tilt and spin there, the
   energy's largest rise in one step and over its running minimum
   (MuJoCo's kinetic + gravitational energy; a rigid model with
   dissipative contacts never gains any), E(8 s)/E0. When cardillo's
   rigid reference (tests/data/contact/tippe_top_stem_reference.json,
   --reference) is there, its runs head the table.
2. A ball (R = 0.1 m) dropped from rest with its centre at 1 m, target
   restitution e = 0.9. MuJoCo has no restitution coefficient; its
   documented way (modeling guide, "Restitution") is solref's direct form
   (-stiffness, -damping), damping 0 for e = 1. For e < 1 the linear
   spring-damper's relation e = exp(-pi zeta / sqrt(1 - zeta^2)) gives
   zeta = -ln e / sqrt(pi^2 + ln^2 e) = 0.0335, used as damping
   2 zeta sqrt(k) in the direct form or as dampratio in the (timeconst,
   dampratio) form (MuJoCo's impedance d(r) in 0.9..0.95 makes the
   effective spring d k, so this is the mapping, not an identity); a last
   row tunes the damping by bisection until the first bounce gives 0.9.
   Exact rigid answers: first impact at t1 = sqrt(2 (1 - R) / g) = 0.42835 s,
   apex ratio e^2 = 0.81, rest at the Zeno time t1 (1 + 2e/(1 - e)) =
   8.1387 s (the literature's rounding: 8.1384 s). Measured: first impact,
   the first apex ratio and the mean of the first five, the bounce count
   before 12 s and the rest time (the last touchdown after which the ball
   never leaves the table again before 12 s).
3. A superball, solid sphere R = 0.03 m, m = 0.05 kg (I = 2/5 m R^2), centre
   at z = 0.5 m, thrown with (vx, vz) = (2, -3) m/s and spin wy = 20 rad/s;
   mu = 0.5 (chosen here; the issue gives none) and normal restitution 0.9
   mapped as in scene 2. Reported: vx and wy after each of the first three
   bounces (read at lift-off). MuJoCo has no tangential restitution; the
   rigid references beside it are Newton (e = 0.9) with the tangential
   impulse that reverses the contact point's slip times e_t, inside
   Coulomb's cone (mu = 0.5): e_t = 0 (slip stopped), e_t = 0.8 and e_t = 1
   (Garwin's superball, Am. J. Phys. 37 (1969) 88). While the cone holds
   the tangential map does not depend on vz: the e_t = 0.8 and 1 rows are
   tests/data/contact/superball.csv's (branch refs) first three impacts.
   One MuJoCo row gives the frictional dimensions their own, stiffer
   solref through an explicit contact pair (solreffriction, elliptic cone).
4. Euler's disk: radius 0.0375 m, thickness 0.006 m, mass 0.4 kg, mu = 0.3,
   a MuJoCo cylinder (torsional friction as in scene 1 where condim >= 4,
   though the rim's contact is no disc); started at a tilt of 30 deg in the steady rolling
   motion with its centre at rest (the precession rate from the balance
   I w' = r_P x m g z for the rim point, 46.7 rad/s here; 4 g / (a sin alpha)
   for a thin disk, Moffatt, Nature 404 (2000) 833). Measured: the time the
   tilt first falls below 0.5 deg (the "rest" time; runs stop there or at
   300 s for dt < 1 ms, 600 s otherwise), the tilt at half way, and the
   exponent n of alpha = A (t0 - t)^n fitted, t0 free, over the last two
   decades of t0 - t before the tilt reaches 1 deg (Moffatt: 1/3), if the
   run gets there; the state at the run's end, the centre's drift in the
   first second (0 in the steady motion) and the deepest penetration.

Wall time: the C stepping alone (one mj_step call with nstep = the run's
steps), measured in a second run from the same start (the least of up to
three when they are short); the first run, step by step from Python,
measures the answers.
"""

import argparse
import json
import math
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from mujoco_tippe_top import CONES, INTEGRATORS  # noqa: E402

G = 9.81
MIN_MU = 1e-5  # MuJoCo's smallest friction coefficient (mjMINMU)


def contensou_rbar(radius):
    """Moeller, Leine & Glocker's drilling lever arm for a Hertzian contact disc."""
    return 3.0 * math.pi / 16.0 * radius


def zeta_for(e):
    """Damping ratio of the linear spring-damper whose bounce has restitution e."""
    return -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)


def setting(dt=2e-3, integrator="Euler", cone="pyramidal", condim=3, impratio=1.0,
            solref=None, solimp=None, noslip=0, note="", solreffriction=None):
    """One MuJoCo configuration; None keeps MuJoCo's default. solreffriction
    (spheres only) makes an explicit contact pair with that solref for the
    frictional dimensions (MuJoCo applies it with the elliptic cone)."""
    return dict(dt=dt, integrator=integrator, cone=cone, condim=condim, impratio=impratio,
                solref=solref, solimp=solimp, noslip=noslip, note=note,
                solreffriction=solreffriction)


DEFAULT = setting(note="MuJoCo defaults")


def describe(s):
    if s["note"] == "MuJoCo defaults":
        return "defaults (Euler, dt 0.002, pyramidal, condim 3)"
    text = f"{s['integrator']}, dt {s['dt']:g}, {s['cone']}, condim {s['condim']}"
    if s["impratio"] != 1.0:
        text += f", impratio {s['impratio']:g}"
    if s["noslip"]:
        text += f", noslip {s['noslip']}"
    if s["solref"]:
        text += f", solref {s['solref'][0]:.4g} {s['solref'][1]:.4g}"
    if s["solimp"]:
        text += ", solimp " + " ".join(f"{v:g}" for v in s["solimp"])
    if s["solreffriction"]:
        text += ", solreffriction " + " ".join(f"{v:g}" for v in s["solreffriction"])
    if s["note"]:
        text += f" ({s['note']})"
    return text


def contact_attrs(s, friction):
    """The geom attributes of every geom (MuJoCo mixes two geoms' values: max
    for condim and friction, the solmix-weighted mean for solref and solimp,
    so equal values on both geoms are the pair's)."""
    text = f'friction="{friction[0]:g} {friction[1]:g} {friction[2]:g}" condim="{s["condim"]}"'
    if s["solref"]:
        text += f' solref="{s["solref"][0]:.10g} {s["solref"][1]:.10g}"'
    if s["solimp"]:
        text += ' solimp="' + " ".join(f"{v:g}" for v in s["solimp"]) + '"'
    return text


def build(xml, s):
    model = mujoco.MjModel.from_xml_string(xml)
    model.opt.timestep = s["dt"]
    model.opt.integrator = INTEGRATORS[s["integrator"]]
    model.opt.cone = CONES[s["cone"]]
    model.opt.impratio = s["impratio"]
    model.opt.noslip_iterations = s["noslip"]
    model.opt.enableflags |= mujoco.mjtEnableBit.mjENBL_ENERGY
    return model


def c_wall(model, data, start, steps):
    """Wall time of the C stepping alone: `steps` steps in one mj_step call,
    the least of up to three runs while they take under a second each (the
    machine is shared)."""
    best = math.inf
    for _ in range(3):
        start(model, data)
        clock = time.perf_counter()
        mujoco.mj_step(model, data, nstep=steps)
        best = min(best, time.perf_counter() - clock)
        if best > 1.0:
            break
    return best


def crossing(t, dt, prev, now):
    """Time at which a quantity going from prev > 0 to now <= 0 passed 0."""
    return t - dt * now / (now - prev)


def omega_world(data, body):
    return data.xmat[body].reshape(3, 3) @ data.qvel[3:6]


def sci(x):
    return "–" if x is None else f"{x:.2e}"


def fmt(x, digits=4, none="never"):
    if x is None:
        return none
    if isinstance(x, str):
        return x
    return f"{x:.{digits}f}"


# --------------------------------------------------------------------------
# 1. The tippe top with its stem
# --------------------------------------------------------------------------

TOP = dict(m=0.006, i1=8e-7, i3=7e-7, r1=0.015, a1=0.003, r2=0.005, a2=0.016, mu=0.3,
           contensou_radius=5e-4, theta0=0.1, spin=180.0, duration=8.0)


def top_xml(s):
    tor = TOP["mu"] * contensou_rbar(TOP["contensou_radius"])
    attrs = contact_attrs(s, (TOP["mu"], tor, MIN_MU))
    return f"""
<mujoco model="Leine-Glocker tippe top with stem">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 .01" {attrs}/>
    <body name="top">
      <freejoint/>
      <inertial pos="0 0 0" mass="{TOP['m']}" diaginertia="{TOP['i1']} {TOP['i1']} {TOP['i3']}"/>
      <geom name="ball" type="sphere" size="{TOP['r1']}" pos="0 0 {TOP['a1']}" {attrs}/>
      <geom name="stem" type="sphere" size="{TOP['r2']}" pos="0 0 {TOP['a2']}" {attrs}/>
    </body>
  </worldbody>
</mujoco>
"""


def top_start(model, data):
    mujoco.mj_resetData(model, data)
    th = TOP["theta0"]
    data.qpos[:3] = [0.0, 0.0, TOP["r1"] - TOP["a1"] * math.cos(th)]
    data.qpos[3:7] = [math.cos(th / 2), math.sin(th / 2), 0.0, 0.0]
    data.qvel[:] = [0.0, 0.0, 0.0, 0.0, 0.0, TOP["spin"]]  # angular: body axes
    mujoco.mj_forward(model, data)


def touching(model, data, geom):
    """Whether an active contact (penetration) involves the geom."""
    for c in data.contact[: data.ncon]:
        if geom in (c.geom1, c.geom2) and c.dist < 0.0:
            return True
    return False


def run_top(s):
    model = build(top_xml(s), s)
    data = mujoco.MjData(model)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "top")
    ball = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "ball")
    stem = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "stem")
    top_start(model, data)
    e0 = data.energy.sum()
    e_min, e_prev, rise, step_rise = e0, e0, 0.0, 0.0
    steps = int(round(TOP["duration"] / s["dt"]))
    z_prev = data.xmat[body][8]
    gap_prev = data.geom_xpos[stem][2] - TOP["r2"]
    horizontal = stem_touch = left_stem = None
    bad, was_stem_only, on_stem_time, theta_max = False, False, 0.0, 0.0
    for _ in range(steps):
        mujoco.mj_step(model, data)
        z = data.xmat[body][8]
        if not np.isfinite(z):
            bad = True
            break
        gap = data.geom_xpos[stem][2] - TOP["r2"]
        if horizontal is None and z_prev > 0.0 >= z:
            horizontal = crossing(data.time, s["dt"], z_prev, z)
        if stem_touch is None and gap_prev > 0.0 >= gap:
            stem_touch = crossing(data.time, s["dt"], gap_prev, gap)
        z_prev, gap_prev = z, gap
        # Contacts of the state this step started from (mj_step's collision).
        stem_only = touching(model, data, stem) and not touching(model, data, ball)
        if stem_only:
            on_stem_time += s["dt"]
        elif was_stem_only:
            left_stem = data.time - s["dt"]
        was_stem_only = stem_only
        theta_max = max(theta_max, math.degrees(math.acos(max(-1.0, min(1.0, z)))))
        # data.energy is the energy of the state before this step's update.
        e = data.energy.sum()
        step_rise = max(step_rise, e - e_prev)
        e_min, e_prev = min(e_min, e), e
        rise = max(rise, e - e_min)
    mujoco.mj_forward(model, data)
    on_ball, on_stem = touching(model, data, ball), touching(model, data, stem)
    ends = {(False, True): "stem only", (True, False): "ball only",
            (True, True): "ball and stem", (False, False): "none"}[(on_ball, on_stem)]
    theta = math.degrees(math.acos(max(-1.0, min(1.0, data.xmat[body][8]))))
    axis = data.xmat[body].reshape(3, 3)[:, 2]
    spin = float(omega_world(data, body) @ axis)
    return dict(setting=describe(s), horizontal=horizontal, stem_touch=stem_touch,
                contact_at_end=ends, on_stem=(ends == "stem only" and theta > 90.0),
                theta_end_deg=theta, theta_max_deg=theta_max, stem_only_seconds=on_stem_time,
                left_stem=left_stem, spin_end=spin, energy_rise_over_e0=rise / e0,
                energy_step_rise_over_e0=step_rise / e0,
                e_end_over_e0=data.energy.sum() / e0, diverged=bad, steps=steps,
                wall=c_wall(model, data, top_start, steps))


def reference_rows(path):
    """The cardillo reference's runs (tests/data/gen/tippe_top_stem_reference.py)
    as rows of the tippe-top table, or [] when its JSON is not there."""
    try:
        doc = json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return []
    rows = []
    for run in doc.get("runs", []):
        end = run.get("end", {})
        ball, stem = run.get("ball_contact_at_end"), run.get("stem_contact_at_end")
        e0 = run.get("energy_start")
        rows.append(dict(
            setting=f"cardillo {run.get('solver')}, dt {run.get('dt'):g} (rigid reference)",
            horizontal=run.get("t_axis_horizontal"),
            stem_touch=run.get("t_stem_gap_first_nonpositive", run.get("t_stem_first_touch")),
            theta_max_deg=run.get("theta_deg_max"), stem_only_seconds=None, left_stem=None,
            contact_at_end={(False, True): "stem only", (True, False): "ball only",
                            (True, True): "ball and stem",
                            (False, False): "none"}.get((ball, stem), "?"),
            theta_end_deg=end.get("theta_deg"),
            spin_end=(end.get("omega_body") or [None] * 3)[2],
            energy_rise_over_e0=None,
            energy_step_rise_over_e0=(run["energy_max_rise"] / e0
                                      if e0 and "energy_max_rise" in run else None),
            e_end_over_e0=end["energy"] / e0 if e0 and "energy" in end else None,
            diverged=False, wall=run.get("wall_seconds")))
    return rows


def top_table(rows):
    print("\n### 1. Leine & Glocker's tippe top with its stem (μ = 0.3, Contensou r = 0.5 mm "
          "as torsional μ·3π/16·r = 8.84e-5 m where condim ≥ 4, e = 0), 8 s\n")
    print("| setting | axis horizontal at (s) | stem touches at (s) | θ max (°) "
          "| on the stem only (s in total) | last left the stem at (s) | in contact at 8 s "
          "| θ at 8 s (°) | spin at 8 s (rad/s) | energy rise in one step / E₀ "
          "| energy rise over its running min / E₀ | E(8 s)/E₀ | wall, 8 s (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        end = r["contact_at_end"] + (" (diverged)" if r["diverged"] else "")
        print(f"| {r['setting']} | {fmt(r['horizontal'])} | {fmt(r['stem_touch'])} "
              f"| {fmt(r['theta_max_deg'], 1, '–')} | {fmt(r['stem_only_seconds'], 2, '–')} "
              f"| {fmt(r['left_stem'], 3, '–')} | {end} "
              f"| {fmt(r['theta_end_deg'], 1, '–')} | {fmt(r['spin_end'], 1, '–')} "
              f"| {sci(r['energy_step_rise_over_e0'])} | {sci(r['energy_rise_over_e0'])} "
              f"| {fmt(r['e_end_over_e0'], 4, '–')} "
              f"| {fmt(r['wall'], 3, '–')} |")
    if any(r["setting"].startswith("cardillo") for r in rows):
        print("\ncardillo rows: tests/data/contact/tippe_top_stem_reference.json (its "
              "energy rise is the largest increase over one step, its stem time the stem "
              "sphere's gap reaching 0; its wall time is Python's).")


# --------------------------------------------------------------------------
# 2. The ball dropped with restitution, and 3. the superball
# --------------------------------------------------------------------------

DROP = dict(radius=0.1, z0=1.0, e=0.9, duration=12.0)


def zeno():
    t1 = math.sqrt(2.0 * (DROP["z0"] - DROP["radius"]) / G)
    e = DROP["e"]
    return t1, t1 * (1.0 + 2.0 * e / (1.0 - e))


def direct(k, e=0.9):
    """solref's direct form for a spring k (1/s^2) and the damping of restitution e."""
    return (-k, -2.0 * zeta_for(e) * math.sqrt(k))


def sphere_xml(s, radius, mass, mu):
    attrs = contact_attrs(s, (mu, 0.005, 0.0001))  # MuJoCo's default torsional, rolling
    inertia = 0.4 * mass * radius ** 2
    pair = ""
    if s["solreffriction"]:
        # A pair replaces the geoms' mixing: everything is given again.
        ref = s["solref"] or (0.02, 1.0)
        imp = s["solimp"] or (0.9, 0.95, 0.001, 0.5, 2.0)
        pair = (f'<contact><pair geom1="floor" geom2="ball" condim="{s["condim"]}" '
                f'friction="{mu:g} {mu:g} 0.005 0.0001 0.0001" '
                f'solref="{ref[0]:.10g} {ref[1]:.10g}" '
                f'solimp="{" ".join(f"{v:g}" for v in imp)}" '
                f'solreffriction="{s["solreffriction"][0]:g} {s["solreffriction"][1]:g}"/>'
                "</contact>")
    return f"""
<mujoco model="sphere on a table">
  <worldbody>
    <geom name="floor" type="plane" size="5 5 .01" {attrs}/>
    <body name="ball">
      <freejoint/>
      <inertial pos="0 0 0" mass="{mass}" diaginertia="{inertia} {inertia} {inertia}"/>
      <geom name="ball" type="sphere" size="{radius}" {attrs}/>
    </body>
  </worldbody>
  {pair}
</mujoco>
"""


def drop_start(model, data):
    mujoco.mj_resetData(model, data)
    data.qpos[:3] = [0.0, 0.0, DROP["z0"]]
    mujoco.mj_forward(model, data)


def bounces(model, data, start, radius, duration, on_liftoff=None):
    """Steps a sphere; returns its touchdown and lift-off times (interpolated
    where its lowest point crosses z = 0), its apex heights (of the lowest
    point, from the ballistic vz at the step where vz turns negative in
    flight) and whether it diverged. on_liftoff(data) is called at each
    lift-off's step."""
    start(model, data)
    dt = model.opt.timestep
    steps = int(round(duration / dt))
    gap_prev, vz_prev = data.qpos[2] - radius, data.qvel[2]
    downs, ups, apexes = [], [], []
    for _ in range(steps):
        mujoco.mj_step(model, data)
        gap, vz = data.qpos[2] - radius, data.qvel[2]
        if not np.isfinite(gap):
            return downs, ups, apexes, True, steps
        if gap_prev > 0.0 >= gap:
            downs.append(crossing(data.time, dt, gap_prev, gap))
        elif gap_prev <= 0.0 < gap:
            ups.append(crossing(data.time, dt, -gap_prev, -gap))
            if on_liftoff:
                on_liftoff(data)
        if gap > 0.0 and vz_prev > 0.0 >= vz and ups:
            apexes.append(gap + vz * vz / (2.0 * G))
        gap_prev, vz_prev = gap, vz
    return downs, ups, apexes, False, steps


def run_drop(s):
    model = build(sphere_xml(s, DROP["radius"], 1.0, 1.0), s)
    data = mujoco.MjData(model)
    downs, ups, apexes, bad, steps = bounces(model, data, drop_start, DROP["radius"],
                                             DROP["duration"])
    h0 = DROP["z0"] - DROP["radius"]
    heights = [h0] + apexes
    ratios = [b / a for a, b in zip(heights, heights[1:])]
    # At rest: the last touchdown, if the ball never left the table after it,
    # touched down at least 0.1 s before the end and has stopped (|vz| < 1 mm/s).
    settled = (downs and (not ups or ups[-1] < downs[-1])
               and downs[-1] < DROP["duration"] - 0.1 and abs(data.qvel[2]) < 1e-3)
    rest = downs[-1] if settled else None
    return dict(setting=describe(s), first_impact=downs[0] if downs else None,
                first_ratio=ratios[0] if ratios else None,
                mean_ratio_5=float(np.mean(ratios[:5])) if ratios else None,
                bounces=len(ups), rest=rest, diverged=bad, steps=steps,
                wall=c_wall(model, data, drop_start, steps))


def tune_drop_damping(dt, k, integrator="Euler"):
    """The direct-form damping at which the first bounce's apex ratio is e^2
    (bisection on the damping ratio; MuJoCo stepped to the first apex)."""
    target = DROP["e"] ** 2

    def first_ratio(zeta):
        s = setting(dt, integrator, solref=(-k, -2.0 * zeta * math.sqrt(k)))
        model = build(sphere_xml(s, DROP["radius"], 1.0, 1.0), s)
        data = mujoco.MjData(model)
        _, _, apexes, _, _ = bounces(model, data, drop_start, DROP["radius"], 1.4)
        return apexes[0] / (DROP["z0"] - DROP["radius"]) if apexes else 0.0

    lo, hi = 0.0, 0.5  # ratio falls as zeta grows
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        if first_ratio(mid) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def drop_table(rows):
    t1, tz = zeno()
    print(f"\n### 2. Ball dropped from 1 m (R = 0.1 m), target e = 0.9 "
          f"(exact: first impact {t1:.5f} s, apex ratio 0.81, rest at {tz:.4f} s)\n")
    print("| MuJoCo setting | first impact (s) | 1st apex ratio (√: e) | mean of first 5 "
          "| bounces < 12 s | at rest from (s) | wall, 12 s (s) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        ratio = (f"{r['first_ratio']:.4f} ({math.sqrt(r['first_ratio']):.4f})"
                 if r["first_ratio"] is not None else "no bounce")
        rest = fmt(r["rest"], 4, "not by 12 s") + (" (diverged)" if r["diverged"] else "")
        print(f"| {r['setting']} | {fmt(r['first_impact'], 5)} | {ratio} "
              f"| {fmt(r['mean_ratio_5'], 4, '–')} | {r['bounces']} | {rest} | {r['wall']:.3f} |")


SUPER = dict(radius=0.03, mass=0.05, mu=0.5, z0=0.5, vx=2.0, vz=-3.0, wy=20.0, e=0.9,
             duration=3.0, n=3)


def super_start(model, data):
    mujoco.mj_resetData(model, data)
    data.qpos[:3] = [0.0, 0.0, SUPER["z0"]]
    data.qvel[:] = [SUPER["vx"], 0.0, SUPER["vz"], 0.0, SUPER["wy"], 0.0]  # identity attitude
    mujoco.mj_forward(model, data)


def super_rigid(tangential):
    """Rigid bounces: Newton's e for the normal impulse, the tangential impulse
    that reverses the contact point's slip u = vx - R wy times `tangential`
    (0: the slip stopped; 1: Garwin's reversal), capped by Coulomb's cone
    (then sliding at mu P_n against the slip)."""
    m, r, mu, e = SUPER["mass"], SUPER["radius"], SUPER["mu"], SUPER["e"]
    inertia = 0.4 * m * r * r
    vx, wy = SUPER["vx"], SUPER["wy"]
    vz = -math.sqrt(SUPER["vz"] ** 2 + 2.0 * G * (SUPER["z0"] - r))
    out = []
    for _ in range(SUPER["n"]):
        pn = m * (1.0 + e) * -vz
        u = vx - r * wy
        pt = -(1.0 + tangential) * u / (1.0 / m + r * r / inertia)
        if abs(pt) > mu * pn:
            pt = -math.copysign(mu * pn, u)
        vx += pt / m
        wy -= r * pt / inertia
        vz = e * vz  # lands again at the same height with the same speed
        out.append((vx, wy))
    return out


def run_super(s):
    model = build(sphere_xml(s, SUPER["radius"], SUPER["mass"], SUPER["mu"]), s)
    data = mujoco.MjData(model)
    after = []

    def liftoff(d):
        after.append((float(d.qvel[0]), float(omega_world(d, 1)[1]), float(d.qvel[2])))

    downs, _, _, bad, steps = bounces(model, data, super_start, SUPER["radius"],
                                      SUPER["duration"], liftoff)
    return dict(setting=describe(s), after=after[: SUPER["n"]], diverged=bad, steps=steps,
                wall=c_wall(model, data, super_start, steps))


def super_table(rows):
    print(f"\n### 3. Superball (R = 0.03 m, m = 0.05 kg, μ = {SUPER['mu']}, e = 0.9), "
          "thrown at (vx, vz) = (2, −3) m/s, ωy = 20 rad/s, from z = 0.5 m\n")
    print("| setting | after bounce 1: vx, ωy | after bounce 2: vx, ωy "
          "| after bounce 3: vx, ωy | vz out/in, bounce 1 | wall, 3 s (s) |")
    print("|---|---|---|---|---|---|")
    vin = math.sqrt(SUPER["vz"] ** 2 + 2.0 * G * (SUPER["z0"] - SUPER["radius"]))
    for name, t in (("rigid: Newton + Coulomb, slip stopped (e_t = 0)", 0.0),
                    ("rigid: tangential restitution e_t = 0.8", 0.8),
                    ("rigid: Garwin's superball (e_t = 1)", 1.0)):
        cells = [f"{vx:.3f}, {wy:.2f}" for vx, wy in super_rigid(t)]
        print(f"| {name} | " + " | ".join(cells) + f" | {SUPER['e']:.4f} | – |")
    for r in rows:
        cells = [f"{vx:.3f}, {wy:.2f}" for vx, wy, _ in r["after"]]
        cells += ["no bounce"] * (SUPER["n"] - len(cells))
        ratio = f"{r['after'][0][2] / vin:.4f}" if r["after"] else "–"
        name = r["setting"] + (" (diverged)" if r["diverged"] else "")
        print(f"| MuJoCo {name} | " + " | ".join(cells) + f" | {ratio} | {r['wall']:.3f} |")


# --------------------------------------------------------------------------
# 4. Euler's disk
# --------------------------------------------------------------------------

DISK = dict(a=0.0375, thickness=0.006, m=0.4, mu=0.3, alpha0=math.radians(30.0),
            duration_fine=300.0, duration_coarse=600.0, rest_deg=0.5, fit_until_deg=1.0)


def disk_inertia():
    a, t, m = DISK["a"], DISK["thickness"], DISK["m"]
    return m * (3.0 * a * a + t * t) / 12.0, m * a * a / 2.0


def disk_precession():
    """Steady rolling with the centre at rest, axis n = (sin al, 0, cos al):
    the rim point r_P = a d - h n (d = (cos al, 0, -sin al)); rolling with G
    fixed needs w = -(Omega sin al / a) r_P, and I w' = Omega z x L = r_P x m g z
    gives Omega^2 = m g a r_x / (sin al (I1 r_x + (I1 - I3) h sin al))."""
    i1, i3 = disk_inertia()
    al, a, h = DISK["alpha0"], DISK["a"], DISK["thickness"] / 2.0
    rp = np.array([a * math.cos(al) - h * math.sin(al), 0.0,
                   -a * math.sin(al) - h * math.cos(al)])
    omega2 = DISK["m"] * G * a * rp[0] / (math.sin(al) * (i1 * rp[0] + (i1 - i3) * h * math.sin(al)))
    big_omega = math.sqrt(omega2)
    return big_omega, -(big_omega * math.sin(al) / a) * rp, rp


def disk_xml(s):
    tor = DISK["mu"] * contensou_rbar(5e-4)
    attrs = contact_attrs(s, (DISK["mu"], tor, MIN_MU))
    i1, i3 = disk_inertia()
    return f"""
<mujoco model="Euler's disk">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 .01" {attrs}/>
    <body name="disk">
      <freejoint/>
      <inertial pos="0 0 0" mass="{DISK['m']}" diaginertia="{i1} {i1} {i3}"/>
      <geom name="disk" type="cylinder" size="{DISK['a']} {DISK['thickness'] / 2}" {attrs}/>
    </body>
  </worldbody>
</mujoco>
"""


def disk_start(model, data):
    mujoco.mj_resetData(model, data)
    al = DISK["alpha0"]
    _, w_world, rp = disk_precession()
    data.qpos[:3] = [0.0, 0.0, -rp[2]]
    data.qpos[3:7] = [math.cos(al / 2), 0.0, math.sin(al / 2), 0.0]
    rot = np.empty(9)
    mujoco.mju_quat2Mat(rot, data.qpos[3:7])
    data.qvel[:3] = 0.0
    data.qvel[3:6] = rot.reshape(3, 3).T @ w_world  # free joint: body axes
    mujoco.mj_forward(model, data)


def finite_time_fit(ts, alphas, t_rest):
    """alpha = A (t0 - t)^n fitted over two decades of t0 - t ending where the
    tilt first falls below fit_until_deg (later the soft contact's own
    length scale shows), t0 free but not before the rest time (the tilt is
    still positive there): the t0 whose least-squares line in
    (log(t0 - t), log alpha) leaves the smallest residual. Returns (n, t0,
    window, rms of the log residual) or Nones when the run does not cover
    two decades."""
    below = alphas < math.radians(DISK["fit_until_deg"])
    if not below.any():
        return None, None, None, None
    t_end = ts[int(np.argmax(below))]
    first = max(ts[1] - ts[0], t_rest - t_end)
    best = None
    for lag in np.geomspace(first, max(2.0, 2.0 * first), 400):  # t0 - t_end
        t0 = t_end + lag
        sel = (ts <= t_end) & (t0 - ts <= 100.0 * lag)
        if ts[0] > t0 - 100.0 * lag or sel.sum() < 20:
            continue
        x, y = np.log(t0 - ts[sel]), np.log(alphas[sel])
        coef, res, *_ = np.polyfit(x, y, 1, full=True)
        rms = math.sqrt(res[0] / sel.sum()) if len(res) else 0.0
        if best is None or rms < best[0]:
            best = (rms, float(coef[0]), float(t0), (float(lag), float(100.0 * lag)))
    return (best[1], best[2], best[3], best[0]) if best else (None, None, None, None)


def disk_duration(s):
    """The longest run: 300 s at dt < 1 ms, 600 s at coarser steps."""
    return DISK["duration_fine"] if s["dt"] < 1e-3 else DISK["duration_coarse"]


def run_disk(s):
    model = build(disk_xml(s), s)
    data = mujoco.MjData(model)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "disk")
    disk_start(model, data)
    dt = s["dt"]
    e0 = data.energy.sum()
    steps = int(round(disk_duration(s) / dt))
    rest_cos = math.cos(math.radians(DISK["rest_deg"]))
    ts, alphas = [0.0], [DISK["alpha0"]]
    t0, bad, drift, depth = None, False, 0.0, 0.0
    n = 0
    while n < steps:
        mujoco.mj_step(model, data)
        n += 1
        c = data.xmat[body][8]
        if not np.isfinite(c):
            bad = True
            break
        ts.append(data.time)
        alphas.append(math.acos(max(-1.0, min(1.0, abs(c)))))
        if data.time < 1.0:
            drift = max(drift, math.hypot(data.qpos[0], data.qpos[1]))
        if data.ncon:
            depth = max(depth, -float(data.contact.dist.min()))
        if abs(c) >= rest_cos:
            t0 = data.time
            break
    ts, alphas = np.array(ts), np.array(alphas)
    exponent, t_zero, window, rms = (finite_time_fit(ts, alphas, t0) if t0
                                     else (None, None, None, None))
    # The tilt one, two and three decades of time before the rest time
    # (Moffatt's law: a factor 10^(1/3) = 2.15 per decade).
    before = ({f"{lag:g}": float(np.degrees(alphas[np.searchsorted(ts, t0 - lag)]))
               for lag in (1.0, 0.1, 0.01)} if t0 and t0 > 1.0 else None)
    half = float(np.degrees(alphas[np.searchsorted(ts, 0.5 * t0)])) if t0 else None
    return dict(setting=describe(s), rest=t0, alpha_half_deg=half, exponent=exponent,
                fitted_t0=t_zero, fit_window=window, fit_rms=rms, alpha_before_rest_deg=before,
                t_end=float(ts[-1]),
                alpha_end_deg=float(np.degrees(alphas[-1])), centre_drift_first_s=drift, max_depth=depth,
                energy_end_over_e0=float(data.energy.sum() / e0),
                diverged=bad, steps=n, wall=c_wall(model, data, disk_start, n))


def disk_table(rows):
    big_omega, _, _ = disk_precession()
    print(f"\n### 4. Euler's disk (a = 37.5 mm, 6 mm thick, 0.4 kg, μ = {DISK['mu']}), "
          f"30° tilt, steady rolling with the centre at rest (precession {big_omega:.2f} rad/s)\n")
    print(f"| MuJoCo setting | tilt < {DISK['rest_deg']}° at t_rest (s) | tilt at t_rest/2 (°) "
          "| tilt 1 s, 0.1 s, 0.01 s before t_rest (°) "
          "| n of α = A (t₀ − t)ⁿ (Moffatt 1/3), fitted t₀ (s), window t₀ − t (s), rms of log α "
          "| at the end: t (s), tilt (°), E/E₀ | centre drift, first 1 s (mm) "
          "| deepest penetration (mm) | wall to the end (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        rest = fmt(r["rest"], 3, f"not by {r['t_end']:g} s")
        if r["diverged"]:
            rest += " (diverged)"
        before = (", ".join(f"{v:.2f}" for v in r["alpha_before_rest_deg"].values())
                  if r["alpha_before_rest_deg"] else "–")
        fit = (f"{r['exponent']:.3f}, {r['fitted_t0']:.3f}, {r['fit_window'][0]:.3g} – "
               f"{r['fit_window'][1]:.3g}, {r['fit_rms']:.2f}" if r["exponent"] is not None
               else "–")
        print(f"| {r['setting']} | {rest} | {fmt(r['alpha_half_deg'], 2, '–')} | {before} "
              f"| {fit} "
              f"| {r['t_end']:.1f}, {r['alpha_end_deg']:.2f}, {r['energy_end_over_e0']:.3f} "
              f"| {1e3 * r['centre_drift_first_s']:.2f} | {1e3 * r['max_depth']:.2f} "
              f"| {r['wall']:.3f} |")


# --------------------------------------------------------------------------


def settings_top(quick):
    rows = [
        DEFAULT,
        setting(1e-3, "Euler"),
        setting(1e-3, "implicitfast"),
        setting(1e-3, "RK4"),
        setting(1e-3, "RK4", "elliptic"),
        setting(1e-3, "RK4", "pyramidal", 4),
        setting(1e-3, "RK4", "elliptic", 4),
        setting(1e-3, "RK4", "elliptic", 6),
        setting(1e-3, "RK4", "elliptic", 4, impratio=10),
        setting(1e-4, "Euler"),
        setting(1e-4, "RK4"),
        setting(1e-4, "RK4", "elliptic", 4),
        setting(1e-4, "RK4", "elliptic", 4, impratio=10),
        setting(1e-4, "RK4", "elliptic", 4, solref=(0.002, 1.0)),
        setting(1e-4, "RK4", "elliptic", 4, solimp=(0.99, 0.999, 0.001, 0.5, 2)),
    ]
    return [rows[i] for i in (0, 3, 6, 11)] if quick else rows


def settings_drop(quick):
    z = zeta_for(DROP["e"])
    rows = [
        DEFAULT,
        setting(note="dampratio for e", solref=(0.02, z)),
        setting(1e-3, "Euler", solref=(0.02, z), note="dampratio for e"),
        setting(1e-4, "Euler", solref=(0.02, z), note="dampratio for e"),
        setting(1e-3, "Euler", solref=(-1e4, 0.0), note="direct, e = 1 form"),
        setting(1e-3, "Euler", solref=direct(1e4)),
        setting(1e-3, "Euler", solref=direct(1e5)),
        setting(1e-4, "Euler", solref=direct(1e6)),
        setting(1e-4, "implicitfast", solref=direct(1e6)),
        setting(1e-4, "RK4", solref=direct(1e6)),
        setting(1e-4, "Euler", solref=direct(1e7)),
        setting(1e-4, "Euler", solref=direct(1e6), solimp=(0.99, 0.99, 0.001, 0.5, 2)),
    ]
    return [rows[i] for i in (0, 1, 7)] if quick else rows


def settings_super(quick, tuned):
    z = zeta_for(SUPER["e"])
    rows = [
        DEFAULT,
        setting(1e-4, "Euler", solref=(0.02, z), note="dampratio for e"),
        setting(1e-4, "Euler", solref=direct(1e6)),
        setting(1e-4, "Euler", "elliptic", solref=direct(1e6)),
        setting(1e-4, "Euler", "elliptic", solref=direct(1e6), impratio=10),
        setting(1e-4, "Euler", "elliptic", 6, solref=direct(1e6)),
        setting(1e-4, "Euler", "pyramidal", solref=direct(1e6), noslip=10),
        setting(1e-4, "RK4", "elliptic", solref=direct(1e7)),
        setting(1e-4, "Euler", "elliptic", solref=direct(1e6), solreffriction=(0.0005, 1.0)),
    ]
    if tuned:
        rows.append(tuned)
    return [rows[i] for i in (0, 2, 8)] if quick else rows


def settings_disk(quick):
    rows = [
        DEFAULT,
        setting(1e-3, "Euler"),
        setting(1e-3, "implicitfast", "elliptic"),
        setting(1e-3, "RK4", "elliptic", 4),
        setting(1e-4, "Euler"),
        setting(1e-4, "RK4", "elliptic"),
        setting(1e-4, "RK4", "elliptic", 4),
        setting(1e-4, "RK4", "elliptic", 4, solref=(0.002, 1.0)),
    ]
    return [rows[i] for i in (0, 1)] if quick else rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer MuJoCo settings")
    parser.add_argument("--json", metavar="OUT", help="also write every row as JSON")
    parser.add_argument("--scenes", default="1234", help="which scenes to run (default 1234)")
    parser.add_argument("--reference", metavar="JSON",
                        default=str(Path(__file__).resolve().parent.parent
                                    / "tests/data/contact/tippe_top_stem_reference.json"),
                        help="cardillo's tippe-top runs, shown beside MuJoCo's when the file "
                             "is there (default: %(default)s)")
    args = parser.parse_args()
    print(f"MuJoCo {mujoco.__version__}, numpy {np.__version__}, Python "
          f"{sys.version.split()[0]}")
    out = {"mujoco": mujoco.__version__, "numpy": np.__version__}

    if "1" in args.scenes:
        out["tippe_top"] = [run_top(s) for s in settings_top(args.quick)]
        top_table(reference_rows(args.reference) + out["tippe_top"])
    tuned = None
    if "2" in args.scenes or "3" in args.scenes:
        k = 1e6
        zeta = tune_drop_damping(1e-4, k)
        tuned = setting(1e-4, "Euler", solref=(-k, -2.0 * zeta * math.sqrt(k)),
                        note=f"damping tuned: 1st bounce e = 0.9, dampratio {zeta:.4f}")
    if "2" in args.scenes:
        out["drop"] = [run_drop(s) for s in settings_drop(args.quick) + [tuned]]
        drop_table(out["drop"])
    if "3" in args.scenes:
        out["superball"] = [run_super(s) for s in settings_super(args.quick, tuned)]
        super_table(out["superball"])
    if "4" in args.scenes:
        out["euler_disk"] = [run_disk(s) for s in settings_disk(args.quick)]
        disk_table(out["euler_disk"])

    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()
