"""Generate the committed rotation reference data used by the Rust tests.

Regenerate (from the repository root):

    pip install -r tests/data/gen/requirements.txt && python3 tests/data/gen/rotations.py

Writes, relative to this script's location (i.e. into tests/data/):

    euler_to_quat.csv     Euler angles -> quaternion (24 conventions)
    quat_to_euler.csv     quaternion -> Euler angles (+ scipy's answer and its error)
    representations.csv   quaternion -> rotation matrix and rotation vector

Conventions
-----------
* Quaternions are scalar-first (w, x, y, z) everywhere in the CSV files
  (scipy uses scalar-last internally; converted here).
* Euler conventions are named like scipy: uppercase ("ZXZ") = intrinsic,
  lowercase ("zxz") = extrinsic.  Intrinsic "ABC" with angles (a0, a1, a2) is
  q = q_A(a0) * q_B(a1) * q_C(a2); extrinsic "abc" is
  q = q_c(a2) * q_b(a1) * q_a(a0), with q_axis(t) = (cos t/2, sin t/2 * e_axis).
* Angles in radians.  Reference angle ranges: first/third in (-pi, pi],
  middle in [0, pi] (proper Euler) or [-pi/2, pi/2] (Tait-Bryan).
* Rotation matrices are active (body -> world, v_world = M v_body), row-major.
* Rotation vectors are axis * angle with angle in [0, pi].
* The reference values are computed with mpmath at 50 significant digits from
  the exact f64 inputs (the quaternion is normalised in mpmath first), then
  correctly rounded (round-to-nearest) to f64.  scipy is only used as a
  cross-check (and, in quat_to_euler.csv, documented as a comparison).
* Every float is written with repr(float(x)) (shortest round-trip form).

The script is deterministic (fixed numpy seeds, one per file).
"""

import math
import os
import sys
import warnings

import mpmath
import numpy as np
import scipy
from mpmath import mp, mpf
from mpmath import libmp
from scipy.spatial.transform import Rotation

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, os.pardir))  # tests/data

PINNED = {"scipy": "1.17.1", "numpy": "2.4.6", "mpmath": "1.3.0"}
VERSIONS = {"scipy": scipy.__version__, "numpy": np.__version__, "mpmath": mpmath.__version__}

TAIT_BRYAN = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]
PROPER = ["XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"]
CONVENTIONS = TAIT_BRYAN + PROPER + [s.lower() for s in TAIT_BRYAN + PROPER]

N_RANDOM_EULER = 40  # random rows per convention
N_PER_DELTA = 2      # random (first, third) pairs per (lock, delta)

DELTAS_E2Q = ["0", "1e-15", "1e-12", "1e-9", "1e-7", "1e-5", "1e-3"]
DELTAS_Q2E = ["0", "1e-15", "1e-14", "1e-13", "1e-12", "1e-11", "1e-10",
              "1e-9", "1e-8", "1e-7", "1e-5", "1e-3"]

AXIS_INDEX = {"x": 0, "y": 1, "z": 2}


# --------------------------------------------------------------------------
# mpmath helpers
# --------------------------------------------------------------------------

def f64(x):
    """Correctly rounded (round-to-nearest-even) f64 value of an mpf."""
    x = mpf(x)
    return libmp.to_float(x._mpf_, strict=True, rnd=libmp.round_nearest)


def f64_chop(x, tiny=mpf("1e-40")):
    """Like f64, but maps mpmath noise around an exact zero (|x| < 1e-40) to 0.0.

    Only used where no legitimate value can be that small."""
    x = mpf(x)
    return 0.0 if abs(x) < tiny else f64(x)


def fmt(x):
    return repr(float(x))


def qmul(p, q):
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return (
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    )


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


def qnorm(q):
    return mp.sqrt(sum(c * c for c in q))


def qnormalize(q):
    n = qnorm(q)
    return tuple(c / n for c in q)


def mpq(q):
    """f64 quaternion (w, x, y, z) -> exact mpf tuple."""
    return tuple(mpf(float(c)) for c in q)


def axis_quat(axis, t):
    h = mpf(t) / 2
    q = [mp.cos(h), mpf(0), mpf(0), mpf(0)]
    q[1 + axis] = mp.sin(h)
    return tuple(q)


def is_proper(seq):
    return seq[0].lower() == seq[2].lower()


def is_intrinsic(seq):
    return seq.isupper()


