"""Reference runs of Leine & Glocker's tippe top on the ground plane.

Regenerate (from the repository root; scipy, numpy; about 4 minutes):

    python3 tests/data/gen/tippe_top.py

Writes ../contact/tippe_top_SCENARIO.csv (relative to this script) for each
scenario and ../contact/tippe_top_touchdown.csv (below), and prints the
checks. `--touchdown` writes the touchdown file only.

Physics (written from Newton-Euler in BODY axes, not from kreisel's
world-axes closed form for N)
------------------------------------------------------------------------
* Body: mass m, inertia I = diag(I1, I1, I3) about the centre of mass in
  body axes; a sphere of radius R centred at c = (0, 0, a) (body axes, from
  the centre of mass; axis 3 points to the stem). Plane z = 0, gravity -g z.
* State y = (q, w, x, v): q = world_from_body (scalar first, Hamilton),
  w = angular velocity in BODY axes, x, v = centre of mass (world).
* Contact point from the centre of mass: rho = R(q) c - R z (world).
  Slip velocity: u = v + (R w) x rho, its horizontal part u_h.
  Friction per newton: viscous f = -mu u_h; sliding f = -mu u_h/sqrt(|u_h|^2+eps^2).
  Contact force N e, e = z + f.
* Unknowns (dv/dt, dw/dt, N), one linear system each evaluation:
      m dv/dt - N e              = -m g z
      I dw/dt - N (R^T rho) x (R^T e) = (I w) x w
      dv_z/dt + [R (dw/dt x c)]_z = -[R (w x (w x c))]_z
  (the last: the second derivative of z_G + [R c]_z - R = 0).
  dq/dt = 1/2 q (x) (0, w), dx/dt = v. Solved with scipy's DOP853 at
  rtol 1e-13; the inversion time (the axis' world z-component R[2,2]
  crossing 0 downwards) is located by solve_ivp's event root finder.
* Output rows: `sample` at t = 0.5, 1, ... with x, v, q, L_world = R I w;
  one `inverted` row (its t, the state there). Checks printed: the same
  run at rtol 1e-11 (the inversion time's change), Jellett's integral
  lambda = L . (R z - R(q) c) and the energy drift.

The stem's ball touching down (../contact/tippe_top_touchdown.csv)
------------------------------------------------------------------------
* Leine & Glocker's top has a second sphere on its stem: radius
  STEM_RAD = 5 mm centred at STEM_C = (0, 0, 16 mm) (body axes, from the
  centre of mass). Its gap to the plane, z_G + [R(q) STEM_C]_z - STEM_RAD,
  is a terminal event (direction -1) of the same equations (the ball's
  contact only) run until it reaches zero: one row per scenario of
  TOUCHDOWN with the time (rtol 1e-13), the same run's time at rtol 1e-11
  (`t_rtol_1e-11`, the reference's own error), the stem ball's approach
  speed -d(gap)/dt = -(v_z + [R(q) (w x STEM_C)]_z) there, and the state.
  Separate runs: the `sample`/`inverted` files above are not changed.
"""

import csv
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

M, RAD, A, I1, I3 = 0.006, 0.015, 0.003, 8e-7, 7e-7
G, THETA0, OMEGA0 = 9.81, 0.1, 180.0
INERTIA = np.diag([I1, I1, I3])
C = np.array([0.0, 0.0, A])
Z = np.array([0.0, 0.0, 1.0])

STEM_RAD = 0.005
STEM_C = np.array([0.0, 0.0, 0.016])

SCENARIOS = {
    "viscous": dict(kind="viscous", mu=0.3, duration=6.0),
    "sliding": dict(kind="sliding", mu=0.3, eps=1e-3, duration=3.0),
}


TOUCHDOWN = {
    "viscous": dict(kind="viscous", mu=0.3, duration=20.0),
    "sliding": dict(kind="sliding", mu=0.3, eps=1e-3, duration=10.0),
}


