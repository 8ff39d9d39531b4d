"""Reference trajectories of free rigid bodies under applied torques and forces.

Regenerate (from the repository root; scipy, numpy, mpmath pinned in
requirements.txt; about 20 minutes):

    python3 tests/data/gen/forced.py [NAME ...]

Writes ../forced/NAME.csv (relative to this script) for each scenario in
SCENARIOS (all of them when no NAME is given) and prints the checks.

Physics and conventions (written from Euler's equations, not from kreisel)
--------------------------------------------------------------------------
* Body frame = the user's body axes; I = inertia tensor about the centre of
  mass in body axes (a full matrix in some scenarios, so the reference does not
  depend on a principal-axes decomposition).
* State y = (q, w, x, v, W): q = world_from_body (scalar first, Hamilton),
  w = angular velocity in BODY axes, x, v = centre of mass position and
  velocity (world), W = work done by the applied loads.
* Torque about the centre of mass in body axes:
      tau_b = R^T tau_w + tau_body + sum_k r_k x (R^T F_k) - c w + R^T tau_law
  Force (world): F = F_w + sum_k F_k + F_law; gravity m g acts besides.
* Equations:
      I dw/dt = (I w) x w + tau_b                  (Euler, body axes)
      dq/dt   = 1/2 q (x) (0, w)
      dx/dt   = v,   m dv/dt = F + m g
      dW/dt   = tau_b . w + F . v
  R = R(q/|q|). Checks: |q| = 1, E(t) - E(0) = W(t) with
  E = 1/2 w.I w + 1/2 m |v|^2 - m g.x, and the closed forms where there are
  some (sphere under a world torque: L_world = L0 + tau t; free fall of the
  centre of mass under constant force: x = x0 + v0 t + a t^2/2).
* On a pivot (scenarios with `pivot_body`, a body point from the centre of
  mass held fixed at world point `pivot_world`): d = -pivot_body (centre of
  mass from the pivot, body axes), J = I + m (|d|^2 E - d d^T), and
      J dw/dt = (J w) x w + tau_b + d x (R^T (F + m g))
      dx/dt = v = R (w x d),   dv/dt = R (w x (w x d) + dw/dt x d)
      dW/dt = tau_b . w + F . v
  (x, v: the centre of mass, carried along; E = 1/2 w.I w + 1/2 m |v|^2 - m g.x
  = 1/2 w.J w - m g.x.)
* Laws (closures in kreisel):
      magnet: tau_w = (R m_body) x B(t),  B(t) = B0 (cos W t, sin W t, bz)
              (time and attitude)
      pd:     tau_w = -k rotvec(q) - c_d R w   (attitude and VELOCITY)
              rotvec: q with qw >= 0, angle 2 atan2(|q_v|, qw), axis q_v/|q_v|

Method
------
Three runs, each from sample to sample (0.1 s apart):
* B (written to the CSV): the equations above in pure Python on mpmath numbers
  (32 digits), Gragg-Bulirsch-Stoer extrapolation (modified midpoint with
  2, 4, ..., 20 substeps, extrapolated in h^2 to order 20) at a macro step of
  0.025 s;
* C (check of B): the same at 0.05 s and order 24: max |B - C| <= 1e-15;
* A (independent check): scipy.integrate.solve_ivp, DOP853, rtol = atol =
  1e-13 on the numpy implementation `rhs`: max |A - B| (attitude angle) is
  printed and asserted below 1e-11.
Invariants and closed forms (above) are asserted on B.

Scenarios (10 s, sampled every 0.1 s)
-------------------------------------
* sphere_world_torque: sphere, constant world torque not parallel to L.
* symmetric_body_torque: symmetric top, constant body-axes torque.
* asymmetric_body_torque: I = (1, 2, 3), constant body torque, started next to
  the intermediate axis (Dzhanibekov).
* asymmetric_world_torque: I = (1, 2, 3), constant world torque.
* point_force_gravity: full inertia tensor, gravity, a force through the centre
  of mass and a force at an offset body point (centre of mass moving).
* damped_asymmetric: I = (1, 2, 3), damping c = 0.3 and a body torque.
* magnet: a dipole in a rotating field (time- and attitude-dependent torque).
* pd_controller: full inertia tensor, PD attitude controller with a constant
  world disturbance torque (velocity-dependent torque).
* top_motor: a symmetric top on a pivot under gravity, spun up by a motor
  torque about its axis against damping (heavy top with inputs).
* top_pushed: an asymmetric top (full tensor, pivot off every axis) under
  gravity, a world torque and a force at a body point.
"""

