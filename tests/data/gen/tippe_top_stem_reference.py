"""Nonsmooth reference for Leine & Glocker's tippe top WITH its stem (cardillo).

Writes ../contact/tippe_top_stem_reference.json (relative to this script):
the model's parameters, and for each run (integrator, step size) the event
times and the final state listed under "Events" below.

Install and run (Python 3.11; about 30 minutes on one free core)
-----------------------------------------------------------
cardillo's Coulomb-Contensou sphere-plane contact and its tippe-top example
were deleted from cardillo in October 2023 (commit 6ee0290f "Removed some
contacts."); the last commit that has both is 832f71fc (2023-10-26):

    git clone https://github.com/cardilloproject/cardillo /tmp/cardillo
    git -C /tmp/cardillo checkout 832f71fc7ba50a2db1addf5eb357f6b7094d4f82
    python3 -m venv /tmp/cardillo-venv
    /tmp/cardillo-venv/bin/pip install numpy==1.26.4 scipy==1.12.0 \\
        tqdm==4.70.1 meshio==5.3.5
    PYTHONPATH=/tmp/cardillo TQDM_DISABLE=1 \\
        /tmp/cardillo-venv/bin/python tests/data/gen/tippe_top_stem_reference.py

(cardillo 3.0.0 by its setup.py; it is imported from PYTHONPATH, not
installed: its setup.py pins meshio to a git fork that only its VTK export
needs, PyPI's meshio imports fine.) `--cache DIR` keeps each run's trajectory
in DIR/<solver>_<dt>_<T>.npz and reuses it; `--runs moreau:2e-4,...` picks
runs (`solver:dt:T` for another end time than --t-end). By default only
Rattle at dt = 1e-3 runs the whole 8 s; the other runs stop at 2 s, past
the stem's first touchdown (Moreau's fixed-point iteration is slow once the
stem touches: 8 s at dt = 1e-4 had not finished after 14 CPU minutes). numpy < 2 is needed (cardillo of 2023 predates numpy 2).

Model (as cardillo's examples/nonsmooth/tippetop.py at 832f71fc, which
cites Leine & Glocker, Eur. J. Mech. A/Solids 22 (2003) 193-216, Sect. 5)
----------------------------------------------------------------------------
* Rigid body: m = 6e-3 kg, inertia about the centre of mass S
  diag(I1, I1, I3) = diag(8e-7, 8e-7, 7e-7) kg m^2 (body axes), g = 9.81.
* Ball: radius R1 = 0.015 m, centre at (0, 0, a1) = (0, 0, 0.003) m in body
  axes from S (so S lies a1 BELOW the ball's centre when the stem is up).
* Stem tip: a sphere of radius R2 = 0.005 m centred at (0, 0, a2) =
  (0, 0, 0.016) m in body axes from S (on the stem side).
* Table: the plane z = 0, normal +z.
* Both contacts: Signorini + Newton impact law with e_N = 0, tangential
  restitution e_F = 0, friction mu = 0.3, Coulomb-Contensou with contact
  radius R = 5e-4 m (Moeller, Leine & Glocker's ellipsoidal approximation):
      generalized friction velocity  gamma_F = (v_C.t1, v_C.t2, Rbar * omega.n)
      Rbar = (3 pi / 16) R      (Hertzian pressure over a disc of radius R;
                                 uniform pressure would give 2/3)
      force/torque on the body:  (F_t1, F_t2, T_n) = (l1, l2, Rbar * l3),
      l = (l1, l2, l3) in the ball |l| <= mu * lambda_N, maximal dissipation
      (l = prox onto that ball). So the admissible set is the ellipsoid
          F_t1^2 + F_t2^2 + (T_n / Rbar)^2 <= (mu lambda_N)^2,
      semi-axes mu N, mu N and mu N Rbar, and while sliding
          F_t = -mu N v_t / s,  T_n = -mu N Rbar^2 omega_n / s,
          s = sqrt(|v_t|^2 + Rbar^2 omega_n^2),
      v_C the velocity of the body's point at the contact (the sphere's
      lowest point), omega_n the angular velocity's vertical component.
* Initial state (L&G: "all zero except z0 = 1.2015e-2 m, theta0 = 0.1 rad,
  psi_dot0 = 180 rad/s"): orientation = rotation by theta0 about world x;
  S at (0, 0, R1 - a1 cos theta0) = (0, 0, 0.0120149875...), at rest
  (L&G and cardillo's example round z0 to 1.2015e-2 m: a 1.25e-8 m gap);
  angular velocity 180 rad/s about the BODY symmetry axis (body (0, 0, 180)).
  The ball touches the table, its contact point slides.
* End time 8 s (cardillo's example; L&G's figures span 8 s).

Integrators (cardillo)
----------------------
* MoreauClassical: midpoint Moreau-Jean time stepping, contacts active when
  the gap at the midpoint is <= 0, fixed-point prox iteration to 1e-10.
* Rattle: cardillo's nonsmooth RATTLE (Capobianco et al.), atol 1e-10.

Independent check of the first phase (ball_phase_ode in the JSON)
-----------------------------------------------------------------
While the ball alone touches, the contact keeps sliding (the Contensou slip
s = |(v_t, Rbar omega_n)| >= Rbar |omega_n| > 0 while the top spins), so the
set-valued law is single-valued there and the motion is a smooth ODE. This
script integrates it itself (numpy/scipy only, not cardillo; DOP853 at rtol
1e-10 and 1e-12) up to the stem's touchdown, the ball's lift-off or a stick,
whichever first, and records the axis-horizontal time, the end of the phase,
and the minimum normal force and slip (both must stay positive). Note: with
Rbar = 0 (plain Coulomb) the tangential slip first vanishes at t = 0.036 s
(a stick/roll transition, where this ODE stops applying); with Contensou
friction the drilling term keeps the contact sliding through the phase.

Events (per run; times in s, linear interpolation between samples where a
sign change is located, else the first sample where it holds)
--------------------------------------------------------------------------
* t_axis_horizontal: the symmetry axis' world z-component (stem direction)
  first drops to 0 (theta = 90 degrees).
* t_stem_first_touch: first step with a positive stem-sphere percussion.
* t_ball_liftoff: the ball's gap first exceeds 1e-6 m (interpolated);
  t_ball_retouch: the first step after that with a positive ball percussion.
* t_both_contacts_first: first step with both percussions positive (ball and
  stem on the table: then theta = theta_two_point_deg =
  arccos((R2 - R1)/(a2 - a1)) = 140.2849 degrees, a geometric check);
  t_stem_last_contact; stem_only_duration: the time spent on the stem with
  the ball off the table.
* t_ball_last_contact: last step with a positive ball percussion;
  ball_contact_at_end, stem_contact_at_end.
* theta at 0.5 s intervals (degrees), final state at t_end: theta, z_S,
  omega (world), spin about the vertical, energy; energy_max_rise: the
  largest increase of the total energy between consecutive steps (a
  nonsmooth scheme with e_N = e_F = 0 must not create energy beyond its
  discretization error) and energy_rises_above_1e-9_J: how many steps rose;
  friction_*_ratio_max: max |l| / (mu P_N) over the steps a contact pushes
  (<= 1 up to the prox iteration's tolerance); the smallest gaps.
"""

