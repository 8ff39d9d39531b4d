"""Generate high-precision reference trajectories of the Lagrange (heavy symmetric) top.

Regenerate (from the repository root; needs only mpmath, pinned in
requirements.txt):

    python3 tests/data/gen/lagrange_top.py

Writes ../lagrange_top/NAME.csv (relative to this script), one per scenario;
`python3 tests/data/gen/lagrange_top.py NAME ...` redoes only those. About 7
minutes on one core of the project machine.

Physics and conventions (kreisel's, see crates/dynamics/src/lagrange_top)
-----------------------------------------------------------------------
* Euler angles (phi, theta, psi), intrinsic ZXZ: world_from_body =
  Rz(phi) Rx(theta) Rz(psi); theta from the UPWARD vertical; symmetry axis =
  body e3; moments I1 = I2 (about the pivot), I3; potential +Mgl cos(theta).
* omega_body = (phi' s(th) s(psi) + th' c(psi), phi' s(th) c(psi) - th' s(psi),
  phi' c(th) + psi').
* The reference does NOT use Euler angles or the closed form: it integrates
  the singularity-free rigid-body equations of the top in the body frame,
      dL/dt = L x omega + Mgl (z x e3),  omega = L / (I1, I1, I3),
      dz/dt = z x omega                  (z = world up in body axes),
      dq/dt = 1/2 q (x) (0, omega)        (q = world_from_body, scalar first),
  a quadratic system, with an explicit Taylor-series method (Taylor
  coefficients by Cauchy products; step by the Jorba-Zou rule), run A at
  mp.dps = 40 (order 30, eps 1e-36) and run B at mp.dps = 60 (order 40,
  eps 1e-52). The CSV holds run B rounded to f64; the script asserts
  |A - B| <= 1e-25 for every output number and the invariants
  (E, L.z, L3, |z|, |q|, q z q^-1 = (0,0,1)) of run B to <= 1e-45.
* Euler angles are extracted from q at 60 digits: theta = atan2(hypot(R13, R23), R33),
  phi = atan2(R13, -R23), psi = atan2(R31, R32) (phi, psi unwrapped).
* Metadata lines (independent of the Rust closed form): the real roots of
  f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2 by mpmath.polyroots (and
  u2 - u1 as its own line, "gap", free of the roots' rounding), the
  nutation period T = 2 int_{u1}^{u2} du / sqrt(f(u)) by mpmath.quad after
  u = u1 + (u2 - u1) sin^2 x (which removes the endpoint singularities;
  checked against 2 K(k^2) / nu with mpmath.ellipk), the mean precession
  rate Delta(phi)/T by the same quadrature of phi' = (b - a u)/(1 - u^2), and the motion kind from the sign of b - a u at the
  turning points.
* Every input is an f64; the comment lines give it with repr(float).
* Fast tops (`python3 tests/data/gen/lagrange_top.py fast`, a few seconds):
  tests/data/lagrange_top/fast_tops.csv holds, for five families of tops at
  psi'0 = 1e3, 1e5, 1e7, 1e10, 1e15 rad/s, the roots, u2 - u1, theta_min,
  theta_max, the nutation period and the mean precession rate by the same
  polyroots + quadrature as above (no trajectory: a fast top would need
  ~psi'0 Taylor steps), computed at mp.dps = 120 and again at 160; the script
  asserts the two agree to 1e-60 relative. FAST_EXTRA adds single
  regression rows (any spin) to the same file. The band u2 - u1 is ~1e-29 at
  psi'0 = 1e15, so the roots need ~30 digits more than the output.
* Fast-top angles (`python3 tests/data/gen/lagrange_top.py fast_angles`, about 3.5
  minutes): tests/data/lagrange_top/fast_top_angles.csv holds, for the 25 rows of
  the five fast families, phi, theta, psi and their rates at t = 0.3 T, T,
  10.37 T and 1000 T (T the period rounded to f64; each t an f64). No
  trajectory integration and no elliptic functions: with
  u = u1 + (u2 - u1) sin^2 x (x increases monotonically along the motion,
  x -> x + pi is one nutation period) t, phi and psi are the quadratures
      t(x) = int 2 dx / sqrt(g),   phi(x) = int phi'(u) 2 dx / sqrt(g),
      psi = psi0 + omega3 t - int u phi'(u) 2 dx / sqrt(g),
  g = beta (u3 - u) (alpha + a^2 for beta = 0), phi'(u) = (b - a u)/(1 - u^2),
  from the start x0 (sin^2 x0 = (u0 - u1)/(u2 - u1), x0 > pi/2 when u'0 < 0);
  t(x) = t is solved by Newton's method after taking out whole periods
  (t(x + pi) = t(x) + T, phi(x + pi) = phi(x) + <phi'> T). Run at mp.dps = 120
  and 160 (agreement to 1e-40 relative, of each number and of the largest
  value of its column, plus the swing max|phi'| T of an angle, asserted); 20 significant digits written.
"""

