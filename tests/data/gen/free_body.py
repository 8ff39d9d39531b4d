"""Generate high-precision reference trajectories of the torque-free rigid body.

Regenerate (from the repository root; needs only mpmath, pinned in
requirements.txt):

    python3 tests/data/gen/free_body.py

It takes about 2 minutes on one core of the project machine (the time is printed
at the end). Writes, relative to this script's location:

    ../free_body/NAME.csv      one trajectory per scenario (see SCENARIOS)
    ../free_body/periods.csv   period of omega(t) and time between flips

Physics and conventions
-----------------------
* Principal moments I = (I1, I2, I3); the body axes are the principal axes.
* State: attitude quaternion q = world_from_body (v_world = q v_body q^-1),
  scalar first (w, x, y, z), Hamilton product; body-frame angular momentum
  L = (lx, ly, lz), omega_body = L / I componentwise.
* Euler's equations  dL/dt = L x omega;  attitude  dq/dt = 1/2 q (x) (0, omega).
* Invariants: E = 1/2 sum L_i^2 / I_i, |L|, L_world = q L q^-1, |q| = 1.

Inputs are exact binary numbers
-------------------------------
Every input (I, omega0 or L0, q0, the sample times) is an f64 and the comment
lines give it with repr(float); all computation starts from those exact binary
values (mpf(float) is exact), never from the decimal literal. Where the input is
omega0, L0 = I * omega0 is formed exactly in mpmath (it is NOT rounded to f64).
The sample time t written in the CSV is the f64 nearest to k * dt, and the state
is computed at exactly that binary time. A non-trivial q0 is normalised in
mpmath from the given decimals' f64 values, rounded to f64 (the value written
in the comments), and the reference then starts from that rounded f64 q0
renormalised in mpmath (so the first row may differ from the comment's q0 by
less than 1 ulp, usually not at all).

Method and verification
-----------------------
* Main method: an explicit Taylor-series integrator written here in mpmath.
  The system is quadratic, so the Taylor coefficients follow from Cauchy
  products (automatic differentiation) exactly; step size by the Jorba-Zou rule
  h = min_k (eps / |c_k|)^(1/k), k in {N-1, N}, so that the last two terms of
  the series are <= eps (relative to max(1, |L|) for L). Steps end exactly on
  the sample times.
* Two independent runs at different resolution: run A (mp.dps = 40, order 30,
  eps = 1e-36) and run B (mp.dps = 60, order 44, eps = 1e-54). The CSV holds
  run B rounded to f64; the script asserts |A - B| <= 1e-24 for every number.
* Invariants (E, |L|, L_world, |q|) of run B are asserted to <= 1e-40 (relative
  to max(1,|L|) resp. E).
* Independent closed forms (no integration involved):
  - asymmetric bodies: omega(t) by Jacobi elliptic functions (mpmath ellipfun),
    and the attitude by q(t) = G (x) qz(psi(t)) (x) qx(theta(t)) (x) qz(phi(t)) (x) P
    (3-1-3 Euler angles about the constant L_world, psi from the quadrature
    psi' = |L| (L_a^2/I_a + L_b^2/I_b) / (L_a^2 + L_b^2), mpmath quad); the
    sign changes of omega2 found by root finding on the Taylor polynomials of
    run B are compared with the closed-form crossing times (2 n K - tau0) / lam;
  - symmetric body I1 = I2: q(t) = exp(t L_world / (2 I1)) (x) q0 (x) exp(-Omega t e3 / 2),
    Omega = (I3 - I1) / I1 * omega3, L_body(t) = Rz(Omega t) L0;
  - sphere: q(t) = q0 (x) exp(t omega0 / 2), L constant.
  All are asserted to agree with run B to <= 1e-24.

Elliptic solution (Landau & Lifshitz, Mechanics, sec. 37), I1 < I2 < I3:
  if |L|^2 > 2 E I2 (L circulates about e3):
    omega1 = A1 cn u, omega2 = A2 sn u, omega3 = A3 dn u,
    lam^2 = (I3 - I2)(|L|^2 - 2 E I1) / (I1 I2 I3),
    m = (I2 - I1)(2 E I3 - |L|^2) / ((I3 - I2)(|L|^2 - 2 E I1)),
  if |L|^2 < 2 E I2 (L circulates about e1): swap the indices 1 and 3:
    omega1 = A1 dn u, omega2 = A2 sn u, omega3 = A3 cn u,
    lam^2 = (I2 - I1)(2 E I3 - |L|^2) / (I1 I2 I3),
    m = (I3 - I2)(|L|^2 - 2 E I1) / ((I2 - I1)(2 E I3 - |L|^2)),
  with u = lam t + tau0, complementary parameter
    m' = 1 - m = (I3 - I1) |2 E I2 - |L|^2| / ((I2 - I1)(2 E I3 - |L|^2))  (e1 side).
  sn, cn have period 4K(m) in u, dn has 2K(m). Hence the period of omega(t) is
  4 K(m) / lam and omega2 changes sign every 2 K(m) / lam (time between flips).

The script is deterministic and checks itself with assertions.
"""