def euler_to_quat_mp(seq, angles):
    """Exact (50-digit) quaternion of the Euler triple; angles are mpf/float."""
    axes = [AXIS_INDEX[c] for c in seq.lower()]
    qa, qb, qc = (axis_quat(ax, a) for ax, a in zip(axes, angles))
    if is_intrinsic(seq):
        return qmul(qmul(qa, qb), qc)
    return qmul(qmul(qc, qb), qa)


def quat_to_matrix_mp(q):
    """Active rotation matrix (row-major, v_world = M v_body) of q / |q|."""
    w, x, y, z = qnormalize(q)
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def parity(i, j, k):
    return 1 if (i, j, k) in ((0, 1, 2), (1, 2, 0), (2, 0, 1)) else -1


def matrix_to_intrinsic_euler_mp(axes, m):
    """Angles (alpha, beta, gamma) with M = R_i(alpha) R_j(beta) R_k(gamma).

    Ranges: alpha, gamma in (-pi, pi]; beta in [0, pi] (proper) or
    [-pi/2, pi/2] (Tait-Bryan).  (mpmath's atan2 has no signed zero, so it
    returns +pi, never -pi.)"""
    i, j, k = axes
    if i == k:  # proper Euler i-j-i; l = remaining axis
        l = 3 - i - j
        e = parity(i, j, l)
        beta = mp.atan2(mp.sqrt(m[i][j] ** 2 + m[i][l] ** 2), m[i][i])
        alpha = mp.atan2(m[j][i], -e * m[l][i])
        gamma = mp.atan2(m[i][j], e * m[i][l])
    else:  # Tait-Bryan i-j-k
        e = parity(i, j, k)
        beta = mp.atan2(e * m[i][k], mp.sqrt(m[i][i] ** 2 + m[i][j] ** 2))
        alpha = mp.atan2(-e * m[j][k], m[k][k])
        gamma = mp.atan2(-e * m[i][j], m[i][i])
    return alpha, beta, gamma


def quat_to_euler_mp(seq, q):
    m = quat_to_matrix_mp(q)
    axes = [AXIS_INDEX[c] for c in seq.lower()]
    if is_intrinsic(seq):
        return matrix_to_intrinsic_euler_mp(axes, m)
    # extrinsic abc (a0, a1, a2) == intrinsic CBA (a2, a1, a0)
    g, b, a = matrix_to_intrinsic_euler_mp(axes[::-1], m)
    return a, b, g


def rot_angle_between(q1, q2):
    """Rotation angle (in [0, pi]) of q1^-1 * q2 (both normalised first)."""
    d = qmul(qconj(qnormalize(q1)), qnormalize(q2))
    return 2 * mp.atan2(mp.sqrt(d[1] ** 2 + d[2] ** 2 + d[3] ** 2), abs(d[0]))


def rotvec_mp(q):
    """Rotation vector of q/|q|: axis*angle, angle in [0, pi].

    q is first made canonical like scipy does: the first non-zero component of
    (w, x, y, z) positive.  This only matters at angle = pi (w = 0), where it
    makes the first non-zero component of the rotation vector positive, so
    the rotation vector is a function of the rotation alone."""
    w, x, y, z = qnormalize(q)
    first_nonzero = next(c for c in (w, x, y, z) if c != 0)
    if first_nonzero < 0:
        w, x, y, z = -w, -x, -y, -z
    vn = mp.sqrt(x * x + y * y + z * z)
    if vn == 0:
        return (mpf(0), mpf(0), mpf(0))
    angle = 2 * mp.atan2(vn, w)
    s = angle / vn
    return (x * s, y * s, z * s)


def wrap_diff(a, b):
    """|a - b| modulo 2*pi, in [0, pi] (floats)."""
    d = math.fmod(float(a) - float(b), 2 * math.pi)
    if d > math.pi:
        d -= 2 * math.pi
    elif d < -math.pi:
        d += 2 * math.pi
    return abs(d)


# --------------------------------------------------------------------------
# scipy helpers (always one rotation at a time: for a single quaternion scipy
# uses its Cython backend; for N-D batches it uses a different "array API"
# backend that wraps angles into [-pi, pi) instead of [-pi, pi])
# --------------------------------------------------------------------------

def scipy_from_wxyz(q):
    w, x, y, z = (float(c) for c in q)
    return Rotation.from_quat(np.array([x, y, z, w]))


def scipy_euler_to_wxyz(seq, angles):
    x, y, z, w = Rotation.from_euler(seq, np.array([float(a) for a in angles])).as_quat()
    return (w, x, y, z)


def scipy_as_euler(seq, q):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # "Gimbal lock detected"
        return [float(a) for a in scipy_from_wxyz(q).as_euler(seq)]


# --------------------------------------------------------------------------
# shared generation helpers
# --------------------------------------------------------------------------

