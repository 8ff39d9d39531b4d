"""Shared helpers of the kreisel Python tests: exact (mpmath, 50 digits)
rotations for ground truth, the repository's paths and the CLI binary."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

import mpmath
from mpmath import mp, mpf

mp.dps = 50

REPO = Path(__file__).resolve().parents[3]
DATA = REPO / "tests" / "data"

TAIT_BRYAN = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]
PROPER = ["XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"]
SEQUENCES = TAIT_BRYAN + PROPER + [s.lower() for s in TAIT_BRYAN + PROPER]


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


def kreisel_binary():
    """The `kreisel` CLI: $KREISEL_BIN, else the workspace's built binary
    (release, then debug), else one built now with cargo, else None."""
    if os.environ.get("KREISEL_BIN"):
        return os.environ["KREISEL_BIN"]
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    for profile in ("release", "debug"):
        path = target / profile / "kreisel"
        if path.exists():
            return str(path)
    if shutil.which("cargo"):
        build = ["cargo", "build", "-q", "--release", "-p", "kreisel-cli"]
        if subprocess.run(build, cwd=REPO).returncode == 0 and (target / "release" / "kreisel").exists():
            return str(target / "release" / "kreisel")
    return shutil.which("kreisel")


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI; returns (exit status, stdout, stderr)."""
    binary = kreisel_binary()
    if binary is None:
        pytest.skip("no kreisel binary: build it with `cargo build -p kreisel-cli --release` or set KREISEL_BIN")

    def run(*args, stdin=None):
        done = subprocess.run([binary, *args], input=stdin, capture_output=True, text=True)
        return done.returncode, done.stdout, done.stderr

    return run