import os
import sys
import time

import mpmath
from mpmath import mp, mpf, libmp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir, "lagrange_top"))
RUN_A = dict(dps=40, order=30, eps_exp=36)
RUN_B = dict(dps=60, order=40, eps_exp=52)
ROWS = 121

# name, description, (I1, I3, Mgl), (phi, theta, psi, phi', theta', psi'), t_end
SCENARIOS = [
    ("no_loops", "phi' > 0 at both turning points",
     (1.25, 0.5, 1.0), (0.3, 0.6, -0.2, 2.5, 0.4, 9.0), 6.0),
    ("loops", "phi' changes sign: released with phi' < 0",
     (1.25, 0.5, 1.0), (0.0, 0.8, 0.5, -0.6, 0.0, 10.0), 6.0),
    ("cusps", "released from rest in theta and phi (theta' = phi' = 0)",
     (1.25, 0.5, 1.0), (1.0, 0.9, 0.0, 0.0, 0.0, 12.0), 5.0),
    ("fast_near_sleeping", "fast top close to the vertical, above the sleeping threshold",
     (1.25, 0.5, 1.0), (0.4, 0.05, 0.0, 0.3, 0.02, 30.0), 3.0),
    ("slow", "slow top, large nutation",
     (1.25, 0.5, 1.0), (0.0, 1.0, 0.0, 0.2, 0.5, 1.0), 12.0),
    ("near_bottom", "u1 close to -1 (the axis swings close to the downward vertical)",
     (1.25, 0.5, 1.0), (0.0, 3.1, 0.0, 0.05, 0.2, 3.0), 12.0),
    ("free_symmetric", "Mgl = 0: the torque-free symmetric top",
     (1.25, 0.5, 0.0), (0.2, 0.7, 0.1, 0.8, 0.3, 2.0), 8.0),
    ("hanging", "Mgl < 0: centre of mass below the pivot",
     (1.25, 0.5, -1.0), (0.0, 2.5, 0.0, 0.4, 0.3, 3.0), 10.0),
    ("through_vertical", "started upright with theta' != 0 (b = a): the axis swings through the vertical",
     (1.25, 0.5, 1.0), (0.3, 0.0, 0.2, 0.0, 0.5, 8.0), 6.0),
]


def f64(x):
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
    r = qmul(qmul(q, (mpf(0), v[0], v[1], v[2])), qconj(q))
    return (r[1], r[2], r[3])


def qaxis(i, angle):
    c, s = mp.cos(angle / 2), mp.sin(angle / 2)
    v = [mpf(0)] * 3
    v[i] = s
    return (c, v[0], v[1], v[2])