# What the committed JSON shows (cardillo 832f71fc, this machine, 2026-11-28):
# * ball phase: the ODE gives t_axis_horizontal = 0.97294717 s and the stem's
#   touchdown at 1.37104325 s with the ball still pressing (min N = 0.0332 N,
#   min slip 0.0432 m/s); Moreau at dt = 2e-4, 1e-4, 5e-5 gives 0.971494,
#   0.972211, 0.972576 and 1.3636, 1.3672, 1.3691: first-order convergence to
#   the ODE's values (errors halve with dt). Rattle: 0.973634 / 1.417 at 1e-3,
#   0.972221 / 1.3715 at 5e-4.
# * the ball leaves the table right after the stem touches (5, 2.3, 1.1 ms
#   later at Moreau 2e-4, 1e-4, 5e-5: simultaneous in the limit); at 2 s
#   the top spins on its stem, theta ~ 172 deg, E ~ 4.58 mJ (from 12.05 mJ),
#   vertical spin ~ 97 rad/s (Moreau, converging at first order).
# * Rattle 1e-3 to 8 s (coarsest, late times not converged): on the stem
#   alone until 4.68 s (theta up to 178.5 deg), then the ball touches again,
#   both on the table at 4.744 s (theta = 140.28 deg, the two-point angle),
#   the stem leaves at 5.55 s and the top ends on its ball at theta = 98 deg,
#   E = 1.05 mJ, vertical spin 10.3 rad/s.
# * energy: Rattle never rises; Moreau (midpoint) rises by at most 3.7e-8,
#   9.2e-9, 2.3e-9 J per step at 2e-4, 1e-4, 5e-5 (ball phase), i.e. O(dt^2).

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

