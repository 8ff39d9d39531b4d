"""Generate high-precision reference trajectories of the heavy top (fixed pivot, uniform gravity).

Regenerate (from the repository root; needs only mpmath, pinned in
requirements.txt):

    python3 tests/data/gen/heavy_top.py [NAME ...]

Writes ../heavy_top/NAME.csv (relative to this script) for each scenario in
SCENARIOS (all of them when no NAME is given); prints timings and the checks.

Physics and conventions
-----------------------
* Body frame = the user's body axes (NOT principal axes: the inertia tensor is
  a full 3x3 matrix here, so the reference does not depend on a principal-axes
  decomposition). The pivot is the body-frame origin; c = centre of mass
  relative to the pivot (body frame); J_cm = inertia tensor about the centre of
  mass (body frame); J = J_cm + M (|c|^2 1 - c c^T) = inertia about the pivot.
* Gravity g_world = (0, 0, -g). gamma = R^T e_z (the world vertical in body
  axes, "Poisson vector").
* State: attitude quaternion q = world_from_body (scalar first, Hamilton),
  body-frame angular momentum about the pivot L, omega = J^-1 L.
* Equations (Euler-Poisson):
      dL/dt     = L x omega + M g gamma x c        (torque c x (M R^T g_world))
      dgamma/dt = gamma x omega
      dq/dt     = 1/2 q (x) (0, omega)
  All right-hand sides are quadratic, so Taylor coefficients follow exactly
  from Cauchy products (automatic differentiation).
* Invariants: E = 1/2 L.omega + M g c.gamma, L_world.e_z = L.gamma, |gamma| = 1,
  |q| = 1, and gamma = R(q)^T e_z; for a symmetric top with c on the symmetry
  axis n, also L.n (p_psi). The script asserts all of them.

Method and verification
-----------------------
Same as free_body.py: an explicit Taylor-series integrator, step size by the
Jorba-Zou rule, two independent runs (A: mp.dps 40, order 30, eps 1e-36;
B: mp.dps 60, order 44, eps 1e-54). The CSV holds run B rounded to f64; the
script asserts |A - B| <= 1e-24 (relative to max(1, |x|)) and the invariants of
run B to <= 1e-40. Inputs are exact f64 values (mpf(float) is exact); sample
times are the f64 nearest to k * dt.

Scenarios
---------
* bruls: the heavy-top benchmark of O. Bruls, A. Cardona, M. Arnold, "Lie
  group generalized-alpha time integration of constrained flexible multibody
  systems", Mech. Mach. Theory 48:121-137 (2012), sec. 6.1: M = 15 kg,
  J_cm = diag(0.234375, 0.46875, 0.234375) kg m^2, c = (0, 1, 0) m,
  g = 9.81 m/s^2, Omega0 = (0, 150, -4.61538) rad/s, R0 = identity, 2 s.
  (A Lagrange top: symmetric about body y, which carries the centre of mass.)
* asymmetric_fast: an asymmetric top, full J_cm, centre of mass off every
  principal axis, spinning at ~150 rad/s, 2 s.
* lagrange_slow: a symmetric top with a slow spin (large nutation, loops), 10 s.
* tumbling: an asymmetric top swinging and tumbling through large angles
  (no fast spin, chaotic), 5 s.
"""

import os
import sys
import time

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from free_body import (PINNED_MPMATH, f64, fmt, horner, qconj, qmul, qnorm,  # noqa: E402
                       sample_times, sci)

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir, "heavy_top"))

RUN_A = dict(dps=40, order=30, eps_exp=36)
RUN_B = dict(dps=60, order=44, eps_exp=54)
TOL_AB = mpf("1e-24")
TOL_INV = mpf("1e-40")

HEADER = "t,qw,qx,qy,qz,lx,ly,lz"

SCENARIOS = [
    dict(name="bruls",
         note="Bruls, Cardona & Arnold (2012) heavy-top benchmark (fast Lagrange top)",
         mass=15.0, inertia_cm=[[0.234375, 0, 0], [0, 0.46875, 0], [0, 0, 0.234375]],
         com=[0.0, 1.0, 0.0], g=9.81, omega0=[0.0, 150.0, -4.61538],
         q0=[1.0, 0.0, 0.0, 0.0], dt=(1, 100), t_end=2, symmetric_axis=[0, 1, 0]),
    dict(name="asymmetric_fast",
         note="asymmetric fast top, centre of mass off the principal axes",
         mass=2.0, inertia_cm=[[0.012, 0.001, -0.0005], [0.001, 0.02, 0.0015], [-0.0005, 0.0015, 0.016]],
         com=[0.01, -0.015, 0.12], g=9.81, omega0=[3.0, -2.0, 150.0],
         q0=[0.9, 0.3, -0.2, 0.1], dt=(1, 100), t_end=2),
    dict(name="lagrange_slow",
         note="slow symmetric top: large nutation with loops",
         mass=0.5, inertia_cm=[[0.002, 0, 0], [0, 0.002, 0], [0, 0, 0.003]],
         com=[0.0, 0.0, 0.08], g=9.81, omega0=[1.5, 0.0, 40.0],
         q0=[0.9238795325112867, 0.3826834323650898, 0.0, 0.0], dt=(1, 20), t_end=10,
         symmetric_axis=[0, 0, 1]),
    dict(name="tumbling",
         note="asymmetric top tumbling through large angles, no fast spin",
         mass=1.0, inertia_cm=[[0.01, 0.002, 0.0], [0.002, 0.02, -0.001], [0.0, -0.001, 0.025]],
         com=[0.05, 0.1, 0.2], g=9.81, omega0=[2.0, -3.0, 5.0],
         q0=[0.6, 0.5, -0.4, 0.3], dt=(1, 20), t_end=5),
]