def initial_state(sc):
    _, _, (i1, i3, mgl), (ph, th, ps, phd, thd, psd), _ = sc
    i1, i3, mgl = mpf(i1), mpf(i3), mpf(mgl)
    ph, th, ps, phd, thd, psd = (mpf(x) for x in (ph, th, ps, phd, thd, psd))
    q = qmul(qmul(qaxis(2, ph), qaxis(0, th)), qaxis(2, ps))
    w = (phd * mp.sin(th) * mp.sin(ps) + thd * mp.cos(ps),
         phd * mp.sin(th) * mp.cos(ps) - thd * mp.sin(ps),
         phd * mp.cos(th) + psd)
    L = (i1 * w[0], i1 * w[1], i3 * w[2])
    z = qrot(qconj(q), (mpf(0), mpf(0), mpf(1)))
    return (i1, i3, mgl), L, q, z


def taylor_coeffs(L, q, z, Iinv, mgl, N):
    Lc, qc, zc = [L], [q], [z]
    wc = [(L[0] * Iinv[0], L[1] * Iinv[1], L[2] * Iinv[2])]
    for k in range(N):
        sx = sy = sz = mpf(0)
        tx = ty = tz = mpf(0)
        pw = px = py = pz = mpf(0)
        for j in range(k + 1):
            b0, b1, b2 = wc[k - j]
            a0, a1, a2 = Lc[j]
            sx += a1 * b2 - a2 * b1
            sy += a2 * b0 - a0 * b2
            sz += a0 * b1 - a1 * b0
            c0, c1, c2 = zc[j]
            tx += c1 * b2 - c2 * b1
            ty += c2 * b0 - c0 * b2
            tz += c0 * b1 - c1 * b0
            w, x, y, zz = qc[j]
            pw -= x * b0 + y * b1 + zz * b2
            px += w * b0 + y * b2 - zz * b1
            py += w * b1 - x * b2 + zz * b0
            pz += w * b2 + x * b1 - y * b0
        f = mpf(1) / (k + 1)
        zk = zc[k]
        # torque Mgl (z x e3) = Mgl (z_y, -z_x, 0)
        Ln = ((sx + mgl * zk[1]) * f, (sy - mgl * zk[0]) * f, sz * f)
        Lc.append(Ln)
        wc.append((Ln[0] * Iinv[0], Ln[1] * Iinv[1], Ln[2] * Iinv[2]))
        zc.append((tx * f, ty * f, tz * f))
        f /= 2
        qc.append((pw * f, px * f, py * f, pz * f))
    return Lc, qc, zc


def horner(coeffs, h):
    acc = [mpf(0)] * len(coeffs[0])
    for c in reversed(coeffs):
        acc = [a * h + ci for a, ci in zip(acc, c)]
    return tuple(acc)


def sample_times(sc):
    t_end = sc[4]
    return [f64(mpf(t_end) * k / (ROWS - 1)) for k in range(ROWS)]


def integrate(sc, dps, order, eps_exp):
    with mp.workdps(dps):
        (i1, i3, mgl), L, q, z = initial_state(sc)
        Iinv = (1 / i1, 1 / i1, 1 / i3)
        Lscale = max(mpf(1), mp.sqrt(sum(x * x for x in L)))
        eps = mpf(10) ** (-eps_exp)
        times = [mpf(t) for t in sample_times(sc)]
        states = [(q, L, z)]
        t = times[0]
        for t_next in times[1:]:
            while t < t_next:
                Lc, qc, zc = taylor_coeffs(L, q, z, Iinv, mgl, order)
                h = t_next - t
                for k in (order - 1, order):
                    r = max(max(abs(c) for c in Lc[k]) / Lscale,
                            max(abs(c) for c in qc[k]), max(abs(c) for c in zc[k]))
                    if r > 0:
                        h = min(h, (eps / r) ** (mpf(1) / k))
                L, q, z = horner(Lc, h), horner(qc, h), horner(zc, h)
                t = t_next if h == t_next - t else t + h
            states.append((q, L, z))
        return states


def invariants(top, L, q, z):
    i1, i3, mgl = top
    e = (L[0] ** 2 + L[1] ** 2) / (2 * i1) + L[2] ** 2 / (2 * i3) + mgl * z[2]
    lz = L[0] * z[0] + L[1] * z[1] + L[2] * z[2]
    up = qrot(qconj(q), (mpf(0), mpf(0), mpf(1)))
    dz = max(abs(up[i] - z[i]) for i in range(3))
    return e, lz, L[2], sum(x * x for x in z), sum(x * x for x in q), dz