import math
import os
import sys

import mpmath
import numpy as np
import scipy
from mpmath import mp, mpf
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir, "forced"))
PINNED = {"scipy": "1.17.1", "numpy": "2.4.6", "mpmath": "1.3.0"}

RTOL_A = 1e-13
DT = 0.1
T_END = 10.0
HEADER = "t,qw,qx,qy,qz,wx,wy,wz,x,y,z,vx,vy,vz,work"


def diag(a, b, c):
    return [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]]


BASE = dict(mass=1.0, gravity=[0.0, 0.0, 0.0], torque_world=[0.0, 0.0, 0.0],
            torque_body=[0.0, 0.0, 0.0], force_world=[0.0, 0.0, 0.0],
            point_body=[0.0, 0.0, 0.0], point_force=[0.0, 0.0, 0.0], damping=0.0,
            law="none", law_params=[0.0], q0=[1.0, 0.0, 0.0, 0.0],
            x0=[0.0, 0.0, 0.0], v0=[0.0, 0.0, 0.0])

SCENARIOS = [
    dict(BASE, name="sphere_world_torque", inertia=diag(2.0, 2.0, 2.0),
         torque_world=[0.3, -0.2, 0.5], omega0=[1.0, 0.5, -0.3],
         q0=[0.9, 0.1, -0.3, 0.2]),
    dict(BASE, name="symmetric_body_torque", inertia=diag(0.6, 0.6, 1.0),
         torque_body=[0.05, 0.0, 0.2], omega0=[0.3, -0.1, 5.0],
         q0=[0.8, 0.4, 0.2, -0.1]),
    dict(BASE, name="asymmetric_body_torque", inertia=diag(1.0, 2.0, 3.0),
         torque_body=[0.1, -0.2, 0.3], omega0=[0.01, 1.0, 0.0]),
    dict(BASE, name="asymmetric_world_torque", inertia=diag(1.0, 2.0, 3.0),
         torque_world=[0.2, 0.1, -0.3], omega0=[0.5, -0.3, 1.2],
         q0=[0.7, -0.1, 0.5, 0.3]),
    dict(BASE, name="point_force_gravity",
         inertia=[[0.05, 0.004, -0.002], [0.004, 0.08, 0.003], [-0.002, 0.003, 0.11]],
         mass=2.0, gravity=[0.0, 0.0, -9.81], force_world=[0.5, 0.0, 0.0],
         point_body=[0.05, -0.02, 0.1], point_force=[0.0, 0.1, 0.5],
         omega0=[2.0, -1.0, 3.0], q0=[0.6, 0.2, 0.5, -0.3],
         x0=[0.0, 0.0, 1.0], v0=[1.0, 0.5, 2.0]),
    dict(BASE, name="damped_asymmetric", inertia=diag(1.0, 2.0, 3.0), damping=0.3,
         torque_body=[0.05, 0.1, 0.0], omega0=[1.0, 2.0, -1.0], q0=[0.5, 0.5, 0.5, 0.5]),
    # law_params: m_body (3), B0, Omega, bz
    dict(BASE, name="magnet", inertia=diag(0.8, 1.0, 1.3), law="magnet",
         law_params=[0.0, 0.0, 0.5, 1.0, 0.7, 0.2], omega0=[0.2, 0.1, 0.5],
         q0=[0.95, 0.0, 0.3, 0.1]),
    # law_params: k, c_d
    dict(BASE, name="pd_controller",
         inertia=[[1.2, 0.1, 0.0], [0.1, 1.8, -0.2], [0.0, -0.2, 2.5]],
         law="pd", law_params=[2.0, 1.5], torque_world=[0.1, 0.0, 0.0],
         omega0=[0.5, -1.0, 0.8], q0=[0.5403023058681398, 0.2248926729, 0.4497853458, 0.6746780187]),
    dict(BASE, name="top_motor", inertia=diag(0.02, 0.02, 0.035), mass=0.5,
         gravity=[0.0, 0.0, -9.81], pivot_body=[0.0, 0.0, -0.05], pivot_world=[0.0, 0.0, 0.0],
         torque_body=[0.0, 0.0, 0.002], damping=0.0005, omega0=[0.5, 0.0, 20.0],
         q0=[0.98, 0.15, 0.1, 0.0]),
    dict(BASE, name="top_pushed",
         inertia=[[0.03, 0.002, -0.001], [0.002, 0.04, 0.003], [-0.001, 0.003, 0.05]],
         mass=1.5, gravity=[0.0, 0.0, -9.81], pivot_body=[0.01, -0.02, -0.08],
         pivot_world=[0.1, 0.2, 0.3], torque_world=[0.01, -0.02, 0.0],
         point_body=[0.03, 0.0, 0.05], point_force=[0.0, 0.2, 0.1],
         omega0=[0.5, -1.0, 4.0], q0=[0.9, 0.2, -0.1, 0.3],
         # a tumbling asymmetric top is sensitive to its start: DOP853's own
         # error (rtol 1e-13) grows to ~1.4e-11 rad over the 10 s (mpmath's
         # two runs agree to 1e-25)
         dop853_agreement=5e-11),
]