def mat_vec(m, v):
    return tuple(sum(m[i][j] * v[j] for j in range(3)) for i in range(3))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def body_vertical(q):
    """gamma = R(q)^T e_z = q^-1 e_z q for a unit quaternion."""
    r = qmul(qmul(qconj(q), (mpf(0), mpf(0), mpf(0), mpf(1))), q)
    return (r[1], r[2], r[3])


def setup(sc):
    """(M g, c, J about the pivot, J^-1, L0, q0) at the current precision from exact f64 inputs."""
    M = mpf(sc["mass"])
    mg = M * mpf(sc["g"])
    c = tuple(mpf(x) for x in sc["com"])
    Jcm = mp.matrix([[mpf(x) for x in row] for row in sc["inertia_cm"]])
    cc = dot(c, c)
    J = mp.matrix(3, 3)
    for i in range(3):
        for j in range(3):
            J[i, j] = Jcm[i, j] + M * ((cc if i == j else 0) - c[i] * c[j])
    Jinv = J ** -1
    Jl = [[J[i, j] for j in range(3)] for i in range(3)]
    Jinvl = [[Jinv[i, j] for j in range(3)] for i in range(3)]
    w0 = tuple(mpf(x) for x in sc["omega0"])
    L0 = mat_vec(Jl, w0)
    q = tuple(mpf(x) for x in sc["q0"])
    n = qnorm(q)
    q0 = tuple(x / n for x in q)
    return mg, c, Jl, Jinvl, L0, q0


def taylor_coeffs(L, gam, q, Jinv, mg, c, N):
    """Taylor coefficients (orders 0..N) of L, gamma and q at the current point."""
    Lc, gc, qc = [L], [gam], [q]
    wc = [mat_vec(Jinv, L)]
    for k in range(N):
        lx = ly = lz = mpf(0)
        gx = gy = gz = mpf(0)
        pw = px = py = pz = mpf(0)
        for j in range(k + 1):
            a0, a1, a2 = Lc[j]
            b0, b1, b2 = wc[k - j]
            lx += a1 * b2 - a2 * b1
            ly += a2 * b0 - a0 * b2
            lz += a0 * b1 - a1 * b0
            g0, g1, g2 = gc[j]
            gx += g1 * b2 - g2 * b1
            gy += g2 * b0 - g0 * b2
            gz += g0 * b1 - g1 * b0
            w, x, y, z = qc[j]
            pw -= x * b0 + y * b1 + z * b2
            px += w * b0 + y * b2 - z * b1
            py += w * b1 - x * b2 + z * b0
            pz += w * b2 + x * b1 - y * b0
        tq = cross(gc[k], c)   # linear term: M g gamma_k x c
        f = mpf(1) / (k + 1)
        Ln = ((lx + mg * tq[0]) * f, (ly + mg * tq[1]) * f, (lz + mg * tq[2]) * f)
        Lc.append(Ln)
        wc.append(mat_vec(Jinv, Ln))
        gc.append((gx * f, gy * f, gz * f))
        f /= 2
        qc.append((pw * f, px * f, py * f, pz * f))
    return Lc, gc, qc


def integrate(sc, dps, order, eps_exp):
    with mp.workdps(dps):
        mg, c, J, Jinv, L, q = setup(sc)
        gam = body_vertical(q)
        scale = max(mpf(1), mp.sqrt(dot(L, L)))
        eps = mpf(10) ** (-eps_exp)
        times = [mpf(t) for t in sample_times(sc)]
        states = [(q, L, gam)]
        t = times[0]
        steps = 0
        for t_next in times[1:]:
            while t < t_next:
                Lc, gc, qc = taylor_coeffs(L, gam, q, Jinv, mg, c, order)
                h = t_next - t
                for k in (order - 1, order):
                    r = max(max(abs(x) for x in Lc[k]) / scale, max(abs(x) for x in gc[k]),
                            max(abs(x) for x in qc[k]))
                    if r > 0:
                        h = min(h, (eps / r) ** (mpf(1) / k))
                L, gam, q = horner(Lc, h), horner(gc, h), horner(qc, h)
                t = t_next if h == t_next - t else t + h
                steps += 1
            states.append((q, L, gam))
        return states, steps