import os
import sys
import time

import mpmath
from mpmath import libmp, mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir, "free_body"))

PINNED_MPMATH = "1.3.0"

RUN_A = dict(dps=40, order=30, eps_exp=36)
RUN_B = dict(dps=60, order=44, eps_exp=54)
TOL_AB = mpf("1e-24")          # |run A - run B| for every output number
TOL_INV = mpf("1e-40")         # invariant drift of run B (relative)
TOL_CLOSED = mpf("1e-24")      # closed forms vs run B
CHECK_DPS = 40                 # precision of the closed-form checks

HEADER = "t,qw,qx,qy,qz,lx,ly,lz"


# --------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------

def f64(x):
    """Correctly rounded (round-to-nearest-even) f64 value of an mpf."""
    x = mpf(x)
    return libmp.to_float(x._mpf_, strict=True, rnd=libmp.round_nearest)


def fmt(x):
    return repr(f64(x))


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


def qrot(q, v):
    """q v q^-1 for a unit quaternion q."""
    r = qmul(qmul(q, (mpf(0), v[0], v[1], v[2])), qconj(q))
    return (r[1], r[2], r[3])


def qnorm(q):
    return mp.sqrt(sum(c * c for c in q))


def qexp(v):
    """Unit quaternion of the rotation vector v (angle |v|): (cos |v|/2, sin |v|/2 v/|v|)."""
    a = mp.sqrt(sum(c * c for c in v))
    if a == 0:
        return (mpf(1), mpf(0), mpf(0), mpf(0))
    s = mp.sin(a / 2) / a
    return (mp.cos(a / 2), s * v[0], s * v[1], s * v[2])


def qaxis(i, angle):
    """Rotation by angle about coordinate axis i (0, 1, 2)."""
    q = [mp.cos(angle / 2), mpf(0), mpf(0), mpf(0)]
    q[1 + i] = mp.sin(angle / 2)
    return tuple(q)


def quat_from_matrix(m):
    """Unit quaternion (w >= 0 branch where possible) of a proper rotation matrix."""
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > -mpf(0.5):
        s = 2 * mp.sqrt(1 + tr)
        return (s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s,
                (m[1][0] - m[0][1]) / s)
    raise ValueError("only needed for the identity and the cyclic permutation")


def energy(L, I):
    return sum(L[i] ** 2 / I[i] for i in range(3)) / 2


def vnorm(v):
    return mp.sqrt(sum(c * c for c in v))