def pivot_arm(sc):
    """d: the centre of mass from the pivot, body axes (None: a free body)."""
    p = sc.get("pivot_body")
    return None if p is None else -np.array(p, dtype=float)


def about_pivot(sc, I):
    """The inertia tensor about the pivot (I itself for a free body)."""
    d = pivot_arm(sc)
    if d is None:
        return I
    return I + sc["mass"] * (d @ d * np.eye(3) - np.outer(d, d))


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz,
                     aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw])


def rot(q):
    """The rotation matrix of q/|q| (body -> world)."""
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def rotvec(q):
    q = q / np.linalg.norm(q)
    if q[0] < 0:
        q = -q
    v = q[1:]
    s = np.linalg.norm(v)
    if s == 0.0:
        return np.zeros(3)
    return 2.0 * math.atan2(s, q[0]) * v / s


def law(sc, t, q, R, w):
    """(tau_world, F_world) of the scenario's user law."""
    p = sc["law_params"]
    if sc["law"] == "none":
        return np.zeros(3), np.zeros(3)
    if sc["law"] == "magnet":
        m_body = np.array(p[0:3])
        b = p[3] * np.array([math.cos(p[4] * t), math.sin(p[4] * t), p[5]])
        return np.cross(R @ m_body, b), np.zeros(3)
    if sc["law"] == "pd":
        k, c_d = p
        return -k * rotvec(q) - c_d * (R @ w), np.zeros(3)
    raise ValueError(sc["law"])


def loads(sc, t, q, w):
    """(tau_body total, F_world total) at (t, q, w)."""
    R = rot(q)
    tau_law, f_law = law(sc, t, q, R, w)
    r = np.array(sc["point_body"])
    fp = np.array(sc["point_force"])
    tau_b = (R.T @ (np.array(sc["torque_world"]) + tau_law) + np.array(sc["torque_body"])
             + np.cross(r, R.T @ fp) - sc["damping"] * w)
    force = np.array(sc["force_world"]) + fp + f_law
    return tau_b, force


def rhs(sc, I, Iinv):
    m = sc["mass"]
    g = np.array(sc["gravity"])
    d = pivot_arm(sc)

    def f(t, y):
        q, w, v = y[0:4], y[4:7], y[10:13]
        tau_b, force = loads(sc, t, q, w)
        dq = 0.5 * qmul(q, np.array([0.0, w[0], w[1], w[2]]))
        if d is None:
            dw = Iinv @ (np.cross(I @ w, w) + tau_b)
            dv = force / m + g
        else:
            R = rot(q)
            dw = Iinv @ (np.cross(I @ w, w) + tau_b + np.cross(d, R.T @ (force + m * g)))
            v = R @ np.cross(w, d)
            dv = R @ (np.cross(w, np.cross(w, d)) + np.cross(dw, d))
        dW = tau_b @ w + force @ v
        return np.concatenate([dq, dw, v, dv, [dW]])
    return f


