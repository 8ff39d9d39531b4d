"""kreisel vs scipy on 10⁶ rotations: from_euler and as_euler, speed and
accuracy side by side in one run.

    python crates/python/bench/bench_rotations.py [--n 1000000] [--repeat 7]

Speed: median wall time of --repeat runs of (kreisel and scipy alternately)
    kreisel.from_euler(seq, a)              vs  Rotation.from_euler(seq, a).as_quat()
    kreisel.as_euler(seq, q)                vs  Rotation.from_quat(q).as_euler(seq)
(both scalar-first where scipy offers it: as_quat(scalar_first=True) and
from_quat(q, scalar_first=True)), for an intrinsic and an extrinsic,
a Tait–Bryan and a proper sequence.

Accuracy: rotation angle between the input quaternion and the rotation
recomposed exactly (mpmath, 50 digits) from each library's f64 angles, on
random rotations and next to gimbal lock (middle angle 1e-3 .. 1e-12 rad
from the lock), over a sample of each set (mpmath is slow).
"""

import argparse
import math
import os

# numpy's OpenBLAS worker threads spin-wait after a BLAS call and take a core
# from whatever runs next (`perf`: blas_thread_server); neither library's
# rotations use BLAS threads (scipy's times are the same either way), so
# keep them from skewing the comparison. Set before numpy is imported.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import statistics
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

import kreisel

# The tests' exact (mpmath) rotations.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from mp_reference import exact_angle_between, exact_quat_of_euler  # noqa: E402
SEQS = ["ZYX", "xyz", "ZXZ", "yxy"]
PROPER = {"XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"}


def exact_error(q, seq, angles):
    """Rotation angle between the f64 quaternion q and the exact rotation of angles."""
    return exact_angle_between(q, exact_quat_of_euler(seq, angles))


def median_times(f, g, repeat):
    """Median wall times of f and g, called alternately (so that a change in
    the machine's load hits both alike)."""
    tf, tg = [], []
    for _ in range(repeat):
        for fn, times in ((f, tf), (g, tg)):
            t0 = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t0)
    return statistics.median(tf), statistics.median(tg)


def near_lock(seq, n, rng):
    locks = [0.0, math.pi] if seq.upper() in PROPER else [-math.pi / 2, math.pi / 2]
    deltas = 10.0 ** -rng.integers(3, 13, size=n)
    lock = np.array(locks)[rng.integers(0, 2, size=n)]
    middle = np.where(lock == 0.0, deltas, np.where(lock == math.pi, lock - deltas, lock - np.sign(lock) * deltas))
    a = rng.uniform(-math.pi, math.pi, size=(n, 3))
    a[:, 1] = middle
    return a


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--sample", type=int, default=300, help="rows per set checked in mpmath")
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    import scipy

    # scipy warns on every row at the lock (the near-lock accuracy sets)
    warnings.filterwarnings("ignore", message="Gimbal lock detected")
    print(f"kreisel {kreisel.__version__}, scipy {scipy.__version__}, numpy {np.__version__}, "
          f"python {sys.version.split()[0]}; n = {args.n}, median of {args.repeat}; "
          f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}")
    print(f"{'seq':4} {'op':10} {'kreisel ms':>10} {'scipy ms':>9} {'ratio':>6}   "
          f"{'kreisel err random':>18} {'scipy err random':>16} {'kreisel err lock':>16} {'scipy err lock':>14}")
    worst = {"ratio_from": math.inf, "ratio_as": math.inf, "k_err": 0.0, "s_err": 0.0}
    for seq in SEQS:
        angles = rng.uniform(-math.pi, math.pi, size=(args.n, 3))
        quats = kreisel.from_euler(seq, angles)
        tk, ts = median_times(lambda: kreisel.from_euler(seq, angles),
                              lambda: Rotation.from_euler(seq, angles).as_quat(scalar_first=True), args.repeat)
        # accuracy of from_euler: exact quaternion of the f64 angles
        idx = rng.integers(0, args.n, size=args.sample)
        qk = quats[idx]
        qs = Rotation.from_euler(seq, angles[idx]).as_quat(scalar_first=True)
        ek = max(exact_error(q, seq, a) for q, a in zip(qk, angles[idx]))
        es = max(exact_error(q, seq, a) for q, a in zip(qs, angles[idx]))
        lock_angles = near_lock(seq, args.sample, rng)
        ekl = max(exact_error(q, seq, a) for q, a in zip(kreisel.from_euler(seq, lock_angles), lock_angles))
        esl = max(exact_error(q, seq, a) for q, a in
                  zip(Rotation.from_euler(seq, lock_angles).as_quat(scalar_first=True), lock_angles))
        print(f"{seq:4} {'from_euler':10} {tk * 1e3:10.1f} {ts * 1e3:9.1f} {ts / tk:6.2f}   "
              f"{ek:18.1e} {es:16.1e} {ekl:16.1e} {esl:14.1e}")
        worst["ratio_from"] = min(worst["ratio_from"], ts / tk)
        worst["k_err"] = max(worst["k_err"], ek, ekl)

        tk, ts = median_times(lambda: kreisel.as_euler(seq, quats),
                              lambda: Rotation.from_quat(quats, scalar_first=True).as_euler(seq), args.repeat)
        ak = kreisel.as_euler(seq, quats[idx])
        as_ = Rotation.from_quat(quats[idx], scalar_first=True).as_euler(seq)
        ek = max(exact_error(q, seq, a) for q, a in zip(quats[idx], ak))
        es = max(exact_error(q, seq, a) for q, a in zip(quats[idx], as_))
        # next to the lock: the f64 quaternion (rounded exact) of near-lock angles
        ql = kreisel.from_euler(seq, lock_angles)
        ekl = max(exact_error(q, seq, a) for q, a in zip(ql, kreisel.as_euler(seq, ql)))
        esl = max(exact_error(q, seq, a) for q, a in zip(ql, Rotation.from_quat(ql, scalar_first=True).as_euler(seq)))
        print(f"{seq:4} {'as_euler':10} {tk * 1e3:10.1f} {ts * 1e3:9.1f} {ts / tk:6.2f}   "
              f"{ek:18.1e} {es:16.1e} {ekl:16.1e} {esl:14.1e}")
        worst["ratio_as"] = min(worst["ratio_as"], ts / tk)
        worst["k_err"] = max(worst["k_err"], ek, ekl)
        worst["s_err"] = max(worst["s_err"], es, esl)
    print(f"\nslowest ratio: from_euler {worst['ratio_from']:.2f}x, as_euler {worst['ratio_as']:.2f}x (goal >= 3x); "
          f"worst error: kreisel {worst['k_err']:.1e} rad (goal <= 1e-14), scipy as_euler {worst['s_err']:.1e} rad")


if __name__ == "__main__":
    main()
