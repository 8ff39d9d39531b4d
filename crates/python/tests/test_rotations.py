"""kreisel's rotations from Python: against exact (mpmath) references,
scipy's Rotation, the CLI bit for bit, and every error path.

Run: pytest crates/python/tests/test_rotations.py  (after `maturin develop`
or `pip install ./crates/python`; the CLI comparisons need the `kreisel`
binary, see kreisel_cli_runner.binary). Needs: pip install -r
crates/python/tests/requirements.txt.
"""

import csv
import doctest
import math
import threading

import numpy as np
import pytest

import kreisel
from conftest import DATA, PROPER, SEQUENCES
from mp_reference import exact_angle_between, exact_quat_of_euler, f64_quat

from scipy.spatial.transform import Rotation

REPRESENTATIONS = ["quat", "quat-xyzw", "matrix", "rotvec", "axis-angle", "euler:ZXZ", "euler:xyz", "euler:YZY"]
DELTAS = [1e-3, 1e-5, 1e-7, 1e-9, 1e-10, 1e-11, 1e-12]


def lock_angles(seq):
    return [0.0, math.pi] if seq.upper() in PROPER else [-math.pi / 2, math.pi / 2]


def near_lock_angles(seq, rng, per_delta=3):
    """Angles whose middle one is `delta` from a lock, both sides, for every
    delta in DELTAS (first and third random)."""
    rows = []
    for lock in lock_angles(seq):
        for delta in DELTAS:
            for side in (-1.0, 1.0):
                middle = lock + side * delta
                if seq.upper() in PROPER and not 0.0 <= middle <= math.pi:
                    middle = lock - side * delta
                for _ in range(per_delta):
                    rows.append([rng.uniform(-math.pi, math.pi), middle, rng.uniform(-math.pi, math.pi)])
    return np.array(rows)


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def angle_between(p, q):
    """Rotation angle between f64 quaternions (float, for quick checks)."""
    d = np.abs(np.sum(np.asarray(p) * np.asarray(q), axis=-1)) / (
        np.linalg.norm(p, axis=-1) * np.linalg.norm(q, axis=-1)
    )
    return 2 * np.arccos(np.minimum(d, 1.0))


# --- against the committed 50-digit references (tests/data/gen/rotations.py) ---


def test_from_euler_matches_the_exact_quaternions_of_the_committed_table():
    worst = 0.0
    for r in rows(DATA / "euler_to_quat.csv"):
        q = kreisel.from_euler(r["seq"], [float(r["a0"]), float(r["a1"]), float(r["a2"])])
        exact = [float(r[k]) for k in ("qw", "qx", "qy", "qz")]
        if exact[0] < 0 or (exact[0] == 0 and q[0] == 0 and np.dot(q, exact) < 0):
            exact = [-x for x in exact]
        assert q[0] >= 0.0
        worst = max(worst, float(np.max(np.abs(q - exact))))
    assert worst <= 4.5e-16, worst  # a few ulps of components of size <= 1


def test_as_euler_matches_the_committed_table():
    table = rows(DATA / "quat_to_euler.csv")
    random_rows = [r for r in table if r["case"] == "random"]
    assert len(random_rows) >= 24 * 40
    for r in random_rows:
        a = kreisel.as_euler(r["seq"], [float(r[k]) for k in ("qw", "qx", "qy", "qz")])
        expect = np.array([float(r["a0"]), float(r["a1"]), float(r["a2"])])
        assert np.max(np.abs(a - expect)) <= 2e-15, (r, a)
    # Next to and at the lock the angles are not unique: compare rotations,
    # recomposed exactly from kreisel's f64 angles.
    for r in table:
        if r["case"] == "random":
            continue
        q = [float(r[k]) for k in ("qw", "qx", "qy", "qz")]
        a = kreisel.as_euler(r["seq"], q)
        assert exact_angle_between(q, exact_quat_of_euler(r["seq"], a)) <= 1e-15, (r, a)