def vmaxdiff(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


# --------------------------------------------------------------------------
# scenarios
# --------------------------------------------------------------------------

def near_separatrix_L0(target_mc):
    """L0 = (a, -0.9, c) with |L| ~ 1 and complementary parameter m' ~ target_mc
    on the e1 side (|L|^2 < 2 E I2) for I = (1, 2, 3); a, c rounded to f64.

    For I = (1, 2, 3): 2 E I2 - |L|^2 = a^2 - c^2 / 3 =: delta and
    m' = 2 delta / (2 E I3 - |L|^2), 2 E I3 - |L|^2 = 2 a^2 + b^2 / 2.
    """
    with mp.workdps(50):
        b = mpf(-0.9)
        s = 1 - b * b                       # a^2 + c^2
        # solve m' = target for delta with a^2 = (s + 3 delta) / 4
        delta = mpf(0)
        for _ in range(50):
            a2 = (s + 3 * delta) / 4
            delta = target_mc * (2 * a2 + b * b / 2) / 2
        a2 = (s + 3 * delta) / 4
        a = f64(mp.sqrt(a2))
        c = f64(mp.sqrt(s - mpf(a) ** 2))
    return (a, f64(b), c)


def ratio_q0():
    with mp.workdps(50):
        raw = [mpf(x) for x in (0.9, 0.1, -0.3, 0.2)]
        n = qnorm(raw)
        return tuple(f64(c / n) for c in raw)


def hlw_L0():
    with mp.workdps(50):
        return (f64(mp.cos(mpf(1.1))), 0.0, f64(mp.sin(mpf(1.1))))


IDENT = (1.0, 0.0, 0.0, 0.0)

SCENARIOS = [
    dict(name="rapier", I=(1.0, 2.0, 3.0), omega0=(0.01, 1.0, 0.0), q0=IDENT,
         t_end=100, dt=(1, 2),
         note="Dzhanibekov flip near the intermediate axis (L circulates about e1)"),
    dict(name="hlw", I=(0.5, 0.85, 1.0), L0=hlw_L0(),
         q0=IDENT, t_end=20, dt=(1, 2),
         note="Hairer-Lubich-Wanner (Geometric Numerical Integration) free rigid body; "
              "L0 = (cos 1.1, 0, sin 1.1) rounded to f64 (1.1 as the f64 1.1)"),
    dict(name="near_separatrix_7", I=(1.0, 2.0, 3.0), L0=near_separatrix_L0(mpf("1e-7")),
         q0=IDENT, t_end=20, dt=(1, 2),
         note="|L| ~ 1 just inside the separatrix on the e1 side (|L|^2 < 2 E I2, L circulates "
              "about the minor axis e1, omega1 > 0 throughout); complementary parameter m' ~ 1e-7; "
              "starts at omega2 = -0.45, omega2 crosses 0 near t = 5 s and then creeps "
              "towards the saddle +e2"),
    dict(name="near_separatrix_12", I=(1.0, 2.0, 3.0), L0=near_separatrix_L0(mpf("1e-12")),
         q0=IDENT, t_end=20, dt=(1, 2),
         note="as near_separatrix_7 with complementary parameter m' ~ 1e-12"),
    dict(name="ratio_1000", I=(0.001, 1.0, 1.0005), omega0=(3.0, 0.2, -0.1), q0=ratio_q0(),
         t_end=5, dt=(1, 10),
         note="thin rod, I3/I1 ~ 1000 (I1 + I2 >= I3 holds); q0 = normalised (0.9, 0.1, -0.3, 0.2)"),
    dict(name="ratio_1000b", I=(1.0, 999.0, 1000.0), omega0=(0.5, 0.01, 0.02), q0=ratio_q0(),
         t_end=5, dt=(1, 10),
         note="flat disc-like body, I3/I1 = 1000; q0 = normalised (0.9, 0.1, -0.3, 0.2)"),
    dict(name="separatrix", I=(3.0, 4.0, 6.0), omega0=(0.5, 0.2, 0.25), q0=ratio_q0(),
         t_end=20, dt=(1, 2), closed=False,
         note="exactly on the separatrix: L0 = (1.5, 0.8, 1.5) gives |L|^2 = 2 E I2 in exact "
              "arithmetic (L1 = L3 with (I2-I1)/I1 = (I3-I2)/I3 = 1/3); L tends to the saddle +e2; "
              "no elliptic closed form (m = 1), checked by the two Taylor runs only"),
    dict(name="symmetric", I=(1.0, 1.0, 2.0), omega0=(0.3, 0.0, 5.0), q0=IDENT,
         t_end=20, dt=(1, 2),
         note="symmetric top I1 = I2: closed form q(t) = exp(t L_world/(2 I1)) q0 exp(-Omega t e3/2), "
              "Omega = (I3 - I1)/I1 omega3 = 5 rad/s"),
    dict(name="sphere", I=(2.0, 2.0, 2.0), omega0=(0.3, -0.2, 1.1), q0=IDENT,
         t_end=20, dt=(1, 1),
         note="spherical body: uniform rotation q(t) = q0 exp(t omega0/2)"),
]


def sample_times(sc):
    """Exact f64 sample times: the f64 nearest to k * dt."""
    from fractions import Fraction
    num, den = sc["dt"]
    n = int(Fraction(sc["t_end"]) / Fraction(num, den))
    return [float(Fraction(k * num, den)) for k in range(n + 1)]


def initial_state(sc):
    """(I, L0, q0) as mpf at the current precision, from the exact f64 inputs."""
    I = tuple(mpf(x) for x in sc["I"])
    if "omega0" in sc:
        L0 = tuple(I[i] * mpf(sc["omega0"][i]) for i in range(3))   # exact product
    else:
        L0 = tuple(mpf(x) for x in sc["L0"])
    q = tuple(mpf(x) for x in sc["q0"])
    n = qnorm(q)
    q0 = tuple(c / n for c in q)
    return I, L0, q0


# --------------------------------------------------------------------------
# Taylor integrator
# --------------------------------------------------------------------------

def taylor_coeffs(L, q, Iinv, N):
    """Taylor coefficients (orders 0..N) of L(t) and q(t) at the current point."""
    Lc = [L]
    wc = [(L[0] * Iinv[0], L[1] * Iinv[1], L[2] * Iinv[2])]
    qc = [q]
    for k in range(N):
        sx = sy = sz = mpf(0)
        pw = px = py = pz = mpf(0)
        for j in range(k + 1):
            a0, a1, a2 = Lc[j]
            b0, b1, b2 = wc[k - j]
            sx += a1 * b2 - a2 * b1
            sy += a2 * b0 - a0 * b2
            sz += a0 * b1 - a1 * b0
            w, x, y, z = qc[j]
            # (w, x, y, z) (x) (0, b)
            pw -= x * b0 + y * b1 + z * b2
            px += w * b0 + y * b2 - z * b1
            py += w * b1 - x * b2 + z * b0
            pz += w * b2 + x * b1 - y * b0
        f = mpf(1) / (k + 1)
        Ln = (sx * f, sy * f, sz * f)
        Lc.append(Ln)
        wc.append((Ln[0] * Iinv[0], Ln[1] * Iinv[1], Ln[2] * Iinv[2]))
        f /= 2
        qc.append((pw * f, px * f, py * f, pz * f))
    return Lc, qc


def horner(coeffs, h):
    acc = [mpf(0)] * len(coeffs[0])
    for c in reversed(coeffs):
        acc = [a * h + ci for a, ci in zip(acc, c)]
    return tuple(acc)


def poly_root(c, h, tol):
    """Root in (0, h) of p(s) = sum c_k s^k, p(0) p(h) < 0 (safeguarded Newton)."""
    def p(s):
        v = mpf(0)
        d = mpf(0)
        for ck in reversed(c):
            d = d * s + v
            v = v * s + ck
        return v, d
    lo, hi = mpf(0), h
    plo = p(lo)[0]
    s = h / 2
    for _ in range(400):
        v, d = p(s)
        if v == 0:
            return s
        if (v > 0) == (plo > 0):
            lo = s
        else:
            hi = s
        s_new = s - v / d if d != 0 else (lo + hi) / 2
        if not (lo < s_new < hi):
            s_new = (lo + hi) / 2
        if abs(s_new - s) < tol:
            return s_new
        s = s_new
    raise RuntimeError("root finding did not converge")


def integrate(sc, dps, order, eps_exp):
    """Integrate one scenario; returns (states, events, stats) as mpf at precision dps.

    states[k] = (q, L) at the k-th sample time; events = times where L2 changes sign.
    """
    with mp.workdps(dps):
        I, L, q = initial_state(sc)
        Iinv = tuple(1 / x for x in I)
        Lscale = max(mpf(1), vnorm(L))
        eps = mpf(10) ** (-eps_exp)
        times = [mpf(t) for t in sample_times(sc)]
        states = [(q, L)]
        events = []
        t = times[0]
        nsteps = 0
        max_tail = mpf(0)
        for t_next in times[1:]:
            while t < t_next:
                Lc, qc = taylor_coeffs(L, q, Iinv, order)
                h = t_next - t
                for k in (order - 1, order):
                    r = max(max(abs(c) for c in Lc[k]) / Lscale, max(abs(c) for c in qc[k]))
                    if r > 0:
                        h = min(h, (eps / r) ** (mpf(1) / k))
                tail = mpf(0)
                for k in (order - 1, order):
                    r = max(max(abs(c) for c in Lc[k]) / Lscale, max(abs(c) for c in qc[k]))
                    tail += r * h ** k
                max_tail = max(max_tail, tail)
                L_new = horner(Lc, h)
                q_new = horner(qc, h)
                if L[1] != 0 and L_new[1] != 0 and (L[1] > 0) != (L_new[1] > 0):
                    c2 = [c[1] for c in Lc]
                    events.append(t + poly_root(c2, h, mpf(10) ** (-dps + 5)))
                L, q = L_new, q_new
                t = t_next if h == t_next - t else t + h
                nsteps += 1
            states.append((q, L))
        return states, events, dict(steps=nsteps, max_tail=max_tail)


# --------------------------------------------------------------------------
# closed forms
# --------------------------------------------------------------------------

def elliptic_params(I, L0):
    """Parameters of the elliptic solution for I1 < I2 < I3 (see module docstring)."""
    I1, I2, I3 = I
    assert I1 < I2 < I3
    L2n = sum(c * c for c in L0)
    E2 = 2 * energy(L0, I)
    w0 = [L0[i] / I[i] for i in range(3)]
    if L2n < E2 * I2:           # circulates about e1: omega1 = A1 dn, omega3 = A3 cn
        c, o = 0, 2
        A = [mp.sqrt((E2 * I3 - L2n) / (I1 * (I3 - I1))),
             mp.sqrt((L2n - E2 * I1) / (I2 * (I2 - I1))),
             mp.sqrt((L2n - E2 * I1) / (I3 * (I3 - I1)))]
        lam = mp.sqrt((I2 - I1) * (E2 * I3 - L2n) / (I1 * I2 * I3))
        m = (I3 - I2) * (L2n - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2n))
    else:                       # circulates about e3: omega1 = A1 cn, omega3 = A3 dn
        c, o = 2, 0
        A = [mp.sqrt((E2 * I3 - L2n) / (I1 * (I3 - I1))),
             mp.sqrt((E2 * I3 - L2n) / (I2 * (I3 - I2))),
             mp.sqrt((L2n - E2 * I1) / (I3 * (I3 - I1)))]
        lam = mp.sqrt((I3 - I2) * (L2n - E2 * I1) / (I1 * I2 * I3))
        m = (I2 - I1) * (E2 * I3 - L2n) / ((I3 - I2) * (L2n - E2 * I1))
    mc = (I3 - I1) * abs(E2 * I2 - L2n) / ((I2 - I1) * (E2 * I3 - L2n))
    if c == 2:
        mc = (I3 - I1) * abs(E2 * I2 - L2n) / ((I3 - I2) * (L2n - E2 * I1))
    assert abs((1 - m) - mc) <= mpf(10) ** (-mp.dps + 10)
    s_c = 1 if w0[c] > 0 else -1
    sign = [0, 0, 0]
    sign[c], sign[1], sign[o] = s_c, s_c, 1          # Euler eqs need sign1 sign3 = sign2
    sn0 = w0[1] / (sign[1] * A[1])
    cn0 = w0[o] / (sign[o] * A[o])
    tau0 = mp.ellipf(mp.atan2(sn0, cn0), m)
    K = mp.ellipk(m)
    return dict(c=c, o=o, A=A, lam=lam, m=m, mc=mc, sign=sign, tau0=tau0, K=K,
                dist=(E2 * I2 - L2n) / L2n)