def euler_from_q(q):
    w, x, y, z = q
    r13 = 2 * (x * z + w * y)
    r23 = 2 * (y * z - w * x)
    r31 = 2 * (x * z - w * y)
    r32 = 2 * (y * z + w * x)
    r33 = 1 - 2 * (x * x + y * y)
    s = mp.sqrt(r13 ** 2 + r23 ** 2)
    return mp.atan2(r13, -r23), mp.atan2(s, r33), mp.atan2(r31, r32)


def constants(sc):
    """a, b, alpha, beta, u0 of the notes from the initial conditions (mpmath)."""
    _, _, (i1, i3, mgl), (ph, th, ps, phd, thd, psd), _ = sc
    i1, i3, mgl = mpf(i1), mpf(i3), mpf(mgl)
    th, phd, thd, psd = mpf(th), mpf(phd), mpf(thd), mpf(psd)
    u0 = mp.cos(th)
    w3 = phd * u0 + psd
    a = i3 * w3 / i1
    b = mp.sin(th) ** 2 * phd + a * u0
    beta = 2 * mgl / i1
    alpha = thd ** 2 + mp.sin(th) ** 2 * phd ** 2 + beta * u0
    return a, b, alpha, beta, u0, w3


def metadata(sc, extraprec=200):
    a, b, alpha, beta, u0, w3 = constants(sc)
    # f(u) = beta u^3 - (alpha + a^2) u^2 + (2ab - beta) u + (alpha - b^2)
    coeffs = [beta, -(alpha + a * a), 2 * a * b - beta, alpha - b * b]
    if beta == 0:
        coeffs = coeffs[1:]
    roots = mp.polyroots(coeffs, maxsteps=200, extraprec=extraprec)
    roots = sorted(mp.re(r) for r in roots)
    if extraprec > 200:
        # Durand-Kerner converges slowly on the nearly double roots of a fast
        # top: finish each root by Newton's method on f with the guard digits.
        with mp.extraprec(extraprec):
            polished = []
            for r in roots:
                for _ in range(200):
                    fr = mp.polyval(coeffs, r)
                    dr = mp.polyval([c * (len(coeffs) - 1 - i) for i, c in enumerate(coeffs[:-1])], r)
                    step = fr / dr
                    r -= step
                    if abs(step) <= mpf(2) ** -(mp.prec - 8) * max(1, abs(r)):
                        break
                polished.append(r)
        roots = sorted(+r for r in polished)
    inside = [r for r in roots if -1 - mpf(10) ** -30 <= r <= 1 + mpf(10) ** -30]
    if beta > 0:
        u1, u2 = roots[0], roots[1]
    elif beta < 0:
        u1, u2 = roots[1], roots[2]
    else:
        u1, u2 = roots[0], roots[1]
    assert len(inside) >= 2

    def f(u):
        return (1 - u * u) * (alpha - beta * u) - (b - a * u) ** 2

    # u = u1 + (u2 - u1) sin^2 x removes the endpoint singularities:
    # du / sqrt(f) = 2 dx / sqrt(g), g = f / ((u - u1)(u2 - u)) = beta (u3 - u)
    # (alpha + a^2 for beta = 0), smooth and > 0 on [u1, u2].
    def g(x):
        u = u1 + (u2 - u1) * mp.sin(x) ** 2
        if beta == 0:
            return u, alpha + a * a
        u3 = roots[2] if beta > 0 else roots[0]
        return u, beta * (u3 - u)

    def dt(x):
        return 2 / mp.sqrt(g(x)[1])

    def dph(x):
        u, gx = g(x)
        return 2 * (b - a * u) / (1 - u * u) / mp.sqrt(gx)

    period = 2 * mp.quad(dt, [0, mp.pi / 4, mp.pi / 2])
    dphi = 2 * mp.quad(dph, [0, mp.pi / 4, mp.pi / 2])
    # check against the elliptic form
    if beta > 0:
        u3 = roots[2]
        nu = mp.sqrt(beta * (u3 - u1)) / 2
        m = (u2 - u1) / (u3 - u1)
    elif beta < 0:
        u3 = roots[0]
        nu = mp.sqrt(beta * (u3 - u2)) / 2
        m = (u2 - u1) / (u2 - u3)
    else:
        nu = mp.sqrt(alpha + a * a) / 2
        m = mpf(0)
    period_k = 2 * mp.ellipk(m) / nu
    assert abs(period_k - period) < mpf(10) ** (15 - mp.dps) * period, (period, period_k)
    s1, s2 = b - a * u1, b - a * u2
    if b == a and abs(u2 - 1) < mpf(10) ** (10 - mp.dps):
        s2 = a / 2  # phi' = (b - a u)/(1 - u^2) = a/(1 + u) at u = 1
    tiny = mpf(10) ** (10 - mp.dps) * (abs(b) + abs(a))
    if extraprec > 200:
        # the coefficient alpha + a^2 rounds at 10^-dps a^2, which moves the
        # roots by that much (f' ~ 1 at them): b - a u by ~a^3 10^-dps
        tiny *= 1 + a * a
    sign = 0 if min(abs(s1), abs(s2)) < tiny else 1 if s1 * s2 > 0 else -1
    kind = {1: "no_loops", -1: "loops", 0: "cusps"}[sign]
    return dict(roots=roots, u1=u1, u2=u2, gap=u2 - u1, period=period, precession=dphi / period,
                kind=kind, a=a, b=b, alpha=alpha, beta=beta, omega3=w3)