# --- against scipy and mpmath, all 24 sequences --------------------------------


@pytest.mark.parametrize("seq", SEQUENCES)
def test_random_rotations_agree_with_scipy(seq):
    rng = np.random.default_rng(abs(hash(seq)) % 2**32)
    angles = rng.uniform(-math.pi, math.pi, size=(500, 3))
    q = kreisel.from_euler(seq, angles)
    assert q.shape == (500, 4) and np.all(q[:, 0] >= 0)
    q_scipy = Rotation.from_euler(seq, angles).as_quat(scalar_first=True)
    assert np.max(angle_between(q, q_scipy)) < 1e-7  # arccos: ~sqrt(eps)
    assert np.max(np.abs(q - np.where(q_scipy[:, :1] < 0, -q_scipy, q_scipy))) < 1e-15
    back = kreisel.as_euler(seq, q)
    assert np.max(angle_between(kreisel.from_euler(seq, back), q)) < 1e-7
    a_scipy = Rotation.from_quat(q, scalar_first=True).as_euler(seq)
    assert np.max(angle_between(kreisel.from_euler(seq, a_scipy), q)) < 1e-7
    # the ranges of the CLI
    assert np.all(back[:, [0, 2]] > -math.pi) and np.all(back[:, [0, 2]] <= math.pi)
    if seq.upper() in PROPER:
        assert np.all(back[:, 1] >= 0) and np.all(back[:, 1] <= math.pi)
    else:
        assert np.all(np.abs(back[:, 1]) <= math.pi / 2)


NEAR_LOCK_ERRORS = {}


@pytest.mark.parametrize("seq", SEQUENCES)
def test_near_gimbal_lock_kreisel_is_exact_to_1e_14(seq):
    """Angles 1e-3 .. 1e-12 rad from the lock: the f64 quaternion of the
    exact rotation, decomposed by kreisel and by scipy, each recomposed
    exactly (mpmath) and compared with the input rotation."""
    rng = np.random.default_rng(7 + SEQUENCES.index(seq))
    angles = near_lock_angles(seq, rng)
    q = np.array([f64_quat(exact_quat_of_euler(seq, a)) for a in angles])
    ours = kreisel.as_euler(seq, q)
    theirs = Rotation.from_quat(q, scalar_first=True).as_euler(seq)
    err_ours = max(exact_angle_between(qi, exact_quat_of_euler(seq, a)) for qi, a in zip(q, ours))
    err_scipy = max(exact_angle_between(qi, exact_quat_of_euler(seq, a)) for qi, a in zip(q, theirs))
    NEAR_LOCK_ERRORS[seq] = (err_ours, err_scipy)
    assert err_ours <= 1e-14, err_ours
    # from_euler next to the lock: the exact quaternion of the f64 angles
    qs = kreisel.from_euler(seq, angles)
    err_from = max(exact_angle_between(qi, exact_quat_of_euler(seq, a)) for qi, a in zip(qs, angles))
    assert err_from <= 1e-15, err_from


def test_near_lock_record():
    """Records kreisel's and scipy's worst error next to the lock (printed
    with -s; the comparison itself is in the test above)."""
    if len(NEAR_LOCK_ERRORS) < len(SEQUENCES):
        pytest.skip("run together with the near-lock tests")
    ours = max(e[0] for e in NEAR_LOCK_ERRORS.values())
    scipy = max(e[1] for e in NEAR_LOCK_ERRORS.values())
    print(f"\nnear gimbal lock (1e-3..1e-12 rad, 24 sequences): kreisel {ours:.2e} rad, scipy {scipy:.2e} rad")
    assert ours <= 1e-14