def elliptic_L(I, P, t):
    u = P["lam"] * t + P["tau0"]
    sn = mp.ellipfun("sn", u, P["m"])
    cn = mp.ellipfun("cn", u, P["m"])
    dn = mp.ellipfun("dn", u, P["m"])
    f = [None, sn, None]
    f[P["c"]] = dn
    f[P["o"]] = cn
    return tuple(I[i] * P["sign"][i] * P["A"][i] * f[i] for i in range(3))


def elliptic_attitude(I, L0, q0, P, times):
    """Attitude from the 3-1-3 Euler angles about L_world (module docstring)."""
    Lmag = vnorm(L0)
    if P["c"] == 0:     # Euler frame C = (e2, e3, e1): v_C = (v2, v3, v1)
        perm = (1, 2, 0)
        M = [[0, 1, 0], [0, 0, 1], [1, 0, 0]]
    else:
        perm = (0, 1, 2)
        M = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    Mq = quat_from_matrix([[mpf(x) for x in row] for row in M])
    ia, ib, ic = perm

    def angles(L):
        theta = mp.acos(L[ic] / Lmag)
        phi = mp.atan2(L[ia], L[ib])
        return theta, phi

    def psidot(t):
        L = elliptic_L(I, P, t)
        return Lmag * (L[ia] ** 2 / I[ia] + L[ib] ** 2 / I[ib]) / (L[ia] ** 2 + L[ib] ** 2)

    th0, ph0 = angles(L0)
    G = qmul(qmul(qmul(q0, qconj(Mq)), qaxis(2, -ph0)), qaxis(0, -th0))
    out = []
    psi = mpf(0)
    max_qerr = mpf(0)
    prev = times[0]
    for t in times:
        if t != prev:
            val, err = mp.quad(psidot, [prev, t], method="gauss-legendre", error=True)
            psi += val
            max_qerr = max(max_qerr, err)
            prev = t
        L = elliptic_L(I, P, t)
        th, ph = angles(L)
        q = qmul(qmul(qmul(qmul(G, qaxis(2, psi)), qaxis(0, th)), qaxis(2, ph)), Mq)
        out.append((q, L))
    return out, max_qerr