def lock_values(seq):
    """[(exact lock value, direction into the valid middle range), ...]"""
    if is_proper(seq):
        return [(mpf(0), +1), (mp.pi, -1)]
    return [(mp.pi / 2, -1), (-mp.pi / 2, +1)]


def random_outer_angle(rng):
    """Uniform in (-pi, pi]."""
    return float(np.pi - rng.uniform(0.0, 2.0 * np.pi))


def random_middle_angle(rng, seq):
    if is_proper(seq):
        return float(rng.uniform(0.0, np.pi))
    return float(rng.uniform(-np.pi / 2, np.pi / 2))


def header_comment(extra_lines=()):
    lines = [
        "# generated by tests/data/gen/rotations.py (scipy %s, numpy %s, mpmath %s, mp.dps=%d) -- do not edit"
        % (VERSIONS["scipy"], VERSIONS["numpy"], VERSIONS["mpmath"], mp.dps)
    ]
    lines += ["# " + s for s in extra_lines]
    return lines


def write_csv(name, comments, header, rows):
    path = os.path.join(OUT_DIR, name)
    with open(path, "w", newline="\n", encoding="ascii") as f:
        for c in comments:
            f.write(c + "\n")
        f.write(header + "\n")
        for r in rows:
            f.write(",".join(r) + "\n")
    return path


# --------------------------------------------------------------------------
# 1. euler_to_quat.csv
# --------------------------------------------------------------------------

def gen_euler_to_quat():
    rng = np.random.default_rng(0x6B7265_01)
    rows = []
    max_diff = 0.0
    for seq in CONVENTIONS:
        triples = []
        for _ in range(N_RANDOM_EULER):
            a0 = random_outer_angle(rng)
            a1 = random_middle_angle(rng, seq)
            a2 = random_outer_angle(rng)
            triples.append(("random", (a0, a1, a2)))
        for lock, direction in lock_values(seq):
            for d in DELTAS_E2Q:
                mid = f64(lock + direction * mpf(d))
                for _ in range(N_PER_DELTA):
                    a0 = random_outer_angle(rng)
                    a2 = random_outer_angle(rng)
                    triples.append(("lock" if d == "0" else "near_lock", (a0, mid, a2)))

        for case, angles in triples:
            q_sp = scipy_euler_to_wxyz(seq, angles)
            q_mp = euler_to_quat_mp(seq, [mpf(a) for a in angles])
            if sum(mpf(float(a)) * b for a, b in zip(q_sp, q_mp)) < 0:
                q_mp = tuple(-c for c in q_mp)
            q_out = [f64(c) for c in q_mp]
            diff = max(abs(a - b) for a, b in zip(q_sp, q_out))
            assert diff <= 1e-15, (seq, angles, q_sp, q_out, diff)
            max_diff = max(max_diff, diff)
            rows.append([seq, case] + [fmt(a) for a in angles] + [fmt(c) for c in q_out])

    comments = header_comment([
        "q = exact (mpmath) quaternion of the f64 angles, scalar-first, sign aligned with "
        "scipy Rotation.from_euler(seq, [a0,a1,a2]).as_quat(); uppercase seq = intrinsic, lowercase = extrinsic",
        "lock rows use the f64 value of the lock angle (f64(pi/2) and f64(pi) are not exactly pi/2, pi)",
    ])
    write_csv("euler_to_quat.csv", comments, "seq,case,a0,a1,a2,qw,qx,qy,qz", rows)
    return len(rows), max_diff


# --------------------------------------------------------------------------
# 2. quat_to_euler.csv
# --------------------------------------------------------------------------

