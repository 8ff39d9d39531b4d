"""Generate the committed elliptic-function reference data used by the Rust tests.

Regenerate (from the repository root):

    pip install mpmath && python3 tests/data/gen/elliptic.py

(mpmath 1.3.0 was used; see tests/data/gen/requirements.txt.)

Writes, relative to this script's location (i.e. into tests/data/):

    elliptic_carlson.csv     Carlson R_F, R_D, R_J (also p < 0, principal value), R_C
    elliptic_complete.csv    K, E, Pi by the parameter m or by mc = 1 - m
    elliptic_incomplete.csv  F, E, Pi (any amplitude phi) by m or by mc
    elliptic_jacobi.csv      sn, cn, dn, am by mc (down to 5e-324) or by m

Conventions
-----------
* Parameter m = k^2, complementary parameter mc = 1 - m.  Pi(n; phi | m) has
  the characteristic n in the form 1 - n sin^2(theta) (as mpmath, DLMF 19.2.7).
* A row's `kind` column says which of m or mc is the exact f64 input; for `mc`
  rows the reference is computed from the exact mc (m = 1 - mc formed in mpmath
  at enough digits: 40 plus the decimal exponent of mc plus that of u), never
  from a rounded f64 m.
* Every reference value is computed with mpmath at that working precision
  (at least 40 significant digits) from the exact f64 inputs and recomputed
  with 20 more digits; the script stops if the two do not round to the same
  f64.  Values are correctly rounded (round-to-nearest) to f64 and written with
  repr(float(x)) (shortest round-trip form).
* Cauchy principal values: R_C(x, y < 0) is mpmath's elliprc.  R_J(x, y, z,
  p < 0) is computed by DLMF 19.20.14 from mpmath's R_J (p > 0), R_F, R_C and
  cross-checked against the real part of mpmath's complex elliprj.  Complete
  Pi(n > 1 | m) is K(m) - Pi(m/n | m) (DLMF 19.6.5), cross-checked against
  -(m/(3n)) R_J(0, mc, 1, 1 - m/n).  Incomplete Pi past the singularity
  (n sin^2 phi > 1) is the Carlson form (DLMF 19.25.14 with 19.20.14),
  cross-checked against the real part of mpmath's ellippi (which is very slow
  there, hence not the primary route).
* am(u | m) is unwrapped so that am(u + 2K) = am(u) + pi.
* The script is deterministic (random.Random with fixed seeds, one per file)
  and takes about 4 minutes.
"""

import math
import os
import random

import mpmath
from mpmath import mp, mpf
from mpmath import libmp

BASE_DPS = 40
CHECK_EXTRA = 20

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir))  # tests/data


def f64(x):
    """Correctly rounded f64 of a real mpf (real part of an mpc)."""
    if isinstance(x, mpmath.mpc):
        x = x.real
    return libmp.to_float(mpf(x)._mpf_, strict=True, rnd=libmp.round_nearest)


def fmt(x):
    return repr(float(x))


def digits_of(*values):
    """Extra decimal digits needed for tiny mc or large arguments."""
    extra = 0
    for v in values:
        if v is None or v == 0:
            continue
        e = -math.log10(abs(v)) if abs(v) < 1 else math.log10(abs(v))
        extra = max(extra, int(math.ceil(e)))
    return extra


def checked(fn, extra_digits=0):
    """Evaluate fn() at two precisions; return the f64 values (tuple or one)."""
    results = []
    for dps in (BASE_DPS + extra_digits, BASE_DPS + extra_digits + CHECK_EXTRA):
        with mp.workdps(dps):
            v = fn()
            if not isinstance(v, tuple):
                v = (v,)
            results.append(tuple(f64(x) for x in v))
    a, b = results
    for x, y in zip(a, b):
        if not (x == y or (math.isnan(x) and math.isnan(y))):
            raise SystemExit(f"precision check failed: {a} vs {b}")
    return a if len(a) > 1 else a[0]


def param_m(kind, param):
    """The exact m for a row given by m or by mc (at the current precision)."""
    return mpf(param) if kind == "m" else 1 - mpf(param)


def param_mc(kind, param):
    return 1 - mpf(param) if kind == "m" else mpf(param)


def write(name, header, rows, comment):
    path = os.path.join(OUT_DIR, name)
    with open(path, "w", newline="\n") as f:
        for line in comment.strip().splitlines():
            f.write("# " + line + "\n")
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(r) + "\n")
    print(f"wrote {path}: {len(rows)} rows")