def test_exact_lock_convention_third_angle_zero():
    s = math.sqrt(0.5)
    for seq in SEQUENCES:
        first, middle = seq[0].lower(), seq[1].lower()
        e_a = np.eye(3)["xyz".index(first)]
        e_b = np.eye(3)["xyz".index(middle)]
        if seq.upper() in PROPER:
            # about the first axis (middle angle 0) and a half turn about the middle axis (π)
            locked = [np.r_[math.cos(0.35), math.sin(0.35) * e_a], np.r_[0.0, e_b]]
            middles = [0.0, math.pi]
        else:
            # a quarter turn about the middle axis, either way: middle angle ±π/2
            locked = [np.r_[s, s * e_b], np.r_[s, -s * e_b]]
            middles = [math.pi / 2, -math.pi / 2]
        for q, middle in zip(locked, middles):
            a = kreisel.as_euler(seq, q)
            assert exact_angle_between(q, exact_quat_of_euler(seq, a)) <= 1e-15, (seq, a)
            assert a[1] == pytest.approx(middle, abs=1e-15) and a[2] == 0.0, (seq, a)
    # the f64 lock angles themselves (not exactly locked): rotations still exact
    for seq in SEQUENCES:
        for lock in lock_angles(seq):
            q = kreisel.from_euler(seq, [0.7, lock, -0.4])
            a = kreisel.as_euler(seq, q)
            assert exact_angle_between(q, exact_quat_of_euler(seq, a)) <= 1e-15


def test_degrees_and_leading_shapes():
    rng = np.random.default_rng(3)
    angles = rng.uniform(-180, 180, size=(2, 3, 5, 3))
    q = kreisel.from_euler("zyx", angles, degrees=True)
    assert q.shape == (2, 3, 5, 4) and q.dtype == np.float64
    assert np.array_equal(q, kreisel.from_euler("zyx", np.radians(angles)))  # to_radians == np.radians
    a = kreisel.as_euler("zyx", q, degrees=True)
    assert a.shape == (2, 3, 5, 3)
    assert np.max(angle_between(kreisel.from_euler("zyx", a, degrees=True), q)) < 1e-7
    assert kreisel.from_euler("ZXZ", [1, 2, 3]).shape == (4,)  # ints and lists
    assert kreisel.from_euler("ZXZ", np.zeros((0, 3))).shape == (0, 4)
    assert kreisel.from_euler("ZXZ", np.zeros((4, 0, 3))).shape == (4, 0, 4)
    f32 = kreisel.from_euler("ZXZ", np.float32([0.1, 0.2, 0.3]))
    assert np.array_equal(f32, kreisel.from_euler("ZXZ", [np.float32(0.1), np.float32(0.2), np.float32(0.3)]))
    strided = angles[:, ::2, ::-1]  # not contiguous
    assert np.array_equal(kreisel.from_euler("XYX", strided), kreisel.from_euler("XYX", strided.copy()))


def test_convert_matches_scipy_for_every_representation():
    rng = np.random.default_rng(11)
    r = Rotation.random(200, random_state=12)
    q = r.as_quat(scalar_first=True)
    got = kreisel.convert(q, "quat", "matrix")
    assert got.shape == (200, 3, 3)
    assert np.max(np.abs(got - r.as_matrix())) < 1e-15
    assert np.max(np.abs(kreisel.convert(got, "matrix", "rotvec") - r.as_rotvec())) < 1e-14
    assert np.max(np.abs(kreisel.convert(q, "quat", "quat-xyzw") - np.where(q[:, :1] < 0, -1, 1) * r.as_quat())) <= 2.3e-16  # 1 ulp: normalised
    aa = kreisel.convert(q, "quat", "axis-angle", degrees=True)
    assert np.max(np.abs(np.radians(aa[:, 3])[:, None] * aa[:, :3] - r.as_rotvec())) < 1e-14
    for src in REPRESENTATIONS:
        v = kreisel.convert(q, "quat", src)
        for dst in REPRESENTATIONS:
            back = kreisel.convert(kreisel.convert(v, src, dst), dst, "quat")
            assert np.max(angle_between(back, q)) < 1e-7, (src, dst)
    # an unnormalised quaternion is normalised, as in the CLI
    assert np.max(np.abs(kreisel.convert(3 * q, "quat", "quat") - kreisel.convert(q, "quat", "quat"))) <= 2.3e-16
    del rng