os.environ.setdefault("TQDM_DISABLE", "1")

import numpy as np  # noqa: E402

OUT = Path(__file__).resolve().parent.parent / "contact" / "tippe_top_stem_reference.json"
CARDILLO_COMMIT = "832f71fc7ba50a2db1addf5eb357f6b7094d4f82"

PARAMS = dict(
    m=6e-3,
    I1=8e-7,
    I3=7e-7,
    g=9.81,
    a1=3e-3,
    a2=1.6e-2,
    R1=1.5e-2,
    R2=5e-3,
    mu=0.3,
    e_N=0.0,
    e_F=0.0,
    R_contensou=5e-4,
    theta0=0.1,
    omega3_body0=180.0,
    t_end=8.0,
)
PARAMS["Rbar"] = 3 * np.pi / 16 * PARAMS["R_contensou"]
PARAMS["z0"] = PARAMS["R1"] - PARAMS["a1"] * np.cos(PARAMS["theta0"])
# both spheres on the table: z + a1 cos(theta) = R1 and z + a2 cos(theta) = R2
PARAMS["theta_two_point_deg"] = float(
    np.degrees(np.arccos((PARAMS["R2"] - PARAMS["R1"]) / (PARAMS["a2"] - PARAMS["a1"])))
)

AIRBORNE = 1e-6  # m: the ball counts as off the table above this gap
DEFAULT_RUNS = "moreau:2e-4:2,moreau:1e-4:2,moreau:5e-5:2,rattle:1e-3,rattle:5e-4:2"


def build():
    """cardillo system and the top's rigid body."""
    from cardillo import System
    from cardillo.contacts import Sphere2PlaneCoulombContensouMoeller
    from cardillo.discrete import RigidBody
    from cardillo.forces import Force
    from cardillo.math import axis_angle2quat

    p = PARAMS
    q0 = np.zeros(7)
    q0[2] = p["z0"]
    q0[3:] = axis_angle2quat(np.array([1.0, 0.0, 0.0]), p["theta0"])
    u0 = np.zeros(6)
    u0[5] = p["omega3_body0"]
    system = System()
    top = RigidBody(p["m"], np.diag([p["I1"], p["I1"], p["I3"]]), q0=q0, u0=u0)
    ball = Sphere2PlaneCoulombContensouMoeller(
        system.origin, top, p["R1"], p["R_contensou"], p["mu"], p["e_N"], p["e_F"],
        K_r_SP=np.array([0.0, 0.0, p["a1"]]),
    )
    stem = Sphere2PlaneCoulombContensouMoeller(
        system.origin, top, p["R2"], p["R_contensou"], p["mu"], p["e_N"], p["e_F"],
        K_r_SP=np.array([0.0, 0.0, p["a2"]]),
    )
    gravity = Force(np.array([0.0, 0.0, -p["m"] * p["g"]]), top)
    system.add(top, ball, stem, gravity)
    system.assemble()
    return system, top