def run(sc):
    name = sc[0]
    t0 = time.time()
    A = integrate(sc, **RUN_A)
    B = integrate(sc, **RUN_B)
    with mp.workdps(60):
        top = initial_state(sc)[0]
        worst = mpf(0)
        for (qa, La, za), (qb, Lb, zb) in zip(A, B):
            for x, y in zip(qa + La + za, qb + Lb + zb):
                worst = max(worst, abs(x - y))
        assert worst < mpf(10) ** -25, (name, worst)
        inv0 = invariants(top, *(B[0][1], B[0][0], B[0][2]))
        drift = mpf(0)
        for (q, L, z) in B:
            inv = invariants(top, L, q, z)
            drift = max(drift, abs(inv[0] - inv0[0]), abs(inv[1] - inv0[1]),
                        abs(inv[2] - inv0[2]), abs(inv[3] - 1), abs(inv[4] - 1), inv[5])
        assert drift < mpf(10) ** -45, (name, drift)
        meta = metadata(sc)
        rows = []
        prev = None
        for t, (q, L, z) in zip(sample_times(sc), B):
            ph, th, ps = euler_from_q(q)
            if prev is not None:
                ph += 2 * mp.pi * mp.nint((prev[0] - ph) / (2 * mp.pi))
                ps += 2 * mp.pi * mp.nint((prev[1] - ps) / (2 * mp.pi))
            prev = (ph, ps)
            rows.append((t, ph, th, ps) + tuple(q))
    write(sc, meta, rows, worst, drift)
    print(f"{name}: |A-B| = {mpmath.nstr(worst, 3)}, drift = {mpmath.nstr(drift, 3)}, "
          f"kind = {meta['kind']}, T = {mpmath.nstr(meta['period'], 17)}, "
          f"{time.time() - t0:.1f} s", flush=True)