def invariants(sc, q, L, gam):
    mg, c, J, Jinv, _, _ = setup(sc)
    w = mat_vec(Jinv, L)
    out = dict(E=dot(L, w) / 2 + mg * dot(c, gam), Lz=dot(L, gam), gnorm=mp.sqrt(dot(gam, gam)),
               qnorm=qnorm(q), gq=max(abs(a - b) for a, b in zip(gam, body_vertical(q))))
    if "symmetric_axis" in sc:
        out["ppsi"] = dot(L, tuple(mpf(x) for x in sc["symmetric_axis"]))
    return out


def run_scenario(sc):
    t0 = time.perf_counter()
    stA, nA = integrate(sc, **RUN_A)
    stB, nB = integrate(sc, **RUN_B)
    with mp.workdps(RUN_B["dps"]):
        dAB = mpf(0)
        for (qa, La, _), (qb, Lb, _) in zip(stA, stB):
            for x, y in zip(qa + La, qb + Lb):
                dAB = max(dAB, abs(x - y) / max(1, abs(y)))
        assert dAB <= TOL_AB, (sc["name"], dAB)
        inv0 = invariants(sc, *stB[0])
        drift = {k: mpf(0) for k in inv0}
        for q, L, gam in stB:
            inv = invariants(sc, q, L, gam)
            for k in inv:
                if k in ("gnorm", "qnorm"):
                    d = abs(inv[k] - 1)
                elif k == "gq":
                    d = inv[k]
                else:
                    d = abs(inv[k] - inv0[k]) / max(1, abs(inv0[k]))
                drift[k] = max(drift[k], d)
        for k, d in drift.items():
            assert d <= TOL_INV, (sc["name"], k, d)
    write_csv(sc, stB, inv0, dAB, drift)
    return dict(name=sc["name"], seconds=time.perf_counter() - t0, stepsA=nA, stepsB=nB, dAB=dAB,
                drift=drift)


def write_csv(sc, states, inv0, dAB, drift):
    with mp.workdps(RUN_B["dps"]):
        mg, c, J, Jinv, L0, q0 = setup(sc)
        lines = [
            "# generated by tests/data/gen/heavy_top.py (mpmath %s) -- do not edit" % mpmath.__version__,
            "# heavy top, pivot at the body origin: dL/dt = L x omega + c x (M R^T g_world), "
            "omega = J^-1 L, dq/dt = 1/2 q (x) (0, omega); q = world_from_body (w, x, y, z); "
            "L = body-frame angular momentum about the pivot",
            "# scenario %s: %s" % (sc["name"], sc["note"]),
            "# mass = %r" % sc["mass"],
            "# inertia_cm = (%s)" % ", ".join(repr(float(x)) for row in sc["inertia_cm"] for x in row),
            "# com = (%s)" % ", ".join(repr(x) for x in sc["com"]),
            "# gravity = (0.0, 0.0, %r)" % -sc["g"],
            "# omega0 = (%s)" % ", ".join(repr(x) for x in sc["omega0"]),
            "# q0 = (%s)" % ", ".join(repr(x) for x in sc["q0"]),
            "# inertia_pivot = (%s)" % ", ".join(fmt(x) for row in J for x in row),
            "# energy = %s" % fmt(inv0["E"]),
            "# l_world_z = %s" % fmt(inv0["Lz"]),
        ]
        if "ppsi" in inv0:
            lines.append("# symmetric_axis = (%s); l_axis = %s"
                         % (", ".join(repr(float(x)) for x in sc["symmetric_axis"]), fmt(inv0["ppsi"])))
        lines.append("# method: Taylor series in mpmath, dps %d order %d eps 1e-%d; cross-checked with dps %d "
                     "order %d eps 1e-%d: max |diff|/max(1,|x|) = %s; invariant drift of the reference: %s"
                     % (RUN_B["dps"], RUN_B["order"], RUN_B["eps_exp"], RUN_A["dps"], RUN_A["order"],
                        RUN_A["eps_exp"], sci(dAB), ", ".join("%s %s" % (k, sci(v)) for k, v in drift.items())))
        lines.append(HEADER)
        for t, (q, L, _) in zip(sample_times(sc), states):
            lines.append(",".join([repr(t)] + [fmt(x) for x in q + L]))
    with open(os.path.join(OUT_DIR, sc["name"] + ".csv"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main():
    if mpmath.__version__ != PINNED_MPMATH:
        print("warning: mpmath %s, pinned %s" % (mpmath.__version__, PINNED_MPMATH), file=sys.stderr)
    os.makedirs(OUT_DIR, exist_ok=True)
    only = set(sys.argv[1:])
    t0 = time.perf_counter()
    for sc in SCENARIOS:
        if only and sc["name"] not in only:
            continue
        r = run_scenario(sc)
        print("%-16s %6.1fs steps A/B %5d/%5d |A-B| %s drift %s"
              % (r["name"], r["seconds"], r["stepsA"], r["stepsB"], sci(r["dAB"]),
                 ", ".join("%s %s" % (k, sci(v)) for k, v in r["drift"].items())))
    print("total %.1f s" % (time.perf_counter() - t0))


if __name__ == "__main__":
    main()