def test_rates_and_angular_velocity():
    rng = np.random.default_rng(5)
    for seq in SEQUENCES:
        angles = rng.uniform(-1.0, 1.0, size=(50, 3)) + [0.0, 1.5 if seq.upper() in PROPER else 0.0, 0.0]
        rates = rng.normal(size=(50, 3))
        # omega from a finite difference of the attitude (independent of the rate matrices)
        h = 1e-6
        q0 = kreisel.from_euler(seq, angles - h * rates)
        q1 = kreisel.from_euler(seq, angles + h * rates)
        for frame in ("body", "world"):
            fd = kreisel.omega_from_attitudes(np.stack([q0, q1], axis=-2), 2 * h, frame=frame)[:, 0]
            omega = kreisel.omega_from_rates(seq, angles, rates, frame=frame)
            assert np.max(np.abs(omega - fd)) < 1e-8, (seq, frame)
            back = kreisel.rates_from_omega(seq, angles, omega, frame=frame)
            assert np.max(np.abs(back - rates)) < 1e-13, (seq, frame)
        deg = kreisel.rates_from_omega(seq, np.degrees(angles), omega, frame="world", degrees=True)
        assert np.max(np.abs(deg - np.degrees(rates))) < 1e-11
    # broadcasting: one attitude, many angular velocities
    w = rng.normal(size=(4, 7, 3))
    out = kreisel.rates_from_omega("ZXZ", [0.1, 0.5, 0.2], w)
    assert out.shape == (4, 7, 3)
    assert np.array_equal(out[2, 3], kreisel.rates_from_omega("ZXZ", [0.1, 0.5, 0.2], w[2, 3]))


def test_omega_from_attitudes_constant_spin_and_series():
    # a constant body rate: exact for every step, both frames, batch axes
    omega = np.array([0.3, -0.2, 0.5])
    t = np.array([0.0, 0.1, 0.25, 0.7, 0.71])
    r = Rotation.from_euler("xyz", [0.2, 0.4, 1.0])
    q = np.stack([(r * Rotation.from_rotvec(omega * ti)).as_quat(scalar_first=True) for ti in t])
    w = kreisel.omega_from_attitudes(q, t)
    assert w.shape == (4, 3)
    assert np.max(np.abs(w - omega)) < 1e-13
    ww = kreisel.omega_from_attitudes(-q, t, frame="world")  # q and -q alike
    assert np.max(np.abs(ww - r.apply(omega))) < 1e-13
    batch = kreisel.omega_from_attitudes(np.stack([q, q, q]), t)
    assert batch.shape == (3, 4, 3)


def test_docstring_examples():
    names = ["from_euler", "as_euler", "convert", "rates_from_omega", "omega_from_rates", "omega_from_attitudes"]
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    parser = doctest.DocTestParser()
    for name in names:
        doc = getattr(kreisel, name).__doc__
        examples = parser.get_doctest(doc, {}, name, None, 0)
        assert examples.examples, name
        runner.run(examples)
    assert runner.summarize(verbose=False).failed == 0


# --- the CLI, bit for bit -------------------------------------------------