def write(sc, meta, rows, worst, drift):
    name, desc, (i1, i3, mgl), init, t_end = sc
    path = os.path.join(OUT_DIR, f"{name}.csv")
    with open(path, "w") as fh:
        fh.write(f"# generated by tests/data/gen/lagrange_top.py (mpmath {mpmath.__version__}) -- do not edit\n")
        fh.write(f"# scenario {name}: {desc}\n")
        fh.write(f"# top = ({repr(i1)}, {repr(i3)}, {repr(mgl)})\n")
        fh.write("# initial = (" + ", ".join(repr(x) for x in init) + ")\n")
        fh.write("# roots = (" + ", ".join(mpmath.nstr(r, 30) for r in meta["roots"]) + ")\n")
        fh.write(f"# gap = {mpmath.nstr(meta['gap'], 30)}\n")
        fh.write(f"# period = {mpmath.nstr(meta['period'], 30)}\n")
        fh.write(f"# precession = {mpmath.nstr(meta['precession'], 30)}\n")
        fh.write(f"# kind = {meta['kind']}\n")
        fh.write(f"# check: |run A - run B| = {mpmath.nstr(worst, 3)}; invariant drift = {mpmath.nstr(drift, 3)}\n")
        fh.write("t,phi,theta,psi,qw,qx,qy,qz\n")
        for r in rows:
            fh.write(",".join(fmt(x) for x in r) + "\n")

# Fast tops: name, (I1, I3, Mgl), (theta0, theta'0, phi'0 or None), description.
# phi'0 = None: phi'0 = 1.5 Mgl / (I3 psi'0) (1.5 times the slow precession
# rate, rounded to f64): phi' swings between ~1.5 and ~0.5 of it (no loops),
# so the mean precession is of the size of phi' itself. (Twice the rate would
# be a near-cusp: phi' ~ 0 at the other turning point.)
FAST_FAMILIES = [
    ("released", (0.3, 0.1, 2.0), (0.5, 0.0, 0.0),
     "released at rest in theta and phi (the README example's top): cusps"),
    ("precessing", (0.3, 0.1, 2.0), (0.5, 0.0, None),
     "phi'0 = 1.5 x the slow precession rate: no loops"),
    ("kicked", (1.25, 0.5, -1.0), (2.5, 0.3, 0.0),
     "hanging (Mgl < 0), theta'0 != 0: phi' swings +-0.5 rad/s about a tiny mean"),
    ("kicked_upright", (1.25, 0.5, 1.0), (0.5, 0.3, 0.0),
     "upright (Mgl > 0), theta'0 != 0: phi' swings +-0.6 rad/s about a tiny mean"),
    ("kicked_precessing", (0.3, 0.1, 2.0), (0.5, 0.3, None),
     "phi'0 = 1.5 x the slow precession rate and theta'0 != 0: loops about a tiny mean"),
]
FAST_SPINS = [1e3, 1e5, 1e7, 1e10, 1e15]
# Single regression rows (not fast), written to the same file: name,
# (I1, I3, Mgl), (theta0, theta'0, phi'0), psi'0, description.
FAST_EXTRA = [
    ("third_root_near_pole", (1.8359669279120632, 0.7906660058757264, -0.6955873852709897),
     (0.5462055191371211, 0.0016225004273098967, 0.4772982490491144), -0.6035043920999813,
     "hanging, u3 = -1.00028 just below the pole: 1 + u1 from the factorised cubic cancelled (2e-12)"),
]


def fast_scenario(family, psd):
    name, (i1, i3, mgl), (th, thd, phd) = family[:3]
    if phd is None:
        phd = float(1.5 * mgl / (i3 * psd))
    return (name, "", (i1, i3, mgl), (0.0, th, 0.0, phd, thd, psd), 0.0)


def fast_row(sc, dps):
    with mp.workdps(dps):
        # b - a u cancels to ~1/psi'0^2 near the roots: ample guard digits.
        meta = metadata(sc, extraprec=12 * dps)
        return [meta["roots"][0], meta["roots"][1], meta["roots"][2] if len(meta["roots"]) > 2 else mpf(0),
                meta["gap"], mp.acos(meta["u2"]), mp.acos(meta["u1"]), meta["period"],
                meta["precession"]], meta["kind"]