def closed_symmetric(I, L0, q0, times):
    Lw = qrot(q0, L0)
    Om = (I[2] - I[0]) / I[0] * (L0[2] / I[2])
    out = []
    for t in times:
        q = qmul(qmul(qexp(tuple(t * c / I[0] for c in Lw)), q0), qexp((0, 0, -Om * t)))
        L = qrot(qconj(q), Lw)
        Lz = qrot(qaxis(2, Om * t), L0)          # body-frame precession of L at rate Omega
        assert vmaxdiff(L, Lz) < mpf(10) ** (-mp.dps + 8)
        out.append((q, L))
    return out


def closed_sphere(I, L0, q0, times):
    w = tuple(L0[i] / I[i] for i in range(3))
    return [(qmul(q0, qexp(tuple(t * c for c in w))), L0) for t in times]


def qdiff_signed(a, b):
    """max |a - b| over components, allowing the closed form's overall sign."""
    return min(vmaxdiff(a, b), vmaxdiff(a, tuple(-c for c in b)))


# --------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------

def rel_invariant_drift(states, I, L0, q0):
    E0 = energy(L0, I)
    n0 = vnorm(L0)
    Lw0 = qrot(q0, L0)
    Ls = max(mpf(1), n0)
    dE = dn = dw = dq = mpf(0)
    for q, L in states:
        dE = max(dE, abs(energy(L, I) - E0) / E0)
        dn = max(dn, abs(vnorm(L) - n0) / Ls)
        qn = qnorm(q)
        dq = max(dq, abs(qn - 1))
        qu = tuple(c / qn for c in q)
        dw = max(dw, vmaxdiff(qrot(qu, L), Lw0) / Ls)
    return dict(E=dE, Lnorm=dn, Lworld=dw, qnorm=dq)