def test_same_numbers_as_the_cli(cli, tmp_path):
    """The committed quaternions and a few near-lock rows through `kreisel
    convert` and through kreisel.convert: identical f64s."""
    q = np.array([[float(r[k]) for k in ("qw", "qx", "qy", "qz")] for r in rows(DATA / "quat_to_euler.csv")])
    q = q[::7]
    for src in REPRESENTATIONS:
        for degrees in (False, True):
            values = kreisel.convert(q, "quat", src, degrees=degrees)
            flat = values.reshape(len(q), -1)
            path = tmp_path / "in.csv"
            path.write_text("".join(",".join(repr(float(x)) for x in row) + "\n" for row in flat))
            for dst in REPRESENTATIONS:
                args = ["convert", "--from", src, "--to", dst, "--input", str(path)]
                status, out, err = cli(*args, *(["--degrees"] if degrees else []))
                assert status == 0, err
                expect = np.array([[float(x) for x in line.split(",")] for line in out.splitlines()])
                got = kreisel.convert(values, src, dst, degrees=degrees).reshape(len(q), -1)
                assert np.array_equal(got, expect), (src, dst, degrees)


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "yxy"])
def test_as_euler_side_by_side_same_numbers_as_the_cli(cli, seq):
    """as_euler converts four rows at a time (SIMD lanes), the CLI one: every
    row the same f64s, whatever its neighbours — generic, next to and at the
    lock, unnormalised (tiny, huge, subnormal) — for 1 … 11 rows (whole
    blocks and the rest), and in degrees."""
    rng = np.random.default_rng(11)
    angles = np.concatenate([rng.uniform(-math.pi, math.pi, size=(8, 3)), near_lock_angles(seq, rng, per_delta=1)])
    locks = np.array([[0.3, lock, -1.2] for lock in lock_angles(seq)])
    q = kreisel.from_euler(seq, np.concatenate([angles, locks]))
    scales = rng.choice([1.0, 3.0, 1e-200, 1e200, 1e-310, -2.5], size=len(q))
    q = q * scales[:, None]
    rng.shuffle(q)
    text = "".join(",".join(repr(float(x)) for x in row) + "\n" for row in q)
    for degrees in (False, True):
        flags = ["--degrees"] if degrees else []
        status, out, err = cli("convert", "--from", "quat", "--to", f"euler:{seq}", *flags, stdin=text)
        assert status == 0, err
        expect = np.array([[float(x) for x in line.split(",")] for line in out.splitlines()])
        for n in range(1, 12):
            for start in (0, 5):
                got = kreisel.as_euler(seq, q[start : start + n], degrees=degrees)
                assert np.array_equal(got, expect[start : start + n]), (n, start, degrees)
        assert np.array_equal(kreisel.as_euler(seq, q, degrees=degrees), expect)


def test_as_euler_names_the_first_bad_row_in_a_block():
    q = kreisel.from_euler("ZYX", np.zeros((10, 3)))
    q[6] = [0.0, 0.0, np.inf, 1.0]
    q[5] = 0.0
    with pytest.raises(kreisel.KreiselError, match=r"^quats\[5\]: .*zero"):
        kreisel.as_euler("ZYX", q)
    q[5] = [1.0, np.nan, 0.0, 0.0]
    with pytest.raises(kreisel.KreiselError, match=r"^quats\[5\]: .*NaN"):
        kreisel.as_euler("ZYX", q)
    q[5] = 1.0
    with pytest.raises(kreisel.KreiselError, match=r"^quats\[6\]: .*inf"):
        kreisel.as_euler("ZYX", q)
    q[6] = 1.0
    q[9] = 0.0  # in the rest after two blocks of four
    with pytest.raises(kreisel.KreiselError, match=r"^quats\[9\]: .*zero"):
        kreisel.as_euler("ZYX", q)


@pytest.mark.parametrize(
    "src, dst, line",
    [
        ("quat", "rotvec", "0 0 0 0"),
        ("quat", "rotvec", "1 0 0"),
        ("matrix", "quat", "-1 0 0 0 1 0 0 0 1"),
        ("matrix", "quat", "1 0 0 0 1 0 0 0 1.1"),
        ("axis-angle", "quat", "0 0 0 1"),
        ("rotvec", "quat", "1.5e308 1.5e308 0"),
        ("euler:ZXZ", "quat", "1 2"),
    ],
)
def test_same_messages_as_the_cli(cli, src, dst, line):
    status, _, err = cli("convert", "--from", src, "--to", dst, stdin=line + "\n")
    assert status == 1
    cli_message = err.strip().split("line 1: ", 1)[1]
    values = np.array([float(x) for x in line.split()])
    if src == "matrix" and len(values) == 9:
        values = values.reshape(3, 3)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.convert(values, src, dst)
    message = str(e.value)
    if "expected" in cli_message:  # a shape problem: same count and name
        assert f"3 numbers for {src}" in message or f"4 numbers for {src}" in message, message
    else:
        assert message == "values: " + cli_message