def initial(sc):
    q0 = np.array(sc["q0"], dtype=float)
    q0 /= np.linalg.norm(q0)
    d = pivot_arm(sc)
    if d is None:
        x0, v0 = sc["x0"], sc["v0"]
    else:
        R = rot(q0)
        x0 = np.array(sc["pivot_world"]) + R @ d
        v0 = R @ np.cross(np.array(sc["omega0"], dtype=float), d)
    return np.concatenate([q0, sc["omega0"], x0, v0, [0.0]])


def integrate(sc, tol):
    I = about_pivot(sc, np.array(sc["inertia"], dtype=float))
    Iinv = np.linalg.inv(I)
    f = rhs(sc, I, Iinv)
    n = int(round(T_END / DT))
    times = [k * DT for k in range(n + 1)]
    ys = [initial(sc)]
    for a, b in zip(times[:-1], times[1:]):
        sol = solve_ivp(f, (a, b), ys[-1], method="DOP853", rtol=tol, atol=tol)
        assert sol.success, sol.message
        ys.append(sol.y[:, -1])
    return times, np.array(ys)


def angle_between(a, b):
    """The rotation angle between the attitudes of quaternions a and b."""
    a = a / np.linalg.norm(a)
    b = b / np.linalg.norm(b)
    if a @ b < 0:
        b = -b
    return 2.0 * math.atan2(np.linalg.norm(a - b), np.linalg.norm(a + b))


def energy(sc, I, y):
    w, x, v = y[4:7], y[7:10], y[10:13]
    g = np.array(sc["gravity"])
    return 0.5 * w @ I @ w + 0.5 * sc["mass"] * v @ v - sc["mass"] * g @ x


def check(sc, times, ys, ys_b):
    """Invariants and closed forms of run ys (B); ys_b is DOP853's run A."""
    I = np.array(sc["inertia"], dtype=float)
    e0 = energy(sc, I, ys[0])
    worst_q = max(abs(np.linalg.norm(y[0:4]) - 1.0) for y in ys)
    # relative to the largest term met (point_force_gravity: kinetic and
    # potential energies of ~1e4 J that nearly cancel), as the samples are f64
    m, g = sc["mass"], np.array(sc["gravity"])
    scale = max(max(0.5 * y[4:7] @ I @ y[4:7], 0.5 * m * y[10:13] @ y[10:13],
                    abs(m * g @ y[7:10]), abs(y[13])) for y in ys)
    worst_e = max(abs(energy(sc, I, y) - e0 - y[13]) for y in ys) / scale
    worst_ab = max(angle_between(a[0:4], b[0:4]) for a, b in zip(ys, ys_b))
    worst_w = max(np.abs(a[4:7] - b[4:7]).max() for a, b in zip(ys, ys_b))
    print(f"  |q|-1: {worst_q:.1e}   (E - E0 - W)/max term: {worst_e:.1e}   "
          f"DOP853 vs mpmath: {worst_ab:.1e} rad, {worst_w:.1e} rad/s")
    agreement = sc.get("dop853_agreement", 1e-11)
    assert worst_q < 1e-14 and worst_e < 1e-14 and worst_ab < agreement, sc["name"]
    if sc["name"] == "sphere_world_torque":
        tau = np.array(sc["torque_world"])
        l0 = rot(ys[0][0:4]) @ I @ ys[0][4:7]
        err = max(np.abs(rot(y[0:4]) @ I @ y[4:7] - (l0 + tau * t)).max()
                  for t, y in zip(times, ys))
        print(f"  L_world vs L0 + tau t: {err:.1e}")
        assert err < 1e-13
    if sc["name"] == "point_force_gravity":
        a = (np.array(sc["force_world"]) + sc["point_force"]) / sc["mass"] + sc["gravity"]
        err = max(np.abs(y[7:10] - (np.array(sc["x0"]) + np.array(sc["v0"]) * t + 0.5 * a * t * t)).max()
                  for t, y in zip(times, ys))
        err /= max(np.abs(y[7:10]).max() for y in ys)
        print(f"  x vs x0 + v0 t + a t^2/2 (relative to max |x|): {err:.1e}")
        assert err < 1e-15