def fast():
    path = os.path.join(OUT_DIR, "fast_tops.csv")
    lines = [f"# generated by tests/data/gen/lagrange_top.py fast (mpmath {mpmath.__version__}) -- do not edit",
             "# fast tops: roots, u2 - u1, theta limits, nutation period and mean precession rate at mp.dps = 120,",
             "# checked against mp.dps = 160 (agreement to 1e-60 relative asserted); 30 significant digits",
             "# families: " + "; ".join(f"{f[0]}: {f[3]}" for f in FAST_FAMILIES),
             "# single rows: " + "; ".join(f"{f[0]}: {f[4]}" for f in FAST_EXTRA),
             "family,i1,i3,mgl,theta0,theta_dot0,phi_dot0,psi_dot0,u1,u2,u3,gap,theta_min,theta_max,period,precession,kind"]
    jobs = [(family, psd) for family in FAST_FAMILIES for psd in FAST_SPINS]
    jobs += [(extra, extra[3]) for extra in FAST_EXTRA]
    for family, psd in jobs:
        sc = fast_scenario(family, psd)
        lo, kind = fast_row(sc, 120)
        hi, kind_hi = fast_row(sc, 160)
        assert kind == kind_hi
        with mp.workdps(160):
            for x, y in zip(lo, hi):
                assert abs(x - y) <= mpf(10) ** -60 * abs(y), (sc, x, y)
        _, _, (i1, i3, mgl), (_, th, _, phd, thd, psd), _ = sc
        inputs = [repr(v) for v in (i1, i3, mgl, th, thd, phd, psd)]
        lines.append(",".join([family[0]] + inputs + [mpmath.nstr(v, 30, min_fixed=0, max_fixed=0) for v in hi] + [kind]))
        print(lines[-1], flush=True)
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


FAST_ANGLE_TIMES = [0.3, 1.0, 10.37, 1000.0]


def fast_angles_case(sc, dps):
    """phi, theta, psi and rates at FAST_ANGLE_TIMES periods (see the module docs)."""
    with mp.workdps(dps):
        meta = metadata(sc, extraprec=12 * dps)
        a, b, alpha, beta = meta["a"], meta["b"], meta["alpha"], meta["beta"]
        u1, u2, gap, roots = meta["u1"], meta["u2"], meta["gap"], meta["roots"]
        w3 = meta["omega3"]
        _, _, _, (ph0, th0, ps0, phd0, thd0, psd0), _ = sc
        th0, thd0 = mpf(th0), mpf(thd0)
        u3 = None if beta == 0 else (roots[2] if beta > 0 else roots[0])

        def u_g(x):
            u = u1 + gap * mp.sin(x) ** 2
            return u, (alpha + a * a) if beta == 0 else beta * (u3 - u)

        def dt(x):
            return 2 / mp.sqrt(u_g(x)[1])

        def phidot(u):
            return (b - a * u) / (1 - u * u)

        def dphi(x):
            u, g = u_g(x)
            return 2 * phidot(u) / mp.sqrt(g)

        def dupsi(x):
            u, g = u_g(x)
            return 2 * u * phidot(u) / mp.sqrt(g)

        def integral(fn, y):
            # from 0 to y, y in [0, pi): split at the turning point pi/2
            if y <= mp.pi / 2:
                return mp.quad(fn, [0, y])
            return mp.quad(fn, [0, mp.pi / 2]) + mp.quad(fn, [mp.pi / 2, y])

        period = 2 * mp.quad(dt, [0, mp.pi / 2])
        phi_per = 2 * mp.quad(dphi, [0, mp.pi / 2])
        upsi_per = 2 * mp.quad(dupsi, [0, mp.pi / 2])

        def at(fn, per, x):
            k = mp.floor(x / mp.pi)
            return k * per + integral(fn, x - k * mp.pi)

        u0 = mp.cos(th0)
        if thd0 == 0:
            # released at a turning point, exactly (asin near 1 would square-root
            # the roots' rounding)
            x0 = mpf(0) if abs(u0 - u1) < abs(u0 - u2) else mp.pi / 2
        else:
            s2 = min(max((u0 - u1) / gap, mpf(0)), mpf(1))
            x0 = mp.asin(mp.sqrt(s2))
            if -mp.sin(th0) * thd0 < 0:
                x0 = mp.pi - x0
        t_x0 = integral(dt, x0)
        phi_x0, upsi_x0 = integral(dphi, x0), integral(dupsi, x0)
        period_f64 = f64(period)
        out = []
        for c in FAST_ANGLE_TIMES:
            t = mpf(f64(c * period_f64))
            target = t + t_x0
            k = mp.floor(target / period)
            rem = target - k * period
            y = mp.pi * rem / period
            for _ in range(100):
                step = (integral(dt, y) - rem) / dt(y)
                y -= step
                if abs(step) <= mpf(2) ** (-mp.prec + 10):
                    break
            x = k * mp.pi + y
            u, g = u_g(x)
            phi = mpf(ph0) + at(dphi, phi_per, x) - phi_x0
            psi = mpf(ps0) + w3 * t - (at(dupsi, upsi_per, x) - upsi_x0)
            theta = mp.acos(u)
            udot = gap * mp.sin(2 * x) * mp.sqrt(g) / 2
            theta_dot = -udot / mp.sin(theta)
            pd = phidot(u)
            out.append([t, phi, theta, psi, pd, theta_dot, w3 - u * pd, period, phi_per / period])
        return out