def gen_quat_to_euler():
    rng = np.random.default_rng(0x6B7265_02)
    rows = []
    err_by_delta = {}      # delta -> max scipy_err over all conventions
    max_random_recompose = mpf(0)
    max_random_scipy_angle = 0.0
    max_random_scipy_err = mpf(0)
    for seq in CONVENTIONS:
        items = []  # (case, delta, f64 quaternion, reference angles as floats)
        for _ in range(N_RANDOM_EULER):
            v = rng.standard_normal(4)
            q_in = tuple(f64(c) for c in qnormalize(tuple(mpf(float(c)) for c in v)))
            ang_mp = quat_to_euler_mp(seq, mpq(q_in))
            ang = tuple(f64(a) for a in ang_mp)
            # exact angles (rounded to f64) recompose to the input rotation
            rec = rot_angle_between(mpq(q_in), euler_to_quat_mp(seq, [mpf(a) for a in ang]))
            assert rec <= mpf("1e-15"), (seq, q_in, ang, rec)
            max_random_recompose = max(max_random_recompose, rec)
            items.append(("random", None, q_in, ang))
        for lock, direction in lock_values(seq):
            for d in DELTAS_Q2E:
                mid = lock + direction * mpf(d)
                for _ in range(N_PER_DELTA):
                    a0 = random_outer_angle(rng)
                    a2 = random_outer_angle(rng)
                    q_exact = euler_to_quat_mp(seq, [mpf(a0), mid, mpf(a2)])
                    q_in = tuple(f64_chop(c) for c in q_exact)
                    ang = (a0, f64(mid), a2)
                    # the generating angles describe the f64 quaternion up to its rounding
                    rec = rot_angle_between(mpq(q_in), euler_to_quat_mp(seq, [mpf(a) for a in ang]))
                    assert rec <= mpf("1e-15"), (seq, q_in, ang, rec)
                    items.append(("lock" if d == "0" else "near_lock", d, q_in, ang))

        for case, d, q_in, ang in items:
            sp = scipy_as_euler(seq, q_in)
            err = rot_angle_between(mpq(q_in), euler_to_quat_mp(seq, [mpf(a) for a in sp]))
            if case == "random":
                for a, b in zip(sp, ang):
                    diff = wrap_diff(a, b)
                    assert diff <= 1e-13, (seq, q_in, sp, ang)
                    max_random_scipy_angle = max(max_random_scipy_angle, diff)
                max_random_scipy_err = max(max_random_scipy_err, err)
            else:
                err_by_delta[d] = max(err_by_delta.get(d, 0.0), f64(err))
            rows.append([seq, case] + [fmt(c) for c in q_in] + [fmt(a) for a in ang]
                        + [fmt(a) for a in sp] + [fmt(f64(err))])

    comments = header_comment([
        "random: a0..a2 = exact (mpmath) Euler angles of the f64 quaternion, rounded; "
        "first/third in (-pi,pi], middle in [0,pi] (proper) or [-pi/2,pi/2] (Tait-Bryan)",
        "near_lock/lock: quaternion = exact quaternion of (a0, lock +- delta, a2) rounded to f64; "
        "a0..a2 = the generating angles (for lock rows the decomposition is not unique: compare rotations)",
        "scipy_a* = scipy Rotation.as_euler(seq) (single-rotation/Cython path); "
        "scipy_err = rotation angle [rad] between the input and the rotation recomposed (in mpmath) from scipy_a*",
    ])
    write_csv("quat_to_euler.csv", comments,
              "seq,case,qw,qx,qy,qz,a0,a1,a2,scipy_a0,scipy_a1,scipy_a2,scipy_err", rows)
    return (len(rows), err_by_delta, f64(max_random_recompose), max_random_scipy_angle,
            f64(max_random_scipy_err))


# --------------------------------------------------------------------------
# 3. representations.csv
# --------------------------------------------------------------------------