# --- run B: mpmath, Gragg-Bulirsch-Stoer extrapolation --------------------
# The same equations in pure Python on mpmath numbers (no numpy): a second,
# independent implementation at 32 digits.

def mp_rot(q):
    n = mp.sqrt(sum(x * x for x in q))
    w, x, y, z = (c / n for c in q)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def mv(m, v):
    return [sum(m[i][j] * v[j] for j in range(3)) for i in range(3)]


def mtv(m, v):
    return [sum(m[j][i] * v[j] for j in range(3)) for i in range(3)]


def mcross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def mdot(a, b):
    return sum(x * y for x, y in zip(a, b))


def mp_rotvec(q):
    n = mp.sqrt(sum(x * x for x in q))
    q = [c / n for c in q]
    if q[0] < 0:
        q = [-c for c in q]
    s = mp.sqrt(mdot(q[1:], q[1:]))
    if s == 0:
        return [mpf(0)] * 3
    k = 2 * mp.atan2(s, q[0]) / s
    return [k * c for c in q[1:]]


def mp_rhs(sc):
    I = [[mpf(x) for x in row] for row in sc["inertia"]]
    d = None if sc.get("pivot_body") is None else [-mpf(x) for x in sc["pivot_body"]]
    if d is not None:
        dd = mdot(d, d)
        I = [[I[i][j] + mpf(sc["mass"]) * ((dd if i == j else 0) - d[i] * d[j])
              for j in range(3)] for i in range(3)]
    Im = mp.matrix(I) ** -1
    Iinv = [[Im[i, j] for j in range(3)] for i in range(3)]
    vec = lambda key: [mpf(x) for x in sc[key]]  # noqa: E731
    m, g, c = mpf(sc["mass"]), vec("gravity"), mpf(sc["damping"])
    tw, tb, fw, r, fp = (vec("torque_world"), vec("torque_body"), vec("force_world"),
                         vec("point_body"), vec("point_force"))
    p = [mpf(x) for x in sc["law_params"]]

    def f(t, y):
        q, w, v = y[0:4], y[4:7], y[10:13]
        R = mp_rot(q)
        tau_law, f_law = [mpf(0)] * 3, [mpf(0)] * 3
        if sc["law"] == "magnet":
            b = [p[3] * mp.cos(p[4] * t), p[3] * mp.sin(p[4] * t), p[3] * p[5]]
            tau_law = mcross(mv(R, p[0:3]), b)
        elif sc["law"] == "pd":
            rv, ww = mp_rotvec(q), mv(R, w)
            tau_law = [-p[0] * a - p[1] * b for a, b in zip(rv, ww)]
        tau_b = [a + b + cc + d - c * e for a, b, cc, d, e in
                 zip(mtv(R, [x + y for x, y in zip(tw, tau_law)]), tb, mcross(r, mtv(R, fp)),
                     [mpf(0)] * 3, w)]
        force = [a + b + cc for a, b, cc in zip(fw, fp, f_law)]
        dq = [-(q[1] * w[0] + q[2] * w[1] + q[3] * w[2]) / 2,
              (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]) / 2,
              (q[0] * w[1] - q[1] * w[2] + q[3] * w[0]) / 2,
              (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]) / 2]
        if d is None:
            dw = mv(Iinv, [a + b for a, b in zip(mcross(mv(I, w), w), tau_b)])
            dv = [a / m + b for a, b in zip(force, g)]
        else:
            arm = mcross(d, mtv(R, [a + m * b for a, b in zip(force, g)]))
            dw = mv(Iinv, [a + b + cc for a, b, cc in zip(mcross(mv(I, w), w), tau_b, arm)])
            wd = mcross(w, d)
            v = mv(R, wd)
            dv = mv(R, [a + b for a, b in zip(mcross(w, wd), mcross(dw, d))])
        dW = mdot(tau_b, w) + mdot(force, v)
        return dq + dw + list(v) + dv + [dW]
    return f