def simulate(solver, dt, t_end, cache):
    """(t, q, u, P_N, P_F, wall seconds) of one run, from the cache if there."""
    name = f"{solver}_{dt:g}_{t_end:g}.npz"
    if cache is not None and (cache / name).exists():
        d = np.load(cache / name)
        return d["t"], d["q"], d["u"], d["P_N"], d["P_F"], float(d.get("wall", np.nan))
    from cardillo.solver import MoreauClassical, Rattle

    system, _ = build()
    start = time.time()
    if solver == "moreau":
        sol = MoreauClassical(system, t_end, dt, atol=1e-10, max_iter=1000).solve()
    elif solver == "rattle":
        sol = Rattle(system, t_end, dt, atol=1e-10).solve()
    else:
        raise SystemExit(f"unknown solver {solver!r} (moreau or rattle)")
    wall = time.time() - start
    out = (sol.t, sol.q, sol.u, sol.P_N, sol.P_F, wall)
    if cache is not None:
        cache.mkdir(parents=True, exist_ok=True)
        np.savez(cache / name, t=sol.t, q=sol.q, u=sol.u, P_N=sol.P_N, P_F=sol.P_F, wall=wall)
    return out


def rotation(quat):
    """world_from_body of a unit quaternion (w, x, y, z)."""
    w, x, y, z = quat / np.linalg.norm(quat)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def crossing(t, f):
    """First time f goes from > 0 to <= 0 (linear interpolation), or None."""
    idx = np.nonzero((f[:-1] > 0) & (f[1:] <= 0))[0]
    if len(idx) == 0:
        return None
    i = idx[0]
    return float(t[i] + (t[i + 1] - t[i]) * f[i] / (f[i] - f[i + 1]))


def analyse(t, q, u, P_N, P_F):
    p = PARAMS
    mats = np.array([rotation(qi[3:]) for qi in q])
    axis_z = mats[:, 2, 2]
    theta = np.arccos(np.clip(axis_z, -1.0, 1.0))
    gap_ball = q[:, 2] + p["a1"] * axis_z - p["R1"]
    gap_stem = q[:, 2] + p["a2"] * axis_z - p["R2"]
    inertia = np.array([p["I1"], p["I1"], p["I3"]])
    energy = (
        0.5 * p["m"] * np.sum(u[:, :3] ** 2, axis=1)
        + 0.5 * np.sum(inertia * u[:, 3:] ** 2, axis=1)
        + p["m"] * p["g"] * q[:, 2]
    )
    omega_world = np.einsum("nij,nj->ni", mats, u[:, 3:])
    ball_on = P_N[:, 0] > 0
    stem_on = P_N[:, 1] > 0
    stem_idx = np.nonzero(stem_on)[0]
    ball_idx = np.nonzero(ball_on)[0]
    rises = np.diff(energy)
    # cardillo's friction percussions: 3 per contact (l1, l2, l3), |l| <= mu P_N
    cone = []
    for k in range(2):
        lam = np.linalg.norm(P_F[:, 3 * k : 3 * k + 3], axis=1)
        on = P_N[:, k] > 1e-14
        cone.append(float(np.max(lam[on] / (p["mu"] * P_N[on, k]))) if on.any() else None)
    samples = {}
    for ts in np.arange(0.5, t[-1] + 1e-9, 0.5):
        i = int(np.argmin(np.abs(t - ts)))
        samples[f"{ts:g}"] = float(np.degrees(theta[i]))
    airborne = gap_ball > AIRBORNE
    lift = np.nonzero(airborne)[0]
    retouch = np.nonzero(ball_on[lift[0]:])[0] + lift[0] if len(lift) else []
    both = np.nonzero(ball_on & stem_on)[0]
    dt = np.diff(t)
    stem_only = float(np.sum(dt[(stem_on & airborne)[1:]]))
    return dict(
        t_axis_horizontal=crossing(t, axis_z),
        t_ball_liftoff=crossing(t, AIRBORNE - gap_ball),
        t_ball_retouch=float(t[retouch[0]]) if len(retouch) else None,
        t_both_contacts_first=float(t[both[0]]) if len(both) else None,
        theta_deg_at_both_contacts_first=(
            float(np.degrees(theta[both[0]])) if len(both) else None
        ),
        t_stem_last_contact=float(t[stem_idx[-1]]) if len(stem_idx) else None,
        stem_only_duration=stem_only,
        t_stem_first_touch=float(t[stem_idx[0]]) if len(stem_idx) else None,
        t_stem_gap_first_nonpositive=crossing(t, gap_stem),
        t_ball_last_contact=float(t[ball_idx[-1]]) if len(ball_idx) else None,
        ball_contact_at_end=bool(ball_on[-1]),
        stem_contact_at_end=bool(stem_on[-1]),
        ball_contact_steps_after_stem_touch=(
            int(np.sum(ball_on[stem_idx[0]:])) if len(stem_idx) else None
        ),
        theta_deg_every_half_second=samples,
        theta_deg_max=float(np.degrees(theta.max())),
        end=dict(
            t=float(t[-1]),
            theta_deg=float(np.degrees(theta[-1])),
            z_com=float(q[-1, 2]),
            gap_ball=float(gap_ball[-1]),
            gap_stem=float(gap_stem[-1]),
            omega_world=[float(x) for x in omega_world[-1]],
            omega_body=[float(x) for x in u[-1, 3:]],
            v_com=[float(x) for x in u[-1, :3]],
            energy=float(energy[-1]),
        ),
        energy_start=float(energy[0]),
        energy_max_rise=float(rises.max()),
        energy_rises_above_1e_9_J=int(np.sum(rises > 1e-9)),
        friction_ball_ratio_max=cone[0],
        friction_stem_ratio_max=cone[1],
        min_gap_ball=float(gap_ball.min()),
        min_gap_stem=float(gap_stem.min()),
    )


