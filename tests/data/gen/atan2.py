"""The polynomial of kreisel-kinematics' atan2 and the reference values it is tested against.

Regenerate (from the repository root):

    pip install -r tests/data/gen/requirements.txt && python3 tests/data/gen/atan2.py

1. Fits P(s), degree 12, to (atan(sqrt s) - sqrt s) / (s sqrt s) on [0, 1/4]
   (mpmath.chebyfit, 40 digits: a Chebyshev fit, within a few percent of minimax), prints
   the coefficients rounded to f64 and its error, and checks that
   crates/kinematics/src/atan2.rs holds exactly these coefficients and pi/4 in two parts.
2. Writes tests/data/atan2.csv: y, x, hi, lo with hi + lo = atan2(y, x) to ~2^-106
   relative (mpmath, 50 digits, from the exact f64 arguments; hi correctly rounded to f64,
   lo the rounded rest), for finite non-zero arguments in all octants: points on
   circles of many radii, ratios next to the reduction's boundary (1/2) and at 1/3,
   tan(pi/8), 2/3, 1 and their reciprocals (a few ulps either side), tiny and huge
   ratios, subnormal arguments, and arguments up to 1e308. (Zeros, infinities and NaN
   follow IEEE 754 / C99 Annex F and are checked in the Rust test directly.)

Deterministic (fixed seed); floats written with repr (shortest round trip).
"""

import math
import os
import random
import re

import mpmath
from mpmath import libmp, mp, mpf

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir, os.pardir))
OUT = os.path.join(ROOT, "tests", "data", "atan2.csv")
RUST = os.path.join(ROOT, "crates", "kinematics", "src", "atan2.rs")

DEGREE = 12


def f64(x):
    """Correctly rounded (round-to-nearest-even) f64 value of an mpf, subnormals included."""
    x = mpf(x)
    if x != 0 and abs(x) < mpf(2) ** -1022:
        return math.ldexp(int(mp.nint(x * mpf(2) ** 1074)), -1074)
    return libmp.to_float(x._mpf_, strict=True, rnd=libmp.round_nearest)


def fit():
    top = mpf("0.25") * mpf("1.0005")  # t up to 1/2, and a little beyond

    def g(s):
        if s == 0:
            return mpf(-1) / 3
        r = mp.sqrt(s)
        return (mp.atan(r) - r) / (s * r)

    poly, err = mp.chebyfit(g, [0, top], DEGREE + 1, error=True)
    coefficients = [f64(c) for c in reversed(poly)]  # lowest degree first
    # relative error in atan t = t + t s P(s): s * |error of P| <= top * err
    print(f"P: degree {DEGREE}, |error| {mp.nstr(err, 3)}, in atan t relative {mp.nstr(err * top, 3)}")
    for c in coefficients:
        print(f"    {c!r},")
    quarter = (f64(mp.pi / 4), f64(mp.pi / 4 - f64(mp.pi / 4)))
    return coefficients, quarter


def rust_floats(text):
    return [float(v.replace("_", "")) for v in re.findall(r"-?\d[\d_]*\.[\d_]+(?:e-?\d+)?", text)]


def check_rust(coefficients, quarter):
    src = open(RUST, encoding="utf-8").read()
    block = re.search(r"const P: \[f64; 13\] = \[(.*?)\];", src, re.S).group(1)
    assert rust_floats(block) == coefficients, "atan2.rs: P differs from the fit"
    assert re.search(r"const QUARTER_PI_HI: f64 = core::f64::consts::FRAC_PI_4;", src)
    hi = math.pi / 4  # FRAC_PI_4: pi rounded, divided by 4 (exact)
    lo = rust_floats(re.search(r"const QUARTER_PI_LO: f64 = (.*?);", src).group(1))[0]
    assert (hi, lo) == quarter, "atan2.rs: pi/4 differs"
    # k * hi exact for k = 0 .. 4: hi ends in three zero bits
    assert (hi * 2**53).is_integer() and (int(hi * 2**53) % 8) == 0
    print("atan2.rs holds these constants")