def fast_angles():
    path = os.path.join(OUT_DIR, "fast_top_angles.csv")
    lines = [f"# generated by tests/data/gen/lagrange_top.py fast_angles (mpmath {mpmath.__version__}) -- do not edit",
             "# fast tops (the families of fast_tops.csv): Euler angles and rates at t = c T (c = "
             + ", ".join(repr(c) for c in FAST_ANGLE_TIMES) + "; T the period rounded to f64, t an f64),",
             "# by quadrature along u = u1 + (u2 - u1) sin^2 x at mp.dps = 120, checked against 160; phi0 = psi0 = 0 (inputs as in fast_tops.csv);",
             "# period and precession (the mean phi') repeated for the tolerances; 20 significant digits",
             "family,i1,i3,mgl,theta0,theta_dot0,phi_dot0,psi_dot0,t,phi,theta,psi,phi_dot,theta_dot,psi_dot,period,precession"]
    for family in FAST_FAMILIES:
        for psd in FAST_SPINS:
            sc = fast_scenario(family, psd)
            lo = fast_angles_case(sc, 120)
            hi = fast_angles_case(sc, 160)
            with mp.workdps(160):
                # each column relative to itself and to its largest value on
                # these rows (plus the mean phi' and the swing |phi'| T of an angle)
                big = [max(abs(r[i]) for r in hi) for i in range(len(hi[0]))]
                swing = (big[4] + abs(hi[0][8])) * hi[0][7]
                for rl, rh in zip(lo, hi):
                    for i, (x, y) in enumerate(zip(rl, rh)):
                        scale = abs(y) + big[i] + (swing if i in (1, 3) else 0)
                        assert abs(x - y) <= mpf(10) ** -40 * scale, (sc, i, x, y)
            _, _, (i1, i3, mgl), (_, th, _, phd, thd, _), _ = sc
            inputs = [repr(v) for v in (i1, i3, mgl, th, thd, phd, psd)]
            for r in hi:
                lines.append(",".join([family[0]] + inputs + [mpmath.nstr(v, 20, min_fixed=0, max_fixed=0) for v in r]))
                print(lines[-1], flush=True)
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main():
    assert mpmath.__version__ == "1.3.0", mpmath.__version__
    os.makedirs(OUT_DIR, exist_ok=True)
    only = sys.argv[1:]
    if only == ["fast"]:
        fast()
        return
    if only == ["fast_angles"]:
        fast_angles()
        return
    for sc in SCENARIOS:
        if not only or sc[0] in only:
            run(sc)


if __name__ == "__main__":
    main()