def ball_phase_ode(rtol=1e-12):
    """Independent check of the first phase (ball alone on the table).

    While only the ball touches and its contact slides (|gamma| > 0), the
    set-valued law is single-valued: F_t = -mu N v_t/s, T_n = -mu N Rbar^2
    omega_n/s, s = |(v_t, Rbar omega_n)|. Newton-Euler (body axes for the
    rotation) with the gap's second derivative held at zero gives a smooth
    ODE, integrated with scipy's DOP853 until the stem's gap reaches 0, the
    normal force reaches 0 (lift-off) or s reaches 0 (stick), whichever first.
    Returns the axis-horizontal time and how the phase ended, and the minima
    of N and s along the way (both must stay > 0 for the ODE to be valid).
    """
    from scipy.integrate import solve_ivp

    p = PARAMS
    m, g, mu, rbar = p["m"], p["g"], p["mu"], p["Rbar"]
    inertia = np.diag([p["I1"], p["I1"], p["I3"]])
    c_ball = np.array([0.0, 0.0, p["a1"]])
    c_stem = np.array([0.0, 0.0, p["a2"]])
    ez = np.array([0.0, 0.0, 1.0])

    def solve(y):
        q, w, v = y[0:4], y[4:7], y[10:13]
        r = rotation(q)
        rho = r @ c_ball - p["R1"] * ez
        omega = r @ w
        u = v + np.cross(omega, rho)
        slip = np.sqrt(u[0] ** 2 + u[1] ** 2 + (rbar * omega[2]) ** 2)
        e = ez - mu * np.array([u[0], u[1], 0.0]) / slip
        tau = -mu * rbar**2 * omega[2] / slip  # drilling torque per newton
        moment_b = r.T @ (np.cross(rho, e) + tau * ez)
        a_mat = np.zeros((7, 7))
        b = np.zeros(7)
        a_mat[0:3, 0:3] = m * np.eye(3)
        a_mat[0:3, 6] = -e
        b[0:3] = -m * g * ez
        a_mat[3:6, 3:6] = inertia
        a_mat[3:6, 6] = -moment_b
        b[3:6] = np.cross(inertia @ w, w)
        # d2/dt2 (z + [R c]_z) = 0
        a_mat[6, 2] = 1.0
        # [R (dw x c)]_z: row i of cross(eye, c) is e_i x c
        a_mat[6, 3:6] = (r @ np.cross(np.eye(3), c_ball).T)[2]
        b[6] = -(r @ np.cross(w, np.cross(w, c_ball)))[2]
        sol = np.linalg.solve(a_mat, b)
        return sol[0:3], sol[3:6], sol[6], slip

    def rhs(_t, y):
        q, w, v = y[0:4], y[4:7], y[10:13]
        dv, dw, _n, _s = solve(y)
        wq = np.array([0.0, *w])
        dq = 0.5 * np.array(
            [
                q[0] * wq[0] - q[1:] @ wq[1:],
                *(q[0] * wq[1:] + wq[0] * q[1:] + np.cross(q[1:], wq[1:])),
            ]
        )
        return np.concatenate([dq, dw, v, dv])

    def axis(_t, y):
        return rotation(y[0:4])[2, 2]

    def stem_gap(_t, y):
        return y[9] + (rotation(y[0:4]) @ c_stem)[2] - p["R2"]

    def normal(_t, y):
        return solve(y)[2]

    def slip(_t, y):
        return solve(y)[3] - 1e-9

    for ev in (stem_gap, normal, slip):
        ev.terminal = True
        ev.direction = -1
    axis.direction = -1
    q0 = np.array([np.cos(p["theta0"] / 2), np.sin(p["theta0"] / 2), 0.0, 0.0])
    y0 = np.concatenate([q0, [0.0, 0.0, p["omega3_body0"]], [0.0, 0.0, p["z0"]], np.zeros(3)])
    res = solve_ivp(
        rhs, (0.0, p["t_end"]), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-3,
        events=(axis, stem_gap, normal, slip), dense_output=True,
    )
    ts = np.linspace(0.0, res.t[-1], 20001)
    ns, ss = zip(*[solve(res.sol(t))[2:] for t in ts])
    ended = [name for name, te in zip(("axis", "stem_touch", "lift_off", "stick"), res.t_events) if name != "axis" and len(te)]
    inertia_d = np.array([p["I1"], p["I1"], p["I3"]])
    energy = lambda y: 0.5 * m * y[10:13] @ y[10:13] + 0.5 * inertia_d @ y[4:7] ** 2 + m * g * y[9]
    e_samples = np.array([energy(res.sol(t)) for t in ts])
    return dict(
        method=f"scipy solve_ivp DOP853, rtol {rtol:g}, atol {rtol * 1e-3:g}",
        t_axis_horizontal=float(res.t_events[0][0]) if len(res.t_events[0]) else None,
        t_end_of_phase=float(res.t[-1]),
        phase_ended_by=ended[0] if ended else "t_end",
        min_normal_force=float(min(ns)),
        min_slip=float(min(ss)),
        energy_max_rise_sampled=float(np.max(np.diff(e_samples))),
        theta_deg_every_half_second={
            f"{t:g}": float(np.degrees(np.arccos(np.clip(rotation(res.sol(t)[0:4])[2, 2], -1, 1))))
            for t in np.arange(0.5, res.t[-1], 0.5)
        },
    )