def test_bad_representation_names_as_the_cli(cli):
    status, _, err = cli("convert", "--from", "bogus", "--to", "quat", stdin="")
    assert status != 0
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.convert([1, 0, 0, 0], "bogus", "quat")
    assert "unknown representation; valid representations: quat, quat-xyzw" in str(e.value)
    assert "unknown representation; valid representations: quat, quat-xyzw" in err
    with pytest.raises(kreisel.KreiselError, match="dst `euler:ZZX`: invalid Euler sequence `ZZX`"):
        kreisel.convert([1, 0, 0, 0], "quat", "euler:ZZX")


# --- every error path -----------------------------------------------------


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: kreisel.from_euler("ZZX", [1, 2, 3]), "seq: invalid Euler sequence `ZZX`: consecutive axes must differ"),
        (lambda: kreisel.from_euler("ZxZ", [1, 2, 3]), "mixed case"),
        (lambda: kreisel.from_euler("", [1, 2, 3]), "expected three axis letters"),
        (lambda: kreisel.from_euler("ABC", [1, 2, 3]), "axis letters must be x, y or z"),
        (lambda: kreisel.from_euler("ZXZ", 1.0), r"angles: expected shape \(..., 3\) \(3 numbers for euler:ZXZ\), found \(\)"),
        (lambda: kreisel.from_euler("ZXZ", [[1, 2, 3, 4]]), r"found \(1, 4\)"),
        (lambda: kreisel.from_euler("ZXZ", [[1, 2, 3], [4, 5]]), "angles: cannot read as an array of float64"),
        (lambda: kreisel.from_euler("ZXZ", [[0, 0, 0], [1, np.inf, 2]]), r"angles\[1\]: number `inf` is not finite"),
        (lambda: kreisel.from_euler("ZXZ", np.full((2, 2, 3), np.nan)), r"angles\[0, 0\]: number `NaN` is not finite"),
        (lambda: kreisel.from_euler("ZXZ", [1e308, 0, 0], degrees=False), None),
        (lambda: kreisel.from_euler("ZXZ", "abc"), "cannot read as an array of float64"),
        (lambda: kreisel.from_euler("ZXZ", None), r"angles: expected shape \(..., 3\) \(3 numbers for euler:ZXZ\), found \(\)"),
        (lambda: kreisel.from_euler("ZXZ", [1j, 0, 0]), "angles: cannot read as an array of float64 numbers: dtype complex128 is not real numbers"),
        (lambda: kreisel.as_euler("XYZ", [[1, 0, 0, 0], [0, 0, 0, 0]]), r"quats\[1\]: quaternion has zero norm"),
        (lambda: kreisel.as_euler("XYZ", np.zeros((3, 3))), r"quats: expected shape \(..., 4\)"),
        (lambda: kreisel.as_euler("XYZ", [1, 0, 0, -np.inf]), "quats: number `-inf` is not finite"),
        (lambda: kreisel.convert(np.eye(3)[None].repeat(2, 0) * [1, 1, -1], "matrix", "quat"), r"values\[0\]: matrix is a reflection"),
        (lambda: kreisel.convert(np.ones(9), "matrix", "quat"), r"values: expected shape \(..., 3, 3\) \(9 numbers for matrix\), found \(9,\)"),
        (lambda: kreisel.convert(np.eye(3) * 1.001, "matrix", "quat"), "matrix is not orthonormal"),
        (lambda: kreisel.convert([0, 0, 0, 90], "axis-angle", "quat", degrees=True), "values: rotation axis is zero but the angle is 90"),
        (lambda: kreisel.convert([1.5e308, 1.5e308, 0], "rotvec", "quat"), "rotation vector length is not a finite number"),
        (lambda: kreisel.convert([1, 0, 0, 0], "quaternion", "quat"), "src `quaternion`: unknown representation"),
        (lambda: kreisel.convert([1, 0, 0, 0], "quat", "euler:"), "dst `euler:`: invalid Euler sequence"),
        (lambda: kreisel.rates_from_omega("ZXZ", [[0, 0.1, 0], [0, 0, 0]], [1, 2, 3]), r"angles\[1\]: Euler rates are singular for ZXZ at middle angle 0"),
        (lambda: kreisel.rates_from_omega("XYZ", [0, math.pi / 2 - 1e-10, 0], [1, 2, 3]), "gimbal lock"),
        (lambda: kreisel.rates_from_omega("ZXZ", [0, 1, 0], [1, 2, 3], frame="space"), "frame `space`: expected `body` or `world`"),
        (lambda: kreisel.rates_from_omega("ZXZ", np.zeros((2, 3)), np.zeros((3, 3))), r"angles of shape \(2, 3\) and omega of shape \(3, 3\) do not broadcast"),
        (lambda: kreisel.rates_from_omega("ZXZ", [0, 1, 0], [[0, 0, 0], [np.nan, 0, 0]]), r"omega\[1\]: number `NaN` is not finite"),
        (lambda: kreisel.rates_from_omega("ZXZ", [0, 1e-8, 0], [1e308, 1e308, 0]), "result overflows"),
        (lambda: kreisel.omega_from_rates("ZXZ", [0, 1, 0], [1, 2]), r"rates: expected shape \(..., 3\)"),
        (lambda: kreisel.omega_from_rates("ZXZ", [0, 0, 0], [1e308, 0, 1e308]), "result overflows"),
        (lambda: kreisel.as_euler("XYZ", [True, False, False, False]), "dtype bool is not real numbers"),
        (lambda: kreisel.convert(["1", "0", "0", "0"], "quat", "quat"), "dtype <U1 is not real numbers"),
        (lambda: kreisel.omega_from_attitudes([[1, 0, 0, 0]], 0.1), "needs at least 2 attitudes along axis -2, found 1"),
        (lambda: kreisel.omega_from_attitudes([1, 0, 0, 0], 0.1), r"quats: expected shape \(..., N, 4\)"),
        (lambda: kreisel.omega_from_attitudes(np.ones((3, 4)), [0, 1, 1]), r"t\[2\]: times must increase strictly"),
        (lambda: kreisel.omega_from_attitudes(np.ones((3, 4)), [0, 1]), r"t: expected 3 times \(one per attitude\), found shape \(2,\)"),
        (lambda: kreisel.omega_from_attitudes(np.ones((3, 4)), -0.1), "t: a time step must be positive and finite, found -0.1"),
        (lambda: kreisel.omega_from_attitudes(np.ones((3, 4)), [0, np.nan, 1]), r"t\[1\]: number `NaN` is not finite"),
        (lambda: kreisel.omega_from_attitudes([[1, 0, 0, 0], [0, 0, 0, 0]], 0.1), r"quats\[1\]: quaternion has zero norm"),
        (lambda: kreisel.omega_from_attitudes([[1, 0, 0, 0], [0, 1, 0, 0]], 5e-324), r"quats\[0\]: angular velocity overflows"),
        (lambda: kreisel.omega_from_attitudes(np.ones((2, 4)), [-1e308, 1e308]), r"t\[1\]: times must increase strictly by finite steps"),
    ],
)
def test_error_paths(call, message):
    if message is None:  # huge finite angles are fine: a rotation, no error
        assert np.all(np.isfinite(call()))
        return
    with pytest.raises(kreisel.KreiselError, match=message) as e:
        call()
    assert isinstance(e.value, ValueError)
    assert "\n" not in str(e.value)