def loguniform(rng, lo, hi):
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))


# --------------------------------------------------------------------------
# Carlson
# --------------------------------------------------------------------------


def rj_pv(x, y, z, p):
    """R_J for p < 0 by DLMF 19.20.14 (x <= y <= z sorted), for cross-checks."""
    x, y, z = sorted([x, y, z])
    q = -p
    pp = (z * (x + y + q) - x * y) / (z + q)
    v = (pp - z) * mpmath.elliprj(x, y, z, pp) - 3 * mpmath.elliprf(x, y, z)
    v += 3 * mpmath.sqrt(x * y * z / (x * y + pp * q)) * mpmath.elliprc(x * y + pp * q, pp * q)
    return v / (z + q)


def carlson_rows():
    rng = random.Random(20240501)
    rows = []

    def add(func, x, y=None, z=None, p=None):
        args = [a for a in (x, y, z, p) if a is not None]

        def fn():
            a = [mpf(t) for t in args]
            if func == "rf":
                return mpmath.elliprf(*a)
            if func == "rd":
                return mpmath.elliprd(*a)
            if func == "rc":
                v = mpmath.elliprc(*a)
                return v.real if isinstance(v, mpmath.mpc) else v
            v = mpmath.elliprj(*a)
            if a[3] < 0:
                pv = rj_pv(*a)
                if abs(v.real - pv) > abs(pv) * mpf(10) ** (-mp.dps // 2):
                    raise SystemExit(f"R_J principal value mismatch at {args}")
                return pv
            return v

        value = checked(fn, digits_of(*args) // 4)
        cols = [fmt(t) if t is not None else "" for t in (x, y, z, p)]
        rows.append([func] + cols + [fmt(value)])

    # random arguments, moderate and wide ranges
    for lo, hi, n in ((1e-3, 1e3, 40), (1e-30, 1e30, 15), (1e-200, 1e200, 6)):
        for _ in range(n):
            x, y, z = (loguniform(rng, lo, hi) for _ in range(3))
            add("rf", x, y, z)
            add("rd", x, y, z)
            add("rj", x, y, z, loguniform(rng, lo, hi))
            add("rc", x, y)
    # one argument zero (complete integrals), near-equal arguments
    for _ in range(15):
        y, z = loguniform(rng, 1e-3, 1e3), loguniform(rng, 1e-3, 1e3)
        add("rf", 0.0, y, z)
        add("rd", 0.0, y, z)
        add("rd", y, z, 0.0 + loguniform(rng, 1e-3, 1e3))
        add("rj", 0.0, y, z, loguniform(rng, 1e-3, 1e3))
        add("rc", 0.0, y)
    for _ in range(10):
        a = rng.uniform(0.5, 2.0)
        d = loguniform(rng, 1e-16, 1e-4)
        add("rf", a, a * (1 + d), a * (1 - d))
        add("rd", a, a * (1 + d), a * (1 - d))
        add("rj", a, a * (1 + d), a * (1 - d), a * (1 + 2 * d))
        add("rc", a, a * (1 + d))
        add("rc", a * (1 + d), a)
    # the complete-integral corner: R_F(0, mc, 1), R_D(0, mc, 1), R_D(0, 1, mc)
    for e in (1, 2, 4, 8, 16, 30, 60, 100, 200, 300, 307):
        mc = 10.0 ** -e
        add("rf", 0.0, mc, 1.0)
        add("rd", 0.0, mc, 1.0)
        add("rd", 0.0, 1.0, mc)
        add("rj", 0.0, mc, 1.0, 0.5)
        add("rj", 0.0, mc, 1.0, mc)
    add("rf", 0.0, 5e-324, 1.0)
    # p near x, p tiny or huge relative to the rest
    for p in (1e-12, 1e-3, 0.999999, 1.0, 1.000001, 1e3, 1e12):
        add("rj", 1.0, 2.0, 3.0, p)
    # Cauchy principal values: R_J with p < 0, R_C with y < 0
    for _ in range(20):
        x, y, z = (loguniform(rng, 1e-2, 1e2) for _ in range(3))
        add("rj", x, y, z, -loguniform(rng, 1e-2, 1e2))
        add("rc", x, -loguniform(rng, 1e-2, 1e2))
    add("rj", 0.0, 0.5, 1.0, -0.25)
    add("rj", 0.0, 1e-20, 1.0, -3.0)
    # x == y and classic test values (Carlson 1995, section 3)
    for x, y in ((0.0, 0.25), (2.25, 2.0), (0.25, -2.0), (1.0, 1.0), (0.0, 1.0)):
        add("rc", x, y)
    add("rf", 1.0, 2.0, 0.0)
    add("rf", 0.5, 1.0, 0.0)
    add("rf", 2.0, 3.0, 4.0)
    add("rd", 0.0, 2.0, 1.0)
    add("rd", 2.0, 3.0, 4.0)
    add("rj", 0.0, 1.0, 2.0, 3.0)
    add("rj", 2.0, 3.0, 4.0, 5.0)
    add("rj", 2.0, 3.0, 4.0, -0.5)
    add("rj", 2.0, 3.0, 4.0, -5.0)
    write(
        "elliptic_carlson.csv",
        ["func", "x", "y", "z", "p", "value"],
        rows,
        """Carlson symmetric elliptic integrals, mpmath reference (tests/data/gen/elliptic.py).
func: rf = R_F(x,y,z), rd = R_D(x,y,z), rj = R_J(x,y,z,p) (Cauchy principal value for p < 0),
rc = R_C(x,y) (Cauchy principal value for y < 0). Unused arguments are empty.""",
    )


# --------------------------------------------------------------------------
# Complete and incomplete Legendre integrals
# --------------------------------------------------------------------------


def complete_value(func, kind, param, n):
    m = param_m(kind, param)
    if func == "K":
        if kind == "mc":
            rf = mpmath.elliprf(0, mpf(param), 1)
            k = mpmath.ellipk(m)
            if abs(rf - k) > abs(k) * mpf(10) ** (-BASE_DPS + 3):
                raise SystemExit(f"K mismatch at mc={param}")
        return mpmath.ellipk(m)
    if func == "E":
        return mpmath.ellipe(m)
    if n > 1:
        # Principal value by DLMF 19.6.5 (mpmath's complex-valued ellippi is
        # very slow here), cross-checked against the Carlson form.
        pv = mpmath.ellipk(m) - mpmath.ellippi(m / mpf(n), m)
        mc = param_mc(kind, param)
        carlson = -(m / (3 * n)) * mpmath.elliprj(0, mc, 1, (n - 1 + mc) / n)
        if abs(carlson - pv) > abs(pv) * mpf(10) ** (-BASE_DPS + 5):
            raise SystemExit(f"Pi principal value mismatch at n={n}, {kind}={param}")
        return pv
    return mpmath.ellippi(mpf(n), m)


def complete_rows():
    rng = random.Random(20240502)
    rows = []

    def add(func, kind, param, n=None):
        extra = digits_of(param) if kind == "mc" else 0
        value = checked(lambda: complete_value(func, kind, param, n), extra)
        rows.append([func, kind, fmt(param), fmt(n) if n is not None else "", fmt(value)])

    ms = [rng.uniform(0.0, 1.0) for _ in range(30)]
    ms += [0.0, 1e-300, 1e-20, 1e-8, 1e-3, 0.5, 0.9, 0.99, 0.999999]
    ms += [1.0 - 2.0**-k for k in (10, 20, 30, 40, 50, 52, 53)]
    ms += [-1e-3, -0.5, -1.0, -10.0, -1e3, -1e8]
    mcs = [10.0**-e for e in (1, 2, 3, 4, 6, 8, 10, 12, 14, 16, 18, 20, 25, 30, 40,
                               50, 70, 100, 150, 200, 250, 300, 307)]
    mcs += [rng.uniform(0.0, 1.0) for _ in range(10)]
    mcs += [5e-324, 2.2250738585072014e-308, 1.0, 2.0, 1e3]
    for func in ("K", "E"):
        for m in ms:
            add(func, "m", m)
        for mc in mcs:
            add(func, "mc", mc)
    ns = [-100.0, -10.0, -1.0, -0.3, 0.0, 1e-8, 0.3, 0.7, 0.9, 0.999, 1.5, 3.0, 100.0]
    for m in ms[:8] + [0.0, 0.99, 1.0 - 2.0**-40, -0.5, -10.0]:
        for n in ns:
            if n > 1 and m < 0:
                continue
            add("PI", "m", m, n)
    for mc in (1e-2, 1e-6, 1e-16, 1e-50, 1e-300, 0.3, 0.8):
        for n in ns:
            add("PI", "mc", mc, n)
    write(
        "elliptic_complete.csv",
        ["func", "kind", "param", "n", "value"],
        rows,
        """Complete elliptic integrals, mpmath reference (tests/data/gen/elliptic.py).
func: K = K(m), E = E(m), PI = Pi(n | m) (Cauchy principal value for n > 1).
kind says whether param is m or the complementary parameter mc = 1 - m (exact input).""",
    )


def incomplete_value(func, kind, phi, param, n):
    m = param_m(kind, param)
    phi = mpf(phi)
    if func == "F":
        return mpmath.ellipf(phi, m)
    if func == "E":
        return mpmath.ellipe(phi, m)
    if n > 1 and n * mpmath.sin(phi) ** 2 > 1:
        # Principal value in Carlson form (DLMF 19.25.14 with R_J by 19.20.14);
        # cross-checked once against the real part of mpmath's ellippi.
        s, c = mpmath.sin(phi), mpmath.cos(phi)
        d2 = 1 - m * s**2
        pv = s * mpmath.elliprf(c**2, d2, 1) + mpf(n) / 3 * s**3 * rj_pv(c**2, d2, mpf(1), 1 - n * s**2)
        if mp.dps == BASE_DPS + CHECK_EXTRA:
            with mp.workdps(BASE_DPS):
                ref = mpmath.ellippi(mpf(n), phi, m).real
            if abs(ref - pv) > abs(pv) * mpf(10) ** (-BASE_DPS // 2):
                raise SystemExit(f"Pi principal value mismatch at n={n}, phi={phi}")
        return pv
    return mpmath.ellippi(mpf(n), phi, m)


def incomplete_rows():
    rng = random.Random(20240503)
    rows = []

    def add(func, kind, phi, param, n=None):
        extra = (digits_of(param) if kind == "mc" else 0) + digits_of(phi)
        value = checked(lambda: incomplete_value(func, kind, phi, param, n), extra)
        rows.append([func, kind, fmt(phi), fmt(param), fmt(n) if n is not None else "",
                     fmt(value)])

    half = math.pi / 2
    phis = [rng.uniform(-half, half) for _ in range(12)]
    phis += [1e-10, 1e-3, 0.5, 1.0, 1.5, 1.5707963, half, -half, 2.0, 3.0, -4.0, 10.0,
             100.0, -1000.0, 1e5]
    ms = [rng.uniform(0.0, 1.0) for _ in range(6)] + [0.0, 1e-12, 0.99, 1.0 - 2.0**-40, -3.0]
    mcs = [1e-4, 1e-12, 1e-30, 1e-100, 1e-300]
    for func in ("F", "E"):
        for phi in phis:
            for m in ms:
                add(func, "m", phi, m)
            for mc in mcs:
                add(func, "mc", phi, mc)
        for phi in (0.1, 0.3, 0.5):  # m > 1 with sin^2 phi <= 1/m
            add(func, "m", phi, 2.0)
        add(func, "m", 1.2, 1.0)
        add(func, "m", 0.3, 1.0)
        add(func, "mc", 0.3, 0.0)
    for phi in phis[:6] + [0.5, 1.5, half, 3.0, -4.0, 10.0]:
        for n in (-10.0, -0.5, 0.0, 0.3, 0.9, 0.999999):
            for m in (0.2, 0.8, 0.0, -2.0):
                add("PI", "m", phi, m, n)
            for mc in (1e-8, 1e-300):
                add("PI", "mc", phi, mc, n)
    for phi in (0.3, 0.6, 1.2, -1.2, half):  # n > 1: principal value past sin^2 = 1/n
        for n in (1.5, 4.0):
            add("PI", "m", phi, 0.5, n)
    write(
        "elliptic_incomplete.csv",
        ["func", "kind", "phi", "param", "n", "value"],
        rows,
        """Incomplete elliptic integrals, mpmath reference (tests/data/gen/elliptic.py).
func: F = F(phi | m), E = E(phi | m), PI = Pi(n; phi | m) (Cauchy principal value for n > 1).
kind says whether param is m or mc = 1 - m (exact input). phi is any real amplitude.""",
    )


# --------------------------------------------------------------------------
# Jacobi elliptic functions
# --------------------------------------------------------------------------


def jacobi_value(kind, param, u):
    m = param_m(kind, param)
    u = mpf(u)
    if param_mc(kind, param) == 0:
        sn, cn = mpmath.tanh(u), mpmath.sech(u)
        dn = cn
        am = mpmath.atan(mpmath.sinh(u))
    else:
        sn, cn, dn = (mpmath.ellipfun(f, u, m) for f in ("sn", "cn", "dn"))
        sn, cn, dn = (v.real if isinstance(v, mpmath.mpc) else v for v in (sn, cn, dn))
        am = None
        if m < 1:
            kk = mpmath.ellipk(m)
            base = mpmath.atan2(sn, cn)
            lin = mpmath.pi * u / (2 * kk)
            am = base + 2 * mpmath.pi * mpmath.nint((lin - base) / (2 * mpmath.pi))
    if am is None:
        return (sn, cn, dn, mpf(0))
    return (sn, cn, dn, am)


def jacobi_rows():
    rng = random.Random(20240504)
    rows = []

    def add(kind, param, u, with_am=True):
        extra = (digits_of(param) if kind == "mc" else 0) + digits_of(u)
        sn, cn, dn, am = checked(lambda: jacobi_value(kind, param, u), extra)
        m_above_one = (param < 0.0) if kind == "mc" else (param > 1.0)
        am_text = fmt(am) if with_am and not m_above_one else ""
        rows.append([kind, fmt(param), fmt(u), fmt(sn), fmt(cn), fmt(dn), am_text])

    mcs = [1.0, 0.9, 0.5, 0.1, 1e-2, 1e-3, 1e-6, 1e-8, 1e-12, 1e-16, 1e-20, 1e-30, 1e-50,
           1e-100, 1e-200, 1e-300, 5e-324, 0.0]
    us = [1e-10, 1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 40.0, 100.0, 300.0,
          1000.0]
    for mc in mcs:
        for u in us:
            add("mc", mc, u)
            if u in (0.5, 3.0, 100.0):
                add("mc", mc, -u)
        for _ in range(6):
            add("mc", mc, loguniform(rng, 1e-2, 1e3) * rng.choice((-1.0, 1.0)))
        # near the quarter periods K, 2K, 3K, 4K and multiples (as f64)
        if mc > 0:
            with mp.workdps(BASE_DPS + digits_of(mc)):
                kk = mpmath.ellipk(1 - mpf(mc))
                quarter = [f64(j * kk) for j in (1, 2, 3, 4, 10, 39)]
            for q in quarter:
                for d in (0.0, 1e-9, -1e-3, 0.25):
                    add("mc", mc, q + d)
    # large arguments: accuracy of the reduction modulo 4K
    for mc in (0.5, 1e-3, 1e-12, 1e-300):
        for u in (1e4, 1.2345678e5, 1e6, -7.654321e5):
            add("mc", mc, u)
    # random (u, mc) pairs
    for _ in range(40):
        add("mc", rng.uniform(0.0, 1.0), rng.uniform(-20.0, 20.0))
    for _ in range(20):
        add("mc", loguniform(rng, 1e-300, 1e-2), rng.uniform(-500.0, 500.0))
    # parametrised by m, including m < 0 (mc > 1) and m > 1 (mc < 0)
    for m in (0.0, 0.3, 0.7, 0.999, 1.0, -0.5, -5.0, 1.5, 4.0):
        for u in (0.2, 1.0, 2.5, -7.0, 30.0):
            add("m", m, u)
    for mc in (2.0, 10.0, -0.5, -3.0):
        for u in (0.2, 1.0, 2.5, -7.0):
            add("mc", mc, u)
    write(
        "elliptic_jacobi.csv",
        ["kind", "param", "u", "sn", "cn", "dn", "am"],
        rows,
        """Jacobi elliptic functions sn, cn, dn and amplitude am, mpmath reference
(tests/data/gen/elliptic.py). kind says whether param is m or mc = 1 - m (exact input);
mc = 0 is the limit tanh/sech/sech and am = gd(u). am is empty where m > 1.
Rows with |u| >= 1e4 test the reduction modulo 4K.""",
    )


def main():
    carlson_rows()
    complete_rows()
    incomplete_rows()
    jacobi_rows()


if __name__ == "__main__":
    main()