def versions():
    import scipy

    out = dict(
        reference_code="cardillo (github.com/cardilloproject/cardillo)",
        cardillo_commit=CARDILLO_COMMIT,
        cardillo_version="3.0.0 (setup.py at that commit)",
        cardillo_files=[
            "examples/nonsmooth/tippetop.py (parameters lines 29-53, initial velocity 79-83, t_final 156)",
            "cardillo/contacts/sphere2plane.py (Sphere2PlaneCoulombContensouMoeller line 291;"
            " R_bar = 3 pi/16 R and A = diag(1, 1, R_bar) lines 309-310; gamma_F 452-458; W_F 479-486)",
            "cardillo/math/prox.py (prox_sphere line 12: the ball |l| <= mu P_N)",
            "cardillo/solver/moreau.py (MoreauClassical line 554, friction prox line 643)",
            "cardillo/solver/rattle.py (Rattle line 11)",
        ],
        python=platform.python_version(),
        numpy=np.__version__,
        scipy=scipy.__version__,
    )
    try:
        import cardillo

        root = Path(cardillo.__file__).resolve().parent.parent
        head = subprocess.run(
            ["git", "-C", str(root), "rev-parse", "HEAD"],
            capture_output=True, text=True, check=False,
        ).stdout.strip()
        if head:
            out["cardillo_checkout_head"] = head
    except Exception:  # noqa: BLE001 (a tarball export has no git)
        pass
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", default=DEFAULT_RUNS)
    ap.add_argument("--cache", type=Path, default=None)
    ap.add_argument("--t-end", type=float, default=PARAMS["t_end"])
    args = ap.parse_args()
    runs = []
    for spec in args.runs.split(","):
        solver, dt, *end = spec.split(":")
        t_end = float(end[0]) if end else args.t_end
        t, q, u, P_N, P_F, wall = simulate(solver, float(dt), t_end, args.cache)
        ev = analyse(t, q, u, P_N, P_F)
        wall = None if not np.isfinite(wall) else round(wall, 1)  # strict JSON: no NaN
        ev.update(solver=solver, dt=float(dt), t_end=t_end, wall_seconds=wall)
        runs.append(ev)
        print(json.dumps({k: ev[k] for k in (
            "solver", "dt", "t_axis_horizontal", "t_stem_first_touch",
            "t_ball_last_contact", "energy_max_rise")}), flush=True)
        print("   end:", json.dumps(ev["end"]), flush=True)
    ode_cache = args.cache / "ball_phase_ode.json" if args.cache is not None else None
    if ode_cache is not None and ode_cache.exists():
        ode = json.loads(ode_cache.read_text())
    else:
        ode = [ball_phase_ode(rtol) for rtol in (1e-10, 1e-12)]
        if ode_cache is not None:
            ode_cache.write_text(json.dumps(ode))
    for o in ode:
        print(json.dumps({k: o[k] for k in ("method", "t_axis_horizontal", "t_end_of_phase", "phase_ended_by")}), flush=True)
    doc = dict(
        description=(
            "Leine & Glocker (2003) tippe top with stem on the table z = 0, "
            "Coulomb-Contensou friction (ellipsoid, Rbar = 3 pi/16 R), e_N = e_F = 0, "
            "simulated with cardillo's nonsmooth integrators; see "
            "tests/data/gen/tippe_top_stem_reference.py for the model and the events"
        ),
        parameters=PARAMS,
        initial_state=dict(
            quaternion_wxyz=[float(np.cos(PARAMS["theta0"] / 2)), float(np.sin(PARAMS["theta0"] / 2)), 0.0, 0.0],
            com=[0.0, 0.0, PARAMS["z0"]],
            v_com=[0.0, 0.0, 0.0],
            omega_body=[0.0, 0.0, PARAMS["omega3_body0"]],
        ),
        friction_law=(
            "(F_t1, F_t2, T_n) = (l1, l2, Rbar l3), |l| <= mu lambda_N, "
            "l = -mu lambda_N gamma/|gamma| when sliding, gamma = (v_t1, v_t2, Rbar omega_n), "
            "Rbar = 3 pi / 16 * R_contensou"
        ),
        code=versions(),
        ball_phase_ode=ode,
        runs=runs,
    )
    OUT.write_text(json.dumps(doc, indent=1, allow_nan=False) + "\n")
    print("wrote", OUT)


if __name__ == "__main__":
    sys.exit(main())