def test_non_string_names_raise_type_error():
    with pytest.raises(TypeError):
        kreisel.from_euler(None, [1, 2, 3])


def test_random_garbage_never_panics():
    """NaN, inf, huge and tiny numbers, wrong shapes, empty arrays, odd
    dtypes: every call returns finite numbers or raises KreiselError (a
    PanicException, a BaseException, would fail the test)."""
    rng = np.random.default_rng(2024)
    specials = np.array([np.nan, np.inf, -np.inf, 0.0, -0.0, 1e308, -1e308, 5e-324, 1.0, 90.0, math.pi / 2, math.pi])
    calls = [
        lambda x: kreisel.from_euler(rng.choice(SEQUENCES), x, degrees=bool(rng.integers(2))),
        lambda x: kreisel.as_euler(rng.choice(SEQUENCES), x, degrees=bool(rng.integers(2))),
        lambda x: kreisel.convert(x, rng.choice(REPRESENTATIONS + ["x", ""]), rng.choice(REPRESENTATIONS), degrees=bool(rng.integers(2))),
        lambda x: kreisel.rates_from_omega(rng.choice(SEQUENCES), x, x[..., ::-1] if x.ndim else x, frame=rng.choice(["body", "world"])),
        lambda x: kreisel.omega_from_rates(rng.choice(SEQUENCES), x, x, degrees=bool(rng.integers(2))),
        lambda x: kreisel.omega_from_attitudes(x, rng.choice([0.1, 5e-324, -1.0, np.nan]), frame=rng.choice(["body", "world"])),
    ]
    outcomes = {"ok": 0, "error": 0}
    for _ in range(3000):
        ndim = int(rng.integers(0, 4))
        shape = tuple(int(rng.choice([0, 1, 2, 3, 4, 9])) for _ in range(ndim))
        x = rng.normal(scale=10.0 ** rng.integers(-5, 5), size=shape)
        mask = rng.random(shape) < 0.2
        x[mask] = rng.choice(specials, size=int(mask.sum()))
        if rng.random() < 0.1:
            x = x.astype(rng.choice([np.float32, np.int64, np.complex128, object]))
        try:
            out = calls[int(rng.integers(len(calls)))](x)
            assert np.all(np.isfinite(out))
            outcomes["ok"] += 1
        except kreisel.KreiselError as e:
            assert "\n" not in str(e) and "internal error" not in str(e), e
            outcomes["error"] += 1
    assert outcomes["ok"] > 100 and outcomes["error"] > 100, outcomes


