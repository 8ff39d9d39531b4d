"""Exact rotations (mpmath, 50 digits) for ground truth, shared by the
tests (test_rotations.py) and the benchmark (bench/bench_rotations.py)."""

import mpmath
from mpmath import mp, mpf

mp.dps = 50


def qmul(p, q):
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return (
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    )


def exact_quat_of_euler(seq, angles):
    """The exact quaternion (mpf, scalar first) of f64 Euler angles."""
    factors = []
    for letter, t in zip(seq, angles):
        half = mpf(float(t)) / 2
        v = [mpf(0)] * 3
        v["xyz".index(letter.lower())] = mpmath.sin(half)
        factors.append((mpmath.cos(half), *v))
    if seq.isupper():  # intrinsic: q_A(a0) q_B(a1) q_C(a2)
        q = qmul(qmul(factors[0], factors[1]), factors[2])
    else:  # extrinsic: q_c(a2) q_b(a1) q_a(a0)
        q = qmul(qmul(factors[2], factors[1]), factors[0])
    return q


def exact_angle_between(p, q):
    """Rotation angle (radians, as float) between two quaternions of any
    length, computed exactly (mpf) from their given values."""
    p = [mpf(float(x)) if not isinstance(x, mpmath.mpf) else x for x in p]
    q = [mpf(float(x)) if not isinstance(x, mpmath.mpf) else x for x in q]
    np_ = mpmath.sqrt(sum(x * x for x in p))
    nq = mpmath.sqrt(sum(x * x for x in q))
    conj = (p[0], -p[1], -p[2], -p[3])
    d = qmul(conj, q)
    v = mpmath.sqrt(d[1] ** 2 + d[2] ** 2 + d[3] ** 2)
    return float(2 * mpmath.atan2(v, abs(d[0])) if np_ * nq else mpf(0))


def f64_quat(q):
    """An mpf quaternion normalised and rounded to f64."""
    n = mpmath.sqrt(sum(x * x for x in q))
    return [float(x / n) for x in q]