def sci(x):
    return mp.nstr(mpf(x), 3, min_fixed=1, max_fixed=0) if x != 0 else "0"


def run_scenario(sc):
    t0 = time.perf_counter()
    times_f = sample_times(sc)
    stA, evA, statA = integrate(sc, **RUN_A)
    stB, evB, statB = integrate(sc, **RUN_B)
    with mp.workdps(RUN_B["dps"]):
        I, L0, q0 = initial_state(sc)
        # A vs B
        dAB = mpf(0)
        dAB_rel = mpf(0)
        for (qa, La), (qb, Lb) in zip(stA, stB):
            for x, y in zip(qa + La, qb + Lb):
                dAB = max(dAB, abs(x - y))
                dAB_rel = max(dAB_rel, abs(x - y) / max(1, abs(y)))
        inv = rel_invariant_drift(stB, I, L0, q0)
        invA = rel_invariant_drift(stA, I, L0, q0)
    assert dAB_rel <= TOL_AB, (sc["name"], dAB_rel)
    for k, v in inv.items():
        assert v <= TOL_INV, (sc["name"], k, v)
    for k, v in invA.items():
        assert v <= mpf("1e-30"), (sc["name"], "run A", k, v)
    # sign continuity: consecutive samples on the same hemisphere, q0 w > 0
    min_dot = min(sum(a * b for a, b in zip(stB[k][0], stB[k + 1][0])) for k in range(len(stB) - 1))
    assert stB[0][0][0] > 0 and min_dot > 0

    res = dict(name=sc["name"], dAB=dAB, dAB_rel=dAB_rel, inv=inv, invA=invA,
               stepsA=statA["steps"], stepsB=statB["steps"], tailA=statA["max_tail"],
               tailB=statB["max_tail"], min_dot=min_dot)

    # closed forms
    with mp.workdps(CHECK_DPS):
        I, L0, q0 = initial_state(sc)
        times = [mpf(t) for t in times_f]
        if not sc.get("closed", True):
            closed = stB
        elif I[0] < I[1] < I[2]:
            P = elliptic_params(I, L0)
            closed, qerr = elliptic_attitude(I, L0, q0, P, times)
            res["P"] = P
            res["quad_err"] = qerr
            # omega2 sign changes: closed form t_n = (2 n K - tau0) / lam
            pred = []
            n = mp.ceil(P["tau0"] / (2 * P["K"]))
            while True:
                tn = (2 * n * P["K"] - P["tau0"]) / P["lam"]
                if tn > times[-1]:
                    break
                if tn > 0:
                    pred.append(tn)
                n += 1
            assert len(pred) == len(evB) == len(evA), (sc["name"], pred, evB)
            res["events"] = evB
            res["event_err"] = max([abs(a - b) for a, b in zip(pred, evB)] + [mpf(0)])
            res["event_errA"] = max([abs(a - b) for a, b in zip(evA, evB)] + [mpf(0)])
        elif I[0] == I[1] == I[2]:
            closed = closed_sphere(I, L0, q0, times)
        else:
            assert I[0] == I[1]
            closed = closed_symmetric(I, L0, q0, times)
        dq = dL = mpf(0)
        for (qc, Lc), (qb, Lb) in zip(closed, stB):
            dq = max(dq, qdiff_signed(qb, qc))
            dL = max(dL, vmaxdiff(Lb, Lc) / max(1, vnorm(L0)))
        res["closed_q"] = dq
        res["closed_L"] = dL
    assert dq <= TOL_CLOSED and dL <= TOL_CLOSED, (sc["name"], dq, dL)
    if "event_err" in res:
        assert res["event_err"] <= TOL_CLOSED and res["event_errA"] <= TOL_AB

    write_csv(sc, times_f, stB, res)
    res["seconds"] = time.perf_counter() - t0
    return res