def test_large_arrays_and_other_threads():
    """10⁶ rotations in one call, while another thread converts too (the GIL
    is released during the loop; both results must be right)."""
    rng = np.random.default_rng(9)
    angles = rng.uniform(-math.pi, math.pi, size=(1_000_000, 3))
    results = {}

    def other():
        results["other"] = kreisel.from_euler("zyx", angles[:1000])

    thread = threading.Thread(target=other)
    thread.start()
    q = kreisel.from_euler("zyx", angles)
    thread.join()
    assert q.shape == (1_000_000, 4)
    assert np.array_equal(results["other"], q[:1000])
    ref = Rotation.from_euler("zyx", angles[::1000]).as_quat(scalar_first=True)
    assert np.max(np.abs(q[::1000] - np.where(ref[:, :1] < 0, -ref, ref))) < 1e-15


def test_large_arrays_split_over_threads_report_the_first_bad_row():
    # 2**17 rows are converted on up to two threads (blocks of rows): the
    # numbers are those of one thread, and the error names the first bad row.
    rng = np.random.default_rng(7)
    q = rng.normal(size=(1 << 17, 4))
    whole = kreisel.as_euler("ZYX", q)
    parts = np.concatenate([kreisel.as_euler("ZYX", q[:1000]), kreisel.as_euler("ZYX", q[1000:])])
    assert np.array_equal(whole, parts)
    q[100_000] = 0.0
    q[40_000] = np.nan
    with pytest.raises(kreisel.KreiselError, match=r"^quats\[40000\]: "):
        kreisel.as_euler("ZYX", q)