def rot(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def quat_mul(a, b):
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return np.array(
        [
            a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
            a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
            a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0,
        ]
    )


def friction(sc, u):
    uh = np.array([u[0], u[1], 0.0])
    if sc["kind"] == "viscous":
        return -sc["mu"] * uh
    return -sc["mu"] * uh / np.sqrt(uh @ uh + sc["eps"] ** 2)


def rhs(sc):
    def f(_t, y):
        q, w, v = y[0:4], y[4:7], y[10:13]
        r = rot(q)
        rho = r @ C - RAD * Z
        e = Z + friction(sc, v + np.cross(r @ w, rho))
        rho_b, e_b = r.T @ rho, r.T @ e
        a_mat = np.zeros((7, 7))
        b = np.zeros(7)
        a_mat[0:3, 0:3] = M * np.eye(3)
        a_mat[0:3, 6] = -e
        b[0:3] = -M * G * Z
        a_mat[3:6, 3:6] = INERTIA
        a_mat[3:6, 6] = -np.cross(rho_b, e_b)
        b[3:6] = np.cross(INERTIA @ w, w)
        # d2/dt2 of z_G + [R c]_z: dv_z + [R (dw x c)]_z + [R (w x (w x c))]_z
        a_mat[6, 2] = 1.0
        for k in range(3):
            ek = np.zeros(3)
            ek[k] = 1.0
            a_mat[6, 3 + k] = (r @ np.cross(ek, C))[2]
        b[6] = -(r @ np.cross(w, np.cross(w, C)))[2]
        sol = np.linalg.solve(a_mat, b)
        dv, dw = sol[0:3], sol[3:6]
        dq = 0.5 * quat_mul(q, np.array([0.0, *w]))
        return np.concatenate([dq, dw, v, dv])

    return f


def initial():
    q = np.array([np.cos(THETA0 / 2), np.sin(THETA0 / 2), 0.0, 0.0])
    w = np.array([0.0, 0.0, OMEGA0])
    r = rot(q)
    x = np.array([0.0, 0.0, RAD - (r @ C)[2]])
    v = np.array([0.0, 0.0, -np.cross(r @ w, r @ C)[2]])
    return np.concatenate([q, w, x, v])


def axis_z(_t, y):
    return rot(y[0:4])[2, 2]


axis_z.direction = -1.0


def solve(sc, rtol):
    atol = np.array([1e-16] * 4 + [1e-13] * 3 + [1e-18] * 6)
    times = np.arange(0.5, sc["duration"] + 1e-9, 0.5)
    return solve_ivp(
        rhs(sc),
        (0.0, sc["duration"]),
        initial(),
        method="DOP853",
        t_eval=times,
        events=axis_z,
        rtol=rtol,
        atol=atol,
        dense_output=False,
    )


def stem_gap(_t, y):
    return y[9] + (rot(y[0:4]) @ STEM_C)[2] - STEM_RAD


stem_gap.terminal = True
stem_gap.direction = -1.0


def stem_approach_speed(y):
    q, w, v = y[0:4], y[4:7], y[10:13]
    return -(v[2] + (rot(q) @ np.cross(w, STEM_C))[2])


def solve_touchdown(sc, rtol):
    atol = np.array([1e-16] * 4 + [1e-13] * 3 + [1e-18] * 6)
    return solve_ivp(
        rhs(sc),
        (0.0, sc["duration"]),
        initial(),
        method="DOP853",
        events=stem_gap,
        rtol=rtol,
        atol=atol,
        dense_output=False,
    )


def touchdowns(out):
    path = os.path.join(out, "tippe_top_touchdown.csv")
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            ["scenario", "t", "t_rtol_1e-11", "approach_speed"]
            + ["x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz", "lx", "ly", "lz"]
        )
        for name, sc in TOUCHDOWN.items():
            fine = solve_touchdown(sc, 1e-13)
            coarse = solve_touchdown(sc, 1e-11)
            t, y = fine.t_events[0][0], fine.y_events[0][0]
            t_coarse = coarse.t_events[0][0]
            speed = stem_approach_speed(y)
            tilt = np.degrees(np.arccos(np.clip(rot(y[0:4])[2, 2], -1.0, 1.0)))
            print(
                f"{name}: stem touches down at {float(t)!r} s (rtol 1e-11: {float(t_coarse)!r}); "
                f"tilt {tilt:.3f} deg, approach speed {speed:.6e} m/s, gap there {stem_gap(t, y):.1e} m; "
                f"{fine.nfev} evaluations"
            )
            lab = row(name, t, y)
            w.writerow(lab[:2] + [repr(float(t_coarse)), repr(float(speed))] + lab[2:])


def invariants(y):
    q, w, x, v = y[0:4], y[4:7], y[7:10], y[10:13]
    r = rot(q)
    lw = r @ (INERTIA @ w)
    lam = lw @ (RAD * Z - r @ C)
    energy = 0.5 * M * v @ v + 0.5 * w @ (INERTIA @ w) + M * G * x[2]
    return lw, lam, energy


def row(label, t, y):
    q, x, v = y[0:4], y[7:10], y[10:13]
    lw, _, _ = invariants(y)
    return [label, repr(float(t))] + [repr(float(u)) for u in [*x, *v, *q, *lw]]


def main():
    out = os.path.join(os.path.dirname(__file__), "..", "contact")
    os.makedirs(out, exist_ok=True)
    for name, sc in SCENARIOS.items():
        fine = solve(sc, 1e-13)
        coarse = solve(sc, 1e-11)
        t_inv = fine.t_events[0][0]
        _, lam0, e0 = invariants(initial())
        lam_err = max(abs(invariants(y)[1] - lam0) for y in fine.y.T) / abs(lam0)
        print(
            f"{name}: inverted at {float(t_inv)!r} s (rtol 1e-11: {float(coarse.t_events[0][0])!r}); "
            f"|dlambda|/lambda {lam_err:.1e}; E {e0:.6e} -> {invariants(fine.y[:, -1])[2]:.6e}; "
            f"{fine.nfev} evaluations"
        )
        path = os.path.join(out, f"tippe_top_{name}.csv")
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(
                ["event", "t", "x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz", "lx", "ly", "lz"]
            )
            for t, y in zip(fine.t, fine.y.T):
                w.writerow(row("sample", t, y))
            w.writerow(row("inverted", t_inv, fine.y_events[0][0]))
    touchdowns(out)


if __name__ == "__main__":
    if sys.argv[1:] == ["--touchdown"]:
        touchdowns(os.path.join(os.path.dirname(__file__), "..", "contact"))
    else:
        main()