def ulps_around(v, n):
    out = [v]
    up = down = v
    for _ in range(n):
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
        out += [up, down]
    return out


def arguments(rng):
    signs = [(1, 1), (1, -1), (-1, 1), (-1, -1)]
    args = []
    # points on circles, radius 1e-3 .. 1e3, angle uniform
    for _ in range(1600):
        r = 10.0 ** rng.uniform(-3, 3)
        t = rng.uniform(-math.pi, math.pi)
        args.append((r * math.sin(t), r * math.cos(t)))
    # unit-quaternion-like products (what from_quat passes): sums of products of components
    for _ in range(400):
        q = [rng.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(c * c for c in q))
        w, x, y, z = (c / n for c in q)
        args.append((x * w + y * z, w * w - x * x))
    # ratios next to the reduction's boundary (1/2), where |t| is largest (1/2 and 1/3),
    # at 1, tan(pi/8) and 2/3 (and, swapped, their reciprocals)
    for ratio in [0.5, 1.0 / 3.0, 1.0, math.tan(math.pi / 8), 2.0 / 3.0]:
        for r in ulps_around(ratio, 6):
            for scale in [1.0, 3.7, 1e-5]:
                for sy, sx in signs:
                    args.append((sy * r * scale, sx * scale))
                    args.append((sx * scale, sy * r * scale))
    for e in range(-320, 309, 7):
        for sy, sx in signs:
            m = rng.uniform(1, 2)
            args.append((sy * m * 10.0**e if e > -308 else sy * 5e-324 * rng.randint(1, 2**40), sx * 1.0))
            args.append((sx * 1.0, sy * m * 10.0**e if e > -308 else sy * 5e-324 * rng.randint(1, 2**40)))
    # independent log-uniform magnitudes (ratios from 1e-600 to 1e600), random signs
    for _ in range(500):
        y = rng.choice([-1, 1]) * 10.0 ** rng.uniform(-300, 300)
        x = rng.choice([-1, 1]) * 10.0 ** rng.uniform(-300, 300)
        args.append((y, x))
    # subnormal arguments, alone and together
    for _ in range(60):
        a = 5e-324 * rng.randint(1, 2**52 - 1)
        b = 5e-324 * rng.randint(1, 2**52 - 1)
        sy, sx = rng.choice(signs)
        args += [(sy * a, sx * b), (sy * a, sx * rng.uniform(1e-310, 1.0)), (sy * rng.uniform(1e-310, 1.0), sx * b)]
    # results next to +-pi and +-pi/2
    for d in [1e-300, 1e-100, 1e-17, 1e-16, 1e-9, 1e-3]:
        for sy in [1, -1]:
            args += [(sy * d, -1.0), (sy * 1.0, d), (sy * 1.0, -d), (sy * d, 1.0)]
    # large arguments (the library's atan2 takes over above 2^1020)
    for v in [1e300, 1e307, 1.1e307, 1.2e307, 1e308, 1.7e308, 1.7976931348623157e308]:
        for sy, sx in signs:
            args += [(sy * v, sx * v * 0.9), (sy * v, sx * 1.0), (sy * 1.0, sx * v)]
    return [(y, x) for y, x in args if y != 0 and x != 0 and math.isfinite(y) and math.isfinite(x)]


def main():
    coefficients, quarter = fit()
    check_rust(coefficients, quarter)
    rng = random.Random(20261124)
    rows = []
    for y, x in arguments(rng):
        v = mp.atan2(mpf(y), mpf(x))
        hi = f64(v)
        lo = f64(v - mpf(hi))
        rows.append(f"{y!r},{x!r},{hi!r},{lo!r}")
    with open(OUT, "w", encoding="utf-8") as out:
        out.write("# atan2(y, x) = hi + lo (mpmath 50 digits, hi correctly rounded); tests/data/gen/atan2.py\n")
        out.write("y,x,hi,lo\n")
        out.write("\n".join(rows) + "\n")
    print(f"wrote {len(rows)} rows to {os.path.relpath(OUT, ROOT)}")


if __name__ == "__main__":
    main()