def gbs_step(f, t, y, H, K):
    """One Gragg-Bulirsch-Stoer step: modified midpoint with n = 2, 4, ..., 2K
    substeps, extrapolated in h^2 to order 2K."""
    table = []
    for j in range(1, K + 1):
        n = 2 * j
        h = H / n
        z0 = y
        z1 = [a + h * b for a, b in zip(y, f(t, y))]
        for k in range(1, n):
            z0, z1 = z1, [a + 2 * h * b for a, b in zip(z0, f(t + k * h, z1))]
        last = f(t + H, z1)
        row = [[(a + b + h * c) / 2 for a, b, c in zip(z1, z0, last)]]
        for k in range(1, j):
            ratio = (mpf(n) / (n - 2 * k)) ** 2 - 1
            prev = table[-1][k - 1]
            row.append([a + (a - b) / ratio for a, b in zip(row[k - 1], prev)])
        table.append(row)
    return table[-1][-1]


def integrate_mp(sc, macro, K, dps):
    with mp.workdps(dps):
        f = mp_rhs(sc)
        q0 = [mpf(x) for x in sc["q0"]]
        n0 = mp.sqrt(sum(x * x for x in q0))
        q0 = [x / n0 for x in q0]
        w0 = [mpf(x) for x in sc["omega0"]]
        if sc.get("pivot_body") is None:
            xv = [mpf(x) for x in sc["x0"] + sc["v0"]]
        else:
            R0, d = mp_rot(q0), [-mpf(x) for x in sc["pivot_body"]]
            xv = ([a + b for a, b in zip([mpf(x) for x in sc["pivot_world"]], mv(R0, d))]
                  + mv(R0, mcross(w0, d)))
        y = q0 + w0 + xv + [mpf(0)]
        n = int(round(T_END / DT))
        per = int(round(DT / macro))
        H = mpf(DT) / per
        times = [k * DT for k in range(n + 1)]
        ys = [[float(x) for x in y]]
        ys_mp = [y]
        for k in range(n):
            t0 = mpf(times[k])
            for i in range(per):
                y = gbs_step(f, t0 + i * H, y, H, K)
            # restart each sample interval from the sample's f64 time
            ys.append([float(x) for x in y])
            ys_mp.append(y)
        return times, np.array(ys), ys_mp


def fmt(x):
    return repr(float(x))


def write(sc, times, ys):
    os.makedirs(OUT_DIR, exist_ok=True)
    path = os.path.join(OUT_DIR, sc["name"] + ".csv")
    lines = [f"# {sc['name']}: generated by tests/data/gen/forced.py "
             f"(mpmath {mpmath.__version__} Gragg-Bulirsch-Stoer, 32 digits; "
             f"checked against scipy {scipy.__version__} DOP853 at rtol = atol = {RTOL_A:g})"]
    flat = lambda v: " ".join(fmt(x) for x in np.ravel(v))  # noqa: E731
    for key in ["inertia", "mass", "gravity", "torque_world", "torque_body", "force_world",
                "point_body", "point_force", "damping", "law_params", "q0", "omega0", "x0", "v0",
                "pivot_body", "pivot_world"]:
        if key in sc:
            lines.append(f"# {key}: {flat(sc[key])}")
    lines.append(f"# law: {sc['law']}")
    lines.append(HEADER)
    for t, y in zip(times, ys):
        lines.append(",".join([fmt(t)] + [fmt(v) for v in y]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"  wrote {os.path.relpath(path)}")


def main(names):
    for mod, want in [(scipy, PINNED["scipy"]), (np, PINNED["numpy"]),
                      (mpmath, PINNED["mpmath"])]:
        if mod.__version__ != want:
            print(f"warning: {mod.__name__} {mod.__version__}, pinned {want}", file=sys.stderr)
    for sc in SCENARIOS:
        if names and sc["name"] not in names:
            continue
        print(sc["name"])
        times, ys_a = integrate(sc, RTOL_A)
        _, ys, ys_mp = integrate_mp(sc, 0.025, 10, 32)
        _, _, ys_c = integrate_mp(sc, 0.05, 12, 32)
        diff = max(abs(float(a - b)) for ya, yc in zip(ys_mp, ys_c) for a, b in zip(ya, yc))
        print(f"  mpmath macro step 0.025 (order 20) vs 0.05 (order 24): {diff:.1e}")
        assert diff <= 1e-15, sc["name"]
        check(sc, times, ys, ys_a)
        write(sc, times, ys)


if __name__ == "__main__":
    main(sys.argv[1:])