def gen_representations():
    rng = np.random.default_rng(0x6B7265_03)

    def random_axis():
        return qnormalize_vec(tuple(mpf(float(c)) for c in rng.standard_normal(3)))

    def qnormalize_vec(v):
        n = mp.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    def axis_angle_quat(axis, angle):
        h = angle / 2
        s = mp.sin(h)
        return (mp.cos(h),) + tuple(s * c for c in axis)

    coord_axes = [(mpf(1), mpf(0), mpf(0)), (mpf(0), mpf(1), mpf(0)), (mpf(0), mpf(0), mpf(1))]

    items = [("identity", (1.0, 0.0, 0.0, 0.0))]
    for _ in range(200):
        q = qnormalize(tuple(mpf(float(c)) for c in rng.standard_normal(4)))
        if q[0] < 0:
            q = tuple(-c for c in q)
        items.append(("random", tuple(f64(c) for c in q)))
    for t in ["1e-300", "1e-200", "1e-100", "1e-20", "1e-12", "1e-8", "1e-4"]:
        for _ in range(2):
            items.append(("tiny", tuple(f64(c) for c in axis_angle_quat(random_axis(), mpf(t)))))
    for eps in ["0", "1e-15", "1e-12", "1e-8", "1e-4"]:
        axes = [random_axis(), random_axis()] + ([] if eps == "0" else coord_axes)
        for ax in axes:
            if eps == "0":
                q = (0.0,) + tuple(f64(c) for c in ax)  # w = cos(pi/2) = 0 exactly
                items.append(("pi", q))
            else:
                q = axis_angle_quat(ax, mp.pi - mpf(eps))
                items.append(("near_pi", tuple(f64(c) for c in q)))
    # exactly pi about the coordinate axes, with both signs of the vector part
    # (w = 0, so q and -q both have w >= 0; they must give the same matrix and rotvec)
    for ax in coord_axes + [tuple(-c for c in a) for a in coord_axes]:
        items.append(("pi", (0.0,) + tuple(f64(c) for c in ax)))

    rows = []
    max_m = 0.0
    max_rv_rel = {}
    for case, q_in in items:
        m = quat_to_matrix_mp(mpq(q_in))
        rv = rotvec_mp(mpq(q_in))
        m_out = [f64(m[r][c]) for r in range(3) for c in range(3)]
        rv_out = [f64(c) for c in rv]
        r_sp = scipy_from_wxyz(q_in)
        m_sp = r_sp.as_matrix().reshape(-1)
        rv_sp = r_sp.as_rotvec()
        dm = max(abs(float(a) - b) for a, b in zip(m_sp, m_out))
        assert dm <= 1e-15, (case, q_in, dm)
        max_m = max(max_m, dm)
        rv_norm = math.sqrt(sum(c * c for c in rv_out))
        drv = math.sqrt(sum((float(a) - b) ** 2 for a, b in zip(rv_sp, rv_out)))
        rel = drv / rv_norm if rv_norm > 0 else drv
        assert rel <= 1e-14, (case, q_in, rv_sp, rv_out, rel)  # also holds for tiny angles
        max_rv_rel[case] = max(max_rv_rel.get(case, 0.0), rel)
        rows.append([case] + [fmt(c) for c in q_in] + [fmt(c) for c in m_out] + [fmt(c) for c in rv_out])

    comments = header_comment([
        "m = active rotation matrix of q/|q| (v_world = M v_body), row-major; "
        "r = rotation vector axis*angle, angle in [0,pi]; at angle pi (w = 0) r is taken from the canonical quaternion "
        "(first non-zero of w,x,y,z positive, as scipy), i.e. the first non-zero component of r is positive",
        "all values computed in mpmath from the exact f64 quaternion (canonical w >= 0), then rounded",
    ])
    write_csv("representations.csv", comments,
              "case,qw,qx,qy,qz,m00,m01,m02,m10,m11,m12,m20,m21,m22,rx,ry,rz", rows)
    return len(rows), max_m, max_rv_rel


# --------------------------------------------------------------------------

def self_test_extraction():
    """The mpmath extraction inverts the mpmath composition for every convention."""
    rng = np.random.default_rng(12345)
    for seq in CONVENTIONS:
        for _ in range(5):
            ang = [mpf(random_outer_angle(rng)), mpf(random_middle_angle(rng, seq)),
                   mpf(random_outer_angle(rng))]
            back = quat_to_euler_mp(seq, euler_to_quat_mp(seq, ang))
            assert max(abs(a - b) for a, b in zip(ang, back)) < mpf("1e-40"), (seq, ang, back)


def main():
    for k, v in PINNED.items():
        if VERSIONS[k] != v:
            print("warning: %s %s differs from the pinned %s; output may differ"
                  % (k, VERSIONS[k], v), file=sys.stderr)
    self_test_extraction()

    n1, d1 = gen_euler_to_quat()
    n2, err_by_delta, rec, ang_diff, rnd_err = gen_quat_to_euler()
    n3, dm, rv_rel = gen_representations()

    print("versions: " + ", ".join("%s %s" % kv for kv in VERSIONS.items()))
    for name, n in [("euler_to_quat.csv", n1), ("quat_to_euler.csv", n2), ("representations.csv", n3)]:
        size = os.path.getsize(os.path.join(OUT_DIR, name))
        print("%-22s %5d rows  %8d bytes" % (name, n, size))
    print("euler_to_quat: max |scipy - exact| quaternion component = %.3g" % d1)
    print("quat_to_euler random: max recomposition error of rounded exact angles = %.3g rad" % rec)
    print("quat_to_euler random: max |scipy - exact| angle (mod 2pi) = %.3g rad, max scipy_err = %.3g rad"
          % (ang_diff, rnd_err))
    print("quat_to_euler near_lock/lock: max scipy_err per delta (all 24 conventions):")
    for d in DELTAS_Q2E:
        print("  delta = %-6s  max scipy_err = %.3e rad" % (d, err_by_delta[d]))
    print("representations: max |scipy - exact| matrix entry = %.3g" % dm)
    print("representations: max relative |scipy - exact| rotvec per case: "
          + ", ".join("%s %.3g" % kv for kv in rv_rel.items()))


if __name__ == "__main__":
    main()