def write_csv(sc, times_f, states, res):
    with mp.workdps(RUN_B["dps"]):
        I, L0, q0 = initial_state(sc)
        w0 = tuple(L0[i] / I[i] for i in range(3))
        E = energy(L0, I)
        Lw = qrot(q0, L0)
        lines = []
        lines.append("# generated by tests/data/gen/free_body.py (mpmath %s) -- do not edit"
                     % mpmath.__version__)
        lines.append("# torque-free rigid body: dL/dt = L x omega, omega = L/I, dq/dt = 1/2 q (x) (0, omega); "
                     "q = world_from_body, scalar first, Hamilton; L = body-frame angular momentum")
        lines.append("# scenario %s: %s" % (sc["name"], sc["note"]))
        lines.append("# I = (%s)" % ", ".join(repr(x) for x in sc["I"]))
        if "omega0" in sc:
            lines.append("# omega0 (body, exact f64 input) = (%s); L0 = I * omega0 formed exactly = (%s)"
                         % (", ".join(repr(x) for x in sc["omega0"]), ", ".join(fmt(x) for x in L0)))
        else:
            lines.append("# L0 (body, exact f64 input) = (%s); omega0 = L0 / I (rounded) = (%s)"
                         % (", ".join(repr(x) for x in sc["L0"]), ", ".join(fmt(x) for x in w0)))
        lines.append("# q0 (f64, renormalised in mpmath before use) = (%s)"
                     % ", ".join(repr(x) for x in sc["q0"]))
        lines.append("# E = %s; |L| = %s; L_world = (%s)"
                     % (fmt(E), fmt(vnorm(L0)), ", ".join(fmt(x) for x in Lw)))
        if "P" in res:
            P = res["P"]
            lines.append("# elliptic motion: L circulates about e%d; m = %s; m' = 1 - m = %s; "
                         "(2 E I2 - |L|^2)/|L|^2 = %s; lam = %s; period of omega 4K/lam = %s; "
                         "time between omega2 sign changes 2K/lam = %s"
                         % (P["c"] + 1, fmt(P["m"]), fmt(P["mc"]), fmt(P["dist"]), fmt(P["lam"]),
                            fmt(4 * P["K"] / P["lam"]), fmt(2 * P["K"] / P["lam"])))
        lines.append("# t: exact f64 sample times (nearest f64 to k*dt); columns: values of the "
                     "high-precision solution at t rounded to nearest f64 (repr)")
        lines.append("# method: Taylor series integrator in mpmath, dps %d order %d eps 1e-%d; "
                     "cross-checked with dps %d order %d eps 1e-%d: max |diff|/max(1,|x|) = %s"
                     % (RUN_B["dps"], RUN_B["order"], RUN_B["eps_exp"], RUN_A["dps"], RUN_A["order"],
                        RUN_A["eps_exp"], sci(res["dAB_rel"])))
        lines.append("# invariant drift (relative) E %s, |L| %s, L_world %s, |q|-1 %s; closed form vs "
                     "reference: q %s, L %s (%s)"
                     % (sci(res["inv"]["E"]), sci(res["inv"]["Lnorm"]), sci(res["inv"]["Lworld"]),
                        sci(res["inv"]["qnorm"]), sci(res["closed_q"]), sci(res["closed_L"]),
                        "elliptic functions + Euler-angle quadrature" if "P" in res else "exact"))
        lines.append(HEADER)
        for t, (q, L) in zip(times_f, states):
            lines.append(",".join([repr(t)] + [fmt(x) for x in q + L]))
    path = os.path.join(OUT_DIR, sc["name"] + ".csv")
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def write_periods(results):
    lines = [
        "# generated by tests/data/gen/free_body.py (mpmath %s) -- do not edit" % mpmath.__version__,
        "# torque-free asymmetric bodies of tests/data/free_body/NAME.csv (same I, L0), in seconds",
        "# period_omega = 4 K(m) / lam: period of omega(t) (sn, cn have period 4K; dn has 2K)",
        "# time_between_flips = 2 K(m) / lam: time between successive sign changes of omega2 (half period)",
        "# L circulating about e1 (|L|^2 < 2 E I2): lam^2 = (I2-I1)(2E I3-|L|^2)/(I1 I2 I3), "
        "m = (I3-I2)(|L|^2-2E I1)/((I2-I1)(2E I3-|L|^2))",
        "# L circulating about e3 (|L|^2 > 2 E I2): lam^2 = (I3-I2)(|L|^2-2E I1)/(I1 I2 I3), "
        "m = (I2-I1)(2E I3-|L|^2)/((I3-I2)(|L|^2-2E I1))",
        "# K = complete elliptic integral of the first kind, parameter m = k^2 (mpmath ellipk); "
        "computed at mp.dps = %d, rounded to f64; verified against the sign changes of omega2 "
        "found in the integrated trajectories" % CHECK_DPS,
        "name,period_omega,time_between_flips",
    ]
    for r in results:
        if "P" in r:
            P = r["P"]
            lines.append("%s,%s,%s" % (r["name"], fmt(4 * P["K"] / P["lam"]), fmt(2 * P["K"] / P["lam"])))
    with open(os.path.join(OUT_DIR, "periods.csv"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main():
    if mpmath.__version__ != PINNED_MPMATH:
        print("warning: mpmath %s, pinned %s" % (mpmath.__version__, PINNED_MPMATH), file=sys.stderr)
    os.makedirs(OUT_DIR, exist_ok=True)
    t_start = time.perf_counter()
    only = set(sys.argv[1:])
    results = []
    for sc in SCENARIOS:
        if only and sc["name"] not in only:
            continue
        r = run_scenario(sc)
        results.append(r)
        print("%-19s %5.1fs steps A/B %4d/%4d  |A-B| %s (rel %s)  drift E %s |L| %s Lw %s |q| %s  "
              "closed q %s L %s  min dot %s"
              % (r["name"], r["seconds"], r["stepsA"], r["stepsB"], sci(r["dAB"]), sci(r["dAB_rel"]),
                 sci(r["inv"]["E"]), sci(r["inv"]["Lnorm"]), sci(r["inv"]["Lworld"]), sci(r["inv"]["qnorm"]),
                 sci(r["closed_q"]), sci(r["closed_L"]), mp.nstr(r["min_dot"], 3)))
        print("    run A drift E %s |L| %s Lw %s |q| %s; tail est A %s B %s"
              % (sci(r["invA"]["E"]), sci(r["invA"]["Lnorm"]), sci(r["invA"]["Lworld"]),
                 sci(r["invA"]["qnorm"]), sci(r["tailA"]), sci(r["tailB"])))
        if "P" in r:
            P = r["P"]
            with mp.workdps(CHECK_DPS):
                print("    e%d side, m = %s, m' = %s, dist = %s, lam = %s, K = %s"
                      % (P["c"] + 1, mp.nstr(P["m"], 20), mp.nstr(P["mc"], 20), mp.nstr(P["dist"], 20),
                         mp.nstr(P["lam"], 25), mp.nstr(P["K"], 25)))
                print("    period 4K/lam = %s, 2K/lam = %s" % (mp.nstr(4 * P["K"] / P["lam"], 30),
                                                          mp.nstr(2 * P["K"] / P["lam"], 30)))
                print("    omega2 sign changes %s; vs closed form %s, run A vs B %s, quad err %s"
                      % ([mp.nstr(e, 20) for e in r["events"]], sci(r["event_err"]),
                         sci(r["event_errA"]), sci(r["quad_err"])))
                ev = r["events"]
                if len(ev) >= 2:
                    print("    measured spacing of sign changes: %s"
                          % [mp.nstr(ev[i + 1] - ev[i], 25) for i in range(len(ev) - 1)])
    if not only:
        write_periods(results)
    print("total %.1f s" % (time.perf_counter() - t_start))


if __name__ == "__main__":
    main()
